// fieldcodec — od::dictionary, a constexpr view over an array of entries sorted by
// (index, sub-index): O(log n) lookup, the sub-entries of one object, iteration.
//
//   inline constexpr std::array<od::entry, 3> entries{{...}};       // sorted
//   inline constexpr od::dictionary dictionary{entries};
//   static_assert(dictionary.is_valid());
//   auto e = dictionary.lookup(0x1018, 2);                         // result<const entry *>
//   for (const od::entry &sub : dictionary.object(0x1018)) { ... }
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/entry.hpp>

#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::od {

class dictionary {
public:
  using const_iterator = std::span<const entry>::iterator;

  constexpr dictionary() noexcept = default;
  constexpr explicit dictionary(std::span<const entry> entries) noexcept : entries_(entries) {}

  /// Strictly increasing (index, sub-index): sorted and no duplicates. Generated headers
  /// static_assert it; lookups assume it.
  [[nodiscard]] constexpr bool is_valid() const noexcept {
    for (std::size_t i = 1; i < entries_.size(); ++i) {
      if (!less(entries_[i - 1U], entries_[i].index, entries_[i].sub)) return false;
    }
    return true;
  }

  [[nodiscard]] constexpr std::size_t size() const noexcept { return entries_.size(); }
  [[nodiscard]] constexpr bool empty() const noexcept { return entries_.empty(); }
  [[nodiscard]] constexpr const_iterator begin() const noexcept { return entries_.begin(); }
  [[nodiscard]] constexpr const_iterator end() const noexcept { return entries_.end(); }
  [[nodiscard]] constexpr std::span<const entry> entries() const noexcept { return entries_; }

  /// The entry (index, sub), or nullptr.
  [[nodiscard]] constexpr const entry *find(std::uint16_t index, std::uint8_t sub) const noexcept {
    const std::size_t i = lower_bound(index, sub);
    if (i < entries_.size() && entries_[i].index == index && entries_[i].sub == sub) {
      return &entries_[i];
    }
    return nullptr;
  }

  /// The entry (index, sub). Errors: unknown_object.
  [[nodiscard]] constexpr result<const entry *> lookup(std::uint16_t index,
                                                       std::uint8_t sub) const noexcept {
    const entry *e = find(index, sub);
    if (e == nullptr) return errc::unknown_object;
    return e;
  }

  [[nodiscard]] constexpr bool contains(std::uint16_t index, std::uint8_t sub) const noexcept {
    return find(index, sub) != nullptr;
  }

  /// All sub-entries of object `index` in sub-index order (empty when the object is unknown).
  [[nodiscard]] constexpr std::span<const entry> object(std::uint16_t index) const noexcept {
    const std::size_t first = lower_bound(index, 0);
    std::size_t lo = first; // end of the object: a second binary search
    std::size_t hi = entries_.size();
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2U;
      if (entries_[mid].index <= index) {
        lo = mid + 1U;
      } else {
        hi = mid;
      }
    }
    return entries_.subspan(first, lo - first);
  }

  /// Number of distinct objects (indices).
  [[nodiscard]] constexpr std::size_t object_count() const noexcept {
    std::size_t n = 0;
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      if (i == 0U || entries_[i].index != entries_[i - 1U].index) ++n;
    }
    return n;
  }

private:
  [[nodiscard]] static constexpr bool less(const entry &e, std::uint16_t index,
                                           std::uint8_t sub) noexcept {
    return e.index < index || (e.index == index && e.sub < sub);
  }
  [[nodiscard]] constexpr std::size_t lower_bound(std::uint16_t index,
                                                  std::uint8_t sub) const noexcept {
    std::size_t lo = 0;
    std::size_t hi = entries_.size();
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2U;
      if (less(entries_[mid], index, sub)) {
        lo = mid + 1U;
      } else {
        hi = mid;
      }
    }
    return lo;
  }

  std::span<const entry> entries_{};
};

} // namespace fieldcodec::od
