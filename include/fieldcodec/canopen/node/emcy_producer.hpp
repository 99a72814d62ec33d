// fieldcodec — the EMCY producer (CiA 301 7.2.7): the list of active errors, the error register
// (1001h) kept consistent with it, the pre-defined error field (1003h, newest first), the EMCY
// COB-ID (1014h) and the inhibit time (1015h).
//
//   node::emcy_producer<8, 8, 4> emcy(5);
//   auto s = emcy.raise(0x2310, now);               // EMCY 0x085 [10 23 03 ...], 1001h = 0x03
//   s = emcy.clear(0x2310, now);                    // last error gone: EMCY [00 00 00 ...]
//   for (auto &f : emcy.poll(now).send) ...         // messages held back by the inhibit time
//
// Rules:
// * raise(code) adds an active error and sends its EMCY; raising a code that is already active
//   changes nothing (one message per occurrence, not per call).
// * The error register is bit 0 (generic) whenever an error is active, plus the class bit of
//   every active code (current 2xxxh, voltage 3xxxh, temperature 4xxxh, communication 81xxh /
//   82xxh), plus the bits the caller gave with raise() (device profile, manufacturer).
// * clear(code) removes it; when the last active error clears, "error reset / no error" is sent
//   (code 0000h, register 00h). With `report_each_reset`, every clear sends 0000h with the
//   register of the errors that remain (CiA 301 allows both).
// * 1003h: every raised error is pushed to the front of the history (sub 1 is the newest,
//   older ones move down; the oldest falls off when the history is full). Its value is the
//   error code in bits 0..15 and the first two manufacturer bytes in bits 16..31.
// * Inhibit time (1015h, 100 µs units, rounded up to the caller's milliseconds): messages wait
//   in a queue of Q; a full queue drops the newest message (counted by dropped()).
// * COB-ID (1014h): bit 31 set = no EMCY is sent (the errors are still kept); bits 11..30 are
//   refused, and the identifier may not change while the EMCY is valid (0x06090030).
// * enable(false) (NMT stopped): messages are not sent and not queued; dropped() counts them.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/node/cob_id_rules.hpp>
#include <fieldcodec/canopen/node/deadlines.hpp>
#include <fieldcodec/canopen/node/lists.hpp>
#include <fieldcodec/canopen/node/values.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fieldcodec::canopen::node {

/// The error register bit CiA 301 gives an error code's class (0 for none). Each class with a
/// bit spans whole ranges of the code's high digits (emcy::classify: current 2000h-2FFFh,
/// voltage 3000h-3FFFh, temperature 4000h-4FFFh, communication 8100h-82FFh), so the high
/// digits are enough (tests/node/emcy_producer_test.cpp checks every code against classify).
[[nodiscard]] constexpr std::uint8_t register_bit(std::uint16_t code) noexcept {
  switch (code >> 12U) {
  case 0x2: return emcy::reg::current;
  case 0x3: return emcy::reg::voltage;
  case 0x4: return emcy::reg::temperature;
  case 0x8: return (code >> 8U) == 0x81U || (code >> 8U) == 0x82U ? emcy::reg::communication : 0U;
  default: return 0U;
  }
}

/// One active error.
struct active_error {
  std::uint16_t code = 0;
  std::uint8_t register_bits = 0; ///< extra register bits given with raise()
  std::array<std::uint8_t, 5> manufacturer{};
};

template <std::size_t MaxActive = 8, std::size_t History = 8, std::size_t Queue = 4>
class emcy_producer {
  static_assert(Queue >= 1U, "the EMCY queue holds at least one message");

public:
  using step = canopen::step<std::uint8_t>; ///< state: the error register

  /// A producer for `node` (the default COB-ID 0x80 + node). A node-ID outside 1..127 leaves
  /// it without COB-ID until set_cob_id().
  constexpr explicit emcy_producer(std::uint8_t node) noexcept
      : cob_(cob_id::emcy(node).value_or(0)), valid_(is_node_id(node)) {}

  // ----- configuration ---------------------------------------------------------------------

