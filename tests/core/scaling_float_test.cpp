// scaling::to_raw from a float (a PLC REAL), an integer of any type, a double and a decimal:
// each read as the number it is, each by its own overload.
#include <fieldcodec/core/scaling.hpp>

#include <doctest/doctest.h>

#include <array>
#include <charconv>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace fc = fieldcodec;
namespace sc = fieldcodec::scaling;
using fc::decimal;
using fc::errc;

namespace {
constexpr sc::linear dpq_pressure{{32767, 2}, {0, 0}}; // scale 327,67 (DPQ manual 004, ch. 3)
constexpr sc::field u16{2, false};
constexpr sc::field s32{4, true};
constexpr sc::range zero_5000{{0, 0}, {5000, 0}};
} // namespace

// Issue 13: a PLC REAL 90.73 at scale 327.67. 90.73 × 327.67 = 29729.4991 → 29729. Widened to
// double first, the float is 90.7300033569336 and would give 29729.50020… → 29730.
static_assert(sc::to_raw(90.73f, dpq_pressure, u16).value() == 29729);
static_assert(sc::to_raw(90.73f, dpq_pressure, u16, zero_5000).value() == 29729);
static_assert(sc::to_raw(static_cast<double>(90.73f), dpq_pressure, u16).value() == 29730);
static_assert(sc::to_raw(90.73, dpq_pressure, u16).value() == 29729); // the double 90.73
static_assert(sc::to_raw(decimal{9073, 2}, dpq_pressure, u16).value() == 29729);
static_assert(sc::to_raw(-90.73f, dpq_pressure, s32).value() == -29729);
// DPQ manual (004) chapter 3, worked example, as a REAL: 4.0 bar → 1310.68 → 1311.
static_assert(sc::to_raw(4.0f, dpq_pressure, u16, zero_5000).value() == 1311);
// The range and field checks apply as for every other input.
static_assert(sc::to_raw(5000.01f, dpq_pressure, s32, zero_5000).error() == errc::out_of_range);
static_assert(sc::to_raw(-0.01f, dpq_pressure, s32, zero_5000).error() == errc::out_of_range);
static_assert(sc::to_raw(200.1f, dpq_pressure, u16).error() == errc::overflow);
static_assert(sc::to_raw(std::numeric_limits<float>::quiet_NaN(), dpq_pressure, s32).error() ==
              errc::not_representable);
static_assert(sc::to_raw(std::numeric_limits<float>::infinity(), dpq_pressure, s32, zero_5000)
                  .error() == errc::not_representable);

// Integers of every width and signedness are exact (no trip through a floating type).
static_assert(sc::to_raw(4, dpq_pressure, u16).value() == 1311);
static_assert(sc::to_raw(std::uint8_t{4}, dpq_pressure, u16).value() == 1311);
static_assert(sc::to_raw(std::int16_t{-4}, dpq_pressure, s32).value() == -1311);
static_assert(sc::to_raw(4U, dpq_pressure, u16, zero_5000).value() == 1311);
static_assert(sc::to_raw(5001L, dpq_pressure, s32, zero_5000).error() == errc::out_of_range);
// 2^53 + 1 would lose its last bit through double; as an integer it stays exact.
static_assert(sc::to_raw(9'007'199'254'740'993LL, {}, sc::field{8, true}).value() ==
              9'007'199'254'740'993LL);
static_assert(sc::to_raw(std::numeric_limits<std::uint64_t>::max(), {}, sc::field{8, false})
                  .error() == errc::not_representable);
static_assert(sc::to_raw(std::numeric_limits<std::int64_t>::min(), {}, sc::field{8, true})
                  .value() == std::numeric_limits<std::int64_t>::min());
static_assert(fc::decimal_from_integer(std::uint64_t{1} << 63U).error() == errc::not_representable);
static_assert(fc::decimal_from_integer((std::uint64_t{1} << 63U) - 1U).value().mantissa ==
              std::numeric_limits<std::int64_t>::max());
static_assert(fc::decimal_from_integer(-7).value().mantissa == -7);

// Every kind of argument picks its own overload; none is ambiguous, bool is refused.
template <class V>
concept to_raw_callable = requires(V v) {
  sc::to_raw(v, dpq_pressure, u16);
  sc::to_raw(v, dpq_pressure, u16, zero_5000);
};
static_assert(to_raw_callable<float>);
static_assert(to_raw_callable<double>);
static_assert(to_raw_callable<decimal>);
static_assert(to_raw_callable<int>);
static_assert(to_raw_callable<unsigned char>);
static_assert(to_raw_callable<signed char>);
static_assert(to_raw_callable<long long>);
static_assert(to_raw_callable<unsigned long long>);
static_assert(to_raw_callable<const float &>);
static_assert(!to_raw_callable<bool>);

namespace {
/// round(n/100 × 327.67) half away from zero, in exact integer arithmetic (n ≥ 0).
constexpr std::int64_t exact_raw(std::int64_t hundredths) {
  const std::int64_t num = hundredths * 32767; // value × 327.67 in units of 10^-4
  return (num + 5'000) / 10'000;
}

/// The float a PLC holds for "n/100": the nearest float to the decimal text.
float real_from_hundredths(std::int64_t n) {
  std::array<char, 32> text{};
  auto res = std::to_chars(text.data(), text.data() + text.size(), n / 100);
  *res.ptr++ = '.';
  *res.ptr++ = static_cast<char>('0' + n % 100 / 10);
  *res.ptr++ = static_cast<char>('0' + n % 10);
  float f = 0;
  const auto parsed = std::from_chars(text.data(), res.ptr, f);
  REQUIRE(parsed.ec == std::errc{});
  return f;
}
} // namespace

TEST_CASE("every two-decimal REAL from 0.00 to 5000.00 scales as its decimal does") {
  // Issue 13's statistic: of these 500 001 values, 8 887 came out one count off when the
  // float was widened to double first. Read as floats, all are exact.
  int wrong_as_float = 0;
  int wrong_via_double = 0;
  for (std::int64_t n = 0; n <= 500'000; ++n) {
    const float real = real_from_hundredths(n);
    const std::int64_t want = exact_raw(n);
    const auto got = sc::to_raw(real, dpq_pressure, s32, zero_5000);
    if (!got || *got != want) ++wrong_as_float;
    const auto widened = sc::to_raw(static_cast<double>(real), dpq_pressure, s32, zero_5000);
    if (!widened || *widened != want) ++wrong_via_double;
  }
  CHECK(wrong_as_float == 0);
  CHECK(wrong_via_double == 8'887);
}

TEST_CASE("a float argument reads as its shortest decimal in both to_raw forms") {
  // 0.1f is 0.100000001490116…: through double (15 digits) it would be 0.100000001490116.
  constexpr sc::linear huge_scale{{1'000'000'000'000, 0}, {0, 0}}; // × 10^12
  CHECK(sc::to_raw(0.1f, huge_scale, sc::field{8, true}) == 100'000'000'000);
  CHECK(sc::to_raw(static_cast<double>(0.1f), huge_scale, sc::field{8, true}) == 100'000'001'490);
  CHECK(sc::to_raw(0.1f, huge_scale, sc::field{8, true}, {{0, 0}, {1, 0}}) == 100'000'000'000);
}
