// DPQ over CANopen: the frames of manual 004, 3.1/3.3/3.4, built from descriptors (dpq/sdo.hpp
// on canopen/), and the DPQ's emergency and abort frames. Where the manual's frame is wrong
// (0x42 request, 2-of-8 data bytes, 4-byte PDO) the correct frame is asserted; see
// docs/errata.md, "Rexroth DPQ (004)", DPQ-F1..F3.
#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/dpq/emergency.hpp>
#include <fieldcodec/dpq/sdo.hpp>
#include <fieldcodec/dpq/sdo_abort.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <initializer_list>

namespace fc = fieldcodec;
namespace co = fieldcodec::canopen;
namespace dpq = fieldcodec::dpq;
namespace od = fieldcodec::od;
using fc::decimal;
using fc::errc;

namespace {
// CiA 301 0x1800 sub 5, event timer of TPDO1, UNSIGNED16 in ms (unscaled).
constexpr od::descriptor event_timer{{.index = 0x1800,
                                      .sub = 5,
                                      .object = od::object_code::record,
                                      .type = od::data_type::unsigned16},
                                     {.name = "Event timer"}};
// 4.100 Inj. P Limit 1.
constexpr od::entry_spec inj_p_limit_1_spec{.index = 0x2023,
                                            .type = od::data_type::unsigned32,
                                            .flags = od::flag::scaled,
                                            .low = od::decimal_number(0, 0),
                                            .high = od::decimal_number(5000, 0)};
constexpr od::descriptor inj_p_limit_1{
    od::entry_of<inj_p_limit_1_spec>, {.name = "Inj. P Limit 1"}, {{32767, 2}, {0, 0}}};
// 4.2 BackP: Decomp Rate 2 (2 bytes, 10.5).
constexpr od::entry_spec decomp_rate_2_spec{.index = 0x219C,
                                            .type = od::data_type::unsigned16,
                                            .flags = od::flag::scaled,
                                            .low = od::decimal_number(0, 0),
                                            .high = od::decimal_number(5000, 0)};
constexpr od::descriptor decomp_rate_2{
    od::entry_of<decomp_rate_2_spec>, {.name = "BackP: Decomp Rate 2"}, {{105, 1}, {0, 0}}};
// 4.168 Position FB : and 4.194 Pressure FB : (read-only, INTEGER32, 327.67).
constexpr od::entry_spec position_fb_spec{.index = 0x2F07,
                                          .type = od::data_type::integer32,
                                          .access_type = od::access::ro,
                                          .flags = od::flag::scaled,
                                          .low = od::decimal_number(0, 0),
                                          .high = od::decimal_number(1000, 0)};
constexpr od::descriptor position_fb{
    od::entry_of<position_fb_spec>, {.name = "Position FB :"}, {{32767, 2}, {0, 0}}};
constexpr od::entry_spec pressure_fb_spec{.index = 0x2F11,
                                          .type = od::data_type::integer32,
                                          .access_type = od::access::ro,
                                          .flags = od::flag::scaled,
                                          .low = od::decimal_number(0, 0),
                                          .high = od::decimal_number(200, 0)};
constexpr od::descriptor pressure_fb{
    od::entry_of<pressure_fb_spec>, {.name = "Pressure FB :"}, {{32767, 2}, {0, 0}}};

constexpr co::can_frame frame8(std::uint16_t id, std::array<std::uint8_t, 8> d) {
  co::can_frame f;
  f.id = id;
  f.dlc = 8;
  f.data = d;
  return f;
}
} // namespace

// The manual's event-timer write and the DPQ parameter write, at compile time.
static_assert(dpq::write_request(5, event_timer, 100.0).value() ==
              frame8(0x605, {0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}));
static_assert(dpq::read_request(5, event_timer).value() ==
              frame8(0x605, {0x40, 0x00, 0x18, 0x05, 0x00, 0x00, 0x00, 0x00}));
static_assert(dpq::write_request(5, inj_p_limit_1, 4.0).value() ==
              frame8(0x605, {0x23, 0x23, 0x20, 0x00, 0x1F, 0x05, 0x00, 0x00}));
static_assert(dpq::read_response(5, inj_p_limit_1,
                                 frame8(0x585, {0x43, 0x23, 0x20, 0x00, 0x1F, 0x05, 0x00, 0x00}))
                  .value()
                  .mantissa == 4001);

namespace {
co::can_frame frame(std::uint16_t id, std::initializer_list<std::uint8_t> bytes) {
  auto f = co::make_frame(id, bytes);
  REQUIRE(f.has_value());
  return f.value();
}
} // namespace

