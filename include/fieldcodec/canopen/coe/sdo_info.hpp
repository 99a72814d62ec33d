// fieldcodec — SDO information (ETG.1000.6 5.6.3): reading a slave's object dictionary over
// CoE: the lists of objects, an object's description, an entry's description, and the error
// reply; responses longer than a mailbox travel in fragments.
//
// After the CoE header (service 8) every SDO information mailbox has a 4-byte header:
//   byte 0      bits 0..6 opcode, bit 7 incomplete (more fragments follow)
//   byte 1      reserved
//   bytes 2..3  fragments left (little-endian): how many fragments follow this one
// then the service data:
//   1 get OD list request           list type (u16): 0 the length of every list, 1 all objects,
//                                   2 RxPDO-mappable, 3 TxPDO-mappable, 4 stored for device
//                                   replacement, 5 startup parameters
//   2 get OD list response          list type (u16), then the indices (u16 each); for list
//                                   type 0 the five lengths of lists 1..5
//   3 get object description req.   index (u16)
//   4 get object description resp.  index (u16), data type (u16), max sub-index (u8), object
//                                   code (u8), name (the rest)
//   5 get entry description req.    index (u16), sub-index (u8), value info (u8)
//   6 get entry description resp.   index (u16), sub-index (u8), value info (u8), data type
//                                   (u16), bit length (u16), object access (u16), then the data
//                                   the value info asked for and the name (the rest)
//   7 SDO information error         abort code (u32): the SDO abort codes
// A response larger than a mailbox is cut into fragments: the service data (as one run of
// bytes) are split, each fragment repeats the CoE and information headers, "fragments left"
// counts down to 0 and "incomplete" is set on every fragment but the last. `fragmenter` cuts a
// response, `reassembler` joins one; the response decoders below read the joined data.
#pragma once

#include <fieldcodec/canopen/coe/mailbox.hpp>
#include <fieldcodec/canopen/coe/service.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>

