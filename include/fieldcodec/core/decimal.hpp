// fieldcodec — exact decimals and decimal fixed point.
//
// `decimal` is mantissa × 10^-places: 327.67 is {32767, 2}, never a binary double. Fixed point
// is an integer count of 10^-n units (positions in 0.001 mm are n = 3). Text conversion is
// strict: an optional '-', digits, optionally '.' and digits; nothing else.
#pragma once

#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <type_traits>

namespace fieldcodec {

/// An exact decimal number: mantissa × 10^-places (places 0..18).
struct decimal {
  std::int64_t mantissa = 0;
  std::uint8_t places = 0;
};

inline constexpr std::uint8_t decimal_max_places = 18;

namespace detail {

/// 10^n for n = 0..19.
inline constexpr std::array<std::uint64_t, 20> pow10_u64 = [] {
  std::array<std::uint64_t, 20> t{};
  std::uint64_t v = 1;
  for (auto &x : t) {
    x = v;
    v *= 10U; // wraps after 10^19, never stored
  }
  return t;
}();

/// 10^n as an int64 for n = 0..18.
[[nodiscard]] constexpr std::int64_t pow10_i64(unsigned n) noexcept {
  return static_cast<std::int64_t>(pow10_u64[n]);
}

// Checked int64 arithmetic (the builtins are constexpr in GCC and Clang). True on success.
constexpr bool mul_i64(std::int64_t a, std::int64_t b, std::int64_t &out) noexcept {
  return !__builtin_mul_overflow(a, b, &out);
}
constexpr bool add_i64(std::int64_t a, std::int64_t b, std::int64_t &out) noexcept {
  return !__builtin_add_overflow(a, b, &out);
}
constexpr bool sub_i64(std::int64_t a, std::int64_t b, std::int64_t &out) noexcept {
  return !__builtin_sub_overflow(a, b, &out);
}

/// round(num / den), half away from zero, den > 0. Cannot overflow.
[[nodiscard]] constexpr std::int64_t round_div_i64(std::int64_t num, std::int64_t den) noexcept {
  // On the magnitude: ⌊(|num| + ⌊den/2⌋) / den⌋ rounds half away from zero for every den > 0
  // (2·rem ≥ den ⟺ rem + ⌊den/2⌋ ≥ den), and an unsigned division by a constant compiles to a
  // multiplication where a signed quotient and remainder do not (issue 18). |num| + den/2 <
  // 2^64; the quotient is at most 2^63 (INT64_MIN / 1), negated without overflow in uint64.
  const auto d = static_cast<std::uint64_t>(den);
  const std::uint64_t mag = num < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(num)
                                    : static_cast<std::uint64_t>(num);
  const std::uint64_t q = (mag + d / 2U) / d;
  return num < 0 ? static_cast<std::int64_t>(std::uint64_t{0} - q) : static_cast<std::int64_t>(q);
}

/// Unsigned 128-bit magnitude as four 32-bit limbs, least significant first. Portable (no
/// __int128, works on 32-bit targets) and constexpr.
struct u128 {
  std::array<std::uint32_t, 4> limb{};

