// pacontrol: RS232 request encoder and the byte-at-a-time acknowledgement decoder.
#include "io.hpp"

#include <fieldcodec/pacontrol/serial_decoder.hpp>

namespace serial = fieldcodec::pacontrol::serial;
using fieldcodec::pacontrol::value;

int main() {
  std::array<std::uint8_t, serial::max_frame_size> tx{};
  const serial::request req{0x0A87, fw::rx_register[0], value::of_int(fw::rx_register[1]).value()};
  if (auto n = serial::encode_request(req, tx)) fw::transmit(std::span(tx).first(n.value()));
  serial::decoder rx({{}, serial::accept::acknowledgements});
  for (int i = 0; i < 64; ++i) {
    auto r = rx.push(fw::rx_register[i]);
    if (r && r.value() == serial::frame_kind::acknowledgement) {
      fw::tx_register[0] = static_cast<std::uint8_t>(rx.acknowledgement().operating_status);
    }
  }
  return 0;
}
