// fieldcodec — COB-IDs of the CiA 301 predefined connection set and node-ID validation.
#pragma once

#include <fieldcodec/core/result.hpp>

#include <cstdint>
#include <string_view>

namespace fieldcodec::canopen {

/// Node-IDs 1..127. 0 addresses all nodes, and only where a broadcast is meant (NMT).
inline constexpr std::uint8_t min_node_id = 1;
inline constexpr std::uint8_t max_node_id = 127;

[[nodiscard]] constexpr bool is_node_id(std::uint8_t node) noexcept {
  return node >= min_node_id && node <= max_node_id;
}
/// Errors: invalid_argument (0 or > 127).
[[nodiscard]] constexpr status check_node_id(std::uint8_t node) noexcept {
  if (!is_node_id(node)) return errc::invalid_argument;
  return {};
}

/// The function codes (bits 10..7 of an 11-bit COB-ID) and what they carry.
enum class function : std::uint8_t {
  nmt,        ///< 0x000
  sync,       ///< 0x080
  emcy,       ///< 0x080 + node
  time,       ///< 0x100
  tpdo1,      ///< 0x180 + node
  rpdo1,      ///< 0x200 + node
  tpdo2,      ///< 0x280 + node
  rpdo2,      ///< 0x300 + node
  tpdo3,      ///< 0x380 + node
  rpdo3,      ///< 0x400 + node
  tpdo4,      ///< 0x480 + node
  rpdo4,      ///< 0x500 + node
  sdo_tx,     ///< 0x580 + node: server -> client
  sdo_rx,     ///< 0x600 + node: client -> server
  nmt_error,  ///< 0x700 + node: boot-up, heartbeat, node guarding
  unassigned, ///< an identifier outside the predefined connection set
};

namespace cob_id {
inline constexpr std::uint16_t nmt = 0x000U;
inline constexpr std::uint16_t sync = 0x080U;
inline constexpr std::uint16_t time = 0x100U;
inline constexpr std::uint16_t emcy_base = 0x080U;
inline constexpr std::uint16_t sdo_tx_base = 0x580U;
inline constexpr std::uint16_t sdo_rx_base = 0x600U;
inline constexpr std::uint16_t nmt_error_base = 0x700U;

namespace detail {
[[nodiscard]] constexpr result<std::uint16_t> with_node(std::uint16_t base,
                                                        std::uint8_t node) noexcept {
  if (!is_node_id(node)) return errc::invalid_argument;
  return static_cast<std::uint16_t>(base + node);
}
} // namespace detail

/// EMCY of a node (0x80 + node). Errors: invalid_argument (node not 1..127).
[[nodiscard]] constexpr result<std::uint16_t> emcy(std::uint8_t node) noexcept {
  return detail::with_node(emcy_base, node);
}
/// TPDO n (1..4) of a node: 0x180, 0x280, 0x380, 0x480 + node.
[[nodiscard]] constexpr result<std::uint16_t> tpdo(unsigned n, std::uint8_t node) noexcept {
  if (n < 1U || n > 4U) return errc::invalid_argument;
  return detail::with_node(static_cast<std::uint16_t>(0x080U + 0x100U * n), node);
}
/// RPDO n (1..4) of a node: 0x200, 0x300, 0x400, 0x500 + node.
[[nodiscard]] constexpr result<std::uint16_t> rpdo(unsigned n, std::uint8_t node) noexcept {
  if (n < 1U || n > 4U) return errc::invalid_argument;
  return detail::with_node(static_cast<std::uint16_t>(0x100U + 0x100U * n), node);
}
/// SDO server -> client (0x580 + node).
[[nodiscard]] constexpr result<std::uint16_t> sdo_tx(std::uint8_t node) noexcept {
  return detail::with_node(sdo_tx_base, node);
}
/// SDO client -> server (0x600 + node).
[[nodiscard]] constexpr result<std::uint16_t> sdo_rx(std::uint8_t node) noexcept {
  return detail::with_node(sdo_rx_base, node);
}
/// NMT error control: boot-up, heartbeat, node guarding (0x700 + node).
[[nodiscard]] constexpr result<std::uint16_t> nmt_error(std::uint8_t node) noexcept {
  return detail::with_node(nmt_error_base, node);
}
} // namespace cob_id

/// What an identifier means in the predefined connection set, and for which node.
struct cob_id_info {
  function fn;
  std::uint8_t node; ///< 0 for NMT, SYNC, TIME and unassigned identifiers
  friend constexpr bool operator==(const cob_id_info &, const cob_id_info &) = default;
};

/// Classify an 11-bit identifier. Errors: invalid_argument (id > 0x7FF).
[[nodiscard]] constexpr result<cob_id_info> classify(std::uint16_t id) noexcept {
  if (id > 0x7FFU) return errc::invalid_argument;
  if (id == cob_id::nmt) return cob_id_info{function::nmt, 0};
  if (id == cob_id::sync) return cob_id_info{function::sync, 0};
  if (id == cob_id::time) return cob_id_info{function::time, 0};
  const auto code = static_cast<unsigned>(id >> 7U);
  const auto node = static_cast<std::uint8_t>(id & 0x7FU);
  if (node == 0U) return cob_id_info{function::unassigned, 0};
  constexpr function by_code[16] = {
      function::unassigned, function::emcy,       function::unassigned, function::tpdo1,
      function::rpdo1,      function::tpdo2,      function::rpdo2,      function::tpdo3,
      function::rpdo3,      function::tpdo4,      function::rpdo4,      function::sdo_tx,
      function::sdo_rx,     function::unassigned, function::nmt_error,  function::unassigned};
  const function fn = by_code[code];
  if (fn == function::unassigned) return cob_id_info{function::unassigned, 0};
  return cob_id_info{fn, node};
}

[[nodiscard]] constexpr std::string_view to_string(function f) noexcept {
  switch (f) {
  case function::nmt: return "NMT";
  case function::sync: return "SYNC";
  case function::emcy: return "EMCY";
  case function::time: return "TIME";
  case function::tpdo1: return "TPDO1";
  case function::rpdo1: return "RPDO1";
  case function::tpdo2: return "TPDO2";
  case function::rpdo2: return "RPDO2";
  case function::tpdo3: return "TPDO3";
  case function::rpdo3: return "RPDO3";
  case function::tpdo4: return "TPDO4";
  case function::rpdo4: return "RPDO4";
  case function::sdo_tx: return "SDO tx";
  case function::sdo_rx: return "SDO rx";
  case function::nmt_error: return "NMT error control";
  case function::unassigned: return "unassigned";
  }
  return "?";
}

} // namespace fieldcodec::canopen
