// fieldcodec — canopen::object_store, the values of a node's objects as the SDO server, the PDO
// engine and the node read and write them, and canopen::dictionary_store, a store over an
// od::dictionary with caller-owned storage. Its answers are CiA 301 abort codes
// (canopen/abort_code.hpp).
//
// A store serves values in parts (offset + chunk) so that no buffer of the server caps the size
// of an object, and it never shows a value half-written: a value becomes visible only when the
// last part of its transfer arrives. A store is anything with
//
//   sdo::abort_code read(od::address a, std::size_t offset, std::span<std::uint8_t> out,
//                        std::size_t &total) const;
//       copies min(out.size(), total − offset) bytes of the value from `offset` and sets
//       `total` to the value's length now;
//   sdo::abort_code begin_write(od::address a, std::optional<std::uint32_t> size);
//       a download of `size` bytes (if known) is about to start: may it? (early aborts:
//       no object, read-only, length);
//   sdo::abort_code write(od::address a, std::size_t offset, std::span<const std::uint8_t> part,
//                         bool last);
//       a part of the value, in order from offset 0; with `last` the value is complete and
//       becomes visible (or is refused, and the old value stays);
//
// each answering sdo::abort_code::none on success. The SDO server passes a value that fits its
// buffer as one part (offset 0, last), so a store without a staging area still takes every
// object up to the server's buffer size.
//
// A store may also name its objects by position, so that a caller that reaches the same objects
// again and again (the PDO engine, at every SYNC and RPDO) looks each one up once
// (canopen::positioned_store; optional, detected at compile time):
//
//   std::size_t position(od::address a) const;      // canopen::no_position when there is no `a`
//   od::address address_at(std::size_t at) const;   // the address position() named
//   sdo::abort_code read_at(std::size_t at, std::size_t offset, std::span<std::uint8_t> out,
//                           std::size_t &total) const;
//   sdo::abort_code write_at(std::size_t at, std::size_t offset,
//                            std::span<const std::uint8_t> part, bool last);
//
// read_at / write_at with at = position(a) do exactly what read / write of `a` do (same checks,
// same abort codes, same hook); a position stays valid as long as the store.
//
// A positioned store may also show where plain values live, so that the PDO engine compiles a
// mapping into copies between its storage and the frame (canopen::plain_store; optional, detected
// at compile time):
//
//   std::span<std::uint8_t> plain_storage();            // the bytes plain values live in
//   canopen::plain_slot plain_at(std::size_t at) const;     // where the value at `at` lives there
//
// A plain_slot of `size` bytes (size 0: not plain) at `offset` in plain_storage() promises, for
// as long as the store lives: `readable` — read_at(at, 0, out, total) with out.size() == size
// answers none and copies exactly these bytes, which are therefore the value in CANopen order
// (little-endian, whatever the host's order); `writable` — write_at(at, 0, v, true) with
// v.size() == size answers none for every v and has no effect but storing v's bytes there as
// they are (no check that could refuse, no conversion, no hook). Slots of different positions
// do not overlap.
#pragma once

#include <fieldcodec/canopen/abort_code.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/value.hpp>
#include <fieldcodec/od/value_kinds.hpp>

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>

