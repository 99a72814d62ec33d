// ds402: statusword decoding and the state walker a CiA 402 master runs every cycle.
#include "io.hpp"

#include <fieldcodec/ds402/state_machine.hpp>

int main() {
  namespace ds402 = fieldcodec::ds402;
  ds402::power_sequencer walker;
  for (int cycle = 0; cycle < 8; ++cycle) {
    auto cw = walker.next(fw::receive_u16(), ds402::state::operation_enabled);
    if (cw) fw::transmit(std::array<std::uint16_t, 1>{cw.value()});
  }
  return 0;
}
