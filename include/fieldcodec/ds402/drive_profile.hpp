// fieldcodec — a drive profile: what one family of CiA 402 drives does where CiA 402 leaves the
// choice to the manufacturer, as data.
//
//   * the controlword bits a cyclic synchronous mode needs besides the command (CiA 402: none;
//     some drives want bit 4 in CSP);
//   * the motions of manufacturer-specific modes (6060h < 0) that run until they are stopped:
//     the controlword bits that start one, those that stop it, and the statusword bits that say
//     it has stopped (a jog mode).
//
// A vendor's folder supplies one; `cia402_profile` is plain CiA 402. Generic code that commands
// a drive (master::drive) takes a profile and names no vendor (docs/ds402.md, "Drive profiles").
// Transport-agnostic like the rest of ds402/: words, not frames.
#pragma once

#include <fieldcodec/ds402/controlword.hpp>

#include <array>
#include <concepts>
#include <cstdint>
#include <span>
#include <type_traits>

namespace fieldcodec::ds402 {

/// A value of an INTEGER8 object given as a scoped enum over std::int8_t (a mode of operation for
/// 6060h, a homing method for 6098h): `ds402::mode`, a vendor's mode or method enum.
template <class E>
concept int8_enum = std::is_enum_v<E> && std::same_as<std::underlying_type_t<E>, std::int8_t>;

/// A motion of a manufacturer-specific mode that runs until it is stopped (a jog).
/// Bits are controlword bits outside the command (bits 4..6, 8, 9, 11..15, never 0..3 or 7).
struct manufacturer_motion {
  std::int8_t mode = -1;          ///< the mode 6061h must show (manufacturer-specific: < 0)
  std::uint16_t start_bits = 0;   ///< held while the motion runs
  std::uint16_t stop_bits = 0;    ///< held while it stops
  std::uint16_t stopped_bits = 0; ///< statusword bits that all show once it has stopped

  friend constexpr bool operator==(const manufacturer_motion &,
                                   const manufacturer_motion &) = default;

  /// A mode of the manufacturer's range, bits outside the command, something to wait for.
  [[nodiscard]] constexpr bool valid() const noexcept {
    return mode < 0 && (start_bits & cw::command_mask) == 0U &&
           (stop_bits & cw::command_mask) == 0U && stopped_bits != 0U;
  }
};

/// The manufacturer's choices of one drive family (see the top of this file).
struct drive_profile {
  /// Controlword bits held while a cyclic synchronous mode runs (master::drive::start_cyclic),
  /// for mode 8 (csp), 9 (csv), 10 (cst) and 11 (cst with commutation angle).
  std::array<std::uint16_t, 4> cyclic_bits{};
  /// The manufacturer motions the drive offers; no other is started.
  std::span<const manufacturer_motion> motions{};

  /// The bits for cyclic synchronous mode `mode` (0 for any other mode).
  [[nodiscard]] constexpr std::uint16_t cyclic_bits_for(std::int8_t mode) const noexcept {
    if (mode < 8 || mode > 11) return 0;
    return cyclic_bits[static_cast<std::size_t>(mode - 8)];
  }
  /// True when `m` is one of the profile's motions.
  [[nodiscard]] constexpr bool offers(const manufacturer_motion &m) const noexcept {
    for (const auto &o : motions) {
      if (o == m) return true;
    }
    return false;
  }
  /// Every bit outside the command, every motion valid.
  [[nodiscard]] constexpr bool valid() const noexcept {
    for (const std::uint16_t b : cyclic_bits) {
      if ((b & cw::command_mask) != 0U) return false;
    }
    for (const auto &m : motions) {
      if (!m.valid()) return false;
    }
    return true;
  }
};

/// CiA 402 as written: no extra bits in the cyclic synchronous modes, no manufacturer motions.
inline constexpr drive_profile cia402_profile{};

} // namespace fieldcodec::ds402