namespace fieldcodec::canopen {

template <class S>
concept object_store = requires(S &s, const S &cs, od::address a, std::size_t offset,
                                std::span<std::uint8_t> out, std::span<const std::uint8_t> in,
                                std::optional<std::uint32_t> size, std::size_t &total, bool last) {
  { cs.read(a, offset, out, total) } -> std::same_as<sdo::abort_code>;
  { s.begin_write(a, size) } -> std::same_as<sdo::abort_code>;
  { s.write(a, offset, in, last) } -> std::same_as<sdo::abort_code>;
};

/// What position() answers for an address the store does not have.
inline constexpr std::size_t no_position = static_cast<std::size_t>(-1);

/// An object store that also reads and writes by position (see above): position(a) once, then
/// read_at / write_at without looking `a` up again.
template <class S>
concept positioned_store = object_store<S> &&
    requires(S &s, const S &cs, od::address a, std::size_t at, std::size_t offset,
             std::span<std::uint8_t> out, std::span<const std::uint8_t> in, std::size_t &total,
             bool last) {
  { cs.position(a) } -> std::same_as<std::size_t>;
  { cs.address_at(at) } -> std::same_as<od::address>;
  { cs.read_at(at, offset, out, total) } -> std::same_as<sdo::abort_code>;
  { s.write_at(at, offset, in, last) } -> std::same_as<sdo::abort_code>;
};

/// Where a store keeps a plain value (canopen::plain_store; see above): `size` bytes at `offset` in
/// plain_storage(), read and / or written there as they are. size 0: not plain (use read_at /
/// write_at).
struct plain_slot {
  std::uint32_t offset = 0;
  std::uint8_t size = 0;
  bool readable = false; ///< read_at copies these bytes and cannot fail
  bool writable = false; ///< write_at of `size` bytes stores them here, accepts every value
  friend constexpr bool operator==(const plain_slot &, const plain_slot &) = default;
};

/// A positioned store that shows where its plain values live (see above).
template <class S>
concept plain_store = positioned_store<S> && requires(S &s, const S &cs, std::size_t at) {
  { s.plain_storage() } -> std::same_as<std::span<std::uint8_t>>;
  { cs.plain_at(at) } -> std::same_as<plain_slot>;
};

// ---------------------------------------------------------------------------------------------
// The layout of a dictionary's values in storage

/// Bytes a byte string's slot spends on its current length (little-endian u32 before the data).
inline constexpr std::size_t length_prefix = 4;

/// Bytes of storage entry `e` needs: width() for fixed-size types; for byte strings the length
/// prefix plus the capacity (0 when the entry declares none: it cannot be stored).
[[nodiscard]] constexpr std::size_t slot_size(const od::entry &e) noexcept {
  if (!od::is_byte_string(e.type)) return e.width();
  const std::uint32_t capacity = e.capacity();
  return capacity == 0U ? 0U : length_prefix + capacity;
}

/// What a store tests at every access of an entry (slot_flags).
namespace slot_flag {
inline constexpr std::uint8_t readable = 0x01U;    ///< od::readable(access_type)
inline constexpr std::uint8_t writable = 0x02U;    ///< od::writable(access_type)
inline constexpr std::uint8_t byte_string = 0x04U; ///< od::is_byte_string(type)
/// Every bit pattern of width() bytes is a valid value, so a write needs no value check
/// (od::decode cannot refuse it): integers (not BOOLEAN) without limits and without a scale.
inline constexpr std::uint8_t any_bits = 0x08U;
} // namespace slot_flag

/// The slot_flag bits of `e`.
[[nodiscard]] constexpr std::uint8_t slot_flags(const od::entry &e) noexcept {
  std::uint8_t f = 0;
  if (od::readable(e.access_type)) f |= slot_flag::readable;
  if (od::writable(e.access_type)) f |= slot_flag::writable;
  if (od::is_byte_string(e.type)) f |= slot_flag::byte_string;
  if (od::is_integer(e.type) && !e.has(od::flag::has_low) && !e.has(od::flag::has_high) &&
      !e.has(od::flag::scaled)) {
    f |= slot_flag::any_bits;
  }
  return f;
}

/// Where each entry's value starts in storage: offsets[i] for entry i in dictionary order,
/// offsets[N] the total size. Computed once (at compile time for a generated dictionary), so a
/// store finds a slot in O(1) after the dictionary's binary search (none by position).
/// `Offset`: the offsets' type; std::uint16_t halves the table of a dictionary whose values
/// take less than 64 kB (make_layout leaves a layout whose total does not fit empty).
template <std::size_t N, class Offset = std::uint32_t>
struct store_layout {
  static_assert(std::is_same_v<Offset, std::uint32_t> || std::is_same_v<Offset, std::uint16_t>);
  std::array<Offset, N + 1> offsets{};
  [[nodiscard]] constexpr std::size_t storage_size() const noexcept { return offsets[N]; }
};

/// The layout of `dict` written into `offsets` (dict.size() + 1 of them: where each entry's value
/// starts, then the total size), for a dictionary loaded at run time. False when `offsets` has
/// another size (nothing written) or the total does not fit an offset (all zero).
template <class Offset>
[[nodiscard]] constexpr bool make_layout(od::dictionary dict, std::span<Offset> offsets) noexcept {
  if (offsets.size() != dict.size() + 1U) return false;
  std::size_t at = 0;
  for (std::size_t i = 0; i < dict.size(); ++i) {
    offsets[i] = static_cast<Offset>(at);
    at += slot_size(dict.entries()[i]);
  }
  offsets[dict.size()] = static_cast<Offset>(at);
  if (at <= std::numeric_limits<Offset>::max()) return true;
  std::fill(offsets.begin(), offsets.end(), Offset{0});
  return false;
}
[[nodiscard]] constexpr bool make_layout(od::dictionary dict,
                                         std::span<std::uint32_t> offsets) noexcept {
  return make_layout<std::uint32_t>(dict, offsets);
}

/// The layout of `dict`, which must have exactly N entries and, with Offset std::uint16_t,
/// values of less than 64 kB (a mismatch leaves the layout empty: every access then answers
/// general_error).
template <std::size_t N, class Offset = std::uint32_t>
[[nodiscard]] constexpr store_layout<N, Offset> make_layout(od::dictionary dict) noexcept {
  store_layout<N, Offset> l;
  (void)make_layout(dict, std::span<Offset>(l.offsets));
  return l;
}

/// The write hook of a store that takes every valid value.
struct accept_writes {
  [[nodiscard]] constexpr sdo::abort_code operator()(const od::entry &,
                                                     std::span<const std::uint8_t>) const noexcept {
    return sdo::abort_code::none;
  }
};

// ---------------------------------------------------------------------------------------------
// An object store over a dictionary

/// Stores the values of every entry of an od::dictionary in caller-owned bytes laid out by a
/// store_layout: fixed-size values little-endian, byte strings (VISIBLE_STRING, OCTET_STRING,
/// UNICODE_STRING, DOMAIN) with their current length and a capacity of `entry.capacity()` bytes.
///
/// Writes (by SDO now, by RPDO through the same `write`) are checked — access type, length
/// (exact for fixed-size types, at most the capacity for byte strings), limits, and the rules
/// of od::decode / od::decode_bytes — and then offered to the write hook `OnWrite`:
///   sdo::abort_code on_write(const od::entry &e, std::span<const std::uint8_t> value)
/// which sees the complete new value before anyone else and may refuse it with an abort code
/// (the old value stays). A value is stored only when complete: a value that arrives in several
/// parts (larger than the SDO server's buffer) is collected in the caller-owned `staging` area
/// and copied when its last part has passed the checks and the hook; without a staging area (or
/// with one too small) such a value is refused with 0x05040005 (out of memory).
///
/// `Kinds`: the kinds of values the store serves (od/value_kinds.hpp; a generated dictionary's
/// `kinds`). Only their checks and conversions are compiled: a store of an integer-only
/// dictionary links no floating point and no 64-bit division. A dictionary with a kind `Kinds`
/// lacks does not fit (as a layout of another dictionary does not): every access answers
/// general_error, init_defaults buffer_too_small.
///
/// `Offset`: the type of the layout's offsets (store_layout).
template <class OnWrite = accept_writes, od::value_kinds Kinds = od::all_kinds,
          class Offset = std::uint32_t>
class dictionary_store {
public:
  template <std::size_t N>
  constexpr dictionary_store(od::dictionary dict, const store_layout<N, Offset> &layout,
                             std::span<std::uint8_t> storage, std::span<std::uint8_t> staging = {},
                             OnWrite on_write = {}) noexcept
      : dict_(dict), offsets_(layout.offsets), storage_(storage), staging_(staging),
        on_write_(on_write),
        fits_(offsets_.size() == dict_.size() + 1U && offsets_.back() <= storage_.size() &&
              slots_agree(dict, layout.offsets) &&
              od::covers(Kinds, od::kinds_of(dict.entries()))) {}
  /// The same with a layout made at run time (make_layout(dict, offsets), for a dictionary
  /// loaded at run time); `offsets` is borrowed and must outlive the store.
  constexpr dictionary_store(od::dictionary dict, std::span<const Offset> offsets,
                             std::span<std::uint8_t> storage, std::span<std::uint8_t> staging = {},
                             OnWrite on_write = {}) noexcept
      : dict_(dict), offsets_(offsets), storage_(storage), staging_(staging), on_write_(on_write),
        fits_(offsets_.size() == dict_.size() + 1U && offsets_.back() <= storage_.size() &&
              slots_agree(dict, offsets) && od::covers(Kinds, od::kinds_of(dict.entries()))) {}

