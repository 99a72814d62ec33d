// fieldcodec — PDO mapping entries (CiA 301 32-bit and POWERLINK 64-bit), bit-level packing,
// mappings checked against a dictionary (at run time and at compile time) that read and write
// values with the mapped object's signedness, the default mappings a dictionary declares, and
// PDO communication parameters (CiA 301).
//
// A CiA 301 mapping entry (sub 1..64 of objects 1600h..17FFh / 1A00h..1BFFh) is
//   index << 16 | sub-index << 8 | length in bits,
// and the entries are packed in mapping order from bit 0 of byte 0 upwards. A POWERLINK mapping
// entry (EPSG DS 301, UNSIGNED64, sub 1..254 of 1600h..16FFh / 1A00h..1AFFh) names its place:
//   length << 48 | bit offset << 32 | (reserved, 0) << 24 | sub-index << 16 | index.
// Inside the PDO, bit k is bit (k mod 8) of byte k / 8 and every value is little-endian
// ("little-endian bit order"), so byte-aligned values look exactly like their SDO encoding.
//
// Values: a mapping built from a dictionary knows each object's signedness. Its get/set and
// pack_all/unpack_all take and return any integer type, checked: an INTEGER32 holding -1 comes
// out as -1, -1 for an UNSIGNED16 or 70000 for an INTEGER16 is refused with overflow, nothing
// wraps. A mapping built without a dictionary reads raw bits (zero-extended) and accepts a value
// that fits the field either as unsigned or as two's complement.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <type_traits>

namespace fieldcodec::canopen::pdo {

/// Longest PDO in bits on classic CAN (8 bytes). CoE and POWERLINK PDOs are longer: pass the
/// limit of the transport (e.g. 8 * 1490 bytes for POWERLINK, the sync-manager size for CoE).
inline constexpr std::size_t can_max_bits = 64;
/// Most entries a CiA 301 mapping object holds (sub 1..64).
inline constexpr std::size_t max_entries = 64;
/// Most entries a POWERLINK mapping object holds (sub 1..254).
inline constexpr std::size_t powerlink_max_entries = 254;

/// A CiA 301 mapping entry (UNSIGNED32).
struct mapping_entry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::uint8_t bits = 0;

  [[nodiscard]] static constexpr mapping_entry from_u32(std::uint32_t v) noexcept {
    return {static_cast<std::uint16_t>(v >> 16U), static_cast<std::uint8_t>((v >> 8U) & 0xFFU),
            static_cast<std::uint8_t>(v & 0xFFU)};
  }
  [[nodiscard]] constexpr std::uint32_t to_u32() const noexcept {
    return (std::uint32_t{index} << 16U) | (std::uint32_t{sub} << 8U) | bits;
  }
  /// A dummy entry (index 0x0001..0x0007, a data type) only reserves space.
  [[nodiscard]] constexpr bool is_dummy() const noexcept { return index >= 1U && index <= 7U; }
  friend constexpr bool operator==(const mapping_entry &, const mapping_entry &) = default;
};

[[nodiscard]] constexpr std::uint32_t mapping_value(std::uint16_t index, std::uint8_t sub,
                                                    std::uint8_t bits) noexcept {
  return mapping_entry{index, sub, bits}.to_u32();
}

