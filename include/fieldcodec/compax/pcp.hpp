// fieldcodec — PCP read/write service requests as the COMPAX manual's examples print them
// (manual 000, every "Example" box: Service, Command Code, Param. counter, Index, Sub-index,
// Length, data bytes).
//
// Decisions (docs/compax.md, "PCP"):
// * Command code 0x8081 = Read request, 0x8082 = Write request, as printed.
// * The manual never defines the parameter counter. Every consistent example fits: it counts the
//   16-bit words that follow it — one communication-reference/invoke word, the index word, the
//   sub-index/length word and ceil(length / 2) data words. So a read has 3, a write
//   3 + ceil(length / 2). Requests whose counter disagrees are rejected (errc::bad_length);
//   errata CX-21, CX-24, CX-25 are examples the manual prints wrongly.
// * The wire layout of encode_pcp_request() follows that word count (big-endian words: command
//   code, parameter counter, invoke id / communication reference, index, sub-index / length,
//   data padded to whole words, the pad byte 0x00). It is an assumption: the manual shows the
//   fields, not the bytes of the Interbus PCP firmware interface.
//
// Responses (confirmations). The manual prints requests only; the layout of the answer follows
// the PCP service definitions of the Interbus master firmware as drive manuals of the same era
// print them (evidence in docs/compax.md, "PCP responses"):
// * The confirmation carries the command code of its request (0x8081 read, 0x8082 write): the
//   code the COMPAX manual prints for the request is the one those manuals print for the read
//   confirmation; a request and its confirmation travel in opposite directions, so the code
//   does not need to tell them apart.
// * Then the parameter counter (16-bit words after it), the invoke id / communication reference
//   word, and the result word: 0x0000 for a positive confirmation, otherwise error class (high
//   byte) and error code (low byte), followed by the additional code word (counter 3).
// * Read (+): a length word (high byte 0x00, low byte the number of data bytes) and the data
//   padded to whole words (pad byte 0x00): counter 3 + ceil(length / 2).
// * Write (+): nothing after the result word: counter 2.
#pragma once

#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::compax {

enum class pcp_service : std::uint16_t {
  read_request = 0x8081,
  write_request = 0x8082,
};

/// Largest object data of a COMPAX request (P, N and S are 32 bytes; the PDU is 64 bytes).
inline constexpr std::size_t pcp_data_max = 32;

struct pcp_request {
  pcp_service service = pcp_service::read_request;
  std::uint16_t param_counter = 3;
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::uint8_t length = 0; ///< data bytes (0 for a read)
  std::uint8_t invoke_id = 0;
  std::uint8_t comm_ref = 0;
  std::array<std::uint8_t, pcp_data_max> data{};

  [[nodiscard]] constexpr std::span<const std::uint8_t> payload() const noexcept {
    return std::span<const std::uint8_t>{data}.first(length <= pcp_data_max ? length : 0U);
  }
  friend constexpr bool operator==(const pcp_request &, const pcp_request &) = default;
};

/// The parameter counter the rule above gives for a service and data length.
[[nodiscard]] constexpr std::uint16_t pcp_param_counter(pcp_service s,
                                                        std::size_t length) noexcept {
  if (s == pcp_service::read_request) return 3;
  return static_cast<std::uint16_t>(3U + (length + 1U) / 2U);
}

/// Check a request: known service, length within pcp_data_max (0 for a read, ≥ 1 for a write),
/// parameter counter as the rule gives. Errors: unknown_command, bad_length.
[[nodiscard]] constexpr status check_pcp_request(const pcp_request &r) noexcept {
  if (r.service != pcp_service::read_request && r.service != pcp_service::write_request) {
    return errc::unknown_command;
  }
  if (r.length > pcp_data_max) return errc::bad_length;
  if (r.service == pcp_service::read_request && r.length != 0U) return errc::bad_length;
  if (r.service == pcp_service::write_request && r.length == 0U) return errc::bad_length;
  if (r.param_counter != pcp_param_counter(r.service, r.length)) return errc::bad_length;
  return {};
}

