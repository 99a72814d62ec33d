// fieldcodec — a classic CAN frame as a value: 11-bit identifier, RTR flag, DLC 0..8, 8 bytes.
//
// CANopen (CiA 301) uses base frames only; extended (29-bit) and CAN FD frames are not
// represented. Bytes past the DLC are kept zero by the constructors so that frames compare
// equal when their meaningful content is equal.
#pragma once

#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>

namespace fieldcodec::canopen {

inline constexpr std::uint16_t max_can_id = 0x7FFU;
inline constexpr std::size_t max_dlc = 8U;

struct can_frame {
  std::uint16_t id = 0; ///< 11-bit identifier (COB-ID)
  bool rtr = false;     ///< remote transmission request
  std::uint8_t dlc = 0; ///< data length code, 0..8 (for RTR: the requested length)
  std::array<std::uint8_t, 8> data{};

  /// The first `dlc` bytes (empty for remote frames).
  [[nodiscard]] constexpr std::span<const std::uint8_t> payload() const noexcept {
    return rtr ? std::span<const std::uint8_t>{} : std::span<const std::uint8_t>(data).first(dlc);
  }
  /// True when id <= 0x7FF, dlc <= 8, and bytes beyond the DLC are zero.
  [[nodiscard]] constexpr bool is_valid() const noexcept {
    if (id > max_can_id || dlc > max_dlc) return false;
    for (std::size_t i = rtr ? 0U : dlc; i < max_dlc; ++i) {
      if (data[i] != 0U) return false;
    }
    return true;
  }
  friend constexpr bool operator==(const can_frame &, const can_frame &) = default;
};

/// A data frame. Errors: invalid_argument (id > 0x7FF), too_long (more than 8 bytes).
[[nodiscard]] constexpr result<can_frame> make_frame(std::uint16_t id,
                                                     std::span<const std::uint8_t> bytes) noexcept {
  if (id > max_can_id) return errc::invalid_argument;
  if (bytes.size() > max_dlc) return errc::too_long;
  can_frame f;
  f.id = id;
  f.dlc = static_cast<std::uint8_t>(bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) f.data[i] = bytes[i];
  return f;
}
[[nodiscard]] constexpr result<can_frame>
make_frame(std::uint16_t id, std::initializer_list<std::uint8_t> bytes) noexcept {
  return make_frame(id, std::span<const std::uint8_t>(bytes.begin(), bytes.size()));
}

/// A remote frame requesting `dlc` bytes. Errors: invalid_argument (id), bad_length (dlc > 8).
[[nodiscard]] constexpr result<can_frame> make_remote_frame(std::uint16_t id,
                                                            std::uint8_t dlc) noexcept {
  if (id > max_can_id) return errc::invalid_argument;
  if (dlc > max_dlc) return errc::bad_length;
  can_frame f;
  f.id = id;
  f.rtr = true;
  f.dlc = dlc;
  return f;
}

/// Common input check for decoders: a valid data frame with exactly `dlc` bytes.
/// Errors: bad_length (wrong DLC or invalid frame), unexpected_frame (remote frame).
[[nodiscard]] constexpr status expect_data(const can_frame &f, std::size_t dlc) noexcept {
  if (f.id > max_can_id || f.dlc > max_dlc) return errc::bad_length;
  if (f.rtr) return errc::unexpected_frame;
  if (f.dlc != dlc) return errc::bad_length;
  return {};
}

} // namespace fieldcodec::canopen
