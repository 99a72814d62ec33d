// fieldcodec — the PDO engine (CiA 301 7.2.2, 7.5.2.35–7.5.2.38): TPDOs built from the store
// by transmission type, RPDOs written into the store, and the communication and mapping
// parameters (1400h–1BFFh) read from the store once and then kept up to date by the writes
// themselves (check_write / written, no rescanning).
//
//   node::pdo_engine<Store, 4, 4> pdo(store, dictionary);
//   pdo.reload();                                   // read 1400h–1BFFh (boot, NMT reset)
//   pdo.set_operational(true, now);                 // PDOs exist only in operational
//   pdo.on_sync(counter, now);                      // synchronous TPDOs, pending RPDOs
//   pdo.on_frame(frame, now);                       // RPDOs, RTR for TPDOs
//   pdo.poll(now);                                  // event timers, inhibit times
//   pdo.mark({0x6041, 0});                          // a mapped object changed: event-driven
//                                                   //   TPDOs that map it are due
//   // around every write of a PDO parameter (node::device does this):
//   if (auto c = pdo.check_write(a, value); c != abort_code::none) refuse(c);
//   else if (store.write(...) == none) pdo.written(a, value, now);
//
// TPDO transmission types: 0 at the next SYNC after an event (mark / request / entering
// operational), 1..240 every n-th SYNC (the first at the SYNC whose counter equals the SYNC
// start value, sub 6, when the SYNC carries a counter), 252 sampled at SYNC and sent on RTR,
// 253 sampled and sent on RTR, 254/255 on an event, at the latest when the event timer (sub 5,
// ms) runs out, never within the inhibit time (sub 3, 100 µs, rounded up to ms) of the last
// transmission. Event-driven TPDOs (0, 254, 255) are sent once on entering operational. An RTR
// on a TPDO whose COB-ID allows it (bit 30 clear) sends its current data (252: the data of the
// last SYNC).
//
// RPDOs: received only in operational; an RPDO shorter than its mapping is not processed
// (too_short, EMCY 8210h by the node); a longer one is processed with its first bytes
// (too_long, EMCY 8220h by the node unless report_long_rpdo(false)); transmission types
// 0..240 are applied at the next SYNC, and discarded when they arrive outside the synchronous
// window; 254/255 at once. Every mapped object is written with the store's write, so the
// application's write hook sees RPDO data as it sees SDO data; an object the store refuses
// keeps its old value (the others take theirs; `refused` in the event counts them). The event
// timer of an RPDO (sub 5) is deadline monitoring: after a first RPDO, no RPDO within it is
// the timeout event (EMCY 8250h by the node).
//
// Parameter writes (CiA 301): the COB-ID (sub 1) refuses bits 11..29 and a change of bits 0..30
// while the PDO is valid, and a valid restricted CAN-ID (0x06090030); transmission types
// 241..251 (and 252/253 for an RPDO) are refused (0x06090030); inhibit time and SYNC start
// value of a valid TPDO cannot change (0x06090030), a SYNC start above 240 is refused. The
// mapping changes only in the CiA 301 sequence: make the PDO invalid (sub 1 bit 31), set
// mapping sub 0 to 0, write the entries, set sub 0 to their number, make the PDO valid.
// Writing sub 0 or an entry while the PDO is valid, or an entry while sub 0 is not 0, is refused
// with 0x06040043; an entry naming no object 0x06020000; one that cannot be mapped in this
// direction (not mappable, access, bit length) 0x06040041; sub 0 above the entries the
// dictionary has (or the engine holds) or a mapping longer than 64 bits 0x06040042. Writing
// the value a parameter already has is always accepted (configuration tools write whole DCFs).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/node/cob_id_rules.hpp>
#include <fieldcodec/canopen/node/deadlines.hpp>
#include <fieldcodec/canopen/node/lists.hpp>
#include <fieldcodec/canopen/node/values.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/dictionary.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>

namespace fieldcodec::canopen::node {

/// The SDO abort code for a mapping problem (see the rules above).
[[nodiscard]] constexpr abort_code mapping_abort(pdo::mapping_problem p) noexcept {
  switch (p) {
  case pdo::mapping_problem::none: return abort_code::none;
  case pdo::mapping_problem::no_object: return abort_code::no_object;
  case pdo::mapping_problem::zero_length:
  case pdo::mapping_problem::not_mappable:
  case pdo::mapping_problem::no_access:
  case pdo::mapping_problem::length_mismatch:
  case pdo::mapping_problem::overlap: return abort_code::not_mappable; // POWERLINK only
  case pdo::mapping_problem::too_long:
  case pdo::mapping_problem::too_many_entries: return abort_code::pdo_too_long;
  }
  return abort_code::general_error;
}

/// The first index of each PDO parameter range.
namespace pdo_index {
inline constexpr std::uint16_t rpdo_comm = 0x1400U;
inline constexpr std::uint16_t rpdo_map = 0x1600U;
inline constexpr std::uint16_t tpdo_comm = 0x1800U;
inline constexpr std::uint16_t tpdo_map = 0x1A00U;
inline constexpr std::uint16_t count = 0x200U; ///< 512 PDOs per direction
} // namespace pdo_index

/// Something the engine did or found, for the application and the node's EMCY.
struct pdo_event {
  enum class kind : std::uint8_t {
    received,       ///< RPDO data written to the store (`refused` objects kept their value)
    too_short,      ///< RPDO shorter than its mapping: not processed
    too_long,       ///< RPDO longer than its mapping: processed with its first bytes
    outside_window, ///< synchronous RPDO after the synchronous window: discarded
    timeout,        ///< RPDO event timer ran out (deadline monitoring)
    not_sent,       ///< a TPDO could not be built (a mapped object could not be read)
  };
  kind what = kind::received;
  pdo::direction dir = pdo::direction::rpdo;
  std::uint16_t number = 0; ///< PDO number 1..512 (comm parameter 1400h/1800h + number − 1)
  std::uint8_t refused = 0; ///< received: objects the store refused
  friend constexpr bool operator==(const pdo_event &, const pdo_event &) = default;
};

/// A short, stable text for a PDO event (for logs; the texts do not change between versions).
[[nodiscard]] constexpr std::string_view to_string(pdo_event::kind k) noexcept {
  switch (k) {
  case pdo_event::kind::received: return "RPDO received";
  case pdo_event::kind::too_short: return "RPDO too short";
  case pdo_event::kind::too_long: return "RPDO too long";
  case pdo_event::kind::outside_window: return "RPDO outside the synchronous window";
  case pdo_event::kind::timeout: return "RPDO timeout";
  case pdo_event::kind::not_sent: return "TPDO not sent";
  }
  return "?";
}

/// The state in a pdo_engine's steps: whether PDOs are exchanged (NMT operational).
/// (0 and 1, the bool it replaced: the engine converts its flag without code.)
enum class pdo_state : std::uint8_t { not_operational = 0, operational = 1 };

[[nodiscard]] constexpr std::string_view to_string(pdo_state s) noexcept {
  return s == pdo_state::operational ? "PDOs exchanged" : "PDOs not exchanged";
}

/// A PDO's parameters as the engine holds them. (Every member is 0 until the engine loads them:
/// an engine's tables start as zeros, which cost a firmware image no initialising code.)
template <std::size_t MaxEntries>
struct pdo_config {
  std::uint16_t number = 0;      ///< 1..512
  std::uint32_t cob = 0;         ///< sub 1 as stored
  std::uint8_t type = 0;         ///< sub 2
  std::uint16_t inhibit = 0;     ///< sub 3, 100 µs
  std::uint16_t event_timer = 0; ///< sub 5, ms
  std::uint8_t sync_start = 0;   ///< sub 6
  std::uint8_t count = 0;        ///< mapping sub 0
  std::uint8_t map_subs = 0;     ///< highest mapping sub-index the dictionary has
  std::uint8_t bytes = 0;        ///< length of the mapped data
  /// Loaded and servable (false before the engine loaded it, or when the stored configuration
  /// is broken: the PDO is then never sent or received).
  bool usable = false;
  std::array<pdo::mapping_entry, MaxEntries> map{};

