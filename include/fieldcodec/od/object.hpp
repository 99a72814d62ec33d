// fieldcodec — od::object, a named view over the sub-entries of one ARRAY, RECORD or
// DEFSTRUCT object of a dictionary (generated headers emit one per such object).
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/entry.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::od {

struct object {
  std::uint16_t index = 0;
  object_code code = object_code::var;
  std::string_view name{};
  std::span<const entry> entries{}; ///< sorted by sub-index (sub-indices may have gaps)

  [[nodiscard]] constexpr std::size_t size() const noexcept { return entries.size(); }
  [[nodiscard]] constexpr auto begin() const noexcept { return entries.begin(); }
  [[nodiscard]] constexpr auto end() const noexcept { return entries.end(); }

  /// The sub-entry `sub`, or nullptr.
  [[nodiscard]] constexpr const entry *find(std::uint8_t sub) const noexcept {
    std::size_t lo = 0;
    std::size_t hi = entries.size();
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2U;
      if (entries[mid].sub < sub) {
        lo = mid + 1U;
      } else {
        hi = mid;
      }
    }
    if (lo < entries.size() && entries[lo].sub == sub) return &entries[lo];
    return nullptr;
  }
  /// Errors: unknown_object.
  [[nodiscard]] constexpr result<const entry *> lookup(std::uint8_t sub) const noexcept {
    const entry *e = find(sub);
    if (e == nullptr) return errc::unknown_object;
    return e;
  }
};

} // namespace fieldcodec::od
