// DPQ parameter conversion (od::descriptor's scaling methods and dpq/parameter.hpp): the
// manual's worked example, rounding of exact halves in both signs, the offset parameter, double
// inputs, bytes and their errors.
// Manual: ../shared/seeds/004_…txt (RE 30146-02-Z), 3.3 / 3.4 "Parameter conversion".
#include <fieldcodec/dpq/parameter.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace fc = fieldcodec;
namespace dpq = fieldcodec::dpq;
namespace od = fieldcodec::od;
using fc::decimal;
using fc::errc;

namespace {
/// A DPQ parameter as the generator emits it: type and printed range (the entry, packed by
/// od::entry_of), scale and offset.
constexpr od::entry_spec spec(od::data_type t, decimal lo, decimal hi) {
  return {.index = 0x2000,
          .type = t,
          .flags = od::flag::scaled,
          .low = od::decimal_number(lo),
          .high = od::decimal_number(hi)};
}
template <const od::entry_spec &Spec>
constexpr od::descriptor param(fc::scaling::linear s) {
  return {od::entry_of<Spec>, {}, s};
}
/// The same without a printed range (only the field applies).
constexpr od::descriptor no_range(od::descriptor d) {
  d.flags = static_cast<std::uint16_t>(d.flags & ~(od::flag::has_low | od::flag::has_high));
  return d;
}
// 4.100 Inj. P Limit 1: 0x2023, 4 bytes, 0…5000, scale 327,67, offset 0 (UNSIGNED32).
constexpr od::entry_spec inj_p_limit_1_spec = spec(od::data_type::unsigned32, {0, 0}, {5000, 0});
constexpr od::descriptor inj_p_limit_1 = param<inj_p_limit_1_spec>({{32767, 2}, {0, 0}});
// 4.197 Program Block: 2 bytes, 0…32, scale 1, offset 1 (INTEGER16) — the only offset.
constexpr od::entry_spec program_block_spec = spec(od::data_type::integer16, {0, 0}, {32, 0});
constexpr od::descriptor program_block = param<program_block_spec>({{1, 0}, {1, 0}});
// 4.66 Hist. Time 1 family: 4 bytes, −100…100, scale 500 (INTEGER32).
constexpr od::entry_spec hist_time_spec = spec(od::data_type::integer32, {-100, 0}, {100, 0});
constexpr od::descriptor hist_time = param<hist_time_spec>({{500, 0}, {0, 0}});
// 4.24 Cavity Press Max Fau family: 2 bytes, −150…150, scale 163,83 (INTEGER16).
constexpr od::entry_spec fau_spec = spec(od::data_type::integer16, {-150, 0}, {150, 0});
constexpr od::descriptor fau = param<fau_spec>({{16383, 2}, {0, 0}});
// 4.35 Decompres.: Limit-: 2 bytes, −100…100, scale 327,7 (INTEGER16, range_exceeds_field).
constexpr od::entry_spec limit_minus_spec = spec(od::data_type::integer16, {-100, 0}, {100, 0});
constexpr od::descriptor limit_minus = param<limit_minus_spec>({{3277, 1}, {0, 0}});
// 4.26 Cavity Press Min: 2 bytes, −100…100, scale 16383,5 (INTEGER16, range_exceeds_field).
constexpr od::entry_spec press_min_spec = spec(od::data_type::integer16, {-100, 0}, {100, 0});
constexpr od::descriptor press_min = param<press_min_spec>({{163835, 1}, {0, 0}});
// 4.2 BackP: Decomp Rate 2: 2 bytes, 0…5000, scale 10,5 (UNSIGNED16: raw up to 52500).
constexpr od::entry_spec decomp_rate_spec = spec(od::data_type::unsigned16, {0, 0}, {5000, 0});
constexpr od::descriptor decomp_rate = param<decomp_rate_spec>({{105, 1}, {0, 0}});

constexpr bool same(fc::result<decimal> r, decimal d) {
  return r.has_value() && r.value().mantissa == d.mantissa && r.value().places == d.places;
}
constexpr bool bytes_are(fc::result<dpq::payload> p, std::array<std::uint8_t, 4> b,
                         std::uint8_t n) {
  if (!p.has_value() || p.value().size != n) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (p.value().bytes[i] != b[i]) return false;
  }
  return true;
}
} // namespace