  /// The kinds of values this store serves.
  static constexpr od::value_kinds kinds = Kinds;

  /// Bytes of storage `dict` needs.
  [[nodiscard]] static constexpr std::size_t storage_size(od::dictionary dict) noexcept {
    std::size_t n = 0;
    for (const auto &e : dict) n += slot_size(e);
    return n;
  }

  /// Fill every slot with the entry's default for `node` (node-ID relative defaults resolved):
  /// numbers from the numeric default; without one, or with one outside the entry's limits,
  /// zero, or the limit nearest to zero when zero is outside them; byte strings from the default
  /// text (its length is the value's length). Errors: buffer_too_small (storage or layout do not
  /// fit the dictionary), too_long (a default text longer than its entry's capacity: cut, the
  /// other entries are filled).
  [[nodiscard]] constexpr status init_defaults(std::uint8_t node) noexcept {
    if (!layout_fits()) return errc::buffer_too_small;
    node_ = node;
    status result{};
    for (std::size_t i = 0; i < dict_.size(); ++i) {
      if (!fill_default(i)) result = errc::too_long;
    }
    return result;
  }

  /// Set the entries of objects `first`..`last` that the network can write (access rw, wo,
  /// rwr, rww) back to their defaults for node(), as init_defaults() does: what an NMT reset
  /// does to the communication area (1000h–1FFFh) and the application area (2000h–FFFFh).
  /// Read-only and constant entries keep their values (the identity, names and versions the
  /// application gave them; 1001h and 1003h are the node's). No write hook is asked.
  /// Errors: as init_defaults.
  [[nodiscard]] constexpr status restore_defaults(std::uint16_t first,
                                                  std::uint16_t last) noexcept {
    if (!layout_fits()) return errc::buffer_too_small;
    status result{};
    for (std::size_t i = 0; i < dict_.size(); ++i) {
      const od::entry &e = dict_.entries()[i];
      if (e.index < first || e.index > last || !od::writable(e.access_type)) continue;
      if (!fill_default(i)) result = errc::too_long;
    }
    return result;
  }