  [[nodiscard]] constexpr bool valid() const noexcept {
    return (cob & cob_bits::invalid) == 0U && usable;
  }
  [[nodiscard]] constexpr std::uint16_t id() const noexcept {
    return static_cast<std::uint16_t>(cob & cob_bits::id);
  }
  [[nodiscard]] constexpr bool rtr_allowed() const noexcept {
    return (cob & cob_bits::bit30) == 0U;
  }
  [[nodiscard]] constexpr bool event_driven() const noexcept { return type == 0U || type >= 254U; }
  [[nodiscard]] constexpr bool synchronous() const noexcept { return type <= 240U; }
  [[nodiscard]] constexpr std::span<const pdo::mapping_entry> entries() const noexcept {
    return std::span<const pdo::mapping_entry>(map.data(), count);
  }
};

template <canopen::object_store Store, std::size_t MaxRpdo, std::size_t MaxTpdo,
          std::size_t MaxEntries = 8>
class pdo_engine {
  static_assert(MaxEntries >= 1U && MaxEntries <= pdo::max_entries);

public:
  using config = pdo_config<MaxEntries>;
  /// State in the steps: whether PDOs are exchanged (NMT operational).
  using step = canopen::step<pdo_state>;
  /// Whether the engine reaches the mapped objects by position (the store models
  /// canopen::positioned_store): each mapping entry is looked up once, when the mapping is loaded,
  /// instead of at every SYNC and RPDO. Otherwise by address, through read / write.
  static constexpr bool by_position = canopen::positioned_store<Store>;
  /// Whether the engine compiles each mapping into copies (the store models canopen::plain_store):
  /// when a mapping is loaded, every entry whose object the store keeps plain (plain_at:
  /// readable for a TPDO, writable for an RPDO) on whole bytes becomes a copy between the
  /// store's bytes and the frame's — adjacent ones merged, then cut into copies of 8, 4, 2 and
  /// 1 bytes, kept in four lists so that each runs as a loop of constant-length copies; the
  /// others (1-bit BOOLEANs and entries after them off byte boundaries, limits or a scale to
  /// check, a write hook, byte strings, objects the store lacks, and every entry of an RPDO
  /// that maps one object twice) keep read_at / write_at, in mapping order, after the copies.
  static constexpr bool by_copy = canopen::plain_store<Store>;

  /// How a PDO's mapping was compiled (by_copy): `copied` entries in `copies` copies of 1, 2, 4
  /// or 8 bytes, the other `per_object` entries by read_at / write_at (dummies are neither).
  struct plan {
    std::uint8_t copied = 0;
    std::uint8_t copies = 0;
    std::uint8_t per_object = 0;
    friend constexpr bool operator==(const plan &, const plan &) = default;
  };

  /// An engine over `store` (borrowed; its reads give the TPDO data, its writes take the RPDO
  /// data and must reach the store the application reads) and `dict` (the dictionary the
  /// mappings are checked against).
  constexpr pdo_engine(Store &store, od::dictionary dict) noexcept : store_(&store), dict_(dict) {}

  /// Read every PDO's parameters from the store (at boot and after an NMT reset). PDOs whose
  /// stored configuration cannot be served (a mapping the dictionary does not allow, more
  /// entries than MaxEntries, a reserved transmission type) are marked unusable: never sent or
  /// received. Errors: too_long (the dictionary has more PDOs than MaxRpdo / MaxTpdo: the first
  /// ones are served), bad_length (a stored configuration was unusable).
  [[nodiscard]] constexpr status reload() noexcept {
    status st{};
    rpdo_count_ = 0;
    tpdo_count_ = 0;
    std::uint16_t last = 0;
    for (const od::entry &e : dict_) {
      if (e.sub != 1U || e.index == last) continue;
      const bool is_rx =
          e.index >= pdo_index::rpdo_comm && e.index < pdo_index::rpdo_comm + pdo_index::count;
      const bool is_tx =
          e.index >= pdo_index::tpdo_comm && e.index < pdo_index::tpdo_comm + pdo_index::count;
      if (!is_rx && !is_tx) continue;
      last = e.index;
      config *cfg = nullptr;
      positions *at = nullptr;
      if (is_rx) {
        if (rpdo_count_ == MaxRpdo) {
          st = errc::too_long;
          continue;
        }
        cfg = &rpdo_[rpdo_count_].c;
        at = &rpdo_[rpdo_count_++].pos;
      } else {
        if (tpdo_count_ == MaxTpdo) {
          st = errc::too_long;
          continue;
        }
        cfg = &tpdo_[tpdo_count_].c;
        at = &tpdo_[tpdo_count_++].pos;
      }
      const std::uint16_t base = is_rx ? pdo_index::rpdo_comm : pdo_index::tpdo_comm;
      if (!load(*cfg, *at, e.index, static_cast<std::uint16_t>(e.index - base + 1U),
                is_rx ? pdo::direction::rpdo : pdo::direction::tpdo) &&
          st) {
        st = errc::bad_length;
      }
    }
    for (std::size_t i = 0; i < tpdo_count_; ++i) tpdo_[i].restart(0, operational_);
    for (std::size_t i = 0; i < rpdo_count_; ++i) rpdo_[i].restart();
    reindex();
    return st;
  }

  /// PDOs on (operational) or off. Entering operational restarts every PDO: event-driven
  /// TPDOs are due at once, SYNC counting and event timers start from `now`.
  constexpr void set_operational(bool on, std::uint32_t now) noexcept {
    operational_ = on;
    for (std::size_t i = 0; i < tpdo_count_; ++i) tpdo_[i].restart(now, on);
    for (std::size_t i = 0; i < rpdo_count_; ++i) rpdo_[i].restart();
  }
  [[nodiscard]] constexpr bool operational() const noexcept { return operational_; }
  /// Process an RPDO longer than its mapping with a too_long event (true, the default) or
  /// silently.
  constexpr void report_long_rpdo(bool on) noexcept { report_long_ = on; }

