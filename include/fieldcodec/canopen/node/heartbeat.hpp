// fieldcodec — NMT error control on the node's side (CiA 301 7.2.8.3): the heartbeat producer
// (1017h), the heartbeat consumer (1016h, one monitor per entry) and life guarding (100Ch guard
// time × 100Dh life time factor). The guarding responses themselves come from
// nmt::guard_responder (canopen/nmt.hpp).
//
//   node::heartbeat_producer hb(5);
//   hb.configure(period_ms, now);                   // 1017h; 0 = off
//   for (auto &f : hb.poll(now, nmt_state).send) transmit(f);
//
//   node::heartbeat_consumer<4> hc;
//   hc.configure(0, 0x0003'01F4, now);              // 1016h sub 1: node 3, 500 ms
//   hc.on_frame(frame, now); hc.poll(now);          // then hc.events(): started, state_changed,
//                                                   //   boot_up, lost
//
//   node::life_guard lg;
//   lg.configure(guard_ms, factor);                 // 100Ch, 100Dh
//   lg.on_request(now);                             // every guarding request (RTR 0x700 + node)
//   lg.poll(now);                                   // state() == lost: the life guarding event
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/nmt.hpp>
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
#include <string_view>

namespace fieldcodec::canopen::node {

// ---------------------------------------------------------------------------------------------
// Producer

/// Sends the node's heartbeat (0x700 + node [state]) every period. The boot-up message counts
/// as the first heartbeat: configure() at boot schedules the next one a period later.
class heartbeat_producer {
public:
  using step = canopen::step<nmt::state>;

  constexpr explicit heartbeat_producer(std::uint8_t node) noexcept : node_(node) {}

  /// Producer heartbeat time (1017h, ms; 0 = off): the next heartbeat is due `period_ms` after
  /// `now`.
  constexpr void configure(std::uint16_t period_ms, std::uint32_t now) noexcept {
    period_ = period_ms;
    due_ = now + period_ms;
  }
  /// No heartbeat until the next configure() (while initialising).
  constexpr void stop() noexcept { period_ = 0; }

  // its object in a node (node::device): 1017h, any value
  [[nodiscard]] constexpr abort_code check_write(od::address, std::uint32_t) const noexcept {
    return abort_code::none;
  }
  constexpr void written(od::address a, std::uint32_t v, std::uint32_t now) noexcept {
    if (a.index == 0x1017U) configure(static_cast<std::uint16_t>(v), now);
  }
  /// 1017h from `store` (0 when absent); the next heartbeat a period after `now` (the boot-up
  /// message, sent at the same time, counts as the first).
  template <class Store>
  constexpr status load(const Store &store, std::uint32_t now) noexcept {
    configure(static_cast<std::uint16_t>(read_u32(store, {0x1017, 0}).value_or(0U)), now);
    return {};
  }

  /// The heartbeat when it is due, with the state `s`. A poll later than one period sends one
  /// heartbeat (not one per missed period) and schedules the next a period after `now`.
  [[nodiscard]] constexpr step poll(std::uint32_t now, nmt::state s) noexcept {
    frames out;
    if (const auto f = due(now, s)) out = frames(*f);
    return {out, s, deadline()};
  }
  /// poll() without the step (what node::device calls): the heartbeat when it is due.
  [[nodiscard]] constexpr std::optional<can_frame> due(std::uint32_t now, nmt::state s) noexcept {
    if (period_ == 0U || !reached(due_, now)) return std::nullopt;
    due_ += period_;
    if (reached(due_, now)) due_ = now + period_;
    if (const auto f = nmt::encode_heartbeat(node_, s)) return f.value();
    return std::nullopt;
  }

