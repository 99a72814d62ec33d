// fieldcodec — CANopen over EtherCAT (ETG.1000.6 5.6): the 2-byte CoE header that follows the
// mailbox header, the emergency, and the PDO services.
//
// A CoE mailbox (mailbox type 3) starts its data with the CoE header (ETG.1000.6 5.6.1,
// Table 29 "CoE elements"), a little-endian 16-bit word:
//   bits 0..8   number   the PDO number for the PDO services; 0 otherwise
//   bits 9..11  reserved
//   bits 12..15 service  1 emergency, 2 SDO request, 3 SDO response, 4 TxPDO, 5 RxPDO,
//                        6 TxPDO remote request, 7 RxPDO remote request, 8 SDO information
// then the service's bytes:
//   emergency (5.6.4)     error code (LE), error register, 5 manufacturer bytes: the 8 bytes of
//                         a CiA 301 EMCY message (canopen/emcy.hpp)
//   TxPDO / RxPDO (5.6.5) the PDO's data
//   remote requests       nothing (the number says which PDO)
//   SDO request/response  canopen/coe/sdo.hpp;  SDO information: canopen/coe/sdo_info.hpp
#pragma once

#include <fieldcodec/canopen/coe/mailbox.hpp>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::canopen::coe {

/// Bytes of the CoE header.
inline constexpr std::size_t coe_header_size = 2;
/// The largest number the CoE header holds (9 bits).
inline constexpr std::uint16_t max_number = 0x1FF;

/// The CoE services.
enum class service : std::uint8_t {
  emergency = 1,
  sdo_request = 2,
  sdo_response = 3,
  txpdo = 4,
  rxpdo = 5,
  txpdo_remote_request = 6,
  rxpdo_remote_request = 7,
  sdo_information = 8,
};

/// The CoE header.
struct coe_header {
  std::uint16_t number = 0; ///< 0..511: the PDO number of a PDO service, 0 otherwise
  service svc = service::sdo_request;
  friend constexpr bool operator==(const coe_header &, const coe_header &) = default;
};

/// The header's 2 bytes. Errors: out_of_range (number over 511), invalid_argument (a service
/// value not listed above).
[[nodiscard]] constexpr result<std::array<std::uint8_t, coe_header_size>>
encode_coe_header(const coe_header &h) noexcept {
  const auto s = static_cast<unsigned>(h.svc);
  if (s < 1U || s > 8U) return errc::invalid_argument;
  if (h.number > max_number) return errc::out_of_range;
  return to_bytes<std::uint16_t>(static_cast<std::uint16_t>(h.number | (s << 12U)),
                                 byte_order::little);
}

/// Read the CoE header from the first 2 bytes of `in` (the reserved bits 9..11 are ignored).
/// Errors: truncated, unknown_command (service 0 or 9..15).
[[nodiscard]] constexpr result<coe_header>
decode_coe_header(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < coe_header_size) return errc::truncated;
  const std::uint16_t w = from_bytes<std::uint16_t>({in[0], in[1]}, byte_order::little);
  const unsigned s = w >> 12U;
  if (s < 1U || s > 8U) return errc::unknown_command;
  return coe_header{static_cast<std::uint16_t>(w & max_number), static_cast<service>(s)};
}

/// A received CoE mailbox: its mailbox header, its CoE header and the service's bytes after it.
struct coe_message {
  mailbox_header mailbox{};
  coe_header coe{};
  std::span<const std::uint8_t> body{};
};

/// Read a CoE mailbox. Errors: those of decode (truncated, bad_length), unexpected_frame (not a
/// CoE mailbox), and of decode_coe_header (truncated: fewer than 2 data bytes, unknown_command).
[[nodiscard]] constexpr result<coe_message>
decode_coe(std::span<const std::uint8_t> bytes) noexcept {
  FIELDCODEC_TRY(const mailbox m, decode(bytes));
  if (m.header.type != static_cast<std::uint8_t>(mailbox_type::coe)) {
    return errc::unexpected_frame;
  }
  FIELDCODEC_TRY(const coe_header h, decode_coe_header(m.data));
  return coe_message{m.header, h, m.data.subspan(coe_header_size)};
}

