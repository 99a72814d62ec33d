// CRC-16/XMODEM (core/crc.hpp), the CRC of CiA 301 SDO block transfer.
#include <fieldcodec/core/crc.hpp>

#include <doctest/doctest.h>

#include "xorshift.hpp"

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace crc = fieldcodec::crc;

// The published check value of CRC-16/XMODEM (poly 0x1021, init 0, no reflection, xorout 0):
// the CRC of the nine ASCII digits "123456789" is 0x31C3.
static_assert(crc::ccitt16(std::string_view{"123456789"}) == 0x31C3);
static_assert(crc::ccitt16(std::span<const std::uint8_t>{}) == 0x0000);
static_assert(crc::ccitt16(std::string_view{"A"}) == 0x58E5);
// incremental: two parts give the CRC of the whole
static_assert(crc::ccitt16(std::string_view{"56789"}, crc::ccitt16(std::string_view{"1234"})) ==
              0x31C3);

namespace {
// A reference of the definition (polynomial division bit by bit over the message followed by
// 16 zero bits), independent of the shift-and-xor form in the header.
std::uint16_t reference(const std::vector<std::uint8_t> &data) {
  std::uint32_t reg = 0;
  auto feed = [&](unsigned bit) {
    reg = (reg << 1U) | bit;
    if ((reg & 0x10000U) != 0U) reg ^= 0x11021U;
  };
  for (auto b : data) {
    for (int i = 7; i >= 0; --i) feed((unsigned{b} >> static_cast<unsigned>(i)) & 1U);
  }
  for (int i = 0; i < 16; ++i) feed(0);
  return static_cast<std::uint16_t>(reg);
}

// The bitwise form the header used before issue 18's services benchmark (eight shift-and-xor
// steps per byte): the byte-at-a-time form must give the same result for every state and byte.
constexpr std::uint16_t bitwise_step(std::uint16_t crc, std::uint8_t b) {
  unsigned r = static_cast<unsigned>(crc) ^ (static_cast<unsigned>(b) << 8U);
  for (int i = 0; i < 8; ++i) r = (r & 0x8000U) != 0U ? (r << 1U) ^ 0x1021U : r << 1U;
  return static_cast<std::uint16_t>(r & 0xFFFFU);
}
} // namespace

TEST_CASE("CRC-16/XMODEM: the byte-at-a-time form equals the bitwise one on every state and byte") {
  // One step is a function of (crc, byte) alone, so agreeing on all 2^24 pairs means agreeing
  // on every message and every split into parts.
  std::size_t mismatches = 0;
  for (unsigned c = 0; c <= 0xFFFFU; ++c) {
    for (unsigned b = 0; b <= 0xFFU; ++b) {
      const std::uint8_t one[1] = {static_cast<std::uint8_t>(b)};
      const auto crc = static_cast<std::uint16_t>(c);
      if (crc::ccitt16(std::span<const std::uint8_t>(one), crc) != bitwise_step(crc, one[0])) {
        ++mismatches;
      }
    }
  }
  CHECK(mismatches == 0U);
}

TEST_CASE("CRC-16/XMODEM check values") {
  // Values of the CRC catalogue / any XMODEM implementation (e.g. Python's binascii.crc_hqx
  // with initial value 0).
  CHECK(crc::ccitt16(std::string_view{"123456789"}) == 0x31C3);
  const std::array<std::uint8_t, 4> ff{0xFF, 0xFF, 0xFF, 0xFF};
  CHECK(crc::ccitt16(ff) == 0x99CF);
  const std::array<std::uint8_t, 1> zero{0};
  CHECK(crc::ccitt16(zero) == 0x0000);
  std::array<std::uint8_t, 256> all{};
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::uint8_t>(i);
  CHECK(crc::ccitt16(all) == 0x7E55);
}

TEST_CASE("CRC-16/XMODEM agrees with the polynomial division and is incremental") {
  std::vector<std::uint8_t> data;
  std::uint32_t x = 12345;
  for (std::size_t n = 0; n < 300; ++n) {
    CAPTURE(n);
    const std::uint16_t whole = crc::ccitt16(data);
    CHECK(whole == reference(data));
    // any split point gives the same result
    const std::size_t cut = n / 3;
    const auto first = std::span<const std::uint8_t>(data).first(cut);
    const auto rest = std::span<const std::uint8_t>(data).subspan(cut);
    CHECK(crc::ccitt16(rest, crc::ccitt16(first)) == whole);
    x = x * 1103515245U + 12345U;
    data.push_back(static_cast<std::uint8_t>(x >> 16U));
  }
  // a single flipped bit changes the CRC
  std::vector<std::uint8_t> msg(64, 0x5A);
  const auto good = crc::ccitt16(msg);
  for (std::size_t i = 0; i < msg.size() * 8; ++i) {
    auto bad = msg;
    bad[i / 8] = static_cast<std::uint8_t>(bad[i / 8] ^ (1U << (i % 8)));
    CHECK(crc::ccitt16(bad) != good);
  }
}

