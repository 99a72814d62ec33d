// fieldcodec — host adapter: conversions between canopen::can_frame and Linux SocketCAN
// `struct can_frame`.
//
// host/ is the only place of fieldcodec that knows an operating system. Its headers belong to
// the CMake target fieldcodec::host (Linux only); nothing under include/fieldcodec/ outside
// host/ includes them, and firmware never builds them. This header is empty where
// <linux/can.h> does not exist. It does no I/O itself: opening and reading the socket stays with
// the application.
#pragma once

#if defined(__has_include)
#if __has_include(<linux/can.h>)
#define FIELDCODEC_HAS_SOCKETCAN 1
#endif
#endif

#ifdef FIELDCODEC_HAS_SOCKETCAN

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/core/result.hpp>

#include <linux/can.h>

#include <cstddef>
#include <cstdint>

namespace fieldcodec::host {

/// A SocketCAN frame for `f` (base frame format; RTR sets CAN_RTR_FLAG).
/// Errors: invalid_argument (id > 0x7FF), bad_length (dlc > 8).
[[nodiscard]] inline result<::can_frame> to_socketcan(const canopen::can_frame &f) noexcept {
  if (f.id > canopen::max_can_id) return errc::invalid_argument;
  if (f.dlc > canopen::max_dlc) return errc::bad_length;
  ::can_frame out{};
  out.can_id = static_cast<canid_t>(f.id) | (f.rtr ? static_cast<canid_t>(CAN_RTR_FLAG) : 0U);
  out.can_dlc = f.dlc;
  if (!f.rtr) {
    for (std::size_t i = 0; i < f.dlc; ++i) out.data[i] = f.data[i];
  }
  return out;
}

/// The frame SocketCAN delivered. Error frames and extended (29-bit) frames are not CANopen
/// base frames. Errors: unexpected_frame (CAN_ERR_FLAG or CAN_EFF_FLAG set), bad_length
/// (length > 8).
[[nodiscard]] inline result<canopen::can_frame> from_socketcan(const ::can_frame &in) noexcept {
  if ((in.can_id & static_cast<canid_t>(CAN_ERR_FLAG)) != 0U) return errc::unexpected_frame;
  if ((in.can_id & static_cast<canid_t>(CAN_EFF_FLAG)) != 0U) return errc::unexpected_frame;
  // A base frame has 11 identifier bits: anything above them would be silently dropped and the
  // frame misrouted (0x1605 read as 0x605), so it is refused (fuzz F10).
  if ((in.can_id & static_cast<canid_t>(CAN_EFF_MASK & ~CAN_SFF_MASK)) != 0U) {
    return errc::invalid_argument;
  }
  if (in.can_dlc > canopen::max_dlc) return errc::bad_length;
  canopen::can_frame f;
  f.id = static_cast<std::uint16_t>(in.can_id & static_cast<canid_t>(CAN_SFF_MASK));
  f.rtr = (in.can_id & static_cast<canid_t>(CAN_RTR_FLAG)) != 0U;
  f.dlc = in.can_dlc;
  if (!f.rtr) {
    for (std::size_t i = 0; i < f.dlc; ++i) f.data[i] = in.data[i];
  }
  return f;
}

} // namespace fieldcodec::host

#endif // FIELDCODEC_HAS_SOCKETCAN
