// fieldcodec — od::entry, the lean core description of one sub-object of an object dictionary,
// and od::entry_info, its descriptive columns.
//
// An entry holds what code needs to move and check a value: address, object code, type, access,
// PDO mapping, flags, size, limits and default. Everything a person reads (name, unit, section,
// remark, vendor columns, the DCF's configured value) is in entry_info, kept in a parallel table
// (od::dictionary::info); the scale of a scaled entry is a third parallel table
// (od::dictionary::scale). od::descriptor (od/descriptor.hpp) joins the three for one
// sub-object. Literal aggregates with defaults: generated dictionaries are designated
// initialisers that name only what the source gives, e.g.
//   {.index = 0x2023, .type = od::data_type::unsigned32, .flags = od::flag::scaled,
//    .low = od::signed_number(0), .high = od::signed_number(5000)}
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/text.hpp>

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
} // namespace flag

/// No node-ID given: a node-ID-relative limit is checked for the widest range any node 1..127
/// gives (low + 1, high + 127). See od/value.hpp.
inline constexpr std::uint8_t any_node = 0;

/// DPQ "Busmanager" column.
enum class bus_manager : std::uint8_t { unspecified, available, not_available };

/// No COMPAX index pointer.
inline constexpr std::uint8_t no_pointer = 0xFF;

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
} // namespace detail

struct entry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  object_code object = object_code::var; ///< code of the object this sub-object belongs to
  data_type type = data_type::unsigned8;
  access access_type = access::rw;
  pdo_mapping pdo = pdo_mapping::no;
  std::uint16_t flags = 0; ///< od::flag bits
  /// Bytes: the capacity of a VISIBLE_STRING / OCTET_STRING / UNICODE_STRING / DOMAIN value
  /// (0: not given); 0 for every other type (its size is fixed_size(type)).
  std::uint32_t size = 0;
  number low{};           ///< lowest allowed value: engineering units when scaled, raw otherwise
  number high{};          ///< highest allowed value, same units as `low`
  number default_value{}; ///< raw default; add the node-ID when flag::default_nodeid
  text default_text{};    ///< default of a string / domain entry, as its bytes

  [[nodiscard]] constexpr bool has(std::uint16_t f) const noexcept { return (flags & f) == f; }

  /// Size of the value in bytes (0 for a byte string without a declared size).
  [[nodiscard]] constexpr std::uint32_t width() const noexcept {
    const std::uint8_t f = fixed_size(type);
    return f != 0U ? f : size;
  }

  /// The integer field a raw value travels in. Errors: type_mismatch (not an integer type).
  [[nodiscard]] constexpr result<scaling::field> raw_field() const noexcept {
    if (!is_integer(type)) return errc::type_mismatch;
    return scaling::field{fixed_size(type), is_signed_integer(type)};
  }

  /// The default value for a node: default_value (+ node_id when flag::default_nodeid).
  /// Errors: unknown_object (no numeric default), overflow, not_representable (a node-ID-relative
  /// value that is not an integer).
  [[nodiscard]] constexpr result<number> default_for(std::uint8_t node_id) const noexcept {
    return detail::plus_node(default_value, has(flag::default_nodeid), node_id);
  }
  /// The low limit for a node: low (+ node_id when flag::low_nodeid). Errors: as default_for.
  [[nodiscard]] constexpr result<number> low_for(std::uint8_t node_id) const noexcept {
    return detail::plus_node(low, has(flag::low_nodeid), node_id);
  }
  /// The high limit for a node: high (+ node_id when flag::high_nodeid). Errors: as default_for.
  [[nodiscard]] constexpr result<number> high_for(std::uint8_t node_id) const noexcept {
    return detail::plus_node(high, has(flag::high_nodeid), node_id);
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
/// Text columns are od::text (od/text.hpp), which read like std::string_view.
struct entry_info {
  text name{}; ///< name as the source prints it
  text unit{};
  text alt_name{};
  text section{}; ///< manual section
  text remark{};
  text acceptance{};                 ///< DPQ: when the card accepts a write
  text denotation{};                 ///< DCF Denotation
  std::uint8_t pointer = no_pointer; ///< COMPAX index pointer
  bus_manager bus = bus_manager::unspecified;
  std::uint32_t obj_flags = 0; ///< EDS ObjFlags
  number parameter_value{};    ///< DCF ParameterValue (configured value), raw; see
                               ///< flag::parameter_nodeid and descriptor::parameter_for
  text parameter_text{};       ///< DCF ParameterValue of a string entry
};

/// What info() answers for an entry that has none.
inline constexpr entry_info no_info{};

} // namespace fieldcodec::od
