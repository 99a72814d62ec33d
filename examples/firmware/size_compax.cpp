// compax: BCD positions and Nx program records (encode a record, decode one from the bus).
#include "io.hpp"

#include <fieldcodec/compax/nx.hpp>
#include <fieldcodec/compax/position.hpp>

namespace compax = fieldcodec::compax;

int main() {
  const auto pos = static_cast<std::int64_t>(fw::rx_register[0]) * 1000;
  if (auto b = compax::encode_bcd_position(pos)) fw::transmit(b.value());
  if (auto p = compax::decode_bcd_position(fw::receive<6>())) {
    fw::tx_register[0] = static_cast<std::uint8_t>(p.value());
  }
  if (auto c = compax::nx::decode_record(fw::receive<20>())) {
    if (auto r = compax::nx::encode_record(c.value())) fw::transmit(r.value());
  }
  return 0;
}
