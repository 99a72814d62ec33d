// Fuzz harness for CiA 402 words (ds402/). The input is a sequence of 7-byte records
//   statusword (2, big-endian) | target selector (1) | previous controlword (2) | mode bits (2)
// and every record is checked against these properties:
//
// * decode_state: a statusword either decodes to a state or fails with bad_state. Canonical
//   form: the state bits (0..3, 5, 6) replaced by state_bits(s) — bit 5 is "don't care" for the
//   states whose pattern ignores it, and state_bits clears it — decode to the same state; every
//   other bit is kept. decode_flags re-encodes to exactly the non-state bits it names.
// * decode_command / with_command: re-encoding the decoded command into the same word decodes
//   to the same command; a command encoded with with_command decodes to its canonical form
//   (switch_on_enable → enable_operation, disable_operation → switch_on) and keeps every
//   non-command bit of the base word.
// * next_controlword never returns anything but one of the six command patterns (0x00, 0x02,
//   0x06, 0x07, 0x0F, 0x80), fails exactly for bad targets (invalid_argument) and undecodable
//   statuswords (bad_state), and — driving a simulated drive (apply) with its answers — reaches
//   the target within a few cycles from every state that has no automatic transition pending.
//   power_sequencer does the same and keeps the caller's mode bits.
// * decode_mode: every standard and manufacturer-specific value decodes to a mode holding that
//   value; only the reserved values (5, 12..127) give out_of_range.
#include "check.hpp"

#include <fieldcodec/ds402/controlword.hpp>
#include <fieldcodec/ds402/modes.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/ds402/statusword.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

namespace ds402 = fieldcodec::ds402;
using ds402::command;
using ds402::state;
using fieldcodec::errc;

