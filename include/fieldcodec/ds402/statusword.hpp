// fieldcodec — CiA 402 statusword (object 6041h): power drive system state and status bits.
#pragma once

#include <fieldcodec/core/result.hpp>

#include <cstdint>
#include <string_view>

namespace fieldcodec::ds402 {

/// Statusword bits (as masks).
namespace sw {
inline constexpr std::uint16_t ready_to_switch_on = 1U << 0U;
inline constexpr std::uint16_t switched_on = 1U << 1U;
inline constexpr std::uint16_t operation_enabled = 1U << 2U;
inline constexpr std::uint16_t fault = 1U << 3U;
inline constexpr std::uint16_t voltage_enabled = 1U << 4U;
inline constexpr std::uint16_t quick_stop = 1U << 5U; ///< active low: 0 = quick stop active
inline constexpr std::uint16_t switch_on_disabled = 1U << 6U;
inline constexpr std::uint16_t warning = 1U << 7U;
inline constexpr std::uint16_t remote = 1U << 9U;
inline constexpr std::uint16_t target_reached = 1U << 10U;
inline constexpr std::uint16_t internal_limit_active = 1U << 11U;
// Profile position mode
inline constexpr std::uint16_t pp_set_point_acknowledge = 1U << 12U;
inline constexpr std::uint16_t pp_following_error = 1U << 13U;
// Homing mode
inline constexpr std::uint16_t hm_attained = 1U << 12U;
inline constexpr std::uint16_t hm_error = 1U << 13U;
// Profile velocity mode
inline constexpr std::uint16_t pv_speed_zero = 1U << 12U;
inline constexpr std::uint16_t pv_max_slippage = 1U << 13U;
// Cyclic synchronous position / velocity / torque modes
inline constexpr std::uint16_t cs_target_value_followed = 1U << 12U; ///< drive follows the target
inline constexpr std::uint16_t csp_following_error = 1U << 13U;
} // namespace sw

/// The states of the power drive system finite state automaton (PDS FSA).
enum class state : std::uint8_t {
  not_ready_to_switch_on,
  switch_on_disabled,
  ready_to_switch_on,
  switched_on,
  operation_enabled,
  quick_stop_active,
  fault_reaction_active,
  fault,
};

/// One row of the CiA 402 statusword table: `(statusword & mask) == value` means `s`.
struct state_pattern {
  std::uint16_t mask;
  std::uint16_t value;
  state s;
};

/// The table of CiA 402 (bits 0, 1, 2, 3, 5, 6).
inline constexpr state_pattern state_patterns[] = {
    {0x004FU, 0x0000U, state::not_ready_to_switch_on},
    {0x004FU, 0x0040U, state::switch_on_disabled},
    {0x006FU, 0x0021U, state::ready_to_switch_on},
    {0x006FU, 0x0023U, state::switched_on},
    {0x006FU, 0x0027U, state::operation_enabled},
    {0x006FU, 0x0007U, state::quick_stop_active},
    {0x004FU, 0x000FU, state::fault_reaction_active},
    {0x004FU, 0x0008U, state::fault},
};

/// The state a statusword shows. Errors: bad_state (the pattern of bits 0..3, 5, 6 matches no
/// state, e.g. 0x0001 or 0x0067).
[[nodiscard]] constexpr result<state> decode_state(std::uint16_t statusword) noexcept {
  for (const auto &p : state_patterns) {
    if ((statusword & p.mask) == p.value) return p.s;
  }
  return errc::bad_state;
}

/// The canonical statusword bits (0..3, 5, 6) of a state, as a drive would show them.
[[nodiscard]] constexpr std::uint16_t state_bits(state s) noexcept {
  switch (s) {
  case state::not_ready_to_switch_on: return 0x0000U;
  case state::switch_on_disabled: return 0x0040U;
  case state::ready_to_switch_on: return 0x0021U;
  case state::switched_on: return 0x0023U;
  case state::operation_enabled: return 0x0027U;
  case state::quick_stop_active: return 0x0007U;
  case state::fault_reaction_active: return 0x000FU;
  case state::fault: return 0x0008U;
  }
  return 0;
}

/// Statusword bits decoded into named flags (bit 12/13 meaning depends on the mode).
struct status_flags {
  bool voltage_enabled;
  bool warning;
  bool remote;
  bool target_reached;
  bool internal_limit_active;
  bool bit12; ///< pp: set-point acknowledge, hm: homing attained, cs*: target followed
  bool bit13; ///< pp/csp: following error, hm: homing error
};

[[nodiscard]] constexpr status_flags decode_flags(std::uint16_t statusword) noexcept {
  return {(statusword & sw::voltage_enabled) != 0U,
          (statusword & sw::warning) != 0U,
          (statusword & sw::remote) != 0U,
          (statusword & sw::target_reached) != 0U,
          (statusword & sw::internal_limit_active) != 0U,
          (statusword & (1U << 12U)) != 0U,
          (statusword & (1U << 13U)) != 0U};
}

[[nodiscard]] constexpr std::string_view to_string(state s) noexcept {
  switch (s) {
  case state::not_ready_to_switch_on: return "not ready to switch on";
  case state::switch_on_disabled: return "switch on disabled";
  case state::ready_to_switch_on: return "ready to switch on";
  case state::switched_on: return "switched on";
  case state::operation_enabled: return "operation enabled";
  case state::quick_stop_active: return "quick stop active";
  case state::fault_reaction_active: return "fault reaction active";
  case state::fault: return "fault";
  }
  return "?";
}

/// The names of the statusword's operation-mode-specific bits 12 and 13 in mode `m` (6061h,
/// modes of operation display), CiA 402-2; empty where the mode gives the bit no meaning
/// (a reserved bit, a manufacturer-specific or unknown mode).
struct mode_bit_names {
  std::string_view bit12;
  std::string_view bit13;
};
[[nodiscard]] constexpr mode_bit_names mode_bits(std::int8_t m) noexcept {
  switch (m) {
  case 1: return {"set-point acknowledge", "following error"};       // profile position
  case 3: return {"speed zero", "max slippage error"};               // profile velocity
  case 6: return {"homing attained", "homing error"};                // homing
  case 7: return {"ip mode active", ""};                             // interpolated position
  case 8: return {"following the command value", "following error"}; // cyclic sync position
  case 9: return {"following the command value", ""};                // cyclic sync velocity
  case 10: return {"following the command value", ""};               // cyclic sync torque
  default: return {};
  }
}

} // namespace fieldcodec::ds402
