// fieldcodec — COMPAX objects by dictionary entry: encode and decode an object's data bytes
// in engineering units, whatever its coding (big-endian integer with scale, signed BCD
// position, BCD speed, boolean). Works with any od::descriptor, in particular the generated
// descriptors of include/fieldcodec/dictionaries/compax_objects.hpp:
//
//   namespace d = fieldcodec::dictionaries::compax_objects;
//   std::array<std::uint8_t, 4> buf{};
//   compax::encode_object(d::lage_ziel, decimal{-1000, 0}, buf);        // FF F0 BD C0
//   compax::encode_object(d::grenzen, 1, decimal{-1650, 0}, buf);      // FF E6 D2 B0
//   compax::encode_px(d::dictionary, 11, decimal{5000, 0}, buf);        // 00 4C 4B 40
//
// A single object (VAR) is named by its descriptor; an element of an ARRAY or RECORD (GRENZEN,
// Px, VX, S7_S8, …) by the object and its sub-index, so the call says which element it means.
#pragma once

#include <fieldcodec/compax/position.hpp>
#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/object.hpp>

#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::compax {

/// Object indices with a coding the data type does not tell.
namespace index {
inline constexpr std::uint16_t posr = 0x5FEF;
inline constexpr std::uint16_t posa = 0x5FF0;
inline constexpr std::uint16_t s1 = 0x5FF9;
inline constexpr std::uint16_t posr0speed = 0x5FED;
inline constexpr std::uint16_t px = 0x5FD4;
inline constexpr std::uint16_t vx = 0x5FCD;
inline constexpr std::uint16_t nx = 0x5FD5;
} // namespace index

/// How an object's bytes carry its value.
enum class coding : std::uint8_t {
  integer,      ///< big-endian two's complement / binary, scaled by the entry
  bcd_position, ///< POSA, POSR, S1: sign byte + 10 BCD digits, 0.001 mm
  bcd_speed,    ///< POSR0SPEED: 6 BCD digits, 0.001 %
  boolean,      ///< 0x00 / 0xFF
  other,        ///< strings, bit words, records: use the typed codecs
};

[[nodiscard]] constexpr coding coding_of(const od::entry &e) noexcept {
  if (e.index == index::posa || e.index == index::posr || e.index == index::s1) {
    return coding::bcd_position;
  }
  if (e.index == index::posr0speed) return coding::bcd_speed;
  if (e.type == od::data_type::boolean) return coding::boolean;
  if (od::is_integer(e.type)) return coding::integer;
  return coding::other;
}

/// Write the object's data bytes for the engineering value `eu` (mm, %, ms, … as the entry's
/// scale says; booleans: 0 or 1) to the front of `out`; returns the number of bytes. Values
/// finer than the resolution are rounded half away from zero, like od::descriptor::to_raw.
/// Errors: out_of_range (outside the entry's limits or the coding's range), overflow (does not
/// fit the field, or is the Integer32 overflow marker), type_mismatch (coding::other),
/// buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> encode_object(const od::descriptor &e, decimal eu,
                                                          std::span<std::uint8_t> out) noexcept {
  switch (coding_of(e)) {
  case coding::integer: {
    auto raw = e.to_raw(eu);
    if (!raw) return raw.error();
    const std::size_t w = od::fixed_size(e.type);
    if (e.type == od::data_type::integer32 && raw.value() == integer32_overflow) {
      return errc::overflow;
    }
    if (out.size() < w) return errc::buffer_too_small;
    if (od::is_signed_integer(e.type)) {
      FIELDCODEC_TRY_STATUS(store_signed(out, w, raw.value(), bus_order));
    } else {
      FIELDCODEC_TRY_STATUS(
          store_unsigned(out, w, static_cast<std::uint64_t>(raw.value()), bus_order));
    }
    return w;
  }
  case coding::bcd_position: {
    auto t = round_to_fixed(eu, position_places);
    if (!t) return t.error() == errc::overflow ? errc::out_of_range : t.error();
    auto b = encode_bcd_position(t.value());
    if (!b) return b.error();
    if (out.size() < b.value().size()) return errc::buffer_too_small;
    for (std::size_t i = 0; i < b.value().size(); ++i) out[i] = b.value()[i];
    return b.value().size();
  }
  case coding::bcd_speed: {
    auto t = round_to_fixed(eu, 3);
    if (!t) return t.error();
    if (t.value() < 0 || t.value() > bcd_speed_max) return errc::out_of_range;
    auto b = encode_bcd_speed(static_cast<std::uint32_t>(t.value()));
    if (!b) return b.error();
    if (out.size() < b.value().size()) return errc::buffer_too_small;
    for (std::size_t i = 0; i < b.value().size(); ++i) out[i] = b.value()[i];
    return b.value().size();
  }
  case coding::boolean: {
    if (out.empty()) return errc::buffer_too_small;
    if (equal(eu, decimal{0, 0})) {
      out[0] = boolean_false;
    } else if (equal(eu, decimal{1, 0})) {
      out[0] = boolean_true;
    } else {
      return errc::out_of_range;
    }
    return std::size_t{1};
  }
  case coding::other: break;
  }
  return errc::type_mismatch;
}

