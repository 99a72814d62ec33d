// fieldcodec — COMPAX XX70 curve memory: CAM_MEM (0x5FCB, 3 bytes) and CAM_MEM_P (0x5FCA),
// manual 000, sections 2.11.7 and 2.11.8.
//
// CAM_MEM holds the content of the curve memory cell CAM_MEM_P points at (1 … 5460); every
// access increments the pointer. The page gives the 3 data bytes as MSB … LSB and nothing else:
// no coding, no sign, no range (the manual states "two's complement" wherever a value is
// signed, and says nothing here). The library does not guess: the 24 bits are read and written
// either as an unsigned number (0 … 16 777 215) or as a two's complement number
// (−8 388 608 … 8 388 607), and the caller names which one (docs/compax.md, "CAM_MEM").
#pragma once

#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::compax {

inline constexpr std::size_t cam_mem_size = 3;
inline constexpr std::uint16_t cam_mem_pointer_min = 1;
inline constexpr std::uint16_t cam_mem_pointer_max = 5460;

using cam_mem_bytes = std::array<std::uint8_t, cam_mem_size>;

/// CAM_MEM content as an unsigned 24-bit number. Any integer type.
/// Errors: out_of_range (outside 0 … 16 777 215).
template <integer_argument T>
[[nodiscard]] constexpr result<cam_mem_bytes> encode_cam_mem_unsigned(T value) noexcept {
  if (!in_closed_range(value, 0, unsigned_max(cam_mem_size))) {
    return errc::out_of_range;
  }
  cam_mem_bytes out{};
  FIELDCODEC_TRY_STATUS(
      store_unsigned(out, cam_mem_size, static_cast<std::uint64_t>(value), bus_order));
  return out;
}

/// CAM_MEM content as a two's complement 24-bit number. Any integer type.
/// Errors: out_of_range (outside −8 388 608 … 8 388 607).
template <integer_argument T>
[[nodiscard]] constexpr result<cam_mem_bytes> encode_cam_mem_signed(T value) noexcept {
  if (!in_closed_range(value, signed_min(cam_mem_size), signed_max(cam_mem_size))) {
    return errc::out_of_range;
  }
  cam_mem_bytes out{};
  FIELDCODEC_TRY_STATUS(
      store_signed(out, cam_mem_size, static_cast<std::int64_t>(value), bus_order));
  return out;
}

/// CAM_MEM data bytes → unsigned 24-bit number. Errors: truncated, bad_length.
[[nodiscard]] constexpr result<std::uint32_t>
decode_cam_mem_unsigned(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < cam_mem_size) return errc::truncated;
  if (in.size() > cam_mem_size) return errc::bad_length;
  return static_cast<std::uint32_t>(load_unsigned(in, cam_mem_size, bus_order).value());
}

/// CAM_MEM data bytes → two's complement 24-bit number. Errors: truncated, bad_length.
[[nodiscard]] constexpr result<std::int32_t>
decode_cam_mem_signed(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < cam_mem_size) return errc::truncated;
  if (in.size() > cam_mem_size) return errc::bad_length;
  return static_cast<std::int32_t>(load_signed(in, cam_mem_size, bus_order).value());
}

/// CAM_MEM_P (Unsigned16, 1 … 5460). Any integer type. Errors: out_of_range.
template <integer_argument T>
[[nodiscard]] constexpr result<std::array<std::uint8_t, 2>> encode_cam_mem_pointer(T n) noexcept {
  if (!in_closed_range(n, cam_mem_pointer_min, cam_mem_pointer_max)) {
    return errc::out_of_range;
  }
  return to_bytes<std::uint16_t>(static_cast<std::uint16_t>(n), bus_order);
}

/// CAM_MEM_P data bytes. Errors: truncated, bad_length, out_of_range (0 or above 5460).
[[nodiscard]] constexpr result<std::uint16_t>
decode_cam_mem_pointer(std::span<const std::uint8_t> in) noexcept {
  auto v = decode_integer<std::uint16_t>(in);
  if (!v) return v.error();
  if (v.value() < cam_mem_pointer_min || v.value() > cam_mem_pointer_max) {
    return errc::out_of_range;
  }
  return v;
}

} // namespace fieldcodec::compax
