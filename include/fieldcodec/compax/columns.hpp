// fieldcodec — the COMPAX column of its object table: each communication object's 7-bit index
// pointer, the number OBJECT_REQ names it by (manual 000, "OBJECT_REQ and OBJECT_RSP";
// compax/object_channel.hpp). It is not a CiA 301 column, so it is not in od::entry_info: the
// generator writes it, for a CSV with a `pointer` column, as the table `compax_columns` beside
// the dictionary (one row per object that has a pointer, sorted like the entries;
// od/columns.hpp):
//
//   namespace d = fieldcodec::dictionaries::compax_objects;
//   compax::index_pointer(d::compax_columns, d::speed)                     → 38
//   compax::object_read(compax::index_pointer(d::compax_columns, d::speed).value())
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/columns.hpp>
#include <fieldcodec/od/entry.hpp>

#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::compax {

/// One row of `compax_columns`: the index pointer of the object at (index, sub).
struct object_columns {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::uint8_t pointer = 0; ///< 0..127 as the table prints it
};

/// The index pointer of the entry at `a` in `table` (a generated `compax_columns`).
/// Errors: unknown_object (the entry has no index pointer: not reachable over OBJECT_REQ).
[[nodiscard]] constexpr result<std::uint8_t> index_pointer(std::span<const object_columns> table,
                                                           od::address a) noexcept {
  const std::size_t i = od::row_position(table, a);
  if (i == table.size()) return errc::unknown_object;
  return table[i].pointer;
}
/// The index pointer of `e` (any entry or descriptor) in `table`. Errors: as above.
[[nodiscard]] constexpr result<std::uint8_t> index_pointer(std::span<const object_columns> table,
                                                           const od::entry &e) noexcept {
  return index_pointer(table, od::address{e.index, e.sub});
}

} // namespace fieldcodec::compax
