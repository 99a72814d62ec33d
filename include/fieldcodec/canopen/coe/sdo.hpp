// fieldcodec — SDO in a CoE mailbox (ETG.1000.6 5.6.2): expedited, normal and segmented
// transfer, complete access, abort.
//
// The SDO part of a CoE mailbox starts with the 8 bytes of a CiA 301 SDO message (command byte,
// index, sub-index, 4 data bytes), read and written by the one SDO codec (canopen/sdo.hpp).
// What CoE adds:
// * Normal transfer: an initiate download request / initiate upload response that is not
//   expedited carries the complete size (bytes 4..7, size indicator set) and then as much of
//   the value as the mailbox holds (mailbox size − 16 bytes). When that is the whole value the
//   transfer ends there; otherwise segments follow.
// * Segments (ETG.1000.6 5.6.2.3, 5.6.2.6) carry as many bytes as the mailbox holds (mailbox
//   size − 9): the command byte, then the data. A segment has at least 7 bytes after the
//   command byte; one with fewer data bytes is padded to 7 and says how many are unused in
//   bits 3..1 of the command byte (as on CAN); a longer one has those bits 0 and its length
//   from the mailbox header.
// * Complete access (bit 4 of the command byte of an initiate, reserved on CAN): the whole
//   object in one transfer, starting at sub-index 0 (sub-index 0 included) or 1 (excluded).
// * No block transfer (command specifiers 5 and 6 are unknown commands here).
// * The service: SDO request (2) for what the client sends and for an abort (from either side),
//   SDO response (3) for what the server answers.
// Every other message is exactly the 8 bytes (mailbox length 10).
#pragma once

#include <fieldcodec/canopen/coe/mailbox.hpp>
#include <fieldcodec/canopen/coe/service.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::canopen::coe {

/// Bytes of the SDO header (command, index, sub-index, 4 data bytes).
inline constexpr std::size_t sdo_header_size = 8;
/// The smallest mailbox an SDO needs: mailbox header, CoE header, SDO header.
inline constexpr std::size_t min_sdo_mailbox =
    header_size + coe_header_size + sdo_header_size; // 16
/// The fewest data bytes a segment carries (shorter data are padded to this).
inline constexpr std::size_t min_segment_data = 7;
/// Bit 4 of an initiate's command byte: complete access.
inline constexpr std::uint8_t complete_access_bit = 0x10;

/// Data bytes an initiate (normal transfer) holds in a mailbox of `mailbox_size` bytes
/// (mailbox_size − 16; 0 for a mailbox smaller than 16 bytes).
[[nodiscard]] constexpr std::size_t initiate_capacity(std::size_t mailbox_size) noexcept {
  return mailbox_size > min_sdo_mailbox ? mailbox_size - min_sdo_mailbox : 0U;
}
/// Data bytes a segment holds in a mailbox of `mailbox_size` bytes (mailbox_size − 9; 0 for a
/// mailbox smaller than 16 bytes).
[[nodiscard]] constexpr std::size_t segment_capacity(std::size_t mailbox_size) noexcept {
  return mailbox_size >= min_sdo_mailbox ? mailbox_size - (header_size + coe_header_size + 1U) : 0U;
}

/// An SDO message of a CoE mailbox. Which members mean something depends on `type`
/// (sdo::message_type; the block transfer types do not occur):
/// * initiate download request / initiate upload response: address, complete_access,
///   expedited; expedited: size_indicated, size (1..4 data bytes; 4 without size indication),
///   value (the data, little-endian); normal: size (the complete size), data (its first part or
///   all of it).
/// * initiate upload request / initiate download response: address, complete_access.
/// * download segment request / upload segment response: toggle, last, data.
/// * upload segment request / download segment response: toggle.
/// * abort: address, abort.
/// `data` points into the mailbox the message was decoded from (or, to encode, at the caller's
/// bytes).
struct sdo_message {
  sdo::message_type type = sdo::message_type::abort;
  bool complete_access = false;
  bool expedited = false;
  bool size_indicated = false; ///< expedited only: normal transfer always indicates the size
  bool toggle = false;
  bool last = false;
  od::address address{};
  std::uint32_t size = 0;
  std::uint32_t value = 0;
  sdo::abort_code abort = sdo::abort_code::none;
  std::span<const std::uint8_t> data{};
};

