// fieldcodec — linear engineering-unit scaling with exact decimals.
//
//   raw = round((eu − offset) × scale)      rounding half away from zero
//   eu  = raw / scale + offset
//
// Scale and offset are exact decimals (327.67 is 32767 × 10^-2). The arithmetic is exact
// (128-bit intermediates), so the only rounding is the one the formula asks for. A value is
// checked against the allowed range (errc::out_of_range) before it is converted and against
// the field's width and signedness (errc::overflow) after, so it can never wrap.
//
// The engineering value may be a decimal, a double, a float or any integer type; each is read
// as the number it is, then converted exactly:
//  * a double is the decimal it stands for with 15 significant digits (decimal_from_double):
//    1.001 × 500 is 500.5 and rounds to 501, as a person computing by hand expects, although
//    the nearest double to 1.001 is slightly smaller than 1.001;
//  * a float (a PLC REAL) is its shortest round-trip decimal (decimal_from_float), never
//    widened to double first: 90.73f × 327.67 = 29729.4991 gives 29729 (through double,
//    90.7300033569336 × 327.67 would give 29730);
//  * an integer is exact (a value beyond int64 is not_representable).
// Each kind has its own overload, so a call never converts one into another.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace fieldcodec::scaling {

/// The integer field a raw value travels in: 1..8 bytes, signed or unsigned.
struct field {
  std::uint8_t bytes = 4;
  bool is_signed = false;

  /// Smallest raw value the field holds.
  [[nodiscard]] constexpr std::int64_t min() const noexcept {
    return is_signed ? signed_min(bytes) : 0;
  }
  /// Largest raw value the field holds, limited to INT64_MAX (raw values are int64).
  [[nodiscard]] constexpr std::int64_t max() const noexcept {
    if (is_signed) return signed_max(bytes);
    return bytes >= 8U ? signed_max(8) : static_cast<std::int64_t>(unsigned_max(bytes));
  }
};

/// Scale and offset. The default is the identity.
struct linear {
  decimal scale{1, 0};
  decimal offset{0, 0};
};

/// Allowed engineering-unit range, both ends inclusive.
struct range {
  decimal low;
  decimal high;
};

/// Errors: overflow when `raw` does not fit `f`; invalid_argument for a field of 0 or > 8 bytes.
[[nodiscard]] constexpr status check_field(std::int64_t raw, field f) noexcept {
  if (f.bytes < 1U || f.bytes > 8U) return errc::invalid_argument;
  if (raw < f.min() || raw > f.max()) return errc::overflow;
  return {};
}

/// Errors: out_of_range when `eu` lies outside [r.low, r.high].
[[nodiscard]] constexpr status check_range(decimal eu, range r) noexcept {
  if (compare(eu, r.low) < 0 || compare(eu, r.high) > 0) return errc::out_of_range;
  return {};
}

namespace decimal_detail {
/// scale_to_raw's int64 path, for arguments it has checked (non-zero scale, places ≤ 18):
/// round((eu − offset) × scale) when nothing overflows int64; false (nothing decided) where
/// the 128-bit path is needed. Inlined so that constant places and scales fold (to_raw's
/// constant-places copies below call it too).
[[gnu::always_inline]] constexpr bool scale_to_raw_i64(decimal eu, linear s,
                                                       std::int64_t &raw) noexcept {
  namespace d = fieldcodec::detail;
  const unsigned p = eu.places > s.offset.places ? eu.places : s.offset.places;
  if (p + s.scale.places > decimal_max_places) return false;
  std::int64_t a = 0;
  std::int64_t b = 0;
  std::int64_t diff = 0;
  std::int64_t prod = 0;
  if (!(d::mul_i64(eu.mantissa, d::pow10_i64(p - eu.places), a) &&
        d::mul_i64(s.offset.mantissa, d::pow10_i64(p - s.offset.places), b) &&
        d::sub_i64(a, b, diff) && d::mul_i64(diff, s.scale.mantissa, prod))) {
    return false;
  }
  raw = d::round_div_i64(prod, d::pow10_i64(p + s.scale.places));
  return true;
}
} // namespace decimal_detail

