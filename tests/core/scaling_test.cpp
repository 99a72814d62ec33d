#include <fieldcodec/core/scaling.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

namespace fc = fieldcodec;
namespace sc = fieldcodec::scaling;
using fc::decimal;
using fc::errc;

namespace {
constexpr sc::linear dpq_pressure{{32767, 2}, {0, 0}}; // scale 327,67 offset 0
constexpr sc::field u32{4, false};
constexpr sc::field s16{2, true};
constexpr sc::field u16{2, false};
constexpr sc::range zero_5000{{0, 0}, {5000, 0}};
} // namespace

// DPQ manual (004) chapter 3, worked example: Inj. P Limit 1 = 4.0 bar, scale 327,67:
// (4.0 − 0) × 327.67 = 1310.68 → arithmetically rounded 1311 = 0x051F.
static_assert(sc::to_raw(decimal{40, 1}, dpq_pressure, u32, zero_5000).value() == 1311);
static_assert(sc::to_raw(4.0, dpq_pressure, u32, zero_5000).value() == 0x051F);
static_assert(sc::to_raw(5000.0, dpq_pressure, u32, zero_5000).value() == 1'638'350);
static_assert(sc::to_raw(5000.001, dpq_pressure, u32, zero_5000).error() == errc::out_of_range);
static_assert(sc::to_raw(-0.001, dpq_pressure, u32, zero_5000).error() == errc::out_of_range);

// Halfway cases round away from zero, in both signs.
static_assert(sc::scale_to_raw({25, 1}, {}).value() == 3);
static_assert(sc::scale_to_raw({-25, 1}, {}).value() == -3);
static_assert(sc::scale_to_raw({24999, 4}, {}).value() == 2);
static_assert(sc::scale_to_raw({-24999, 4}, {}).value() == -2);
static_assert(sc::scale_to_raw({5, 1}, {}).value() == 1);
static_assert(sc::scale_to_raw({-5, 1}, {}).value() == -1);
// A binary double is taken as the decimal it stands for: 1.001 × 500 = 500.5 → 501.
static_assert(sc::to_raw(1.001, {{500, 0}, {0, 0}}, u32).value() == 501);
static_assert(sc::to_raw(-1.001, {{500, 0}, {0, 0}}, sc::field{4, true}).value() == -501);
// Offset: raw = round((EU − offset) × scale).
static_assert(sc::scale_to_raw({100, 0}, {{10, 0}, {-50, 0}}).value() == 1500);
static_assert(sc::scale_to_raw({-50, 0}, {{10, 0}, {-50, 0}}).value() == 0);
static_assert(sc::scale_to_raw({1, 0}, {{-2, 0}, {0, 0}}).value() == -2); // negative scale

// Field width and signedness: never wrap. 2 bytes, scale 10.5, max 5000 → 52500.
static_assert(sc::to_raw(5000.0, {{105, 1}, {}}, s16).error() == errc::overflow);
static_assert(sc::to_raw(5000.0, {{105, 1}, {}}, u16).value() == 52500);
static_assert(sc::to_raw(-1.0, {}, u16).error() == errc::overflow);
static_assert(sc::to_raw(32767.0, {}, s16).value() == 32767);
static_assert(sc::to_raw(32768.0, {}, s16).error() == errc::overflow);
static_assert(sc::to_raw(-32768.0, {}, s16).value() == -32768);
static_assert(sc::to_raw(-32769.0, {}, s16).error() == errc::overflow);
static_assert(sc::to_raw(65535.0, {}, u16).value() == 65535);
static_assert(sc::to_raw(65536.0, {}, u16).error() == errc::overflow);
static_assert(sc::to_raw(32767.4, {}, s16).value() == 32767);
static_assert(sc::to_raw(32767.5, {}, s16).error() == errc::overflow); // rounds to 32768

