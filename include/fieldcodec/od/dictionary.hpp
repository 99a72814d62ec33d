// fieldcodec — od::dictionary, a constexpr view over up to three parallel tables: the entries
// sorted by (index, sub-index), their descriptive columns (infos) and their scales. The last two
// may be empty; when present they have one element per entry, joined by position.
//
//   inline constexpr std::array<od::entry, 3> entries{{...}};       // sorted
//   inline constexpr std::array<od::entry_info, 3> infos{{...}};    // same order
//   inline constexpr od::dictionary dictionary{entries, infos};
//   static_assert(dictionary.is_valid());
//   auto e = dictionary.lookup({0x1018, 2});                       // result<const entry *>
//   dictionary.info(*e.value()).name                                // "Product code"
//   auto d = dictionary.at({0x1018, 2});                           // result<od::descriptor>
//   for (const od::entry &sub : dictionary.object(0x1018)) { ... }
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/detail/search.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/object.hpp>

#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::od {

class dictionary {
public:
  using const_iterator = std::span<const entry>::iterator;

  constexpr dictionary() noexcept = default;
  constexpr explicit dictionary(std::span<const entry> entries,
                                std::span<const entry_info> infos = {},
                                std::span<const scaling::linear> scales = {}) noexcept
      : entries_(entries), infos_(infos), scales_(scales) {}

