// fieldcodec — the Rexroth VT-HACD-DPQ SDO abort table mapped onto CiA 301 abort codes
// (manual RE 30146-02-Z, 3.3 "Interruption of an SDO transfer").
//
// The manual prints an abort frame as: byte 0 = 0x80, bytes 1–3 index and sub-index, bytes 4+5
// "additional code", byte 6 "error code", byte 7 "error class", and lists each abort as the
// four bytes 4, 5, 6, 7. Read little-endian, bytes 4–7 are exactly the CiA 301 32-bit abort
// code: class << 24 | code << 16 | additional. Every one of the 16 rows is a standard CiA 301
// abort code; the DPQ's wording differs from CiA 301 for some of them (see `dpq_text` and
// `cia_text`, both fieldcodec's own short wording). The frame itself is built and parsed by the
// generic CANopen SDO layer.
#pragma once

#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <string_view>

namespace fieldcodec::dpq {

/// class << 24 | code << 16 | additional: the CiA 301 abort code from the manual's columns.
[[nodiscard]] constexpr std::uint32_t compose_abort_code(std::uint16_t additional,
                                                         std::uint8_t error_code,
                                                         std::uint8_t error_class) noexcept {
  return (std::uint32_t{error_class} << 24U) | (std::uint32_t{error_code} << 16U) | additional;
}

/// One row of the DPQ abort table.
struct sdo_abort_row {
  std::uint16_t additional; ///< bytes 4+5 of the abort frame (LSB first)
  std::uint8_t error_code;  ///< byte 6
  std::uint8_t error_class; ///< byte 7
  std::uint32_t abort_code; ///< the CiA 301 abort code (bytes 4–7, little-endian)
  std::string_view dpq_text;
  std::string_view cia_text;
  errc error; ///< closest fieldcodec error
};

/// The 16 rows in the manual's order.
inline constexpr std::array<sdo_abort_row, 16> sdo_abort_table{{
    {0x0011, 0x09, 0x06, 0x0609'0011, "no such sub-index", "sub-index does not exist",
     errc::unknown_object},
    {0x0000, 0x01, 0x06, 0x0601'0000, "object is read-only or write-only",
     "unsupported access to an object", errc::access_denied},
    {0x0031, 0x09, 0x06, 0x0609'0031, "value too large", "written value too high",
     errc::out_of_range},
    {0x0032, 0x09, 0x06, 0x0609'0032, "value too small", "written value too low",
     errc::out_of_range},
    {0x0010, 0x07, 0x06, 0x0607'0010, "unknown data type",
     "data type or service parameter length does not match", errc::type_mismatch},
    {0x0012, 0x07, 0x06, 0x0607'0012, "data too long", "service parameter length too high",
     errc::too_long},
    {0x0013, 0x07, 0x06, 0x0607'0013, "data too short", "service parameter length too low",
     errc::bad_length},
    {0x0041, 0x04, 0x06, 0x0604'0041, "object cannot be mapped", "object cannot be mapped to a PDO",
     errc::invalid_argument},
    {0x0042, 0x04, 0x06, 0x0604'0042, "PDO too long", "mapped objects exceed the PDO length",
     errc::too_long},
    {0x0043, 0x04, 0x06, 0x0604'0043, "invalid value", "general parameter incompatibility",
     errc::invalid_argument},
    {0x0000, 0x03, 0x05, 0x0503'0000, "toggle bit wrong", "toggle bit not alternated",
     errc::bad_toggle},
    {0x0000, 0x02, 0x06, 0x0602'0000, "no such object", "object does not exist in the dictionary",
     errc::unknown_object},
    {0x0021, 0x00, 0x08, 0x0800'0021, "internal error", "cannot transfer or store: local control",
     errc::aborted},
    {0x0022, 0x00, 0x08, 0x0800'0022, "service error",
     "cannot transfer or store: present device state", errc::bad_state},
    {0x0001, 0x04, 0x05, 0x0504'0001, "unknown service request",
     "command specifier not valid or unknown", errc::unknown_command},
    {0x0047, 0x04, 0x06, 0x0604'0047, "initialisation error", "general internal incompatibility",
     errc::aborted},
}};

/// The row for a 32-bit abort code, or nullptr for a code the DPQ does not list.
[[nodiscard]] constexpr const sdo_abort_row *find_sdo_abort(std::uint32_t abort_code) noexcept {
  for (const auto &row : sdo_abort_table) {
    if (row.abort_code == abort_code) return &row;
  }
  return nullptr;
}

/// The DPQ's text for an abort code; empty for a code the DPQ does not list.
[[nodiscard]] constexpr std::string_view describe_sdo_abort(std::uint32_t abort_code) noexcept {
  const sdo_abort_row *row = find_sdo_abort(abort_code);
  return row != nullptr ? row->dpq_text : std::string_view{};
}

/// The fieldcodec error for an abort code: the row's `error`, errc::aborted when not listed.
[[nodiscard]] constexpr errc sdo_abort_errc(std::uint32_t abort_code) noexcept {
  const sdo_abort_row *row = find_sdo_abort(abort_code);
  return row != nullptr ? row->error : errc::aborted;
}

} // namespace fieldcodec::dpq
