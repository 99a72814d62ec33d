// Helpers for the PA-CONTROL tests: byte strings written as hex text.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace pactest {

/// Up to 160 bytes parsed from "01 02 3B …" at compile time.
struct bytes {
  std::array<std::uint8_t, 160> data{};
  std::size_t size = 0;

  [[nodiscard]] constexpr std::span<const std::uint8_t> span() const noexcept {
    return {data.data(), size};
  }
  friend constexpr bool operator==(const bytes &a, std::span<const std::uint8_t> b) noexcept {
    return a.size == b.size() && std::equal(b.begin(), b.end(), a.data.begin());
  }
};

constexpr int nibble(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

/// "01 02 30" → {0x01, 0x02, 0x30}. Spaces are ignored.
constexpr bytes hex(std::string_view s) noexcept {
  bytes b;
  int hi = -1;
  for (const char c : s) {
    const int v = nibble(c);
    if (v < 0) continue;
    if (hi < 0) {
      hi = v;
    } else {
      b.data[b.size++] = static_cast<std::uint8_t>(hi * 16 + v);
      hi = -1;
    }
  }
  return b;
}

/// The bytes of a text (control characters written as \x01 etc. by the caller).
constexpr bytes text(std::string_view s) noexcept {
  bytes b;
  for (const char c : s) b.data[b.size++] = static_cast<std::uint8_t>(c);
  return b;
}

/// SOH STX body ETX check EOT.
constexpr bytes frame(std::string_view body, std::string_view check) noexcept {
  bytes b;
  b.data[b.size++] = 0x01;
  b.data[b.size++] = 0x02;
  for (const char c : body) b.data[b.size++] = static_cast<std::uint8_t>(c);
  b.data[b.size++] = 0x03;
  for (const char c : check) b.data[b.size++] = static_cast<std::uint8_t>(c);
  b.data[b.size++] = 0x04;
  return b;
}

} // namespace pactest
