// fieldcodec — values of communication objects as the node services read and write them:
// 1..4 little-endian bytes as an unsigned 32-bit number, read through a store's parts
// interface (canopen/object_store.hpp) or written with the store's set().
#pragma once

#include <fieldcodec/canopen/abort_code.hpp>
#include <fieldcodec/od/address.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fieldcodec::canopen::node {

using sdo::abort_code;

/// A value of 1..4 bytes (little-endian) as an unsigned 32-bit number; nullopt for any other
/// length (the store then refuses the write with its own length abort code).
[[nodiscard]] constexpr std::optional<std::uint32_t>
u32_of(std::span<const std::uint8_t> v) noexcept {
  if (v.empty() || v.size() > 4U) return std::nullopt;
  std::uint32_t n = 0;
  for (std::size_t i = 0; i < v.size(); ++i) n |= std::uint32_t{v[i]} << (8U * i);
  return n;
}

/// Read a value of at most 4 bytes through a store's parts interface (canopen::object_store's
/// read; nullopt when the object is missing, unreadable or longer).
template <class Store>
[[nodiscard]] constexpr std::optional<std::uint32_t> read_u32(const Store &s,
                                                              od::address a) noexcept {
  std::array<std::uint8_t, 4> b{};
  std::size_t total = 0;
  if (s.read(a, 0, b, total) != abort_code::none || total == 0U || total > 4U) {
    return std::nullopt;
  }
  return u32_of(std::span<const std::uint8_t>(b).first(total));
}

/// Little-endian bytes of `v` in the width of `a`'s entry (1..4), for the node's own writes.
struct le_value {
  std::array<std::uint8_t, 4> bytes{};
  std::size_t size = 0;
  [[nodiscard]] constexpr std::span<const std::uint8_t> span() const noexcept {
    return std::span<const std::uint8_t>(bytes).first(size);
  }
};
[[nodiscard]] constexpr le_value encode_le(std::uint32_t v, std::size_t width) noexcept {
  le_value out;
  out.size = width > 4U ? 4U : width;
  for (std::size_t i = 0; i < out.size; ++i) {
    out.bytes[i] = static_cast<std::uint8_t>((v >> (8U * i)) & 0xFFU);
  }
  return out;
}

} // namespace fieldcodec::canopen::node
