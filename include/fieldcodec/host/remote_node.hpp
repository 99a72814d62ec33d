// fieldcodec — host adapters: a remote CANopen node's objects as values, over a host::can_bus.
// What python canopen's RemoteNode.sdo gives: read an object and get its value in the object's
// own unit (a number or a string), write a value and have it checked first; never bare bytes.
//
//   // my_drive: a generated dictionary whose limit_i_force (UNSIGNED16) allows less than
//   // 30000 mA; my_units: the device folder's od::unit_rule table, which gives it the unit "mA"
//   // at 10 mA per raw step
//   namespace x = fieldcodec::dictionaries::my_drive;
//   host::remote_node drive(bus, 5, x::dictionary, my_units);
//   auto v = drive.read_text(x::identity_object_vendor_id);    // result<string>: "0x0000021B"
//   auto n = drive.read(x::identity_object_vendor_id);         // result<od::number>
//   drive.write(x::limit_i_force, "1500 mA");                  // parsed, checked, sent: raw 150
//   drive.write(x::limit_i_force, od::unsigned_number(30000)); // refused: above the high limit
//   drive.read_text({0x1008, 0});                              // by address, via the dictionary
//   if (!v) puts(v.error().what.c_str());
//
// One value path (DESIGN.md): every value goes through od/engineering.hpp and od/value_text.hpp
// with the limits of this node (node-ID-relative limits resolved for it), its scaling and its
// capacity; a value that cannot be sent is refused before any frame exists (sdo_error::value
// says why). Reads convert what the device sent, without checking its limits (a device's value
// is shown as it is). An expedited upload whose size the server did not indicate carries 4
// bytes: CiA 301 lets the object's type decide its size, so the bytes beyond it are dropped
// when they are zero (also when a server indicated 4 bytes for a shorter object), and the
// value is refused (bad_length) when they are not.
//
// The node as a network machine (python's RemoteNode: emcy, nmt, tpdo/rpdo): its EMCY, its
// heartbeat (NMT state, boot-up; a loss when watch_heartbeat gave a time) and its TPDOs become
// events; its PDO mappings, read by read_pdos() or configured by configure_pdo(), turn TPDOs
// into named values and RPDOs into frames, through the same value path:
//
//   (void)drive.read_pdos();                              // 14xxh/16xxh/18xxh/1Axxh by SDO
//   drive.watch_heartbeat(300);                           // lost after 300 ms without one
//   drive.listen(100ms);                                  // or: net.add(drive) on a network
//   while (auto e = drive.next_event()) { ... }           // boot-up, state, EMCY, TPDO, …
//   auto sw = drive.received("Statusword");               // the last TPDO's value
//   drive.set_pdo("Controlword", od::unsigned_number(6)); // checked, kept in its RPDO
//   drive.send_pdo(1);                                    // RPDO 1 on the bus
//
// The frames are taken in on_frame (a host::network runs the node), in listen(), and while an
// SDO transfer of the node waits (sdo_session::observe): none is lost to a blocking call.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/node/heartbeat.hpp>
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/host/bus.hpp>
#include <fieldcodec/host/deadline.hpp>
#include <fieldcodec/host/sdo.hpp>
#include <fieldcodec/host/value_text.hpp>
#include <fieldcodec/master/pdo_config.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/engineering.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/value_text.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fieldcodec::host {

/// What a remote node did (remote_node::next_event).
struct node_event {
  enum class kind : std::uint8_t {
    boot_up,           ///< its boot-up message: the node was reset (state: boot_up)
    state,             ///< a heartbeat with another NMT state than the last one (or the first)
    heartbeat_lost,    ///< no heartbeat within watch_heartbeat's time (state: the last one)
    heartbeat_resumed, ///< a heartbeat after a loss (state: its state)
    emcy,              ///< an EMCY (emcy: the message; error code 0000h is the error reset)
    pdo,               ///< one of its TPDOs (pdo: the number); received() has its values
    bad_frame,         ///< a frame on its heartbeat, EMCY or TPDO COB-ID that cannot be taken
                       ///< (code: why — bad_length, out_of_range —, frame: it); nothing changed
  };
  kind what = kind::state;
  std::uint32_t time = 0; ///< the node's milliseconds (remote_node::now)
  canopen::nmt::state state = canopen::nmt::state::boot_up;
  canopen::emcy::message emcy{};
  std::uint16_t pdo = 0;
  errc code{};
  canopen::can_frame frame{};
};

/// A short, stable text for an event kind.
[[nodiscard]] constexpr std::string_view to_string(node_event::kind k) noexcept {
  switch (k) {
  case node_event::kind::boot_up: return "boot-up";
  case node_event::kind::state: return "NMT state";
  case node_event::kind::heartbeat_lost: return "heartbeat lost";
  case node_event::kind::heartbeat_resumed: return "heartbeat resumed";
  case node_event::kind::emcy: return "EMCY";
  case node_event::kind::pdo: return "PDO";
  case node_event::kind::bad_frame: return "bad frame";
  }
  return "?";
}