  /// A new node-ID (an LSS master configured one, CiA 305; it takes effect at the NMT reset
  /// that follows): the entries that no reset restores (read-only and constant ones) and whose
  /// default is node-ID-relative ($NODEID) get their default for `node` now; the writable ones
  /// get it at the next restore_defaults() of their range, which resolves for `node` from now
  /// on. Errors: as init_defaults.
  [[nodiscard]] constexpr status set_node(std::uint8_t node) noexcept {
    if (!layout_fits()) return errc::buffer_too_small;
    node_ = node;
    status result{};
    for (std::size_t i = 0; i < dict_.size(); ++i) {
      const od::entry &e = dict_.entries()[i];
      if (!e.has(od::flag::default_nodeid) || od::writable(e.access_type)) continue;
      if (!fill_default(i)) result = errc::too_long;
    }
    return result;
  }

  [[nodiscard]] constexpr sdo::abort_code read(od::address a, std::size_t offset,
                                               std::span<std::uint8_t> out,
                                               std::size_t &total) const noexcept {
    return read_located(locate(a), offset, out, total);
  }

  [[nodiscard]] constexpr sdo::abort_code begin_write(od::address a,
                                                      std::optional<std::uint32_t> size) noexcept {
    const located l = locate(a);
    if (l.code != sdo::abort_code::none) return l.code;
    if ((l.flags & slot_flag::writable) == 0U) return sdo::abort_code::write_read_only;
    staged_ = 0;
    staged_address_ = a;
    if (!size) return sdo::abort_code::none;
    // width(): a byte string's capacity, which it may fill up to
    if (*size > l.e->width()) return sdo::abort_code::length_too_high;
    if (*size < l.e->width() && (l.flags & slot_flag::byte_string) == 0U) {
      return sdo::abort_code::length_too_low;
    }
    return sdo::abort_code::none;
  }

  /// Out of line (g++, clang): an SDO server inlines the flush of its buffer, a call of write,
  /// into its segment loop, and with the whole of write inlined there g++ stopped inlining that
  /// loop (block download: +20 % Ir). write_at, the PDO engine's, keeps it inline.
  [[nodiscard, gnu::noinline]] constexpr sdo::abort_code
  write(od::address a, std::size_t offset, std::span<const std::uint8_t> part, bool last) noexcept {
    return write_located(locate(a), a, offset, part, last);
  }

  // ----- by position (canopen::positioned_store): the entry's position in dictionary() ---------

