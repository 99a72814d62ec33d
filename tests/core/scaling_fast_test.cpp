// scaling::to_raw from a double or a float takes a fast path in binary floating point when the
// result cannot differ from the exact decimal computation (issue 18). This file proves that it
// never does: every result (value or error code) is compared with the code as it was before
// the fast path, kept here as the reference, over millions of inputs chosen to hit exact
// decimal halves, range limits, magnitudes from 1e-30 to 1e300 and every special value.
#include <fieldcodec/core/scaling.hpp>

#include <doctest/doctest.h>

#include "short_runs.hpp"
#include "xorshift.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <type_traits>

namespace fc = fieldcodec;
namespace sc = fieldcodec::scaling;
using fc::decimal;
using fc::errc;

namespace {

// The reference: to_raw(double/float) before issue 18 (read the decimal, convert it exactly).
fc::result<std::int64_t> reference(double eu, sc::linear s, sc::field f, const sc::range *r) {
  auto d = fc::decimal_from_double(eu);
  if (!d) return d.error();
  return r != nullptr ? sc::to_raw(d.value(), s, f, *r) : sc::to_raw(d.value(), s, f);
}
fc::result<std::int64_t> reference(float eu, sc::linear s, sc::field f, const sc::range *r) {
  auto d = fc::decimal_from_float(eu);
  if (!d) return d.error();
  return r != nullptr ? sc::to_raw(d.value(), s, f, *r) : sc::to_raw(d.value(), s, f);
}

template <class T>
fc::result<std::int64_t> under_test(T eu, sc::linear s, sc::field f, const sc::range *r) {
  return r != nullptr ? sc::to_raw(eu, s, f, *r) : sc::to_raw(eu, s, f);
}

bool same(const fc::result<std::int64_t> &a, const fc::result<std::int64_t> &b) {
  if (a.has_value() != b.has_value()) return false;
  return a.has_value() ? a.value() == b.value() : a.error() == b.error();
}

struct rng : fieldcodec::test::xorshift {
  rng() : xorshift(0x9E37'79B9'7F4A'7C15ULL) {}
  std::uint64_t below(std::uint64_t n) { return next() % n; }
};

constexpr std::array scales{
    sc::linear{{32767, 2}, {0, 0}},                 // DPQ pressure 327.67
    sc::linear{{10, 0}, {-50, 0}},                  // (x + 50) × 10
    sc::linear{{5, 0}, {0, 0}},                     // halves everywhere: x.x × 5
    sc::linear{{5, 1}, {0, 0}},                     // 0.5
    sc::linear{{500, 0}, {0, 0}},                   // 1.001 × 500 = 500.5
    sc::linear{{125, 2}, {25, 1}},                  // 1.25, offset 2.5
    sc::linear{{-4, 0}, {1, 3}},                    // negative scale
    sc::linear{{1, 0}, {0, 0}},                     // identity
    sc::linear{{1, 3}, {0, 0}},                     // 0.001
    sc::linear{{123'456'789, 5}, {-12'345, 3}},     // odd digits
    sc::linear{{1'000'000'000, 0}, {0, 0}},         // large products
    sc::linear{{3, 18}, {0, 0}},                    // tiny scale
    sc::linear{{9'007'199'254'740'993, 0}, {0, 0}}, // 2^53 + 1: not exact as a double
    sc::linear{{0, 0}, {0, 0}},                     // invalid: zero scale
    sc::linear{{1, 19}, {0, 0}},                    // invalid: 19 places
};
constexpr std::array fields{sc::field{2, false}, sc::field{4, true}, sc::field{8, true},
                            sc::field{1, false}, sc::field{0, false}};
constexpr std::array ranges{
    sc::range{{0, 0}, {100, 0}},
    sc::range{{-50, 0}, {150, 0}},
    sc::range{{15, 1}, {25, 1}},
    sc::range{{-1'000'000, 0}, {1'000'000, 0}},
    sc::range{{-1, 3}, {1, 3}},
    sc::range{{std::numeric_limits<std::int64_t>::min(), 0},
              {std::numeric_limits<std::int64_t>::max(), 0}}, // beyond 1e15: generic margins
    sc::range{{-5, 19}, {5, 19}},                             // 19 places: exact path only
    sc::range{{100, 0}, {0, 0}},                              // empty
    sc::range{{1'000'000'000'000'002, 13}, {1'000'000'000'000'001, 12}}, // 16 digits: the
    // 15-digit reading of a double a few ulps inside may fall outside (100.00000000000049 is
    // read as 100.000000000000 < 100.0000000000002)
};

// A double near a decimal that may sit on a half after scaling: m·10^-p, moved by a few ulps.
double decimal_double(rng &g) {
  const auto p = static_cast<int>(g.below(8));
  const std::uint64_t digits = g.below(16) + 1;
  const auto m = static_cast<double>(g.below(static_cast<std::uint64_t>(std::pow(10.0, digits))));
  double v = m / std::pow(10.0, p);
  if (g.below(2) == 0U) v = -v;
  switch (g.below(4)) {
  case 0: v = std::nextafter(v, 1e300); break;
  case 1: v = std::nextafter(v, -1e300); break;
  default: break;
  }
  return v;
}

// A double that lands (nearly) on a half-integer after scaling with `s`, or on a range limit.
double tricky_double(rng &g, sc::linear s, const sc::range &r) {
  const double scale = static_cast<double>(s.scale.mantissa) / std::pow(10.0, s.scale.places);
  const double off = static_cast<double>(s.offset.mantissa) / std::pow(10.0, s.offset.places);
  double v = 0;
  switch (g.below(3)) {
  case 0: {
    const double half =
        static_cast<double>(static_cast<std::int64_t>(g.below(2'000'000)) - 1'000'000) + 0.5;
    v = scale != 0.0 ? half / scale + off : half;
    break;
  }
  case 1: v = static_cast<double>(r.low.mantissa) / std::pow(10.0, r.low.places); break;
  default: v = static_cast<double>(r.high.mantissa) / std::pow(10.0, r.high.places); break;
  }
  for (auto k = g.below(40); k > 0; --k) v = std::nextafter(v, g.below(2) == 0U ? 1e300 : -1e300);
  return v;
}

double any_double(rng &g) {
  switch (g.below(6)) {
  case 0: return std::bit_cast<double>(g.next()); // every exponent, NaN and infinity included
  case 1: {
    const double specials[] = {0.0,
                               -0.0,
                               std::numeric_limits<double>::quiet_NaN(),
                               std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::denorm_min(),
                               1e-19,
                               5e-19,
                               1e15,
                               9e18,
                               1.001,
                               90.73,
                               4503599627370496.5};
    return specials[g.below(std::size(specials))];
  }
  default: return decimal_double(g);
  }
}

template <class T>
void compare_all(rng &g, int count, bool tricky) {
  int mismatches = 0;
  for (int i = 0; i < count; ++i) {
    const sc::linear s = scales[g.below(scales.size())];
    const sc::field f = fields[g.below(fields.size())];
    const sc::range &rr = ranges[g.below(ranges.size())];
    const sc::range *r = g.below(3) == 0U ? nullptr : &rr;
    const double d = tricky ? tricky_double(g, s, rr) : any_double(g);
    // (a double beyond the float range becomes the float infinity, not undefined behaviour)
    const T eu =
        std::is_same_v<T, float> && std::isfinite(d) &&
                std::fabs(d) > static_cast<double>(std::numeric_limits<float>::max())
            ? (d < 0 ? -std::numeric_limits<T>::infinity() : std::numeric_limits<T>::infinity())
            : static_cast<T>(d);
    const auto got = under_test(eu, s, f, r);
    const auto want = reference(eu, s, f, r);
    if (!same(got, want) && ++mismatches <= 10) {
      INFO("eu = ", static_cast<double>(eu), ", scale ", s.scale.mantissa, "e-",
           int{s.scale.places}, ", offset ", s.offset.mantissa, "e-", int{s.offset.places},
           ", range ", r != nullptr);
      CHECK(got.has_value() == want.has_value());
      if (got.has_value() && want.has_value()) CHECK(got.value() == want.value());
      if (!got.has_value() && !want.has_value()) CHECK(got.error() == want.error());
    }
  }
  CHECK(mismatches == 0);
}

} // namespace

TEST_CASE("to_raw(double): the fast path gives the exact path's result on every input") {
  rng g;
  compare_all<double>(g, fieldcodec_test::runs(400'000), false);
  compare_all<double>(g, fieldcodec_test::runs(400'000), true);
}

TEST_CASE("to_raw(float): the fast path gives the exact path's result on every input") {
  rng g;
  compare_all<float>(g, fieldcodec_test::runs(400'000), false);
  compare_all<float>(g, fieldcodec_test::runs(400'000), true);
}

// The cases the fast path must hand over to the exact one (each an exact decimal half or a
// limit); written out so that a regression names the input.
TEST_CASE("to_raw from binary: exact decimal halves and limits") {
  constexpr sc::linear x500{{500, 0}, {0, 0}};
  constexpr sc::field s32{4, true};
  CHECK(sc::to_raw(1.001, x500, s32).value() == 501);   // 500.5 → 501 (binary: 500.49999…)
  CHECK(sc::to_raw(-1.001, x500, s32).value() == -501); // half away from zero
  CHECK(sc::to_raw(1.001f, x500, s32).value() == 501);  // the float's shortest decimal 1.001
  CHECK(sc::to_raw(0.0, x500, s32, sc::range{{0, 0}, {1, 0}}).value() == 0); // at the limit
  CHECK(sc::to_raw(1.0, x500, s32, sc::range{{0, 0}, {1, 0}}).value() == 500);
  CHECK(sc::to_raw(std::nextafter(1.0, 2.0), x500, s32, sc::range{{0, 0}, {1, 0}}).value() ==
        500); // 1.0000000000000002 reads as 1 (15 digits): inside
  CHECK(sc::to_raw(1.0000001, x500, s32, sc::range{{0, 0}, {1, 0}}).error() == errc::out_of_range);
  CHECK(sc::to_raw(90.73f, sc::linear{{32767, 2}, {0, 0}}, s32).value() == 29729);
  constexpr sc::range sixteen{{1'000'000'000'000'002, 13}, {1000, 0}}; // 100.0000000000002
  CHECK(sc::to_raw(100.00000000000049, x500, s32, sixteen).error() == errc::out_of_range);
  static_assert(sc::to_raw(1.001, x500, s32).value() == 501);
  static_assert(sc::to_raw(90.73, sc::linear{{32767, 2}, {0, 0}}, s32).value() == 29729);
}
