// fieldcodec — typed encode/decode of an entry's value to and from bytes.
//
// CANopen values are little-endian; every function takes the byte order as a last argument
// (default little) because some buses (Interbus-S) send the same objects big-endian.
// Numeric values are checked against the entry's raw limits (for a `scaled` entry the limits
// are engineering units and are converted to raw first) and against the field's width.
//
//   od::encode(e, od::signed_number(-5), out) → bytes written     (number form)
//   od::encode(e, std::int16_t{-5}, out)      → bytes written     (typed form; any integer type,
//                                                                  float, double, enumerations)
//   od::encode(obj, 2, value, out)            → bytes written     (sub-object 2 of an od::object)
//   od::decode(e, in)                         → od::number
//   od::decode<std::int16_t>(e, in)           → std::int16_t
//   od::encode_bytes / od::decode_bytes         strings and domains
//
// `e` is an od::entry or an od::descriptor; a scaled entry's limits (engineering units) need the
// descriptor. Node-ID-relative limits take the node as the last argument.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/ieee754.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/object.hpp>
#include <fieldcodec/od/value_kinds.hpp>

#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

namespace fieldcodec::od {

/// Whether decode checks a received value against the entry's limits.
enum class limits : std::uint8_t { check, ignore };

/// TIME_OF_DAY / TIME_DIFFERENCE: milliseconds after midnight (28 bits) and days since
/// 1984-01-01 (TIME_OF_DAY) or a day count (TIME_DIFFERENCE).
struct time_value {
  std::uint32_t ms = 0;
  std::uint16_t days = 0;
  friend constexpr bool operator==(const time_value &, const time_value &) noexcept = default;
};
inline constexpr std::uint32_t time_ms_max = (std::uint32_t{1} << 28U) - 1U;

/// The time as the 48-bit number encode/decode use (ms in bits 0..27, days in bits 32..47).
[[nodiscard]] constexpr number to_number(time_value t) noexcept {
  return unsigned_number(std::uint64_t{t.ms} | (std::uint64_t{t.days} << 32U));
}
/// Errors: out_of_range (ms beyond 28 bits or reserved bits set), type_mismatch.
[[nodiscard]] constexpr result<time_value> to_time(number n) noexcept {
  auto u = n.to_uint64();
  if (!u) return errc::type_mismatch;
  const std::uint64_t v = u.value();
  if ((v & 0xFFFF'0000'0000'0000U) != 0U || (v & 0xFFFF'FFFFU) > time_ms_max) {
    return errc::out_of_range;
  }
  return time_value{static_cast<std::uint32_t>(v & 0xFFFF'FFFFU),
                    static_cast<std::uint16_t>(v >> 32U)};
}

namespace detail {

/// The scale of the entry being converted, when it is known (a descriptor) or not (a plain
/// od::entry). A flag says which, not a null pointer: g++ 12 with -fsanitize=undefined cannot
/// constant-evaluate the comparison of the address of a constexpr descriptor's member with
/// nullptr, and these functions run in constant expressions.
struct maybe_scale {
  const scaling::linear *p = nullptr; ///< read only when `known`
  bool known = false;
};

/// A signed 65-bit integer as sign + magnitude, for comparisons across int64 and uint64.
struct wide_int {
  bool negative = false;
  std::uint64_t mag = 0;
};
[[nodiscard]] constexpr int compare(wide_int a, wide_int b) noexcept {
  if (a.negative != b.negative) return a.negative ? -1 : 1;
  if (a.mag == b.mag) return 0;
  const bool less = a.mag < b.mag;
  return (less != a.negative) ? -1 : 1;
}
[[nodiscard]] constexpr wide_int from_int64(std::int64_t v) noexcept {
  return v < 0 ? wide_int{true, std::uint64_t{0} - static_cast<std::uint64_t>(v)}
               : wide_int{false, static_cast<std::uint64_t>(v)};
}

/// A raw integer limit. For a scaled entry the limit is in engineering units:
/// raw = round((limit − offset) × scale). Errors: anything; the caller then does not check that
/// end (a limit that is not given, or that no raw integer can stand for).
[[nodiscard]] constexpr result<wide_int> raw_limit(const entry &e, maybe_scale scale,
                                                   result<number> limit) noexcept {
  if (!limit) return limit.error();
  const number lim = limit.value();
  if (e.has(flag::scaled) && scale.known) {
    auto d = lim.to_decimal();
    if (!d) return d.error();
    auto r = scaling::scale_to_raw(d.value(), *scale.p);
    if (!r) return r.error();
    return from_int64(r.value());
  }
  if (lim.kind == number_kind::unsigned_) return wide_int{false, lim.bits};
  if (lim.kind == number_kind::signed_) return from_int64(static_cast<std::int64_t>(lim.bits));
  auto d = lim.to_decimal();
  if (!d) return d.error();
  auto r = round_to_fixed(d.value(), 0);
  if (!r) return r.error();
  return from_int64(r.value());
}

/// Errors: out_of_range when v lies outside the entry's limits for `node`; invalid_argument when
/// the entry is scaled and has a limit but its scale is not known (a plain od::entry: pass the
/// od::descriptor).
[[nodiscard]] constexpr status check_int_limits(const entry &e, maybe_scale scale, wide_int v,
                                                std::uint8_t node) noexcept {
  if (e.has(flag::scaled) && !scale.known && (e.has(flag::has_low) || e.has(flag::has_high))) {
    return errc::invalid_argument;
  }
  auto lo = raw_limit(e, scale, checked_limit(e, false, node));
  auto hi = raw_limit(e, scale, checked_limit(e, true, node));
  if (e.has(flag::scaled) && scale.known && scale.p->scale.mantissa < 0) {
    // a negative scale turns the engineering low into the raw high and vice versa
    if (lo && compare(v, lo.value()) > 0) return errc::out_of_range;
    if (hi && compare(v, hi.value()) < 0) return errc::out_of_range;
    return {};
  }
  if (lo && compare(v, lo.value()) < 0) return errc::out_of_range;
  if (hi && compare(v, hi.value()) > 0) return errc::out_of_range;
  return {};
}

[[nodiscard]] constexpr status check_real_limits(const entry &e, double v,
                                                 std::uint8_t node) noexcept {
  if (auto lo = checked_limit(e, false, node); lo && v < lo.value().to_double()) {
    return errc::out_of_range;
  }
  if (auto hi = checked_limit(e, true, node); hi && v > hi.value().to_double()) {
    return errc::out_of_range;
  }
  return {};
}

/// The number as a wide_int. Errors: type_mismatch (none), not_representable (fractional).
[[nodiscard]] constexpr result<wide_int> to_wide(number v) noexcept {
  switch (v.kind) {
  case number_kind::none: return errc::type_mismatch;
  case number_kind::unsigned_: return wide_int{false, v.bits};
  case number_kind::signed_: return from_int64(static_cast<std::int64_t>(v.bits));
  case number_kind::real:
  case number_kind::decimal_: {
    auto i = v.to_int64();
    if (!i) return i.error();
    return from_int64(i.value());
  }
  }
  return errc::type_mismatch;
}

/// The value of a number for a REAL32 / REAL64 entry. An integer must be exactly representable
/// in the type (24 / 53 significant bits); a real or decimal is rounded to the nearest value.
/// Errors: not_representable (NaN, an integer the type cannot hold exactly), overflow (beyond
/// the largest finite REAL32).
[[nodiscard]] constexpr result<double> real_value(number v, bool single) noexcept {
  if (v.kind == number_kind::signed_ || v.kind == number_kind::unsigned_) {
    const wide_int x = v.kind == number_kind::unsigned_
                           ? wide_int{false, v.bits}
                           : from_int64(static_cast<std::int64_t>(v.bits));
    if (x.mag != 0U) {
      const int significant = static_cast<int>(std::bit_width(x.mag)) - std::countr_zero(x.mag);
      if (significant > (single ? 24 : 53)) return errc::not_representable;
    }
    const double m = static_cast<double>(x.mag); // exact: at most 53 significant bits
    return x.negative ? -m : m;
  }
  const double d = v.to_double();
  if (d != d) return errc::not_representable;
  if (single && (d > static_cast<double>(std::numeric_limits<float>::max()) ||
                 d < -static_cast<double>(std::numeric_limits<float>::max()))) {
    return errc::overflow;
  }
  return d;
}

/// The integer part of encode: limits, field, bytes. `e` must have an integer type (raw values
/// of an integer-only dictionary take this path directly, without the REAL and TIME code of
/// encode).
[[nodiscard]] constexpr result<std::size_t> encode_integer(const entry &e, maybe_scale scale,
                                                           wide_int x, std::span<std::uint8_t> out,
                                                           byte_order order,
                                                           std::uint8_t node) noexcept {
  const std::size_t w = fixed_size(e.type);
  if (!is_integer(e.type)) return errc::type_mismatch;
  if (out.size() < w) return errc::buffer_too_small;
  FIELDCODEC_TRY_STATUS(check_int_limits(e, scale, x, node));
  if (is_signed_integer(e.type)) {
    if (!x.negative && x.mag > static_cast<std::uint64_t>(signed_max(w))) return errc::overflow;
    if (x.negative && x.mag > std::uint64_t{0} - static_cast<std::uint64_t>(signed_min(w))) {
      return errc::overflow;
    }
    const std::uint64_t bits = x.negative ? std::uint64_t{0} - x.mag : x.mag;
    FIELDCODEC_TRY_STATUS(store_signed(out, w, static_cast<std::int64_t>(bits), order));
    return w;
  }
  if (x.negative) return errc::overflow;
  FIELDCODEC_TRY_STATUS(store_unsigned(out, w, x.mag, order));
  return w;
}

/// encode for an entry whose scale is `scale` (maybe_scale{}: not known).
[[nodiscard]] constexpr result<std::size_t> encode(const entry &e, maybe_scale scale, number v,
                                                   std::span<std::uint8_t> out, byte_order order,
                                                   std::uint8_t node) noexcept {
  const std::size_t w = fixed_size(e.type);
  if (w == 0U || !v) return errc::type_mismatch;
  if (out.size() < w) return errc::buffer_too_small;
  if (is_real(e.type)) {
    auto d = real_value(v, e.type == data_type::real32);
    if (!d) return d.error();
    FIELDCODEC_TRY_STATUS(check_real_limits(e, d.value(), node));
    if (e.type == data_type::real32) {
      auto b = ieee754::encode_float32(static_cast<float>(d.value()), order);
      if (!b) return b.error();
      for (std::size_t i = 0; i < 4U; ++i) out[i] = b.value()[i];
      return std::size_t{4};
    }
    auto b = ieee754::encode_float64(d.value(), order);
    if (!b) return b.error();
    for (std::size_t i = 0; i < 8U; ++i) out[i] = b.value()[i];
    return std::size_t{8};
  }
  if (is_time(e.type)) {
    auto t = to_time(v);
    if (!t) return t.error();
    FIELDCODEC_TRY_STATUS(store_unsigned(out, 4, t.value().ms, order));
    FIELDCODEC_TRY_STATUS(store_unsigned(out.subspan(4), 2, t.value().days, order));
    return std::size_t{6};
  }
  auto wv = to_wide(v);
  if (!wv) return wv.error();
  const wide_int x = wv.value();
  if (e.type == data_type::boolean) {
    if (x.negative || x.mag > 1U) return errc::out_of_range;
    out[0] = static_cast<std::uint8_t>(x.mag);
    return std::size_t{1};
  }
  return encode_integer(e, scale, x, out, order, node);
}

/// decode for an entry whose scale is `scale` (maybe_scale{}: not known).
[[nodiscard]] constexpr result<number> decode(const entry &e, maybe_scale scale,
                                              std::span<const std::uint8_t> in, byte_order order,
                                              limits lim, std::uint8_t node) noexcept {
  const std::size_t w = fixed_size(e.type);
  if (w == 0U) return errc::type_mismatch;
  if (in.size() < w) return errc::truncated;
  if (in.size() > w) return errc::bad_length;
  if (e.type == data_type::real32 || e.type == data_type::real64) {
    double d = 0;
    if (e.type == data_type::real32) {
      auto f = ieee754::decode_float32(in, order);
      if (!f) return f.error();
      d = static_cast<double>(f.value());
    } else {
      auto f = ieee754::decode_float64(in, order);
      if (!f) return f.error();
      d = f.value();
    }
    if (lim == limits::check) FIELDCODEC_TRY_STATUS(check_real_limits(e, d, node));
    return real_number(d);
  }
  if (is_time(e.type)) {
    auto ms = load_unsigned(in, 4, order);
    auto days = load_unsigned(in.subspan(4), 2, order);
    if (!ms || !days) return errc::truncated;
    if (ms.value() > time_ms_max) return errc::out_of_range;
    return to_number(time_value{static_cast<std::uint32_t>(ms.value()),
                                static_cast<std::uint16_t>(days.value())});
  }
  if (e.type == data_type::boolean) {
    if (in[0] > 1U) return errc::out_of_range;
    return unsigned_number(in[0]);
  }
  number n;
  wide_int x;
  if (is_signed_integer(e.type)) {
    auto v = load_signed(in, w, order);
    if (!v) return v.error();
    n = signed_number(v.value());
    x = from_int64(v.value());
  } else {
    auto v = load_unsigned(in, w, order);
    if (!v) return v.error();
    n = unsigned_number(v.value());
    x = {false, v.value()};
  }
  if (lim == limits::check) FIELDCODEC_TRY_STATUS(check_int_limits(e, scale, x, node));
  return n;
}

/// Errors: out_of_range, invalid_argument (scaled entry without its scale), type_mismatch,
/// not_representable.
[[nodiscard]] constexpr status check_limits(const entry &e, maybe_scale scale, number v,
                                            std::uint8_t node) noexcept {
  if (!v || fixed_size(e.type) == 0U) return errc::type_mismatch;
  if (is_real(e.type)) {
    auto d = real_value(v, e.type == data_type::real32);
    if (!d) return d.error();
    return check_real_limits(e, d.value(), node);
  }
  auto x = to_wide(v);
  if (!x) return x.error();
  return check_int_limits(e, scale, x.value(), node);
}

template <class>
inline constexpr bool always_false = false;

} // namespace detail

// --- number form -----------------------------------------------------------------------------
//
// Every function exists for an od::entry and for an od::descriptor. They differ only for a
// scaled entry: its limits are engineering units, which only a descriptor can turn into raw
// limits (round((limit − offset) × scale)); a plain entry that is scaled and has a limit gives
// errc::invalid_argument when its limits are checked. `node` is the node-ID for node-ID-relative
// limits (flag::low_nodeid / high_nodeid); with od::any_node such an end is checked for the widest
// range any node 1..127 gives (low + 1, high + 127).

/// Whether `v` lies within the limits of `e` for `node` (number and REAL types; BOOLEAN and the
/// field's width are encode's business). Errors: out_of_range, invalid_argument (scaled entry
/// without its scale), type_mismatch (byte-string type or no value), not_representable.
[[nodiscard]] constexpr status check_limits(const entry &e, number v,
                                            std::uint8_t node = any_node) noexcept {
  return detail::check_limits(e, detail::maybe_scale{}, v, node);
}
[[nodiscard]] constexpr status check_limits(const descriptor &d, number v,
                                            std::uint8_t node = any_node) noexcept {
  return detail::check_limits(d, detail::maybe_scale{&d.scale, true}, v, node);
}

/// Write the value `v` of entry `e` to the front of `out`; returns the number of bytes.
/// Integers, BOOLEAN (0/1), REAL32/REAL64 and TIME_* (see to_number(time_value)).
/// Errors: type_mismatch (byte-string type, or no value), not_representable (fraction for an
/// integer type, NaN/infinity, an integer a REAL type cannot hold exactly), out_of_range
/// (outside the entry's limits, BOOLEAN not 0/1, time fields), overflow (does not fit the
/// field), buffer_too_small, invalid_argument (scaled entry without its scale).
[[nodiscard]] constexpr result<std::size_t> encode(const entry &e, number v,
                                                   std::span<std::uint8_t> out,
                                                   byte_order order = byte_order::little,
                                                   std::uint8_t node = any_node) noexcept {
  return detail::encode(e, detail::maybe_scale{}, v, out, order, node);
}
[[nodiscard]] constexpr result<std::size_t> encode(const descriptor &d, number v,
                                                   std::span<std::uint8_t> out,
                                                   byte_order order = byte_order::little,
                                                   std::uint8_t node = any_node) noexcept {
  return detail::encode(d, detail::maybe_scale{&d.scale, true}, v, out, order, node);
}

/// Read the value of entry `e` from `in`, which must hold exactly width() bytes.
/// Errors: type_mismatch (byte-string type), truncated (too few bytes), bad_length (too many),
/// out_of_range (outside the limits with limits::check, BOOLEAN other than 0/1, time reserved
/// bits), not_representable (NaN/infinity), invalid_argument (limits::check of a scaled entry
/// without its scale).
[[nodiscard]] constexpr result<number> decode(const entry &e, std::span<const std::uint8_t> in,
                                              byte_order order = byte_order::little,
                                              limits lim = limits::check,
                                              std::uint8_t node = any_node) noexcept {
  return detail::decode(e, detail::maybe_scale{}, in, order, lim, node);
}
[[nodiscard]] constexpr result<number> decode(const descriptor &d, std::span<const std::uint8_t> in,
                                              byte_order order = byte_order::little,
                                              limits lim = limits::check,
                                              std::uint8_t node = any_node) noexcept {
  return detail::decode(d, detail::maybe_scale{&d.scale, true}, in, order, lim, node);
}

// --- typed form --------------------------------------------------------------------------------

/// The types the typed forms accept: bool, every integer type, float, double, and enumerations
/// (taken as their underlying type, so a scoped enum such as ds402::mode is its number).
template <class T>
concept value_type =
    std::integral<T> || std::same_as<T, float> || std::same_as<T, double> || std::is_enum_v<T>;

/// The number a typed value stands for, for entry `e`. Integers (and enumerations) are taken
/// exactly, whatever their width and signedness: the field check of encode refuses what does
/// not fit, nothing wraps. A double is read as the decimal it stands for (15 significant
/// digits) unless the entry is REAL; a float is its own bits for a REAL32 and its shortest
/// round-trip decimal otherwise (a REAL64 gets the double nearest that decimal).
/// Errors: not_representable (NaN, infinity).
template <value_type T>
[[nodiscard]] constexpr result<number> to_number(const entry &e, T v) noexcept {
  if constexpr (std::is_enum_v<T>) {
    return to_number(e, static_cast<std::underlying_type_t<T>>(v));
  } else if constexpr (std::same_as<T, float>) {
    // a float is the float it is: its own bits for REAL32, otherwise its shortest round-trip
    // decimal (90.73f is 90.73, not the 90.7300033569336 widening to double gives)
    if (e.type == data_type::real32) return real_number(static_cast<double>(v));
    FIELDCODEC_TRY(const decimal d, decimal_from_float(v));
    return decimal_number(d);
  } else if constexpr (std::same_as<T, double>) {
    if (is_real(e.type)) return real_number(v);
    FIELDCODEC_TRY(const decimal d, decimal_from_double(v));
    return decimal_number(d);
  } else if constexpr (std::is_signed_v<T>) {
    return signed_number(static_cast<std::int64_t>(v));
  } else {
    return unsigned_number(static_cast<std::uint64_t>(v));
  }
}

/// Typed form of encode: any value_type, checked against the entry's type, field and limits.
template <value_type T>
[[nodiscard]] constexpr result<std::size_t> encode(const entry &e, T v, std::span<std::uint8_t> out,
                                                   byte_order order = byte_order::little,
                                                   std::uint8_t node = any_node) noexcept {
  auto n = to_number(e, v);
  if (!n) return n.error();
  return detail::encode(e, detail::maybe_scale{}, n.value(), out, order, node);
}
template <value_type T>
[[nodiscard]] constexpr result<std::size_t>
encode(const descriptor &d, T v, std::span<std::uint8_t> out, byte_order order = byte_order::little,
       std::uint8_t node = any_node) noexcept {
  auto n = to_number(d, v);
  if (!n) return n.error();
  return detail::encode(d, detail::maybe_scale{&d.scale, true}, n.value(), out, order, node);
}

/// The number `v` as a T (value_type), never narrowed: an integer T takes an integer that fits
/// it, a floating-point T an integer it holds exactly (24 / 53 significant bits, as encode
/// requires of an integer for a REAL entry) or a real it holds exactly (a REAL32 value into
/// float or double, a REAL64 value into double; a REAL64 value into float only when it is a
/// float value), an enumeration its underlying type's. A decimal (decode never gives one) into a
/// floating-point T is its nearest value: decimal digits have no exact binary form in general.
/// decode<T> and canopen::sdo::upload_value<T> use it.
/// Errors: unknown_object (no value), overflow (an integer outside T's range, a real beyond
/// float's finite range), not_representable (a real or a fraction for an integer T, an integer
/// or real a floating-point T cannot hold exactly, NaN).
template <value_type T>
[[nodiscard]] constexpr result<T> number_as(number v) noexcept {
  if (v.kind == number_kind::none) return errc::unknown_object;
  if constexpr (std::is_enum_v<T>) {
    auto u = number_as<std::underlying_type_t<T>>(v);
    if (!u) return u.error();
    return static_cast<T>(u.value());
  } else if constexpr (std::floating_point<T>) {
    constexpr bool single = std::same_as<T, float>;
    auto d = detail::real_value(v, single); // integers exactly or not at all; range; NaN
    if (!d) return d.error();
    if (v.kind == number_kind::signed_ || v.kind == number_kind::unsigned_) {
      return static_cast<T>(d.value());
    }
    if (v.kind == number_kind::decimal_) return static_cast<T>(d.value()); // nearest, see above
    if constexpr (single) {
      const auto f = static_cast<float>(d.value()); // within float's range: real_value checked
      if (static_cast<double>(f) != d.value()) return errc::not_representable;
      return f;
    } else {
      return d.value();
    }
  } else {
    if (v.kind == number_kind::real) return errc::not_representable;
    detail::wide_int x;
    if (v.kind == number_kind::unsigned_) {
      x = {false, v.bits};
    } else if (v.kind == number_kind::signed_) {
      x = detail::from_int64(static_cast<std::int64_t>(v.bits));
    } else { // a decimal: an integer only. Its digits are divided off here: number::to_int64
             // and to_fixed would link the conversion of reals or the powers of ten into every
             // decode<integer> (+1.4 kB on a Cortex-M), the loop costs 64 bytes.
      auto m = static_cast<std::int64_t>(v.bits);
      for (unsigned p = v.places; p > 0U && m != 0; --p) {
        if (m % 10 != 0) return errc::not_representable;
        m /= 10;
      }
      x = detail::from_int64(m);
    }
    if (x.negative) {
      if constexpr (std::is_signed_v<T>) {
        constexpr auto min_mag =
            std::uint64_t{0} -
            static_cast<std::uint64_t>(std::int64_t{std::numeric_limits<T>::min()});
        if (x.mag > min_mag) return errc::overflow;
        return static_cast<T>(static_cast<std::int64_t>(std::uint64_t{0} - x.mag));
      } else {
        return errc::overflow; // a negative value is never an unsigned T's
      }
    }
    if (x.mag > static_cast<std::uint64_t>(std::numeric_limits<T>::max())) return errc::overflow;
    return static_cast<T>(x.mag);
  }
}

/// Typed form of decode (the number as number_as<T> gives it). Errors: those of decode and of
/// number_as: overflow when the value does not fit T, not_representable when a real value is
/// asked for as an integer or T cannot hold the value exactly.
template <value_type T>
[[nodiscard]] constexpr result<T>
decode(const entry &e, std::span<const std::uint8_t> in, byte_order order = byte_order::little,
       limits lim = limits::check, std::uint8_t node = any_node) noexcept {
  auto n = detail::decode(e, detail::maybe_scale{}, in, order, lim, node);
  if (!n) return n.error();
  return number_as<T>(n.value());
}
template <value_type T>
[[nodiscard]] constexpr result<T>
decode(const descriptor &d, std::span<const std::uint8_t> in, byte_order order = byte_order::little,
       limits lim = limits::check, std::uint8_t node = any_node) noexcept {
  auto n = detail::decode(d, detail::maybe_scale{&d.scale, true}, in, order, lim, node);
  if (!n) return n.error();
  return number_as<T>(n.value());
}

// --- object + sub-index ------------------------------------------------------------------------

/// encode of sub-object `sub` of an ARRAY/RECORD view (its descriptor: limits of scaled
/// entries are checked too). Errors: unknown_object (no such sub-index), those of encode.
template <class V>
requires value_type<V> || std::same_as<V, number>
[[nodiscard]] constexpr result<std::size_t> encode(const object &o, std::uint8_t sub, V v,
                                                   std::span<std::uint8_t> out,
                                                   byte_order order = byte_order::little,
                                                   std::uint8_t node = any_node) noexcept {
  auto d = o.at(sub);
  if (!d) return d.error();
  return encode(d.value(), v, out, order, node);
}
/// An object without a sub-index does not say which value is meant: a compile error that says so.
template <class V>
constexpr result<std::size_t> encode(const object &, V, std::span<std::uint8_t>,
                                     byte_order = byte_order::little) noexcept {
  static_assert(detail::always_false<V>,
                "od::encode of an od::object needs the sub-index: od::encode(object, sub, value, "
                "out) or od::encode(object[sub], value, out)");
  return errc::invalid_argument;
}

/// decode of sub-object `sub` of an ARRAY/RECORD view. Errors: unknown_object, those of decode.
[[nodiscard]] constexpr result<number> decode(const object &o, std::uint8_t sub,
                                              std::span<const std::uint8_t> in,
                                              byte_order order = byte_order::little,
                                              limits lim = limits::check,
                                              std::uint8_t node = any_node) noexcept {
  auto d = o.at(sub);
  if (!d) return d.error();
  return decode(d.value(), in, order, lim, node);
}
template <value_type T>
[[nodiscard]] constexpr result<T>
decode(const object &o, std::uint8_t sub, std::span<const std::uint8_t> in,
       byte_order order = byte_order::little, limits lim = limits::check,
       std::uint8_t node = any_node) noexcept {
  auto d = o.at(sub);
  if (!d) return d.error();
  return decode<T>(d.value(), in, order, lim, node);
}

/// Copy a byte-string value (VISIBLE_STRING, OCTET_STRING, UNICODE_STRING, DOMAIN) to `out`.
/// VISIBLE_STRING allows the characters 0x20..0x7E; UNICODE_STRING needs an even length.
/// Errors: type_mismatch, too_long (longer than the entry's declared size), bad_character,
/// bad_length, buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> encode_bytes(const entry &e,
                                                         std::span<const std::uint8_t> value,
                                                         std::span<std::uint8_t> out) noexcept {
  if (!is_byte_string(e.type)) return errc::type_mismatch;
  if (const std::uint32_t cap = e.capacity(); cap != 0U && value.size() > cap) {
    return errc::too_long;
  }
  if (e.type == data_type::unicode_string && value.size() % 2U != 0U) return errc::bad_length;
  if (e.type == data_type::visible_string) {
    for (const std::uint8_t c : value) {
      if (c < 0x20U || c > 0x7EU) return errc::bad_character;
    }
  }
  if (out.size() < value.size()) return errc::buffer_too_small;
  for (std::size_t i = 0; i < value.size(); ++i) out[i] = value[i];
  return value.size();
}

/// A byte-string value received for `e`: the same bytes, validated. A VISIBLE_STRING may be
/// padded with trailing NULs, which are cut off.
/// Errors: type_mismatch, too_long, bad_character, bad_length.
[[nodiscard]] constexpr result<std::span<const std::uint8_t>>
decode_bytes(const entry &e, std::span<const std::uint8_t> in) noexcept {
  if (!is_byte_string(e.type)) return errc::type_mismatch;
  if (const std::uint32_t cap = e.capacity(); cap != 0U && in.size() > cap) return errc::too_long;
  if (e.type == data_type::unicode_string && in.size() % 2U != 0U) return errc::bad_length;
  if (e.type == data_type::visible_string) {
    std::size_t n = in.size();
    while (n > 0U && in[n - 1U] == 0U) --n;
    in = in.first(n);
    for (const std::uint8_t c : in) {
      if (c < 0x20U || c > 0x7EU) return errc::bad_character;
    }
  }
  return in;
}

// --- checking a stored value -------------------------------------------------------------------

/// What od::check_value says of a value.
enum class value_check : std::uint8_t {
  ok,       ///< a value of the type, within the limits
  invalid,  ///< no value of the type (BOOLEAN other than 0/1, NaN, TIME's reserved bits), a
            ///< scaled entry's value outside its limits, or a kind the code was not made for
  too_low,  ///< below the low limit
  too_high, ///< above the high limit
};

namespace detail {

/// check_value for every kind, through decode; a value outside the limits is compared with
/// them to say which end it passed: an integer with the raw limits decode used, a REAL as a
/// double (a scaled entry's: invalid, its ends are engineering units).
[[nodiscard]] constexpr value_check check_any(const entry &e, const scaling::linear &scale,
                                              std::span<const std::uint8_t> in,
                                              std::uint8_t node) noexcept {
  const maybe_scale s{&scale, true};
  auto v = decode(e, s, in, byte_order::little, limits::check, node);
  if (v) return value_check::ok;
  if (v.error() != errc::out_of_range || e.type == data_type::boolean || e.has(flag::scaled) ||
      is_time(e.type)) {
    return value_check::invalid;
  }
  auto raw = decode(e, s, in, byte_order::little, limits::ignore, node);
  if (!raw) return value_check::invalid;
  if (is_real(e.type)) {
    const double d = raw.value().to_double();
    if (auto hi = checked_limit(e, true, node); hi && d > hi.value().to_double()) {
      return value_check::too_high;
    }
    if (auto lo = checked_limit(e, false, node); lo && d < lo.value().to_double()) {
      return value_check::too_low;
    }
    return value_check::invalid;
  }
  auto x = to_wide(raw.value());
  if (!x) return value_check::invalid;
  if (auto hi = raw_limit(e, s, checked_limit(e, true, node))) {
    if (compare(x.value(), hi.value()) > 0) return value_check::too_high;
  }
  if (auto lo = raw_limit(e, s, checked_limit(e, false, node))) {
    if (compare(x.value(), lo.value()) < 0) return value_check::too_low;
  }
  return value_check::invalid;
}

/// An integer entry's value against limits packed in its own width: W-bit integer comparisons
/// (W = 32 unless the code serves wide integers). Values are compared as unsigned W-bit keys:
/// a signed value sign-extended with W's sign bit flipped, which orders like the values.
template <value_kinds K>
[[nodiscard]] constexpr value_check check_in_width(const entry &e, std::span<const std::uint8_t> in,
                                                   std::uint8_t node) noexcept {
  using W = std::conditional_t<K.wide, std::uint64_t, std::uint32_t>;
  const std::size_t w = in.size();
  if (w > sizeof(W)) return value_check::invalid;
  const bool is_signed = is_signed_integer(e.type);
  const auto key = [&](std::uint64_t raw) {
    auto x = static_cast<W>(raw);
    if (is_signed) {
      const W sign = W{1} << (8U * w - 1U);
      x = static_cast<W>(static_cast<W>((x ^ sign) - sign) ^ (W{1} << (8U * sizeof(W) - 1U)));
    }
    return x;
  };
  const W v = key(load_le(in.data(), w));
  const char *p = e.extra + e.limits_at();
  const bool has_low = e.has(flag::has_low);
  // High first, as the abort code has always been chosen (a value below a low limit that lies
  // above the high one is too high).
  if (e.has(flag::has_high)) {
    W h = key(load_le(p + (has_low ? w : 0U), w));
    bool checked = true;
    if (e.has(flag::high_nodeid)) {
      if constexpr (K.node_limits) {
        const W n = limit_node(true, node);
        // past W: beyond every value of a 32-bit field (no constraint), or beyond 64 bits,
        // which plus_node refuses (the end is not checked)
        checked = static_cast<W>(h + n) >= h;
        h = static_cast<W>(h + n);
      } else {
        return value_check::invalid;
      }
    }
    if (checked && v > h) return value_check::too_high;
  }
  if (has_low) {
    W l = key(load_le(p, w));
    if (e.has(flag::low_nodeid)) {
      if constexpr (K.node_limits) {
        const W n = limit_node(false, node);
        if (static_cast<W>(l + n) < l) {
          // past W: above every value of a 32-bit field, or not checked (64 bits, as above)
          if constexpr (K.wide) return value_check::ok;
          return value_check::too_low;
        }
        l = static_cast<W>(l + n);
      } else {
        return value_check::invalid;
      }
    }
    if (v < l) return value_check::too_low;
  }
  return value_check::ok;
}

} // namespace detail

/// Checks `bytes`, exactly width() bytes of a value of `e` as CANopen sends it (little-endian),
/// for node `node` (node-ID-relative limits; any_node: the widest range): the type's rules and
/// the limits, as decode with limits::check does, and which end a value outside the limits
/// passed. `scale` is the entry's (identity when it is not scaled). `K`: the kinds of values the
/// code serves (od/value_kinds.hpp): only their paths are compiled, and a value of a kind `K`
/// lacks is `invalid`, never unchecked. An integer entry whose limits fit its width (the usual
/// case) is checked with integer comparisons in 32 bits (64 with K.wide); a byte string, a wrong
/// number of bytes: `invalid` (byte strings are decode_bytes' business).
template <value_kinds K = all_kinds>
[[nodiscard]] constexpr value_check check_value(const entry &e, const scaling::linear &scale,
                                                std::span<const std::uint8_t> bytes,
                                                std::uint8_t node = any_node) noexcept {
  const std::size_t w = fixed_size(e.type);
  if (w == 0U || bytes.size() != w) return value_check::invalid;
  if (e.type == data_type::boolean) return bytes[0] > 1U ? value_check::invalid : value_check::ok;
  const bool limited = e.has(flag::has_low) || e.has(flag::has_high);
  if (is_real(e.type) || is_time(e.type) || e.has(flag::scaled) ||
      (limited && e.has(flag::limits_number))) {
    if constexpr (K.real || K.time || K.scaled || K.numbers) {
      if (!covers(K, kinds_of(e))) return value_check::invalid;
      return detail::check_any(e, scale, bytes, node);
    } else {
      return value_check::invalid;
    }
  }
  if (!limited) return value_check::ok; // an integer: every bit pattern is a value
  if constexpr (K.limits) {
    return detail::check_in_width<K>(e, bytes, node);
  } else {
    return value_check::invalid;
  }
}

} // namespace fieldcodec::od