/// One PDO of a remote node as its mapping and communication parameters say (read_pdos).
struct remote_pdo {
  canopen::pdo::direction dir = canopen::pdo::direction::tpdo;
  std::uint16_t number = 1; ///< 1..512 (RPDO n: 1400h + n - 1; TPDO n: 1800h + n - 1)
  std::uint16_t cob_id = 0;
  bool valid = false;                 ///< COB-ID bit 31 clear
  std::uint8_t transmission = 0;      ///< sub 2 (0 when the device has none)
  canopen::pdo::mapping<> map{};      ///< checked against the node's dictionary
  std::array<std::uint8_t, 8> data{}; ///< TPDO: the last one received; RPDO: what send_pdo sends
  bool received = false;              ///< TPDO: data holds a received PDO
  std::uint32_t time = 0;             ///< TPDO: when it was received
  /// Position of the mapped object `a` in map (map.size() when it is not mapped).
  [[nodiscard]] std::size_t find(od::address a) const noexcept {
    for (std::size_t i = 0; i < map.size(); ++i) {
      if (map[i].index == a.index && map[i].sub == a.sub) return i;
    }
    return map.size();
  }
};

class remote_node {
public:
  /// Node `node` (1..127) on `bus`, its objects described by `dict` (a generated header's
  /// `dictionary`, or the view of a dictionary loaded at run time), with the units and scales
  /// a vendor supplies for objects the dictionary file cannot describe (`units`, the device
  /// folder's od::unit_rule table; od::with_unit applies them to every descriptor used). The bus,
  /// the dictionary's tables and the rules must outlive the node.
  remote_node(can_bus &bus, std::uint8_t node, od::dictionary dict,
              std::span<const od::unit_rule> units = {}, sdo_options o = {})
      : bus_(&bus), dict_(dict), units_(units), sdo_(bus, node, o) {
    sdo_.observe([this](const canopen::can_frame &f, std::uint32_t now) { take(f, now); });
  }
  remote_node(const remote_node &) = delete; // its SDO session calls back into it
  remote_node &operator=(const remote_node &) = delete;

  /// The value of `d` in its engineering unit (a scaled entry's as an exact decimal; `o.unit =
  /// raw` for the number that travels). Errors (sdo_error::code): those of sdo_session::read;
  /// type_mismatch for a byte-string object (read_text or read_bytes take it); bad_length when
  /// the device sent a value of another size.
  result<od::number, sdo_error> read(const od::descriptor &given, od::value_options o = {}) {
    auto u = with_units(given);
    if (!u) return u.error();
    const od::descriptor &d = u.value();
    auto b = value_bytes(d);
    if (!b) return b.error();
    auto v = od::decode_value(d, b.value(), for_node(o));
    if (!v) return value_failed(d, od::value_error{v.error()}, "cannot decode the value read");
    return v.value();
  }

  /// The number that travels for the value `v` of `a` (meant in `o.unit`), as write() would
  /// send it: od::encode_value with this node's limits, the vendor's unit and the field.
  /// Errors: unknown_object (not in the dictionary), the value's (sdo_error::value).
  result<std::int64_t, sdo_error> to_raw(od::address a, od::number v,
                                         od::value_options o = {}) const {
    auto d = describe(a);
    if (!d) return d.error();
    auto u = with_units(d.value());
    if (!u) return u.error();
    std::array<std::uint8_t, 8> buf{};
    auto n = od::encode_value(u.value(), v, buf, for_node(o));
    if (!n) return value_failed(u.value(), n.error(), "refused");
    auto raw = od::decode_value(u.value(), std::span<const std::uint8_t>(buf).first(n.value()),
                                for_node({.unit = od::value_unit::raw}));
    if (!raw) return value_failed(u.value(), od::value_error{raw.error()}, "not a raw number");
    auto i = raw.value().to_int64();
    if (!i) return value_failed(u.value(), od::value_error{i.error()}, "not a 64-bit integer");
    return i.value();
  }

  /// The value of `d` as text, as od::format_value writes it ("1500 mA", "0x0000021B", a
  /// device name); write(d, text) takes it back as the same bytes. Errors: those of read
  /// (but a byte string is text too).
  result<std::string, sdo_error> read_text(const od::descriptor &given, od::value_options o = {}) {
    auto u = with_units(given);
    if (!u) return u.error();
    const od::descriptor &d = u.value();
    auto b = value_bytes(d);
    if (!b) return b.error();
    auto t = host::format_value(d, b.value(), for_node(o));
    if (!t) return value_failed(d, od::value_error{t.error()}, "cannot show the value read");
    return t.value();
  }

  /// The bytes of `d` as the device sent them (a DOMAIN's or OCTET_STRING's contents); valid
  /// until the next call. Errors: those of sdo_session::read.
  result<std::span<const std::uint8_t>, sdo_error> read_bytes(const od::descriptor &d) {
    return sdo_.read(at(d));
  }