/// A read request for index/sub-index (any integer types).
/// Errors: out_of_range (index not 0..0xFFFF, sub-index not 0..255).
template <integer_argument I, integer_argument S>
[[nodiscard]] constexpr result<pcp_request> pcp_read(I index, S sub) noexcept {
  auto i = checked_narrow<std::uint16_t>(index);
  auto s = checked_narrow<std::uint8_t>(sub);
  if (!i || !s) return errc::out_of_range;
  pcp_request r{};
  r.service = pcp_service::read_request;
  r.param_counter = pcp_param_counter(r.service, 0);
  r.index = i.value();
  r.sub = s.value();
  return r;
}

/// A write request with the object's data bytes (index/sub-index of any integer types).
/// Errors: out_of_range (index not 0..0xFFFF, sub-index not 0..255), bad_length (data empty or
/// above 32 bytes).
template <integer_argument I, integer_argument S>
[[nodiscard]] constexpr result<pcp_request> pcp_write(I index, S sub,
                                                      std::span<const std::uint8_t> data) noexcept {
  auto idx = checked_narrow<std::uint16_t>(index);
  auto sx = checked_narrow<std::uint8_t>(sub);
  if (!idx || !sx) return errc::out_of_range;
  if (data.empty() || data.size() > pcp_data_max) return errc::bad_length;
  pcp_request r{};
  r.service = pcp_service::write_request;
  r.index = idx.value();
  r.sub = sx.value();
  r.length = static_cast<std::uint8_t>(data.size());
  r.param_counter = pcp_param_counter(r.service, data.size());
  for (std::size_t i = 0; i < data.size(); ++i) r.data[i] = data[i];
  return r;
}

/// Bytes of a request on the wire (layout: see the header comment).
[[nodiscard]] constexpr std::size_t pcp_request_size(const pcp_request &r) noexcept {
  return 2U * (2U + static_cast<std::size_t>(r.param_counter));
}

