// The communication objects of the DPQ manual's chapter 3 (../shared/seeds/004_…txt) in the
// generated dictionary (dictionaries/dpq_parameters.csv, sections 3.1/3.4/3.5): found by
// address and by name, with the type, access, range and default the manual gives (CiA 301
// where it is silent, docs/dpq.md "Communication objects"), and written through the
// dictionary-checked path dpq::write_request, which refuses values outside the range.
#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/emergency.hpp>
#include <fieldcodec/dpq/lookup.hpp>
#include <fieldcodec/dpq/sdo.hpp>
#include <fieldcodec/od/address.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <string_view>

namespace fc = fieldcodec;
namespace co = fieldcodec::canopen;
namespace dpq = fieldcodec::dpq;
namespace od = fieldcodec::od;
namespace p = fieldcodec::dictionaries::dpq_parameters;
using fc::errc;

namespace {

constexpr co::can_frame frame8(std::uint16_t id, std::array<std::uint8_t, 8> d) {
  co::can_frame f;
  f.id = id;
  f.dlc = 8;
  f.data = d;
  return f;
}

// What the manual (or, where it is silent, CiA 301) says about one object.
struct expected {
  std::uint16_t index;
  std::uint8_t sub;
  std::string_view name;
  std::string_view section;
  od::object_code object;
  od::data_type type;
  od::access access;
  bool has_range;
  std::int64_t low, high;
  bool has_default;
  std::int64_t default_value;
  std::string_view unit;
};

using oc = od::object_code;
using dt = od::data_type;
using ac = od::access;

// 3.1: Guard Time and Life Time Factor "Pre-set values" 0 (Guard Time in ms); Consumer and
// Producer Heartbeat Time Interval pre-set 0 ms. 3.4: the event timer of each Tx-PDO
// (1800h..1803h, 3.2), written with 2 bytes in the example. 3.5: error register 1001h, error
// history 1003h (sub 0 the number of errors, at most 4 saved, sub 1 the newest).
constexpr std::array<expected, 19> objects{{
    {0x1001, 0, "Error Register", "3.5", oc::var, dt::unsigned8, ac::ro, false, 0, 0, false, 0, ""},
    {0x1003, 0, "Error History", "3.5", oc::array, dt::unsigned8, ac::rw, true, 0, 4, true, 0, ""},
    {0x1003, 1, "Error Code 1", "3.5", oc::array, dt::unsigned32, ac::ro, false, 0, 0, false, 0,
     ""},
    {0x1003, 2, "Error Code 2", "3.5", oc::array, dt::unsigned32, ac::ro, false, 0, 0, false, 0,
     ""},
    {0x1003, 3, "Error Code 3", "3.5", oc::array, dt::unsigned32, ac::ro, false, 0, 0, false, 0,
     ""},
    {0x1003, 4, "Error Code 4", "3.5", oc::array, dt::unsigned32, ac::ro, false, 0, 0, false, 0,
     ""},
    {0x100C, 0, "Guard Time", "3.1", oc::var, dt::unsigned16, ac::rw, true, 0, 65535, true, 0,
     "ms"},
    {0x100D, 0, "Life Time Factor", "3.1", oc::var, dt::unsigned8, ac::rw, true, 0, 255, true, 0,
     ""},
    {0x1016, 0, "Consumer Heartbeat Time", "3.1", oc::array, dt::unsigned8, ac::ro, true, 1, 127,
     false, 0, ""},
    {0x1016, 1, "Consumer Heartbeat Time Interval", "3.1", oc::array, dt::unsigned32, ac::rw, true,
     0, 0xFFFFFF, true, 0, ""},
    {0x1017, 0, "Producer Heartbeat Time Interval", "3.1", oc::var, dt::unsigned16, ac::rw, true, 0,
     65535, true, 0, "ms"},
    {0x1800, 0, "Tx-PDO1 Communication Parameter", "3.4", oc::record, dt::unsigned8, ac::ro, true,
     5, 6, false, 0, ""},
    {0x1800, 5, "Tx-PDO1 Event Timer", "3.4", oc::record, dt::unsigned16, ac::rw, true, 0, 65535,
     true, 0, "ms"},
    {0x1801, 0, "Tx-PDO2 Communication Parameter", "3.4", oc::record, dt::unsigned8, ac::ro, true,
     5, 6, false, 0, ""},
    {0x1801, 5, "Tx-PDO2 Event Timer", "3.4", oc::record, dt::unsigned16, ac::rw, true, 0, 65535,
     true, 0, "ms"},
    {0x1802, 0, "Tx-PDO3 Communication Parameter", "3.4", oc::record, dt::unsigned8, ac::ro, true,
     5, 6, false, 0, ""},
    {0x1802, 5, "Tx-PDO3 Event Timer", "3.4", oc::record, dt::unsigned16, ac::rw, true, 0, 65535,
     true, 0, "ms"},
    {0x1803, 0, "Tx-PDO4 Communication Parameter", "3.4", oc::record, dt::unsigned8, ac::ro, true,
     5, 6, false, 0, ""},
    {0x1803, 5, "Tx-PDO4 Event Timer", "3.4", oc::record, dt::unsigned16, ac::rw, true, 0, 65535,
     true, 0, "ms"},
}};

void check_object(const expected &x, const od::descriptor &d) {
  CHECK(d.index == x.index);
  CHECK(d.sub == x.sub);
  CHECK(d.info.name == x.name);
  CHECK(d.info.section == x.section);
  CHECK(d.object == x.object);
  CHECK(d.type == x.type);
  CHECK(d.access_type == x.access);
  CHECK(d.info.unit == x.unit);
  // raw values: no scale, no DPQ acceptance or Bus Manager text, not PDO-mappable
  CHECK(!d.has(od::flag::scaled));
  CHECK((d.flags & ~od::flag::packed) == 0); // no DPQ flag, no scale
  CHECK(dpq::columns_of(p::dpq_columns, d).value_acceptance == dpq::acceptance::unknown);
  CHECK(dpq::columns_of(p::dpq_columns, d).bus == dpq::bus_manager::unspecified);
  CHECK(d.pdo == od::pdo_mapping::no);
  REQUIRE(d.low().has_value() == x.has_range);
  REQUIRE(d.high().has_value() == x.has_range);
  if (x.has_range) {
    CHECK(d.low().to_int64().value() == x.low);
    CHECK(d.high().to_int64().value() == x.high);
  }
  REQUIRE(d.default_value().has_value() == x.has_default);
  if (x.has_default) CHECK(d.default_value().to_int64().value() == x.default_value);
}

} // namespace

