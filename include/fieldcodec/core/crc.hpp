// fieldcodec — cyclic redundancy checks over byte ranges.
//
// crc::crc8 (polynomial 0x07, initial 0xFF) is the checksum of an EtherCAT slave's
// configuration area (SII EEPROM words 0..6).
//
// crc::ccitt16 is the CRC of CiA 301's SDO block transfer: polynomial x^16 + x^12 + x^5 + 1
// (0x1021), initial value 0, most significant bit first, no reflection, no final XOR — the
// catalogue's CRC-16/XMODEM (check value 0x31C3 for "123456789"). It is incremental: feed the
// result of one call as `crc` of the next to checksum data that arrives in parts.
//
// Two ways to compute it, with the same results: crc::ccitt16 without a table (~17 instructions
// a byte on x86-64, no flash beyond its code) and crc::ccitt16_by_table with the 256-entry
// table crc::ccitt16_table (~9 a byte, 512 bytes of flash). The table is linked only into
// programs that call ccitt16_by_table. The SDO machines take the choice as a type,
// crc::ccitt16_no_table (the default) or crc::ccitt16_with_table (docs/canopen.md, "Block
// transfer: the CRC").
#pragma once

#include <array>
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

/// The table of ccitt16_by_table: entry b is the CRC of the one byte b from 0 (512 bytes; only
/// programs that call ccitt16_by_table hold it).
inline constexpr std::array<std::uint16_t, 256> ccitt16_table = [] {
  std::array<std::uint16_t, 256> t{};
  for (unsigned b = 0; b < t.size(); ++b) {
    const std::uint8_t one[1] = {static_cast<std::uint8_t>(b)};
    t[b] = ccitt16(std::span<const std::uint8_t>(one));
  }
  return t;
}();

/// ccitt16(data, crc) by the table: the same result, about half the instructions a byte, and
/// ccitt16_table in flash.
[[nodiscard]] constexpr std::uint16_t ccitt16_by_table(std::span<const std::uint8_t> data,
                                                       std::uint16_t crc = 0) noexcept {
  for (const std::uint8_t b : data) {
    crc =
        static_cast<std::uint16_t>(((static_cast<unsigned>(crc) << 8U) & 0xFF00U) ^
                                   ccitt16_table[((static_cast<unsigned>(crc) >> 8U) ^ b) & 0xFFU]);
  }
  return crc;
}

/// How a machine computes the CRC of SDO block transfers (the template argument `Crc` of
/// sdo::server, sdo::basic_client, sdo::basic_block_sender, sdo::basic_block_receiver):
/// `Crc::update(data, crc)` is ccitt16(data, crc).
struct ccitt16_no_table { ///< without a table: no flash for it (the default)
  [[nodiscard]] static constexpr std::uint16_t update(std::span<const std::uint8_t> data,
                                                      std::uint16_t crc) noexcept {
    return ccitt16(data, crc);
  }
};
struct ccitt16_with_table { ///< by ccitt16_table: faster, 512 bytes of flash
  [[nodiscard]] static constexpr std::uint16_t update(std::span<const std::uint8_t> data,
                                                      std::uint16_t crc) noexcept {
    return ccitt16_by_table(data, crc);
  }
};

/// The same over the characters of `text`.
[[nodiscard]] constexpr std::uint16_t ccitt16(std::string_view text,
                                              std::uint16_t crc = 0) noexcept {
  for (const char c : text) {
    const std::uint8_t b[1] = {static_cast<std::uint8_t>(c)};
    crc = ccitt16(std::span<const std::uint8_t>(b), crc);
  }
  return crc;
}

/// CRC-8 with polynomial x^8 + x^2 + x + 1 (0x07), most significant bit first, no reflection,
/// no final XOR, of `data` continuing from `crc` (initial value 0xFF): the checksum of an
/// EtherCAT slave's configuration area, EEPROM words 0..6 (ETG.1000.6 5.4; check value 0xFB for
/// "123456789"; from 0 instead of 0xFF it is CRC-8/SMBUS). Bitwise: it runs over 14 bytes once per
/// image.
[[nodiscard]] constexpr std::uint8_t crc8(std::span<const std::uint8_t> data,
                                          std::uint8_t crc = 0xFF) noexcept {
  for (const std::uint8_t b : data) {
    unsigned c = static_cast<unsigned>(crc) ^ b;
    for (int i = 0; i < 8; ++i)
      c = (c & 0x80U) != 0U ? ((c << 1U) ^ 0x07U) & 0xFFU : (c << 1U) & 0xFFU;
    crc = static_cast<std::uint8_t>(c);
  }
  return crc;
}

} // namespace fieldcodec::crc
