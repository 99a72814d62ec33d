#include <fieldcodec/core/decimal.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

namespace fc = fieldcodec;
using fc::decimal;
using fc::errc;

namespace {
constexpr bool same(fc::result<decimal> r, std::int64_t m, unsigned p) {
  return r.has_value() && r.value().mantissa == m && r.value().places == p;
}
} // namespace

// Strict parsing.
static_assert(same(fc::parse_decimal("327.67"), 32767, 2));
static_assert(same(fc::parse_decimal("-1055.88"), -105588, 2));
static_assert(same(fc::parse_decimal("5552.0"), 55520, 1));
static_assert(same(fc::parse_decimal("0"), 0, 0));
static_assert(same(fc::parse_decimal("-0.001"), -1, 3));
static_assert(fc::parse_decimal("").error() == errc::bad_syntax);
static_assert(fc::parse_decimal("-").error() == errc::bad_syntax);
static_assert(fc::parse_decimal(".5").error() == errc::bad_syntax);
static_assert(fc::parse_decimal("5.").error() == errc::bad_syntax);
static_assert(fc::parse_decimal("1.2.3").error() == errc::bad_digit);
static_assert(fc::parse_decimal("327,67").error() == errc::bad_digit);
static_assert(fc::parse_decimal("1e3").error() == errc::bad_digit);
static_assert(fc::parse_decimal("+1").error() == errc::bad_digit);
static_assert(fc::parse_decimal(" 1").error() == errc::bad_digit);
static_assert(fc::parse_decimal("9223372036854775807").has_value());
static_assert(fc::parse_decimal("9223372036854775808").error() == errc::overflow);
static_assert(fc::parse_decimal("-9223372036854775808").value().mantissa == INT64_MIN);
static_assert(fc::parse_decimal("-9223372036854775809").error() == errc::overflow);
static_assert(fc::parse_decimal("0.1234567890123456789").error() == errc::overflow);

// Fixed point: ×1000 positions are places = 3.
static_assert(fc::parse_fixed("-1055.88", 2).value() == -105588);
static_assert(fc::parse_fixed("1516.950", 3).value() == 1516950);
static_assert(fc::parse_fixed("5552.0", 3).value() == 5552000);
static_assert(fc::parse_fixed("1.2340", 3).value() == 1234); // trailing zero is fine
static_assert(fc::parse_fixed("1.2345", 3).error() == errc::not_representable);
static_assert(fc::parse_fixed("9300000000000000", 3).error() == errc::overflow);
static_assert(fc::round_to_fixed({12345, 4}, 3).value() == 1235);   // 1.2345 → 1.235
static_assert(fc::round_to_fixed({-12345, 4}, 3).value() == -1235); // half away from zero
static_assert(fc::round_to_fixed({12344, 4}, 3).value() == 1234);
static_assert(fc::round_to_fixed({-12, 1}, 0).value() == -1);
static_assert(fc::round_to_fixed({-15, 1}, 0).value() == -2);
static_assert(fc::round_to_fixed({15, 1}, 0).value() == 2);
static_assert(fc::round_to_fixed({1, 0}, 19).error() == errc::invalid_argument);

// Comparison and normal form.
static_assert(fc::compare({150, 2}, {15, 1}) == 0);
static_assert(fc::compare({-1, 0}, {0, 3}) < 0);
static_assert(fc::compare({INT64_MAX, 0}, {INT64_MAX, 18}) > 0);
static_assert(fc::compare({-5000, 0}, {-49999, 1}) < 0);
static_assert(fc::normalize({1500, 3}).mantissa == 15 && fc::normalize({1500, 3}).places == 1);
static_assert(fc::equal({0, 5}, {0, 0}));

// A double turned into the decimal it stands for.
static_assert(same(fc::decimal_from_double(1.001), 1001, 3));
static_assert(same(fc::decimal_from_double(4.0), 4, 0));
static_assert(same(fc::decimal_from_double(-0.1), -1, 1));
static_assert(same(fc::decimal_from_double(327.67), 32767, 2));
static_assert(same(fc::decimal_from_double(1516.95), 151695, 2));
static_assert(same(fc::decimal_from_double(1e-10), 1, 10));
static_assert(same(fc::decimal_from_double(0.0), 0, 0));
static_assert(fc::decimal_from_double(1e19).error() == errc::not_representable);
static_assert(fc::decimal_from_double(std::numeric_limits<double>::infinity()).error() ==
              errc::not_representable);
static_assert(fc::decimal_from_double(-std::numeric_limits<double>::infinity()).error() ==
              errc::not_representable);
static_assert(fc::decimal_from_double(std::numeric_limits<double>::quiet_NaN()).error() ==
              errc::not_representable);
static_assert(fc::decimal_from_double(1.0, 18).error() == errc::invalid_argument);

namespace {
std::string_view fmt(std::array<char, 48> &buf, decimal d) {
  auto n = fc::format_decimal(d, buf);
  REQUIRE(n);
  return {buf.data(), n.value()};
}
} // namespace