namespace fieldcodec::canopen::coe {

/// Bytes of the SDO information header.
inline constexpr std::size_t info_header_size = 4;

/// The SDO information services.
enum class info_opcode : std::uint8_t {
  get_od_list_request = 1,
  get_od_list_response = 2,
  get_object_description_request = 3,
  get_object_description_response = 4,
  get_entry_description_request = 5,
  get_entry_description_response = 6,
  error = 7, ///< SDO information error request (an abort code)
};

/// The lists of a get OD list request.
enum class list_type : std::uint16_t {
  lengths = 0, ///< the number of objects in each of the lists below
  all = 1,     ///< all objects
  rxpdo = 2,   ///< objects mappable in an RxPDO
  txpdo = 3,   ///< objects mappable in a TxPDO
  backup = 4,  ///< objects stored for device replacement
  startup = 5, ///< startup parameters
};
inline constexpr std::uint16_t max_list_type = 5;

/// Value info bits of an entry description: which values follow the fixed part.
namespace value_info {
inline constexpr std::uint8_t unit_type = 0x08;
inline constexpr std::uint8_t default_value = 0x10;
inline constexpr std::uint8_t minimum = 0x20;
inline constexpr std::uint8_t maximum = 0x40;
} // namespace value_info

/// Object access bits of an entry description.
namespace object_access {
inline constexpr std::uint16_t read_preop = 0x0001;
inline constexpr std::uint16_t read_safeop = 0x0002;
inline constexpr std::uint16_t read_op = 0x0004;
inline constexpr std::uint16_t write_preop = 0x0008;
inline constexpr std::uint16_t write_safeop = 0x0010;
inline constexpr std::uint16_t write_op = 0x0020;
inline constexpr std::uint16_t rxpdo_mappable = 0x0040;
inline constexpr std::uint16_t txpdo_mappable = 0x0080;
inline constexpr std::uint16_t backup = 0x0100;
inline constexpr std::uint16_t settings = 0x0200;
inline constexpr std::uint16_t read = read_preop | read_safeop | read_op;
inline constexpr std::uint16_t write = write_preop | write_safeop | write_op;
} // namespace object_access

/// The SDO information header.
struct info_header {
  info_opcode opcode = info_opcode::get_od_list_request;
  bool incomplete = false;          ///< more fragments follow
  std::uint16_t fragments_left = 0; ///< how many
  friend constexpr bool operator==(const info_header &, const info_header &) = default;
};

/// A received SDO information mailbox (one fragment of a response).
struct info_message {
  mailbox_header mailbox{};
  info_header header{};
  std::span<const std::uint8_t> data{}; ///< this fragment's service data
};

/// Read an SDO information mailbox. Errors: those of decode_coe, unexpected_frame (another
/// service), truncated (fewer than 4 bytes after the CoE header), unknown_command (opcode 0 or
/// over 7).
[[nodiscard]] constexpr result<info_message>
decode_info(std::span<const std::uint8_t> bytes) noexcept {
  FIELDCODEC_TRY(const coe_message c, decode_coe(bytes));
  if (c.coe.svc != service::sdo_information) return errc::unexpected_frame;
  if (c.body.size() < info_header_size) return errc::truncated;
  const unsigned op = c.body[0] & 0x7FU;
  if (op < 1U || op > 7U) return errc::unknown_command;
  info_header h{static_cast<info_opcode>(op), (c.body[0] & 0x80U) != 0U,
                from_bytes<std::uint16_t>({c.body[2], c.body[3]}, byte_order::little)};
  return info_message{c.mailbox, h, c.body.subspan(info_header_size)};
}

/// Write an SDO information mailbox with `data` after the headers. Returns the bytes written.
/// Errors: invalid_argument (an opcode not listed), those of write_coe_header.
[[nodiscard]] constexpr result<std::size_t>
encode_info(std::span<std::uint8_t> out, std::uint8_t counter, const mailbox_options &o,
            const info_header &h, std::span<const std::uint8_t> data) noexcept {
  const auto op = static_cast<unsigned>(h.opcode);
  if (op < 1U || op > 7U) return errc::invalid_argument;
  FIELDCODEC_TRY(const std::span<std::uint8_t> body,
                 write_coe_header(out, counter, o, {0, service::sdo_information},
                                  info_header_size + data.size()));
  body[0] = static_cast<std::uint8_t>(op | (h.incomplete ? 0x80U : 0U));
  body[1] = 0;
  const auto fl = to_bytes<std::uint16_t>(h.fragments_left, byte_order::little);
  body[2] = fl[0];
  body[3] = fl[1];
  for (std::size_t i = 0; i < data.size(); ++i) body[info_header_size + i] = data[i];
  return header_size + coe_header_size + info_header_size + data.size();
}

// ---------------------------------------------------------------------------------------------
// Requests (and the error reply): one mailbox each

/// Write a get OD list request. Errors: out_of_range (list type over 5), those of encode_info.
[[nodiscard]] constexpr result<std::size_t> encode_get_od_list(std::span<std::uint8_t> out,
                                                               std::uint8_t counter,
                                                               const mailbox_options &o,
                                                               list_type t) noexcept {
  if (static_cast<std::uint16_t>(t) > max_list_type) return errc::out_of_range;
  const auto b = to_bytes<std::uint16_t>(static_cast<std::uint16_t>(t), byte_order::little);
  return encode_info(out, counter, o, {info_opcode::get_od_list_request, false, 0}, b);
}
/// Write a get object description request for `index`.
[[nodiscard]] constexpr result<std::size_t>
encode_get_object_description(std::span<std::uint8_t> out, std::uint8_t counter,
                              const mailbox_options &o, std::uint16_t index) noexcept {
  const auto b = to_bytes<std::uint16_t>(index, byte_order::little);
  return encode_info(out, counter, o, {info_opcode::get_object_description_request, false, 0}, b);
}
/// Write a get entry description request for `a` asking for the values `info` names
/// (value_info bits; 0: the fixed part and the name only).
[[nodiscard]] constexpr result<std::size_t>
encode_get_entry_description(std::span<std::uint8_t> out, std::uint8_t counter,
                             const mailbox_options &o, od::address a, std::uint8_t info) noexcept {
  const auto i = to_bytes<std::uint16_t>(a.index, byte_order::little);
  const std::array<std::uint8_t, 4> b{i[0], i[1], a.sub, info};
  return encode_info(out, counter, o, {info_opcode::get_entry_description_request, false, 0}, b);
}
/// Write an SDO information error with abort code `code`.
[[nodiscard]] constexpr result<std::size_t> encode_info_error(std::span<std::uint8_t> out,
                                                              std::uint8_t counter,
                                                              const mailbox_options &o,
                                                              sdo::abort_code code) noexcept {
  const auto b = to_bytes<std::uint32_t>(static_cast<std::uint32_t>(code), byte_order::little);
  return encode_info(out, counter, o, {info_opcode::error, false, 0}, b);
}

namespace detail {
/// The data of a request of opcode `op`: exactly `n` bytes in a single fragment.
[[nodiscard]] constexpr result<std::span<const std::uint8_t>>
request_data(const info_message &m, info_opcode op, std::size_t n) noexcept {
  if (m.header.opcode != op) return errc::unexpected_frame;
  if (m.header.incomplete || m.header.fragments_left != 0U) return errc::bad_length;
  if (m.data.size() < n) return errc::truncated;
  if (m.data.size() > n) return errc::too_long;
  return m.data;
}
} // namespace detail

/// The list type of a get OD list request. Errors: unexpected_frame (another opcode),
/// bad_length (marked as fragmented), truncated, too_long, out_of_range (list type over 5).
[[nodiscard]] constexpr result<list_type> decode_get_od_list(const info_message &m) noexcept {
  FIELDCODEC_TRY(const auto d, detail::request_data(m, info_opcode::get_od_list_request, 2));
  const std::uint16_t t = from_bytes<std::uint16_t>({d[0], d[1]}, byte_order::little);
  if (t > max_list_type) return errc::out_of_range;
  return static_cast<list_type>(t);
}
/// The index of a get object description request. Errors: as decode_get_od_list (but
/// out_of_range).
[[nodiscard]] constexpr result<std::uint16_t>
decode_get_object_description(const info_message &m) noexcept {
  FIELDCODEC_TRY(const auto d,
                 detail::request_data(m, info_opcode::get_object_description_request, 2));
  return from_bytes<std::uint16_t>({d[0], d[1]}, byte_order::little);
}
/// What a get entry description request asks for.
struct entry_request {
  od::address address{};
  std::uint8_t info = 0; ///< value_info bits
  friend constexpr bool operator==(const entry_request &, const entry_request &) = default;
};
[[nodiscard]] constexpr result<entry_request>
decode_get_entry_description(const info_message &m) noexcept {
  FIELDCODEC_TRY(const auto d,
                 detail::request_data(m, info_opcode::get_entry_description_request, 4));
  return entry_request{{from_bytes<std::uint16_t>({d[0], d[1]}, byte_order::little), d[2]}, d[3]};
}
/// The abort code of an SDO information error.
[[nodiscard]] constexpr result<sdo::abort_code> decode_info_error(const info_message &m) noexcept {
  FIELDCODEC_TRY(const auto d, detail::request_data(m, info_opcode::error, 4));
  return static_cast<sdo::abort_code>(
      from_bytes<std::uint32_t>({d[0], d[1], d[2], d[3]}, byte_order::little));
}

// ---------------------------------------------------------------------------------------------
// Responses: the service data of a whole response (all fragments joined)

/// A get OD list response: the list type and its indices (for list type 0: the five lengths).
struct od_list {
  list_type type = list_type::all;
  std::span<const std::uint8_t> raw{}; ///< the u16 values, little-endian
  [[nodiscard]] constexpr std::size_t size() const noexcept { return raw.size() / 2U; }
  /// Value `i` (0 ≤ i < size()).
  [[nodiscard]] constexpr std::uint16_t operator[](std::size_t i) const noexcept {
    return from_bytes<std::uint16_t>({raw[2U * i], raw[2U * i + 1U]}, byte_order::little);
  }
};
/// Read a get OD list response's data. Errors: truncated (no list type), bad_length (an odd
/// number of bytes after it; list type 0 with other than five lengths), out_of_range (list
/// type over 5).
[[nodiscard]] constexpr result<od_list> decode_od_list(std::span<const std::uint8_t> d) noexcept {
  if (d.size() < 2U) return errc::truncated;
  const std::uint16_t t = from_bytes<std::uint16_t>({d[0], d[1]}, byte_order::little);
  if (t > max_list_type) return errc::out_of_range;
  const auto raw = d.subspan(2);
  if (raw.size() % 2U != 0U) return errc::bad_length;
  if (t == 0U && raw.size() != 2U * max_list_type) return errc::bad_length;
  return od_list{static_cast<list_type>(t), raw};
}
/// Write a get OD list response's data (list type, then `values`) into `out`; returns the
/// bytes written. Errors: out_of_range (list type), buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> encode_od_list(list_type t,
                                                           std::span<const std::uint16_t> values,
                                                           std::span<std::uint8_t> out) noexcept {
  if (static_cast<std::uint16_t>(t) > max_list_type) return errc::out_of_range;
  byte_writer w(out);
  FIELDCODEC_TRY_STATUS(w.write(static_cast<std::uint16_t>(t), byte_order::little));
  for (const std::uint16_t v : values) FIELDCODEC_TRY_STATUS(w.write(v, byte_order::little));
  return w.size();
}

