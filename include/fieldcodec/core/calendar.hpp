// fieldcodec — days ↔ civil dates (proleptic Gregorian calendar), exactly and constexpr.
//
//   calendar::from_days(0)                          → 1970-01-01
//   calendar::to_days({1984, 1, 1})                 → 5113
//   calendar::from_days(calendar::cia301_epoch + 14610) → 2024-01-01
//
// CiA 301 counts TIME_OF_DAY days from 1984-01-01 (cia301_epoch); the TIME object (1012h) and
// od's value text (od/value_text.hpp) show them as dates through these two functions.
#pragma once

#include <fieldcodec/core/result.hpp>

#include <cstdint>

namespace fieldcodec::calendar {

/// A civil date: year, month 1..12, day 1..31.
struct date {
  std::int32_t year = 1970;
  std::uint8_t month = 1;
  std::uint8_t day = 1;
  friend constexpr bool operator==(const date &, const date &) noexcept = default;
};

/// 1984-01-01, the first day of CiA 301's TIME_OF_DAY, in days after 1970-01-01.
inline constexpr std::int64_t cia301_epoch = 5113;

[[nodiscard]] constexpr bool is_leap(std::int32_t y) noexcept {
  return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}

/// Days in month `m` (1..12) of year `y`; 0 for another month.
[[nodiscard]] constexpr unsigned days_in_month(std::int32_t y, unsigned m) noexcept {
  constexpr unsigned days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (m < 1U || m > 12U) return 0;
  return m == 2U && is_leap(y) ? 29U : days[m - 1U];
}

/// The date `days` days after 1970-01-01 (negative: before). Valid for |days| < 2^40.
[[nodiscard]] constexpr date from_days(std::int64_t days) noexcept {
  // eras of 400 years (146097 days) starting 0000-03-01
  const std::int64_t z = days + 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const std::int64_t doe = z - era * 146097;                                      // [0, 146096]
  const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365; // [0, 399]
  const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);               // [0, 365]
  const std::int64_t mp = (5 * doy + 2) / 153;                                    // [0, 11]
  const std::int64_t d = doy - (153 * mp + 2) / 5 + 1;                            // [1, 31]
  const std::int64_t m = mp < 10 ? mp + 3 : mp - 9;                               // [1, 12]
  const std::int64_t y = yoe + era * 400 + (m <= 2 ? 1 : 0);
  return {static_cast<std::int32_t>(y), static_cast<std::uint8_t>(m), static_cast<std::uint8_t>(d)};
}

/// Days after 1970-01-01 of a valid date. Errors: out_of_range (month not 1..12, day not in the
/// month).
[[nodiscard]] constexpr result<std::int64_t> to_days(date v) noexcept {
  if (v.day < 1U || v.day > days_in_month(v.year, v.month)) return errc::out_of_range;
  const std::int64_t y = std::int64_t{v.year} - (v.month <= 2U ? 1 : 0);
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t yoe = y - era * 400;                           // [0, 399]
  const std::int64_t mp = v.month > 2U ? v.month - 3 : v.month + 9; // [0, 11]
  const std::int64_t doy = (153 * mp + 2) / 5 + v.day - 1;          // [0, 365]
  const std::int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;   // [0, 146096]
  return era * 146097 + doe - 719468;
}

} // namespace fieldcodec::calendar
