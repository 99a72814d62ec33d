// End to end over CANopen, written like the XENAX manual's examples (5.2.1 profile position,
// 5.2.2 reset after failure, 5.4.1 jog): a master built from canopen/ and ds402/ talks to a
// simulated XENAX (an SDO server over the generated CAN dictionary plus a CiA 402 drive model)
// and every frame on the bus is asserted. Node-ID 1. The manual prints object/value tables, not
// frames; the frames follow from CiA 301 (see docs/errata.md, XENAX, Codec).
#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/xenax/bus.hpp>
#include <fieldcodec/xenax/error_code.hpp>
#include <fieldcodec/xenax/homing.hpp>
#include <fieldcodec/xenax/modes.hpp>
#include <fieldcodec/xenax/units.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace pdo = fieldcodec::canopen::pdo;
namespace ds402 = fieldcodec::ds402;
namespace xenax = fieldcodec::xenax;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;
using fieldcodec::byte_order;

namespace {
constexpr std::uint8_t node = xenax::node_id(1).value(); // the XENAX takes 1-99 (2.5, CI)

co::can_frame F(std::uint16_t id, std::initializer_list<std::uint8_t> b) {
  return co::make_frame(id, b).value();
}

// The fixed CAN PDO 2 mappings of the XENAX (9.1.5, 9.1.16), checked at compile time.
constexpr pdo::mapping_entry rpdo2_map[] = {{0x6040, 0, 16}, {0x607A, 0, 32}};
constexpr auto map_rpdo2 =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::rpdo, rpdo2_map);
constexpr pdo::mapping_entry tpdo2_map[] = {{0x6041, 0, 16}, {0x6064, 0, 32}};
constexpr auto map_tpdo2 =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::tpdo, tpdo2_map);
constexpr pdo::mapping_entry pdo1_rx_map[] = {{0x6040, 0, 16}};
constexpr auto map_rpdo1 =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::rpdo, pdo1_rx_map);
constexpr pdo::mapping_entry pdo1_tx_map[] = {{0x6041, 0, 16}};
constexpr auto map_tpdo1 =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::tpdo, pdo1_tx_map);

// A XENAX as far as these examples need it.
constexpr auto xcan_layout = co::make_layout<xcan::dictionary.size()>(xcan::dictionary);

struct simulated_xenax {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(xcan_layout.storage_size());
  co::dictionary_store<> store{xcan::dictionary, xcan_layout, storage};
  std::array<std::uint8_t, 256> sdo_buffer{};
  sdo::server<co::dictionary_store<>> server{node, store, sdo_buffer};
  co::nmt::state nmt = co::nmt::state::pre_operational;
  ds402::state state = ds402::state::switch_on_disabled;
  std::uint16_t previous_cw = 0;
  std::uint16_t mode_bits = 0; // statusword bits 10, 12
  std::int32_t position = 0;
  std::int32_t goal = 0;
  std::uint8_t error_number = 0;

  simulated_xenax() { REQUIRE(store.init_defaults(node).has_value()); }

  std::uint16_t statusword() const {
    return static_cast<std::uint16_t>(ds402::state_bits(state) | ds402::sw::remote | mode_bits);
  }
  std::int8_t mode_display() const {
    return static_cast<std::int8_t>(store.value({0x6061, 0}).value()[0]);
  }
  void store_value(std::uint16_t index, std::int64_t v) {
    std::array<std::uint8_t, 8> b{};
    const auto n = store.value({index, 0}).value().size();
    auto r =
        v < 0 ? fieldcodec::store_signed(b, n, v, byte_order::little)
              : fieldcodec::store_unsigned(b, n, static_cast<std::uint64_t>(v), byte_order::little);
    REQUIRE(r.has_value());
    REQUIRE(store.set({index, 0}, std::span(b).first(n)) == sdo::abort_code::none);
  }
  std::vector<co::can_frame> power_on() { return {co::nmt::encode_boot_up(node).value()}; }
  void fail(std::uint8_t number) { // a following error, say
    state = ds402::state::fault;
    error_number = number;
    store_value(0x603F, xenax::encode_error_code(number).value());
    store_value(0x2004, number);
  }