  static constexpr u128 from(std::uint64_t v) noexcept {
    u128 r;
    r.limb[0] = static_cast<std::uint32_t>(v);
    r.limb[1] = static_cast<std::uint32_t>(v >> 32U);
    return r;
  }
  [[nodiscard]] constexpr bool fits_u64() const noexcept { return limb[2] == 0U && limb[3] == 0U; }
  [[nodiscard]] constexpr std::uint64_t low64() const noexcept {
    return (std::uint64_t{limb[1]} << 32U) | limb[0];
  }
  [[nodiscard]] constexpr bool is_zero() const noexcept {
    return (limb[0] | limb[1] | limb[2] | limb[3]) == 0U;
  }
};

/// a × b; false when the product needs more than 128 bits.
constexpr bool mul(u128 &a, std::uint64_t b) noexcept {
  const std::uint32_t bl[2] = {static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(b >> 32U)};
  std::uint32_t out[6]{};
  for (std::size_t i = 0; i < 4; ++i) {
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < 2; ++j) {
      const std::uint64_t t = std::uint64_t{a.limb[i]} * bl[j] + out[i + j] + carry;
      out[i + j] = static_cast<std::uint32_t>(t);
      carry = t >> 32U;
    }
    out[i + 2] = static_cast<std::uint32_t>(carry);
  }
  for (std::size_t i = 0; i < 4; ++i) a.limb[i] = out[i];
  return out[4] == 0U && out[5] == 0U;
}

/// a / d, returns the remainder.
constexpr std::uint32_t divmod(u128 &a, std::uint32_t d) noexcept {
  std::uint64_t rem = 0;
  for (std::size_t i = 4; i-- > 0;) {
    const std::uint64_t cur = (rem << 32U) | a.limb[i];
    a.limb[i] = static_cast<std::uint32_t>(cur / d);
    rem = cur % d;
  }
  return static_cast<std::uint32_t>(rem);
}

/// a + b; false on carry out.
constexpr bool add(u128 &a, const u128 &b) noexcept {
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const std::uint64_t t = std::uint64_t{a.limb[i]} + b.limb[i] + carry;
    a.limb[i] = static_cast<std::uint32_t>(t);
    carry = t >> 32U;
  }
  return carry == 0U;
}

/// a - b, requires a >= b.
constexpr void sub(u128 &a, const u128 &b) noexcept {
  std::int64_t borrow = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    std::int64_t t = static_cast<std::int64_t>(a.limb[i]) - b.limb[i] - borrow;
    borrow = t < 0 ? 1 : 0;
    if (t < 0) t += std::int64_t{1} << 32U;
    a.limb[i] = static_cast<std::uint32_t>(t);
  }
}

constexpr int compare(const u128 &a, const u128 &b) noexcept {
  for (std::size_t i = 4; i-- > 0;) {
    if (a.limb[i] != b.limb[i]) return a.limb[i] < b.limb[i] ? -1 : 1;
  }
  return 0;
}

/// a / d for any non-zero 64-bit divisor (bitwise long division), returns the remainder.
constexpr std::uint64_t divmod64(u128 &a, std::uint64_t d) noexcept {
  u128 q;
  std::uint64_t rem = 0;
  for (std::size_t i = 128; i-- > 0;) {
    const std::uint64_t carry = rem >> 63U;
    rem = (rem << 1U) | ((a.limb[i / 32U] >> (i % 32U)) & 1U);
    if (carry != 0U || rem >= d) {
      rem -= d;
      q.limb[i / 32U] |= std::uint32_t{1} << (i % 32U);
    }
  }
  a = q;
  return rem;
}

/// A signed wide value: sign and 128-bit magnitude.
struct wide {
  bool negative = false;
  u128 mag;
};

constexpr std::uint64_t magnitude(std::int64_t v) noexcept {
  return v < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
}

/// d.mantissa × 10^(places − d.places) as a wide value (places >= d.places, places <= 36).
constexpr bool widen(decimal d, unsigned places, wide &out) noexcept {
  out.negative = d.mantissa < 0;
  out.mag = u128::from(magnitude(d.mantissa));
  for (unsigned i = d.places; i < places; ++i) {
    if (!mul(out.mag, 10U)) return false;
  }
  return true;
}

constexpr bool add(wide &a, const wide &b) noexcept {
  if (a.negative == b.negative) return add(a.mag, b.mag);
  if (compare(a.mag, b.mag) >= 0) {
    sub(a.mag, b.mag);
  } else {
    u128 t = b.mag;
    sub(t, a.mag);
    a.mag = t;
    a.negative = b.negative;
  }
  if (a.mag.is_zero()) a.negative = false;
  return true;
}

constexpr int compare(const wide &a, const wide &b) noexcept {
  const bool an = a.negative && !a.mag.is_zero();
  const bool bn = b.negative && !b.mag.is_zero();
  if (an != bn) return an ? -1 : 1;
  const int c = compare(a.mag, b.mag);
  return an ? -c : c;
}

