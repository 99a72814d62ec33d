// fieldcodec — PA-CONTROL typed command and acknowledgement dates.
//
// A date (PAR_2 of a request, Q_PAR of an acknowledgement) is either an integer (TYP 0, a
// signed 32-bit number) or a real number (TYP 1); its type is od::command_value, the type the
// command table gives each command's date and reply. Real numbers are kept as exact decimals, so
// "5552.0" and "1516.950" travel back out exactly as they came in; binary floats are turned
// into decimals in one of two styles:
//
//   float_style::master  the shortest decimal that reads back as the same float, with at least
//                        one fractional digit (5552.0f → "5552.0", 0.1f → "0.1");
//   float_style::device  seven significant digits with trailing zeros kept, as the PA-CONTROL
//                        prints them (640.0f → "640.0000", 1516.95f → "1516.950").
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/integer.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/command.hpp>

#include <cstdint>
#include <limits>

namespace fieldcodec::pacontrol {

/// How a binary float becomes decimal text.
enum class float_style : std::uint8_t {
  master, ///< shortest round-trip form, at least one fractional digit ("5552.0")
  device, ///< seven significant digits, trailing zeros kept ("1516.950")
};

/// Significant digits of the device style.
inline constexpr unsigned device_significant_digits = 7;

namespace detail {

/// Number of digits of the integer part of |d| (at least 1).
[[nodiscard]] constexpr unsigned integer_digits(decimal d) noexcept {
  std::uint64_t m = fieldcodec::detail::magnitude(d.mantissa);
  for (unsigned i = 0; i < d.places; ++i) m /= 10U;
  unsigned n = 1;
  while (m >= 10U) {
    m /= 10U;
    ++n;
  }
  return n;
}

/// `d` with at least `places` fractional digits (appending zeros). Errors: overflow.
[[nodiscard]] constexpr result<decimal> pad_places(decimal d, unsigned places) noexcept {
  while (d.places < places) {
    if (d.mantissa > std::numeric_limits<std::int64_t>::max() / 10 ||
        d.mantissa < std::numeric_limits<std::int64_t>::min() / 10) {
      return errc::overflow;
    }
    d.mantissa *= 10;
    ++d.places;
  }
  return d;
}

} // namespace detail

/// The nearest double to an exact decimal (one correctly rounded division).
[[nodiscard]] constexpr double to_double(decimal d) noexcept {
  return scaling::to_eu(d.mantissa,
                        scaling::linear{decimal{fieldcodec::detail::pow10_i64(d.places), 0}, {}});
}

/// The float a decimal stands for (through the nearest double).
[[nodiscard]] constexpr float to_float(decimal d) noexcept {
  return static_cast<float>(to_double(d));
}

/// The shortest decimal (1..9 significant digits) that converts back to exactly `v`.
/// Errors: not_representable (NaN, infinity, |v| >= 9e18, or too small to be written with 18
/// fractional digits).
[[nodiscard]] constexpr result<decimal> shortest_decimal(float v) noexcept {
  if (v == 0.0F) return decimal{0, 0};
  for (unsigned sig = 1; sig <= 9U; ++sig) {
    auto d = decimal_from_double(static_cast<double>(v), sig);
    if (!d) return d.error();
    if (to_float(d.value()) == v) return d;
  }
  return errc::not_representable;
}

/// `v` as decimal text would carry it in the given style (see the header comment).
/// Errors: not_representable (NaN, infinity, out of reach of an exact decimal), overflow.
[[nodiscard]] constexpr result<decimal> float_to_decimal(float v, float_style style) noexcept {
  if (style == float_style::master) {
    auto d = shortest_decimal(v);
    if (!d) return d.error();
    return detail::pad_places(d.value(), 1);
  }
  auto d = decimal_from_double(static_cast<double>(v), device_significant_digits);
  if (!d) return d.error();
  const unsigned digits = detail::integer_digits(d.value());
  const unsigned places =
      digits >= device_significant_digits ? 1U : device_significant_digits - digits;
  return detail::pad_places(d.value(), places);
}

/// A typed date: an int32 (places 0) or an exact decimal real number.
struct value {
  od::command_value type = od::command_value::integer; ///< integer or real (none is invalid)
  decimal number{};

  /// An integer date. Errors: overflow (outside int32).
  template <integer_argument T>
  [[nodiscard]] static constexpr result<value> of_int(T v) noexcept {
    auto i = checked_narrow<std::int32_t>(v);
    if (!i) return i.error();
    return value{od::command_value::integer, decimal{i.value(), 0}};
  }
  /// A real date, written exactly as `d` (trailing zeros included).
  /// Errors: invalid_argument (more than 18 places).
  [[nodiscard]] static constexpr result<value> of_real(decimal d) noexcept {
    if (d.places > decimal_max_places) return errc::invalid_argument;
    return value{od::command_value::real, d};
  }
  /// A real date from a float. Errors: not_representable (NaN, infinity), overflow.
  [[nodiscard]] static constexpr result<value>
  of_float(float v, float_style style = float_style::master) noexcept {
    auto d = float_to_decimal(v, style);
    if (!d) return d.error();
    return value{od::command_value::real, d.value()};
  }

  /// The integer. Errors: type_mismatch (a real date), overflow (not an int32: an invalid
  /// value, see validate()).
  [[nodiscard]] constexpr result<std::int32_t> as_int() const noexcept {
    if (type != od::command_value::integer || number.places != 0U) return errc::type_mismatch;
    return checked_narrow<std::int32_t>(number.mantissa);
  }
  /// The value as a float (integers convert too).
  [[nodiscard]] constexpr float as_float() const noexcept { return to_float(number); }

  /// Same type and the same number: 5552.0 == 5552.000 (use same_text to compare the text a
  /// frame carries).
  friend constexpr bool operator==(const value &a, const value &b) noexcept {
    return a.type == b.type && equal(a.number, b.number);
  }
  /// Same type and the same text: 5552.0 and 5552.000 differ (they are different frames).
  [[nodiscard]] constexpr bool same_text(const value &other) const noexcept {
    return type == other.type && number.mantissa == other.number.mantissa &&
           number.places == other.number.places;
  }
};

/// Checks the invariants of a value: an integer has no places and fits int32; a real has at
/// most 18 places. Errors: overflow (integer outside int32), type_mismatch (integer with a
/// fraction), invalid_argument (too many places, or the type `none`).
[[nodiscard]] constexpr status validate(const value &v) noexcept {
  if (v.number.places > decimal_max_places) return errc::invalid_argument;
  if (v.type == od::command_value::integer) {
    if (v.number.places != 0U) return errc::type_mismatch;
    if (v.number.mantissa < std::numeric_limits<std::int32_t>::min() ||
        v.number.mantissa > std::numeric_limits<std::int32_t>::max()) {
      return errc::overflow;
    }
  } else if (v.type != od::command_value::real) {
    return errc::invalid_argument;
  }
  return {};
}

} // namespace fieldcodec::pacontrol