  std::vector<co::can_frame> receive(const co::can_frame &f) {
    std::vector<co::can_frame> out;
    if (auto m = co::nmt::decode(f); m) {
      if (m.value().node == 0 || m.value().node == node) {
        nmt = co::nmt::state_after(m.value().cs);
      }
      return out;
    }
    if (f.id == co::cob_id::sdo_rx(node).value()) {
      const auto r = server.on_frame(f, 0);
      out.insert(out.end(), r.send.begin(), r.send.end());
      // 6061h follows 6060h once the drive has switched modes
      REQUIRE(store.set({0x6061, 0}, store.value({0x6060, 0}).value()) == sdo::abort_code::none);
      return out;
    }
    if (nmt != co::nmt::state::operational) return out;
    if (f.id == co::cob_id::rpdo(1, node).value()) {
      controlword(static_cast<std::uint16_t>(map_rpdo1.get(f.payload(), 0).value()), out);
    } else if (f.id == co::cob_id::rpdo(2, node).value()) {
      store_value(0x607A, map_rpdo2.get_signed(f.payload(), 1).value());
      controlword(static_cast<std::uint16_t>(map_rpdo2.get(f.payload(), 0).value()), out);
    }
    return out;
  }

  void controlword(std::uint16_t cw, std::vector<co::can_frame> &out) {
    const std::uint16_t before = statusword();
    const auto step = ds402::apply(state, cw, previous_cw);
    state = step.to;
    if (step.transition == 15) {
      error_number = 0;
      store_value(0x603F, 0);
    }
    const bool rising = (cw & xenax::cw::start) != 0 && (previous_cw & xenax::cw::start) == 0;
    const bool falling = (cw & xenax::cw::start) == 0 && (previous_cw & xenax::cw::start) != 0;
    if (state == ds402::state::operation_enabled &&
        mode_display() == static_cast<std::int8_t>(xenax::mode::profile_position)) {
      if (rising) { // new set-point: acknowledge, motion starts
        const auto target = static_cast<std::int32_t>(
            fieldcodec::load_signed(store.value({0x607A, 0}).value(), 4, byte_order::little)
                .value());
        goal = (cw & xenax::cw::relative) != 0 ? position + target : target;
        mode_bits = xenax::sw::bit12;
      } else if (falling && mode_bits == xenax::sw::bit12) { // the move completes at once
        position = goal;
        mode_bits = xenax::sw::bit10;
      }
    }
    if (state == ds402::state::operation_enabled && rising &&
        mode_display() == static_cast<std::int8_t>(xenax::mode::reference)) {
      // the reference run completes at once: performed (bit 10) and achieved (bit 12)
      position = 0;
      mode_bits = xenax::sw::bit10 | xenax::sw::bit12;
    }
    previous_cw = cw;
    store_value(0x6040, cw);
    store_value(0x6041, statusword());
    store_value(0x6064, position);
    if (statusword() != before) { // TxPDO 1 and 2: transmission type 0xFF, on statusword change
      std::array<std::uint8_t, 8> b{};
      REQUIRE(map_tpdo1.set(b, 0, statusword()).has_value());
      out.push_back(
          co::make_frame(co::cob_id::tpdo(1, node).value(), std::span(b).first(map_tpdo1.bytes()))
              .value());
      REQUIRE(map_tpdo2.set(b, 0, statusword()).has_value());
      REQUIRE(map_tpdo2.set(b, 1, position).has_value());
      out.push_back(
          co::make_frame(co::cob_id::tpdo(2, node).value(), std::span(b).first(map_tpdo2.bytes()))
              .value());
    }
  }
};

// The master: an SDO client, the last statusword seen in a TPDO, and a log of the bus.
struct master {
  explicit master(simulated_xenax &d) : drive(d) {}
  simulated_xenax &drive;
  sdo::client client{node};
  std::vector<co::can_frame> log;
  std::uint16_t statusword = 0;
  std::int32_t actual_position = 0;
  std::uint16_t previous_cw = 0;