/// round(a / 10^n), half away from zero, as int64. Errors: overflow.
constexpr result<std::int64_t> round_div_pow10(wide a, unsigned n) noexcept {
  unsigned digit = 0;
  for (unsigned i = 0; i < n; ++i) digit = divmod(a.mag, 10U);
  // Half away from zero: only the first discarded digit decides (>= 5 rounds the magnitude up).
  if (n > 0U && digit >= 5U) {
    if (!add(a.mag, u128::from(1))) return errc::overflow;
  }
  if (!a.mag.fits_u64()) return errc::overflow;
  const std::uint64_t m = a.mag.low64();
  const std::uint64_t limit = a.negative ? std::uint64_t{1} << 63U : (std::uint64_t{1} << 63U) - 1U;
  if (m > limit) return errc::overflow;
  return a.negative ? static_cast<std::int64_t>(std::uint64_t{0} - m)
                    : static_cast<std::int64_t>(m);
}

} // namespace detail

/// Exact comparison: negative, zero or positive.
namespace detail {
/// compare()'s int64 path: both brought to the same places in int64; false (nothing decided)
/// where that would overflow or a place count is over 18.
[[gnu::always_inline]] constexpr bool compare_i64(decimal a, decimal b, int &out) noexcept {
  if (a.places > decimal_max_places || b.places > decimal_max_places) return false;
  std::int64_t x = a.mantissa;
  std::int64_t y = b.mantissa;
  if (!(a.places >= b.places ? mul_i64(y, pow10_i64(a.places - b.places), y)
                             : mul_i64(x, pow10_i64(b.places - a.places), x))) {
    return false;
  }
  out = x < y ? -1 : (x > y ? 1 : 0);
  return true;
}
} // namespace detail

[[nodiscard]] constexpr int compare(decimal a, decimal b) noexcept {
  // Fast path: bring both to the same places in int64 when that cannot overflow.
  if (int c = 0; detail::compare_i64(a, b, c)) return c;
  const unsigned p = a.places > b.places ? a.places : b.places;
  detail::wide wa;
  detail::wide wb;
  detail::widen(a, p, wa); // at most 63 + 60 bits: cannot fail
  detail::widen(b, p, wb);
  return detail::compare(wa, wb);
}

/// Numeric equality (1.50 == 1.5).
[[nodiscard]] constexpr bool equal(decimal a, decimal b) noexcept { return compare(a, b) == 0; }

/// The same value with trailing fractional zeros removed (1.500 → 1.5, canonical form).
[[nodiscard]] constexpr decimal normalize(decimal d) noexcept {
  // Trailing zeros go 8, then 4, 2 and 1 at a time: a few divisions instead of one per zero.
  while (d.places >= 8U && d.mantissa % 100'000'000 == 0) {
    d.mantissa /= 100'000'000;
    d.places = static_cast<std::uint8_t>(d.places - 8U);
  }
  if (d.places >= 4U && d.mantissa % 10'000 == 0) {
    d.mantissa /= 10'000;
    d.places = static_cast<std::uint8_t>(d.places - 4U);
  }
  if (d.places >= 2U && d.mantissa % 100 == 0) {
    d.mantissa /= 100;
    d.places = static_cast<std::uint8_t>(d.places - 2U);
  }
  if (d.places >= 1U && d.mantissa % 10 == 0) {
    d.mantissa /= 10;
    d.places = static_cast<std::uint8_t>(d.places - 1U);
  }
  return d;
}

/// The value in units of 10^-places, exactly. Errors: not_representable (non-zero digits
/// beyond `places`), overflow (outside int64), invalid_argument (places > 18).
[[nodiscard]] constexpr result<std::int64_t> to_fixed(decimal d, unsigned places) noexcept {
  if (places > decimal_max_places || d.places > decimal_max_places) return errc::invalid_argument;
  if (d.places > places) { // the extra digits must be zeros
    const std::int64_t p = detail::pow10_i64(d.places - places);
    if (d.mantissa % p != 0) return errc::not_representable;
    return d.mantissa / p;
  }
  std::int64_t v = 0;
  if (!detail::mul_i64(d.mantissa, detail::pow10_i64(places - d.places), v)) return errc::overflow;
  return v;
}

/// The value in units of 10^-places, rounded half away from zero.
/// Errors: overflow, invalid_argument (places > 18).
[[nodiscard]] constexpr result<std::int64_t> round_to_fixed(decimal d, unsigned places) noexcept {
  if (places > decimal_max_places || d.places > decimal_max_places) return errc::invalid_argument;
  if (d.places <= places) return to_fixed(d, places);
  return detail::round_div_i64(d.mantissa, detail::pow10_i64(d.places - places));
}

