// fieldcodec — XENAX Xvi modes of operation and the meaning of the mode-specific controlword and
// statusword bits (XENAX bus manual 4.2.2-4.2.5, 5.1-5.4). Built on ds402/.
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/ds402/controlword.hpp>
#include <fieldcodec/ds402/modes.hpp>
#include <fieldcodec/ds402/statusword.hpp>

#include <cstdint>
#include <string_view>

namespace fieldcodec::xenax {

/// The modes a XENAX accepts in 6060h (INTEGER8, manual limits -2..10). A scoped enum over
/// std::int8_t: od::encode, sdo::download and the PDO mappings take it as it is, so jog (-1)
/// goes out as 0xFF (5.4.1, "0xFF (-1)"), never as 255.
enum class mode : std::int8_t {
  vendor_reserved = -2, ///< "XENAX specific, not used"
  jog = -1,             ///< Jenny Science jog mode
  no_mode = 0,
  profile_position = 1,
  reference = 6, ///< CiA 402 homing
  cyclic_sync_position = 8,
};

/// 6502h, supported modes: bit 0 PP, bit 5 homing, bit 7 CSP, bit 16 jog (vendor bit).
inline constexpr std::uint32_t supported_modes = 0x000100A1U;

/// The mode a 6060h / 6061h value names. Errors: out_of_range (a value the XENAX does not
/// implement, including the reserved -2).
[[nodiscard]] constexpr result<mode> decode_mode(std::int8_t v) noexcept {
  switch (v) {
  case -1: return mode::jog;
  case 0: return mode::no_mode;
  case 1: return mode::profile_position;
  case 6: return mode::reference;
  case 8: return mode::cyclic_sync_position;
  default: return errc::out_of_range;
  }
}
/// True when 6502h announces the mode.
[[nodiscard]] constexpr bool is_supported(std::uint32_t supported, mode m) noexcept {
  switch (m) {
  case mode::profile_position: return (supported & (1U << 0U)) != 0U;
  case mode::reference: return (supported & (1U << 5U)) != 0U;
  case mode::cyclic_sync_position: return (supported & (1U << 7U)) != 0U;
  case mode::jog: return (supported & (1U << 16U)) != 0U;
  case mode::no_mode: return true;
  case mode::vendor_reserved: return false;
  }
  return false;
}

[[nodiscard]] constexpr std::string_view to_string(mode m) noexcept {
  switch (m) {
  case mode::vendor_reserved: return "XENAX reserved";
  case mode::jog: return "jog (Jenny Science)";
  case mode::no_mode: return "no mode";
  case mode::profile_position: return "profile position";
  case mode::reference: return "reference";
  case mode::cyclic_sync_position: return "cyclic synchronous position";
  }
  return "?";
}

// ---------------------------------------------------------------------------------------------
// Controlword (operation enabled = 0x0F plus the mode bits)

namespace cw {
inline constexpr std::uint16_t start = 1U << 4U;    ///< new set-point / reference / jog / CSP start
inline constexpr std::uint16_t relative = 1U << 6U; ///< PP: 1 relative, 0 absolute
inline constexpr std::uint16_t positive = 1U << 6U; ///< jog: 1 positive, 0 negative
inline constexpr std::uint16_t halt = ds402::cw::halt;
inline constexpr std::uint16_t enabled = 0x000FU;
} // namespace cw

enum class positioning : std::uint8_t { absolute, relative };
enum class jog_direction : std::uint8_t { negative, positive };

/// PP: start a move (5.2.1: 0x1F absolute, 0x5F relative). Send 0x0F again before the next.
[[nodiscard]] constexpr std::uint16_t pp_start(positioning p) noexcept {
  return static_cast<std::uint16_t>(cw::enabled | cw::start |
                                    (p == positioning::relative ? cw::relative : 0U));
}
/// PP: abort a move with halt (5.2.3: 0x10F).
inline constexpr std::uint16_t pp_halt = cw::enabled | cw::halt;
/// Jog: start (5.4.1: 0x1F negative, 0x5F positive).
[[nodiscard]] constexpr std::uint16_t jog_start(jog_direction d) noexcept {
  return static_cast<std::uint16_t>(cw::enabled | cw::start |
                                    (d == jog_direction::positive ? cw::positive : 0U));
}
/// Jog: stop with halt as the manual prints it (5.4.1: 0x11F for both directions).
inline constexpr std::uint16_t jog_stop = cw::enabled | cw::start | cw::halt;
/// Reference (homing): start (5.1.2: 0x1F). CSP: start (5.3.1: 0x1F).
inline constexpr std::uint16_t reference_start = cw::enabled | cw::start;
inline constexpr std::uint16_t csp_start = cw::enabled | cw::start;

// ---------------------------------------------------------------------------------------------
// Statusword

namespace sw {
inline constexpr std::uint16_t bit10 = 1U << 10U;
inline constexpr std::uint16_t soft_limit = 1U << 11U; ///< XENAX: soft-limit position reached
inline constexpr std::uint16_t bit12 = 1U << 12U;
inline constexpr std::uint16_t bit13 = 1U << 13U;
} // namespace sw

/// A statusword read in the light of the active mode.
struct status {
  ds402::state state;
  bool warning;
  bool remote;
  bool soft_limit_reached;    ///< bit 11 (all modes)
  bool target_reached;        ///< bit 10 in PP and CSP
  bool set_point_acknowledge; ///< bit 12 in PP
  bool target_used;           ///< bit 12 in CSP
  bool following_error;       ///< bit 13 in PP (5.2) and CSP
  bool constant_speed;        ///< bit 10 in jog
  bool speed_zero;            ///< bit 12 in jog
  bool reference_performed;   ///< bit 10 in reference mode
  bool reference_achieved;    ///< bit 12 in reference mode
  bool reference_error;       ///< bit 13 in reference mode
};

/// Decode a statusword for the mode shown in 6061h. Errors: bad_state (no PDS state matches).
[[nodiscard]] constexpr result<status> decode_status(std::uint16_t statusword, mode m) noexcept {
  FIELDCODEC_TRY(const ds402::state s, ds402::decode_state(statusword));
  const bool b10 = (statusword & sw::bit10) != 0U;
  const bool b12 = (statusword & sw::bit12) != 0U;
  const bool b13 = (statusword & sw::bit13) != 0U;
  status r{s,
           (statusword & ds402::sw::warning) != 0U,
           (statusword & ds402::sw::remote) != 0U,
           (statusword & sw::soft_limit) != 0U,
           false,
           false,
           false,
           false,
           false,
           false,
           false,
           false,
           false};
  switch (m) {
  case mode::profile_position:
    r.target_reached = b10;
    r.set_point_acknowledge = b12;
    r.following_error = b13;
    break;
  case mode::cyclic_sync_position:
    r.target_reached = b10;
    r.target_used = b12;
    r.following_error = b13;
    break;
  case mode::jog:
    r.constant_speed = b10;
    r.speed_zero = b12;
    break;
  case mode::reference:
    r.reference_performed = b10;
    r.reference_achieved = b12;
    r.reference_error = b13;
    break;
  case mode::no_mode:
  case mode::vendor_reserved: break;
  }
  return r;
}

} // namespace fieldcodec::xenax
