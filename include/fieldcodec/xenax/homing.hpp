// fieldcodec — XENAX reference (homing) methods, object 6098h (manual 4.2.19, 5.1).
#pragma once

#include <fieldcodec/core/result.hpp>

#include <cstdint>
#include <string_view>

namespace fieldcodec::xenax {

/// 6098h values (INTEGER8, 1..15; 7..9 are not defined).
enum class reference_method : std::int8_t {
  linear_positive = 1,            ///< LINAX/ELAX, start in positive direction
  linear_negative = 2,            ///< LINAX/ELAX, start in negative direction
  gantry_same_positive = 3,       ///< gantry, same measuring-system orientation, positive
  gantry_same_negative = 4,       ///< gantry, same orientation, negative
  gantry_contrary_positive = 5,   ///< gantry, contrary orientation, positive
  gantry_contrary_negative = 6,   ///< gantry, contrary orientation, negative
  cw_sensor_ccw_zmark = 10,       ///< rotary: clockwise to the sensor, counter-clockwise to Z
  cw_sensor_cw_zmark = 11,        ///< rotary: clockwise to the sensor, clockwise to Z
  ccw_sensor_ccw_zmark = 12,      ///< rotary: counter-clockwise to sensor and to Z
  ccw_sensor_cw_zmark = 13,       ///< rotary: counter-clockwise to sensor, clockwise to Z
  cw_sensor_shortest_zmark = 14,  ///< ROTAX Rxvp: clockwise to the sensor, shortest way to Z
  ccw_sensor_shortest_zmark = 15, ///< ROTAX Rxvp: counter-clockwise to sensor, shortest way to Z
};

/// Errors: out_of_range (not 1..6 or 10..15).
[[nodiscard]] constexpr result<reference_method> decode_reference_method(std::int8_t v) noexcept {
  if ((v >= 1 && v <= 6) || (v >= 10 && v <= 15)) return static_cast<reference_method>(v);
  return errc::out_of_range;
}
[[nodiscard]] constexpr std::uint8_t method_byte(reference_method m) noexcept {
  return static_cast<std::uint8_t>(static_cast<std::int8_t>(m));
}
[[nodiscard]] constexpr bool is_gantry(reference_method m) noexcept {
  const auto v = static_cast<std::int8_t>(m);
  return v >= 3 && v <= 6;
}
[[nodiscard]] constexpr bool is_rotary(reference_method m) noexcept {
  return static_cast<std::int8_t>(m) >= 10;
}
/// Jog mode is refused in a gantry configuration (manual 5.4). The manual states the rule as
/// "6098h >= 3", which would also forbid jog after a rotary reference; 5.1.6 offers jog after
/// exactly such a reference, so only the gantry methods 3..6 forbid it (errata, Codec).
[[nodiscard]] constexpr bool allows_jog(reference_method m) noexcept { return !is_gantry(m); }

[[nodiscard]] constexpr std::string_view to_string(reference_method m) noexcept {
  switch (m) {
  case reference_method::linear_positive: return "linear, start positive";
  case reference_method::linear_negative: return "linear, start negative";
  case reference_method::gantry_same_positive: return "gantry, same orientation, positive";
  case reference_method::gantry_same_negative: return "gantry, same orientation, negative";
  case reference_method::gantry_contrary_positive: return "gantry, contrary orientation, positive";
  case reference_method::gantry_contrary_negative: return "gantry, contrary orientation, negative";
  case reference_method::cw_sensor_ccw_zmark: return "rotary: CW to sensor, CCW to Z-mark";
  case reference_method::cw_sensor_cw_zmark: return "rotary: CW to sensor, CW to Z-mark";
  case reference_method::ccw_sensor_ccw_zmark: return "rotary: CCW to sensor, CCW to Z-mark";
  case reference_method::ccw_sensor_cw_zmark: return "rotary: CCW to sensor, CW to Z-mark";
  case reference_method::cw_sensor_shortest_zmark:
    return "rotary: CW to sensor, shortest way to Z-mark";
  case reference_method::ccw_sensor_shortest_zmark:
    return "rotary: CCW to sensor, shortest way to Z-mark";
  }
  return "?";
}

} // namespace fieldcodec::xenax