  // ----- parameter writes ------------------------------------------------------------------

  /// Would writing `value` to `a` be accepted (CiA 301 rules above)? abort_code::none for
  /// objects outside 1400h–1BFFh, for PDOs the engine does not serve, and for values of a
  /// length the store will refuse itself.
  [[nodiscard]] constexpr abort_code
  check_write(od::address a, std::span<const std::uint8_t> value) const noexcept {
    const auto v = u32_of(value);
    return v ? check_write(a, *v) : abort_code::none;
  }
  /// The same for a value of 1..4 bytes as a number (node::device decodes it once for all its
  /// services).
  [[nodiscard]] constexpr abort_code check_write(od::address a, std::uint32_t v) const noexcept {
    const place where = locate(a.index);
    if (!where.found) return abort_code::none;
    return where.mapping ? check_mapping(slot(where), where.dir, a, v)
                         : check_comm(slot(where), where.dir, a.sub, v);
  }

  /// `value` was stored at `a`: follow it.
  constexpr void written(od::address a, std::span<const std::uint8_t> value,
                         std::uint32_t now) noexcept {
    if (const auto v = u32_of(value)) written(a, *v, now);
  }
  constexpr void written(od::address a, std::uint32_t v, std::uint32_t now) noexcept {
    const place where = locate(a.index);
    if (!where.found) return;
    config &c = slot(where);
    if (where.mapping) {
      if (a.sub == 0U) {
        c.count = static_cast<std::uint8_t>(v);
        (void)load_mapping(c, positions_of(where), where.dir);
        reindex();
      }
      return;
    }
    const bool was_valid = c.valid();
    if (!set_comm(c, a.sub, v)) return;
    // a new COB-ID, type or timer: the PDO starts afresh (a TPDO that became valid is due)
    if (where.dir == pdo::direction::tpdo) {
      if (a.sub != 1U || !was_valid) tpdo_[where.slot].restart(now, operational_);
    } else {
      rpdo_[where.slot].restart();
    }
    reindex();
  }
  /// reload(), as node::device starts its services (the engine reads through its own store).
  template <class Any>
  constexpr status load(const Any &, std::uint32_t) noexcept {
    return reload();
  }

  // ----- traffic ---------------------------------------------------------------------------

  /// A SYNC (with its counter when it carried one): apply the synchronous RPDOs received since
  /// the last SYNC, then send the synchronous TPDOs that are due.
  [[nodiscard]] constexpr step on_sync(std::optional<std::uint8_t> counter,
                                       std::uint32_t now) noexcept {
    begin();
    if (!operational_) return make(now);
    for (std::size_t i = 0; any_buffered_ && i < rpdo_count_; ++i) {
      rx_slot &r = rpdo_[i];
      if (!sync_rx_[i] || !r.buffered) continue;
      r.buffered = false;
      apply(r, std::span<const std::uint8_t>(r.data).first(r.dlc));
    }
    any_buffered_ = false;
    for (std::size_t i = 0; i < tpdo_count_; ++i) { // valid, types 0..240 and 252
      if (!sync_tx_[i]) continue;
      tx_slot &t = tpdo_[i];
      if (t.c.type == 0U) {
        if (t.pending) send(t, now);
      } else if (t.c.type <= 240U) {
        if (t.waiting_start && counter) {
          if (*counter != t.c.sync_start) continue;
          t.waiting_start = false;
          t.sync_count = 0;
          send(t, now);
          continue;
        }
        t.waiting_start = false;
        if (++t.sync_count >= t.c.type) {
          t.sync_count = 0;
          send(t, now);
        }
      } else {
        t.sampled = build(t, t.data);
      }
    }
    return make(now);
  }

  /// An RPDO, or an RTR for a TPDO. `sync_window_open`: false when a synchronous window is set
  /// and has passed since the last SYNC (synchronous RPDOs are then discarded).
  [[nodiscard]] constexpr step on_frame(const can_frame &f, std::uint32_t now,
                                        bool sync_window_open = true) noexcept {
    begin();
    if (!operational_ || f.id > max_can_id) return make(now);
    if (f.rtr) {
      for (std::size_t i = 0; i < tpdo_count_; ++i) {
        tx_slot &t = tpdo_[i];
        if (!t.c.valid() || t.c.id() != f.id || !t.c.rtr_allowed()) continue;
        if (t.c.type == 252U && t.sampled) {
          emit(t);
        } else {
          send(t, now);
        }
      }
      return make(now);
    }
    // the valid RPDOs with this COB-ID, in the order of their numbers
    for (std::size_t i = 0; i < rpdo_count_; ++i) {
      if (rx_id_[i] != f.id) continue;
      rx_slot &r = rpdo_[i];
      if (f.dlc < r.c.bytes) {
        r.short_error = true;
        rpdo_event(pdo_event::kind::too_short, r);
        continue;
      }
      r.short_error = false;
      r.long_error = report_long_ && f.dlc > r.c.bytes;
      if (r.long_error) {
        rpdo_event(pdo_event::kind::too_long, r);
      }
      if (r.c.event_timer != 0U) {
        r.monitored = true;
        r.timed_out = false;
        r.due = now + r.c.event_timer;
      }
      const auto data = f.payload().first(r.c.bytes);
      if (r.c.synchronous()) {
        if (!sync_window_open) {
          rpdo_event(pdo_event::kind::outside_window, r);
          continue;
        }
        r.buffered = true;
        any_buffered_ = true;
        r.dlc = static_cast<std::uint8_t>(data.size());
        for (std::size_t k = 0; k < data.size(); ++k) r.data[k] = data[k];
      } else {
        apply(r, data);
      }
    }
    return make(now);
  }

  /// Event timers and inhibit times of TPDOs, deadline monitoring of RPDOs.
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    begin();
    if (!operational_) return make(now);
    for (std::size_t i = 0; i < tpdo_count_; ++i) {
      tx_slot &t = tpdo_[i];
      if (!t.c.valid() || t.c.type < 254U) continue;
      if (t.c.event_timer != 0U && reached(t.event_due, now)) {
        t.pending = true;
        t.event_due = now + t.c.event_timer;
      }
      if (!t.pending) continue;
      if (t.inhibited && !reached(t.inhibit_until, now)) continue;
      send(t, now);
    }
    for (std::size_t i = 0; i < rpdo_count_; ++i) {
      rx_slot &r = rpdo_[i];
      if (!r.c.valid() || !r.monitored || r.timed_out || !reached(r.due, now)) continue;
      r.timed_out = true;
      rpdo_event(pdo_event::kind::timeout, r);
    }
    return make(now);
  }

