// fieldcodec — times of the node services (canopen/node/): the earlier of two deadlines, and
// the CiA 301 times in 100 µs and µs as the caller's milliseconds.
#pragma once

#include <fieldcodec/canopen/step.hpp>

#include <cstdint>
#include <optional>

namespace fieldcodec::canopen::node {

/// The earlier of two optional deadlines (wrap-around safe, relative to `now`). By reference:
/// an optional passed by value costs every caller a copy on the stack (Cortex-M).
[[nodiscard]] constexpr std::optional<std::uint32_t> earliest(const std::optional<std::uint32_t> &a,
                                                              const std::optional<std::uint32_t> &b,
                                                              std::uint32_t now) noexcept {
  if (!a) return b;
  if (!b) return a;
  // compare distances from now; a deadline already passed (distance ≥ 2^31) counts as now
  const std::uint32_t da = reached(*a, now) ? 0U : *a - now;
  const std::uint32_t db = reached(*b, now) ? 0U : *b - now;
  return da <= db ? a : b;
}

/// A time in units of 100 µs (inhibit times) as whole milliseconds of the caller's counter,
/// rounded up: an inhibit time is a minimum, so 1 (100 µs) waits 1 ms.
[[nodiscard]] constexpr std::uint32_t ms_from_100us(std::uint32_t t) noexcept {
  return t / 10U + (t % 10U != 0U ? 1U : 0U);
}
/// Microseconds (1006h, 1007h) as milliseconds, rounded up.
[[nodiscard]] constexpr std::uint32_t ms_from_us(std::uint32_t t) noexcept {
  return t / 1000U + (t % 1000U != 0U ? 1U : 0U);
}

} // namespace fieldcodec::canopen::node
