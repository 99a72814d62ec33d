// fieldcodec — od::object, a named view over the sub-entries of one ARRAY, RECORD or DEFSTRUCT
// object of a dictionary (generated headers emit one per such object; od::dictionary::object
// returns one for any index), with their descriptive columns and scales by position.
//
//   namespace d = fieldcodec::dictionaries::my_drive;   // a generated dictionary with 1018h
//                                                       // "Identity object" (a RECORD)
//   d::identity_object[2]              → od::descriptor of 1018h sub 2 (traps if there is none)
//   d::identity_object.at(2)           → result<od::descriptor> (unknown_object if there is none)
//   d::identity_object.find(2)         → const od::entry * (nullptr if there is none)
//   od::encode(d::identity_object, 2, value, out)        (od/value.hpp: object + sub-index)
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/detail/search.hpp>
#include <fieldcodec/od/entry.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

namespace fieldcodec::od {

namespace detail {

/// Position of `e` in `s`, or s.size() when `e` is not an element of `s` (compared by address;
/// at compile time by a scan, because ordering pointers into different arrays is not a
/// constant expression).
[[nodiscard]] constexpr std::size_t position_of(std::span<const entry> s, const entry &e) noexcept {
  if (std::is_constant_evaluated()) {
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (&s[i] == &e) return i;
    }
    return s.size();
  }
  // At run time by address arithmetic on integers: ordering pointers into different arrays
  // with `<` is unspecified, comparing their integer values is not.
  const auto at = reinterpret_cast<std::uintptr_t>(&e);
  const auto first = reinterpret_cast<std::uintptr_t>(s.data());
  if (at < first || at - first >= s.size_bytes() || (at - first) % sizeof(entry) != 0U) {
    return s.size();
  }
  return static_cast<std::size_t>((at - first) / sizeof(entry));
}

/// The descriptor of entry `i` of parallel tables (`infos` / `scales` may be empty).
[[nodiscard]] constexpr descriptor describe_at(std::span<const entry> entries,
                                               std::span<const entry_info> infos,
                                               std::span<const scaling::linear> scales,
                                               std::size_t i) noexcept {
  descriptor d{entries[i]};
  if (i < infos.size()) d.info = infos[i];
  if (i < scales.size()) d.scale = scales[i];
  return d;
}

/// Ends the program (at compile time: not a constant expression) — a missing sub-index asked
/// for with operator[].
[[noreturn]] inline void missing_sub_index() noexcept { __builtin_trap(); }

} // namespace detail

struct object {
  std::uint16_t index = 0;
  object_code code = object_code::var;
  std::string_view name{};                   ///< empty when made by od::dictionary::object
  std::span<const entry> entries{};          ///< sorted by sub-index (sub-indices may have gaps)
  std::span<const entry_info> infos{};       ///< parallel to entries, or empty
  std::span<const scaling::linear> scales{}; ///< parallel to entries, or empty (no scales)

  [[nodiscard]] constexpr std::size_t size() const noexcept { return entries.size(); }
  [[nodiscard]] constexpr bool empty() const noexcept { return entries.empty(); }
  [[nodiscard]] constexpr auto begin() const noexcept { return entries.begin(); }
  [[nodiscard]] constexpr auto end() const noexcept { return entries.end(); }

  /// Position of sub-entry `sub` in entries(), or size() when there is none.
  [[nodiscard]] constexpr std::size_t position(std::uint8_t sub) const noexcept {
    return detail::position(entries, sub, [](const entry &e) { return e.sub; });
  }
  /// The sub-entry `sub`, or nullptr.
  [[nodiscard]] constexpr const entry *find(std::uint8_t sub) const noexcept {
    const std::size_t i = position(sub);
    return i < entries.size() ? entries.data() + i : nullptr;
  }
  /// Whether sub-entry `sub` exists.
  [[nodiscard]] constexpr bool contains(std::uint8_t sub) const noexcept {
    return position(sub) < entries.size();
  }
  /// The sub-entry `sub`. Errors: unknown_object.
  [[nodiscard]] constexpr result<const entry *> lookup(std::uint8_t sub) const noexcept {
    const std::size_t i = position(sub);
    if (i == entries.size()) return errc::unknown_object;
    return entries.data() + i;
  }

  /// The descriptor of sub-object `sub`. Errors: unknown_object.
  [[nodiscard]] constexpr result<descriptor> at(std::uint8_t sub) const noexcept {
    const std::size_t i = position(sub);
    if (i == entries.size()) return errc::unknown_object;
    return detail::describe_at(entries, infos, scales, i);
  }
  /// The descriptor of sub-object `sub`, which must exist: a missing sub-index ends the program
  /// (and is a compile error in a constant expression). Use at() or find() when it may not.
  [[nodiscard]] constexpr descriptor operator[](std::uint8_t sub) const noexcept {
    const std::size_t i = position(sub);
    if (i == entries.size()) detail::missing_sub_index();
    return detail::describe_at(entries, infos, scales, i);
  }

  /// The descriptive columns of `e` (by position); od::no_info when `e` is not one of this
  /// object's entries or the object has no infos.
  [[nodiscard]] constexpr const entry_info &info(const entry &e) const noexcept {
    const std::size_t i = detail::position_of(entries, e);
    return i < infos.size() ? infos[i] : no_info;
  }
  /// The scale of `e` (by position); the identity when `e` is not one of this object's entries
  /// or the object has no scales.
  [[nodiscard]] constexpr scaling::linear scale(const entry &e) const noexcept {
    const std::size_t i = detail::position_of(entries, e);
    return i < scales.size() ? scales[i] : scaling::linear{};
  }
  /// `e` with its info and scale. Errors: unknown_object (`e` is not one of this object's
  /// entries: its scale is not known here).
  [[nodiscard]] constexpr result<descriptor> describe(const entry &e) const noexcept {
    const std::size_t i = detail::position_of(entries, e);
    if (i == entries.size()) return errc::unknown_object;
    return detail::describe_at(entries, infos, scales, i);
  }
};

} // namespace fieldcodec::od
