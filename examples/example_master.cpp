// A CANopen master for one XENAX axis (node 5), built from fieldcodec's master machines:
//   boot-up (reset communication, identity check, configuration list, NMT start), then the
//   CiA 402 drive helper: enable, profile position move, homing (XENAX reference method),
//   disable. The drive is simulated in the same program (an SDO server over the generated XENAX
//   dictionary plus a CiA 402 drive model), connected through an in-memory bus; a real master
//   puts the same frames on SocketCAN or its CAN controller.
// docs/master.md walks through this program.
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/master/boot.hpp>
#include <fieldcodec/master/drive.hpp>
#include <fieldcodec/xenax/drive_profile.hpp>
#include <fieldcodec/xenax/homing.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace ds402 = fieldcodec::ds402;
namespace master = fieldcodec::master;
namespace xenax = fieldcodec::xenax;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;

namespace {

constexpr std::uint8_t node = 5;

// ----- the simulated XENAX -------------------------------------------------------------------

constexpr auto layout = co::make_layout<xcan::dictionary.size()>(xcan::dictionary);

struct simulated_xenax {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(layout.storage_size());
  co::dictionary_store<> store{xcan::dictionary, layout, storage};
  std::array<std::uint8_t, 256> buffer{};
  sdo::server<co::dictionary_store<>> server{node, store, buffer};
  co::nmt::state nmt = co::nmt::state::pre_operational;
  ds402::state state = ds402::state::switch_on_disabled;
  std::uint16_t previous_cw = 0;
  std::int32_t position = 1234;
  std::int32_t goal = 0;
  bool ack = false;
  bool reached = true;
  bool homing = false;
  bool homed = false;

  simulated_xenax() {
    if (!store.init_defaults(node)) std::printf("store init failed\n");
    set({0x1018, 1}, 0x21B); // vendor-ID of Jenny Science in this simulation
  }
  void set(fieldcodec::od::address a, std::uint32_t v) {
    std::array<std::uint8_t, 4> b{};
    for (std::size_t i = 0; i < 4U; ++i) b[i] = static_cast<std::uint8_t>(v >> (8U * i));
    const auto n = store.value(a).value().size();
    (void)store.set(a, std::span<const std::uint8_t>(b).first(n));
  }
  [[nodiscard]] std::int32_t get(fieldcodec::od::address a) const {
    const auto v = store.value(a).value();
    std::uint32_t r = 0;
    for (std::size_t i = 0; i < v.size() && i < 4U; ++i) r |= std::uint32_t{v[i]} << (8U * i);
    if (v.size() == 1U) return static_cast<std::int8_t>(r);
    return static_cast<std::int32_t>(r);
  }
  [[nodiscard]] std::int8_t mode() const { return static_cast<std::int8_t>(get({0x6061, 0})); }
  [[nodiscard]] std::uint16_t statusword() const {
    auto w = static_cast<std::uint16_t>(ds402::state_bits(state) | ds402::sw::remote |
                                        ds402::sw::voltage_enabled);
    const auto bit = [&w](bool on, std::uint16_t b) {
      if (on) w = static_cast<std::uint16_t>(w | b);
    };
    if (mode() == 1) {
      bit(reached, xenax::sw::bit10);
      bit(ack, xenax::sw::bit12);
    } else if (mode() == 6) {
      bit(!homing && homed, xenax::sw::bit10);
      bit(!homing && homed, xenax::sw::bit12);
    }
    return w;
  }

  // one millisecond of motion
  void tick() {
    if (state != ds402::state::operation_enabled) return;
    const auto step_to = [this](std::int32_t target) {
      const std::int32_t d = target - position;
      position += d > 500 ? 500 : (d < -500 ? -500 : d);
      return position == target;
    };
    if (mode() == 1 && !reached) reached = step_to(goal);
    if (mode() == 6 && homing && step_to(0)) {
      homing = false;
      homed = true;
    }
  }

  std::vector<co::can_frame> receive(const co::can_frame &f) {
    std::vector<co::can_frame> out;
    if (auto m = co::nmt::decode(f); m && (m.value().node == 0 || m.value().node == node)) {
      nmt = co::nmt::state_after(m.value().cs);
      if (m.value().cs == co::nmt::command::reset_communication) {
        out.push_back(co::nmt::encode_boot_up(node).value());
      }
      return out;
    }
    if (f.id == co::cob_id::sdo_rx(node).value()) {
      const auto r = server.on_frame(f, 0);
      out.insert(out.end(), r.send.begin(), r.send.end());
      set({0x6061, 0}, static_cast<std::uint8_t>(get({0x6060, 0}))); // the mode follows
      return out;
    }
    if (nmt == co::nmt::state::operational && f.id == co::cob_id::rpdo(1, node).value()) {
      const auto cw = static_cast<std::uint16_t>(f.data[0] | (f.data[1] << 8U));
      state = ds402::apply(state, cw, previous_cw).to;
      const bool rising = (cw & 0x10U) != 0U && (previous_cw & 0x10U) == 0U;
      if (state == ds402::state::operation_enabled && rising) {
        if (mode() == 1) { // new set-point
          goal = get({0x607A, 0});
          if ((cw & xenax::cw::relative) != 0U) goal += position;
          ack = true;
          reached = false;
        } else if (mode() == 6) {
          homing = true;
          homed = false;
        }
      }
      if ((cw & 0x10U) == 0U) ack = false;
      previous_cw = cw;
      // TPDO 1: the statusword, sent at once (transmission type 255 in this simulation)
      const auto sw = statusword();
      out.push_back(
          co::make_frame(co::cob_id::tpdo(1, node).value(),
                         {static_cast<std::uint8_t>(sw), static_cast<std::uint8_t>(sw >> 8U)})
              .value());
    }
    return out;
  }
};

// ----- the master ------------------------------------------------------------------------------

// What the generator writes from a DCF (fieldcodec-gen --config-list), here written out: a
// following error window of 500 increments and the reference method 12.
constexpr std::uint8_t v_window[] = {0xF4, 0x01, 0x00, 0x00};
constexpr std::uint8_t v_method[] = {12};
constexpr master::config_item items[] = {
    {{0x6065, 0}, v_window, 0, "Following Position Error Window"},
    {{0x6098, 0}, v_method, 0, "Reference Methods"},
};
constexpr master::configuration axis_config{items, {0x00020192U, 0x21BU, 0, 0, 0}, node};

struct bus {
  simulated_xenax &device;
  std::deque<co::can_frame> to_master{};
  int frames = 0;
  void send(const co::frames &fs) {
    for (const auto &f : fs) {
      ++frames;
      for (const auto &r : device.receive(f)) to_master.push_back(r);
    }
  }
};

/// The drive helper's SDO request, run by the client; returns false when it cannot start.
bool start_sdo(sdo::client &client, const master::sdo_request &r, std::array<std::uint8_t, 4> &buf,
               bus &b, std::uint32_t now) {
  auto s = r.what == master::sdo_request::kind::download
               ? client.download(r.address, r.bytes(), now)
               : client.upload(r.address, buf, now);
  if (!s) return false;
  b.send(s.value().send);
  return true;
}

} // namespace

