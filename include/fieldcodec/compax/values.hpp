// fieldcodec — COMPAX-M/S Interbus-S basic data types (manual 000, section 1.7).
//
// Multi-byte integers travel most significant byte first (data byte 1 = highest byte).
// Integer32 0x80000000 is not a number: the drive sends it when a value lies outside the
// Integer32 range ("overflow"), so it decodes as errc::overflow and is never encoded.
// Boolean is one byte: 0x00 FALSE, 0xFF TRUE; any other byte is rejected.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/integer.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

namespace fieldcodec::compax {

namespace detail {
/// An integer argument of any type as an int64; values above INT64_MAX (only an unsigned 64-bit
/// argument has them) become INT64_MAX, which every field's range check refuses: builders that
/// cannot fail keep the value this way and the encoder reports it, nothing wraps.
template <integer_argument T>
[[nodiscard]] constexpr std::int64_t saturate_i64(T v) noexcept {
  auto n = checked_narrow<std::int64_t>(v);
  return n ? n.value() : std::numeric_limits<std::int64_t>::max();
}
} // namespace detail

/// Byte order of every integer object on this bus.
inline constexpr byte_order bus_order = byte_order::big;

/// The Integer32 bit pattern that means "value outside the range" (section 1.7.2).
inline constexpr std::int32_t integer32_overflow = std::numeric_limits<std::int32_t>::min();

inline constexpr std::uint8_t boolean_false = 0x00;
inline constexpr std::uint8_t boolean_true = 0xFF;

/// Boolean → its byte.
[[nodiscard]] constexpr std::uint8_t encode_boolean(bool v) noexcept {
  return v ? boolean_true : boolean_false;
}

/// Byte → boolean. Errors: out_of_range (neither 0x00 nor 0xFF).
[[nodiscard]] constexpr result<bool> decode_boolean(std::uint8_t b) noexcept {
  if (b == boolean_true) return true;
  if (b == boolean_false) return false;
  return errc::out_of_range;
}

/// Byte span of exactly one byte → boolean. Errors: truncated, bad_length, out_of_range.
[[nodiscard]] constexpr result<bool> decode_boolean(std::span<const std::uint8_t> in) noexcept {
  if (in.empty()) return errc::truncated;
  if (in.size() != 1U) return errc::bad_length;
  return decode_boolean(in[0]);
}

/// An integer object's bytes (big-endian). Integer32 refuses the overflow pattern.
/// Errors: overflow (std::int32_t min).
template <wire_integer T>
[[nodiscard]] constexpr result<std::array<std::uint8_t, sizeof(T)>>
encode_integer(T value) noexcept {
  if constexpr (std::is_same_v<T, std::int32_t>) {
    if (value == integer32_overflow) return errc::overflow;
  }
  return to_bytes<T>(value, bus_order);
}

/// An integer object from exactly sizeof(T) bytes. Errors: truncated (fewer bytes),
/// bad_length (more bytes), overflow (Integer32 0x80000000, the drive's overflow marker).
template <wire_integer T>
[[nodiscard]] constexpr result<T> decode_integer(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < sizeof(T)) return errc::truncated;
  if (in.size() > sizeof(T)) return errc::bad_length;
  auto v = load<T>(in, bus_order);
  if (!v) return v.error();
  if constexpr (std::is_same_v<T, std::int32_t>) {
    if (v.value() == integer32_overflow) return errc::overflow;
  }
  return v;
}

/// Write an integer object into the front of `out`. Errors: buffer_too_small, overflow.
template <wire_integer T>
[[nodiscard]] constexpr status encode_integer(T value, std::span<std::uint8_t> out) noexcept {
  auto b = encode_integer<T>(value);
  if (!b) return b.error();
  if (out.size() < sizeof(T)) return errc::buffer_too_small;
  for (std::size_t i = 0; i < sizeof(T); ++i) out[i] = b.value()[i];
  return {};
}

/// Visible strings (COMMAND, P, S, N): characters 0x20..0x7F, padded with spaces to the
/// object's length (the manual's examples, e.g. 2.4.11 COMMAND, pad with 0x20). Errors: too_long
/// (text longer than `out`), bad_character.
[[nodiscard]] constexpr status encode_visible_string(std::string_view text,
                                                     std::span<std::uint8_t> out) noexcept {
  if (text.size() > out.size()) return errc::too_long;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto c = static_cast<std::uint8_t>(i < text.size() ? text[i] : ' ');
    if (c < 0x20U || c > 0x7FU) return errc::bad_character;
    out[i] = c;
  }
  return {};
}

/// The text of a visible string without its padding; the characters stay in `in` (no copy).
/// Padding is what follows the text: spaces (as the manual's examples and encode_visible_string
/// write it) or NUL bytes (as some drives and masters fill a reply). The text ends at the first
/// NUL; after it only NUL and space may follow; trailing spaces of the text are padding too.
/// Errors: bad_character (a byte outside 0x20..0x7F in the text, or anything but NUL or space
/// after the first NUL).
[[nodiscard]] constexpr result<std::span<const std::uint8_t>>
decode_visible_string(std::span<const std::uint8_t> in) noexcept {
  std::size_t n = 0;
  while (n < in.size() && in[n] != 0x00U) {
    if (in[n] < 0x20U || in[n] > 0x7FU) return errc::bad_character;
    ++n;
  }
  for (std::size_t i = n; i < in.size(); ++i) {
    if (in[i] != 0x00U && in[i] != 0x20U) return errc::bad_character;
  }
  while (n > 0U && in[n - 1U] == 0x20U) --n;
  return in.first(n);
}

} // namespace fieldcodec::compax
