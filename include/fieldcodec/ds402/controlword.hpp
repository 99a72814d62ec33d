// fieldcodec — CiA 402 controlword (object 6040h): device-control commands and mode-specific
// bits.
//
// Transport-agnostic: a controlword is a 16-bit value, whether it travels in a CAN PDO, a CoE
// PDO, an SDO or a DRIVECOM process-data word. The command bits are 0, 1, 2, 3 and 7; bits 4, 5,
// 6, 8 and 9 depend on the mode of operation; bits 11..15 belong to the manufacturer.
#pragma once

#include <fieldcodec/core/result.hpp>

#include <cstdint>
#include <string_view>

namespace fieldcodec::ds402 {

/// Controlword bits (bit numbers as masks).
namespace cw {
inline constexpr std::uint16_t switch_on = 1U << 0U;
inline constexpr std::uint16_t enable_voltage = 1U << 1U;
inline constexpr std::uint16_t quick_stop = 1U << 2U; ///< active low: 0 requests quick stop
inline constexpr std::uint16_t enable_operation = 1U << 3U;
inline constexpr std::uint16_t fault_reset = 1U << 7U; ///< acts on the rising edge 0 -> 1
inline constexpr std::uint16_t halt = 1U << 8U;
/// The bits that form the device-control command (0, 1, 2, 3, 7).
inline constexpr std::uint16_t command_mask = 0x008FU;

// Profile position mode (pp)
inline constexpr std::uint16_t pp_new_set_point = 1U << 4U;
inline constexpr std::uint16_t pp_change_set_immediately = 1U << 5U;
inline constexpr std::uint16_t pp_relative = 1U << 6U; ///< 0 = absolute target, 1 = relative
inline constexpr std::uint16_t pp_change_on_set_point = 1U << 9U;
// Homing mode (hm)
inline constexpr std::uint16_t hm_start = 1U << 4U;
// Profile velocity (pv) and cyclic synchronous modes have no mode bits besides halt.
// Interpolated position mode (ip)
inline constexpr std::uint16_t ip_enable = 1U << 4U;
} // namespace cw

/// The device-control commands of the controlword.
enum class command : std::uint8_t {
  shutdown,          ///< xxxx x110 -> ready to switch on (transitions 2, 6, 8)
  switch_on,         ///< xxxx 0111 -> switched on (3); equal to disable_operation (5)
  switch_on_enable,  ///< xxxx 1111 from ready to switch on: 3 + 4 at once; enable operation (4, 16)
  disable_voltage,   ///< xxxx xx0x -> switch on disabled (7, 9, 10, 12)
  quick_stop,        ///< xxxx x01x -> quick stop active / switch on disabled (7, 10, 11)
  disable_operation, ///< xxxx 0111 -> switched on (5)
  enable_operation,  ///< xxxx 1111 -> operation enabled (4, 16)
  fault_reset,       ///< bit 7 rising edge -> switch on disabled (15)
};

/// The command bits of `c` (bits 0..3, 7). Fault reset gives 0x80: to be effective it must
/// follow a controlword with bit 7 clear.
[[nodiscard]] constexpr std::uint16_t command_bits(command c) noexcept {
  switch (c) {
  case command::shutdown: return 0x0006U;
  case command::switch_on: return 0x0007U;
  case command::switch_on_enable: return 0x000FU;
  case command::disable_voltage: return 0x0000U;
  case command::quick_stop: return 0x0002U;
  case command::disable_operation: return 0x0007U;
  case command::enable_operation: return 0x000FU;
  case command::fault_reset: return 0x0080U;
  }
  return 0;
}

/// `base` with its command bits replaced by those of `c` (mode bits, halt and manufacturer bits
/// of `base` are kept).
[[nodiscard]] constexpr std::uint16_t with_command(std::uint16_t base, command c) noexcept {
  return static_cast<std::uint16_t>((base & ~cw::command_mask) | command_bits(c));
}

/// The command a controlword carries, given the previous controlword (needed for the fault reset
/// edge). Priority follows CiA 402: fault reset edge, then disable voltage, quick stop, shutdown,
/// switch on / enable operation. Returns `switch_on` for xxxx 0111 and `enable_operation` for
/// xxxx 1111 (the state decides whether that is "switch on" or "disable operation" etc.).
/// Bit 7 held high without an edge is ignored for the command decision. Cannot fail: every
/// 16-bit pattern is some command.
[[nodiscard]] constexpr command decode_command(std::uint16_t controlword,
                                               std::uint16_t previous) noexcept {
  if ((controlword & cw::fault_reset) != 0U && (previous & cw::fault_reset) == 0U) {
    return command::fault_reset;
  }
  if ((controlword & cw::enable_voltage) == 0U) return command::disable_voltage;
  if ((controlword & cw::quick_stop) == 0U) return command::quick_stop;
  if ((controlword & cw::switch_on) == 0U) return command::shutdown;
  if ((controlword & cw::enable_operation) == 0U) return command::switch_on;
  return command::enable_operation;
}

[[nodiscard]] constexpr std::string_view to_string(command c) noexcept {
  switch (c) {
  case command::shutdown: return "shutdown";
  case command::switch_on: return "switch on";
  case command::switch_on_enable: return "switch on + enable operation";
  case command::disable_voltage: return "disable voltage";
  case command::quick_stop: return "quick stop";
  case command::disable_operation: return "disable operation";
  case command::enable_operation: return "enable operation";
  case command::fault_reset: return "fault reset";
  }
  return "?";
}

} // namespace fieldcodec::ds402