  /// The position of `a` in dictionary(), no_position when the dictionary has no `a`.
  [[nodiscard]] constexpr std::size_t position(od::address a) const noexcept {
    const std::size_t i = dict_.position(a);
    return i < dict_.size() ? i : no_position;
  }
  /// The address of the entry at position `at` (which position() gave).
  [[nodiscard]] constexpr od::address address_at(std::size_t at) const noexcept {
    const od::entry &e = dict_.entries()[at];
    return {e.index, e.sub};
  }
  /// read() of the entry at `at`, without looking it up. A position that is not one
  /// (no_position, past the dictionary) answers no_object.
  [[nodiscard]] constexpr sdo::abort_code read_at(std::size_t at, std::size_t offset,
                                                  std::span<std::uint8_t> out,
                                                  std::size_t &total) const noexcept {
    return read_located(locate_at(at), offset, out, total);
  }
  /// write() of the entry at `at`, without looking it up (same checks, same hook).
  [[nodiscard]] constexpr sdo::abort_code write_at(std::size_t at, std::size_t offset,
                                                   std::span<const std::uint8_t> part,
                                                   bool last) noexcept {
    const located l = locate_at(at);
    if (l.code != sdo::abort_code::none) return l.code;
    return write_located(l, {l.e->index, l.e->sub}, offset, part, last);
  }

  // ----- plain values (canopen::plain_store) ---------------------------------------------------

  /// The caller-owned storage: fixed-size values are kept there little-endian (CANopen order)
  /// on every host, as they arrive, so a plain_at slot is the value's bytes.
  [[nodiscard]] constexpr std::span<std::uint8_t> plain_storage() noexcept { return storage_; }
  /// Where the value at position `at` lives in plain_storage(), when read_at / write_at would
  /// only copy it: a fixed-size value (byte strings carry a length; size 0 for them, for a
  /// position that is not one and for a layout that does not fit), readable when the entry is,
  /// writable when the entry is writable, takes any bits (an integer without limits or scale:
  /// no od::decode check) and the store has no write hook (OnWrite is accept_writes).
  [[nodiscard]] constexpr plain_slot plain_at(std::size_t at) const noexcept {
    plain_slot p;
    if (at >= dict_.size() || !layout_fits()) return p;
    const std::uint8_t f = slot_flags(dict_.entries()[at]);
    if ((f & slot_flag::byte_string) != 0U) return p;
    p.offset = offsets_[at];
    p.size = static_cast<std::uint8_t>(slot_at(at).size()); // width(): 1..8
    p.readable = (f & slot_flag::readable) != 0U;
    p.writable = std::is_same_v<OnWrite, accept_writes> && (f & slot_flag::writable) != 0U &&
                 (f & slot_flag::any_bits) != 0U;
    return p;
  }

  /// The application's side: the current value of `a` (fixed-size: width() bytes; byte
  /// strings: the length written). Errors: unknown_object, access_denied (no storage).
  [[nodiscard]] constexpr result<std::span<const std::uint8_t>>
  value(od::address a) const noexcept {
    const located l = locate(a);
    if (l.code == sdo::abort_code::unsupported_access) return errc::access_denied;
    if (l.code != sdo::abort_code::none) return errc::unknown_object;
    return current(l);
  }
  /// Would an SDO write of the whole `value` to `a` be stored? The checks of write — access
  /// type, length, type, limits — without the write hook; nothing is stored. Returns none or the
  /// abort code the write would get (node::device asks it before an object's own write hook).
  [[nodiscard]] constexpr sdo::abort_code check(od::address a,
                                                std::span<const std::uint8_t> value) noexcept {
    const located l = locate(a);
    if (l.code != sdo::abort_code::none) return l.code;
    if ((l.flags & slot_flag::writable) == 0U) return sdo::abort_code::write_read_only;
    return store<false>(l, value, false);
  }
  /// The application sets a value (also of read-only objects): the same checks as an SDO write
  /// except access type, no write hook. Returns none or the abort code an SDO write would get.
  [[nodiscard]] constexpr sdo::abort_code set(od::address a,
                                              std::span<const std::uint8_t> value) noexcept {
    const located l = locate(a);
    if (l.code != sdo::abort_code::none) return l.code;
    return store(l, value, false);
  }

  [[nodiscard]] constexpr od::dictionary dictionary() const noexcept { return dict_; }
  /// The node-ID init_defaults() resolved relative values for.
  [[nodiscard]] constexpr std::uint8_t node() const noexcept { return node_; }
  [[nodiscard]] constexpr OnWrite &hook() noexcept { return on_write_; }

private:
  struct located {
    sdo::abort_code code = sdo::abort_code::none;
    const od::entry *e = nullptr;
    std::span<std::uint8_t> slot{};
    std::uint8_t flags = 0; ///< slot_flag bits
    std::size_t at = 0;     ///< position in the dictionary
  };

