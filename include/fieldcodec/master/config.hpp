// fieldcodec — a device's configuration list: the SDO downloads that bring it from its EDS
// defaults to the values of a DCF, in the order they must be written, and the identity to check.
//
// fieldcodec-gen writes one from a DCF (`--config-list FILE`, docs/master.md); a program may also
// write its own. The list is data only: `master::configurator` runs it through an SDO client,
// `write_concise_dcf` turns it into the binary form of object 1F22h, `check_concise_dcf` and
// `read_concise_entry` read that form back (a configurator runs a concise DCF as well).
//
// The other form of a configuration is what a CiA 302 master keeps in its own dictionary for
// each slave (`slave_objects`: 1F81h, 1F84h..1F88h, 1F22h, ...): fieldcodec-gen --nmt-slaves
// writes a table of them from a master DCF, `master::boot` boots a slave from them.
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::master {

/// Flags of a configuration item.
namespace config_flag {
/// The value is node-ID relative ("$NODEID+x"): the bytes hold x, the node-ID is added when the
/// list runs (for the DCF's node-ID or one given at run time).
inline constexpr std::uint8_t node_relative = 1U << 0U;
/// Not read back when the configurator verifies (write-only objects).
inline constexpr std::uint8_t no_verify = 1U << 1U;
} // namespace config_flag

/// One SDO download: object, value bytes (little-endian as on the bus), flags, and the object's
/// name for reports.
struct config_item {
  od::address address{};
  std::span<const std::uint8_t> value{};
  std::uint8_t flags = 0;
  std::string_view name{};
};

/// The identity to compare at boot (1000h, 1018h sub 1..4). 0 means "do not check" (CiA 302).
struct identity {
  std::uint32_t device_type = 0;  ///< 1000h
  std::uint32_t vendor_id = 0;    ///< 1018h sub 1
  std::uint32_t product_code = 0; ///< 1018h sub 2
  std::uint32_t revision = 0;     ///< 1018h sub 3
  std::uint32_t serial = 0;       ///< 1018h sub 4
  friend constexpr bool operator==(const identity &, const identity &) = default;
};

/// A whole configuration: the items in order, the identity, and the node-ID the DCF names (0:
/// none; node-ID-relative items then need a node-ID at run time).
struct configuration {
  std::span<const config_item> items{};
  identity expected{};
  std::uint8_t node_id = 0;
};

/// The bytes an item sends to `node`: the value as is, or x + node-ID for a node-relative item
/// (an unsigned number of the value's width, 1..8 bytes). Returns the number of bytes in `out`
/// (only for node-relative items; others send `item.value` directly and return its size with
/// `out` untouched). Errors: invalid_argument (node not 1..127 for a node-relative item),
/// bad_length (a node-relative value of 0 or more than 8 bytes), overflow (x + node-ID does not
/// fit the width).
[[nodiscard]] constexpr result<std::size_t> resolve(const config_item &item, std::uint8_t node,
                                                    std::span<std::uint8_t, 8> out) noexcept {
  if ((item.flags & config_flag::node_relative) == 0U) return item.value.size();
  if (node < 1U || node > 127U) return errc::invalid_argument;
  const std::size_t n = item.value.size();
  if (n == 0U || n > 8U) return errc::bad_length;
  // x + node-ID byte by byte, little-endian, with the carry (no 64-bit arithmetic on a small
  // controller); a carry out of the top byte does not fit the width
  unsigned carry = node;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned sum = item.value[i] + carry;
    out[i] = static_cast<std::uint8_t>(sum);
    carry = sum >> 8U;
  }
  if (carry != 0U) return errc::overflow;
  return n;
}

/// The bytes of `item` for `node` in `scratch` or in the item itself.
/// Errors as resolve.
[[nodiscard]] constexpr result<std::span<const std::uint8_t>>
resolved_value(const config_item &item, std::uint8_t node,
               std::span<std::uint8_t, 8> scratch) noexcept {
  FIELDCODEC_TRY(const std::size_t n, resolve(item, node, scratch));
  if ((item.flags & config_flag::node_relative) == 0U) return item.value;
  return std::span<const std::uint8_t>(scratch.data(), n);
}