// The named descriptors of the generated header are these objects.
static_assert(p::tx_pdo1_event_timer.index == 0x1800 && p::tx_pdo1_event_timer.sub == 5);
static_assert(p::tx_pdo4_event_timer.index == 0x1803 && p::tx_pdo4_event_timer.sub == 5);
static_assert(p::producer_heartbeat_time_interval.index == 0x1017);
static_assert(p::guard_time.index == 0x100C && p::life_time_factor.index == 0x100D);
static_assert(p::error_register.index == 0x1001);
static_assert(p::error_history.index == 0x1003 && p::error_history[0].sub == 0);
static_assert(p::error_code_1.index == 0x1003 && p::error_code_1.sub == 1);
static_assert(p::consumer_heartbeat_time_interval.index == 0x1016 &&
              p::consumer_heartbeat_time_interval.sub == 1);
// The chapter-3 section names no single object: find by name or by address.
static_assert(dpq::find_by_name(p::dictionary, "Tx-PDO1 Event Timer").value().index == 0x1800);

// Manual 004, 3.4 "Starting the PDO transmission": node 5, event timer of the 1st Tx-PDO to
// 100 ms = 605: 2B 00 18 05 64 00 00 00 (the printed frame), through the generated descriptor.
static_assert(dpq::write_request(5, p::tx_pdo1_event_timer, 100).value() ==
              frame8(0x605, {0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}));
static_assert(dpq::write_request(5, p::tx_pdo1_event_timer, 65536).is(errc::out_of_range));

