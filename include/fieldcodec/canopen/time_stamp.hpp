// fieldcodec — the TIME stamp (CiA 301 TIME, COB-ID 0x100): milliseconds since midnight and
// days since 1984-01-01, as od::time_value.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/value.hpp>

#include <cstdint>
#include <span>

namespace fieldcodec::canopen {

namespace time_stamp {
/// TIME: 0x100 DLC 6 [ms since midnight (28 bits, LE u32), days since 1984-01-01 (LE u16)].
/// Errors: out_of_range (ms >= 2^28).
[[nodiscard]] constexpr result<can_frame> encode(od::time_value t) noexcept {
  if (t.ms > od::time_ms_max) return errc::out_of_range;
  can_frame f;
  f.id = cob_id::time;
  f.dlc = 6;
  (void)store_unsigned(std::span<std::uint8_t>(f.data), 4, t.ms, byte_order::little);
  (void)store_unsigned(std::span<std::uint8_t>(f.data).subspan(4), 2, t.days, byte_order::little);
  return f;
}
/// Errors: unexpected_frame (not 0x100 or a remote frame), bad_length (DLC not 6), out_of_range
/// (reserved bits 28..31 of the milliseconds set).
[[nodiscard]] constexpr result<od::time_value> decode(const can_frame &f) noexcept {
  if (f.id != cob_id::time) return errc::unexpected_frame;
  FIELDCODEC_TRY_STATUS(expect_data(f, 6));
  const auto ms = load_unsigned(f.payload(), 4, byte_order::little).value();
  const auto days = load_unsigned(f.payload().subspan(4), 2, byte_order::little).value();
  if (ms > od::time_ms_max) return errc::out_of_range;
  return od::time_value{static_cast<std::uint32_t>(ms), static_cast<std::uint16_t>(days)};
}
} // namespace time_stamp

} // namespace fieldcodec::canopen
