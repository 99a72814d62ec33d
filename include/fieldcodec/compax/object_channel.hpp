// fieldcodec — OBJECT_REQ / OBJECT_RSP: object access over the 8-byte process-data channel
// (manual 000, "OBJECT_REQ and OBJECT_RSP for 8 byte process data channel"; fragment 002).
//
// OBJECT_REQ (6 bytes, PAD): byte 1 bit 7 = access (0 write, 1 read), bits 6..0 = the object's
// 7-bit *index pointer* (not its 16-bit index); byte 2 = sub-index; bytes 3..6 = object data
// bytes 1..4 (objects of at most 4 bytes, left aligned, big-endian like on PCP).
// OBJECT_RSP (6 bytes, PED): a write is acknowledged by echoing the request, a read answers
// bytes 1-2 of the request and the object data; an error is byte 1 = 0xFF, byte 2 = sub-index,
// byte 3 = error number (82..85, or a COMPAX error number), bytes 4..6 = 0.
// Every change of OBJECT_REQ is acknowledged by complementing AckToggle (STATUSWORT / CPX_ZSW
// data byte 1 bit 0) once the access is complete. Repeating an identical request requires
// writing index pointer 0 in between (object_channel below does that).
#pragma once

#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace fieldcodec::compax {

inline constexpr std::size_t object_req_size = 6;
inline constexpr std::size_t object_data_max = 4;
/// Largest usable index pointer: 127 with the read bit would read 0xFF, the error marker.
inline constexpr std::uint8_t object_pointer_max = 126;
inline constexpr std::uint8_t object_rsp_error_marker = 0xFF;

using object_frame = std::array<std::uint8_t, object_req_size>;
using object_data = std::array<std::uint8_t, object_data_max>;

enum class object_access : std::uint8_t { write = 0, read = 1 };

/// One OBJECT_REQ. Pointer 0 is the "no object" request used between identical requests.
struct object_request {
  object_access access = object_access::read;
  std::uint8_t pointer = 0;
  std::uint8_t sub = 0;
  object_data data{};

  friend constexpr bool operator==(const object_request &, const object_request &) = default;
};

namespace detail {
/// Pointer (0..126) and sub-index (0..255) of any integer types. Errors: out_of_range.
template <integer_argument P, integer_argument S>
[[nodiscard]] constexpr result<object_request> object_address(object_access a, P pointer,
                                                              S sub) noexcept {
  auto p = checked_narrow<std::uint8_t>(pointer);
  auto s = checked_narrow<std::uint8_t>(sub);
  if (!p || !s || p.value() > object_pointer_max) return errc::out_of_range;
  return object_request{a, p.value(), s.value(), {}};
}
} // namespace detail

/// A read request for `pointer`/`sub` (any integer types; pointer 0 is the "no object" request).
/// Errors: out_of_range (pointer above 126, sub-index above 255 or negative).
template <integer_argument P, integer_argument S = std::uint8_t>
[[nodiscard]] constexpr result<object_request> object_read(P pointer, S sub = 0) noexcept {
  return detail::object_address(object_access::read, pointer, sub);
}

/// A write request; `data` (1..4 bytes, the object's bytes as on PCP) is left aligned.
/// Errors: out_of_range (pointer, sub-index), bad_length (data empty or more than 4 bytes).
template <integer_argument P, integer_argument S>
[[nodiscard]] constexpr result<object_request>
object_write(P pointer, S sub, std::span<const std::uint8_t> data) noexcept {
  auto a = detail::object_address(object_access::write, pointer, sub);
  if (!a) return a.error();
  if (data.empty() || data.size() > object_data_max) return errc::bad_length;
  object_request r = a.value();
  for (std::size_t i = 0; i < data.size(); ++i) r.data[i] = data[i];
  return r;
}

/// OBJECT_REQ bytes. Errors: out_of_range (pointer above 126).
[[nodiscard]] constexpr result<object_frame>
encode_object_request(const object_request &r) noexcept {
  if (r.pointer > object_pointer_max) return errc::out_of_range;
  object_frame f{};
  f[0] = static_cast<std::uint8_t>((r.access == object_access::read ? 0x80U : 0x00U) | r.pointer);
  f[1] = r.sub;
  for (std::size_t i = 0; i < object_data_max; ++i) f[2U + i] = r.data[i];
  return f;
}

/// OBJECT_REQ bytes → request. Errors: truncated, bad_length, out_of_range (0xFF: pointer 127
/// with the read bit, indistinguishable from an error reply).
[[nodiscard]] constexpr result<object_request>
decode_object_request(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < object_req_size) return errc::truncated;
  if (in.size() > object_req_size) return errc::bad_length;
  const auto pointer = static_cast<std::uint8_t>(in[0] & 0x7FU);
  if (pointer > object_pointer_max) return errc::out_of_range;
  object_request r{
      (in[0] & 0x80U) != 0U ? object_access::read : object_access::write, pointer, in[1], {}};
  for (std::size_t i = 0; i < object_data_max; ++i) r.data[i] = in[2U + i];
  return r;
}

/// Error numbers of OBJECT_RSP (others are COMPAX error numbers of the product manual).
enum class object_error : std::uint8_t {
  bad_pointer = 82,  ///< wrong index pointer
  bad_subindex = 83, ///< wrong sub-index
  not_readable = 84, ///< object cannot be read
  not_writable = 85, ///< object cannot be written
};

/// Short text of an OBJECT_RSP error number ("" for a number the interface manual does not list).
[[nodiscard]] constexpr std::string_view to_string(object_error e) noexcept {
  switch (e) {
  case object_error::bad_pointer: return "wrong index pointer";
  case object_error::bad_subindex: return "wrong sub-index";
  case object_error::not_readable: return "object not readable";
  case object_error::not_writable: return "object not writable";
  }
  return "";
}

