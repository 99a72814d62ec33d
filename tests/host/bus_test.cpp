// host::can_bus::receive over a scripted bus: error frames become errors (bus-off, error
// passive), extended frames are skipped, timeouts; the blocking SDO layer goes on through an
// error-passive warning and stops at bus-off. (SocketCAN delivers such frames; CI has no vcan,
// so the shared code is tested here.)
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/host/bus.hpp>
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/sdo.hpp>

#include <doctest/doctest.h>

#include <deque>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace host = fieldcodec::host;
using fieldcodec::errc;
using namespace std::chrono_literals;

namespace {

constexpr auto layout = co::make_layout<fieldcodec::dictionaries::xenax_canopen::entries.size()>(
    fieldcodec::dictionaries::xenax_canopen::dictionary);

/// A bus with a node 5 behind it, and error or foreign frames injected before its answers.
class scripted_bus final : public host::can_bus {
public:
  scripted_bus() {
    name_ = "test0";
    (void)store_.init_defaults(5);
  }
  fieldcodec::status send(const co::can_frame &f) override {
    sent.push_back(f);
    for (const auto &g : server_.on_frame(f, 0).send) queue.push_back(host::to_record(g));
    return {};
  }
  fieldcodec::result<host::frame_record> receive_record(std::chrono::milliseconds) override {
    if (!inject.empty()) {
      auto r = inject.front();
      inject.pop_front();
      return r;
    }
    if (queue.empty()) return fail(errc::timeout, 0, "no frame in time");
    auto r = queue.front();
    queue.pop_front();
    return r;
  }
  std::deque<host::frame_record> inject, queue;
  std::vector<co::can_frame> sent;

private:
  std::vector<std::uint8_t> storage_ = std::vector<std::uint8_t>(
      co::dictionary_store<>::storage_size(fieldcodec::dictionaries::xenax_canopen::dictionary));
  co::dictionary_store<> store_{fieldcodec::dictionaries::xenax_canopen::dictionary, layout,
                                storage_};
  std::array<std::uint8_t, 64> buffer_{};
  sdo::server<co::dictionary_store<>> server_{5, store_, buffer_};
};

host::frame_record line(const char *s) { return host::candump::parse_line(s).value(); }

} // namespace

TEST_CASE("can_bus::receive: error frames are errors, extended frames skipped") {
  scripted_bus bus;
  bus.inject.push_back(line("12345678#00"));
  bus.inject.push_back(line("705#05"));
  auto r = bus.receive(10ms);
  REQUIRE(r);
  CHECK(r.value().frame == co::make_frame(0x705, {0x05}).value());

  bus.inject.push_back(line("20000040#0000000000000000"));
  CHECK(bus.receive(10ms) == errc::bad_state);
  CHECK(bus.last_error().from_error_frame);
  CHECK(bus.last_error().frame.is_bus_off());
  CHECK(bus.last_error().what == "test0: bus-off");

  bus.inject.push_back(line("20000004#0010000000000000"));
  CHECK(bus.receive(10ms) == errc::bad_state);
  CHECK(bus.last_error().frame.is_error_passive());
  CHECK(bus.last_error().what == "test0: error passive (rx)");

  CHECK(bus.receive(10ms) == errc::timeout);
  CHECK(bus.last_error().what == "test0: no frame in time");
  CHECK_FALSE(bus.last_error().from_error_frame);
  // only extended frames until the time is up: a timeout
  bus.inject.push_back(line("12345678#00"));
  CHECK(bus.receive(0ms) == errc::timeout);
}

TEST_CASE("blocking SDO: warnings pass, bus-off stops the transfer") {
  scripted_bus bus;
  bus.inject.push_back(line("20000004#0020000000000000")); // error passive: go on
  auto v = host::sdo_read(bus, 5, {0x1000, 0}, 100ms);
  REQUIRE(v);
  CHECK(v.value() == std::vector<std::uint8_t>{0x92, 0x01, 0x02, 0x00});

  bus.inject.push_back(line("20000040#0000000000000000")); // bus-off: stop
  v = host::sdo_read(bus, 5, {0x1000, 0}, 100ms);
  REQUIRE_FALSE(v);
  CHECK(v.error().code == errc::bad_state);
  CHECK(v.error().bus_failed);
  CHECK(v.error().what == "node 5, 1000h:00: test0: bus-off");
}
