// fieldcodec — COMPAX control and status objects (manual 000, sections 2.4, 2.7.13, 2.7.14,
// 2.8.2, 2.9.1, 2.10): typed words with named bits and typed selection codes.
//
// Bit numbers are word bits: data byte 1 of a 2-byte object is bits 15..8, data byte 2 bits
// 7..0 (so "1[1]" is bit 9 and "2[1]" is bit 1).
//
// STEUERWORT / STATUSWORT (0x6040 / 0x6041) are the DRIVECOM profile 22 words; their low byte
// has the bit positions of the CiA 402 controlword/statusword (DRIVECOM is its ancestor), so
// the ds402 module's state machine applies to the whole word unchanged (drivecom.hpp).
#pragma once

#include <fieldcodec/compax/bits.hpp>
#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

namespace fieldcodec::compax {

// ---------------------------------------------------------------- STEUERBYTE (0x5FCE, 2.4.3)

enum class steuerbyte_bit : std::uint8_t {
  record_0 = 0, ///< record select 2^0 (bits 3..0: record 1..15, 0 = go to machine zero)
  record_1 = 1, ///< record select 2^1 (printed "2^3", erratum CX-16)
  record_2 = 2,
  record_3 = 3,
  start = 4,            ///< rising edge: start as selected by bit 5; falling edge: stop
  continue_program = 5, ///< 1: continue the program, 0: new start at the selected record
  stop = 6,             ///< rising edge: stop with ramp P10 without clearing
  quit = 7,             ///< rising edge: acknowledge an error (not with P190 = 22)
};

struct steuerbyte : bit_word<steuerbyte_bit, std::uint8_t> {
  /// The selected record (0..15; 0 with a new start approaches machine zero).
  [[nodiscard]] constexpr std::uint8_t record() const noexcept {
    return static_cast<std::uint8_t>(raw & 0x0FU);
  }
  /// Select a record (any integer type). Errors: out_of_range (not 0..15).
  template <integer_argument T>
  [[nodiscard]] constexpr status set_record(T n) noexcept {
    if (!in_closed_range(n, 0, 15)) return errc::out_of_range;
    raw = static_cast<std::uint8_t>((raw & 0xF0U) | static_cast<unsigned>(n));
    return {};
  }
};

// ---------------------------------------------------------------- STATUSBYTE (0x5FCF, 2.4.4)

enum class statusbyte_bit : std::uint8_t {
  fault = 0,
  warning = 1,
  ready_for_start = 2,
  lag_error = 3,
  motor_stalled = 4,
  position_reached = 5, ///< programmed nominal position reached
  idle_after_stop = 6,
  machine_zero_approached = 7,
};
using statusbyte = bit_word<statusbyte_bit, std::uint8_t>;

// ---------------------------------------------------------------- CPX_STW (0x5FD2, 2.4.5)

/// Device functions of CPX_STW (enabled by P221/P222). The second name of a bit is its
/// function while SHIFT (bit 0) is set.
enum class cpx_stw_bit : std::uint8_t {
  shift = 0,
  hand_plus = 1,
  approach_machine_zero = 1, ///< with SHIFT
  hand_minus = 2,
  approach_real_zero = 2, ///< with SHIFT
  quit = 3,               ///< not with P190 = 22
  teach_real_zero = 3,    ///< with SHIFT
  start = 4,
  stop = 5,
  break_ = 5,            ///< with SHIFT
  freeze_pad = 8,        ///< 1[0], OBJECT_REQ handshake (PD length 8, P196 bits 5 and 7 set)
  object_req_enable = 9, ///< 1[1], OBJECT_REQ handshake (erratum CX-17)
};

struct cpx_stw : bit_word<cpx_stw_bit, std::uint16_t> {
  /// Virtual input E17..E32 (word bit n − 17; any integer type). Errors: out_of_range.
  template <integer_argument T>
  [[nodiscard]] constexpr result<bool> virtual_input(T n) const noexcept {
    if (!in_closed_range(n, 17, 32)) return errc::out_of_range;
    return ((raw >> (static_cast<unsigned>(n) - 17U)) & 1U) != 0U;
  }
  template <integer_argument T>
  [[nodiscard]] constexpr status set_virtual_input(T n, bool on) noexcept {
    if (!in_closed_range(n, 17, 32)) return errc::out_of_range;
    const auto m = static_cast<std::uint16_t>(1U << (static_cast<unsigned>(n) - 17U));
    raw = on ? static_cast<std::uint16_t>(raw | m) : static_cast<std::uint16_t>(raw & ~m);
    return {};
  }
};

// ---------------------------------------------------------------- CPX_ZSW (0x5FD3, 2.4.6)

/// CPX_ZSW with P203 bit 0 = 0 (standard). Bits 0 and 1 are inverted: 1 = no fault / no
/// warning. Use has_fault()/has_warning() rather than reading them directly.
enum class cpx_zsw_bit : std::uint8_t {
  no_fault = 0,
  no_warning = 1,
  machine_zero_reached = 2,
  ready_for_start = 3,
  target_position_reached = 4,
  idle_after_stop = 5,
  lag_error = 6,
  motor_stalled = 7,
  ack_toggle = 8, ///< also status A9 (AckToggle only in the 8-byte OBJECT_REQ mode)
  status_a9 = 8,
  status_a10 = 9,
  status_a11 = 10,
  status_a12 = 11,
  status_a13 = 12,
  status_a14 = 13,
  status_a15 = 14,
  status_a16 = 15,
};
using cpx_zsw = bit_word<cpx_zsw_bit, std::uint16_t>;

/// CPX_ZSW with P203 bit 0 = 1 (status S16/S17 assigned). Bits 7..6 are the OUTPUT A0 state
/// (see output_a0()); bits 0 and 1 are inverted as in the standard layout.
enum class cpx_zsw_s16_bit : std::uint8_t {
  no_fault = 0,
  no_warning = 1,
  machine_zero_reached = 2,
  ready_for_start = 3,
  target_position_reached = 4,
  idle_after_stop = 5,
  output_a0_low = 6,
  output_a0_high = 7,
  ack_toggle = 8, ///< also "password 302 active"
  password_302_active = 8,
  service_password_active = 9,
  command_active = 10,
  program_running = 11,
  stop_via_e6 = 12,
  run = 14, ///< 0: drive off, or switched off by an error
};
using cpx_zsw_s16 = bit_word<cpx_zsw_s16_bit, std::uint16_t>;

template <class W>
concept cpx_status_word = std::is_same_v<W, cpx_zsw> || std::is_same_v<W, cpx_zsw_s16>;

/// Fault present (the "no fault" bit is clear).
template <cpx_status_word W>
[[nodiscard]] constexpr bool has_fault(W w) noexcept {
  return !w.test(W::bit_type::no_fault);
}
/// Warning present (the "no warning" bit is clear).
template <cpx_status_word W>
[[nodiscard]] constexpr bool has_warning(W w) noexcept {
  return !w.test(W::bit_type::no_warning);
}
/// The last OUTPUT A0=x (0, 1 or 2). Errors: out_of_range (bits 7..6 = 11).
[[nodiscard]] constexpr result<std::uint8_t> output_a0(cpx_zsw_s16 w) noexcept {
  const auto v = static_cast<std::uint8_t>((w.raw >> 6U) & 0x03U);
  if (v == 3U) return errc::out_of_range;
  return v;
}

// ------------------------------------------------ STEUERWORT / STATUSWORT (0x6040/0x6041)

/// STEUERWORT. Bits 7..0 are the DRIVECOM/CiA 402 controlword bits, bits 15..8 COMPAX
/// functions. Every bit has its CiA 402 name and, where it differs, the manual's own term
/// (2.4.7) as a second name with the same value. Bits 1 and 2 are active low: the manual's
/// "Disable voltage" and "Rapid stop" happen when the bit is 0, so their manual names carry the
/// suffix _n (0 = active): set(enable_voltage) == set(disable_voltage_n) enables the voltage.
enum class steuerwort_bit : std::uint8_t {
  switch_on = 0,
  power_on = 0, ///< manual: "Power on"
  enable_voltage = 1,
  disable_voltage_n = 1, ///< manual: "Disable voltage", active low (0 = disable voltage)
  quick_stop = 2,
  rapid_stop_n = 2, ///< manual: "Rapid stop", active low (0 = rapid stop)
  enable_operation = 3,
  new_set_point = 4, ///< LAGE_ZIEL handshake (set_point.hpp)
  relative = 6,
  target_position_relative = 6, ///< manual: "Target position relative (1) or absolute (0)"
  fault_reset = 7,
  reset_fault = 7,            ///< manual: "Reset fault"
  freeze_pad = 8,             ///< 1[0] "FreezePAD"
  object_req_enable = 9,      ///< 1[1] "ObjectReqEnable"
  approach_machine_zero = 10, ///< 1[2] "Approach machine zero (MZ)"
  hand_plus = 11,             ///< 1[3] "Hand+"
  hand_minus = 12,            ///< 1[4] "Hand-"
  start = 13,                 ///< 1[5] "START"
  stop = 14,                  ///< 1[6] "STOP"
  spm = 15,                   ///< 1[7] "SPM", toggled by the master to acknowledge a pop-up message
};
using steuerwort = bit_word<steuerwort_bit, std::uint16_t>;

/// The manual's term for a STEUERWORT bit (2.4.7; "" for bit 5, which it leaves empty).
[[nodiscard]] constexpr std::string_view manual_term(steuerwort_bit b) noexcept {
  constexpr std::array<std::string_view, 16> terms{"Power on",
                                                   "Disable voltage",
                                                   "Rapid stop",
                                                   "Enable operation",
                                                   "New set point",
                                                   "",
                                                   "Target position relative or absolute",
                                                   "Reset fault",
                                                   "FreezePAD",
                                                   "ObjectReqEnable",
                                                   "Approach machine zero (MZ)",
                                                   "Hand+",
                                                   "Hand-",
                                                   "START",
                                                   "STOP",
                                                   "SPM"};
  const auto n = static_cast<std::size_t>(b);
  return n < terms.size() ? terms[n] : std::string_view{};
}

/// STATUSWORT (normal display, i.e. while SPM of status and control word are equal). CiA 402
/// names and, where they differ, the manual's terms (2.4.8) as second names.
enum class statuswort_bit : std::uint8_t {
  ready_to_switch_on = 0,
  ready_to_start = 0, ///< manual: "Ready to start"
  switched_on = 1,
  operation_enabled = 2,
  fault = 3,
  voltage_disabled = 4, ///< manual: "Voltage disabled" (CiA 402: voltage enabled)
  quick_stop = 5,
  rapid_stop_n = 5, ///< manual: "Rapid stop", active low as in CiA 402 (0 = rapid stop)
  switch_on_disabled = 6,
  warning = 7,
  message = 8, ///< also AckToggle in the 8-byte OBJECT_REQ mode
  ack_toggle = 8,
  remote = 9,
  set_point_reached = 10,
  limit_value = 11,
  set_point_acknowledge = 12,        ///< LAGE_ZIEL handshake (set_point.hpp); erratum CX-36
  actual_value_acknowledgement = 12, ///< manual's table: "Actual value acknowledgement"
  machine_zero_reached = 13,
  mn_reached = 13, ///< manual: "MN was reached"
  idle_after_stop = 14,
  spm = 15,
};
using statuswort = bit_word<statuswort_bit, std::uint16_t>;

/// The manual's term for a STATUSWORT bit (2.4.8).
[[nodiscard]] constexpr std::string_view manual_term(statuswort_bit b) noexcept {
  constexpr std::array<std::string_view, 16> terms{"Ready to start",
                                                   "Switched on",
                                                   "Operation enabled",
                                                   "Fault",
                                                   "Voltage disabled",
                                                   "Rapid stop",
                                                   "Switch on disabled",
                                                   "Warning",
                                                   "Message/AckToggle",
                                                   "Remote",
                                                   "Set point reached",
                                                   "Limit value",
                                                   "Actual value acknowledgement",
                                                   "MN was reached",
                                                   "Idle after stop",
                                                   "SPM"};
  const auto n = static_cast<std::size_t>(b);
  return n < terms.size() ? terms[n] : std::string_view{};
}

/// Kind of a pop-up message (2.4.9; enabled by P193).
enum class popup_kind : std::uint8_t {
  error = 1,
  set_point_reached = 2,
  comparator_reached = 3,
};

/// A pop-up message shown in STATUSWORT: identifier in bits 14..8, error or comparator number
/// in bits 7..0.
struct popup_message {
  popup_kind kind = popup_kind::error;
  std::uint8_t number = 0;
  friend constexpr bool operator==(const popup_message &, const popup_message &) = default;
};

/// True when STATUSWORT shows a pop-up message (its SPM differs from the control word's).
[[nodiscard]] constexpr bool shows_popup(statuswort s, steuerwort c) noexcept {
  return s.test(statuswort_bit::spm) != c.test(steuerwort_bit::spm);
}

/// The pop-up message in `s`. Errors: bad_state (no pop-up shown), out_of_range (unknown
/// identifier).
[[nodiscard]] constexpr result<popup_message> decode_popup(statuswort s, steuerwort c) noexcept {
  if (!shows_popup(s, c)) return errc::bad_state;
  const auto id = static_cast<std::uint8_t>((s.raw >> 8U) & 0x7FU);
  if (id < 1U || id > 3U) return errc::out_of_range;
  return popup_message{static_cast<popup_kind>(id), static_cast<std::uint8_t>(s.raw & 0xFFU)};
}

/// The control word that acknowledges the pop-up message shown in `s` (SPM made equal).
[[nodiscard]] constexpr steuerwort acknowledge_popup(statuswort s, steuerwort c) noexcept {
  return c.with(steuerwort_bit::spm, s.test(statuswort_bit::spm));
}

// ---------------------------------------------------------------- CONTROL (0x5FE9, 2.4.10)

enum class control_command : std::uint8_t {
  go_to_machine_zero = 1,
  program_start = 2,
  stop = 3,
  break_ = 4,
  acknowledge_error = 5,
  teach_real_zero = 6, ///< read current position as real null
  declare_valid = 7,
  declare_configuration_valid = 8,
  speed_from_external_encoder = 9,
  torque_free_brake_open = 10,
  dead_brake_closed = 11,
  dead_brake_open = 12,
  jump_via_inputs = 13,
  password_off_302 = 14,
  password_on_270 = 15,
  password_off_620 = 16,
  declare_curve_valid = 17,
  emergency_stop_clear = 18,
  emergency_stop_keep = 19,
  object_rsp_enable = 20,
  object_rsp_disable = 21,
};

/// Errors: out_of_range (0 or 22..255: not assigned).
[[nodiscard]] constexpr result<control_command> decode_control(std::uint8_t b) noexcept {
  if (b < 1U || b > 21U) return errc::out_of_range;
  return static_cast<control_command>(b);
}

[[nodiscard]] constexpr std::string_view to_string(control_command c) noexcept {
  switch (c) {
  case control_command::go_to_machine_zero: return "go to machine zero";
  case control_command::program_start: return "start program";
  case control_command::stop: return "stop program or positioning";
  case control_command::break_: return "break program or positioning";
  case control_command::acknowledge_error: return "acknowledge error";
  case control_command::teach_real_zero: return "take current position as real zero";
  case control_command::declare_valid: return "declare valid";
  case control_command::declare_configuration_valid: return "declare configuration valid";
  case control_command::speed_from_external_encoder: return "speed from external encoder";
  case control_command::torque_free_brake_open: return "torque-free, brake open";
  case control_command::dead_brake_closed: return "drive off, brake closed";
  case control_command::dead_brake_open: return "drive off, brake open";
  case control_command::jump_via_inputs: return "program jump via inputs";
  case control_command::password_off_302: return "password off (302)";
  case control_command::password_on_270: return "password on (270)";
  case control_command::password_off_620: return "password off (620)";
  case control_command::declare_curve_valid: return "declare curve valid";
  case control_command::emergency_stop_clear: return "emergency stop, clear";
  case control_command::emergency_stop_keep: return "emergency stop, keep";
  case control_command::object_rsp_enable: return "OBJECT_RSP on PED";
  case control_command::object_rsp_disable: return "OBJECT_RSP off PED";
  }
  return "";
}

// ------------------------------------------------- selection codes (Integer16, big-endian)

/// BETRIEBSART / BETR_ART_AZ (0x6060 / 0x6061, 2.4.1).
enum class operating_mode : std::int16_t {
  reset = -2,
  continuous = -1,
  target_position = 1,
  speed_input_2 = 3,
};
/// REF_MODE (0x6098, 2.7.14): approach the machine-zero initiator in direction 1 or 2.
enum class ref_mode : std::int16_t {
  initiator_direction_1 = 8,
  initiator_direction_2 = 12,
};
/// RAMPENFORM (0x6086, 2.9.1).
enum class ramp_form : std::int16_t {
  square = -1,
  linear = 0,
  jerk_free = 2,
};

namespace detail {
template <class E>
[[nodiscard]] constexpr bool is_known(E e) noexcept {
  if constexpr (std::is_same_v<E, operating_mode>) {
    return e == operating_mode::reset || e == operating_mode::continuous ||
           e == operating_mode::target_position || e == operating_mode::speed_input_2;
  } else if constexpr (std::is_same_v<E, ref_mode>) {
    return e == ref_mode::initiator_direction_1 || e == ref_mode::initiator_direction_2;
  } else {
    return e == ramp_form::square || e == ramp_form::linear || e == ramp_form::jerk_free;
  }
}
} // namespace detail

template <class E>
concept selection_code = std::is_same_v<E, operating_mode> || std::is_same_v<E, ref_mode> ||
    std::is_same_v<E, ramp_form>;

/// A selection code's 2 bytes.
template <selection_code E>
[[nodiscard]] constexpr std::array<std::uint8_t, 2> encode_selection(E e) noexcept {
  return to_bytes<std::int16_t>(static_cast<std::int16_t>(e), bus_order);
}
/// 2 bytes → selection code. Errors: truncated, bad_length, out_of_range (code not listed).
template <selection_code E>
[[nodiscard]] constexpr result<E> decode_selection(std::span<const std::uint8_t> in) noexcept {
  auto v = decode_integer<std::int16_t>(in);
  if (!v) return v.error();
  const auto e = static_cast<E>(v.value());
  if (!detail::is_known(e)) return errc::out_of_range;
  return e;
}

// ---------------------------------------------------------------- POLARITAET (0x607E)

/// Bit 7: 1 = direction reversed (motor turns left), 0 = default (right). Other bits ignored.
[[nodiscard]] constexpr std::uint8_t encode_polarity(bool reversed) noexcept {
  return reversed ? 0x80U : 0x00U;
}
[[nodiscard]] constexpr bool decode_polarity(std::uint8_t b) noexcept { return (b & 0x80U) != 0U; }

// ---------------------------------------------------------------- OVERRIDE (0x5FEE, 2.8.2)

/// 255 = 100 % (erratum CX-13: not "1 = 1/255 %").
inline constexpr scaling::linear override_scale{decimal{255, 2}, decimal{0, 0}};

/// Percent (0..100) → byte, rounded half away from zero. Errors: out_of_range.
[[nodiscard]] constexpr result<std::uint8_t> encode_override(decimal percent) noexcept {
  auto raw = scaling::to_raw(percent, override_scale, scaling::field{1, false},
                             scaling::range{decimal{0, 0}, decimal{100, 0}});
  if (!raw) return raw.error();
  return static_cast<std::uint8_t>(raw.value());
}
/// Byte → percent, rounded to `places` decimals (default 2).
[[nodiscard]] constexpr result<decimal> decode_override(std::uint8_t b,
                                                        unsigned places = 2) noexcept {
  return scaling::to_eu_decimal(b, override_scale, places);
}

// ------------------------------------------ digital I/O words and PA_ENABLE (2.10, 2.12.8)

/// INPUT_WORD, OUTPUT_WORD, OUTPUT_MASK: bit n − 1 is input/output n (1..16).
struct io_word {
  std::uint16_t raw = 0;
  /// Input/output n (any integer type). Errors: out_of_range (n not 1..16).
  template <integer_argument T>
  [[nodiscard]] constexpr result<bool> test(T n) const noexcept {
    if (!in_closed_range(n, 1, 16)) return errc::out_of_range;
    return ((raw >> (static_cast<unsigned>(n) - 1U)) & 1U) != 0U;
  }
  template <integer_argument T>
  [[nodiscard]] constexpr status set(T n, bool on = true) noexcept {
    if (!in_closed_range(n, 1, 16)) return errc::out_of_range;
    const auto m = static_cast<std::uint16_t>(1U << (static_cast<unsigned>(n) - 1U));
    raw = on ? static_cast<std::uint16_t>(raw | m) : static_cast<std::uint16_t>(raw & ~m);
    return {};
  }
  [[nodiscard]] constexpr std::array<std::uint8_t, 2> bytes() const noexcept {
    return to_bytes<std::uint16_t>(raw, bus_order);
  }
  [[nodiscard]] static constexpr result<io_word> decode(std::span<const std::uint8_t> in) noexcept {
    auto v = decode_integer<std::uint16_t>(in);
    if (!v) return v.error();
    return io_word{v.value()};
  }
  friend constexpr bool operator==(const io_word &, const io_word &) = default;
};

/// PA_ENABLE: bits 0..5 enable PA byte 1..6 (3..8 with 8-byte process data); bit 7 = 1 stops
/// the automatic acceptance of a changed LAGE_ZIEL.
enum class pa_enable_bit : std::uint8_t {
  pa_byte_1 = 0,
  pa_byte_2 = 1,
  pa_byte_3 = 2,
  pa_byte_4 = 3,
  pa_byte_5 = 4,
  pa_byte_6 = 5,
  no_auto_target = 7,
};
using pa_enable = bit_word<pa_enable_bit, std::uint8_t>;

} // namespace fieldcodec::compax