/// A POWERLINK mapping entry (UNSIGNED64, EPSG DS 301): the object, its bit offset in the PDO
/// and its bit length. The value 0 is an empty entry (nothing mapped; POWERLINK skips it).
struct powerlink_mapping_entry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::uint16_t offset = 0; ///< bit offset in the PDO
  std::uint16_t bits = 0;   ///< bit length

  /// Errors: out_of_range (reserved bits 24..31 set).
  [[nodiscard]] static constexpr result<powerlink_mapping_entry>
  from_u64(std::uint64_t v) noexcept {
    if ((v & 0xFF00'0000U) != 0U) return errc::out_of_range;
    return powerlink_mapping_entry{
        static_cast<std::uint16_t>(v & 0xFFFFU), static_cast<std::uint8_t>((v >> 16U) & 0xFFU),
        static_cast<std::uint16_t>((v >> 32U) & 0xFFFFU), static_cast<std::uint16_t>(v >> 48U)};
  }
  [[nodiscard]] constexpr std::uint64_t to_u64() const noexcept {
    return (std::uint64_t{bits} << 48U) | (std::uint64_t{offset} << 32U) |
           (std::uint64_t{sub} << 16U) | index;
  }
  [[nodiscard]] constexpr bool is_empty() const noexcept { return to_u64() == 0U; }
  [[nodiscard]] constexpr bool is_dummy() const noexcept { return index >= 1U && index <= 7U; }
  friend constexpr bool operator==(const powerlink_mapping_entry &,
                                   const powerlink_mapping_entry &) = default;
};

[[nodiscard]] constexpr std::uint64_t powerlink_mapping_value(std::uint16_t index, std::uint8_t sub,
                                                              std::uint16_t offset,
                                                              std::uint16_t bits) noexcept {
  return powerlink_mapping_entry{index, sub, offset, bits}.to_u64();
}

// ---------------------------------------------------------------------------------------------
// Bit-level packing

/// Write the low `length` bits (1..64) of `raw` at bit `offset` of `pdo`; other bits untouched.
/// Errors: bad_length (length 0 or > 64), overflow (raw needs more than `length` bits),
/// buffer_too_small (offset + length beyond the buffer).
[[nodiscard]] constexpr status pack(std::span<std::uint8_t> pdo, std::size_t offset,
                                    std::size_t length, std::uint64_t raw) noexcept {
  if (length < 1U || length > 64U) return errc::bad_length;
  if (length < 64U && (raw >> length) != 0U) return errc::overflow;
  if (offset + length > pdo.size() * 8U) return errc::buffer_too_small;
#if !defined(__OPTIMIZE_SIZE__) // built for size (-Os, firmware) the loop below serves whole bytes
  if (offset % 8U == 0U && length % 8U == 0U) { // whole bytes: a little-endian store
    return store_unsigned(pdo.subspan(offset / 8U), length / 8U, raw, byte_order::little);
  }
#endif
  // A byte at a time: at most 9 steps for 64 bits (a whole byte per step when aligned).
  std::size_t bit = offset;
  std::size_t done = 0;
  while (done < length) {
    const std::size_t shift = bit % 8U;
    const std::size_t n = 8U - shift < length - done ? 8U - shift : length - done;
    const unsigned low = (1U << n) - 1U;
    const auto mask = static_cast<unsigned>(low << shift);
    const auto bits = static_cast<unsigned>((raw >> done) & low);
    std::uint8_t &b = pdo[bit / 8U];
    b = static_cast<std::uint8_t>((b & ~mask) | (bits << shift));
    bit += n;
    done += n;
  }
  return {};
}

/// Two's complement form of pack. Errors: bad_length, overflow (outside the signed range of
/// `length` bits), buffer_too_small.
[[nodiscard]] constexpr status pack_signed(std::span<std::uint8_t> pdo, std::size_t offset,
                                           std::size_t length, std::int64_t value) noexcept {
  if (length < 1U || length > 64U) return errc::bad_length;
  if (length < 64U) {
    const std::int64_t lo = -(std::int64_t{1} << (length - 1U));
    const std::int64_t hi = (std::int64_t{1} << (length - 1U)) - 1;
    if (value < lo || value > hi) return errc::overflow;
  }
  const auto u = static_cast<std::uint64_t>(value);
  return pack(pdo, offset, length, length == 64U ? u : u & ((std::uint64_t{1} << length) - 1U));
}

/// Read `length` bits (1..64) at bit `offset`. Errors: bad_length, truncated.
[[nodiscard]] constexpr result<std::uint64_t>
unpack(std::span<const std::uint8_t> pdo, std::size_t offset, std::size_t length) noexcept {
  if (length < 1U || length > 64U) return errc::bad_length;
  if (offset + length > pdo.size() * 8U) return errc::truncated;
#if !defined(__OPTIMIZE_SIZE__) // built for size (-Os, firmware) the loop below serves whole bytes
  if (offset % 8U == 0U && length % 8U == 0U) { // whole bytes: a little-endian load
    return load_unsigned(pdo.subspan(offset / 8U), length / 8U, byte_order::little);
  }
#endif
  std::uint64_t v = 0;
  std::size_t bit = offset;
  std::size_t done = 0;
  while (done < length) {
    const std::size_t shift = bit % 8U;
    const std::size_t n = 8U - shift < length - done ? 8U - shift : length - done;
    const unsigned bits = (static_cast<unsigned>(pdo[bit / 8U]) >> shift) & ((1U << n) - 1U);
    v |= std::uint64_t{bits} << done;
    bit += n;
    done += n;
  }
  return v;
}

/// Copy `length` bits from bit `from_bit` of `from` to bit `to_bit` of `to`, in the PDO's bit
/// order (bit 0 is the low bit of byte 0); the other bits of `to` are untouched. One bit per
/// step and no arithmetic wider than a byte: the PDO engine's path for values off byte
/// boundaries (1-bit BOOLEANs and what follows them), where size counts more than speed.
/// False, nothing copied, when either range lies beyond its bytes.
[[nodiscard]] constexpr bool copy_bits(std::span<const std::uint8_t> from, std::size_t from_bit,
                                       std::span<std::uint8_t> to, std::size_t to_bit,
                                       std::size_t length) noexcept {
  if (from_bit + length > from.size() * 8U || to_bit + length > to.size() * 8U) return false;
  for (std::size_t i = 0; i < length; ++i) {
    const std::size_t f = from_bit + i;
    const std::size_t t = to_bit + i;
    const auto mask = static_cast<std::uint8_t>(1U << (t % 8U));
    const bool set = ((static_cast<unsigned>(from[f / 8U]) >> (f % 8U)) & 1U) != 0U;
    to[t / 8U] = static_cast<std::uint8_t>(set ? to[t / 8U] | mask : to[t / 8U] & ~mask);
  }
  return true;
}

namespace detail {
/// The low `length` bits (1..64) of `raw` as a two's complement number: shifted up to bit 63
/// and arithmetically back, without a test of the sign bit (issue 18: for a length known after
/// inlining this is one sign-extending move). Bits of `raw` above `length` do not matter.
[[nodiscard]] constexpr std::int64_t sign_extend(std::uint64_t raw, std::size_t length) noexcept {
  const std::size_t up = 64U - length;
  return static_cast<std::int64_t>(raw << up) >> up;
}
} // namespace detail

/// Read `length` bits as a two's complement number, sign-extended.
[[nodiscard]] constexpr result<std::int64_t>
unpack_signed(std::span<const std::uint8_t> pdo, std::size_t offset, std::size_t length) noexcept {
  FIELDCODEC_TRY(const std::uint64_t v, unpack(pdo, offset, length));
  return detail::sign_extend(v, length);
}

// ---------------------------------------------------------------------------------------------
// Values with the object's signedness

/// How the bits of a mapped object are read and written.
enum class signedness : std::uint8_t {
  unknown,   ///< no type known (mapping without dictionary, REAL, strings): raw bits
  unsigned_, ///< UNSIGNEDn, BOOLEAN
  signed_,   ///< INTEGERn
};

[[nodiscard]] constexpr signedness signedness_of(od::data_type t) noexcept {
  if (od::is_signed_integer(t)) return signedness::signed_;
  if (od::is_unsigned_integer(t) || t == od::data_type::boolean) return signedness::unsigned_;
  return signedness::unknown;
}

namespace detail {
/// A scoped enum over an integer type (ds402::mode, a device folder's mode, …): written as its
/// value.
template <class T>
concept scoped_enum = std::is_enum_v<T> && !std::is_convertible_v<T, std::underlying_type_t<T>> &&
                      wire_integer<std::underlying_type_t<T>>;
template <class T>
concept pdo_value = wire_integer<T> || scoped_enum<T>;
template <pdo_value T>
[[nodiscard]] constexpr auto as_integer(T v) noexcept {
  if constexpr (scoped_enum<T>) {
    return static_cast<std::underlying_type_t<T>>(v);
  } else {
    return v;
  }
}

/// The `length` low bits that carry `v`. Errors: bad_length, overflow (v outside the field:
/// signed range for signed_, unsigned range for unsigned_, either for unknown).
template <wire_integer T>
[[nodiscard]] constexpr result<std::uint64_t> field_bits(T v, std::size_t length,
                                                         signedness s) noexcept {
  if (length < 1U || length > 64U) return errc::bad_length;
  const std::uint64_t mask = length == 64U ? ~std::uint64_t{0} : (std::uint64_t{1} << length) - 1U;
  if constexpr (std::is_signed_v<T>) {
    if (v < 0) {
      if (s == signedness::unsigned_) return errc::overflow;
      const auto x = static_cast<std::int64_t>(v);
      if (length < 64U && x < -(std::int64_t{1} << (length - 1U))) return errc::overflow;
      return static_cast<std::uint64_t>(x) & mask;
    }
  }
  const auto u = static_cast<std::uint64_t>(v);
  const std::uint64_t max = s == signedness::signed_ ? mask >> 1U : mask;
  if (u > max) return errc::overflow;
  return u;
}

/// `raw` (the field's `length` low bits) as T, with the field's signedness.
/// Errors: overflow (the value does not fit T).
template <wire_integer T>
[[nodiscard]] constexpr result<T> field_value(std::uint64_t raw, std::size_t length,
                                              signedness s) noexcept {
  if (s == signedness::signed_) {
    const std::int64_t x = sign_extend(raw, length);
    if (x < 0) {
      if constexpr (std::is_signed_v<T>) {
        if (x < static_cast<std::int64_t>(std::numeric_limits<T>::min())) return errc::overflow;
        return static_cast<T>(x);
      } else {
        return errc::overflow;
      }
    }
  }
  if (raw > static_cast<std::uint64_t>(std::numeric_limits<T>::max())) return errc::overflow;
  return static_cast<T>(raw);
}

template <wire_integer T>
[[nodiscard]] constexpr status pack_value(std::span<std::uint8_t> pdo, std::size_t offset,
                                          std::size_t length, signedness s, T v) noexcept {
  FIELDCODEC_TRY(const std::uint64_t bits, field_bits(v, length, s));
  return pack(pdo, offset, length, bits);
}

template <wire_integer T>
[[nodiscard]] constexpr result<T> unpack_value(std::span<const std::uint8_t> pdo,
                                               std::size_t offset, std::size_t length,
                                               signedness s) noexcept {
  FIELDCODEC_TRY(const std::uint64_t raw, unpack(pdo, offset, length));
  return field_value<T>(raw, length, s);
}
} // namespace detail

// ---------------------------------------------------------------------------------------------
// Mappings against a dictionary

/// RPDO: the device receives (objects must be writable and RPDO-mappable);
/// TPDO: the device transmits (readable and TPDO-mappable).
enum class direction : std::uint8_t { rpdo, tpdo };

/// Bit length an object occupies when mapped: 8 × size; BOOLEAN may be mapped as 1 or 8 bits.
[[nodiscard]] constexpr bool length_fits(const od::entry &e, std::size_t bits) noexcept {
  if (e.type == od::data_type::boolean) return bits == 1U || bits == 8U;
  if (od::is_byte_string(e.type)) return bits % 8U == 0U && bits <= 8U * e.width() && bits > 0U;
  return bits == 8U * od::fixed_size(e.type);
}

/// What is wrong with one entry (or nothing).
enum class mapping_problem : std::uint8_t {
  none,
  zero_length,      ///< length 0
  no_object,        ///< index:sub not in the dictionary (SDO abort 0602 0000)
  not_mappable,     ///< PDOMapping not allowed for this direction (0604 0041)
  no_access,        ///< RPDO of a read-only or TPDO of a write-only object (0604 0041)
  length_mismatch,  ///< length does not fit the object's type (0607 0010)
  too_long,         ///< the mapping exceeds the PDO length (0604 0042)
  too_many_entries, ///< more than 64 entries (POWERLINK: 254)
  overlap,          ///< POWERLINK: two entries claim the same bits
};

[[nodiscard]] constexpr std::string_view to_string(mapping_problem p) noexcept {
  switch (p) {
  case mapping_problem::none: return "ok";
  case mapping_problem::zero_length: return "entry of length 0";
  case mapping_problem::no_object: return "object not in the dictionary";
  case mapping_problem::not_mappable: return "object is not PDO-mappable in this direction";
  case mapping_problem::no_access: return "object access does not allow this direction";
  case mapping_problem::length_mismatch: return "bit length does not match the object's type";
  case mapping_problem::too_long: return "mapping exceeds the PDO length";
  case mapping_problem::too_many_entries: return "more entries than the mapping object holds";
  case mapping_problem::overlap: return "entries overlap";
  }
  return "?";
}

/// The errc for a problem.
[[nodiscard]] constexpr errc to_errc(mapping_problem p) noexcept {
  switch (p) {
  case mapping_problem::zero_length:
  case mapping_problem::length_mismatch: return errc::bad_length;
  case mapping_problem::no_object: return errc::unknown_object;
  case mapping_problem::not_mappable:
  case mapping_problem::no_access: return errc::access_denied;
  case mapping_problem::too_long:
  case mapping_problem::too_many_entries: return errc::too_long;
  case mapping_problem::overlap:
  case mapping_problem::none: break;
  }
  return errc::invalid_argument;
}

namespace detail {
/// The sub-entry `sub` among the sub-entries of one object, as a position in `object`
/// (object.size() when absent). A position, not a pointer: g++ with -fsanitize=undefined
/// instruments `pointer == nullptr` and then cannot evaluate it in a constant expression when
/// the pointer addresses an element of a constexpr table (issue 12 #13), which made
/// make_static_mapping(dictionary, …) fail to compile under the sanitizer.
[[nodiscard]] constexpr std::size_t sub_position(std::span<const od::entry> object,
                                                 std::uint8_t sub) noexcept {
  std::size_t i = 0;
  while (i < object.size() && object[i].sub != sub) ++i;
  return i;
}

/// Check one mapped object (index, sub, length) against a dictionary; dummy entries against
/// their data type. `type` receives the object's data type when the check passes.
[[nodiscard]] constexpr mapping_problem check_object(const od::dictionary &dict, direction d,
                                                     std::uint16_t index, std::uint8_t sub,
                                                     std::size_t bits,
                                                     od::data_type &type) noexcept {
  if (bits == 0U) return mapping_problem::zero_length;
  if (index >= 1U && index <= 7U) { // dummy entry
    if (sub != 0U) return mapping_problem::no_object;
    type = static_cast<od::data_type>(index);
    if (type == od::data_type::boolean) {
      return bits == 1U ? mapping_problem::none : mapping_problem::length_mismatch;
    }
    return bits == 8U * od::fixed_size(type) ? mapping_problem::none
                                             : mapping_problem::length_mismatch;
  }
  const std::size_t at = dict.position(od::address{index, sub});
  if (at == dict.size()) return mapping_problem::no_object;
  const od::entry &e = dict.entries()[at];
  if (d == direction::rpdo) {
    if (!od::mappable_rx(e.pdo)) return mapping_problem::not_mappable;
    if (!od::writable(e.access_type)) return mapping_problem::no_access;
  } else {
    if (!od::mappable_tx(e.pdo)) return mapping_problem::not_mappable;
    if (!od::readable(e.access_type)) return mapping_problem::no_access;
  }
  if (!length_fits(e, bits)) return mapping_problem::length_mismatch;
  type = e.type;
  return mapping_problem::none;
}
} // namespace detail

/// Check one entry against a dictionary (dummy entries against their data type).
[[nodiscard]] constexpr mapping_problem check_entry(const od::dictionary &dict, direction d,
                                                    mapping_entry m) noexcept {
  od::data_type type{};
  return detail::check_object(dict, d, m.index, m.sub, m.bits, type);
}

/// Where a check failed.
struct mapping_report {
  mapping_problem problem = mapping_problem::none;
  std::size_t entry = 0;      ///< position (0-based) of the offending entry
  std::size_t total_bits = 0; ///< length of the whole mapping when problem == none
  [[nodiscard]] constexpr bool ok() const noexcept { return problem == mapping_problem::none; }
};

/// Check a whole mapping: every entry, at most 64 entries, total length <= max_bits.
[[nodiscard]] constexpr mapping_report check_mapping(const od::dictionary &dict, direction d,
                                                     std::span<const mapping_entry> entries,
                                                     std::size_t max_bits = can_max_bits) noexcept {
  if (entries.size() > max_entries) return {mapping_problem::too_many_entries, max_entries, 0};
  std::size_t total = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (auto p = check_entry(dict, d, entries[i]); p != mapping_problem::none) return {p, i, 0};
    total += entries[i].bits;
    if (total > max_bits) return {mapping_problem::too_long, i, 0};
  }
  return {mapping_problem::none, 0, total};
}

