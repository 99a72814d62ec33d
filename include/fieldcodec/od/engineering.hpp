// fieldcodec — an entry's value in engineering units: the one checked path between the value a
// person means (a number in the entry's unit, or the raw number when asked for explicitly) and
// the bytes of the entry. od/value_text.hpp puts text on top of it; the CLI and host code call
// these two headers, never their own conversions.
//
//   // my_drive: a generated dictionary; its pressure_limit is a UNSIGNED32 entry in bar,
//   // scale 327.67 (raw per bar), offset 0, limits 0..5000
//   namespace p = fieldcodec::dictionaries::my_drive;
//   od::encode_value(p::pressure_limit, od::decimal_number(4, 0), out)   → 4 bytes, raw 1311
//   od::encode_value(p::pressure_limit, od::signed_number(6000), out)
//                    → value_error{out_of_range, high_limit, limit 5000}   (nothing written)
//   od::encode_value(d, od::unsigned_number(16), out, {.unit = od::value_unit::raw}) → raw 16
//   od::decode_value(p::pressure_limit, bytes)                           → 4.001 (exact decimal)
//
// Rules (docs/od.md, "Values in engineering units"):
// * An integer entry flagged `scaled` has engineering units: raw = round((EU − offset) × scale)
//   half away from zero, EU = raw / scale + offset shown at round_trip_places(scale) decimals,
//   the fewest at which the EU reads back to the same raw value. Its limits are engineering
//   units and are checked on the engineering value (the manual's min/max), then the raw value
//   is checked against the field. Every other entry's engineering value is its raw value.
// * value_unit::raw takes and gives the number that travels, also for a scaled entry; its
//   limits are then the raw limits od::encode uses (round((limit − offset) × scale)).
// * Limits are those of the target node (value_options::node; node-ID-relative limits resolved
//   for it, od::any_node: the widest range any node gives). A refused value names the limit.
// * Nothing is written when a check fails.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/value.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::od {

/// In which unit a value is meant.
enum class value_unit : std::uint8_t {
  engineering, ///< the entry's unit: converted with its scale when it is scaled
  raw,         ///< the number that travels, also for a scaled entry
};

/// How od/value_text.hpp writes an integer.
enum class radix : std::uint8_t {
  decimal,
  hex, ///< "0x0000012E" (the field's width in digits): for a value ≥ 0 that is not scaled
};

/// How a value is meant and, for text, written.
struct value_options {
  value_unit unit = value_unit::engineering;
  std::uint8_t node = any_node; ///< node-ID-relative limits are those of this node
  byte_order order = byte_order::little;
  radix integers = radix::decimal; ///< value_text: how integers are written
  bool unit_suffix = true;         ///< value_text: " mA" after a number when the entry has a unit
};

/// What exactly was wrong with a value (the errc says the kind).
enum class value_issue : std::uint8_t {
  none,
  syntax,      ///< not a number, not hex bytes, an unterminated quote (position: where)
  not_integer, ///< a fraction for an integer that is not scaled (or a raw value)
  hex_is_raw,  ///< "0x…" for a scaled entry in engineering units: hex spells a raw value
  unit,        ///< a unit after the number that is not the entry's
  low_limit,   ///< below the low limit (limit: it)
  high_limit,  ///< above the high limit (limit: it)
  field,       ///< does not fit the data type (raw value outside its width and signedness)
  capacity,    ///< longer than the entry's capacity (capacity: it)
  character,   ///< a character a VISIBLE_STRING cannot hold, or bad UTF-8 (position: where)
  type,        ///< the entry's type takes no such value (a number for a string, …)
};

/// Why a value was refused: the errc and what a message needs to name the cause.
struct value_error {
  errc code = errc::invalid_argument;
  value_issue issue = value_issue::none;
  number limit{};             ///< low_limit / high_limit: the limit in the value's unit
  std::uint32_t capacity = 0; ///< capacity: how many bytes the entry holds
  std::uint32_t position = 0; ///< syntax / character: offset in the text or the value

