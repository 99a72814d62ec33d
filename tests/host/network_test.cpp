// host::network: one loop for any number of machines over an in-memory bus — a node::device and
// an SDO client sharing a network, frames from the bus dispatched, deadlines polled, filters;
// bad input: a machine's failed start, an unknown machine, a bus that fails to send, error
// frames (a warning passes, bus-off stops), a receive failure, a condition never met. And the
// example's node (examples/serve_node.hpp, the lines docs/host.md shows).
#include "../../examples/serve_node.hpp"

#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/network.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdio>
#include <deque>
#include <vector>

namespace doc = fieldcodec::examples; // docs/host.md, "Running machines: host::network"

namespace co = fieldcodec::canopen;
namespace node = fieldcodec::canopen::node;
namespace sdo = fieldcodec::canopen::sdo;
namespace host = fieldcodec::host;
namespace x = fieldcodec::dictionaries::xenax_canopen;
using fieldcodec::errc;
using namespace std::chrono_literals;

namespace {

constexpr auto layout = co::make_layout<x::entries.size()>(x::dictionary);

/// A bus: what is sent is recorded; what is queued is received (frames or records, e.g. error
/// frames); `fail_send` / `fail_receive` make the next calls fail.
class wire final : public host::can_bus {
public:
  wire() { name_ = "test0"; }
  fieldcodec::status send(const co::can_frame &f) override {
    if (fail_send) return fail(errc::bad_state, 0, "write failed");
    sent.push_back(f);
    return {};
  }
  fieldcodec::result<host::frame_record> receive_record(std::chrono::milliseconds t) override {
    waits.push_back(t);
    if (fail_receive) return fail(errc::bad_state, 5, "read");
    if (queue.empty()) return fail(errc::timeout, 0, "no frame in time");
    auto r = queue.front();
    queue.pop_front();
    return r;
  }
  void inject(const char *candump) { queue.push_back(host::candump::parse_line(candump).value()); }
  [[nodiscard]] std::size_t count(std::uint16_t id) const {
    std::size_t n = 0;
    for (const auto &f : sent) n += f.id == id ? 1U : 0U;
    return n;
  }
  std::deque<host::frame_record> queue;
  std::vector<co::can_frame> sent;
  std::vector<std::chrono::milliseconds> waits; ///< what each receive was given
  bool fail_send = false;
  bool fail_receive = false;
};

/// Node 5 with the XENAX CANopen dictionary.
struct xenax_node {
  xenax_node() { (void)store.init_defaults(5); }
  std::vector<std::uint8_t> storage =
      std::vector<std::uint8_t>(co::dictionary_store<>::storage_size(x::dictionary));
  co::dictionary_store<> store{x::dictionary, layout, storage};
  node::device<co::dictionary_store<>, node::capacity_for(x::dictionary)> dev{store, 5};
};

/// A machine that counts what it is given and answers nothing.
struct counter {
  struct step_t {
    co::frames send{};
    int state = 0;
    std::optional<std::uint32_t> deadline{};
  };
  step_t on_frame(const co::can_frame &f, std::uint32_t) {
    seen.push_back(f);
    return {};
  }
  step_t poll(std::uint32_t) {
    ++polls;
    return {};
  }
  std::vector<co::can_frame> seen;
  int polls = 0;
};

} // namespace