/// Check a POWERLINK mapping: every non-empty entry against the dictionary, at most 254
/// entries, every entry inside max_bits, no two entries on the same bits. Empty entries (value
/// 0) are skipped. total_bits is the end of the last mapped bit.
[[nodiscard]] constexpr mapping_report
check_mapping(const od::dictionary &dict, direction d,
              std::span<const powerlink_mapping_entry> entries, std::size_t max_bits) noexcept {
  if (entries.size() > powerlink_max_entries) {
    return {mapping_problem::too_many_entries, powerlink_max_entries, 0};
  }
  std::size_t end = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const powerlink_mapping_entry &m = entries[i];
    if (m.is_empty()) continue;
    od::data_type type{};
    if (auto p = detail::check_object(dict, d, m.index, m.sub, m.bits, type);
        p != mapping_problem::none) {
      return {p, i, 0};
    }
    const std::size_t last = std::size_t{m.offset} + m.bits;
    if (last > max_bits) return {mapping_problem::too_long, i, 0};
    for (std::size_t j = 0; j < i; ++j) {
      const powerlink_mapping_entry &o = entries[j];
      if (o.is_empty()) continue;
      if (m.offset < std::size_t{o.offset} + o.bits && o.offset < last) {
        return {mapping_problem::overlap, i, 0};
      }
    }
    if (last > end) end = last;
  }
  return {mapping_problem::none, 0, end};
}

