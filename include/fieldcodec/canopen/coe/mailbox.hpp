// fieldcodec — the EtherCAT mailbox (ETG.1000.6 5.5, ETG.1000.4): the 6-byte header every
// mailbox service starts with, the mailbox counter, and the mailbox error reply.
//
// A mailbox is what an EtherCAT master writes into a slave's receive SyncManager (SM0) or reads
// from its send SyncManager (SM1): a 6-byte header, then `length` bytes of the service (CoE,
// EoE, FoE, …). The SyncManager area has a fixed size (the mailbox size); the bytes after
// 6 + length are padding.
//
//   bytes 0..1  length   bytes of the service data after the header (little-endian)
//   bytes 2..3  address  station address of the source (master → slave) or destination
//   byte  4     bits 0..5 channel (0 by default), bits 6..7 priority (0 lowest … 3 highest)
//   byte  5     bits 0..3 type (0 error, 1 AoE, 2 EoE, 3 CoE, 4 FoE, 5 SoE, 15 vendor),
//               bits 4..6 counter (1..7; 0: not used), bit 7 reserved
//
// The codec is transport-agnostic: it reads and writes spans of bytes; how they reach the
// SyncManager (an EtherCAT master library, an ESC's process data interface) is the caller's.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::canopen::coe {

/// Bytes of the mailbox header.
inline constexpr std::size_t header_size = 6;
/// The largest `length` a header can say (a 16-bit field).
inline constexpr std::size_t max_length = 0xFFFF;

/// What a mailbox carries (byte 5, bits 0..3).
enum class mailbox_type : std::uint8_t {
  error = 0,   ///< mailbox error reply (below)
  aoe = 1,     ///< ADS over EtherCAT
  eoe = 2,     ///< Ethernet over EtherCAT
  coe = 3,     ///< CANopen over EtherCAT
  foe = 4,     ///< File access over EtherCAT
  soe = 5,     ///< Servo drive profile over EtherCAT
  vendor = 15, ///< vendor specific
};

/// The mailbox header. `type` is the 4-bit value as sent (mailbox_type names the known ones).
struct mailbox_header {
  std::uint16_t length = 0;  ///< bytes after the header
  std::uint16_t address = 0; ///< station address
  std::uint8_t channel = 0;  ///< 0..63
  std::uint8_t priority = 0; ///< 0..3
  std::uint8_t type = 0;     ///< 0..15
  std::uint8_t counter = 0;  ///< 0..7 (0: the counter is not used)
  friend constexpr bool operator==(const mailbox_header &, const mailbox_header &) = default;
};

/// The header's 6 bytes. Errors: out_of_range (channel over 63, priority over 3, type over 15,
/// counter over 7).
[[nodiscard]] constexpr result<std::array<std::uint8_t, header_size>>
encode_header(const mailbox_header &h) noexcept {
  if (h.channel > 63U || h.priority > 3U || h.type > 15U || h.counter > 7U) {
    return errc::out_of_range;
  }
  const auto len = to_bytes<std::uint16_t>(h.length, byte_order::little);
  const auto adr = to_bytes<std::uint16_t>(h.address, byte_order::little);
  return std::array<std::uint8_t, header_size>{
      len[0],
      len[1],
      adr[0],
      adr[1],
      static_cast<std::uint8_t>(h.channel | (h.priority << 6U)),
      static_cast<std::uint8_t>(h.type | (h.counter << 4U))};
}

/// Read a header from the first 6 bytes of `in` (the reserved bit 7 of byte 5 is ignored).
/// Errors: truncated (fewer than 6 bytes).
[[nodiscard]] constexpr result<mailbox_header>
decode_header(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < header_size) return errc::truncated;
  mailbox_header h;
  h.length = from_bytes<std::uint16_t>({in[0], in[1]}, byte_order::little);
  h.address = from_bytes<std::uint16_t>({in[2], in[3]}, byte_order::little);
  h.channel = static_cast<std::uint8_t>(in[4] & 0x3FU);
  h.priority = static_cast<std::uint8_t>(in[4] >> 6U);
  h.type = static_cast<std::uint8_t>(in[5] & 0x0FU);
  h.counter = static_cast<std::uint8_t>((in[5] >> 4U) & 0x07U);
  return h;
}

/// A received mailbox: its header and the `length` bytes of service data after it.
struct mailbox {
  mailbox_header header{};
  std::span<const std::uint8_t> data{};
};

/// Read a mailbox from `bytes` (what was read from the SyncManager: the whole area or at least
/// 6 + length bytes; bytes past 6 + length are padding and ignored).
/// Errors: truncated (fewer than 6 bytes), bad_length (the length field says more bytes than
/// `bytes` holds after the header).
[[nodiscard]] constexpr result<mailbox> decode(std::span<const std::uint8_t> bytes) noexcept {
  FIELDCODEC_TRY(const mailbox_header h, decode_header(bytes));
  if (h.length > bytes.size() - header_size) return errc::bad_length;
  return mailbox{h, bytes.subspan(header_size, h.length)};
}

/// The counter after `c`: 1, 2, …, 7, 1, … (0, "not used", is followed by 1 as well).
[[nodiscard]] constexpr std::uint8_t next_counter(std::uint8_t c) noexcept {
  return c >= 7U ? std::uint8_t{1} : static_cast<std::uint8_t>(c + 1U);
}

/// Is a received mailbox with counter `c` a repeat of the one received before, whose counter
/// was `previous`? A sender gives every new mailbox the next counter and repeats a mailbox with
/// its counter unchanged, so the same counter twice in a row is a repeat; 0 means the sender
/// does not count, and nothing is then a repeat.
[[nodiscard]] constexpr bool is_repeat(std::uint8_t c, std::uint8_t previous) noexcept {
  return c != 0U && c == previous;
}