/// Write the mailbox and CoE headers for `body_size` bytes of the service into `out` and return
/// the body for the caller to fill. Errors: those of write_header and encode_coe_header.
[[nodiscard]] constexpr result<std::span<std::uint8_t>>
write_coe_header(std::span<std::uint8_t> out, std::uint8_t counter, const mailbox_options &o,
                 const coe_header &h, std::size_t body_size) noexcept {
  FIELDCODEC_TRY(const auto ch, encode_coe_header(h));
  if (body_size > max_length - coe_header_size) return errc::too_long;
  FIELDCODEC_TRY(const std::span<std::uint8_t> data,
                 write_header(out, mailbox_type::coe, counter, o, coe_header_size + body_size));
  data[0] = ch[0];
  data[1] = ch[1];
  return data.subspan(coe_header_size);
}

// ---------------------------------------------------------------------------------------------
// Emergency (ETG.1000.6 5.6.4): the 8 bytes of a CiA 301 EMCY after the CoE header

/// Bytes of an emergency after the CoE header.
inline constexpr std::size_t emergency_size = 8;

/// Write a CoE emergency into `out`. Returns the bytes written (16).
/// Errors: those of write_header.
[[nodiscard]] constexpr result<std::size_t> encode_emergency(std::span<std::uint8_t> out,
                                                             std::uint8_t counter,
                                                             const mailbox_options &o,
                                                             const emcy::message &m) noexcept {
  FIELDCODEC_TRY(const std::span<std::uint8_t> body,
                 write_coe_header(out, counter, o, {0, service::emergency}, emergency_size));
  const auto p = emcy::encode_payload(m);
  for (std::size_t i = 0; i < emergency_size; ++i) body[i] = p[i];
  return header_size + coe_header_size + emergency_size;
}

/// The EMCY message of a CoE emergency. Errors: unexpected_frame (another service), truncated
/// (fewer than 8 bytes), too_long (more than 8).
[[nodiscard]] constexpr result<emcy::message> decode_emergency(const coe_message &m) noexcept {
  if (m.coe.svc != service::emergency) return errc::unexpected_frame;
  if (m.body.size() < emergency_size) return errc::truncated;
  if (m.body.size() > emergency_size) return errc::too_long;
  return emcy::decode_payload(m.body.first<emergency_size>());
}

// ---------------------------------------------------------------------------------------------
// PDOs over the mailbox (ETG.1000.6 5.6.5): TxPDO / RxPDO carry the PDO's data, their remote
// requests nothing; the CoE header's number says which PDO.

/// A PDO service of a mailbox.
struct pdo_message {
  service svc = service::txpdo;
  std::uint16_t number = 0;
  std::span<const std::uint8_t> data{}; ///< empty for a remote request
};

[[nodiscard]] constexpr bool is_pdo_service(service s) noexcept {
  return s == service::txpdo || s == service::rxpdo || s == service::txpdo_remote_request ||
         s == service::rxpdo_remote_request;
}
[[nodiscard]] constexpr bool is_remote_request(service s) noexcept {
  return s == service::txpdo_remote_request || s == service::rxpdo_remote_request;
}

/// Write a PDO service into `out`: TxPDO / RxPDO with `data`, a remote request with none.
/// Returns the bytes written. Errors: invalid_argument (not a PDO service, or data for a
/// remote request), out_of_range (number over 511), those of write_header.
[[nodiscard]] constexpr result<std::size_t> encode_pdo(std::span<std::uint8_t> out,
                                                       std::uint8_t counter,
                                                       const mailbox_options &o,
                                                       const pdo_message &m) noexcept {
  if (!is_pdo_service(m.svc)) return errc::invalid_argument;
  if (is_remote_request(m.svc) && !m.data.empty()) return errc::invalid_argument;
  FIELDCODEC_TRY(const std::span<std::uint8_t> body,
                 write_coe_header(out, counter, o, {m.number, m.svc}, m.data.size()));
  for (std::size_t i = 0; i < m.data.size(); ++i) body[i] = m.data[i];
  return header_size + coe_header_size + m.data.size();
}

/// The PDO service of a CoE mailbox. Errors: unexpected_frame (another service), too_long (a
/// remote request with data).
[[nodiscard]] constexpr result<pdo_message> decode_pdo(const coe_message &m) noexcept {
  if (!is_pdo_service(m.coe.svc)) return errc::unexpected_frame;
  if (is_remote_request(m.coe.svc) && !m.body.empty()) return errc::too_long;
  return pdo_message{m.coe.svc, m.coe.number, m.body};
}

} // namespace fieldcodec::canopen::coe
