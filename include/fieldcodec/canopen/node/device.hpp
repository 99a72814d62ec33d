// fieldcodec — node::device, a CANopen node (CiA 301 slave) assembled from the node services
// over a dictionary and a store: NMT slave, heartbeat producer and consumer, node guarding and
// life guarding, EMCY producer, SYNC consumer and (capacity::sync_producer) producer, TIME
// producer and consumer (capacity::time), store/restore parameters (capacity::storage, 1010h,
// 1011h), PDO engine, SDO channels and the error behaviour (1029h), with frames routed
// by COB-ID. One plain object the caller owns: no heap, no threads, no I/O, no clock.
//
//   std::array<std::uint8_t, layout.storage_size()> storage{};
//   canopen::dictionary_store<> store{dict, layout, storage};
//   (void)store.init_defaults(5);
//   node::device<canopen::dictionary_store<>, node::capacity_for(dict)> dev(store, 5);
//   send(dev.start(now).value());                   // boot-up, pre-operational
//   on every received frame: send(dev.on_frame(frame, now));
//   or several (a receive FIFO): auto r = dev.on_frames(rx, now); send(r.last);
//                                rx = rx.subspan(r.consumed);  // until rx is empty
//   at the deadline (or every tick): send(dev.poll(now));
//   send(dev.set({0x6041, 0}, bytes, now).value()); // the application's own values (and
//                                                   //   the event-driven TPDOs they make due)
//   for (const node::event &e : dev.events()) ...   // what the last call did
//   send(dev.produce_time({ms, days}, now).value()); // TIME (1012h bit 30), the application's
//                                                   //   clock: the node has none
//
// Every call returns canopen::step<nmt::state>: the frames to send (valid until the next call),
// the NMT state, and when to poll at the latest. What happened is in events().
//
// The node keeps the store and its services consistent through the store's writes: SDO
// downloads and RPDOs reach the store through the device (device::access). Each service owns
// its communication objects (the SYNC consumer 1005h, 1007h, 1019h; life guarding 100Ch,
// 100Dh; the EMCY producer 1001h, 1003h, 1014h, 1015h; the heartbeat producer 1017h and
// consumer 1016h; TIME 1012h; the PDO engine 1400h–1BFFh; the SDO channels 1200h–12FFh; the
// error behaviour 1029h) and has the
// three members the device calls for every service in turn (each_service): check_write (the
// CiA 301 rules of its objects), written (follow a stored value) and load (read them all at
// start and after a reset). A write is checked by the owning service, stored by the store
// (its checks and the application's write hook), followed by the owning service, and the
// event-driven TPDOs that map the object are marked. Nothing is rescanned. The application
// writes its own values with set() (same path, no access check, no hook).
//
// The node owns 1001h (error register) and 1003h (pre-defined error field) and writes them
// whenever its EMCY producer changes, and it raises and clears these EMCY codes itself:
// 8130h (a heartbeat consumer or life guarding lost its node; the first manufacturer-specific
// byte, EMCY byte 3, holds the lost node's ID, 0 for life guarding), 8210h / 8220h (an RPDO too
// short / too long), 8240h (a SYNC of unexpected length), 8250h (an RPDO timeout); each stays
// active while its condition lasts and clears when it is over.
//
// Error behaviour (1029h): a communication error — a heartbeat consumer losing its node, life
// guarding losing its master, or a bus-off the driver reports through report_error(1, now) —
// first sends its EMCY, then enters the state 1029h sub 1 asks for: 0 (the default, also
// without 1029h) pre-operational when operational, 1 no change, 2 stopped. The application
// reports its own error classes (1029h sub 2..) the same way.
//
// NMT: frames are taken per CiA 301 Table 48 (node::allowed): in stopped only NMT and node
// guarding are answered and the heartbeat is produced; SDO transfers of the servers end
// silently on stop. Reset communication restores the writable entries of 1000h–1FFFh to their
// defaults (canopen::dictionary_store::restore_defaults), forgets errors and history, reloads every
// service and sends the boot-up message; reset node also restores 2000h–FFFFh first. Both are
// reported as events so that the application re-applies what it keeps elsewhere.
//
// The application's hooks on single objects (capacity::hooks, add_hook before start;
// node/object_hooks.hpp): a read hook computes a value at each SDO upload and TPDO sampling, a
// write hook has the last word on an SDO or RPDO write after every check above, and a DOMAIN
// can be streamed to and from the application in parts (the store never holds it).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/node/deadlines.hpp>
#include <fieldcodec/canopen/node/emcy_producer.hpp>
#include <fieldcodec/canopen/node/error_behaviour.hpp>
#include <fieldcodec/canopen/node/heartbeat.hpp>
#include <fieldcodec/canopen/node/lists.hpp>
#include <fieldcodec/canopen/node/lss_slave.hpp>
#include <fieldcodec/canopen/node/nmt_slave.hpp>
#include <fieldcodec/canopen/node/object_hooks.hpp>
#include <fieldcodec/canopen/node/parameter_storage.hpp>
#include <fieldcodec/canopen/node/pdo_engine.hpp>
#include <fieldcodec/canopen/node/sdo_channels.hpp>
#include <fieldcodec/canopen/node/store.hpp>
#include <fieldcodec/canopen/node/sync_consumer.hpp>
#include <fieldcodec/canopen/node/sync_producer.hpp>
#include <fieldcodec/canopen/node/time_service.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/crc.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/dictionary.hpp>

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>