  /// Strictly increasing (index, sub-index) (sorted, no duplicates), infos and scales either
  /// empty or one per entry, and a scale table when an entry is scaled. Generated headers
  /// static_assert it; lookups assume it.
  [[nodiscard]] constexpr bool is_valid() const noexcept {
    if (!infos_.empty() && infos_.size() != entries_.size()) return false;
    if (!scales_.empty() && scales_.size() != entries_.size()) return false;
    // Plain integer work on a pointer and a count, no call per entry: every generated header
    // evaluates this at compile time for each of its entries, and a span subscript and a key_of
    // call per entry made it 3 times as dear (docs/performance.md, "Compile time").
    const entry *const e = entries_.data();
    const std::size_t n = entries_.size();
    std::uint32_t previous = 0;
    std::uint16_t flags = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t key = (std::uint32_t{e[i].index} << 8U) | e[i].sub;
      if (i > 0U && key <= previous) return false;
      previous = key;
      flags = static_cast<std::uint16_t>(flags | e[i].flags);
    }
    return !scales_.empty() || (flags & flag::scaled) == 0U;
  }

  [[nodiscard]] constexpr std::size_t size() const noexcept { return entries_.size(); }
  [[nodiscard]] constexpr bool empty() const noexcept { return entries_.empty(); }
  [[nodiscard]] constexpr const_iterator begin() const noexcept { return entries_.begin(); }
  [[nodiscard]] constexpr const_iterator end() const noexcept { return entries_.end(); }
  [[nodiscard]] constexpr std::span<const entry> entries() const noexcept { return entries_; }
  [[nodiscard]] constexpr std::span<const entry_info> infos() const noexcept { return infos_; }
  [[nodiscard]] constexpr std::span<const scaling::linear> scales() const noexcept {
    return scales_;
  }

  /// Position of the entry at `a` in entries(), or size() when there is none. O(log n).
  [[nodiscard]] constexpr std::size_t position(address a) const noexcept {
    return detail::position(entries_, key_of(a), key_of_entry);
  }
  /// The entry at `a`, or nullptr. O(log n).
  [[nodiscard]] constexpr const entry *find(address a) const noexcept {
    const std::size_t i = position(a);
    return i < entries_.size() ? entries_.data() + i : nullptr;
  }
  [[nodiscard]] constexpr const entry *find(std::uint16_t index, std::uint8_t sub) const noexcept {
    return find(address{index, sub});
  }

  /// The entry at `a`. Errors: unknown_object.
  [[nodiscard]] constexpr result<const entry *> lookup(address a) const noexcept {
    const std::size_t i = position(a);
    if (i == entries_.size()) return errc::unknown_object;
    return entries_.data() + i;
  }
  [[nodiscard]] constexpr result<const entry *> lookup(std::uint16_t index,
                                                       std::uint8_t sub) const noexcept {
    return lookup(address{index, sub});
  }

  [[nodiscard]] constexpr bool contains(address a) const noexcept {
    return position(a) < entries_.size();
  }
  [[nodiscard]] constexpr bool contains(std::uint16_t index, std::uint8_t sub) const noexcept {
    return contains(address{index, sub});
  }

  /// The descriptor (entry, info, scale) at `a`. Errors: unknown_object.
  [[nodiscard]] constexpr result<descriptor> at(address a) const noexcept {
    const std::size_t i = position(a);
    if (i == entries_.size()) return errc::unknown_object;
    return detail::describe_at(entries_, infos_, scales_, i);
  }
  [[nodiscard]] constexpr result<descriptor> at(std::uint16_t index,
                                                std::uint8_t sub) const noexcept {
    return at(address{index, sub});
  }

  /// Position of `e` in entries(), or size() when `e` is not an element of this dictionary.
  [[nodiscard]] constexpr std::size_t position(const entry &e) const noexcept {
    return detail::position_of(entries_, e);
  }
  /// The descriptive columns of `e` (by position); od::no_info when `e` is not an element of
  /// this dictionary or the dictionary has no infos.
  [[nodiscard]] constexpr const entry_info &info(const entry &e) const noexcept {
    const std::size_t i = position(e);
    return i < infos_.size() ? infos_[i] : no_info;
  }
  /// The scale of `e` (by position); the identity when `e` is not an element of this dictionary
  /// or the dictionary has no scales.
  [[nodiscard]] constexpr scaling::linear scale(const entry &e) const noexcept {
    const std::size_t i = position(e);
    return i < scales_.size() ? scales_[i] : scaling::linear{};
  }
  /// `e` with its info and scale. Errors: unknown_object (`e` is not an element of this
  /// dictionary: its scale is not known here).
  [[nodiscard]] constexpr result<descriptor> describe(const entry &e) const noexcept {
    const std::size_t i = position(e);
    if (i == entries_.size()) return errc::unknown_object;
    return detail::describe_at(entries_, infos_, scales_, i);
  }

  /// All sub-entries of object `index` in sub-index order, with their infos and scales (empty
  /// when the object is unknown). The view's name is empty: a dictionary keeps the names of
  /// sub-objects, not of ARRAY/RECORD objects (generated headers name those).
  [[nodiscard]] constexpr od::object object(std::uint16_t index) const noexcept {
    const std::size_t first =
        detail::lower_bound(entries_, key_of(address{index, 0}), key_of_entry);
    const std::size_t last =
        detail::lower_bound(entries_, key_of(address{index, 0xFF}) + 1U, key_of_entry);
    const std::size_t n = last - first;
    od::object o;
    o.index = index;
    o.entries = entries_.subspan(first, n);
    if (n != 0U) o.code = entries_[first].object;
    if (!infos_.empty()) o.infos = infos_.subspan(first, n);
    if (!scales_.empty()) o.scales = scales_.subspan(first, n);
    return o;
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
  /// (index, sub) as one integer in the same order as od::address.
  [[nodiscard]] static constexpr std::uint32_t key_of(address a) noexcept {
    return (std::uint32_t{a.index} << 8U) | a.sub;
  }
  [[nodiscard]] static constexpr std::uint32_t key_of(const entry &e) noexcept {
    return (std::uint32_t{e.index} << 8U) | e.sub;
  }
  [[nodiscard]] static constexpr std::uint32_t key_of_entry(const entry &e) noexcept {
    return key_of(e);
  }

  std::span<const entry> entries_{};
  std::span<const entry_info> infos_{};
  std::span<const scaling::linear> scales_{};
};

} // namespace fieldcodec::od
