// fieldcodec — od::number, a small tagged number for limits and default values.
//
// Holds nothing, an int64, a uint64, a double or an exact decimal (mantissa × 10^-places) in
// 16 bytes, so a generated dictionary can write `od::signed_number(-5)`,
// `od::unsigned_number(0xFFFF)`, `od::real_number(1.5)` or `od::decimal_number(32767, 2)` in a
// plain aggregate initialiser.
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>

#include <bit>
#include <cstdint>
#include <limits>

namespace fieldcodec::od {

enum class number_kind : std::uint8_t {
  none,      ///< not given
  signed_,   ///< std::int64_t
  unsigned_, ///< std::uint64_t
  real,      ///< double
  decimal_,  ///< exact decimal (mantissa as int64, places)
};

struct number {
  number_kind kind = number_kind::none;
  std::uint8_t places = 0; ///< decimal places (decimal_ only)
  std::uint64_t bits = 0;  ///< the value's bits (int64 two's complement, double's IEEE bits)

  [[nodiscard]] constexpr bool has_value() const noexcept { return kind != number_kind::none; }
  [[nodiscard]] constexpr explicit operator bool() const noexcept { return has_value(); }

  /// The value as an exact decimal. Errors: unknown_object (none), overflow (uint64 beyond
  /// INT64_MAX), not_representable (NaN, infinity, |x| ≥ 9e18).
  [[nodiscard]] constexpr result<decimal> to_decimal() const noexcept {
    switch (kind) {
    case number_kind::none: return errc::unknown_object;
    case number_kind::signed_: return decimal{static_cast<std::int64_t>(bits), 0};
    case number_kind::unsigned_:
      if (bits > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        return errc::overflow;
      }
      return decimal{static_cast<std::int64_t>(bits), 0};
    case number_kind::real: return decimal_from_double(std::bit_cast<double>(bits));
    case number_kind::decimal_: return decimal{static_cast<std::int64_t>(bits), places};
    }
    return errc::unknown_object;
  }

  /// The value as an int64 when it is an integer that fits. Errors: unknown_object (none),
  /// overflow, not_representable (fractional).
  [[nodiscard]] constexpr result<std::int64_t> to_int64() const noexcept {
    switch (kind) {
    case number_kind::none: return errc::unknown_object;
    case number_kind::signed_: return static_cast<std::int64_t>(bits);
    case number_kind::unsigned_:
      if (bits > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        return errc::overflow;
      }
      return static_cast<std::int64_t>(bits);
    case number_kind::real:
    case number_kind::decimal_: {
      auto d = to_decimal();
      if (!d) return d.error();
      return to_fixed(d.value(), 0);
    }
    }
    return errc::unknown_object;
  }

  /// The value as a uint64 when it is a non-negative integer. Errors: as to_int64, overflow
  /// for negative values.
  [[nodiscard]] constexpr result<std::uint64_t> to_uint64() const noexcept {
    if (kind == number_kind::unsigned_) return bits;
    auto v = to_int64();
    if (!v) return v.error();
    if (v.value() < 0) return errc::overflow;
    return static_cast<std::uint64_t>(v.value());
  }

  /// The value as a double (nearest; a decimal is mantissa / 10^places in one division). NaN for
  /// none.
  [[nodiscard]] constexpr double to_double() const noexcept {
    switch (kind) {
    case number_kind::none: return std::numeric_limits<double>::quiet_NaN();
    case number_kind::signed_: return static_cast<double>(static_cast<std::int64_t>(bits));
    case number_kind::unsigned_: return static_cast<double>(bits);
    case number_kind::real: return std::bit_cast<double>(bits);
    case number_kind::decimal_: // one division: correctly rounded for |mantissa| ≤ 2^53
      return static_cast<double>(static_cast<std::int64_t>(bits)) /
             fieldcodec::detail::pow10_double(places);
    }
    return std::numeric_limits<double>::quiet_NaN();
  }

  /// Same kind and bits (1.5 as decimal and 1.5 as double are different numbers here).
  friend constexpr bool operator==(const number &, const number &) noexcept = default;
};

// Factories, one per kind (generated dictionaries and tests use them).

/// A signed integer (number_kind::signed_).
[[nodiscard]] constexpr number signed_number(std::int64_t v) noexcept {
  return {number_kind::signed_, 0, static_cast<std::uint64_t>(v)};
}
/// An unsigned integer (number_kind::unsigned_).
[[nodiscard]] constexpr number unsigned_number(std::uint64_t v) noexcept {
  return {number_kind::unsigned_, 0, v};
}
/// A binary floating-point value (number_kind::real).
[[nodiscard]] constexpr number real_number(double v) noexcept {
  return {number_kind::real, 0, std::bit_cast<std::uint64_t>(v)};
}
/// An exact decimal mantissa × 10^-places (number_kind::decimal_): 327.67 is (32767, 2).
[[nodiscard]] constexpr number decimal_number(std::int64_t mantissa, std::uint8_t places) noexcept {
  return {number_kind::decimal_, places, static_cast<std::uint64_t>(mantissa)};
}
[[nodiscard]] constexpr number decimal_number(decimal v) noexcept {
  return decimal_number(v.mantissa, v.places);
}

} // namespace fieldcodec::od