namespace detail {
[[nodiscard]] constexpr bool is_initiate(sdo::message_type t) noexcept {
  return t == sdo::message_type::initiate_download_request ||
         t == sdo::message_type::initiate_upload_request ||
         t == sdo::message_type::initiate_upload_response ||
         t == sdo::message_type::initiate_download_response;
}
[[nodiscard]] constexpr bool is_segment(sdo::message_type t) noexcept {
  return t == sdo::message_type::download_segment_request ||
         t == sdo::message_type::upload_segment_response;
}
/// Does `t` travel as an SDO response (service 3)? Everything else, aborts included, is a
/// request (service 2).
[[nodiscard]] constexpr bool is_response(sdo::message_type t) noexcept {
  return t == sdo::message_type::initiate_upload_response ||
         t == sdo::message_type::initiate_download_response ||
         t == sdo::message_type::upload_segment_response ||
         t == sdo::message_type::download_segment_response;
}
/// The 8 bytes of an SDO header (everything but a segment): canopen/sdo.hpp's encode of the
/// same message, with bit 4 set for complete access.
[[nodiscard]] constexpr result<sdo::payload> sdo_head(const sdo_message &m, bool normal) noexcept {
  sdo::message c;
  c.type = m.type;
  c.address = m.address;
  c.toggle = m.toggle;
  c.abort = m.abort;
  c.expedited = m.expedited;
  if (m.expedited) {
    c.size_indicated = m.size_indicated;
    c.size = m.size;
    c.value = m.value;
  } else if (normal) {
    c.size_indicated = true;
    c.size = m.size;
  }
  FIELDCODEC_TRY(sdo::payload p, sdo::encode(c));
  if (m.complete_access) p[0] = static_cast<std::uint8_t>(p[0] | complete_access_bit);
  return p;
}
} // namespace detail

/// Bytes of `m`'s SDO part (after the CoE header). Errors: invalid_argument (a block transfer
/// type).
[[nodiscard]] constexpr result<std::size_t> sdo_body_size(const sdo_message &m) noexcept {
  if (detail::is_segment(m.type)) {
    return 1U + (m.data.size() < min_segment_data ? min_segment_data : m.data.size());
  }
  const bool normal = (m.type == sdo::message_type::initiate_download_request ||
                       m.type == sdo::message_type::initiate_upload_response) &&
                      !m.expedited;
  switch (m.type) {
  case sdo::message_type::initiate_download_request:
  case sdo::message_type::initiate_upload_response:
  case sdo::message_type::initiate_upload_request:
  case sdo::message_type::initiate_download_response:
  case sdo::message_type::upload_segment_request:
  case sdo::message_type::download_segment_response:
  case sdo::message_type::abort: return sdo_header_size + (normal ? m.data.size() : 0U);
  default: return errc::invalid_argument;
  }
}

/// Write `m` as a CoE SDO mailbox into `out` (the mailbox buffer: its size is the mailbox
/// size). Returns the bytes written (6 + the length field). The command bytes are those of
/// canopen/sdo.hpp's encode, with bit 4 set for complete access.
/// Errors: too_long (the message does not fit `out`), invalid_argument (a block transfer type;
/// complete access on a message that is no initiate; data on a message without data), bad_length
/// (a normal initiate whose data exceed its complete size), out_of_range (complete access with a
/// sub-index other than 0 or 1), those of sdo::encode (an expedited value, …) and write_header.
[[nodiscard]] constexpr result<std::size_t> encode_sdo(std::span<std::uint8_t> out,
                                                       std::uint8_t counter,
                                                       const mailbox_options &o,
                                                       const sdo_message &m) noexcept {
  FIELDCODEC_TRY(const std::size_t body_size, sdo_body_size(m));
  const bool initiate = detail::is_initiate(m.type);
  const bool normal = (m.type == sdo::message_type::initiate_download_request ||
                       m.type == sdo::message_type::initiate_upload_response) &&
                      !m.expedited;
  if (m.complete_access && !initiate) return errc::invalid_argument;
  if (m.complete_access && m.address.sub > 1U) return errc::out_of_range;
  if (!detail::is_segment(m.type) && !normal && !m.data.empty()) return errc::invalid_argument;
  if (normal && m.data.size() > m.size) return errc::bad_length;
  sdo::payload head{};
  if (detail::is_segment(m.type)) {
    const std::size_t n = m.data.size(); // download and upload segments: command specifier 0
    head[0] = static_cast<std::uint8_t>((m.toggle ? 0x10U : 0U) |
                                        (n < min_segment_data ? (min_segment_data - n) << 1U : 0U) |
                                        (m.last ? 0x01U : 0U));
  } else {
    FIELDCODEC_TRY(head, detail::sdo_head(m, normal));
  }
  const coe_header ch{0,
                      detail::is_response(m.type) ? service::sdo_response : service::sdo_request};
  FIELDCODEC_TRY(const std::span<std::uint8_t> body,
                 write_coe_header(out, counter, o, ch, body_size));
  if (detail::is_segment(m.type)) {
    body[0] = head[0];
    for (std::size_t i = 0; i < m.data.size(); ++i) body[1U + i] = m.data[i];
    for (std::size_t i = 1U + m.data.size(); i < body.size(); ++i) body[i] = 0;
  } else {
    for (std::size_t i = 0; i < sdo_header_size; ++i) body[i] = head[i];
    for (std::size_t i = 0; i < m.data.size(); ++i) body[sdo_header_size + i] = m.data[i];
  }
  return header_size + coe_header_size + body_size;
}

