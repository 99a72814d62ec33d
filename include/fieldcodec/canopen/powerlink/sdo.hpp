// fieldcodec — POWERLINK SDO over ASnd (EPSG DS 301): the ASnd frame that carries it, the SDO
// sequence layer header and the SDO command layer. All fields little-endian.
//
// A POWERLINK SDO frame, after the 14-byte Ethernet header (EtherType 0x88AB):
//   byte 0      message type: 0x06 (ASnd)
//   byte 1      destination node-ID        byte 2  source node-ID
//   byte 3      ASnd service ID: 0x05 (SDO)
//   sequence layer, 4 bytes:
//     byte 4    bits 7..2 receive sequence number (the last frame received in order),
//               bits 1..0 receive connection (0 none, 1 initialization, 2 valid, 3 error
//               response: retransmission request)
//     byte 5    bits 7..2 send sequence number (+1 with every new frame, modulo 64),
//               bits 1..0 send connection (0 none, 1 initialization, 2 valid, 3 valid with
//               acknowledge request)
//     bytes 6..7 reserved
//   command layer, 8 bytes and the segment:
//     byte 0    reserved               byte 1  transaction ID (the client's, per command)
//     byte 2    bit 7 response, bit 6 abort, bits 5..4 segmentation (0 expedited, 1
//               initiate, 2 segment, 3 complete)
//     byte 3    command ID (table `command_id`)
//     bytes 4..5 segment size: the bytes of the segment that follows (an initiate's data size
//               field included)
//     bytes 6..7 reserved
//     segment   initiate: first the data size (4 bytes: the whole transfer's bytes after the
//               fixed header, these 4 included), then the data; WriteByIndex / ReadByIndex
//               requests begin with index (2 bytes), sub-index, a reserved byte; an abort
//               carries the abort code (4 bytes, the SDO abort codes of canopen/abort_code.hpp)
// An ASnd frame has no length of its own (Ethernet pads it to 46 bytes at least, and carries
// 1500 at most): a frame of the sequence layer alone (connection set-up, acknowledgements)
// reads as a NIL command (command ID 0, segment size 0) when padded with zeros, or as no
// command when the bytes end after the sequence layer.
//
// What is here: the codecs, pure and constexpr, and the sequence number rule a receiver applies.
// What is not: the sequence layer's connection machine (set-up, acknowledgement, retransmission
// from a history of sent frames) and the command layer's transfers over it — see
// docs/canopen.md, "POWERLINK SDO over ASnd".
#pragma once

#include <fieldcodec/canopen/abort_code.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fieldcodec::canopen::powerlink {

/// The EtherType of POWERLINK frames.
inline constexpr std::uint16_t ethertype = 0x88AB;
/// Bytes of the Ethernet header before the POWERLINK frame (two MAC addresses, EtherType).
inline constexpr std::size_t ethernet_header_size = 14;
/// The longest POWERLINK frame (the Ethernet payload; an asynchronous MTU of 1500 bytes).
inline constexpr std::size_t max_frame_size = 1500;
/// Message type of an asynchronous send frame.
inline constexpr std::uint8_t message_type_asnd = 0x06;
/// ASnd service ID of SDO.
inline constexpr std::uint8_t service_sdo = 0x05;
/// Bytes of the ASnd header (message type, destination, source, service ID).
inline constexpr std::size_t asnd_header_size = 4;
/// Bytes of the sequence layer header.
inline constexpr std::size_t sequence_header_size = 4;
/// Bytes of the command layer's fixed header, and of an initiate's data size field.
inline constexpr std::size_t command_header_size = 8;
inline constexpr std::size_t data_size_field = 4;
/// Bytes of the index header of WriteByIndex / ReadByIndex requests.
inline constexpr std::size_t index_header_size = 4;
/// The longest segment one ASnd frame carries (its data size field included).
inline constexpr std::size_t max_segment_size =
    max_frame_size - asnd_header_size - sequence_header_size - command_header_size;
/// The largest sequence number (6 bits).
inline constexpr std::uint8_t max_sequence = 63;

// ---------------------------------------------------------------------------------------------
// Sequence layer

