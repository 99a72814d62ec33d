// Fuzz harness for the master machines (master/boot.hpp, configurator.hpp, drive.hpp), fed
// arbitrary answers: SDO responses (well-formed answers to the last request with fuzzed values,
// aborts and wrong objects, or any bytes), boot-up messages and heartbeats of any state,
// statuswords, modes of operation, EMCYs, SDO completions and failures, commands in any order,
// and time.
//
// Byte 0 selects the machine (0 configurator, 1 boot, 2 and 3 drive; bits 2-7 options), byte 1
// the node-ID; then operations, each a byte and its arguments.
//
// Invariants, checked after every call:
// * boot and configurator: every frame sent is an SDO request to the node (0x600 + node, DLC 8)
//   or an NMT command to the node (reset communication before the boot-up, start at the end);
//   an SDO download writes only an object of the list (an upload reads only 1000h, 1018h:1..4
//   or an object of the list when verifying); NMT start is sent only once the identity read
//   matched what was expected and the configurator completed every item; the step's deadline
//   is never in the past; the configurator's completed() never exceeds the list, and done means
//   all of it; failed comes with an error, done without.
// * drive: every controlword, applied to the state the statusword of that cycle shows, is a
//   command CiA 402 defines for that state (a transition of its state machine, or the command
//   that holds the state); it powers the drive up (transitions 2, 3, 4, 16) only while the
//   application asked for that (enable(), or disable() to a higher state) since the last
//   quick stop, disable, fault or failure; it resets a fault (transition 15) only after
//   reset_fault(); at most one SDO transfer is outstanding; the deadline is never in the past.
#include "check.hpp"
#include "input.hpp"

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/ds402/drive_profile.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/ds402/statusword.hpp>
#include <fieldcodec/master/boot.hpp>
#include <fieldcodec/master/config.hpp>
#include <fieldcodec/master/configurator.hpp>
#include <fieldcodec/master/drive.hpp>
#include <fieldcodec/xenax/drive_profile.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <span>
#include <string>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace master = fieldcodec::master;
namespace ds402 = fieldcodec::ds402;
namespace od = fieldcodec::od;

