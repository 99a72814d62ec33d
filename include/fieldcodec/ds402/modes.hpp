// fieldcodec — CiA 402 modes of operation (objects 6060h / 6061h, INTEGER8).
//
// `mode` is a scoped enum over std::int8_t, the type of 6060h/6061h: od::encode, sdo::download
// and the PDO mappings take it as it is (jog, -1, is sent as 0xFF, never as 255).
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
[[nodiscard]] constexpr bool is_standard_mode(mode m) noexcept {
  return is_standard_mode(static_cast<std::int8_t>(m));
}
/// True for the manufacturer-specific range (-128..-1).
[[nodiscard]] constexpr bool is_manufacturer_mode(std::int8_t v) noexcept { return v < 0; }
[[nodiscard]] constexpr bool is_manufacturer_mode(mode m) noexcept {
  return is_manufacturer_mode(static_cast<std::int8_t>(m));
}

/// The mode a 6060h / 6061h value names. A negative value is a valid manufacturer-specific
/// mode: it is returned as it is (a `mode` holding the value, is_manufacturer_mode() true,
/// to_string() "manufacturer-specific") for the vendor's module to interpret (a jog mode at -1,
/// say). Errors: out_of_range (5, 12..127: reserved by CiA 402).
[[nodiscard]] constexpr result<mode> decode_mode(std::int8_t v) noexcept {
  if (is_standard_mode(v) || is_manufacturer_mode(v)) return static_cast<mode>(v);
  return errc::out_of_range;
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
  return is_manufacturer_mode(m) ? "manufacturer-specific" : "reserved";
}

} // namespace fieldcodec::ds402
