// fieldcodec — the SYNC producer (CiA 301 7.2.5): a node whose 1005h has bit 30 ("generate")
// set sends a SYNC every communication cycle period (1006h, µs), with a counter when the
// counter overflow value (1019h) is 2..240.
//
//   node::sync_producer p;
//   p.written({0x1006, 0}, 10000, now);             // 10 ms
//   p.written({0x1005, 0}, 0x4000'0080U, now);      // generate, COB-ID 80h
//   if (auto f = p.poll(now)) send(*f);             // at p.deadline() at the latest
//
// The period is counted in the caller's milliseconds: 1006h is rounded up to whole ms. The
// first SYNC comes one period after the producer starts (bit 30 set, a new period, a new
// COB-ID or 1019h, or load); then every period after the last one was due, so that late polls
// do not shift the cycle; a poll later than a whole period sends one SYNC, not one per missed
// period, and the cycle starts again from it. The counter (1..1019h) restarts at 1 when the
// producer starts and when the node enters operational (restart_counter()).
//
// The rules of 1005h and 1019h (the SYNC consumer's check_write) hold for the producer too:
// 1019h only while 1006h is 0, and 1005h's identifier not while bit 30 stays set.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/node/cob_id_rules.hpp>
#include <fieldcodec/canopen/node/deadlines.hpp>
#include <fieldcodec/canopen/node/values.hpp>
#include <fieldcodec/canopen/sync.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <cstdint>
#include <optional>

namespace fieldcodec::canopen::node {

class sync_producer {
public:
  /// The SYNC consumer checks 1005h, 1006h and 1019h for both: none.
  [[nodiscard]] constexpr abort_code check_write(od::address, std::uint32_t) const noexcept {
    return abort_code::none;
  }
  /// `v` was stored at `a`: follow 1005h, 1006h, 1019h (a changed value starts the producer
  /// afresh; the same value written again changes nothing).
  constexpr void written(od::address a, std::uint32_t v, std::uint32_t now) noexcept {
    if (a.index == 0x1005U) {
      const auto id = static_cast<std::uint16_t>(v & cob_bits::id);
      const bool generate = (v & cob_bits::bit30) != 0U;
      if (id == id_ && generate == generate_) return;
      id_ = id;
      generate_ = generate;
    } else if (a.index == 0x1006U) {
      if (ms_from_us(v) == period_ms_) return;
      period_ms_ = ms_from_us(v);
    } else if (a.index == 0x1019U) {
      counter_ = sync::producer(static_cast<std::uint8_t>(v <= 0xFFU ? v : 0U));
    } else {
      return;
    }
    start(now);
  }
  /// Start afresh from 1005h, 1006h and 1019h in `store` (boot, NMT reset).
  template <class Store>
  constexpr status load(const Store &store, std::uint32_t now) noexcept {
    *this = sync_producer{};
    constexpr std::uint16_t objects[] = {0x1005, 0x1006, 0x1019};
    for (const std::uint16_t i : objects) {
      if (const auto v = read_u32(store, {i, 0})) written({i, 0}, *v, now);
    }
    return {};
  }

  /// Producing: 1005h bit 30 set and 1006h not 0.
  [[nodiscard]] constexpr bool active() const noexcept { return generate_ && period_ms_ != 0U; }
  /// The SYNC due at `now` (nullopt when none is due or the producer is not active).
  [[nodiscard]] constexpr std::optional<can_frame> poll(std::uint32_t now) noexcept {
    if (!active() || !reached(due_, now)) return std::nullopt;
    can_frame f = counter_.next();
    f.id = id_;
    due_ += period_ms_;
    if (reached(due_, now)) due_ = now + period_ms_; // a whole period late: start again
    return f;
  }
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline() const noexcept {
    if (!active()) return std::nullopt;
    return due_;
  }
  /// The counter restarts at 1 (the node entered operational).
  constexpr void restart_counter() noexcept { counter_.reset(); }
  [[nodiscard]] constexpr std::uint32_t period_ms() const noexcept { return period_ms_; }

private:
  constexpr void start(std::uint32_t now) noexcept {
    due_ = now + period_ms_;
    counter_.reset();
  }

  sync::producer counter_{};
  std::uint32_t period_ms_ = 0;
  std::uint32_t due_ = 0;
  std::uint16_t id_ = cob_id::sync;
  bool generate_ = false;
};

} // namespace fieldcodec::canopen::node
