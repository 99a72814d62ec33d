// fieldcodec — od::descriptor, one sub-object with everything known about it: the lean core
// entry, its descriptive columns (info) and its scale. Generated headers name each VAR object (and
// each named sub-object of a record) as a standalone `inline constexpr od::descriptor`, so
// firmware that names one parameter keeps only that constant, not the dictionary's tables.
//
//   // my_drive: a generated dictionary; its pressure_limit is a UNSIGNED32 entry in bar,
//   // scale 327.67 (raw per bar), offset 0, limits 0..5000
//   namespace p = fieldcodec::dictionaries::my_drive;
//   p::pressure_limit.to_raw(4.0)              → 1311            (EU → raw: range, rounding, field;
//                                                                  decimal, double, float, integer)
//   p::pressure_limit.to_eu(1311)              → 4.000976…       (raw → EU as a double)
//   p::pressure_limit.to_eu_decimal(1311, 3)   → 4.001           (raw → EU, exact decimal)
//   p::pressure_limit.info.unit                → "bar"
//
// This is the one scaling surface of the library: `to_raw` takes an engineering value (exact
// decimal, double, float or any integer, each read as the number it is), `to_eu` always answers
// a double, `to_eu_decimal` always an exact decimal
// rounded half away from zero; the arithmetic is core/scaling's.
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/number.hpp>

#include <concepts>
#include <cstdint>

namespace fieldcodec::od {

struct descriptor : entry {
  entry_info info{};
  scaling::linear scale{}; ///< raw = round((EU − offset) × scale); identity when not scaled

  /// Engineering units → raw: range check against [low, high] (engineering units when scaled,
  /// raw otherwise; a missing end is not checked; a node-ID-relative end is checked for any
  /// node, see od::any_node), round((eu − offset) × scale) half away from zero, then a check
  /// against the field's width and signedness.
  /// Errors: type_mismatch (not an integer type), out_of_range, overflow, invalid_argument
  /// (zero scale).
  [[nodiscard]] constexpr result<std::int64_t> to_raw(decimal eu) const noexcept {
    auto f = raw_field();
    if (!f) return f.error();
    if (auto lo = detail::checked_limit(*this, false, any_node)) {
      if (auto d = lo.value().to_decimal(); d && compare(eu, d.value()) < 0) {
        return errc::out_of_range;
      }
    }
    if (auto hi = detail::checked_limit(*this, true, any_node)) {
      if (auto d = hi.value().to_decimal(); d && compare(eu, d.value()) > 0) {
        return errc::out_of_range;
      }
    }
    return scaling::to_raw(eu, scale, f.value());
  }
  /// The same from a double, read as the decimal it stands for with 15 significant digits
  /// (core decimal_from_double). Errors: also not_representable (NaN, infinity).
  [[nodiscard]] constexpr result<std::int64_t> to_raw(double eu) const noexcept {
    FIELDCODEC_TRY(const decimal d, decimal_from_double(eu));
    return to_raw(d);
  }
  /// The same from a float (a PLC REAL), read as its shortest round-trip decimal, never widened
  /// to double first: 90.73f at scale 327.67 is 29729.4991 → 29729 (core decimal_from_float).
  /// Errors: also not_representable (NaN, infinity).
  [[nodiscard]] constexpr result<std::int64_t> to_raw(float eu) const noexcept {
    FIELDCODEC_TRY(const decimal d, decimal_from_float(eu));
    return to_raw(d);
  }
  /// The same from an integer of any type, exactly. Errors: also not_representable (an
  /// unsigned value above INT64_MAX).
  template <std::integral I>
  requires(!std::same_as<I, bool>)
      [[nodiscard]] constexpr result<std::int64_t> to_raw(I eu) const noexcept {
    FIELDCODEC_TRY(const decimal d, decimal_from_integer(eu));
    return to_raw(d);
  }
  /// A bool is not an engineering value.
  result<std::int64_t> to_raw(bool) const = delete;

  /// Raw → engineering units as a double: raw / scale + offset.
  [[nodiscard]] constexpr double to_eu(std::int64_t raw) const noexcept {
    return scaling::to_eu(raw, scale);
  }
  /// Raw → engineering units, exactly, rounded half away from zero to `places` decimal places.
  /// Errors: invalid_argument (zero scale, places > 18), overflow.
  [[nodiscard]] constexpr result<decimal> to_eu_decimal(std::int64_t raw,
                                                        unsigned places) const noexcept {
    return scaling::to_eu_decimal(raw, scale, places);
  }

  /// The DCF ParameterValue for a node: info.parameter_value (+ node_id when
  /// flag::parameter_nodeid). Errors: as entry::default_for.
  [[nodiscard]] constexpr result<number> parameter_for(std::uint8_t node_id) const noexcept {
    return detail::plus_node(info.parameter_value, has(flag::parameter_nodeid), node_id);
  }
};

} // namespace fieldcodec::od
