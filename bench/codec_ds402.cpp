// Benchmarks of ds402/ (statusword decode + next controlword) against a hand-written version.
#include "codec_harness.hpp"

#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/ds402/statusword.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

namespace {

namespace ds402 = fieldcodec::ds402;

struct cycle_input {
  std::uint16_t statusword = 0;
  std::uint16_t previous = 0;
  bool operator==(const cycle_input &) const = default;
};

bench::inputs<cycle_input> g_cycles;

void fill_inputs() {
  bench::rng r(402);
  // Statuswords of every state (and a few undecodable ones) with random other bits.
  constexpr std::array<std::uint16_t, 9> patterns{0x0000, 0x0040, 0x0021, 0x0023, 0x0027,
                                                  0x0007, 0x000F, 0x0008, 0x0001};
  for (auto &c : g_cycles) {
    const std::uint16_t base = patterns[r.below(patterns.size())];
    const auto noise = static_cast<std::uint16_t>(r.below(0x10000) & 0xFF90U); // bits 4, 7..15
    c.statusword = static_cast<std::uint16_t>(base | noise);
    c.previous = static_cast<std::uint16_t>(r.below(2) != 0U ? 0x0080U : 0x000FU);
  }
}

/// Hand-written: decode the state from the statusword and pick the controlword that moves the
/// drive towards "operation enabled" (CiA 402 transitions 2, 3, 4, 15, 16; fault reset edge).
std::uint16_t hand_next_towards_enabled(std::uint16_t sw, std::uint16_t previous) {
  if ((sw & 0x4FU) == 0x00U) return 0x0000; // not ready to switch on
  if ((sw & 0x4FU) == 0x40U) return 0x0006; // switch on disabled
  if ((sw & 0x6FU) == 0x21U) return 0x000F; // ready to switch on
  if ((sw & 0x6FU) == 0x23U) return 0x000F; // switched on
  if ((sw & 0x6FU) == 0x27U) return 0x000F; // operation enabled
  if ((sw & 0x6FU) == 0x07U) return 0x000F; // quick stop active
  if ((sw & 0x4FU) == 0x0FU) return 0x0000; // fault reaction active
  if ((sw & 0x4FU) == 0x08U) return (previous & 0x80U) != 0U ? 0x00 : 0x80; // fault: edge
  return 0xFFFF;                                                            // undecodable
}

bench::registry make_registry() {
  fill_inputs();
  bench::registry r;
  bench::add_harness<g_cycles>(r);
  bench::add<g_cycles>(
      r, "ds402/decode_state",
      [](const cycle_input &c) {
        auto s = ds402::decode_state(c.statusword);
        return s ? static_cast<int>(s.value()) : -1;
      },
      [](const cycle_input &c) {
        const std::uint16_t sw = c.statusword;
        if ((sw & 0x4FU) == 0x00U) return 0;
        if ((sw & 0x4FU) == 0x40U) return 1;
        if ((sw & 0x6FU) == 0x21U) return 2;
        if ((sw & 0x6FU) == 0x23U) return 3;
        if ((sw & 0x6FU) == 0x27U) return 4;
        if ((sw & 0x6FU) == 0x07U) return 5;
        if ((sw & 0x4FU) == 0x0FU) return 6;
        if ((sw & 0x4FU) == 0x08U) return 7;
        return -1;
      });
  bench::add<g_cycles>(
      r, "ds402/statusword -> next_controlword",
      [](const cycle_input &c) -> std::uint16_t {
        return ds402::next_controlword(c.statusword, ds402::state::operation_enabled, c.previous)
            .value_or(0xFFFF);
      },
      [](const cycle_input &c) { return hand_next_towards_enabled(c.statusword, c.previous); });
  return r;
}

} // namespace

int main(int argc, char **argv) { return bench::main(argc, argv, make_registry()); }
