// The typed builder over the generated PA-CONTROL command table
// (dictionaries/pacontrol_commands.csv → <fieldcodec/dictionaries/pacontrol_commands.hpp>).
// Compiled only once the generated header exists.
#if __has_include(<fieldcodec/dictionaries/pacontrol_commands.hpp>)

#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/pacontrol/command.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>

#include "pac_test_util.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstdint>

namespace fc = fieldcodec;
namespace pac = fc::pacontrol;
namespace cmds = fc::dictionaries::pacontrol_commands;
using fc::errc;
using fc::od::command_value;

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

// The seven requests of manual 001, 3.4, from the generated table (corrected bytes).
static_assert(same(encode(pac::make_request(cmds::cmd_put_int_reg, 5, 12345)),
                   pactest::frame("0906;5;0;12345", "0")));
static_assert(same(encode(pac::make_request(cmds::cmd_get_single_input, 5)),
                   pactest::frame("1900;5;0;0", "6")));
static_assert(same(encode(pac::make_request(cmds::cmd_get_int_reg, 2)),
                   pactest::frame("1906;2;0;0", "7")));
static_assert(same(encode(pac::make_request(cmds::cmd_put_int_reg, 3, 333)),
                   pactest::frame("0906;3;0;333", "4")));
static_assert(same(encode(pac::make_request(cmds::cmd_get_float_reg, 1)),
                   pactest::frame("1907;1;1;0", "4")));
static_assert(same(encode(pac::make_request(cmds::cmd_start_online)),
                   pactest::frame("0603;0;0;0", "14")));
static_assert(same(encode(pac::make_request(cmds::cmd_pos_axis_absolut, 2, 5552.0F)),
                   pactest::frame("0A87;2;1;5552.0", "95")));
// A float where an integer belongs, and the reverse.
static_assert(pac::make_request(cmds::cmd_put_int_reg, 5, 12345.0F).error() == errc::type_mismatch);
static_assert(pac::make_request(cmds::cmd_pos_axis_absolut, 2, 5552).error() ==
              errc::type_mismatch);

} // namespace

TEST_CASE("pacontrol command table: every command builds with its own type only") {
  CHECK(cmds::commands.size() == 66);
  std::size_t built = 0;
  for (const auto &c : cmds::table) {
    INFO("command ", c.name);
    const auto par = c.parameter_min.to_int64().value_or(0);
    std::array<std::uint8_t, pac::serial::max_frame_size> buf{};
    fc::result<pac::serial::request> r = errc::truncated;
    switch (c.date_type) {
    case command_value::none:
      r = pac::make_request(c, par);
      CHECK(pac::make_request(c, par, 1).error() == errc::type_mismatch);
      CHECK(pac::make_request(c, par, 1.0F).error() == errc::type_mismatch);
      break;
    case command_value::integer:
      r = pac::make_request(c, par, c.date_max.to_int64().value_or(-7));
      CHECK(pac::make_request(c, par, 1.5F).error() == errc::type_mismatch);
      CHECK(pac::make_request(c, par).error() == errc::type_mismatch);
      break;
    case command_value::real:
      r = pac::make_request(c, par, -7.25F);
      CHECK(pac::make_request(c, par, 7).error() == errc::type_mismatch);
      CHECK(pac::make_request(c, par).error() == errc::type_mismatch);
      break;
    }
    REQUIRE(r);
    auto n = pac::serial::encode_request(r.value(), buf);
    REQUIRE(n);
    auto d = pac::serial::decode_frame(std::span<const std::uint8_t>(buf.data(), n.value()));
    REQUIRE(d);
    CHECK(d.value().req == r.value());
    CHECK(d.value().req.date.type == pac::request_date_type(c));
    if (auto hi = c.parameter_max.to_int64(); hi && hi.value() < 65535) {
      CHECK(pac::make_request(c, hi.value() + 1).error() ==
            (c.date_type == command_value::none ? errc::out_of_range : errc::type_mismatch));
    }
    ++built;
  }
  CHECK(built == 66);
}

#endif
