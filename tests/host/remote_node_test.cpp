// host::remote_node: a remote node's objects as values, through od's one value path, against a
// fieldcodec SDO server with the XENAX CANopen dictionary behind an in-memory bus.
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/remote_node.hpp>
#include <fieldcodec/host/socketcan_bus.hpp>
#include <fieldcodec/xenax/canopen_units.hpp>

#include <doctest/doctest.h>

#include <unistd.h>

#include <array>
#include <cstdio>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace co = fieldcodec::canopen;
namespace od = fieldcodec::od;
namespace sdo = fieldcodec::canopen::sdo;
using fieldcodec::errc;

// docs/host.md, "Reading one object" (tests/docs_check/run.cmake compares the lines)
namespace doc {
namespace host = fieldcodec::host;
namespace x = fieldcodec::dictionaries::xenax_canopen;

int print_vendor_id(host::can_bus &bus) {
  host::remote_node drive(bus, 5, x::dictionary, fieldcodec::xenax::canopen_units);
  auto vendor = drive.read_text(x::identity_object_vendor_id);
  std::puts(vendor ? vendor.value().c_str() : vendor.error().what.c_str());
  return vendor ? 0 : 1;
}

int run() {
  host::socketcan_bus bus;
  if (!bus.open("can0")) return std::puts(bus.last_error().what.c_str()), 1;
  return print_vendor_id(bus);
}
} // namespace doc

namespace host = fieldcodec::host;
namespace x = fieldcodec::dictionaries::xenax_canopen;

namespace {

constexpr auto layout = co::make_layout<x::entries.size()>(x::dictionary);

/// Node 5 (an SDO server over the XENAX dictionary) on an in-memory bus; or, with `answer`
/// set, a device that answers every request with that frame.
class device_bus final : public host::can_bus {
public:
  device_bus() {
    name_ = "test0";
    (void)store_.init_defaults(5);
  }
  fieldcodec::status send(const co::can_frame &f) override {
    sent.push_back(f);
    if (answer) {
      queue.push_back(*answer);
      return {};
    }
    for (const auto &g : server_.on_frame(f, 0).send) queue.push_back(g);
    return {};
  }
  fieldcodec::result<host::frame_record> receive_record(std::chrono::milliseconds) override {
    if (queue.empty()) return fail(errc::timeout, 0, "no frame in time");
    auto r = host::to_record(queue.front());
    queue.pop_front();
    return r;
  }
  void set(od::address a, std::vector<std::uint8_t> bytes) {
    REQUIRE(store_.set(a, bytes) == sdo::abort_code::none);
  }
  std::vector<std::uint8_t> value(od::address a) {
    auto v = store_.value(a).value();
    return {v.begin(), v.end()};
  }

  std::deque<co::can_frame> queue;
  std::vector<co::can_frame> sent;
  std::optional<co::can_frame> answer;

private:
  std::vector<std::uint8_t> storage_ =
      std::vector<std::uint8_t>(co::dictionary_store<>::storage_size(x::dictionary));
  co::dictionary_store<> store_{x::dictionary, layout, storage_};
  std::array<std::uint8_t, 256> buffer_{};
  sdo::server<co::dictionary_store<>> server_{5, store_, buffer_};
};

using bytes = std::vector<std::uint8_t>;

} // namespace

TEST_CASE("remote_node: what read_text shows, write takes back as the same bytes (XENAX mA)") {
  device_bus bus;
  host::remote_node drive(bus, 5, x::dictionary, fieldcodec::xenax::canopen_units);
  bus.set({0x6073, 0}, {150, 0}); // raw 150 = 1500 mA (10 mA per raw unit)

  auto text = drive.read_text(x::limit_i_force);
  REQUIRE(text);
  CHECK(text.value() == "1500 mA");
  auto n = drive.read(x::limit_i_force);
  REQUIRE(n);
  CHECK(n.value().to_decimal().value().mantissa == 1500);
  CHECK(n.value().to_decimal().value().places == 0);
  auto raw = drive.read(x::limit_i_force, {.unit = od::value_unit::raw});
  REQUIRE(raw);
  CHECK(raw.value().to_int64().value() == 150);

  REQUIRE(drive.write(x::limit_i_force, "1230 mA"));
  CHECK(bus.value({0x6073, 0}) == bytes{123, 0});
  REQUIRE(drive.write(x::limit_i_force, text.value())); // what was read goes back unchanged
  CHECK(bus.value({0x6073, 0}) == bytes{150, 0});
  REQUIRE(drive.write(x::limit_i_force, od::unsigned_number(2000)));
  CHECK(bus.value({0x6073, 0}) == bytes{200, 0});
  REQUIRE(drive.write(x::limit_i_force, od::unsigned_number(40), {.unit = od::value_unit::raw}));
  CHECK(bus.value({0x6073, 0}) == bytes{40, 0});
  // by address: the dictionary's descriptor, with the vendor's unit
  REQUIRE(drive.write(od::address{0x6073, 0}, "800 mA"));
  CHECK(bus.value({0x6073, 0}) == bytes{80, 0});
  CHECK(drive.read_text(od::address{0x6073, 0}).value() == "800 mA");
}

