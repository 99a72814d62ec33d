// fieldcodec — PA-CONTROL axis parameter addresses (manual 001, 5.2.3).
//
// The commands 0800, 1800, 1801 and 1802 address one parameter of one axis through their
// command parameter PAR_1: the axis number (1-16) in the high byte, the axis parameter number
// (1-50, from traverse speed to enable mode) in the low byte.
//
//   encode_axis_parameter({3, 6})  → 0x0306 = 774   (axis 3, acceleration; 5.2.3 example)
//   decode_axis_parameter(543)     → {2, 31}        (axis 2, invert shaft encoder; 5.2.3.1)
//
// A number outside those ranges is refused (errc::out_of_range) before a frame is built; the
// device would answer QUIT 32 (axis number unknown) or 33 (axis parameter unknown).
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/integer.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>

namespace fieldcodec::pacontrol {

/// Axes a PA-CONTROL addresses (1-16).
inline constexpr std::uint8_t max_axis = 16;
/// Highest axis parameter number (32 hex, "enable mode for axes").
inline constexpr std::uint8_t max_axis_parameter = 50;

/// One parameter of one axis.
struct axis_parameter {
  std::uint8_t axis = 1;   ///< 1-16
  std::uint8_t number = 1; ///< 1-50 (1 traverse speed, 6 acceleration, 31 invert encoder, …)

  friend constexpr bool operator==(const axis_parameter &,
                                   const axis_parameter &) noexcept = default;
};

/// An axis parameter from any integer types. Errors: out_of_range (axis not 1-16, parameter
/// not 1-50).
template <integer_argument A, integer_argument N>
[[nodiscard]] constexpr result<axis_parameter> make_axis_parameter(A axis, N number) noexcept {
  if (!in_closed_range(axis, 1, max_axis) || !in_closed_range(number, 1, max_axis_parameter)) {
    return errc::out_of_range;
  }
  return axis_parameter{static_cast<std::uint8_t>(axis), static_cast<std::uint8_t>(number)};
}

/// PAR_1 of an axis parameter: axis in the high byte, parameter number in the low byte.
/// Errors: out_of_range (axis not 1-16, parameter not 1-50).
[[nodiscard]] constexpr result<std::uint16_t> encode_axis_parameter(axis_parameter p) noexcept {
  auto checked = make_axis_parameter(p.axis, p.number);
  if (!checked) return checked.error();
  return from_bytes<std::uint16_t>(std::array<std::uint8_t, 2>{p.axis, p.number}, byte_order::big);
}

/// The axis parameter a PAR_1 addresses. Errors: overflow (negative or beyond 16 bits),
/// out_of_range (axis not 1-16, parameter not 1-50).
template <integer_argument T>
[[nodiscard]] constexpr result<axis_parameter> decode_axis_parameter(T par1) noexcept {
  auto word = checked_narrow<std::uint16_t>(par1);
  if (!word) return word.error();
  const auto b = to_bytes<std::uint16_t>(word.value(), byte_order::big);
  return make_axis_parameter(b[0], b[1]);
}

} // namespace fieldcodec::pacontrol