/// check_mapping as a result: the total length in bits. Errors: see to_errc.
[[nodiscard]] constexpr result<std::size_t> validate(const od::dictionary &dict, direction d,
                                                     std::span<const mapping_entry> entries,
                                                     std::size_t max_bits = can_max_bits) noexcept {
  const auto r = check_mapping(dict, d, entries, max_bits);
  if (!r.ok()) return to_errc(r.problem);
  return r.total_bits;
}
[[nodiscard]] constexpr result<std::size_t>
validate(const od::dictionary &dict, direction d, std::span<const powerlink_mapping_entry> entries,
         std::size_t max_bits) noexcept {
  const auto r = check_mapping(dict, d, entries, max_bits);
  if (!r.ok()) return to_errc(r.problem);
  return r.total_bits;
}

// ---------------------------------------------------------------------------------------------
// Whole mappings without a dictionary (raw bits)

namespace detail {
/// pack_all's fast path (issue 18) for a mapping of at most 64 bits, the length of every CAN
/// PDO: every value checked (as field_bits with unknown signedness) and placed in one 64-bit
/// word, then the word merged into the buffer's bytes (bits past the mapping keep their value,
/// as pack leaves them). False — nothing written — when an entry has length 0, the mapping is
/// longer than 64 bits or the buffer shorter than it, or a value does not fit: the general
/// loop then gives the error, and writes what it wrote before.
template <wire_integer T>
[[nodiscard]] constexpr bool pack_word(std::span<const mapping_entry> entries,
                                       std::span<const T> values, std::span<std::uint8_t> pdo,
                                       std::size_t &bits) noexcept {
  std::uint64_t word = 0;
  std::size_t offset = 0;
  bool fits = true;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::size_t b = entries[i].bits;
    if (b == 0U || offset + b > 64U) return false;
    if constexpr (std::is_signed_v<T>) {
      // fits as unsigned or as two's complement: v >> (b - 1) is -1, 0 or 1
      const std::int64_t top = static_cast<std::int64_t>(values[i]) >> (b - 1U);
      fits &= static_cast<std::uint64_t>(top) + 1U <= 2U;
    } else {
      fits &= ((static_cast<std::uint64_t>(values[i]) >> (b - 1U)) >> 1U) == 0U;
    }
    word |= (static_cast<std::uint64_t>(values[i]) & (~std::uint64_t{0} >> (64U - b))) << offset;
    offset += b;
  }
  if (!fits) return false;
  const std::uint64_t keep = offset == 64U ? 0U : ~std::uint64_t{0} << offset;
  if (pdo.size() >= 8U) { // one load and one store of 8 bytes
    const std::uint64_t old = load_unsigned(pdo, 8, byte_order::little).value_or(0);
    (void)store_unsigned(pdo, 8, (old & keep) | word, byte_order::little); // cannot fail
  } else {
    const std::size_t n = (offset + 7U) / 8U;
    if (n > pdo.size()) return false;
    for (std::size_t k = 0; k < n; ++k) {
      const auto mask = static_cast<std::uint8_t>(keep >> (8U * k));
      pdo[k] =
          static_cast<std::uint8_t>((pdo[k] & mask) | static_cast<std::uint8_t>(word >> (8U * k)));
    }
  }
  bits = offset;
  return true;
}

