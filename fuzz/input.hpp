// The fuzz input as a stream of arguments: bytes, little-endian words; zero once exhausted, so
// that every harness can read as much as it likes from any input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace fuzz_input {

struct reader {
  std::span<const std::uint8_t> in;
  std::uint8_t byte() {
    if (in.empty()) return 0;
    const std::uint8_t b = in[0];
    in = in.subspan(1);
    return b;
  }
  std::uint16_t u16() { return static_cast<std::uint16_t>(byte() | (byte() << 8U)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(u16() | (u16() << 16U)); }
  [[nodiscard]] bool empty() const { return in.empty(); }
  /// The next `n` bytes (zeros past the end).
  std::vector<std::uint8_t> bytes(std::size_t n) {
    std::vector<std::uint8_t> v(n);
    for (auto &b : v) b = byte();
    return v;
  }
};

} // namespace fuzz_input