/// A get object description response.
struct object_description {
  std::uint16_t index = 0;
  std::uint16_t data_type = 0;          ///< CiA 301 data type index (0x0007 UNSIGNED32, …)
  std::uint8_t max_sub = 0;             ///< highest sub-index
  std::uint8_t object_code = 0;         ///< 7 VAR, 8 ARRAY, 9 RECORD
  std::span<const std::uint8_t> name{}; ///< the name's bytes (points into the response)
};
inline constexpr std::size_t object_description_fixed = 6;
/// Read a get object description response's data. Errors: truncated (fewer than 6 bytes).
[[nodiscard]] constexpr result<object_description>
decode_object_description(std::span<const std::uint8_t> d) noexcept {
  if (d.size() < object_description_fixed) return errc::truncated;
  object_description r;
  r.index = from_bytes<std::uint16_t>({d[0], d[1]}, byte_order::little);
  r.data_type = from_bytes<std::uint16_t>({d[2], d[3]}, byte_order::little);
  r.max_sub = d[4];
  r.object_code = d[5];
  r.name = d.subspan(object_description_fixed);
  return r;
}
/// Write a get object description response's data into `out`. Errors: buffer_too_small.
[[nodiscard]] constexpr result<std::size_t>
encode_object_description(const object_description &r, std::span<std::uint8_t> out) noexcept {
  byte_writer w(out);
  FIELDCODEC_TRY_STATUS(w.write(r.index, byte_order::little));
  FIELDCODEC_TRY_STATUS(w.write(r.data_type, byte_order::little));
  FIELDCODEC_TRY_STATUS(w.write_u8(r.max_sub));
  FIELDCODEC_TRY_STATUS(w.write_u8(r.object_code));
  FIELDCODEC_TRY_STATUS(w.write_bytes(r.name));
  return w.size();
}

