// scaling::to_raw from a decimal takes, where scale and offset are compile-time constants, a
// copy of its int64 path in which the decimal's places are a constant too (issue 18): the
// decimal is first written with 6 places (to_raw_decimal_at6), then the 6-place copy runs.
// This file proves that the copies never change a result: every result (value or error code)
// of the fast path is compared with the code as it was before, kept here as the reference
// (check_range, scale_to_raw, check_field in that order), over millions of inputs chosen to hit
// exact halves, both signs, range limits, int64 overflow, every field width and bad arguments.
// The fast path is tested directly (decimal_detail::to_raw_decimal_at6, the code the dispatch
// runs, and the template to_raw_decimal_i64<P> for every P 0..6), because whether the public to_raw
// takes it depends on the optimiser; the public to_raw is compared too, with constant scales (the
// fast path in optimised builds).
#include <fieldcodec/core/scaling.hpp>

#include <doctest/doctest.h>

#include "xorshift.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace fc = fieldcodec;
namespace sc = fieldcodec::scaling;
using fc::decimal;
using fc::errc;

namespace {

// The reference: to_raw(decimal …) before issue 18's dispatch.
fc::result<std::int64_t> reference(decimal eu, sc::linear s, sc::field f, bool ranged,
                                   sc::range r) {
  if (ranged) {
    if (auto st = sc::check_range(eu, r); !st) return st.error();
  }
  auto raw = sc::scale_to_raw(eu, s);
  if (!raw) return raw.error();
  if (auto st = sc::check_field(raw.value(), f); !st) return st.error();
  return raw.value();
}

bool same(const fc::result<std::int64_t> &a, const fc::result<std::int64_t> &b) {
  if (a.has_value() != b.has_value()) return false;
  return a.has_value() ? a.value() == b.value() : a.error() == b.error();
}

struct rng : fieldcodec::test::xorshift {
  rng() : xorshift(0x2545'F491'4F6C'DD1DULL) {}
  std::uint64_t below(std::uint64_t n) { return next() % n; }
  std::int64_t between(std::int64_t lo, std::int64_t hi) {
    return lo + static_cast<std::int64_t>(below(static_cast<std::uint64_t>(hi - lo) + 1U));
  }
};

constexpr std::int64_t i64_min = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t i64_max = std::numeric_limits<std::int64_t>::max();

// A mantissa: small, around powers of ten, exact halves of the scale, or near the int64 ends.
std::int64_t mantissa(rng &g) {
  const std::int64_t sign = g.below(2) == 0U ? 1 : -1;
  switch (g.below(6)) {
  case 0: return g.between(-1000, 1000);
  case 1: return sign * g.between(0, 200'000);
  case 2: {
    std::int64_t p = 1;
    for (auto n = g.below(19); n > 0; --n) p *= 10;
    return sign * (p + g.between(-2, 2));
  }
  case 3: return sign * static_cast<std::int64_t>(g.next() >> (1U + g.below(63)));
  case 4: return g.below(2) == 0U ? i64_min + g.between(0, 3) : i64_max - g.between(0, 3);
  default: return sign * (g.between(0, 99'999) * 10 + 5); // ends in 5: halves after scaling
  }
}

decimal any_decimal(rng &g, unsigned max_places) {
  return {mantissa(g), static_cast<std::uint8_t>(g.below(max_places + 1U))};
}

sc::linear any_scale(rng &g) {
  static constexpr std::array<decimal, 10> scales{{{32767, 2},
                                                   {105, 1},
                                                   {10, 0},
                                                   {1, 0},
                                                   {163835, 1},
                                                   {128, 0},
                                                   {-5, 1},
                                                   {0, 0},
                                                   {1, 18},
                                                   {999'999'999, 3}}};
  sc::linear s;
  s.scale = g.below(4) == 0U ? any_decimal(g, 20) : scales[g.below(scales.size())];
  s.offset = g.below(2) == 0U ? decimal{0, 0} : any_decimal(g, 20);
  if (g.below(3) == 0U) s.offset = {g.between(-100, 100), static_cast<std::uint8_t>(g.below(3))};
  return s;
}

sc::field any_field(rng &g) {
  return {static_cast<std::uint8_t>(g.below(10)), g.below(2) == 0U}; // 0 and 9 are invalid
}

sc::range any_range(rng &g, decimal eu) {
  sc::range r{any_decimal(g, 20), any_decimal(g, 20)};
  if (g.below(3) == 0U) r = {{-100, 0}, {100, 0}};
  if (g.below(4) == 0U) r.low = eu; // on the limit
  if (g.below(4) == 0U) r.high = eu;
  return r;
}

template <std::uint8_t P>
struct outcome {
  std::size_t decided = 0;
  std::size_t differ = 0;
};

template <std::uint8_t P>
void check_places(rng &g, std::size_t n, outcome<P> &o) {
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t m = mantissa(g);
    const decimal eu{m, P};
    const sc::linear s = any_scale(g);
    const sc::field f = any_field(g);
    const bool ranged = g.below(4) != 0U;
    const sc::range r = any_range(g, eu);
    fc::result<std::int64_t> out{errc::invalid_argument};
    if (!sc::decimal_detail::to_raw_decimal_i64<P>(m, s, f, ranged, r, out)) continue;
    ++o.decided;
    if (!same(out, reference(eu, s, f, ranged, r))) {
      ++o.differ;
      if (o.differ <= 5) {
        FAIL_CHECK("places " << int{P} << " mantissa " << m << " scale " << s.scale.mantissa << "e-"
                             << int{s.scale.places} << " offset " << s.offset.mantissa << "e-"
                             << int{s.offset.places} << " field " << int{f.bytes}
                             << (f.is_signed ? "s" : "u"));
      }
    }
  }
}

template <std::uint8_t P>
void run_places(std::size_t n) {
  rng g;
  for (std::uint8_t k = 0; k < P; ++k) (void)g.next(); // a different stream per precision
  outcome<P> o;
  check_places<P>(g, n, o);
  INFO("places " << int{P});
  CHECK(o.differ == 0U);
  CHECK(o.decided > n / 3); // the fast path decides most inputs: the comparison is not vacuous
}

// What the dispatch runs: the decimal written with 6 places, then the 6-place copy. Places
// 0..8 (7 and 8 must give up) and mantissas that overflow when multiplied by 10^(6 − places).
void check_at6(rng &g, std::size_t n) {
  std::size_t decided = 0;
  std::size_t differ = 0;
  std::size_t gave_up_beyond_6 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const decimal eu = any_decimal(g, 8);
    const sc::linear s = any_scale(g);
    const sc::field f = any_field(g);
    const bool ranged = g.below(4) != 0U;
    const sc::range r = any_range(g, eu);
    fc::result<std::int64_t> out{errc::invalid_argument};
    if (!sc::decimal_detail::to_raw_decimal_at6(eu, s, f, ranged, r, out)) {
      if (eu.places > 6U) ++gave_up_beyond_6;
      continue;
    }
    if (eu.places > 6U) FAIL_CHECK("decided a decimal of " << int{eu.places} << " places");
    ++decided;
    if (!same(out, reference(eu, s, f, ranged, r)) && ++differ <= 5) {
      FAIL_CHECK("places " << int{eu.places} << " mantissa " << eu.mantissa << " scale "
                           << s.scale.mantissa << "e-" << int{s.scale.places} << " offset "
                           << s.offset.mantissa << "e-" << int{s.offset.places} << " field "
                           << int{f.bytes} << (f.is_signed ? "s" : "u"));
    }
  }
  CHECK(differ == 0U);
  CHECK(decided > n / 4); // not vacuous: most inputs of 0..6 places are decided here
  CHECK(gave_up_beyond_6 > 0U);
}

// The public to_raw with constant scales (the bench's and the DPQ's): in an optimised build the
// dispatch takes the fast path, in any build the result is the reference's.
template <sc::linear S, sc::field F>
void public_matches(rng &g, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const decimal eu = any_decimal(g, 8);
    const sc::range r = any_range(g, eu);
    CHECK(same(sc::to_raw(eu, S, F, r), reference(eu, S, F, true, r)));
    CHECK(same(sc::to_raw(eu, S, F), reference(eu, S, F, false, {})));
  }
}

} // namespace

// At compile time (the dispatch is constexpr): the example and an exact half.
static_assert(sc::to_raw(decimal{4000, 3}, {{32767, 2}, {0, 0}}, {4, false}, {{0, 0}, {5000, 0}})
                  .value() == 1311);
static_assert(sc::to_raw(decimal{-25, 1}, {{1, 0}, {0, 0}}, {2, true}).value() == -3);
static_assert([] {
  fc::result<std::int64_t> out{errc::invalid_argument};
  return sc::decimal_detail::to_raw_decimal_i64<1>(-25, {{1, 0}, {0, 0}}, {2, true}, false, {},
                                                   out) &&
         out.value() == -3;
}());

static_assert([] {
  fc::result<std::int64_t> out{errc::invalid_argument};
  return sc::decimal_detail::to_raw_decimal_at6({-25, 1}, {{1, 0}, {0, 0}}, {2, true}, false, {},
                                                out) &&
         out.value() == -3;
}());

TEST_CASE("to_raw(decimal): the constant-places fast path gives the reference's result") {
  constexpr std::size_t n = 300'000;
  run_places<0>(n);
  run_places<1>(n);
  run_places<2>(n);
  run_places<3>(n);
  run_places<4>(n);
  run_places<5>(n);
  run_places<6>(n);
}

TEST_CASE("to_raw(decimal): the 6-place normalisation the dispatch runs gives the reference's "
          "result") {
  rng g;
  for (int k = 0; k < 11; ++k) (void)g.next(); // a stream of its own
  check_at6(g, 1'000'000);
  // the multiplication by 10^(6 − places) overflows: nothing decided, the general code decides
  fc::result<std::int64_t> out{errc::invalid_argument};
  CHECK(!sc::decimal_detail::to_raw_decimal_at6({i64_max / 1000, 0}, {{1, 0}, {0, 0}}, {8, true},
                                                false, {}, out));
  CHECK(sc::to_raw(decimal{i64_max / 1000, 0}, {{1, 0}, {0, 0}}, {8, true}).value() ==
        i64_max / 1000);
  REQUIRE(sc::decimal_detail::to_raw_decimal_at6({40005, 4}, {{32767, 2}, {0, 0}}, {4, false}, true,
                                                 {{0, 0}, {100, 0}}, out));
  CHECK(out.value() == 1311); // 4.0005 × 327.67 = 1310.8438…
}

TEST_CASE("to_raw(decimal): exact halves, limits and overflow on the fast path") {
  fc::result<std::int64_t> out{errc::invalid_argument};
  namespace dd = sc::decimal_detail;
  // 4.0 bar × 327.67 = 1310.68 → 1311; 0.0015 × 1000 = 1.5 → 2; −1.5 → −2 (half away from zero)
  REQUIRE(dd::to_raw_decimal_i64<3>(4000, {{32767, 2}, {0, 0}}, {4, false}, true,
                                    {{0, 0}, {5000, 0}}, out));
  CHECK(out.value() == 1311);
  REQUIRE(dd::to_raw_decimal_i64<4>(15, {{1000, 0}, {0, 0}}, {2, true}, false, {}, out));
  CHECK(out.value() == 2);
  REQUIRE(dd::to_raw_decimal_i64<4>(-15, {{1000, 0}, {0, 0}}, {2, true}, false, {}, out));
  CHECK(out.value() == -2);
  REQUIRE(dd::to_raw_decimal_i64<4>(-14, {{1000, 0}, {0, 0}}, {2, true}, false, {}, out));
  CHECK(out.value() == -1);
  // range first, then scale, then field, as before
  REQUIRE(dd::to_raw_decimal_i64<0>(101, {{0, 0}, {0, 0}}, {0, false}, true, {{-100, 0}, {100, 0}},
                                    out));
  CHECK(out.error() == errc::out_of_range);
  REQUIRE(dd::to_raw_decimal_i64<0>(100, {{0, 0}, {0, 0}}, {2, false}, true, {{-100, 0}, {100, 0}},
                                    out));
  CHECK(out.error() == errc::invalid_argument);
  REQUIRE(dd::to_raw_decimal_i64<0>(-1, {{1, 0}, {0, 0}}, {2, false}, false, {}, out));
  CHECK(out.error() == errc::overflow);
  REQUIRE(dd::to_raw_decimal_i64<0>(1, {{1, 0}, {0, 0}}, {9, false}, false, {}, out));
  CHECK(out.error() == errc::invalid_argument);
  // what needs 128 bits is left to the general path (and the public to_raw gets it right)
  CHECK(!dd::to_raw_decimal_i64<0>(i64_max, {{10, 0}, {0, 0}}, {8, true}, false, {}, out));
  CHECK(sc::to_raw(decimal{i64_max, 0}, {{10, 0}, {0, 0}}, {8, true}).error() == errc::overflow);
  CHECK(!dd::to_raw_decimal_i64<6>(1, {{1, 13}, {0, 0}}, {8, true}, false, {}, out));
  CHECK(sc::to_raw(decimal{5, 6}, {{1, 13}, {0, 0}}, {8, true}).value() == 0);
  // INT64_MIN as the product: its magnitude is 2^63
  REQUIRE(dd::to_raw_decimal_i64<1>(i64_min, {{1, 0}, {0, 0}}, {8, true}, false, {}, out));
  CHECK(same(out, reference({i64_min, 1}, {{1, 0}, {0, 0}}, {8, true}, false, {})));
}

TEST_CASE("to_raw(decimal): the public function with constant scales") {
  rng g;
  public_matches<sc::linear{{32767, 2}, {0, 0}}, sc::field{2, false}>(g, 50'000);
  public_matches<sc::linear{{10, 0}, {-50, 0}}, sc::field{2, true}>(g, 50'000);
  public_matches<sc::linear{{105, 1}, {0, 0}}, sc::field{4, false}>(g, 50'000);
  public_matches<sc::linear{{1, 0}, {1, 0}}, sc::field{2, true}>(g, 50'000);
  public_matches<sc::linear{{163835, 1}, {0, 0}}, sc::field{8, true}>(g, 50'000);
}