/// round((eu − offset) × scale), half away from zero, exactly.
/// Errors: invalid_argument (zero scale or places > 18), overflow (result outside int64).
[[nodiscard]] constexpr result<std::int64_t> scale_to_raw(decimal eu, linear s) noexcept {
  if (s.scale.mantissa == 0 || eu.places > decimal_max_places ||
      s.offset.places > decimal_max_places || s.scale.places > decimal_max_places) {
    return errc::invalid_argument;
  }
  // Fast path: everything in int64 when nothing overflows (the usual case); same result.
  if (std::int64_t raw = 0; decimal_detail::scale_to_raw_i64(eu, s, raw)) return raw;
  const unsigned p = eu.places > s.offset.places ? eu.places : s.offset.places;
  detail::wide diff;
  detail::wide off;
  detail::widen(eu, p, diff);      // ≤ 63 + 60 bits, cannot fail
  detail::widen(s.offset, p, off); // then − offset, without negating the int64 (INT64_MIN)
  off.negative = !off.negative && !off.mag.is_zero();
  if (!detail::add(diff, off)) return errc::overflow;
  if (!detail::mul(diff.mag, detail::magnitude(s.scale.mantissa))) return errc::overflow;
  if (s.scale.mantissa < 0) diff.negative = !diff.negative;
  return detail::round_div_pow10(diff, p + s.scale.places);
}

namespace decimal_detail {
// The one implementation of to_raw(decimal …); `ranged` says whether r applies.
[[gnu::always_inline]] constexpr result<std::int64_t>
to_raw_decimal(decimal eu, linear s, field f, bool ranged, range r) noexcept {
  if (ranged) FIELDCODEC_TRY_STATUS(check_range(eu, r));
  FIELDCODEC_TRY(const std::int64_t raw, scale_to_raw(eu, s));
  FIELDCODEC_TRY_STATUS(check_field(raw, f));
  return raw;
}
// The same, never inlined: where the fast path below gives up (an int64 overflow, a limit of
// more than 18 places), so that its copies stay small.
[[gnu::noinline, gnu::cold]] constexpr result<std::int64_t>
to_raw_decimal_slow(decimal eu, linear s, field f, bool ranged, range r) noexcept {
  return to_raw_decimal(eu, s, f, ranged, r);
}

// to_raw_decimal in int64 only, for a decimal whose places are a compile-time constant (a
// template parameter, so that the copies stay distinct functions; see below): the checks in the
// same order with the same errors, compare()'s and scale_to_raw's own int64 paths; false
// (nothing decided) where those would need 128 bits.
template <std::uint8_t Places>
[[gnu::always_inline]] constexpr bool to_raw_decimal_i64(std::int64_t mantissa, linear s, field f,
                                                         bool ranged, range r,
                                                         result<std::int64_t> &out) noexcept {
  const decimal eu{mantissa, Places};
  if (ranged) {
    int lo = 0;
    int hi = 0;
    if (!fieldcodec::detail::compare_i64(eu, r.low, lo) ||
        !fieldcodec::detail::compare_i64(eu, r.high, hi)) {
      return false;
    }
    if (lo < 0 || hi > 0) {
      out = errc::out_of_range;
      return true;
    }
  }
  if (s.scale.mantissa == 0 || eu.places > decimal_max_places ||
      s.offset.places > decimal_max_places || s.scale.places > decimal_max_places) {
    out = errc::invalid_argument;
    return true;
  }
  std::int64_t raw = 0;
  if (!scale_to_raw_i64(eu, s, raw)) return false;
  if (const status st = check_field(raw, f); !st) {
    out = st.error();
  } else {
    out = raw;
  }
  return true;
}

// A decimal's places are usually known only at run time (text parsed by parse_decimal, a value
// from the network), so its powers of ten and the division by 10^(places + scale places) stay
// run-time operations even where scale, offset and range are constants (a named descriptor).
// For the precisions 0..6 (what a PLC, a text field or a parser hands over) the call first
// writes the decimal with exactly 6 places (one multiplication by 10^(6 − places), checked) and
// then runs the copy of the int64 path in which the places are the constant 6: the powers of
// ten fold, the range check compares mantissas and the division becomes a multiplication, as in
// code written for one precision. The value is the same decimal, so the checks, the exact
// arithmetic and the result are the same for every input; where the 6-place mantissa or a
// product would overflow int64 it gives up (false) and the general code decides
// (tests/core/scaling_decimal_fast_test.cpp keeps the previous code as its reference). (Round 3
// switched on the places to one copy per precision 0..6; the jump table and the larger frame
// cost ~8 instructions more than this multiplication.) Only where the scale and offset are
// compile-time constants after inlining (__builtin_constant_p), since otherwise nothing would
// fold; not in builds for size (-Os, __OPTIMIZE_SIZE__: on a Cortex-M a 64-bit division is a
// library call anyway).
[[gnu::always_inline]] constexpr bool to_raw_decimal_at6(decimal eu, linear s, field f, bool ranged,
                                                         range r,
                                                         result<std::int64_t> &out) noexcept {
  std::int64_t m = 0;
  return eu.places <= 6U &&
         fieldcodec::detail::mul_i64(eu.mantissa, fieldcodec::detail::pow10_i64(6U - eu.places),
                                     m) &&
         to_raw_decimal_i64<6>(m, s, f, ranged, r, out);
}

[[gnu::always_inline]] constexpr bool constant_scale(const linear &s) noexcept {
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
  return __builtin_constant_p(s.scale.mantissa) && __builtin_constant_p(s.scale.places) &&
         __builtin_constant_p(s.offset.mantissa) && __builtin_constant_p(s.offset.places);
#else
  (void)s;
  return false;
#endif
}

[[gnu::always_inline]] constexpr result<std::int64_t>
to_raw_decimal_dispatch(decimal eu, linear s, field f, bool ranged, range r) noexcept {
  if (constant_scale(s)) {
    result<std::int64_t> out{errc::invalid_argument};
    if (to_raw_decimal_at6(eu, s, f, ranged, r, out)) return out;
    return to_raw_decimal_slow(eu, s, f, ranged, r);
  }
  return to_raw_decimal(eu, s, f, ranged, r);
}
} // namespace decimal_detail