  constexpr value_error() noexcept = default;
  constexpr value_error(errc c) noexcept : code(c) {} // NOLINT: plain errors propagate
  constexpr value_error(errc c, value_issue i) noexcept : code(c), issue(i) {}
  friend constexpr bool operator==(const value_error &, const value_error &) noexcept = default;
};

/// Whether the entry's values are converted with its scale: an integer entry flagged scaled.
[[nodiscard]] constexpr bool is_scaled(const descriptor &d) noexcept {
  return d.has(flag::scaled) && is_integer(d.type);
}

/// The decimal places a scaled entry's engineering value is shown at: round_trip_places of its
/// scale (0 for an entry that is not scaled). Errors: those of scaling::round_trip_places.
[[nodiscard]] constexpr result<unsigned> eu_places(const descriptor &d) noexcept {
  if (!is_scaled(d)) return 0U;
  return scaling::round_trip_places(d.scale);
}

namespace detail {

/// A number as a wide integer, or not_representable for a fraction / a real.
[[nodiscard]] constexpr result<wide_int> integer_of(number v) noexcept {
  if (v.kind == number_kind::none) return errc::type_mismatch;
  if (v.kind == number_kind::real) {
    FIELDCODEC_TRY(const decimal d, v.to_decimal());
    FIELDCODEC_TRY(const std::int64_t i, to_fixed(d, 0));
    return from_int64(i);
  }
  return to_wide(v);
}

[[nodiscard]] constexpr number number_of(wide_int w) noexcept {
  if (!w.negative) return unsigned_number(w.mag);
  return signed_number(static_cast<std::int64_t>(std::uint64_t{0} - w.mag));
}

/// The limit `high` of `d` for `node`, as a raw wide integer (scaled entries: converted with
/// the scale; a negative scale swaps the ends, so "low" is the lower raw end). Errors: when the
/// end is not checked (no limit, or one no raw integer stands for).
[[nodiscard]] constexpr result<wide_int> raw_end(const descriptor &d, bool high,
                                                 std::uint8_t node) noexcept {
  const bool swapped = d.has(flag::scaled) && d.scale.scale.mantissa < 0;
  return raw_limit(d, maybe_scale{&d.scale, true}, checked_limit(d, high != swapped, node));
}

/// Raw limits check naming the end. Errors: out_of_range (low_limit / high_limit).
[[nodiscard]] constexpr result<void, value_error> check_raw(const descriptor &d, wide_int x,
                                                            std::uint8_t node) noexcept {
  if (auto lo = raw_end(d, false, node); lo && compare(x, lo.value()) < 0) {
    value_error e{errc::out_of_range, value_issue::low_limit};
    e.limit = number_of(lo.value());
    return e;
  }
  if (auto hi = raw_end(d, true, node); hi && compare(x, hi.value()) > 0) {
    value_error e{errc::out_of_range, value_issue::high_limit};
    e.limit = number_of(hi.value());
    return e;
  }
  return {};
}

/// Engineering limits check of a scaled entry (decimal EU against the EU limits).
[[nodiscard]] constexpr result<void, value_error> check_eu(const descriptor &d, decimal eu,
                                                           std::uint8_t node) noexcept {
  if (auto lo = checked_limit(d, false, node)) {
    if (auto l = lo.value().to_decimal(); l && compare(eu, l.value()) < 0) {
      value_error e{errc::out_of_range, value_issue::low_limit};
      e.limit = lo.value();
      return e;
    }
  }
  if (auto hi = checked_limit(d, true, node)) {
    if (auto h = hi.value().to_decimal(); h && compare(eu, h.value()) > 0) {
      value_error e{errc::out_of_range, value_issue::high_limit};
      e.limit = hi.value();
      return e;
    }
  }
  return {};
}

/// REAL limits check naming the end.
[[nodiscard]] constexpr result<void, value_error> check_real(const descriptor &d, double v,
                                                             std::uint8_t node) noexcept {
  if (auto lo = checked_limit(d, false, node); lo && v < lo.value().to_double()) {
    value_error e{errc::out_of_range, value_issue::low_limit};
    e.limit = lo.value();
    return e;
  }
  if (auto hi = checked_limit(d, true, node); hi && v > hi.value().to_double()) {
    value_error e{errc::out_of_range, value_issue::high_limit};
    e.limit = hi.value();
    return e;
  }
  return {};
}

[[nodiscard]] constexpr value_error field_error(errc c) noexcept {
  return c == errc::overflow ? value_error{c, value_issue::field} : value_error{c};
}

} // namespace detail