enum class receive_con : std::uint8_t {
  no_connection = 0,
  initialization = 1,
  connection_valid = 2,
  error_response = 3, ///< retransmission request
};
enum class send_con : std::uint8_t {
  no_connection = 0,
  initialization = 1,
  connection_valid = 2,
  acknowledge_request = 3, ///< connection valid, with acknowledge request
};

struct sequence_header {
  std::uint8_t receive_sequence = 0; ///< 0..63
  receive_con rcon = receive_con::no_connection;
  std::uint8_t send_sequence = 0; ///< 0..63
  send_con scon = send_con::no_connection;
  friend constexpr bool operator==(const sequence_header &, const sequence_header &) = default;
};

/// The sequence number after `n` (modulo 64).
[[nodiscard]] constexpr std::uint8_t next_sequence(std::uint8_t n) noexcept {
  return static_cast<std::uint8_t>((n + 1U) & max_sequence);
}

/// What a receiver makes of a frame's send sequence number, given the last one it received in
/// order: true for the next frame (take it, acknowledge it), false for the same one again (a
/// repeat: already taken, drop it). Errors: unexpected_frame (any other number: frames were
/// lost; answer with receive_con::error_response so that the sender repeats them), out_of_range
/// (a number over 63).
[[nodiscard]] constexpr result<bool> is_next_frame(std::uint8_t last_received,
                                                   std::uint8_t received) noexcept {
  if (last_received > max_sequence || received > max_sequence) return errc::out_of_range;
  if (received == next_sequence(last_received)) return true;
  if (received == last_received) return false;
  return errc::unexpected_frame;
}

/// The 4 bytes of a sequence layer header. Errors: out_of_range (a sequence number over 63, a
/// connection value over 3).
[[nodiscard]] constexpr result<std::array<std::uint8_t, sequence_header_size>>
encode_sequence(const sequence_header &h) noexcept {
  if (h.receive_sequence > max_sequence || h.send_sequence > max_sequence ||
      static_cast<unsigned>(h.rcon) > 3U || static_cast<unsigned>(h.scon) > 3U) {
    return errc::out_of_range;
  }
  return std::array<std::uint8_t, sequence_header_size>{
      static_cast<std::uint8_t>((unsigned{h.receive_sequence} << 2U) |
                                static_cast<unsigned>(h.rcon)),
      static_cast<std::uint8_t>((unsigned{h.send_sequence} << 2U) | static_cast<unsigned>(h.scon)),
      0, 0};
}
/// Read a sequence layer header (the reserved bytes are ignored). Errors: truncated.
[[nodiscard]] constexpr result<sequence_header>
decode_sequence(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < sequence_header_size) return errc::truncated;
  return sequence_header{static_cast<std::uint8_t>(in[0] >> 2U),
                         static_cast<receive_con>(in[0] & 3U),
                         static_cast<std::uint8_t>(in[1] >> 2U), static_cast<send_con>(in[1] & 3U)};
}

// ---------------------------------------------------------------------------------------------
// Command layer

enum class segmentation : std::uint8_t { expedited = 0, initiate = 1, segment = 2, complete = 3 };

/// The command IDs of the SDO protocol. A command's `id` keeps any value as sent: 0x80..0xFF
/// are manufacturer-specific, others are reserved (is_defined_command).
namespace command_id {
inline constexpr std::uint8_t nil = 0x00;
inline constexpr std::uint8_t write_by_index = 0x01;
inline constexpr std::uint8_t read_by_index = 0x02;
inline constexpr std::uint8_t write_all_by_index = 0x03;
inline constexpr std::uint8_t read_all_by_index = 0x04;
inline constexpr std::uint8_t write_by_name = 0x05;
inline constexpr std::uint8_t read_by_name = 0x06;
inline constexpr std::uint8_t file_write = 0x20;
inline constexpr std::uint8_t file_read = 0x21;
inline constexpr std::uint8_t write_multiple_by_index = 0x31;
inline constexpr std::uint8_t read_multiple_by_index = 0x32;
inline constexpr std::uint8_t max_segment_size = 0x70;
} // namespace command_id

