// PA-CONTROL Profibus-DP / Interbus-S interfaces (manual 001, 2.3-2.7 and 4.2): CMD with the
// SEND/RECEIVE handshake, CTRL with its active-low bits, module/axis blocks.
#include <fieldcodec/pacontrol/profibus_axis.hpp>
#include <fieldcodec/pacontrol/profibus_cmd.hpp>
#include <fieldcodec/pacontrol/profibus_ctrl.hpp>

#include "pac_test_util.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <limits>

namespace fc = fieldcodec;
namespace pb = fc::pacontrol::profibus;
using fc::errc;
using fc::pacontrol::position_format;
using pactest::hex;

namespace {

template <std::size_t N>
constexpr bool same(const std::array<std::uint8_t, N> &a, const pactest::bytes &b) {
  return b == std::span<const std::uint8_t>(a);
}

// 4.2.4 Interbus example (l. 1742-1751). Requests as printed (staged, then toggled).
constexpr pb::cmd_request in5_staged{0, 5, 0x1900, false};
constexpr pb::cmd_request in5{0, 5, 0x1900, true};
constexpr pb::cmd_request n2_staged{0, 2, 0x1906, true};
constexpr pb::cmd_request n2{0, 2, 0x1906, false};
constexpr pb::cmd_request n3_staged{333, 3, 0x0906, false};
constexpr pb::cmd_request n3{333, 3, 0x0906, true};
constexpr pb::cmd_request r1_staged{0, 1, 0x1907, true};
constexpr pb::cmd_request r1{0, 1, 0x1907, false};
static_assert(same(pb::encode_cmd_request(in5_staged).value(), hex("00 00 00 00 00 05 19 00")));
static_assert(same(pb::encode_cmd_request(in5).value(), hex("00 00 00 00 00 05 99 00")));
static_assert(same(pb::encode_cmd_request(n2_staged).value(), hex("00 00 00 00 00 02 99 06")));
static_assert(same(pb::encode_cmd_request(n2).value(), hex("00 00 00 00 00 02 19 06")));
static_assert(same(pb::encode_cmd_request(n3_staged).value(), hex("00 00 01 4D 00 03 09 06")));
static_assert(same(pb::encode_cmd_request(n3).value(), hex("00 00 01 4D 00 03 89 06")));
static_assert(same(pb::encode_cmd_request(r1_staged).value(), hex("00 00 00 00 00 01 99 07")));
static_assert(same(pb::encode_cmd_request(r1).value(), hex("00 00 00 00 00 01 19 07")));

// Replies. Input 5 = 1 and N3 = 333 are printed correctly (RF 1, BF 1 → A0 00).
constexpr pb::cmd_reply in5_reply{1, false, 1, true, false, true, 0};
constexpr pb::cmd_reply n3_reply{333, false, 1, true, false, true, 0};
static_assert(same(pb::encode_cmd_reply(in5_reply).value(), hex("00 00 00 01 00 01 A0 00")));
static_assert(same(pb::encode_cmd_reply(n3_reply).value(), hex("00 00 01 4D 00 01 A0 00")));
// N2 = 12345678 and R1 = 640.0 are printed with word 3 = 02 00 (bit 9) and R1 as 4420 2000
// (= 640.5): errata "Other examples" (l. 1747, 1751) and the IEEE table. End of processing is
// bit 13 and RF is 0 after the toggle to 0: 20 00.
constexpr pb::cmd_reply n2_reply{12345678, false, 1, false, false, true, 0};
constexpr pb::cmd_reply r1_reply{0x44200000U, false, 1, false, false, true, 0};
static_assert(same(pb::encode_cmd_reply(n2_reply).value(), hex("00 BC 61 4E 00 01 20 00")));
static_assert(same(pb::encode_cmd_reply(r1_reply).value(), hex("44 20 00 00 00 01 20 00")));
static_assert(pb::date_from_float(640.0F).value() == 0x44200000U);

} // namespace

