// fieldcodec — the one binary search of the od layer: the first element of a sorted span whose
// key is not less than a wanted key. Dictionaries (by address), objects (by sub-index) and
// command tables (by code) all search through it.
#pragma once

#include <cstddef>
#include <span>

namespace fieldcodec::od::detail {

/// Index of the first element `x` of `s` with `!(key_of(x) < key)`, or `s.size()` when there is
/// none. `s` must be sorted by `key_of` (non-decreasing). O(log n), constexpr.
template <class T, class Key, class KeyOf>
[[nodiscard]] constexpr std::size_t lower_bound(std::span<const T> s, const Key &key,
                                                KeyOf key_of) noexcept {
  std::size_t lo = 0;
  std::size_t hi = s.size();
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2U; // spans hold far fewer than SIZE_MAX / 2 elements
    if (key_of(s[mid]) < key) {
      lo = mid + 1U;
    } else {
      hi = mid;
    }
  }
  return lo;
}

/// Index of the element whose key equals `key`, or `s.size()` when there is none (`s` sorted,
/// keys unique). Lookups that answer "not found" test this index, never a pointer: g++ 12 with
/// -fsanitize=undefined cannot constant-evaluate the comparison of a pointer into a constexpr
/// table with nullptr, and the lookups run in static_asserts.
template <class T, class Key, class KeyOf>
[[nodiscard]] constexpr std::size_t position(std::span<const T> s, const Key &key,
                                             KeyOf key_of) noexcept {
  const std::size_t i = lower_bound(s, key, key_of);
  return i < s.size() && key_of(s[i]) == key ? i : s.size();
}

/// The element whose key equals `key`, or nullptr (`s` sorted, keys unique).
template <class T, class Key, class KeyOf>
[[nodiscard]] constexpr const T *find(std::span<const T> s, const Key &key, KeyOf key_of) noexcept {
  const std::size_t i = position(s, key, key_of);
  return i < s.size() ? s.data() + i : nullptr;
}

} // namespace fieldcodec::od::detail
