// fieldcodec — errors as values.
//
// result<T> holds either a T or an errc. It is constexpr, [[nodiscard]] and works without
// exceptions or RTTI. Reading the value of an error (or the error of a value) is never silent:
// in a constant expression it does not compile, at run time it traps.
#pragma once

#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

namespace fieldcodec {

/// Every way a fieldcodec operation can fail. The numeric values are stable (they may be stored
/// or sent); new values are only ever appended.
enum class errc : std::uint8_t {
  truncated = 1,     ///< input ended before the value or frame was complete
  bad_length,        ///< a length, size or count disagrees with the content or the rules
  bad_digit,         ///< a character or nibble is not a valid digit
  bad_sign,          ///< a sign byte or sign character is not one of the allowed ones
  bad_checksum,      ///< a check value does not match the data
  out_of_range,      ///< the value lies outside the allowed minimum/maximum
  overflow,          ///< the value does not fit the field's width and signedness
  not_representable, ///< NaN, infinity, or a value that would lose precision
  unknown_object,    ///< index/sub-index, parameter or object not known
  unexpected_frame,  ///< a frame arrived that does not fit the current protocol step
  bad_toggle,        ///< a toggle bit did not alternate
  unknown_command,   ///< a command code or command specifier is not defined
  buffer_too_small,  ///< the caller's output buffer cannot hold the result
  bad_syntax,        ///< text does not follow the required format
  type_mismatch,     ///< the value's type is not the type the object or command requires
  access_denied,     ///< read of a write-only or write of a read-only object
  timeout,           ///< the peer did not answer in time
  aborted,           ///< the peer aborted the transfer
  bad_state,         ///< the operation is not allowed in the current state
  invalid_argument,  ///< an argument is outside what the function accepts (e.g. node-ID 0)
  too_long,          ///< a field or frame is longer than the protocol allows
  bad_character,     ///< a character outside the allowed set
};

/// A short, stable, lower-case text for each error (never changes once released).
[[nodiscard]] constexpr std::string_view to_string(errc e) noexcept {
  switch (e) {
  case errc::truncated: return "truncated input";
  case errc::bad_length: return "bad length";
  case errc::bad_digit: return "bad digit";
  case errc::bad_sign: return "bad sign";
  case errc::bad_checksum: return "bad checksum";
  case errc::out_of_range: return "value out of range";
  case errc::overflow: return "value does not fit the field";
  case errc::not_representable: return "value not representable";
  case errc::unknown_object: return "unknown object";
  case errc::unexpected_frame: return "unexpected frame";
  case errc::bad_toggle: return "toggle bit did not alternate";
  case errc::unknown_command: return "unknown command";
  case errc::buffer_too_small: return "output buffer too small";
  case errc::bad_syntax: return "bad syntax";
  case errc::type_mismatch: return "type mismatch";
  case errc::access_denied: return "access denied";
  case errc::timeout: return "timeout";
  case errc::aborted: return "aborted by peer";
  case errc::bad_state: return "not allowed in the current state";
  case errc::invalid_argument: return "invalid argument";
  case errc::too_long: return "too long";
  case errc::bad_character: return "character not allowed";
  }
  return "unknown error";
}

namespace detail {
// Not constexpr on purpose: reaching it during constant evaluation is a compile error.
[[noreturn]] inline void bad_result_access() noexcept { __builtin_trap(); }

// Where result<T> keeps its value and its error. Two plain members when T can be default
// constructed: GCC's scalar replacement of aggregates gives up on unions, so a union made every
// result<std::array<...>> cost extra stores of temporaries (an encoder returning 4 bytes took
// 18 instructions instead of 11). Other types share one union.
template <class T, bool Split = std::is_default_constructible_v<T>>
struct result_storage {
  constexpr explicit result_storage(const T &v) noexcept(std::is_nothrow_copy_constructible_v<T>)
      : value_(v) {}
  constexpr explicit result_storage(T &&v) noexcept(std::is_nothrow_move_constructible_v<T>)
      : value_(std::move(v)) {}
  constexpr explicit result_storage(errc e) noexcept : value_(), error_(e) {}
  T value_;
  errc error_{};
};
template <class T>
struct result_storage<T, false> {
  constexpr explicit result_storage(const T &v) noexcept(std::is_nothrow_copy_constructible_v<T>)
      : value_(v) {}
  constexpr explicit result_storage(T &&v) noexcept(std::is_nothrow_move_constructible_v<T>)
      : value_(std::move(v)) {}
  constexpr explicit result_storage(errc e) noexcept : error_(e) {}
  union {
    T value_;
    errc error_;
  };
};
} // namespace detail

template <class T>
class [[nodiscard]] result {
  static_assert(!std::is_same_v<std::remove_cv_t<T>, errc>, "result<errc> is ambiguous");
  static_assert(!std::is_reference_v<T>, "result<T&> is not supported");
  static_assert(std::is_trivially_destructible_v<T>, "fieldcodec results hold plain values");

public:
  using value_type = T;

