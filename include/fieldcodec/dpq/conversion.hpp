// fieldcodec — Rexroth VT-HACD-DPQ parameter conversion (manual RE 30146-02-Z, 3.3 / 3.4).
//
//   PLC → card:  raw = round((EU − offset) × scale), half away from zero ("arithmetically
//                rounded"), then checked against the printed Min./Max. (errc::out_of_range)
//                and against the field's width and signedness (errc::overflow).
//   card → PLC:  EU = raw / scale + offset.
//
// All arithmetic is core/scaling: scale and offset are exact decimals (327,67 is {32767, 2}),
// intermediates are exact, the only rounding is the one the formula asks for. A value whose raw
// number does not fit the field is refused, never wrapped: the card must never see a negative
// number where a positive one was meant (the warning at the end of manual section 3.3).
//
// Binary floating-point inputs (`double`): the double is first read as the decimal it stands
// for with 15 significant digits (core decimal_from_double), and that decimal is converted
// exactly. So 1.001 × 500 gives 500.5 → 501, what a person computing by hand gets, although
// the double nearest to 1.001 is a little smaller than 1.001 and a naive `std::lround(1.001 *
// 500.0)` gives 500. A double that carries more than 15 significant digits is shortened to 15
// first; callers who need more pass a `decimal`.
//
// On the wire every DPQ value is a 2- or 4-byte integer, least significant byte first (manual
// chapter 3, "Intel format"). `payload` holds exactly the field's bytes (1F 05 00 00 for 1311
// in a 4-byte field); padding to the 4 data bytes of an expedited SDO is the SDO layer's job.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>

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

/// Smallest number of decimal places p (0..18) at which every raw value of a parameter with
/// this scale and offset survives raw → EU (rounded to p places) → raw unchanged: p must be at
/// least the offset's places and 10^p ≥ |scale| (then the rounding error of the EU, at most
/// ½·10^-p, moves raw by less than ½; when 10^p = |scale| the EU is exact). 327.67 → 3,
/// 10.5 → 2, 16383.5 → 5, 1 → 0.
/// Errors: invalid_argument (offset or scale with more than 18 places), not_representable
/// (|scale| > 10^18: no p ≤ 18 round-trips — found by fuzz_dpq, F8).
[[nodiscard]] constexpr result<unsigned> round_trip_places(scaling::linear s) noexcept {
  if (s.offset.places > decimal_max_places || s.scale.places > decimal_max_places) {
    return errc::invalid_argument;
  }
  // |scale| without negating INT64_MIN (F3): its magnitude 2^63 is never a power of ten, so
  // comparing against INT64_MAX instead decides every "10^p >= |scale|" the same way.
  const std::int64_t m = s.scale.mantissa;
  const decimal mag{m == std::numeric_limits<std::int64_t>::min()
                        ? std::numeric_limits<std::int64_t>::max()
                    : m < 0 ? -m
                            : m,
                    s.scale.places};
  unsigned p = s.offset.places;
  std::int64_t pow = 1;
  for (unsigned i = 0; i < p; ++i) pow *= 10; // p <= 18: at most 10^18
  while (compare(decimal{pow, 0}, mag) < 0) {
    if (p == decimal_max_places) return errc::not_representable;
    ++p;
    pow *= 10;
  }
  return p;
}

/// Everything needed to convert one parameter: scale/offset, the field, the printed range.
/// A literal type, so it works in constant expressions.
struct conversion {
  scaling::linear scale{};
  scaling::field field{};
  scaling::range range{};
  bool has_range = true; ///< false: only the field limits apply

