// Regression tests for inputs found by fuzz/fuzz_pacontrol_serial.cpp and
// fuzz/fuzz_pacontrol_profibus.cpp and fuzz/fuzz_pacontrol_command.cpp (see fuzz/FINDINGS.md).
// A test marked may_fail reproduces an OPEN finding: it reports the failure without failing the
// suite. Whoever fixes the finding removes the decorator (and the finding's status says fixed).
#include <fieldcodec/core/ieee754.hpp>
#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/pacontrol/command.hpp>
#include <fieldcodec/pacontrol/position.hpp>
#include <fieldcodec/pacontrol/profibus_axis.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <limits>
#include <span>

namespace fc = fieldcodec;
namespace pac = fc::pacontrol;
namespace serial = fc::pacontrol::serial;

namespace {

// What the encoder writes, the decoder reads back to the same acknowledgement — or the encoder
// refuses it.
void check_ack_round_trip(fc::decimal date) {
  const serial::acknowledgement ack{0, true, 31, 0, {fc::od::command_value::real, date}};
  std::array<std::uint8_t, serial::max_frame_size> out{};
  auto n = serial::encode_acknowledgement(ack, out);
  if (!n) return; // refusing is a valid fix
  auto back = serial::decode_frame(std::span<const std::uint8_t>(out).first(n.value()));
  REQUIRE(back.has_value()); // F1 failed here with errc::too_long (fixed: max_field_chars 21)
  CHECK(back.value().kind == serial::frame_kind::acknowledgement);
  CHECK(back.value().ack == ack);
}

} // namespace

// F1 (2026-11-21, fuzz_pacontrol_serial, encode mode): a real date of 21 characters
// ("-0.000000000000000001", "-922337203685477580.8") passes validate() and is encoded, but the
// decoder refused any field longer than max_field_chars = 20 with errc::too_long. The longest
// text format_decimal writes for a valid real date is 21 characters. Fixed: max_field_chars is
// 21, so every date the encoder writes fits the decoder.
TEST_CASE("fuzz F1: the decoder reads back every date the encoder writes") {
  check_ack_round_trip({-1, 18});
  check_ack_round_trip({std::numeric_limits<std::int64_t>::min(), 1});
}

// F2 (2026-11-21, fuzz_pacontrol_profibus): a ×1000 position near the int32 limits
// (7F FF FF FF = 2147483.647) decodes to the nearest float, 2147483.75, and encode_position of
// that float fails with errc::overflow (its shortest decimal 2147483.8 × 1000 is beyond int32):
// an axis status read from the bus cannot be written back. Same for 80 00 00 00.
TEST_CASE("fuzz F2: a decoded x1000 position re-encodes") {
  using pac::position_format;
  for (const auto raw : {std::array<std::uint8_t, 4>{0x7F, 0xFF, 0xFF, 0xFF},
                         std::array<std::uint8_t, 4>{0x80, 0x00, 0x00, 0x00}}) {
    auto f = pac::decode_position(raw, position_format::milli_integer);
    REQUIRE(f.has_value());
    auto back = pac::encode_position(f.value(), position_format::milli_integer);
    REQUIRE(back.has_value()); // fixed: the nearest float towards zero near the limits
    CHECK(pac::decode_position(back.value(), position_format::milli_integer).value() == f.value());
  }
  const std::array<std::uint8_t, 12> status{0x00, 0x00, 0xC3, 0x41, 0x00, 0x00,
                                            0x00, 0x00, 0x7F, 0xFF, 0xFF, 0xFF};
  auto s = pac::profibus::decode_axis_status(status, position_format::milli_integer);
  REQUIRE(s.has_value());
  CHECK(pac::profibus::encode_axis_status(s.value(), position_format::milli_integer).has_value());
}

// F9 (2026-11-21, fuzz_pacontrol_command): reply_value(cmd, profibus reply) documents only
// not_representable for NaN/±∞, but refuses finite floats too: below about 1e-10 (no decimal of
// at most 18 places, e.g. 1e-20 or any denormal, i.e. an int32 date 1..8388607 read as a float)
// with not_representable, and from about 9.2e17 on with overflow (the master style's ".0"
// multiplies the int64 mantissa by 10). A float R register holding such a value cannot be read.
// Decided: such dates have no exponent-free decimal form, so they cannot travel as PA-CONTROL
// text either; reply_value refuses them with the documented errors (no silent wrong value).
TEST_CASE("fuzz F9: float reply dates beyond decimal reach are refused as documented") {
  const auto &cmd = fieldcodec::dictionaries::pacontrol_commands::cmd_put_float_reg;
  pac::profibus::cmd_reply reply{};
  reply.date = fc::ieee754::to_bits(1e-20F);
  CHECK(pac::reply_value(cmd, reply).error() == fc::errc::not_representable);
  reply.date = 1U; // the smallest denormal
  CHECK(pac::reply_value(cmd, reply).error() == fc::errc::not_representable);
  reply.date = fc::ieee754::to_bits(1e18F);
  CHECK(pac::reply_value(cmd, reply).error() == fc::errc::overflow);
  reply.date = fc::ieee754::to_bits(1e-9F); // still representable
  CHECK(pac::reply_value(cmd, reply).has_value());
  reply.date = fc::ieee754::to_bits(1e17F);
  CHECK(pac::reply_value(cmd, reply).has_value());
}
