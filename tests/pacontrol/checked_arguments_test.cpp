// Regression tests of issue 12 #11 and issue 13 ("nothing narrows silently"): every PA-CONTROL
// parameter and date is taken as any integer type and checked against the command table of
// manual 001 (5.2) before a frame is built. Each of these failed before the fix: 65537 was
// sent as PAR_1 = 1, dates outside the printed ranges were sent, the overloads for unsigned /
// long / int64 dates were ambiguous, axis parameters were only range-checked as a whole, and
// operating status 14 (6.4) was unknown.
#if __has_include(<fieldcodec/dictionaries/pacontrol_commands.hpp>)

#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/pacontrol/codes.hpp>
#include <fieldcodec/pacontrol/command.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>

#include "pac_test_util.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <limits>

namespace fc = fieldcodec;
namespace pac = fc::pacontrol;
namespace cmds = fc::dictionaries::pacontrol_commands;
using fc::errc;

namespace {

constexpr pactest::bytes encode(const fc::result<pac::serial::request> &r) {
  pactest::bytes b;
  if (!r) return b;
  std::array<std::uint8_t, pac::serial::max_frame_size> buf{};
  auto n = pac::serial::encode_request(r.value(), buf);
  if (!n) return b;
  for (std::size_t i = 0; i < n.value(); ++i) b.data[b.size++] = buf[i];
  return b;
}
constexpr bool same(const pactest::bytes &a, const pactest::bytes &b) { return a == b.span(); }

// --- PAR_1 never wraps (it was taken as std::uint16_t: 65537 addressed input 1).
static_assert(pac::make_request(cmds::cmd_get_single_input, 65537).error() == errc::out_of_range);
static_assert(pac::make_request(cmds::cmd_get_single_input, 65536U).error() == errc::out_of_range);
static_assert(pac::make_request(cmds::cmd_get_single_input, -1).error() == errc::out_of_range);
static_assert(pac::make_request(cmds::cmd_get_single_input,
                                std::numeric_limits<std::uint64_t>::max())
                  .error() == errc::overflow); // beyond int64: cannot even be compared as such
// No range in the table (1934): the 16-bit field itself refuses.
static_assert(pac::make_request(cmds::cmd_send_system_flag, 65536).error() == errc::overflow);
static_assert(pac::make_request(cmds::cmd_send_system_flag, -1).error() == errc::overflow);
static_assert(pac::make_request(cmds::cmd_send_system_flag, 65535).value().parameter == 65535);
// Commands without a parameter ("--" in 5.2) take only 0.
static_assert(pac::make_request(cmds::cmd_start_online, 1).error() == errc::out_of_range);
static_assert(pac::make_request(cmds::cmd_start_online, 0).has_value());

// --- Any integer type for the date: no ambiguous overloads (12345u, long, int64 did not
// compile), and each gives the frame of the int (5.2.4.11 / 3.4.1: "0906;5;0;12345").
constexpr auto n5 = pactest::frame("0906;5;0;12345", "0");
static_assert(same(encode(pac::make_request(cmds::cmd_put_int_reg, 5, 12345)), n5));
static_assert(same(encode(pac::make_request(cmds::cmd_put_int_reg, 5, 12345U)), n5));
static_assert(same(encode(pac::make_request(cmds::cmd_put_int_reg, 5, 12345L)), n5));
static_assert(same(encode(pac::make_request(cmds::cmd_put_int_reg, 5, 12345UL)), n5));
static_assert(same(encode(pac::make_request(cmds::cmd_put_int_reg, 5, std::int64_t{12345})), n5));
static_assert(same(encode(pac::make_request(cmds::cmd_put_int_reg, 5, std::int16_t{12345})), n5));
static_assert(same(encode(pac::make_request(cmds::cmd_put_int_reg, std::uint8_t{5}, 12345)), n5));
static_assert(same(encode(pac::make_request(cmds::cmd_put_int_reg, 5L, std::uint64_t{12345})), n5));
// ... and checked: beyond int32 is refused, not wrapped.
static_assert(pac::make_request(cmds::cmd_put_int_reg, 5, std::int64_t{1} << 31).error() ==
              errc::overflow);
static_assert(pac::make_request(cmds::cmd_put_int_reg, 5, -(std::int64_t{1} << 31) - 1).error() ==
              errc::overflow);
static_assert(pac::make_request(cmds::cmd_put_int_reg, 5, 4294967295U).error() == errc::overflow);
static_assert(pac::make_request(cmds::cmd_put_int_reg, 5, std::numeric_limits<std::int32_t>::min())
                  .has_value());
// A bool is 0 or 1 (M11 := 1, 5.2.4.7).
static_assert(same(encode(pac::make_request(cmds::cmd_put_single_flag, 11, true)),
                   pactest::frame("0904;11;0;1", "55")));
// A long double date is read as the float it stands for (0A87 to 5552.0, 3.4.3).
static_assert(same(encode(pac::make_request(cmds::cmd_pos_axis_absolut, 2, 5552.0L)),
                   pactest::frame("0A87;2;1;5552.0", "95")));

// --- Dates outside the printed ranges of 5.2 (the device would answer QUIT 41, "value outside
// range", 6.5).
static_assert(pac::make_request(cmds::cmd_put_single_output, 13, 2).error() ==
              errc::out_of_range); // 0902: 0 or 1 (5.2.4.3)
static_assert(pac::make_request(cmds::cmd_put_single_output, 13, 1).has_value());
static_assert(pac::make_request(cmds::cmd_put_single_output, 13, 0).has_value());
static_assert(pac::make_request(cmds::cmd_put_single_flag, 11, -1).error() ==
              errc::out_of_range); // 0904: 0 or 1 (5.2.4.7)
static_assert(pac::make_request(cmds::cmd_put_output_word, 25, 65536).error() ==
              errc::out_of_range); // 0903: 0-65535 (5.2.4.5)
static_assert(pac::make_request(cmds::cmd_put_output_word, 25, 65535).has_value());
static_assert(pac::make_request(cmds::cmd_put_output_word, 25, -1).error() == errc::out_of_range);
static_assert(pac::make_request(cmds::cmd_put_flag_word, 17, 65536).error() ==
              errc::out_of_range); // 0905: 0-65535 (5.2.4.9)
static_assert(pac::make_request(cmds::cmd_put_limit_switch_monitoring_on_off, 1, 2).error() ==
              errc::out_of_range); // 0AA2: 0 off, 1 on (5.2.6.22)
static_assert(pac::make_request(cmds::cmd_put_limit_switch_monitoring_on_off, 0, 1).has_value());
// A value given as a pac::value is checked the same way.
static_assert(pac::make_request(cmds::cmd_put_single_output, 13, pac::value::of_int(2).value())
                  .error() == errc::out_of_range);

// --- Axis parameters (5.2.3): axis 1-16 in the high byte, parameter 1-50 in the low byte
// (QUIT 32 "axis number unknown" / 33 "axis parameter unknown", 6.5). The printed range
// 0101-10FF hex let axis 1 parameter 51 (0133 hex) and every parameter above 50 through.
static_assert(pac::make_request(cmds::cmd_get_axis_parameter, 0x0133).error() ==
              errc::out_of_range);
static_assert(pac::make_request(cmds::cmd_get_axis_parameter, 0x10FF).error() ==
              errc::out_of_range);
static_assert(pac::make_request(cmds::cmd_get_axis_parameter, 0x0100).error() ==
              errc::out_of_range); // parameter 0
static_assert(pac::make_request(cmds::cmd_get_axis_parameter, 0x1101).error() ==
              errc::out_of_range); // axis 17
static_assert(pac::make_request(cmds::cmd_get_axis_parameter, 0x0001).error() ==
              errc::out_of_range);                                                  // axis 0
static_assert(pac::make_request(cmds::cmd_get_axis_parameter, 0x1032).has_value()); // 16, 50
static_assert(pac::make_request(cmds::cmd_get_axis_parameter, 543).value().parameter == 0x021F);
static_assert(pac::make_request(cmds::cmd_set_axis_parameter, 0x0333, 1.0F).error() ==
              errc::out_of_range);
static_assert(pac::make_request(cmds::cmd_get_axis_parameter_max, pac::axis_parameter{17, 1})
                  .error() == errc::out_of_range);
static_assert(pac::make_request(cmds::cmd_get_axis_parameter_min, pac::axis_parameter{4, 51})
                  .error() == errc::out_of_range);
// An axis_parameter where the command does not address one.
static_assert(pac::make_request(cmds::cmd_get_actual_pos, pac::axis_parameter{2, 1}).error() ==
              errc::type_mismatch);

// --- Operating status 14 is listed in 6.4 with an empty text: known, not an error.
static_assert(pac::describe_operating_status(14).has_value());
static_assert(pac::describe_operating_status(4).error() == errc::unknown_object);
static_assert(pac::describe_operating_status(65536 + 31).error() == errc::unknown_object);

} // namespace