/// The value `v`, meant in `o.unit`, as the bytes of `d` at the front of `out`; returns how many.
/// Checked before anything is written: the type takes a number, the limits of node `o.node`
/// (engineering limits for a scaled entry in engineering units, raw limits otherwise), the
/// field's width and signedness, BOOLEAN 0/1, REAL range, TIME fields.
/// Errors (value_error::code / issue): type_mismatch / type (a byte-string entry, no value),
/// not_representable / not_integer (a fraction for an integer that is not scaled, NaN),
/// out_of_range / low_limit, high_limit (limit set), overflow / field, buffer_too_small,
/// invalid_argument (zero scale), and those of od::encode.
[[nodiscard]] constexpr result<std::size_t, value_error>
encode_value(const descriptor &d, number v, std::span<std::uint8_t> out,
             value_options o = {}) noexcept {
  if (is_byte_string(d.type) || !v) return value_error{errc::type_mismatch, value_issue::type};
  if (is_real(d.type)) {
    auto x = detail::real_value(v, d.type == data_type::real32);
    if (!x) return detail::field_error(x.error());
    FIELDCODEC_TRY_STATUS(detail::check_real(d, x.value(), o.node));
    auto n = encode(static_cast<const entry &>(d), real_number(x.value()), out, o.order, o.node);
    if (!n) return detail::field_error(n.error());
    return n.value();
  }
  if (!is_integer(d.type)) { // BOOLEAN, TIME_OF_DAY, TIME_DIFFERENCE
    auto n = encode(d, v, out, o.order, o.node);
    if (!n) return n.error();
    return n.value();
  }
  auto f = d.raw_field();
  if (!f) return f.error();
  if (is_scaled(d) && o.unit == value_unit::engineering) {
    auto eu = v.to_decimal();
    if (!eu) return eu.error();
    FIELDCODEC_TRY_STATUS(detail::check_eu(d, eu.value(), o.node));
    auto raw = scaling::to_raw(eu.value(), d.scale, f.value());
    if (!raw) return detail::field_error(raw.error());
    auto n = encode(d, signed_number(raw.value()), out, o.order, o.node);
    if (!n) return detail::field_error(n.error());
    return n.value();
  }
  auto x = detail::integer_of(v);
  if (!x) {
    return x.error() == errc::not_representable
               ? value_error{errc::not_representable, value_issue::not_integer}
               : value_error{x.error()};
  }
  FIELDCODEC_TRY_STATUS(detail::check_raw(d, x.value(), o.node));
  auto n = encode(d, detail::number_of(x.value()), out, o.order, o.node);
  if (!n) return detail::field_error(n.error());
  return n.value();
}

/// The bytes of `d` as its value in `o.unit`: for a scaled entry in engineering units an exact
/// decimal at eu_places(d) (encode_value of it gives the same bytes again); otherwise the number
/// od::decode gives (a signed or unsigned integer, a real, BOOLEAN 0/1, a TIME value). Limits
/// are not checked: a device's value is shown as it is.
/// Errors: those of od::decode (truncated, bad_length, type_mismatch for a byte string, …);
/// for a scaled entry also those of eu_places and to_eu_decimal (overflow: an UNSIGNED64 above
/// INT64_MAX).
[[nodiscard]] constexpr result<number>
decode_value(const descriptor &d, std::span<const std::uint8_t> in, value_options o = {}) noexcept {
  FIELDCODEC_TRY(const number raw,
                 decode(static_cast<const entry &>(d), in, o.order, limits::ignore, o.node));
  if (!is_scaled(d) || o.unit == value_unit::raw) return raw;
  FIELDCODEC_TRY(const std::int64_t r, raw.to_int64());
  FIELDCODEC_TRY(const unsigned places, eu_places(d));
  FIELDCODEC_TRY(const decimal eu, d.to_eu_decimal(r, places));
  return decimal_number(eu);
}