namespace fieldcodec::canopen::node {

/// What a device can hold (compile time: every table is a fixed array).
struct capacity {
  std::size_t rpdos = 4;
  std::size_t tpdos = 4;
  std::size_t mapped = 8;              ///< mapping entries per PDO (1..64)
  std::size_t heartbeat_consumers = 4; ///< entries of 1016h
  std::size_t sdo_servers = 1;         ///< the default server plus 1201h..
  std::size_t sdo_clients = 0;         ///< 1280h..
  /// Bytes per SDO server (see sdo::server). The default holds a whole sub-block of 127
  /// segments, what masters ask for in a block upload (python canopen, the common C stacks);
  /// a smaller buffer serves block uploads of at most sdo_buffer / 7 segments per sub-block
  /// and aborts larger ones with 0x05040002. At least 8.
  std::size_t sdo_buffer = 889;
  /// The SDO servers compute the CRC of block transfers by a 256-entry table
  /// (crc::ccitt16_with_table: 512 bytes of flash, about half the instructions a byte) instead
  /// of without one (the default). The SDO clients compute it without a table either way.
  bool sdo_crc_table = false;
  /// The PDO engine copies the mapped objects that the store keeps plain as runs of bytes
  /// (pdo_engine::by_copy, the fastest way; the default) instead of reading and writing them
  /// one by one (false: about 0.8 kB less flash on Cortex-M, each mapped object then costs a
  /// store call per SYNC or RPDO). Same frames and stored values either way.
  bool pdo_copies = true;
  std::size_t active_errors = 8;
  std::size_t error_history = 8; ///< entries of 1003h
  std::size_t emcy_queue = 4;    ///< EMCY messages held back by the inhibit time
  std::size_t error_classes = 1; ///< sub-indices of 1029h (error behaviour) served
  /// The node can be the SYNC producer (1005h bit 30, 1006h; node/sync_producer.hpp). Without
  /// it 1005h refuses bit 30 and no producer code is in the image; capacity_for sets it when
  /// the dictionary has 1006h.
  bool sync_producer = false;
  /// The node serves 1012h (COB-ID TIME): it consumes TIME (bit 31; a `time` event) and
  /// produces it (bit 30; produce_time) (node/time_service.hpp). Without it no TIME code is in
  /// the image and frames on 100h go where they went before (a PDO, if one uses it);
  /// capacity_for sets it when the dictionary has 1012h.
  bool time = false;
  /// The node is an LSS slave (CiA 305, node/lss_slave.hpp): it answers an LSS master on
  /// 7E5h/7E4h, can start without node-ID (lss::unconfigured) and takes a new node-ID at its
  /// next NMT reset. Without it no LSS code is in the image. capacity_for keeps it from `base`
  /// (a dictionary does not say it).
  bool lss = false;
  /// The node serves the commands of 1010h (store parameters) and 1011h (restore default
  /// parameters) with the application's storage_hook (set_storage; node/parameter_storage.hpp).
  /// Without it 1010h/1011h are plain objects of the store; capacity_for sets it when the
  /// dictionary has 1010h or 1011h.
  bool storage = false;
  /// Hooks of the application on single objects or ranges (add_hook; node/object_hooks.hpp):
  /// values computed when read, writes the application checks, streamed DOMAINs. 0: no hook
  /// table and no hook code in the image. capacity_for keeps it from `base`.
  std::size_t hooks = 0;
};

/// The capacity `dict` needs: its PDOs, mapping entries, 1016h and 1003h entries and SDO
/// channels; the rest from `base`. consteval-friendly: for a generated dictionary,
///   node::device<Store, node::capacity_for(gen::dictionary)>.
[[nodiscard]] constexpr capacity capacity_for(od::dictionary dict, capacity base = {}) noexcept {
  capacity c = base;
  c.rpdos = 0;
  c.tpdos = 0;
  c.mapped = 1;
  c.heartbeat_consumers = 0;
  c.error_history = 0;
  c.sdo_servers = 1;
  c.sdo_clients = 0;
  c.error_classes = 1;
  for (const od::entry &e : dict) {
    const std::uint16_t i = e.index;
    if (e.sub == 1U) {
      if (i >= pdo_index::rpdo_comm && i < pdo_index::rpdo_map) ++c.rpdos;
      if (i >= pdo_index::tpdo_comm && i < pdo_index::tpdo_map) ++c.tpdos;
      if (i > sdo_index::server && i < sdo_index::client) ++c.sdo_servers;
      if (i >= sdo_index::client && i < sdo_index::client + sdo_index::count) ++c.sdo_clients;
    }
    const bool mapping = (i >= pdo_index::rpdo_map && i < pdo_index::tpdo_comm) ||
                         (i >= pdo_index::tpdo_map && i < pdo_index::tpdo_map + pdo_index::count);
    if (mapping && e.sub > c.mapped) c.mapped = e.sub;
    if (i == 0x1016U && e.sub > c.heartbeat_consumers) c.heartbeat_consumers = e.sub;
    if (i == 0x1003U && e.sub > c.error_history) c.error_history = e.sub;
    if (i == 0x1029U && e.sub > c.error_classes) c.error_classes = e.sub;
    if (i == 0x1006U) c.sync_producer = true;
    if (i == time_service::index) c.time = true;
    if (i == parameter_storage::store_index || i == parameter_storage::restore_index) {
      c.storage = true;
    }
  }
  if (c.mapped > pdo::max_entries) c.mapped = pdo::max_entries;
  return c;
}

/// Choices made at run time.
struct options {
  std::uint32_t sdo_timeout_ms = 1000; ///< SDO servers and clients
  sdo::server_options sdo{};           ///< block transfer, CRC
  bool self_start = false;             ///< enter operational after boot-up by itself
  bool report_long_rpdo = true;        ///< EMCY 8220h for an RPDO longer than its mapping
  bool report_each_reset = false;      ///< EMCY 0000h at every cleared error, not only the last
};

/// What a call into the device did, besides the frames it returns.
struct event {
  enum class kind : std::uint8_t {
    nmt_state,           ///< the node's NMT state changed (`state`)
    reset_application,   ///< NMT reset node carried out (application area restored)
    reset_communication, ///< NMT reset communication carried out
    heartbeat,           ///< a heartbeat consumer event (`heartbeat`)
    life_guard_lost,     ///< no guarding request within the life time
    life_guard_resumed,  ///< guarding requests again after a loss
    pdo,                 ///< a PDO engine event (`pdo`)
    sync,                ///< a SYNC was taken (`counter`)
    time,                ///< a TIME was taken (the time: device::time().received())
    lss,                 ///< an LSS event: its details in lss().last_event() (capacity::lss)
  };
  kind what = kind::nmt_state;
  nmt::state state = nmt::state::boot_up;
  heartbeat_event heartbeat{};
  pdo_event pdo{};
  std::optional<std::uint8_t> counter{};
  friend constexpr bool operator==(const event &, const event &) = default;
};

/// A short, stable text for a device event (for logs; the texts do not change between
/// versions). The event's details have their own: to_string(e.state), to_string(e.heartbeat.what),
/// to_string(e.pdo.what).
[[nodiscard]] constexpr std::string_view to_string(event::kind k) noexcept {
  switch (k) {
  case event::kind::nmt_state: return "NMT state changed";
  case event::kind::reset_application: return "reset application";
  case event::kind::reset_communication: return "reset communication";
  case event::kind::heartbeat: return "heartbeat consumer event";
  case event::kind::life_guard_lost: return "life guarding lost";
  case event::kind::life_guard_resumed: return "life guarding resumed";
  case event::kind::pdo: return "PDO event";
  case event::kind::sync: return "SYNC received";
  case event::kind::time: return "TIME received";
  case event::kind::lss: return "LSS event";
  }
  return "?";
}

/// The node-managed EMCY codes (see above).
namespace managed_code {
inline constexpr std::uint16_t guarding = 0x8130U;    ///< life guard or heartbeat error
inline constexpr std::uint16_t rpdo_short = 0x8210U;  ///< PDO not processed: length error
inline constexpr std::uint16_t rpdo_long = 0x8220U;   ///< PDO length exceeded
inline constexpr std::uint16_t sync_length = 0x8240U; ///< unexpected SYNC data length
inline constexpr std::uint16_t rpdo_timeout = 0x8250U;
} // namespace managed_code

template <node_store Store, capacity C = capacity{}>
class device {
  static_assert(C.sdo_servers >= 1U, "a node has its default SDO server");
  static_assert(C.mapped >= 1U && C.mapped <= pdo::max_entries);
  static_assert(
      !C.lss ||
          requires(Store & s, std::uint8_t n) {
            { s.set_node(n) } -> std::same_as<status>;
          },
      "an LSS slave's store resolves node-ID-relative defaults for a new node-ID: set_node()");
  static_assert(
      C.hooks == 0U ||
          requires(Store & s, od::address a, std::span<const std::uint8_t> v) {
            { s.check(a, v) } -> std::same_as<abort_code>;
          },
      "a device with hooks asks the store's checks before a write hook: check()");

public:
  using step = canopen::step<nmt::state>;
  /// What on_frames did with a run of received frames.
  struct batch_step {
    std::size_t consumed = 0; ///< frames taken from the front of the span (≥ 1 unless empty)
    step last{};              ///< the step to act on: on_frame's step for the last frame taken
  };

