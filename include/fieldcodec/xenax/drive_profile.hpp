// fieldcodec — the XENAX Xvi as a CiA 402 drive profile (ds402/drive_profile.hpp): what a generic
// CiA 402 master (master::drive) needs to know of it beyond CiA 402.
//
//   master::drive axis({.profile = xenax::profile});
//   axis.start_motion(xenax::jog(xenax::jog_direction::positive), now);   // 0x5F
//   axis.stop_motion(now);                                 // 0x11F until bit 12 (speed zero)
//   if (auto e = axis.error(); e && e->error_code_read) xenax::decode_error_code(e->error_code);
#pragma once

#include <fieldcodec/ds402/controlword.hpp>
#include <fieldcodec/ds402/drive_profile.hpp>
#include <fieldcodec/xenax/modes.hpp>

#include <cstdint>

namespace fieldcodec::xenax {

/// Jog (mode −1, manual 5.4.1): started by 0x1F (negative) / 0x5F (positive), stopped by 0x11F
/// as the manual prints it for both directions, stopped once the statusword shows speed zero
/// (bit 12).
[[nodiscard]] constexpr ds402::manufacturer_motion jog(jog_direction d) noexcept {
  return {static_cast<std::int8_t>(mode::jog),
          static_cast<std::uint16_t>(jog_start(d) & ~ds402::cw::command_mask),
          static_cast<std::uint16_t>(jog_stop & ~ds402::cw::command_mask), sw::bit12};
}

/// The motions of a XENAX: jog in both directions.
inline constexpr ds402::manufacturer_motion motions[] = {jog(jog_direction::negative),
                                                         jog(jog_direction::positive)};

/// The XENAX's profile: CSP runs with bit 4 set (manual 5.3.1: 0x1F), jog as above. Its error
/// numbers in 603Fh (0xFF00 + n) are read with `decode_error_code` (xenax/error_code.hpp).
inline constexpr ds402::drive_profile profile{
    {static_cast<std::uint16_t>(csp_start & ~ds402::cw::command_mask), 0, 0, 0}, motions};

static_assert(profile.valid());
static_assert(jog(jog_direction::positive).start_bits == 0x0050U);
static_assert(jog(jog_direction::negative).stop_bits == 0x0110U);

} // namespace fieldcodec::xenax
