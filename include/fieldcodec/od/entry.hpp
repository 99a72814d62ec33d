// fieldcodec — od::entry, the description of one sub-object of an object dictionary.
//
// A literal aggregate: generated dictionaries are plain designated initialisers, e.g.
//   {.index = 0x2023, .type = od::data_type::unsigned32, .name = "Inj. P Limit 1",
//    .low = od::num::i(0), .high = od::num::i(5000), .scale = {{32767, 2}, {0, 0}},
//    .scaled = true}
// Every member has a default, so an initialiser names only what the source file gives.
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/number.hpp>

#include <cstdint>
#include <limits>
#include <string_view>

namespace fieldcodec::od {

/// Flags of the dictionary-formats contract (bitmask in entry::flags).
namespace flag {
inline constexpr std::uint8_t range_exceeds_field = 0x01; ///< printed range does not fit the field
inline constexpr std::uint8_t index_anomaly = 0x02;       ///< printed index is odd, see remark
inline constexpr std::uint8_t signedness_guess = 0x04;    ///< signedness decided from the range
} // namespace flag

/// DPQ "Busmanager" column.
enum class bus_manager : std::uint8_t { unspecified, available, not_available };

/// No COMPAX index pointer.
inline constexpr std::uint8_t no_pointer = 0xFF;

struct entry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  object_code object = object_code::var; ///< code of the object this sub-object belongs to
  data_type type = data_type::unsigned8;
  access access_type = access::rw;
  pdo_mapping pdo = pdo_mapping::no;
  std::uint8_t flags = 0;  ///< od::flag bits
  std::uint32_t size = 0;  ///< bytes; 0 means fixed_size(type) (byte strings: size not given)
  std::string_view name{}; ///< name as the source prints it
  number low{};            ///< lowest allowed value: engineering units when `scaled`, raw otherwise
  number high{};           ///< highest allowed value, same units as `low`
  number default_value{};  ///< raw default; add the node-ID when `default_nodeid`
  bool default_nodeid = false;     ///< default is "$NODEID + default_value"
  std::string_view default_text{}; ///< default of a string / domain entry, as text
  scaling::linear scale{};         ///< raw = round((EU − offset) × scale)
  bool scaled = false;             ///< the source gives a scale (limits are then engineering units)
  std::string_view unit{};
  std::string_view alt_name{};
  std::uint8_t pointer = no_pointer; ///< COMPAX index pointer
  bus_manager bus = bus_manager::unspecified;
  std::string_view acceptance{};
  std::string_view section{};
  std::string_view remark{};
  std::uint32_t obj_flags = 0; ///< EDS ObjFlags
  number parameter_value{};    ///< DCF ParameterValue (configured value), raw
  bool parameter_nodeid = false;
  std::string_view parameter_text{}; ///< DCF ParameterValue of a string entry
  std::string_view denotation{};     ///< DCF Denotation

  /// Size of the value in bytes (0 for a byte string without a declared size).
  [[nodiscard]] constexpr std::uint32_t width() const noexcept {
    const std::uint8_t f = fixed_size(type);
    return f != 0U ? f : size;
  }

  /// The integer field a raw value travels in. Errors: type_mismatch (not an integer type).
  [[nodiscard]] constexpr result<scaling::field> raw_field() const noexcept {
    if (!is_integer(type)) return errc::type_mismatch;
    return scaling::field{fixed_size(type), is_signed_integer(type)};
  }

  /// The default value for a node: default_value (+ node_id when node-ID relative).
  /// Errors: unknown_object (no numeric default), overflow.
  [[nodiscard]] constexpr result<number> default_for(std::uint8_t node_id) const noexcept {
    return resolve(default_value, default_nodeid, node_id);
  }
  /// The same for the DCF ParameterValue.
  [[nodiscard]] constexpr result<number> parameter_for(std::uint8_t node_id) const noexcept {
    return resolve(parameter_value, parameter_nodeid, node_id);
  }

  /// Engineering units → raw: range check against [low, high] (engineering units when
  /// `scaled`, raw otherwise; a missing end is not checked), round((eu − offset) × scale)
  /// half away from zero, then a check against the field's width and signedness.
  /// Errors: type_mismatch (not an integer type), out_of_range, overflow, not_representable.
  [[nodiscard]] constexpr result<std::int64_t> to_raw(decimal eu) const noexcept {
    auto f = raw_field();
    if (!f) return f.error();
    if (auto lo = low.to_decimal(); lo && compare(eu, lo.value()) < 0) {
      return errc::out_of_range;
    }
    if (auto hi = high.to_decimal(); hi && compare(eu, hi.value()) > 0) {
      return errc::out_of_range;
    }
    return scaling::to_raw(eu, scale, f.value());
  }
  [[nodiscard]] constexpr result<std::int64_t> to_raw(double eu) const noexcept {
    auto d = decimal_from_double(eu);
    if (!d) return d.error();
    return to_raw(d.value());
  }

  /// Raw → engineering units: raw / scale + offset.
  [[nodiscard]] constexpr double to_eu(std::int64_t raw) const noexcept {
    return scaling::to_eu(raw, scale);
  }
  /// Raw → engineering units, exactly, rounded to `places` decimal places.
  [[nodiscard]] constexpr result<decimal> to_eu_decimal(std::int64_t raw,
                                                        unsigned places) const noexcept {
    return scaling::to_eu_decimal(raw, scale, places);
  }

private:
  [[nodiscard]] static constexpr result<number> resolve(number v, bool relative,
                                                        std::uint8_t node_id) noexcept {
    if (!v) return errc::unknown_object;
    if (!relative) return v;
    if (v.kind == number_kind::unsigned_) {
      if (v.bits > ~std::uint64_t{0} - node_id) return errc::overflow;
      return num::u(v.bits + node_id);
    }
    auto i = v.to_int64();
    if (!i) return i.error();
    if (i.value() > std::numeric_limits<std::int64_t>::max() - node_id) return errc::overflow;
    return num::i(i.value() + node_id);
  }
};

} // namespace fieldcodec::od
