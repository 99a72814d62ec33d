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

/// round((eu − offset) × scale), half away from zero, exactly.
/// Errors: invalid_argument (zero scale or places > 18), overflow (result outside int64).
[[nodiscard]] constexpr result<std::int64_t> scale_to_raw(decimal eu, linear s) noexcept {
  if (s.scale.mantissa == 0 || eu.places > decimal_max_places ||
      s.offset.places > decimal_max_places || s.scale.places > decimal_max_places) {
    return errc::invalid_argument;
  }
  const unsigned p = eu.places > s.offset.places ? eu.places : s.offset.places;
  // Fast path: everything in int64 when nothing overflows (the usual case); same result.
  if (p + s.scale.places <= decimal_max_places) {
    std::int64_t a = 0;
    std::int64_t b = 0;
    std::int64_t diff = 0;
    std::int64_t prod = 0;
    if (detail::mul_i64(eu.mantissa, detail::pow10_i64(p - eu.places), a) &&
        detail::mul_i64(s.offset.mantissa, detail::pow10_i64(p - s.offset.places), b) &&
        detail::sub_i64(a, b, diff) && detail::mul_i64(diff, s.scale.mantissa, prod)) {
      return detail::round_div_i64(prod, detail::pow10_i64(p + s.scale.places));
    }
  }
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

/// The same from a double, read with 15 significant digits (see the header comment).
/// Errors: also not_representable (NaN, ∞, |eu| ≥ 9e18).
[[nodiscard]] constexpr result<std::int64_t> to_raw(double eu, linear s, field f,
                                                    range r) noexcept {
  FIELDCODEC_TRY(const decimal d, decimal_from_double(eu));
  return to_raw(d, s, f, r);
}
[[nodiscard]] constexpr result<std::int64_t> to_raw(double eu, linear s, field f) noexcept {
  FIELDCODEC_TRY(const decimal d, decimal_from_double(eu));
  return to_raw(d, s, f);
}

/// The same from a float, read as its shortest round-trip decimal (90.73f is 90.73).
/// Errors: also not_representable (NaN, ∞, |eu| > 9.2e18).
[[nodiscard]] constexpr result<std::int64_t> to_raw(float eu, linear s, field f, range r) noexcept {
  FIELDCODEC_TRY(const decimal d, decimal_from_float(eu));
  return to_raw(d, s, f, r);
}
[[nodiscard]] constexpr result<std::int64_t> to_raw(float eu, linear s, field f) noexcept {
  FIELDCODEC_TRY(const decimal d, decimal_from_float(eu));
  return to_raw(d, s, f);
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

} // namespace fieldcodec::scaling
