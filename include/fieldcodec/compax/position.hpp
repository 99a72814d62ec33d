// fieldcodec — COMPAX BCD values: signed 6-byte positions (POSA, POSR, S1) and the 3-byte
// speed of POSR0SPEED (manual 000, sections 2.7.1, 2.7.2, 2.7.4, 2.8.3).
//
// Position: data byte 1 is the sign (0x00 +, 0xFF −), bytes 2..6 hold 10 BCD digits, most
// significant nibble first, in units of 0.001 mm (or inch). The printed range
// "-4 000 000 000 ... +4 000 000 000" is in those units, i.e. ±4 000 000.000 mm (erratum CX-14).
// POSR0SPEED: 6 unsigned BCD digits in units of 0.001 %, 1 ... 600 000.
#pragma once

#include <fieldcodec/core/bcd.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/integer.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <utility>

namespace fieldcodec::compax {

/// Bytes of a BCD position (sign byte + 5 digit bytes).
inline constexpr std::size_t bcd_position_size = 6;
/// Largest magnitude of a BCD position in 0.001 mm (4 000 000.000 mm).
inline constexpr std::int64_t bcd_position_limit = 4'000'000'000;
/// Decimal places of a position (resolution 0.001).
inline constexpr unsigned position_places = 3;

using bcd_position_bytes = std::array<std::uint8_t, bcd_position_size>;

/// A position in 0.001 mm (any integer type) → 6 BCD bytes.
/// Errors: out_of_range (beyond ±4 000 000.000).
template <integer_argument T>
[[nodiscard]] constexpr result<bcd_position_bytes> encode_bcd_position(T thousandths) noexcept {
  if (!in_closed_range(thousandths, -bcd_position_limit, bcd_position_limit)) {
    return errc::out_of_range;
  }
  return bcd::encode_signed<bcd_position_size>(checked_narrow<std::int64_t>(thousandths).value());
}

/// A position given as an exact decimal in mm ("7350.15"). Errors: not_representable (finer
/// than 0.001), out_of_range, overflow.
[[nodiscard]] constexpr result<bcd_position_bytes> encode_bcd_position(decimal mm) noexcept {
  auto t = to_fixed(mm, position_places);
  if (!t) return t.error() == errc::overflow ? errc::out_of_range : t.error();
  return encode_bcd_position(t.value());
}

/// 6 BCD bytes → position in 0.001 mm. Errors: truncated, bad_length (more than 6 bytes),
/// bad_sign (sign byte not 0x00/0xFF), bad_digit (nibble A–F), out_of_range (beyond ±4e9).
[[nodiscard]] constexpr result<std::int64_t>
decode_bcd_position(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < bcd_position_size) return errc::truncated;
  if (in.size() > bcd_position_size) return errc::bad_length;
  auto v = bcd::decode_signed(in);
  if (!v) return v.error();
  if (v.value() > bcd_position_limit || v.value() < -bcd_position_limit) {
    return errc::out_of_range;
  }
  return v;
}

/// Bytes of the POSR0SPEED value.
inline constexpr std::size_t bcd_speed_size = 3;
inline constexpr std::uint32_t bcd_speed_min = 1;       ///< 0.001 %
inline constexpr std::uint32_t bcd_speed_max = 600'000; ///< 600.000 %

using bcd_speed_bytes = std::array<std::uint8_t, bcd_speed_size>;

/// A speed in 0.001 % (any integer type) → 3 BCD bytes (POSR0SPEED).
/// Errors: out_of_range (outside 1..600 000).
template <integer_argument T>
[[nodiscard]] constexpr result<bcd_speed_bytes> encode_bcd_speed(T thousandths_percent) noexcept {
  if (!in_closed_range(thousandths_percent, bcd_speed_min, bcd_speed_max)) {
    return errc::out_of_range;
  }
  return bcd::encode<bcd_speed_size>(checked_narrow<std::uint64_t>(thousandths_percent).value());
}

/// 3 BCD bytes → speed in 0.001 %. Errors: truncated, bad_length, bad_digit, out_of_range.
[[nodiscard]] constexpr result<std::uint32_t>
decode_bcd_speed(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < bcd_speed_size) return errc::truncated;
  if (in.size() > bcd_speed_size) return errc::bad_length;
  auto v = bcd::decode(in);
  if (!v) return v.error();
  if (v.value() < bcd_speed_min || v.value() > bcd_speed_max) return errc::out_of_range;
  return static_cast<std::uint32_t>(v.value());
}

} // namespace fieldcodec::compax