/// Whether `id` is a command ID of EPSG DS 301 (the table above) or manufacturer-specific
/// (0x80..0xFF); a reserved value is neither.
[[nodiscard]] constexpr bool is_defined_command(std::uint8_t id) noexcept {
  return id <= command_id::read_by_name || id == command_id::file_write ||
         id == command_id::file_read || id == command_id::write_multiple_by_index ||
         id == command_id::read_multiple_by_index || id == command_id::max_segment_size ||
         id >= 0x80U;
}

/// A command layer frame. `segment` is the segment after the fixed header without the data
/// size field of an initiate (`data_size`), pointing into the bytes decoded (or, to encode, at
/// the caller's bytes).
struct command {
  std::uint8_t transaction_id = 0;
  bool response = false;
  bool abort = false;
  segmentation seg = segmentation::expedited;
  std::uint8_t id = command_id::nil;
  std::optional<std::uint32_t> data_size{}; ///< initiate only, as on the wire
  std::span<const std::uint8_t> segment{};
};

/// The data size field of an initiate for a transfer of `bytes` after the fixed header (the
/// index header of a WriteByIndex request included, the data size field not): `bytes` + 4.
/// Errors: too_long (more than the 32-bit field holds).
[[nodiscard]] constexpr result<std::uint32_t> data_size_for(std::size_t bytes) noexcept {
  if (bytes > 0xFFFFFFFFU - data_size_field) return errc::too_long;
  return static_cast<std::uint32_t>(bytes + data_size_field);
}

/// The bytes a transfer carries after the fixed header and the data size field, this frame's and
/// those of the segments to come: data size − 4 for an initiate, the segment for any other
/// frame. Errors: bad_length (an initiate's data size smaller than its own 4 bytes and this
/// frame's segment).
[[nodiscard]] constexpr result<std::size_t> transfer_size(const command &c) noexcept {
  if (c.seg != segmentation::initiate || !c.data_size) return c.segment.size();
  if (*c.data_size < data_size_field || *c.data_size - data_size_field < c.segment.size()) {
    return errc::bad_length;
  }
  return static_cast<std::size_t>(*c.data_size - data_size_field);
}

/// Read a command layer frame from `in` (bytes past the segment are padding and ignored).
/// Errors: truncated (fewer than 8 bytes; fewer than the segment size says; an initiate whose
/// segment cannot hold its data size field).
[[nodiscard]] constexpr result<command> decode_command(std::span<const std::uint8_t> in) noexcept {
  byte_reader r(in);
  command c;
  FIELDCODEC_TRY_STATUS(r.skip(1));
  FIELDCODEC_TRY(c.transaction_id, r.read_u8());
  FIELDCODEC_TRY(const std::uint8_t flags, r.read_u8());
  FIELDCODEC_TRY(c.id, r.read_u8());
  FIELDCODEC_TRY(const std::uint16_t size, r.read<std::uint16_t>(byte_order::little));
  FIELDCODEC_TRY_STATUS(r.skip(2));
  c.response = (flags & 0x80U) != 0U;
  c.abort = (flags & 0x40U) != 0U;
  c.seg = static_cast<segmentation>((flags >> 4U) & 3U);
  FIELDCODEC_TRY(const auto seg, r.read_bytes(size));
  byte_reader s(seg);
  if (c.seg == segmentation::initiate) {
    FIELDCODEC_TRY(c.data_size, s.read<std::uint32_t>(byte_order::little));
  }
  c.segment = s.rest();
  return c;
}

/// Bytes encode_command writes for `c`.
[[nodiscard]] constexpr std::size_t command_size(const command &c) noexcept {
  return command_header_size + (c.seg == segmentation::initiate ? data_size_field : 0U) +
         c.segment.size();
}