TEST_CASE("dpq frames: event timer of TPDO1 on node 5 = 100 ms (3.4)") {
  // Request as printed: 0x605 2B 00 18 05 64 00 00 00.
  auto req = dpq::write_request(5, event_timer, 100.0);
  REQUIRE(req.has_value());
  CHECK(req.value() == frame(0x605, {0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}));
  CHECK(dpq::write_raw_request(5, event_timer, 100).value() == req.value());
  // Reply as printed: 0x585 60 00 18 05 00 00 00 00.
  const auto reply = frame(0x585, {0x60, 0x00, 0x18, 0x05, 0x00, 0x00, 0x00, 0x00});
  CHECK(co::sdo::channel::default_for(5).value().response(
            co::sdo::download_response({0x1800, 5})) == reply);
  CHECK(dpq::write_response(5, event_timer, reply).has_value());
  // "The contents of the data bytes are arbitrary and must be ignored by the control."
  CHECK(dpq::write_response(5, event_timer,
                            frame(0x585, {0x60, 0x00, 0x18, 0x05, 0xAA, 0xBB, 0xCC, 0xDD}))
            .has_value());
}

TEST_CASE("dpq frames: read-back of the event timer (3.4, errata DPQ-F1/F2)") {
  // The manual prints command 0x42 for the request; an upload request is 0x40.
  auto req = dpq::read_request(5, event_timer);
  REQUIRE(req.has_value());
  CHECK(req.value() == frame(0x605, {0x40, 0x00, 0x18, 0x05, 0x00, 0x00, 0x00, 0x00}));
  CHECK(req.value().data[0] != 0x42);
  // The reply has 8 bytes: 4B 00 18 05 64 00 00 00 (the manual shows only "64 00").
  const auto reply = frame(0x585, {0x4B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00});
  const std::array<std::uint8_t, 2> value{0x64, 0x00};
  CHECK(co::sdo::channel::default_for(5).value().response(
            co::sdo::expedited_upload_response({0x1800, 5}, value)) == reply);
  CHECK(dpq::read_raw_response(5, event_timer, reply).value() == 100);
  CHECK(dpq::read_response(5, event_timer, reply).value().mantissa == 100);
  // The frame exactly as printed (6 bytes) is refused.
  const auto printed = frame(0x585, {0x4B, 0x00, 0x18, 0x05, 0x64, 0x00});
  CHECK(dpq::read_raw_response(5, event_timer, printed).error() == errc::bad_length);
}

TEST_CASE("dpq frames: NMT start of node 5 (3.4) and the other NMT commands (3.1)") {
  CHECK(co::nmt::encode(co::nmt::command::start, 5).value() == frame(0x000, {0x01, 0x05}));
  CHECK(co::nmt::encode(co::nmt::command::enter_pre_operational, 5).value() ==
        frame(0x000, {0x80, 0x05}));
  CHECK(co::nmt::encode(co::nmt::command::reset_node, 0).value() == frame(0x000, {0x81, 0x00}));
  CHECK(co::nmt::encode(co::nmt::command::reset_communication, 5).value() ==
        frame(0x000, {0x82, 0x05}));
}

TEST_CASE("dpq frames: write and read a DPQ parameter by descriptor") {
  // Inj. P Limit 1 = 4.0 bar on node 5: 4 bytes → command 0x23, 1F 05 00 00.
  auto w = dpq::write_request(5, inj_p_limit_1, 4.0);
  REQUIRE(w.has_value());
  CHECK(w.value() == frame(0x605, {0x23, 0x23, 0x20, 0x00, 0x1F, 0x05, 0x00, 0x00}));
  CHECK(dpq::write_response(5, inj_p_limit_1, frame(0x585, {0x60, 0x23, 0x20, 0x00, 0, 0, 0, 0}))
            .has_value());
  CHECK(dpq::read_request(5, inj_p_limit_1).value() ==
        frame(0x605, {0x40, 0x23, 0x20, 0x00, 0, 0, 0, 0}));
  const auto reply = frame(0x585, {0x43, 0x23, 0x20, 0x00, 0x1F, 0x05, 0x00, 0x00});
  auto eu = dpq::read_response(5, inj_p_limit_1, reply);
  REQUIRE(eu.has_value());
  CHECK(eu.value().mantissa == 4001);
  CHECK(eu.value().places == 3);
  // Unsized expedited reply (0x42): the 4 data bytes are the value.
  CHECK(dpq::read_raw_response(5, inj_p_limit_1,
                               frame(0x585, {0x42, 0x23, 0x20, 0x00, 0x1F, 0x05, 0x00, 0x00}))
            .value() == 1311);
  // A 2-byte parameter: 100 × 10.5 = 1050 = 0x041A, command 0x2B.
  CHECK(dpq::write_request(5, decomp_rate_2, decimal{100, 0}).value() ==
        frame(0x605, {0x2B, 0x9C, 0x21, 0x00, 0x1A, 0x04, 0x00, 0x00}));
  CHECK(dpq::read_raw_response(5, decomp_rate_2,
                               frame(0x585, {0x4B, 0x9C, 0x21, 0x00, 0x1A, 0x04, 0x00, 0x00}))
            .value() == 1050);
  // 52500 (EU 5000) uses the full UNSIGNED16: 14 CD.
  CHECK(dpq::write_request(5, decomp_rate_2, 5000.0).value() ==
        frame(0x605, {0x2B, 0x9C, 0x21, 0x00, 0x14, 0xCD, 0x00, 0x00}));
}