  /// Read a byte-string object (a large DOMAIN) in parts: `sink(std::span<const std::uint8_t>)`
  /// gets each part in order (sdo_session::read_parts: one buffer of sdo_options::part_size
  /// bytes, kept by the session). Returns the bytes read. Errors: type_mismatch (not a byte
  /// string: read or read_text take it; nothing sent), those of sdo_session::read_parts.
  template <class Sink>
  result<std::size_t, sdo_error> read_parts(const od::descriptor &d, Sink &&sink) {
    if (!od::is_byte_string(d.type)) return not_bytes(d);
    return sdo_.read_parts(at(d), std::forward<Sink>(sink));
  }
  /// Write `size` bytes to a byte-string object in parts, `source(std::span<std::uint8_t>)`
  /// giving the next bytes (sdo_session::write_parts). Errors: type_mismatch (not a byte
  /// string), too_long (more than the object's capacity, when the dictionary gives one; nothing
  /// sent; value.issue capacity), those of sdo_session::write_parts.
  template <class Source>
  result<void, sdo_error> write_parts(const od::descriptor &d, std::uint32_t size,
                                      Source &&source) {
    if (!od::is_byte_string(d.type)) return not_bytes(d);
    if (d.capacity() != 0U && size > d.capacity()) {
      od::value_error v{errc::too_long};
      v.issue = od::value_issue::capacity;
      v.capacity = d.capacity();
      return value_failed(d, v, std::to_string(size) + " bytes refused");
    }
    return sdo_.write_parts(at(d), size, std::forward<Source>(source));
  }

  /// Write the number `v`, meant in `o.unit`, to `d` (od::encode_value: the limits of this
  /// node, the scale, the field). Errors: the value's (sdo_error::value.issue set, nothing
  /// sent), then those of sdo_session::write.
  result<void, sdo_error> write(const od::descriptor &given, od::number v,
                                od::value_options o = {}) {
    auto u = with_units(given);
    if (!u) return u.error();
    const od::descriptor &d = u.value();
    std::array<std::uint8_t, 8> buf{};
    auto n = od::encode_value(d, v, buf, for_node(o));
    if (!n) return value_failed(d, n.error(), "refused");
    return sdo_.write(at(d), std::span<const std::uint8_t>(buf).first(n.value()));
  }

  /// Write the value `text` to `d`, parsed as read_text writes it (od::parse_value: a number in
  /// the entry's unit, hex only where it is not scaled, a string within the capacity).
  /// Errors: as write(d, number).
  result<void, sdo_error> write(const od::descriptor &given, std::string_view text,
                                od::value_options o = {}) {
    auto u = with_units(given);
    if (!u) return u.error();
    const od::descriptor &d = u.value();
    auto b = host::parse_value(d, text, for_node(o));
    if (!b) return value_failed(d, b.error(), "'" + std::string(text) + "' refused");
    return sdo_.write(at(d), b.value());
  }

  /// The same by address, with the dictionary's descriptor. Errors: unknown_object (not in the
  /// dictionary; nothing sent), then those of the descriptor's call.
  result<od::number, sdo_error> read(od::address a, od::value_options o = {}) {
    auto d = describe(a);
    if (!d) return d.error();
    return read(d.value(), o);
  }
  result<std::string, sdo_error> read_text(od::address a, od::value_options o = {}) {
    auto d = describe(a);
    if (!d) return d.error();
    return read_text(d.value(), o);
  }
  result<void, sdo_error> write(od::address a, od::number v, od::value_options o = {}) {
    auto d = describe(a);
    if (!d) return d.error();
    return write(d.value(), v, o);
  }
  result<void, sdo_error> write(od::address a, std::string_view text, od::value_options o = {}) {
    auto d = describe(a);
    if (!d) return d.error();
    return write(d.value(), text, o);
  }

  // ----- the node as a machine: events ------------------------------------------------------

  /// The step a network sees (canopen/step.hpp): nothing to send, the heartbeat deadline.
  using step = canopen::step<std::size_t>; ///< state: events waiting

  /// A frame from the bus: the node's heartbeat / boot-up, EMCY and TPDOs become events, other
  /// frames are ignored.
  step on_frame(const canopen::can_frame &f, std::uint32_t now) {
    take(f, now);
    return make(now);
  }
  /// Time: a watched heartbeat that is overdue is lost (one event).
  step poll(std::uint32_t now) {
    check_heartbeat(now);
    return make(now);
  }
  /// Take the bus's frames for `ms` (blocking use, without a network). Errors: bad_state when
  /// the bus failed (bus-off, a read error; error-passive warnings are skipped).
  result<void, sdo_error> listen(std::chrono::milliseconds ms) {
    const auto end = std::chrono::steady_clock::now() + ms;
    for (;;) {
      poll_now();
      const auto left = time_left(end);
      if (left.count() == 0) return {};
      auto r = bus_->receive(left);
      if (r) {
        take(r.value().frame, now());
        continue;
      }
      if (r.error() == errc::timeout) continue;
      const bus_error &be = bus_->last_error();
      if (be.from_error_frame && !be.frame.is_bus_off()) continue;
      return bus_failed();
    }
  }
  /// listen() until an event is waiting or `ms` have passed; the event, or none.
  std::optional<node_event> wait_event(std::chrono::milliseconds ms) {
    const auto end = std::chrono::steady_clock::now() + ms;
    while (events_.empty()) {
      const auto left = time_left(end);
      if (left.count() == 0) break;
      if (auto r = listen_once(left); !r) break; // the bus failed: listen() says why
    }
    return next_event();
  }
  /// The oldest event not yet taken (at most max_events are kept; older ones are dropped and
  /// counted in dropped_events()).
  std::optional<node_event> next_event() {
    if (events_.empty()) return std::nullopt;
    node_event e = events_.front();
    events_.pop_front();
    return e;
  }
  [[nodiscard]] std::size_t pending_events() const noexcept { return events_.size(); }
  [[nodiscard]] std::size_t dropped_events() const noexcept { return dropped_; }
  static constexpr std::size_t max_events = 1024;