// The table of ccitt16_by_table (an opt-in of the SDO machines, issue 18 round 5): the check
// value, and its first entries as the CRC catalogue's table for polynomial 0x1021 lists them.
static_assert(crc::ccitt16_by_table(std::span<const std::uint8_t>{}) == 0x0000);
static_assert(crc::ccitt16_table[0] == 0x0000 && crc::ccitt16_table[1] == 0x1021 &&
              crc::ccitt16_table[2] == 0x2042 && crc::ccitt16_table[255] == 0x1EF0);
static_assert(crc::ccitt16_with_table::update(std::span<const std::uint8_t>{}, 0x1234) == 0x1234);

TEST_CASE("CRC-16/XMODEM by table equals the bitwise form on every state and byte") {
  std::size_t mismatches = 0;
  for (unsigned c = 0; c <= 0xFFFFU; ++c) {
    for (unsigned b = 0; b <= 0xFFU; ++b) {
      const std::uint8_t one[1] = {static_cast<std::uint8_t>(b)};
      const auto crc = static_cast<std::uint16_t>(c);
      if (crc::ccitt16_by_table(std::span<const std::uint8_t>(one), crc) !=
          bitwise_step(crc, one[0])) {
        ++mismatches;
      }
    }
  }
  CHECK(mismatches == 0U);
  const std::string_view digits = "123456789";
  std::vector<std::uint8_t> d(digits.begin(), digits.end());
  CHECK(crc::ccitt16_by_table(d) == 0x31C3);
}

TEST_CASE("CRC-16/XMODEM by table equals the bitwise form on random data of every length "
          "0..1000, from random start values") {
  // the two machine policies too (crc::ccitt16_no_table / ccitt16_with_table)
  fieldcodec::test::xorshift g(0x9E37'79B9'7F4A'7C15ULL);
  auto next = [&] { return g.next(); };
  std::size_t compared = 0;
  for (std::size_t n = 0; n <= 1000; ++n) {
    std::vector<std::uint8_t> data(n);
    for (auto &b : data) b = static_cast<std::uint8_t>(next() >> 56U);
    for (int k = 0; k < 8; ++k) {
      const auto start = static_cast<std::uint16_t>(next() >> 48U);
      std::uint16_t bitwise = start;
      for (const auto b : data) bitwise = bitwise_step(bitwise, b);
      CAPTURE(n);
      CAPTURE(start);
      CHECK(crc::ccitt16_by_table(data, start) == bitwise);
      CHECK(crc::ccitt16_with_table::update(data, start) == bitwise);
      CHECK(crc::ccitt16_no_table::update(data, start) == bitwise);
      ++compared;
    }
  }
  CHECK(compared == 1001U * 8U);
}

// CRC-8, polynomial 0x07, initial 0xFF, no reflection, no final XOR: the EtherCAT SII
// configuration area checksum (ETG.1000.6 5.4; SOEM computes it the same way). Check value of
// "123456789": 0xFB (computed by the definition below; the catalogue has no entry with these
// parameters: CRC-8/SMBUS starts from 0 and gives 0xF4, CRC-8/ROHC reflects and gives 0xD0).
namespace {
constexpr std::uint8_t nine[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
} // namespace
static_assert(crc::crc8(nine) == 0xFB);
static_assert(crc::crc8(std::span<const std::uint8_t>{}) == 0xFF);
// A real configuration area (siitool's published sii_example image, words 0..6: PDI control
// 0x0E08, PDI configuration 0x8802, the rest 0) and its word 7, checksum 0x2F.
namespace {
constexpr std::uint8_t sii_words_0_6[14] = {0x08, 0x0E, 0x02, 0x88, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
} // namespace
static_assert(crc::crc8(sii_words_0_6) == 0x2F);
static_assert(crc::crc8(std::span<const std::uint8_t>(nine).subspan(4),
                        crc::crc8(std::span<const std::uint8_t>(nine).first(4))) == 0xFB);

TEST_CASE("crc8: the SII checksum, incrementally and against the bitwise definition") {
  CHECK(crc::crc8(nine) == 0xFBU);
  const std::uint8_t zero[1] = {0};
  CHECK(crc::crc8(zero, 0) == 0x00U); // CRC-8/SMBUS's start: 0 stays 0
  CHECK(crc::crc8(nine, 0) == 0xF4U); // and its check value
  // the division written out: shift in each bit, xor the polynomial on a carry
  for (unsigned v = 0; v < 256; ++v) {
    const std::uint8_t one[1] = {static_cast<std::uint8_t>(v)};
    unsigned r = 0xFFU ^ v;
    for (int i = 0; i < 8; ++i) r = (r & 0x80U) != 0U ? ((r << 1U) ^ 0x107U) : (r << 1U);
    CHECK(crc::crc8(one) == (r & 0xFFU));
  }
}
