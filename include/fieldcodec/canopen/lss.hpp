// fieldcodec — CiA 305 layer setting services (LSS): the messages on 7E5h (master → slaves) and
// 7E4h (slave → master), decoded into one value each. Eight data bytes; byte 0 is the command
// specifier, the rest depends on it (node-ID, bit timing table and index, switch delay, a
// 32-bit identity value, a fastscan probe, an error code).
//
//   auto m = lss::decode(frame);   // 7E5h [11 05 00 …] → configure_node_id, node_id 5
//   lss::to_string(m.value().cs)   // "configure node-ID"
//
//   lss::encode(lss::answer(lss::command::inquire_node_id, 5))   // 7E4h [5E 05 00 …]
//
// A codec only: the LSS slave (canopen/node/lss_slave.hpp) builds on it.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::canopen::lss {

inline constexpr std::uint16_t master_id = 0x7E5; ///< LSS master → slaves
inline constexpr std::uint16_t slave_id = 0x7E4;  ///< LSS slave → master

/// The node-ID of a node that has none (CiA 305 "not configured"): it stays in NMT
/// initialisation and waits for an LSS master to give it one.
inline constexpr std::uint8_t unconfigured = 0xFF;

/// The LSS address of a node: its identity object 1018h sub 1..4.
struct address {
  std::uint32_t vendor = 0;
  std::uint32_t product = 0;
  std::uint32_t revision = 0;
  std::uint32_t serial = 0;
  /// Part `i` (0 vendor-ID, 1 product code, 2 revision number, 3 serial number: the LSSSub of
  /// fastscan); 0 for any other i.
  [[nodiscard]] constexpr std::uint32_t part(std::uint8_t i) const noexcept {
    switch (i) {
    case 0: return vendor;
    case 1: return product;
    case 2: return revision;
    case 3: return serial;
    default: return 0;
    }
  }
  friend constexpr bool operator==(const address &, const address &) = default;
};

/// The error codes of the configure and store answers (byte 1); byte 2 holds the
/// manufacturer's code when byte 1 is `manufacturer`.
namespace error_code {
inline constexpr std::uint8_t none = 0;
/// configure node-ID: the node-ID is out of range; configure bit timing: the bit timing is not
/// supported; store configuration: storing is not supported.
inline constexpr std::uint8_t not_supported = 1;
inline constexpr std::uint8_t storage_access = 2; ///< store configuration: the media failed
inline constexpr std::uint8_t manufacturer = 0xFF;
} // namespace error_code

/// The largest bit_checked of a fastscan probe; 0x80 resets the scan.
inline constexpr std::uint8_t fastscan_last_bit = 31;
inline constexpr std::uint8_t fastscan_reset = 0x80;

/// The command specifiers of CiA 305 (the same value in a request and its answer, except the
/// switch-selective and identify answers).
enum class command : std::uint8_t {
  switch_global = 0x04,
  configure_node_id = 0x11,
  configure_bit_timing = 0x13,
  activate_bit_timing = 0x15,
  store_configuration = 0x17,
  switch_selective_vendor = 0x40,
  switch_selective_product = 0x41,
  switch_selective_revision = 0x42,
  switch_selective_serial = 0x43,
  switch_selective_response = 0x44,
  identify_vendor = 0x46,
  identify_product = 0x47,
  identify_revision_low = 0x48,
  identify_revision_high = 0x49,
  identify_serial_low = 0x4A,
  identify_serial_high = 0x4B,
  identify_non_configured = 0x4C,
  identify_slave = 0x4F,
  identify_non_configured_slave = 0x50,
  fastscan = 0x51,
  inquire_vendor = 0x5A,
  inquire_product = 0x5B,
  inquire_revision = 0x5C,
  inquire_serial = 0x5D,
  inquire_node_id = 0x5E,
};

