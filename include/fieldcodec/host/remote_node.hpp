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
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/host/bus.hpp>
#include <fieldcodec/host/sdo.hpp>
#include <fieldcodec/host/value_text.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/engineering.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/value_text.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::host {

class remote_node {
public:
  /// Node `node` (1..127) on `bus`, its objects described by `dict` (a generated header's
  /// `dictionary`, or the view of a dictionary loaded at run time), with the units and scales
  /// a vendor supplies for objects the dictionary file cannot describe (`units`, the device
  /// folder's od::unit_rule table; od::with_unit applies them to every descriptor used). The bus,
  /// the dictionary's tables and the rules must outlive the node.
  remote_node(can_bus &bus, std::uint8_t node, od::dictionary dict,
              std::span<const od::unit_rule> units = {}, sdo_options o = {})
      : dict_(dict), units_(units), sdo_(bus, node, o) {}

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

  od::dictionary dict_;
  std::span<const od::unit_rule> units_;
  sdo_session sdo_;
};

} // namespace fieldcodec::host