#if defined(__OPTIMIZE_SIZE__)
// Builds for size keep one copy of the conversion (see to_raw_decimal_dispatch).

/// PLC → device: range check, conversion, field check.
/// Errors: out_of_range, overflow, invalid_argument.
[[nodiscard]] constexpr result<std::int64_t> to_raw(decimal eu, linear s, field f,
                                                    range r) noexcept {
  FIELDCODEC_TRY_STATUS(check_range(eu, r));
  FIELDCODEC_TRY(const std::int64_t raw, scale_to_raw(eu, s));
  FIELDCODEC_TRY_STATUS(check_field(raw, f));
  return raw;
}

/// PLC → device without an engineering range (only the field limits apply).
[[nodiscard]] constexpr result<std::int64_t> to_raw(decimal eu, linear s, field f) noexcept {
  FIELDCODEC_TRY(const std::int64_t raw, scale_to_raw(eu, s));
  FIELDCODEC_TRY_STATUS(check_field(raw, f));
  return raw;
}
#else
/// PLC → device: range check, conversion, field check.
/// Errors: out_of_range, overflow, invalid_argument.
[[nodiscard, gnu::always_inline]] constexpr result<std::int64_t> to_raw(decimal eu, linear s,
                                                                        field f, range r) noexcept {
  return decimal_detail::to_raw_decimal_dispatch(eu, s, f, true, r);
}

/// PLC → device without an engineering range (only the field limits apply).
[[nodiscard, gnu::always_inline]] constexpr result<std::int64_t> to_raw(decimal eu, linear s,
                                                                        field f) noexcept {
  return decimal_detail::to_raw_decimal_dispatch(eu, s, f, false, {});
}
#endif