TEST_CASE("remote_node: a value that cannot be sent is refused before any frame") {
  device_bus bus;
  host::remote_node drive(bus, 5, x::dictionary, fieldcodec::xenax::canopen_units);
  const bytes before = bus.value({0x6073, 0});

  // 6073h: HighLimit 0x7D0 raw = 20000 mA
  auto high = drive.write(x::limit_i_force, od::unsigned_number(20010));
  REQUIRE_FALSE(high);
  CHECK(high.error().code == errc::out_of_range);
  CHECK(high.error().value.issue == od::value_issue::high_limit);
  CHECK(high.error().what == "node 5, 6073h:00: refused: above the high limit 20000 mA");
  auto raw_high = drive.write(x::limit_i_force, "2001", {.unit = od::value_unit::raw});
  REQUIRE_FALSE(raw_high);
  CHECK(raw_high.error().value.issue == od::value_issue::high_limit);
  // hex spells a raw value: not taken for a scaled object in engineering units
  auto hex = drive.write(x::limit_i_force, "0x10");
  REQUIRE_FALSE(hex);
  CHECK(hex.error().value.issue == od::value_issue::hex_is_raw);
  auto unit = drive.write(x::limit_i_force, "1500 A");
  REQUIRE_FALSE(unit);
  CHECK(unit.error().value.issue == od::value_issue::unit);
  auto fraction = drive.write(x::limit_i_force, "1505 mA"); // not a multiple of 10 mA: rounds
  CHECK(fraction);
  CHECK(bus.value({0x6073, 0}) == bytes{151, 0}); // half away from zero, as od::encode_value
  bus.set({0x6073, 0}, before);
  bus.sent.clear();

  // a string longer than the object holds (5011h: Size=30), a character VISIBLE_STRING cannot
  // hold
  const std::string too_long(31, 'A');
  auto cap = drive.write(x::signateq_sensor_model_type_sqsmt, too_long);
  REQUIRE_FALSE(cap);
  CHECK(cap.error().value.issue == od::value_issue::capacity);
  CHECK(cap.error().what ==
        "node 5, 5011h:00: '" + too_long + "' refused: longer than the 30 bytes the object holds");
  auto ctl = drive.write(x::signateq_sensor_model_type_sqsmt, "a\tb");
  REQUIRE_FALSE(ctl);
  CHECK(ctl.error().value.issue == od::value_issue::character);
  // a number for a string, text that is no number
  CHECK(drive.write(x::signateq_sensor_model_type_sqsmt, od::unsigned_number(1))
            .error()
            .value.issue == od::value_issue::type);
  CHECK(drive.write(x::controlword, "1x").error().value.issue == od::value_issue::syntax);
  CHECK(drive.write(x::controlword, od::signed_number(-1)).error().code == errc::out_of_range);
  // not in the dictionary
  auto unknown = drive.write(od::address{0x2FFF, 7}, "1");
  REQUIRE_FALSE(unknown);
  CHECK(unknown.error().code == errc::unknown_object);
  CHECK(unknown.error().what == "node 5, 2FFFh:07: not in the node's dictionary (nothing sent)");
  CHECK(drive.read(od::address{0x2FFF, 7}).error().code == errc::unknown_object);

  CHECK(bus.sent.empty()); // none of them put a frame on the bus
  CHECK(bus.value({0x6073, 0}) == before);
}