/// The bytes of a byte-string value (VISIBLE_STRING, OCTET_STRING, UNICODE_STRING, DOMAIN) for
/// `d`, copied to `out` after the checks of od::encode_bytes.
/// Errors: type_mismatch / type, too_long / capacity (capacity set), bad_character / character
/// (position: the first such byte), bad_length (UNICODE_STRING of odd length), buffer_too_small.
[[nodiscard]] constexpr result<std::size_t, value_error>
encode_bytes_value(const descriptor &d, std::span<const std::uint8_t> value,
                   std::span<std::uint8_t> out) noexcept {
  auto n = encode_bytes(d, value, out);
  if (n) return n.value();
  value_error e{n.error()};
  if (n.error() == errc::type_mismatch) e.issue = value_issue::type;
  if (n.error() == errc::too_long) {
    e.issue = value_issue::capacity;
    e.capacity = d.capacity();
  }
  if (n.error() == errc::bad_character) {
    e.issue = value_issue::character;
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (value[i] < 0x20U || value[i] > 0x7EU) {
        e.position = static_cast<std::uint32_t>(i);
        break;
      }
    }
  }
  return e;
}

/// A unit (and scale) that a device's manual gives for objects its dictionary file cannot
/// describe: CiA 306 has no key for either. The device's folder supplies a table of them (a
/// constexpr array of unit_rule); with_unit puts a rule on a descriptor, after which every value
/// of the entry goes through the same path as a dictionary's own scaled entries.
struct unit_rule {
  std::uint16_t index = 0;
  /// The sub-index; -1: every sub-index that holds a value (sub-index 0 of an ARRAY or RECORD
  /// counts its entries and gets no unit).
  std::int16_t sub = -1;
  text unit{};
  /// raw = round((EU − offset) × scale): {{1, 1}, {0, 0}} (0.1) for 10 mA per raw step; the
  /// identity gives only the unit.
  scaling::linear scale{};

  [[nodiscard]] constexpr bool matches(const entry &e) const noexcept {
    if (e.index != index) return false;
    if (sub >= 0) return e.sub == static_cast<std::uint16_t>(sub);
    return e.object == object_code::var || e.sub != 0U;
  }
};

/// What a unit rule makes of one entry: its spec (limits in engineering units and flag::scaled
/// when the rule has a scale), its unit and its scale.
struct unit_spec {
  entry_spec spec{};
  text unit{};
  scaling::linear scale{};
};

