// fieldcodec — COMPAX device identification (manual 000, 2.3): S31_S39 (object 0x5FD6, 2.3.2)
// and the function group description FKT_GRUPPE (object 0x600F, 2.3.1).
//
// S31_S39: every sub-index holds 12 unsigned BCD digits in 6 bytes, most significant nibble
// first. Sub-indices 2 (software date) and 6 (date/version of the bus option) split the 6 bytes
// into day, month, year (one BCD byte each), version (two BCD bytes) and identifier (one BCD
// byte).
//
// FKT_GRUPPE: sub-indices 1..7, 4 bytes each: data bytes 1..2 the profile number (profile
// group and profile version), byte 3 the function group identification, byte 4 the function
// version. Where the profile number splits is not clear from the page (erratum CX-35): the bit
// ruler printed under it marks b15 b12 | b11 … b4 | b3 b0, so the group is taken from bits 15..12
// (its 14 codes 0x0…0xD fit) and the version from bits 11..0; the 16-bit number is kept as sent
// so that a reader can split it otherwise.
#pragma once

#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bcd.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <utility>

namespace fieldcodec::compax {

/// Sub-indices of S31_S39.
enum class identification_item : std::uint8_t {
  software_version = 1,
  software_date = 2,
  job_number = 3,
  part_number = 4,
  version = 5,
  bus_option_date = 6, ///< date and version of the bus option
  device_identification = 7,
  device_family = 8,
  device = 9,
};

/// True for the sub-indices whose bytes are a date record.
[[nodiscard]] constexpr bool is_date_item(identification_item i) noexcept {
  return i == identification_item::software_date || i == identification_item::bus_option_date;
}

inline constexpr std::size_t identification_size = 6;
inline constexpr std::uint64_t identification_max = 999'999'999'999;

using identification_bytes = std::array<std::uint8_t, identification_size>;

/// 12-digit number (any integer type) → 6 BCD bytes. Errors: out_of_range (negative),
/// overflow (more than 12 digits).
template <integer_argument T>
[[nodiscard]] constexpr result<identification_bytes> encode_identification(T value) noexcept {
  auto v = checked_narrow<std::uint64_t>(value);
  if (!v) return errc::out_of_range; // negative
  return bcd::encode<identification_size>(v.value());
}

/// 6 BCD bytes → number. Errors: truncated, bad_length, bad_digit.
[[nodiscard]] constexpr result<std::uint64_t>
decode_identification(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < identification_size) return errc::truncated;
  if (in.size() > identification_size) return errc::bad_length;
  return bcd::decode(in);
}

/// The date record of sub-indices 2 and 6. Year is the two-digit year as sent.
struct identification_date {
  std::uint8_t day = 1;        ///< 1..31
  std::uint8_t month = 1;      ///< 1..12
  std::uint8_t year = 0;       ///< 0..99
  std::uint16_t version = 0;   ///< 0..9999 (data bytes 4 and 5)
  std::uint8_t identifier = 0; ///< 0..99

  friend constexpr bool operator==(const identification_date &,
                                   const identification_date &) = default;
};

/// Date record → 6 BCD bytes. Errors: out_of_range (day not 1..31, month not 1..12, year or
/// identifier above 99, version above 9999).
[[nodiscard]] constexpr result<identification_bytes>
encode_identification_date(identification_date d) noexcept {
  if (d.day < 1U || d.day > 31U || d.month < 1U || d.month > 12U || d.year > 99U ||
      d.version > 9999U || d.identifier > 99U) {
    return errc::out_of_range;
  }
  identification_bytes out{};
  const std::span<std::uint8_t> o{out};
  // cannot fail: every field was range checked above
  (void)bcd::encode(d.day, o.subspan(0, 1));
  (void)bcd::encode(d.month, o.subspan(1, 1));
  (void)bcd::encode(d.year, o.subspan(2, 1));
  (void)bcd::encode(d.version, o.subspan(3, 2));
  (void)bcd::encode(d.identifier, o.subspan(5, 1));
  return out;
}

/// 6 BCD bytes → date record. Errors: truncated, bad_length, bad_digit, out_of_range (day 0 or
/// above 31, month 0 or above 12).
[[nodiscard]] constexpr result<identification_date>
decode_identification_date(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < identification_size) return errc::truncated;
  if (in.size() > identification_size) return errc::bad_length;
  auto day = bcd::decode(in.subspan(0, 1));
  auto month = bcd::decode(in.subspan(1, 1));
  auto year = bcd::decode(in.subspan(2, 1));
  auto version = bcd::decode(in.subspan(3, 2));
  auto ident = bcd::decode(in.subspan(5, 1));
  if (!day || !month || !year || !version || !ident) return errc::bad_digit;
  if (day.value() < 1U || day.value() > 31U || month.value() < 1U || month.value() > 12U) {
    return errc::out_of_range;
  }
  return identification_date{
      static_cast<std::uint8_t>(day.value()), static_cast<std::uint8_t>(month.value()),
      static_cast<std::uint8_t>(year.value()), static_cast<std::uint16_t>(version.value()),
      static_cast<std::uint8_t>(ident.value())};
}