TEST_CASE("pacontrol checked arguments: the same checks at run time") {
  // 65537 held in an int (the report of issue 12): refused, not input 1.
  const int wide = 65537;
  CHECK(pac::make_request(cmds::cmd_get_single_input, wide).error() == errc::out_of_range);
  const long par = 5;
  const unsigned date = 12345;
  auto r = pac::make_request(cmds::cmd_put_int_reg, par, date);
  REQUIRE(r);
  CHECK(r->code == 0x0906);
  CHECK(r->parameter == 5);
  CHECK(r->date.as_int().value() == 12345);
  // Dates outside the printed ranges.
  CHECK(pac::make_request(cmds::cmd_put_single_output, 13, 2).error() == errc::out_of_range);
  CHECK(pac::make_request(cmds::cmd_put_single_flag, 11, -1).error() == errc::out_of_range);
  CHECK(pac::make_request(cmds::cmd_put_output_word, 25, 65536).error() == errc::out_of_range);
  CHECK(pac::make_request(cmds::cmd_put_limit_switch_monitoring_on_off, 1, 2).error() ==
        errc::out_of_range);
  CHECK(pac::describe_operating_status(14).has_value());
}

TEST_CASE("pacontrol checked arguments: every table range holds at both ends") {
  for (const auto &c : cmds::table) {
    INFO("command ", c.name);
    const auto lo = c.parameter_min.to_int64();
    const auto hi = c.parameter_max.to_int64();
    const auto make = [&](std::int64_t p) {
      switch (c.date_type) {
      case fc::od::command_value::none: return pac::make_request(c, p);
      case fc::od::command_value::integer:
        return pac::make_request(c, p, c.date_min.to_int64().value_or(0));
      case fc::od::command_value::real: return pac::make_request(c, p, 1.5F);
      }
      return pac::make_request(c, p);
    };
    if (lo) {
      CHECK(make(lo.value()));
      CHECK(make(lo.value() - 1).error() == errc::out_of_range);
    }
    if (hi) {
      CHECK(make(hi.value()));
      CHECK(make(hi.value() + 1).error() == errc::out_of_range);
    }
    CHECK_FALSE(make(65536));
    CHECK_FALSE(make(-1));
    if (c.date_type != fc::od::command_value::integer) continue;
    const auto p = lo.value_or(0);
    if (auto dlo = c.date_min.to_int64()) {
      CHECK(pac::make_request(c, p, dlo.value()));
      CHECK(pac::make_request(c, p, dlo.value() - 1).error() == errc::out_of_range);
    }
    if (auto dhi = c.date_max.to_int64()) {
      CHECK(pac::make_request(c, p, dhi.value()));
      CHECK(pac::make_request(c, p, dhi.value() + 1).error() == errc::out_of_range);
    }
  }
}

TEST_CASE("pacontrol checked arguments: Profibus CMD interface takes the same arguments") {
  pac::profibus::cmd_handshake hs;
  CHECK(pac::start_command(hs, cmds::cmd_get_single_input, 65537).error() == errc::out_of_range);
  CHECK(pac::start_command(hs, cmds::cmd_put_single_output, 13, 2).error() == errc::out_of_range);
  // 0800, axis 3 acceleration 200.0 (5.2.3): 0800 | 0306 | 4348 0000.
  auto req =
      pac::start_command(hs, cmds::cmd_set_axis_parameter, pac::axis_parameter{3, 6}, 200.0F);
  REQUIRE(req);
  CHECK(req->code == 0x0800);
  CHECK(req->parameter == 0x0306);
  CHECK(req->date == 0x43480000U);
  CHECK(hs.update({0x43480000U, false, 1, true, false, true, 0}) ==
        pac::profibus::cmd_progress::done);
  // 0906 N97 := 12589 with an unsigned date (5.2.4.11): 0000 312D.
  req = pac::start_command(hs, cmds::cmd_put_int_reg, 97U, 12589U);
  REQUIRE(req);
  CHECK(req->date == 0x312DU);
  CHECK(req->parameter == 97);
}

#endif
