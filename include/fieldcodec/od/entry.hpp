// fieldcodec — od::entry, the lean core description of one sub-object of an object dictionary,
// and od::entry_info, its descriptive columns.
//
// An entry holds what code needs to move and check a value: address, object code, type, access,
// PDO mapping and flags in its own 8 bytes (object code, access and PDO mapping as bit-fields of 4
// bits, the type in one byte: every data_type is below 0x100), and a pointer (`extra`) to the
// columns that only some entries have — default, limits, the capacity of a byte string, its
// default text — packed in as few bytes as they need (12 bytes an entry on a 32-bit target, 16
// on a 64-bit host). A number
// travels in the entry's own width there (a UNSIGNED8 default is one byte); only what the width
// cannot hold exactly (a scaled entry's limits in engineering units, a fraction, a value beyond
// the field, a REAL that is no float of the entry's type) is a 10-byte od::number. The accessors
// (default_value(), low(), high(), capacity(), default_text()) unpack them; nobody reads `extra`
// directly. Layout of the packed columns, each present when its flag says so, in this order:
//
//   capacity      4 bytes, little-endian                             flag::has_size
//   default       width() bytes, or 10 with flag::default_number     flag::has_default
//   low, high     width() bytes each, or 10 with flag::limits_number flag::has_low / has_high
//   default text  4-byte little-endian length, then the bytes        flag::has_text
//
// width() bytes are the value as CANopen sends it (little-endian two's complement, IEEE 754 bits,
// TIME's 6 bytes); a 10-byte number is its kind, its places and its 8 bits, little-endian.
//
// Everything a person reads (name, unit, section, remark, the DCF's configured value) is in
// entry_info, kept in a parallel table (od::dictionary::info); the scale of a scaled entry is a
// third parallel table (od::dictionary::scale). od::descriptor (od/descriptor.hpp) joins the
// three for one sub-object. Generated dictionaries write entries as designated initialisers with
// the packed columns as a string literal, e.g.
//   {.index = 0x1400, .sub = 2, .type = od::data_type::unsigned8,
//    .flags = od::flag::has_default, .extra = "\377"}
// Hand-written dictionaries write od::entry_spec (od/entry_spec.hpp), which od::table packs.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/text.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace fieldcodec::od {

/// The bits of entry::flags.
namespace flag {
inline constexpr std::uint16_t range_exceeds_field =
    0x0001;                                               ///< printed range does not fit the field
inline constexpr std::uint16_t index_anomaly = 0x0002;    ///< printed index is odd, see remark
inline constexpr std::uint16_t signedness_guess = 0x0004; ///< signedness decided from the range
inline constexpr std::uint16_t scaled =
    0x0008; ///< the source gives a scale: limits are engineering units
inline constexpr std::uint16_t default_nodeid = 0x0010;   ///< default is "$NODEID + default_value"
inline constexpr std::uint16_t low_nodeid = 0x0020;       ///< low limit is "$NODEID + low"
inline constexpr std::uint16_t high_nodeid = 0x0040;      ///< high limit is "$NODEID + high"
inline constexpr std::uint16_t parameter_nodeid = 0x0080; ///< DCF ParameterValue is "$NODEID + …"
// Which packed columns `extra` holds (see the top of this file).
inline constexpr std::uint16_t has_default = 0x0100;    ///< a numeric default
inline constexpr std::uint16_t has_low = 0x0200;        ///< a low limit
inline constexpr std::uint16_t has_high = 0x0400;       ///< a high limit
inline constexpr std::uint16_t default_number = 0x0800; ///< the default is a packed od::number
inline constexpr std::uint16_t limits_number = 0x1000;  ///< the limits are packed od::numbers
inline constexpr std::uint16_t has_size = 0x2000;       ///< a byte string's capacity
inline constexpr std::uint16_t has_text = 0x4000;       ///< a default text (byte strings)
/// The bits that describe the packed columns: od::pack sets them, an entry_spec's are ignored.
inline constexpr std::uint16_t packed =
    has_default | has_low | has_high | default_number | limits_number | has_size | has_text;
} // namespace flag

/// No node-ID given: a node-ID-relative limit is checked for the widest range any node 1..127
/// gives (low + 1, high + 127). See od/value.hpp.
inline constexpr std::uint8_t any_node = 0;

/// Bytes of a packed od::number: kind, places, 8 bytes of bits (little-endian).
inline constexpr std::size_t packed_number_size = 10;

