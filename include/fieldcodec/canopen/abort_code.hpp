// fieldcodec — the CiA 301 abort codes (and the two CoE adds for complete access) (SDO abort
// transfer; also the answers of object stores, write hooks and the PDO engine): one table {code,
// errc, text}, used by the SDO client and server, the object store, the node and device folders.
#pragma once

#include <fieldcodec/core/result.hpp>

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string_view>

namespace fieldcodec::canopen::sdo {

/// An SDO abort code. The named values are those of CiA 301 and the two that CANopen over
/// EtherCAT adds for complete access (ETG.1000.6); any other 32-bit value a peer
/// sends is kept as it is (is_known() tells them apart). `none` (0) is never sent: it means
/// "no abort" where a function answers with an abort code (stores, write hooks).
enum class abort_code : std::uint32_t {
  none = 0,
  toggle_not_alternated = 0x05030000U,
  timeout = 0x05040000U,
  unknown_command = 0x05040001U,
  invalid_block_size = 0x05040002U,
  invalid_sequence_number = 0x05040003U,
  crc_error = 0x05040004U,
  out_of_memory = 0x05040005U,
  unsupported_access = 0x06010000U,
  read_write_only = 0x06010001U,
  write_read_only = 0x06010002U,
  sub0_must_be_zero = 0x06010003U,           ///< CoE complete access (ETG.1000.6)
  complete_access_unsupported = 0x06010004U, ///< CoE complete access (ETG.1000.6)
  no_object = 0x06020000U,
  not_mappable = 0x06040041U,
  pdo_too_long = 0x06040042U,
  parameter_incompatible = 0x06040043U,
  device_incompatible = 0x06040047U,
  hardware_error = 0x06060000U,
  length_mismatch = 0x06070010U,
  length_too_high = 0x06070012U,
  length_too_low = 0x06070013U,
  no_sub_index = 0x06090011U,
  invalid_value = 0x06090030U,
  value_too_high = 0x06090031U,
  value_too_low = 0x06090032U,
  max_less_than_min = 0x06090036U,
  no_sdo_connection = 0x060A0023U,
  general_error = 0x08000000U,
  cannot_store = 0x08000020U,
  cannot_store_local_control = 0x08000021U,
  cannot_store_device_state = 0x08000022U,
  no_dictionary = 0x08000023U,
  no_data = 0x08000024U,
};

/// One row of the abort table: the code, the fieldcodec error closest to it, and a short
/// description (fieldcodec's own wording of CiA 301).
struct abort_info {
  abort_code code;
  errc error;
  std::string_view text;
};

/// Every named abort code (CiA 301 and the two of CoE complete access), in numeric order.
inline constexpr abort_info abort_codes[] = {
    {abort_code::toggle_not_alternated, errc::bad_toggle, "toggle bit did not alternate"},
    {abort_code::timeout, errc::timeout, "SDO protocol timed out"},
    {abort_code::unknown_command, errc::unknown_command,
     "client/server command specifier invalid or unknown"},
    {abort_code::invalid_block_size, errc::out_of_range, "invalid block size (block mode)"},
    {abort_code::invalid_sequence_number, errc::unexpected_frame,
     "invalid sequence number (block mode)"},
    {abort_code::crc_error, errc::bad_checksum, "CRC error (block mode)"},
    {abort_code::out_of_memory, errc::buffer_too_small, "out of memory"},
    {abort_code::unsupported_access, errc::access_denied, "access to this object not supported"},
    {abort_code::read_write_only, errc::access_denied, "read of a write-only object"},
    {abort_code::write_read_only, errc::access_denied, "write to a read-only object"},
    {abort_code::sub0_must_be_zero, errc::bad_state,
     "sub-index cannot be written: sub-index 0 must be 0 for write access"},
    {abort_code::complete_access_unsupported, errc::access_denied, "complete access not supported"},
    {abort_code::no_object, errc::unknown_object, "object not in the object dictionary"},
    {abort_code::not_mappable, errc::invalid_argument, "object cannot be mapped into a PDO"},
    {abort_code::pdo_too_long, errc::too_long, "mapped objects exceed the PDO length"},
    {abort_code::parameter_incompatible, errc::invalid_argument,
     "general parameter incompatibility"},
    {abort_code::device_incompatible, errc::aborted,
     "general internal incompatibility in the device"},
    {abort_code::hardware_error, errc::aborted, "access failed: hardware error"},
    {abort_code::length_mismatch, errc::type_mismatch, "data type mismatch: length does not match"},
    {abort_code::length_too_high, errc::too_long, "data type mismatch: length too high"},
    {abort_code::length_too_low, errc::bad_length, "data type mismatch: length too low"},
    {abort_code::no_sub_index, errc::unknown_object, "sub-index does not exist"},
    {abort_code::invalid_value, errc::out_of_range, "invalid value (download only)"},
    {abort_code::value_too_high, errc::out_of_range, "value too high (download only)"},
    {abort_code::value_too_low, errc::out_of_range, "value too low (download only)"},
    {abort_code::max_less_than_min, errc::out_of_range, "maximum value below minimum value"},
    {abort_code::no_sdo_connection, errc::bad_state, "resource not available: SDO connection"},
    {abort_code::general_error, errc::aborted, "general error"},
    {abort_code::cannot_store, errc::aborted, "data cannot be transferred or stored"},
    {abort_code::cannot_store_local_control, errc::aborted,
     "data cannot be transferred or stored: local control"},
    {abort_code::cannot_store_device_state, errc::bad_state,
     "data cannot be transferred or stored: device state"},
    {abort_code::no_dictionary, errc::unknown_object,
     "no object dictionary present or generation failed"},
    {abort_code::no_data, errc::bad_state, "no data available"},
};

namespace detail {
/// Position of `code` in abort_codes (std::size(abort_codes) when absent). The lookups below
/// compare positions, not pointers with nullptr: g++ -fsanitize=undefined cannot evaluate the
/// null comparison of a pointer into a constexpr table in a constant expression.
[[nodiscard]] constexpr std::size_t abort_position(abort_code code) noexcept {
  std::size_t i = 0;
  while (i < std::size(abort_codes) && abort_codes[i].code != code) ++i;
  return i;
}
} // namespace detail

/// The row of `code`, or nullptr for a code CiA 301 does not define (and for `none`).
[[nodiscard]] constexpr const abort_info *find_abort(abort_code code) noexcept {
  const std::size_t i = detail::abort_position(code);
  return i < std::size(abort_codes) ? &abort_codes[i] : nullptr;
}
/// True for the codes of the CiA 301 table.
[[nodiscard]] constexpr bool is_known(abort_code code) noexcept {
  return detail::abort_position(code) < std::size(abort_codes);
}
/// The description of a code: "no abort" for none, empty for a code CiA 301 does not define.
[[nodiscard]] constexpr std::string_view to_string(abort_code code) noexcept {
  if (code == abort_code::none) return "no abort";
  const std::size_t i = detail::abort_position(code);
  return i < std::size(abort_codes) ? abort_codes[i].text : std::string_view{};
}
/// The fieldcodec error closest to a code; errc::aborted for a code CiA 301 does not define.
[[nodiscard]] constexpr errc to_errc(abort_code code) noexcept {
  const std::size_t i = detail::abort_position(code);
  return i < std::size(abort_codes) ? abort_codes[i].error : errc::aborted;
}

} // namespace fieldcodec::canopen::sdo
