// fieldcodec — CiA 402 modes of operation (objects 6060h / 6061h, INTEGER8).
#pragma once

#include <fieldcodec/core/result.hpp>

#include <cstdint>
#include <string_view>

namespace fieldcodec::ds402 {

/// Modes of operation defined by CiA 402. Negative values belong to the manufacturer.
enum class mode : std::int8_t {
  no_mode = 0,
  profile_position = 1,
  velocity = 2,
  profile_velocity = 3,
  profile_torque = 4,
  homing = 6,
  interpolated_position = 7,
  cyclic_sync_position = 8,
  cyclic_sync_velocity = 9,
  cyclic_sync_torque = 10,
  cyclic_sync_torque_commutation = 11,
};

/// True for the values CiA 402 defines (0..4, 6..11).
[[nodiscard]] constexpr bool is_standard_mode(std::int8_t v) noexcept {
  return (v >= 0 && v <= 4) || (v >= 6 && v <= 11);
}
/// True for the manufacturer-specific range (-128..-1).
[[nodiscard]] constexpr bool is_manufacturer_mode(std::int8_t v) noexcept { return v < 0; }

/// A standard mode from its INTEGER8 value. Errors: out_of_range (5, 12..127: reserved),
/// unknown_command (negative: manufacturer-specific, decode it with the vendor's module).
[[nodiscard]] constexpr result<mode> decode_mode(std::int8_t v) noexcept {
  if (is_standard_mode(v)) return static_cast<mode>(v);
  if (v < 0) return errc::unknown_command;
  return errc::out_of_range;
}

/// The byte that carries a mode in an SDO or PDO.
[[nodiscard]] constexpr std::uint8_t mode_byte(std::int8_t v) noexcept {
  return static_cast<std::uint8_t>(v);
}
[[nodiscard]] constexpr std::uint8_t mode_byte(mode m) noexcept {
  return static_cast<std::uint8_t>(static_cast<std::int8_t>(m));
}

[[nodiscard]] constexpr std::string_view to_string(mode m) noexcept {
  switch (m) {
  case mode::no_mode: return "no mode";
  case mode::profile_position: return "profile position";
  case mode::velocity: return "velocity";
  case mode::profile_velocity: return "profile velocity";
  case mode::profile_torque: return "profile torque";
  case mode::homing: return "homing";
  case mode::interpolated_position: return "interpolated position";
  case mode::cyclic_sync_position: return "cyclic synchronous position";
  case mode::cyclic_sync_velocity: return "cyclic synchronous velocity";
  case mode::cyclic_sync_torque: return "cyclic synchronous torque";
  case mode::cyclic_sync_torque_commutation:
    return "cyclic synchronous torque with commutation angle";
  }
  return "?";
}

} // namespace fieldcodec::ds402
