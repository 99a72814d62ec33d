// fieldcodec — PA-CONTROL positions and R registers on Profibus-DP / Interbus-S.
//
// Four bytes, big-endian, in one of two formats chosen by bit 15 of the CTRL control word
// (latched when AUTOMATIC or ONLINE starts):
//
//   ieee_float     IEEE-754 single precision;
//   milli_integer  the value × 1000 as a signed 32-bit integer (12.345 ↔ 12345).
//
// ×1000 rounding: the exact decimal a value stands for is multiplied by 1000 and rounded half
// away from zero (core/scaling). For a float that decimal is its shortest round-trip form
// (2.0005f → 2.0005 → 2001, although the float itself is 2.00049996…); for a double it is
// the value to 15 significant digits. Results outside int32 are refused (errc::overflow),
// never wrapped or clamped; NaN and infinity are refused in both formats.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/ieee754.hpp>
#include <fieldcodec/core/integer.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/pacontrol/value.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <span>

namespace fieldcodec::pacontrol {

/// How positions and R registers travel in the module/axis blocks.
enum class position_format : std::uint8_t {
  ieee_float,    ///< IEEE-754 single precision (CTRL control word bit 15 = 0)
  milli_integer, ///< value × 1000 as int32 (bit 15 = 1)
};

namespace detail {
inline constexpr scaling::linear milli_scale{decimal{1000, 0}, decimal{0, 0}};
inline constexpr scaling::field int32_field{4, true};
} // namespace detail

/// round(v × 1000) as int32. Errors: overflow (outside int32), invalid_argument (places > 18).
[[nodiscard]] constexpr result<std::int32_t> to_milli(decimal v) noexcept {
  auto raw = scaling::to_raw(v, detail::milli_scale, detail::int32_field);
  if (!raw) return raw.error();
  return static_cast<std::int32_t>(raw.value());
}

/// round(v × 1000) of a float's shortest decimal. Errors: not_representable (NaN, ±∞),
/// overflow.
[[nodiscard]] constexpr result<std::int32_t> to_milli(float v) noexcept {
  if (ieee754::is_nonfinite_bits(ieee754::to_bits(v))) return errc::not_representable;
  if (v >= 1.0e7F || v <= -1.0e7F) return errc::overflow;
  auto d = shortest_decimal(v);
  if (!d) return d.error();
  return to_milli(d.value());
}

/// round(v × 1000) of a double to 15 significant digits. Errors: not_representable, overflow.
[[nodiscard]] constexpr result<std::int32_t> to_milli(double v) noexcept {
  if (ieee754::is_nonfinite_bits(ieee754::to_bits(v))) return errc::not_representable;
  if (v >= 1.0e10 || v <= -1.0e10) return errc::overflow;
  auto raw = scaling::to_raw(v, detail::milli_scale, detail::int32_field);
  if (!raw) return raw.error();
  return static_cast<std::int32_t>(raw.value());
}

/// raw / 1000, exactly (12345 → 12.345).
[[nodiscard]] constexpr decimal from_milli(std::int32_t raw) noexcept { return decimal{raw, 3}; }

/// The 4 bytes of a position. Errors: not_representable (NaN, ±∞), overflow (×1000 outside
/// int32).
[[nodiscard]] constexpr result<std::array<std::uint8_t, 4>>
encode_position(float v, position_format format) noexcept {
  if (format == position_format::ieee_float) {
    return ieee754::encode_float32(v, byte_order::big, ieee754::nonfinite::reject);
  }
  auto raw = to_milli(v);
  if (!raw) return raw.error();
  return to_bytes<std::int32_t>(raw.value(), byte_order::big);
}

/// The 4 bytes of an exact decimal position (the float format carries its nearest float).
/// Errors: overflow, invalid_argument.
[[nodiscard]] constexpr result<std::array<std::uint8_t, 4>>
encode_position(decimal v, position_format format) noexcept {
  if (v.places > decimal_max_places) return errc::invalid_argument;
  if (format == position_format::ieee_float) {
    const float f = to_float(v);
    if (ieee754::is_nonfinite_bits(ieee754::to_bits(f))) return errc::overflow;
    return ieee754::encode_float32(f, byte_order::big, ieee754::nonfinite::reject);
  }
  auto raw = to_milli(v);
  if (!raw) return raw.error();
  return to_bytes<std::int32_t>(raw.value(), byte_order::big);
}

/// The 4 bytes of a position given as a double: the float format carries its nearest float,
/// the ×1000 format rounds the double itself (15 significant digits, as to_milli(double)) —
/// never through a float first (1234567.891 → 1234567891, not the float's 1234567900).
/// Errors: not_representable (NaN, ±∞, beyond float range in float format), overflow.
[[nodiscard]] constexpr result<std::array<std::uint8_t, 4>>
encode_position(double v, position_format format) noexcept {
  if (format == position_format::ieee_float) {
    if (!(v <= static_cast<double>(std::numeric_limits<float>::max()) &&
          v >= static_cast<double>(std::numeric_limits<float>::lowest()))) {
      return errc::not_representable; // also NaN
    }
    return encode_position(static_cast<float>(v), format);
  }
  auto raw = to_milli(v);
  if (!raw) return raw.error();
  return to_bytes<std::int32_t>(raw.value(), byte_order::big);
}

/// The 4 bytes of a whole-unit position of any integer type (5 → 5.0, 5000 in ×1000 format).
/// Errors: overflow (×1000 outside int32, or beyond int64).
template <integer_argument T>
[[nodiscard]] constexpr result<std::array<std::uint8_t, 4>>
encode_position(T v, position_format format) noexcept {
  auto i = checked_narrow<std::int64_t>(v);
  if (!i) return i.error();
  return encode_position(decimal{i.value(), 0}, format);
}

/// A position from the first 4 bytes of `in`. In integer format the result is the float
/// nearest to raw / 1000 — except within 22 of the int32 limits, where that float (e.g.
/// 2147483.75 for 7F FF FF FF) would not fit ×1000 into int32 again: there it is the nearest
/// float towards zero, so every decoded position encodes again (fuzz F2). Use
/// decode_position_decimal for the exact value.
/// Errors: truncated, not_representable (NaN or ±∞ in float format).
[[nodiscard]] constexpr result<float> decode_position(std::span<const std::uint8_t> in,
                                                      position_format format) noexcept {
  if (format == position_format::ieee_float) {
    return ieee754::decode_float32(in, byte_order::big, ieee754::nonfinite::reject);
  }
  auto raw = load<std::int32_t>(in, byte_order::big);
  if (!raw) return raw.error();
  float f = to_float(from_milli(raw.value()));
  // Decrementing the bit pattern of a non-zero float moves its magnitude one step towards zero.
  while (!to_milli(f) && f != 0.0F) f = ieee754::from_bits(ieee754::to_bits(f) - 1U);
  return f;
}

/// A position as an exact decimal: raw / 1000 in integer format, the shortest decimal of the
/// float otherwise. Errors: truncated, not_representable.
[[nodiscard]] constexpr result<decimal> decode_position_decimal(std::span<const std::uint8_t> in,
                                                                position_format format) noexcept {
  if (format == position_format::ieee_float) {
    auto f = ieee754::decode_float32(in, byte_order::big, ieee754::nonfinite::reject);
    if (!f) return f.error();
    return shortest_decimal(f.value());
  }
  auto raw = load<std::int32_t>(in, byte_order::big);
  if (!raw) return raw.error();
  return from_milli(raw.value());
}

} // namespace fieldcodec::pacontrol