  /// Watch the node's heartbeat: `ms` without one is heartbeat_lost (0: not watched). The
  /// node's state and boot-up are followed either way.
  void watch_heartbeat(std::uint16_t ms) {
    const std::uint32_t v = ms == 0U ? 0U : (std::uint32_t{node()} << 16U) | ms;
    (void)consumer_.configure(0, v, now());
  }
  /// The NMT state of the last heartbeat (boot_up after a boot-up message; empty until one).
  [[nodiscard]] std::optional<canopen::nmt::state> nmt_state() const noexcept { return state_; }
  /// The last EMCY (an error reset included); empty until one.
  [[nodiscard]] std::optional<canopen::emcy::message> last_emcy() const noexcept { return emcy_; }
  /// EMCYs received so far (whether their events were taken or not).
  [[nodiscard]] std::size_t emcy_count() const noexcept { return emcy_count_; }
  /// The milliseconds events and machines are given (the SDO session's clock).
  [[nodiscard]] std::uint32_t now() const noexcept { return sdo_.now(); }

  /// Send the NMT command `c` to the node (start, stop, pre-operational, reset node, reset
  /// communication; python's `nmt.state = ...`). Errors: invalid_argument (node-ID), bad_state
  /// (the bus failed).
  result<void, sdo_error> send_nmt(canopen::nmt::command c) {
    auto f = canopen::nmt::encode(c, node());
    if (!f) {
      sdo_error e(f.error());
      e.what = "node " + std::to_string(node()) + ": no NMT command for this node";
      return e;
    }
    if (!bus_->send(f.value())) {
      return bus_failed();
    }
    return {};
  }

  // ----- PDOs by name -------------------------------------------------------------------------

  /// Read every RPDO and TPDO the dictionary has (communication parameters 1400h/1800h + n - 1,
  /// mappings 1600h/1A00h + n - 1) from the node by SDO; the mappings of valid PDOs are checked
  /// against the dictionary (an object it does not have, a length that does not fit). Errors:
  /// those of read (the PDO's object named), those of canopen::pdo::make_mapping with the PDO
  /// named; the PDOs read before stay.
  result<void, sdo_error> read_pdos() {
    pdos_.clear();
    for (const auto dir : {canopen::pdo::direction::rpdo, canopen::pdo::direction::tpdo}) {
      for (std::uint16_t n = 1; n <= 512U; ++n) {
        if (!dict_.contains({comm_index(dir, n), 1})) continue;
        auto p = read_pdo(dir, n);
        if (!p) return p.error();
        pdos_.push_back(p.value());
      }
    }
    return {};
  }

  /// Map objects into RPDO / TPDO `r.number` of the node (master::plan_pdo: the CiA 301
  /// sequence, checked against the dictionary before anything is sent), then read it back.
  /// Errors: invalid_argument / unknown_object / access_denied / bad_length / too_long (the
  /// plan's, nothing sent; `what` names the entry), those of the SDO writes.
  result<void, sdo_error> configure_pdo(master::pdo_request r) {
    r.node = node();
    master::pdo_sequence seq;
    auto plan = master::plan_pdo(dict_, r, seq);
    if (!plan) {
      sdo_error e(plan.error().code);
      e.address = plan.error().object;
      e.what = "node " + std::to_string(node()) + ", " + pdo_name(r.dir, r.number) + ": " +
               format_address(plan.error().object) + ": " +
               (plan.error().problem != canopen::pdo::mapping_problem::none
                    ? std::string(canopen::pdo::to_string(plan.error().problem))
                    : std::string(fieldcodec::to_string(plan.error().code))) +
               " (nothing sent)";
      return e;
    }
    for (const master::config_item &i : seq.items()) {
      if (auto w = sdo_.write(i.address, i.value); !w) return w.error();
    }
    auto p = read_pdo(r.dir, r.number);
    if (!p) return p.error();
    for (auto &q : pdos_) {
      if (q.dir == r.dir && q.number == r.number) {
        q = p.value();
        return {};
      }
    }
    pdos_.push_back(p.value());
    return {};
  }

  /// The PDOs read_pdos / configure_pdo found.
  [[nodiscard]] std::span<const remote_pdo> pdos() const noexcept { return pdos_; }
  /// RPDO or TPDO `n` (nullptr when not read).
  [[nodiscard]] const remote_pdo *pdo(canopen::pdo::direction d, std::uint16_t n) const noexcept {
    for (const auto &p : pdos_) {
      if (p.dir == d && p.number == n) return &p;
    }
    return nullptr;
  }
  /// The valid PDO in direction `d` that maps `a` (the lowest number), or nullptr.
  [[nodiscard]] const remote_pdo *mapping_of(canopen::pdo::direction d,
                                             od::address a) const noexcept {
    for (const auto &p : pdos_) {
      if (p.dir == d && p.valid && p.find(a) < p.map.size()) return &p;
    }
    return nullptr;
  }

