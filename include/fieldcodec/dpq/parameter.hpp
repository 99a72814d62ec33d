// fieldcodec — Rexroth VT-HACD-DPQ parameters by descriptor: engineering units ↔ raw ↔ bytes
// for an od::descriptor of the DPQ dictionary (generated from dictionaries/dpq_parameters.csv;
// manual RE 30146-02-Z, 3.3 / 3.4 "Parameter conversion").
//
//   namespace p = fieldcodec::dictionaries::dpq_parameters;
//   p::inj_p_limit_1.to_raw(4.0)                  → 1311            (od::descriptor: range, field)
//   dpq::to_bytes(p::inj_p_limit_1, 4.0)          → 1F 05 00 00     (payload of the field)
//   dpq::from_bytes(p::inj_p_limit_1, bytes)      → 4.001 (decimal) (exact, round-trip places)
//
//   PLC → card:  raw = round((EU − offset) × scale), half away from zero ("arithmetically
//                rounded"), then checked against the printed Min./Max. (errc::out_of_range)
//                and against the field's width and signedness (errc::overflow).
//   card → PLC:  EU = raw / scale + offset.
//
// The conversion itself is the descriptor's (od/descriptor.hpp: to_raw, to_eu → double,
// to_eu_decimal → exact decimal), over core/scaling; the bytes are od::encode / od::decode. What
// this header adds is DPQ's: the payload of a 2- or 4-byte field, the precision at which a value
// read back round-trips (round_trip_places), and a write check that refuses read-only
// parameters. A value whose raw number does not fit the field is refused, never wrapped: the
// card must never see a negative number where a positive one was meant (the warning at the end
// of manual section 3.3).
//
// Binary floating-point inputs: a double is first read as the decimal it stands for with 15
// significant digits (core decimal_from_double), a float as its shortest round-trip decimal
// (decimal_from_float), and that decimal is converted exactly. So 1.001 × 500 gives 500.5 →
// 501, what a person computing by hand gets, and a PLC REAL 90.73 at 327.67 gives 29729. On the
// wire every DPQ value is a 2- or 4-byte integer, least significant byte first (manual chapter 3,
// "Intel format"); padding to the 4 data bytes of an expedited SDO is the SDO layer's job.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/value.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace fieldcodec::dpq {

/// The bytes of one value as they travel: the field's width, least significant byte first.
struct payload {
  std::array<std::uint8_t, 8> bytes{};
  std::uint8_t size = 0;

  [[nodiscard]] constexpr std::span<const std::uint8_t> span() const noexcept {
    return std::span<const std::uint8_t>(bytes.data(), size);
  }
  friend constexpr bool operator==(const payload &a, const payload &b) noexcept {
    if (a.size != b.size) return false;
    for (std::size_t i = 0; i < a.size; ++i) {
      if (a.bytes[i] != b.bytes[i]) return false;
    }
    return true;
  }
};

/// The decimal places at which a value read back round-trips: core/scaling's
/// round_trip_places (327.67 → 3, 10.5 → 2, 16383.5 → 5, 1 → 0).
using scaling::round_trip_places;

/// A raw value as the parameter's bytes (LSB first), checked against the printed range
/// (converted to raw) and the field. Errors: type_mismatch (not an integer type), out_of_range,
/// overflow (does not fit the field).
[[nodiscard]] constexpr result<payload> raw_to_bytes(const od::descriptor &d,
                                                     std::int64_t raw) noexcept {
  payload p;
  auto n = od::detail::encode_integer(d, od::detail::maybe_scale{&d.scale, true},
                                      od::detail::from_int64(raw), std::span<std::uint8_t>(p.bytes),
                                      byte_order::little, od::any_node);
  if (!n) return n.error();
  p.size = static_cast<std::uint8_t>(n.value());
  return p;
}

/// An engineering value `descriptor::to_raw` takes: a decimal, a double, a float or an integer
/// of any type, each read as the number it is (not bool).
template <class EU>
concept engineering_value = requires(const od::descriptor &d, EU eu) {
  d.to_raw(eu);
};

/// EU → bytes: d.to_raw(eu), then raw_to_bytes. Errors: those of both.
template <engineering_value EU>
[[nodiscard]] constexpr result<payload> to_bytes(const od::descriptor &d, EU eu) noexcept {
  FIELDCODEC_TRY(const std::int64_t raw, d.to_raw(eu));
  return raw_to_bytes(d, raw);
}

/// The same for a value that is about to be written: also refuses a read-only parameter.
/// Errors: access_denied, and those of to_bytes.
template <engineering_value EU>
[[nodiscard]] constexpr result<payload> write_bytes(const od::descriptor &d, EU eu) noexcept {
  if (!od::writable(d.access_type)) return errc::access_denied;
  return to_bytes(d, eu);
}

/// The entry's bytes → raw value (sign-extended for a signed type). `in` must hold exactly the
/// field's width. The printed range is not checked (actual values may lie outside a display
/// range). Errors: type_mismatch, truncated, bad_length, overflow (UNSIGNED64 above INT64_MAX).
[[nodiscard]] constexpr result<std::int64_t>
raw_from_bytes(const od::entry &e, std::span<const std::uint8_t> in) noexcept {
  if (!od::is_integer(e.type)) return errc::type_mismatch;
  return od::decode<std::int64_t>(e, in, byte_order::little, od::limits::ignore);
}

/// raw → EU, exactly, at round_trip_places of the parameter's scale (converting the result
/// back gives `raw` again). Errors: those of round_trip_places and to_eu_decimal.
[[nodiscard]] constexpr result<decimal> to_eu_decimal(const od::descriptor &d,
                                                      std::int64_t raw) noexcept {
  auto p = round_trip_places(d.scale);
  if (!p) return p.error();
  return d.to_eu_decimal(raw, p.value());
}

/// Bytes → EU (exact, round-trip places). Errors: those of raw_from_bytes and to_eu_decimal.
[[nodiscard]] constexpr result<decimal> from_bytes(const od::descriptor &d,
                                                   std::span<const std::uint8_t> in) noexcept {
  auto raw = raw_from_bytes(d, in);
  if (!raw) return raw.error();
  return to_eu_decimal(d, raw.value());
}

} // namespace fieldcodec::dpq