TEST_CASE("remote_node: strings, node-relative values, the device's errors") {
  device_bus bus;
  host::remote_node drive(bus, 5, x::dictionary);
  bus.set({0x1008, 0}, bytes{'X', 'v', 'i'});
  CHECK(drive.read_text(x::manufacturer_device_name).value() == "\"Xvi\"");
  CHECK(drive.read(x::manufacturer_device_name).error().code == errc::type_mismatch);
  auto b = drive.read_bytes(x::manufacturer_device_name);
  REQUIRE(b);
  CHECK(bytes(b.value().begin(), b.value().end()) == bytes{'X', 'v', 'i'});
  REQUIRE(drive.write(x::signateq_sensor_model_type_sqsmt, "Axis 1"));
  CHECK(bus.value({0x5011, 0}) == bytes{'A', 'x', 'i', 's', ' ', '1'});
  auto shown = drive.read_text(x::signateq_sensor_model_type_sqsmt);
  REQUIRE(shown);
  CHECK(shown.value() == "\"Axis 1\"");
  REQUIRE(drive.write(x::signateq_sensor_model_type_sqsmt, shown.value())); // read back, same
  CHECK(bus.value({0x5011, 0}) == bytes{'A', 'x', 'i', 's', ' ', '1'});

  // the node's own COB-ID default (node-ID-relative): 1014h of node 5 is 85h
  auto emcy = drive.read(od::address{0x1014, 0});
  REQUIRE(emcy);
  CHECK(emcy.value().to_int64().value() == 0x85);

  // a write the server refuses: the abort, with node and object
  auto ro = drive.write(x::identity_object_vendor_id, od::unsigned_number(1));
  REQUIRE_FALSE(ro);
  CHECK(ro.error().code == errc::aborted);
  CHECK(ro.error().abort == sdo::abort_code::write_read_only);
  CHECK(ro.error().value.issue == od::value_issue::none);
  CHECK(ro.error().what.rfind("node 5, 1018h:01: SDO abort 06010002h", 0) == 0);
}

TEST_CASE("remote_node: an expedited upload without a size: the object's type decides") {
  device_bus bus;
  host::remote_node drive(bus, 5, x::dictionary);
  // 43h would say 4 bytes; 42h says nothing: 4 bytes, of which UNSIGNED16 takes 2
  bus.answer = co::make_frame(0x585, {0x42, 0x40, 0x60, 0x00, 0xE9, 0x03, 0x00, 0x00}).value();
  auto n = drive.read(x::controlword);
  REQUIRE(n);
  CHECK(n.value().to_int64().value() == 1001);
  CHECK(drive.read_text(x::controlword).value() == "1001");
  // the bytes beyond the object's size are not zero: refused, not guessed
  bus.answer = co::make_frame(0x585, {0x42, 0x40, 0x60, 0x00, 0xE9, 0x03, 0x01, 0x00}).value();
  auto stray = drive.read(x::controlword);
  REQUIRE_FALSE(stray);
  CHECK(stray.error().code == errc::bad_length);
  CHECK(stray.error().what ==
        "node 5, 6040h:00: 4 bytes read, UNSIGNED16 has 2 (and the others are not zero)");
  // a server that indicates the size: 2 bytes (4Bh) are the value, 1 byte (4Fh) is too short
  bus.answer = co::make_frame(0x585, {0x4B, 0x40, 0x60, 0x00, 0xE9, 0x03, 0x00, 0x00}).value();
  CHECK(drive.read(x::controlword).value().to_int64().value() == 1001);
  bus.answer = co::make_frame(0x585, {0x4F, 0x40, 0x60, 0x00, 0xE9, 0x00, 0x00, 0x00}).value();
  CHECK(drive.read(x::controlword).error().code == errc::bad_length);
}

TEST_CASE("docs/host.md: reading one object, and values not bytes") {
  {
    device_bus bus;
    bus.set({0x1018, 1}, {0x1B, 0x02, 0, 0});
    CHECK(doc::print_vendor_id(bus) == 0); // prints 539
    device_bus silent;
    silent.answer = co::make_frame(0x585, {0x80, 0x18, 0x10, 0x01, 0x00, 0x00, 0x02, 0x06}).value();
    CHECK(doc::print_vendor_id(silent) == 1); // prints the abort
  }
  // run() opens can0: where there is none (a test machine), it says so and returns 1
  if (::access("/sys/class/net/can0", F_OK) != 0) CHECK(doc::run() == 1);

  device_bus bus;
  bus.set({0x6073, 0}, {150, 0});
  host::remote_node drive(bus, 5, x::dictionary, fieldcodec::xenax::canopen_units);
  auto limit = drive.read_text(x::limit_i_force);           // "1500 mA" (raw 150)
  auto sent = drive.write(x::limit_i_force, "1230 mA");     // raw 123 on the wire
  auto refused = drive.write(x::limit_i_force, "20010 mA"); // nothing sent:
  // refused.error().what == "node 5, 6073h:00: '20010 mA' refused: above the high limit 20000 mA"
  CHECK(limit.value() == "1500 mA");
  CHECK(sent);
  CHECK(bus.value({0x6073, 0}) == bytes{123, 0});
  REQUIRE_FALSE(refused);
  CHECK(refused.error().what ==
        "node 5, 6073h:00: '20010 mA' refused: above the high limit 20000 mA");
}