template <wire_integer T>
[[nodiscard]] constexpr result<std::size_t> pack_raw(std::span<const mapping_entry> entries,
                                                     std::span<const T> values,
                                                     std::span<std::uint8_t> pdo) noexcept {
  if (values.size() != entries.size()) return errc::bad_length;
  if (std::size_t bits = 0; pack_word(entries, values, pdo, bits)) return (bits + 7U) / 8U;
  std::size_t offset = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    FIELDCODEC_TRY_STATUS(pack_value(pdo, offset, entries[i].bits, signedness::unknown, values[i]));
    offset += entries[i].bits;
  }
  return (offset + 7U) / 8U;
}
} // namespace detail

/// Pack one value per entry (dummy entries take 0) into `pdo` in mapping order; returns the
/// bytes used (total bits rounded up). Without a dictionary the signedness is unknown: a value
/// is accepted when it fits the field as unsigned or as two's complement (-5 for 16 bits gives
/// 0xFFFB; a uint64 is never taken as a negative number). Use a mapping built from a
/// dictionary (make_mapping) to have values checked against each object's signedness.
/// Errors: bad_length (value count != entry count, zero length), overflow, buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> pack_all(std::span<const mapping_entry> entries,
                                                     std::span<const std::uint64_t> values,
                                                     std::span<std::uint8_t> pdo) noexcept {
  return detail::pack_raw(entries, values, pdo);
}
[[nodiscard]] constexpr result<std::size_t> pack_all(std::span<const mapping_entry> entries,
                                                     std::span<const std::int64_t> values,
                                                     std::span<std::uint8_t> pdo) noexcept {
  return detail::pack_raw(entries, values, pdo);
}

/// Unpack every entry's raw bits (zero-extended: no dictionary, no signedness) into `raws`.
/// For values with their signedness use a mapping built from a dictionary (make_mapping).
/// Errors: bad_length (raws too small), truncated (the PDO is shorter than the mapping).
[[nodiscard]] constexpr status unpack_all(std::span<const mapping_entry> entries,
                                          std::span<const std::uint8_t> pdo,
                                          std::span<std::uint64_t> raws) noexcept {
  if (raws.size() < entries.size()) return errc::bad_length;
  std::size_t offset = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    FIELDCODEC_TRY(raws[i], unpack(pdo, offset, entries[i].bits));
    offset += entries[i].bits;
  }
  return {};
}

// ---------------------------------------------------------------------------------------------
// Mappings built from a dictionary (run time)

/// One mapped object: where its bits are and how to read them.
struct slot {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  signedness sign = signedness::unknown;
  std::uint16_t offset = 0; ///< bit offset in the PDO
  std::uint16_t bits = 0;   ///< bit length
  friend constexpr bool operator==(const slot &, const slot &) = default;
};

/// A mapping checked against a dictionary, with each object's place and signedness. Fixed
/// capacity, no heap; build it with make_mapping. Values of any integer type are checked
/// against the object's signedness and width (overflow otherwise); reads return the value with
/// the object's signedness (INTEGER32 0xFFFFFFFF is -1).
template <std::size_t Capacity = max_entries>
class mapping {
public:
  constexpr mapping() noexcept = default;

  [[nodiscard]] constexpr std::size_t size() const noexcept { return count_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return count_ == 0U; }
  /// End of the last mapped bit.
  [[nodiscard]] constexpr std::size_t total_bits() const noexcept { return total_bits_; }
  [[nodiscard]] constexpr std::size_t bytes() const noexcept { return (total_bits_ + 7U) / 8U; }
  [[nodiscard]] constexpr std::span<const slot> slots() const noexcept {
    return std::span<const slot>(slots_.data(), count_);
  }
  [[nodiscard]] constexpr const slot &operator[](std::size_t i) const noexcept { return slots_[i]; }

  /// The value of entry i. Errors: invalid_argument (no entry i), truncated, overflow (does not
  /// fit T).
  template <wire_integer T = std::int64_t>
  [[nodiscard]] constexpr result<T> get(std::span<const std::uint8_t> pdo,
                                        std::size_t i) const noexcept {
    if (i >= count_) return errc::invalid_argument;
    return detail::unpack_value<T>(pdo, slots_[i].offset, slots_[i].bits, slots_[i].sign);
  }
  /// Pack the value of entry i (any integer type, or a scoped enum such as ds402::mode as its
  /// value). Errors: invalid_argument, overflow, buffer_too_small.
  template <detail::pdo_value T>
  [[nodiscard]] constexpr status set(std::span<std::uint8_t> pdo, std::size_t i,
                                     T value) const noexcept {
    if (i >= count_) return errc::invalid_argument;
    return detail::pack_value(pdo, slots_[i].offset, slots_[i].bits, slots_[i].sign,
                              detail::as_integer(value));
  }

