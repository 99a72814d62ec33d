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
  // A byte at a time without a table: the eight shift-and-xor steps of the division by 0x1021
  // collapse into three shifts of the byte's quotient x (0x1021 = 2^12 + 2^5 + 1, and the top
  // nibble of x folds into its bottom one). About a quarter of the instructions of the bitwise
  // loop, and no 512-byte table in flash.
  for (const std::uint8_t b : data) {
    unsigned x = ((static_cast<unsigned>(crc) >> 8U) ^ b) & 0xFFU;
    x ^= x >> 4U;
    crc = static_cast<std::uint16_t>(
        ((static_cast<unsigned>(crc) << 8U) ^ (x << 12U) ^ (x << 5U) ^ x) & 0xFFFFU);
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