// ------------------------------------------------------------- FKT_GRUPPE (0x600F, 2.3.1)

inline constexpr std::size_t function_group_size = 4;
inline constexpr std::uint8_t function_group_sub_min = 1;
inline constexpr std::uint8_t function_group_sub_max = 7;

/// Profile groups of the profile number (2.3.1 table; the codes 0x03, 0x05, 0x06 are
/// "reserved").
enum class profile_group : std::uint8_t {
  manufacturer_specific = 0x00, ///< no profile
  sensor_actuator = 0x01,
  drivecom = 0x02,
  interface_components = 0x04,
  encoder = 0x07,
  process_controller = 0x08,
  robot_control = 0x09,
  screw_control = 0x0A,
  iso_valve_terminal = 0x0B,
  weld_control = 0x0C,
  operating_display_device = 0x0D,
};

/// Function groups (2.3.1 table).
enum class function_group_id : std::uint8_t {
  device_control = 0x01, ///< status equipment device control
  general = 0x02,
  operation_mode = 0x03,
  speed_1 = 0x04,
  speed_2 = 0x05,
  position = 0x06,
  torque = 0x07,
  actual_value_generator = 0x08,
  factor = 0x09,
  program = 0x0A,
};

/// Short text of a profile group ("" for a reserved or unknown code).
[[nodiscard]] constexpr std::string_view to_string(profile_group g) noexcept {
  switch (g) {
  case profile_group::manufacturer_specific: return "no profile (manufacturer specific)";
  case profile_group::sensor_actuator: return "sensor/actuator";
  case profile_group::drivecom: return "DRIVECOM";
  case profile_group::interface_components: return "interface components";
  case profile_group::encoder: return "encoder";
  case profile_group::process_controller: return "process controller";
  case profile_group::robot_control: return "robot control";
  case profile_group::screw_control: return "screw control";
  case profile_group::iso_valve_terminal: return "ISO valve terminal";
  case profile_group::weld_control: return "weld control";
  case profile_group::operating_display_device: return "operating/display device";
  }
  return "";
}

/// Short text of a function group ("" for a code the table does not list).
[[nodiscard]] constexpr std::string_view to_string(function_group_id g) noexcept {
  switch (g) {
  case function_group_id::device_control: return "device control";
  case function_group_id::general: return "general functions";
  case function_group_id::operation_mode: return "operation mode functions";
  case function_group_id::speed_1: return "speed functions 1";
  case function_group_id::speed_2: return "speed functions 2";
  case function_group_id::position: return "position functions";
  case function_group_id::torque: return "torque functions";
  case function_group_id::actual_value_generator: return "actual value generator";
  case function_group_id::factor: return "factor functions";
  case function_group_id::program: return "program functions";
  }
  return "";
}

/// One FKT_GRUPPE entry, the bytes as sent. A read-only object: codes the tables do not list
/// are kept (to_string gives "" for them), not refused.
struct function_group {
  std::uint16_t profile_number = 0; ///< data bytes 1..2
  std::uint8_t group = 0;           ///< data byte 3: function group identification
  std::uint8_t version = 0;         ///< data byte 4: function version

  /// Profile group: bits 15..12 of the profile number (decision, erratum CX-35).
  [[nodiscard]] constexpr profile_group profile() const noexcept {
    return static_cast<profile_group>(profile_number >> 12U);
  }
  /// Profile version: bits 11..0 of the profile number (decision, erratum CX-35).
  [[nodiscard]] constexpr std::uint16_t profile_version() const noexcept {
    return static_cast<std::uint16_t>(profile_number & 0x0FFFU);
  }
  [[nodiscard]] constexpr function_group_id id() const noexcept {
    return static_cast<function_group_id>(group);
  }
  friend constexpr bool operator==(const function_group &, const function_group &) = default;
};

/// The profile number of a profile group and version. Errors: out_of_range (version above
/// 0xFFF, or a group above 0xF).
[[nodiscard]] constexpr result<std::uint16_t> make_profile_number(profile_group g,
                                                                  std::uint16_t version) noexcept {
  if (static_cast<std::uint8_t>(g) > 0x0FU || version > 0x0FFFU) return errc::out_of_range;
  return static_cast<std::uint16_t>((static_cast<unsigned>(g) << 12U) | version);
}

/// FKT_GRUPPE data bytes → entry. Errors: truncated, bad_length.
[[nodiscard]] constexpr result<function_group>
decode_function_group(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < function_group_size) return errc::truncated;
  if (in.size() > function_group_size) return errc::bad_length;
  return function_group{load<std::uint16_t>(in, bus_order).value(), in[2], in[3]};
}

/// Entry → FKT_GRUPPE data bytes (for simulators and tests).
[[nodiscard]] constexpr std::array<std::uint8_t, function_group_size>
encode_function_group(const function_group &f) noexcept {
  const auto p = to_bytes<std::uint16_t>(f.profile_number, bus_order);
  return {p[0], p[1], f.group, f.version};
}

} // namespace fieldcodec::compax
