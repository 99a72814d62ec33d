// fieldcodec — SDO frame codec (CiA 301): every command specifier, expedited and segmented
// transfer, abort codes. Block transfer is recognised (and answered with an abort by the
// server in sdo_server.hpp) but not performed.
//
// Byte 0 of an SDO frame is the command byte:
//   client -> server (COB-ID 0x600 + node), "ccs" in bits 7..5
//     0 download segment        000t nnnc   t toggle, n = 7 - data bytes, c = last
//     1 initiate download       001x nnes   e expedited, s size indicated, n = 4 - bytes (e=s=1)
//     2 initiate upload         0100 0000
//     3 upload segment request  011t 0000
//     4 abort                   1000 0000
//     5 block upload, 6 block download
//   server -> client (COB-ID 0x580 + node), "scs" in bits 7..5
//     0 upload segment          000t nnnc
//     1 download segment resp.  001t 0000
//     2 initiate upload resp.   010x nnes
//     3 initiate download resp. 0110 0000
//     4 abort                   1000 0000
//     5 block download resp., 6 block upload resp.
// Bytes 1..2 are the index (little-endian) and byte 3 the sub-index in initiate, abort and block
// initiate frames; bytes 4..7 carry expedited data, the size of a segmented transfer or the
// abort code. Every SDO frame has DLC 8.
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

namespace fieldcodec::canopen::sdo {

// ---------------------------------------------------------------------------------------------
// Abort codes

/// The SDO abort codes of CiA 301. `none` (0) is not sent; it marks success in server stores.
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

/// Every code of the table above except `none`, in numeric order.
inline constexpr abort_code all_abort_codes[] = {
    abort_code::toggle_not_alternated,
    abort_code::timeout,
    abort_code::unknown_command,
    abort_code::invalid_block_size,
    abort_code::invalid_sequence_number,
    abort_code::crc_error,
    abort_code::out_of_memory,
    abort_code::unsupported_access,
    abort_code::read_write_only,
    abort_code::write_read_only,
    abort_code::no_object,
    abort_code::not_mappable,
    abort_code::pdo_too_long,
    abort_code::parameter_incompatible,
    abort_code::device_incompatible,
    abort_code::hardware_error,
    abort_code::length_mismatch,
    abort_code::length_too_high,
    abort_code::length_too_low,
    abort_code::no_sub_index,
    abort_code::invalid_value,
    abort_code::value_too_high,
    abort_code::value_too_low,
    abort_code::max_less_than_min,
    abort_code::no_sdo_connection,
    abort_code::general_error,
    abort_code::cannot_store,
    abort_code::cannot_store_local_control,
    abort_code::cannot_store_device_state,
    abort_code::no_dictionary,
    abort_code::no_data,
};

/// A description of each abort code (empty for codes CiA 301 does not define).
[[nodiscard]] constexpr std::string_view to_string(abort_code c) noexcept {
  switch (c) {
  case abort_code::none: return "no abort";
  case abort_code::toggle_not_alternated: return "toggle bit did not alternate";
  case abort_code::timeout: return "SDO protocol timed out";
  case abort_code::unknown_command: return "client/server command specifier invalid or unknown";
  case abort_code::invalid_block_size: return "invalid block size (block mode)";
  case abort_code::invalid_sequence_number: return "invalid sequence number (block mode)";
  case abort_code::crc_error: return "CRC error (block mode)";
  case abort_code::out_of_memory: return "out of memory";
  case abort_code::unsupported_access: return "access to this object not supported";
  case abort_code::read_write_only: return "read of a write-only object";
  case abort_code::write_read_only: return "write to a read-only object";
  case abort_code::no_object: return "object not in the object dictionary";
  case abort_code::not_mappable: return "object cannot be mapped into a PDO";
  case abort_code::pdo_too_long: return "mapped objects exceed the PDO length";
  case abort_code::parameter_incompatible: return "general parameter incompatibility";
  case abort_code::device_incompatible: return "general internal incompatibility in the device";
  case abort_code::hardware_error: return "access failed: hardware error";
  case abort_code::length_mismatch: return "data type mismatch: length does not match";
  case abort_code::length_too_high: return "data type mismatch: length too high";
  case abort_code::length_too_low: return "data type mismatch: length too low";
  case abort_code::no_sub_index: return "sub-index does not exist";
  case abort_code::invalid_value: return "invalid value (download only)";
  case abort_code::value_too_high: return "value too high (download only)";
  case abort_code::value_too_low: return "value too low (download only)";
  case abort_code::max_less_than_min: return "maximum value below minimum value";
  case abort_code::no_sdo_connection: return "resource not available: SDO connection";
  case abort_code::general_error: return "general error";
  case abort_code::cannot_store: return "data cannot be transferred or stored";
  case abort_code::cannot_store_local_control:
    return "data cannot be transferred or stored: local control";
  case abort_code::cannot_store_device_state:
    return "data cannot be transferred or stored: device state";
  case abort_code::no_dictionary: return "no object dictionary present or generation failed";
  case abort_code::no_data: return "no data available";
  }
  return "";
}

/// True for the codes of the CiA 301 table.
[[nodiscard]] constexpr bool is_known(std::uint32_t code) noexcept {
  for (auto c : all_abort_codes) {
    if (static_cast<std::uint32_t>(c) == code) return true;
  }
  return false;
}

// ---------------------------------------------------------------------------------------------
// Messages

/// What an SDO frame is.
enum class kind : std::uint8_t {
  // client -> server
  initiate_download_request,
  download_segment_request,
  initiate_upload_request,
  upload_segment_request,
  block_upload_request,
  block_download_request,
  // server -> client
  initiate_download_response,
  download_segment_response,
  initiate_upload_response,
  upload_segment_response,
  block_download_response,
  block_upload_response,
  // either way
  abort,
};

/// A decoded SDO frame. Which members mean something depends on `k`:
/// * initiate download request / initiate upload response: index, sub, expedited,
///   size_indicated, size (expedited: the data bytes, 1..4 or 4 when not indicated; segmented:
///   the announced total when size_indicated), data/data_size (expedited data).
/// * download segment request / upload segment response: toggle, last, data/data_size (0..7).
/// * upload segment request / download segment response: toggle.
/// * initiate upload request / initiate download response: index, sub.
/// * abort: index, sub, code.
/// * block frames: command (byte 0), and index/sub as bytes 1..3 show them.
struct message {
  kind k = kind::abort;
  std::uint8_t command = 0; ///< byte 0 as received
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  bool expedited = false;
  bool size_indicated = false;
  bool toggle = false;
  bool last = false;
  std::uint32_t size = 0;
  std::uint32_t code = 0; ///< abort code (raw, may be outside the CiA table)
  std::array<std::uint8_t, 7> data{};
  std::uint8_t data_size = 0;