// Worked example (3.3 and 3.4): (4.0 − 0) × 327.67 = 1310.68 → arithmetically rounded 1311 =
// 0x051F; 4 bytes LSB first: 1F 05 00 00. Back: 1311 / 327.67 = 4.000976… → 4.001 at 3 places.
static_assert(inj_p_limit_1.to_raw(decimal{40, 1}).value() == 1311);
static_assert(inj_p_limit_1.to_raw(4.0).value() == 0x051F);
static_assert(bytes_are(dpq::to_bytes(inj_p_limit_1, 4.0), {0x1F, 0x05, 0x00, 0x00}, 4));
static_assert(dpq::raw_from_bytes(inj_p_limit_1, std::array<std::uint8_t, 4>{0x1F, 0x05, 0, 0})
                  .value() == 1311);
static_assert(same(dpq::from_bytes(inj_p_limit_1, std::array<std::uint8_t, 4>{0x1F, 0x05, 0, 0}),
                   decimal{4001, 3}));
static_assert(inj_p_limit_1.to_raw(5000.0).value() == 1'638'350);
static_assert(inj_p_limit_1.to_raw(5000.001).error() == errc::out_of_range);
static_assert(inj_p_limit_1.to_raw(-0.001).error() == errc::out_of_range);

// Round-trip precision per scale.
static_assert(dpq::round_trip_places({{32767, 2}, {0, 0}}).value() == 3);
static_assert(dpq::round_trip_places({{105, 1}, {0, 0}}).value() == 2);
static_assert(dpq::round_trip_places({{163835, 1}, {0, 0}}).value() == 5);
static_assert(dpq::round_trip_places({{128, 0}, {0, 0}}).value() == 3);
static_assert(dpq::round_trip_places({{500, 0}, {0, 0}}).value() == 3);
static_assert(dpq::round_trip_places({{1, 0}, {1, 0}}).value() == 0);
static_assert(dpq::round_trip_places({{100, 0}, {0, 0}}).value() == 2);
static_assert(dpq::round_trip_places({{1, 0}, {5, 1}}).value() == 1);

TEST_CASE("dpq: worked example of the manual, 4.0 bar -> 1311 -> 1F 05 00 00 -> 4.001") {
  // 004 manual, 3.3 "Parameter conversion" (and its copy in 3.4).
  auto raw = inj_p_limit_1.to_raw(4.0);
  REQUIRE(raw.has_value());
  CHECK(raw.value() == 1311);
  CHECK(raw.value() == 0x051F);
  auto p = dpq::to_bytes(inj_p_limit_1, 4.0);
  REQUIRE(p.has_value());
  CHECK(p.value().size == 4);
  CHECK(p.value().bytes[0] == 0x1F);
  CHECK(p.value().bytes[1] == 0x05);
  CHECK(p.value().bytes[2] == 0x00);
  CHECK(p.value().bytes[3] == 0x00);
  CHECK(dpq::raw_from_bytes(inj_p_limit_1, p.value().span()).value() == 1311);
  CHECK(same(dpq::from_bytes(inj_p_limit_1, p.value().span()), decimal{4001, 3}));
  CHECK(inj_p_limit_1.to_eu(1311) == doctest::Approx(4.000976592303232).epsilon(1e-14));
  // The exact intermediate 1310.68 rounds up; 1310.5 (EU 3.999450…) would round up too.
  CHECK(inj_p_limit_1.to_raw(decimal{3999450, 6}).value() == 1310); // 1310.4998…
  CHECK(inj_p_limit_1.to_raw(decimal{3999451, 6}).value() == 1311); // 1310.5001…
}

TEST_CASE("dpq: exact halves round away from zero in both signs") {
  // 500: ±0.001 → ±0.5 → ±1; ±0.003 → ±1.5 → ±2 (half-even would give 0 and ±2).
  CHECK(hist_time.to_raw(decimal{1, 3}).value() == 1);
  CHECK(hist_time.to_raw(decimal{-1, 3}).value() == -1);
  CHECK(hist_time.to_raw(decimal{5, 3}).value() == 3);   // 2.5 → 3 (half-even: 2)
  CHECK(hist_time.to_raw(decimal{-5, 3}).value() == -3); // −2.5 → −3
  // 163.83: ±150 → ±24574.5 → ±24575 (half-even would give ±24574), the printed limits.
  CHECK(fau.to_raw(decimal{150, 0}).value() == 24575);
  CHECK(fau.to_raw(decimal{-150, 0}).value() == -24575);
  CHECK(fau.to_raw(decimal{50, 0}).value() == 8192);   // 8191.5
  CHECK(fau.to_raw(decimal{-50, 0}).value() == -8192); // −8191.5
  // 10.5: 1 → 10.5 → 11, 3 → 31.5 → 32.
  CHECK(decomp_rate.to_raw(decimal{1, 0}).value() == 11);
  CHECK(decomp_rate.to_raw(decimal{3, 0}).value() == 32);
  // 16383.5: ±1 → ±16383.5 → ±16384.
  CHECK(press_min.to_raw(decimal{1, 0}).value() == 16384);
  CHECK(press_min.to_raw(decimal{-1, 0}).value() == -16384);
  // Just below a half rounds towards zero in both signs.
  CHECK(hist_time.to_raw(decimal{9999, 7}).value() == 0);  // 0.49995
  CHECK(hist_time.to_raw(decimal{-9999, 7}).value() == 0); // −0.49995
}