  /// Would `value` be accepted for 1014h? (see the rules above)
  [[nodiscard]] constexpr abort_code check_cob_id(std::uint32_t value) const noexcept {
    if ((value & cob_bits::bit30) != 0U) return abort_code::invalid_value; // reserved
    return node::check_cob_id(value, cob_id_value(), true);
  }
  /// Set 1014h; returns check_cob_id()'s verdict (a refused value changes nothing).
  constexpr abort_code set_cob_id(std::uint32_t value) noexcept {
    if (const auto c = check_cob_id(value); c != abort_code::none) return c;
    cob_ = static_cast<std::uint16_t>(value & cob_bits::id);
    valid_ = (value & cob_bits::invalid) == 0U;
    return abort_code::none;
  }
  /// Take 1014h as stored (configuration at boot or after a reset: no rule about the value
  /// before; bits other than 31 and 0..10 are ignored).
  constexpr void load_cob_id(std::uint32_t value) noexcept {
    cob_ = static_cast<std::uint16_t>(value & cob_bits::id);
    valid_ = (value & cob_bits::invalid) == 0U;
  }
  [[nodiscard]] constexpr std::uint32_t cob_id_value() const noexcept {
    return std::uint32_t{cob_} | (valid_ ? 0U : cob_bits::invalid);
  }
  /// 1015h, in units of 100 µs.
  constexpr void set_inhibit(std::uint16_t t) noexcept { inhibit_ms_ = ms_from_100us(t); }
  /// Send (pre-operational, operational) or not (stopped, initialising).
  constexpr void enable(bool on) noexcept {
    enabled_ = on;
    if (!on) {
      dropped_ += queued_;
      queued_ = 0;
    }
  }

  // ----- errors ----------------------------------------------------------------------------

  /// An error occurred: add it, push it to the history and send its EMCY. Raising an active
  /// code again changes nothing. Errors: invalid_argument (code 0000h, which means "no error"),
  /// buffer_too_small (MaxActive errors are active already: nothing changes).
  [[nodiscard]] constexpr result<step>
  raise(std::uint16_t code, std::uint32_t now, std::uint8_t register_bits = 0,
        std::array<std::uint8_t, 5> manufacturer = {}) noexcept {
    if (const status st = raise_error(code, now, register_bits, manufacturer); !st) {
      return st.error();
    }
    return make(now);
  }
  /// An error is gone. Errors: unknown_object (the code is not active: nothing sent).
  [[nodiscard]] constexpr result<step> clear(std::uint16_t code, std::uint32_t now) noexcept {
    if (const status st = clear_error(code, now); !st) return st.error();
    return make(now);
  }
  /// raise() and clear() without the step (what node::device calls): the frames they send are
  /// sent() until the next call.
  constexpr status raise_error(std::uint16_t code, std::uint32_t now,
                               std::uint8_t register_bits = 0,
                               std::array<std::uint8_t, 5> manufacturer = {}) noexcept {
    out_.clear();
    if (code == emcy::code::error_reset) return errc::invalid_argument;
    if (find(code) < MaxActive) return {};
    if (count_ == MaxActive) return errc::buffer_too_small;
    active_[count_++] = {code, static_cast<std::uint8_t>(register_bits & ~emcy::reg::reserved),
                         manufacturer};
    push_history(std::uint32_t{code} | (std::uint32_t{manufacturer[0]} << 16U) |
                 (std::uint32_t{manufacturer[1]} << 24U));
    changed_ = true;
    enqueue({code, error_register(), manufacturer});
    send_queued(now);
    return {};
  }
  constexpr status clear_error(std::uint16_t code, std::uint32_t now) noexcept {
    out_.clear();
    const std::size_t i = find(code);
    if (i >= MaxActive) return errc::unknown_object;
    for (std::size_t k = i + 1U; k < count_; ++k) active_[k - 1U] = active_[k];
    --count_;
    changed_ = true;
    if (count_ == 0U || report_each_reset_) {
      enqueue({emcy::code::error_reset, error_register(), {}});
    }
    send_queued(now);
    return {};
  }
  /// The frames the last call sent.
  [[nodiscard]] constexpr std::span<const can_frame> sent() const noexcept { return out_.span(); }

  /// Every error gone at once (one "error reset" message when any was active).
  [[nodiscard]] constexpr step clear_all(std::uint32_t now) noexcept {
    out_.clear();
    if (count_ == 0U) return make(now);
    count_ = 0;
    changed_ = true;
    enqueue({emcy::code::error_reset, 0, {}});
    return flush(now);
  }