/// Write the request into `out`; returns the bytes written.
/// Errors: those of check_pcp_request, buffer_too_small.
[[nodiscard]] constexpr result<std::size_t>
encode_pcp_request(const pcp_request &r, std::span<std::uint8_t> out) noexcept {
  if (auto c = check_pcp_request(r); !c) return c.error();
  byte_writer w{out};
  FIELDCODEC_TRY_STATUS(w.write(static_cast<std::uint16_t>(r.service), byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write(r.param_counter, byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write_u8(r.invoke_id));
  FIELDCODEC_TRY_STATUS(w.write_u8(r.comm_ref));
  FIELDCODEC_TRY_STATUS(w.write(r.index, byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write_u8(r.sub));
  FIELDCODEC_TRY_STATUS(w.write_u8(r.length));
  FIELDCODEC_TRY_STATUS(w.write_bytes(r.payload()));
  if ((r.length & 1U) != 0U) FIELDCODEC_TRY_STATUS(w.write_u8(0));
  return w.size();
}

/// Bytes → request. Errors: truncated, bad_length (counter/length disagree, or bytes left
/// over), unknown_command, unexpected_frame (pad byte after odd-length data not 0x00).
[[nodiscard]] constexpr result<pcp_request>
decode_pcp_request(std::span<const std::uint8_t> in) noexcept {
  byte_reader rd{in};
  auto code = rd.read<std::uint16_t>(byte_order::big);
  auto counter = rd.read<std::uint16_t>(byte_order::big);
  auto invoke = rd.read_u8();
  auto cr = rd.read_u8();
  auto index = rd.read<std::uint16_t>(byte_order::big);
  auto sub = rd.read_u8();
  auto len = rd.read_u8();
  if (!code || !counter || !invoke || !cr || !index || !sub || !len) return errc::truncated;
  pcp_request r{};
  r.service = static_cast<pcp_service>(code.value());
  r.param_counter = counter.value();
  r.invoke_id = invoke.value();
  r.comm_ref = cr.value();
  r.index = index.value();
  r.sub = sub.value();
  r.length = len.value();
  if (auto c = check_pcp_request(r); !c) return c.error();
  auto data = rd.read_bytes(r.length);
  if (!data) return data.error();
  for (std::size_t i = 0; i < r.length; ++i) r.data[i] = data.value()[i];
  if ((r.length & 1U) != 0U) {
    auto pad = rd.read_u8();
    if (!pad) return pad.error();
    if (pad.value() != 0U) return errc::unexpected_frame; // the pad byte is 0x00, as written
  }
  if (!rd.empty()) return errc::bad_length;
  return r;
}

// ------------------------------------------------------------------ responses

/// A PCP confirmation: positive (with the read data) or negative (with the error).
struct pcp_response {
  pcp_service service = pcp_service::read_request; ///< the service confirmed
  std::uint16_t param_counter = 2;
  std::uint8_t invoke_id = 0;
  std::uint8_t comm_ref = 0;
  bool is_error = false;
  std::uint8_t error_class = 0;      ///< negative only (non-zero)
  std::uint8_t error_code = 0;       ///< negative only
  std::uint16_t additional_code = 0; ///< negative only
  std::uint8_t length = 0;           ///< positive read only: data bytes
  std::array<std::uint8_t, pcp_data_max> data{};

  [[nodiscard]] constexpr std::span<const std::uint8_t> payload() const noexcept {
    return std::span<const std::uint8_t>{data}.first(length <= pcp_data_max ? length : 0U);
  }
  friend constexpr bool operator==(const pcp_response &, const pcp_response &) = default;
};

/// The parameter counter of a confirmation (see the header comment).
[[nodiscard]] constexpr std::uint16_t pcp_response_counter(pcp_service s, bool is_error,
                                                           std::size_t length) noexcept {
  if (is_error) return 3;
  if (s == pcp_service::write_request) return 2;
  return static_cast<std::uint16_t>(3U + (length + 1U) / 2U);
}

/// Check a confirmation: known service; a negative one has a non-zero error class and no data;
/// a positive write no data; a positive read at most pcp_data_max bytes; counter as the rule
/// gives. Errors: unknown_command, bad_length, invalid_argument (error fields that contradict
/// is_error).
[[nodiscard]] constexpr status check_pcp_response(const pcp_response &r) noexcept {
  if (r.service != pcp_service::read_request && r.service != pcp_service::write_request) {
    return errc::unknown_command;
  }
  if (r.length > pcp_data_max) return errc::bad_length;
  if (r.is_error) {
    if (r.error_class == 0U) return errc::invalid_argument; // 0x0000 is the positive result
    if (r.length != 0U) return errc::bad_length;
  } else {
    if (r.error_class != 0U || r.error_code != 0U || r.additional_code != 0U) {
      return errc::invalid_argument;
    }
    if (r.service == pcp_service::write_request && r.length != 0U) return errc::bad_length;
  }
  if (r.param_counter != pcp_response_counter(r.service, r.is_error, r.length)) {
    return errc::bad_length;
  }
  return {};
}

/// The positive confirmation of `req` (a read: with `data`; a write: none).
/// Errors: bad_length (read data above 32 bytes, or data for a write), those of
/// check_pcp_request.
[[nodiscard]] constexpr result<pcp_response>
pcp_confirm(const pcp_request &req, std::span<const std::uint8_t> data = {}) noexcept {
  if (auto c = check_pcp_request(req); !c) return c.error();
  if (data.size() > pcp_data_max) return errc::bad_length;
  if (req.service == pcp_service::write_request && !data.empty()) return errc::bad_length;
  pcp_response r{};
  r.service = req.service;
  r.invoke_id = req.invoke_id;
  r.comm_ref = req.comm_ref;
  r.length = static_cast<std::uint8_t>(data.size());
  for (std::size_t i = 0; i < data.size(); ++i) r.data[i] = data[i];
  r.param_counter = pcp_response_counter(r.service, false, data.size());
  return r;
}

/// The negative confirmation of `req`. Errors: invalid_argument (error class 0), those of
/// check_pcp_request.
[[nodiscard]] constexpr result<pcp_response> pcp_refuse(const pcp_request &req,
                                                        std::uint8_t error_class,
                                                        std::uint8_t error_code,
                                                        std::uint16_t additional_code) noexcept {
  if (auto c = check_pcp_request(req); !c) return c.error();
  if (error_class == 0U) return errc::invalid_argument;
  pcp_response r{};
  r.service = req.service;
  r.invoke_id = req.invoke_id;
  r.comm_ref = req.comm_ref;
  r.is_error = true;
  r.error_class = error_class;
  r.error_code = error_code;
  r.additional_code = additional_code;
  r.param_counter = pcp_response_counter(r.service, true, 0);
  return r;
}

/// Does `rsp` confirm `req`? Same service, invoke id and communication reference.
[[nodiscard]] constexpr bool answers(const pcp_request &req, const pcp_response &rsp) noexcept {
  return req.service == rsp.service && req.invoke_id == rsp.invoke_id &&
         req.comm_ref == rsp.comm_ref;
}

/// Bytes of a confirmation on the wire.
[[nodiscard]] constexpr std::size_t pcp_response_size(const pcp_response &r) noexcept {
  return 2U * (2U + static_cast<std::size_t>(r.param_counter));
}

/// Write the confirmation into `out` (for simulators and tests); returns the bytes written.
/// Errors: those of check_pcp_response, buffer_too_small.
[[nodiscard]] constexpr result<std::size_t>
encode_pcp_response(const pcp_response &r, std::span<std::uint8_t> out) noexcept {
  if (auto c = check_pcp_response(r); !c) return c.error();
  byte_writer w{out};
  FIELDCODEC_TRY_STATUS(w.write(static_cast<std::uint16_t>(r.service), byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write(r.param_counter, byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write_u8(r.invoke_id));
  FIELDCODEC_TRY_STATUS(w.write_u8(r.comm_ref));
  if (r.is_error) {
    FIELDCODEC_TRY_STATUS(w.write_u8(r.error_class));
    FIELDCODEC_TRY_STATUS(w.write_u8(r.error_code));
    FIELDCODEC_TRY_STATUS(w.write(r.additional_code, byte_order::big));
    return w.size();
  }
  FIELDCODEC_TRY_STATUS(w.write(std::uint16_t{0}, byte_order::big)); // result (+)
  if (r.service == pcp_service::write_request) return w.size();
  FIELDCODEC_TRY_STATUS(w.write(std::uint16_t{r.length}, byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write_bytes(r.payload()));
  if ((r.length & 1U) != 0U) FIELDCODEC_TRY_STATUS(w.write_u8(0));
  return w.size();
}

/// Bytes → confirmation. Errors: truncated, bad_length (counter and content disagree, data
/// above 32 bytes, or bytes left over), unknown_command (service code), unexpected_frame (the
/// high byte of the length word or the pad byte after odd-length data is not 0x00).
[[nodiscard]] constexpr result<pcp_response>
decode_pcp_response(std::span<const std::uint8_t> in) noexcept {
  byte_reader rd{in};
  auto code = rd.read<std::uint16_t>(byte_order::big);
  auto counter = rd.read<std::uint16_t>(byte_order::big);
  auto invoke = rd.read_u8();
  auto cr = rd.read_u8();
  auto result_hi = rd.read_u8();
  auto result_lo = rd.read_u8();
  if (!code || !counter || !invoke || !cr || !result_hi || !result_lo) return errc::truncated;
  pcp_response r{};
  r.service = static_cast<pcp_service>(code.value());
  if (r.service != pcp_service::read_request && r.service != pcp_service::write_request) {
    return errc::unknown_command;
  }
  r.param_counter = counter.value();
  r.invoke_id = invoke.value();
  r.comm_ref = cr.value();
  if (result_hi.value() != 0U || result_lo.value() != 0U) {
    r.is_error = true;
    r.error_class = result_hi.value();
    r.error_code = result_lo.value();
    if (r.error_class == 0U) return errc::unexpected_frame; // 0x00xx is no error class
    auto add = rd.read<std::uint16_t>(byte_order::big);
    if (!add) return add.error();
    r.additional_code = add.value();
  } else if (r.service == pcp_service::read_request) {
    auto len_hi = rd.read_u8();
    auto len = rd.read_u8();
    if (!len_hi || !len) return errc::truncated;
    if (len_hi.value() != 0U) return errc::unexpected_frame;
    if (len.value() > pcp_data_max) return errc::bad_length;
    r.length = len.value();
    auto data = rd.read_bytes(r.length);
    if (!data) return data.error();
    for (std::size_t i = 0; i < r.length; ++i) r.data[i] = data.value()[i];
    if ((r.length & 1U) != 0U) {
      auto pad = rd.read_u8();
      if (!pad) return pad.error();
      if (pad.value() != 0U) return errc::unexpected_frame;
    }
  }
  if (r.param_counter != pcp_response_counter(r.service, r.is_error, r.length)) {
    return errc::bad_length;
  }
  if (!rd.empty()) return errc::bad_length;
  return r;
}

} // namespace fieldcodec::compax