TEST_CASE("dpq communication objects: by address and by name, as the manual says") {
  for (const auto &x : objects) {
    INFO(x.name);
    const auto by_address = p::dictionary.at(x.index, x.sub);
    REQUIRE(by_address.has_value());
    check_object(x, by_address.value());
    const auto by_name = dpq::find_by_name(p::dictionary, x.name);
    REQUIRE(by_name.has_value());
    CHECK(od::address{by_name.value().index, by_name.value().sub} == od::address{x.index, x.sub});
    check_object(x, by_name.value());
  }
  // the named descriptors
  check_object(objects[0], p::error_register);
  check_object(objects[1], p::error_history_sub0);
  check_object(objects[2], p::error_code_1);
  check_object(objects[5], p::error_code_4);
  check_object(objects[6], p::guard_time);
  check_object(objects[7], p::life_time_factor);
  check_object(objects[8], p::consumer_heartbeat_time_sub0);
  check_object(objects[9], p::consumer_heartbeat_time_interval);
  check_object(objects[10], p::producer_heartbeat_time_interval);
  check_object(objects[11], p::tx_pdo1_sub0);
  check_object(objects[12], p::tx_pdo1_event_timer);
  check_object(objects[14], p::tx_pdo2_event_timer);
  check_object(objects[16], p::tx_pdo3_event_timer);
  check_object(objects[18], p::tx_pdo4_event_timer);
  // the objects as views: 1003h sub 1..4 are the error history fields of dpq/emergency.hpp
  CHECK(p::error_history.entries.size() == 5);
  CHECK(p::consumer_heartbeat_time.entries.size() == 2);
  CHECK(p::tx_pdo1.entries.size() == 2);
  for (std::uint8_t n = 1; n <= dpq::error_history_capacity; ++n) {
    const auto a = dpq::error_history_address(n);
    const auto d = p::dictionary.at(a.index, a.sub);
    REQUIRE(d.has_value());
    CHECK(d.value().type == od::data_type::unsigned32);
  }
  // nothing past what the manual describes
  CHECK(p::dictionary.at(0x1003, 5) == errc::unknown_object);
  CHECK(p::dictionary.at(0x1800, 1) == errc::unknown_object);
  CHECK(p::dictionary.at(0x1804, 5) == errc::unknown_object);
  CHECK(p::dictionary.at(0x1A00, 0) == errc::unknown_object);
  CHECK(dpq::find_by_name(p::dictionary, "Event Timer") == errc::unknown_object);
}

TEST_CASE("dpq communication objects: the frames of 3.4 through the dictionary") {
  // write 100 ms, the card's confirmation, the read-back (0x40; the manual prints 0x42, see
  // errata DPQ-F1) and its 2-byte answer 4B … 64 00
  const auto w = dpq::write_request(5, p::tx_pdo1_event_timer, 100);
  REQUIRE(w.has_value());
  CHECK(w.value() == frame8(0x605, {0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}));
  CHECK(dpq::write_response(5, p::tx_pdo1_event_timer,
                            frame8(0x585, {0x60, 0x00, 0x18, 0x05, 0, 0, 0, 0}))
            .has_value());
  CHECK(dpq::read_request(5, p::tx_pdo1_event_timer).value() ==
        frame8(0x605, {0x40, 0x00, 0x18, 0x05, 0, 0, 0, 0}));
  const auto answer = frame8(0x585, {0x4B, 0x00, 0x18, 0x05, 0x64, 0x00, 0, 0});
  CHECK(dpq::read_raw_response(5, p::tx_pdo1_event_timer, answer).value() == 100);
  // an answer for Tx-PDO2's timer is not an answer for Tx-PDO1's
  CHECK(dpq::read_raw_response(5, p::tx_pdo2_event_timer, answer).error().code ==
        errc::unexpected_frame);
}