  /// EU → raw. Errors: out_of_range (outside the printed Min./Max.), overflow (raw value does
  /// not fit the field), invalid_argument (zero scale, bad field width).
  [[nodiscard]] constexpr result<std::int64_t> to_raw(decimal eu) const noexcept {
    if (field.bytes < 1U || field.bytes > 8U) return errc::invalid_argument;
    if (has_range) return scaling::to_raw(eu, scale, field, range);
    return scaling::to_raw(eu, scale, field);
  }
  /// The same from a double (read with 15 significant digits, see the header comment).
  /// Errors: also not_representable (NaN, infinity).
  [[nodiscard]] constexpr result<std::int64_t> to_raw(double eu) const noexcept {
    auto d = decimal_from_double(eu);
    if (!d) return d.error();
    return to_raw(d.value());
  }

  /// raw → EU as a double (one division, one addition in binary floating point).
  [[nodiscard]] constexpr double to_eu(std::int64_t raw) const noexcept {
    return scaling::to_eu(raw, scale);
  }
  /// raw → EU exactly, rounded half away from zero to `places` decimal places.
  [[nodiscard]] constexpr result<decimal> to_eu_decimal(std::int64_t raw,
                                                        unsigned places) const noexcept {
    return scaling::to_eu_decimal(raw, scale, places);
  }
  /// raw → EU exactly at round_trip_places(scale): converting the result back gives `raw`.
  [[nodiscard]] constexpr result<decimal> to_eu_decimal(std::int64_t raw) const noexcept {
    auto p = round_trip_places(scale);
    if (!p) return p.error();
    return scaling::to_eu_decimal(raw, scale, p.value());
  }

  /// A raw value as the field's bytes, least significant first.
  /// Errors: overflow (does not fit the field), invalid_argument (bad field width).
  [[nodiscard]] constexpr result<payload> encode_raw(std::int64_t raw) const noexcept {
    if (auto c = scaling::check_field(raw, field); !c) return c.error();
    payload p;
    p.size = field.bytes;
    const std::span<std::uint8_t> out(p.bytes.data(), p.size);
    const status st =
        field.is_signed
            ? store_signed(out, field.bytes, raw, byte_order::little)
            : store_unsigned(out, field.bytes, static_cast<std::uint64_t>(raw), byte_order::little);
    if (!st) return st.error();
    return p;
  }
  /// EU → bytes: to_raw, then encode_raw. Errors: those of both.
  [[nodiscard]] constexpr result<payload> encode(decimal eu) const noexcept {
    auto raw = to_raw(eu);
    if (!raw) return raw.error();
    return encode_raw(raw.value());
  }
  [[nodiscard]] constexpr result<payload> encode(double eu) const noexcept {
    auto raw = to_raw(eu);
    if (!raw) return raw.error();
    return encode_raw(raw.value());
  }

  /// The field's bytes → raw value, sign-extended for a signed field. `in` must hold exactly
  /// the field's width. The printed range is not checked: actual values read from the card may
  /// lie outside a display range. Errors: truncated (fewer bytes), bad_length (more bytes),
  /// invalid_argument (bad field width).
  [[nodiscard]] constexpr result<std::int64_t>
  decode_raw(std::span<const std::uint8_t> in) const noexcept {
    if (field.bytes < 1U || field.bytes > 8U) return errc::invalid_argument;
    if (in.size() < field.bytes) return errc::truncated;
    if (in.size() > field.bytes) return errc::bad_length;
    if (field.is_signed) return load_signed(in, field.bytes, byte_order::little);
    auto u = load_unsigned(in, field.bytes, byte_order::little);
    if (!u) return u.error();
    if (u.value() > static_cast<std::uint64_t>(field.max())) return errc::overflow; // 8 bytes
    return static_cast<std::int64_t>(u.value());
  }
  /// Bytes → EU exactly at round_trip_places. Errors: those of decode_raw and to_eu_decimal.
  [[nodiscard]] constexpr result<decimal> decode(std::span<const std::uint8_t> in) const noexcept {
    auto raw = decode_raw(in);
    if (!raw) return raw.error();
    return to_eu_decimal(raw.value());
  }
};

} // namespace fieldcodec::dpq
