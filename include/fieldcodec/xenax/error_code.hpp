// fieldcodec — XENAX error numbers in 603Fh (manual 4.2.1) and 2004h.
//
// 603Fh = 0 when the XENAX display shows no error, otherwise 0xFF00 + the XENAX error number
// (1..99). The bus manual names only error 50; the other texts are in the XENAX product manual
// and can be read at run time from 5020h (TES, VISIBLE_STRING).
#pragma once

#include <fieldcodec/core/result.hpp>

#include <cstdint>
#include <string_view>

namespace fieldcodec::xenax {

inline constexpr std::uint16_t error_code_base = 0xFF00U;
inline constexpr std::uint8_t max_error_number = 99;
/// Following (position) error: the 6065h window was exceeded (manual 4.2.7, 5.1.1).
inline constexpr std::uint8_t error_following = 50;

/// 603Fh for a XENAX error number (0 = no error). Errors: out_of_range (> 99).
[[nodiscard]] constexpr result<std::uint16_t> encode_error_code(std::uint8_t number) noexcept {
  if (number > max_error_number) return errc::out_of_range;
  if (number == 0U) return std::uint16_t{0};
  return static_cast<std::uint16_t>(error_code_base + number);
}

/// The XENAX error number in 603Fh (0 = no error). Errors: out_of_range (anything other than
/// 0 and 0xFF01..0xFF63, e.g. a CiA 402 code such as 0x8611).
[[nodiscard]] constexpr result<std::uint8_t> decode_error_code(std::uint16_t code) noexcept {
  if (code == 0U) return std::uint8_t{0};
  if (code <= error_code_base || code > error_code_base + max_error_number) {
    return errc::out_of_range;
  }
  return static_cast<std::uint8_t>(code - error_code_base);
}

/// A short text for the error numbers the bus manual describes; empty for the others (read
/// 5020h TES for the device's own text).
[[nodiscard]] constexpr std::string_view error_text(std::uint8_t number) noexcept {
  switch (number) {
  case 0: return "no error";
  case error_following: return "following error (position error window exceeded)";
  default: return "";
  }
}

/// After error 50 no new reference is needed: write 0x2010 (PWC, power continue) to 5000h.
[[nodiscard]] constexpr bool needs_reference_after(std::uint8_t number) noexcept {
  return number != error_following;
}

} // namespace fieldcodec::xenax