TEST_CASE("dpq communication objects: writes outside the range are refused before a frame") {
  // 1800h sub 5 and 1017h: UNSIGNED16 milliseconds
  for (const od::descriptor &d : {p::tx_pdo1_event_timer, p::tx_pdo3_event_timer,
                                  p::producer_heartbeat_time_interval, p::guard_time}) {
    INFO(d.info.name);
    CHECK(dpq::write_request(5, d, 0).has_value());
    CHECK(dpq::write_request(5, d, 65535).value().data[0] == 0x2B);
    CHECK(dpq::write_request(5, d, 65536).error() == errc::out_of_range);
    CHECK(dpq::write_request(5, d, 70000).error() == errc::out_of_range);
    CHECK(dpq::write_request(5, d, -1).error() == errc::out_of_range);
    CHECK(dpq::write_request(5, d, 65535.5).error() == errc::out_of_range);
    // a fraction is rounded half away from zero like every DPQ value (3.3), identity scale
    CHECK(dpq::write_request(5, d, 100.5).value().data[4] == 101);
    CHECK(dpq::write_request(5, d, 100.4).value().data[4] == 100);
  }
  CHECK(dpq::write_request(5, p::producer_heartbeat_time_interval, 1000).value() ==
        frame8(0x605, {0x2B, 0x17, 0x10, 0x00, 0xE8, 0x03, 0, 0}));
  // 100Dh: UNSIGNED8, one data byte (2F)
  CHECK(dpq::write_request(5, p::life_time_factor, 3).value() ==
        frame8(0x605, {0x2F, 0x0D, 0x10, 0x00, 0x03, 0, 0, 0}));
  CHECK(dpq::write_request(5, p::life_time_factor, 256).error() == errc::out_of_range);
  // 1016h sub 1: node 3 watched every 200 ms; bits 24..31 are reserved
  CHECK(dpq::write_request(5, p::consumer_heartbeat_time_interval, 0x000300C8).value() ==
        frame8(0x605, {0x23, 0x16, 0x10, 0x01, 0xC8, 0x00, 0x03, 0x00}));
  CHECK(dpq::write_request(5, p::consumer_heartbeat_time_interval, 0x01000000).error() ==
        errc::out_of_range);
  // 1003h sub 0: 0 clears the history (2F 03 10 00 00); more than 4 errors cannot be
  CHECK(dpq::write_request(5, p::error_history_sub0, 0).value() ==
        frame8(0x605, {0x2F, 0x03, 0x10, 0x00, 0x00, 0, 0, 0}));
  CHECK(dpq::write_request(5, p::error_history_sub0, 5).error() == errc::out_of_range);
  // read-only objects are never written
  CHECK(dpq::write_request(5, p::error_register, 0).error() == errc::access_denied);
  CHECK(dpq::write_request(5, p::error_code_1, 0).error() == errc::access_denied);
  CHECK(dpq::write_request(5, p::tx_pdo1_sub0, 5).error() == errc::access_denied);
}

TEST_CASE("dpq communication objects: the error history read through the dictionary") {
  // 1003h sub 0 = 2, sub 1 = 3400h (newest), sub 2 = 8302h, read as the card answers them
  CHECK(dpq::read_request(5, p::error_history_sub0).value() ==
        frame8(0x605, {0x40, 0x03, 0x10, 0x00, 0, 0, 0, 0}));
  const auto count = dpq::read_raw_response(5, p::error_history_sub0,
                                            frame8(0x585, {0x4F, 0x03, 0x10, 0x00, 0x02, 0, 0, 0}));
  REQUIRE(count.has_value());
  const auto f1 = dpq::read_raw_response(
      5, p::error_code_1, frame8(0x585, {0x43, 0x03, 0x10, 0x01, 0x00, 0x34, 0x00, 0x00}));
  const auto f2 = dpq::read_raw_response(
      5, p::error_code_2, frame8(0x585, {0x43, 0x03, 0x10, 0x02, 0x02, 0x83, 0x00, 0x00}));
  REQUIRE(f1.has_value());
  REQUIRE(f2.has_value());
  const std::array<std::uint32_t, 2> fields{static_cast<std::uint32_t>(f1.value()),
                                            static_cast<std::uint32_t>(f2.value())};
  const auto h = dpq::decode_error_history(static_cast<std::uint8_t>(count.value()), fields);
  REQUIRE(h.has_value());
  REQUIRE(h.value().present().size() == 2);
  CHECK(h.value().present()[0].code == 0x3400);
  CHECK(h.value().present()[1].code == 0x8302);
  // a count the dictionary's range does not allow is refused by the decoder too
  CHECK(dpq::decode_error_history(5, fields).error() == errc::out_of_range);
}
