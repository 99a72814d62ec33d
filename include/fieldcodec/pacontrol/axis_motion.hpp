// fieldcodec — what the PA-CONTROL reports about an axis through commands (manual 001):
//
//   1910 cmd_get_status_axis           one of five motion states (0, 1, 2, 4, 8)
//   1911 cmd_get_status_all_axis       bit n-1 set = axis n moving
//   1921 cmd_get_extended_status_axis  four bytes, most significant first: power pack ready,
//                                      positive limit switch, negative limit switch (each 1 or
//                                      0; a limit switch byte is 0 when the switch is
//                                      actuated) and the motion state of 1910
//
//   decode_extended_axis_status(16777476)  (0100 0104 hex, 5.2.4.28 example)
//     → {power pack ready, positive limit actuated, negative not, stopped with fault}
//
// (The Profibus module/axis interface has its own 32-bit status word: profibus_axis.hpp.)
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/integer.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/pacontrol/axis_parameter.hpp>

#include <array>
#include <cstdint>
#include <string_view>

namespace fieldcodec::pacontrol {

/// Motion state of an axis (1910; bits 7-0 of 1921).
enum class axis_motion : std::uint8_t {
  in_position = 0,        ///< standing, in position
  moving = 1,             ///< moving
  stopped = 2,            ///< standing, was stopped
  stopped_with_fault = 4, ///< standing with a malfunction
  measuring_mode = 8,     ///< in measuring mode (0AA0)
};

[[nodiscard]] constexpr std::string_view name(axis_motion m) noexcept {
  switch (m) {
  case axis_motion::in_position: return "in position";
  case axis_motion::moving: return "moving";
  case axis_motion::stopped: return "stopped";
  case axis_motion::stopped_with_fault: return "stopped with fault";
  case axis_motion::measuring_mode: return "measuring mode";
  }
  return "";
}

/// The motion state a 1910 acknowledgement date stands for. Errors: unknown_object (not one
/// of 0, 1, 2, 4, 8).
template <integer_argument T>
[[nodiscard]] constexpr result<axis_motion> decode_axis_motion(T v) noexcept {
  for (const auto m : {axis_motion::in_position, axis_motion::moving, axis_motion::stopped,
                       axis_motion::stopped_with_fault, axis_motion::measuring_mode}) {
    if (in_closed_range(v, static_cast<unsigned>(m), static_cast<unsigned>(m))) return m;
  }
  return errc::unknown_object;
}

/// Whether axis `axis` (1-16) is moving according to a 1911 acknowledgement date.
/// Errors: out_of_range (axis not 1-16), overflow (date negative or beyond 16 bits).
template <integer_argument W, integer_argument A>
[[nodiscard]] constexpr result<bool> axis_moving(W all_axes, A axis) noexcept {
  auto word = checked_narrow<std::uint16_t>(all_axes);
  if (!word) return word.error();
  if (!in_closed_range(axis, 1, max_axis)) return errc::out_of_range;
  return (word.value() & (1U << (static_cast<unsigned>(axis) - 1U))) != 0U;
}

/// The acknowledgement date of 1921.
struct extended_axis_status {
  bool power_pack_ready = false;        ///< bits 31-24 = 1
  bool positive_limit_actuated = false; ///< bits 23-16 = 0
  bool negative_limit_actuated = false; ///< bits 15-8 = 0
  axis_motion motion = axis_motion::in_position;

  friend constexpr bool operator==(const extended_axis_status &,
                                   const extended_axis_status &) noexcept = default;
};

/// Errors: overflow (negative or beyond 32 bits), out_of_range (one of the three upper bytes
/// not 0 or 1), unknown_object (motion byte not 0, 1, 2, 4, 8).
template <integer_argument T>
[[nodiscard]] constexpr result<extended_axis_status> decode_extended_axis_status(T date) noexcept {
  auto d = checked_narrow<std::uint32_t>(date);
  if (!d) return d.error();
  const auto b = to_bytes<std::uint32_t>(d.value(), byte_order::big);
  if (b[0] > 1U || b[1] > 1U || b[2] > 1U) return errc::out_of_range;
  auto motion = decode_axis_motion(b[3]);
  if (!motion) return motion.error();
  return extended_axis_status{b[0] == 1U, b[1] == 0U, b[2] == 0U, motion.value()};
}

/// The 32-bit date of 1921 (for simulators and tests).
[[nodiscard]] constexpr std::uint32_t
encode_extended_axis_status(const extended_axis_status &s) noexcept {
  const std::array<std::uint8_t, 4> b{
      static_cast<std::uint8_t>(s.power_pack_ready ? 1U : 0U),
      static_cast<std::uint8_t>(s.positive_limit_actuated ? 0U : 1U),
      static_cast<std::uint8_t>(s.negative_limit_actuated ? 0U : 1U),
      static_cast<std::uint8_t>(s.motion)};
  return from_bytes<std::uint32_t>(b, byte_order::big);
}

} // namespace fieldcodec::pacontrol