/// Size of the concise DCF of `c`: 4 (count) + per item 7 (index, sub, size) + the value.
[[nodiscard]] constexpr std::size_t concise_dcf_size(const configuration &c) noexcept {
  std::size_t n = 4;
  for (const auto &i : c.items) n += 7U + i.value.size();
  return n;
}

/// Writes the concise DCF (the format of object 1F22h, CiA 302: UNSIGNED32 number of entries,
/// then per entry UNSIGNED16 index, UNSIGNED8 sub-index, UNSIGNED32 size, the data; all
/// little-endian) of `c` for `node` into `out`; node-relative values are resolved (a concise DCF
/// holds plain values). Returns the bytes written. Errors: buffer_too_small, and those of
/// resolve.
[[nodiscard]] constexpr result<std::size_t>
write_concise_dcf(const configuration &c, std::uint8_t node, std::span<std::uint8_t> out) noexcept {
  if (out.size() < concise_dcf_size(c)) return errc::buffer_too_small;
  std::size_t at = 0;
  const auto put = [&out, &at](std::uint64_t v, std::size_t bytes) {
    for (std::size_t i = 0; i < bytes; ++i) out[at++] = static_cast<std::uint8_t>(v >> (8U * i));
  };
  put(c.items.size(), 4);
  for (const auto &i : c.items) {
    std::array<std::uint8_t, 8> scratch{};
    FIELDCODEC_TRY(const auto v, resolved_value(i, node, scratch));
    put(i.address.index, 2);
    put(i.address.sub, 1);
    put(v.size(), 4);
    for (const std::uint8_t b : v) out[at++] = b;
  }
  return at;
}

// ---------------------------------------------------------------------------------------------
// The CiA 302 objects of the master for one slave

/// The bits of an NMT slave assignment (1F81h, one UNSIGNED32 per node, CiA 302-2).
namespace assignment_bit {
inline constexpr std::uint32_t slave = 1U << 0U; ///< the node is a slave of this master
/// Boot it (identity, software, configuration); clear: error control and start only.
inline constexpr std::uint32_t boot = 1U << 2U;
/// Mandatory: the network must not start without it (the caller's NMT start-up decides).
inline constexpr std::uint32_t mandatory = 1U << 3U;
/// Keep alive: never reset communication while the node is operational.
inline constexpr std::uint32_t keep_alive = 1U << 4U;
inline constexpr std::uint32_t verify_software = 1U << 5U; ///< check 1F56h sub 1 against 1F55h
inline constexpr std::uint32_t update_software = 1U << 6U; ///< a software update is allowed
/// Restore defaults first: "load" to 1011h, sub-index from 1F8Ah.
inline constexpr std::uint32_t restore = 1U << 7U;
} // namespace assignment_bit

/// Node guarding of the assignment: bits 8..15 retry factor, bits 16..31 guard time (ms).
[[nodiscard]] constexpr std::uint8_t retry_factor(std::uint32_t assignment) noexcept {
  return static_cast<std::uint8_t>(assignment >> 8U);
}
[[nodiscard]] constexpr std::uint16_t guard_time_ms(std::uint32_t assignment) noexcept {
  return static_cast<std::uint16_t>(assignment >> 16U);
}

