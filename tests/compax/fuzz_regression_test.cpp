// Regression tests for inputs found by fuzz/fuzz_compax.cpp (see fuzz/FINDINGS.md).
#include <fieldcodec/compax/objects.hpp>
#include <fieldcodec/dictionaries/compax_objects.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>

namespace cx = fieldcodec::compax;
namespace d = fieldcodec::dictionaries::compax_objects;

// F14 (2026-11-21, fuzz_compax in CI's 20 s run): POSA = FF 00 00 00 00 00 (a BCD "negative
// zero") decodes to 0 and is written back as 00 00 00 00 00 00. Not a codec bug — zero has one
// canonical form, as core/bcd documents — but the harness had not stated that form; it does now,
// and this pins the behaviour.
TEST_CASE("fuzz F14: a BCD negative zero position reads as 0 and writes as +0") {
  const std::array<std::uint8_t, 6> negative_zero{0xFF, 0x00, 0x00, 0x00, 0x00, 0x00};
  auto eu = cx::decode_object(d::posa, negative_zero);
  REQUIRE(eu.has_value());
  CHECK(eu.value().mantissa == 0);
  std::array<std::uint8_t, 6> out{};
  auto n = cx::encode_object(d::posa, eu.value(), out);
  REQUIRE(n.has_value());
  CHECK(n.value() == 6);
  CHECK(out == std::array<std::uint8_t, 6>{0x00, 0x00, 0x00, 0x00, 0x00, 0x00});
}