  [[nodiscard]] constexpr std::uint16_t period() const noexcept { return period_; }
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline() const noexcept {
    if (period_ == 0U) return std::nullopt;
    return due_;
  }

private:
  std::uint8_t node_;
  std::uint16_t period_ = 0;
  std::uint32_t due_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Consumer

/// One entry of 1016h: bits 0..15 heartbeat time (ms), bits 16..23 node-ID, bits 24..31
/// reserved (0). Node 0 or time 0 switches the entry off.
struct consumer_entry {
  std::uint8_t node = 0;
  std::uint16_t time_ms = 0;
  [[nodiscard]] constexpr bool active() const noexcept { return node != 0U && time_ms != 0U; }
  [[nodiscard]] constexpr std::uint32_t to_u32() const noexcept {
    return (std::uint32_t{node} << 16U) | time_ms;
  }
  friend constexpr bool operator==(const consumer_entry &, const consumer_entry &) = default;
};

/// Decode a 1016h value. Errors: invalid_argument (reserved bits 24..31 set, node-ID > 127).
[[nodiscard]] constexpr result<consumer_entry> decode_consumer_entry(std::uint32_t v) noexcept {
  if ((v & 0xFF00'0000U) != 0U) return errc::invalid_argument;
  const auto node = static_cast<std::uint8_t>((v >> 16U) & 0xFFU);
  if (node > max_node_id) return errc::invalid_argument;
  return consumer_entry{node, static_cast<std::uint16_t>(v & 0xFFFFU)};
}

/// The state of one monitor.
enum class monitor_state : std::uint8_t {
  off,     ///< entry not configured (node 0 or time 0)
  waiting, ///< configured, no heartbeat since configuration, boot-up or the consumer's start
  active,  ///< heartbeats arrive in time
  lost,    ///< the heartbeat time passed without a heartbeat (the heartbeat event)
};

struct heartbeat_event {
  enum class kind : std::uint8_t {
    started,       ///< first heartbeat of a waiting monitor (s = its state)
    state_changed, ///< an active node reports another state (s = the new state)
    boot_up,       ///< the node sent its boot-up message: it was reset (monitor waits again)
    lost,          ///< heartbeat event: no heartbeat within the consumer time
    resumed,       ///< a heartbeat arrived after a loss (s = its state)
  };
  kind what = kind::started;
  std::uint8_t monitor = 0; ///< entry (0 = 1016h sub 1)
  std::uint8_t node = 0;
  nmt::state s = nmt::state::boot_up;
  friend constexpr bool operator==(const heartbeat_event &, const heartbeat_event &) = default;
};

/// A short, stable text for a heartbeat consumer event (for logs; the texts do not change
/// between versions).
[[nodiscard]] constexpr std::string_view to_string(heartbeat_event::kind k) noexcept {
  switch (k) {
  case heartbeat_event::kind::started: return "heartbeat started";
  case heartbeat_event::kind::state_changed: return "NMT state changed";
  case heartbeat_event::kind::boot_up: return "boot-up";
  case heartbeat_event::kind::lost: return "heartbeat lost";
  case heartbeat_event::kind::resumed: return "heartbeat resumed";
  }
  return "?";
}

/// How many of the monitors are active and lost (the consumer's state in its steps).
struct consumer_summary {
  std::uint8_t active = 0;
  std::uint8_t lost = 0;
  friend constexpr bool operator==(const consumer_summary &, const consumer_summary &) = default;
};

/// N monitors (the entries 1016h sub 1..N). A monitor starts on the first heartbeat after its
/// configuration (CiA 301: monitoring starts with the first heartbeat received); a boot-up
/// message makes it wait again; it is lost when its time passes without a heartbeat.
template <std::size_t N>
class heartbeat_consumer {
public:
  using step = canopen::step<consumer_summary>;

  /// Would writing `value` to entry `i` be accepted? 0x06090030 for reserved bits or a node-ID
  /// above 127; 0x06040043 (CiA 301 7.5.2.17) when another active entry already monitors the
  /// same node; 0x06090011 for an entry beyond N.
  [[nodiscard]] constexpr abort_code check(std::size_t i, std::uint32_t value) const noexcept {
    if (i >= N) return abort_code::no_sub_index;
    auto e = decode_consumer_entry(value);
    if (!e) return abort_code::invalid_value;
    if (!e.value().active()) return abort_code::none;
    for (std::size_t k = 0; k < N; ++k) {
      if (k != i && m_[k].entry.active() && m_[k].entry.node == e.value().node) {
        return abort_code::parameter_incompatible;
      }
    }
    return abort_code::none;
  }

  /// Set entry `i` (1016h sub i + 1) to `value`; the monitor waits for a first heartbeat.
  /// Returns check()'s verdict; a refused value changes nothing.
  constexpr abort_code configure(std::size_t i, std::uint32_t value,
                                 [[maybe_unused]] std::uint32_t now) noexcept {
    if (const auto c = check(i, value); c != abort_code::none) return c;
    m_[i].entry = decode_consumer_entry(value).value();
    m_[i].state = m_[i].entry.active() ? monitor_state::waiting : monitor_state::off;
    return abort_code::none;
  }

  // ----- its object in a node (node::device): 1016h sub 1..N ---------------------------------

  /// Would `v` be accepted for `a`? 1016h sub 1..N as check() says; a sub-index beyond N takes
  /// only 0 (an entry the consumer cannot serve may stay off; anything else is 0x06040047).
  [[nodiscard]] constexpr abort_code check_write(od::address a, std::uint32_t v) const noexcept {
    if (a.index != 0x1016U || a.sub == 0U) return abort_code::none;
    if (a.sub > N) return v == 0U ? abort_code::none : abort_code::device_incompatible;
    return check(a.sub - 1U, v);
  }
  constexpr void written(od::address a, std::uint32_t v, std::uint32_t now) noexcept {
    if (a.index == 0x1016U && a.sub >= 1U && a.sub <= N) (void)configure(a.sub - 1U, v, now);
  }
  /// Every entry from 1016h in `store`, each monitor waiting for a first heartbeat. Errors:
  /// too_long (1016h has more entries than N: those are not served), invalid_argument (a stored
  /// entry check() refuses, e.g. a second entry for a node: left off).
  template <class Store>
  constexpr status load(const Store &store, std::uint32_t now) noexcept {
    status st{};
    for (std::size_t i = 0; i < N; ++i) (void)configure(i, 0, now);
    for (const auto &e : store.dictionary().object(0x1016)) {
      if (e.sub == 0U) continue;
      if (e.sub > N) {
        st = errc::too_long;
        continue;
      }
      const auto v = read_u32(store, {0x1016, e.sub}).value_or(0U);
      if (configure(e.sub - 1U, v, now) != abort_code::none && st) st = errc::invalid_argument;
    }
    restart();
    return st;
  }

  /// Monitoring on or off (the node's NMT state: on in pre-operational and operational). Off
  /// sets every configured monitor back to waiting.
  constexpr void enable(bool on) noexcept {
    if (on == enabled_) return;
    enabled_ = on;
    for (auto &m : m_) {
      if (m.entry.active()) m.state = monitor_state::waiting;
    }
  }

  /// A heartbeat or boot-up message (0x701..0x77F, DLC 1). Other frames, frames of nodes no
  /// monitor watches and guarding responses (bit 7 set) are ignored; error() says why a frame
  /// on 0x701..0x77F was not taken.
  [[nodiscard]] constexpr step on_frame(const can_frame &f, std::uint32_t now) noexcept {
    receive(f, now);
    return make(now);
  }
  /// on_frame() without the step (what node::device calls): its events() and error().
  constexpr void receive(const can_frame &f, std::uint32_t now) noexcept {
    events_.clear();
    if (f.rtr || f.id <= cob_id::nmt_error_base || f.id > cob_id::nmt_error_base + max_node_id) {
      return;
    }
    auto hb = nmt::decode_heartbeat(f);
    if (!hb) {
      error_ = hb.error();
      return;
    }
    error_ = errc{};
    if (!enabled_) return;
    for (std::size_t i = 0; i < N; ++i) {
      monitor &m = m_[i];
      if (m.state == monitor_state::off || m.entry.node != hb.value().node) continue;
      const nmt::state s = hb.value().s;
      const bool boot_up = hb.value().is_boot_up();
      // the event this heartbeat makes (one push for all of them)
      auto what = heartbeat_event::kind::boot_up;
      if (!boot_up) {
        switch (m.state) {
        case monitor_state::waiting: what = heartbeat_event::kind::started; break;
        case monitor_state::lost: what = heartbeat_event::kind::resumed; break;
        case monitor_state::active:
        case monitor_state::off: // not reached: skipped above
          what = heartbeat_event::kind::state_changed;
          break;
        }
      }
      if (what != heartbeat_event::kind::state_changed || s != m.last) {
        events_.push({what, static_cast<std::uint8_t>(i), m.entry.node, s});
      }
      m.last = s;
      if (boot_up) {
        m.state = monitor_state::waiting; // a boot-up: the node was reset, wait for it again
        continue;
      }
      m.state = monitor_state::active;
      m.due = now + m.entry.time_ms;
    }
  }

  /// Check the times: a monitor whose heartbeat is overdue becomes lost (one event).
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    check_times(now);
    return make(now);
  }
  /// poll() without the step (what node::device calls): its events().
  constexpr void check_times(std::uint32_t now) noexcept {
    events_.clear();
    for (std::size_t i = 0; i < N; ++i) {
      monitor &m = m_[i];
      if (m.state == monitor_state::active && reached(m.due, now)) {
        m.state = monitor_state::lost;
        events_.push(
            {heartbeat_event::kind::lost, static_cast<std::uint8_t>(i), m.entry.node, m.last});
      }
    }
  }

  /// Every monitor back to its configuration's start (off or waiting), e.g. after a reset.
  constexpr void restart() noexcept {
    for (auto &m : m_) m.state = m.entry.active() ? monitor_state::waiting : monitor_state::off;
  }

  /// What the last call found.
  [[nodiscard]] constexpr std::span<const heartbeat_event> events() const noexcept {
    return events_.span();
  }
  [[nodiscard]] constexpr monitor_state state(std::size_t i) const noexcept {
    return i < N ? m_[i].state : monitor_state::off;
  }
  [[nodiscard]] constexpr consumer_entry entry(std::size_t i) const noexcept {
    return i < N ? m_[i].entry : consumer_entry{};
  }
  /// The state the node reported last (boot_up before its first heartbeat).
  [[nodiscard]] constexpr nmt::state last_state(std::size_t i) const noexcept {
    return i < N ? m_[i].last : nmt::state::boot_up;
  }
  [[nodiscard]] constexpr bool any_lost() const noexcept { return lost_node() != 0U; }
  /// The node-ID of the first lost monitor (lowest entry), 0 when none is lost.
  [[nodiscard]] constexpr std::uint8_t lost_node() const noexcept {
    for (const auto &m : m_) {
      if (m.state == monitor_state::lost) return m.entry.node;
    }
    return 0;
  }
  [[nodiscard]] constexpr std::optional<errc> error() const noexcept {
    if (error_ == errc{}) return std::nullopt;
    return error_;
  }
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline(std::uint32_t now) const noexcept {
    std::optional<std::uint32_t> d;
    for (const auto &m : m_) {
      if (m.state == monitor_state::active) d = earliest(d, m.due, now);
    }
    return d;
  }
  static constexpr std::size_t size() noexcept { return N; }

private:
  struct monitor {
    consumer_entry entry{};
    monitor_state state = monitor_state::off;
    nmt::state last = nmt::state::boot_up;
    std::uint32_t due = 0;
  };

  [[nodiscard]] constexpr consumer_summary summary() const noexcept {
    consumer_summary s;
    for (const auto &m : m_) {
      if (m.state == monitor_state::active) ++s.active;
      if (m.state == monitor_state::lost) ++s.lost;
    }
    return s;
  }
  [[nodiscard]] constexpr step make(std::uint32_t now) const noexcept {
    return {{}, summary(), deadline(now)};
  }

  std::array<monitor, N> m_{};
  // one frame changes one monitor per node (active entries never share a node), a poll each
  event_list<heartbeat_event, (N == 0U ? 1U : N)> events_{};
  /// errc{} (no code of errc is 0) when there is none; a plain member for the reason given in
  /// nmt_slave.hpp (g++ 12 -O3 -Wmaybe-uninitialized on a copied std::optional).
  errc error_{};
  bool enabled_ = true;
};

// ---------------------------------------------------------------------------------------------
// Life guarding

enum class guard_state : std::uint8_t {
  off,     ///< guard time or life time factor 0
  waiting, ///< configured, no guarding request yet (life guarding starts with the first)
  active,  ///< requests arrive within the life time
  lost,    ///< the life time passed without a request (the life guarding event)
};

/// The node's side of node guarding: the life time is guard time (100Ch, ms) × life time
/// factor (100Dh); after the first guarding request, a life time without a request is the life
/// guarding event (CiA 301 7.2.8.3.2.1). The master's request is answered by
/// nmt::guard_responder.
class life_guard {
public:
  using step = canopen::step<guard_state>;

  constexpr void configure(std::uint16_t guard_ms, std::uint8_t factor) noexcept {
    guard_ms_ = guard_ms;
    factor_ = factor;
    life_ = std::uint32_t{guard_ms} * factor;
    state_ = life_ == 0U ? guard_state::off : guard_state::waiting;
  }

  // its objects in a node (node::device): 100Ch guard time, 100Dh life time factor
  [[nodiscard]] constexpr abort_code check_write(od::address, std::uint32_t) const noexcept {
    return abort_code::none;
  }
  constexpr void written(od::address a, std::uint32_t v, std::uint32_t) noexcept {
    if (a.index == 0x100CU) configure(static_cast<std::uint16_t>(v), factor_);
    if (a.index == 0x100DU) configure(guard_ms_, static_cast<std::uint8_t>(v));
  }
  /// 100Ch and 100Dh from `store` (0 when absent); waiting for a first request.
  template <class Store>
  constexpr status load(const Store &store, std::uint32_t) noexcept {
    configure(static_cast<std::uint16_t>(read_u32(store, {0x100C, 0}).value_or(0U)),
              static_cast<std::uint8_t>(read_u32(store, {0x100D, 0}).value_or(0U)));
    return {};
  }
  /// A guarding request arrived (the caller answers it with nmt::guard_responder).
  [[nodiscard]] constexpr step on_request(std::uint32_t now) noexcept {
    if (state_ != guard_state::off) {
      state_ = guard_state::active;
      due_ = now + life_;
    }
    return make();
  }
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    if (state_ == guard_state::active && reached(due_, now)) state_ = guard_state::lost;
    return make();
  }
  /// Back to waiting (after a reset of communication).
  constexpr void restart() noexcept {
    state_ = life_ == 0U ? guard_state::off : guard_state::waiting;
  }
  [[nodiscard]] constexpr guard_state state() const noexcept { return state_; }
  [[nodiscard]] constexpr std::uint32_t life_time_ms() const noexcept { return life_; }
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline() const noexcept {
    if (state_ != guard_state::active) return std::nullopt;
    return due_;
  }

private:
  [[nodiscard]] constexpr step make() const noexcept { return {{}, state_, deadline()}; }
  std::uint32_t life_ = 0;
  std::uint32_t due_ = 0;
  std::uint16_t guard_ms_ = 0;
  std::uint8_t factor_ = 0;
  guard_state state_ = guard_state::off;
};

} // namespace fieldcodec::canopen::node