int main() {
  simulated_xenax xenax_drive;
  bus b{xenax_drive};
  sdo::client client(node, 100);
  std::uint32_t now = 0;

  // 1. boot-up
  master::boot boot(node, client);
  auto s = boot.start(axis_config, now);
  if (!s) return 1;
  b.send(s.value().send);
  while (boot.busy() && now < 5000) {
    if (b.to_master.empty()) {
      now += 1;
      b.send(boot.poll(now).send);
      continue;
    }
    const auto f = b.to_master.front();
    b.to_master.pop_front();
    b.send(boot.on_frame(f, now).send);
  }
  if (boot.state() != master::boot_state::done) {
    std::printf("boot failed: %d\n", static_cast<int>(boot.error()->failure));
    return 1;
  }
  std::printf("boot: node %u identity 1000h=%08X vendor=%08X, configured, started (%d frames)\n",
              node, boot.read_identity_values().device_type, boot.read_identity_values().vendor_id,
              b.frames);

  // 2. the cyclic task: 1 ms cycle, RPDO 1 carries the controlword, TPDO 1 the statusword
  master::drive axis({.profile = xenax::profile, .target_over_sdo = true});
  std::uint16_t statusword = xenax_drive.statusword();
  std::array<std::uint8_t, 4> sdo_buffer{};
  const auto cycle = [&]() {
    ++now;
    xenax_drive.tick();
    const auto out = axis.cycle(statusword, now);
    if (out.sdo && !start_sdo(client, *out.sdo, sdo_buffer, b, now)) {
      std::printf("SDO client busy\n");
    }
    b.send(co::frames(co::make_frame(co::cob_id::rpdo(1, node).value(),
                                     {static_cast<std::uint8_t>(out.controlword),
                                      static_cast<std::uint8_t>(out.controlword >> 8U)})
                          .value()));
    while (!b.to_master.empty()) {
      const auto f = b.to_master.front();
      b.to_master.pop_front();
      if (f.id == co::cob_id::tpdo(1, node).value()) {
        statusword = static_cast<std::uint16_t>(f.data[0] | (f.data[1] << 8U));
        continue;
      }
      b.send(client.on_frame(f, now).send);
      if (client.state() == sdo::transfer_state::done && axis.sdo_pending()) {
        axis.sdo_done(client.received(), now);
      } else if (client.state() == sdo::transfer_state::failed && axis.sdo_pending()) {
        axis.sdo_failed(*client.error(), now);
      }
    }
  };
  const auto run = [&](const char *what) {
    const auto start = now;
    do {
      cycle();
    } while (axis.busy() && now - start < 10000);
    cycle();
    const bool ok = !axis.error();
    std::printf("%-36s %-6s after %4u ms, position %d\n", what, ok ? "ok" : "FAILED", now - start,
                xenax_drive.position);
    return ok;
  };

  if (!axis.switch_mode(xenax::mode::profile_position, now) || !run("switch to profile position")) {
    return 1;
  }
  if (!axis.enable(now) || !run("enable (0x06, 0x0F)")) return 1;
  if (!axis.move_to(10000, now) || !run("move to 10000 (set-point handshake)")) return 1;
  if (xenax_drive.position != 10000) return 1;
  if (!axis.move_to(-2500, now, true) || !run("move by -2500 (relative)")) return 1;
  if (xenax_drive.position != 7500) return 1;
  if (!axis.switch_mode(xenax::mode::reference, now) || !run("switch to reference (homing)")) {
    return 1;
  }
  if (!axis.home(now, xenax::reference_method::linear_negative) ||
      !run("reference run, method 2")) {
    return 1;
  }
  if (xenax_drive.position != 0 || xenax_drive.get({0x6098, 0}) != 2) return 1;
  if (!axis.disable(now) || !run("disable")) return 1;
  if (xenax_drive.state != ds402::state::switch_on_disabled) return 1;
  std::printf("done: %d frames on the bus\n", b.frames);
  return 0;
}