// Implementation of to_raw from a double or a float (not public API: a separate name, because
// `detail::` inside `scaling` must keep meaning fieldcodec::detail).
namespace binary_detail {
/// A decimal of at most 18 places as the nearest double, within 2.3e-16 of its value
/// (an exact power of ten, at most two roundings).
[[nodiscard]] constexpr double decimal_to_double(decimal d) noexcept {
  return static_cast<double>(d.mantissa) / detail::pow10_double(d.places);
}
/// |x| (at run time one instruction; `x < 0 ? -x : x` keeps -0 and compiles to a select).
[[nodiscard]] constexpr double abs_double(double x) noexcept {
  if (std::is_constant_evaluated()) return x < 0.0 ? -x : x;
  return __builtin_fabs(x);
}

/// The fast path of to_raw from a binary floating-point value, without building the decimal.
///
/// The exact path reads `eu` as a decimal d (decimal_from_double or decimal_from_float), checks
/// d against the range and rounds (d − offset) × scale half away from zero, exactly. The
/// decimal lies within `rel`·|eu| + 1e-18 of eu (decimal_from_double: |d − eu| ≤
/// 0.5625·10^-p with eu·10^p ≥ 10^14 when no place is cut, and ≤ 0.57·10^-18 when it is, so
/// rel = 1e-14 leaves more than 40 % to spare; decimal_from_float: within half a float ulp,
/// 2^-24·|eu|, so rel = 1.2e-7), and offset and scale as doubles within 2.3e-16 of theirs, so
/// y = (eu − offset) × scale computed in double lies within
/// tol = ((|eu| + |offset|)·(rel + 2e-15) + 2e-18)·|scale| of the exact product (the 2e-15
/// covers the conversions and the two roundings, 7e-16 together). The result is taken from y
/// only when the exact product cannot be on the other side of a half-integer
/// (|frac(y) − 0.5| > tol) and the decimal is clearly inside the range (by twice its distance
/// bound plus 2e-15 of the limit; with a range below 1e15 every bound uses the range's largest
/// magnitude instead of |eu|, which makes them constants): then rounding y and rounding
/// the exact product give the same integer, and the range check the same answer. Everything
/// else (exact halves such as 1.001 × 500, values at a range limit, huge or invalid values,
/// NaN) takes the exact path, so the result is always the exact path's. Proven by
/// tests/core/scaling_fast_test.cpp against the exact path on millions of inputs.
/// Returns false to mean "take the exact path"; `raw` is set only on true.
[[nodiscard]] constexpr bool to_raw_fast(double eu, double rel, linear s, bool ranged, range r,
                                         std::int64_t &raw) noexcept {
  if (s.scale.mantissa == 0 || s.scale.places > decimal_max_places ||
      s.offset.places > decimal_max_places) {
    return false; // the exact path reports invalid_argument
  }
  const double off = decimal_to_double(s.offset);
  const double sc = decimal_to_double(s.scale);
  const double rs = rel + 2e-15;
  const double a = abs_double(eu);
  // In constant evaluation, arithmetic on NaN or infinity is an error (Clang): leave those, and
  // everything the test below would send to the exact path anyway, to the exact path first.
  if (std::is_constant_evaluated() && !(a < 1e15)) return false;
  double near = a * (rel + 1e-15) + 1e-18; // |d − eu| bound, with the slack
  double tol = (a * rs + abs_double(off) * rs + 2e-18) * abs_double(sc);
  bool reach = false; // |eu| < 1e15 for certain: decimal_from_double / _from_float cannot fail
  bool small = false; // |y| < 2^50 for certain
  int sign = 0;       // the sign of y when it is known beforehand (1, −1), else 0
  if (ranged) {
    if (r.low.places > decimal_max_places || r.high.places > decimal_max_places) return false;
    const double lo = decimal_to_double(r.low);
    const double hi = decimal_to_double(r.high);
    const double bound = abs_double(lo) > abs_double(hi) ? abs_double(lo) : abs_double(hi);
    if (bound < 1e15) {
      // Inside the range |eu| < bound: the margins become constants when the range and the
      // scale are (a larger tolerance only sends more values to the exact path).
      near = bound * (rel + 1e-15) + 1e-18;
      tol = (bound * rs + abs_double(off) * rs + 2e-18) * abs_double(sc);
      reach = true;
      small = (bound + abs_double(off)) * abs_double(sc) < 1e15;
      if (lo >= off) sign = sc > 0 ? 1 : -1; // eu > lo ≥ offset
    }
    // d > low and d < high for certain (false for NaN); doubled margins cover the rounding of
    // these limits themselves.
    if (!(eu > lo + abs_double(lo) * 2e-15 + 2 * near &&
          eu < hi - abs_double(hi) * 2e-15 - 2 * near)) {
      return false;
    }
  }
  if (!reach && !(a < 1e15)) return false; // also NaN and infinity
  const double y = (eu - off) * sc;
  const double ay = sign > 0 ? y : (sign < 0 ? -y : abs_double(y));
  if (!small && !(ay < 1125899906842624.0)) return false; // 2^50: the fraction below is exact
  const auto t = static_cast<std::int64_t>(ay);
  const double frac = ay - static_cast<double>(t);
  if (abs_double(frac - 0.5) <= tol) return false; // possibly an exact half: decide exactly
  const std::int64_t m = t + (frac > 0.5 ? 1 : 0);
  raw = sign > 0 ? m : (sign < 0 ? -m : (y < 0.0 ? -m : m));
  return true;
}
} // namespace binary_detail