/// What the master's own CiA 302 objects hold for one slave (each at sub-index = its node-ID).
struct slave_objects {
  std::uint32_t assignment = 0; ///< 1F81h
  /// 1F84h (device type), 1F85h..1F88h (vendor-ID, product code, revision, serial); 0: not
  /// checked.
  identity expected{};
  std::span<const std::uint8_t> concise_dcf{}; ///< 1F22h (empty: nothing to download)
  std::uint16_t consumer_time_ms = 0;          ///< the master's 1016h entry for the node (0: none)
  std::uint32_t software_version = 0;          ///< 1F55h: 1F56h sub 1 expected (bit 5)
  /// 1F26h / 1F27h: when both are set and the device's 1020h sub 1 / 2 show them, the device
  /// keeps its configuration and the concise DCF is not downloaded.
  std::uint32_t configuration_date = 0;
  std::uint32_t configuration_time = 0;
  std::uint8_t restore_sub = 0; ///< 1F8Ah: the 1011h sub-index for "load" (bit 7; 0: none)
  friend constexpr bool operator==(const slave_objects &a, const slave_objects &b) noexcept {
    bool same = a.concise_dcf.size() == b.concise_dcf.size();
    for (std::size_t i = 0; same && i < a.concise_dcf.size(); ++i) {
      same = a.concise_dcf[i] == b.concise_dcf[i];
    }
    return same && a.assignment == b.assignment && a.expected == b.expected &&
           a.consumer_time_ms == b.consumer_time_ms && a.software_version == b.software_version &&
           a.configuration_date == b.configuration_date &&
           a.configuration_time == b.configuration_time && a.restore_sub == b.restore_sub;
  }
};

/// One slave of a master DCF (fieldcodec-gen --nmt-slaves writes a table of them).
struct nmt_slave {
  std::uint8_t node = 0;
  slave_objects objects{};
};

/// The slave `node` of a table, or nullptr.
[[nodiscard]] constexpr const nmt_slave *find_slave(std::span<const nmt_slave> slaves,
                                                    std::uint8_t node) noexcept {
  for (const auto &s : slaves) {
    if (s.node == node) return &s;
  }
  return nullptr;
}

/// One entry of a concise DCF: the object and the bytes to download there.
struct concise_entry {
  od::address address{};
  std::span<const std::uint8_t> value{};
};

/// The entry of the concise DCF `dcf` that starts at `offset` (the first at 4, after the count);
/// `offset` moves past it. Errors: truncated (the header or the data ends early), bad_length (a
/// data size of 0: nothing to download).
[[nodiscard]] constexpr result<concise_entry> read_concise_entry(std::span<const std::uint8_t> dcf,
                                                                 std::size_t &offset) noexcept {
  if (offset > dcf.size() || dcf.size() - offset < 7U) return errc::truncated;
  const auto b = dcf.subspan(offset);
  const auto index = static_cast<std::uint16_t>(b[0] | (b[1] << 8U));
  const std::uint32_t size = std::uint32_t{b[3]} | (std::uint32_t{b[4]} << 8U) |
                             (std::uint32_t{b[5]} << 16U) | (std::uint32_t{b[6]} << 24U);
  if (size == 0U) return errc::bad_length;
  if (b.size() - 7U < size) return errc::truncated;
  offset += 7U + size;
  return concise_entry{{index, b[2]}, b.subspan(7, size)};
}

/// The number of entries of a concise DCF (1F22h format), after checking all of it: the count,
/// every entry's header and data inside the bytes, nothing after the last entry. Errors:
/// truncated (shorter than its count, an entry or its data), bad_length (bytes after the last
/// entry, or an entry of size 0).
[[nodiscard]] constexpr result<std::uint32_t>
check_concise_dcf(std::span<const std::uint8_t> dcf) noexcept {
  if (dcf.size() < 4U) return errc::truncated;
  const std::uint32_t n = std::uint32_t{dcf[0]} | (std::uint32_t{dcf[1]} << 8U) |
                          (std::uint32_t{dcf[2]} << 16U) | (std::uint32_t{dcf[3]} << 24U);
  std::size_t at = 4;
  for (std::uint32_t i = 0; i < n; ++i) {
    FIELDCODEC_TRY(const concise_entry e, read_concise_entry(dcf, at));
    (void)e;
  }
  if (at != dcf.size()) return errc::bad_length;
  return n;
}

} // namespace fieldcodec::master
