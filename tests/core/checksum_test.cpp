#include <fieldcodec/core/checksum.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <string_view>

namespace cs = fieldcodec::checksum;

static_assert(cs::xor8(std::array<std::uint8_t, 3>{0x01, 0x02, 0x04}) == 0x07);
static_assert(cs::xor8(std::array<std::uint8_t, 2>{0xFF, 0xFF}) == 0x00);
static_assert(cs::xor8(std::span<const std::uint8_t>{}) == 0x00);
static_assert(cs::xor8(std::span<const std::uint8_t>{}, 0x03) == 0x03);
static_assert(cs::xor8(std::string_view{"AB"}) == ('A' ^ 'B'));

TEST_CASE("xor8 over text and over bytes agree") {
  constexpr std::string_view text = "0A87;2;1;5520.0";
  std::uint8_t expect = 0;
  for (char c : text) expect = static_cast<std::uint8_t>(expect ^ static_cast<std::uint8_t>(c));
  CHECK(cs::xor8(text) == expect);
  CHECK(cs::xor8(text, 0x03) == (expect ^ 0x03)); // the ETX-inclusive variant
}
