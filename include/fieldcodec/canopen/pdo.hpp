// fieldcodec — PDO mapping entries, bit-level packing, mappings checked against a dictionary
// (at run time and at compile time), and PDO communication parameters (CiA 301).
//
// A mapping entry (sub 1..64 of objects 1600h..17FFh / 1A00h..1BFFh) is
//   index << 16 | sub-index << 8 | length in bits.
// Values are packed in mapping order from bit 0 of byte 0 upwards; inside the PDO, bit k is
// bit (k mod 8) of byte k / 8 and every value is little-endian ("little-endian bit order"), so
// byte-aligned values look exactly like their SDO encoding.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::canopen::pdo {

/// Longest PDO in bits on classic CAN (8 bytes). CoE and POWERLINK PDOs are longer: pass the
/// limit of the transport (e.g. 8 * 1490 bytes for POWERLINK, the sync-manager size for CoE).
inline constexpr std::size_t can_max_bits = 64;
/// Most entries a mapping object holds (sub 1..64).
inline constexpr std::size_t max_entries = 64;

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
  if (offset % 8U == 0U && length % 8U == 0U) { // whole bytes: a little-endian store
    return store_unsigned(pdo.subspan(offset / 8U), length / 8U, raw, byte_order::little);
  }
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
  if (offset % 8U == 0U && length % 8U == 0U) { // whole bytes: a little-endian load
    return load_unsigned(pdo.subspan(offset / 8U), length / 8U, byte_order::little);
  }
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

/// Read `length` bits as a two's complement number, sign-extended.
[[nodiscard]] constexpr result<std::int64_t>
unpack_signed(std::span<const std::uint8_t> pdo, std::size_t offset, std::size_t length) noexcept {
  auto u = unpack(pdo, offset, length);
  if (!u) return u.error();
  std::uint64_t v = u.value();
  if (length < 64U && ((v >> (length - 1U)) & 1U) != 0U) v |= ~std::uint64_t{0} << length;
  return static_cast<std::int64_t>(v);
}

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
  too_many_entries, ///< more than 64 entries
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
  case mapping_problem::too_many_entries: return "more than 64 entries";
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
  case mapping_problem::none: break;
  }
  return errc::invalid_argument;
}

/// Check one entry against a dictionary (dummy entries against their data type).
[[nodiscard]] constexpr mapping_problem check_entry(const od::dictionary &dict, direction d,
                                                    mapping_entry m) noexcept {
  if (m.bits == 0U) return mapping_problem::zero_length;
  if (m.is_dummy()) {
    if (m.sub != 0U) return mapping_problem::no_object;
    const auto t = static_cast<od::data_type>(m.index);
    if (t == od::data_type::boolean) {
      return m.bits == 1U ? mapping_problem::none : mapping_problem::length_mismatch;
    }
    return m.bits == 8U * od::fixed_size(t) ? mapping_problem::none
                                            : mapping_problem::length_mismatch;
  }
  const od::entry *e = dict.find(m.index, m.sub);
  if (e == nullptr) return mapping_problem::no_object;
  if (d == direction::rpdo) {
    if (!od::mappable_rx(e->pdo)) return mapping_problem::not_mappable;
    if (!od::writable(e->access_type)) return mapping_problem::no_access;
  } else {
    if (!od::mappable_tx(e->pdo)) return mapping_problem::not_mappable;
    if (!od::readable(e->access_type)) return mapping_problem::no_access;
  }
  if (!length_fits(*e, m.bits)) return mapping_problem::length_mismatch;
  return mapping_problem::none;
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

/// check_mapping as a result: the total length in bits. Errors: see to_errc.
[[nodiscard]] constexpr result<std::size_t> validate(const od::dictionary &dict, direction d,
                                                     std::span<const mapping_entry> entries,
                                                     std::size_t max_bits = can_max_bits) noexcept {
  const auto r = check_mapping(dict, d, entries, max_bits);
  if (!r.ok()) return to_errc(r.problem);
  return r.total_bits;
}

/// Pack one raw value per entry (dummy entries take 0) into `pdo`; returns the bytes used
/// (total bits rounded up). Signed objects take their two's complement bits, e.g.
/// static_cast<std::uint64_t>(-5) for an INTEGER16 is fine: only the low `bits` are checked to
/// be the sign-extension. Errors: bad_length (value count != entry count, zero length),
/// overflow, buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> pack_all(std::span<const mapping_entry> entries,
                                                     std::span<const std::uint64_t> raws,
                                                     std::span<std::uint8_t> pdo) noexcept {
  if (raws.size() != entries.size()) return errc::bad_length;
  std::size_t offset = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::size_t n = entries[i].bits;
    std::uint64_t v = raws[i];
    if (n < 64U && n > 0U) {
      const std::uint64_t high = v >> (n - 1U);
      const std::uint64_t all_ones = ~std::uint64_t{0} >> (n - 1U);
      if (high == all_ones) v &= (std::uint64_t{1} << n) - 1U; // a sign-extended negative value
    }
    FIELDCODEC_TRY_STATUS(pack(pdo, offset, n, v));
    offset += n;
  }
  return (offset + 7U) / 8U;
}

