// fieldcodec — reading and writing a DPQ parameter by its descriptor with expedited SDO
// (manual RE 30146-02-Z, 3.3 "SDO - general description" and 3.4 "Starting the PDO
// transmission").
//
//   dpq::write_request(5, p::inj_p_limit_1, 4.0)   → 0x605: 23 23 20 00 1F 05 00 00
//   dpq::read_request(5, p::inj_p_limit_1)         → 0x605: 40 23 20 00 00 00 00 00
//   dpq::read_response(5, p::inj_p_limit_1, f)     ← 0x585: 43 23 20 00 1F 05 00 00 → 4.001
//
// Every DPQ parameter has 2 or 4 bytes, so expedited transfer always suffices. Writes are sent
// with size indication (0x2B for 2 bytes, 0x23 for 4), reads with 0x40. The frames come from
// canopen/sdo.hpp, the values from dpq/parameter.hpp; this header only joins them and checks
// that a response belongs to the request (node, command, index, sub-index, size).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_transfer.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/dpq/parameter.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/entry.hpp>

#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::dpq {

/// Why the card's answer was not the expected one: canopen::sdo::transfer_error, the library's
/// one SDO error with context (docs/contributing.md, "Errors"; `r.is(errc)` and `r == errc` work
/// on a result carrying it).
///   code == aborted: the card sent an SDO abort, `abort` is its code (bytes 4–7), `text()` the
///     CiA 301 description from the one abort table `canopen::sdo::abort_codes`, `cause()` the
///     errc that table maps it to, dpq::describe_sdo_abort(abort) the DPQ manual's wording;
///   otherwise the frame itself was wrong (unexpected_frame, bad_length, …) and `abort` is none.
/// `address` is the object of the request.
using sdo_error = canopen::sdo::transfer_error;

/// What write_response returns.
using sdo_status = result<void, sdo_error>;

namespace detail {
/// The expedited download of `bytes` to `e` on the predefined channel of `node`.
[[nodiscard]] constexpr result<canopen::can_frame>
download_frame(std::uint8_t node, const od::entry &e,
               std::span<const std::uint8_t> bytes) noexcept {
  auto ch = canopen::sdo::channel::default_for(node);
  if (!ch) return ch.error();
  return ch.value().request(canopen::sdo::expedited_download({e.index, e.sub}, bytes));
}
} // namespace detail

/// Expedited download of a raw value. Errors: access_denied (read-only), those of raw_to_bytes,
/// invalid_argument (node not 1..127).
[[nodiscard]] constexpr result<canopen::can_frame>
write_raw_request(std::uint8_t node, const od::descriptor &e, std::int64_t raw) noexcept {
  if (!od::writable(e.access_type)) return errc::access_denied;
  auto p = raw_to_bytes(e, raw);
  if (!p) return p.error();
  return detail::download_frame(node, e, p.value().span());
}

/// Expedited download of an engineering value (decimal, double, float or integer: see
/// dpq::engineering_value). Errors: access_denied, out_of_range, overflow, not_representable,
/// type_mismatch, invalid_argument (node).
template <engineering_value EU>
[[nodiscard]] constexpr result<canopen::can_frame>
write_request(std::uint8_t node, const od::descriptor &e, EU eu) noexcept {
  auto p = write_bytes(e, eu);
  if (!p) return p.error();
  return detail::download_frame(node, e, p.value().span());
}

/// Upload request (command 0x40; the manual's example prints 0x42, see errata DPQ-F1).
/// Errors: access_denied (write-only), invalid_argument (node).
[[nodiscard]] constexpr result<canopen::can_frame> read_request(std::uint8_t node,
                                                                const od::entry &e) noexcept {
  if (!od::readable(e.access_type)) return errc::access_denied;
  auto ch = canopen::sdo::channel::default_for(node);
  if (!ch) return ch.error();
  return ch.value().request(canopen::sdo::initiate_upload({e.index, e.sub}));
}

namespace detail {
/// The response of `node` to a request about `e`, decoded. Errors: unexpected_frame (other
/// COB-ID, other index or sub-index), aborted (the card sent an abort; its code is kept),
/// bad_length, unknown_command, invalid_argument (node).
[[nodiscard]] constexpr result<canopen::sdo::message, sdo_error>
response_for(std::uint8_t node, const od::entry &e, const canopen::can_frame &f) noexcept {
  const od::address at{e.index, e.sub};
  auto ch = canopen::sdo::channel::default_for(node);
  if (!ch) return sdo_error{ch.error(), {}, at};
  if (!ch.value().is_response(f)) return sdo_error{errc::unexpected_frame, {}, at};
  auto m = canopen::sdo::decode(f, canopen::sdo::direction::to_client);
  if (!m) return sdo_error{m.error(), {}, at};
  if (m.value().address != at) return sdo_error{errc::unexpected_frame, {}, at};
  if (m.value().type == canopen::sdo::message_type::abort) {
    return sdo_error{errc::aborted, m.value().abort, at};
  }
  return m.value();
}
} // namespace detail

/// Check the card's answer to a write: a download response (0x60) for the same object.
/// The data bytes of the response are ignored, as the manual says.
/// Errors (sdo_error): those of detail::response_for (an abort keeps its code), unexpected_frame
/// (another kind of response).
[[nodiscard]] constexpr sdo_status write_response(std::uint8_t node, const od::entry &e,
                                                  const canopen::can_frame &f) noexcept {
  auto m = detail::response_for(node, e, f);
  if (!m) return m.error();
  if (m.value().type != canopen::sdo::message_type::initiate_download_response) {
    return sdo_error{errc::unexpected_frame, {}, m.value().address};
  }
  return {};
}

/// The raw value in the card's answer to a read: an expedited upload response for the same
/// object. With size indication the size must be the entry's width (bad_length otherwise);
/// without (0x42) the first width bytes of the four are the value.
/// Errors (sdo_error): those of detail::response_for (an abort keeps its code),
/// unexpected_frame (segmented or another kind), bad_length, type_mismatch.
[[nodiscard]] constexpr result<std::int64_t, sdo_error>
read_raw_response(std::uint8_t node, const od::entry &e, const canopen::can_frame &f) noexcept {
  auto m = detail::response_for(node, e, f);
  if (!m) return m.error();
  const canopen::sdo::message &msg = m.value();
  if (msg.type != canopen::sdo::message_type::initiate_upload_response || !msg.expedited) {
    return sdo_error{errc::unexpected_frame, {}, msg.address};
  }
  const std::uint32_t w = e.width();
  if (w == 0U || w > 4U) return sdo_error{errc::type_mismatch, {}, msg.address};
  if (msg.size_indicated && msg.size != w) return sdo_error{errc::bad_length, {}, msg.address};
  const auto bytes = msg.value_bytes();
  auto raw = raw_from_bytes(e, std::span<const std::uint8_t>(bytes).first(w));
  if (!raw) return sdo_error{raw.error(), {}, msg.address};
  return raw.value();
}

/// The engineering value in the card's answer to a read (exact, round-trip places).
/// Errors (sdo_error): those of read_raw_response and to_eu_decimal.
[[nodiscard]] constexpr result<decimal, sdo_error>
read_response(std::uint8_t node, const od::descriptor &e, const canopen::can_frame &f) noexcept {
  auto raw = read_raw_response(node, e, f);
  if (!raw) return raw.error();
  auto eu = to_eu_decimal(e, raw.value());
  if (!eu) return sdo_error{eu.error(), {}, od::address{e.index, e.sub}};
  return eu.value();
}

} // namespace fieldcodec::dpq