TEST_CASE("pacontrol CMD: Interbus example 4.2.4 decodes") {
  CHECK(pb::decode_cmd_request(hex("00 00 01 4D 00 03 89 06").span()).value() == n3);
  CHECK(pb::decode_cmd_reply(hex("00 00 00 01 00 01 A0 00").span()).value() == in5_reply);
  CHECK(pb::decode_cmd_reply(hex("00 BC 61 4E 00 01 20 00").span()).value() == n2_reply);
  CHECK(pb::date_as_int(pb::decode_cmd_reply(hex("00 BC 61 4E 00 01 20 00").span())->date) ==
        12345678);
  auto r1r = pb::decode_cmd_reply(hex("44 20 00 00 00 01 20 00").span());
  REQUIRE(r1r);
  CHECK(pb::date_as_float(r1r->date).value() == 640.0F);
  // As printed: bit 9 is not a defined flag, so the reply reads "not finished", and the date
  // is 640.5.
  auto printed = pb::decode_cmd_reply(hex("44 20 20 00 00 01 02 00").span());
  REQUIRE(printed);
  CHECK_FALSE(printed->end_of_processing);
  CHECK(printed->command_error_number == 0x0200);
  CHECK(pb::date_as_float(printed->date).value() == 640.5F);
}

TEST_CASE("pacontrol CMD: fields at their limits and bad input") {
  const pb::cmd_request all{0xFFFFFFFFU, 0xFFFF, 0x7FFF, true};
  CHECK(same(pb::encode_cmd_request(all).value(), hex("FF FF FF FF FF FF FF FF")));
  CHECK(pb::decode_cmd_request(hex("FF FF FF FF FF FF FF FF").span()).value() == all);
  CHECK(pb::encode_cmd_request({0, 0, 0x8000, false}).error() == errc::overflow);
  const pb::cmd_reply full{0x80000000U, true, 0xFF, true, true, true, 0x1FFF};
  CHECK(same(pb::encode_cmd_reply(full).value(), hex("80 00 00 00 80 FF FF FF")));
  CHECK(pb::decode_cmd_reply(hex("80 00 00 00 80 FF FF FF").span()).value() == full);
  CHECK(pb::encode_cmd_reply({0, false, 0, false, false, false, 0x2000}).error() == errc::overflow);
  // Unused bits 14-8 of word 2 are ignored.
  CHECK(pb::decode_cmd_reply(hex("00 00 00 00 7F 1F 00 00").span())->operating_status == 0x1F);
  CHECK_FALSE(pb::decode_cmd_reply(hex("00 00 00 00 7F 1F 00 00").span())->controller_error);
  // Command error 19 (unknown command) with RF 1 and KF 1: word 3 = C0 13.
  auto err = pb::decode_cmd_reply(hex("00 00 00 00 00 01 C0 13").span());
  REQUIRE(err);
  CHECK(err->command_error);
  CHECK(err->command_error_number == 19);
  CHECK(pb::decode_cmd_reply(hex("00 00 00 00 00 01 C0").span()).error() == errc::truncated);
  CHECK(pb::decode_cmd_request(hex("").span()).error() == errc::truncated);
  CHECK(pb::date_from_float(std::numeric_limits<float>::quiet_NaN()).error() ==
        errc::not_representable);
  CHECK(pb::date_from_float(-std::numeric_limits<float>::infinity()).error() ==
        errc::not_representable);
  CHECK(pb::date_as_float(0x7FC00000U).error() == errc::not_representable);
  CHECK(pb::date_from_int(-1).value() == 0xFFFFFFFFU);
  CHECK(pb::date_from_int(std::int64_t{1} << 31).error() == errc::overflow);
  CHECK(pb::date_from_int(-2147483648LL).value() == 0x80000000U);
  CHECK(pb::date_from_float(640.0).value() == 0x44200000U); // a double: its nearest float
  CHECK(pb::date_from_float(1.0e39).error() == errc::not_representable);
  CHECK(pb::raw_date(0xFFFFFFFFU).value() == 0xFFFFFFFFU);
  CHECK(pb::raw_date(-1).value() == 0xFFFFFFFFU);
  CHECK(pb::raw_date(std::int64_t{1} << 32).error() == errc::overflow);
  CHECK(pb::raw_date(-(std::int64_t{1} << 31) - 1).error() == errc::overflow);
  CHECK(pb::date_as_int(0x80000000U) == std::numeric_limits<std::int32_t>::min());
}