  /// The view of the store that the SDO servers and the PDO engine use: reads go to the store,
  /// writes through the device's rules (see above). The device's own; not for the
  /// application.
  class access {
  public:
    constexpr explicit access(device &d) noexcept : d_(&d) {}
    [[nodiscard]] constexpr abort_code read(od::address a, std::size_t offset,
                                            std::span<std::uint8_t> out,
                                            std::size_t &total) const noexcept {
      if constexpr (C.hooks > 0U) {
        if (const object_hook *h = d_->hooks_.find(a)) {
          if (h->streams()) return d_->stream_read(*h, a, offset, out, total);
          if (offset == 0U) {
            if (const abort_code r = d_->refresh(*h, a); r != abort_code::none) return r;
          }
        }
      }
      const abort_code c = d_->store_->read(a, offset, out, total);
      if constexpr (C.storage) {
        // 1010h/1011h sub 1..: what the node can do, not the stored value
        if (c == abort_code::none && parameter_storage::owns(a) && offset == 0U && total == 4U &&
            out.size() >= 4U) {
          const le_value v = encode_le(d_->storage_.capability(a), 4);
          for (std::size_t i = 0; i < 4U; ++i) out[i] = v.bytes[i];
        }
      }
      return c;
    }
    [[nodiscard]] constexpr od::dictionary dictionary() const noexcept {
      return d_->store_->dictionary();
    }
    [[nodiscard]] constexpr abort_code begin_write(od::address a,
                                                   std::optional<std::uint32_t> size) noexcept {
      if constexpr (C.hooks > 0U) {
        if (const object_hook *h = d_->hooks_.find(a); h != nullptr && h->streams()) {
          return d_->stream_begin(*h, a, size);
        }
      }
      return d_->store_->begin_write(a, size);
    }
    /// A transfer of `a` ended unfinished (sdo::server): a streamed object's `ended`.
    constexpr void abandoned(od::address a, abort_code why) noexcept requires(C.hooks > 0U) {
      const object_hook *h = d_->hooks_.find(a);
      if (h != nullptr && h->streams() && h->ended != nullptr) h->ended(h->context, a, why);
    }
    [[nodiscard]] constexpr abort_code write(od::address a, std::size_t offset,
                                             std::span<const std::uint8_t> part,
                                             bool last) noexcept {
      return d_->write_object(a, offset, part, last);
    }
    // by position, when the store has positions (the PDO engine then looks each mapped object
    // up once): the same reads and the same writes through the device's rules
    [[nodiscard]] constexpr std::size_t
    position(od::address a) const noexcept requires canopen::positioned_store<Store> {
      return d_->store_->position(a);
    }
    [[nodiscard]] constexpr od::address
    address_at(std::size_t at) const noexcept requires canopen::positioned_store<Store> {
      return d_->store_->address_at(at);
    }
    [[nodiscard]] constexpr abort_code
    read_at(std::size_t at, std::size_t offset, std::span<std::uint8_t> out,
            std::size_t &total) const noexcept requires canopen::positioned_store<Store> {
      if constexpr (C.hooks > 0U) {
        const od::address a = d_->store_->address_at(at);
        if (const object_hook *h = d_->hooks_.find(a)) {
          if (h->streams()) return d_->stream_read(*h, a, offset, out, total);
          if (offset == 0U) {
            if (const abort_code r = d_->refresh(*h, a); r != abort_code::none) return r;
          }
        }
      }
      return d_->store_->read_at(at, offset, out, total);
    }
    [[nodiscard]] constexpr abort_code
    write_at(std::size_t at, std::size_t offset, std::span<const std::uint8_t> part,
             bool last) noexcept requires canopen::positioned_store<Store> {
      return d_->write_object(d_->store_->address_at(at), offset, part, last, at);
    }
    // plain values (the PDO engine then copies a TPDO's plain objects from the store's bytes):
    // reads as the store shows them; never writable, since every write of the device, an
    // RPDO's too, goes through its rules (check, follow: the services, mark), which a copy
    // would skip
    [[nodiscard]] constexpr std::span<std::uint8_t> plain_storage() noexcept
        requires(canopen::plain_store<Store> &&C.pdo_copies) {
      return d_->store_->plain_storage();
    }
    [[nodiscard]] constexpr canopen::plain_slot plain_at(std::size_t at) const noexcept
        requires(canopen::plain_store<Store> &&C.pdo_copies) {
      canopen::plain_slot p = d_->store_->plain_at(at);
      p.writable = false;
      if constexpr (C.hooks > 0U) {
        // a hooked object is read through its hook (read_at), never copied
        if (d_->hooks_.find(d_->store_->address_at(at)) != nullptr) p = {};
      }
      return p;
    }

  private:
    device *d_;
  };

  using pdo_type = pdo_engine<access, C.rpdos, C.tpdos, C.mapped>;
  using sdo_type = sdo_channels<
      access, C.sdo_servers, C.sdo_clients, C.sdo_buffer,
      std::conditional_t<C.sdo_crc_table, crc::ccitt16_with_table, crc::ccitt16_no_table>>;
  using emcy_type = emcy_producer<C.active_errors, C.error_history, C.emcy_queue>;
  using consumer_type = heartbeat_consumer<C.heartbeat_consumers>;
  using errors_type = error_behaviour<C.error_classes>;

  /// A node `node` (1..127; with capacity::lss also lss::unconfigured) over `store`
  /// (borrowed, already holding its power-on values, e.g. from init_defaults). Nothing is sent
  /// before start(). `l`: the LSS slave's bit rates and store hook (capacity::lss; a node
  /// without LSS keeps nothing of it).
  constexpr device(Store &store, std::uint8_t node, options o = {},
                   [[maybe_unused]] lss_options l = {}) noexcept
      : store_(&store), self_start_(o.self_start), node_(node), nmt_(node), producer_(node),
        guard_(node), emcy_(node), lss_(make_lss(node, l)), access_(*this),
        pdo_(access_, store.dictionary()), sdo_(access_, node, o.sdo_timeout_ms, o.sdo) {
    pdo_.report_long_rpdo(o.report_long_rpdo);
    sync_.allow_producer(C.sync_producer);
    emcy_.report_each_reset(o.report_each_reset);
  }
  device(const device &) = delete;
  device &operator=(const device &) = delete;

  // ----- the step interface ----------------------------------------------------------------

  /// Power-on: read the configuration of every service from the store, send the boot-up
  /// message and enter pre-operational (operational with options::self_start). With
  /// capacity::lss a node started as lss::unconfigured stays in initialising (state()
  /// boot_up), sends nothing and answers only the LSS master until it has a node-ID.
  /// Errors: invalid_argument (node-ID not 1..127, nor unconfigured with LSS), bad_state
  /// (already started). A configuration the services cannot serve completely (more PDOs or
  /// channels than the capacity, an unusable stored mapping) does not stop the start:
  /// configuration() says so.
  [[nodiscard]] constexpr result<step> start(std::uint32_t now) noexcept {
    const bool waits = C.lss && node_ == lss::unconfigured;
    if (!is_node_id(node_) && !waits) return errc::invalid_argument;
    if (started_) return errc::bad_state;
    started_ = true;
    begin(now);
    configure(now);
    if (!waits) boot(now);
    return finish(now);
  }

