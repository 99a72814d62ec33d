// fieldcodec — SYNC (with optional counter, CiA 301). The TIME stamp is in time_stamp.hpp.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/core/result.hpp>

#include <cstdint>
#include <optional>

namespace fieldcodec::canopen {

namespace sync {
/// SYNC counter values are 1..240; the counter overflow value (object 1019h) is 2..240, or 0
/// for a SYNC without counter.
inline constexpr std::uint8_t max_counter = 240;

/// SYNC without counter: 0x080 DLC 0.
[[nodiscard]] constexpr can_frame encode() noexcept { return make_frame(cob_id::sync, {}).value(); }
/// SYNC with counter: 0x080 DLC 1 [counter]. Errors: out_of_range (counter not 1..240).
[[nodiscard]] constexpr result<can_frame> encode(std::uint8_t counter) noexcept {
  if (counter < 1U || counter > max_counter) return errc::out_of_range;
  return make_frame(cob_id::sync, {counter});
}
/// The counter of a SYNC (nullopt without counter). Errors: unexpected_frame (not 0x080 or a
/// remote frame), bad_length (DLC not 0 or 1), out_of_range (counter 0 or > 240).
[[nodiscard]] constexpr result<std::optional<std::uint8_t>> decode(const can_frame &f) noexcept {
  if (f.id != cob_id::sync || f.rtr) return errc::unexpected_frame;
  // Built in place: a disengaged optional moved into the result copies its uninitialised
  // payload, which g++ 12 -O2/-O3/-Os reports as -Wmaybe-uninitialized in users' builds.
  if (f.dlc == 0U) return result<std::optional<std::uint8_t>>{std::in_place, std::nullopt};
  if (f.dlc != 1U) return errc::bad_length;
  if (f.data[0] < 1U || f.data[0] > max_counter) return errc::out_of_range;
  return std::optional<std::uint8_t>{f.data[0]};
}

/// A SYNC producer: counts 1..overflow and wraps to 1. overflow 0 or 1 = no counter
/// (CiA 301 reserves 1 and 241..255; they are treated like 0 here).
class producer {
public:
  constexpr explicit producer(std::uint8_t overflow = 0) noexcept
      : overflow_(overflow >= 2U && overflow <= max_counter ? overflow : 0U) {}
  [[nodiscard]] constexpr can_frame next() noexcept {
    if (overflow_ == 0U) return encode();
    const std::uint8_t c = counter_;
    counter_ = c >= overflow_ ? std::uint8_t{1} : static_cast<std::uint8_t>(c + 1U);
    return encode(c).value();
  }
  /// After NMT start, reset communication or a change of 1019h the counter restarts at 1.
  constexpr void reset() noexcept { counter_ = 1; }

private:
  std::uint8_t overflow_;
  std::uint8_t counter_ = 1;
};
} // namespace sync

} // namespace fieldcodec::canopen