TEST_CASE("dpq: the offset parameter (4.197 Program Block, offset 1)") {
  CHECK(program_block.to_raw(decimal{0, 0}).value() == -1); // printed minimum is raw −1
  CHECK(program_block.to_raw(decimal{1, 0}).value() == 0);
  CHECK(program_block.to_raw(decimal{32, 0}).value() == 31);
  CHECK(program_block.to_raw(decimal{5, 1}).value() == -1); // 0.5 − 1 = −0.5 → −1
  CHECK(program_block.to_raw(decimal{15, 1}).value() == 1); // 1.5 − 1 = 0.5 → 1
  CHECK(program_block.to_raw(decimal{25, 1}).value() == 2); // 1.5 → 2
  CHECK(program_block.to_raw(decimal{-1, 0}).error() == errc::out_of_range);
  CHECK(program_block.to_raw(decimal{33, 0}).error() == errc::out_of_range);
  CHECK(program_block.to_raw(decimal{3201, 2}).error() == errc::out_of_range);
  // raw −1 = FF FF on the wire; read back as EU 0 (INTEGER16), not 65536.
  auto p = dpq::to_bytes(program_block, decimal{0, 0});
  REQUIRE(p.has_value());
  CHECK(p.value().size == 2);
  CHECK(p.value().bytes[0] == 0xFF);
  CHECK(p.value().bytes[1] == 0xFF);
  CHECK(same(dpq::from_bytes(program_block, p.value().span()), decimal{0, 0}));
  CHECK(program_block.to_eu(-1) == 0.0);
  CHECK(program_block.to_eu(31) == 32.0);
  CHECK(same(dpq::to_eu_decimal(program_block, 7), decimal{8, 0}));
  CHECK(same(program_block.to_eu_decimal(7, 2), decimal{800, 2}));
}

TEST_CASE("dpq: binary floating-point inputs are read as 15-digit decimals") {
  // 1.001 is stored as 1.000999999999999889…; read as the decimal 1.001 it gives 500.5 → 501.
  CHECK(hist_time.to_raw(1.001).value() == 501);
  CHECK(hist_time.to_raw(-1.001).value() == -501);
  // A naive binary computation rounds differently: this is what the decimal step avoids.
  CHECK(std::lround(1.001 * 500.0) == 500);
  CHECK(hist_time.to_raw(decimal{1001, 3}).value() == 501); // the same as the decimal input
  // 0.1 + 0.2 is 0.30000000000000004 in binary; 15 digits make it 0.3 → 150.
  CHECK(hist_time.to_raw(0.1 + 0.2).value() == 150);
  // 4.0 via a computation that lands a hair off: still 1311.
  CHECK(inj_p_limit_1.to_raw(0.1 * 40.0).value() == 1311);
  // More than 15 significant digits are cut to 15: 1.0009999999999999 → 1.00100000000000 → 501.
  CHECK(hist_time.to_raw(1.0009999999999999).value() == 501);
  CHECK(hist_time.to_raw(std::numeric_limits<double>::quiet_NaN()).error() ==
        errc::not_representable);
  CHECK(hist_time.to_raw(std::numeric_limits<double>::infinity()).error() ==
        errc::not_representable);
  CHECK(hist_time.to_raw(-std::numeric_limits<double>::infinity()).error() ==
        errc::not_representable);
  // −0.0 is zero.
  CHECK(hist_time.to_raw(-0.0).value() == 0);
}