  /// A received frame: routed by COB-ID to the service it belongs to.
  [[nodiscard]] constexpr step on_frame(const can_frame &f, std::uint32_t now) noexcept {
    begin(now);
    route(f, now);
    return finish(now);
  }

  /// Several received frames in order (what a CAN driver took from its receive FIFO), each
  /// exactly as on_frame(frame, now) takes it, all at the same `now`. It stops after the first
  /// frame that answers — its step has frames to send, or the call reported events (events()
  /// not empty: an NMT state change or reset, a SYNC, an RPDO, a heartbeat or guarding event)
  /// — and returns {frames taken including that one, on_frame's step for it}; events() are that
  /// frame's. Act on the step and the events, then call again with the rest. When no frame
  /// answers, every frame is taken and `last` is the step on_frame gave for the last of them
  /// (nothing to send, the state and deadline after them; events() empty). An empty span takes
  /// nothing and changes nothing: consumed 0, nothing to send, the state and deadline as they
  /// are, events() still those of the last call. Like on_frame it does not look at the
  /// deadline: call poll(now) for that. So the frames sent, the events, the states and the
  /// stored bytes are those of on_frame called for each frame
  /// (tests/node/device_batch_test.cpp). A run of frames in front for one SDO server (its
  /// request COB-ID, while the NMT state lets SDO through) goes to that server's on_frames in
  /// one piece (sdo::server::on_frames: the segments of a block download without a step each);
  /// every other frame, and the first of each call, goes through on_frame.
  [[nodiscard]] constexpr batch_step on_frames(std::span<const can_frame> fs,
                                               std::uint32_t now) noexcept {
    if (fs.empty()) {
      step s;
      s.state = nmt_.state();
      s.deadline = carry_ ? std::optional<std::uint32_t>(now) : deadline(now);
      return {0, s};
    }
    // the first frame as on_frame takes it: it sends what an earlier call left (a burst's
    // companions), and its end settles the node (its own EMCY after the application's set());
    // after a frame that answered nothing, one more that answers nothing changes only what it
    // was for
    nmt::state before = nmt_.state();
    step s = on_frame(fs[0], now);
    std::size_t i = 1;
    if (answered(s, before)) return {i, s};
    while (i < fs.size()) {
      before = nmt_.state();
      const std::size_t k = sdo_server_for(fs[i]);
      if (k == C.sdo_servers) {
        s = on_frame(fs[i++], now);
        if (answered(s, before)) return {i, s};
        continue;
      }
      // the run: what routes as fs[i] does — the routing of a frame that is not a remote frame
      // and has a DLC of at most 8 depends, within a call, only on its identifier
      const std::uint16_t id = fs[i].id;
      std::size_t n = 1;
      while (i + n < fs.size() && fs[i + n].id == id && !fs[i + n].rtr &&
             fs[i + n].dlc <= max_dlc) {
        ++n;
      }
      // the server stops after its first frame that answers (frames, its state, a refusal) and
      // every frame before it was for on_frame a call without effect beyond the server's (a
      // store write always comes with a response): that frame as on_frame ends it
      const sdo::batch_step r = sdo_.on_server_frames(k, fs.subspan(i, n), now);
      i += r.consumed;
      begin(now);
      if (r.last.send.is_burst()) {
        burst_ = r.last.send;
      } else {
        take(r.last);
      }
      s = finish(now);
      if (answered(s, before)) return {i, s};
    }
    return {i, s};
  }

  /// Time: heartbeat, consumer and life guarding timeouts, SDO timeouts, PDO timers, EMCY
  /// inhibit time.
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    begin(now);
    const nmt::state s = nmt_.state();
    if (!started_ || s == nmt::state::boot_up) return finish(now);
    if (const auto f = producer_.due(now, s)) out_.push(*f);
    if constexpr (C.sync_producer) {
      if (allowed(s, service::sync)) {
        if (const auto f = sync_out_.poll(now)) {
          out_.push(*f);
          sync_frame(*f, now); // the node's own SYNC counts for its PDOs
        }
      }
    }
    consumer_.check_times(now);
    bool lost = consumer_events();
    const auto before = life_.state();
    if (life_.poll(now).state == guard_state::lost && before != guard_state::lost) {
      push_event(event::kind::life_guard_lost);
      lost = true;
    }
    if (lost) error_found(errors_type::communication, now);
    const auto sdo = sdo_.poll(now);
    if (allowed(s, service::sdo)) take(sdo); // in stopped the timeouts end silently
    take(pdo_.poll(now));
    pdo_events();
    take_frames(emcy_.send_due(now));
    return finish(now);
  }

  // ----- the application -------------------------------------------------------------------