TEST_CASE("pacontrol CMD: handshake (acknowledgement mechanism 2.4)") {
  pb::cmd_handshake hs;
  const pb::cmd_reply quiet{};
  CHECK(hs.update(quiet) == pb::cmd_progress::idle);
  // Read input 5: the staged image keeps SF, start() toggles it.
  CHECK(hs.stage(0x1900, 5, 0).value() == in5_staged);
  CHECK(hs.stage(0x8000, 5, 0).error() == errc::overflow);
  auto req = hs.start(0x1900, 5, 0);
  REQUIRE(req);
  CHECK(req.value() == in5);
  // A second start before the device saw the first would undo the toggle.
  CHECK(hs.start(0x1906, 2, 0).error() == errc::bad_state);
  CHECK(hs.update(quiet) == pb::cmd_progress::waiting);  // SF 1, RF 0
  CHECK(hs.update(in5_reply) == pb::cmd_progress::done); // RF 1, BF 1
  CHECK(hs.update(in5_reply) == pb::cmd_progress::done); // stays done
  // Read N2: SF back to 0.
  req = hs.start(0x1906, 2, 0);
  REQUIRE(req);
  CHECK(req.value() == n2);
  CHECK(hs.update(in5_reply) == pb::cmd_progress::waiting); // old reply, RF still 1
  CHECK(hs.update(n2_reply) == pb::cmd_progress::done);
  // A traverse: running until BF; then a command error.
  req = hs.start(0x0A87, 2, pb::date_from_float(200.0F).value());
  REQUIRE(req);
  CHECK(same(pb::encode_cmd_request(req.value()).value(), hex("43 48 00 00 00 02 8A 87")));
  pb::cmd_reply moving{0x449CE666U, false, 31, true, false, false, 0};
  CHECK(hs.update(moving) == pb::cmd_progress::running);
  moving.end_of_processing = true;
  CHECK(hs.update(moving) == pb::cmd_progress::done);
  req = hs.start(0x1999, 0, 0);
  REQUIRE(req);
  const pb::cmd_reply unknown{0, false, 31, false, true, false, 19};
  CHECK(hs.update(unknown) == pb::cmd_progress::failed);
  CHECK(hs.start(0x8000, 0, 0).error() == errc::overflow);
  // Any integer types, checked, never wrapped; a refused start does not toggle.
  CHECK(hs.start(-1, 0, 0).error() == errc::overflow);
  CHECK(hs.start(0x1906, 65536, 0).error() == errc::overflow);
  CHECK(hs.start(0x1906, -1, 0).error() == errc::overflow);
  CHECK(hs.start(0x1906, 2, std::int64_t{1} << 32).error() == errc::overflow);
  CHECK(hs.stage(0x1906U, std::uint8_t{2}, -1).value().date == 0xFFFFFFFFU);
  CHECK(hs.send_flag() == false);
}

TEST_CASE("pacontrol CMD: handshake after a master restart") {
  // The device still shows RF = 1 from an earlier session; a fresh master with SF = 0 that
  // toggled to 1 would find RF = SF at once and take a stale reply for the result.
  pb::cmd_handshake hs;
  const pb::cmd_reply stale{1, false, 1, true, false, true, 0};
  CHECK(hs.update(stale) == pb::cmd_progress::idle);
  CHECK(hs.start(0x1900, 5, 0).error() == errc::bad_state);
  hs.synchronize(stale);
  CHECK(hs.send_flag());
  auto req = hs.start(0x1900, 5, 0);
  REQUIRE(req);
  CHECK_FALSE(req->send_flag);
  CHECK(hs.update(stale) == pb::cmd_progress::waiting);
}

// --- CTRL (2.5) ---
static_assert(pb::control_word({}) == 0x0007); // quiet: all active-low bits at 1
static_assert(pb::control_word({false, false, false, true, false, false}) == 0x0003); // cancel
static_assert(pb::control_word({false, false, false, false, true, false}) == 0x0005); // stop
static_assert(pb::control_word({false, false, false, false, false, true}) == 0x0006); // reset
static_assert(pb::control_word({true, true, false, false, false, false}) == 0x8017);
static_assert(pb::control_word({false, false, true, false, false, false}) == 0x000F);