  /// The object `a` changed: every event-driven TPDO (types 0, 254, 255) that maps it is due.
  constexpr void mark(od::address a) noexcept {
    for (std::size_t i = 0; i < tpdo_count_; ++i) {
      tx_slot &t = tpdo_[i];
      if (!t.c.event_driven()) continue;
      for (const auto &m : t.c.entries()) {
        if (m.index == a.index && m.sub == a.sub) {
          t.pending = true;
          break;
        }
      }
    }
  }
  /// The application's event for TPDO `number` (1..512). Errors: unknown_object (no such TPDO),
  /// bad_state (its transmission type is not event-driven: 1..240, 252, 253).
  [[nodiscard]] constexpr status request(std::uint16_t number) noexcept {
    for (std::size_t i = 0; i < tpdo_count_; ++i) {
      if (tpdo_[i].c.number != number) continue;
      if (!tpdo_[i].c.event_driven()) return errc::bad_state;
      tpdo_[i].pending = true;
      return {};
    }
    return errc::unknown_object;
  }

  // ----- state -----------------------------------------------------------------------------

  [[nodiscard]] constexpr std::span<const pdo_event> events() const noexcept {
    return events_.span();
  }
  [[nodiscard]] constexpr std::size_t rpdo_count() const noexcept { return rpdo_count_; }
  [[nodiscard]] constexpr std::size_t tpdo_count() const noexcept { return tpdo_count_; }
  [[nodiscard]] constexpr const config &rpdo(std::size_t i) const noexcept { return rpdo_[i].c; }
  [[nodiscard]] constexpr const config &tpdo(std::size_t i) const noexcept { return tpdo_[i].c; }
  /// How RPDO / TPDO `i`'s current mapping is served (by_copy engines).
  [[nodiscard]] constexpr plan compiled_plan(pdo::direction d,
                                             std::size_t i) const noexcept requires by_copy {
    const resolved &p = d == pdo::direction::rpdo ? rpdo_[i].pos : tpdo_[i].pos;
    plan n;
    n.per_object = p.per_objects;
    n.copies = p.first[4];
    const config &c = d == pdo::direction::rpdo ? rpdo_[i].c : tpdo_[i].c;
    std::uint8_t dummies = 0;
    for (const auto &m : c.entries()) {
      if (m.is_dummy()) ++dummies;
    }
    n.copied = static_cast<std::uint8_t>(c.count - dummies - n.per_object);
    return n;
  }
  /// An RPDO's last frame was too short / too long; an RPDO's deadline passed.
  [[nodiscard]] constexpr bool any_too_short() const noexcept { return rpdo_errors().too_short; }
  [[nodiscard]] constexpr bool any_too_long() const noexcept { return rpdo_errors().too_long; }
  [[nodiscard]] constexpr bool any_timed_out() const noexcept { return rpdo_errors().timed_out; }
  /// The three at once (one pass over the RPDOs).
  struct rpdo_error_flags {
    bool too_short = false;
    bool too_long = false;
    bool timed_out = false;
  };
  [[nodiscard]] constexpr rpdo_error_flags rpdo_errors() const noexcept {
    rpdo_error_flags e;
    for (std::size_t i = 0; i < rpdo_count_; ++i) {
      const rx_slot &r = rpdo_[i];
      if (!r.c.valid()) continue;
      e.too_short = e.too_short || r.short_error;
      e.too_long = e.too_long || r.long_error;
      e.timed_out = e.timed_out || r.timed_out;
    }
    return e;
  }
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline(std::uint32_t now) const noexcept {
    if (!operational_) return std::nullopt;
    // earliest() over every time below, as a running minimum of distances from now (a time
    // already passed is at distance 0; the first of equal ones stays)
    std::optional<std::uint32_t> d;
    std::uint32_t nearest = 0;
    const auto consider = [&](std::uint32_t at) {
      const std::uint32_t distance = reached(at, now) ? 0U : at - now;
      if (!d || distance < nearest) {
        d = at;
        nearest = distance;
      }
    };
    for (std::size_t i = 0; i < tpdo_count_; ++i) {
      const tx_slot &t = tpdo_[i];
      if (!t.c.valid() || t.c.type < 254U) continue;
      if (t.pending) consider(t.inhibited ? t.inhibit_until : now);
      if (t.c.event_timer != 0U) consider(t.event_due);
    }
    for (std::size_t i = 0; i < rpdo_count_; ++i) {
      const rx_slot &r = rpdo_[i];
      if (r.c.valid() && r.monitored && !r.timed_out) consider(r.due);
    }
    return d;
  }

  /// Whether what the engine derives from the parameters to save work on every SYNC and frame
  /// (see reindex()) matches the parameters now: always true — the tests check it after every
  /// step and parameter write.
  [[nodiscard]] constexpr bool derived_current() const noexcept {
    bool any_timed = false;
    for (std::size_t i = 0; i < tpdo_count_; ++i) {
      if (sync_tx_[i] != sync_acts(tpdo_[i].c)) return false;
      any_timed = any_timed || timed(tpdo_[i].c, pdo::direction::tpdo);
    }
    for (std::size_t i = 0; i < rpdo_count_; ++i) {
      if (sync_rx_[i] != sync_buffers(rpdo_[i].c) || rx_id_[i] != match_id(rpdo_[i].c)) {
        return false;
      }
      any_timed = any_timed || timed(rpdo_[i].c, pdo::direction::rpdo);
    }
    return any_timed == timed_;
  }

private:
  /// Mapping entry `entry`, at bit `bit` of the frame, read or written by position.
  struct object_step {
    std::uint8_t bit = 0;
    std::uint8_t entry = 0;
  };
  struct no_steps {};
  /// The bytes of plain_storage() a compiled mapping reaches: offsets of 16 bits.
  static constexpr std::uint32_t copy_reach = 0x10000U;
  /// A compiled mapping (by_copy; compile() sets it with the positions, so it describes the
  /// mapping in force): copy i moves 2^c bytes between the store's plain_storage() at
  /// storage[i] and frame byte frame[i], for i in first[c]..first[c + 1] (c = 0..3: 1, 2, 4, 8
  /// bytes; a frame has 8 bytes, so there are at most 8 copies); then the per-object entries.
  /// Storage offsets have 16 bits: a value whose bytes do not all lie in the first 64 kB of
  /// the store's plain_storage() is read or written by position instead (copy_reach).
  struct compiled {
    std::array<std::uint16_t, 8> storage{};
    std::array<std::uint8_t, 8> frame{};
    std::array<std::uint8_t, 5> first{};
    std::uint8_t per_objects = 0;
    std::array<object_step, MaxEntries> object{};
  };
  /// Where each mapped object is in the store (positioned stores; empty otherwise): entry k of
  /// the mapping is at at[k], canopen::no_position for a dummy or an object the store lacks; and,
  /// by_copy, the compiled mapping. Set by load_mapping, the only place that changes a mapping,
  /// so it never goes stale.
  struct resolved : std::conditional_t<by_copy, compiled, no_steps> {
    std::array<std::size_t, MaxEntries> at{};
  };
  struct no_positions {};
  using positions = std::conditional_t<by_position, resolved, no_positions>;