namespace binary_detail {
// The exact paths, out of line: the fast path stays small where it is inlined.
[[gnu::noinline]] constexpr result<std::int64_t> to_raw_exact(double eu, linear s, field f,
                                                              bool ranged, range r) noexcept {
  FIELDCODEC_TRY(const decimal d, decimal_from_double(eu));
  return ranged ? to_raw(d, s, f, r) : to_raw(d, s, f);
}
[[gnu::noinline]] constexpr result<std::int64_t> to_raw_exact(float eu, linear s, field f,
                                                              bool ranged, range r) noexcept {
  FIELDCODEC_TRY(const decimal d, decimal_from_float(eu));
  return ranged ? to_raw(d, s, f, r) : to_raw(d, s, f);
}
template <class Binary>
[[nodiscard]] constexpr result<std::int64_t> to_raw(Binary eu, linear s, field f, bool ranged,
                                                    range r) noexcept {
  // decimal_from_double is within 5.63e-15·|eu| (+ 1e-18), decimal_from_float within 2^-24·|eu|.
  constexpr double rel = std::is_same_v<Binary, float> ? 1.2e-7 : 1e-14;
  if (std::int64_t raw = 0; to_raw_fast(static_cast<double>(eu), rel, s, ranged, r, raw)) {
    FIELDCODEC_TRY_STATUS(check_field(raw, f));
    return raw;
  }
  return to_raw_exact(eu, s, f, ranged, r);
}
} // namespace binary_detail

/// The same from a double, read with 15 significant digits (see the header comment).
/// Errors: also not_representable (NaN, ∞, |eu| ≥ 9e18).
[[nodiscard]] constexpr result<std::int64_t> to_raw(double eu, linear s, field f,
                                                    range r) noexcept {
  return binary_detail::to_raw(eu, s, f, true, r);
}
[[nodiscard]] constexpr result<std::int64_t> to_raw(double eu, linear s, field f) noexcept {
  return binary_detail::to_raw(eu, s, f, false, {});
}

/// The same from a float, read as its shortest round-trip decimal (90.73f is 90.73).
/// Errors: also not_representable (NaN, ∞, |eu| > 9.2e18).
[[nodiscard]] constexpr result<std::int64_t> to_raw(float eu, linear s, field f, range r) noexcept {
  return binary_detail::to_raw(eu, s, f, true, r);
}
[[nodiscard]] constexpr result<std::int64_t> to_raw(float eu, linear s, field f) noexcept {
  return binary_detail::to_raw(eu, s, f, false, {});
}

/// An integer engineering value, exactly (any integer type; bool is refused at compile time).
/// Errors: also not_representable (an unsigned value above INT64_MAX).
template <std::integral I>
requires(!std::same_as<I, bool>)
    [[nodiscard]] constexpr result<std::int64_t> to_raw(I eu, linear s, field f, range r) noexcept {
  FIELDCODEC_TRY(const decimal d, decimal_from_integer(eu));
  return to_raw(d, s, f, r);
}
template <std::integral I>
requires(!std::same_as<I, bool>)
    [[nodiscard]] constexpr result<std::int64_t> to_raw(I eu, linear s, field f) noexcept {
  FIELDCODEC_TRY(const decimal d, decimal_from_integer(eu));
  return to_raw(d, s, f);
}
// A bool is not an engineering value (it would otherwise convert to float and double alike).
result<std::int64_t> to_raw(bool, linear, field, range) = delete;
result<std::int64_t> to_raw(bool, linear, field) = delete;

/// Device → PLC as a double: raw / scale + offset. Each decimal becomes a double with one
/// division by an exact power of ten (327.67 is 32767 / 100, the nearest double to 327.67),
/// then one division and one addition in binary.
[[nodiscard]] constexpr double to_eu(std::int64_t raw, linear s) noexcept {
  const double scale = static_cast<double>(s.scale.mantissa) / detail::pow10_double(s.scale.places);
  const double offset =
      static_cast<double>(s.offset.mantissa) / detail::pow10_double(s.offset.places);
  return static_cast<double>(raw) / scale + offset;
}