  /// The address of the mapped object named `name` (the dictionary's name of the entry, ASCII
  /// case ignored; "6041h" or "6041h:00" work too). Errors: unknown_object (no PDO maps an
  /// object of that name), invalid_argument (two mapped objects have it: use the address).
  result<od::address, sdo_error> pdo_object(std::string_view name) const {
    if (auto a = parse_address(name)) return *a;
    std::optional<od::address> found;
    for (const auto &p : pdos_) {
      for (const auto &sl : p.map.slots()) {
        const od::address a{sl.index, sl.sub};
        const od::entry *e = dict_.find(a);
        if (e == nullptr || !same_name(dict_.info(*e).name.view(), name)) continue;
        if (found && *found != a) {
          return named_error(errc::invalid_argument, name,
                             "two mapped objects have this name (" + format_address(*found) + ", " +
                                 format_address(a) + "): give the address");
        }
        found = a;
      }
    }
    if (!found) return named_error(errc::unknown_object, name, "no PDO of the node maps it");
    return *found;
  }

  /// The value of `a` in the last TPDO received that maps it, in its unit (od::decode_value, as
  /// read). Errors: unknown_object (no valid TPDO maps it), bad_state (none received yet),
  /// those of the value.
  result<od::number, sdo_error> received(od::address a, od::value_options o = {}) const {
    auto b = received_bytes(a);
    if (!b) return b.error();
    auto u = with_units(b.value().d);
    if (!u) return u.error();
    auto v = od::decode_value(u.value(), b.value().span(), for_node(o));
    if (!v)
      return value_failed(u.value(), od::value_error{v.error()}, "cannot decode the PDO's value");
    return v.value();
  }
  result<od::number, sdo_error> received(std::string_view name, od::value_options o = {}) const {
    auto a = pdo_object(name);
    if (!a) return a.error();
    return received(a.value(), o);
  }
  /// The same as text (as read_text writes it).
  result<std::string, sdo_error> received_text(od::address a, od::value_options o = {}) const {
    auto b = received_bytes(a);
    if (!b) return b.error();
    auto u = with_units(b.value().d);
    if (!u) return u.error();
    auto t = host::format_value(u.value(), b.value().span(), for_node(o));
    if (!t)
      return value_failed(u.value(), od::value_error{t.error()}, "cannot show the PDO's value");
    return t.value();
  }
  result<std::string, sdo_error> received_text(std::string_view name,
                                               od::value_options o = {}) const {
    auto a = pdo_object(name);
    if (!a) return a.error();
    return received_text(a.value(), o);
  }

  /// Put `v` (meant in `o.unit`) for `a` into every valid RPDO that maps it, checked as write()
  /// checks (limits of this node, scale, field; the mapped length). Nothing is sent: send_pdo
  /// does. Errors: unknown_object (no valid RPDO maps it), the value's (nothing changed).
  result<void, sdo_error> set_pdo(od::address a, od::number v, od::value_options o = {}) {
    auto d = describe(a);
    if (!d) return d.error();
    auto u = with_units(d.value());
    if (!u) return u.error();
    std::array<std::uint8_t, 8> buf{};
    auto n = od::encode_value(u.value(), v, buf, for_node(o));
    if (!n) return value_failed(u.value(), n.error(), "refused");
    return put(u.value(), std::span<const std::uint8_t>(buf).first(n.value()));
  }
  /// The same with text, parsed as write(d, text) parses it.
  result<void, sdo_error> set_pdo(od::address a, std::string_view text, od::value_options o = {}) {
    auto d = describe(a);
    if (!d) return d.error();
    auto u = with_units(d.value());
    if (!u) return u.error();
    auto b = host::parse_value(u.value(), text, for_node(o));
    if (!b) return value_failed(u.value(), b.error(), "'" + std::string(text) + "' refused");
    return put(u.value(), b.value());
  }
  result<void, sdo_error> set_pdo(std::string_view name, od::number v, od::value_options o = {}) {
    auto a = pdo_object(name);
    if (!a) return a.error();
    return set_pdo(a.value(), v, o);
  }
  result<void, sdo_error> set_pdo(std::string_view name, std::string_view text,
                                  od::value_options o = {}) {
    auto a = pdo_object(name);
    if (!a) return a.error();
    return set_pdo(a.value(), text, o);
  }
  /// Send RPDO `n` with the values set_pdo put into it (zero where none was set). Errors:
  /// unknown_object (no RPDO n read), bad_state (RPDO n is not valid, or the bus failed).
  result<void, sdo_error> send_pdo(std::uint16_t n) {
    const remote_pdo *p = pdo(canopen::pdo::direction::rpdo, n);
    if (p == nullptr || !p->valid) {
      sdo_error e(p == nullptr ? errc::unknown_object : errc::bad_state);
      e.what = "node " + std::to_string(node()) + ", " +
               pdo_name(canopen::pdo::direction::rpdo, n) +
               (p == nullptr ? ": not read (read_pdos)" : ": not valid (COB-ID bit 31)");
      return e;
    }
    canopen::can_frame f;
    f.id = p->cob_id;
    f.dlc = static_cast<std::uint8_t>(p->map.bytes());
    f.data = p->data;
    if (!bus_->send(f)) {
      return bus_failed();
    }
    return {};
  }