/// How a sender addresses its mailboxes (the header fields besides length, type and counter).
struct mailbox_options {
  std::uint16_t address = 0; ///< master → slave: the source's station address (0: the master)
  std::uint8_t channel = 0;  ///< 0..63
  std::uint8_t priority = 0; ///< 0..3
};

/// Write a header for `body_size` bytes of `type` at the front of `out` (the mailbox buffer,
/// whose size is the mailbox size) and return the `body_size` bytes after it, for the caller to
/// fill. Errors: too_long (6 + body_size does not fit `out`, or body_size over 65535),
/// out_of_range (a header field, see encode_header).
[[nodiscard]] constexpr result<std::span<std::uint8_t>>
write_header(std::span<std::uint8_t> out, mailbox_type type, std::uint8_t counter,
             const mailbox_options &o, std::size_t body_size) noexcept {
  if (body_size > max_length || out.size() < header_size || body_size > out.size() - header_size) {
    return errc::too_long;
  }
  FIELDCODEC_TRY(const auto h,
                 encode_header({static_cast<std::uint16_t>(body_size), o.address, o.channel,
                                o.priority, static_cast<std::uint8_t>(type), counter}));
  for (std::size_t i = 0; i < header_size; ++i) out[i] = h[i];
  return out.subspan(header_size, body_size);
}

// ---------------------------------------------------------------------------------------------
// Mailbox error reply (type 0): a mailbox the receiver could not take is answered with
//   bytes 0..1  type    0x0001 (mailbox command)
//   bytes 2..3  detail  the reason below

/// Why a mailbox was refused (the detail of a mailbox error reply). Other values a peer sends
/// are kept as they are.
enum class mailbox_error : std::uint16_t {
  syntax = 0x0001,                ///< the header does not follow the syntax
  unsupported_protocol = 0x0002,  ///< the mailbox type is not supported
  invalid_channel = 0x0003,       ///< the channel field is not 0
  service_not_supported = 0x0004, ///< the service of the protocol is not supported
  invalid_header = 0x0005,        ///< the protocol header is wrong
  size_too_short = 0x0006,        ///< the data are shorter than the service needs
  no_more_memory = 0x0007,        ///< the service cannot be taken for lack of memory
  invalid_size = 0x0008,          ///< the data length disagrees with the service
};

/// A short description of a mailbox error; empty for a value not named above.
[[nodiscard]] constexpr std::string_view to_string(mailbox_error e) noexcept {
  switch (e) {
  case mailbox_error::syntax: return "mailbox header syntax error";
  case mailbox_error::unsupported_protocol: return "mailbox protocol not supported";
  case mailbox_error::invalid_channel: return "mailbox channel not valid";
  case mailbox_error::service_not_supported: return "mailbox service not supported";
  case mailbox_error::invalid_header: return "mailbox protocol header not valid";
  case mailbox_error::size_too_short: return "mailbox data too short";
  case mailbox_error::no_more_memory: return "mailbox service: no memory";
  case mailbox_error::invalid_size: return "mailbox data length not valid";
  }
  return {};
}

/// The fieldcodec error closest to a mailbox error (unknown_command for an unnamed value).
[[nodiscard]] constexpr errc to_errc(mailbox_error e) noexcept {
  switch (e) {
  case mailbox_error::syntax:
  case mailbox_error::invalid_header: return errc::bad_syntax;
  case mailbox_error::unsupported_protocol:
  case mailbox_error::service_not_supported: return errc::unknown_command;
  case mailbox_error::invalid_channel: return errc::invalid_argument;
  case mailbox_error::size_too_short: return errc::truncated;
  case mailbox_error::no_more_memory: return errc::buffer_too_small;
  case mailbox_error::invalid_size: return errc::bad_length;
  }
  return errc::unknown_command;
}

/// Bytes of a mailbox error reply's data.
inline constexpr std::size_t error_reply_size = 4;

/// Write a mailbox error reply into `out`. Returns the bytes written (10).
/// Errors: those of write_header.
[[nodiscard]] constexpr result<std::size_t> encode_error_reply(std::span<std::uint8_t> out,
                                                               std::uint8_t counter,
                                                               const mailbox_options &o,
                                                               mailbox_error e) noexcept {
  FIELDCODEC_TRY(const std::span<std::uint8_t> body,
                 write_header(out, mailbox_type::error, counter, o, error_reply_size));
  body[0] = 0x01;
  body[1] = 0x00;
  const auto d = to_bytes<std::uint16_t>(static_cast<std::uint16_t>(e), byte_order::little);
  body[2] = d[0];
  body[3] = d[1];
  return header_size + error_reply_size;
}

/// The reason of a mailbox error reply. Errors: unexpected_frame (not a type 0 mailbox),
/// truncated (fewer than 4 bytes), too_long (more than 4), unknown_command (type field not 1).
[[nodiscard]] constexpr result<mailbox_error> decode_error_reply(const mailbox &m) noexcept {
  if (m.header.type != static_cast<std::uint8_t>(mailbox_type::error)) {
    return errc::unexpected_frame;
  }
  if (m.data.size() < error_reply_size) return errc::truncated;
  if (m.data.size() > error_reply_size) return errc::too_long;
  if (m.data[0] != 0x01U || m.data[1] != 0x00U) return errc::unknown_command;
  return static_cast<mailbox_error>(
      from_bytes<std::uint16_t>({m.data[2], m.data[3]}, byte_order::little));
}

} // namespace fieldcodec::canopen::coe