TEST_CASE("dpq frames: refusals and mismatches") {
  CHECK(dpq::write_request(5, inj_p_limit_1, 5000.5).error() == errc::out_of_range);
  CHECK(dpq::write_request(5, position_fb, 1.0).error() == errc::access_denied);
  CHECK(dpq::write_raw_request(5, position_fb, 1).error() == errc::access_denied);
  CHECK(dpq::write_request(0, inj_p_limit_1, 4.0).error() == errc::invalid_argument);
  CHECK(dpq::write_request(128, inj_p_limit_1, 4.0).error() == errc::invalid_argument);
  CHECK(dpq::read_request(0, inj_p_limit_1).error() == errc::invalid_argument);
  const auto reply = frame(0x585, {0x43, 0x23, 0x20, 0x00, 0x1F, 0x05, 0x00, 0x00});
  // Another node, another object, the request direction, wrong size, wrong kind.
  CHECK(dpq::read_response(6, inj_p_limit_1, reply).error() == errc::unexpected_frame);
  CHECK(dpq::read_response(5, decomp_rate_2, reply).error() == errc::unexpected_frame);
  CHECK(dpq::read_response(5, inj_p_limit_1,
                           frame(0x605, {0x43, 0x23, 0x20, 0x00, 0x1F, 0x05, 0x00, 0x00}))
            .error() == errc::unexpected_frame);
  CHECK(dpq::read_response(5, inj_p_limit_1,
                           frame(0x585, {0x4B, 0x23, 0x20, 0x00, 0x1F, 0x05, 0x00, 0x00}))
            .error() == errc::bad_length);
  CHECK(dpq::read_response(5, inj_p_limit_1, frame(0x585, {0x60, 0x23, 0x20, 0x00, 0, 0, 0, 0}))
            .error() == errc::unexpected_frame);
  CHECK(dpq::write_response(5, inj_p_limit_1, reply).error() == errc::unexpected_frame);
  CHECK(dpq::read_response(5, inj_p_limit_1,
                           frame(0x585, {0x41, 0x23, 0x20, 0x00, 0x04, 0x00, 0x00, 0x00}))
            .error() == errc::unexpected_frame); // segmented
}

