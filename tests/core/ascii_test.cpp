#include <fieldcodec/core/ascii.hpp>

#include <doctest/doctest.h>

#include <array>
#include <string_view>

namespace ascii = fieldcodec::ascii;
using fieldcodec::errc;

static_assert(ascii::parse_unsigned("0").value() == 0);
static_assert(ascii::parse_unsigned("18446744073709551615").value() == UINT64_MAX);
static_assert(ascii::parse_unsigned("18446744073709551616").error() == errc::overflow);
static_assert(ascii::parse_unsigned("").error() == errc::bad_syntax);
static_assert(ascii::parse_unsigned("12a").error() == errc::bad_digit);
static_assert(ascii::parse_unsigned(" 1").error() == errc::bad_digit);
static_assert(ascii::parse_unsigned("+1").error() == errc::bad_digit);
static_assert(ascii::parse_signed("-9223372036854775808").value() == INT64_MIN);
static_assert(ascii::parse_signed("9223372036854775807").value() == INT64_MAX);
static_assert(ascii::parse_signed("9223372036854775808").error() == errc::overflow);
static_assert(ascii::parse_signed("-9223372036854775809").error() == errc::overflow);
static_assert(ascii::parse_signed("-").error() == errc::bad_syntax);
static_assert(ascii::parse_signed("--1").error() == errc::bad_digit);
static_assert(ascii::parse_hex("0A87", ascii::hex_case::upper).value() == 0x0A87);
static_assert(ascii::parse_hex("0a87", ascii::hex_case::upper).error() == errc::bad_digit);
static_assert(ascii::parse_hex("0a87", ascii::hex_case::lower).value() == 0x0A87);
static_assert(ascii::parse_hex("0A87", ascii::hex_case::lower).error() == errc::bad_digit);
static_assert(ascii::parse_hex("FfFf").value() == 0xFFFF);
static_assert(ascii::parse_hex("FFFFFFFFFFFFFFFF").value() == UINT64_MAX);
static_assert(ascii::parse_hex("10000000000000000").error() == errc::overflow);
static_assert(ascii::parse_hex("0x12").error() == errc::bad_digit);
static_assert(ascii::parse_hex("G").error() == errc::bad_digit);
static_assert(ascii::parse_hex("").error() == errc::bad_syntax);
static_assert(ascii::hex_byte('0', '0') == 0x00);
static_assert(ascii::hex_byte('F', 'f') == 0xFF);
static_assert(ascii::hex_byte('a', '5') == 0xA5);
static_assert(ascii::hex_byte('5', 'a', ascii::hex_case::upper) == -1);
static_assert(ascii::hex_byte('G', '0') == -1);
static_assert(ascii::hex_byte('0', ' ') == -1);
static_assert(ascii::hex_byte('-', '1') == -1);

namespace {
template <class F>
std::string_view formatted(std::array<char, 32> &buf, F f) {
  auto n = f(std::span<char>(buf));
  REQUIRE(n);
  return {buf.data(), n.value()};
}
} // namespace

TEST_CASE("integer formatting") {
  std::array<char, 32> buf{};
  CHECK(formatted(buf, [](auto s) { return ascii::format_unsigned(0, s); }) == "0");
  CHECK(formatted(buf, [](auto s) { return ascii::format_unsigned(UINT64_MAX, s); }) ==
        "18446744073709551615");
  CHECK(formatted(buf, [](auto s) { return ascii::format_signed(INT64_MIN, s); }) ==
        "-9223372036854775808");
  CHECK(formatted(buf, [](auto s) { return ascii::format_signed(-42, s); }) == "-42");
  CHECK(formatted(buf, [](auto s) { return ascii::format_hex(0x0A87, 4, s); }) == "0A87");
  CHECK(formatted(buf, [](auto s) { return ascii::format_hex(0xBEEF, 2, s, false); }) == "beef");
  CHECK(formatted(buf, [](auto s) { return ascii::format_hex(0, 0, s); }) == "0");
  CHECK(formatted(buf, [](auto s) { return ascii::format_hex(UINT64_MAX, 1, s); }) ==
        "FFFFFFFFFFFFFFFF");
}

TEST_CASE("integer formatting into a short buffer") {
  std::array<char, 3> small{};
  CHECK(ascii::format_unsigned(1234, small).error() == errc::buffer_too_small);
  CHECK(ascii::format_signed(-123, small).error() == errc::buffer_too_small);
  CHECK(ascii::format_signed(-1, std::span<char>{}).error() == errc::buffer_too_small);
  CHECK(ascii::format_hex(0x1234, 4, small).error() == errc::buffer_too_small);
  CHECK(ascii::format_hex(1, 17, small).error() == errc::invalid_argument);
  CHECK(ascii::format_signed(-12, small).value() == 3);
}

TEST_CASE("round trips") {
  std::array<char, 32> buf{};
  for (std::int64_t v : {std::int64_t{0}, std::int64_t{-1}, std::int64_t{2147483647},
                         std::int64_t{-2147483648}, INT64_MAX, INT64_MIN}) {
    auto n = ascii::format_signed(v, buf).value();
    CHECK(ascii::parse_signed({buf.data(), n}).value() == v);
  }
}