  [[nodiscard]] std::uint8_t node() const noexcept { return sdo_.node(); }
  [[nodiscard]] od::dictionary dictionary() const noexcept { return dict_; }
  /// The SDO session the node's transfers run on (its options, its last error).
  [[nodiscard]] sdo_session &sdo() noexcept { return sdo_; }

private:
  static od::address at(const od::descriptor &d) noexcept { return {d.index, d.sub}; }

  od::value_options for_node(od::value_options o) const noexcept {
    o.node = sdo_.node();
    return o;
  }

  result<od::descriptor, sdo_error> describe(od::address a) const {
    auto d = dict_.at(a);
    if (d) return d.value();
    sdo_error e(errc::unknown_object);
    e.address = a;
    e.what = "node " + std::to_string(sdo_.node()) + ", " + format_address(a) +
             ": not in the node's dictionary (nothing sent)";
    return e;
  }

  /// `d` with its vendor unit (od::with_unit). Errors: invalid_argument (the rule does not fit
  /// the entry; nothing sent).
  result<od::unit_descriptor, sdo_error> with_units(const od::descriptor &d) const {
    auto u = od::with_unit(d, units_);
    if (u) return u.value();
    sdo_error e(u.error());
    e.address = at(d);
    e.what = "node " + std::to_string(sdo_.node()) + ", " + format_address(at(d)) +
             ": the vendor's unit does not fit the object: " + std::string(to_string(u.error()));
    return e;
  }

  sdo_error value_failed(const od::descriptor &d, const od::value_error &v,
                         const std::string &what) const {
    sdo_error e(v.code);
    e.address = at(d);
    e.value = v;
    e.what = "node " + std::to_string(sdo_.node()) + ", " + format_address(at(d)) + ": " + what +
             ": " + host::describe(v, d, for_node({}));
    return e;
  }

  /// The bytes read for `d`, cut to its size when an expedited upload padded them with zeros.
  result<std::span<const std::uint8_t>, sdo_error> value_bytes(const od::descriptor &d) {
    auto r = sdo_.read(at(d));
    if (!r) return r.error();
    std::span<const std::uint8_t> b = r.value();
    const std::uint32_t w = od::fixed_size(d.type);
    if (w == 0U || b.size() == w) return b;
    if (b.size() == 4U && w < 4U) { // expedited, size not indicated: the type decides
      bool zero = true;
      for (std::size_t i = w; i < b.size(); ++i) zero = zero && b[i] == 0U;
      if (zero) return b.first(w);
    }
    sdo_error e(errc::bad_length);
    e.address = at(d);
    e.what = "node " + std::to_string(sdo_.node()) + ", " + format_address(at(d)) + ": " +
             std::to_string(b.size()) + " bytes read, " + std::string(od::name(d.type)) + " has " +
             std::to_string(w) + (b.size() == 4U ? " (and the others are not zero)" : "");
    return e;
  }

  // ----- events and PDOs ---------------------------------------------------------------------

  static constexpr std::uint16_t comm_index(canopen::pdo::direction d, std::uint16_t n) noexcept {
    return static_cast<std::uint16_t>((d == canopen::pdo::direction::rpdo ? 0x1400U : 0x1800U) + n -
                                      1U);
  }
  static std::string pdo_name(canopen::pdo::direction d, std::uint16_t n) {
    return (d == canopen::pdo::direction::rpdo ? "RPDO " : "TPDO ") + std::to_string(n);
  }

  /// A number read by SDO as its raw unsigned value.
  result<std::uint64_t, sdo_error> read_raw(od::address a) {
    auto v = read(a, {.unit = od::value_unit::raw});
    if (!v) return v.error();
    auto u = v.value().to_uint64();
    if (!u)
      return value_failed(describe(a).value(), od::value_error{u.error()}, "not a raw number");
    return u.value();
  }

  result<remote_pdo, sdo_error> read_pdo(canopen::pdo::direction dir, std::uint16_t n) {
    remote_pdo p;
    p.dir = dir;
    p.number = n;
    const std::uint16_t comm = comm_index(dir, n);
    const auto map = static_cast<std::uint16_t>(comm + 0x200U);
    auto cob = read_raw({comm, 1});
    if (!cob) return cob.error();
    auto id = canopen::pdo::decode_cob_id(static_cast<std::uint32_t>(cob.value()));
    if (!id) return pdo_failed(p, id.error(), {comm, 1}, "COB-ID not an 11-bit identifier");
    p.cob_id = id.value().id;
    p.valid = id.value().valid;
    if (dict_.contains({comm, 2})) {
      auto t = read_raw({comm, 2});
      if (!t) return t.error();
      p.transmission = static_cast<std::uint8_t>(t.value());
    }
    if (!p.valid || !dict_.contains({map, 0})) return p;
    auto count = read_raw({map, 0});
    if (!count) return count.error();
    if (count.value() > canopen::pdo::max_entries) {
      return pdo_failed(p, errc::too_long, {map, 0}, "more than 64 entries");
    }
    std::array<canopen::pdo::mapping_entry, canopen::pdo::max_entries> entries{};
    for (std::size_t i = 0; i < count.value(); ++i) {
      const od::address a{map, static_cast<std::uint8_t>(i + 1U)};
      auto v = read_raw(a);
      if (!v) return v.error();
      entries[i] = canopen::pdo::mapping_entry::from_u32(static_cast<std::uint32_t>(v.value()));
    }
    const auto used = std::span<const canopen::pdo::mapping_entry>(entries).first(count.value());
    auto m = canopen::pdo::make_mapping(dict_, dir, used);
    if (!m) {
      const auto report = canopen::pdo::check_mapping(dict_, dir, used);
      const auto &bad = used[report.entry < used.size() ? report.entry : 0];
      return pdo_failed(p, m.error(), {bad.index, bad.sub},
                        "mapped: " + std::string(canopen::pdo::to_string(report.problem)));
    }
    p.map = m.value();
    return p;
  }