TEST_CASE("dpq: values that would wrap are refused with overflow, never wrapped") {
  // 327.7 × 100 = 32770 does not fit INTEGER16: the manual's warning about negative values.
  CHECK(limit_minus.to_raw(decimal{100, 0}).error() == errc::overflow);
  CHECK(limit_minus.to_raw(decimal{-100, 0}).error() == errc::overflow);
  CHECK(dpq::to_bytes(limit_minus, 100.0).error() == errc::overflow);
  // Exact edges: 32767.5 / 327.7 = 99.99237…, −32768.5 / 327.7 = −99.99542…
  CHECK(limit_minus.to_raw(decimal{9999237, 5}).value() == 32767);          // 32767.4996…
  CHECK(limit_minus.to_raw(decimal{9999238, 5}).error() == errc::overflow); // 32767.5029…
  CHECK(limit_minus.to_raw(decimal{-9999542, 5}).value() == -32768);        // −32768.4991…
  CHECK(limit_minus.to_raw(decimal{-9999543, 5}).error() == errc::overflow);
  // 16383.5: representable only for −2.0000915… ≤ EU < 2.0000305…
  CHECK(press_min.to_raw(decimal{2, 0}).value() == 32767);
  CHECK(press_min.to_raw(decimal{2000030, 6}).value() == 32767);
  CHECK(press_min.to_raw(decimal{2000031, 6}).error() == errc::overflow);
  CHECK(press_min.to_raw(decimal{-2000091, 6}).value() == -32768);
  CHECK(press_min.to_raw(decimal{-2000092, 6}).error() == errc::overflow);
  CHECK(press_min.to_raw(decimal{100, 0}).error() == errc::overflow);
  // Range is checked before the field: outside the printed range is out_of_range.
  CHECK(limit_minus.to_raw(decimal{1001, 1}).error() == errc::out_of_range);
  // An unsigned field refuses a negative raw value even without a printed range.
  constexpr od::descriptor open = no_range(decomp_rate);
  CHECK(open.to_raw(decimal{-1, 0}).error() == errc::overflow);
  CHECK(open.to_raw(decimal{6241, 0}).value() == 65531);          // 65530.5 → 65531
  CHECK(open.to_raw(decimal{6242, 0}).error() == errc::overflow); // 65541
  CHECK(decomp_rate.to_raw(decimal{5000, 0}).value() == 52500);
}

TEST_CASE("dpq: raw_to_bytes / raw_from_bytes check the range, the field and the length") {
  constexpr od::descriptor rate = no_range(decomp_rate);
  constexpr od::descriptor fau_field = no_range(fau);
  CHECK(dpq::raw_to_bytes(rate, 65535).has_value());
  CHECK(dpq::raw_to_bytes(rate, 65536).error() == errc::overflow);
  CHECK(dpq::raw_to_bytes(rate, -1).error() == errc::overflow);
  CHECK(dpq::raw_to_bytes(fau_field, -32768).has_value());
  CHECK(dpq::raw_to_bytes(fau_field, -32769).error() == errc::overflow);
  CHECK(dpq::raw_to_bytes(fau_field, 32768).error() == errc::overflow);
  // with the printed range: 0…5000 EU is raw 0…52500
  CHECK(dpq::raw_to_bytes(decomp_rate, 52500).has_value());
  CHECK(dpq::raw_to_bytes(decomp_rate, 52501).error() == errc::out_of_range);
  const std::array<std::uint8_t, 2> ffff{0xFF, 0xFF};
  CHECK(dpq::raw_from_bytes(decomp_rate, ffff).value() == 65535);
  CHECK(dpq::raw_from_bytes(fau, ffff).value() == -1);
  const std::array<std::uint8_t, 1> one{0x01};
  const std::array<std::uint8_t, 3> three{0x01, 0x02, 0x03};
  CHECK(dpq::raw_from_bytes(fau, one).error() == errc::truncated);
  CHECK(dpq::raw_from_bytes(fau, three).error() == errc::bad_length);
  CHECK(dpq::raw_from_bytes(fau, {}).error() == errc::truncated);
  CHECK(dpq::raw_from_bytes(inj_p_limit_1, std::array<std::uint8_t, 4>{0xFF, 0xFF, 0xFF, 0xFF})
            .value() == 4294967295);
  // Read-back values outside the printed range still decode (actual values, display range).
  CHECK(same(dpq::from_bytes(inj_p_limit_1, std::array<std::uint8_t, 4>{0xFF, 0xFF, 0xFF, 0x7F}),
             decimal{6553800003, 3})); // 2147483647 / 327.67 = 6553800.00305…
  od::descriptor zero_scale = fau;
  zero_scale.scale.scale = {0, 0};
  CHECK(zero_scale.to_raw(decimal{1, 0}).error() == errc::invalid_argument);
  CHECK(dpq::to_eu_decimal(zero_scale, 1).error() == errc::invalid_argument);
}