  /// The application writes `value` to `a`: the store's checks except access, no write hook
  /// (canopen::dictionary_store::set), plus the node's rules and effects for communication
  /// objects; event-driven TPDOs mapping `a` become due and the next call sends them (poll,
  /// or set with `now` below). No call itself: the step before stays valid. Times the node
  /// needs (e.g. a new heartbeat period) count from the `now` of the last call.
  [[nodiscard]] constexpr abort_code set(od::address a,
                                         std::span<const std::uint8_t> value) noexcept {
    if (const auto c = store_value(a, value); c != abort_code::none) return c;
    follow(a, value);
    return abort_code::none;
  }
  /// set(a, value) at `now` as a call like the others: its step sends the event-driven TPDOs
  /// (254, 255) that are due, this value's and those of earlier set(a, value) calls, unless
  /// their inhibit time holds them back (a later call sends them, by the step's deadline); a
  /// type 0 TPDO waits for the next SYNC. Several objects of one TPDO: write all but the last
  /// with set(a, value) and the last with this one, so that the TPDO carries all of them. The
  /// frames of the step before are no longer valid once the value is stored: send them first.
  /// The error: the abort code of the refusal (nothing stored, nothing sent, the step before
  /// still valid).
  [[nodiscard]] constexpr result<step, abort_code>
  set(od::address a, std::span<const std::uint8_t> value, std::uint32_t now) noexcept {
    if (const auto c = store_value(a, value); c != abort_code::none) return c;
    begin(now);
    follow(a, value);
    if (started_ && nmt_.state() != nmt::state::boot_up) {
      take(pdo_.poll(now));
      pdo_events();
    }
    return finish(now);
  }
  /// The current value of `a` (see canopen::dictionary_store::value).
  [[nodiscard]] constexpr result<std::span<const std::uint8_t>>
  value(od::address a) const noexcept {
    return store_->value(a);
  }
  /// The application's event for TPDO `number` (1..512: 1800h + number − 1).
  [[nodiscard]] constexpr status request_tpdo(std::uint16_t number) noexcept {
    return pdo_.request(number);
  }
  /// An application error: EMCY, 1001h, 1003h (see emcy_producer::raise).
  [[nodiscard]] constexpr result<step>
  raise(std::uint16_t code, std::uint32_t now, std::uint8_t register_bits = 0,
        std::array<std::uint8_t, 5> manufacturer = {}) noexcept {
    begin(now);
    if (const status r = emcy_.raise_error(code, now, register_bits, manufacturer); !r) {
      return r.error();
    }
    take_frames(emcy_.sent());
    return finish(now);
  }
  /// An application error is gone (see emcy_producer::clear).
  [[nodiscard]] constexpr result<step> clear(std::uint16_t code, std::uint32_t now) noexcept {
    begin(now);
    if (const status r = emcy_.clear_error(code, now); !r) return r.error();
    take_frames(emcy_.sent());
    return finish(now);
  }
  /// An error of class `sub` of 1029h was found (1 = communication error: e.g. the CAN driver
  /// reports bus-off; 2.. the device profile's or the application's classes): the node enters
  /// the state 1029h sub `sub` asks for (error_behaviour; a class 1029h does not have: enter
  /// pre-operational from operational). The node finds heartbeat and life guarding losses
  /// itself. Errors: invalid_argument (sub 0), bad_state (not started).
  [[nodiscard]] constexpr result<step> report_error(std::uint8_t sub, std::uint32_t now) noexcept {
    if (sub == 0U) return errc::invalid_argument;
    if (!started_ || nmt_.state() == nmt::state::boot_up) return errc::bad_state;
    begin(now);
    error_found(sub, now);
    return finish(now);
  }
  /// The application's time `t` (milliseconds after midnight, days since 1984-01-01: its own
  /// clock, e.g. an RTC or, on a host, host::time_of_day) as a TIME message on 1012h's CAN-ID
  /// (capacity::time). The node has no wall clock and no TIME period: it sends when the
  /// application calls, e.g. once a second or when its clock was set. Errors: bad_state (not
  /// started, 1012h bit 30 clear, or the NMT state does not allow TIME: stopped), out_of_range
  /// (t.ms not below 86 400 000). Nothing is sent on an error.
  [[nodiscard]] constexpr result<step> produce_time(od::time_value t, std::uint32_t now) noexcept
      requires(C.time) {
    if (!started_ || !allowed(nmt_.state(), service::time)) return errc::bad_state;
    FIELDCODEC_TRY(const can_frame f, time_.produce(t));
    begin(now);
    out_.push(f);
    return finish(now);
  }
  /// A local NMT state change (the device's error behaviour, or no NMT master).
  /// Errors: those of nmt_slave::enter.
  [[nodiscard]] constexpr result<step> enter(nmt::state s, std::uint32_t now) noexcept {
    begin(now);
    const nmt::state before = nmt_.state();
    auto r = nmt_.enter(s);
    if (!r) return r.error();
    if (nmt_.state() != before) state_changed(now);
    return finish(now);
  }
  /// SDO client i (1280h + i): start transfers on it; its responses come in through on_frame
  /// and its timeouts through poll.
  [[nodiscard]] constexpr sdo::client &client(std::size_t i) noexcept { return sdo_.client(i); }

  // ----- state -----------------------------------------------------------------------------

  [[nodiscard]] constexpr nmt::state state() const noexcept { return nmt_.state(); }
  [[nodiscard]] constexpr std::uint8_t node_id() const noexcept { return node_; }
  [[nodiscard]] constexpr std::span<const event> events() const noexcept { return events_.span(); }
  /// How the last configuration (start or reset) went: too_long (more PDOs, channels or
  /// consumers in the dictionary than the capacity), bad_length (a stored PDO configuration
  /// that cannot be served), or a store error.
  [[nodiscard]] constexpr status configuration() const noexcept { return config_; }
  [[nodiscard]] constexpr const nmt_slave &nmt() const noexcept { return nmt_; }
  [[nodiscard]] constexpr const heartbeat_producer &producer() const noexcept { return producer_; }
  [[nodiscard]] constexpr const consumer_type &consumer() const noexcept { return consumer_; }
  [[nodiscard]] constexpr const life_guard &guarding() const noexcept { return life_; }
  [[nodiscard]] constexpr const emcy_type &emcy() const noexcept { return emcy_; }
  [[nodiscard]] constexpr const sync_consumer &sync() const noexcept { return sync_; }
  [[nodiscard]] constexpr const errors_type &errors() const noexcept { return errors_; }
  /// TIME (capacity::time): 1012h as followed, the last TIME received (received(): what a
  /// `time` event reports) and why the last TIME frame was ignored (error()).
  [[nodiscard]] constexpr const time_service &time() const noexcept requires(C.time) {
    return time_;
  }
  /// The application's storage for 1010h/1011h (capacity::storage; see parameter_storage).
  constexpr void set_storage(storage_hook h) noexcept requires(C.storage) { storage_.set_hook(h); }
  [[nodiscard]] constexpr const parameter_storage &storage() const noexcept requires(C.storage) {
    return storage_;
  }
  /// Add the application's hook `h` (capacity::hooks; node/object_hooks.hpp) before start():
  /// the PDO engine decides at start which mapped objects it copies and which it reads through
  /// the hooks. Errors: bad_state (started), those of object_hooks::add (invalid_argument,
  /// unknown_object, type_mismatch, too_long: capacity::hooks are added).
  [[nodiscard]] constexpr status add_hook(const object_hook &h) noexcept requires(C.hooks > 0U) {
    if (started_) return errc::bad_state;
    return hooks_.add(h, store_->dictionary());
  }
  /// The LSS slave (capacity::lss): its state, pending node-ID and bit timing, LSS address.
  [[nodiscard]] constexpr const lss_slave &lss() const noexcept requires(C.lss) { return lss_; }
  [[nodiscard]] constexpr const pdo_type &pdo() const noexcept { return pdo_; }
  [[nodiscard]] constexpr const sdo_type &sdo() const noexcept { return sdo_; }
  /// Frames or events that did not fit their lists (a sizing error; always 0).
  [[nodiscard]] constexpr std::size_t lost() const noexcept { return out_.lost() + events_.lost(); }

  static constexpr capacity capacities() noexcept { return C; }

private:
  // ----- call frame ------------------------------------------------------------------------