namespace detail {
/// `v`, plus `node_id` when `relative`. A node-ID-relative value is an integer ("$NODEID+0x180").
/// Errors: unknown_object (no value), overflow, not_representable (relative and not an integer).
[[nodiscard]] constexpr result<number> plus_node(number v, bool relative,
                                                 std::uint8_t node_id) noexcept {
  if (!v) return errc::unknown_object;
  if (!relative) return v;
  if (v.kind == number_kind::unsigned_) {
    if (v.bits > ~std::uint64_t{0} - node_id) return errc::overflow;
    return unsigned_number(v.bits + node_id);
  }
  if (v.kind != number_kind::signed_) return errc::not_representable;
  const auto i = static_cast<std::int64_t>(v.bits);
  if (i > std::numeric_limits<std::int64_t>::max() - node_id) return errc::overflow;
  return signed_number(i + node_id);
}

/// The packed bytes of a value in an entry's own width as the number they stand for: a signed
/// integer sign-extended, REAL32 / REAL64 as a real, everything else (unsigned, BOOLEAN, TIME)
/// unsigned.
[[nodiscard]] constexpr number unpack_width(data_type t, const char *p, std::size_t w) noexcept {
  const std::uint64_t bits = load_le(p, w);
  if (t == data_type::real32) {
    return real_number(static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(bits))));
  }
  if (t == data_type::real64) return real_number(std::bit_cast<double>(bits));
  if (is_signed_integer(t)) {
    const std::uint64_t sign = std::uint64_t{1} << (8U * w - 1U);
    return signed_number(static_cast<std::int64_t>((bits ^ sign) - sign));
  }
  return unsigned_number(bits);
}

/// A packed od::number (packed_number_size bytes at `p`).
[[nodiscard]] constexpr number unpack_number(const char *p) noexcept {
  number n;
  n.kind = static_cast<number_kind>(static_cast<std::uint8_t>(p[0]));
  n.places = static_cast<std::uint8_t>(p[1]);
  n.bits = load_le(p + 2, 8);
  return n;
}
} // namespace detail