TEST_CASE("network: a device and an SDO client of it on one network") {
  wire bus;
  xenax_node n;
  REQUIRE(n.store.set({0x1018, 1}, std::array<std::uint8_t, 4>{0x1B, 0x02, 0, 0}) ==
          sdo::abort_code::none);
  host::network net(bus);
  std::vector<co::nmt::state> states;
  const auto dev = net.add(n.dev, [&](const auto &s, std::uint32_t) { states.push_back(s.state); });
  sdo::client client(5);
  const auto cl = net.add(client);
  CHECK(net.size() == 2);

  auto booted = net.send(dev, n.dev.start(net.now()));
  REQUIRE(booted);
  CHECK(booted.value() == co::nmt::state::pre_operational);
  REQUIRE(bus.sent.size() == 1);
  CHECK(bus.sent[0] == co::make_frame(0x705, {0x00}).value()); // boot-up

  // the client's request reaches the device through the network, its answer the client
  std::array<std::uint8_t, 4> buf{};
  auto up = net.send(cl, client.upload({0x1018, 1}, buf, net.now()));
  REQUIRE(up);
  CHECK(client.state() == sdo::transfer_state::done);
  CHECK(std::vector<std::uint8_t>(client.received().begin(), client.received().end()) ==
        std::vector<std::uint8_t>{0x1B, 0x02, 0, 0});
  CHECK(bus.count(0x605) == 1); // both frames are on the bus too
  CHECK(bus.count(0x585) == 1);

  // a frame from the bus: NMT start (to every node) is dispatched to the device
  bus.inject("000#0100");
  REQUIRE(net.run_once(0ms));
  CHECK(n.dev.state() == co::nmt::state::operational);
  CHECK(states.back() == co::nmt::state::operational);
  // an SDO request from another node on the bus: the answer goes out
  bus.inject("605#4000100000000000");
  REQUIRE(net.run_once(0ms));
  CHECK(bus.sent.back() ==
        co::make_frame(0x585, {0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0x02, 0x00}).value());
}

TEST_CASE("network: deadlines are polled (heartbeat), the wait is no longer than the earliest") {
  wire bus;
  xenax_node n;
  // heartbeat producer time 20 ms (1017h is read-only in this dictionary: the application's)
  REQUIRE(n.store.set({0x1017, 0}, std::array<std::uint8_t, 4>{20, 0, 0, 0}) ==
          sdo::abort_code::none);
  host::network net(bus);
  const auto dev = net.add(n.dev);
  REQUIRE(net.send(dev, n.dev.start(net.now())));
  // the network waits for a frame until the next heartbeat is due, not for max_wait
  REQUIRE(net.run_once(1000ms));
  CHECK(bus.waits.back() <= 20ms);
  const std::size_t before = bus.count(0x705);
  REQUIRE(net.run_for(110ms));
  // about 5 heartbeats (each 20 ms); a loaded machine may lose some, never add any
  CHECK(bus.count(0x705) - before >= 2);
  CHECK(bus.count(0x705) - before <= 6);
  CHECK(bus.sent.back() == co::make_frame(0x705, {0x7F}).value()); // pre-operational
}

TEST_CASE("network: filters, no frame back to its sender, removal") {
  wire bus;
  host::network net(bus);
  counter all, only_sdo;
  const auto a = net.add(all);
  const auto b = net.add(only_sdo);
  net.filter(b, [](const co::can_frame &f) { return f.id == 0x605; });
  bus.inject("000#0100");
  bus.inject("605#4000100000000000");
  REQUIRE(net.run_once(0ms));
  REQUIRE(net.run_once(0ms));
  CHECK(all.seen.size() == 2);
  REQUIRE(only_sdo.seen.size() == 1);
  CHECK(only_sdo.seen[0].id == 0x605);
  CHECK(all.polls == 0); // no deadline: never polled
  CHECK(bus.waits.back() == 0ms);
  REQUIRE(net.run_once(250ms));
  CHECK(bus.waits.back() > 200ms); // no deadline: the whole wait (less what receive took)

  // a frame a machine sends goes to the others, not back to it
  co::step<int> one;
  one.send = co::frames(co::make_frame(0x605, {0x40}).value());
  REQUIRE(net.send(a, one));
  CHECK(all.seen.size() == 2);
  CHECK(only_sdo.seen.size() == 2);
  // a machine due now is polled
  one.send = {};
  one.deadline = net.now();
  REQUIRE(net.send(a, one));
  REQUIRE(net.run_once(0ms));
  CHECK(all.polls == 1);

  net.remove(b);
  CHECK(net.size() == 1);
  bus.inject("000#0100");
  REQUIRE(net.run_once(0ms));
  CHECK(only_sdo.seen.size() == 2);
  CHECK(all.seen.size() == 3);
}