  constexpr void begin(std::uint32_t now) noexcept {
    now_ = now;
    if (!carry_) out_.clear();
    carry_ = false;
    burst_ = {};
    events_.clear();
  }
  [[nodiscard]] constexpr step finish(std::uint32_t now) noexcept {
    update_errors(now);
    emcy_.publish(*store_);
    step s;
    s.state = nmt_.state();
    s.deadline = deadline(now);
    if (!burst_.empty()) {
      s.send = burst_;
      carry_ = !out_.empty(); // the node's own frames go out with the next call
      if (carry_) s.deadline = now;
    } else {
      s.send = frames(out_.span());
    }
    return s;
  }
  template <class Step>
  constexpr void take(const Step &s) noexcept {
    take_frames(s.send);
  }
  /// The frames a service's step sends go out with the node's (one function for every
  /// service: called from many places, not inlined into each).
  [[gnu::noinline]] constexpr void take_frames(const frames &send) noexcept {
    for (const can_frame &f : send) out_.push(f);
  }
  [[gnu::noinline]] constexpr void take_frames(std::span<const can_frame> send) noexcept {
    for (const can_frame &f : send) out_.push(f);
  }
  // the events and their loops: one function each, called from several places
  [[gnu::noinline]] constexpr void push_event(const event &e) noexcept { events_.push(e); }
  [[gnu::noinline]] constexpr void push_event(event::kind k) noexcept { push_event(event{k}); }
  /// The heartbeat consumer's events; true when a monitor lost its node.
  [[gnu::noinline]] constexpr bool consumer_events() noexcept {
    bool lost = false;
    for (const auto &h : consumer_.events()) {
      event e{event::kind::heartbeat};
      e.heartbeat = h;
      push_event(e);
      lost = lost || h.what == heartbeat_event::kind::lost;
    }
    return lost;
  }
  [[gnu::noinline]] constexpr void pdo_events() noexcept {
    for (const auto &p : pdo_.events()) {
      event e{event::kind::pdo};
      e.pdo = p;
      push_event(e);
    }
  }
  /// Did the call that returned `s` answer (see on_frames)? `before`: the state before it.
  [[nodiscard]] constexpr bool answered(const step &s, nmt::state before) const noexcept {
    return !s.send.empty() || !events_.span().empty() || s.state != before;
  }
  /// The SDO server on_frame would hand `f` to, or C.sdo_servers (on_frame's routing: the
  /// checks before the SDO channels, then sdo_channels::server_of).
  [[nodiscard]] constexpr std::size_t sdo_server_for(const can_frame &f) const noexcept {
    const nmt::state s = nmt_.state();
    if (!started_ || s == nmt::state::boot_up || f.id > max_can_id || f.dlc > max_dlc ||
        f.id == cob_id::nmt || f.rtr || !allowed(s, service::sdo) ||
        (f.id == sync_.cob_id() && allowed(s, service::sync)) || time_frame_for(f, s)) {
      return C.sdo_servers; // remote frames: guarding, or no server's (is_request)
    }
    return sdo_.server_of(f);
  }
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline(std::uint32_t now) const noexcept {
    if (!started_ || nmt_.state() == nmt::state::boot_up) return std::nullopt;
    std::optional<std::uint32_t> sync_due;
    if constexpr (C.sync_producer) {
      if (allowed(nmt_.state(), service::sync)) sync_due = sync_out_.deadline();
    }
    const std::optional<std::uint32_t> due[] = {
        producer_.deadline(), consumer_.deadline(now), life_.deadline(), emcy_.deadline(),
        pdo_.deadline(now),   sdo_.deadline(now),      sync_due};
    // the earliest, as a distance from now; a deadline the caller let pass (a frame handled
    // after it, before the poll) is now: poll at once; never a time in the past, which a
    // wrapping counter would read as 2^32 ms ahead
    std::optional<std::uint32_t> wait;
    for (const auto &d : due) {
      if (!d) continue;
      const std::uint32_t w = reached(*d, now) ? 0U : *d - now;
      if (!wait || w < *wait) wait = w;
    }
    if (!wait) return std::nullopt;
    return now + *wait;
  }

  /// on_frame's routing (the step is built once, after it).
  constexpr void route(const can_frame &f, std::uint32_t now) noexcept {
    if (!started_ || f.id > max_can_id || f.dlc > max_dlc) return;
    if (f.id == cob_id::nmt) {
      nmt_frame(f, now);
      return;
    }
    if constexpr (C.lss) {
      if (f.id == lss::master_id) { // in every NMT state, initialising included
        lss_frame(f, now);
        return;
      }
    }
    const nmt::state s = nmt_.state();
    if (s == nmt::state::boot_up) return;
    if (f.rtr && f.id == cob_id::nmt_error_base + node_) {
      if (const auto r = guard_.answer(s)) out_.push(*r); // route's checks: this node's request
      const auto before = life_.state();
      (void)life_.on_request(now);
      if (before == guard_state::lost) push_event(event::kind::life_guard_resumed);
      return;
    }
    if (f.id == sync_.cob_id() && !f.rtr && allowed(s, service::sync)) {
      sync_frame(f, now);
      return;
    }
    if (time_frame_for(f, s)) {
      if constexpr (C.time) {
        if (time_.on_frame(f)) push_event(event::kind::time);
      }
      return;
    }
    if (allowed(s, service::sdo)) {
      if (auto r = sdo_.on_frame(f, now)) {
        if (r->send.is_burst()) {
          burst_ = r->send;
        } else {
          take(*r);
        }
        return;
      }
    }
    if (!f.rtr && f.id > cob_id::nmt_error_base && f.id <= cob_id::nmt_error_base + max_node_id) {
      consumer_.receive(f, now);
      (void)consumer_events();
      return;
    }
    if (allowed(s, service::pdo)) {
      take(pdo_.on_frame(f, now, !sync_.window_passed(now)));
      pdo_events();
    }
  }

  /// Is `f` a TIME for the consumer in state `s` (capacity::time, 1012h bit 31, its CAN-ID)?
  [[nodiscard]] constexpr bool time_frame_for(const can_frame &f, nmt::state s) const noexcept {
    if constexpr (C.time) {
      return time_.takes(f) && allowed(s, service::time);
    } else {
      (void)f;
      (void)s;
      return false;
    }
  }

  /// A SYNC, received or the node's own: the consumer takes it, the PDOs follow.
  constexpr void sync_frame(const can_frame &f, std::uint32_t now) noexcept {
    if (!sync_.receive(f, now)) return;
    event e{event::kind::sync};
    e.counter = sync_.counter();
    push_event(e);
    take(pdo_.on_sync(e.counter, now));
    pdo_events();
  }

  // ----- NMT -------------------------------------------------------------------------------

  constexpr void nmt_frame(const can_frame &f, std::uint32_t now) noexcept {
    const nmt::state before = nmt_.state();
    nmt_.receive(f);
    if (nmt_.pending_reset() != reset::none) {
      carry_out(nmt_.pending_reset(), now);
    } else if (nmt_.state() != before) {
      state_changed(now);
    }
  }
  /// An NMT reset: restore, reload every service, boot. With LSS the pending node-ID becomes
  /// the node's first; without node-ID (lss::unconfigured) the node stays initialising.
  constexpr void carry_out(reset r, std::uint32_t now) noexcept {
    push_event(r == reset::application ? event::kind::reset_application
                                       : event::kind::reset_communication);
    status st{};
    if constexpr (C.lss) {
      const std::uint8_t to = lss_.activate();
      if (to != node_) st = renumber(to);
    }
    // reset node: 2000h–FFFFh and 1000h–1FFFh, in one pass (the ranges are adjacent)
    const std::uint16_t first = restored(reset::communication).first;
    if (auto s1 = store_->restore_defaults(first, restored(r).last); !s1 && st) st = s1;
    guard_.reset();
    configure(now);
    if (!st && config_) config_ = st;
    if (is_node_id(node_)) {
      boot(now);
    } else {
      state_changed(now); // initialising: every service silent
    }
  }
  /// Send the boot-up message and enter pre-operational (or operational).
  constexpr void boot(std::uint32_t now) noexcept {
    if (const auto f = nmt_.boot_up(self_start_)) out_.push(*f);
    state_changed(now);
  }
  constexpr void state_changed(std::uint32_t now) noexcept {
    const nmt::state s = nmt_.state();
    pdo_.set_operational(s == nmt::state::operational, now);
    emcy_.enable(allowed(s, service::emcy));
    consumer_.enable(s == nmt::state::pre_operational || s == nmt::state::operational);
    if (s == nmt::state::stopped) sdo_.stop_servers();
    if constexpr (C.sync_producer) {
      if (s == nmt::state::operational) sync_out_.restart_counter();
    }
    event e{event::kind::nmt_state};
    e.state = s;
    push_event(e);
  }

