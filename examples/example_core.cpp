// The core primitives on the manuals' own numbers: a COMPAX BCD position and a DPQ pressure.
#include <fieldcodec/core/bcd.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/scaling.hpp>

#include <cstdio>

namespace fc = fieldcodec;

int main() {
  // COMPAX POSA 7350.150 mm in 0.001 mm steps: sign byte + 10 BCD digits.
  constexpr auto posa = fc::bcd::encode_signed<6>(7'350'150);
  std::printf("POSA 7350.150 mm ->");
  for (auto b : posa.value()) std::printf(" %02X", b);
  std::printf("\n");

  // DPQ Inj. P Limit 1 = 4.0 bar, scale 327.67, 4-byte field: raw 1311 = 0x051F.
  constexpr fc::scaling::linear pressure{{32767, 2}, {0, 0}};
  constexpr auto raw = fc::scaling::to_raw(4.0, pressure, {4, false}, {{0, 0}, {5000, 0}});
  static_assert(raw.value() == 1311);
  const auto bytes = fc::to_bytes(static_cast<std::uint32_t>(raw.value()), fc::byte_order::little);
  std::printf("Inj. P Limit 1 4.0 bar -> raw %lld ->", static_cast<long long>(raw.value()));
  for (auto b : bytes) std::printf(" %02X", b);
  std::printf("\n");

  // A value the card cannot hold is refused, never wrapped.
  auto too_big = fc::scaling::to_raw(5000.5, pressure, {4, false}, {{0, 0}, {5000, 0}});
  std::printf("5000.5 bar -> %s\n", fc::to_string(too_big.error()).data());
  return posa.value()[5] == 0x50 && raw.value() == 1311 ? 0 : 1;
}