/// One LSS message.
struct message {
  command cs = command::switch_global;
  bool from_master = true;
  /// switch_global: the mode (0 waiting, 1 configuration); configure_node_id (master): the
  /// node-ID; answers of configure/store: the error code (0 ok, 1 …, 0xFF manufacturer);
  /// inquire_node_id (slave): the node-ID; configure_bit_timing (master): the table selector.
  std::uint8_t b1 = 0;
  /// configure_bit_timing (master): the table index; answers of configure/store: the
  /// manufacturer's error code when b1 = 0xFF.
  std::uint8_t b2 = 0;
  /// switch_selective_*, identify_* (master), inquire_* (slave answers of 5Ah–5Dh): the 32-bit
  /// value; activate_bit_timing: the switch delay in ms; fastscan: the IDNumber.
  std::uint32_t value = 0;
  std::uint8_t bit_checked = 0; ///< fastscan: 0..31, or 0x80 (reset)
  std::uint8_t lss_sub = 0;     ///< fastscan: which identity field (0..3)
  std::uint8_t lss_next = 0;    ///< fastscan: the field to check next
};

/// Whether `cs` is a command of the master (7E5h) or an answer of a slave (7E4h).
[[nodiscard]] constexpr bool is_master_command(std::uint8_t cs) noexcept {
  switch (cs) {
  case 0x04:
  case 0x11:
  case 0x13:
  case 0x15:
  case 0x17:
  case 0x40:
  case 0x41:
  case 0x42:
  case 0x43:
  case 0x46:
  case 0x47:
  case 0x48:
  case 0x49:
  case 0x4A:
  case 0x4B:
  case 0x4C:
  case 0x51:
  case 0x5A:
  case 0x5B:
  case 0x5C:
  case 0x5D:
  case 0x5E: return true;
  default: return false;
  }
}
[[nodiscard]] constexpr bool is_slave_answer(std::uint8_t cs) noexcept {
  switch (cs) {
  case 0x11:
  case 0x13:
  case 0x17:
  case 0x44:
  case 0x4F:
  case 0x50:
  case 0x5A:
  case 0x5B:
  case 0x5C:
  case 0x5D:
  case 0x5E: return true;
  default: return false;
  }
}

/// An LSS frame. Errors: unexpected_frame (not 7E4h/7E5h, or a remote frame), bad_length (DLC
/// not 8), unknown_command (a command specifier CiA 305 does not give that direction).
[[nodiscard]] constexpr result<message> decode(const can_frame &f) noexcept {
  if (f.rtr || (f.id != master_id && f.id != slave_id)) return errc::unexpected_frame;
  if (f.dlc != 8U) return errc::bad_length;
  message m;
  m.from_master = f.id == master_id;
  const std::uint8_t cs = f.data[0];
  if (m.from_master ? !is_master_command(cs) : !is_slave_answer(cs)) return errc::unknown_command;
  m.cs = static_cast<command>(cs);
  m.b1 = f.data[1];
  m.b2 = f.data[2];
  const auto word = [&f](std::size_t at) {
    return static_cast<std::uint32_t>(
        load_unsigned(std::span<const std::uint8_t>(f.data).subspan(at, 4), 4, byte_order::little)
            .value_or(0));
  };
  switch (m.cs) {
  case command::activate_bit_timing:
    m.value = static_cast<std::uint32_t>(f.data[1] | (f.data[2] << 8U));
    break;
  case command::fastscan:
    m.value = word(1);
    m.bit_checked = f.data[5];
    m.lss_sub = f.data[6];
    m.lss_next = f.data[7];
    break;
  case command::inquire_vendor:
  case command::inquire_product:
  case command::inquire_revision:
  case command::inquire_serial:
    if (!m.from_master) m.value = word(1);
    break;
  default:
    if (cs >= 0x40U && cs <= 0x4BU && m.from_master) m.value = word(1);
    break;
  }
  return m;
}

