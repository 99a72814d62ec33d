// fieldcodec — host adapters: the millisecond counter the machines take as `now`.
//
// Every machine (SDO client and server, node services, master sequences) is fed a caller-owned
// `std::uint32_t` millisecond count that may wrap (docs/canopen.md, "Machines"). On a host that
// count is the steady clock since some start: `host::steady_ms` is that, once.
//
//   host::steady_ms clock;                    // starts at 0 now
//   auto s = client.poll(clock.now());        // milliseconds since the clock was made
//
// And the wall clock as CiA 301's time of day, for a node's TIME producer (1012h bit 30):
//   send(dev.produce_time(host::time_of_day(std::chrono::system_clock::now()).value(), now));
#pragma once

#include <fieldcodec/core/calendar.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/value.hpp>

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

/// A time of the system clock (UTC, as std::chrono::system_clock counts it) as CiA 301's
/// TIME_OF_DAY: milliseconds after midnight (the rest of the millisecond dropped, as a clock
/// reading is) and days since 1984-01-01. Errors: out_of_range (before 1984-01-01, or after
/// day 65 535: 2163-06-06).
[[nodiscard]] inline result<od::time_value>
time_of_day(std::chrono::system_clock::time_point t) noexcept {
  using namespace std::chrono;
  const auto ms = floor<milliseconds>(t.time_since_epoch()).count();
  constexpr std::int64_t day = 86'400'000;
  const std::int64_t unix_days = ms >= 0 ? ms / day : (ms - day + 1) / day;
  const std::int64_t days = unix_days - calendar::cia301_epoch;
  if (days < 0 || days > 0xFFFF) return errc::out_of_range;
  return od::time_value{static_cast<std::uint32_t>(ms - unix_days * day),
                        static_cast<std::uint16_t>(days)};
}

} // namespace fieldcodec::host
