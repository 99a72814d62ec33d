// A firmware-style program for a Cortex-M4 master that drives a XENAX over CANopen, a COMPAX
// over Interbus, a PA-CONTROL over RS232 and a DPQ card: every module a drive controller or a
// PLC-side master uses, no heap, no exceptions, one cyclic task.
#include "io.hpp"

#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/compax/nx.hpp>
#include <fieldcodec/compax/position.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/dpq/parameter.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>

namespace co = fieldcodec::canopen;
namespace pdo = fieldcodec::canopen::pdo;
namespace ds402 = fieldcodec::ds402;
namespace compax = fieldcodec::compax;
namespace serial = fieldcodec::pacontrol::serial;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;
namespace dpqp = fieldcodec::dictionaries::dpq_parameters;

// Generated descriptors are standalone constants: naming one keeps only that one in flash.
using dpqp::inj_p_limit_1;

namespace {

// RPDO1: controlword + target position; TPDO1: statusword + actual position. A wrong entry
// here would not compile.
constexpr pdo::mapping_entry rx_entries[] = {{0x6040, 0, 16}, {0x607A, 0, 32}};
constexpr auto rx_map =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::rpdo, rx_entries);
constexpr pdo::mapping_entry tx_entries[] = {{0x6041, 0, 16}, {0x6064, 0, 32}};
constexpr auto tx_map =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::tpdo, tx_entries);

struct master {
  co::sdo::client sdo{1, 500};
  ds402::power_sequencer power;
  serial::decoder pa_rx{{{}, serial::accept::acknowledgements}};
  std::int32_t target = 0;
};

void send_can(const co::can_frame &f) { fw::transmit(f.data); }

void canopen_cycle(master &m) {
  // SDO: set profile position mode (6060h = 1) once, then serve responses.
  if (m.sdo.state() == co::sdo::transfer_state::idle) {
    const std::array<std::uint8_t, 1> mode{1};
    if (auto s = m.sdo.download({0x6060, 0}, mode, fw::tick)) {
      for (const auto &f : s.value().send) send_can(f);
    }
  }
  co::can_frame in{};
  in.id = static_cast<std::uint16_t>(0x580U + 1U);
  in.dlc = 8;
  in.data = fw::receive<8>();
  for (const auto &f : m.sdo.on_frame(in, fw::tick).send) send_can(f);

  // TPDO in → statusword → next controlword towards "operation enabled" → RPDO out.
  const auto tpdo = fw::receive<6>(8);
  const auto sw = tx_map.get(tpdo, 0);
  if (!sw) return;
  auto cw = m.power.next(static_cast<std::uint16_t>(sw.value()), ds402::state::operation_enabled);
  if (!cw) return;
  std::array<std::uint8_t, 8> rpdo{};
  if (rx_map.set(rpdo, 0, cw.value()) && rx_map.set(rpdo, 1, m.target)) {
    fw::transmit(std::span(rpdo).first(rx_map.bytes()));
  }
}

void compax_cycle() {
  // POSA in 0.001 mm as BCD for the process data, and an Nx record from the program memory.
  const std::int64_t posa = 7'350'150 + fw::rx_register[1];
  if (auto b = compax::encode_bcd_position(posa)) fw::transmit(b.value());
  if (auto c = compax::nx::decode_record(fw::receive<20>(20))) {
    if (auto r = compax::nx::encode_record(c.value())) fw::transmit(r.value());
  }
}

void pacontrol_cycle(master &m) {
  // Move axis 2 to an absolute position (cmd 0A87), then feed received bytes to the decoder.
  std::array<std::uint8_t, serial::max_frame_size> tx{};
  auto date =
      fieldcodec::pacontrol::value::of_int(static_cast<std::int32_t>(fw::rx_register[3])).value();
  if (auto n = serial::encode_request({0x0A87, 2, date}, tx)) {
    fw::transmit(std::span(tx).first(n.value()));
  }
  for (int i = 0; i < 16; ++i) {
    auto r = m.pa_rx.push(fw::rx_register[40 + i]);
    if (r && r.value() == serial::frame_kind::acknowledgement) {
      fw::tx_register[1] =
          static_cast<std::uint8_t>(m.pa_rx.acknowledgement().command_error_number);
    }
  }
}

void dpq_cycle() {
  // Inj. P Limit 1 in bar → card bytes (4.0 bar → 1F 05 00 00), and a read-back to bar.
  const fieldcodec::decimal bar{static_cast<std::int64_t>(fw::rx_register[4]), 1};
  if (auto b = fieldcodec::dpq::to_bytes(inj_p_limit_1, bar)) fw::transmit(b.value().span());
  if (auto eu = fieldcodec::dpq::from_bytes(inj_p_limit_1, fw::receive<4>(30))) {
    fw::tx_register[2] = static_cast<std::uint8_t>(eu.value().mantissa);
  }
}

} // namespace

int main() {
  master m;
  for (;;) {
    m.target = static_cast<std::int32_t>(fw::tick);
    canopen_cycle(m);
    compax_cycle();
    pacontrol_cycle(m);
    dpq_cycle();
    if (fw::tick == 0xFFFF'FFFFU) break;
  }
  return 0;
}