  sdo_error pdo_failed(const remote_pdo &p, errc c, od::address a, const std::string &what) const {
    sdo_error e(c);
    e.address = a;
    e.what = "node " + std::to_string(node()) + ", " + pdo_name(p.dir, p.number) + ", " +
             format_address(a) + ": " + what;
    return e;
  }

  sdo_error not_bytes(const od::descriptor &d) const {
    sdo_error e(errc::type_mismatch);
    e.address = at(d);
    e.what = "node " + std::to_string(node()) + ", " + format_address(at(d)) + ": " +
             std::string(od::name(d.type)) + " is no byte string: read or write its value";
    return e;
  }

  sdo_error bus_failed() const {
    sdo_error e(errc::bad_state);
    e.bus_failed = true;
    e.what = "node " + std::to_string(node()) + ": " + bus_->last_error().what;
    return e;
  }

  sdo_error named_error(errc c, std::string_view name, const std::string &what) const {
    sdo_error e(c);
    e.what = "node " + std::to_string(node()) + ", '" + std::string(name) + "': " + what;
    return e;
  }

  static bool same_name(std::string_view a, std::string_view b) noexcept {
    if (a.size() != b.size() || a.empty()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const auto lower = [](char c) {
        return c >= 'A' && c <= 'Z' ? static_cast<char>(c + 32) : c;
      };
      if (lower(a[i]) != lower(b[i])) return false;
    }
    return true;
  }

  /// "6041h" / "6041h:00" (hex, as format_address writes it); anything else is a name.
  static std::optional<od::address> parse_address(std::string_view t) noexcept {
    const auto hex = [](std::string_view s, std::uint32_t max) -> std::optional<std::uint32_t> {
      if (s.empty() || s.size() > 4U) return std::nullopt;
      std::uint32_t v = 0;
      for (char c : s) {
        const int d = c >= '0' && c <= '9'   ? c - '0'
                      : c >= 'a' && c <= 'f' ? c - 'a' + 10
                      : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                             : -1;
        if (d < 0) return std::nullopt;
        v = v * 16U + static_cast<std::uint32_t>(d);
      }
      if (v > max) return std::nullopt;
      return v;
    };
    const std::size_t h = t.find('h');
    if (h == std::string_view::npos || h != 4U) return std::nullopt;
    auto index = hex(t.substr(0, 4), 0xFFFFU);
    if (!index) return std::nullopt;
    std::uint32_t sub = 0;
    if (t.size() > 5U) {
      if (t[5] != ':' || t.size() != 8U) return std::nullopt;
      auto s = hex(t.substr(6), 0xFFU);
      if (!s) return std::nullopt;
      sub = *s;
    } else if (t.size() != 5U) {
      return std::nullopt;
    }
    return od::address{static_cast<std::uint16_t>(*index), static_cast<std::uint8_t>(sub)};
  }

  struct pdo_bytes {
    od::descriptor d;
    std::array<std::uint8_t, 8> b{};
    std::size_t n = 0;
    [[nodiscard]] std::span<const std::uint8_t> span() const noexcept {
      return std::span<const std::uint8_t>(b).first(n);
    }
  };

  /// The bytes of `a` in the last TPDO that carries it (zero-extended to the object's size).
  result<pdo_bytes, sdo_error> received_bytes(od::address a) const {
    auto d = describe(a);
    if (!d) return d.error();
    const remote_pdo *p = mapping_of(canopen::pdo::direction::tpdo, a);
    if (p == nullptr) {
      sdo_error e(errc::unknown_object);
      e.address = a;
      e.what = "node " + std::to_string(node()) + ", " + format_address(a) +
               ": no valid TPDO of the node maps it";
      return e;
    }
    if (!p->received) {
      sdo_error e(errc::bad_state);
      e.address = a;
      e.what = "node " + std::to_string(node()) + ", " + format_address(a) + ": " +
               pdo_name(p->dir, p->number) + " not received yet";
      return e;
    }
    const auto &sl = p->map[p->find(a)];
    auto raw = canopen::pdo::unpack(p->data, sl.offset, sl.bits);
    if (!raw) return pdo_failed(*p, raw.error(), a, "cannot unpack");
    pdo_bytes out{d.value()};
    const std::size_t w = od::fixed_size(d.value().type);
    out.n = w == 0U ? (sl.bits + 7U) / 8U : w;
    if (out.n > out.b.size()) return pdo_failed(*p, errc::bad_length, a, "longer than 8 bytes");
    for (std::size_t i = 0; i < out.n; ++i) {
      out.b[i] = static_cast<std::uint8_t>(i < 8U ? raw.value() >> (8U * i) : 0U);
    }
    return out;
  }