/// A get entry description response. `data` holds what follows the fixed part: the values the
/// value info names — unit type, default, minimum, maximum, in that order, each present when
/// its bit is set — and then the name. The default, minimum and maximum take the entry's bit
/// length rounded up to bytes; `values()` splits them off when the unit type is not among
/// them (fieldcodec's sources do not fix the width of the unit type field, so a response that
/// carries one is left to the caller as `data`).
struct entry_description {
  od::address address{};
  std::uint8_t info = 0;       ///< value_info bits
  std::uint16_t data_type = 0; ///< CiA 301 data type index
  std::uint16_t bit_length = 0;
  std::uint16_t access = 0; ///< object_access bits
  std::span<const std::uint8_t> data{};

  /// The default, minimum and maximum (each empty when not asked for) and the name.
  struct split {
    std::span<const std::uint8_t> default_value{};
    std::span<const std::uint8_t> minimum{};
    std::span<const std::uint8_t> maximum{};
    std::span<const std::uint8_t> name{};
  };
  /// Errors: not_representable (the unit type is present), truncated (fewer bytes than the
  /// values need).
  [[nodiscard]] constexpr result<split> values() const noexcept {
    if ((info & value_info::unit_type) != 0U) return errc::not_representable;
    const std::size_t w = (std::size_t{bit_length} + 7U) / 8U;
    split s;
    std::span<const std::uint8_t> rest = data;
    for (const std::uint8_t bit :
         {value_info::default_value, value_info::minimum, value_info::maximum}) {
      if ((info & bit) == 0U) continue;
      if (rest.size() < w) return errc::truncated;
      const auto v = rest.first(w);
      if (bit == value_info::default_value) s.default_value = v;
      if (bit == value_info::minimum) s.minimum = v;
      if (bit == value_info::maximum) s.maximum = v;
      rest = rest.subspan(w);
    }
    s.name = rest;
    return s;
  }
};
inline constexpr std::size_t entry_description_fixed = 10;
/// Read a get entry description response's data. Errors: truncated (fewer than 10 bytes).
[[nodiscard]] constexpr result<entry_description>
decode_entry_description(std::span<const std::uint8_t> d) noexcept {
  if (d.size() < entry_description_fixed) return errc::truncated;
  entry_description r;
  r.address = {from_bytes<std::uint16_t>({d[0], d[1]}, byte_order::little), d[2]};
  r.info = d[3];
  r.data_type = from_bytes<std::uint16_t>({d[4], d[5]}, byte_order::little);
  r.bit_length = from_bytes<std::uint16_t>({d[6], d[7]}, byte_order::little);
  r.access = from_bytes<std::uint16_t>({d[8], d[9]}, byte_order::little);
  r.data = d.subspan(entry_description_fixed);
  return r;
}
/// Write a get entry description response's data (the fixed part, then `r.data`) into `out`.
/// Errors: buffer_too_small.
[[nodiscard]] constexpr result<std::size_t>
encode_entry_description(const entry_description &r, std::span<std::uint8_t> out) noexcept {
  byte_writer w(out);
  FIELDCODEC_TRY_STATUS(w.write(r.address.index, byte_order::little));
  FIELDCODEC_TRY_STATUS(w.write_u8(r.address.sub));
  FIELDCODEC_TRY_STATUS(w.write_u8(r.info));
  FIELDCODEC_TRY_STATUS(w.write(r.data_type, byte_order::little));
  FIELDCODEC_TRY_STATUS(w.write(r.bit_length, byte_order::little));
  FIELDCODEC_TRY_STATUS(w.write(r.access, byte_order::little));
  FIELDCODEC_TRY_STATUS(w.write_bytes(r.data));
  return w.size();
}

