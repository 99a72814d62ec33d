// fieldcodec — PA-CONTROL module/axis blocks on Profibus-DP (12 bytes each, up to 8) and the
// layout of the whole process image.
//
// ONLINE (and HOME POSITION) mode, one block per axis:
//   master → PA-CONTROL   control word (32 bit) | acceleration ‰ (16) | speed ‰ (16) | target
//   PA-CONTROL → master   status word (32 bit)  | CMD error no. (16)   | axis error (16) | position
// AUTOMATIC mode, one block per module k: flag word FWk, register Nk, register Rk (master →
// PA-CONTROL modules 1-8, PA-CONTROL → master modules 17-24). The printed size row of that
// table (4 | 2 | 2 | 4 bytes under FW | not used | N | R) puts a 16-bit flag word in 4 bytes
// and a 32-bit N register in 2; module_layout selects a reading (docs/pacontrol.md).
// Positions and R registers are float or ×1000 integer per the CTRL bit (position.hpp).
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/pacontrol/position.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace fieldcodec::pacontrol::profibus {

inline constexpr std::size_t module_size = 12;
inline constexpr std::size_t max_modules = 8;

/// Control word of an axis (master → PA-CONTROL), bits as on the wire.
namespace axis_control {
inline constexpr std::uint32_t axis_on = 1U << 0U;
inline constexpr std::uint32_t disable_drive = 1U << 1U;  ///< G140 / G141
inline constexpr std::uint32_t start = 1U << 2U;          ///< rising edge starts the traverse
inline constexpr std::uint32_t reference_run = 1U << 3U;  ///< G25
inline constexpr std::uint32_t set_referenced = 1U << 4U; ///< G26 (printed "G29", errata)
inline constexpr std::uint32_t set_position = 1U << 5U;   ///< G29
inline constexpr std::uint32_t absolute = 1U << 6U;
inline constexpr std::uint32_t relative = 1U << 7U;
inline constexpr std::uint32_t while_input_1 = 1U << 8U; ///< G123 Ix..1
inline constexpr std::uint32_t while_input_0 = 1U << 9U; ///< G123 Ix..0
inline constexpr std::uint32_t jog_positive = 1U << 10U; ///< no reference or range check
inline constexpr std::uint32_t jog_negative = 1U << 11U; ///< no reference or range check
inline constexpr std::uint32_t delete_g29_offset = 1U << 12U;
inline constexpr std::uint32_t reset_moved_while_off = 1U << 13U;
inline constexpr std::uint32_t to_max_range = 1U << 14U;
inline constexpr std::uint32_t to_min_range = 1U << 15U;
inline constexpr std::uint32_t reset_axis_error = 1U << 16U;
inline constexpr std::uint32_t disable_limit_switches = 1U << 17U; ///< G142
inline constexpr std::uint32_t reserved = 0xFFFC'0000U;            ///< bits 18-31
} // namespace axis_control

/// Status word of an axis (PA-CONTROL → master).
namespace axis_state {
inline constexpr std::uint32_t drive_enabled = 1U << 0U;
inline constexpr std::uint32_t halt = 1U << 1U;
inline constexpr std::uint32_t drive_disabled = 1U << 2U;
inline constexpr std::uint32_t safe = 1U << 3U;
inline constexpr std::uint32_t idle = 1U << 4U;
inline constexpr std::uint32_t disabled = 1U << 5U;
inline constexpr std::uint32_t fault = 1U << 6U;
inline constexpr std::uint32_t active = 1U << 7U;
inline constexpr std::uint32_t referenced = 1U << 8U;
inline constexpr std::uint32_t negative_limit_n = 1U << 9U;  ///< 0 = limit switch actuated
inline constexpr std::uint32_t positive_limit_n = 1U << 10U; ///< 0 = limit switch actuated
inline constexpr std::uint32_t stopped_by_g123 = 1U << 11U;
inline constexpr std::uint32_t displaced_while_off = 1U << 12U;
inline constexpr std::uint32_t group_displaced_while_off = 1U << 13U;
inline constexpr std::uint32_t command_error = 1U << 14U; ///< read command_error_number
inline constexpr std::uint32_t axis_error = 1U << 15U;    ///< read axis_error_number
} // namespace axis_state

/// Acceleration and speed are per mill of the axis parameter (2.7.5, 2.7.6).
inline constexpr std::uint16_t min_acceleration = 1;
inline constexpr std::uint16_t max_speed = 1000;

/// One axis, master → PA-CONTROL (ONLINE mode).
struct axis_command {
  std::uint32_t control = 0;         ///< axis_control bits
  std::uint16_t acceleration = 1000; ///< ‰ of the acceleration parameter, 1 … 65535
  std::uint16_t speed = 1000;        ///< ‰ of the traverse speed parameter, 1 … 1000
  float target = 0.0F;               ///< target position

  friend constexpr bool operator==(const axis_command &, const axis_command &) noexcept = default;
};

/// One axis, PA-CONTROL → master.
struct axis_status {
  std::uint32_t status = 0;               ///< axis_state bits
  std::uint16_t command_error_number = 0; ///< the axis's command error number (QUIT numbers)
  std::uint16_t axis_error_number = 0;    ///< the axis's error number (Exxx)
  float position = 0.0F;                  ///< current position

  [[nodiscard]] constexpr bool has(std::uint32_t bits) const noexcept {
    return (status & bits) == bits;
  }
  /// The limit switch bits are active low: 0 means actuated.
  [[nodiscard]] constexpr bool negative_limit_actuated() const noexcept {
    return (status & axis_state::negative_limit_n) == 0U;
  }
  [[nodiscard]] constexpr bool positive_limit_actuated() const noexcept {
    return (status & axis_state::positive_limit_n) == 0U;
  }
  friend constexpr bool operator==(const axis_status &, const axis_status &) noexcept = default;
};

/// The 12 bytes of an axis command.
/// Errors: invalid_argument (reserved control bits 18-31 set), out_of_range (acceleration 0,
/// speed 0 or above 1000), not_representable (NaN/∞ target), overflow (×1000 beyond int32).
[[nodiscard]] constexpr result<std::array<std::uint8_t, module_size>>
encode_axis_command(const axis_command &c, position_format format) noexcept {
  if ((c.control & axis_control::reserved) != 0U) return errc::invalid_argument;
  if (c.acceleration < min_acceleration) return errc::out_of_range;
  if (c.speed < 1U || c.speed > max_speed) return errc::out_of_range;
  auto pos = encode_position(c.target, format);
  if (!pos) return pos.error();
  std::array<std::uint8_t, module_size> out{};
  byte_writer w(out);
  FIELDCODEC_TRY_STATUS(w.write<std::uint32_t>(c.control, byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write<std::uint16_t>(c.acceleration, byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write<std::uint16_t>(c.speed, byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write_bytes(pos.value()));
  return out;
}

/// An axis command from 12 bytes (the PA-CONTROL side). Values are taken as they are; only
/// what cannot be represented fails. Errors: truncated, not_representable (NaN/∞ target).
[[nodiscard]] constexpr result<axis_command> decode_axis_command(std::span<const std::uint8_t> in,
                                                                 position_format format) noexcept {
  if (in.size() < module_size) return errc::truncated;
  byte_reader r(in);
  const auto control = r.read<std::uint32_t>(byte_order::big).value();
  const auto acc = r.read<std::uint16_t>(byte_order::big).value();
  const auto speed = r.read<std::uint16_t>(byte_order::big).value();
  auto pos = decode_position(r.rest(), format);
  if (!pos) return pos.error();
  return axis_command{control, acc, speed, pos.value()};
}

/// The 12 bytes of an axis status (the PA-CONTROL side, simulators).
/// Errors: not_representable, overflow (position).
[[nodiscard]] constexpr result<std::array<std::uint8_t, module_size>>
encode_axis_status(const axis_status &s, position_format format) noexcept {
  auto pos = encode_position(s.position, format);
  if (!pos) return pos.error();
  std::array<std::uint8_t, module_size> out{};
  byte_writer w(out);
  FIELDCODEC_TRY_STATUS(w.write<std::uint32_t>(s.status, byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write<std::uint16_t>(s.command_error_number, byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write<std::uint16_t>(s.axis_error_number, byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write_bytes(pos.value()));
  return out;
}

/// An axis status from 12 bytes. Errors: truncated, not_representable (NaN/∞ position).
[[nodiscard]] constexpr result<axis_status> decode_axis_status(std::span<const std::uint8_t> in,
                                                               position_format format) noexcept {
  if (in.size() < module_size) return errc::truncated;
  byte_reader r(in);
  const auto status = r.read<std::uint32_t>(byte_order::big).value();
  const auto cmd_err = r.read<std::uint16_t>(byte_order::big).value();
  const auto axis_err = r.read<std::uint16_t>(byte_order::big).value();
  auto pos = decode_position(r.rest(), format);
  if (!pos) return pos.error();
  return axis_status{status, cmd_err, axis_err, pos.value()};
}

// ---------------------------------------------------------------------------------------------
// AUTOMATIC mode: flag word, N register, R register.

/// How the 12 bytes of a flag/register module are read (see the header comment).
enum class module_layout : std::uint8_t {
  /// FW 2 bytes | 2 unused | N 4 bytes | R 4 bytes: every value in a field of its own width,
  /// 32-bit fields on 4-byte boundaries. The default.
  word_aligned,
  /// The printed size row taken literally: FW in 4 bytes (flags in the low 16 bits, bytes 2-3)
  /// | 2 unused | N 2 bytes (int16) | R 4 bytes.
  as_printed,
};

/// One AUTOMATIC module: FWk (flags M16k-15 … M16k, bit 0 = lowest flag), Nk and Rk.
struct flag_module {
  std::uint16_t flags = 0;
  std::int32_t n = 0;
  float r = 0.0F;

  friend constexpr bool operator==(const flag_module &, const flag_module &) noexcept = default;
};

/// Errors: overflow (N outside int16 in as_printed layout; R ×1000 beyond int32),
/// not_representable (NaN/∞ R).
[[nodiscard]] constexpr result<std::array<std::uint8_t, module_size>>
encode_flag_module(const flag_module &m, position_format format,
                   module_layout layout = module_layout::word_aligned) noexcept {
  auto r = encode_position(m.r, format);
  if (!r) return r.error();
  std::array<std::uint8_t, module_size> out{};
  byte_writer w(out);
  if (layout == module_layout::word_aligned) {
    FIELDCODEC_TRY_STATUS(w.write<std::uint16_t>(m.flags, byte_order::big));
    FIELDCODEC_TRY_STATUS(w.pad(2));
    FIELDCODEC_TRY_STATUS(w.write<std::int32_t>(m.n, byte_order::big));
  } else {
    FIELDCODEC_TRY_STATUS(w.write<std::uint32_t>(m.flags, byte_order::big));
    FIELDCODEC_TRY_STATUS(w.pad(2));
    FIELDCODEC_TRY_STATUS(w.write_signed(2, m.n, byte_order::big));
  }
  FIELDCODEC_TRY_STATUS(w.write_bytes(r.value()));
  return out;
}

/// Errors: truncated, not_representable (NaN/∞ R).
[[nodiscard]] constexpr result<flag_module>
decode_flag_module(std::span<const std::uint8_t> in, position_format format,
                   module_layout layout = module_layout::word_aligned) noexcept {
  if (in.size() < module_size) return errc::truncated;
  byte_reader rd(in);
  flag_module m{};
  if (layout == module_layout::word_aligned) {
    m.flags = rd.read<std::uint16_t>(byte_order::big).value();
    FIELDCODEC_TRY_STATUS(rd.skip(2));
    m.n = rd.read<std::int32_t>(byte_order::big).value();
  } else {
    m.flags = static_cast<std::uint16_t>(rd.read<std::uint32_t>(byte_order::big).value());
    FIELDCODEC_TRY_STATUS(rd.skip(2));
    m.n = rd.read<std::int16_t>(byte_order::big).value();
  }
  auto r = decode_position(rd.rest(), format);
  if (!r) return r.error();
  m.r = r.value();
  return m;
}

// ---------------------------------------------------------------------------------------------
// The whole image: CMD (8) [+ CTRL (8) [+ 1 … 8 modules (12 each)]], 8 … 112 bytes.

/// Size of the process image in each direction.
/// Errors: out_of_range (more than 8 modules), invalid_argument (modules without CTRL: the
/// CTRL interface is the first extension, the modules come after it).
[[nodiscard]] constexpr result<std::size_t> image_size(bool with_ctrl,
                                                       std::size_t modules) noexcept {
  if (modules > max_modules) return errc::out_of_range;
  if (modules > 0U && !with_ctrl) return errc::invalid_argument;
  return std::size_t{8} + (with_ctrl ? 8U : 0U) + modules * module_size;
}

/// Offset of the CTRL block in the image.
inline constexpr std::size_t ctrl_offset = 8;

/// Offset of module/axis block `index` (0 … 7) in an image with CTRL. Errors: out_of_range.
[[nodiscard]] constexpr result<std::size_t> module_offset(std::size_t index) noexcept {
  if (index >= max_modules) return errc::out_of_range;
  return std::size_t{16} + index * module_size;
}

} // namespace fieldcodec::pacontrol::profibus