/// `s` (an entry whose own unit is `unit` and scale `scale`) under the first rule of `rules`
/// that matches it. An entry with a unit of its own keeps it (the dictionary wins), and so does
/// one without a matching rule. A rule's scale makes an integer entry scaled: its raw limits
/// become engineering limits (exact decimals at the entry's new eu_places). Errors:
/// invalid_argument (a scale for an entry that is not an integer, already scaled, or has
/// node-ID-relative limits), those of round_trip_places and to_eu_decimal.
[[nodiscard]] constexpr result<unit_spec> apply_unit(const entry_spec &s, text unit,
                                                     const scaling::linear &scale,
                                                     std::span<const unit_rule> rules) noexcept {
  unit_spec out{s, unit, scale};
  if (!unit.empty()) return out;
  const entry probe = make_entry(s, nullptr); // address and object code only
  for (const unit_rule &r : rules) {
    if (!r.matches(probe)) continue;
    const bool identity =
        equal(r.scale.scale, decimal{1, 0}) && equal(r.scale.offset, decimal{0, 0});
    if (!identity) {
      if (!is_integer(s.type) ||
          (s.flags & (flag::scaled | flag::low_nodeid | flag::high_nodeid)) != 0U) {
        return errc::invalid_argument;
      }
      FIELDCODEC_TRY(const unsigned places, scaling::round_trip_places(r.scale));
      number *const limits[] = {&out.spec.low, &out.spec.high};
      for (number *limit : limits) {
        if (!*limit) continue;
        FIELDCODEC_TRY(const std::int64_t raw, limit->to_int64());
        FIELDCODEC_TRY(const decimal eu, scaling::to_eu_decimal(raw, r.scale, places));
        *limit = decimal_number(eu);
      }
      out.spec.flags = static_cast<std::uint16_t>(out.spec.flags | flag::scaled);
      out.scale = r.scale;
    }
    out.unit = r.unit;
    return out;
  }
  return out;
}

/// A descriptor with a vendor unit (with_unit's result). When the unit's scale rewrote the
/// limits, the packed columns its entry points to are kept here; a copy points at its own copy
/// of them. Use it as a `const descriptor &` while it lives: a plain od::descriptor copied out
/// of it may point into it.
class unit_descriptor : public descriptor {
public:
  /// The bytes an integer entry's packed columns take at most: a default and two limits, each
  /// as a packed od::number.
  static constexpr std::size_t max_packed = 3U * packed_number_size;

  constexpr unit_descriptor() noexcept = default;
  /// `d` as it is (its entry keeps pointing at d's packed columns).
  constexpr explicit unit_descriptor(const descriptor &d) noexcept : descriptor(d) {}
  constexpr unit_descriptor(const unit_descriptor &o) noexcept
      : descriptor(o), bytes_(o.bytes_), owned_(o.owned_) {
    if (owned_) extra = bytes_.data();
  }
  constexpr unit_descriptor &operator=(const unit_descriptor &o) noexcept {
    static_cast<descriptor &>(*this) = o;
    bytes_ = o.bytes_;
    owned_ = o.owned_;
    if (owned_) extra = bytes_.data();
    return *this;
  }
  constexpr ~unit_descriptor() = default;

  /// `u.spec` packed into this descriptor's own bytes, with `info` (its unit replaced) and the
  /// rule's scale. Errors: buffer_too_small (never for an integer entry).
  [[nodiscard]] static constexpr result<unit_descriptor> make(const unit_spec &u,
                                                              const entry_info &info) noexcept {
    unit_descriptor out;
    FIELDCODEC_TRY(const std::size_t n, pack(u.spec, std::span<char>(out.bytes_)));
    (void)n;
    static_cast<entry &>(out) = make_entry(u.spec, out.bytes_.data());
    out.owned_ = true;
    out.info = info;
    out.info.unit = u.unit;
    out.scale = u.scale;
    return out;
  }

private:
  std::array<char, max_packed> bytes_{};
  bool owned_ = false;
};

/// `d` with the unit and scale of the first rule of `rules` that matches it (apply_unit): an
/// entry with a scale from the rule gets new packed columns (its limits in engineering units),
/// held by the result, so values go through encode_value / decode_value like any scaled
/// entry's. Errors: those of apply_unit.
[[nodiscard]] constexpr result<unit_descriptor>
with_unit(const descriptor &d, std::span<const unit_rule> rules) noexcept {
  FIELDCODEC_TRY(const unit_spec u, apply_unit(spec_of(d), d.info.unit, d.scale, rules));
  if ((u.spec.flags & flag::scaled) == (d.flags & flag::scaled)) {
    unit_descriptor same(d); // no new limits: d's packed columns serve
    same.info.unit = u.unit;
    return same;
  }
  return unit_descriptor::make(u, d.info);
}

} // namespace fieldcodec::od