  /// Every entry's value. Errors: bad_length (values too small), truncated, overflow (an
  /// UNSIGNED64 above INT64_MAX for int64 values, a negative value for uint64 values).
  [[nodiscard]] constexpr status unpack_all(std::span<const std::uint8_t> pdo,
                                            std::span<std::int64_t> values) const noexcept {
    return unpack_into(pdo, values);
  }
  [[nodiscard]] constexpr status unpack_all(std::span<const std::uint8_t> pdo,
                                            std::span<std::uint64_t> values) const noexcept {
    return unpack_into(pdo, values);
  }
  /// Pack one value per entry; returns bytes(). Errors: bad_length (count differs), overflow,
  /// buffer_too_small.
  [[nodiscard]] constexpr result<std::size_t> pack_all(std::span<const std::int64_t> values,
                                                       std::span<std::uint8_t> pdo) const noexcept {
    return pack_from(values, pdo);
  }
  [[nodiscard]] constexpr result<std::size_t> pack_all(std::span<const std::uint64_t> values,
                                                       std::span<std::uint8_t> pdo) const noexcept {
    return pack_from(values, pdo);
  }

  /// Append a slot (make_mapping does this after the dictionary check). Errors: too_long (full).
  [[nodiscard]] constexpr status add(slot s) noexcept {
    if (count_ == Capacity) return errc::too_long;
    slots_[count_++] = s;
    if (std::size_t{s.offset} + s.bits > total_bits_) total_bits_ = std::size_t{s.offset} + s.bits;
    return {};
  }

private:
  template <class T>
  [[nodiscard]] constexpr status unpack_into(std::span<const std::uint8_t> pdo,
                                             std::span<T> values) const noexcept {
    if (values.size() < count_) return errc::bad_length;
    for (std::size_t i = 0; i < count_; ++i) {
      FIELDCODEC_TRY(values[i], get<T>(pdo, i));
    }
    return {};
  }
  template <class T>
  [[nodiscard]] constexpr result<std::size_t>
  pack_from(std::span<const T> values, std::span<std::uint8_t> pdo) const noexcept {
    if (values.size() != count_) return errc::bad_length;
    for (std::size_t i = 0; i < count_; ++i) FIELDCODEC_TRY_STATUS(set(pdo, i, values[i]));
    return bytes();
  }

  std::array<slot, Capacity> slots_{};
  std::size_t count_ = 0;
  std::size_t total_bits_ = 0;
};

/// A CiA 301 mapping checked against `dict` (check_mapping) with each object's signedness.
/// Errors: those of validate, too_long (more entries than Capacity).
template <std::size_t Capacity = max_entries>
[[nodiscard]] constexpr result<mapping<Capacity>>
make_mapping(const od::dictionary &dict, direction d, std::span<const mapping_entry> entries,
             std::size_t max_bits = can_max_bits) noexcept {
  const auto r = check_mapping(dict, d, entries, max_bits);
  if (!r.ok()) return to_errc(r.problem);
  if (r.total_bits > 0xFFFFU) return errc::too_long; // slot offsets are 16-bit, as POWERLINK's
  mapping<Capacity> m;
  std::size_t offset = 0;
  for (const mapping_entry &e : entries) {
    od::data_type type{};
    (void)detail::check_object(dict, d, e.index, e.sub, e.bits, type);
    FIELDCODEC_TRY_STATUS(m.add(
        slot{e.index, e.sub, signedness_of(type), static_cast<std::uint16_t>(offset), e.bits}));
    offset += e.bits;
  }
  return m;
}

/// A POWERLINK mapping checked against `dict`; empty entries are left out.
/// Errors: those of validate, too_long (more entries than Capacity).
template <std::size_t Capacity = max_entries>
[[nodiscard]] constexpr result<mapping<Capacity>>
make_mapping(const od::dictionary &dict, direction d,
             std::span<const powerlink_mapping_entry> entries, std::size_t max_bits) noexcept {
  const auto r = check_mapping(dict, d, entries, max_bits);
  if (!r.ok()) return to_errc(r.problem);
  mapping<Capacity> m;
  for (const powerlink_mapping_entry &e : entries) {
    if (e.is_empty()) continue;
    od::data_type type{};
    (void)detail::check_object(dict, d, e.index, e.sub, e.bits, type);
    FIELDCODEC_TRY_STATUS(m.add(slot{e.index, e.sub, signedness_of(type), e.offset, e.bits}));
  }
  return m;
}

// ---------------------------------------------------------------------------------------------
// Default mappings declared in a dictionary

/// A list of mapping entries with a fixed capacity (no heap).
template <class Entry, std::size_t Capacity>
struct entry_list {
  std::array<Entry, Capacity> items{};
  std::size_t count = 0;

  [[nodiscard]] constexpr std::size_t size() const noexcept { return count; }
  [[nodiscard]] constexpr bool empty() const noexcept { return count == 0U; }
  [[nodiscard]] constexpr const Entry &operator[](std::size_t i) const noexcept { return items[i]; }
  [[nodiscard]] constexpr std::span<const Entry> entries() const noexcept {
    return std::span<const Entry>(items.data(), count);
  }
  [[nodiscard]] constexpr const Entry *begin() const noexcept { return items.data(); }
  [[nodiscard]] constexpr const Entry *end() const noexcept { return items.data() + count; }
};

namespace detail {
/// The default of sub `sub` of `object` as an unsigned integer of type `type`.
[[nodiscard]] constexpr result<std::uint64_t>
default_of(std::span<const od::entry> object, std::uint8_t sub, od::data_type type) noexcept {
  const std::size_t at = sub_position(object, sub);
  if (at == object.size()) return errc::unknown_object;
  if (object[at].type != type) return errc::type_mismatch;
  auto n = object[at].default_for(0);
  if (!n) return errc::unknown_object;
  return n.value().to_uint64();
}

template <class Entry, std::size_t Capacity, class Decode>
[[nodiscard]] constexpr result<entry_list<Entry, Capacity>>
read_default(const od::dictionary &dict, std::uint16_t index, od::data_type type,
             Decode decode) noexcept {
  const std::span<const od::entry> object = dict.object(index);
  FIELDCODEC_TRY(const std::uint64_t count, default_of(object, 0, od::data_type::unsigned8));
  for (const od::entry &e : object) { // every entry, also those beyond the default count
    if (e.sub != 0U && e.type != type) return errc::type_mismatch;
  }
  if (count > Capacity) return errc::too_long;
  entry_list<Entry, Capacity> list;
  for (std::size_t i = 1; i <= count; ++i) {
    FIELDCODEC_TRY(const std::uint64_t v, default_of(object, static_cast<std::uint8_t>(i), type));
    FIELDCODEC_TRY(list.items[list.count], decode(v));
    ++list.count;
  }
  return list;
}
} // namespace detail

