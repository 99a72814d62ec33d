// fieldcodec — packed BCD (two decimal digits per byte, high nibble first).
//
// Unsigned: N bytes hold 2N digits. Signed: one sign byte (0x00 positive, 0xFF negative)
// followed by the unsigned digits, as some drives send positions.
#pragma once

#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::bcd {

/// Largest number of digit bytes handled (18 digits always fit a uint64_t).
inline constexpr std::size_t max_bytes = 9;

/// Sign byte values of the signed form.
inline constexpr std::uint8_t sign_positive = 0x00;
inline constexpr std::uint8_t sign_negative = 0xFF;

/// 10^n for n = 0..19.
[[nodiscard]] constexpr std::uint64_t pow10(std::size_t n) noexcept {
  std::uint64_t v = 1;
  for (std::size_t i = 0; i < n; ++i) v *= 10U;
  return v;
}

/// Decode all bytes of `in` as 2·size digits. Errors: bad_length (empty or more than
/// max_bytes), bad_digit (a nibble A–F).
[[nodiscard]] constexpr result<std::uint64_t> decode(std::span<const std::uint8_t> in) noexcept {
  if (in.empty() || in.size() > max_bytes) return errc::bad_length;
  // Two bytes (four digits) per step: half the loop overhead of a byte loop.
  std::uint64_t v = 0;
  std::size_t i = in.size() % 2U;
  if (i != 0U) {
    const unsigned hi = in[0] >> 4U;
    const unsigned lo = in[0] & 0x0FU;
    if (hi > 9U || lo > 9U) return errc::bad_digit;
    v = hi * 10U + lo;
  }
  for (; i < in.size(); i += 2U) {
    const unsigned a = in[i];
    const unsigned b = in[i + 1U];
    if ((a >> 4U) > 9U || (a & 0x0FU) > 9U || (b >> 4U) > 9U || (b & 0x0FU) > 9U) {
      return errc::bad_digit;
    }
    v = v * 10000U + (a >> 4U) * 1000U + (a & 0x0FU) * 100U + (b >> 4U) * 10U + (b & 0x0FU);
  }
  return v;
}

namespace detail {
/// The digits of `value` into all bytes of `out`, leading zeros; `value` must fit (checked by
/// the callers). One loop for the span and the fixed-size forms.
constexpr void write_digits(std::uint64_t value, std::span<std::uint8_t> out) noexcept {
  for (std::size_t i = out.size(); i-- > 0;) {
    const auto lo = static_cast<unsigned>(value % 10U);
    value /= 10U;
    const auto hi = static_cast<unsigned>(value % 10U);
    value /= 10U;
    out[i] = static_cast<std::uint8_t>((hi << 4U) | lo);
  }
}
} // namespace detail

/// Encode `value` into all bytes of `out` (2·size digits, leading zeros).
/// Errors: bad_length (empty or more than max_bytes), overflow (more digits than fit).
[[nodiscard]] constexpr status encode(std::uint64_t value, std::span<std::uint8_t> out) noexcept {
  if (out.empty() || out.size() > max_bytes) return errc::bad_length;
  if (value >= pow10(2U * out.size())) return errc::overflow;
  detail::write_digits(value, out);
  return {};
}

/// Fixed-size form of encode().
template <std::size_t N>
[[nodiscard]] constexpr result<std::array<std::uint8_t, N>> encode(std::uint64_t value) noexcept {
  static_assert(N >= 1 && N <= max_bytes);
  std::array<std::uint8_t, N> out{};
  FIELDCODEC_TRY_STATUS(encode(value, out));
  return out;
}

/// Decode a sign byte followed by digit bytes. Errors: bad_length (fewer than 2 or more than
/// 1 + max_bytes bytes), bad_sign (sign byte not 0x00/0xFF), bad_digit.
/// Negative zero (0xFF, 0…0) decodes as 0.
[[nodiscard]] constexpr result<std::int64_t>
decode_signed(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < 2U || in.size() > 1U + max_bytes) return errc::bad_length;
  const std::uint8_t sign = in[0];
  if (sign != sign_positive && sign != sign_negative) return errc::bad_sign;
  FIELDCODEC_TRY(const std::uint64_t mag, decode(in.subspan(1)));
  const auto m = static_cast<std::int64_t>(mag); // < 10^18, fits
  return sign == sign_negative ? -m : m;
}

/// Encode `value` as sign byte + digit bytes into all of `out`. Zero is always positive.
/// Errors: bad_length, overflow (magnitude has more digits than fit).
[[nodiscard]] constexpr status encode_signed(std::int64_t value,
                                             std::span<std::uint8_t> out) noexcept {
  if (out.size() < 2U || out.size() > 1U + max_bytes) return errc::bad_length;
  // magnitude without overflow for INT64_MIN
  const std::uint64_t mag = value < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(value)
                                      : static_cast<std::uint64_t>(value);
  FIELDCODEC_TRY_STATUS(encode(mag, out.subspan(1)));
  out[0] = value < 0 ? sign_negative : sign_positive;
  return {};
}

/// Fixed-size form of encode_signed(); N counts the sign byte.
template <std::size_t N>
[[nodiscard]] constexpr result<std::array<std::uint8_t, N>>
encode_signed(std::int64_t value) noexcept {
  static_assert(N >= 2 && N <= 1 + max_bytes);
  // the span form's checks with N known: no length test, the limit a constant (issue 18)
  const std::uint64_t mag = value < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(value)
                                      : static_cast<std::uint64_t>(value);
  if (mag >= pow10(2U * (N - 1U))) return errc::overflow;
  std::array<std::uint8_t, N> out{};
  out[0] = value < 0 ? sign_negative : sign_positive;
  detail::write_digits(mag, std::span<std::uint8_t>(out).subspan(1));
  return out;
}

} // namespace fieldcodec::bcd