  constexpr result(const T &v) noexcept(std::is_nothrow_copy_constructible_v<T>)
      : s_(v), has_(true) {}
  constexpr result(T &&v) noexcept(std::is_nothrow_move_constructible_v<T>)
      : s_(std::move(v)), has_(true) {}
  constexpr result(errc e) noexcept : s_(e), has_(false) {}

  [[nodiscard]] constexpr bool has_value() const noexcept { return has_; }
  [[nodiscard]] constexpr explicit operator bool() const noexcept { return has_; }

  /// The value. Traps (or fails to compile in a constant expression) on an error.
  [[nodiscard]] constexpr const T &value() const &noexcept {
    if (!has_) detail::bad_result_access();
    return s_.value_;
  }
  [[nodiscard]] constexpr T &value() &noexcept {
    if (!has_) detail::bad_result_access();
    return s_.value_;
  }
  [[nodiscard]] constexpr T value() &&noexcept {
    if (!has_) detail::bad_result_access();
    return std::move(s_.value_);
  }
  [[nodiscard]] constexpr const T &operator*() const &noexcept { return value(); }
  [[nodiscard]] constexpr const T *operator->() const noexcept { return &value(); }

  /// The error. Traps (or fails to compile in a constant expression) on a value.
  [[nodiscard]] constexpr errc error() const noexcept {
    if (has_) detail::bad_result_access();
    return s_.error_;
  }

  /// The value, or `fallback` on an error.
  [[nodiscard]] constexpr T value_or(T fallback) const noexcept {
    return has_ ? s_.value_ : fallback;
  }

  /// True when this holds the error `e`.
  [[nodiscard]] constexpr bool is(errc e) const noexcept { return !has_ && s_.error_ == e; }

  /// Apply `f` to the value; an error passes through unchanged.
  template <class F>
  constexpr auto transform(F &&f) const {
    using U = std::remove_cvref_t<decltype(f(s_.value_))>;
    if (!has_) return result<U>(s_.error_);
    return result<U>(f(s_.value_));
  }
  /// Apply `f` (which returns a result) to the value; an error passes through unchanged.
  template <class F>
  constexpr auto and_then(F &&f) const {
    using R = std::remove_cvref_t<decltype(f(s_.value_))>;
    if (!has_) return R(s_.error_);
    return f(s_.value_);
  }

  friend constexpr bool operator==(const result &a, const result &b) noexcept {
    if (a.has_ != b.has_) return false;
    return a.has_ ? a.s_.value_ == b.s_.value_ : a.s_.error_ == b.s_.error_;
  }
  friend constexpr bool operator==(const result &a, errc e) noexcept { return a.is(e); }

private:
  detail::result_storage<T> s_;
  bool has_;
};

/// Success or an error, without a value.
template <>
class [[nodiscard]] result<void> {
public:
  using value_type = void;
  constexpr result() noexcept = default;
  constexpr result(errc e) noexcept : error_(e), has_(false) {}

  [[nodiscard]] constexpr bool has_value() const noexcept { return has_; }
  [[nodiscard]] constexpr explicit operator bool() const noexcept { return has_; }
  /// Traps (or fails to compile in a constant expression) on an error.
  constexpr void value() const noexcept {
    if (!has_) detail::bad_result_access();
  }
  [[nodiscard]] constexpr errc error() const noexcept {
    if (has_) detail::bad_result_access();
    return error_;
  }
  [[nodiscard]] constexpr bool is(errc e) const noexcept { return !has_ && error_ == e; }
  friend constexpr bool operator==(const result &a, const result &b) noexcept {
    return a.has_ == b.has_ && (a.has_ || a.error_ == b.error_);
  }
  friend constexpr bool operator==(const result &a, errc e) noexcept { return a.is(e); }

private:
  errc error_{errc::truncated};
  bool has_{true};
};

using status = result<void>;

} // namespace fieldcodec

/// Propagate an error from an expression of type result<...>; otherwise continue.
#define FIELDCODEC_TRY_STATUS(expr)                                                                \
  do {                                                                                             \
    if (auto fieldcodec_try_r_ = (expr); !fieldcodec_try_r_) return fieldcodec_try_r_.error();     \
  } while (false)
