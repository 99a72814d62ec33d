// fieldcodec — the NMT slave (CiA 301 7.3.2): the node's NMT state, the commands of the NMT
// master, the boot-up message, what the two resets restore, and which communication services
// each state allows.
//
//   node::nmt_slave nmt(5);
//   auto s = nmt.boot();                        // after power-on: boot-up 0x705 [00],
//                                               //   state pre-operational
//   s = nmt.on_frame(frame, now);               // NMT command (0x000 [cs, node])
//   if (nmt.pending_reset() != node::reset::none) {
//     ... restore what node::restored(nmt.pending_reset()) names, then: s = nmt.boot();
//   }
//   if (node::allowed(nmt.state(), node::service::pdo)) ...
//
// States (nmt::state): boot_up stands for "initialising" (the slave is resetting or has not
// booted yet; it answers nothing), then pre_operational, operational, stopped. The commands act
// from every state but initialising: start → operational, stop → stopped, enter
// pre-operational → pre-operational, reset node / reset communication → initialising with
// pending_reset() set; the caller carries the reset out and calls boot(), which sends the
// boot-up message and enters pre-operational (CiA 301 Figure 48).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/result.hpp>

#include <cstdint>
#include <optional>

namespace fieldcodec::canopen::node {

/// The communication services of CiA 301, for the "which service in which state" table.
enum class service : std::uint8_t {
  nmt,           ///< NMT module control (commands from the master)
  error_control, ///< heartbeat, node guarding / life guarding
  sdo,
  emcy,
  sync,
  time,
  pdo,
};

/// May the node use `s` in NMT state `state`? CiA 301 Table 48: initialising nothing (the
/// slave sends its boot-up message itself); pre-operational everything but PDOs; operational
/// everything; stopped only NMT and error control.
[[nodiscard]] constexpr bool allowed(nmt::state state, service s) noexcept {
  switch (state) {
  case nmt::state::boot_up: return false;
  case nmt::state::pre_operational: return s != service::pdo;
  case nmt::state::operational: return true;
  case nmt::state::stopped: return s == service::nmt || s == service::error_control;
  }
  return false;
}

/// What an NMT reset command asks for.
enum class reset : std::uint8_t {
  none,
  application,   ///< reset node: application area and communication area
  communication, ///< reset communication: communication area only
};

/// The index ranges a reset sets back to their power-on values (CiA 301 7.3.2.2.1):
/// communication → 1000h–1FFFh; application → 2000h–FFFFh (manufacturer, profile and network
/// variable areas), followed by a reset of communication.
struct index_range {
  std::uint16_t first = 0;
  std::uint16_t last = 0;
};
[[nodiscard]] constexpr index_range restored(reset r) noexcept {
  switch (r) {
  case reset::application: return {0x2000U, 0xFFFFU};
  case reset::communication: return {0x1000U, 0x1FFFU};
  case reset::none: break;
  }
  return {};
}

class nmt_slave {
public:
  using step = canopen::step<nmt::state>;

  /// The slave of node `node` (1..127; any other node-ID answers only broadcast commands and
  /// cannot send its boot-up message: boot() then stays in initialising).
  constexpr explicit nmt_slave(std::uint8_t node) noexcept : node_(node) {}

  /// Power-on or a carried-out reset: send the boot-up message (0x700 + node [00]) and enter
  /// pre-operational, or operational when `self_start` (the "NMT start-up" behaviour of 1F80h
  /// bit 2 that a device without an NMT master needs). Clears pending_reset().
  [[nodiscard]] constexpr step boot(bool self_start = false) noexcept {
    const auto f = boot_up(self_start);
    return make(f ? frames(*f) : frames{});
  }
  /// boot() without the step (what node::device calls): the boot-up message to send.
  [[nodiscard]] constexpr std::optional<can_frame> boot_up(bool self_start = false) noexcept {
    pending_ = reset::none;
    const auto f = nmt::encode_boot_up(node_);
    if (!f) {
      error_ = f.error();
      return std::nullopt;
    }
    state_ = self_start ? nmt::state::operational : nmt::state::pre_operational;
    return f.value();
  }

  /// An NMT command frame (COB-ID 0). Frames on other identifiers are not for the slave and are
  /// ignored silently; a malformed NMT frame (DLC ≠ 2, RTR, unknown command specifier, node-ID
  /// > 127) is ignored and error() says why; commands for another node are ignored; while
  /// initialising every command is ignored (error(): bad_state).
  [[nodiscard]] constexpr step on_frame(const can_frame &f,
                                        [[maybe_unused]] std::uint32_t now) noexcept {
    receive(f);
    return make({});
  }
  /// on_frame() without the step (what node::device calls): state(), pending_reset(), error().
  constexpr void receive(const can_frame &f) noexcept {
    if (f.id != cob_id::nmt) return;
    auto m = nmt::decode(f);
    if (!m) {
      error_ = m.error();
      return;
    }
    if (m.value().node != 0U && m.value().node != node_) return;
    if (state_ == nmt::state::boot_up) {
      error_ = errc::bad_state;
      return;
    }
    error_ = errc{};
    switch (m.value().cs) {
    case nmt::command::start: state_ = nmt::state::operational; break;
    case nmt::command::stop: state_ = nmt::state::stopped; break;
    case nmt::command::enter_pre_operational: state_ = nmt::state::pre_operational; break;
    case nmt::command::reset_node:
      state_ = nmt::state::boot_up;
      pending_ = reset::application;
      break;
    case nmt::command::reset_communication:
      state_ = nmt::state::boot_up;
      // a reset node still pending stays the larger reset
      if (pending_ != reset::application) pending_ = reset::communication;
      break;
    }
  }

  /// A state change the device decides itself (its error behaviour, e.g. 1029h, or an
  /// application without NMT master). Errors: invalid_argument (boot_up: use a reset),
  /// bad_state (initialising: boot() first).
  [[nodiscard]] constexpr result<step> enter(nmt::state s) noexcept {
    if (s == nmt::state::boot_up) return errc::invalid_argument;
    if (state_ == nmt::state::boot_up) return errc::bad_state;
    state_ = s;
    return make({});
  }

  [[nodiscard]] constexpr nmt::state state() const noexcept { return state_; }
  [[nodiscard]] constexpr std::uint8_t node_id() const noexcept { return node_; }
  /// The reset the last command asked for, until boot() completes it.
  [[nodiscard]] constexpr reset pending_reset() const noexcept { return pending_; }
  [[nodiscard]] constexpr bool allows(service s) const noexcept { return allowed(state_, s); }
  /// Why the last NMT frame was ignored (empty when it was taken).
  [[nodiscard]] constexpr std::optional<errc> error() const noexcept {
    if (error_ == errc{}) return std::nullopt;
    return error_;
  }

private:
  [[nodiscard]] constexpr step make(frames f) const noexcept { return {f, state_, {}}; }

  std::uint8_t node_;
  nmt::state state_ = nmt::state::boot_up;
  reset pending_ = reset::none;
  /// errc{} (no code of errc is 0) while the last frame was taken. A plain member, not a
  /// std::optional: g++ 12 at -O3 (s390x) warned that the optional's payload may be read
  /// uninitialised when it is copied out (-Wmaybe-uninitialized), in users' -Werror builds too.
  errc error_{};
};

} // namespace fieldcodec::canopen::node