  void deliver(const std::vector<co::can_frame> &frames) {
    for (const auto &f : frames) {
      log.push_back(f);
      if (f.id == co::cob_id::tpdo(1, node).value()) {
        statusword = static_cast<std::uint16_t>(map_tpdo1.get(f.payload(), 0).value());
      } else if (f.id == co::cob_id::tpdo(2, node).value()) {
        statusword = static_cast<std::uint16_t>(map_tpdo2.get(f.payload(), 0).value());
        actual_position = static_cast<std::int32_t>(map_tpdo2.get_signed(f.payload(), 1).value());
      } else if (f.id == co::cob_id::sdo_tx(node).value()) {
        const auto o = client.on_frame(f, 0);
        for (const auto &g : o.send) send(g);
      }
    }
  }
  void send(const co::can_frame &f) {
    log.push_back(f);
    deliver(drive.receive(f));
  }
  void send(const sdo::step &s) {
    for (const auto &f : s.send) send(f);
  }
  void sdo_write(std::uint16_t index, std::uint8_t sub, std::span<const std::uint8_t> bytes) {
    send(client.download({index, sub}, bytes, 0).value());
    REQUIRE(client.state() == sdo::transfer_state::done);
  }
  template <class T>
  void sdo_write(std::uint16_t index, T value) {
    const auto b = fieldcodec::to_bytes(value, byte_order::little);
    sdo_write(index, 0, b);
  }
  std::vector<std::uint8_t> sdo_read(std::uint16_t index, std::uint8_t sub = 0) {
    std::array<std::uint8_t, 64> buf{};
    send(client.upload({index, sub}, buf, 0).value());
    REQUIRE(client.state() == sdo::transfer_state::done);
    return {client.received().begin(), client.received().end()};
  }
  void rpdo1(std::uint16_t cw) {
    std::array<std::uint8_t, 8> b{};
    REQUIRE(map_rpdo1.set(b, 0, cw).has_value());
    previous_cw = cw;
    send(co::make_frame(co::cob_id::rpdo(1, node).value(), std::span(b).first(map_rpdo1.bytes()))
             .value());
  }
  void rpdo2(std::uint16_t cw, std::int32_t target) {
    std::array<std::uint8_t, 8> b{};
    REQUIRE(map_rpdo2.set(b, 0, cw).has_value());
    REQUIRE(map_rpdo2.set(b, 1, target).has_value());
    previous_cw = cw;
    send(co::make_frame(co::cob_id::rpdo(2, node).value(), std::span(b).first(map_rpdo2.bytes()))
             .value());
  }
  // Walk the power state machine to `target` one controlword per cycle, like the manual's
  // "wait until state ... is reached" rows.
  void power_to(ds402::state target) {
    for (int cycle = 0; cycle < 5; ++cycle) {
      const auto st = ds402::decode_state(statusword).value();
      if (st == target) return;
      rpdo1(ds402::next_controlword(statusword, target, previous_cw).value());
    }
    FAIL("drive did not reach the target state");
  }
  std::vector<co::can_frame> take_log() {
    auto l = log;
    log.clear();
    return l;
  }
};

void check_frames(const std::vector<co::can_frame> &got, const std::vector<co::can_frame> &want) {
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    CAPTURE(i);
    CHECK(got[i].id == want[i].id);
    CHECK(got[i] == want[i]);
  }
}
} // namespace