TEST_CASE("exact decimal formatting") {
  std::array<char, 48> b{};
  CHECK(fmt(b, {-105588, 2}) == "-1055.88");
  CHECK(fmt(b, {5, 2}) == "0.05");
  CHECK(fmt(b, {-5, 1}) == "-0.5");
  CHECK(fmt(b, {0, 3}) == "0.000");
  CHECK(fmt(b, {42, 0}) == "42");
  CHECK(fmt(b, {1516950, 3}) == "1516.950");
  CHECK(fmt(b, {INT64_MIN, 18}) == "-9.223372036854775808");
  CHECK(fmt(b, {1, 18}) == "0.000000000000000001");
  std::array<char, 4> small{};
  CHECK(fc::format_decimal({12345, 1}, small).error() == errc::buffer_too_small);
  CHECK(fc::format_decimal({1, 19}, b).error() == errc::invalid_argument);
  std::array<char, 48> f{};
  auto n = fc::format_fixed(-105588, 2, f);
  CHECK(std::string_view(f.data(), n.value()) == "-1055.88");
  CHECK(fc::format_fixed(1, 19, f).error() == errc::invalid_argument);
}

TEST_CASE("text round trip of fixed point values") {
  std::array<char, 48> b{};
  for (std::int64_t v :
       {std::int64_t{0}, std::int64_t{1}, std::int64_t{-1}, std::int64_t{999}, std::int64_t{-1000},
        std::int64_t{4'000'000'000'000}, std::int64_t{-2'147'483'648}, INT64_MAX, INT64_MIN}) {
    for (unsigned p : {0U, 1U, 3U, 6U, 18U}) {
      auto n = fc::format_fixed(v, p, b);
      REQUIRE(n);
      CHECK(fc::parse_fixed({b.data(), n.value()}, p).value() == v);
    }
  }
}

TEST_CASE("fixed point limits") {
  CHECK(fc::parse_fixed("9223372036854775.807", 3).value() == INT64_MAX);
  CHECK(fc::parse_fixed("-9223372036854775.808", 3).value() == INT64_MIN);
  CHECK(fc::parse_fixed("9223372036854775.808", 3).error() == errc::overflow);
  CHECK(fc::parse_fixed("1", 19).error() == errc::invalid_argument);
  CHECK(fc::to_fixed({1, 19}, 3).error() == errc::invalid_argument);
}

TEST_CASE("leading zeros parse and format canonically (fuzz regression)") {
  // fuzz_core found that "-05" formats back as "-5": leading zeros are accepted on input and
  // dropped on output; the value and the number of places are kept exactly.
  auto d = fc::parse_decimal("-05");
  REQUIRE(d);
  CHECK(d.value().mantissa == -5);
  CHECK(d.value().places == 0);
  std::array<char, 48> b{};
  CHECK(fmt(b, d.value()) == "-5");
  CHECK(fmt(b, fc::parse_decimal("007.50").value()) == "7.50");
}

// detail::round_div_i64 rounds on the magnitude (issue 18); it must answer as the signed
// quotient-and-remainder form it replaced, kept here, for every den > 0 and every num.
namespace {
constexpr std::int64_t reference_round_div_i64(std::int64_t num, std::int64_t den) {
  std::int64_t q = num / den;
  const std::int64_t rem = num % den;
  const std::int64_t arem = rem < 0 ? -rem : rem;
  if (arem >= den - arem) q += num < 0 ? -1 : 1;
  return q;
}
} // namespace

static_assert(fieldcodec::detail::round_div_i64(INT64_MIN, 1) == INT64_MIN);
static_assert(fieldcodec::detail::round_div_i64(-15, 10) == -2);
static_assert(fieldcodec::detail::round_div_i64(-14, 10) == -1);
static_assert(fieldcodec::detail::round_div_i64(7, 3) == 2 &&
              fieldcodec::detail::round_div_i64(-8, 3) == -3);

TEST_CASE("decimal: round_div_i64 answers as the signed form it replaced") {
  std::uint64_t x = 0x243F6A8885A308D3ULL;
  auto next = [&x] {
    x ^= x >> 12U;
    x ^= x << 25U;
    x ^= x >> 27U;
    return x * 0x2545F4914F6CDD1DULL;
  };
  std::vector<std::int64_t> dens{1, 2, 3, 5, 7, INT64_MAX};
  std::int64_t p = 1;
  for (int d = 0; d <= 18; ++d) {
    dens.push_back(p);
    if (d < 18) p *= 10;
  }
  for (int i = 0; i < 200; ++i)
    dens.push_back(static_cast<std::int64_t>(next() >> (1U + next() % 63U)) + 1);
  for (const std::int64_t den : dens) {
    for (const std::int64_t num :
         {INT64_MIN, INT64_MIN + 1, std::int64_t{-1}, std::int64_t{0}, std::int64_t{1}, INT64_MAX,
          den / 2, -(den / 2), den / 2 + 1, -(den / 2 + 1)}) {
      REQUIRE(fieldcodec::detail::round_div_i64(num, den) == reference_round_div_i64(num, den));
    }
    for (int i = 0; i < 500; ++i) {
      const auto num = static_cast<std::int64_t>(next()) >> (next() % 64U);
      REQUIRE(fieldcodec::detail::round_div_i64(num, den) == reference_round_div_i64(num, den));
    }
  }
}