struct entry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  object_code object : 4 = object_code::var; ///< code of the object this sub-object belongs to
  data_type type : 8 = data_type::unsigned8; ///< (every data_type is below 0x100)
  access access_type : 4 = access::rw;
  pdo_mapping pdo : 4 = pdo_mapping::no;
  std::uint16_t flags = 0; ///< od::flag bits
  /// The packed columns (see the top of this file); read only through the accessors, and only
  /// where `flags` says a column is there.
  const char *extra = nullptr;

  [[nodiscard]] constexpr bool has(std::uint16_t f) const noexcept { return (flags & f) == f; }

  /// The capacity in bytes of a VISIBLE_STRING / OCTET_STRING / UNICODE_STRING / DOMAIN value
  /// (0: not given); 0 for every other type (its size is fixed_size(type)).
  [[nodiscard]] constexpr std::uint32_t capacity() const noexcept {
    return has(flag::has_size) ? static_cast<std::uint32_t>(load_le(extra, 4)) : 0U;
  }

  /// Size of the value in bytes (0 for a byte string without a declared size).
  [[nodiscard]] constexpr std::uint32_t width() const noexcept {
    const std::uint8_t f = fixed_size(type);
    return f != 0U ? f : capacity();
  }

  /// The numeric default as the source gives it (raw; add the node-ID when
  /// flag::default_nodeid, see default_for); none when there is none. The integers of an
  /// integer, BOOLEAN or TIME entry are of the kind of the entry's signedness.
  [[nodiscard]] constexpr number default_value() const noexcept {
    if (!has(flag::has_default)) return {};
    return value_at(default_at(), has(flag::default_number));
  }
  /// The lowest allowed value (engineering units when flag::scaled, raw otherwise; add the
  /// node-ID when flag::low_nodeid, see low_for); none when there is none.
  [[nodiscard]] constexpr number low() const noexcept {
    if (!has(flag::has_low)) return {};
    return value_at(limits_at(), has(flag::limits_number));
  }
  /// The highest allowed value, same units as low(); none when there is none.
  [[nodiscard]] constexpr number high() const noexcept {
    if (!has(flag::has_high)) return {};
    return value_at(limits_at() + (has(flag::has_low) ? limit_size() : 0U),
                    has(flag::limits_number));
  }
  /// The default of a string / domain entry, as its bytes (empty when there is none).
  [[nodiscard]] constexpr text default_text() const noexcept {
    if (!has(flag::has_text)) return text{};
    const std::size_t at = text_at();
    return text{extra + at + 4U, static_cast<std::size_t>(load_le(extra + at, 4))};
  }

  /// The integer field a raw value travels in. Errors: type_mismatch (not an integer type).
  [[nodiscard]] constexpr result<scaling::field> raw_field() const noexcept {
    if (!is_integer(type)) return errc::type_mismatch;
    return scaling::field{fixed_size(type), is_signed_integer(type)};
  }

  /// The default value for a node: default_value() (+ node_id when flag::default_nodeid).
  /// Errors: unknown_object (no numeric default), overflow, not_representable (a node-ID-relative
  /// value that is not an integer).
  [[nodiscard]] constexpr result<number> default_for(std::uint8_t node_id) const noexcept {
    return detail::plus_node(default_value(), has(flag::default_nodeid), node_id);
  }
  /// The low limit for a node: low() (+ node_id when flag::low_nodeid). Errors: as default_for.
  [[nodiscard]] constexpr result<number> low_for(std::uint8_t node_id) const noexcept {
    return detail::plus_node(low(), has(flag::low_nodeid), node_id);
  }
  /// The high limit for a node: high() (+ node_id when flag::high_nodeid). Errors: as
  /// default_for.
  [[nodiscard]] constexpr result<number> high_for(std::uint8_t node_id) const noexcept {
    return detail::plus_node(high(), has(flag::high_nodeid), node_id);
  }

  // Where the packed columns start in `extra` (only meaningful when present).
  [[nodiscard]] constexpr std::size_t default_at() const noexcept {
    return has(flag::has_size) ? 4U : 0U;
  }
  [[nodiscard]] constexpr std::size_t limits_at() const noexcept {
    if (!has(flag::has_default)) return default_at();
    return default_at() + (has(flag::default_number) ? packed_number_size : fixed_size(type));
  }
  [[nodiscard]] constexpr std::size_t limit_size() const noexcept {
    return has(flag::limits_number) ? packed_number_size : fixed_size(type);
  }
  [[nodiscard]] constexpr std::size_t text_at() const noexcept {
    return limits_at() + (has(flag::has_low) ? limit_size() : 0U) +
           (has(flag::has_high) ? limit_size() : 0U);
  }

private:
  [[nodiscard]] constexpr number value_at(std::size_t at, bool as_number) const noexcept {
    return as_number ? detail::unpack_number(extra + at)
                     : detail::unpack_width(type, extra + at, fixed_size(type));
  }
};

namespace detail {
/// The node-ID that limit checks add to a node-ID-relative low (high = false) or high limit:
/// `node`, or for any_node the one that gives the widest range (1 for low, 127 for high).
[[nodiscard]] constexpr std::uint8_t limit_node(bool high, std::uint8_t node) noexcept {
  if (node != any_node) return node;
  return high ? std::uint8_t{127} : std::uint8_t{1};
}
/// The limit a check uses. Errors: those of low_for / high_for (the end is then not checked).
[[nodiscard]] constexpr result<number> checked_limit(const entry &e, bool high,
                                                     std::uint8_t node) noexcept {
  const std::uint8_t n = limit_node(high, node);
  return high ? e.high_for(n) : e.low_for(n);
}
} // namespace detail

/// The descriptive columns of one entry (joined to it by position, see od::dictionary::info).
/// Text columns are od::text (od/text.hpp), which read like std::string_view. A column that only
/// one manufacturer's table has is not here: it is generated as a table of its own beside the
/// dictionary, with a row type the device's folder defines (od/columns.hpp).
struct entry_info {
  text name{}; ///< name as the source prints it
  text unit{};
  text alt_name{};
  text section{}; ///< manual section
  text remark{};
  text denotation{};           ///< DCF Denotation
  std::uint32_t obj_flags = 0; ///< EDS ObjFlags
  number parameter_value{};    ///< DCF ParameterValue (configured value), raw; see
                               ///< flag::parameter_nodeid and descriptor::parameter_for
  text parameter_text{};       ///< DCF ParameterValue of a string entry
};

/// What info() answers for an entry that has none.
inline constexpr entry_info no_info{};

} // namespace fieldcodec::od
