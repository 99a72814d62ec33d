// fieldcodec — cyclic redundancy checks over byte ranges.
//
// crc::ccitt16 is the CRC of CiA 301's SDO block transfer: polynomial x^16 + x^12 + x^5 + 1
// (0x1021), initial value 0, most significant bit first, no reflection, no final XOR — the
// catalogue's CRC-16/XMODEM (check value 0x31C3 for "123456789"). It is incremental: feed the
// result of one call as `crc` of the next to checksum data that arrives in parts.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::crc {

/// CRC-16/XMODEM (CCITT polynomial 0x1021, initial 0) of `data`, continuing from `crc`.
[[nodiscard]] constexpr std::uint16_t ccitt16(std::span<const std::uint8_t> data,
                                              std::uint16_t crc = 0) noexcept {
  // Bitwise on purpose: 8 shifts per byte cost less flash than a 512-byte table, and block
  // transfer moves at most a few hundred bytes per millisecond.
  for (const std::uint8_t b : data) {
    unsigned r = static_cast<unsigned>(crc) ^ (static_cast<unsigned>(b) << 8U);
    for (int i = 0; i < 8; ++i) r = (r & 0x8000U) != 0U ? (r << 1U) ^ 0x1021U : r << 1U;
    crc = static_cast<std::uint16_t>(r & 0xFFFFU);
  }
  return crc;
}

/// The same over the characters of `text`.
[[nodiscard]] constexpr std::uint16_t ccitt16(std::string_view text,
                                              std::uint16_t crc = 0) noexcept {
  for (const char c : text) {
    const std::uint8_t b[1] = {static_cast<std::uint8_t>(c)};
    crc = ccitt16(std::span<const std::uint8_t>(b), crc);
  }
  return crc;
}

} // namespace fieldcodec::crc
