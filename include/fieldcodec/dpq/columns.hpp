// fieldcodec — the DPQ's own columns of its parameter table (manual RE 30146-02-Z, chapter 4):
// each parameter's "Value acceptance" and whether BODAC's Bus Manager can map it. They are not
// CiA 301 columns, so they are not in od::entry_info: the generator writes them, for a CSV with an
// `acceptance` or `bus_manager` column, as the table `dpq_columns` beside the dictionary (one row
// per parameter that has them, sorted like the entries; od/columns.hpp):
//
//   namespace p = fieldcodec::dictionaries::dpq_parameters;
//   dpq::columns_of(p::dpq_columns, p::inj_p_limit_1).value_acceptance
//       → dpq::acceptance::also_when_enabled
//   dpq::columns_of(p::dpq_columns, p::inj_p_limit_1).bus → dpq::bus_manager::available
//
// dpq/lookup.hpp checks a write against the acceptance (dpq::check_acceptance).
#pragma once

#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/columns.hpp>
#include <fieldcodec/od/entry.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::dpq {

/// When the card takes a new value of a parameter (chapter 4, "Value acceptance").
enum class acceptance : std::uint8_t {
  unknown,            ///< no or an unrecognised text (not a DPQ parameter)
  only_when_disabled, ///< "only with deactivated enabling"
  also_when_enabled,  ///< "also with active enabling"
};

/// The acceptance a printed text names (exactly as printed); unknown for any other text.
[[nodiscard]] constexpr acceptance parse_acceptance(std::string_view text) noexcept {
  if (text == "only with deactivated enabling") return acceptance::only_when_disabled;
  if (text == "also with active enabling") return acceptance::also_when_enabled;
  return acceptance::unknown;
}

/// The "Busmanager" column: can BODAC's Bus Manager map the parameter into a PDO.
enum class bus_manager : std::uint8_t { unspecified, available, not_available };

/// The Bus Manager value a printed text names ("available", "not available", exactly);
/// unspecified for any other text.
[[nodiscard]] constexpr bus_manager parse_bus_manager(std::string_view text) noexcept {
  if (text == "available") return bus_manager::available;
  if (text == "not available") return bus_manager::not_available;
  return bus_manager::unspecified;
}

/// One row of `dpq_columns`: the DPQ columns of the parameter at (index, sub).
struct parameter_columns {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  acceptance value_acceptance = acceptance::unknown;
  bus_manager bus = bus_manager::unspecified;
};

/// The DPQ columns of the entry at `a` in `table` (a generated `dpq_columns`); a row with
/// acceptance::unknown and bus_manager::unspecified when the entry has none (a communication
/// object of chapter 3, or an entry of another dictionary).
[[nodiscard]] constexpr parameter_columns columns_of(std::span<const parameter_columns> table,
                                                     od::address a) noexcept {
  const std::size_t i = od::row_position(table, a);
  if (i == table.size()) return parameter_columns{a.index, a.sub, {}, {}};
  return table[i];
}
/// The DPQ columns of `e` (any entry or descriptor) in `table`.
[[nodiscard]] constexpr parameter_columns columns_of(std::span<const parameter_columns> table,
                                                     const od::entry &e) noexcept {
  return columns_of(table, od::address{e.index, e.sub});
}

} // namespace fieldcodec::dpq
