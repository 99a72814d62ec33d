// fieldcodec — a device's configuration list: the SDO downloads that bring it from its EDS
// defaults to the values of a DCF, in the order they must be written, and the identity to check.
//
// fieldcodec-gen writes one from a DCF (`--config-list FILE`, docs/master.md); a program may also
// write its own. The list is data only: `master::configurator` runs it through an SDO client,
// `write_concise_dcf` turns it into the binary form of object 1F22h.
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
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < n; ++i) v |= std::uint64_t{item.value[i]} << (8U * i);
  const std::uint64_t max = n == 8U ? ~std::uint64_t{0} : (std::uint64_t{1} << (8U * n)) - 1U;
  if (v > max - node) return errc::overflow;
  v += node;
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>(v >> (8U * i));
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

} // namespace fieldcodec::master