/// Write `c` into `out`; returns the bytes written. Errors: invalid_argument (a data size on a
/// frame that is no initiate, or none on an initiate), too_long (a segment over 65535 bytes
/// with its data size field), buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> encode_command(std::span<std::uint8_t> out,
                                                           const command &c) noexcept {
  const bool initiate = c.seg == segmentation::initiate;
  if (initiate != c.data_size.has_value()) return errc::invalid_argument;
  const std::size_t size = (initiate ? data_size_field : 0U) + c.segment.size();
  if (size > 0xFFFFU) return errc::too_long;
  if (out.size() < command_header_size + size) return errc::buffer_too_small;
  byte_writer w(out);
  FIELDCODEC_TRY_STATUS(w.write_u8(0));
  FIELDCODEC_TRY_STATUS(w.write_u8(c.transaction_id));
  FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(
      (c.response ? 0x80U : 0U) | (c.abort ? 0x40U : 0U) | (static_cast<unsigned>(c.seg) << 4U))));
  FIELDCODEC_TRY_STATUS(w.write_u8(c.id));
  FIELDCODEC_TRY_STATUS(w.write(static_cast<std::uint16_t>(size), byte_order::little));
  FIELDCODEC_TRY_STATUS(w.pad(2));
  if (initiate) {
    FIELDCODEC_TRY_STATUS(w.write(*c.data_size, byte_order::little));
  }
  FIELDCODEC_TRY_STATUS(w.write_bytes(c.segment));
  return w.size();
}

/// The index header of a WriteByIndex / ReadByIndex request and the data after it.
struct by_index {
  od::address address{};
  std::span<const std::uint8_t> data{};
};
/// Read the index header at the start of `segment`. Errors: truncated (fewer than 4 bytes).
[[nodiscard]] constexpr result<by_index>
decode_by_index(std::span<const std::uint8_t> segment) noexcept {
  byte_reader r(segment);
  by_index b;
  FIELDCODEC_TRY(b.address.index, r.read<std::uint16_t>(byte_order::little));
  FIELDCODEC_TRY(b.address.sub, r.read_u8());
  FIELDCODEC_TRY_STATUS(r.skip(1));
  b.data = r.rest();
  return b;
}
/// Write an index header and `data` into `out`; returns the bytes written.
/// Errors: buffer_too_small.
[[nodiscard]] constexpr result<std::size_t>
encode_by_index(std::span<std::uint8_t> out, od::address a,
                std::span<const std::uint8_t> data) noexcept {
  if (out.size() < index_header_size + data.size()) return errc::buffer_too_small;
  byte_writer w(out);
  FIELDCODEC_TRY_STATUS(w.write(a.index, byte_order::little));
  FIELDCODEC_TRY_STATUS(w.write_u8(a.sub));
  FIELDCODEC_TRY_STATUS(w.pad(1));
  FIELDCODEC_TRY_STATUS(w.write_bytes(data));
  return w.size();
}

/// A WriteByIndex or ReadByIndex request as a server reads it: the object, this frame's data,
/// and the size of the whole value (the data of the segments to come included).
struct index_request {
  std::uint8_t id = command_id::nil; ///< write_by_index or read_by_index
  od::address address{};
  std::span<const std::uint8_t> data{};
  std::size_t value_size = 0;
};
/// Read the request that starts a WriteByIndex or ReadByIndex transfer (an expedited frame or an
/// initiate). Errors: unexpected_frame (a response, an abort, a follow-on segment, a segmented
/// ReadByIndex), unknown_command (another command ID: a server answers
/// sdo::abort_code::unknown_command), truncated (no room for the index header), too_long (a
/// ReadByIndex with bytes after its index header), bad_length (an initiate's data size smaller
/// than what it carries).
[[nodiscard]] constexpr result<index_request> decode_index_request(const command &c) noexcept {
  if (c.response || c.abort) return errc::unexpected_frame;
  if (c.id != command_id::write_by_index && c.id != command_id::read_by_index) {
    return errc::unknown_command;
  }
  const bool read = c.id == command_id::read_by_index;
  if (c.seg == segmentation::segment || c.seg == segmentation::complete ||
      (read && c.seg == segmentation::initiate)) {
    return errc::unexpected_frame;
  }
  FIELDCODEC_TRY(const std::size_t total, transfer_size(c));
  FIELDCODEC_TRY(const by_index b, decode_by_index(c.segment));
  if (read && !b.data.empty()) return errc::too_long;
  return index_request{c.id, b.address, b.data, total - index_header_size};
}