  /// Place the value's bytes `v` of `d` into every valid RPDO that maps it.
  result<void, sdo_error> put(const od::descriptor &d, std::span<const std::uint8_t> v) {
    std::uint64_t raw = 0;
    if (v.size() > 8U) return value_failed(d, od::value_error{errc::too_long}, "longer than a PDO");
    for (std::size_t i = v.size(); i-- > 0;) raw = (raw << 8U) | v[i];
    bool any = false;
    for (auto &p : pdos_) {
      if (p.dir != canopen::pdo::direction::rpdo || !p.valid) continue;
      const std::size_t i = p.find(at(d));
      if (i == p.map.size()) continue;
      auto copy = p.data;
      if (auto r = canopen::pdo::pack(copy, p.map[i].offset, p.map[i].bits, raw); !r) {
        return pdo_failed(p, r.error(), at(d),
                          "the value does not fit the " + std::to_string(p.map[i].bits) +
                              " mapped bits");
      }
      p.data = copy;
      any = true;
    }
    if (any) return {};
    sdo_error e(errc::unknown_object);
    e.address = at(d);
    e.what = "node " + std::to_string(node()) + ", " + format_address(at(d)) +
             ": no valid RPDO of the node maps it (nothing changed)";
    return e;
  }

  void push(node_event e) {
    if (events_.size() >= max_events) {
      events_.pop_front();
      ++dropped_;
    }
    events_.push_back(e);
  }
  void bad(const canopen::can_frame &f, errc c, std::uint32_t now) {
    node_event e;
    e.what = node_event::kind::bad_frame;
    e.time = now;
    e.code = c;
    e.frame = f;
    push(e);
  }

  /// A frame of the bus: the node's heartbeat, EMCY or TPDO becomes an event.
  void take(const canopen::can_frame &f, std::uint32_t now) {
    namespace co = canopen;
    if (f.rtr) return; // a node-guarding request, an RTR for a TPDO: the master's frames
    if (f.id == co::cob_id::nmt_error_base + node()) {
      auto hb = co::nmt::decode_heartbeat(f);
      if (!hb) return bad(f, hb.error(), now);
      const co::nmt::state s = hb.value().s;
      node_event e;
      e.time = now;
      e.state = s;
      if (hb.value().is_boot_up()) {
        e.what = node_event::kind::boot_up;
        push(e);
      } else if (!state_ || *state_ != s) {
        e.what = node_event::kind::state;
        push(e);
      }
      state_ = s;
      (void)consumer_.on_frame(f, now); // the heartbeat consumer: started, resumed after a loss
      for (const auto &c : consumer_.events()) {
        if (c.what != co::node::heartbeat_event::kind::resumed) continue;
        e.what = node_event::kind::heartbeat_resumed;
        push(e);
      }
      return;
    }
    if (f.id == co::cob_id::emcy_base + node()) {
      auto m = co::emcy::decode(f);
      if (!m) return bad(f, m.error(), now);
      emcy_ = m.value().m;
      ++emcy_count_;
      node_event e;
      e.what = node_event::kind::emcy;
      e.time = now;
      e.emcy = m.value().m;
      push(e);
      return;
    }
    for (auto &p : pdos_) {
      if (p.dir != co::pdo::direction::tpdo || !p.valid || p.cob_id != f.id) continue;
      if (f.dlc < p.map.bytes()) return bad(f, errc::bad_length, now); // CiA 301: too short
      p.data = f.data;
      p.received = true;
      p.time = now;
      node_event e;
      e.what = node_event::kind::pdo;
      e.time = now;
      e.pdo = p.number;
      push(e);
      return;
    }
  }

  void check_heartbeat(std::uint32_t now) {
    (void)consumer_.poll(now);
    for (const auto &c : consumer_.events()) {
      if (c.what != canopen::node::heartbeat_event::kind::lost) continue;
      node_event e;
      e.what = node_event::kind::heartbeat_lost;
      e.time = now;
      e.state = c.s;
      push(e);
    }
  }
  void poll_now() { check_heartbeat(now()); }

  status listen_once(std::chrono::milliseconds wait) {
    poll_now();
    auto r = bus_->receive(wait);
    if (r) take(r.value().frame, now());
    poll_now();
    if (!r && r.error() != errc::timeout) return r.error();
    return {};
  }

  step make(std::uint32_t now) const { return {{}, events_.size(), consumer_.deadline(now)}; }

  can_bus *bus_;
  od::dictionary dict_;
  std::span<const od::unit_rule> units_;
  sdo_session sdo_;
  std::vector<remote_pdo> pdos_;
  std::deque<node_event> events_;
  std::size_t dropped_ = 0;
  std::size_t emcy_count_ = 0;
  std::optional<canopen::nmt::state> state_{};
  std::optional<canopen::emcy::message> emcy_{};
  canopen::node::heartbeat_consumer<1> consumer_{};
};

} // namespace fieldcodec::host