  [[nodiscard]] constexpr sdo::abort_code read_located(const located &l, std::size_t offset,
                                                       std::span<std::uint8_t> out,
                                                       std::size_t &total) const noexcept {
    if (l.code != sdo::abort_code::none) return l.code;
    if ((l.flags & slot_flag::readable) == 0U) return sdo::abort_code::read_write_only;
    const auto v = current(l);
    if (offset > v.size()) return sdo::abort_code::general_error;
    const std::size_t n = v.size() - offset < out.size() ? v.size() - offset : out.size();
    fieldcodec::copy_bytes(v.data() + offset, out.data(), n);
    total = v.size();
    return sdo::abort_code::none;
  }

  [[nodiscard]] constexpr sdo::abort_code write_located(const located &l, od::address a,
                                                        std::size_t offset,
                                                        std::span<const std::uint8_t> part,
                                                        bool last) noexcept {
    if (l.code != sdo::abort_code::none) return l.code;
    if ((l.flags & slot_flag::writable) == 0U) return sdo::abort_code::write_read_only;
    if (offset == 0U && last) return store(l, part, true);
    if (offset == 0U) {
      staged_ = 0;
      staged_address_ = a;
    }
    if (staged_address_ != a || offset != staged_) return sdo::abort_code::general_error;
    if (offset + part.size() > l.e->width()) { // a byte string's width() is its capacity
      return sdo::abort_code::length_too_high;
    }
    if (offset + part.size() > staging_.size()) return sdo::abort_code::out_of_memory;
    for (std::size_t i = 0; i < part.size(); ++i) staging_[offset + i] = part[i];
    staged_ = offset + part.size();
    if (!last) return sdo::abort_code::none;
    const std::size_t n = staged_;
    staged_ = 0;
    return store(l, std::span<const std::uint8_t>(staging_).first(n), true);
  }

  [[nodiscard]] constexpr bool layout_fits() const noexcept { return fits_; }
  /// Entry i's slot in storage (the layout fits).
  [[nodiscard]] constexpr std::span<std::uint8_t> slot_at(std::size_t i) const noexcept {
    const std::size_t at = offsets_[i];
    return storage_.subspan(at, std::size_t{offsets_[i + 1U]} - at);
  }

  /// The layout's slots are the entries' (make_layout's): a layout of another dictionary, or
  /// one built by hand with other sizes, does not fit — every access answers general_error and
  /// init_defaults buffer_too_small, rather than a slot too small for its value.
  template <std::size_t N>
  [[nodiscard]] static constexpr bool slots_agree(od::dictionary dict,
                                                  const std::array<Offset, N> &offsets) noexcept {
    return slots_agree(dict, std::span<const Offset>(offsets));
  }
  [[nodiscard]] static constexpr bool slots_agree(od::dictionary dict,
                                                  std::span<const Offset> offsets) noexcept {
    const std::size_t n = offsets.size();
    if (dict.size() + 1U != n) return false;
    for (std::size_t i = 0; i + 1U < n; ++i) {
      if (offsets[i + 1U] < offsets[i] ||
          std::size_t{offsets[i + 1U]} - offsets[i] != slot_size(dict.entries()[i])) {
        return false;
      }
    }
    return true;
  }

  /// The scale of the entry at position i (the identity without a scale table).
  [[nodiscard]] constexpr const scaling::linear &scale_at(std::size_t i) const noexcept {
    return i < dict_.scales().size() ? dict_.scales()[i] : identity_;
  }
  static constexpr scaling::linear identity_{};

  /// Entry i's default for node_ into its slot; false when a default text had to be cut.
  constexpr bool fill_default(std::size_t i) noexcept {
    const od::entry &e = dict_.entries()[i];
    const auto slot = slot_at(i);
    std::fill(slot.begin(), slot.end(), std::uint8_t{0});
    if (od::is_byte_string(e.type)) {
      if (slot.empty()) return true;
      const od::text t = e.default_text();
      const std::uint32_t capacity = e.capacity();
      std::size_t n = t.size();
      const bool fits = n <= capacity;
      if (!fits) n = capacity;
      for (std::size_t k = 0; k < n; ++k) {
        slot[length_prefix + k] = static_cast<std::uint8_t>(t[k]);
      }
      set_length(slot, n);
      return fits;
    }
    if (slot.empty()) return true;
    if (e.has(od::flag::has_default)) {
      if (e.has(od::flag::default_number)) {
        if constexpr (Kinds.numbers) {
          if (auto d = e.default_for(node_)) {
            (void)od::detail::encode(e, od::detail::maybe_scale{&scale_at(i), true}, d.value(),
                                     slot, byte_order::little, node_);
          }
        }
      } else if (slot.size() == od::fixed_size(e.type)) {
        // in the entry's own width: the value's bytes as CANopen sends them
        copy_packed(e.extra + e.default_at(), slot);
        if (e.has(od::flag::default_nodeid) && !plus_node(e, slot)) {
          std::fill(slot.begin(), slot.end(), std::uint8_t{0});
        }
      }
    }
    within_limits(i, slot);
    return true;
  }