  /// Send what the inhibit time held back.
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept { return flush(now); }
  /// poll() without the step (what node::device calls): the frames it sends.
  [[nodiscard]] constexpr std::span<const can_frame> send_due(std::uint32_t now) noexcept {
    out_.clear();
    send_queued(now);
    return sent();
  }

  /// Forget everything (NMT reset): no active errors, empty history, nothing queued. Sends
  /// nothing.
  constexpr void reset() noexcept {
    count_ = 0;
    history_count_ = 0;
    queued_ = 0;
    inhibited_ = false;
    changed_ = true;
  }

  /// 1003h sub 0 written with 0: the history is emptied. (Other values are refused by the
  /// caller with 0x06090030, see node::device.)
  constexpr void clear_history() noexcept {
    history_count_ = 0;
    changed_ = true;
  }

  /// With `on`, every clear() sends "error reset" (0000h) with the remaining register.
  constexpr void report_each_reset(bool on) noexcept { report_each_reset_ = on; }

  // ----- its objects in a node (node::device) ------------------------------------------------

  /// Would `v` be accepted for `a`? 1003h sub 0 takes only 0 (it empties the history), 1014h
  /// as check_cob_id says (0x06090030); none for every other object.
  [[nodiscard]] constexpr abort_code check_write(od::address a, std::uint32_t v) const noexcept {
    if (a.index == 0x1003U) {
      return a.sub == 0U && v != 0U ? abort_code::invalid_value : abort_code::none;
    }
    if (a.index == 0x1014U) return check_cob_id(v);
    return abort_code::none;
  }
  /// `v` was stored at `a`: follow 1003h sub 0 (history emptied), 1014h and 1015h.
  constexpr void written(od::address a, std::uint32_t v, std::uint32_t) noexcept {
    if (a.index == 0x1003U && a.sub == 0U) clear_history();
    if (a.index == 0x1014U) (void)set_cob_id(v);
    if (a.index == 0x1015U) set_inhibit(static_cast<std::uint16_t>(v));
  }
  /// Start afresh (boot, NMT reset: no errors, empty history, nothing queued) with 1014h and
  /// 1015h from `store`, and note where 1003h is, for publish().
  template <class Store>
  constexpr status load(const Store &store, std::uint32_t) noexcept {
    reset();
    if (const auto v = read_u32(store, {0x1014, 0})) load_cob_id(*v);
    if (const auto v = read_u32(store, {0x1015, 0})) set_inhibit(static_cast<std::uint16_t>(*v));
    const auto entries = store.dictionary().object(0x1003);
    history_subs_ = 0;
    for (const auto &e : entries) {
      if (e.sub > history_subs_) history_subs_ = e.sub;
    }
    has_history_ = !entries.empty();
    return {};
  }
  /// After a change (take_changed()): write the error register to 1001h and the history to
  /// 1003h (sub 1.. newest first, the others 0, then sub 0 = the number of entries) with the
  /// store's set().
  template <class Store>
  constexpr void publish(Store &store) noexcept {
    if (!take_changed()) return;
    (void)store.set({0x1001, 0}, encode_le(error_register(), 1).span());
    if (!has_history_) return;
    const std::size_t n = history_count_ < history_subs_ ? history_count_ : history_subs_;
    for (std::size_t k = 1; k <= history_subs_; ++k) {
      const std::uint32_t v = k <= n ? history_[k - 1U] : 0U;
      (void)store.set({0x1003, static_cast<std::uint8_t>(k)}, encode_le(v, 4).span());
    }
    (void)store.set({0x1003, 0}, encode_le(static_cast<std::uint32_t>(n), 1).span());
  }

  // ----- state -----------------------------------------------------------------------------

