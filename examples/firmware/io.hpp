// Stand-ins for a firmware's hardware: bytes come from and go to volatile "registers", so the
// compiler cannot fold the codecs away and the measured sizes are honest.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace fw {

inline volatile std::uint8_t rx_register[64];
inline volatile std::uint8_t tx_register[64];
inline volatile std::uint32_t tick;

template <std::size_t N>
inline std::array<std::uint8_t, N> receive(std::size_t offset = 0) {
  std::array<std::uint8_t, N> a{};
  for (std::size_t i = 0; i < N; ++i) a[i] = rx_register[(offset + i) % 64U];
  return a;
}

template <class Range>
inline void transmit(const Range &bytes) {
  std::size_t i = 0;
  for (auto b : bytes) tx_register[i++ % 64U] = static_cast<std::uint8_t>(b);
}

inline std::uint16_t receive_u16() {
  return static_cast<std::uint16_t>(rx_register[0] | (rx_register[1] << 8U));
}

} // namespace fw
