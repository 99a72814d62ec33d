// fieldcodec — the SDO message codec (CiA 301): the 8 data bytes of every SDO message
// (expedited, segmented and block transfer, abort) and the SDO channel that puts messages on CAN
// identifiers. The abort codes are in canopen/abort_code.hpp (included).
//
// The codec knows nothing about CAN identifiers: `encode(message)` gives the 8 bytes
// (`sdo::payload`), `decode(payload, direction)` reads them, so the same codec and the transfer
// machines serve CAN, CoE (EtherCAT's mailbox carries the same 8 bytes) or a test bus. An
// `sdo::channel` holds the two COB-IDs of one SDO connection (request: client → server,
// response: server → client): `channel::default_for(node)` is the predefined 0x600 + node /
// 0x580 + node, `channel::from_cob_ids(sub1, sub2)` reads the values of an SDO parameter object
// (1200h–127Fh server, 1280h–12FFh client: sub 1 is always client → server).
//
// Byte 0 of an SDO message is the command byte, its bits 7..5 the command specifier; one table
// (`detail::commands`) lists every command of both directions with the bits that select it and
// the layout of the other bytes, and drives both the encoder and the decoder:
//   client → server                         server → client
//   0 download segment      000t nnnc       0 upload segment          000t nnnc
//   1 initiate download     001x nnes       1 download segment resp.  001t 0000
//   2 initiate upload       0100 0000       2 initiate upload resp.   010x nnes
//   3 upload segment req.   011t 0000       3 initiate download resp. 0110 0000
//   4 abort                 1000 0000       4 abort                   1000 0000
//   5 block upload:  initiate 1010 0c00,    5 block download: initiate resp. 1010 0s00,
//     end response 1010 0001, ack 1010 0010,  end response 1010 0001, ack 1010 0010
//     start 1010 0011
//   6 block download: initiate 1100 0cs0,   6 block upload: initiate resp. 1100 0cs0,
//     end 110n nn01                           end 110n nn01
// t toggle, n unused bytes, c last segment (segments) or CRC supported (block initiate), e
// expedited, s size indicated. Bytes 1..2 are the index (little-endian) and byte 3 the
// sub-index in initiate and abort messages; bytes 4..7 carry expedited data, a size or the
// abort code. The segments of a block transfer (byte 0 = c << 7 | sequence number 1..127, then
// 7 data bytes) carry no command specifier: only the transfer's state tells them apart, so they
// have their own functions (encode_block_segment / decode_block_segment).
#pragma once

#include <fieldcodec/canopen/abort_code.hpp>
#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <span>
#include <string_view>
#include <type_traits>

namespace fieldcodec::canopen::sdo {

// ---------------------------------------------------------------------------------------------
// Messages

/// The 8 data bytes of one SDO message.
using payload = std::array<std::uint8_t, 8>;

/// Which side sent a message.
enum class direction : std::uint8_t { to_server, to_client };

/// What an SDO message is. Block acknowledgements, ends and end responses have the same bytes
/// in both directions, so they are one type each.
enum class message_type : std::uint8_t {
  // client -> server
  initiate_download_request,
  download_segment_request,
  initiate_upload_request,
  upload_segment_request,
  block_download_initiate,
  block_upload_initiate,
  block_upload_start,
  // server -> client
  initiate_download_response,
  download_segment_response,
  initiate_upload_response,
  upload_segment_response,
  block_download_initiate_response,
  block_upload_initiate_response,
  // either way
  block_ack,          ///< receiver of a sub-block: last good sequence number, next block size
  block_end,          ///< sender of a block transfer: unused bytes of the last segment, CRC
  block_end_response, ///< receiver of a block transfer: end confirmed
  block_segment,      ///< a segment of a sub-block (only from decode_block_segment)
  abort,
};

/// A decoded SDO message. Which members mean something depends on `type`:
/// * initiate download request / initiate upload response: address, expedited, size_indicated,
///   size (expedited: the data bytes, 1..4, or 4 when not indicated; segmented: the announced
///   total when size_indicated), value (expedited: the data bytes as one little-endian number,
///   the bytes past `size` zero; value_bytes() gives them as bytes). An expedited message never
///   uses data/data_size (encode refuses one that does).
/// * download segment request / upload segment response: toggle, last, data/data_size (0..7).
/// * upload segment request / download segment response: toggle.
/// * initiate upload request / initiate download response: address.
/// * abort: address, abort.
/// * block download initiate: address, crc, size_indicated, size. Block upload initiate
///   response: the same. Block upload initiate: address, crc, block_size, switch_threshold.
///   Block download initiate response: address, crc, block_size.
/// * block ack: sequence (last good sequence number, 0..127), block_size (next sub-block).
/// * block end: unused (bytes of the last segment without data), checksum (CRC).
/// * block segment: sequence (1..127), last (no more segments), data (7 bytes).
struct message {
  // (the one-byte members first, then `address`: 36 bytes, no padding but address's own byte)
  message_type type = message_type::abort;
  bool expedited = false;
  bool size_indicated = false;
  bool toggle = false;
  bool last = false;
  bool crc = false;                  ///< block initiate: CRC supported by the sender
  std::uint8_t block_size = 0;       ///< block initiate (response), block ack: segments 1..127
  std::uint8_t sequence = 0;         ///< block ack: last good sequence number; block segment
  std::uint8_t switch_threshold = 0; ///< block upload initiate: protocol switch threshold
  std::uint8_t unused = 0;           ///< block end: bytes of the last segment without data
  od::address address{};
  std::uint16_t checksum = 0; ///< block end: CRC-16 of the data
  std::uint32_t size = 0;
  std::uint32_t value = 0; ///< expedited initiate: the data, little-endian
  abort_code abort = abort_code::none;
  std::array<std::uint8_t, 7> data{}; ///< segments: the data bytes
  std::uint8_t data_size = 0;         ///< segments: how many of `data` are data, 0..7