  [[nodiscard]] constexpr std::uint8_t error_register() const noexcept {
    std::uint8_t r = 0;
    for (std::size_t i = 0; i < count_; ++i) {
      r = static_cast<std::uint8_t>(r | emcy::reg::generic | register_bit(active_[i].code) |
                                    active_[i].register_bits);
    }
    return r;
  }
  [[nodiscard]] constexpr std::span<const active_error> active() const noexcept {
    return std::span<const active_error>(active_.data(), count_);
  }
  [[nodiscard]] constexpr bool is_active(std::uint16_t code) const noexcept {
    return find(code) < MaxActive;
  }
  /// 1003h sub 1.. (newest first).
  [[nodiscard]] constexpr std::span<const std::uint32_t> history() const noexcept {
    return std::span<const std::uint32_t>(history_.data(), history_count_);
  }
  /// Messages not sent: NMT state, or a full queue.
  [[nodiscard]] constexpr std::size_t dropped() const noexcept { return dropped_; }
  /// True once after the register or the history changed (the caller mirrors them into
  /// 1001h / 1003h); reading it clears it.
  [[nodiscard]] constexpr bool take_changed() noexcept {
    const bool c = changed_;
    changed_ = false;
    return c;
  }
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline() const noexcept {
    if (queued_ == 0U || !inhibited_) return std::nullopt;
    return inhibit_until_;
  }
  static constexpr std::size_t history_capacity() noexcept { return History; }
  static constexpr std::size_t queue_capacity() noexcept { return Queue; }

private:
  [[nodiscard]] constexpr std::size_t find(std::uint16_t code) const noexcept {
    for (std::size_t i = 0; i < count_; ++i) {
      if (active_[i].code == code) return i;
    }
    return MaxActive;
  }
  constexpr void push_history(std::uint32_t v) noexcept {
    if constexpr (History > 0U) {
      const std::size_t n = history_count_ < History ? history_count_ + 1U : History;
      for (std::size_t k = n - 1U; k > 0U; --k) history_[k] = history_[k - 1U];
      history_[0] = v;
      history_count_ = n;
    }
  }
  constexpr void enqueue(const emcy::message &m) noexcept {
    if (!valid_) return; // COB-ID not valid: the EMCY object does not exist
    if (!enabled_ || queued_ == Queue) {
      ++dropped_;
      return;
    }
    queue_[queued_++] = m;
  }
  [[nodiscard]] constexpr step flush(std::uint32_t now) noexcept {
    out_.clear();
    send_queued(now);
    return make(now);
  }
  /// Send what the queue holds and the inhibit time allows (appended to out_).
  constexpr void send_queued(std::uint32_t now) noexcept {
    if (inhibited_ && reached(inhibit_until_, now)) inhibited_ = false;
    while (queued_ > 0U && !inhibited_) {
      can_frame f;
      f.id = cob_;
      f.dlc = 8;
      const emcy::message &m = queue_[0];
      f.data[0] = static_cast<std::uint8_t>(m.error_code & 0xFFU);
      f.data[1] = static_cast<std::uint8_t>(m.error_code >> 8U);
      f.data[2] = m.error_register;
      for (std::size_t i = 0; i < 5U; ++i) f.data[3U + i] = m.manufacturer[i];
      out_.push(f);
      for (std::size_t k = 1; k < queued_; ++k) queue_[k - 1U] = queue_[k];
      --queued_;
      if (inhibit_ms_ != 0U) {
        inhibited_ = true;
        inhibit_until_ = now + inhibit_ms_;
      }
    }
  }
  [[nodiscard]] constexpr step make([[maybe_unused]] std::uint32_t now) const noexcept {
    return {out_.view(), error_register(), deadline()};
  }

  std::array<active_error, MaxActive> active_{};
  std::size_t count_ = 0;
  std::array<std::uint32_t, (History == 0U ? 1U : History)> history_{};
  std::size_t history_count_ = 0;
  std::array<emcy::message, Queue> queue_{};
  std::size_t queued_ = 0;
  frame_list<Queue> out_{};
  std::uint32_t inhibit_ms_ = 0;
  std::uint32_t inhibit_until_ = 0;
  std::size_t dropped_ = 0;
  std::uint16_t cob_;
  bool valid_;
  bool inhibited_ = false;
  bool enabled_ = true;
  bool changed_ = false;
  bool report_each_reset_ = false;
  std::uint8_t history_subs_ = 0; ///< the highest sub-index of 1003h (load)
  bool has_history_ = false;      ///< the dictionary has 1003h (load)
};

} // namespace fieldcodec::canopen::node