TEST_CASE("pacontrol CTRL: control and status words") {
  pb::ctrl_command c{};
  c.integer_positions = true;
  c.start_online = true;
  CHECK(same(pb::encode_ctrl_command(c), hex("80 17 00 00 00 00 00 00")));
  CHECK(c.format() == position_format::milli_integer);
  CHECK(pb::decode_ctrl_command(hex("80 17 00 00 00 00 00 00").span()).value() == c);
  // All zeros on the wire = cancel, stop and error reset all asserted.
  const auto z = pb::decode_ctrl_command(hex("00 00 00 00 00 00 00 00").span()).value();
  CHECK(z.cancel);
  CHECK(z.stop);
  CHECK(z.reset_error);
  CHECK(z.format() == position_format::ieee_float);
  for (unsigned w = 0; w <= 0xFFFFU; ++w) {
    const auto word = static_cast<std::uint16_t>(w);
    REQUIRE(pb::control_word(pb::from_control_word(word)) ==
            (word & static_cast<std::uint16_t>(0x801FU)));
    REQUIRE(pb::status_word(pb::from_status_word(word)) ==
            (word & static_cast<std::uint16_t>(0x8F07U)));
  }
  // Status: ONLINE active, ready, battery ok, integer mode.
  const auto s = pb::decode_ctrl_status(hex("84 03 00 00 00 00 00 00").span()).value();
  CHECK(s.integer_positions);
  CHECK(s.online_active);
  CHECK_FALSE(s.online_stopped);
  CHECK(s.battery_ok);
  CHECK(s.ready);
  CHECK_FALSE(s.system_error);
  CHECK(s.format() == position_format::milli_integer);
  CHECK(same(pb::encode_ctrl_status(s), hex("84 03 00 00 00 00 00 00")));
  CHECK(pb::decode_ctrl_status(hex("84 03 00").span()).error() == errc::truncated);
  CHECK(pb::decode_ctrl_command(hex("80").span()).error() == errc::truncated);
}

// --- Module/axis blocks (2.6, 2.7) ---
TEST_CASE("pacontrol axis block, ONLINE mode") {
  namespace ac = pb::axis_control;
  const pb::axis_command go{ac::axis_on | ac::start | ac::absolute, 500, 1000, 5552.0F};
  CHECK(same(pb::encode_axis_command(go, position_format::ieee_float).value(),
             hex("00 00 00 45 01 F4 03 E8 45 AD 80 00")));
  CHECK(same(pb::encode_axis_command(go, position_format::milli_integer).value(),
             hex("00 00 00 45 01 F4 03 E8 00 54 B7 80")));
  CHECK(pb::decode_axis_command(hex("00 00 00 45 01 F4 03 E8 00 54 B7 80").span(),
                                position_format::milli_integer)
            .value() == go);
  pb::axis_command bad = go;
  bad.control |= 1U << 18U;
  CHECK(pb::encode_axis_command(bad, position_format::ieee_float).error() ==
        errc::invalid_argument);
  bad = go;
  bad.acceleration = 0;
  CHECK(pb::encode_axis_command(bad, position_format::ieee_float).error() == errc::out_of_range);
  bad = go;
  bad.speed = 0;
  CHECK(pb::encode_axis_command(bad, position_format::ieee_float).error() == errc::out_of_range);
  bad.speed = 1001;
  CHECK(pb::encode_axis_command(bad, position_format::ieee_float).error() == errc::out_of_range);
  bad = go;
  bad.acceleration = 65535;
  CHECK(pb::encode_axis_command(bad, position_format::ieee_float));
  bad.target = std::numeric_limits<float>::quiet_NaN();
  CHECK(pb::encode_axis_command(bad, position_format::ieee_float).error() ==
        errc::not_representable);
  bad.target = 3.0e6F;
  CHECK(pb::encode_axis_command(bad, position_format::milli_integer).error() == errc::overflow);
  CHECK(pb::encode_axis_command(bad, position_format::ieee_float));
  CHECK(pb::decode_axis_command(hex("00 00 00 45 01 F4 03 E8 7F C0 00 00").span(),
                                position_format::ieee_float)
            .error() == errc::not_representable);
  CHECK(pb::decode_axis_command(hex("00 00 00 45 01 F4 03 E8 7F C0 00").span(),
                                position_format::ieee_float)
            .error() == errc::truncated);
}