/// Unpack every entry's raw bits (zero-extended) into `raws`. Errors: bad_length (raws too
/// small), truncated (the PDO is shorter than the mapping).
[[nodiscard]] constexpr status unpack_all(std::span<const mapping_entry> entries,
                                          std::span<const std::uint8_t> pdo,
                                          std::span<std::uint64_t> raws) noexcept {
  if (raws.size() < entries.size()) return errc::bad_length;
  std::size_t offset = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    auto v = unpack(pdo, offset, entries[i].bits);
    if (!v) return v.error();
    raws[i] = v.value();
    offset += entries[i].bits;
  }
  return {};
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
} // namespace compile_error

/// A mapping fixed at compile time with its bit offsets.
template <std::size_t N>
struct static_mapping {
  std::array<mapping_entry, N> entries{};
  std::array<std::size_t, N> offsets{};
  std::size_t total_bits = 0;

  [[nodiscard]] constexpr std::size_t bytes() const noexcept { return (total_bits + 7U) / 8U; }
  /// Mapping object values (sub 1..N).
  [[nodiscard]] constexpr std::array<std::uint32_t, N> values() const noexcept {
    std::array<std::uint32_t, N> v{};
    for (std::size_t i = 0; i < N; ++i) v[i] = entries[i].to_u32();
    return v;
  }
  /// Pack the value of entry i (two's complement bits for signed objects are accepted).
  [[nodiscard]] constexpr status set(std::span<std::uint8_t> pdo, std::size_t i,
                                     std::uint64_t raw) const noexcept {
    if (i >= N) return errc::invalid_argument;
    const std::size_t n = entries[i].bits;
    if (n < 64U && (raw >> (n - 1U)) == (~std::uint64_t{0} >> (n - 1U))) {
      raw &= (std::uint64_t{1} << n) - 1U;
    }
    return pack(pdo, offsets[i], n, raw);
  }
  [[nodiscard]] constexpr result<std::uint64_t> get(std::span<const std::uint8_t> pdo,
                                                    std::size_t i) const noexcept {
    if (i >= N) return errc::invalid_argument;
    return unpack(pdo, offsets[i], entries[i].bits);
  }
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
  }
}
template <std::size_t N>
consteval static_mapping<N> layout(const mapping_entry (&e)[N]) {
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

/// A mapping checked at compile time against a (constexpr) dictionary. Mistakes do not compile.
template <std::size_t N>
consteval static_mapping<N> make_static_mapping(const od::dictionary &dict, direction d,
                                                const mapping_entry (&e)[N],
                                                std::size_t max_bits = can_max_bits) {
  const auto r = check_mapping(dict, d, std::span<const mapping_entry>(e, N), max_bits);
  detail::raise(r.problem);
  return detail::layout(e);
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