namespace {

constexpr std::uint16_t state_bit_mask = 0x006FU;

constexpr std::array<state, 8> all_states{
    state::not_ready_to_switch_on, state::switch_on_disabled,
    state::ready_to_switch_on,     state::switched_on,
    state::operation_enabled,      state::quick_stop_active,
    state::fault_reaction_active,  state::fault,
};
constexpr std::array<command, 8> all_commands{
    command::shutdown,         command::switch_on,   command::switch_on_enable,
    command::disable_voltage,  command::quick_stop,  command::disable_operation,
    command::enable_operation, command::fault_reset,
};

bool is_command_pattern(std::uint16_t cw) {
  switch (cw) {
  case 0x0000U:
  case 0x0002U:
  case 0x0006U:
  case 0x0007U:
  case 0x000FU:
  case 0x0080U: return true;
  default: return false;
  }
}

command canonical(command c) {
  if (c == command::switch_on_enable) return command::enable_operation;
  if (c == command::disable_operation) return command::switch_on;
  return c;
}

std::uint16_t with_state(std::uint16_t statusword, state s) {
  return static_cast<std::uint16_t>((statusword & ~state_bit_mask) | ds402::state_bits(s));
}

void check_statusword(std::uint16_t sw) {
  auto s = ds402::decode_state(sw);
  if (s) {
    FUZZ_CHECK(ds402::decode_state(with_state(sw, s.value())).value() == s.value());
    FUZZ_CHECK(ds402::to_string(s.value()) != "?");
  } else {
    FUZZ_CHECK(s.error() == errc::bad_state);
  }
  const auto f = ds402::decode_flags(sw);
  const auto b = [](bool on, unsigned bit) { return on ? 1U << bit : 0U; };
  const unsigned back = b(f.voltage_enabled, 4) | b(f.warning, 7) | b(f.remote, 9) |
                        b(f.target_reached, 10) | b(f.internal_limit_active, 11) | b(f.bit12, 12) |
                        b(f.bit13, 13);
  FUZZ_CHECK(back == (sw & 0x3E90U));
}

void check_command(std::uint16_t cw, std::uint16_t previous) {
  const command d = ds402::decode_command(cw, previous);
  FUZZ_CHECK(d != command::switch_on_enable && d != command::disable_operation);
  FUZZ_CHECK(ds402::decode_command(ds402::with_command(cw, d), previous) == d);
  for (const command c : all_commands) {
    const std::uint16_t w = ds402::with_command(cw, c);
    FUZZ_CHECK((w & ~ds402::cw::command_mask) == (cw & ~ds402::cw::command_mask));
    FUZZ_CHECK((w & ds402::cw::command_mask) == ds402::command_bits(c));
    if (c == command::fault_reset) {
      if ((previous & ds402::cw::fault_reset) == 0U) {
        FUZZ_CHECK(ds402::decode_command(w, previous) == command::fault_reset);
      }
    } else {
      FUZZ_CHECK(ds402::decode_command(w, previous) == canonical(c));
    }
  }
}

// Drives a simulated drive, starting from the state `sw` shows, towards `target`.
void check_convergence(std::uint16_t sw, state target, std::uint16_t previous,
                       std::uint16_t mode_bits) {
  auto start = ds402::decode_state(sw);
  if (!start) return;
  const state s0 = start.value();
  // Automatic transitions (0, 1, 14) are the drive's business: no controlword moves these.
  const bool stuck = s0 == state::not_ready_to_switch_on || s0 == state::fault_reaction_active;

  // next_controlword with the caller tracking `previous`
  state cur = s0;
  std::uint16_t prev = previous;
  bool reached = cur == target;
  for (int i = 0; i < 8 && !reached; ++i) {
    auto cw = ds402::next_controlword(with_state(sw, cur), target, prev);
    FUZZ_CHECK(cw.has_value());
    FUZZ_CHECK(is_command_pattern(cw.value()));
    const auto st = ds402::apply(cur, cw.value(), prev);
    prev = cw.value();
    cur = st.to;
    reached = cur == target;
  }
  if (!stuck) FUZZ_CHECK(reached);

  // power_sequencer: same, with mode bits kept
  ds402::power_sequencer seq(previous);
  cur = s0;
  reached = cur == target;
  for (int i = 0; i < 8 && !reached; ++i) {
    const std::uint16_t before = seq.previous();
    auto cw = seq.next(with_state(sw, cur), target, mode_bits);
    FUZZ_CHECK(cw.has_value());
    FUZZ_CHECK(is_command_pattern(cw.value() & ds402::cw::command_mask));
    FUZZ_CHECK((cw.value() & ~ds402::cw::command_mask) == (mode_bits & ~ds402::cw::command_mask));
    FUZZ_CHECK(seq.previous() == cw.value());
    cur = ds402::apply(cur, cw.value(), before).to;
    reached = cur == target;
  }
  if (!stuck) FUZZ_CHECK(reached);
}

void check_next(std::uint16_t sw, std::uint8_t target_byte, std::uint16_t previous,
                std::uint16_t mode_bits) {
  const auto target = static_cast<state>(target_byte % 10U); // 8, 9: not states at all
  const bool valid_target = target == state::switch_on_disabled ||
                            target == state::ready_to_switch_on || target == state::switched_on ||
                            target == state::operation_enabled ||
                            target == state::quick_stop_active;
  auto cw = ds402::next_controlword(sw, target, previous);
  if (!valid_target) {
    FUZZ_CHECK(cw.is(errc::invalid_argument));
    return;
  }
  if (!ds402::decode_state(sw)) {
    FUZZ_CHECK(cw.is(errc::bad_state));
    return;
  }
  FUZZ_CHECK(cw.has_value());
  FUZZ_CHECK(is_command_pattern(cw.value()));
  check_convergence(sw, target, previous, mode_bits);
}

void check_mode(std::uint8_t byte) {
  const auto v = static_cast<std::int8_t>(byte);
  auto m = ds402::decode_mode(v);
  if (m) {
    // the mode holds the INTEGER8 value itself: standard or manufacturer-specific
    FUZZ_CHECK(static_cast<std::uint8_t>(static_cast<std::int8_t>(m.value())) == byte);
    FUZZ_CHECK(ds402::is_standard_mode(v) != ds402::is_manufacturer_mode(v));
    FUZZ_CHECK(ds402::is_manufacturer_mode(m.value()) == (v < 0));
    FUZZ_CHECK(ds402::to_string(m.value()) != "?" && ds402::to_string(m.value()) != "reserved");
    FUZZ_CHECK((ds402::to_string(m.value()) == "manufacturer-specific") == (v < 0));
  } else {
    FUZZ_CHECK(m.error() == errc::out_of_range);
    FUZZ_CHECK(!ds402::is_standard_mode(v) && !ds402::is_manufacturer_mode(v));
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  // Every state's canonical bits decode to that state (cheap, independent of the input).
  for (const state s : all_states) FUZZ_CHECK(ds402::decode_state(ds402::state_bits(s)) == s);

  for (std::size_t at = 0; at + 7 <= size; at += 7) {
    const std::uint8_t *r = data + at;
    const auto sw = static_cast<std::uint16_t>(r[0] << 8U | r[1]);
    const auto previous = static_cast<std::uint16_t>(r[3] << 8U | r[4]);
    const auto mode_bits = static_cast<std::uint16_t>(r[5] << 8U | r[6]);
    check_statusword(sw);
    check_command(sw, previous); // the statusword bytes double as a controlword
    check_next(sw, r[2], previous, mode_bits);
    check_mode(r[2]);
    check_mode(r[6]);
  }
  return 0;
}
