// fieldcodec — the SYNC consumer (CiA 301 7.2.5): the SYNC COB-ID (1005h), the counter its
// frames carry when the counter overflow value (1019h) is above 1, and the synchronous window
// length (1007h) after each SYNC.
//
//   node::sync_consumer sync;
//   sync.set_cob_id(0x80); sync.set_window_us(2000); sync.set_overflow(8);
//   auto s = sync.on_frame(frame, now);     // s.state.received: a SYNC (s.state.counter)
//   sync.inside_window(now);                // synchronous PDOs only inside the window
//
// A frame whose length does not fit 1019h (DLC 1 with a counter overflow of 2..240, DLC 0 with
// 0) is not taken as a SYNC, and length_error() stays set until a SYNC of the right length
// arrives: the node reports EMCY 8240h "unexpected SYNC data length" meanwhile (CiA 301).
// Without 1019h in the dictionary (overflow never set) DLC 0 and 1 are both right. 1019h can
// be written only while the communication cycle period (1006h) is 0 (0x08000022 otherwise). A
// counter outside 1..240 is ignored too (error() = out_of_range).
//
// 1005h with bit 30 ("generate") set is refused (0x06090030) unless the node has a SYNC
// producer (allow_producer: node::device with capacity::sync_producer, node/sync_producer.hpp),
// so that a configuration tool learns whether the device can be the SYNC producer; with one,
// the identifier cannot change while bit 30 stays set (0x06090030; the same value is taken).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/node/cob_id_rules.hpp>
#include <fieldcodec/canopen/node/deadlines.hpp>
#include <fieldcodec/canopen/node/values.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/canopen/sync.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <cstdint>
#include <optional>

namespace fieldcodec::canopen::node {

/// What the consumer holds after a call.
struct sync_state {
  bool received = false;               ///< the call took a SYNC
  std::optional<std::uint8_t> counter; ///< its counter (when it carried one)
  bool in_window = false;              ///< inside the synchronous window of the last SYNC
  friend constexpr bool operator==(const sync_state &, const sync_state &) = default;
};

class sync_consumer {
public:
  using step = canopen::step<sync_state>;

  /// Would `value` be accepted for 1005h? Refused (0x06090030): bit 30 (this node produces no
  /// SYNC), bit 29 (29-bit), bits 11..28. The identifier may change at any time (a consumer).
  [[nodiscard]] static constexpr abort_code check_cob_id(std::uint32_t value) noexcept {
    if ((value & cob_bits::bit30) != 0U) return abort_code::invalid_value;
    return node::check_cob_id(value & ~cob_bits::invalid, std::nullopt, false);
  }
  constexpr abort_code set_cob_id(std::uint32_t value) noexcept {
    if (const auto c = check_cob_id(value); c != abort_code::none) return c;
    id_ = static_cast<std::uint16_t>(value & cob_bits::id);
    return abort_code::none;
  }
  /// 1019h: 0 (SYNC without counter) or 2..240; 1 and 241..255 are reserved (0x06090030).
  [[nodiscard]] static constexpr abort_code check_overflow(std::uint32_t value) noexcept {
    if (value == 0U || (value >= 2U && value <= sync::max_counter)) return abort_code::none;
    return abort_code::invalid_value;
  }
  constexpr abort_code set_overflow(std::uint32_t value) noexcept {
    if (const auto c = check_overflow(value); c != abort_code::none) return c;
    overflow_ = static_cast<std::uint8_t>(value);
    return abort_code::none;
  }
  /// 1007h, µs (0 = no window); rounded up to the caller's milliseconds.
  constexpr void set_window_us(std::uint32_t us) noexcept { window_ms_ = ms_from_us(us); }

  // ----- its objects in a node (node::device) ------------------------------------------------

  /// Would `v` be accepted for `a`? 1005h and 1019h as check_cob_id / check_overflow say, and
  /// 1019h only while the communication cycle period (1006h) is 0: otherwise 0x08000022
  /// (CiA 301, 1019h: the counter overflow cannot change while the cycle runs); none for
  /// every other object.
  [[nodiscard]] constexpr abort_code check_write(od::address a, std::uint32_t v) const noexcept {
    if (a.index == 0x1005U) {
      if (!producer_ || (v & cob_bits::bit30) == 0U) return check_cob_id(v);
      if ((cob_value_ & cob_bits::bit30) != 0U && (v & cob_bits::id) != id_) {
        return abort_code::invalid_value;
      }
      return check_cob_id(v & ~cob_bits::bit30);
    }
    if (a.index == 0x1019U) {
      if (period_us_ != 0U) return abort_code::cannot_store_device_state;
      return check_overflow(v);
    }
    return abort_code::none;
  }
  /// `v` was stored at `a`: follow 1005h, 1006h, 1007h, 1019h.
  constexpr void written(od::address a, std::uint32_t v, std::uint32_t) noexcept {
    if (a.index == 0x1005U) {
      cob_value_ = v;
      (void)set_cob_id(v & ~(producer_ ? cob_bits::bit30 : 0U));
    }
    if (a.index == 0x1006U) period_us_ = v;
    if (a.index == 0x1007U) set_window_us(v);
    if (a.index == 0x1019U) (void)set_overflow(v);
  }
  /// Start afresh from the values of 1005h, 1006h, 1007h and 1019h in `store` (boot, NMT
  /// reset).
  template <class Store>
  constexpr status load(const Store &store, std::uint32_t now) noexcept {
    const bool producer = producer_;
    *this = sync_consumer{};
    producer_ = producer;
    constexpr std::uint16_t objects[] = {0x1005, 0x1006, 0x1007, 0x1019};
    for (const std::uint16_t i : objects) {
      if (const auto v = read_u32(store, {i, 0})) written({i, 0}, *v, now);
    }
    return {};
  }

