// fieldcodec — SDO frames for dictionary entries: typed, limit-checked expedited download,
// upload request, and the value of an expedited upload response.
//
//   auto f = canopen::sdo::download(node, xenax_canopen::modes_of_operation_requested, -1);
//   // 0x601: 2F 60 60 00 FF 00 00 00
// Values longer than 4 bytes go through sdo::client (segmented transfer).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/value.hpp>

#include <array>
#include <concepts>
#include <cstdint>
#include <span>

namespace fieldcodec::canopen::sdo {

/// Expedited download of `value` to entry `e` (od::encode rules: limits, field width).
/// Errors: those of od::encode (out_of_range, overflow, type_mismatch, not_representable),
/// access_denied (read-only or constant entry), too_long (more than 4 bytes: use the client),
/// invalid_argument (node).
/// `e` is an od::entry or an od::descriptor (a scaled entry's limits need the descriptor);
/// node-ID-relative limits are checked for `node`.
template <class E, od::value_type T>
requires std::derived_from<E, od::entry>
[[nodiscard]] constexpr result<can_frame> download(std::uint8_t node, const E &e,
                                                   T value) noexcept {
  if (!od::writable(e.access_type)) return errc::access_denied;
  if (od::fixed_size(e.type) > 4U || od::fixed_size(e.type) == 0U) return errc::too_long;
  std::array<std::uint8_t, 8> b{};
  auto n = od::encode(e, value, b, byte_order::little, node);
  if (!n) return n.error();
  return expedited_download(node, e.index, e.sub,
                            std::span<const std::uint8_t>(b).first(n.value()));
}

/// Initiate upload of entry `e`. Errors: access_denied (write-only), invalid_argument (node).
[[nodiscard]] constexpr result<can_frame> upload(std::uint8_t node, const od::entry &e) noexcept {
  if (!od::readable(e.access_type)) return errc::access_denied;
  return initiate_upload(node, e.index, e.sub);
}

/// The value in an expedited upload response for entry `e`.
/// Errors: aborted (an abort frame), unexpected_frame (another kind of frame, another object,
/// or a segmented response), bad_length (indicated size differs from the type's size), those of
/// decode_response and od::decode (limits are not checked: the device reports what it has).
[[nodiscard]] constexpr result<od::number> upload_value(const od::entry &e,
                                                        const can_frame &f) noexcept {
  auto m = decode_response(f);
  if (!m) return m.error();
  const message &r = m.value();
  if (r.k == kind::abort) return errc::aborted;
  if (r.k != kind::initiate_upload_response || !r.expedited) return errc::unexpected_frame;
  if (r.index != e.index || r.sub != e.sub) return errc::unexpected_frame;
  const std::size_t w = od::fixed_size(e.type);
  if (w == 0U || w > 4U) return errc::type_mismatch;
  if (r.size_indicated && r.data_size != w) return errc::bad_length;
  return od::decode(e, r.bytes().first(w), byte_order::little, od::limits::ignore);
}

} // namespace fieldcodec::canopen::sdo
