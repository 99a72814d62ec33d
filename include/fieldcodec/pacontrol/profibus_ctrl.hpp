// fieldcodec — PA-CONTROL CTRL interface on Profibus-DP (8 bytes after the CMD interface).
//
// Word 0 of the master's data is the control word of the control; word 0 of the
// PA-CONTROL's data is its status word. Three control bits are active low: cancel (bit 2),
// stop (bit 1) and error reset (bit 0) act while the bit is 0, so the quiet control word is
// 0x0007. The structs below speak in actions (true = "do it") and invert on the wire.
// Bit 15 selects float or ×1000 integer positions for the module blocks; the PA-CONTROL
// latches it when AUTOMATIC or ONLINE starts, so set it in HOME POSITION.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/pacontrol/position.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace fieldcodec::pacontrol::profibus {

inline constexpr std::size_t ctrl_size = 8;

/// Bits of the control word (master → PA-CONTROL), as on the wire.
namespace ctrl_bits {
inline constexpr std::uint16_t integer_positions = 1U << 15U; ///< ×1000 integers, not floats
inline constexpr std::uint16_t start_online = 1U << 4U;
inline constexpr std::uint16_t start_automatic = 1U << 3U;
inline constexpr std::uint16_t cancel_n = 1U << 2U;      ///< cancel while 0 (active low)
inline constexpr std::uint16_t stop_n = 1U << 1U;        ///< stop while 0 (active low)
inline constexpr std::uint16_t error_reset_n = 1U << 0U; ///< reset errors while 0 (active low)
inline constexpr std::uint16_t active_low = cancel_n | stop_n | error_reset_n;
} // namespace ctrl_bits

/// Bits of the status word (PA-CONTROL → master).
namespace status_bits {
inline constexpr std::uint16_t integer_positions = 1U << 15U;
inline constexpr std::uint16_t online_stopped = 1U << 11U;
inline constexpr std::uint16_t online_active = 1U << 10U;
inline constexpr std::uint16_t automatic_stopped = 1U << 9U;
inline constexpr std::uint16_t automatic_active = 1U << 8U;
inline constexpr std::uint16_t system_error = 1U << 2U;
inline constexpr std::uint16_t battery_ok = 1U << 1U;
inline constexpr std::uint16_t ready = 1U << 0U;
} // namespace status_bits

/// The control word as actions. All false = the quiet word 0x0007.
struct ctrl_command {
  bool integer_positions = false; ///< module positions and R registers as ×1000 integers
  bool start_online = false;
  bool start_automatic = false;
  bool cancel = false;      ///< sent as bit 2 = 0
  bool stop = false;        ///< sent as bit 1 = 0
  bool reset_error = false; ///< sent as bit 0 = 0

  [[nodiscard]] constexpr position_format format() const noexcept {
    return integer_positions ? position_format::milli_integer : position_format::ieee_float;
  }
  friend constexpr bool operator==(const ctrl_command &, const ctrl_command &) noexcept = default;
};

/// The control word on the wire (active-low bits inverted).
[[nodiscard]] constexpr std::uint16_t control_word(const ctrl_command &c) noexcept {
  std::uint16_t w = 0;
  if (c.integer_positions) w |= ctrl_bits::integer_positions;
  if (c.start_online) w |= ctrl_bits::start_online;
  if (c.start_automatic) w |= ctrl_bits::start_automatic;
  if (!c.cancel) w |= ctrl_bits::cancel_n;
  if (!c.stop) w |= ctrl_bits::stop_n;
  if (!c.reset_error) w |= ctrl_bits::error_reset_n;
  return w;
}

/// Actions from a control word; unassigned bits 14-5 are ignored.
[[nodiscard]] constexpr ctrl_command from_control_word(std::uint16_t w) noexcept {
  return ctrl_command{(w & ctrl_bits::integer_positions) != 0U,
                      (w & ctrl_bits::start_online) != 0U,
                      (w & ctrl_bits::start_automatic) != 0U,
                      (w & ctrl_bits::cancel_n) == 0U,
                      (w & ctrl_bits::stop_n) == 0U,
                      (w & ctrl_bits::error_reset_n) == 0U};
}

/// The 8 bytes master → PA-CONTROL: the control word, then three words written as 0 (word 1
/// "not used"; word 2 is labelled "system error number" in the manual, see docs/errata.md).
[[nodiscard]] constexpr std::array<std::uint8_t, ctrl_size>
encode_ctrl_command(const ctrl_command &c) noexcept {
  std::array<std::uint8_t, ctrl_size> out{};
  const auto w = to_bytes<std::uint16_t>(control_word(c), byte_order::big);
  out[0] = w[0];
  out[1] = w[1];
  return out;
}

/// The control word from the first 8 bytes of `in`. Errors: truncated.
[[nodiscard]] constexpr result<ctrl_command>
decode_ctrl_command(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < ctrl_size) return errc::truncated;
  return from_control_word(load<std::uint16_t>(in, byte_order::big).value());
}

/// The status word of the control.
struct ctrl_status {
  bool integer_positions = false; ///< positions and R registers travel as ×1000 integers
  bool online_stopped = false;
  bool online_active = false;
  bool automatic_stopped = false;
  bool automatic_active = false;
  bool system_error = false;
  bool battery_ok = false;
  bool ready = false;

  [[nodiscard]] constexpr position_format format() const noexcept {
    return integer_positions ? position_format::milli_integer : position_format::ieee_float;
  }
  friend constexpr bool operator==(const ctrl_status &, const ctrl_status &) noexcept = default;
};

[[nodiscard]] constexpr std::uint16_t status_word(const ctrl_status &s) noexcept {
  std::uint16_t w = 0;
  if (s.integer_positions) w |= status_bits::integer_positions;
  if (s.online_stopped) w |= status_bits::online_stopped;
  if (s.online_active) w |= status_bits::online_active;
  if (s.automatic_stopped) w |= status_bits::automatic_stopped;
  if (s.automatic_active) w |= status_bits::automatic_active;
  if (s.system_error) w |= status_bits::system_error;
  if (s.battery_ok) w |= status_bits::battery_ok;
  if (s.ready) w |= status_bits::ready;
  return w;
}

[[nodiscard]] constexpr ctrl_status from_status_word(std::uint16_t w) noexcept {
  return ctrl_status{
      (w & status_bits::integer_positions) != 0U, (w & status_bits::online_stopped) != 0U,
      (w & status_bits::online_active) != 0U,     (w & status_bits::automatic_stopped) != 0U,
      (w & status_bits::automatic_active) != 0U,  (w & status_bits::system_error) != 0U,
      (w & status_bits::battery_ok) != 0U,        (w & status_bits::ready) != 0U};
}

/// The 8 bytes PA-CONTROL → master (status word, words 1-3 as 0).
[[nodiscard]] constexpr std::array<std::uint8_t, ctrl_size>
encode_ctrl_status(const ctrl_status &s) noexcept {
  std::array<std::uint8_t, ctrl_size> out{};
  const auto w = to_bytes<std::uint16_t>(status_word(s), byte_order::big);
  out[0] = w[0];
  out[1] = w[1];
  return out;
}

/// The status word from the first 8 bytes of `in`; unassigned bits are ignored.
/// Errors: truncated.
[[nodiscard]] constexpr result<ctrl_status>
decode_ctrl_status(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < ctrl_size) return errc::truncated;
  return from_status_word(load<std::uint16_t>(in, byte_order::big).value());
}

} // namespace fieldcodec::pacontrol::profibus
