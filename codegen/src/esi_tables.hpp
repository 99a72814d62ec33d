// fieldcodec-gen — the data type names of ESI files (ETG.2000, base types of ETG.1000.6 /
// ETG.1020) and what the model holds them as: one table, read by the ESI reader and writer and
// by the SII writer.
#pragma once

#include <cstdint>
#include <string_view>

namespace fieldcodec::gen::esi {

/// An ESI base type: the CiA 301 code the model holds it as (the same value; BYTE, WORD, DWORD
/// and the BITARRn bit strings as the unsigned integer of their width, BIT1 as BOOLEAN), its
/// size in bits, and its ETG.1000.6 code (the code an SII PDO entry or an SDO Information
/// reply carries; 0 where it is the CiA code). `standard` is false for names that are no
/// ETG.2000 name but occur in files (UINT32, INT16, ...): read with a warning.
struct base_type {
  std::string_view name;
  std::uint16_t code;
  std::uint16_t bits;
  std::uint16_t etg_code = 0;
  bool standard = true;
};

inline constexpr base_type base_types[] = {
    {"BOOL", 0x0001, 1},
    {"BIT", 0x0001, 1, 0x0030},
    {"BIT1", 0x0001, 1, 0x0030},
    {"SINT", 0x0002, 8},
    {"INT", 0x0003, 16},
    {"DINT", 0x0004, 32},
    {"USINT", 0x0005, 8},
    {"UINT", 0x0006, 16},
    {"UDINT", 0x0007, 32},
    {"REAL", 0x0008, 32},
    {"TIME_OF_DAY", 0x000C, 48},
    {"TIME_DIFFERENCE", 0x000D, 48},
    {"INT24", 0x0010, 24},
    {"LREAL", 0x0011, 64},
    {"INT40", 0x0012, 40},
    {"INT48", 0x0013, 48},
    {"INT56", 0x0014, 56},
    {"LINT", 0x0015, 64},
    {"UINT24", 0x0016, 24},
    {"UINT40", 0x0018, 40},
    {"UINT48", 0x0019, 48},
    {"UINT56", 0x001A, 56},
    {"ULINT", 0x001B, 64},
    {"BYTE", 0x0005, 8, 0x001E},
    {"WORD", 0x0006, 16, 0x001F},
    {"DWORD", 0x0007, 32, 0x0020},
    {"LWORD", 0x001B, 64},
    {"BITARR8", 0x0005, 8, 0x002D},
    {"BITARR16", 0x0006, 16, 0x002E},
    {"BITARR32", 0x0007, 32, 0x002F},
    {"INT8", 0x0002, 8, 0, false},
    {"INT16", 0x0003, 16, 0, false},
    {"INT32", 0x0004, 32, 0, false},
    {"INT64", 0x0015, 64, 0, false},
    {"UINT8", 0x0005, 8, 0, false},
    {"UINT16", 0x0006, 16, 0, false},
    {"UINT32", 0x0007, 32, 0, false},
    {"UINT64", 0x001B, 64, 0, false},
    {"FLOAT", 0x0008, 32, 0, false},
    {"DOUBLE", 0x0011, 64, 0, false},
};

/// BIT2 .. BIT8 (ETG.1000.6 codes 0x0031 .. 0x0037): bit fields with no CiA 301 type, kept as
/// DOMAIN with that code.
inline constexpr std::uint16_t bit_field_code(unsigned bits) noexcept {
  return static_cast<std::uint16_t>(0x0030U + bits - 1U);
}

/// The ESI name the writer writes for a CiA 301 code (the first row of the table that has it).
[[nodiscard]] constexpr std::string_view name_of(std::uint16_t code) noexcept {
  for (const auto &t : base_types) {
    if (t.code == code && t.standard) return t.name;
  }
  return {};
}

/// The row of a name (nullptr: not a base type).
[[nodiscard]] constexpr const base_type *find_base_type(std::string_view name) noexcept {
  for (const auto &t : base_types) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

} // namespace fieldcodec::gen::esi
