// decimal_from_float: the shortest decimal that reads back as the same float, checked against
// independent references: std::to_chars (shortest round trip, nearest on ties) and, for the
// tiny floats whose shortest form needs more than 18 places, printf's exact "%.18f".
//
// CI checks 10^7 floats where the shortest form matters, 10^6 over all bit patterns and every
// binade edge. The whole float
// range is a skipped test case, run by hand (about 10 minutes in a Release build):
//   build-rel/tests/test_core --no-skip -tc='decimal_from_float: all 2^32 floats'
#include <fieldcodec/core/decimal.hpp>

#include <doctest/doctest.h>

#include "short_runs.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>

using fieldcodec::decimal;
using fieldcodec::decimal_from_float;
using fieldcodec::errc;

namespace {
constexpr bool same(fieldcodec::result<decimal> r, std::int64_t mantissa, unsigned places) {
  return r && r->mantissa == mantissa && r->places == places;
}
constexpr float from_bits(std::uint32_t b) { return std::bit_cast<float>(b); }
} // namespace

// The PLC REAL and friends: what a person typed comes back.
static_assert(same(decimal_from_float(90.73f), 9073, 2));
static_assert(same(decimal_from_float(-90.73f), -9073, 2));
static_assert(same(decimal_from_float(0.1f), 1, 1));
static_assert(same(decimal_from_float(0.3f), 3, 1));
static_assert(same(decimal_from_float(1.001f), 1001, 3));
static_assert(same(decimal_from_float(4.0f), 4, 0));
static_assert(same(decimal_from_float(327.67f), 32767, 2));
static_assert(same(decimal_from_float(5000.0f), 5000, 0));
static_assert(same(decimal_from_float(1e-5f), 1, 5));
static_assert(same(decimal_from_float(123456.7f), 1234567, 1));
static_assert(same(decimal_from_float(3.1415927f), 31415927, 7));  // 8 digits needed
static_assert(same(decimal_from_float(16777216.0f), 16777216, 0)); // 2^24
static_assert(same(decimal_from_float(16777218.0f), 16777218, 0));
static_assert(same(decimal_from_float(1e10f), 10'000'000'000, 0));
static_assert(same(decimal_from_float(1e-9f), 1, 9));
static_assert(same(decimal_from_float(0.0f), 0, 0));
static_assert(same(decimal_from_float(-0.0f), 0, 0));
// 1 + 2^-23 = 1.00000011920929: eight digits are enough.
static_assert(same(decimal_from_float(from_bits(0x3F80'0001U)), 10000001, 7));
// Nine digits: 10.0000104904175 (0x4120000B); no 8-digit decimal lies in its interval.
static_assert(same(decimal_from_float(from_bits(0x4120'000BU)), 100000105, 7));
// The float just below 1 (1 − 2^-24): the gap above it is twice the gap below.
static_assert(same(decimal_from_float(from_bits(0x3F7F'FFFFU)), 99999994, 8));
// An exact tie between two shortest candidates takes the even one: 1048576.25f lies halfway
// between 1048576.2 and 1048576.3, both 8 digits and both read back as it.
static_assert(same(decimal_from_float(1048576.25f), 10485762, 1));
static_assert(same(decimal_from_float(1048576.75f), 10485768, 1));
// Largest magnitudes: 2^63 is 9.223372e18 (fits int64), the next float does not fit.
static_assert(same(decimal_from_float(9.223372e18f), 9'223'372'000'000'000'000, 0));
static_assert(same(decimal_from_float(-9.223372e18f), -9'223'372'000'000'000'000, 0));
static_assert(decimal_from_float(from_bits(0x5F00'0001U)) == errc::not_representable);
static_assert(decimal_from_float(1e19f) == errc::not_representable);
static_assert(decimal_from_float(std::numeric_limits<float>::max()) == errc::not_representable);
static_assert(decimal_from_float(std::numeric_limits<float>::infinity()) ==
              errc::not_representable);
static_assert(decimal_from_float(-std::numeric_limits<float>::infinity()) ==
              errc::not_representable);
static_assert(decimal_from_float(std::numeric_limits<float>::quiet_NaN()) ==
              errc::not_representable);
// Below 18 places: rounded to 18 places (1.5e-18 → 2e-18; the smallest floats → 0).
static_assert(same(decimal_from_float(1.5e-18f), 2, 18));
static_assert(same(decimal_from_float(1.2345678e-12f), 1234568, 18));
static_assert(same(decimal_from_float(4e-19f), 0, 0));
static_assert(same(decimal_from_float(std::numeric_limits<float>::denorm_min()), 0, 0));
static_assert(same(decimal_from_float(std::numeric_limits<float>::min()), 0, 0));
// 1e-12f needs 12 places: shortest, not rounded.
static_assert(same(decimal_from_float(1e-12f), 1, 12));

namespace {
/// What decimal_from_float must return for `f`, from the C++ library alone.
struct expected {
  bool representable = true;
  decimal d{};
};

expected reference(float f) {
  if (f == 0.0f) return {true, {0, 0}};
  // Shortest round trip, nearest on ties: std::to_chars in scientific form, "-d.ddde-XX".
  std::array<char, 64> buf{};
  const auto res =
      std::to_chars(buf.data(), buf.data() + buf.size(), f, std::chars_format::scientific);
  const char *c = buf.data();
  const bool neg = *c == '-';
  if (neg) ++c;
  std::uint64_t m = 0;
  int digits = 0;
  for (; *c != 'e'; ++c) {
    if (*c == '.') continue;
    m = m * 10U + static_cast<std::uint64_t>(*c - '0');
    ++digits;
  }
  ++c; // 'e'
  const bool eneg = *c == '-';
  int exp10 = 0;
  for (++c; c != res.ptr; ++c) exp10 = exp10 * 10 + (*c - '0');
  if (eneg) exp10 = -exp10;
  const int places = digits - 1 - exp10;
  if (places > 18) {
    // Rounded to 18 places: printf prints the float's exact value correctly rounded.
    std::array<char, 128> fixed{};
    std::snprintf(fixed.data(), fixed.size(), "%.18f", static_cast<double>(f));
    const auto d = fieldcodec::parse_decimal(fixed.data());
    if (!d) return {false, {}};
    return {true, fieldcodec::normalize(*d)};
  }
  for (int i = places; i < 0; ++i) {
    if (m > std::numeric_limits<std::uint64_t>::max() / 10U) return {false, {}};
    m *= 10U;
  }
  if (m > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) return {false, {}};
  const auto sm = static_cast<std::int64_t>(m);
  return {true, {neg ? -sm : sm, static_cast<std::uint8_t>(places < 0 ? 0 : places)}};
}

/// Compares one float; returns false (and reports) on a mismatch.
bool agrees(std::uint32_t bits) {
  const float f = std::bit_cast<float>(bits);
  const auto got = decimal_from_float(f);
  if (!std::isfinite(f)) return got == errc::not_representable;
  const expected want = reference(f);
  const bool ok = want.representable
                      ? (got && got->mantissa == want.d.mantissa && got->places == want.d.places)
                      : got == errc::not_representable;
  if (!ok) {
    std::array<char, 160> msg{};
    std::snprintf(msg.data(), msg.size(), "float bits %08x: got %lld e-%d, want %lld e-%d%s",
                  static_cast<unsigned>(bits), static_cast<long long>(got ? got->mantissa : 0),
                  got ? int{got->places} : 0, static_cast<long long>(want.d.mantissa),
                  int{want.d.places}, want.representable ? "" : " (not representable)");
    MESSAGE(msg.data());
  }
  return ok;
}
} // namespace

TEST_CASE("decimal_from_float: every binade edge") {
  // For every exponent, both signs: the smallest, next-to-smallest, middle and largest
  // significands (where the rounding interval is asymmetric, or ends at a power of ten).
  int failures = 0;
  for (std::uint32_t sign = 0; sign < 2; ++sign) {
    for (std::uint32_t biased = 0; biased < 256; ++biased) {
      for (const std::uint32_t frac : {0x000000U, 0x000001U, 0x000002U, 0x000003U, 0x400000U,
                                       0x7FFFFDU, 0x7FFFFEU, 0x7FFFFFU}) {
        if (!agrees((sign << 31U) | (biased << 23U) | frac)) ++failures;
      }
    }
  }
  CHECK(failures == 0);
}

TEST_CASE("decimal_from_float: 10^7 floats from 1e-12 to 2^64") {
  // Where the shortest form matters (and a little below, where rounding to 18 places starts):
  // every 87th bit pattern from 0x2B800000 (9.1e-13) to 0x5F5E… (just below 2^64), both signs,
  // with a varying low byte so that the low bits are not the same few patterns.
  int failures = 0;
  std::uint32_t low = 0x9E37'79B9U;
  for (std::uint32_t i = 0; i < fieldcodec_test::runs(10'000'000U); ++i) {
    low = low * 1'664'525U + 1'013'904'223U; // LCG for the low byte and the sign
    const std::uint32_t bits = ((0x2B80'0000U + i * 87U) ^ (low >> 24U)) | (low & 0x8000'0000U);
    if (!agrees(bits) && ++failures > 20) break;
  }
  CHECK(failures == 0);
}

TEST_CASE("decimal_from_float: 10^6 floats over all bit patterns") {
  // The whole range: tiny floats rounded to 18 places, subnormals, too large, NaN, infinity.
  int failures = 0;
  for (std::uint32_t i = 0; i < fieldcodec_test::runs(1'000'000U); ++i) {
    if (!agrees(i * 4295U + (i >> 3U)) && ++failures > 20) break;
  }
  CHECK(failures == 0);
}

TEST_CASE("decimal_from_float: the shortest form reads back as the same float") {
  // Independent of to_chars: format the decimal, read it with strtof.
  std::uint32_t bits = 1;
  for (int i = 0; i < 200'000; ++i) {
    bits = bits * 2'891'336'453U + 1U;
    const float f = std::bit_cast<float>(bits);
    if (f != f || std::abs(f) > 9e18f || std::abs(f) < 1e-9f) continue;
    const auto d = decimal_from_float(f);
    REQUIRE(d);
    std::array<char, 48> text{};
    const auto n = fieldcodec::format_decimal(*d, text);
    REQUIRE(n);
    CHECK(std::strtof(text.data(), nullptr) == f);
  }
}

namespace {
/// The simple model: round to n = 1..9 significant digits (printf %.{n}e), keep the first that
/// reads back. Compares it with decimal_from_float; false on a disagreement; counts the floats
/// for which the model needs more digits.
bool agrees_with_model(float f, int &longer) {
  std::array<char, 64> text{};
  int digits = 1;
  for (; digits <= 9; ++digits) {
    std::snprintf(text.data(), text.size(), "%.*e", digits - 1, static_cast<double>(f));
    if (std::strtof(text.data(), nullptr) == f) break;
  }
  const auto d = decimal_from_float(f);
  if (digits > 9 || !d) return false;
  std::uint64_t m = static_cast<std::uint64_t>(d->mantissa < 0 ? -d->mantissa : d->mantissa);
  while (m % 10U == 0U && m != 0U) m /= 10U;
  int ours = 0;
  for (; m != 0U; m /= 10U) ++ours;
  if (ours > digits) return false;
  if (ours < digits) {
    ++longer;
    return true;
  }
  std::array<char, 48> ourtext{};
  if (!fieldcodec::format_decimal(*d, ourtext)) return false;
  return std::strtod(ourtext.data(), nullptr) == std::strtod(text.data(), nullptr);
}
} // namespace

TEST_CASE("decimal_from_float against the 'try 1 to 9 digits' model") {
  // The model is never shorter than decimal_from_float; where it needs the same number of
  // digits it gives the same decimal. In principle it can be longer: at a power of two the
  // interval is asymmetric, and the nearest n-digit decimal may fall outside it while another
  // n-digit decimal is inside. Between 1e-9 and 9e18 no float was found to do so, neither
  // among these nor at any binade edge.
  int disagreements = 0;
  int longer = 0;
  int tried = 0;
  const auto in_range = [](float f) {
    return std::isfinite(f) && f != 0.0f && std::abs(f) <= 9e18f && std::abs(f) >= 1e-9f;
  };
  std::uint32_t bits = 7;
  for (int i = 0; i < 200'000; ++i) {
    bits = bits * 747'796'405U + 2'891'336'453U;
    const float f = std::bit_cast<float>(bits);
    if (!in_range(f)) continue;
    ++tried;
    if (!agrees_with_model(f, longer)) ++disagreements;
  }
  for (std::uint32_t biased = 1; biased < 255; ++biased) {
    for (const std::uint32_t frac : {0x000000U, 0x000001U, 0x000002U, 0x7FFFFEU, 0x7FFFFFU}) {
      const float f = std::bit_cast<float>((biased << 23U) | frac);
      if (!in_range(f)) continue;
      ++tried;
      if (!agrees_with_model(f, longer)) ++disagreements;
    }
  }
  CHECK(disagreements == 0);
  CHECK(tried > 70'000); // about 36 % of all bit patterns lie in range
  MESSAGE("the simple model needed more digits for " << longer << " of " << tried << " floats");
}

TEST_CASE("decimal_from_float: all 2^32 floats" * doctest::skip()) {
  std::uint64_t failures = 0;
  for (std::uint64_t b = 0; b <= 0xFFFF'FFFFU; ++b) {
    if (!agrees(static_cast<std::uint32_t>(b)) && ++failures > 20) break;
    if ((b & 0x0FFF'FFFFU) == 0x0FFF'FFFFU) MESSAGE("checked up to " << b);
  }
  CHECK(failures == 0);
}