  [[nodiscard]] constexpr std::uint16_t cob_id() const noexcept { return id_; }
  /// The node has a SYNC producer: 1005h takes bit 30 (node::device sets it).
  constexpr void allow_producer(bool on) noexcept { producer_ = on; }
  /// The communication cycle period (1006h, µs; 0 when absent).
  [[nodiscard]] constexpr std::uint32_t period_us() const noexcept { return period_us_; }

  /// A frame on the SYNC COB-ID (others are ignored).
  [[nodiscard]] constexpr step on_frame(const can_frame &f, std::uint32_t now) noexcept {
    return make(now, receive(f, now));
  }
  /// on_frame() without the step (what node::device calls): true when `f` is a SYNC that was
  /// taken (its counter: counter()).
  [[nodiscard]] constexpr bool receive(const can_frame &f, std::uint32_t now) noexcept {
    if (f.id != id_ || f.rtr) return false;
    const bool right_length = overflow_ ? (f.dlc == (*overflow_ >= 2U ? 1U : 0U)) : f.dlc <= 1U;
    if (!right_length) {
      length_error_ = true;
      error_ = errc::bad_length;
      return false;
    }
    std::optional<std::uint8_t> counter;
    if (f.dlc == 1U) {
      if (f.data[0] < 1U || f.data[0] > sync::max_counter) {
        error_ = errc::out_of_range;
        return false;
      }
      counter = f.data[0];
    }
    length_error_ = false;
    error_ = errc{};
    seen_ = true;
    last_ = now;
    counter_ = counter;
    return true;
  }
  /// The counter of the last SYNC taken (nullopt: it carried none).
  [[nodiscard]] constexpr std::optional<std::uint8_t> counter() const noexcept { return counter_; }

  /// The window closing is a state change (in_window becomes false).
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept { return make(now, false); }

  /// Inside the synchronous window of the last SYNC (always, when no window is set; never
  /// before the first SYNC).
  [[nodiscard]] constexpr bool inside_window(std::uint32_t now) const noexcept {
    if (!seen_) return false;
    if (window_ms_ == 0U) return true;
    return !reached(last_ + window_ms_, now);
  }
  /// A synchronous window is set and has passed since the last SYNC (false before the first
  /// SYNC): synchronous RPDOs arriving now are discarded until the next SYNC.
  [[nodiscard]] constexpr bool window_passed(std::uint32_t now) const noexcept {
    return seen_ && window_ms_ != 0U && !inside_window(now);
  }
  /// The last SYNC's length did not fit 1019h.
  [[nodiscard]] constexpr bool length_error() const noexcept { return length_error_; }
  [[nodiscard]] constexpr std::optional<errc> error() const noexcept {
    if (error_ == errc{}) return std::nullopt;
    return error_;
  }
  /// Forget the last SYNC (NMT reset).
  constexpr void restart() noexcept {
    seen_ = false;
    length_error_ = false;
  }
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline(std::uint32_t now) const noexcept {
    if (!seen_ || window_ms_ == 0U || !inside_window(now)) return std::nullopt;
    return last_ + window_ms_;
  }

private:
  [[nodiscard]] constexpr step make(std::uint32_t now, bool received) const noexcept {
    return {{}, {received, received ? counter_ : std::nullopt, inside_window(now)}, deadline(now)};
  }

  std::uint16_t id_ = cob_id::sync;
  std::optional<std::uint8_t> overflow_{};
  std::uint32_t window_ms_ = 0;
  std::uint32_t period_us_ = 0;
  std::uint32_t cob_value_ = 0;
  std::uint32_t last_ = 0;
  std::optional<std::uint8_t> counter_{};
  /// errc{} (no code of errc is 0) when there is none; a plain member for the reason given in
  /// nmt_slave.hpp (g++ 12 -O3 -Wmaybe-uninitialized on a copied std::optional).
  errc error_{};
  bool seen_ = false;
  bool length_error_ = false;
  bool producer_ = false;
};

} // namespace fieldcodec::canopen::node