TEST_CASE("dpq frames: an abort from the card (3.3 table)") {
  // "Default value too great" for Inj. P Limit 1 on node 5: 80 23 20 00 | 31 00 09 06.
  const auto f = frame(0x585, {0x80, 0x23, 0x20, 0x00, 0x31, 0x00, 0x09, 0x06});
  CHECK(dpq::write_response(5, inj_p_limit_1, f).error() == errc::aborted);
  CHECK(dpq::read_response(5, inj_p_limit_1, f).error() == errc::aborted);
  // The abort code, its text and the object are kept in the error.
  const dpq::sdo_error w = dpq::write_response(5, inj_p_limit_1, f).error();
  CHECK(w.code == errc::aborted);
  CHECK(w.abort == co::sdo::abort_code::value_too_high);
  CHECK(w.address == od::address{0x2023, 0});
  CHECK(w.text() == co::sdo::to_string(co::sdo::abort_code::value_too_high));
  CHECK(w.text() == "value too high (download only)");
  CHECK(w.cause() == errc::out_of_range);
  CHECK(dpq::read_raw_response(5, inj_p_limit_1, f).error() == w);
  CHECK(dpq::read_response(5, inj_p_limit_1, f).error() == w);
  // A code CiA 301 does not define is kept as sent, with no text and cause aborted.
  const auto odd = frame(0x585, {0x80, 0x23, 0x20, 0x00, 0x78, 0x56, 0x34, 0x12});
  const dpq::sdo_error o = dpq::read_response(5, inj_p_limit_1, odd).error();
  CHECK(static_cast<std::uint32_t>(o.abort) == 0x12345678U);
  CHECK(o.text().empty());
  CHECK(o.cause() == errc::aborted);
  // An abort for another object is a wrong frame, not this object's abort.
  const auto other = frame(0x585, {0x80, 0x24, 0x20, 0x00, 0x31, 0x00, 0x09, 0x06});
  const dpq::sdo_error u = dpq::write_response(5, inj_p_limit_1, other).error();
  CHECK(u.code == errc::unexpected_frame);
  CHECK(u.abort == co::sdo::abort_code::none);
  CHECK(u.text() == "no abort");
  CHECK(u.cause() == errc::unexpected_frame);
  // Every row of the DPQ table arrives with its code and the shared table's meaning.
  for (const auto &row : dpq::sdo_abort_table) {
    const auto a = co::sdo::abort({0x2023, 0}, row.code);
    const co::can_frame fr{0x585, false, 8, a};
    const dpq::sdo_error e = dpq::read_response(5, inj_p_limit_1, fr).error();
    CHECK(e.abort == row.code);
    CHECK(e.cause() == row.error());
    CHECK(e.text() == row.cia_text());
  }
  auto m = co::sdo::decode(f, co::sdo::direction::to_client);
  REQUIRE(m.has_value());
  CHECK(m.value().abort == co::sdo::abort_code::value_too_high);
  CHECK(dpq::describe_sdo_abort(m.value().abort) == "value too large");
  CHECK(dpq::sdo_abort_errc(m.value().abort) == errc::out_of_range);
  // Every row of the table, framed by the generic encoder, decodes to the same code.
  for (const auto &row : dpq::sdo_abort_table) {
    const auto a = co::sdo::abort({0x2023, 0}, row.code);
    CHECK(a[4] == static_cast<std::uint8_t>(row.additional & 0xFFU));
    CHECK(a[5] == static_cast<std::uint8_t>(row.additional >> 8U));
    CHECK(a[6] == row.error_code);
    CHECK(a[7] == row.error_class);
    CHECK(co::sdo::is_known(row.code)); // all 16 are CiA 301 codes
  }
}

TEST_CASE("dpq frames: emergency of node 5 (3.5)") {
  // Pressure monitor error, register: generic + manufacturer bit as an example.
  const auto f = frame(0x085, {0x02, 0x83, 0x81, 0, 0, 0, 0, 0});
  auto e = co::emcy::decode(f);
  REQUIRE(e.has_value());
  CHECK(e.value().node == 5);
  CHECK(e.value().m.error_code == 0x8302);
  CHECK(dpq::describe_emcy(e.value().m.error_code) == "pressure monitor tripped");
  std::array<std::string_view, 8> bits{};
  REQUIRE(dpq::error_register::describe(e.value().m.error_register, bits) == 2);
  CHECK(bits[0] == "generic error");
  CHECK(bits[1] == "manufacturer-specific");
  // "No-error telegram" once everything is cleared.
  auto clear = co::emcy::decode(frame(0x085, {0, 0, 0, 0, 0, 0, 0, 0}));
  REQUIRE(clear.has_value());
  CHECK(dpq::describe_emcy(clear.value().m.error_code) == "no error (all errors cleared)");
}

TEST_CASE("dpq frames: a TPDO1 of the 3.4 example (errata DPQ-F3)") {
  // The example's first 8 transmit bytes: Position FB (4) + Pressure FB (4). 0x185 carries 8
  // bytes; 100.0 mm = 32767 = FF 7F 00 00, 50.0 bar = 16383.5 → 16384 = 00 40 00 00.
  const auto f = frame(0x185, {0xFF, 0x7F, 0x00, 0x00, 0x00, 0x40, 0x00, 0x00});
  const auto data = f.payload();
  CHECK(dpq::from_bytes(position_fb, data.first(4)).value().mantissa == 100000);
  CHECK(dpq::from_bytes(pressure_fb, data.subspan(4, 4)).value().mantissa == 50002); // 50.002
  // The manual's frame has 4 bytes: the second mapped value is missing.
  const auto printed = frame(0x185, {0x00, 0x12, 0x23, 0x11});
  CHECK(printed.payload().size() == 4);
  CHECK(dpq::from_bytes(pressure_fb, printed.payload().subspan(4)).error() == errc::truncated);
  // Its first four bytes as Position FB would be raw 0x11231200 = 287 511 040, far outside
  // 0…1000 mm (≈ 877 435 mm): the printed bytes are placeholders.
  CHECK(dpq::raw_from_bytes(position_fb, printed.payload()).value() == 0x11231200);
}
