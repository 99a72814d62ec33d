// fieldcodec — the DRIVECOM profile 22 state machine of COMPAX (manual 000, chapter 3; active
// with P190 = 22) as thin wrappers over ds402/: DRIVECOM is the ancestor of CiA 402 and uses
// the same bit positions in the low byte of STEUERWORT/STATUSWORT and the same states
// (NICHT-EINSCHALTBEREIT = not ready to switch on, EINSCHALTSPERRE = switch on disabled,
// EINSCHALTBEREIT = ready to switch on, EINGESCHALTET = switched on, BETRIEB-FREIGEGEBEN =
// operation enabled, SCHNELLHALT-AKTIV = quick stop active, STÖRUNGSREAKTION = fault reaction
// active, STÖRUNG = fault). The high bytes carry COMPAX functions and are kept as they are.
#pragma once

#include <fieldcodec/compax/control.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/ds402/statusword.hpp>

#include <cstdint>

namespace fieldcodec::compax {

/// The device state STATUSWORT shows (only meaningful while no pop-up message is shown).
/// Errors: bad_state (bit pattern of no state).
[[nodiscard]] constexpr result<ds402::state> drivecom_state(statuswort s) noexcept {
  return ds402::decode_state(s.raw);
}

/// The next STEUERWORT that moves the drive towards `target`: the ds402 command bits in the
/// low byte, the COMPAX bits of `previous` (bits 4..6 and the high byte: FreezePAD,
/// ObjectReqEnable, Hand±, START, STOP, SPM, new set point, relative) kept.
/// Errors: those of ds402::next_controlword.
[[nodiscard]] constexpr result<steuerwort> next_steuerwort(statuswort s, ds402::state target,
                                                           steuerwort previous) noexcept {
  auto cw = ds402::next_controlword(s.raw, target, previous.raw);
  if (!cw) return cw.error();
  const auto kept = static_cast<std::uint16_t>(previous.raw & ~ds402::cw::command_mask);
  return steuerwort{static_cast<std::uint16_t>(kept | cw.value())};
}

} // namespace fieldcodec::compax
