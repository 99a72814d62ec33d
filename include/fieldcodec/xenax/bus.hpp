// fieldcodec — what differs per bus on the XENAX Xvi: the bus module, the node-ID range and the
// scaling of 60B2h (manual 2.5, 4.2.23). The object dictionary of each bus is generated from
// its own EDS (dictionaries/xenax_{canopen,ethercat,powerlink}.eds, docs/xenax.md).
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>

#include <concepts>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace fieldcodec::xenax {

/// The bus the XENAX's bus module speaks.
enum class bus : std::uint8_t {
  canopen,   ///< CANopen on CAN, bus module 130 10 05
  ethercat,  ///< CANopen over EtherCAT (CoE), 130 10 00
  powerlink, ///< CANopen over POWERLINK, 130 10 10
};

[[nodiscard]] constexpr std::string_view to_string(bus b) noexcept {
  switch (b) {
  case bus::canopen: return "CANopen";
  case bus::ethercat: return "EtherCAT";
  case bus::powerlink: return "POWERLINK";
  }
  return "?";
}

// ---------------------------------------------------------------------------------------------
// Node-ID (manual 2.5, l. 310-312: parameter CI "Card Identifier", range 1-99, for CANopen and
// for POWERLINK; default 0 = not set). CiA 301 allows 1..127; a XENAX accepts only 1..99.

inline constexpr std::uint8_t min_node_id = 1;
inline constexpr std::uint8_t max_node_id = 99;

/// A XENAX node-ID from any integer type. Errors: out_of_range (0, the unset default, and
/// everything above 99 — including the CiA 301 IDs 100..127 the XENAX cannot take).
template <std::integral T>
[[nodiscard]] constexpr result<std::uint8_t> node_id(T v) noexcept {
  if constexpr (std::is_signed_v<T>) {
    if (v < 0) return errc::out_of_range;
  }
  if (static_cast<std::uint64_t>(v) < min_node_id || static_cast<std::uint64_t>(v) > max_node_id) {
    return errc::out_of_range;
  }
  return static_cast<std::uint8_t>(v);
}

// ---------------------------------------------------------------------------------------------
// 60B2h "torque offset" = acceleration feed-forward in CSP mode (4.2.23, l. 1385-1410):
//   acceleration [inc/s²] = 60B2h × Acceleration_Scaling,
//   Acceleration_Scaling = 50 000 on EtherCAT, 1 on the other buses.
// 60B2h is INTEGER16 (-32768..32767), so EtherCAT reaches ±1.6e9 inc/s² in steps of 50 000
// and CANopen/POWERLINK only ±32 767 inc/s².

/// Acceleration_Scaling of the bus.
[[nodiscard]] constexpr std::int32_t acceleration_scaling(bus b) noexcept {
  return b == bus::ethercat ? 50'000 : 1;
}

/// Acceleration (inc/s²) → 60B2h for the bus, rounded half away from zero to a multiple of
/// the scaling. Errors: overflow (outside INTEGER16 after scaling).
[[nodiscard]] constexpr result<std::int16_t>
torque_offset_from_acceleration(std::int64_t inc_per_s2, bus b) noexcept {
  // raw = acceleration / scaling, i.e. a scale of 1 / 50 000 = 0.00002 on EtherCAT
  const scaling::linear s{b == bus::ethercat ? decimal{2, 5} : decimal{1, 0}, {0, 0}};
  FIELDCODEC_TRY(const std::int64_t raw,
                 scaling::to_raw(decimal{inc_per_s2, 0}, s, scaling::field{2, true}));
  return static_cast<std::int16_t>(raw);
}

/// 60B2h → the acceleration (inc/s²) the XENAX applies on the bus. Exact.
[[nodiscard]] constexpr std::int32_t acceleration_from_torque_offset(std::int16_t raw,
                                                                     bus b) noexcept {
  return std::int32_t{raw} * acceleration_scaling(b);
}

} // namespace fieldcodec::xenax
