// fieldcodec — Rexroth VT-HACD-DPQ emergency error codes and error register bits
// (manual RE 30146-02-Z, 3.5 "Emergency telegram").
//
// The card sends an 8-byte EMCY on 0x080 + node: bytes 0–1 error code (LSB first), byte 2
// error register (object 0x1001), bytes 3–7 manufacturer-specific (unused by the DPQ). Once
// every error is gone it sends code 0000 ("no error"). The frame, the register bits and the
// code classes are canopen/emcy.hpp; this header only adds the DPQ's codes and texts (in
// fieldcodec's own short wording of the manual's table).
#pragma once

#include <fieldcodec/canopen/emcy.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace fieldcodec::dpq {

/// The emergency error codes the DPQ documents (not every firmware sends every code).
enum class emcy_code : std::uint16_t {
  no_error = 0x0000,
  generic = 0x1000,
  current_input_cable_break = 0x3400,
  control_undervoltage = 0x3422,
  sensor = 0x5230,
  external_sensor = 0x5235,
  position_sensor = 0x5236,
  software = 0x6000,
  watchdog_reset = 0x6010,
  internal_software = 0x6100,
  user_software = 0x6200,
  data_set = 0x6300,
  parameter_lost = 0x6310,
  parameter_error = 0x6320,
  communication = 0x8100,
  control_loop_monitoring = 0x8300,
  position_monitor = 0x8301,
  pressure_monitor = 0x8302,
};

/// All 18 documented codes in ascending order.
inline constexpr std::array<emcy_code, 18> emcy_codes{
    emcy_code::no_error,
    emcy_code::generic,
    emcy_code::current_input_cable_break,
    emcy_code::control_undervoltage,
    emcy_code::sensor,
    emcy_code::external_sensor,
    emcy_code::position_sensor,
    emcy_code::software,
    emcy_code::watchdog_reset,
    emcy_code::internal_software,
    emcy_code::user_software,
    emcy_code::data_set,
    emcy_code::parameter_lost,
    emcy_code::parameter_error,
    emcy_code::communication,
    emcy_code::control_loop_monitoring,
    emcy_code::position_monitor,
    emcy_code::pressure_monitor,
};

/// True for a code listed in the DPQ manual.
[[nodiscard]] constexpr bool is_documented(std::uint16_t code) noexcept {
  for (const emcy_code c : emcy_codes) {
    if (static_cast<std::uint16_t>(c) == code) return true;
  }
  return false;
}

/// Short English text for a DPQ code; empty for a code the manual does not list.
[[nodiscard]] constexpr std::string_view describe(emcy_code c) noexcept {
  switch (c) {
  case emcy_code::no_error: return "no error (all errors cleared)";
  case emcy_code::generic: return "generic error";
  case emcy_code::current_input_cable_break: return "current input: cable break";
  case emcy_code::control_undervoltage: return "control supply undervoltage";
  case emcy_code::sensor: return "sensor fault";
  case emcy_code::external_sensor: return "external sensor fault";
  case emcy_code::position_sensor: return "position sensor fault";
  case emcy_code::software: return "software error";
  case emcy_code::watchdog_reset: return "watchdog reset";
  case emcy_code::internal_software: return "internal software error";
  case emcy_code::user_software: return "user software error";
  case emcy_code::data_set: return "data set error";
  case emcy_code::parameter_lost: return "parameters lost or overwritten";
  case emcy_code::parameter_error: return "parameter error";
  case emcy_code::communication: return "communication error";
  case emcy_code::control_loop_monitoring: return "control loop monitoring";
  case emcy_code::position_monitor: return "position monitor tripped";
  case emcy_code::pressure_monitor: return "pressure monitor tripped";
  }
  return {};
}
[[nodiscard]] constexpr std::string_view describe_emcy(std::uint16_t code) noexcept {
  return is_documented(code) ? describe(static_cast<emcy_code>(code)) : std::string_view{};
}

/// Bits of the error register (object 0x1001, EMCY byte 2). The DPQ ORs the register of all
/// present errors. Bit 6 is reserved.
namespace error_register {
inline constexpr std::uint8_t generic = canopen::emcy::reg::generic;
inline constexpr std::uint8_t current = canopen::emcy::reg::current;
inline constexpr std::uint8_t voltage = canopen::emcy::reg::voltage;
inline constexpr std::uint8_t temperature = canopen::emcy::reg::temperature;
inline constexpr std::uint8_t communication = canopen::emcy::reg::communication;
inline constexpr std::uint8_t device_profile = canopen::emcy::reg::device_profile;
inline constexpr std::uint8_t reserved = canopen::emcy::reg::reserved;
inline constexpr std::uint8_t manufacturer = canopen::emcy::reg::manufacturer;

/// Text of bit `bit` (0..7); empty for a bit number above 7.
[[nodiscard]] constexpr std::string_view describe_bit(unsigned bit) noexcept {
  switch (bit) {
  case 0: return "generic error";
  case 1: return "current";
  case 2: return "voltage";
  case 3: return "temperature";
  case 4: return "communication";
  case 5: return "device profile";
  case 6: return "reserved";
  case 7: return "manufacturer-specific";
  default: return {};
  }
}

/// The texts of the set bits of `reg`, lowest bit first, in `out`; returns how many were set.
[[nodiscard]] constexpr std::size_t describe(std::uint8_t reg,
                                             std::array<std::string_view, 8> &out) noexcept {
  std::size_t n = 0;
  for (unsigned bit = 0; bit < 8U; ++bit) {
    if (((unsigned{reg} >> bit) & 1U) != 0U) out[n++] = describe_bit(bit);
  }
  return n;
}

/// True when bit 6 (reserved, always 0 in CiA 301) is set.
[[nodiscard]] constexpr bool has_reserved_bit(std::uint8_t reg) noexcept {
  return (reg & reserved) != 0U;
}
} // namespace error_register

/// The error register bit a CiA 301 error code class implies (canopen::emcy::classify):
/// current → current, voltage → voltage, temperature → temperature, 0x81xx/0x82xx →
/// communication, 0xFFxx → manufacturer; 0 otherwise. The generic bit (bit 0) is set by the
/// device for every error and is not included here.
[[nodiscard]] constexpr std::uint8_t implied_register_bit(std::uint16_t code) noexcept {
  using canopen::emcy::error_class;
  switch (canopen::emcy::classify(code)) {
  case error_class::current: return error_register::current;
  case error_class::voltage: return error_register::voltage;
  case error_class::temperature: return error_register::temperature;
  case error_class::monitoring:
    if ((code >> 8U) == 0x81U || (code >> 8U) == 0x82U) return error_register::communication;
    return 0;
  case error_class::device_specific: return error_register::manufacturer;
  default: return 0;
  }
}

} // namespace fieldcodec::dpq