// Device → PLC.
static_assert(sc::to_eu_decimal(1311, dpq_pressure, 2).value().mantissa == 400); // 4.00097.. → 4.00
static_assert(sc::to_eu_decimal(1311, dpq_pressure, 5).value().mantissa == 400098);
static_assert(sc::to_eu_decimal(1500, {{10, 0}, {-50, 0}}, 0).value().mantissa == 100);
static_assert(sc::to_eu_decimal(-5, {{10, 0}, {0, 0}}, 0).value().mantissa == -1); // −0.5 → −1
static_assert(sc::to_eu_decimal(5, {{10, 0}, {0, 0}}, 0).value().mantissa == 1);
static_assert(sc::to_eu_decimal(1, {{0, 0}, {0, 0}}, 0).error() == errc::invalid_argument);

TEST_CASE("to_eu in binary floating point") {
  CHECK(sc::to_eu(1311, dpq_pressure) == doctest::Approx(4.000976).epsilon(1e-6));
  CHECK(sc::to_eu(0, {{10, 0}, {-50, 0}}) == -50.0);
  CHECK(sc::to_eu(52500, {{105, 1}, {}}) == 5000.0);
  // The scale is the nearest double to 327.67 (one exact division), not a value accumulated by
  // repeated division: 32767 / 327.67 is exactly 100.
  CHECK(sc::to_eu(32767, dpq_pressure) == 100.0);
  for (std::int64_t raw = -70000; raw <= 70000; raw += 7) {
    CHECK(sc::to_eu(raw, dpq_pressure) == static_cast<double>(raw) / 327.67);
  }
}

TEST_CASE("bad arguments and non-finite inputs") {
  CHECK(sc::to_raw(std::nan(""), dpq_pressure, u32).error() == errc::not_representable);
  CHECK(sc::to_raw(std::numeric_limits<double>::infinity(), dpq_pressure, u32).error() ==
        errc::not_representable);
  CHECK(sc::to_raw(std::nan(""), dpq_pressure, u32, zero_5000).error() == errc::not_representable);
  CHECK(sc::scale_to_raw({1, 0}, {{0, 0}, {}}).error() == errc::invalid_argument);
  CHECK(sc::check_field(0, {0, false}).is(errc::invalid_argument));
  CHECK(sc::check_field(0, {9, false}).is(errc::invalid_argument));
  CHECK(sc::scale_to_raw({INT64_MAX, 0}, {{INT64_MAX, 0}, {}}).error() == errc::overflow);
  CHECK(sc::scale_to_raw({INT64_MAX, 0}, {{1, 0}, {}}).value() == INT64_MAX);
  CHECK(sc::scale_to_raw({INT64_MIN, 0}, {{1, 0}, {}}).value() == INT64_MIN);
  CHECK(sc::scale_to_raw({INT64_MIN, 0}, {{1, 0}, {1, 0}}).error() == errc::overflow);
}

TEST_CASE("field limits of every width") {
  for (std::uint8_t w = 1; w <= 8; ++w) {
    const sc::field s{w, true};
    const sc::field u{w, false};
    CHECK(sc::check_field(s.max(), s));
    CHECK(sc::check_field(s.min(), s));
    CHECK(sc::check_field(u.max(), u));
    CHECK(sc::check_field(-1, u).is(errc::overflow));
    if (w < 8) {
      CHECK(sc::check_field(s.max() + 1, s).is(errc::overflow));
      CHECK(sc::check_field(s.min() - 1, s).is(errc::overflow));
      CHECK(sc::check_field(u.max() + 1, u).is(errc::overflow));
    }
  }
}

TEST_CASE("round trip PLC → card → PLC stays within half a raw step") {
  for (int i = 0; i <= 5000; i += 7) {
    const double eu = i * 1.0;
    auto raw = sc::to_raw(eu, dpq_pressure, u32, zero_5000);
    REQUIRE(raw);
    CHECK(std::fabs(sc::to_eu(raw.value(), dpq_pressure) - eu) <= 0.5 / 327.67 + 1e-12);
  }
}