// ---------------------------------------------------------------------------------------------
// Fragments

/// Service data bytes one fragment holds in a mailbox of `mailbox_size` bytes (mailbox_size −
/// 12; 0 for a mailbox of 12 bytes or fewer).
[[nodiscard]] constexpr std::size_t info_capacity(std::size_t mailbox_size) noexcept {
  constexpr std::size_t headers = header_size + coe_header_size + info_header_size;
  return mailbox_size > headers ? mailbox_size - headers : 0U;
}

/// Cuts the service data of a response into the fragments of a mailbox size.
class fragmenter {
public:
  /// Fragments of `data` (a response's whole service data) for opcode `op`, in mailboxes of
  /// `mailbox_size` bytes. `data` is borrowed.
  constexpr fragmenter(info_opcode op, std::span<const std::uint8_t> data,
                       std::size_t mailbox_size) noexcept
      : op_(op), data_(data), capacity_(info_capacity(mailbox_size)) {}

  /// How many fragments the response takes (at least 1); 0 when the mailbox holds no data
  /// byte (and the data are not empty) or more than 65536 fragments would be needed.
  [[nodiscard]] constexpr std::size_t count() const noexcept {
    if (data_.empty()) return 1;
    if (capacity_ == 0U) return 0;
    const std::size_t n = (data_.size() + capacity_ - 1U) / capacity_;
    return n > std::size_t{max_length} + 1U ? 0U : n;
  }
  /// Write fragment `k` (0 ≤ k < count()) into `out`; returns the bytes written.
  /// Errors: out_of_range (k not below count()), those of encode_info.
  [[nodiscard]] constexpr result<std::size_t> write(std::size_t k, std::span<std::uint8_t> out,
                                                    std::uint8_t counter,
                                                    const mailbox_options &o) const noexcept {
    const std::size_t n = count();
    if (k >= n) return errc::out_of_range;
    const std::size_t from = k * capacity_;
    const std::size_t len = data_.size() - from < capacity_ ? data_.size() - from : capacity_;
    const auto left = static_cast<std::uint16_t>(n - 1U - k);
    return encode_info(out, counter, o, {op_, left != 0U, left}, data_.subspan(from, len));
  }

private:
  info_opcode op_;
  std::span<const std::uint8_t> data_;
  std::size_t capacity_;
};

