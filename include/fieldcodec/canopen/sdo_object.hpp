// fieldcodec — SDO messages for dictionary entries: typed, limit-checked expedited download,
// upload request, and the value of an expedited upload response (as an od::number or as a
// C++ type: upload_value<std::int16_t>(entry, response)).
//
//   // my_drive: a generated dictionary with 6060h (INTEGER8) and 6040h (UNSIGNED16)
//   auto f = canopen::sdo::download(1, my_drive::modes_of_operation, -1);
//   // 0x601: 2F 60 60 00 FF 00 00 00
//   auto p = canopen::sdo::download(my_drive::controlword, 0x0F);   // the 8 bytes only
// Values longer than 4 bytes go through sdo::client (segmented or block transfer).
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

/// Expedited download of `value` to entry `e`. `value` may be of any arithmetic or enumeration
/// type: it is taken as the number it is (never converted to the entry's type first) and checked
/// against the entry's limits and field (od::encode rules), so nothing narrows or wraps silently
/// (0xFF as a uint8_t is 255, too large for an INTEGER8; −1 for an UNSIGNED8 overflows).
/// `e` is an od::entry or an od::descriptor (a scaled entry's limits need the descriptor);
/// node-ID-relative limits are checked for `node` (od::any_node: for any node).
/// Errors: those of od::encode (out_of_range, overflow, type_mismatch, not_representable,
/// invalid_argument), access_denied (read-only or constant entry), too_long (more than 4 bytes:
/// use the client).
template <class E, od::value_type T>
requires std::derived_from<E, od::entry>
[[nodiscard]] constexpr result<payload> download(const E &e, T value,
                                                 std::uint8_t node = od::any_node) noexcept {
  if (!od::writable(e.access_type)) return errc::access_denied;
  if (od::fixed_size(e.type) > 4U || od::fixed_size(e.type) == 0U) return errc::too_long;
  std::array<std::uint8_t, 8> b{};
  auto n = od::encode(e, value, b, byte_order::little, node);
  if (!n) return n.error();
  return expedited_download({e.index, e.sub}, std::span<const std::uint8_t>(b).first(n.value()));
}
/// The same as a frame on channel `ch`.
template <class E, od::value_type T>
requires std::derived_from<E, od::entry>
[[nodiscard]] constexpr result<can_frame> download(const channel &ch, const E &e,
                                                   T value) noexcept {
  return ch.request(download(e, value));
}
/// The same as a frame to the server of `node` (predefined channel). Errors: invalid_argument
/// (node not 1..127) and those above.
template <class E, od::value_type T>
requires std::derived_from<E, od::entry>
[[nodiscard]] constexpr result<can_frame> download(std::uint8_t node, const E &e,
                                                   T value) noexcept {
  auto ch = channel::default_for(node);
  if (!ch) return ch.error();
  return ch.value().request(download(e, value, node));
}

/// Initiate upload of entry `e`. Errors: access_denied (write-only).
[[nodiscard]] constexpr result<payload> upload(const od::entry &e) noexcept {
  if (!od::readable(e.access_type)) return errc::access_denied;
  return initiate_upload({e.index, e.sub});
}
/// The same as a frame to the server of `node`. Errors: access_denied, invalid_argument.
[[nodiscard]] constexpr result<can_frame> upload(std::uint8_t node, const od::entry &e) noexcept {
  auto ch = channel::default_for(node);
  if (!ch) return ch.error();
  return ch.value().request(upload(e));
}

/// The value in an expedited upload response for entry `e`.
/// Errors: aborted (an abort message), unexpected_frame (another kind of message, another
/// object, or a segmented response), bad_length (indicated size differs from the type's size),
/// type_mismatch, those of decode and od::decode (limits are not checked: the device reports
/// what it has).
[[nodiscard]] constexpr result<od::number> upload_value(const od::entry &e,
                                                        const payload &p) noexcept {
  auto m = decode(p, direction::to_client);
  if (!m) return m.error();
  const message &r = m.value();
  if (r.type == message_type::abort) return errc::aborted;
  if (r.type != message_type::initiate_upload_response || !r.expedited) {
    return errc::unexpected_frame;
  }
  if (r.address != od::address{e.index, e.sub}) return errc::unexpected_frame;
  const std::size_t w = od::fixed_size(e.type);
  if (w == 0U || w > 4U) return errc::type_mismatch;
  if (r.size_indicated && r.size != w) return errc::bad_length;
  const auto bytes = r.value_bytes();
  return od::decode(e, std::span<const std::uint8_t>(bytes).first(w), byte_order::little,
                    od::limits::ignore);
}
/// The same from a frame (the COB-ID is not checked). Errors: also bad_length (DLC not 8),
/// unexpected_frame (remote frame).
[[nodiscard]] constexpr result<od::number> upload_value(const od::entry &e,
                                                        const can_frame &f) noexcept {
  auto p = payload_of(f);
  if (!p) return p.error();
  return upload_value(e, p.value());
}

/// The value in an expedited upload response for entry `e` as a T (bool, any integer type,
/// float, double or an enumeration), never narrowed: od::number_as<T> of upload_value(e, p), so
/// `upload_value<std::uint8_t>(unsigned16_entry, p)` of 0x0100 is overflow, not 0, and
/// `upload_value<std::uint32_t>(integer32_entry, p)` of −1 is overflow, not 0xFFFFFFFF.
/// Errors: those of upload_value, overflow (the value is outside T's range, a negative value
/// for an unsigned T), not_representable (a REAL32 value for an integer T, an integer beyond
/// 24 significant bits for a float).
template <od::value_type T>
[[nodiscard]] constexpr result<T> upload_value(const od::entry &e, const payload &p) noexcept {
  auto n = upload_value(e, p);
  if (!n) return n.error();
  return od::number_as<T>(n.value());
}
/// The same from a frame (the COB-ID is not checked).
template <od::value_type T>
[[nodiscard]] constexpr result<T> upload_value(const od::entry &e, const can_frame &f) noexcept {
  auto n = upload_value(e, f);
  if (!n) return n.error();
  return od::number_as<T>(n.value());
}

} // namespace fieldcodec::canopen::sdo