/// Read the SDO part of a CoE mailbox (`body`: the bytes after the CoE header) sent in
/// direction `d`. Errors: truncated (fewer bytes than the message needs: 8, or a segment's 1 +
/// 7), too_long (a message of fixed size with more bytes), bad_length (a normal initiate without
/// its complete size or with more data than it; a segment longer than 8 bytes whose command
/// byte says bytes are unused), unknown_command (no such command in that direction; block
/// transfer), out_of_range (complete access with a sub-index other than 0 or 1).
[[nodiscard]] constexpr result<sdo_message> decode_sdo_body(std::span<const std::uint8_t> body,
                                                            sdo::direction d) noexcept {
  if (body.empty()) return errc::truncated;
  const unsigned b0 = body[0];
  const unsigned ccs = b0 >> 5U;
  if (ccs > 4U) return errc::unknown_command; // block transfer (5, 6) and 7
  sdo_message m;
  if (ccs == 0U) { // download segment request / upload segment response
    if (body.size() < 1U + min_segment_data) return errc::truncated;
    const unsigned unused = (b0 >> 1U) & 7U;
    std::size_t n = body.size() - 1U;
    if (n == min_segment_data) {
      n -= unused;
    } else if (unused != 0U) {
      return errc::bad_length;
    }
    m.type = d == sdo::direction::to_server ? sdo::message_type::download_segment_request
                                            : sdo::message_type::upload_segment_response;
    m.toggle = (b0 & 0x10U) != 0U;
    m.last = (b0 & 0x01U) != 0U;
    m.data = body.subspan(1, n);
    return m;
  }
  if (body.size() < sdo_header_size) return errc::truncated;
  sdo::payload p{};
  for (std::size_t i = 0; i < sdo_header_size; ++i) p[i] = body[i];
  FIELDCODEC_TRY(const sdo::message c, sdo::decode(p, d));
  m.type = c.type;
  m.address = c.address;
  m.toggle = c.toggle;
  m.abort = c.abort;
  m.expedited = c.expedited;
  const std::span<const std::uint8_t> rest = body.subspan(sdo_header_size);
  const bool normal_capable = c.type == sdo::message_type::initiate_download_request ||
                              c.type == sdo::message_type::initiate_upload_response;
  if (detail::is_initiate(c.type)) {
    m.complete_access = (b0 & complete_access_bit) != 0U;
    if (m.complete_access && m.address.sub > 1U) return errc::out_of_range;
  }
  if (normal_capable && !c.expedited) {
    if (!c.size_indicated) return errc::bad_length;
    if (rest.size() > c.size) return errc::bad_length;
    m.size = c.size;
    m.data = rest;
    return m;
  }
  if (!rest.empty()) return errc::too_long;
  if (c.expedited) {
    m.size_indicated = c.size_indicated;
    m.size = c.size;
    m.value = c.value;
  }
  return m;
}

/// A received CoE SDO mailbox: the headers and the SDO message.
struct sdo_mailbox {
  mailbox_header mailbox{};
  sdo_message sdo{};
};

/// Read a CoE mailbox holding an SDO message sent in direction `d`. To the server only SDO
/// requests (service 2) are SDO messages; to the client SDO responses (3), and an abort may
/// come as either. Errors: those of decode_coe, unexpected_frame (another service), those of
/// decode_sdo_body.
[[nodiscard]] constexpr result<sdo_mailbox> decode_sdo(std::span<const std::uint8_t> bytes,
                                                       sdo::direction d) noexcept {
  FIELDCODEC_TRY(const coe_message c, decode_coe(bytes));
  if (c.coe.svc != service::sdo_request && c.coe.svc != service::sdo_response) {
    return errc::unexpected_frame;
  }
  FIELDCODEC_TRY(const sdo_message m, decode_sdo_body(c.body, d));
  const bool abort = m.type == sdo::message_type::abort;
  const service want =
      d == sdo::direction::to_server ? service::sdo_request : service::sdo_response;
  if (c.coe.svc != want && !abort) return errc::unexpected_frame;
  return sdo_mailbox{c.mailbox, m};
}

} // namespace fieldcodec::canopen::coe