/// The default mapping a dictionary declares in CiA 301 mapping object `index` (1600h..17FFh,
/// 1A00h..1BFFh): sub 0's default is the number of entries, subs 1..n hold UNSIGNED32 entries.
/// Errors: unknown_object (no such object, a sub-entry 0..n missing or without a default),
/// type_mismatch (sub 0 not UNSIGNED8, an entry not UNSIGNED32 — a POWERLINK dictionary:
/// use default_powerlink_mapping), too_long (more than Capacity entries).
template <std::size_t Capacity = max_entries>
[[nodiscard]] constexpr result<entry_list<mapping_entry, Capacity>>
default_mapping(const od::dictionary &dict, std::uint16_t index) noexcept {
  return detail::read_default<mapping_entry, Capacity>(
      dict, index, od::data_type::unsigned32, [](std::uint64_t v) -> result<mapping_entry> {
        if (v > 0xFFFF'FFFFU) return errc::overflow;
        return mapping_entry::from_u32(static_cast<std::uint32_t>(v));
      });
}

/// The default mapping a POWERLINK dictionary declares in mapping object `index` (1600h..16FFh,
/// 1A00h..1AFFh): subs 1..n hold UNSIGNED64 entries. Errors: as default_mapping (type_mismatch
/// when the entries are not UNSIGNED64), out_of_range (reserved bits set in an entry).
template <std::size_t Capacity = powerlink_max_entries>
[[nodiscard]] constexpr result<entry_list<powerlink_mapping_entry, Capacity>>
default_powerlink_mapping(const od::dictionary &dict, std::uint16_t index) noexcept {
  return detail::read_default<powerlink_mapping_entry, Capacity>(
      dict, index, od::data_type::unsigned64,
      [](std::uint64_t v) { return powerlink_mapping_entry::from_u64(v); });
}

// ---------------------------------------------------------------------------------------------
// Compile-time mappings

namespace compile_error {
// Not constexpr on purpose: reaching one of these while building a static_mapping is a compile
// error whose message names the problem.
inline void pdo_mapping_entry_has_zero_length() noexcept {}
inline void pdo_mapping_object_not_in_dictionary() noexcept {}
inline void pdo_mapping_object_not_mappable_in_this_direction() noexcept {}
inline void pdo_mapping_object_access_forbids_this_direction() noexcept {}
inline void pdo_mapping_length_does_not_match_object_type() noexcept {}
inline void pdo_mapping_exceeds_pdo_length() noexcept {}
inline void pdo_mapping_has_more_than_64_entries() noexcept {}
inline void pdo_mapping_entries_overlap() noexcept {}
} // namespace compile_error

/// A mapping fixed at compile time with its bit offsets. Built from a dictionary it knows each
/// object's signedness (`signs`); built from lengths only, every sign is unknown (raw bits).
template <std::size_t N>
struct static_mapping {
  std::array<mapping_entry, N> entries{};
  std::array<std::size_t, N> offsets{};
  std::array<signedness, N> signs{};
  std::size_t total_bits = 0;

  [[nodiscard]] constexpr std::size_t bytes() const noexcept { return (total_bits + 7U) / 8U; }
  /// Mapping object values (sub 1..N).
  [[nodiscard]] constexpr std::array<std::uint32_t, N> values() const noexcept {
    std::array<std::uint32_t, N> v{};
    for (std::size_t i = 0; i < N; ++i) v[i] = entries[i].to_u32();
    return v;
  }
  /// Pack the value of entry i (any integer type, or a scoped enum such as ds402::mode as its
  /// value), checked against the object's signedness and width. Errors: invalid_argument (no
  /// entry i), overflow, buffer_too_small.
  template <detail::pdo_value T>
  [[nodiscard]] constexpr status set(std::span<std::uint8_t> pdo, std::size_t i,
                                     T value) const noexcept {
    if (i >= N) return errc::invalid_argument;
    return detail::pack_value(pdo, offsets[i], entries[i].bits, signs[i],
                              detail::as_integer(value));
  }
  /// The value of entry i with the object's signedness (raw bits when unknown).
  /// Errors: invalid_argument, truncated, overflow (does not fit T).
  template <wire_integer T = std::int64_t>
  [[nodiscard]] constexpr result<T> get(std::span<const std::uint8_t> pdo,
                                        std::size_t i) const noexcept {
    if (i >= N) return errc::invalid_argument;
    return detail::unpack_value<T>(pdo, offsets[i], entries[i].bits, signs[i]);
  }
  /// Entry i read as two's complement whatever the object's type (for length-only mappings).
  [[nodiscard]] constexpr result<std::int64_t> get_signed(std::span<const std::uint8_t> pdo,
                                                          std::size_t i) const noexcept {
    if (i >= N) return errc::invalid_argument;
    return unpack_signed(pdo, offsets[i], entries[i].bits);
  }
};

namespace detail {
consteval void raise(mapping_problem p) {
  switch (p) {
  case mapping_problem::none: return;
  case mapping_problem::zero_length: compile_error::pdo_mapping_entry_has_zero_length(); return;
  case mapping_problem::no_object: compile_error::pdo_mapping_object_not_in_dictionary(); return;
  case mapping_problem::not_mappable:
    compile_error::pdo_mapping_object_not_mappable_in_this_direction();
    return;
  case mapping_problem::no_access:
    compile_error::pdo_mapping_object_access_forbids_this_direction();
    return;
  case mapping_problem::length_mismatch:
    compile_error::pdo_mapping_length_does_not_match_object_type();
    return;
  case mapping_problem::too_long: compile_error::pdo_mapping_exceeds_pdo_length(); return;
  case mapping_problem::too_many_entries:
    compile_error::pdo_mapping_has_more_than_64_entries();
    return;
  case mapping_problem::overlap: compile_error::pdo_mapping_entries_overlap(); return;
  }
}
template <std::size_t N>
constexpr static_mapping<N> layout(const mapping_entry (&e)[N]) noexcept {
  static_mapping<N> m;
  for (std::size_t i = 0; i < N; ++i) {
    m.entries[i] = e[i];
    m.offsets[i] = m.total_bits;
    m.total_bits += e[i].bits;
  }
  return m;
}
} // namespace detail

/// A mapping checked at compile time against lengths only (no dictionary): no zero-length
/// entry, at most 64 entries, total <= max_bits. Mistakes do not compile.
template <std::size_t N>
consteval static_mapping<N> make_static_mapping(const mapping_entry (&e)[N],
                                                std::size_t max_bits = can_max_bits) {
  if (N > max_entries) detail::raise(mapping_problem::too_many_entries);
  std::size_t total = 0;
  for (const auto &x : e) {
    if (x.bits == 0U) detail::raise(mapping_problem::zero_length);
    total += x.bits;
  }
  if (total > max_bits) detail::raise(mapping_problem::too_long);
  return detail::layout(e);
}

/// A mapping checked at compile time against a (constexpr) dictionary, with each object's
/// signedness. Mistakes do not compile.
template <std::size_t N>
consteval static_mapping<N> make_static_mapping(const od::dictionary &dict, direction d,
                                                const mapping_entry (&e)[N],
                                                std::size_t max_bits = can_max_bits) {
  const auto r = check_mapping(dict, d, std::span<const mapping_entry>(e, N), max_bits);
  detail::raise(r.problem);
  auto m = detail::layout(e);
  for (std::size_t i = 0; i < N; ++i) {
    od::data_type type{};
    (void)detail::check_object(dict, d, e[i].index, e[i].sub, e[i].bits, type);
    m.signs[i] = signedness_of(type);
  }
  return m;
}

// ---------------------------------------------------------------------------------------------
// Communication parameters (1400h..15FFh, 1800h..19FFh)

/// Sub 1: COB-ID used by the PDO. Bit 31 set = PDO not valid, bit 30 set = no RTR allowed,
/// bit 29 set = 29-bit identifier (not supported by this toolkit's CAN frames).
struct cob_id_param {
  std::uint16_t id = 0;
  bool valid = true;
  bool rtr_allowed = true;
  friend constexpr bool operator==(const cob_id_param &, const cob_id_param &) = default;
};

inline constexpr std::uint32_t cob_id_invalid_bit = 0x8000'0000U;
inline constexpr std::uint32_t cob_id_no_rtr_bit = 0x4000'0000U;
inline constexpr std::uint32_t cob_id_frame_bit = 0x2000'0000U;

/// Errors: invalid_argument (id > 0x7FF).
[[nodiscard]] constexpr result<std::uint32_t> encode_cob_id(cob_id_param p) noexcept {
  if (p.id > max_can_id) return errc::invalid_argument;
  return std::uint32_t{p.id} | (p.valid ? 0U : cob_id_invalid_bit) |
         (p.rtr_allowed ? 0U : cob_id_no_rtr_bit);
}
/// Errors: out_of_range (bit 29 set: extended identifier; or bits 11..28 set with bit 29 clear).
[[nodiscard]] constexpr result<cob_id_param> decode_cob_id(std::uint32_t v) noexcept {
  if ((v & cob_id_frame_bit) != 0U) return errc::out_of_range;
  if ((v & 0x1FFF'F800U) != 0U) return errc::out_of_range;
  return cob_id_param{static_cast<std::uint16_t>(v & 0x7FFU), (v & cob_id_invalid_bit) == 0U,
                      (v & cob_id_no_rtr_bit) == 0U};
}

/// Sub 2: transmission type.
enum class transmission : std::uint8_t {
  synchronous_acyclic, ///< 0: on SYNC after an event
  synchronous_cyclic,  ///< 1..240: every n-th SYNC
  reserved,            ///< 241..251
  rtr_synchronous,     ///< 252: sampled at SYNC, sent on RTR (TPDO only)
  rtr_event,           ///< 253: sent on RTR (TPDO only)
  event_manufacturer,  ///< 254: event-driven, manufacturer-specific
  event_profile,       ///< 255: event-driven, device/application profile
};

[[nodiscard]] constexpr transmission classify_transmission(std::uint8_t type) noexcept {
  if (type == 0U) return transmission::synchronous_acyclic;
  if (type <= 240U) return transmission::synchronous_cyclic;
  if (type <= 251U) return transmission::reserved;
  if (type == 252U) return transmission::rtr_synchronous;
  if (type == 253U) return transmission::rtr_event;
  if (type == 254U) return transmission::event_manufacturer;
  return transmission::event_profile;
}

/// A PDO's communication parameter record.
struct comm_params {
  cob_id_param cob_id{};
  std::uint8_t transmission_type = 255;
  std::uint16_t inhibit_time = 0; ///< sub 3, multiples of 100 µs (TPDO)
  std::uint16_t event_timer = 0;  ///< sub 5, ms (0 = off)
  std::uint8_t sync_start = 0;    ///< sub 6, SYNC counter start value (0 = not used)

  /// Inhibit time in microseconds.
  [[nodiscard]] constexpr std::uint32_t inhibit_us() const noexcept {
    return std::uint32_t{inhibit_time} * 100U;
  }
};

/// Check a record for the given direction. Errors: out_of_range (reserved transmission type
/// 241..251, RTR types on an RPDO, sync_start above 240), invalid_argument (COB-ID > 0x7FF).
[[nodiscard]] constexpr status check(const comm_params &p, direction d) noexcept {
  if (p.cob_id.id > max_can_id) return errc::invalid_argument;
  const auto t = classify_transmission(p.transmission_type);
  if (t == transmission::reserved) return errc::out_of_range;
  if (d == direction::rpdo &&
      (t == transmission::rtr_synchronous || t == transmission::rtr_event)) {
    return errc::out_of_range;
  }
  if (p.sync_start > 240U) return errc::out_of_range;
  return {};
}

/// The PDO as a CAN frame: COB-ID from the parameters, the packed bytes as payload.
/// Errors: bad_state (PDO not valid), too_long (more than 8 bytes), invalid_argument.
[[nodiscard]] constexpr result<can_frame> to_frame(cob_id_param id,
                                                   std::span<const std::uint8_t> bytes) noexcept {
  if (!id.valid) return errc::bad_state;
  return make_frame(id.id, bytes);
}

} // namespace fieldcodec::canopen::pdo