namespace detail {
// The general parser: exact error classification and overflow checks on every digit.
[[nodiscard]] constexpr result<decimal> parse_decimal_checked(std::string_view s) noexcept {
  const bool neg = !s.empty() && s.front() == '-';
  if (neg) s.remove_prefix(1);
  const auto dot = s.find('.');
  const std::string_view ip = s.substr(0, dot);
  const std::string_view fp =
      dot == std::string_view::npos ? std::string_view{} : s.substr(dot + 1);
  if (ip.empty() || (dot != std::string_view::npos && fp.empty())) {
    for (char c : s) {
      if (!ascii::is_digit(c) && c != '.') return errc::bad_digit;
    }
    return errc::bad_syntax;
  }
  if (fp.size() > decimal_max_places) return errc::overflow;
  std::uint64_t m = 0;
  const std::uint64_t limit = neg ? std::uint64_t{1} << 63U : (std::uint64_t{1} << 63U) - 1U;
  for (std::string_view part : {ip, fp}) {
    for (const char c : part) {
      if (!ascii::is_digit(c)) return errc::bad_digit;
      const auto d = static_cast<std::uint64_t>(c - '0');
      if (m > (limit - d) / 10U) return errc::overflow;
      m = m * 10U + d;
    }
  }
  const auto sm =
      neg ? static_cast<std::int64_t>(std::uint64_t{0} - m) : static_cast<std::int64_t>(m);
  return decimal{sm, static_cast<std::uint8_t>(fp.size())};
}
} // namespace detail

/// Parse strict decimal text: `-?[0-9]+(\.[0-9]+)?`. Trailing fractional zeros are kept in
/// `places` ("5552.0" is {55520, 1}). Errors: bad_syntax (empty, lone '-', '.' without digits
/// on both sides), bad_digit (any other character), overflow (more than 18 significant digits
/// or more than 18 places).
[[nodiscard]] constexpr result<decimal> parse_decimal(std::string_view s) noexcept {
  // One pass over well-formed text of at most 18 digits (which cannot overflow); anything else
  // goes to the checked parser, which classifies the error.
  const std::size_t n = s.size();
  const bool neg = n != 0U && s[0] == '-';
  std::size_t i = neg ? 1U : 0U;
  const std::size_t int_start = i;
  std::uint64_t m = 0;
  while (i < n && ascii::is_digit(s[i])) m = m * 10U + static_cast<std::uint64_t>(s[i++] - '0');
  const std::size_t int_digits = i - int_start;
  std::size_t frac_digits = 0;
  bool dot = false;
  if (i < n && s[i] == '.') {
    dot = true;
    const std::size_t frac_start = ++i;
    while (i < n && ascii::is_digit(s[i])) m = m * 10U + static_cast<std::uint64_t>(s[i++] - '0');
    frac_digits = i - frac_start;
  }
  if (i != n || int_digits == 0U || (dot && frac_digits == 0U) || int_digits + frac_digits > 18U) {
    return detail::parse_decimal_checked(s);
  }
  const auto sm = static_cast<std::int64_t>(m); // < 10^18
  return decimal{neg ? -sm : sm, static_cast<std::uint8_t>(frac_digits)};
}

/// Write `d` with exactly d.places fractional digits ("-1055.88"; "0.05"; "-0.5").
/// Returns the number of characters. Errors: buffer_too_small, invalid_argument (places > 18).
[[nodiscard]] constexpr result<std::size_t> format_decimal(decimal d,
                                                           std::span<char> out) noexcept {
  if (d.places > decimal_max_places) return errc::invalid_argument;
  // Built backwards: fractional digits, '.', at least one integer digit, sign.
  char tmp[1 + 20 + 1 + decimal_max_places]{};
  std::size_t k = sizeof tmp;
  std::uint64_t m = detail::magnitude(d.mantissa);
  for (std::size_t i = 0; i < d.places; ++i) {
    tmp[--k] = static_cast<char>('0' + static_cast<int>(m % 10U));
    m /= 10U;
  }
  if (d.places > 0U) tmp[--k] = '.';
  do {
    tmp[--k] = static_cast<char>('0' + static_cast<int>(m % 10U));
    m /= 10U;
  } while (m != 0U);
  if (d.mantissa < 0) tmp[--k] = '-';
  const std::size_t len = sizeof tmp - k;
  if (out.size() < len) return errc::buffer_too_small;
  for (std::size_t i = 0; i < len; ++i) out[i] = tmp[k + i];
  return len;
}