/// Joins the fragments of a response into a caller's buffer.
class reassembler {
public:
  /// Join into `buffer` (borrowed).
  constexpr explicit reassembler(std::span<std::uint8_t> buffer) noexcept : buf_(buffer) {}

  /// Take the next fragment. Returns true when it was the last one (data() then holds the
  /// response), false when more follow. An SDO information error ends the response: the
  /// result is aborted and abort() gives its code. Errors: aborted, unexpected_frame (an opcode
  /// that is no response, or not that of the first fragment; fragments left not one less than
  /// before), bad_length (the incomplete flag disagrees with fragments left), buffer_too_small,
  /// bad_state (called again after the last fragment or an error: reset() first).
  [[nodiscard]] constexpr result<bool> take(const info_message &m) noexcept {
    if (ended_) return errc::bad_state;
    if (m.header.opcode == info_opcode::error) {
      ended_ = true;
      auto code = decode_info_error(m);
      abort_ = code ? code.value() : sdo::abort_code::general_error;
      return errc::aborted;
    }
    const auto op = static_cast<unsigned>(m.header.opcode);
    if (op % 2U != 0U) return fail(errc::unexpected_frame); // a request
    if (started_ && (m.header.opcode != op_ || m.header.fragments_left + 1U != left_)) {
      return fail(errc::unexpected_frame);
    }
    if (m.header.incomplete != (m.header.fragments_left != 0U)) return fail(errc::bad_length);
    if (m.data.size() > buf_.size() - size_) return fail(errc::buffer_too_small);
    for (std::size_t i = 0; i < m.data.size(); ++i) buf_[size_ + i] = m.data[i];
    size_ += m.data.size();
    started_ = true;
    op_ = m.header.opcode;
    left_ = m.header.fragments_left;
    if (left_ != 0U) return false;
    ended_ = true;
    return true;
  }
  /// The joined service data so far.
  [[nodiscard]] constexpr std::span<const std::uint8_t> data() const noexcept {
    return std::span<const std::uint8_t>(buf_).first(size_);
  }
  /// The opcode of the response (that of its first fragment).
  [[nodiscard]] constexpr info_opcode opcode() const noexcept { return op_; }
  /// The abort code of an SDO information error (none before one).
  [[nodiscard]] constexpr sdo::abort_code abort() const noexcept { return abort_; }
  /// Start again for the next response.
  constexpr void reset() noexcept {
    size_ = 0;
    left_ = 0;
    started_ = false;
    ended_ = false;
    abort_ = sdo::abort_code::none;
  }

private:
  [[nodiscard]] constexpr result<bool> fail(errc e) noexcept {
    ended_ = true;
    return e;
  }
  std::span<std::uint8_t> buf_;
  std::size_t size_ = 0;
  std::uint16_t left_ = 0;
  info_opcode op_ = info_opcode::get_od_list_response;
  bool started_ = false;
  bool ended_ = false;
  sdo::abort_code abort_ = sdo::abort_code::none;
};

} // namespace fieldcodec::canopen::coe