/// Device → PLC exactly, rounded half away from zero to `places` decimal places:
/// eu = (raw·10^(sp+op) + o·m) · 10^places / (m · 10^op) with scale = m·10^-sp and
/// offset = o·10^-op — one division, one rounding.
/// Errors: invalid_argument (zero scale, places > 18), overflow (intermediate beyond 128 bits,
/// m · 10^op beyond 64 bits, or result beyond int64).
[[nodiscard]] constexpr result<decimal> to_eu_decimal(std::int64_t raw, linear s,
                                                      unsigned places) noexcept {
  if (s.scale.mantissa == 0 || places > decimal_max_places ||
      s.offset.places > decimal_max_places || s.scale.places > decimal_max_places) {
    return errc::invalid_argument;
  }
  // Fast path: everything in int64 when nothing overflows (the usual case); same result.
  // n = raw·10^(sp+op+places) + o·m·10^places (for a constant `s`, o·m·10^places folds).
  const unsigned shift = s.scale.places + s.offset.places + places;
  if (shift <= decimal_max_places && s.scale.mantissa != std::numeric_limits<std::int64_t>::min()) {
    std::int64_t n = 0;
    std::int64_t om = 0;
    std::int64_t den = 0;
    const std::int64_t m = s.scale.mantissa < 0 ? -s.scale.mantissa : s.scale.mantissa;
    if (detail::mul_i64(raw, detail::pow10_i64(shift), n) &&
        detail::mul_i64(s.offset.mantissa, s.scale.mantissa, om) &&
        detail::mul_i64(om, detail::pow10_i64(places), om) && detail::add_i64(n, om, n) &&
        detail::mul_i64(m, detail::pow10_i64(s.offset.places), den)) {
      const std::int64_t q = detail::round_div_i64(n, den);
      return decimal{s.scale.mantissa < 0 ? -q : q, static_cast<std::uint8_t>(places)};
    }
  }
  detail::wide n;
  if (!detail::widen(decimal{raw, 0}, s.scale.places + s.offset.places, n)) return errc::overflow;
  detail::wide om;
  om.negative = (s.offset.mantissa < 0) != (s.scale.mantissa < 0);
  om.mag = detail::u128::from(detail::magnitude(s.offset.mantissa));
  if (!detail::mul(om.mag, detail::magnitude(s.scale.mantissa))) return errc::overflow;
  if (!detail::add(n, om)) return errc::overflow;
  for (unsigned i = 0; i < places; ++i) {
    if (!detail::mul(n.mag, 10U)) return errc::overflow;
  }
  detail::u128 den = detail::u128::from(detail::magnitude(s.scale.mantissa));
  for (unsigned i = 0; i < s.offset.places; ++i) {
    if (!detail::mul(den, 10U)) return errc::overflow;
  }
  if (!den.fits_u64()) return errc::overflow;
  const std::uint64_t d = den.low64();
  const std::uint64_t rem = detail::divmod64(n.mag, d);
  if (rem >= d - rem) { // remainder at least half: away from zero
    if (!detail::add(n.mag, detail::u128::from(1))) return errc::overflow;
  }
  if (s.scale.mantissa < 0) n.negative = !n.negative;
  FIELDCODEC_TRY(const std::int64_t m, detail::round_div_pow10(n, 0));
  return decimal{m, static_cast<std::uint8_t>(places)};
}

/// Smallest number of decimal places p (0..18) at which every raw value of a parameter with
/// this scale and offset survives raw → EU (rounded to p places) → raw unchanged: p must be at
/// least the offset's places and 10^p ≥ |scale| (then the rounding error of the EU, at most
/// ½·10^-p, moves raw by less than ½; when 10^p = |scale| the EU is exact). 327.67 → 3,
/// 10.5 → 2, 16383.5 → 5, 1 → 0.
/// Errors: invalid_argument (offset or scale with more than 18 places), not_representable
/// (|scale| > 10^18: no p ≤ 18 round-trips — found by fuzzing, F8). od/engineering.hpp shows
/// every scaled entry's value at these places; device folders use this same function.
[[nodiscard]] constexpr result<unsigned> round_trip_places(linear s) noexcept {
  if (s.offset.places > decimal_max_places || s.scale.places > decimal_max_places) {
    return errc::invalid_argument;
  }
  // |scale| without negating INT64_MIN (F3): its magnitude 2^63 is never a power of ten, so
  // comparing against INT64_MAX instead decides every "10^p >= |scale|" the same way.
  const std::int64_t m = s.scale.mantissa;
  const decimal mag{m == std::numeric_limits<std::int64_t>::min()
                        ? std::numeric_limits<std::int64_t>::max()
                    : m < 0 ? -m
                            : m,
                    s.scale.places};
  unsigned p = s.offset.places;
  std::int64_t pow = 1;
  for (unsigned i = 0; i < p; ++i) pow *= 10; // p <= 18: at most 10^18
  while (compare(decimal{pow, 0}, mag) < 0) {
    if (p == decimal_max_places) return errc::not_representable;
    ++p;
    pow *= 10;
  }
  return p;
}

} // namespace fieldcodec::scaling
