// fieldcodec — COMPAX fault codes (STOERUNG 0x603F, manual 000, 2.5.1), the error number of
// S30 and the Interbus-S error message (chapter 5). Texts are short own words, not the
// manual's sentences.
#pragma once

#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::compax {

/// STOERUNG: byte 1 bits 7..4 main group, bits 3..0 subgroup, byte 2 details (the DRIVECOM
/// error code, e.g. 0x8611). 0 = no fault.
struct fault_code {
  std::uint16_t raw = 0;
  [[nodiscard]] constexpr std::uint8_t main_group() const noexcept {
    return static_cast<std::uint8_t>(raw >> 12U);
  }
  [[nodiscard]] constexpr std::uint8_t subgroup() const noexcept {
    return static_cast<std::uint8_t>((raw >> 8U) & 0x0FU);
  }
  [[nodiscard]] constexpr std::uint8_t details() const noexcept {
    return static_cast<std::uint8_t>(raw & 0xFFU);
  }
  [[nodiscard]] constexpr bool is_fault() const noexcept { return raw != 0U; }
  [[nodiscard]] constexpr std::array<std::uint8_t, 2> bytes() const noexcept {
    return to_bytes<std::uint16_t>(raw, bus_order);
  }
  [[nodiscard]] static constexpr result<fault_code>
  decode(std::span<const std::uint8_t> in) noexcept {
    auto v = decode_integer<std::uint16_t>(in);
    if (!v) return v.error();
    return fault_code{v.value()};
  }
  friend constexpr bool operator==(const fault_code &, const fault_code &) = default;
};

/// One COMPAX error E00..E71 with its STOERUNG code.
struct compax_error {
  std::uint8_t number;
  std::uint16_t code;
  std::string_view text; ///< empty where the manual gives none
};

/// E00..E71 (2.5.1). Numbers 72..255 report code 0x1000 without text, except E73 (bus).
inline constexpr std::array<compax_error, 72> compax_errors{{
    {0, 0x0000, "no error"},
    {1, 0x6320, "not configured"},
    {2, 0x6320, "limits"},
    {3, 0x1000, ""},
    {4, 0x1000, ""},
    {5, 0x7300, "machine-zero initiator not found"},
    {6, 0x1000, ""},
    {7, 0x8200, "processor fault"},
    {8, 0x8200, "synchronous stop active"},
    {9, 0x8200, "drive not running"},
    {10, 0x8611, "following error too large"},
    {11, 0x8600, "programmed position missed"},
    {12, 0x7320, "slip"},
    {13, 0x7300, "initiator 1 not damped"},
    {14, 0x7300, "initiator 2 not damped"},
    {15, 0x7320, "second measuring system fault"},
    {16, 0x6300, "record does not exist"},
    {17, 0x6300, "record number too large"},
    {18, 0x6300, "record 250 in use"},
    {19, 0x6300, "program memory full"},
    {20, 0x8612, "target beyond positive limit"},
    {21, 0x8612, "target beyond negative limit"},
    {22, 0x8500, "machine zero not approached"},
    {23, 0x6200, "command not allowed"},
    {24, 0x8400, "invalid speed"},
    {25, 0x8600, "invalid position"},
    {26, 0x6300, "REPEAT without END"},
    {27, 0x6320, "parameter read-only"},
    {28, 0x1000, ""},
    {29, 0x6320, "motor data missing"},
    {30, 0x5500, "hardware fault"},
    {31, 0x6320, "parameter fault"},
    {32, 0x6320, "parameter fault"},
    {33, 0x6300, "data memory fault"},
    {34, 0x6300, "data memory fault"},
    {35, 0x5500, "hardware fault"},
    {36, 0x5500, "hardware fault"},
    {37, 0x5111, "+15 V auxiliary supply missing"},
    {38, 0x5120, "DC link voltage too high"},
    {39, 0x4210, "over-temperature"},
    {40, 0x1000, ""},
    {41, 0x5410, "output stage fault"},
    {42, 0x7303, "resolver fault"},
    {43, 0x2300, "output overload"},
    {44, 0x5111, "positive auxiliary supply out of tolerance"},
    {45, 0x5111, "negative auxiliary supply out of tolerance"},
    {46, 0x5112, "24 V too high"},
    {47, 0x5112, "24 V too low"},
    {48, 0x4310, "motor thermostat tripped"},
    {49, 0x7121, "motor or drive disabled"},
    {50, 0x8612, "limit switch 1"},
    {51, 0x8612, "limit switch 2"},
    {52, 0x7200, "emergency stop control fault"},
    {53, 0x7120, "motor overload"},
    {54, 0x8400, "speed too high"},
    {55, 0x8000, "external emergency stop"},
    {56, 0x8000, "emergency stop in COMPAX-M"},
    {57, 0x5120, "DC link voltage too low"},
    {58, 0x4200, "temperature rising"},
    {59, 0x1000, ""},
    {60, 0x7200, "slip warning"},
    {61, 0x1000, ""},
    {62, 0x1000, ""},
    {63, 0x1000, ""},
    {64, 0x1000, ""},
    {65, 0x7305, "encoder module not enabled"},
    {66, 0x1000, ""},
    {67, 0x1000, ""},
    {68, 0x1000, ""},
    {69, 0x1000, ""},
    {70, 0x1000, ""},
    {71, 0x1000, ""},
}};

/// Interbus-S error message E73 (chapter 5): bus time-out, reaction set by P191.
inline constexpr std::uint8_t bus_timeout_error = 73;

/// STOERUNG code of error number `e` (0x1000 for 71..255, as the table's last row says).
[[nodiscard]] constexpr fault_code fault_code_of(std::uint8_t e) noexcept {
  if (e < compax_errors.size()) return fault_code{compax_errors[e].code};
  return fault_code{0x1000};
}

/// Short text of error number `e` ("" where the manual gives none).
[[nodiscard]] constexpr std::string_view error_text(std::uint8_t e) noexcept {
  if (e < compax_errors.size()) return compax_errors[e].text;
  if (e == bus_timeout_error) return "bus time-out";
  return "";
}

} // namespace fieldcodec::compax
