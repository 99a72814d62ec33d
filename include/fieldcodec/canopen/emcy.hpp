// fieldcodec — EMCY messages (CiA 301): error code, error register, manufacturer bytes.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::canopen::emcy {

/// Error register bits (object 1001h, byte 2 of an EMCY).
namespace reg {
inline constexpr std::uint8_t generic = 1U << 0U;
inline constexpr std::uint8_t current = 1U << 1U;
inline constexpr std::uint8_t voltage = 1U << 2U;
inline constexpr std::uint8_t temperature = 1U << 3U;
inline constexpr std::uint8_t communication = 1U << 4U;
inline constexpr std::uint8_t device_profile = 1U << 5U;
inline constexpr std::uint8_t reserved = 1U << 6U; ///< always 0
inline constexpr std::uint8_t manufacturer = 1U << 7U;
} // namespace reg

/// The error code classes of CiA 301 (by the code's high byte / high nibble).
enum class error_class : std::uint8_t {
  no_error,             ///< 0x00xx: error reset or no error
  generic,              ///< 0x10xx
  current,              ///< 0x2xxx (0x21 input side, 0x22 inside, 0x23 output side)
  voltage,              ///< 0x3xxx (0x31 mains, 0x32 inside, 0x33 output)
  temperature,          ///< 0x4xxx (0x41 ambient, 0x42 device)
  device_hardware,      ///< 0x50xx
  device_software,      ///< 0x6xxx (0x61 internal, 0x62 user, 0x63 data set)
  additional_modules,   ///< 0x70xx
  monitoring,           ///< 0x8xxx (0x81 communication, 0x82 protocol error)
  external,             ///< 0x90xx
  additional_functions, ///< 0xF0xx
  device_specific,      ///< 0xFFxx
  unassigned,           ///< anything else
};

[[nodiscard]] constexpr error_class classify(std::uint16_t code) noexcept {
  const auto hi = static_cast<unsigned>(code >> 8U);
  switch (hi >> 4U) {
  case 0x0: return hi == 0x00U ? error_class::no_error : error_class::unassigned;
  case 0x1: return hi == 0x10U ? error_class::generic : error_class::unassigned;
  case 0x2: return error_class::current;
  case 0x3: return error_class::voltage;
  case 0x4: return error_class::temperature;
  case 0x5: return hi == 0x50U ? error_class::device_hardware : error_class::unassigned;
  case 0x6: return error_class::device_software;
  case 0x7: return hi == 0x70U ? error_class::additional_modules : error_class::unassigned;
  case 0x8: return error_class::monitoring;
  case 0x9: return hi == 0x90U ? error_class::external : error_class::unassigned;
  case 0xF:
    if (hi == 0xF0U) return error_class::additional_functions;
    if (hi == 0xFFU) return error_class::device_specific;
    return error_class::unassigned;
  default: return error_class::unassigned;
  }
}

[[nodiscard]] constexpr std::string_view to_string(error_class c) noexcept {
  switch (c) {
  case error_class::no_error: return "no error / error reset";
  case error_class::generic: return "generic error";
  case error_class::current: return "current";
  case error_class::voltage: return "voltage";
  case error_class::temperature: return "temperature";
  case error_class::device_hardware: return "device hardware";
  case error_class::device_software: return "device software";
  case error_class::additional_modules: return "additional modules";
  case error_class::monitoring: return "monitoring";
  case error_class::external: return "external error";
  case error_class::additional_functions: return "additional functions";
  case error_class::device_specific: return "device specific";
  case error_class::unassigned: return "unassigned";
  }
  return "?";
}

/// Some well-known codes of CiA 301.
namespace code {
inline constexpr std::uint16_t error_reset = 0x0000U;
inline constexpr std::uint16_t generic = 0x1000U;
inline constexpr std::uint16_t communication = 0x8100U;
inline constexpr std::uint16_t can_overrun = 0x8110U;
inline constexpr std::uint16_t can_error_passive = 0x8120U;
inline constexpr std::uint16_t life_guard_error = 0x8130U;
inline constexpr std::uint16_t recovered_from_bus_off = 0x8140U;
inline constexpr std::uint16_t can_id_collision = 0x8150U;
inline constexpr std::uint16_t pdo_length_error = 0x8210U;
inline constexpr std::uint16_t pdo_length_exceeded = 0x8220U;
inline constexpr std::uint16_t dam_mpdo_not_processed = 0x8230U;
inline constexpr std::uint16_t unexpected_sync_length = 0x8240U;
inline constexpr std::uint16_t rpdo_timeout = 0x8250U;
inline constexpr std::uint16_t external = 0x9000U;
inline constexpr std::uint16_t device_specific = 0xFF00U;
} // namespace code

struct message {
  std::uint16_t error_code = 0;
  std::uint8_t error_register = 0;
  std::array<std::uint8_t, 5> manufacturer{};
  friend constexpr bool operator==(const message &, const message &) = default;
};

/// The 8 bytes of an EMCY message [error code LE, error register, 5 manufacturer bytes]: the
/// data of a CAN EMCY frame and of a CoE emergency (canopen/coe/service.hpp).
[[nodiscard]] constexpr std::array<std::uint8_t, 8> encode_payload(const message &m) noexcept {
  std::array<std::uint8_t, 8> p{};
  p[0] = static_cast<std::uint8_t>(m.error_code & 0xFFU);
  p[1] = static_cast<std::uint8_t>(m.error_code >> 8U);
  p[2] = m.error_register;
  for (std::size_t i = 0; i < 5U; ++i) p[3U + i] = m.manufacturer[i];
  return p;
}
/// The message in 8 EMCY bytes (the reverse of encode_payload).
[[nodiscard]] constexpr message decode_payload(std::span<const std::uint8_t, 8> p) noexcept {
  message m;
  m.error_code = static_cast<std::uint16_t>(p[0] | (p[1] << 8U));
  m.error_register = p[2];
  for (std::size_t i = 0; i < 5U; ++i) m.manufacturer[i] = p[3U + i];
  return m;
}

/// EMCY of `node`: 0x080+node DLC 8 [code LE, register, 5 manufacturer bytes].
/// Errors: invalid_argument (node not 1..127).
[[nodiscard]] constexpr result<can_frame> encode(std::uint8_t node, const message &m) noexcept {
  auto id = cob_id::emcy(node);
  if (!id) return id.error();
  can_frame f;
  f.id = id.value();
  f.dlc = 8;
  f.data = encode_payload(m);
  return f;
}

struct received {
  std::uint8_t node;
  message m;
  friend constexpr bool operator==(const received &, const received &) = default;
};

/// Decode an EMCY. Errors: unexpected_frame (not 0x081..0x0FF, or a remote frame), bad_length
/// (DLC not 8).
[[nodiscard]] constexpr result<received> decode(const can_frame &f) noexcept {
  if (f.id <= cob_id::emcy_base || f.id > cob_id::emcy_base + max_node_id) {
    return errc::unexpected_frame;
  }
  FIELDCODEC_TRY_STATUS(expect_data(f, 8));
  return received{static_cast<std::uint8_t>(f.id - cob_id::emcy_base),
                  decode_payload(std::span<const std::uint8_t, 8>(f.data))};
}

} // namespace fieldcodec::canopen::emcy