/// Parse decimal text into units of 10^-places ("-1055.88" at 2 → −105588). More fractional
/// digits than `places` are accepted only if they are zeros. Errors: those of parse_decimal,
/// not_representable (non-zero digits beyond `places`), overflow.
[[nodiscard]] constexpr result<std::int64_t> parse_fixed(std::string_view s,
                                                         unsigned places) noexcept {
  FIELDCODEC_TRY(const decimal d, parse_decimal(s));
  return to_fixed(d, places);
}

/// Write `units` × 10^-places with exactly `places` fractional digits.
[[nodiscard]] constexpr result<std::size_t> format_fixed(std::int64_t units, unsigned places,
                                                         std::span<char> out) noexcept {
  if (places > decimal_max_places) return errc::invalid_argument;
  return format_decimal(decimal{units, static_cast<std::uint8_t>(places)}, out);
}

namespace detail {
/// 10^k as a double for k = 0..22 (all exact).
inline constexpr std::array<double, 23> pow10_double_table = [] {
  std::array<double, 23> t{};
  double v = 1.0;
  for (auto &x : t) {
    x = v;
    v *= 10.0;
  }
  return t;
}();
/// 10^k as a double, exact for k = 0..22.
constexpr double pow10_double(unsigned k) noexcept {
  if (k < pow10_double_table.size()) return pow10_double_table[k];
  double v = pow10_double_table.back();
  for (unsigned i = 22; i < k; ++i) v *= 10.0;
  return v;
}
} // namespace detail

/// The decimal a binary double stands for, to `significant` digits (1..17, default 15).
/// Every decimal of up to 15 significant digits survives the trip through a double, so the
/// default recovers the number a user typed (1.001, not 1.000999999999999889...). Digits
/// beyond 18 decimal places are rounded away (|v| < 5e-19 becomes 0).
/// Errors: invalid_argument (significant not 1..17), not_representable (NaN, infinity,
/// |v| >= 9e18).
[[nodiscard]] constexpr result<decimal> decimal_from_double(double v,
                                                            unsigned significant = 15) noexcept {
  if (significant < 1U || significant > 17U) return errc::invalid_argument;
  if (v != v) return errc::not_representable;
  const bool neg = v < 0;
  const double a = neg ? -v : v;
  if (a == 0.0) return decimal{0, 0};
  if (a >= 9.0e18) return errc::not_representable; // also catches infinity
  // magnitude: a < 10^int_digits (exact comparisons against exact powers of ten)
  int int_digits = 0;
  while (int_digits < 19 && a >= detail::pow10_double(static_cast<unsigned>(int_digits))) {
    ++int_digits;
  }
  int places = static_cast<int>(significant) - int_digits;
  if (int_digits == 0) {
    // leading zeros after the point do not count as significant
    int zeros = 0;
    while (zeros < decimal_max_places &&
           a * detail::pow10_double(static_cast<unsigned>(zeros + 1)) < 1.0) {
      ++zeros;
    }
    places += zeros;
  }
  if (places < 0) places = 0;
  if (places > decimal_max_places) places = decimal_max_places;
  // One multiplication by an exact power of ten: a single rounding step.
  const double scaled = a * detail::pow10_double(static_cast<unsigned>(places));
  if (scaled >= 9.0e18) return errc::not_representable;
  auto m = static_cast<std::int64_t>(scaled);
  if (scaled - static_cast<double>(m) >= 0.5) ++m; // half away from zero on the magnitude
  return normalize(decimal{neg ? -m : m, static_cast<std::uint8_t>(places)});
}

