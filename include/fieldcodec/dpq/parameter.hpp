// fieldcodec — DPQ parameters by descriptor: engineering units ↔ raw ↔ bytes for an od::entry
// of the DPQ dictionary (generated from dictionaries/dpq_parameters.csv).
//
//   namespace p = fieldcodec::dictionaries::dpq_parameters;
//   p::inj_p_limit_1.to_raw(4.0)                 → 1311               (od::entry, range + field)
//   dpq::to_bytes(p::inj_p_limit_1, 4.0)         → 1F 05 00 00        (payload of the field)
//   dpq::from_bytes(p::inj_p_limit_1, bytes)     → 4.001 (decimal)    (exact, round-trip places)
//
// A thin layer: the range check, rounding and field check are od::entry::to_raw (core/scaling),
// the bytes are od::encode / od::decode (core/bytes). What it adds: the whole conversion in one
// call, exact decimal read-back at a precision that round-trips, and a write check that refuses
// read-only parameters. See dpq/conversion.hpp for the rules, including double inputs.
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/dpq/conversion.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/value.hpp>

#include <cstdint>
#include <limits>
#include <span>

namespace fieldcodec::dpq {

/// The conversion of an entry. A missing limit becomes the widest decimal (the field check
/// still applies). Errors: type_mismatch (not an integer type), those of number::to_decimal.
[[nodiscard]] constexpr result<conversion> conversion_of(const od::entry &e) noexcept {
  auto f = e.raw_field();
  if (!f) return f.error();
  conversion c;
  c.scale = e.scale;
  c.field = f.value();
  c.range = {decimal{std::numeric_limits<std::int64_t>::min(), 0},
             decimal{std::numeric_limits<std::int64_t>::max(), 0}};
  if (e.low) {
    auto lo = e.low.to_decimal();
    if (!lo) return lo.error();
    c.range.low = lo.value();
  }
  if (e.high) {
    auto hi = e.high.to_decimal();
    if (!hi) return hi.error();
    c.range.high = hi.value();
  }
  return c;
}

/// EU → raw (range, rounding half away from zero, field). Errors: type_mismatch, out_of_range,
/// overflow, not_representable (NaN, infinity).
[[nodiscard]] constexpr result<std::int64_t> to_raw(const od::entry &e, decimal eu) noexcept {
  return e.to_raw(eu);
}
[[nodiscard]] constexpr result<std::int64_t> to_raw(const od::entry &e, double eu) noexcept {
  return e.to_raw(eu);
}

/// A raw value as the entry's bytes (LSB first). Errors: type_mismatch, out_of_range (outside
/// the printed range converted to raw), overflow (does not fit the field).
[[nodiscard]] constexpr result<payload> raw_to_bytes(const od::entry &e,
                                                     std::int64_t raw) noexcept {
  if (!is_integer(e.type)) return errc::type_mismatch;
  payload p;
  auto n = od::encode(e, od::num::i(raw), std::span<std::uint8_t>(p.bytes));
  if (!n) return n.error();
  p.size = static_cast<std::uint8_t>(n.value());
  return p;
}

/// EU → bytes. Errors: those of to_raw and raw_to_bytes.
[[nodiscard]] constexpr result<payload> to_bytes(const od::entry &e, decimal eu) noexcept {
  auto raw = e.to_raw(eu);
  if (!raw) return raw.error();
  return raw_to_bytes(e, raw.value());
}
[[nodiscard]] constexpr result<payload> to_bytes(const od::entry &e, double eu) noexcept {
  auto raw = e.to_raw(eu);
  if (!raw) return raw.error();
  return raw_to_bytes(e, raw.value());
}

/// The same for a value that is about to be written: also refuses a read-only parameter.
/// Errors: access_denied, and those of to_bytes.
[[nodiscard]] constexpr result<payload> write_bytes(const od::entry &e, decimal eu) noexcept {
  if (!od::writable(e.access_type)) return errc::access_denied;
  return to_bytes(e, eu);
}
[[nodiscard]] constexpr result<payload> write_bytes(const od::entry &e, double eu) noexcept {
  if (!od::writable(e.access_type)) return errc::access_denied;
  return to_bytes(e, eu);
}

/// The entry's bytes → raw value. `in` must hold exactly the field's width. The printed range
/// is not checked (actual values may lie outside a display range).
/// Errors: type_mismatch, truncated, bad_length.
[[nodiscard]] constexpr result<std::int64_t>
raw_from_bytes(const od::entry &e, std::span<const std::uint8_t> in) noexcept {
  if (!is_integer(e.type)) return errc::type_mismatch;
  auto n = od::decode(e, in, byte_order::little, od::limits::ignore);
  if (!n) return n.error();
  return n.value().to_int64();
}

/// raw → EU, exactly, at round_trip_places of the entry's scale (converting the result back
/// gives `raw` again). Errors: those of scaling::to_eu_decimal.
[[nodiscard]] constexpr result<decimal> to_eu(const od::entry &e, std::int64_t raw) noexcept {
  auto p = round_trip_places(e.scale);
  if (!p) return p.error();
  return e.to_eu_decimal(raw, p.value());
}

/// Bytes → EU. Errors: those of raw_from_bytes and to_eu.
[[nodiscard]] constexpr result<decimal> from_bytes(const od::entry &e,
                                                   std::span<const std::uint8_t> in) noexcept {
  auto raw = raw_from_bytes(e, in);
  if (!raw) return raw.error();
  return to_eu(e, raw.value());
}

} // namespace fieldcodec::dpq
