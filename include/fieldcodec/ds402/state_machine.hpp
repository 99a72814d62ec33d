// fieldcodec — CiA 402 power drive system state machine: transitions 0..16 and a pure helper that
// computes the next controlword to walk a drive towards a target state.
//
// Both directions are here: `apply` tells what a drive does with a controlword (useful for
// simulated drives and for checking a master), `next_controlword` tells what a master sends.
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/ds402/controlword.hpp>
#include <fieldcodec/ds402/statusword.hpp>

#include <cstdint>

namespace fieldcodec::ds402 {

/// Transition numbers of CiA 402 (0..16; 13 is the fault event, 0, 1 and 14 are automatic).
inline constexpr std::uint8_t no_transition = 0xFFU;

/// The result of applying a controlword to a state.
struct step {
  state to;
  std::uint8_t transition;        ///< no_transition when the state stays
  std::uint8_t second_transition; ///< 4 when 0x0F from "ready to switch on" does 3 + 4
  friend constexpr bool operator==(const step &, const step &) = default;
};

/// What a drive in state `from` does on receiving `controlword` (after `previous`), not
/// counting automatic transitions (0, 1, 14) and the fault event (13). Quick stop active is left
/// only by disable voltage (12) or enable operation (16); the automatic return after the quick
/// stop ramp (option code dependent) is the drive's business.
[[nodiscard]] constexpr step apply(state from, std::uint16_t controlword,
                                   std::uint16_t previous) noexcept {
  command c = decode_command(controlword, previous);
  if (c == command::fault_reset && from != state::fault) {
    c = decode_command(controlword, controlword); // the edge only matters in fault
  }
  const step stay{from, no_transition, no_transition};
  switch (from) {
  case state::not_ready_to_switch_on:
  case state::fault_reaction_active: return stay;
  case state::fault:
    return c == command::fault_reset ? step{state::switch_on_disabled, 15, no_transition} : stay;
  case state::switch_on_disabled:
    return c == command::shutdown ? step{state::ready_to_switch_on, 2, no_transition} : stay;
  case state::ready_to_switch_on:
    switch (c) {
    case command::switch_on: return {state::switched_on, 3, no_transition};
    case command::enable_operation: return {state::operation_enabled, 3, 4};
    case command::disable_voltage:
    case command::quick_stop: return {state::switch_on_disabled, 7, no_transition};
    default: return stay;
    }
  case state::switched_on:
    switch (c) {
    case command::enable_operation: return {state::operation_enabled, 4, no_transition};
    case command::shutdown: return {state::ready_to_switch_on, 6, no_transition};
    case command::disable_voltage:
    case command::quick_stop: return {state::switch_on_disabled, 10, no_transition};
    default: return stay;
    }
  case state::operation_enabled:
    switch (c) {
    case command::switch_on: return {state::switched_on, 5, no_transition};
    case command::shutdown: return {state::ready_to_switch_on, 8, no_transition};
    case command::disable_voltage: return {state::switch_on_disabled, 9, no_transition};
    case command::quick_stop: return {state::quick_stop_active, 11, no_transition};
    default: return stay;
    }
  case state::quick_stop_active:
    switch (c) {
    case command::disable_voltage: return {state::switch_on_disabled, 12, no_transition};
    case command::enable_operation: return {state::operation_enabled, 16, no_transition};
    default: return stay;
    }
  }
  return stay;
}

/// The command bits (0..3, 7) to send next so that a drive showing `statusword` moves one step
/// towards `target`, given the controlword sent in the previous cycle.
///
/// * target must be switch_on_disabled, ready_to_switch_on, switched_on, operation_enabled or
///   quick_stop_active (reached through operation enabled); others give invalid_argument.
/// * From "ready to switch on" towards operation enabled it sends 0x0F at once (3 + 4).
/// * In fault it sends 0x80 when `previous` had bit 7 clear (the rising edge, transition 15)
///   and 0x00 when `previous` had bit 7 set, so a fault that persists gets a new edge every
///   second cycle. power_sequencer instead holds bit 7 until the drive leaves fault, as some
///   manufacturers' examples do. In fault reaction active it sends 0x00 (waits, prepares the
///   edge).
/// * In "not ready to switch on" it sends 0x00 and waits for the automatic transition 1.
/// * An undecodable statusword gives bad_state.
/// The caller ORs in its mode-specific bits (`with_command` keeps them).
[[nodiscard]] constexpr result<std::uint16_t>
next_controlword(std::uint16_t statusword, state target, std::uint16_t previous) noexcept {
  switch (target) {
  case state::switch_on_disabled:
  case state::ready_to_switch_on:
  case state::switched_on:
  case state::operation_enabled:
  case state::quick_stop_active: break;
  default: return errc::invalid_argument;
  }
  auto cur = decode_state(statusword);
  if (!cur) return cur.error();
  const auto bits = [](command c) { return command_bits(c); };
  switch (cur.value()) {
  case state::not_ready_to_switch_on:
  case state::fault_reaction_active: return bits(command::disable_voltage);
  case state::fault:
    return (previous & cw::fault_reset) != 0U ? bits(command::disable_voltage)
                                              : bits(command::fault_reset);
  case state::switch_on_disabled:
    return target == state::switch_on_disabled ? bits(command::disable_voltage)
                                               : bits(command::shutdown);
  case state::ready_to_switch_on:
  case state::switched_on:
    switch (target) {
    case state::switch_on_disabled: return bits(command::disable_voltage);
    case state::ready_to_switch_on: return bits(command::shutdown);
    case state::switched_on: return bits(command::switch_on);
    default: return bits(command::switch_on_enable);
    }
  case state::operation_enabled:
    switch (target) {
    case state::switch_on_disabled: return bits(command::disable_voltage);
    case state::ready_to_switch_on: return bits(command::shutdown);
    case state::switched_on: return bits(command::disable_operation);
    case state::quick_stop_active: return bits(command::quick_stop);
    default: return bits(command::enable_operation);
    }
  case state::quick_stop_active:
    switch (target) {
    case state::quick_stop_active: return bits(command::quick_stop);
    case state::operation_enabled: return bits(command::enable_operation); // 16
    default: return bits(command::disable_voltage);                        // 12
    }
  }
  return errc::bad_state;
}

/// A tiny state object for a cyclic task: remembers the previous controlword so that the fault
/// reset edge is produced, and keeps the caller's mode bits.
class power_sequencer {
public:
  constexpr power_sequencer() noexcept = default;
  constexpr explicit power_sequencer(std::uint16_t initial) noexcept : previous_(initial) {}

  /// The full controlword for this cycle: `mode_bits` (bits other than 0..3, 7) plus the command
  /// bits from next_controlword, except in fault: once the rising edge of bit 7 has been sent,
  /// bit 7 is held until the drive leaves fault (then the next command clears it).
  /// Errors as next_controlword.
  [[nodiscard]] constexpr result<std::uint16_t> next(std::uint16_t statusword, state target,
                                                     std::uint16_t mode_bits = 0) noexcept {
    auto bits = next_controlword(statusword, target, previous_);
    if (!bits) return bits.error();
    std::uint16_t cmd = bits.value();
    const bool in_fault = decode_state(statusword).value() == state::fault;
    if (in_fault && edge_sent_) cmd = command_bits(command::fault_reset); // hold bit 7
    edge_sent_ = in_fault && (cmd & cw::fault_reset) != 0U;
    previous_ = static_cast<std::uint16_t>((mode_bits & ~cw::command_mask) | cmd);
    return previous_;
  }
  [[nodiscard]] constexpr std::uint16_t previous() const noexcept { return previous_; }

private:
  std::uint16_t previous_ = 0;
  bool edge_sent_ = false;
};

} // namespace fieldcodec::ds402