/// An integer as a decimal with no places, exactly (any integer type but bool).
/// Errors: not_representable (an unsigned value above INT64_MAX).
template <std::integral I>
requires(!std::same_as<I, bool>)
    [[nodiscard]] constexpr result<decimal> decimal_from_integer(I v) noexcept {
  if constexpr (std::is_unsigned_v<I>) {
    if (static_cast<std::uint64_t>(v) >
        static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      return errc::not_representable;
    }
  }
  return decimal{static_cast<std::int64_t>(v), 0};
}

namespace detail {
/// floor(x · log10 2) for |x| < 2^20 (log10 2 · 2^32 = 1292913986.08; the error stays far
/// below the distance of any x · log10 2 from an integer in that range, except x = 0).
[[nodiscard]] constexpr int floor_log10_pow2(int x) noexcept {
  return static_cast<int>((static_cast<std::int64_t>(x) * 1'292'913'986) >> 32U);
}

/// floor(n × 10^s × 2^e2) for n < 2^27 and s ≤ 19, which the caller knows to be below 2^64;
/// `exact` tells whether nothing was cut off.
constexpr std::uint64_t scaled_floor(std::uint64_t n, unsigned s, int e2, bool &exact) noexcept {
  // n × 10^s as hi·2^64 + lo, from 32-bit halves (no __int128: works on 32-bit targets).
  const std::uint64_t b = pow10_u64[s];
  const std::uint64_t low = n * (b & 0xFFFF'FFFFU); // < 2^59
  const std::uint64_t high = n * (b >> 32U);        // < 2^59
  const std::uint64_t lo = low + (high << 32U);
  const std::uint64_t hi = (high >> 32U) + (lo < low ? 1U : 0U);
  if (e2 >= 0) { // v ≥ 2^25 here, so s ≤ 2 and n × 10^s fits 64 bits
    exact = true;
    return lo << static_cast<unsigned>(e2);
  }
  const auto k = static_cast<unsigned>(-e2);
  if (k >= 128U) {
    exact = (hi | lo) == 0U;
    return 0;
  }
  if (k >= 64U) {
    const unsigned r = k - 64U;
    exact = lo == 0U && (r == 0U || (hi & ((std::uint64_t{1} << r) - 1U)) == 0U);
    return hi >> r;
  }
  exact = (lo & ((std::uint64_t{1} << k) - 1U)) == 0U;
  return (lo >> k) | (k == 0U ? 0U : hi << (64U - k));
}
} // namespace detail

/// The shortest decimal that reads back as the same float: 90.73f is 90.73 (not the
/// 90.7300033569336 that widening to double first would give), 1e-5f is 0.00001, 16777216.0f is
/// 16777216. Of several shortest candidates the one nearest the float wins (ties: even last
/// digit), as with std::to_chars. Exact integer arithmetic, no tables, constexpr.
/// Limits of `decimal`: a float whose shortest form needs more than 18 decimal places
/// (|v| < 1e-9 or so) is rounded to 18 places instead (|v| < 5e-19 becomes 0), like
/// decimal_from_double. Errors: not_representable (NaN, infinity, or a mantissa beyond int64:
/// |v| > 9.223372e18).
[[nodiscard]] constexpr result<decimal> decimal_from_float(float v) noexcept {
  const auto bits = std::bit_cast<std::uint32_t>(v);
  const bool neg = (bits >> 31U) != 0U;
  const std::uint32_t biased = (bits >> 23U) & 0xFFU;
  const std::uint32_t frac = bits & 0x7F'FFFFU;
  if (biased == 0xFFU) return errc::not_representable;  // NaN, infinity
  if (biased == 0U && frac == 0U) return decimal{0, 0}; // ±0
  // v = m × 2^e exactly, m < 2^24.
  const std::uint64_t m = biased == 0U ? frac : (frac | 0x80'0000U);
  const int e = biased == 0U ? -149 : static_cast<int>(biased) - 150;
  if (e > 40) return errc::not_representable; // |v| >= 2^64: far beyond int64

  // The floats near v round to v on the interval between the midpoints to its neighbours, in
  // units of 2^(e-2): low = 4m − 2 (4m − 1 at the bottom of a binade, where the gap below is
  // half as wide), high = 4m + 2. The midpoints themselves belong to v when m is even
  // (round-half-even on reading).
  const int e2 = e - 2;
  const std::uint64_t mv = 4U * m;
  const bool binade_bottom = frac == 0U && biased > 1U;
  const std::uint64_t mm = mv - (binade_bottom ? 1U : 2U);
  const std::uint64_t mp = mv + 2U;
  const bool accept_bounds = (m & 1U) == 0U;

  // Count in units of 10^-p. A float needs at most 9 significant digits, and v ≥ 2^(e+23) ≥
  // 10^f with f = floor((e + 23) · log10 2), so its shortest form has at most 8 − f places:
  // p = 9 − f is one digit finer (that digit decides the rounding), capped at 19 places (one
  // more than a decimal holds). v < 2^(e+24) < 10^(f+2), so v × 10^p < 10^11: no overflow.
  const int f = detail::floor_log10_pow2(e + 23);
  const auto p = static_cast<unsigned>(9 - f < 0 ? 0 : (9 - f > 19 ? 19 : 9 - f));
  bool vr_exact = false;
  bool vp_exact = false;
  bool vm_exact = false;
  std::uint64_t vr = detail::scaled_floor(mv, p, e2, vr_exact);
  std::uint64_t vp = detail::scaled_floor(mp, p, e2, vp_exact);
  std::uint64_t vm = detail::scaled_floor(mm, p, e2, vm_exact);

  // Cut digits while the interval still holds a candidate (Ryu's general case, with exact
  // values instead of its tables), then round what is left to the nearest candidate.
  bool vm_trailing_zeros = accept_bounds && vm_exact; // vm itself is a candidate
  bool vr_trailing_zeros = vr_exact;                  // all digits cut off vr so far are 0
  if (!accept_bounds && vp_exact) --vp;               // the upper midpoint is excluded
  unsigned removed = 0;
  unsigned last_removed = 0;
  while (vp / 10U > vm / 10U) {
    vm_trailing_zeros = vm_trailing_zeros && vm % 10U == 0U;
    vr_trailing_zeros = vr_trailing_zeros && last_removed == 0U;
    last_removed = static_cast<unsigned>(vr % 10U);
    vr /= 10U;
    vp /= 10U;
    vm /= 10U;
    ++removed;
  }
  if (vm_trailing_zeros) {
    while (vm % 10U == 0U) {
      vr_trailing_zeros = vr_trailing_zeros && last_removed == 0U;
      last_removed = static_cast<unsigned>(vr % 10U);
      vr /= 10U;
      vp /= 10U;
      vm /= 10U;
      ++removed;
    }
  }
  std::uint64_t out = 0;
  if (p > removed + decimal_max_places) {
    // Nothing was cut at 19 places: no decimal of at most 18 places reads back as v (only for
    // |v| < 1e-9 or so). Round v itself to 18 places, half up (an exact tie cannot occur this
    // far below 1).
    out = vr / 10U + (vr % 10U >= 5U ? 1U : 0U);
    removed = 1;
  } else {
    // At least one digit was cut (with p ≤ 18 the shortest form is coarser than 10^-p, and for
    // p = 19 the branch above caught the other case), so last_removed and vr_trailing_zeros
    // describe the exact remainder.
    if (vr_trailing_zeros && last_removed == 5U && vr % 2U == 0U) last_removed = 4U; // tie: even
    const bool below_interval = vr == vm && (!accept_bounds || !vm_trailing_zeros);
    out = vr + ((below_interval || last_removed >= 5U) ? 1U : 0U);
  }
  // out × 10^(removed − p); fewer than 10 significant digits, so out < 2^63 when places remain.
  decimal d{};
  if (removed >= p) {
    std::int64_t mant = 0;
    if (removed - p > decimal_max_places ||
        out > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()) ||
        !detail::mul_i64(static_cast<std::int64_t>(out), detail::pow10_i64(removed - p), mant)) {
      return errc::not_representable;
    }
    d = decimal{mant, 0};
  } else {
    d = decimal{static_cast<std::int64_t>(out), static_cast<std::uint8_t>(p - removed)};
  }
  if (neg) d.mantissa = -d.mantissa;
  return normalize(d);
}

} // namespace fieldcodec
