// A CiA 402 master's codecs: SDO client, PDO pack/unpack with mappings checked at compile time
// against the generated XENAX dictionary, and the ds402 state walker. Budget: under a third of
// the ~13 kB a complete C CANopen stack with a small dictionary needs.
#include "io.hpp"

#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/ds402/state_machine.hpp>

namespace co = fieldcodec::canopen;
namespace pdo = fieldcodec::canopen::pdo;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;

namespace {
constexpr pdo::mapping_entry rx_entries[] = {{0x6040, 0, 16}, {0x607A, 0, 32}};
constexpr auto rx_map =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::rpdo, rx_entries);
constexpr pdo::mapping_entry tx_entries[] = {{0x6041, 0, 16}, {0x6064, 0, 32}};
constexpr auto tx_map =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::tpdo, tx_entries);
} // namespace

int main() {
  co::sdo::client client(1, 500);
  const auto mode = fw::receive<1>();
  if (auto s = client.download({0x6060, 0}, mode, fw::tick)) {
    for (const auto &f : s.value().send) fw::transmit(f.data);
  }
  for (int i = 0; i < 4; ++i) {
    co::can_frame in{};
    in.id = static_cast<std::uint16_t>(0x580U + fw::rx_register[0]);
    in.dlc = 8;
    in.data = fw::receive<8>();
    for (const auto &f : client.on_frame(in, fw::tick).send) fw::transmit(f.data);
  }
  fieldcodec::ds402::power_sequencer walker;
  const auto tpdo = fw::receive<8>();
  const auto sw = tx_map.get(tpdo, 0);
  auto cw = walker.next(static_cast<std::uint16_t>(sw.value_or(0)),
                        fieldcodec::ds402::state::operation_enabled);
  std::array<std::uint8_t, 8> rpdo{};
  (void)rx_map.set(rpdo, 0, cw.value_or(0));
  (void)rx_map.set(rpdo, 1, fw::rx_register[2]);
  fw::transmit(rpdo);
  if (auto pos = tx_map.get_signed(tpdo, 1))
    fw::tx_register[0] = static_cast<std::uint8_t>(pos.value());
  return 0;
}
