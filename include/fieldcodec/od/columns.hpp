// fieldcodec — od::row_position: tables of columns that only some devices have, kept beside a
// generated dictionary instead of in od::entry_info (a manufacturer's column of a parameter
// table, e.g. when a device accepts a write). The row type is the device folder's; od knows only
// that a row names its sub-object by `index` and `sub`. The generator writes such a table in the
// dictionary's namespace, one row per entry that has the columns, in the order of the entries
// (sorted by index, then sub-index); a device header answers from it by address:
//
//   struct my_columns { std::uint16_t index; std::uint8_t sub; std::uint8_t level; };
//   inline constexpr my_columns rows[]{{.index = 0x2000, .level = 3}, {.index = 0x2001, .level =
//   1}}; od::row_position(std::span<const my_columns>(rows), {0x2001, 0})   → 1
//   od::row_position(std::span<const my_columns>(rows), {0x2002, 0})   → 2 (rows.size(): none)
#pragma once

#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/detail/search.hpp>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::od {

/// A row of a column table: names its sub-object by `index` and `sub`.
template <class Row>
concept column_row = requires(const Row &r) {
  { r.index } -> std::convertible_to<std::uint16_t>;
  { r.sub } -> std::convertible_to<std::uint8_t>;
};

namespace detail {
template <column_row Row>
[[nodiscard]] constexpr std::uint32_t row_key(const Row &r) noexcept {
  return (std::uint32_t{r.index} << 8U) | r.sub;
}
} // namespace detail

/// Strictly increasing (index, sub-index): sorted, one row per sub-object. row_position assumes it.
template <column_row Row>
[[nodiscard]] constexpr bool rows_sorted(std::span<const Row> rows) noexcept {
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (detail::row_key(rows[i]) <= detail::row_key(rows[i - 1U])) return false;
  }
  return true;
}

/// The position of the row of `a` in `rows` (sorted, see rows_sorted), or rows.size() when `a`
/// has none. O(log n), constexpr.
template <column_row Row>
[[nodiscard]] constexpr std::size_t row_position(std::span<const Row> rows, address a) noexcept {
  const std::uint32_t key = (std::uint32_t{a.index} << 8U) | a.sub;
  return detail::position(rows, key, [](const Row &r) { return detail::row_key(r); });
}

} // namespace fieldcodec::od
