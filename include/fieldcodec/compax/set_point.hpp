// fieldcodec — the LAGE_ZIEL set-point handshake (object 0x607A on the process output data,
// manual 000, section 2.7.3; PA_ENABLE bit 7, 2.12.8).
//
// With LAGE_ZIEL on the cyclic PAD, a new target is accepted through a handshake between
// STEUERWORT bit 4 "new set point" (data byte 2 bit 4) and STATUSWORT bit 12 "set-point
// acknowledgement" (data byte 1 bit 4):
//   1  master: LAGE_ZIEL = new target, new set point = 1   (only while the acknowledgement is 0)
//   2  drive:  acknowledgement = 1                          (set point recognised)
//   3  master: new set point = 0
//   4  drive:  acknowledgement = 0                          (a new target can be transferred)
// STEUERWORT bit 6 says whether the target is absolute (0) or relative (1). PA_ENABLE bit 7 = 1
// turns the automatic acceptance of a changed LAGE_ZIEL off, so that only this handshake moves
// the axis.
//
// set_point_handshake is a pure machine like object_channel: the caller owns it and, every
// process-data cycle, sends control(previous STEUERWORT) and target_bytes() and feeds the
// STATUSWORT it received, with the STEUERWORT it sent, to poll(). A STATUSWORT that shows a
// pop-up message (its SPM differs from the control word's) carries no handshake bit and is
// ignored. Timeouts are the caller's business (cancel()).
#pragma once

#include <fieldcodec/compax/control.hpp>
#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>

namespace fieldcodec::compax {

/// LAGE_ZIEL data bytes for a target in mm (or inch), exact to 0.001.
/// Errors: not_representable (finer than 0.001), overflow (outside Integer32, or the Integer32
/// overflow marker 0x80000000).
[[nodiscard]] constexpr result<std::array<std::uint8_t, 4>>
encode_lage_ziel(decimal target_mm) noexcept {
  auto t = to_fixed(target_mm, 3);
  if (!t) return t.error();
  auto v = checked_narrow<std::int32_t>(t.value());
  if (!v) return errc::overflow;
  return encode_integer<std::int32_t>(v.value());
}

class set_point_handshake {
public:
  enum class phase : std::uint8_t {
    idle,         ///< nothing pending; new set point = 0
    announced,    ///< transition 1 sent: new set point = 1, waiting for the acknowledgement
    acknowledged, ///< transition 2 seen, 3 sent: new set point = 0, waiting for transition 4
  };

  /// Start transition 1 with a target in mm (or inch), absolute or relative (STEUERWORT bit 6).
  /// `status` is the latest STATUSWORT and `control` the STEUERWORT it answered.
  /// Errors: bad_state (a set point is pending, the acknowledgement is still 1, or the status
  /// word shows a pop-up message), those of encode_lage_ziel.
  [[nodiscard]] constexpr status submit(decimal target_mm, bool relative, statuswort status,
                                        steuerwort control) noexcept {
    if (phase_ != phase::idle || shows_popup(status, control) ||
        status.test(statuswort_bit::set_point_acknowledge)) {
      return errc::bad_state;
    }
    auto b = encode_lage_ziel(target_mm);
    if (!b) return b.error();
    target_ = b.value();
    relative_ = relative;
    phase_ = phase::announced;
    return {};
  }

  /// Feed one cycle's STATUSWORT (and the STEUERWORT it answered). Returns true exactly once,
  /// in the cycle the drive acknowledges the set point (transition 2); the machine is idle
  /// again when the acknowledgement has fallen back to 0 (transition 4).
  [[nodiscard]] constexpr bool poll(statuswort status, steuerwort control) noexcept {
    if (shows_popup(status, control)) return false;
    const bool ack = status.test(statuswort_bit::set_point_acknowledge);
    if (phase_ == phase::announced && ack) {
      phase_ = phase::acknowledged;
      return true;
    }
    if (phase_ == phase::acknowledged && !ack) phase_ = phase::idle;
    return false;
  }

  /// `previous` with "new set point" as the phase wants it and "relative" as submitted; every
  /// other bit is kept.
  [[nodiscard]] constexpr steuerwort control(steuerwort previous) const noexcept {
    return previous.with(steuerwort_bit::new_set_point, phase_ == phase::announced)
        .with(steuerwort_bit::target_position_relative, relative_);
  }

  /// The LAGE_ZIEL bytes to send (the last submitted target).
  [[nodiscard]] constexpr const std::array<std::uint8_t, 4> &target_bytes() const noexcept {
    return target_;
  }

  /// Drop a pending set point: new set point goes back to 0.
  constexpr void cancel() noexcept { phase_ = phase::idle; }

  [[nodiscard]] constexpr phase current_phase() const noexcept { return phase_; }
  [[nodiscard]] constexpr bool busy() const noexcept { return phase_ != phase::idle; }

private:
  std::array<std::uint8_t, 4> target_{};
  bool relative_ = false;
  phase phase_ = phase::idle;
};

} // namespace fieldcodec::compax
