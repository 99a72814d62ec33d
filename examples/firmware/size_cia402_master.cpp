// A CiA 402 master: SDO client, the configuration runner (master::configurator) with a small
// list, the drive helper (master::drive: enable, mode switch, profile position handshake, fault
// report) and two PDOs with mappings checked at compile time against the generated XENAX
// dictionary (RPDO: controlword + target position, TPDO: statusword + position actual value).
// Budget: docs/performance.md, "Cortex-M".
#include "io.hpp"

#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/master/configurator.hpp>
#include <fieldcodec/master/drive.hpp>
#include <fieldcodec/xenax/drive_profile.hpp>

namespace co = fieldcodec::canopen;
namespace pdo = fieldcodec::canopen::pdo;
namespace master = fieldcodec::master;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;

namespace {
constexpr pdo::mapping_entry rx_entries[] = {{0x6040, 0, 16}, {0x607A, 0, 32}};
constexpr auto rx_map =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::rpdo, rx_entries);
constexpr pdo::mapping_entry tx_entries[] = {{0x6041, 0, 16}, {0x6064, 0, 32}};
constexpr auto tx_map =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::tpdo, tx_entries);

constexpr std::uint8_t window[] = {0xF4, 0x01, 0x00, 0x00};
constexpr std::uint8_t cob[] = {0x80, 0x01, 0x00, 0x00};
constexpr master::config_item items[] = {
    {{0x6065, 0}, window, 0, "Following Position Error Window"},
    {{0x1800, 1}, cob, master::config_flag::node_relative, "TPDO 1 COB-ID"},
};

co::can_frame received() {
  co::can_frame in{};
  in.id = static_cast<std::uint16_t>(0x580U + fw::rx_register[0]);
  in.dlc = 8;
  in.data = fw::receive<8>();
  return in;
}
} // namespace

int main() {
  co::sdo::client client(1, 500);
  // configuration at boot
  master::configurator config(client, {.retries = 2, .timeout_ms = 200, .verify = true});
  if (auto s = config.start({items, {}, 1}, fw::tick)) {
    for (const auto &f : s.value().send) fw::transmit(f.data);
  }
  while (config.busy()) {
    for (const auto &f : config.on_frame(received(), fw::tick).send) fw::transmit(f.data);
    for (const auto &f : config.poll(fw::tick).send) fw::transmit(f.data);
  }
  fw::tx_register[1] = static_cast<std::uint8_t>(config.state());

  // the cyclic task
  master::drive axis({.profile = fieldcodec::xenax::profile});
  (void)axis.switch_mode(fieldcodec::ds402::mode::profile_position, fw::tick);
  (void)axis.enable(fw::tick);
  std::array<std::uint8_t, 4> sdo_buffer{};
  for (int cycle = 0; cycle < 100; ++cycle) {
    const auto tpdo = fw::receive<8>();
    const auto sw = static_cast<std::uint16_t>(tx_map.get(tpdo, 0).value_or(0));
    const auto out = axis.cycle(sw, fw::tick, static_cast<std::int8_t>(fw::rx_register[9]));
    if (out.sdo) {
      auto s = out.sdo->what == master::sdo_request::kind::download
                   ? client.download(out.sdo->address, out.sdo->bytes(), fw::tick)
                   : client.upload(out.sdo->address, sdo_buffer, fw::tick);
      if (s) {
        for (const auto &f : s.value().send) fw::transmit(f.data);
      }
    }
    for (const auto &f : client.on_frame(received(), fw::tick).send) fw::transmit(f.data);
    if (client.state() == co::sdo::transfer_state::done) axis.sdo_done(client.received(), fw::tick);
    if (auto e = client.error(); e && client.state() == co::sdo::transfer_state::failed) {
      axis.sdo_failed(*e, fw::tick);
    }
    if (axis.state() == master::drive_state::enabled && fw::rx_register[10] != 0U) {
      (void)axis.move_to(static_cast<std::int32_t>(fw::rx_register[11]), fw::tick);
    }
    if (axis.state() == master::drive_state::fault && fw::rx_register[12] != 0U) {
      (void)axis.reset_fault(fw::tick);
    }
    std::array<std::uint8_t, 8> rpdo{};
    (void)rx_map.set(rpdo, 0, out.controlword);
    (void)rx_map.set(rpdo, 1, static_cast<std::uint32_t>(out.target));
    fw::transmit(rpdo);
    if (auto pos = tx_map.get_signed(tpdo, 1)) {
      fw::tx_register[0] = static_cast<std::uint8_t>(pos.value());
    }
  }
  if (auto e = axis.error()) fw::tx_register[2] = static_cast<std::uint8_t>(e->error_code);
  return 0;
}