  // ----- the services and their objects ---------------------------------------------------

  /// Call f(service) for every service that owns objects, in this order (the order of their
  /// loads: configuration() keeps the first error). A service owns its objects: it checks a
  /// value written to them (check_write: abort_code::none for objects that are not its own),
  /// follows a stored one (written) and reads them all from the store when the node starts or
  /// resets (load). Adding a service to the node is a member and a line here.
  template <class Self, class F>
  static constexpr void each_service(Self &self, F f) noexcept {
    f(self.sync_);
    if constexpr (C.sync_producer) f(self.sync_out_);
    if constexpr (C.time) f(self.time_);
    if constexpr (C.storage) f(self.storage_);
    f(self.life_);
    f(self.emcy_);
    f(self.producer_);
    f(self.consumer_);
    f(self.pdo_);
    f(self.sdo_);
    f(self.errors_);
    if constexpr (C.lss) f(self.lss_);
  }

  /// Read every service's objects from the store (start, NMT resets).
  constexpr void configure(std::uint32_t now) noexcept {
    config_ = status{};
    own_errors_ = 0;
    each_service(*this, [&](auto &service) {
      if (const status st = service.load(access_, now); !st && config_) config_ = st;
    });
  }

  /// The application's write (set): the owning service's check, then the store's set.
  [[nodiscard]] constexpr abort_code store_value(od::address a,
                                                 std::span<const std::uint8_t> value) noexcept {
    if (const auto c = check(a, value); c != abort_code::none) return c;
    if (const auto c = storage_command(a, value)) return *c;
    return store_->set(a, value);
  }
  /// A command to 1010h/1011h (capacity::storage) that check() accepted: carried out by the
  /// application's hook, nothing stored; nullopt for every other write.
  [[nodiscard]] constexpr std::optional<abort_code>
  storage_command(od::address a, std::span<const std::uint8_t> value) const noexcept {
    if constexpr (C.storage) {
      if (parameter_storage::owns(a) && value.size() == 4U) return storage_.command(a);
    } else {
      (void)a;
      (void)value;
    }
    return std::nullopt;
  }

  /// The CiA 301 rules of the communication objects: the check of the service that owns `a`.
  [[nodiscard]] constexpr abort_code check(od::address a,
                                           std::span<const std::uint8_t> value) const noexcept {
    const auto v = u32_of(value);
    abort_code c = abort_code::none;
    if (!v || a.index < 0x1000U || a.index > 0x1FFFU) return c;
    each_service(*this, [&](const auto &service) {
      if (c == abort_code::none) c = service.check_write(a, *v);
    });
    return c;
  }

  /// A value was stored at `a` (by SDO, RPDO or set()): the service that owns it follows it,
  /// and the event-driven TPDOs that map it become due.
  constexpr void follow(od::address a, std::span<const std::uint8_t> value) noexcept {
    const auto v = u32_of(value);
    if (v && a.index >= 0x1000U && a.index <= 0x1FFFU) {
      each_service(*this, [&](auto &service) { service.written(a, *v, now_); });
    }
    pdo_.mark(a);
  }

  /// The path of every SDO and RPDO write (device::access); `at`: a's position in a
  /// positioned store (the store's write_at is used), or no_position (its write).
  [[nodiscard]] constexpr abort_code write_object(od::address a, std::size_t offset,
                                                  std::span<const std::uint8_t> part, bool last,
                                                  std::size_t at = canopen::no_position) noexcept {
    const bool whole = offset == 0U && last;
    if constexpr (C.hooks > 0U) {
      if (const object_hook *h = hooks_.find(a)) {
        if (h->streams()) return stream_write(*h, a, offset, part, last);
        if (h->write != nullptr) {
          if (!whole) return abort_code::out_of_memory; // the hook sees whole values only
          // every check first: what the hook accepts is stored
          if (const auto c = check(a, part); c != abort_code::none) return c;
          if (const auto c = store_->check(a, part); c != abort_code::none) return c;
          if (const auto c = h->write(h->context, a, part); c != abort_code::none) return c;
        }
      }
    }
    if (const auto c = check(a, part); c != abort_code::none) {
      // a communication value in parts would pass unchecked: the servers' buffers (≥ 8 bytes)
      // always hold the ≤ 4 bytes of one, so a part refused is a value of the wrong length
      return whole ? c : abort_code::length_too_high;
    }
    if (whole) {
      if (const auto c = storage_command(a, part)) return *c;
    }
    abort_code c = abort_code::none;
    if constexpr (canopen::positioned_store<Store>) {
      c = at == canopen::no_position ? store_->write(a, offset, part, last)
                                     : store_->write_at(at, offset, part, last);
    } else {
      (void)at;
      c = store_->write(a, offset, part, last);
    }
    if (c != abort_code::none || !last) return c;
    if (whole) {
      follow(a, part);
    } else {
      pdo_.mark(a);
    }
    return abort_code::none;
  }

  // ----- the application's hooks (capacity::hooks) -----------------------------------------

  /// A read hook computes the value of `a` (fixed size, 2000h on: object_hooks::add) before it
  /// is read; the store keeps it with its checks. A hook without `read`: nothing to do.
  [[nodiscard]] constexpr abort_code refresh(const object_hook &h, od::address a) noexcept {
    if (h.read == nullptr) return abort_code::none;
    const od::entry *e = store_->dictionary().find(a);
    if (e == nullptr || !od::readable(e->access_type)) return abort_code::none; // the store's
    std::array<std::uint8_t, 8> buf{};
    // at most 8 bytes (a fixed-size type): said to the compiler too, whose -Wstringop-overflow
    // at -O3 in a user's build cannot see it through fixed_size's table
    const std::size_t n = std::min<std::size_t>(od::fixed_size(e->type), buf.size());
    const auto value = std::span<std::uint8_t>(buf).first(n);
    if (const auto v = store_->value(a); v && v.value().size() == value.size()) {
      for (std::size_t i = 0; i < value.size(); ++i) value[i] = v.value()[i];
    }
    if (const auto c = h.read(h.context, a, value); c != abort_code::none) return c;
    if (store_->set(a, value) != abort_code::none) return abort_code::general_error;
    return abort_code::none;
  }
  /// The entry of streamed `a` and the check of its access (`write`: writable, else readable)
  /// and of the function for that direction.
  [[nodiscard]] constexpr abort_code stream_entry(const object_hook &h, od::address a, bool write,
                                                  const od::entry *&e) const noexcept {
    const od::dictionary dict = store_->dictionary();
    e = dict.find(a);
    if (e == nullptr) {
      return dict.object(a.index).empty() ? abort_code::no_object : abort_code::no_sub_index;
    }
    if (write ? !od::writable(e->access_type) : !od::readable(e->access_type)) {
      return write ? abort_code::write_read_only : abort_code::read_write_only;
    }
    if ((write ? h.download == nullptr : h.upload == nullptr)) {
      return abort_code::unsupported_access;
    }
    return abort_code::none;
  }
  [[nodiscard]] constexpr abort_code stream_read(const object_hook &h, od::address a,
                                                 std::size_t offset, std::span<std::uint8_t> out,
                                                 std::size_t &total) const noexcept {
    const od::entry *e = nullptr;
    if (const auto c = stream_entry(h, a, false, e); c != abort_code::none) return c;
    std::size_t t = 0;
    if (const auto c = h.upload(h.context, a, offset, out, t); c != abort_code::none) return c;
    if (offset > t) return abort_code::general_error;
    total = t;
    return abort_code::none;
  }
  [[nodiscard]] constexpr abort_code
  stream_begin(const object_hook &h, od::address a,
               std::optional<std::uint32_t> size) const noexcept {
    const od::entry *e = nullptr;
    if (const auto c = stream_entry(h, a, true, e); c != abort_code::none) return c;
    if (size && e->capacity() != 0U && *size > e->capacity()) return abort_code::length_too_high;
    return abort_code::none;
  }
  [[nodiscard]] constexpr abort_code stream_write(const object_hook &h, od::address a,
                                                  std::size_t offset,
                                                  std::span<const std::uint8_t> part,
                                                  bool last) noexcept {
    const od::entry *e = nullptr;
    if (const auto c = stream_entry(h, a, true, e); c != abort_code::none) return c;
    if (e->capacity() != 0U && (offset > e->capacity() || part.size() > e->capacity() - offset)) {
      return abort_code::length_too_high;
    }
    return h.download(h.context, a, offset, part, last);
  }

