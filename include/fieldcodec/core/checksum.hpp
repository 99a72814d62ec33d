// fieldcodec — check values over byte ranges.
#pragma once

#include <cstdint>
#include <span>

namespace fieldcodec::checksum {

/// XOR of all bytes of `data`, starting from `initial`.
[[nodiscard]] constexpr std::uint8_t xor8(std::span<const std::uint8_t> data,
                                          std::uint8_t initial = 0) noexcept {
  std::uint8_t x = initial;
  for (const std::uint8_t b : data) x = static_cast<std::uint8_t>(x ^ b);
  return x;
}

/// XOR of the characters of `text` (for ASCII protocols), starting from `initial`.
[[nodiscard]] constexpr std::uint8_t xor8(std::span<const char> text,
                                          std::uint8_t initial = 0) noexcept {
  std::uint8_t x = initial;
  for (const char c : text) x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(c));
  return x;
}

} // namespace fieldcodec::checksum