TEST_CASE("pacontrol axis status, active-low limit switches") {
  namespace as = pb::axis_state;
  // Enabled, referenced, both limit switches not actuated (bits 9, 10 = 1), at 1516.95.
  const auto st = pb::decode_axis_status(hex("00 00 07 81 00 00 00 00 44 BD 9E 66").span(),
                                         position_format::ieee_float);
  REQUIRE(st);
  CHECK(st->has(as::drive_enabled | as::referenced | as::active));
  CHECK_FALSE(st->negative_limit_actuated());
  CHECK_FALSE(st->positive_limit_actuated());
  CHECK(st->position == 1516.95F);
  // Positive limit switch actuated (bit 10 = 0), axis error 529, CMD error 43.
  const auto lim = pb::decode_axis_status(hex("00 00 C3 41 00 2B 02 11 00 54 B7 80").span(),
                                          position_format::milli_integer);
  REQUIRE(lim);
  CHECK(lim->positive_limit_actuated());
  CHECK_FALSE(lim->negative_limit_actuated());
  CHECK(lim->has(as::axis_error | as::command_error | as::fault));
  CHECK(lim->command_error_number == 43);
  CHECK(lim->axis_error_number == 529);
  CHECK(lim->position == 5552.0F);
  CHECK(same(pb::encode_axis_status(lim.value(), position_format::milli_integer).value(),
             hex("00 00 C3 41 00 2B 02 11 00 54 B7 80")));
  CHECK(pb::decode_axis_status(hex("00 00 C3 41 00 2B 02 11 7F 80 00 00").span(),
                               position_format::ieee_float)
            .error() == errc::not_representable);
  CHECK(pb::decode_axis_status(hex("00 00 C3 41").span(), position_format::ieee_float).error() ==
        errc::truncated);
}

TEST_CASE("pacontrol flag/register module, AUTOMATIC mode") {
  const pb::flag_module m{0x8001, -2, 12.345F};
  CHECK(same(pb::encode_flag_module(m, position_format::milli_integer).value(),
             hex("80 01 00 00 FF FF FF FE 00 00 30 39")));
  CHECK(same(
      pb::encode_flag_module(m, position_format::ieee_float, pb::module_layout::as_printed).value(),
      hex("00 00 80 01 00 00 FF FE 41 45 85 1F")));
  CHECK(pb::decode_flag_module(hex("80 01 00 00 FF FF FF FE 00 00 30 39").span(),
                               position_format::milli_integer)
            .value() == m);
  CHECK(pb::decode_flag_module(hex("00 00 80 01 00 00 FF FE 41 45 85 1F").span(),
                               position_format::ieee_float, pb::module_layout::as_printed)
            .value() == m);
  const pb::flag_module big{0, 40000, 0.0F};
  CHECK(pb::encode_flag_module(big, position_format::ieee_float, pb::module_layout::as_printed)
            .error() == errc::overflow);
  CHECK(pb::encode_flag_module(big, position_format::ieee_float));
  CHECK(pb::decode_flag_module(hex("80 01").span(), position_format::ieee_float).error() ==
        errc::truncated);
}

TEST_CASE("pacontrol process image layout (2.3)") {
  CHECK(pb::image_size(false, 0).value() == 8);
  CHECK(pb::image_size(true, 0).value() == 16);
  CHECK(pb::image_size(true, 1).value() == 28);
  CHECK(pb::image_size(true, 8).value() == 112);
  CHECK(pb::image_size(true, 9).error() == errc::out_of_range);
  CHECK(pb::image_size(false, 1).error() == errc::invalid_argument);
  CHECK(pb::module_offset(0).value() == 16);
  CHECK(pb::module_offset(7).value() == 100);
  CHECK(pb::module_offset(8).error() == errc::out_of_range);
}