  /// A segment's data bytes (empty for every other message).
  [[nodiscard]] constexpr std::span<const std::uint8_t> bytes() const noexcept {
    return std::span<const std::uint8_t>(data).first(data_size);
  }
  /// An expedited initiate's data as bytes: the first `size` are data, the rest zero.
  [[nodiscard]] constexpr std::array<std::uint8_t, 4> value_bytes() const noexcept {
    return to_bytes<std::uint32_t>(value, byte_order::little);
  }
  friend constexpr bool operator==(const message &, const message &) noexcept = default;
};

/// Largest number of segments in a sub-block.
inline constexpr std::uint8_t max_block_size = 127;

namespace detail {
inline constexpr std::uint8_t toggle_bit = 0x10U;

/// How the bytes after the command byte are laid out.
enum class layout : std::uint8_t {
  segment,        ///< t nnn c in byte 0, data in bytes 1..7
  toggle,         ///< t in byte 0, nothing else
  initiate,       ///< nn e s in byte 0, address, expedited data or size in bytes 4..7
  address,        ///< address only
  abort,          ///< address, abort code
  block_initiate, ///< c s in byte 0 (bits 2, 1), address, size
  block_response, ///< c in byte 0, address, block size in byte 4
  block_upload,   ///< c in byte 0, address, block size in byte 4, threshold in byte 5
  block_ack,      ///< sequence in byte 1, block size in byte 2
  block_end,      ///< nnn in byte 0 (bits 4..2), CRC in bytes 1..2
  command_only,   ///< nothing after the command byte
};

/// One command: it is the message `type` when byte 0 masked with `mask` equals `bits` in
/// direction `dir`.
struct command {
  direction dir;
  std::uint8_t mask;
  std::uint8_t bits;
  message_type type;
  layout lay;
};

inline constexpr command commands[] = {
    {direction::to_server, 0xE0, 0x00, message_type::download_segment_request, layout::segment},
    {direction::to_server, 0xE0, 0x20, message_type::initiate_download_request, layout::initiate},
    {direction::to_server, 0xE0, 0x40, message_type::initiate_upload_request, layout::address},
    {direction::to_server, 0xE0, 0x60, message_type::upload_segment_request, layout::toggle},
    {direction::to_server, 0xE0, 0x80, message_type::abort, layout::abort},
    {direction::to_server, 0xE3, 0xA0, message_type::block_upload_initiate, layout::block_upload},
    {direction::to_server, 0xE3, 0xA1, message_type::block_end_response, layout::command_only},
    {direction::to_server, 0xE3, 0xA2, message_type::block_ack, layout::block_ack},
    {direction::to_server, 0xE3, 0xA3, message_type::block_upload_start, layout::command_only},
    {direction::to_server, 0xE1, 0xC0, message_type::block_download_initiate,
     layout::block_initiate},
    {direction::to_server, 0xE1, 0xC1, message_type::block_end, layout::block_end},
    {direction::to_client, 0xE0, 0x00, message_type::upload_segment_response, layout::segment},
    {direction::to_client, 0xE0, 0x20, message_type::download_segment_response, layout::toggle},
    {direction::to_client, 0xE0, 0x40, message_type::initiate_upload_response, layout::initiate},
    {direction::to_client, 0xE0, 0x60, message_type::initiate_download_response, layout::address},
    {direction::to_client, 0xE0, 0x80, message_type::abort, layout::abort},
    {direction::to_client, 0xE3, 0xA0, message_type::block_download_initiate_response,
     layout::block_response},
    {direction::to_client, 0xE3, 0xA1, message_type::block_end_response, layout::command_only},
    {direction::to_client, 0xE3, 0xA2, message_type::block_ack, layout::block_ack},
    {direction::to_client, 0xE1, 0xC0, message_type::block_upload_initiate_response,
     layout::block_initiate},
    {direction::to_client, 0xE1, 0xC1, message_type::block_end, layout::block_end},
};

// Positions in `commands` (std::size(commands) when absent), not pointers: see abort_position.
[[nodiscard]] constexpr std::size_t command_for(message_type t) noexcept {
  std::size_t i = 0;
  while (i < std::size(commands) && commands[i].type != t) ++i;
  return i;
}
// The masks look at bits 7..5 (the command specifier) and 1..0 only, so a command is found in
// one step from those five bits: index (byte0 >> 5) << 2 | (byte0 & 3), per direction.
static_assert([] {
  for (const auto &c : commands) {
    if ((c.mask & ~0xE3U) != 0U) return false;
  }
  return std::size(commands) < 0xFFU;
}());
inline constexpr std::uint8_t no_command = 0xFF;
/// [direction][key] → position in `commands` of the first command matching (no_command: none).
inline constexpr std::array<std::array<std::uint8_t, 32>, 2> command_index = [] {
  std::array<std::array<std::uint8_t, 32>, 2> t{};
  for (std::size_t d = 0; d < 2U; ++d) {
    for (unsigned key = 0; key < 32U; ++key) {
      const auto byte0 = static_cast<std::uint8_t>(((key >> 2U) << 5U) | (key & 3U));
      t[d][key] = no_command;
      for (std::size_t i = 0; i < std::size(commands); ++i) {
        const command &c = commands[i];
        if (static_cast<std::size_t>(c.dir) == d && (byte0 & c.mask) == c.bits) {
          t[d][key] = static_cast<std::uint8_t>(i);
          break;
        }
      }
    }
  }
  return t;
}();
/// The position of the command `byte0` stands for in direction `d`, std::size(commands) when
/// there is none; one table load (issue 18) instead of a scan of the table.
[[nodiscard]] constexpr std::size_t command_for(direction d, std::uint8_t byte0) noexcept {
  const auto dir = static_cast<std::size_t>(d);
  if (dir > 1U) return std::size(commands);
  const unsigned b = byte0;
  const std::uint8_t i = command_index[dir][((b >> 5U) << 2U) | (b & 3U)];
  return i == no_command ? std::size(commands) : i;
}

constexpr void put_address(payload &p, od::address a) noexcept {
  const auto i = to_bytes<std::uint16_t>(a.index, byte_order::little);
  p[1] = i[0];
  p[2] = i[1];
  p[3] = a.sub;
}
[[nodiscard]] constexpr od::address get_address(const payload &p) noexcept {
  return {from_bytes<std::uint16_t>({p[1], p[2]}, byte_order::little), p[3]};
}
constexpr void put_u32(payload &p, std::uint32_t v) noexcept {
  const auto b = to_bytes<std::uint32_t>(v, byte_order::little);
  for (std::size_t i = 0; i < 4U; ++i) p[4U + i] = b[i];
}
[[nodiscard]] constexpr std::uint32_t get_u32(const payload &p) noexcept {
  return from_bytes<std::uint32_t>({p[4], p[5], p[6], p[7]}, byte_order::little);
}
[[nodiscard]] constexpr bool valid_block_size(std::uint8_t n) noexcept {
  return n >= 1U && n <= max_block_size;
}

/// The data of an expedited initiate (bit 1 of byte 0 set; bits 3..2 the unused bytes when
/// bit 0 says the size is indicated) into `m`: size = 1..4 data bytes (4 without size
/// indication), value = those bytes as one little-endian word (the unused bytes zero, whatever
/// the sender put there).
constexpr void read_expedited_data(const payload &p, message &m) noexcept {
  const unsigned b0 = p[0];
  const unsigned n = (b0 & 0x01U) != 0U ? (b0 >> 2U) & 3U : 0U;
  m.size = 4U - n;
  m.value = get_u32(p) & (0xFFFF'FFFFU >> (8U * n));
}

// The writers of the layouts: byte 0 is `bits` (a command's bits from `commands`) with the
// flags of the layout, then its fields. encode(message) and the named constructors below both
// write through them, so each layout is written in one place; a named constructor passes its
// command's bits as a constant (command_bits) and builds no message.

/// The bits of the command of type `t` (0 for block_segment, which has none).
[[nodiscard]] constexpr unsigned command_bits(message_type t) noexcept {
  const std::size_t i = command_for(t);
  return i < std::size(commands) ? commands[i].bits : 0U;
}
[[nodiscard]] constexpr payload write_address(unsigned b0, od::address a) noexcept {
  payload p{};
  p[0] = static_cast<std::uint8_t>(b0);
  put_address(p, a);
  return p;
}
// Each writer below that can refuse its arguments checks them and calls the one that writes
// the bytes (put_…), which a machine whose arguments hold by construction calls directly (no
// result to build and unwrap on every segment).

/// layout::segment: `bytes` (at most 7; exactly 7 unless `last`) and their count in byte 0.
/// Requires at most 7 bytes.
[[nodiscard]] constexpr payload
put_segment(unsigned bits, bool toggle, std::span<const std::uint8_t> bytes, bool last) noexcept {
  const std::size_t n = bytes.size();
  payload p{};
  p[0] = static_cast<std::uint8_t>(bits | (toggle ? toggle_bit : 0U) | ((7U - n) << 1U) |
                                   (last ? 1U : 0U));
  for (std::size_t i = 0; i < n; ++i) p[1U + i] = bytes[i];
  return p;
}
[[nodiscard]] constexpr result<payload>
write_segment(unsigned bits, bool toggle, std::span<const std::uint8_t> bytes, bool last) noexcept {
  const std::size_t n = bytes.size();
  if (n > 7U) return errc::too_long;
  if (!last && n != 7U) return errc::bad_length;
  return put_segment(bits, toggle, bytes, last);
}
/// layout::toggle, and layout::command_only (toggle false).
[[nodiscard]] constexpr payload write_toggle(unsigned bits, bool toggle) noexcept {
  payload p{};
  p[0] = static_cast<std::uint8_t>(bits | (toggle ? toggle_bit : 0U));
  return p;
}
/// An initiate that is not expedited (layout::initiate, size flag 0x01) or a block initiate
/// (layout::block_initiate, size flag 0x02, `bits` with the CRC flag): the address and, when
/// indicated, the size.
[[nodiscard]] constexpr payload write_sized(unsigned bits, unsigned size_flag, od::address a,
                                            bool size_indicated, std::uint32_t size) noexcept {
  payload p = write_address(bits | (size_indicated ? size_flag : 0U), a);
  if (size_indicated) put_u32(p, size);
  return p;
}
/// layout::abort.
[[nodiscard]] constexpr payload write_abort(unsigned bits, od::address a,
                                            abort_code code) noexcept {
  payload p = write_address(bits, a);
  put_u32(p, static_cast<std::uint32_t>(code));
  return p;
}
/// layout::block_response and layout::block_upload (`bits` with the CRC flag): the address,
/// the block size (1..127) and the protocol switch threshold (block_upload only: 0 otherwise).
[[nodiscard]] constexpr payload put_block_size(unsigned bits, od::address a,
                                               std::uint8_t block_size,
                                               std::uint8_t threshold) noexcept {
  payload p = write_address(bits, a);
  p[4] = block_size;
  p[5] = threshold;
  return p;
}
[[nodiscard]] constexpr result<payload> write_block_size(unsigned bits, od::address a,
                                                         std::uint8_t block_size,
                                                         std::uint8_t threshold) noexcept {
  if (!valid_block_size(block_size)) return errc::out_of_range;
  return put_block_size(bits, a, block_size, threshold);
}
/// layout::block_ack: the last good sequence number (0..127) and the next block size (1..127).
[[nodiscard]] constexpr payload put_block_ack(unsigned bits, std::uint8_t sequence,
                                              std::uint8_t block_size) noexcept {
  payload p{};
  p[0] = static_cast<std::uint8_t>(bits);
  p[1] = sequence;
  p[2] = block_size;
  return p;
}
[[nodiscard]] constexpr result<payload> write_block_ack(unsigned bits, std::uint8_t sequence,
                                                        std::uint8_t block_size) noexcept {
  if (sequence > max_block_size || !valid_block_size(block_size)) return errc::out_of_range;
  return put_block_ack(bits, sequence, block_size);
}
/// layout::block_end: the unused bytes of the last segment (0..7) and the CRC.
[[nodiscard]] constexpr payload put_block_end(unsigned bits, std::uint8_t unused,
                                              std::uint16_t checksum) noexcept {
  payload p{};
  p[0] = static_cast<std::uint8_t>(bits | (static_cast<unsigned>(unused) << 2U));
  p[1] = static_cast<std::uint8_t>(checksum & 0xFFU);
  p[2] = static_cast<std::uint8_t>(checksum >> 8U);
  return p;
}
[[nodiscard]] constexpr result<payload> write_block_end(unsigned bits, std::uint8_t unused,
                                                        std::uint16_t checksum) noexcept {
  if (unused > 7U) return errc::out_of_range;
  return put_block_end(bits, unused, checksum);
}
} // namespace detail

/// The 8 bytes of `m`. Unused bytes are zero.
/// Errors: bad_length (expedited without data — size 0 — or unsized with a size other than 4, a
/// non-last segment without exactly 7 bytes), too_long (expedited size over 4 or a segment over
/// 7 bytes), out_of_range (an expedited value with bits set past its size, block size not
/// 1..127, sequence number over 127 — or 0 for a segment —, unused bytes over 7),
/// invalid_argument (an unknown type, an expedited message with data_size set: its data goes
/// in `value`; an initiate that is not expedited with `value` or `data_size` set: its data goes
/// in the segments).
[[nodiscard]] constexpr result<payload> encode(const message &m) noexcept {
  if (m.type == message_type::block_segment) {
    if (m.sequence == 0U || m.sequence > max_block_size) return errc::out_of_range;
    if (m.data_size > 7U) return errc::too_long;
    payload p{};
    p[0] = static_cast<std::uint8_t>((m.last ? 0x80U : 0U) | m.sequence);
    for (std::size_t i = 0; i < m.data_size; ++i) p[1U + i] = m.data[i];
    return p;
  }
  const std::size_t ci = detail::command_for(m.type);
  if (ci == std::size(detail::commands)) return errc::invalid_argument;
  const detail::command *c = &detail::commands[ci];
  const unsigned bits = c->bits;
  const unsigned crc = m.crc ? 0x04U : 0U;
  switch (c->lay) {
  case detail::layout::segment:
    if (m.data_size > 7U) return errc::too_long;
    return detail::write_segment(bits, m.toggle, m.bytes(), m.last);
  case detail::layout::toggle: return detail::write_toggle(bits, m.toggle);
  case detail::layout::initiate:
    if (m.expedited) {
      if (m.data_size != 0U) return errc::invalid_argument;
      if (m.size == 0U) return errc::bad_length;
      if (m.size > 4U) return errc::too_long;
      if (!m.size_indicated && m.size != 4U) return errc::bad_length;
      if (m.size < 4U && (m.value >> (8U * m.size)) != 0U) return errc::out_of_range;
      payload p = detail::write_address(
          bits | (m.size_indicated ? ((4U - m.size) << 2U) | 0x03U : 0x02U), m.address);
      detail::put_u32(p, m.value);
      return p;
    }
    // data for a transfer that is not expedited goes in segments: refuse it here rather than
    // send an initiate without it
    if (m.value != 0U || m.data_size != 0U) return errc::invalid_argument;
    return detail::write_sized(bits, 0x01U, m.address, m.size_indicated, m.size);
  case detail::layout::address: return detail::write_address(bits, m.address);
  case detail::layout::abort: return detail::write_abort(bits, m.address, m.abort);
  case detail::layout::block_initiate:
    return detail::write_sized(bits | crc, 0x02U, m.address, m.size_indicated, m.size);
  case detail::layout::block_response:
    return detail::write_block_size(bits | crc, m.address, m.block_size, 0);
  case detail::layout::block_upload:
    return detail::write_block_size(bits | crc, m.address, m.block_size, m.switch_threshold);
  case detail::layout::block_ack: return detail::write_block_ack(bits, m.sequence, m.block_size);
  case detail::layout::block_end: return detail::write_block_end(bits, m.unused, m.checksum);
  case detail::layout::command_only: return detail::write_toggle(bits, false);
  }
  return errc::invalid_argument;
}

// `decode(payload, direction)` is the straight path of expedited initiates plus a call of the
// table decoder, which stays out of line (issue 18, round 4): inlined where it is called, a
// caller's tests of the type fold and the message is built in the caller's frame. GCC's own
// choice varied with what else a program holds (it inlined the table into `decode` and stopped
// inlining `decode` into the SDO client and server: ~30 instructions more per message), so it
// is said here. Built for size (-Os, firmware) the compiler decides.
#if defined(__OPTIMIZE_SIZE__) || !defined(__GNUC__)
#define FIELDCODEC_SDO_OUT_OF_LINE
#define FIELDCODEC_SDO_INLINE
#else
#define FIELDCODEC_SDO_OUT_OF_LINE [[gnu::noinline]]
#define FIELDCODEC_SDO_INLINE [[gnu::always_inline]]
#endif

namespace detail {
// The fields of byte 0, for readers that take a message's bytes in place (the SDO client).
/// The command specifier (bits 7..5).
[[nodiscard]] constexpr unsigned specifier(std::uint8_t b0) noexcept { return b0 >> 5U; }
/// The command specifier of message type `t` (for constants: the table is not linked).
[[nodiscard]] constexpr unsigned specifier_of(message_type t) noexcept {
  return commands[command_for(t)].bits >> 5U;
}
/// A segment (layout::segment): toggle (bit 4), data bytes (7 − bits 3..1), last (bit 0).
[[nodiscard]] constexpr bool segment_toggle(std::uint8_t b0) noexcept {
  return (b0 & toggle_bit) != 0U;
}
[[nodiscard]] constexpr std::uint8_t segment_size(std::uint8_t b0) noexcept {
  return static_cast<std::uint8_t>(7U - ((b0 >> 1U) & 7U));
}
[[nodiscard]] constexpr bool segment_last(std::uint8_t b0) noexcept { return (b0 & 0x01U) != 0U; }
/// An initiate (layout::initiate): expedited (bit 1), size indicated (bit 0).
[[nodiscard]] constexpr bool initiate_expedited(std::uint8_t b0) noexcept {
  return (b0 & 0x02U) != 0U;
}
[[nodiscard]] constexpr bool initiate_size_indicated(std::uint8_t b0) noexcept {
  return (b0 & 0x01U) != 0U;
}
/// An expedited initiate's data bytes: 4 − bits 3..2 when the size is indicated, else 4 (what
/// read_expedited_data gives as `size`).
[[nodiscard]] constexpr std::uint8_t expedited_size(std::uint8_t b0) noexcept {
  return static_cast<std::uint8_t>(initiate_size_indicated(b0) ? 4U - ((b0 >> 2U) & 3U) : 4U);
}
/// A block initiate (layout::block_initiate, block_response, block_upload): CRC supported
/// (bit 2); size indicated (bit 1, block_initiate only).
[[nodiscard]] constexpr bool block_crc(std::uint8_t b0) noexcept { return (b0 & 0x04U) != 0U; }
[[nodiscard]] constexpr bool block_size_indicated(std::uint8_t b0) noexcept {
  return (b0 & 0x02U) != 0U;
}
/// layout::block_response / block_upload: the block size (byte 4); block_upload: the protocol
/// switch threshold (byte 5).
[[nodiscard]] constexpr std::uint8_t initiate_block_size(const payload &p) noexcept { return p[4]; }
[[nodiscard]] constexpr std::uint8_t switch_threshold(const payload &p) noexcept { return p[5]; }
/// layout::block_ack: the last good sequence number (byte 1), the next block size (byte 2).
[[nodiscard]] constexpr std::uint8_t ack_sequence(const payload &p) noexcept { return p[1]; }
[[nodiscard]] constexpr std::uint8_t ack_block_size(const payload &p) noexcept { return p[2]; }
/// layout::block_end: bytes of the last segment without data (bits 4..2), the CRC (bytes 1..2).
[[nodiscard]] constexpr std::uint8_t end_unused(std::uint8_t b0) noexcept {
  return static_cast<std::uint8_t>((b0 >> 2U) & 7U);
}
[[nodiscard]] constexpr std::uint16_t end_checksum(const payload &p) noexcept {
  return from_bytes<std::uint16_t>({p[1], p[2]}, byte_order::little);
}
/// layout::abort: the abort code (bytes 4..7).
[[nodiscard]] constexpr abort_code abort_of(const payload &p) noexcept {
  return static_cast<abort_code>(get_u32(p));
}

/// The type of the command `b0` stands for in direction `D`, or no_type: one byte of a
/// 32-byte table computed from `commands` (the table itself stays out of the image), for a
/// machine that reads the rest of a message in place through the readers here (the server).
inline constexpr auto no_type = static_cast<message_type>(0xFFU);
template <direction D>
inline constexpr std::array<message_type, 32> command_types = [] {
  std::array<message_type, 32> t{};
  for (std::size_t k = 0; k < t.size(); ++k) {
    const std::uint8_t i = command_index[static_cast<std::size_t>(D)][k];
    t[k] = i == no_command ? no_type : commands[i].type;
  }
  return t;
}();
template <direction D>
[[nodiscard]] constexpr message_type type_of(std::uint8_t b0) noexcept {
  return command_types<D>[(specifier(b0) << 2U) | (b0 & 3U)];
}

// The readers of the layouts: each fills the members of its layout from the 8 bytes (`type` is
// the caller's). decode_by_table reads through them.
constexpr void read_segment(const payload &p, message &m) noexcept {
  m.toggle = segment_toggle(p[0]);
  m.last = segment_last(p[0]);
  m.data_size = segment_size(p[0]);
  for (std::size_t i = 0; i < 7U; ++i) { // not a copy of run-time length: no call of memcpy
    if (i < m.data_size) m.data[i] = p[1U + i];
  }
}
constexpr void read_toggle(const payload &p, message &m) noexcept {
  m.toggle = segment_toggle(p[0]);
}
constexpr void read_initiate(const payload &p, message &m) noexcept {
  m.address = get_address(p);
  m.expedited = initiate_expedited(p[0]);
  m.size_indicated = initiate_size_indicated(p[0]);
  if (m.expedited) {
    read_expedited_data(p, m);
  } else if (m.size_indicated) {
    m.size = get_u32(p);
  }
}
constexpr void read_abort(const payload &p, message &m) noexcept {
  m.address = get_address(p);
  m.abort = abort_of(p);
}

/// decode through the command table: every command (decode takes expedited initiates first, by
/// straight code that gives the same message).
FIELDCODEC_SDO_OUT_OF_LINE [[nodiscard]] constexpr result<message>
decode_by_table(const payload &p, direction d) noexcept {
  const std::size_t ci = detail::command_for(d, p[0]);
  if (ci == std::size(detail::commands)) return errc::unknown_command;
  const detail::command *c = &detail::commands[ci];
  // built in the result that is returned (no copy of the message on the way out)
  result<message> r{message{}};
  message &m = r.value();
  m.type = c->type;
  switch (c->lay) {
  case detail::layout::segment: read_segment(p, m); break;
  case detail::layout::toggle: read_toggle(p, m); break;
  case detail::layout::initiate: read_initiate(p, m); break;
  case detail::layout::address: m.address = detail::get_address(p); break;
  case detail::layout::abort: read_abort(p, m); break;
  case detail::layout::block_initiate:
    m.address = detail::get_address(p);
    m.crc = block_crc(p[0]);
    m.size_indicated = block_size_indicated(p[0]);
    if (m.size_indicated) m.size = detail::get_u32(p);
    break;
  case detail::layout::block_response:
  case detail::layout::block_upload:
    m.address = detail::get_address(p);
    m.crc = block_crc(p[0]);
    m.block_size = initiate_block_size(p);
    if (c->lay == detail::layout::block_upload) m.switch_threshold = switch_threshold(p);
    break;
  case detail::layout::block_ack:
    m.sequence = ack_sequence(p);
    m.block_size = ack_block_size(p);
    break;
  case detail::layout::block_end:
    m.unused = end_unused(p[0]);
    m.checksum = end_checksum(p);
    break;
  case detail::layout::command_only: break;
  }
  return r;
}

/// The byte-0 keys (command_index's) of the commands a server sends: bit k set when key k is
/// one. Computed from the table, so is_server_message answers without linking it.
inline constexpr std::uint32_t to_client_keys = [] {
  std::uint32_t keys = 0;
  for (unsigned k = 0; k < 32U; ++k) {
    if (command_index[static_cast<std::size_t>(direction::to_client)][k] != no_command) {
      keys |= 1U << k;
    }
  }
  return keys;
}();
} // namespace detail

/// Read the 8 bytes of a message sent in direction `d` (see the table at the top). Reserved
/// bits are ignored; values the machines must judge (block sizes, sequence numbers) are
/// reported as they are. Errors: unknown_command (no such command in that direction).
FIELDCODEC_SDO_INLINE [[nodiscard]] constexpr result<message> decode(const payload &p,
                                                                     direction d) noexcept {
  // The commonest message first (issue 18): an expedited initiate, 001x nn1s to the server
  // (download request), 010x nn1s to the client (upload response), built by straight code so
  // that a caller's tests of type and `expedited` fold after inlining. The table gives the
  // same message for these bytes (layout::initiate, expedited). A value of `d` that is no
  // direction matches nothing (0x100) and the table refuses it.
  const unsigned b0 = p[0];
  const unsigned expedited_bits = d == direction::to_server   ? 0x22U
                                  : d == direction::to_client ? 0x42U
                                                              : 0x100U;
  if ((b0 & 0xE2U) == expedited_bits) {
    message m;
    m.type = d == direction::to_server ? message_type::initiate_download_request
                                       : message_type::initiate_upload_response;
    m.address = detail::get_address(p);
    m.expedited = true;
    m.size_indicated = (b0 & 0x01U) != 0U;
    detail::read_expedited_data(p, m);
    return m;
  }
  auto r = detail::decode_by_table(p, d);
  // What the table gives here is never expedited (those bytes were taken above). Written down
  // as a store the compiler sees, unlike the table's answer: a caller's code for expedited
  // data then runs only after the straight path (70 -> 64 instructions in the benchmark).
  if (r.has_value()) r.value().expedited = false;
  return r;
}

/// True when `byte0` begins a message a server sends: what decode(…, direction::to_client)
/// does not refuse with unknown_command (one bit of a constant, no table).
[[nodiscard]] constexpr bool is_server_message(std::uint8_t byte0) noexcept {
  const unsigned key = (detail::specifier(byte0) << 2U) | (byte0 & 3U);
  return ((detail::to_client_keys >> key) & 1U) != 0U;
}

/// A segment of a sub-block: byte 0 = last << 7 | sequence, then 7 data bytes (all 7 are sent;
/// how many of the last segment's bytes are data is said by the block end message).
/// Errors: out_of_range (sequence number 0).
[[nodiscard]] constexpr result<message> decode_block_segment(const payload &p) noexcept {
  message m;
  m.type = message_type::block_segment;
  m.sequence = static_cast<std::uint8_t>(p[0] & 0x7FU);
  if (m.sequence == 0U) return errc::out_of_range;
  m.last = (p[0] & 0x80U) != 0U;
  m.data_size = 7;
  for (std::size_t i = 0; i < 7U; ++i) m.data[i] = p[1U + i];
  return m;
}

// ----- named constructors ---------------------------------------------------------------------

namespace detail {
static_assert(commands[command_for(message_type::initiate_download_request)].bits == 0x20U &&
              commands[command_for(message_type::initiate_download_request)].lay ==
                  layout::initiate &&
              commands[command_for(message_type::initiate_upload_response)].bits == 0x40U &&
              commands[command_for(message_type::initiate_upload_response)].lay ==
                  layout::initiate);
/// The payload encode() makes of an expedited initiate message (written directly: the bytes
/// and errors are encode's, in its order). `t` is initiate_download_request or
/// initiate_upload_response.
/// put_expedited writes it (requires 1..4 bytes, exactly 4 when the size is not indicated).
[[nodiscard]] constexpr payload put_expedited(message_type t, od::address a,
                                              std::span<const std::uint8_t> bytes,
                                              bool size_indicated) noexcept {
  const unsigned bits = t == message_type::initiate_download_request ? 0x20U : 0x40U;
  payload p{};
  p[0] = static_cast<std::uint8_t>(bits |
                                   (size_indicated ? ((4U - bytes.size()) << 2U) | 0x03U : 0x02U));
  put_address(p, a);
  for (std::size_t i = 0; i < bytes.size(); ++i) p[4U + i] = bytes[i];
  return p;
}
[[nodiscard]] constexpr result<payload> expedited(message_type t, od::address a,
                                                  std::span<const std::uint8_t> bytes,
                                                  bool size_indicated) noexcept {
  if (bytes.size() > 4U) return errc::too_long;
  if (bytes.empty() || (!size_indicated && bytes.size() != 4U)) return errc::bad_length;
  return put_expedited(t, a, bytes, size_indicated);
}
/// The bits of command `T` as a constant (what a named constructor writes).
template <message_type T>
inline constexpr unsigned bits_of = command_bits(T);
} // namespace detail

// client -> server

/// Expedited download of 1..4 bytes with size indication (0x2F, 0x2B, 0x27, 0x23).
/// Errors: bad_length (no bytes), too_long (more than 4 bytes).
[[nodiscard]] constexpr result<payload>
expedited_download(od::address a, std::span<const std::uint8_t> bytes) noexcept {
  return detail::expedited(message_type::initiate_download_request, a, bytes, true);
}
/// Expedited download without size indication (0x22): exactly 4 bytes. Errors: bad_length.
[[nodiscard]] constexpr result<payload>
expedited_download_unsized(od::address a, std::span<const std::uint8_t> bytes) noexcept {
  return detail::expedited(message_type::initiate_download_request, a, bytes, false);
}
/// Initiate a segmented download of `size` bytes (0x21), or without size indication (0x20).
[[nodiscard]] constexpr payload initiate_download(od::address a, std::uint32_t size,
                                                  bool size_indicated = true) noexcept {
  return detail::write_sized(detail::bits_of<message_type::initiate_download_request>, 0x01U, a,
                             size_indicated, size);
}
/// A download segment: 0..7 bytes (exactly 7 unless last).
/// Errors: too_long (> 7 bytes), bad_length (fewer than 7 in a non-last segment).
[[nodiscard]] constexpr result<payload>
download_segment(bool toggle, std::span<const std::uint8_t> bytes, bool last) noexcept {
  return detail::write_segment(detail::bits_of<message_type::download_segment_request>, toggle,
                               bytes, last);
}
/// Initiate upload (0x40).
[[nodiscard]] constexpr payload initiate_upload(od::address a) noexcept {
  return detail::write_address(detail::bits_of<message_type::initiate_upload_request>, a);
}
/// Upload segment request (0x60 / 0x70).
[[nodiscard]] constexpr payload upload_segment_request(bool toggle) noexcept {
  return detail::write_toggle(detail::bits_of<message_type::upload_segment_request>, toggle);
}

// server -> client

/// Initiate download response (0x60).
[[nodiscard]] constexpr payload download_response(od::address a) noexcept {
  return detail::write_address(detail::bits_of<message_type::initiate_download_response>, a);
}
/// Download segment response (0x20 / 0x30).
[[nodiscard]] constexpr payload download_segment_response(bool toggle) noexcept {
  return detail::write_toggle(detail::bits_of<message_type::download_segment_response>, toggle);
}
/// Expedited upload response with size indication (0x4F, 0x4B, 0x47, 0x43).
/// Errors: bad_length (no bytes), too_long (more than 4 bytes).
[[nodiscard]] constexpr result<payload>
expedited_upload_response(od::address a, std::span<const std::uint8_t> bytes) noexcept {
  return detail::expedited(message_type::initiate_upload_response, a, bytes, true);
}
/// Expedited upload response without size indication (0x42): exactly 4 bytes.
[[nodiscard]] constexpr result<payload>
expedited_upload_response_unsized(od::address a, std::span<const std::uint8_t> bytes) noexcept {
  return detail::expedited(message_type::initiate_upload_response, a, bytes, false);
}
/// Initiate upload response of a segmented upload of `size` bytes (0x41), or without size
/// indication (0x40).
[[nodiscard]] constexpr payload upload_response(od::address a, std::uint32_t size,
                                                bool size_indicated = true) noexcept {
  return detail::write_sized(detail::bits_of<message_type::initiate_upload_response>, 0x01U, a,
                             size_indicated, size);
}
/// An upload segment: 0..7 bytes (exactly 7 unless last). Errors: too_long, bad_length.
[[nodiscard]] constexpr result<payload>
upload_segment(bool toggle, std::span<const std::uint8_t> bytes, bool last) noexcept {
  return detail::write_segment(detail::bits_of<message_type::upload_segment_response>, toggle,
                               bytes, last);
}

// both

/// Abort transfer (0x80), sent by either side.
[[nodiscard]] constexpr payload abort(od::address a, abort_code code) noexcept {
  return detail::write_abort(detail::bits_of<message_type::abort>, a, code);
}

// block transfer

/// Block download initiate (client, 0xC0 | crc << 2 | s << 1) with the size when known.
[[nodiscard]] constexpr payload block_download_initiate(od::address a, std::uint32_t size,
                                                        bool size_indicated, bool crc) noexcept {
  return detail::write_sized(detail::bits_of<message_type::block_download_initiate> |
                                 (crc ? 0x04U : 0U),
                             0x02U, a, size_indicated, size);
}
/// Block download initiate response (server, 0xA0 | crc << 2): the first block size.
/// Errors: out_of_range (block size not 1..127).
[[nodiscard]] constexpr result<payload>
block_download_initiate_response(od::address a, std::uint8_t block_size, bool crc) noexcept {
  return detail::write_block_size(detail::bits_of<message_type::block_download_initiate_response> |
                                      (crc ? 0x04U : 0U),
                                  a, block_size, 0);
}
/// Block upload initiate (client, 0xA0 | crc << 2): block size and protocol switch threshold
/// (0: no switch). Errors: out_of_range (block size not 1..127).
[[nodiscard]] constexpr result<payload> block_upload_initiate(od::address a,
                                                              std::uint8_t block_size,
                                                              std::uint8_t switch_threshold,
                                                              bool crc) noexcept {
  return detail::write_block_size(detail::bits_of<message_type::block_upload_initiate> |
                                      (crc ? 0x04U : 0U),
                                  a, block_size, switch_threshold);
}
/// Block upload initiate response (server, 0xC0 | crc << 2 | s << 1) with the size.
[[nodiscard]] constexpr payload block_upload_initiate_response(od::address a, std::uint32_t size,
                                                               bool size_indicated,
                                                               bool crc) noexcept {
  return detail::write_sized(detail::bits_of<message_type::block_upload_initiate_response> |
                                 (crc ? 0x04U : 0U),
                             0x02U, a, size_indicated, size);
}
/// Block upload start (client, 0xA3).
[[nodiscard]] constexpr payload block_upload_start() noexcept {
  return detail::write_toggle(detail::bits_of<message_type::block_upload_start>, false);
}
namespace detail {

/// The one writer of a block segment's 8 bytes (encode_block_segment checks its arguments and
/// calls it; a burst's loop of full segments, whose arguments hold by construction, calls it
/// directly): byte 0 = last << 7 | sequence, then `bytes`, then zeros. Requires sequence
/// 1..127 and at most 7 bytes. Writes all 8 bytes of `p`.
constexpr void write_block_segment(payload &p, std::uint8_t sequence,
                                   std::span<const std::uint8_t> bytes, bool last) noexcept {
  p[0] = static_cast<std::uint8_t>((last ? 0x80U : 0U) | sequence);
  if (bytes.size() == 7U) { // every segment but the last: a copy of constant length
    fieldcodec::copy_bytes<7>(bytes.data(), p.data() + 1);
    return;
  }
  for (std::size_t i = 0; i < 7U; ++i) p[1U + i] = i < bytes.size() ? bytes[i] : std::uint8_t{0};
}

} // namespace detail

/// A segment of a sub-block: sequence number 1..127, up to 7 bytes (the rest zero), `last` for
/// the last segment of the transfer. Errors: out_of_range (sequence), too_long.
[[nodiscard]] constexpr result<payload> encode_block_segment(std::uint8_t sequence,
                                                             std::span<const std::uint8_t> bytes,
                                                             bool last) noexcept {
  if (bytes.size() > 7U) return errc::too_long;
  if (sequence == 0U || sequence > max_block_size) return errc::out_of_range;
  // written directly (encode(message)'s bytes and errors): a burst makes up to 127 of these
  // per sub-block, and building a 28-byte message for each cost several times the copy
  payload p{};
  detail::write_block_segment(p, sequence, bytes, last);
  return p;
}
/// Block acknowledgement (0xA2): the last segment received in sequence (0: none) and the size
/// of the next sub-block. Errors: out_of_range.
[[nodiscard]] constexpr result<payload> block_ack(std::uint8_t sequence,
                                                  std::uint8_t block_size) noexcept {
  return detail::write_block_ack(detail::bits_of<message_type::block_ack>, sequence, block_size);
}
/// Block end (0xC1 | unused << 2): bytes of the last segment without data (0..7) and the CRC
/// of the data (0 when CRC is not used). Errors: out_of_range (unused over 7).
[[nodiscard]] constexpr result<payload> block_end(std::uint8_t unused,
                                                  std::uint16_t checksum) noexcept {
  return detail::write_block_end(detail::bits_of<message_type::block_end>, unused, checksum);
}
/// Block end response (0xA1).
[[nodiscard]] constexpr payload block_end_response() noexcept {
  return detail::write_toggle(detail::bits_of<message_type::block_end_response>, false);
}

// ---------------------------------------------------------------------------------------------
// The channel: the CAN identifiers of one SDO connection

/// The two COB-IDs of an SDO connection. Messages from the client travel on `request_id`,
/// answers from the server on `response_id`; every SDO frame has DLC 8.
struct channel {
  std::uint16_t request_id = 0;  ///< client → server (1200h/1280h sub 1)
  std::uint16_t response_id = 0; ///< server → client (1200h/1280h sub 2)

