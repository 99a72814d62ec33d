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
//   data padded to whole words). It is an assumption: the manual shows the fields, not the
//   bytes of the Interbus PCP firmware interface.
#pragma once

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

/// A read request for index/sub-index.
[[nodiscard]] constexpr pcp_request pcp_read(std::uint16_t index, std::uint8_t sub) noexcept {
  pcp_request r{};
  r.service = pcp_service::read_request;
  r.param_counter = pcp_param_counter(r.service, 0);
  r.index = index;
  r.sub = sub;
  return r;
}

/// A write request with the object's data bytes. Errors: bad_length (empty or above 32 bytes).
[[nodiscard]] constexpr result<pcp_request> pcp_write(std::uint16_t index, std::uint8_t sub,
                                                      std::span<const std::uint8_t> data) noexcept {
  if (data.empty() || data.size() > pcp_data_max) return errc::bad_length;
  pcp_request r{};
  r.service = pcp_service::write_request;
  r.index = index;
  r.sub = sub;
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

} // namespace fieldcodec::compax
