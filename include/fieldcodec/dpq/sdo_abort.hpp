// fieldcodec — the Rexroth VT-HACD-DPQ SDO abort table mapped onto CiA 301 abort codes
// (manual RE 30146-02-Z, 3.3 "Interruption of an SDO transfer").
//
// The manual prints an abort frame as: byte 0 = 0x80, bytes 1–3 index and sub-index, bytes 4+5
// "additional code", byte 6 "error code", byte 7 "error class", and lists each abort as the
// four bytes 4, 5, 6, 7. Read little-endian, bytes 4–7 are exactly the CiA 301 32-bit abort
// code: class << 24 | code << 16 | additional. Every one of the 16 rows is a standard CiA 301
// abort code. This table keeps what only the DPQ manual says (its byte columns and its own
// wording, fieldcodec's short form of it); the CiA 301 description and the nearest errc come
// from the one abort table of canopen/sdo.hpp (`canopen::sdo::abort_codes`), shared with the
// SDO client and server. The frame itself is built and parsed by the generic SDO layer.
#pragma once

#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <string_view>

namespace fieldcodec::dpq {

using canopen::sdo::abort_code;

/// class << 24 | code << 16 | additional: the CiA 301 abort code from the manual's columns.
[[nodiscard]] constexpr abort_code compose_abort_code(std::uint16_t additional,
                                                      std::uint8_t error_code,
                                                      std::uint8_t error_class) noexcept {
  return static_cast<abort_code>((std::uint32_t{error_class} << 24U) |
                                 (std::uint32_t{error_code} << 16U) | additional);
}

/// One row of the DPQ abort table.
struct sdo_abort_row {
  std::uint16_t additional; ///< bytes 4+5 of the abort frame (LSB first)
  std::uint8_t error_code;  ///< byte 6
  std::uint8_t error_class; ///< byte 7
  abort_code code;          ///< the CiA 301 abort code (bytes 4–7, little-endian)
  std::string_view dpq_text;

  /// The CiA 301 description (canopen::sdo::to_string).
  [[nodiscard]] constexpr std::string_view cia_text() const noexcept {
    return canopen::sdo::to_string(code);
  }
  /// The closest fieldcodec error (canopen::sdo::to_errc).
  [[nodiscard]] constexpr errc error() const noexcept { return canopen::sdo::to_errc(code); }
};

/// The 16 rows in the manual's order.
inline constexpr std::array<sdo_abort_row, 16> sdo_abort_table{{
    {0x0011, 0x09, 0x06, abort_code::no_sub_index, "no such sub-index"},
    {0x0000, 0x01, 0x06, abort_code::unsupported_access, "object is read-only or write-only"},
    {0x0031, 0x09, 0x06, abort_code::value_too_high, "value too large"},
    {0x0032, 0x09, 0x06, abort_code::value_too_low, "value too small"},
    {0x0010, 0x07, 0x06, abort_code::length_mismatch, "unknown data type"},
    {0x0012, 0x07, 0x06, abort_code::length_too_high, "data too long"},
    {0x0013, 0x07, 0x06, abort_code::length_too_low, "data too short"},
    {0x0041, 0x04, 0x06, abort_code::not_mappable, "object cannot be mapped"},
    {0x0042, 0x04, 0x06, abort_code::pdo_too_long, "PDO too long"},
    {0x0043, 0x04, 0x06, abort_code::parameter_incompatible, "invalid value"},
    {0x0000, 0x03, 0x05, abort_code::toggle_not_alternated, "toggle bit wrong"},
    {0x0000, 0x02, 0x06, abort_code::no_object, "no such object"},
    {0x0021, 0x00, 0x08, abort_code::cannot_store_local_control, "internal error"},
    {0x0022, 0x00, 0x08, abort_code::cannot_store_device_state, "service error"},
    {0x0001, 0x04, 0x05, abort_code::unknown_command, "unknown service request"},
    {0x0047, 0x04, 0x06, abort_code::device_incompatible, "initialisation error"},
}};

/// The row for an abort code, or nullptr for a code the DPQ does not list.
[[nodiscard]] constexpr const sdo_abort_row *find_sdo_abort(abort_code code) noexcept {
  for (const auto &row : sdo_abort_table) {
    if (row.code == code) return &row;
  }
  return nullptr;
}

/// The DPQ's text for an abort code; empty for a code the DPQ does not list.
[[nodiscard]] constexpr std::string_view describe_sdo_abort(abort_code code) noexcept {
  // by the rows, not by find_sdo_abort's pointer: see od/detail/search.hpp on g++
  // -fsanitize=undefined and constant evaluation
  for (const auto &row : sdo_abort_table) {
    if (row.code == code) return row.dpq_text;
  }
  return std::string_view{};
}

/// The fieldcodec error for an abort code (the shared table's; errc::aborted when unknown).
[[nodiscard]] constexpr errc sdo_abort_errc(abort_code code) noexcept {
  return canopen::sdo::to_errc(code);
}

} // namespace fieldcodec::dpq