  /// Whether entry i's own checks accept what `slot` holds.
  [[nodiscard]] constexpr bool accepted(std::size_t i,
                                        std::span<const std::uint8_t> slot) const noexcept {
    return od::check_value<Kinds>(dict_.entries()[i], scale_at(i), slot, node_) ==
           od::value_check::ok;
  }

  /// Keep entry i's slot within its own limits: a default it refuses (out of its limits, or
  /// beyond its field for this node) or no default at all leaves zero when the entry accepts
  /// zero, else the limit nearest to zero (a low limit above zero, or a high limit below it). The
  /// store never holds a value its own checks refuse: a write-only 1..8 parameter without a default
  /// held 0 (fuzz/FINDINGS.md F25).
  constexpr void within_limits(std::size_t i, std::span<std::uint8_t> slot) noexcept {
    if (accepted(i, slot)) return;
    std::fill(slot.begin(), slot.end(), std::uint8_t{0});
    if constexpr (Kinds.limits) {
      const od::entry &e = dict_.entries()[i];
      const od::value_check zero = od::check_value<Kinds>(e, scale_at(i), slot, node_);
      if (zero == od::value_check::ok) return;
      // zero above the high limit: the high one is nearest; below the low limit: the low one
      const bool high_first = zero == od::value_check::too_high;
      for (const bool second : {false, true}) {
        const bool high = second != high_first;
        if (!e.has(high ? od::flag::has_high : od::flag::has_low)) continue;
        if (e.has(od::flag::limits_number)) {
          if constexpr (Kinds.numbers) {
            const auto l = high ? e.high_for(node_) : e.low_for(node_);
            if (!l || !od::detail::encode(e, od::detail::maybe_scale{&scale_at(i), true}, l.value(),
                                          slot, byte_order::little, node_)) {
              continue;
            }
          } else {
            continue;
          }
        } else {
          if (slot.size() != od::fixed_size(e.type)) continue;
          const std::size_t at =
              e.limits_at() + (high && e.has(od::flag::has_low) ? e.limit_size() : 0U);
          copy_packed(e.extra + at, slot);
          if (e.has(high ? od::flag::high_nodeid : od::flag::low_nodeid) && !plus_node(e, slot)) {
            continue; // (the slot is written again below)
          }
        }
        if (accepted(i, slot)) return;
      }
      std::fill(slot.begin(), slot.end(), std::uint8_t{0});
    }
  }

  /// A packed value in its entry's own width (slot.size() bytes at `p`, little-endian) into
  /// `slot` as it is.
  static constexpr void copy_packed(const char *p, std::span<std::uint8_t> slot) noexcept {
    for (std::size_t k = 0; k < slot.size(); ++k) slot[k] = static_cast<std::uint8_t>(p[k]);
  }

  /// A node-ID-relative value: node_ added to the little-endian integer in `slot`, byte by
  /// byte (no arithmetic wider than the bytes). False when the entry is no integer or the sum
  /// does not fit its field (the slot then holds no value: the caller writes it again).
  [[nodiscard]] constexpr bool plus_node(const od::entry &e,
                                         std::span<std::uint8_t> slot) const noexcept {
    const bool is_signed = od::is_signed_integer(e.type);
    if (!is_signed && !od::is_unsigned_integer(e.type)) return false;
    const bool was_negative = (slot.back() & 0x80U) != 0U;
    unsigned carry = node_;
    for (std::uint8_t &b : slot) {
      carry += b;
      b = static_cast<std::uint8_t>(carry);
      carry >>= 8U;
    }
    // unsigned: no carry out of the top byte; signed (node_ >= 0): no turn from >= 0 to < 0
    return is_signed ? was_negative || (slot.back() & 0x80U) == 0U : carry == 0U;
  }