/// The engineering value of the object's data bytes, rounded to `places` decimals (default 6,
/// exact for every COMPAX resolution except OVERRIDE's 1/2.55).
/// Errors: truncated, bad_length, overflow (Integer32 0x80000000), bad_sign, bad_digit,
/// out_of_range, type_mismatch (coding::other).
[[nodiscard]] constexpr result<decimal> decode_object(const od::descriptor &e,
                                                      std::span<const std::uint8_t> in,
                                                      unsigned places = 6) noexcept {
  switch (coding_of(e)) {
  case coding::integer: {
    const std::size_t w = od::fixed_size(e.type);
    if (in.size() < w) return errc::truncated;
    if (in.size() > w) return errc::bad_length;
    std::int64_t raw = 0;
    if (od::is_signed_integer(e.type)) {
      auto v = load_signed(in, w, bus_order);
      if (!v) return v.error();
      raw = v.value();
      if (e.type == od::data_type::integer32 && raw == integer32_overflow) return errc::overflow;
    } else {
      auto v = load_unsigned(in, w, bus_order);
      if (!v) return v.error();
      if (v.value() > static_cast<std::uint64_t>(signed_max(8))) return errc::overflow;
      raw = static_cast<std::int64_t>(v.value());
    }
    auto eu = e.to_eu_decimal(raw, places);
    if (!eu) return eu.error();
    return normalize(eu.value());
  }
  case coding::bcd_position: {
    auto t = decode_bcd_position(in);
    if (!t) return t.error();
    return normalize(decimal{t.value(), 3});
  }
  case coding::bcd_speed: {
    auto t = decode_bcd_speed(in);
    if (!t) return t.error();
    return normalize(decimal{t.value(), 3});
  }
  case coding::boolean: {
    auto b = decode_boolean(in);
    if (!b) return b.error();
    return decimal{b.value() ? 1 : 0, 0};
  }
  case coding::other: break;
  }
  return errc::type_mismatch;
}

namespace detail {
/// The element `sub` of an ARRAY/RECORD object. Any integer type. Errors: unknown_object.
template <integer_argument S>
[[nodiscard]] constexpr result<od::descriptor> element(const od::object &o, S sub) noexcept {
  auto s = checked_narrow<std::uint8_t>(sub);
  if (!s) return errc::unknown_object;
  return o.at(s.value());
}
/// The entry (index, sub) of a dictionary. Any integer type. Errors: unknown_object.
template <integer_argument S>
[[nodiscard]] constexpr result<od::descriptor> element(const od::dictionary &d, std::uint16_t index,
                                                       S sub) noexcept {
  auto s = checked_narrow<std::uint8_t>(sub);
  if (!s) return errc::unknown_object;
  return d.at(index, s.value());
}
} // namespace detail

/// Element `sub` of an ARRAY or RECORD object (e.g. GRENZEN sub 1, the negative limit) in
/// engineering units. `sub` of any integer type. Errors: unknown_object (no such sub-index),
/// and those of encode_object(descriptor, …).
template <integer_argument S>
[[nodiscard]] constexpr result<std::size_t> encode_object(const od::object &o, S sub, decimal eu,
                                                          std::span<std::uint8_t> out) noexcept {
  auto e = detail::element(o, sub);
  if (!e) return e.error();
  return encode_object(e.value(), eu, out);
}

/// Element `sub` of an ARRAY or RECORD object from its bytes. Errors: unknown_object, and those
/// of decode_object(descriptor, …).
template <integer_argument S>
[[nodiscard]] constexpr result<decimal> decode_object(const od::object &o, S sub,
                                                      std::span<const std::uint8_t> in,
                                                      unsigned places = 6) noexcept {
  auto e = detail::element(o, sub);
  if (!e) return e.error();
  return decode_object(e.value(), in, places);
}

/// An ARRAY or RECORD has no single value: name the element, encode_object(d::grenzen, 1, …).
std::size_t encode_object(const od::object &, decimal, std::span<std::uint8_t>) = delete;
/// An ARRAY or RECORD has no single value: name the element, decode_object(d::grenzen, 1, …).
decimal decode_object(const od::object &, std::span<const std::uint8_t>, unsigned = 6) = delete;

/// Px parameter `n` (1..250, any integer type) in engineering units, with the resolution of its
/// dictionary row. Errors: unknown_object (no such parameter), and those of encode_object.
template <integer_argument N>
[[nodiscard]] constexpr result<std::size_t> encode_px(const od::dictionary &d, N n, decimal eu,
                                                      std::span<std::uint8_t> out) noexcept {
  auto e = detail::element(d, index::px, n);
  if (!e) return e.error();
  return encode_object(e.value(), eu, out);
}

/// Px parameter `n` from its 4 bytes. Errors: unknown_object, and those of decode_object.
template <integer_argument N>
[[nodiscard]] constexpr result<decimal> decode_px(const od::dictionary &d, N n,
                                                  std::span<const std::uint8_t> in) noexcept {
  auto e = detail::element(d, index::px, n);
  if (!e) return e.error();
  return decode_object(e.value(), in);
}

} // namespace fieldcodec::compax
