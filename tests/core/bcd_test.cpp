#include <fieldcodec/core/bcd.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace bcd = fieldcodec::bcd;
using fieldcodec::errc;
using bytes6 = std::array<std::uint8_t, 6>;

// COMPAX-M/S Interbus manual (000), object POSA: 7350.150 mm → 00 00 07 35 01 50
static_assert(bcd::encode_signed<6>(7'350'150).value() ==
              bytes6{0x00, 0x00, 0x07, 0x35, 0x01, 0x50});
static_assert(bcd::decode_signed(bytes6{0x00, 0x00, 0x07, 0x35, 0x01, 0x50}).value() == 7'350'150);
// COMPAX POSR: −37891.210 mm → FF 00 37 89 12 10
static_assert(bcd::encode_signed<6>(-37'891'210).value() ==
              bytes6{0xFF, 0x00, 0x37, 0x89, 0x12, 0x10});
static_assert(bcd::decode_signed(bytes6{0xFF, 0x00, 0x37, 0x89, 0x12, 0x10}).value() ==
              -37'891'210);

static_assert(bcd::encode<2>(1234).value() == std::array<std::uint8_t, 2>{0x12, 0x34});
static_assert(bcd::decode(std::array<std::uint8_t, 2>{0x99, 0x99}).value() == 9999);
static_assert(bcd::encode<2>(10000).error() == errc::overflow);
static_assert(bcd::encode<9>(999'999'999'999'999'999ULL).value()[0] == 0x99);
static_assert(bcd::decode(std::array<std::uint8_t, 2>{0x1A, 0x00}).error() == errc::bad_digit);
static_assert(bcd::decode(std::array<std::uint8_t, 2>{0xA1, 0x00}).error() == errc::bad_digit);
static_assert(bcd::decode_signed(bytes6{0x01, 0, 0, 0, 0, 0}).error() == errc::bad_sign);
static_assert(bcd::decode_signed(bytes6{0x80, 0, 0, 0, 0, 0}).error() == errc::bad_sign);
static_assert(bcd::decode_signed(bytes6{0xFE, 0, 0, 0, 0, 0}).error() == errc::bad_sign);

TEST_CASE("unsigned BCD: every nibble value") {
  for (unsigned hi = 0; hi < 16; ++hi) {
    for (unsigned lo = 0; lo < 16; ++lo) {
      const std::array<std::uint8_t, 1> b{static_cast<std::uint8_t>(hi << 4U | lo)};
      auto r = bcd::decode(b);
      if (hi <= 9 && lo <= 9) {
        CHECK(r.value() == hi * 10 + lo);
      } else {
        CHECK(r.error() == errc::bad_digit);
      }
    }
  }
}

TEST_CASE("unsigned BCD: lengths and limits") {
  std::array<std::uint8_t, 10> ten{};
  CHECK(bcd::decode(std::span<const std::uint8_t>{}).error() == errc::bad_length);
  CHECK(bcd::decode(ten).error() == errc::bad_length);
  CHECK(bcd::encode(1, std::span<std::uint8_t>{}).is(errc::bad_length));
  CHECK(bcd::encode(1, ten).is(errc::bad_length));
  std::array<std::uint8_t, 6> six{};
  CHECK(bcd::encode(999'999'999'999ULL, six)); // 12 digits (COMPAX S31_S39 identification)
  CHECK(six == bytes6{0x99, 0x99, 0x99, 0x99, 0x99, 0x99});
  CHECK(bcd::encode(1'000'000'000'000ULL, six).is(errc::overflow));
  CHECK(bcd::decode(six).value() == 999'999'999'999ULL);
}

TEST_CASE("signed BCD: signs, zero, limits, bad input") {
  CHECK(bcd::encode_signed<6>(0).value() == bytes6{});
  CHECK(bcd::decode_signed(bytes6{0xFF, 0, 0, 0, 0, 0}).value() == 0); // negative zero
  CHECK(bcd::encode_signed<6>(9'999'999'999).value() == bytes6{0x00, 0x99, 0x99, 0x99, 0x99, 0x99});
  CHECK(bcd::encode_signed<6>(-9'999'999'999).value() ==
        bytes6{0xFF, 0x99, 0x99, 0x99, 0x99, 0x99});
  CHECK(bcd::encode_signed<6>(10'000'000'000).error() == errc::overflow);
  CHECK(bcd::encode_signed<6>(-10'000'000'000).error() == errc::overflow);
  CHECK(bcd::encode_signed<6>(INT64_MIN).error() == errc::overflow);
  CHECK(bcd::decode_signed(bytes6{0x00, 0x00, 0x07, 0x3F, 0x01, 0x50}).error() == errc::bad_digit);
  CHECK(bcd::decode_signed(std::array<std::uint8_t, 1>{0x00}).error() == errc::bad_length);
  std::array<std::uint8_t, 11> eleven{};
  CHECK(bcd::decode_signed(eleven).error() == errc::bad_length);
  CHECK(bcd::encode_signed(1, std::span(eleven)).is(errc::bad_length));
  for (std::int64_t v : {std::int64_t{1}, std::int64_t{-1}, std::int64_t{4'000'000'000},
                         std::int64_t{-4'000'000'000}, std::int64_t{123'456'789}}) {
    CHECK(bcd::decode_signed(bcd::encode_signed<6>(v).value()).value() == v);
  }
}

// The fixed-size encode_signed<N> checks with N known (issue 18); it must answer exactly as the
// span form does: same bytes, same error, for every N and values around every digit limit.
template <std::size_t N>
void check_fixed_against_span(std::int64_t v) {
  std::array<std::uint8_t, N> via_span{};
  const auto s = bcd::encode_signed(v, std::span<std::uint8_t>(via_span));
  const auto f = bcd::encode_signed<N>(v);
  REQUIRE(f.has_value() == s.has_value());
  if (f) {
    CHECK(f.value() == via_span);
  } else {
    CHECK(f.error() == s.error());
  }
}

TEST_CASE("bcd: encode_signed<N> answers as the span form") {
  std::uint64_t x = 0x9E3779B97F4A7C15ULL;
  auto next = [&x] {
    x ^= x >> 12U;
    x ^= x << 25U;
    x ^= x >> 27U;
    return x * 0x2545F4914F6CDD1DULL;
  };
  std::vector<std::int64_t> values{0, 1, -1, INT64_MIN, INT64_MAX};
  std::int64_t p = 1;
  for (int d = 0; d <= 18; ++d) {
    for (std::int64_t k : {p - 1, p, p + 1}) {
      values.push_back(k);
      values.push_back(-k);
    }
    if (d < 18) p *= 10; // 10^18 is the last power an int64 holds
  }
  for (int i = 0; i < 20000; ++i) {
    const auto r = static_cast<std::int64_t>(next());
    values.push_back(r);
    values.push_back(r >> (next() % 63U));
  }
  for (const std::int64_t v : values) {
    check_fixed_against_span<2>(v);
    check_fixed_against_span<3>(v);
    check_fixed_against_span<4>(v);
    check_fixed_against_span<5>(v);
    check_fixed_against_span<6>(v);
    check_fixed_against_span<7>(v);
    check_fixed_against_span<8>(v);
    check_fixed_against_span<9>(v);
    check_fixed_against_span<10>(v);
  }
}