  struct tx_slot {
    config c{};
    [[no_unique_address]] positions pos{};
    std::array<std::uint8_t, 8> data{};
    std::uint32_t inhibit_until = 0;
    std::uint32_t event_due = 0;
    std::uint8_t sync_count = 0;
    bool pending = false;
    bool inhibited = false;
    bool waiting_start = false;
    bool sampled = false;

    constexpr void restart(std::uint32_t now, bool operational) noexcept {
      pending = operational && c.event_driven();
      inhibited = false;
      sync_count = 0;
      waiting_start = c.sync_start != 0U;
      sampled = false;
      event_due = now + c.event_timer;
    }
  };
  struct rx_slot {
    config c{};
    [[no_unique_address]] positions pos{};
    std::array<std::uint8_t, 8> data{};
    std::uint32_t due = 0;
    std::uint8_t dlc = 0;
    bool buffered = false;
    bool monitored = false;
    bool timed_out = false;
    bool short_error = false;
    bool long_error = false;

    constexpr void restart() noexcept {
      buffered = false;
      monitored = false;
      timed_out = false;
      short_error = false;
      long_error = false;
    }
  };
  /// Where a parameter index belongs: which PDO (slot), which direction, comm or mapping.
  struct place {
    bool found = false;
    pdo::direction dir = pdo::direction::rpdo;
    bool mapping = false;
    std::size_t slot = 0;
  };

  // ----- where a parameter lives -----------------------------------------------------------

  [[nodiscard]] constexpr place locate(std::uint16_t index) const noexcept {
    place l;
    // 1400h–1BFFh: bit 10 of the offset from 1400h is the direction (1800h: TPDOs), bit 9 the
    // mapping (1600h, 1A00h), bits 0..8 the PDO number − 1
    if (index < pdo_index::rpdo_comm || index >= pdo_index::tpdo_map + pdo_index::count) return l;
    const auto offset = static_cast<std::uint16_t>(index - pdo_index::rpdo_comm);
    const bool is_rx = offset < 2U * pdo_index::count;
    l.dir = is_rx ? pdo::direction::rpdo : pdo::direction::tpdo;
    l.mapping = (offset & pdo_index::count) != 0U;
    const auto number = static_cast<std::uint16_t>((offset & (pdo_index::count - 1U)) + 1U);
    const std::size_t n = is_rx ? rpdo_count_ : tpdo_count_;
    for (std::size_t i = 0; i < n; ++i) {
      if ((is_rx ? rpdo_[i].c.number : tpdo_[i].c.number) == number) {
        l.found = true;
        l.slot = i;
        return l;
      }
    }
    return l;
  }
  [[nodiscard]] constexpr config &slot(place p) noexcept {
    return p.dir == pdo::direction::rpdo ? rpdo_[p.slot].c : tpdo_[p.slot].c;
  }
  [[nodiscard]] constexpr const config &slot(place p) const noexcept {
    return p.dir == pdo::direction::rpdo ? rpdo_[p.slot].c : tpdo_[p.slot].c;
  }
  [[nodiscard]] constexpr positions &positions_of(place p) noexcept {
    return p.dir == pdo::direction::rpdo ? rpdo_[p.slot].pos : tpdo_[p.slot].pos;
  }

  // ----- parameter checks ------------------------------------------------------------------

  [[nodiscard]] static constexpr abort_code check_comm(const config &c, pdo::direction d,
                                                       std::uint8_t sub, std::uint32_t v) noexcept {
    const bool tpdo = d == pdo::direction::tpdo;
    switch (sub) {
    case 1: return check_cob_id(v, c.cob, true);
    case 2:
      if (v >= 241U && v <= 251U) return abort_code::invalid_value;
      if (!tpdo && (v == 252U || v == 253U)) return abort_code::invalid_value;
      return abort_code::none;
    case 3:
      return tpdo && c.valid() && v != c.inhibit ? abort_code::invalid_value : abort_code::none;
    case 6:
      if (v > 240U) return abort_code::invalid_value;
      return tpdo && c.valid() && v != c.sync_start ? abort_code::invalid_value : abort_code::none;
    default: return abort_code::none;
    }
  }

  [[nodiscard]] constexpr abort_code check_mapping(const config &c, pdo::direction d, od::address a,
                                                   std::uint32_t v) const noexcept {
    if (a.sub == 0U) {
      if (v == c.count) return abort_code::none;
      if ((c.cob & cob_bits::invalid) == 0U) return abort_code::parameter_incompatible;
      if (v == 0U) return abort_code::none;
      if (v > MaxEntries || v > c.map_subs) return abort_code::pdo_too_long;
      std::array<pdo::mapping_entry, MaxEntries> e{};
      for (std::size_t k = 0; k < v; ++k) {
        const auto m = read_u32(*store_, {a.index, static_cast<std::uint8_t>(k + 1U)});
        if (!m) return abort_code::no_sub_index;
        e[k] = pdo::mapping_entry::from_u32(*m);
      }
      const auto r = pdo::check_mapping(dict_, d, std::span<const pdo::mapping_entry>(e.data(), v),
                                        pdo::can_max_bits);
      return mapping_abort(r.problem);
    }
    if (const auto cur = read_u32(*store_, a); cur && *cur == v) return abort_code::none;
    if ((c.cob & cob_bits::invalid) == 0U || c.count != 0U) {
      return abort_code::parameter_incompatible;
    }
    if (v == 0U) return abort_code::none;
    const auto m = pdo::mapping_entry::from_u32(v);
    if (const auto p = pdo::check_entry(dict_, d, m); p != pdo::mapping_problem::none) {
      return mapping_abort(p);
    }
    return m.bits > pdo::can_max_bits ? abort_code::pdo_too_long : abort_code::none;
  }

  // ----- loading ---------------------------------------------------------------------------