  // ----- LSS (capacity::lss) -------------------------------------------------------------

  [[nodiscard]] static constexpr auto make_lss([[maybe_unused]] std::uint8_t node,
                                               [[maybe_unused]] const lss_options &o) noexcept {
    if constexpr (C.lss) {
      return lss_slave(node, o);
    } else {
      return std::monostate{};
    }
  }
  /// A frame on 7E5h: the LSS slave's answer and event; a node that just got its first node-ID
  /// boots with it (a reset communication).
  constexpr void lss_frame(const can_frame &f, std::uint32_t now) noexcept requires(C.lss) {
    const auto r = lss_.on_frame(f);
    if (r.answer) out_.push(*r.answer);
    if (r.event) push_event(event::kind::lss);
    if (r.boot) carry_out(reset::communication, now);
  }
  /// Every service that knows the node-ID takes `to` (an NMT reset, then reloads them all).
  [[nodiscard]] constexpr status renumber(std::uint8_t to) noexcept requires(C.lss) {
    node_ = to;
    nmt_ = nmt_slave(to);
    producer_ = heartbeat_producer(to);
    guard_ = nmt::guard_responder(to);
    const auto emcy_id = cob_id::emcy(to);
    emcy_.load_cob_id(emcy_id ? std::uint32_t{emcy_id.value()} : cob_bits::invalid);
    sdo_.set_node(to);
    return store_->set_node(to);
  }

  // ----- error behaviour (1029h) ----------------------------------------------------------

  /// An error of class `sub` (1029h): its EMCY goes out first (the node's own codes, while the
  /// state still lets EMCY through), then the node enters the state 1029h asks for.
  constexpr void error_found(std::uint8_t sub, std::uint32_t now) noexcept {
    const auto to = errors_.target(sub, nmt_.state());
    if (!to) return;
    update_errors(now);
    if (nmt_.enter(*to)) state_changed(now);
  }

  // ----- EMCY ------------------------------------------------------------------------------

  /// Raise or clear the node-managed codes as their conditions are now: bit i of own_errors_
  /// is managed_codes[i], raised by the node.
  static constexpr std::uint16_t managed_codes[] = {
      managed_code::guarding, managed_code::rpdo_short, managed_code::rpdo_long,
      managed_code::sync_length, managed_code::rpdo_timeout};
  constexpr void update_errors(std::uint32_t now) noexcept {
    if (!started_) return;
    const auto pdo = pdo_.rpdo_errors();
    const std::uint8_t lost = consumer_.lost_node();
    const unsigned on = (lost != 0U || life_.state() == guard_state::lost ? 1U : 0U) |
                        (pdo.too_short ? 2U : 0U) | (pdo.too_long ? 4U : 0U) |
                        (sync_.length_error() ? 8U : 0U) | (pdo.timed_out ? 16U : 0U);
    if (on == own_errors_) return;
    for (std::size_t i = 0; i < std::size(managed_codes); ++i) {
      const unsigned bit = 1U << i;
      if (((on ^ own_errors_) & bit) != 0U) change_error(i, (on & bit) != 0U, now, lost);
    }
  }
  /// Raise (`on`) or clear managed_codes[i]; 8130h carries `lost` (the node-ID of the first
  /// lost heartbeat producer, 0 for life guarding) in its first manufacturer-specific byte.
  constexpr void change_error(std::size_t i, bool on, std::uint32_t now,
                              std::uint8_t lost) noexcept {
    const auto bit = static_cast<std::uint8_t>(1U << i);
    const std::array<std::uint8_t, 5> manufacturer{i == 0U ? lost : std::uint8_t{0}};
    const status r = on ? emcy_.raise_error(managed_codes[i], now, 0, manufacturer)
                        : emcy_.clear_error(managed_codes[i], now);
    if (!on) own_errors_ = static_cast<std::uint8_t>(own_errors_ & ~bit);
    if (!r) return;
    take_frames(emcy_.sent());
    if (on) own_errors_ = static_cast<std::uint8_t>(own_errors_ | bit);
  }
  // ----- members ---------------------------------------------------------------------------

  // one call sends at most: boot-up or heartbeat, a SYNC, a guarding response, each TPDO once, one
  // frame per SDO channel, the EMCY messages (the queue, or the raises and clears of the
  // five node-managed codes when no inhibit time holds them back), an LSS answer and a TIME
  static constexpr std::size_t out_capacity =
      3U + (C.lss ? 1U : 0U) + C.tpdos + C.sdo_servers + C.sdo_clients +
      (C.emcy_queue > 5U ? C.emcy_queue : 5U) + 1U + (C.time ? 1U : 0U);
  static constexpr std::size_t event_capacity =
      4U + (C.lss ? 1U : 0U) + C.heartbeat_consumers + 2U * C.rpdos + C.tpdos + 1U;

  Store *store_;
  bool self_start_; ///< options::self_start (the other options are taken by the services)
  std::uint8_t node_;
  nmt_slave nmt_;
  heartbeat_producer producer_;
  consumer_type consumer_{};
  life_guard life_{};
  nmt::guard_responder guard_;
  emcy_type emcy_;
  sync_consumer sync_{};
  [[no_unique_address]] std::conditional_t<C.sync_producer, sync_producer, std::monostate>
      sync_out_{};
  [[no_unique_address]] std::conditional_t<C.time, time_service, std::monostate> time_{};
  [[no_unique_address]] std::conditional_t<C.storage, parameter_storage, std::monostate> storage_{};
  errors_type errors_{};
  [[no_unique_address]] std::conditional_t<C.lss, lss_slave, std::monostate> lss_;
  [[no_unique_address]] std::conditional_t<(C.hooks > 0U), object_hooks<C.hooks>, std::monostate>
      hooks_{};
  access access_;
  pdo_type pdo_;
  sdo_type sdo_;
  frame_list<out_capacity> out_{};
  event_list<event, event_capacity> events_{};
  frames burst_{};
  status config_{};
  std::uint32_t now_ = 0;
  std::uint8_t own_errors_ = 0;
  bool started_ = false;
  bool carry_ = false;
};

} // namespace fieldcodec::canopen::node