  /// The predefined connection of `node`: 0x600 + node / 0x580 + node.
  /// Errors: invalid_argument (node not 1..127).
  [[nodiscard]] static constexpr result<channel> default_for(std::uint8_t node) noexcept {
    if (!is_node_id(node)) return errc::invalid_argument;
    return channel{static_cast<std::uint16_t>(cob_id::sdo_rx_base + node),
                   static_cast<std::uint16_t>(cob_id::sdo_tx_base + node)};
  }
  /// The connection an SDO parameter object describes: the values of sub 1 (client → server)
  /// and sub 2 (server → client). Bit 31 set means "not valid", bit 29 a 29-bit identifier.
  /// Errors: bad_state (a COB-ID not valid), out_of_range (29-bit identifier, or bits 11..28
  /// set).
  [[nodiscard]] static constexpr result<channel>
  from_cob_ids(std::uint32_t client_to_server, std::uint32_t server_to_client) noexcept {
    constexpr std::uint32_t invalid = 0x8000'0000U;
    for (const std::uint32_t v : {client_to_server, server_to_client}) {
      if ((v & invalid) != 0U) return errc::bad_state;
      if ((v & 0x3FFF'F800U) != 0U) return errc::out_of_range; // frame bit 29 or bits 11..28
    }
    return channel{static_cast<std::uint16_t>(client_to_server & max_can_id),
                   static_cast<std::uint16_t>(server_to_client & max_can_id)};
  }

  /// The CAN frame of a message from the client / from the server.
  [[nodiscard]] constexpr can_frame request(const payload &p) const noexcept {
    return frame(request_id, p);
  }
  [[nodiscard]] constexpr can_frame response(const payload &p) const noexcept {
    return frame(response_id, p);
  }
  [[nodiscard]] constexpr result<can_frame> request(const result<payload> &p) const noexcept {
    if (!p) return p.error();
    return can_frame{request_id, false, 8, p.value()}; // built in place: no copy of a frame
  }
  [[nodiscard]] constexpr result<can_frame> response(const result<payload> &p) const noexcept {
    if (!p) return p.error();
    return can_frame{response_id, false, 8, p.value()}; // built in place: no copy of a frame
  }
  /// Is `f` a data frame on this connection's request / response identifier (any DLC)? A
  /// channel without identifiers (0: the NMT COB-ID, never an SDO) matches nothing.
  [[nodiscard]] constexpr bool is_request(const can_frame &f) const noexcept {
    return request_id != 0U && f.id == request_id && !f.rtr;
  }
  [[nodiscard]] constexpr bool is_response(const can_frame &f) const noexcept {
    return response_id != 0U && f.id == response_id && !f.rtr;
  }

  friend constexpr bool operator==(const channel &, const channel &) noexcept = default;

private:
  [[nodiscard]] static constexpr can_frame frame(std::uint16_t id, const payload &p) noexcept {
    can_frame f;
    f.id = id;
    f.dlc = 8;
    f.data = p;
    return f;
  }
};

/// The 8 bytes of an SDO frame. Errors: unexpected_frame (remote frame), bad_length (DLC not 8
/// or an invalid frame).
[[nodiscard]] constexpr result<payload> payload_of(const can_frame &f) noexcept {
  FIELDCODEC_TRY_STATUS(expect_data(f, 8));
  return f.data;
}

/// Decode an SDO frame sent in direction `d` (the COB-ID is not checked).
/// Errors: those of payload_of and decode.
[[nodiscard]] constexpr result<message> decode(const can_frame &f, direction d) noexcept {
  FIELDCODEC_TRY_STATUS(expect_data(f, 8)); // payload_of's check, without copying the bytes
  return decode(f.data, d);
}

/// What an expedited download request carries (client → server, 0x22 / 0x23 / 0x27 / 0x2B /
/// 0x2F): the object, 1..4 data bytes and their value (little-endian, unused bytes not read).
struct expedited_write {
  od::address address{};
  std::uint8_t size = 0; ///< data bytes, 1..4 (4 without size indication)
  bool size_indicated = false;
  std::uint32_t value = 0;

  friend constexpr bool operator==(const expedited_write &,
                                   const expedited_write &) noexcept = default;
};

/// A server's hot path: read an expedited download request straight from the frame, without
/// building a `message` (`decode` gives the same object, size and bytes for such a frame).
/// Errors: those of payload_of; unexpected_frame (a valid SDO request of another kind, or a
/// byte 0 that is no request; `decode` tells them apart).
[[nodiscard]] constexpr result<expedited_write>
decode_expedited_write(const can_frame &f) noexcept {
  FIELDCODEC_TRY_STATUS(expect_data(f, 8));
  const unsigned b0 = f.data[0];
  if ((b0 & 0xE2U) != 0x22U) return errc::unexpected_frame;
  const bool indicated = (b0 & 0x01U) != 0U;
  const unsigned n = indicated ? (b0 >> 2U) & 3U : 0U;
  return expedited_write{detail::get_address(f.data), static_cast<std::uint8_t>(4U - n), indicated,
                         detail::get_u32(f.data) & (0xFFFF'FFFFU >> (8U * n))};
}

/// A decoded frame of the predefined connection set with its node and direction.
struct addressed {
  std::uint8_t node;
  direction dir;
  message m;
};

/// Decode any SDO frame of the predefined connection set (0x581..0x5FF, 0x601..0x67F): the
/// COB-ID gives node and direction. Errors: unexpected_frame (another COB-ID, remote frame),
/// bad_length, unknown_command.
[[nodiscard]] constexpr result<addressed> decode(const can_frame &f) noexcept {
  direction d = direction::to_client;
  std::uint16_t base = cob_id::sdo_tx_base;
  if (f.id > cob_id::sdo_rx_base && f.id <= cob_id::sdo_rx_base + max_node_id) {
    d = direction::to_server;
    base = cob_id::sdo_rx_base;
  } else if (f.id <= cob_id::sdo_tx_base || f.id > cob_id::sdo_tx_base + max_node_id) {
    return errc::unexpected_frame;
  }
  auto m = decode(f, d);
  if (!m) return m.error();
  return addressed{static_cast<std::uint8_t>(f.id - base), d, m.value()};
}

} // namespace fieldcodec::canopen::sdo