  /// Read one PDO's parameters; false when they cannot be served (the PDO is then unusable).
  [[nodiscard]] constexpr bool load(config &c, positions &at, std::uint16_t comm,
                                    std::uint16_t number, pdo::direction d) noexcept {
    c = config{};
    at = positions{}; // a PDO found unusable below keeps no steps of an earlier mapping
    c.number = number;
    c.cob = cob_bits::invalid; // what a PDO without the sub-object has
    c.type = 255U;
    for (std::uint8_t sub = 1; sub <= 6U; ++sub) {
      if (const auto v = read_u32(*store_, {comm, sub})) (void)set_comm(c, sub, *v);
    }
    const auto map = static_cast<std::uint16_t>(comm + pdo_index::count);
    for (const od::entry &e : dict_.object(map)) {
      if (e.sub > c.map_subs) c.map_subs = e.sub;
    }
    c.count = static_cast<std::uint8_t>(read_u32(*store_, {map, 0}).value_or(0U));
    c.usable = check_comm(config{}, d, 2, c.type) == abort_code::none &&
               (c.cob & 0x3FFF'F800U) == 0U && load_mapping(c, at, d);
    return c.usable;
  }

  /// Communication parameter `sub` (1, 2, 3, 5, 6) of `c` set to `v`; false for another sub.
  static constexpr bool set_comm(config &c, std::uint8_t sub, std::uint32_t v) noexcept {
    switch (sub) {
    case 1: c.cob = v; return true;
    case 2: c.type = static_cast<std::uint8_t>(v); return true;
    case 3: c.inhibit = static_cast<std::uint16_t>(v); return true;
    case 5: c.event_timer = static_cast<std::uint16_t>(v); return true;
    case 6: c.sync_start = static_cast<std::uint8_t>(v); return true;
    default: return false;
    }
  }

  /// Read mapping entries 1..count from the store and check them; false (and count 0) when
  /// they cannot be served. A positioned store: look each mapped object up (at[k]).
  constexpr bool load_mapping(config &c, positions &at, pdo::direction d) noexcept {
    const std::uint32_t first =
        d == pdo::direction::rpdo ? pdo_index::rpdo_map : pdo_index::tpdo_map;
    const auto map = static_cast<std::uint16_t>(first + c.number - 1U);
    c.bytes = 0;
    if constexpr (by_copy) {
      at.first = {}; // the steps always describe c.map[0..count): none until it is checked
      at.per_objects = 0;
    }
    if (c.count > MaxEntries || c.count > c.map_subs) {
      c.count = 0;
      return false;
    }
    for (std::size_t k = 0; k < c.count; ++k) {
      const auto v = read_u32(*store_, {map, static_cast<std::uint8_t>(k + 1U)});
      if (!v) {
        c.count = 0;
        return false;
      }
      c.map[k] = pdo::mapping_entry::from_u32(*v);
    }
    const auto r = pdo::check_mapping(dict_, d, c.entries(), pdo::can_max_bits);
    if (!r.ok()) {
      c.count = 0;
      return false;
    }
    c.bytes = static_cast<std::uint8_t>((r.total_bits + 7U) / 8U);
    if constexpr (by_position) {
      for (std::size_t k = 0; k < c.count; ++k) {
        const pdo::mapping_entry &m = c.map[k];
        at.at[k] = m.is_dummy() ? canopen::no_position : store_->position({m.index, m.sub});
      }
      if constexpr (by_copy) compile(c, at, d);
    } else {
      (void)at;
    }
    return true;
  }

  /// Compile a checked mapping (by_copy): the entries the store keeps plain for this direction
  /// on whole bytes become runs of bytes — an entry joins the run before it when both the
  /// store's bytes and the frame's are adjacent —, each run cut into copies of 8, 4, 2, 1 bytes
  /// (largest first) and filed by length; the others are per-object steps, in mapping order.
  /// Dummies get nothing (a TPDO's data starts zeroed, an RPDO skips them). An RPDO that maps
  /// one object twice is written entry by entry, so that the later entry wins as it does by
  /// position and by address.
  constexpr void compile(const config &c, resolved &at, pdo::direction d) noexcept {
    const bool rx = d == pdo::direction::rpdo;
    bool twice = false;
    for (std::size_t k = 0; rx && k < c.count; ++k) {
      for (std::size_t j = 0; j < k; ++j) {
        if (at.at[k] != canopen::no_position && at.at[k] == at.at[j]) twice = true;
      }
    }
    struct run {
      std::uint32_t storage = 0;
      std::size_t frame = 0;
      std::size_t size = 0;
    };
    std::array<run, MaxEntries> runs{};
    std::size_t n_runs = 0;
    at.per_objects = 0;
    const std::size_t room = store_->plain_storage().size();
    std::size_t bit = 0;
    for (std::size_t k = 0; k < c.count; ++k) {
      const pdo::mapping_entry &m = c.map[k];
      if (!m.is_dummy()) {
        canopen::plain_slot s{};
        if (!twice && at.at[k] != canopen::no_position && (bit % 8U) == 0U && (m.bits % 8U) == 0U) {
          s = store_->plain_at(at.at[k]);
        }
        // (a slot that would reach past the storage is a broken promise: not copied; one past
        // the 16-bit offsets of a compiled mapping goes by position)
        if (s.size == 0U || s.size * 8U != m.bits || !(rx ? s.writable : s.readable) ||
            s.offset > room || room - s.offset < s.size || s.offset > copy_reach - s.size) {
          at.object[at.per_objects++] = {static_cast<std::uint8_t>(bit),
                                         static_cast<std::uint8_t>(k)};
        } else if (n_runs != 0U && runs[n_runs - 1U].storage + runs[n_runs - 1U].size == s.offset &&
                   runs[n_runs - 1U].frame + runs[n_runs - 1U].size == bit / 8U) {
          runs[n_runs - 1U].size += s.size;
        } else {
          runs[n_runs++] = {s.offset, bit / 8U, s.size};
        }
      }
      bit += m.bits;
    }
    std::size_t n = 0;
    for (std::size_t cls = 0; cls < 4U; ++cls) {
      at.first[cls] = static_cast<std::uint8_t>(n);
      const std::size_t len = std::size_t{1} << cls;
      for (std::size_t r = 0; r < n_runs; ++r) {
        for (std::size_t o = 0; o < runs[r].size;) {
          const std::size_t left = runs[r].size - o;
          const std::size_t chunk = left >= 8U ? 8U : left >= 4U ? 4U : left >= 2U ? 2U : 1U;
          if (chunk == len) {
            at.storage[n] = static_cast<std::uint16_t>(runs[r].storage + o);
            at.frame[n++] = static_cast<std::uint8_t>(runs[r].frame + o);
          }
          o += chunk;
        }
      }
    }
    at.first[4] = static_cast<std::uint8_t>(n);
  }

  // ----- data ------------------------------------------------------------------------------

  /// The 8 data bytes of a frame.
  using frame_bytes = std::array<std::uint8_t, 8>;
  /// Sample a TPDO's mapped objects into `data` (t.data; zero past the mapping's bits). False
  /// when an object could not be read.
  [[nodiscard]] constexpr bool build(tx_slot &t, frame_bytes &data) noexcept {
    if constexpr (by_copy) {
      return build_by_copy(t, data);
    } else if constexpr (by_position) {
      return build_at(t, data);
    } else {
      return build_by_address(t, data);
    }
  }
  /// build() by position: value by value, each on whole bytes straight into the frame's bytes
  /// (read_entry).
  [[nodiscard]] constexpr bool build_at(tx_slot &t, frame_bytes &data) noexcept {
    data = {};
    std::size_t offset = 0;
    for (std::size_t k = 0; k < t.c.count; ++k) {
      if (!t.c.map[k].is_dummy() && !read_entry(t, k, offset, data)) return false;
      offset += t.c.map[k].bits;
    }
    return true;
  }
  /// Read mapping entry k (not a dummy) of a TPDO by position into `data` from bit `offset`.
  [[nodiscard, gnu::noinline]] constexpr bool
  read_entry(const tx_slot &t, std::size_t k, std::size_t offset, frame_bytes &data) noexcept {
    const pdo::mapping_entry &m = t.c.map[k];
    const std::size_t at = t.pos.at[k];
    if (at == canopen::no_position) return false;
    // on whole bytes straight into the frame, else through v (one read_at: it is inlined)
    const bool whole = ((offset | m.bits) % 8U) == 0U;
    std::array<std::uint8_t, 8> v{};
    const auto out = whole ? std::span<std::uint8_t>(data).subspan(offset / 8U, m.bits / 8U)
                           : std::span<std::uint8_t>(v);
    std::size_t total = 0;
    if (store_->read_at(at, 0, out, total) != abort_code::none) return false;
    return whole || pdo::copy_bits(v, 0, data, offset, m.bits);
  }
  /// build() by the compiled mapping: the copies from the store's bytes, then the other
  /// entries by position (the first that cannot be read stops the TPDO, as above; the frame's
  /// bytes of different entries never overlap, so the order does not show).
  /// (The copies go to a local frame first: stores into the engine's frames could, for all the
  /// compiler knows, change the compiled mapping, whose bounds it would then reload after every
  /// copy.)
  [[nodiscard]] constexpr bool build_by_copy(tx_slot &t, frame_bytes &data) noexcept {
    const resolved &p = t.pos;
    const std::uint8_t *from = store_->plain_storage().data();
    frame_bytes local{};
    std::uint8_t *to = local.data();
    copies<1, true>(p, 0, to, from);
    copies<2, true>(p, 1, to, from);
    copies<4, true>(p, 2, to, from);
    copies<8, true>(p, 3, to, from);
    data = local;
    for (std::size_t i = 0; i < p.per_objects; ++i) {
      if (!read_entry(t, p.object[i].entry, p.object[i].bit, data)) return false;
    }
    return true;
  }
  /// The copies of N bytes (list `cls` of a compiled mapping): into the frame's bytes `to`
  /// from the storage `from` (ToFrame), or into the storage `to` from the frame's bytes `from`.
  template <std::size_t N, bool ToFrame>
  static constexpr void copies(const resolved &p, std::size_t cls, std::uint8_t *to,
                               const std::uint8_t *from) noexcept {
    const std::size_t end = p.first[cls + 1U]; // (once: a copy into the store could alias p)
    for (std::size_t i = p.first[cls]; i < end; ++i) {
      if constexpr (ToFrame) {
        fieldcodec::copy_bytes<N>(from + p.storage[i], to + p.frame[i]);
      } else {
        fieldcodec::copy_bytes<N>(from + p.frame[i], to + p.storage[i]);
      }
    }
  }
  /// build() through the store's read by address (a store without positions).
  [[nodiscard]] constexpr bool build_by_address(const tx_slot &t, frame_bytes &data) noexcept {
    data = {};
    std::size_t offset = 0;
    for (const auto &m : t.c.entries()) {
      if (!m.is_dummy()) {
        std::array<std::uint8_t, 8> v{};
        std::size_t total = 0;
        if (store_->read({m.index, m.sub}, 0, v, total) != abort_code::none) return false;
        const std::size_t n = (m.bits + 7U) / 8U;
        std::uint64_t raw = load_unsigned(v, n, byte_order::little).value_or(0);
        if (m.bits < 64U) raw &= (std::uint64_t{1} << m.bits) - 1U;
        if (!pdo::pack(data, offset, m.bits, raw)) return false;
      }
      offset += m.bits;
    }
    return true;
  }
  /// Send t.data (built by send(), or sampled at the last SYNC for a type-252 TPDO).
  constexpr void emit(const tx_slot &t) noexcept {
    can_frame f;
    f.id = t.c.id();
    f.dlc = t.c.bytes;
    f.data = t.data; // zero past c.bytes: build writes only the mapping's bits
    out_.push(f);
  }
  /// Sample and send a TPDO now; restarts its inhibit time and event timer.
  constexpr void send(tx_slot &t, std::uint32_t now) noexcept {
    t.pending = false;
    if (!build(t, t.data)) {
      events_.push({pdo_event::kind::not_sent, pdo::direction::tpdo, t.c.number, 0});
      return;
    }
    emit(t);
    if (t.c.type >= 254U) {
      t.inhibited = t.c.inhibit != 0U;
      t.inhibit_until = now + ms_from_100us(t.c.inhibit);
      t.event_due = now + t.c.event_timer;
    }
  }

  /// Write an RPDO's data (at least c.bytes long) into the mapped objects.
  constexpr void apply(const rx_slot &r, std::span<const std::uint8_t> data) noexcept {
    if constexpr (by_copy) {
      apply_by_copy(r, data);
    } else if constexpr (by_position) {
      apply_at(r, data);
    } else {
      apply_by_address(r.c, data);
    }
  }
  /// apply() by position: an object on whole bytes is written straight from the frame's bytes.
  /// Its length, (bits + 7) / 8, is what apply_by_address takes from the dictionary: a mapping
  /// that passed pdo::check_mapping has bits = 8 × width for fixed-size types, 1 or 8 for a
  /// BOOLEAN (width 1) and whole bytes for byte strings.
  constexpr void apply_at(const rx_slot &r, std::span<const std::uint8_t> data) noexcept {
    std::size_t offset = 0;
    std::uint8_t refused = 0;
    for (std::size_t k = 0; k < r.c.count; ++k) {
      if (!r.c.map[k].is_dummy() && write_entry(r, k, offset, data) != abort_code::none) {
        ++refused;
      }
      offset += r.c.map[k].bits;
    }
    rpdo_event(pdo_event::kind::received, r, refused);
  }
  /// Write mapping entry k (not a dummy) of an RPDO by position from bit `offset` of `data`.
  [[nodiscard, gnu::noinline]] constexpr abort_code
  write_entry(const rx_slot &r, std::size_t k, std::size_t offset,
              std::span<const std::uint8_t> data) noexcept {
    const pdo::mapping_entry &m = r.c.map[k];
    const std::size_t at = r.pos.at[k];
    // the store has no such object: refused, as its write would refuse it
    if (at == canopen::no_position) return abort_code::general_error;
    const std::size_t n = (m.bits + 7U) / 8U;
    // on whole bytes straight from the frame, else through v (one write_at: it is inlined)
    std::array<std::uint8_t, 8> v{};
    std::span<const std::uint8_t> value = std::span<const std::uint8_t>(v).first(n);
    if (((offset | m.bits) % 8U) == 0U && offset / 8U + n <= data.size()) {
      value = data.subspan(offset / 8U, n);
    } else if (!pdo::copy_bits(data, offset, v, 0, m.bits)) {
      return abort_code::general_error;
    }
    return store_->write_at(at, 0, value, true);
  }
  /// apply() by the compiled mapping: the copies into the store's bytes (objects that take
  /// every value with no effect but being stored: nothing to refuse), then the other entries by
  /// position, in mapping order. (The copies go first; no entry of another object sees the
  /// difference, and an RPDO that maps an object twice has no copies.)
  constexpr void apply_by_copy(const rx_slot &r, std::span<const std::uint8_t> data) noexcept {
    const resolved &p = r.pos;
    std::uint8_t *to = store_->plain_storage().data();
    // data holds at least c.bytes bytes (see apply), within which every copy lies
    const std::uint8_t *from = data.data();
    copies<1, false>(p, 0, to, from);
    copies<2, false>(p, 1, to, from);
    copies<4, false>(p, 2, to, from);
    copies<8, false>(p, 3, to, from);
    std::uint8_t refused = 0;
    for (std::size_t i = 0; i < p.per_objects; ++i) {
      if (write_entry(r, p.object[i].entry, p.object[i].bit, data) != abort_code::none) {
        ++refused;
      }
    }
    rpdo_event(pdo_event::kind::received, r, refused);
  }
  /// apply() through the store's write by address (a store without positions).
  constexpr void apply_by_address(const config &c, std::span<const std::uint8_t> data) noexcept {
    std::size_t offset = 0;
    std::uint8_t refused = 0;
    for (const auto &m : c.entries()) {
      if (!m.is_dummy()) {
        const od::entry *e = dict_.find(m.index, m.sub);
        std::array<std::uint8_t, 8> v{};
        std::size_t n = 0;
        if (e != nullptr) {
          n = od::is_byte_string(e->type) ? m.bits / 8U : e->width();
          const auto raw = pdo::unpack(data, offset, m.bits);
          if (n > v.size() || !raw ||
              !store_unsigned(std::span<std::uint8_t>(v).first(n), n, raw.value(),
                              byte_order::little)) {
            n = 0;
          }
        }
        if (n == 0U || store_->write({m.index, m.sub}, 0, std::span<const std::uint8_t>(v).first(n),
                                     true) != abort_code::none) {
          ++refused;
        }
      }
      offset += m.bits;
    }
    events_.push({pdo_event::kind::received, pdo::direction::rpdo, c.number, refused});
  }

  /// An event of RPDO `r` (out of line: the engine reports from six places).
  [[gnu::noinline]] constexpr void rpdo_event(pdo_event::kind k, const rx_slot &r,
                                              std::uint8_t refused = 0) noexcept {
    events_.push({k, pdo::direction::rpdo, r.c.number, refused});
  }
  constexpr void begin() noexcept {
    out_.clear();
    events_.clear();
  }
  /// The step: the frames to send, the state, and deadline(now) — which is nullopt without a
  /// scan when no PDO has timing (timed_).
  [[nodiscard]] constexpr step make(std::uint32_t now) const noexcept {
    return {out_.view(), static_cast<pdo_state>(operational_),
            timed_ ? deadline(now) : std::nullopt};
  }
  /// Rebuild what the engine derives from the PDOs' parameters, for the paths every SYNC and
  /// every frame take: per PDO one byte or two, tested there instead of the parameters
  /// themselves — sync_tx_ (a valid TPDO a SYNC acts on: types 0..240 and 252), sync_rx_ (a
  /// valid synchronous RPDO, buffered until a SYNC), rx_id_ (an RPDO's COB-ID when it is valid,
  /// no_rx_id otherwise) — and timed_ (whether any PDO can have a deadline: a valid TPDO of type
  /// 254/255, a valid RPDO with an event timer; deadline monitoring starts only with one, and
  /// every change of it restarts the RPDO). The one place that sets them, from the rules below
  /// (derived_current() checks them against the same rules); called wherever a parameter
  /// changes: at the end of reload() and of every written() that stored a PDO parameter.
  constexpr void reindex() noexcept {
    bool any_timed = false;
    for (std::size_t i = 0; i < tpdo_count_; ++i) {
      const config &c = tpdo_[i].c;
      sync_tx_[i] = sync_acts(c);
      any_timed = any_timed || timed(c, pdo::direction::tpdo);
    }
    for (std::size_t i = 0; i < rpdo_count_; ++i) {
      const config &c = rpdo_[i].c;
      sync_rx_[i] = sync_buffers(c);
      rx_id_[i] = match_id(c);
      any_timed = any_timed || timed(c, pdo::direction::rpdo);
    }
    timed_ = any_timed;
  }
  /// A SYNC acts on this TPDO: valid, type 0..240 (sent) or 252 (sampled).
  [[nodiscard]] static constexpr bool sync_acts(const config &c) noexcept {
    return c.valid() && (c.type <= 240U || c.type == 252U);
  }
  /// This RPDO's data waits for a SYNC: valid, type 0..240.
  [[nodiscard]] static constexpr bool sync_buffers(const config &c) noexcept {
    return c.valid() && c.synchronous();
  }
  /// The identifier a frame must carry to be this RPDO (no_rx_id: none).
  [[nodiscard]] static constexpr std::uint16_t match_id(const config &c) noexcept {
    return c.valid() ? c.id() : no_rx_id;
  }
  /// This PDO can have a deadline.
  [[nodiscard]] static constexpr bool timed(const config &c, pdo::direction d) noexcept {
    return c.valid() && (d == pdo::direction::tpdo ? c.type >= 254U : c.event_timer != 0U);
  }

  static constexpr std::size_t out_capacity = MaxTpdo == 0U ? 1U : MaxTpdo;
  static constexpr std::size_t event_capacity = 2U * MaxRpdo + MaxTpdo + 1U;

  Store *store_;
  od::dictionary dict_;
  std::array<rx_slot, (MaxRpdo == 0U ? 1U : MaxRpdo)> rpdo_{};
  std::array<tx_slot, (MaxTpdo == 0U ? 1U : MaxTpdo)> tpdo_{};
  std::size_t rpdo_count_ = 0;
  std::size_t tpdo_count_ = 0;
  /// rx_id_ of an RPDO that is not valid: no frame has this identifier.
  static constexpr std::uint16_t no_rx_id = 0xFFFFU;
  // derived from the parameters by reindex() (see there), per PDO
  std::array<bool, (MaxTpdo == 0U ? 1U : MaxTpdo)> sync_tx_{};
  std::array<bool, (MaxRpdo == 0U ? 1U : MaxRpdo)> sync_rx_{};
  std::array<std::uint16_t, (MaxRpdo == 0U ? 1U : MaxRpdo)> rx_id_{};
  frame_list<out_capacity> out_{};
  event_list<pdo_event, event_capacity> events_{};
  bool operational_ = false;
  bool report_long_ = true;
  bool timed_ = false;        ///< see reindex()
  bool any_buffered_ = false; ///< an RPDO may be buffered for the next SYNC (set with buffered)
};

} // namespace fieldcodec::canopen::node