TEST_CASE("XENAX 5.2.1: power on and a profile position move over CANopen") {
  simulated_xenax drive;
  master m(drive);
  m.deliver(drive.power_on());
  m.statusword = drive.statusword(); // known before the first TPDO (switch on disabled)
  check_frames(m.take_log(), {F(0x701, {0x00})}); // boot-up

  // 6060h := 1, wait until 6061h = 1
  m.sdo_write<std::int8_t>(0x6060, 1);
  const auto mode = m.sdo_read(0x6061);
  REQUIRE(mode.size() == 1);
  CHECK(xenax::decode_mode(static_cast<std::int8_t>(mode[0])).value() ==
        xenax::mode::profile_position);
  check_frames(m.take_log(), {
                                 F(0x601, {0x2F, 0x60, 0x60, 0x00, 0x01, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x60, 0x60, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x601, {0x40, 0x61, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x4F, 0x61, 0x60, 0x00, 0x01, 0x00, 0x00, 0x00}),
                             });

  // Profile position parameters: S-curve 2000h, acceleration 6083h, speed 6081h, windows
  // 6065h / 6067h.
  m.sdo_write<std::uint32_t>(0x2000, 50);
  m.sdo_write<std::uint32_t>(0x6083, 1'000'000);
  m.sdo_write<std::uint32_t>(0x6081, 200'000);
  m.sdo_write<std::uint32_t>(0x6065, 2'000);
  m.sdo_write<std::uint32_t>(0x6067, 100);
  check_frames(m.take_log(), {
                                 F(0x601, {0x23, 0x00, 0x20, 0x00, 0x32, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x60, 0x00, 0x20, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x601, {0x23, 0x83, 0x60, 0x00, 0x40, 0x42, 0x0F, 0x00}),
                                 F(0x581, {0x60, 0x83, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x601, {0x23, 0x81, 0x60, 0x00, 0x40, 0x0D, 0x03, 0x00}),
                                 F(0x581, {0x60, 0x81, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x601, {0x23, 0x65, 0x60, 0x00, 0xD0, 0x07, 0x00, 0x00}),
                                 F(0x581, {0x60, 0x65, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x601, {0x23, 0x67, 0x60, 0x00, 0x64, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x60, 0x67, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                             });

  // NMT start, then the power state machine: 0x06, 0x07, 0x0F as in 5.1.2, each answered by
  // TxPDO 1 (statusword) and TxPDO 2 (statusword + actual position).
  m.send(co::nmt::encode(co::nmt::command::start, node).value());
  m.power_to(ds402::state::ready_to_switch_on);
  m.power_to(ds402::state::switched_on);
  m.power_to(ds402::state::operation_enabled);
  check_frames(m.take_log(), {
                                 F(0x000, {0x01, 0x01}),
                                 F(0x201, {0x06, 0x00}),
                                 F(0x181, {0x21, 0x02}),
                                 F(0x281, {0x21, 0x02, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x201, {0x07, 0x00}),
                                 F(0x181, {0x23, 0x02}),
                                 F(0x281, {0x23, 0x02, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x201, {0x0F, 0x00}),
                                 F(0x181, {0x27, 0x02}),
                                 F(0x281, {0x27, 0x02, 0x00, 0x00, 0x00, 0x00}),
                             });
  CHECK(ds402::decode_state(m.statusword).value() == ds402::state::operation_enabled);

  // Absolute move to 100000: controlword 0x1F with the target in RxPDO 2; the drive
  // acknowledges the set-point (bit 12); controlword back to 0x0F; target reached (bit 10).
  m.rpdo2(xenax::pp_start(xenax::positioning::absolute), 100'000);
  auto s = xenax::decode_status(m.statusword, xenax::mode::profile_position).value();
  CHECK(s.set_point_acknowledge);
  CHECK(!s.target_reached);
  m.rpdo2(xenax::cw::enabled, 100'000);
  s = xenax::decode_status(m.statusword, xenax::mode::profile_position).value();
  CHECK(s.target_reached); // "Bit 10 = True, Bit 12 = False"
  CHECK(!s.set_point_acknowledge);
  CHECK(m.actual_position == 100'000);

  // Relative move by 10000: controlword 0x5F (bit 6).
  m.rpdo2(xenax::pp_start(xenax::positioning::relative), 10'000);
  m.rpdo2(xenax::cw::enabled, 10'000);
  CHECK(m.actual_position == 110'000);
  check_frames(m.take_log(), {
                                 F(0x301, {0x1F, 0x00, 0xA0, 0x86, 0x01, 0x00}),
                                 F(0x181, {0x27, 0x12}),
                                 F(0x281, {0x27, 0x12, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x301, {0x0F, 0x00, 0xA0, 0x86, 0x01, 0x00}),
                                 F(0x181, {0x27, 0x06}),
                                 F(0x281, {0x27, 0x06, 0xA0, 0x86, 0x01, 0x00}),
                                 F(0x301, {0x5F, 0x00, 0x10, 0x27, 0x00, 0x00}),
                                 F(0x181, {0x27, 0x12}),
                                 F(0x281, {0x27, 0x12, 0xA0, 0x86, 0x01, 0x00}),
                                 F(0x301, {0x0F, 0x00, 0x10, 0x27, 0x00, 0x00}),
                                 F(0x181, {0x27, 0x06}),
                                 F(0x281, {0x27, 0x06, 0xB0, 0xAD, 0x01, 0x00}),
                             });

  // The statusword and position can also be read by SDO (6041h, 6064h).
  CHECK(m.sdo_read(0x6041) == std::vector<std::uint8_t>{0x27, 0x06});
  CHECK(m.sdo_read(0x6064) == std::vector<std::uint8_t>{0xB0, 0xAD, 0x01, 0x00});
  check_frames(m.take_log(), {
                                 F(0x601, {0x40, 0x41, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x4B, 0x41, 0x60, 0x00, 0x27, 0x06, 0x00, 0x00}),
                                 F(0x601, {0x40, 0x64, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x43, 0x64, 0x60, 0x00, 0xB0, 0xAD, 0x01, 0x00}),
                             });
}

TEST_CASE("XENAX 5.2.2: reset a profile position failure (error 50)") {
  simulated_xenax drive;
  master m(drive);
  m.send(co::nmt::encode(co::nmt::command::start, 0).value()); // all nodes
  m.sdo_write<std::int8_t>(0x6060, 1);
  m.statusword = drive.statusword();
  m.power_to(ds402::state::operation_enabled);
  (void)m.take_log();

  drive.fail(xenax::error_following);
  m.statusword = drive.statusword();
  CHECK(ds402::decode_state(m.statusword).value() == ds402::state::fault);
  // 603Fh tells which error: 0xFF00 + 50
  const auto code = m.sdo_read(0x603F);
  REQUIRE(code.size() == 2);
  const auto number =
      xenax::decode_error_code(static_cast<std::uint16_t>(code[0] | code[1] << 8)).value();
  CHECK(number == 50);
  CHECK(!xenax::needs_reference_after(number));
  // 0x80 (fault reset), wait for bit 3 to clear, then 0x06 and on to operation enabled.
  ds402::power_sequencer seq(m.previous_cw);
  for (int i = 0;
       i < 4 && ds402::decode_state(m.statusword).value() != ds402::state::operation_enabled; ++i) {
    m.rpdo1(seq.next(m.statusword, ds402::state::operation_enabled).value());
  }
  check_frames(m.take_log(), {
                                 F(0x601, {0x40, 0x3F, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x4B, 0x3F, 0x60, 0x00, 0x32, 0xFF, 0x00, 0x00}),
                                 F(0x201, {0x80, 0x00}),
                                 F(0x181, {0x40, 0x02}),
                                 F(0x281, {0x40, 0x02, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x201, {0x06, 0x00}),
                                 F(0x181, {0x21, 0x02}),
                                 F(0x281, {0x21, 0x02, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x201, {0x0F, 0x00}), // 3 + 4 at once
                                 F(0x181, {0x27, 0x02}),
                                 F(0x281, {0x27, 0x02, 0x00, 0x00, 0x00, 0x00}),
                             });
  CHECK(m.sdo_read(0x603F) == std::vector<std::uint8_t>{0x00, 0x00});
}

TEST_CASE("XENAX 5.4.1: jog mode is selected with 6060h = 0xFF (-1)") {
  simulated_xenax drive;
  master m(drive);
  m.sdo_write<std::int8_t>(0x6060, static_cast<std::int8_t>(xenax::mode::jog));
  const auto shown = m.sdo_read(0x6061);
  CHECK(xenax::decode_mode(static_cast<std::int8_t>(shown[0])).value() == xenax::mode::jog);
  // 6060h limits are -2..10: 11 is refused by the server with "value too high"
  const std::array<std::uint8_t, 1> eleven{11};
  (void)m.take_log();
  m.send(m.client.download({0x6060, 0}, eleven, 0).value());
  check_frames(m.take_log(), {
                                 F(0x601, {0x2F, 0x60, 0x60, 0x00, 0x0B, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x80, 0x60, 0x60, 0x00, 0x31, 0x00, 0x09, 0x06}),
                             });
  CHECK(m.client.state() == sdo::transfer_state::failed);
  CHECK(m.client.error()->abort == sdo::abort_code::value_too_high);
}

TEST_CASE("XENAX 5.1.2 reference of a LINAX, then 5.3.1 cyclic synchronous position set-up") {
  simulated_xenax drive;
  master m(drive);
  m.send(co::nmt::encode(co::nmt::command::start, node).value());
  m.statusword = drive.statusword();
  (void)m.take_log();

  // 6060h := 6, wait 6061h = 6, 6098h := 1 (start direction positive)
  m.sdo_write<std::int8_t>(0x6060, static_cast<std::int8_t>(xenax::mode::reference));
  CHECK(xenax::decode_mode(static_cast<std::int8_t>(m.sdo_read(0x6061).at(0))).value() ==
        xenax::mode::reference);
  m.sdo_write<std::int8_t>(0x6098,
                           static_cast<std::int8_t>(xenax::reference_method::linear_positive));
  // 0x06, 0x07, 0x0F, then 0x1F starts the reference; wait for bit 12 (reference achieved)
  m.power_to(ds402::state::ready_to_switch_on);
  m.power_to(ds402::state::switched_on);
  m.power_to(ds402::state::operation_enabled);
  m.rpdo1(xenax::reference_start);
  const auto ref = xenax::decode_status(m.statusword, xenax::mode::reference).value();
  CHECK(ref.reference_achieved);
  CHECK(!ref.reference_error);
  check_frames(m.take_log(), {
                                 F(0x601, {0x2F, 0x60, 0x60, 0x00, 0x06, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x60, 0x60, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x601, {0x40, 0x61, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x4F, 0x61, 0x60, 0x00, 0x06, 0x00, 0x00, 0x00}),
                                 F(0x601, {0x2F, 0x98, 0x60, 0x00, 0x01, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x60, 0x98, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x201, {0x06, 0x00}),
                                 F(0x181, {0x21, 0x02}),
                                 F(0x281, {0x21, 0x02, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x201, {0x07, 0x00}),
                                 F(0x181, {0x23, 0x02}),
                                 F(0x281, {0x23, 0x02, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x201, {0x0F, 0x00}),
                                 F(0x181, {0x27, 0x02}),
                                 F(0x281, {0x27, 0x02, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x201, {0x1F, 0x00}),
                                 F(0x181, {0x27, 0x16}),
                                 F(0x281, {0x27, 0x16, 0x00, 0x00, 0x00, 0x00}),
                             });

  // 5.3.1: 6060h := 8; 60C2h sub 1 := 0x05, sub 2 := 0xFC (500 us); 6065h window
  m.sdo_write<std::int8_t>(0x6060, static_cast<std::int8_t>(xenax::mode::cyclic_sync_position));
  const auto t = xenax::encode_cycle_time(500).value();
  const std::array<std::uint8_t, 1> base{t.base};
  const std::array<std::uint8_t, 1> exponent{static_cast<std::uint8_t>(t.exponent)};
  m.sdo_write(0x60C2, 1, base);
  m.sdo_write(0x60C2, 2, exponent);
  m.sdo_write<std::uint32_t>(0x6065, 2'000);
  check_frames(m.take_log(), {
                                 F(0x601, {0x2F, 0x60, 0x60, 0x00, 0x08, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x60, 0x60, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x601, {0x2F, 0xC2, 0x60, 0x01, 0x05, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x60, 0xC2, 0x60, 0x01, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x601, {0x2F, 0xC2, 0x60, 0x02, 0xFC, 0x00, 0x00, 0x00}),
                                 F(0x581, {0x60, 0xC2, 0x60, 0x02, 0x00, 0x00, 0x00, 0x00}),
                                 F(0x601, {0x23, 0x65, 0x60, 0x00, 0xD0, 0x07, 0x00, 0x00}),
                                 F(0x581, {0x60, 0x65, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}),
                             });
  // read back: 5 x 10^-4 s
  const auto b = m.sdo_read(0x60C2, 1);
  const auto e = m.sdo_read(0x60C2, 2);
  CHECK(xenax::decode_cycle_time({b.at(0), static_cast<std::int8_t>(e.at(0))}).value() == 500);
}
