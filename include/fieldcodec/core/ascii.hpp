// fieldcodec — integers as ASCII text, strictly: no locale, no whitespace, no allocation.
//
// Decimal fractions (fixed point and exact decimals as text) are in decimal.hpp, built on this.
#pragma once

#include <fieldcodec/core/result.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>

namespace fieldcodec::ascii {

/// Which letters a hexadecimal parser accepts.
enum class hex_case : std::uint8_t { upper, lower, any };

[[nodiscard]] constexpr bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }

/// Value of a hex digit, or -1.
[[nodiscard]] constexpr int hex_value(char c, hex_case letters = hex_case::any) noexcept {
  if (is_digit(c)) return c - '0';
  if (letters != hex_case::lower && c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (letters != hex_case::upper && c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

/// The byte written as the two hex digits `hi` `lo` (0..255), or -1 if either is not a hex digit.
[[nodiscard]] constexpr int hex_byte(char hi, char lo, hex_case letters = hex_case::any) noexcept {
  const int h = hex_value(hi, letters);
  const int l = hex_value(lo, letters);
  return h < 0 || l < 0 ? -1 : h * 16 + l;
}

/// Parse a non-empty string of decimal digits. No sign, no spaces.
/// Errors: bad_syntax (empty), bad_digit, overflow (> UINT64_MAX).
[[nodiscard]] constexpr result<std::uint64_t> parse_unsigned(std::string_view s) noexcept {
  if (s.empty()) return errc::bad_syntax;
  std::uint64_t v = 0;
  constexpr auto max = std::numeric_limits<std::uint64_t>::max();
  for (const char c : s) {
    if (!is_digit(c)) return errc::bad_digit;
    const auto d = static_cast<std::uint64_t>(c - '0');
    if (v > (max - d) / 10U) return errc::overflow;
    v = v * 10U + d;
  }
  return v;
}

/// Parse an optional '-' followed by decimal digits ("+" is not accepted).
/// Errors: bad_syntax (empty or a lone '-'), bad_digit, overflow (outside int64).
[[nodiscard]] constexpr result<std::int64_t> parse_signed(std::string_view s) noexcept {
  const bool neg = !s.empty() && s.front() == '-';
  if (neg) s.remove_prefix(1);
  FIELDCODEC_TRY(const std::uint64_t m, parse_unsigned(s));
  const std::uint64_t limit = neg ? std::uint64_t{1} << 63U : (std::uint64_t{1} << 63U) - 1U;
  if (m > limit) return errc::overflow;
  return neg ? static_cast<std::int64_t>(std::uint64_t{0} - m) : static_cast<std::int64_t>(m);
}

/// Parse a non-empty string of hex digits, no prefix.
/// Errors: bad_syntax (empty), bad_digit (incl. letters of the wrong case), overflow.
[[nodiscard]] constexpr result<std::uint64_t> parse_hex(std::string_view s,
                                                        hex_case letters = hex_case::any) noexcept {
  if (s.empty()) return errc::bad_syntax;
  std::uint64_t v = 0;
  for (const char c : s) {
    const int d = hex_value(c, letters);
    if (d < 0) return errc::bad_digit;
    if ((v >> 60U) != 0U) return errc::overflow;
    v = (v << 4U) | static_cast<std::uint64_t>(d);
  }
  return v;
}

/// Write the decimal digits of `v` into `out`; returns the number of characters written.
/// Errors: buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> format_unsigned(std::uint64_t v,
                                                            std::span<char> out) noexcept {
  char tmp[20]{};
  std::size_t n = 0;
  do {
    tmp[n++] = static_cast<char>('0' + static_cast<int>(v % 10U));
    v /= 10U;
  } while (v != 0U);
  if (out.size() < n) return errc::buffer_too_small;
  for (std::size_t i = 0; i < n; ++i) out[i] = tmp[n - 1U - i];
  return n;
}

/// Write `v` in decimal with a leading '-' when negative. Errors: buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> format_signed(std::int64_t v,
                                                          std::span<char> out) noexcept {
  if (v >= 0) return format_unsigned(static_cast<std::uint64_t>(v), out);
  if (out.empty()) return errc::buffer_too_small;
  FIELDCODEC_TRY(const std::size_t n,
                 format_unsigned(std::uint64_t{0} - static_cast<std::uint64_t>(v), out.subspan(1)));
  out[0] = '-';
  return n + 1U;
}

/// Write `v` in hex, zero-padded to at least `min_digits` digits.
/// Errors: buffer_too_small, invalid_argument (min_digits > 16).
[[nodiscard]] constexpr result<std::size_t> format_hex(std::uint64_t v, std::size_t min_digits,
                                                       std::span<char> out,
                                                       bool upper = true) noexcept {
  if (min_digits > 16U) return errc::invalid_argument;
  const char *digits = upper ? "0123456789ABCDEF" : "0123456789abcdef";
  char tmp[16]{};
  std::size_t n = 0;
  do {
    tmp[n++] = digits[v & 0x0FU];
    v >>= 4U;
  } while (v != 0U);
  while (n < min_digits) tmp[n++] = '0';
  if (out.size() < n) return errc::buffer_too_small;
  for (std::size_t i = 0; i < n; ++i) out[i] = tmp[n - 1U - i];
  return n;
}

} // namespace fieldcodec::ascii