/// The abort code of an abort frame. Errors: unexpected_frame (no abort flag), truncated (fewer
/// than 4 bytes in the segment), too_long (more).
[[nodiscard]] constexpr result<sdo::abort_code> decode_abort(const command &c) noexcept {
  if (!c.abort) return errc::unexpected_frame;
  byte_reader r(c.segment);
  FIELDCODEC_TRY(const std::uint32_t code, r.read<std::uint32_t>(byte_order::little));
  if (!r.empty()) return errc::too_long;
  return static_cast<sdo::abort_code>(code);
}
/// Write the command layer frame that aborts transaction `transaction_id` of command `id` with
/// `code` (`response`: sent by the server; a client's abort has it clear); returns the bytes
/// written (12). Errors: invalid_argument (abort_code::none), buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> encode_abort(std::span<std::uint8_t> out,
                                                         std::uint8_t transaction_id,
                                                         std::uint8_t id, sdo::abort_code code,
                                                         bool response = true) noexcept {
  if (code == sdo::abort_code::none) return errc::invalid_argument;
  const auto bytes = to_bytes(static_cast<std::uint32_t>(code), byte_order::little);
  return encode_command(out, command{transaction_id, response, true, segmentation::expedited, id,
                                     std::nullopt, bytes});
}

// ---------------------------------------------------------------------------------------------
// The ASnd frame

/// An SDO frame over ASnd: addresses, the sequence layer, and the command layer when present.
struct asnd_sdo {
  std::uint8_t destination = 0;
  std::uint8_t source = 0;
  sequence_header sequence{};
  std::optional<command> cmd{}; ///< none when the bytes end after the sequence layer
};

/// Read an SDO ASnd frame from `in`, which starts at the message type (byte 14 of the Ethernet
/// frame) and ends where the Ethernet payload ends. Errors: truncated (fewer than 8 bytes; those
/// of decode_command), too_long (more than 1500 bytes), unexpected_frame (not an ASnd frame, or
/// not the SDO service).
[[nodiscard]] constexpr result<asnd_sdo> decode_asnd(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < asnd_header_size + sequence_header_size) return errc::truncated;
  if (in.size() > max_frame_size) return errc::too_long;
  if (in[0] != message_type_asnd || in[3] != service_sdo) return errc::unexpected_frame;
  asnd_sdo f;
  f.destination = in[1];
  f.source = in[2];
  FIELDCODEC_TRY(f.sequence, decode_sequence(in.subspan(asnd_header_size)));
  const auto rest = in.subspan(asnd_header_size + sequence_header_size);
  if (!rest.empty()) {
    FIELDCODEC_TRY(f.cmd, decode_command(rest));
  }
  return f;
}
/// Read an SDO ASnd frame from a whole Ethernet frame (from the destination MAC address on,
/// without the frame check sequence). Errors: truncated (no Ethernet header), unexpected_frame
/// (another EtherType), those of decode_asnd.
[[nodiscard]] constexpr result<asnd_sdo>
decode_ethernet(std::span<const std::uint8_t> frame) noexcept {
  if (frame.size() < ethernet_header_size) return errc::truncated;
  if (from_bytes<std::uint16_t>({frame[12], frame[13]}, byte_order::big) != ethertype) {
    return errc::unexpected_frame;
  }
  return decode_asnd(frame.subspan(ethernet_header_size));
}

/// Write an SDO ASnd frame (from the message type on) into `out`; returns the bytes written
/// (the caller pads a frame shorter than 46 bytes, as Ethernet requires). Errors: those of
/// encode_sequence and encode_command, too_long (a frame over 1500 bytes), buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> encode_asnd(std::span<std::uint8_t> out,
                                                        const asnd_sdo &f) noexcept {
  FIELDCODEC_TRY(const auto seq, encode_sequence(f.sequence));
  if (f.cmd && command_size(*f.cmd) > max_frame_size - asnd_header_size - sequence_header_size) {
    return errc::too_long;
  }
  byte_writer w(out);
  FIELDCODEC_TRY_STATUS(w.write_u8(message_type_asnd));
  FIELDCODEC_TRY_STATUS(w.write_u8(f.destination));
  FIELDCODEC_TRY_STATUS(w.write_u8(f.source));
  FIELDCODEC_TRY_STATUS(w.write_u8(service_sdo));
  FIELDCODEC_TRY_STATUS(w.write_bytes(seq));
  std::size_t n = w.size();
  if (f.cmd) {
    FIELDCODEC_TRY(const std::size_t k, encode_command(out.subspan(n), *f.cmd));
    n += k;
  }
  return n;
}

} // namespace fieldcodec::canopen::powerlink
