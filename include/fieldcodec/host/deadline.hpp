// fieldcodec — host adapters: how long until a deadline of the steady clock. Every adapter that
// waits (serial port, slcan, the PA-CONTROL link, a bus's receive, the network loop) computes an
// end time once, `steady_clock::now() + timeout`, and asks this before each wait, so that a
// wait that is woken early never waits longer than the caller's timeout overall.
//
//   const auto end = std::chrono::steady_clock::now() + timeout;
//   for (;;) {
//     const auto left = host::time_left(end);       // 0 ms once the deadline has passed
//     auto n = port.read(buffer, left);             // a read of 0 ms only polls
//     ...
//   }
#pragma once

#include <chrono>

namespace fieldcodec::host {

/// Whole milliseconds from now until `end` (rounded down), 0 when less than one is left or the
/// deadline has passed: never negative.
[[nodiscard]] inline std::chrono::milliseconds
time_left(std::chrono::steady_clock::time_point end) noexcept {
  const auto left =
      std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
  return left.count() > 0 ? left : std::chrono::milliseconds(0);
}

} // namespace fieldcodec::host
