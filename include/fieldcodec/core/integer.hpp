// fieldcodec — integer arguments of any type, checked instead of narrowed.
//
// A function that fills a narrower field (a 16-bit command parameter, an int32 date) takes
// any integer type the caller has (`int`, `unsigned`, `long`, `std::int64_t`, `std::uint8_t`,
// `bool`) through the `integer_argument` concept, so that no overload set can be ambiguous,
// and compares the value itself — never a converted copy — against the field:
//
//   checked_narrow<std::uint16_t>(65537)        → errc::overflow (not 1)
//   checked_narrow<std::int32_t>(-1L)           → -1
//   in_closed_range(std::uint64_t{1} << 63, 0, 10) → false (no wrap to a negative number)
//
// Character types (`char`, `wchar_t`, `char8_t`, `char16_t`, `char32_t`) are not integer
// arguments: a character where a number belongs is a mistake at the call site.
#pragma once

#include <fieldcodec/core/result.hpp>

#include <concepts>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

namespace fieldcodec {

namespace detail {
template <class T>
inline constexpr bool is_character_v =
    std::is_same_v<std::remove_cv_t<T>, char> || std::is_same_v<std::remove_cv_t<T>, wchar_t> ||
    std::is_same_v<std::remove_cv_t<T>, char8_t> || std::is_same_v<std::remove_cv_t<T>, char16_t> ||
    std::is_same_v<std::remove_cv_t<T>, char32_t>;
} // namespace detail

/// Any integer type (signed, unsigned, bool) except the character types.
template <class T>
concept integer_argument = std::integral<T> && !detail::is_character_v<T>;

namespace detail {
/// `bool` is an integer argument, but the std::cmp_* functions do not take it: 0 or 1.
template <integer_argument T>
[[nodiscard]] constexpr auto comparable(T v) noexcept {
  if constexpr (std::is_same_v<std::remove_cv_t<T>, bool>) {
    return v ? 1U : 0U;
  } else {
    return v;
  }
}
} // namespace detail

/// True when `lo <= v <= hi`, compared by value whatever the types' signedness.
template <integer_argument T, integer_argument L, integer_argument H>
[[nodiscard]] constexpr bool in_closed_range(T v, L lo, H hi) noexcept {
  const auto x = detail::comparable(v);
  return !std::cmp_less(x, detail::comparable(lo)) && !std::cmp_greater(x, detail::comparable(hi));
}

/// `v` as a `To` (not `bool`) when it fits. Errors: overflow (outside the range of `To`).
template <integer_argument To, integer_argument From>
requires(!std::is_same_v<std::remove_cv_t<To>, bool>)
    [[nodiscard]] constexpr result<To> checked_narrow(From v) noexcept {
  const auto x = detail::comparable(v);
  if (!std::in_range<To>(x)) return errc::overflow;
  return static_cast<To>(x);
}

} // namespace fieldcodec