  [[nodiscard]] constexpr std::span<const std::uint8_t> bytes() const noexcept {
    return std::span<const std::uint8_t>(data).first(data_size);
  }
};

/// Which side sent a frame.
enum class direction : std::uint8_t { to_server, to_client };

namespace detail {
inline constexpr std::uint8_t toggle_bit = 0x10U;

[[nodiscard]] constexpr can_frame frame8(std::uint16_t id, std::uint8_t command,
                                         std::uint16_t index, std::uint8_t sub) noexcept {
  can_frame f;
  f.id = id;
  f.dlc = 8;
  f.data[0] = command;
  f.data[1] = static_cast<std::uint8_t>(index & 0xFFU);
  f.data[2] = static_cast<std::uint8_t>(index >> 8U);
  f.data[3] = sub;
  return f;
}
constexpr void put_u32(can_frame &f, std::uint32_t v) noexcept {
  for (std::size_t i = 0; i < 4U; ++i) f.data[4U + i] = static_cast<std::uint8_t>(v >> (8U * i));
}
[[nodiscard]] constexpr std::uint32_t get_u32(const can_frame &f) noexcept {
  return static_cast<std::uint32_t>(f.data[4]) | (static_cast<std::uint32_t>(f.data[5]) << 8U) |
         (static_cast<std::uint32_t>(f.data[6]) << 16U) |
         (static_cast<std::uint32_t>(f.data[7]) << 24U);
}
[[nodiscard]] constexpr result<std::uint16_t> id_for(direction d, std::uint8_t node) noexcept {
  return d == direction::to_server ? cob_id::sdo_rx(node) : cob_id::sdo_tx(node);
}
// initiate with expedited data: 0x20 (download) or 0x40 (upload response) base
[[nodiscard]] constexpr result<can_frame>
expedited(direction d, std::uint8_t base, std::uint8_t node, std::uint16_t index, std::uint8_t sub,
          std::span<const std::uint8_t> bytes, bool size_indicated) noexcept {
  auto id = id_for(d, node);
  if (!id) return id.error();
  if (bytes.empty()) return errc::bad_length;
  if (bytes.size() > 4U) return errc::too_long;
  if (!size_indicated && bytes.size() != 4U) return errc::bad_length;
  const auto n = static_cast<unsigned>(4U - bytes.size());
  const auto cmd = static_cast<std::uint8_t>(base | (size_indicated ? (n << 2U) | 0x03U : 0x02U));
  auto f = frame8(id.value(), cmd, index, sub);
  for (std::size_t i = 0; i < bytes.size(); ++i) f.data[4U + i] = bytes[i];
  return f;
}
[[nodiscard]] constexpr result<can_frame> segment(direction d, std::uint8_t node, bool toggle,
                                                  std::span<const std::uint8_t> bytes,
                                                  bool last) noexcept {
  auto id = id_for(d, node);
  if (!id) return id.error();
  if (bytes.size() > 7U) return errc::too_long;
  if (!last && bytes.size() != 7U) return errc::bad_length;
  const auto n = static_cast<unsigned>(7U - bytes.size());
  const auto cmd =
      static_cast<std::uint8_t>((toggle ? toggle_bit : 0U) | (n << 1U) | (last ? 1U : 0U));
  auto f = frame8(id.value(), cmd, 0, 0);
  f.data[1] = f.data[2] = f.data[3] = 0;
  for (std::size_t i = 0; i < bytes.size(); ++i) f.data[1U + i] = bytes[i];
  return f;
}
} // namespace detail

// ----- client -> server ------------------------------------------------------------------------

/// Expedited download of 1..4 bytes with size indication (0x2F, 0x2B, 0x27, 0x23).
/// Errors: invalid_argument (node), bad_length (no bytes), too_long (more than 4 bytes).
[[nodiscard]] constexpr result<can_frame>
expedited_download(std::uint8_t node, std::uint16_t index, std::uint8_t sub,
                   std::span<const std::uint8_t> bytes) noexcept {
  return detail::expedited(direction::to_server, 0x20U, node, index, sub, bytes, true);
}
/// Expedited download without size indication (0x22): exactly 4 bytes.
/// Errors: invalid_argument, bad_length (not 4 bytes).
[[nodiscard]] constexpr result<can_frame>
expedited_download_unsized(std::uint8_t node, std::uint16_t index, std::uint8_t sub,
                           std::span<const std::uint8_t> bytes) noexcept {
  return detail::expedited(direction::to_server, 0x20U, node, index, sub, bytes, false);
}
/// Initiate a segmented download of `size` bytes (0x21), or without size indication (0x20).
[[nodiscard]] constexpr result<can_frame> initiate_download(std::uint8_t node, std::uint16_t index,
                                                            std::uint8_t sub, std::uint32_t size,
                                                            bool size_indicated = true) noexcept {
  auto id = cob_id::sdo_rx(node);
  if (!id) return id.error();
  auto f = detail::frame8(id.value(), size_indicated ? 0x21U : 0x20U, index, sub);
  if (size_indicated) detail::put_u32(f, size);
  return f;
}
/// A download segment: 0..7 bytes (exactly 7 unless last), toggle as given.
/// Errors: invalid_argument, too_long (> 7 bytes), bad_length (fewer than 7 in a non-last
/// segment).
[[nodiscard]] constexpr result<can_frame> download_segment(std::uint8_t node, bool toggle,
                                                           std::span<const std::uint8_t> bytes,
                                                           bool last) noexcept {
  return detail::segment(direction::to_server, node, toggle, bytes, last);
}
/// Initiate upload (0x40).
[[nodiscard]] constexpr result<can_frame> initiate_upload(std::uint8_t node, std::uint16_t index,
                                                          std::uint8_t sub) noexcept {
  auto id = cob_id::sdo_rx(node);
  if (!id) return id.error();
  return detail::frame8(id.value(), 0x40U, index, sub);
}
/// Upload segment request (0x60 / 0x70).
[[nodiscard]] constexpr result<can_frame> upload_segment_request(std::uint8_t node,
                                                                 bool toggle) noexcept {
  auto id = cob_id::sdo_rx(node);
  if (!id) return id.error();
  return detail::frame8(id.value(), toggle ? 0x70U : 0x60U, 0, 0);
}

// ----- server -> client ------------------------------------------------------------------------

/// Initiate download response (0x60).
[[nodiscard]] constexpr result<can_frame> download_response(std::uint8_t node, std::uint16_t index,
                                                            std::uint8_t sub) noexcept {
  auto id = cob_id::sdo_tx(node);
  if (!id) return id.error();
  return detail::frame8(id.value(), 0x60U, index, sub);
}
/// Download segment response (0x20 / 0x30).
[[nodiscard]] constexpr result<can_frame> download_segment_response(std::uint8_t node,
                                                                    bool toggle) noexcept {
  auto id = cob_id::sdo_tx(node);
  if (!id) return id.error();
  return detail::frame8(id.value(), toggle ? 0x30U : 0x20U, 0, 0);
}
/// Expedited upload response with size indication (0x4F, 0x4B, 0x47, 0x43).
[[nodiscard]] constexpr result<can_frame>
expedited_upload_response(std::uint8_t node, std::uint16_t index, std::uint8_t sub,
                          std::span<const std::uint8_t> bytes) noexcept {
  return detail::expedited(direction::to_client, 0x40U, node, index, sub, bytes, true);
}
/// Expedited upload response without size indication (0x42): exactly 4 bytes.
[[nodiscard]] constexpr result<can_frame>
expedited_upload_response_unsized(std::uint8_t node, std::uint16_t index, std::uint8_t sub,
                                  std::span<const std::uint8_t> bytes) noexcept {
  return detail::expedited(direction::to_client, 0x40U, node, index, sub, bytes, false);
}
/// Initiate upload response of a segmented upload of `size` bytes (0x41), or without size
/// indication (0x40).
[[nodiscard]] constexpr result<can_frame> upload_response(std::uint8_t node, std::uint16_t index,
                                                          std::uint8_t sub, std::uint32_t size,
                                                          bool size_indicated = true) noexcept {
  auto id = cob_id::sdo_tx(node);
  if (!id) return id.error();
  auto f = detail::frame8(id.value(), size_indicated ? 0x41U : 0x40U, index, sub);
  if (size_indicated) detail::put_u32(f, size);
  return f;
}
/// An upload segment: 0..7 bytes (exactly 7 unless last).
[[nodiscard]] constexpr result<can_frame> upload_segment(std::uint8_t node, bool toggle,
                                                         std::span<const std::uint8_t> bytes,
                                                         bool last) noexcept {
  return detail::segment(direction::to_client, node, toggle, bytes, last);
}

// ----- both ------------------------------------------------------------------------------------

/// Abort transfer (0x80) sent by the client (`to_server`) or by the server (`to_client`).
[[nodiscard]] constexpr result<can_frame> abort(direction d, std::uint8_t node, std::uint16_t index,
                                                std::uint8_t sub, abort_code code) noexcept {
  auto id = detail::id_for(d, node);
  if (!id) return id.error();
  auto f = detail::frame8(id.value(), 0x80U, index, sub);
  detail::put_u32(f, static_cast<std::uint32_t>(code));
  return f;
}

// ----- decoding --------------------------------------------------------------------------------

namespace detail {
constexpr void read_mux(const can_frame &f, message &m) noexcept {
  m.index = static_cast<std::uint16_t>(f.data[1] | (f.data[2] << 8U));
  m.sub = f.data[3];
}
constexpr void read_initiate(const can_frame &f, message &m) noexcept {
  read_mux(f, m);
  m.expedited = (f.data[0] & 0x02U) != 0U;
  m.size_indicated = (f.data[0] & 0x01U) != 0U;
  if (m.expedited) {
    const std::uint8_t n =
        m.size_indicated ? static_cast<std::uint8_t>((f.data[0] >> 2U) & 3U) : 0U;
    m.data_size = static_cast<std::uint8_t>(4U - n);
    m.size = m.data_size;
    for (std::size_t i = 0; i < m.data_size; ++i) m.data[i] = f.data[4U + i];
  } else if (m.size_indicated) {
    m.size = get_u32(f);
  }
}
constexpr void read_segment(const can_frame &f, message &m) noexcept {
  m.toggle = (f.data[0] & toggle_bit) != 0U;
  m.last = (f.data[0] & 0x01U) != 0U;
  m.data_size = static_cast<std::uint8_t>(7U - ((f.data[0] >> 1U) & 7U));
  for (std::size_t i = 0; i < m.data_size; ++i) m.data[i] = f.data[1U + i];
}
} // namespace detail

/// Decode a frame sent to the server (COB-ID is not checked). Errors: unexpected_frame (remote
/// frame), bad_length (DLC not 8), unknown_command (ccs 7).
[[nodiscard]] constexpr result<message> decode_request(const can_frame &f) noexcept {
  FIELDCODEC_TRY_STATUS(expect_data(f, 8));
  message m;
  m.command = f.data[0];
  switch (f.data[0] >> 5U) {
  case 0:
    m.k = kind::download_segment_request;
    detail::read_segment(f, m);
    break;
  case 1:
    m.k = kind::initiate_download_request;
    detail::read_initiate(f, m);
    break;
  case 2:
    m.k = kind::initiate_upload_request;
    detail::read_mux(f, m);
    break;
  case 3:
    m.k = kind::upload_segment_request;
    m.toggle = (f.data[0] & detail::toggle_bit) != 0U;
    break;
  case 4:
    m.k = kind::abort;
    detail::read_mux(f, m);
    m.code = detail::get_u32(f);
    break;
  case 5:
    m.k = kind::block_upload_request;
    detail::read_mux(f, m);
    break;
  case 6:
    m.k = kind::block_download_request;
    detail::read_mux(f, m);
    break;
  default: return errc::unknown_command;
  }
  return m;
}

/// Decode a frame sent to the client (COB-ID is not checked). Errors: unexpected_frame (remote
/// frame), bad_length (DLC not 8), unknown_command (scs 7).
[[nodiscard]] constexpr result<message> decode_response(const can_frame &f) noexcept {
  FIELDCODEC_TRY_STATUS(expect_data(f, 8));
  message m;
  m.command = f.data[0];
  switch (f.data[0] >> 5U) {
  case 0:
    m.k = kind::upload_segment_response;
    detail::read_segment(f, m);
    break;
  case 1:
    m.k = kind::download_segment_response;
    m.toggle = (f.data[0] & detail::toggle_bit) != 0U;
    break;
  case 2:
    m.k = kind::initiate_upload_response;
    detail::read_initiate(f, m);
    break;
  case 3:
    m.k = kind::initiate_download_response;
    detail::read_mux(f, m);
    break;
  case 4:
    m.k = kind::abort;
    detail::read_mux(f, m);
    m.code = detail::get_u32(f);
    break;
  case 5:
    m.k = kind::block_download_response;
    detail::read_mux(f, m);
    break;
  case 6:
    m.k = kind::block_upload_response;
    detail::read_mux(f, m);
    break;
  default: return errc::unknown_command;
  }
  return m;
}

/// A decoded frame with its node and direction, told apart by the COB-ID.
struct addressed {
  std::uint8_t node;
  direction dir;
  message m;
};

/// Decode any SDO frame of the predefined connection set (0x581..0x5FF, 0x601..0x67F).
/// Errors: unexpected_frame (another COB-ID, remote frame), bad_length, unknown_command.
[[nodiscard]] constexpr result<addressed> decode(const can_frame &f) noexcept {
  if (f.id > cob_id::sdo_tx_base && f.id <= cob_id::sdo_tx_base + max_node_id) {
    auto m = decode_response(f);
    if (!m) return m.error();
    return addressed{static_cast<std::uint8_t>(f.id - cob_id::sdo_tx_base), direction::to_client,
                     m.value()};
  }
  if (f.id > cob_id::sdo_rx_base && f.id <= cob_id::sdo_rx_base + max_node_id) {
    auto m = decode_request(f);
    if (!m) return m.error();
    return addressed{static_cast<std::uint8_t>(f.id - cob_id::sdo_rx_base), direction::to_server,
                     m.value()};
  }
  return errc::unexpected_frame;
}

} // namespace fieldcodec::canopen::sdo