namespace {

using fuzz_input::reader;

// ---- boot and configurator ----------------------------------------------------------------

constexpr std::array<std::uint8_t, 2> v1017{0x64, 0x00};
constexpr std::array<std::uint8_t, 4> v1400{0x00, 0x02, 0x00, 0x00}; // $NODEID+0x200
constexpr std::array<std::uint8_t, 1> v6060{0x01};
constexpr std::array<std::uint8_t, 12> v2000{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
constexpr std::array<master::config_item, 4> items{{
    {{0x1017, 0}, v1017, 0, "Producer heartbeat time"},
    {{0x1400, 1}, v1400, master::config_flag::node_relative, "COB-ID used by RPDO 1"},
    {{0x6060, 0}, v6060, master::config_flag::no_verify, "Modes of operation"},
    {{0x2000, 0}, v2000, 0, "A long value"},
}};

bool in_list(od::address a) {
  for (const auto &i : items) {
    if (i.address == a) return true;
  }
  return false;
}

/// The last SDO request the machine sent, to answer it.
struct last_request {
  std::optional<sdo::message> m;
};

/// Checks a frame the boot machine or the configurator sends. Returns the NMT command or 0xFF.
std::uint8_t check_sent(const co::can_frame &f, std::uint8_t node, bool boot, bool verify,
                        last_request &last) {
  if (f.id == 0U) {
    FUZZ_CHECK(boot && f.dlc == 2U && !f.rtr && f.data[1] == node);
    FUZZ_CHECK(f.data[0] == 0x82U || f.data[0] == 0x01U);
    return f.data[0];
  }
  FUZZ_CHECK(f.id == 0x600U + node && f.dlc == 8U && !f.rtr);
  const auto m = sdo::decode(f.data, sdo::direction::to_server);
  FUZZ_CHECK(m.has_value()); // a machine never sends a request it cannot decode itself
  const sdo::message &msg = m.value();
  if (msg.type == sdo::message_type::initiate_download_request ||
      msg.type == sdo::message_type::block_download_initiate) {
    FUZZ_CHECK(in_list(msg.address));
  }
  if (msg.type == sdo::message_type::initiate_upload_request ||
      msg.type == sdo::message_type::block_upload_initiate) {
    const bool identity =
        msg.address == od::address{0x1000, 0} ||
        (msg.address.index == 0x1018U && msg.address.sub >= 1U && msg.address.sub <= 4U);
    FUZZ_CHECK((boot && identity) || (verify && in_list(msg.address)));
  }
  last.m = msg;
  return 0xFF;
}

/// A response from the node: any bytes, or an answer to the last request.
co::can_frame response(reader &in, std::uint8_t node, const last_request &last) {
  co::can_frame f = co::make_frame(static_cast<std::uint16_t>(0x580U + node), {}).value();
  f.dlc = 8;
  const std::uint8_t kind = in.byte();
  if (kind < 0x40U || !last.m) {
    for (auto &b : f.data) b = in.byte();
    return f;
  }
  const sdo::message &m = *last.m;
  const od::address a = (kind & 0x20U) != 0U ? od::address{in.u16(), in.byte()} : m.address;
  // command byte, object, 4 bytes of data: an SDO response as CiA 301 lays it out
  const auto answer = [&a](std::uint8_t command, std::uint32_t v) {
    return std::array<std::uint8_t, 8>{command,
                                       static_cast<std::uint8_t>(a.index),
                                       static_cast<std::uint8_t>(a.index >> 8U),
                                       a.sub,
                                       static_cast<std::uint8_t>(v),
                                       static_cast<std::uint8_t>(v >> 8U),
                                       static_cast<std::uint8_t>(v >> 16U),
                                       static_cast<std::uint8_t>(v >> 24U)};
  };
  std::array<std::uint8_t, 8> d{};
  switch (m.type) {
  case sdo::message_type::initiate_download_request: d = answer(0x60, 0); break;
  case sdo::message_type::download_segment_request:
    d = {static_cast<std::uint8_t>(0x20U | (m.toggle ? 0x10U : 0U))};
    break;
  case sdo::message_type::initiate_upload_request: // expedited, 4 bytes (0x21B: the vendor)
    d = answer(0x43, (kind & 0x10U) != 0U ? in.u32() : 0x21BU);
    break;
  default:
    for (auto &b : d) b = in.byte();
    break;
  }
  if ((kind & 0x08U) != 0U) d = answer(0x80, in.u32()); // an abort instead
  f.data = d;
  return f;
}

template <class Step>
void check_deadline(const Step &s, std::uint32_t now) {
  if (s.deadline && co::reached(*s.deadline, now) && *s.deadline != now) {
    std::fprintf(stderr, "deadline %u at now %u, state %d\n", *s.deadline, now,
                 static_cast<int>(s.state));
  }
  if (s.deadline) FUZZ_CHECK(!co::reached(*s.deadline, now) || *s.deadline == now);
}

void run_configurator(reader &in, std::uint8_t node, std::uint8_t options) {
  sdo::client client(node, 300);
  std::array<std::uint8_t, 16> verify_buffer{};
  master::config_options o;
  o.retries = static_cast<std::uint8_t>(options & 3U);
  o.timeout_ms = 400;
  o.verify = (options & 4U) != 0U;
  o.verify_buffer = verify_buffer;
  master::configurator run(client, o);
  const master::configuration c{items, {}, node};
  std::uint32_t now = 100;
  last_request last;
  const auto check = [&](const master::configurator::step &s) {
    for (const co::can_frame &f : s.send) {
      FUZZ_CHECK(check_sent(f, node, false, o.verify, last) == 0xFFU);
    }
    check_deadline(s, now);
    FUZZ_CHECK(run.completed() <= items.size());
    FUZZ_CHECK(s.state == run.state());
    if (run.state() == master::config_state::done) {
      FUZZ_CHECK(run.completed() == items.size() && !run.error());
    }
    if (run.state() == master::config_state::failed) FUZZ_CHECK(run.error().has_value());
  };
  auto s = run.start(c, now);
  FUZZ_CHECK(s.has_value());
  check(s.value());
  for (int ops = 0; ops < 200 && !in.empty(); ++ops) {
    const std::uint8_t op = in.byte();
    if (op % 3U == 0U) {
      now += in.u16() % 1000U;
      check(run.poll(now));
    } else if (op % 3U == 1U) {
      check(run.on_frame(response(in, node, last), now));
    } else if (!run.busy()) { // again, from the start
      if (auto again = run.start(c, now)) check(again.value());
    }
  }
}

void run_boot(reader &in, std::uint8_t node, std::uint8_t options) {
  sdo::client client(node, 300);
  master::boot_options o;
  o.reset_communication = (options & 1U) != 0U;
  o.wait_boot_up = (options & 2U) != 0U;
  o.heartbeat_timeout_ms = (options & 4U) != 0U ? 500U : 0U;
  o.consumer_time_ms = 300;
  o.start = (options & 8U) != 0U;
  o.config.retries = 1;
  o.config.timeout_ms = 400;
  master::boot machine(node, client, o);
  const master::identity expected{0, 0x21B, 0, 0, 0};
  const master::configuration c{items, expected, node};
  std::uint32_t now = 100;
  last_request last;
  bool vendor_matched = false;
  const auto check = [&](const master::boot::step &s) {
    for (const co::can_frame &f : s.send) {
      const std::uint8_t nmt = check_sent(f, node, true, false, last);
      if (nmt == 0x01U) {
        // start: only after the identity matched and the configuration completed
        FUZZ_CHECK(o.start && vendor_matched);
        FUZZ_CHECK(machine.state() == master::boot_state::done);
        FUZZ_CHECK(machine.read_identity_values().vendor_id == expected.vendor_id);
      }
    }
    if (machine.read_identity_values().vendor_id == expected.vendor_id) vendor_matched = true;
    check_deadline(s, now);
    FUZZ_CHECK(s.state == machine.state());
    FUZZ_CHECK((machine.state() == master::boot_state::failed) == machine.error().has_value());
  };
  auto s = machine.start(c, now);
  FUZZ_CHECK(s.has_value());
  check(s.value());
  for (int ops = 0; ops < 200 && !in.empty(); ++ops) {
    const std::uint8_t op = in.byte();
    switch (op % 4U) {
    case 0:
      now += in.u16() % 1500U;
      check(machine.poll(now));
      break;
    case 1: check(machine.on_frame(response(in, node, last), now)); break;
    case 2: { // boot-up or heartbeat of any state, maybe from another node
      const std::uint8_t who = (in.byte() & 1U) != 0U ? node : in.byte();
      const auto hb =
          co::make_frame(static_cast<std::uint16_t>(0x700U + (who & 0x7FU)), {in.byte()});
      check(machine.on_frame(hb.value(), now));
      break;
    }
    default:
      if (!machine.busy()) {
        vendor_matched = false;
        if (auto again = machine.start(c, now)) check(again.value());
      }
      break;
    }
  }
}

// ---- drive ----------------------------------------------------------------------------------

/// The command that keeps a drive in `s` (CiA 402 Table: no transition).
bool holds(ds402::state s, ds402::command c) {
  using ds402::command;
  switch (s) {
  case ds402::state::not_ready_to_switch_on:
  case ds402::state::fault_reaction_active: return true; // the drive ignores every command
  case ds402::state::fault: return c == command::disable_voltage || c == command::quick_stop;
  case ds402::state::switch_on_disabled:
    return c == command::disable_voltage || c == command::quick_stop;
  case ds402::state::ready_to_switch_on: return c == command::shutdown;
  case ds402::state::switched_on: return c == command::switch_on;
  case ds402::state::operation_enabled: return c == command::enable_operation;
  case ds402::state::quick_stop_active: return c == command::quick_stop;
  }
  return false;
}

void run_drive(reader &in, std::uint8_t options) {
  master::drive_options o;
  // plain CiA 402, or the XENAX's profile (a CSP bit, jog as a manufacturer motion)
  o.profile = (options & 1U) != 0U ? fieldcodec::xenax::profile : ds402::cia402_profile;
  o.target_over_sdo = (options & 2U) != 0U;
  o.read_error_code = (options & 4U) != 0U;
  o.reset_attempts = static_cast<std::uint8_t>(options >> 3U & 3U);
  master::drive d(o);
  std::uint32_t now = 100;
  std::uint16_t previous = 0; // the controlword of the cycle before
  int power = 0;              // how far the application asked to power up: 0, 2 (ready),
                              // 3 (switched on), 4 (operation enabled)
  bool reset_asked = false;
  const bool trace = std::getenv("FUZZ_TRACE") != nullptr; // print every cycle
  for (int ops = 0; ops < 300 && !in.empty(); ++ops) {
    const std::uint8_t op = in.byte();
    switch (op % 8U) {
    case 0:
    case 1: { // a cycle with a statusword (mostly one of a real state), maybe the mode display
      std::uint16_t sw = in.u16();
      if ((op & 0x10U) == 0U) {
        static constexpr std::array<std::uint16_t, 8> states{0x0000, 0x0040, 0x0021, 0x0023,
                                                             0x0027, 0x0007, 0x000F, 0x0008};
        sw = static_cast<std::uint16_t>((sw & 0xFF90U) | states[sw % states.size()]);
      }
      now += in.byte();
      std::optional<std::int8_t> mode;
      if ((op & 0x20U) != 0U) mode = static_cast<std::int8_t>(in.byte());
      const master::drive_step s = d.cycle(sw, now, mode);
      check_deadline(s, now);
      if (s.sdo) FUZZ_CHECK(d.sdo_pending());
      const auto seen = ds402::decode_state(sw);
      if (!seen) {
        previous = s.controlword;
        break;
      }
      const ds402::state from = seen.value();
      if (trace) {
        std::fprintf(stderr, "cycle sw %04X (%s) -> cw %04X after %04X, machine %s, power %d\n", sw,
                     std::string(ds402::to_string(from)).c_str(), s.controlword, previous,
                     std::string(master::to_string(s.state)).c_str(), power);
      }
      if (from == ds402::state::fault || from == ds402::state::fault_reaction_active) power = 0;
      const ds402::step t = ds402::apply(from, s.controlword, previous);
      if (t.transition == ds402::no_transition) {
        FUZZ_CHECK(holds(from, ds402::decode_command(s.controlword, previous)) ||
                   (from == ds402::state::fault && (s.controlword & ds402::cw::fault_reset) != 0U));
      }
      switch (t.transition) {
      case 2: FUZZ_CHECK(power >= 2); break;
      case 3: FUZZ_CHECK(power >= 3); break;
      case 4:
      case 16: FUZZ_CHECK(power >= 4); break;
      case 15: FUZZ_CHECK(reset_asked); break;
      default: break;
      }
      if (t.second_transition == 4) FUZZ_CHECK(power >= 4);
      if (s.state == master::drive_state::failed || s.state == master::drive_state::fault ||
          s.state == master::drive_state::idle) {
        power = 0; // powering up again needs a new command
      }
      if (from != ds402::state::fault && from != ds402::state::fault_reaction_active) {
        reset_asked = false; // a reset ends when the drive leaves fault
      }
      previous = s.controlword;
      break;
    }
    case 2: { // power commands
      const std::uint8_t c = in.byte();
      if (trace) std::fprintf(stderr, "command %u\n", c % 4U);
      if (c % 4U == 0U) {
        if (d.enable(now)) power = 4;
      } else if (c % 4U == 1U) {
        static constexpr std::array<ds402::state, 4> targets{
            ds402::state::switch_on_disabled, ds402::state::ready_to_switch_on,
            ds402::state::switched_on, ds402::state::operation_enabled};
        const ds402::state target = targets[c / 4U % targets.size()];
        if (d.disable(now, target)) {
          power = target == ds402::state::switched_on          ? 3
                  : target == ds402::state::ready_to_switch_on ? 2
                                                               : 0;
        }
      } else if (c % 4U == 2U) {
        d.quick_stop(now);
        power = 0;
      } else if (d.reset_fault(now)) {
        reset_asked = true;
        power = 0;
      }
      break;
    }
    case 3: { // motion commands
      const std::uint8_t c = in.byte();
      const std::int32_t v = static_cast<std::int32_t>(in.u32());
      switch (c % 8U) {
      case 0: (void)d.switch_mode(static_cast<std::int8_t>(in.byte()), now); break;
      case 1: (void)d.move_to(v, now, (c & 0x10U) != 0U, (c & 0x20U) != 0U); break;
      case 2: (void)d.run_velocity(v, now); break;
      case 3:
        (void)d.home(now, (c & 0x10U) != 0U ? std::optional<std::int8_t>{} : std::int8_t{35});
        break;
      case 4: (void)d.start_cyclic(v, now); break;
      case 5: d.set_target(v); break;
      case 6: d.stop_running(); break;
      default: d.halt((c & 0x10U) != 0U); break;
      }
      break;
    }
    case 4: { // the SDO transfer it asked for completes, with any bytes
      std::array<std::uint8_t, 4> value{};
      const std::size_t n = in.byte() % 5U;
      for (std::size_t i = 0; i < n; ++i) value[i] = in.byte();
      d.sdo_done(std::span(value).first(n), now);
      break;
    }
    case 5: { // ... or fails
      sdo::transfer_error e{
          fieldcodec::errc::aborted, static_cast<sdo::abort_code>(in.u32()), {0x6060, 0}};
      d.sdo_failed(e, now);
      break;
    }
    case 6: { // an EMCY of the axis
      co::emcy::message m{};
      m.error_code = in.u16();
      m.error_register = in.byte();
      d.on_emcy(m);
      break;
    }
    default: { // XENAX jog: a manufacturer motion (refused when the profile has none)
      if ((op & 0x10U) != 0U) {
        (void)d.start_motion(
            fieldcodec::xenax::jog((op & 0x20U) != 0U ? fieldcodec::xenax::jog_direction::positive
                                                      : fieldcodec::xenax::jog_direction::negative),
            now);
      } else {
        (void)d.stop_motion(now);
      }
      break;
    }
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size < 2) return 0;
  reader in{std::span<const std::uint8_t>(data + 2, size - 2)};
  const auto node = static_cast<std::uint8_t>(1U + data[1] % 127U);
  const auto options = static_cast<std::uint8_t>(data[0] >> 2U);
  switch (data[0] & 3U) {
  case 0: run_configurator(in, node, options); break;
  case 1: run_boot(in, node, options); break;
  default: run_drive(in, options); break;
  }
  return 0;
}