  [[nodiscard]] constexpr located locate(od::address a) const noexcept {
    const std::size_t i = dict_.position(a);
    if (i >= dict_.size()) {
      located l;
      l.code = dict_.object(a.index).empty() ? sdo::abort_code::no_object
                                             : sdo::abort_code::no_sub_index;
      return l;
    }
    return locate_at(i);
  }
  /// The entry at position i (no_object when i is past the dictionary).
  [[nodiscard]] constexpr located locate_at(std::size_t i) const noexcept {
    located l;
    if (i >= dict_.size()) {
      l.code = sdo::abort_code::no_object;
      return l;
    }
    l.e = &dict_.entries()[i];
    if (!layout_fits()) {
      l.code = sdo::abort_code::general_error;
      return l;
    }
    l.slot = slot_at(i);
    l.flags = slot_flags(*l.e);
    l.at = i;
    if (l.slot.empty()) l.code = sdo::abort_code::unsupported_access; // a byte string without size
    return l;
  }

  [[nodiscard]] static constexpr std::size_t
  length_of(std::span<const std::uint8_t> slot) noexcept {
    return static_cast<std::size_t>(load_le(slot.data(), length_prefix));
  }
  static constexpr void set_length(std::span<std::uint8_t> slot, std::size_t n) noexcept {
    store_le(slot.data(), n, length_prefix);
  }
  [[nodiscard]] static constexpr std::span<const std::uint8_t> current(const located &l) noexcept {
    if ((l.flags & slot_flag::byte_string) == 0U) return l.slot;
    std::size_t n = length_of(l.slot);
    if (n > l.slot.size() - length_prefix) n = l.slot.size() - length_prefix;
    return std::span<const std::uint8_t>(l.slot).subspan(length_prefix, n);
  }

  /// Check a complete value, ask the hook (SDO/RPDO writes), then store it (`Commit`; else
  /// only the checks: check()).
  template <bool Commit = true>
  [[nodiscard]] constexpr sdo::abort_code
  store(const located &l, std::span<const std::uint8_t> data, bool ask_hook) noexcept {
    const od::entry &e = *l.e;
    if ((l.flags & slot_flag::byte_string) != 0U) {
      const std::uint32_t capacity = e.capacity();
      if (data.size() > capacity) return sdo::abort_code::length_too_high;
      auto v = od::decode_bytes(e, data);
      if (!v) {
        return v.error() == errc::too_long ? sdo::abort_code::length_too_high
                                           : sdo::abort_code::invalid_value;
      }
      if constexpr (!Commit) return sdo::abort_code::none;
      if (ask_hook) {
        if (const auto c = on_write_(e, v.value()); c != sdo::abort_code::none) return c;
      }
      const auto value = v.value(); // visible strings: trailing NULs cut
      // whole runs (a memmove and a memset at run time): a block download stores hundreds of
      // bytes at once (docs/performance.md, "Services")
      const auto out = l.slot.subspan(length_prefix);
      std::copy(value.begin(), value.end(), out.begin());
      std::fill(out.begin() + static_cast<std::ptrdiff_t>(value.size()),
                out.begin() + static_cast<std::ptrdiff_t>(capacity), std::uint8_t{0});
      set_length(l.slot, value.size());
      return sdo::abort_code::none;
    }
    if (data.size() > l.slot.size()) return sdo::abort_code::length_too_high;
    if (data.size() < l.slot.size()) return sdo::abort_code::length_too_low;
    if ((l.flags & slot_flag::any_bits) == 0U) { // every bit pattern of the others is a value
      switch (od::check_value<Kinds>(e, scale_at(l.at), data, node_)) {
      case od::value_check::ok: break;
      case od::value_check::too_low: return sdo::abort_code::value_too_low;
      case od::value_check::too_high: return sdo::abort_code::value_too_high;
      case od::value_check::invalid: return sdo::abort_code::invalid_value;
      }
    }
    if constexpr (!Commit) return sdo::abort_code::none;
    if (ask_hook) {
      if (const auto c = on_write_(e, data); c != sdo::abort_code::none) return c;
    }
    fieldcodec::copy_bytes(data.data(), l.slot.data(), l.slot.size());
    return sdo::abort_code::none;
  }

  od::dictionary dict_;
  std::span<const Offset> offsets_;
  std::span<std::uint8_t> storage_;
  std::span<std::uint8_t> staging_;
  OnWrite on_write_;
  bool fits_ = false; ///< layout and storage fit the dictionary (they never change)
  std::size_t staged_ = 0;
  od::address staged_address_{};
  std::uint8_t node_ = 0;
};

static_assert(object_store<dictionary_store<>>);
static_assert(positioned_store<dictionary_store<>>);
static_assert(plain_store<dictionary_store<>>);

} // namespace fieldcodec::canopen
