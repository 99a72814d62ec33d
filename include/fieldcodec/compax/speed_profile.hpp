// fieldcodec — COMPAX speed step profiles: the combined objects POSRXSPEEDY (0x5FE4, 8 bytes)
// and PRXSDYALZ (0x5FC7, 10 bytes), manual 000, sections 2.8.4 and 2.8.5.
//
// Both are written once per step (a profile has at most 8 steps): after `position` (relative
// to the start point of the positioning) the drive continues at `speed`; PRXSDYALZ adds the
// ramp time to reach it.
//   bytes 1..4   position, two's complement, most significant byte first, 1 = 0.001 mm (or inch),
//                printed range −2 147 483 648 … +2 147 483 647
//   bytes 5..8   speed, binary, most significant byte first, 1 = 0.001 %, 1 … 600 000
//   bytes 9..10  ramp time (PRXSDYALZ only), binary, MSB first, 1 = 1 ms, 0 … 65 000
// The objects are octet strings with their own coding, not Integer32 objects: the page prints
// −2 147 483 648 as a value, so the Integer32 overflow marker (1.7.2) does not apply here
// (docs/compax.md, "Speed step profiles").
#pragma once

#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace fieldcodec::compax {

inline constexpr std::size_t posrxspeedy_size = 8;
inline constexpr std::size_t prxsdyalz_size = 10;
/// Decimal places of position (mm) and speed (%): resolution 0.001.
inline constexpr unsigned speed_step_places = 3;
inline constexpr std::int64_t speed_step_speed_min = 1;       ///< 0.001 %
inline constexpr std::int64_t speed_step_speed_max = 600'000; ///< 600.000 %
inline constexpr std::int64_t speed_step_ramp_max = 65'000;   ///< ms

/// One step of a speed step profile, in engineering units.
struct speed_step {
  decimal position{}; ///< mm (or inch) from the start point, at most 3 decimal places
  decimal speed{};    ///< % of the nominal speed, 0.001 … 600
};

/// One step with its ramp time (PRXSDYALZ).
struct speed_step_ramp {
  decimal position{};       ///< mm (or inch) from the start point, at most 3 decimal places
  decimal speed{};          ///< % of the nominal speed, 0.001 … 600
  std::int64_t ramp_ms = 0; ///< ramp time in ms, 0 … 65 000
};

namespace detail {

/// Position in 0.001 mm. Errors: not_representable (finer than 0.001), out_of_range.
[[nodiscard]] constexpr result<std::int32_t> step_position(decimal mm) noexcept {
  auto t = to_fixed(mm, speed_step_places);
  if (!t) return t.error() == errc::overflow ? errc::out_of_range : t.error();
  auto p = checked_narrow<std::int32_t>(t.value());
  if (!p) return errc::out_of_range;
  return p;
}
/// Speed in 0.001 %. Errors: not_representable, out_of_range (outside 1 … 600 000).
[[nodiscard]] constexpr result<std::uint32_t> step_speed(decimal percent) noexcept {
  auto t = to_fixed(percent, speed_step_places);
  if (!t) return t.error() == errc::overflow ? errc::out_of_range : t.error();
  if (t.value() < speed_step_speed_min || t.value() > speed_step_speed_max) {
    return errc::out_of_range;
  }
  return static_cast<std::uint32_t>(t.value());
}
/// The position and speed bytes (1..8) of both objects.
[[nodiscard]] constexpr status write_step(std::span<std::uint8_t> out, decimal position,
                                          decimal speed) noexcept {
  auto p = step_position(position);
  if (!p) return p.error();
  auto v = step_speed(speed);
  if (!v) return v.error();
  FIELDCODEC_TRY_STATUS(store<std::int32_t>(out, p.value(), bus_order));
  return store<std::uint32_t>(out.subspan(4), v.value(), bus_order);
}
/// Bytes 1..8 → position and speed. Errors: out_of_range (speed outside 1 … 600 000).
[[nodiscard]] constexpr result<speed_step> read_step(std::span<const std::uint8_t> in) noexcept {
  const auto p = load<std::int32_t>(in, bus_order).value();
  const auto v = load<std::uint32_t>(in.subspan(4), bus_order).value();
  if (v < speed_step_speed_min || v > speed_step_speed_max) return errc::out_of_range;
  return speed_step{normalize(decimal{p, speed_step_places}),
                    normalize(decimal{static_cast<std::int64_t>(v), speed_step_places})};
}

} // namespace detail

/// POSRXSPEEDY data bytes. Errors: not_representable (finer than 0.001), out_of_range (position
/// outside the 32-bit range, speed outside 0.001 … 600 %).
[[nodiscard]] constexpr result<std::array<std::uint8_t, posrxspeedy_size>>
encode_posrxspeedy(const speed_step &s) noexcept {
  std::array<std::uint8_t, posrxspeedy_size> out{};
  FIELDCODEC_TRY_STATUS(detail::write_step(out, s.position, s.speed));
  return out;
}

/// POSRXSPEEDY data bytes → step. Errors: truncated, bad_length, out_of_range (speed).
[[nodiscard]] constexpr result<speed_step>
decode_posrxspeedy(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < posrxspeedy_size) return errc::truncated;
  if (in.size() > posrxspeedy_size) return errc::bad_length;
  return detail::read_step(in);
}

/// PRXSDYALZ data bytes. Errors: those of encode_posrxspeedy, out_of_range (ramp outside
/// 0 … 65 000 ms).
[[nodiscard]] constexpr result<std::array<std::uint8_t, prxsdyalz_size>>
encode_prxsdyalz(const speed_step_ramp &s) noexcept {
  std::array<std::uint8_t, prxsdyalz_size> out{};
  if (s.ramp_ms < 0 || s.ramp_ms > speed_step_ramp_max) return errc::out_of_range;
  FIELDCODEC_TRY_STATUS(detail::write_step(out, s.position, s.speed));
  FIELDCODEC_TRY_STATUS(store<std::uint16_t>(std::span<std::uint8_t>{out}.subspan(8),
                                             static_cast<std::uint16_t>(s.ramp_ms), bus_order));
  return out;
}

/// PRXSDYALZ data bytes → step. Errors: truncated, bad_length, out_of_range (speed, ramp).
[[nodiscard]] constexpr result<speed_step_ramp>
decode_prxsdyalz(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < prxsdyalz_size) return errc::truncated;
  if (in.size() > prxsdyalz_size) return errc::bad_length;
  auto s = detail::read_step(in);
  if (!s) return s.error();
  const auto ramp = load<std::uint16_t>(in.subspan(8), bus_order).value();
  if (ramp > speed_step_ramp_max) return errc::out_of_range;
  return speed_step_ramp{s.value().position, s.value().speed, ramp};
}

} // namespace fieldcodec::compax
