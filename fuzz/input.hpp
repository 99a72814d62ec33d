// The fuzz input as a stream of arguments: bytes, little-endian words; zero once exhausted, so
// that every harness can read as much as it likes from any input.
#pragma once

#include <cstdint>
#include <span>

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
};

} // namespace fuzz_input
