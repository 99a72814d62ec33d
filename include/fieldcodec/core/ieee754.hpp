// fieldcodec — IEEE-754 binary32/binary64 values as bytes in either byte order.
//
// The bit pattern is obtained with std::bit_cast (no aliasing tricks) and written with the
// integer byte-order primitives, so the result does not depend on the host's byte order.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <span>

namespace fieldcodec::ieee754 {

static_assert(std::numeric_limits<float>::is_iec559 && sizeof(float) == 4,
              "fieldcodec needs IEEE-754 binary32 floats");
static_assert(std::numeric_limits<double>::is_iec559 && sizeof(double) == 8,
              "fieldcodec needs IEEE-754 binary64 doubles");

/// What to do with NaN and infinity.
enum class nonfinite : std::uint8_t {
  reject, ///< errc::not_representable (positions, set-points: never move to NaN)
  allow,  ///< pass them through bit-exactly
};

[[nodiscard]] constexpr std::uint32_t to_bits(float v) noexcept {
  return std::bit_cast<std::uint32_t>(v);
}
[[nodiscard]] constexpr float from_bits(std::uint32_t bits) noexcept {
  return std::bit_cast<float>(bits);
}
[[nodiscard]] constexpr std::uint64_t to_bits(double v) noexcept {
  return std::bit_cast<std::uint64_t>(v);
}
[[nodiscard]] constexpr double from_bits64(std::uint64_t bits) noexcept {
  return std::bit_cast<double>(bits);
}

/// True for NaN and ±infinity, judged on the bit pattern (exponent all ones).
[[nodiscard]] constexpr bool is_nonfinite_bits(std::uint32_t bits) noexcept {
  return (bits & 0x7F80'0000U) == 0x7F80'0000U;
}
[[nodiscard]] constexpr bool is_nonfinite_bits(std::uint64_t bits) noexcept {
  return (bits & 0x7FF0'0000'0000'0000U) == 0x7FF0'0000'0000'0000U;
}

/// The 4 bytes of `v`. Errors: not_representable (NaN/infinity under nonfinite::reject).
[[nodiscard]] constexpr result<std::array<std::uint8_t, 4>>
encode_float32(float v, byte_order order, nonfinite policy = nonfinite::reject) noexcept {
  const std::uint32_t bits = to_bits(v);
  if (policy == nonfinite::reject && is_nonfinite_bits(bits)) return errc::not_representable;
  return to_bytes<std::uint32_t>(bits, order);
}

/// A float from the first 4 bytes of `in`.
/// Errors: truncated, not_representable (NaN/infinity under nonfinite::reject).
[[nodiscard]] constexpr result<float>
decode_float32(std::span<const std::uint8_t> in, byte_order order,
               nonfinite policy = nonfinite::reject) noexcept {
  FIELDCODEC_TRY(const std::uint32_t bits, load<std::uint32_t>(in, order));
  if (policy == nonfinite::reject && is_nonfinite_bits(bits)) return errc::not_representable;
  return from_bits(bits);
}

/// The 8 bytes of `v`. Errors: not_representable (NaN/infinity under nonfinite::reject).
[[nodiscard]] constexpr result<std::array<std::uint8_t, 8>>
encode_float64(double v, byte_order order, nonfinite policy = nonfinite::reject) noexcept {
  const std::uint64_t bits = to_bits(v);
  if (policy == nonfinite::reject && is_nonfinite_bits(bits)) return errc::not_representable;
  return to_bytes<std::uint64_t>(bits, order);
}

/// A double from the first 8 bytes of `in`.
/// Errors: truncated, not_representable (NaN/infinity under nonfinite::reject).
[[nodiscard]] constexpr result<double>
decode_float64(std::span<const std::uint8_t> in, byte_order order,
               nonfinite policy = nonfinite::reject) noexcept {
  FIELDCODEC_TRY(const std::uint64_t bits, load<std::uint64_t>(in, order));
  if (policy == nonfinite::reject && is_nonfinite_bits(bits)) return errc::not_representable;
  return from_bits64(bits);
}

} // namespace fieldcodec::ieee754
