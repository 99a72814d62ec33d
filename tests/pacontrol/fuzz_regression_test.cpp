// Regression tests for inputs found by fuzz/fuzz_pacontrol_serial.cpp (see fuzz/FINDINGS.md).
// A test marked may_fail reproduces an OPEN finding: it reports the failure without failing the
// suite. Whoever fixes the finding removes the decorator (and the finding's status says fixed).
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
  const serial::acknowledgement ack{0, true, 31, 0, {pac::data_type::real, date}};
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
