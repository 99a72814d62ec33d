// fieldcodec — COMPAX device identification S31_S39 (object 0x5FD6, manual 000, 2.3.2).
//
// Every sub-index holds 12 unsigned BCD digits in 6 bytes, most significant nibble first.
// Sub-indices 2 (software date) and 6 (date/version of the bus option) split the 6 bytes into
// day, month, year (one BCD byte each), version (two BCD bytes) and identifier (one BCD byte).
#pragma once

#include <fieldcodec/core/bcd.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace fieldcodec::compax {

/// Sub-indices of S31_S39.
enum class identification_item : std::uint8_t {
  software_version = 1,
  software_date = 2,
  job_number = 3,
  part_number = 4,
  version = 5,
  bus_option_date = 6, ///< date and version of the bus option
  device_identification = 7,
  device_family = 8,
  device = 9,
};

/// True for the sub-indices whose bytes are a date record.
[[nodiscard]] constexpr bool is_date_item(identification_item i) noexcept {
  return i == identification_item::software_date || i == identification_item::bus_option_date;
}

inline constexpr std::size_t identification_size = 6;
inline constexpr std::uint64_t identification_max = 999'999'999'999;

using identification_bytes = std::array<std::uint8_t, identification_size>;

/// 12-digit number → 6 BCD bytes. Errors: overflow (more than 12 digits).
[[nodiscard]] constexpr result<identification_bytes>
encode_identification(std::uint64_t value) noexcept {
  return bcd::encode<identification_size>(value);
}

/// 6 BCD bytes → number. Errors: truncated, bad_length, bad_digit.
[[nodiscard]] constexpr result<std::uint64_t>
decode_identification(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < identification_size) return errc::truncated;
  if (in.size() > identification_size) return errc::bad_length;
  return bcd::decode(in);
}

/// The date record of sub-indices 2 and 6. Year is the two-digit year as sent.
struct identification_date {
  std::uint8_t day = 1;        ///< 1..31
  std::uint8_t month = 1;      ///< 1..12
  std::uint8_t year = 0;       ///< 0..99
  std::uint16_t version = 0;   ///< 0..9999 (data bytes 4 and 5)
  std::uint8_t identifier = 0; ///< 0..99

  friend constexpr bool operator==(const identification_date &,
                                   const identification_date &) = default;
};

/// Date record → 6 BCD bytes. Errors: out_of_range (day not 1..31, month not 1..12, year or
/// identifier above 99, version above 9999).
[[nodiscard]] constexpr result<identification_bytes>
encode_identification_date(identification_date d) noexcept {
  if (d.day < 1U || d.day > 31U || d.month < 1U || d.month > 12U || d.year > 99U ||
      d.version > 9999U || d.identifier > 99U) {
    return errc::out_of_range;
  }
  identification_bytes out{};
  const std::span<std::uint8_t> o{out};
  // cannot fail: every field was range checked above
  (void)bcd::encode(d.day, o.subspan(0, 1));
  (void)bcd::encode(d.month, o.subspan(1, 1));
  (void)bcd::encode(d.year, o.subspan(2, 1));
  (void)bcd::encode(d.version, o.subspan(3, 2));
  (void)bcd::encode(d.identifier, o.subspan(5, 1));
  return out;
}

/// 6 BCD bytes → date record. Errors: truncated, bad_length, bad_digit, out_of_range (day 0 or
/// above 31, month 0 or above 12).
[[nodiscard]] constexpr result<identification_date>
decode_identification_date(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < identification_size) return errc::truncated;
  if (in.size() > identification_size) return errc::bad_length;
  auto day = bcd::decode(in.subspan(0, 1));
  auto month = bcd::decode(in.subspan(1, 1));
  auto year = bcd::decode(in.subspan(2, 1));
  auto version = bcd::decode(in.subspan(3, 2));
  auto ident = bcd::decode(in.subspan(5, 1));
  if (!day || !month || !year || !version || !ident) return errc::bad_digit;
  if (day.value() < 1U || day.value() > 31U || month.value() < 1U || month.value() > 12U) {
    return errc::out_of_range;
  }
  return identification_date{
      static_cast<std::uint8_t>(day.value()), static_cast<std::uint8_t>(month.value()),
      static_cast<std::uint8_t>(year.value()), static_cast<std::uint16_t>(version.value()),
      static_cast<std::uint8_t>(ident.value())};
}

} // namespace fieldcodec::compax