TEST_CASE("network: bad input — failed starts, unknown machines, failing buses") {
  wire bus;
  xenax_node n;
  host::network net(bus);
  const auto dev = net.add(n.dev);
  REQUIRE(net.send(dev, n.dev.start(net.now())));

  // a machine's start that fails: its errc, its id, nothing sent
  const std::size_t sent = bus.sent.size();
  auto again = net.send(dev, n.dev.start(net.now()));
  REQUIRE_FALSE(again);
  CHECK(again.error().code == errc::bad_state);
  CHECK(again.error().machine == dev);
  CHECK_FALSE(again.error().bus_failed);
  CHECK(again.error().what == "machine 0: " + std::string(fieldcodec::to_string(errc::bad_state)));
  CHECK(bus.sent.size() == sent);
  // an SDO client of a node that does not answer stays busy: a second upload is refused
  sdo::client client(9);
  const auto cl = net.add(client);
  std::array<std::uint8_t, 4> buf{};
  REQUIRE(net.send(cl, client.upload({0x1018, 1}, buf, net.now())));
  CHECK(bus.sent.back().id == 0x609);
  auto second = net.send(cl, client.upload({0x1018, 2}, buf, net.now()));
  REQUIRE_FALSE(second);
  CHECK(second.error().code == errc::bad_state);
  CHECK(second.error().machine == cl);
  CHECK(bus.sent.back().data[1] == 0x18); // nothing more sent
  CHECK(bus.sent.back().data[3] == 0x01);

  // a device's set() refused (a value of the wrong size): its abort code's errc, nothing sent
  const std::size_t before_set = bus.sent.size();
  auto too_long =
      net.send(dev, n.dev.set({0x6073, 0}, std::array<std::uint8_t, 4>{1, 2, 3, 4}, net.now()));
  REQUIRE_FALSE(too_long);
  CHECK(too_long.error().code ==
        co::sdo::to_errc(co::sdo::abort_code::length_too_high)); // 4 bytes for an UNSIGNED16
  CHECK(too_long.error().machine == dev);
  CHECK(bus.sent.size() == before_set);

  // an id the network does not know
  auto unknown = net.send(7, co::step<int>{});
  REQUIRE_FALSE(unknown);
  CHECK(unknown.error().code == errc::invalid_argument);
  CHECK(unknown.error().what == "machine 7: not on the network");
  net.remove(cl);
  CHECK_FALSE(net.send(cl, co::step<int>{}));

  // the bus fails to send: the bus's context, the machine that sent
  bus.fail_send = true;
  bus.inject("605#4000100000000000");
  auto no_send = net.run_once(0ms);
  REQUIRE_FALSE(no_send);
  CHECK(no_send.error().bus_failed);
  CHECK(no_send.error().code == errc::bad_state);
  CHECK(no_send.error().machine == dev);
  CHECK(no_send.error().what == "test0: write failed");
  bus.fail_send = false;

  // an error-passive warning is counted and skipped; bus-off stops
  bus.inject("20000004#0010000000000000");
  REQUIRE(net.run_once(0ms));
  CHECK(net.warnings() == 1);
  bus.inject("20000040#0000000000000000");
  auto off = net.run_once(0ms);
  REQUIRE_FALSE(off);
  CHECK(off.error().bus_failed);
  CHECK_FALSE(off.error().machine);
  CHECK(off.error().what == "test0: bus-off");

  // a receive that fails
  bus.fail_receive = true;
  auto no_read = net.run_once(0ms);
  REQUIRE_FALSE(no_read);
  CHECK(no_read.error().code == errc::bad_state);
  CHECK(no_read.error().bus.sys_errno == 5);
  bus.fail_receive = false;

  // a condition not met in time
  auto never = net.run_until([] { return false; }, 20ms);
  REQUIRE_FALSE(never);
  CHECK(never.error().code == errc::timeout);
  CHECK(never.error().what == "not done within 20 ms");
}

TEST_CASE("network: the guide's node (docs/host.md) boots and answers") {
  wire bus;
  bus.inject("605#4000100000000000");
  bus.inject("000#0105");
  CHECK(doc::serve(bus, 30ms) == 0);
  REQUIRE(bus.sent.size() >= 2);
  CHECK(bus.sent[0] == co::make_frame(0x705, {0x00}).value());
  CHECK(bus.sent[1] ==
        co::make_frame(0x585, {0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0x02, 0x00}).value());
  bus.fail_send = true; // a bus that cannot send: the boot-up fails, exit 1
  CHECK(doc::serve(bus, 30ms) == 1);
  bus.fail_send = false;
  bus.fail_receive = true; // a bus that fails while running: its line, exit 1
  CHECK(doc::serve(bus, 30ms) == 1);
}