/// The 8-byte frame of `m`: 7E5h for a master's command, 7E4h for a slave's answer, the fields
/// placed as decode() reads them (the bytes it does not read are 0). decode(encode(m)) == m for
/// every field that m's command uses.
[[nodiscard]] constexpr can_frame encode(const message &m) noexcept {
  can_frame f;
  f.id = m.from_master ? master_id : slave_id;
  f.dlc = 8;
  f.data[0] = static_cast<std::uint8_t>(m.cs);
  const auto word = [&f](std::size_t at, std::uint32_t v) {
    for (std::size_t i = 0; i < 4U; ++i) f.data[at + i] = static_cast<std::uint8_t>(v >> (8U * i));
  };
  const auto cs = static_cast<std::uint8_t>(m.cs);
  if (m.cs == command::activate_bit_timing) {
    f.data[1] = static_cast<std::uint8_t>(m.value);
    f.data[2] = static_cast<std::uint8_t>(m.value >> 8U);
  } else if (m.cs == command::fastscan) {
    word(1, m.value);
    f.data[5] = m.bit_checked;
    f.data[6] = m.lss_sub;
    f.data[7] = m.lss_next;
  } else if (cs >= 0x5AU && cs <= 0x5DU && !m.from_master) {
    word(1, m.value);
  } else if (cs >= 0x40U && cs <= 0x4BU && m.from_master) {
    word(1, m.value);
  } else {
    f.data[1] = m.b1;
    f.data[2] = m.b2;
  }
  return f;
}

/// A slave's answer with command specifier `cs` and byte 1 (an error code, a node-ID).
[[nodiscard]] constexpr message answer(command cs, std::uint8_t b1 = 0,
                                       std::uint8_t b2 = 0) noexcept {
  message m;
  m.cs = cs;
  m.from_master = false;
  m.b1 = b1;
  m.b2 = b2;
  return m;
}

[[nodiscard]] constexpr std::string_view to_string(command c) noexcept {
  switch (c) {
  case command::switch_global: return "switch state global";
  case command::configure_node_id: return "configure node-ID";
  case command::configure_bit_timing: return "configure bit timing";
  case command::activate_bit_timing: return "activate bit timing";
  case command::store_configuration: return "store configuration";
  case command::switch_selective_vendor: return "switch state selective: vendor-ID";
  case command::switch_selective_product: return "switch state selective: product code";
  case command::switch_selective_revision: return "switch state selective: revision number";
  case command::switch_selective_serial: return "switch state selective: serial number";
  case command::switch_selective_response: return "switch state selective: slave in configuration";
  case command::identify_vendor: return "identify remote slave: vendor-ID";
  case command::identify_product: return "identify remote slave: product code";
  case command::identify_revision_low: return "identify remote slave: revision number low";
  case command::identify_revision_high: return "identify remote slave: revision number high";
  case command::identify_serial_low: return "identify remote slave: serial number low";
  case command::identify_serial_high: return "identify remote slave: serial number high";
  case command::identify_non_configured: return "identify non-configured remote slave";
  case command::identify_slave: return "identify slave: present";
  case command::identify_non_configured_slave: return "identify non-configured slave: present";
  case command::fastscan: return "fastscan";
  case command::inquire_vendor: return "inquire vendor-ID";
  case command::inquire_product: return "inquire product code";
  case command::inquire_revision: return "inquire revision number";
  case command::inquire_serial: return "inquire serial number";
  case command::inquire_node_id: return "inquire node-ID";
  }
  return "?";
}

/// The bit rate of an index of CiA 305's standard bit timing table (table selector 0), in
/// kbit/s; 0 for a reserved index, 0xFFFF for automatic bit rate detection (9).
[[nodiscard]] constexpr std::uint16_t standard_bit_rate(std::uint8_t index) noexcept {
  constexpr std::uint16_t table[] = {1000, 800, 500, 250, 125, 0, 50, 20, 10, 0xFFFF};
  return index < 10U ? table[index] : std::uint16_t{0};
}

} // namespace fieldcodec::canopen::lss