/// One decoded OBJECT_RSP.
struct object_response {
  bool is_error = false;
  object_access access = object_access::read; ///< meaningless for an error
  std::uint8_t pointer = 0;                   ///< meaningless for an error
  std::uint8_t sub = 0;
  object_data data{};            ///< read data or the echoed write data
  std::uint8_t error_number = 0; ///< only for an error (see object_error)

  friend constexpr bool operator==(const object_response &, const object_response &) = default;
};

/// OBJECT_RSP bytes → response. Errors: truncated, bad_length, unexpected_frame (error reply
/// whose bytes 4..6 are not zero).
[[nodiscard]] constexpr result<object_response>
decode_object_response(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < object_req_size) return errc::truncated;
  if (in.size() > object_req_size) return errc::bad_length;
  object_response r{};
  r.sub = in[1];
  if (in[0] == object_rsp_error_marker) {
    if (in[3] != 0U || in[4] != 0U || in[5] != 0U) return errc::unexpected_frame;
    r.is_error = true;
    r.error_number = in[2];
    return r;
  }
  r.access = (in[0] & 0x80U) != 0U ? object_access::read : object_access::write;
  r.pointer = static_cast<std::uint8_t>(in[0] & 0x7FU);
  for (std::size_t i = 0; i < object_data_max; ++i) r.data[i] = in[2U + i];
  return r;
}

/// OBJECT_RSP bytes the drive sends for `r` (for simulators and tests).
[[nodiscard]] constexpr object_frame encode_object_response(const object_response &r) noexcept {
  object_frame f{};
  f[1] = r.sub;
  if (r.is_error) {
    f[0] = object_rsp_error_marker;
    f[2] = r.error_number;
    return f;
  }
  f[0] = static_cast<std::uint8_t>((r.access == object_access::read ? 0x80U : 0x00U) |
                                   (r.pointer & 0x7FU));
  for (std::size_t i = 0; i < object_data_max; ++i) f[2U + i] = r.data[i];
  return f;
}

/// Does `rsp` answer `req`? An error must carry the request's sub-index; a read must echo
/// access, pointer and sub-index; a write must echo all six bytes.
[[nodiscard]] constexpr bool answers(const object_request &req,
                                     const object_response &rsp) noexcept {
  if (rsp.is_error) return rsp.sub == req.sub;
  if (rsp.access != req.access || rsp.pointer != req.pointer || rsp.sub != req.sub) {
    return false;
  }
  return req.access == object_access::read || rsp.data == req.data;
}

/// Non-blocking OBJECT_REQ/OBJECT_RSP handshake. The caller owns it and, every process-data
/// cycle, puts pad() into the OBJECT_REQ bytes of the PAD and feeds the AckToggle bit and the
/// OBJECT_RSP bytes of the PED to poll(). Identical consecutive requests are separated by a
/// request with index pointer 0, as the manual requires. Timeouts are the caller's business
/// (cancel() drops a pending request).
class object_channel {
public:
  enum class phase : std::uint8_t { idle, clearing, waiting };

  /// `ack_toggle` is the current AckToggle bit (the reference for the first change).
  constexpr explicit object_channel(bool ack_toggle = false) noexcept : toggle_(ack_toggle) {}

  /// Start a request. Errors: bad_state (one is pending), invalid_argument (pointer 0),
  /// out_of_range (pointer above 126).
  [[nodiscard]] constexpr status submit(const object_request &r, bool ack_toggle) noexcept {
    if (phase_ != phase::idle) return errc::bad_state;
    if (r.pointer == 0U) return errc::invalid_argument;
    auto f = encode_object_request(r);
    if (!f) return f.error();
    request_ = r;
    toggle_ = ack_toggle;
    if (f.value() == pad_) {
      pad_[0] = static_cast<std::uint8_t>(pad_[0] & 0x80U); // same request again: pointer 0 first
      phase_ = phase::clearing;
    } else {
      pad_ = f.value();
      phase_ = phase::waiting;
    }
    return {};
  }

  /// Feed one cycle. Returns the response once the request completed, std::nullopt while it
  /// is pending (or when idle). Errors: unexpected_frame (the reply does not answer the
  /// request, or is malformed); the channel is idle again after an error.
  [[nodiscard]] constexpr result<std::optional<object_response>>
  poll(bool ack_toggle, std::span<const std::uint8_t> object_rsp) noexcept {
    if (phase_ == phase::idle || ack_toggle == toggle_) return std::optional<object_response>{};
    toggle_ = ack_toggle;
    if (phase_ == phase::clearing) {
      pad_ = encode_object_request(request_).value(); // validated in submit()
      phase_ = phase::waiting;
      return std::optional<object_response>{};
    }
    phase_ = phase::idle;
    auto rsp = decode_object_response(object_rsp);
    if (!rsp) return errc::unexpected_frame;
    if (!answers(request_, rsp.value())) return errc::unexpected_frame;
    return std::optional<object_response>{rsp.value()};
  }

  /// Drop a pending request (e.g. after a timeout). The PAD keeps its last bytes.
  constexpr void cancel() noexcept { phase_ = phase::idle; }

  /// The OBJECT_REQ bytes to send this cycle.
  [[nodiscard]] constexpr const object_frame &pad() const noexcept { return pad_; }
  [[nodiscard]] constexpr phase current_phase() const noexcept { return phase_; }
  [[nodiscard]] constexpr bool busy() const noexcept { return phase_ != phase::idle; }

private:
  object_request request_{};
  object_frame pad_{};
  bool toggle_ = false;
  phase phase_ = phase::idle;
};

} // namespace fieldcodec::compax
