// fieldcodec — host adapters: the millisecond counter the machines take as `now`.
//
// Every machine (SDO client and server, node services, master sequences) is fed a caller-owned
// `std::uint32_t` millisecond count that may wrap (docs/canopen.md, "Machines"). On a host that
// count is the steady clock since some start: `host::steady_ms` is that, once.
//
//   host::steady_ms clock;                    // starts at 0 now
//   auto s = client.poll(clock.now());        // milliseconds since the clock was made
#pragma once

#include <chrono>
#include <cstdint>

namespace fieldcodec::host {

/// Milliseconds of std::chrono::steady_clock since construction, as the machines' `now`: a
/// std::uint32_t that wraps after about 49.7 days (the machines handle the wrap).
class steady_ms {
public:
  steady_ms() noexcept : start_(std::chrono::steady_clock::now()) {}

  /// Milliseconds since construction, modulo 2^32.
  [[nodiscard]] std::uint32_t now() const noexcept { return at(std::chrono::steady_clock::now()); }

  /// The same count for another time point of the steady clock (e.g. a deadline computed from
  /// a receive time).
  [[nodiscard]] std::uint32_t at(std::chrono::steady_clock::time_point t) const noexcept {
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(t - start_).count();
    return static_cast<std::uint32_t>(static_cast<std::uint64_t>(ms)); // modulo 2^32
  }

  /// When the clock started.
  [[nodiscard]] std::chrono::steady_clock::time_point start() const noexcept { return start_; }

private:
  std::chrono::steady_clock::time_point start_;
};

} // namespace fieldcodec::host
