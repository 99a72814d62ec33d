// fieldcodec — errors as values.
//
// result<T, E = errc> holds either a T or an E, shaped like std::expected (has_value, value,
// error, value_or, transform, and_then, or_else, transform_error). It is constexpr,
// [[nodiscard]] and works without exceptions or RTTI. Reading the value of an error (or the
// error of a value) is never silent: in a constant expression it does not compile, at run time
// it traps. Host programs that prefer an exception ask for one explicitly:
// core/result_exception.hpp (value_or_throw, describe), which is empty under -fno-exceptions.
//
// The codecs use plain errc. An error with context (an SDO transfer's abort code and object) is
// a struct with a public data member `errc code`: errc_of(e) reads it, r.is(errc) and
// `r == errc` work on it as on a plain errc.
//
// result<T> for a trivially copyable T (every codec result) is itself trivially copyable and
// trivially destructible: firmware copies it in registers. Owning types (std::vector,
// std::string, move-only types) are allowed for host code and are constructed, copied, moved
// and destroyed properly.
#pragma once

#include <concepts>
#include <cstdint>
#include <new>
#include <string_view>
#include <type_traits>
#include <utility>

namespace fieldcodec {

/// Every way a fieldcodec operation can fail. The numeric values are stable (they may be stored
/// or sent); new values are only ever appended. `errc{}` (0) is not an error: nothing returns
/// it, and "no error yet" is a `status{}`, never an errc (see docs/contributing.md, "Errors").
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

/// The errc an error value carries: the errc itself, or the public data member `errc code` of
/// an error with context (`struct transfer_error { errc code; std::uint32_t abort; … };`).
[[nodiscard]] constexpr errc errc_of(errc e) noexcept { return e; }
template <class E>
requires requires(const E &e) {
  { e.code } -> std::same_as<const errc &>;
}
[[nodiscard]] constexpr errc errc_of(const E &e) noexcept { return e.code; }

/// An error type that is an errc or carries one (errc_of works on it).
template <class E>
concept carries_errc = requires(const E &e) {
  { fieldcodec::errc_of(e) } -> std::same_as<errc>;
};

/// Tag: construct the error in place, `result<T, E>(unexpect, args…)` (like std::unexpect).
struct unexpect_t {
  explicit unexpect_t() = default;
};
inline constexpr unexpect_t unexpect{};

template <class T, class E = errc>
class result;

namespace detail {
// Not constexpr on purpose: reaching it during constant evaluation is a compile error.
[[noreturn]] inline void bad_result_access() noexcept { __builtin_trap(); }

template <class R>
inline constexpr bool is_result_v = false;
template <class T, class E>
inline constexpr bool is_result_v<result<T, E>> = true;

/// What result<void, E> holds as its "value".
struct unit {};

// Where result<T, E> keeps its value, its error and which one it holds. Four layouts:
//  0  T and E trivially destructible and default constructible: two plain members (a struct
//     of their own, then the flag). GCC's scalar replacement of aggregates gives up on unions,
//     so a union made every result<std::array<...>> cost extra stores of temporaries (an
//     encoder returning 4 bytes took 18 instructions instead of 11).
//  1  T and E trivially copyable (but one is not default constructible): one union; every
//     special member is implicit and trivial.
//  2  anything else (std::vector, std::string, move-only types): one union whose members are
//     constructed, copied, moved, assigned and destroyed by hand.
//  3  result<void, E> with E as for 0: the error and the flag.
template <class T, class E>
inline constexpr bool plain_members_v =
    std::conjunction_v<std::is_trivially_destructible<T>, std::is_trivially_destructible<E>,
                       std::is_default_constructible<T>, std::is_default_constructible<E>>;
template <class T, class E>
inline constexpr bool trivial_union_v =
    std::conjunction_v<std::is_trivially_copyable<T>, std::is_trivially_copyable<E>>;
template <class T, class E>
inline constexpr int storage_kind = plain_members_v<T, E> ? 0 : (trivial_union_v<T, E> ? 1 : 2);

template <class T, class E, int Kind = storage_kind<T, E>>
struct result_storage;

// Layout 0 places the flag where the first result<T> had it: after a {T, E} pair, at the
// pair's alignment. Packing it right after E instead (16 instead of 24 bytes for
// std::int64_t) measured 1 to 3 instructions more per call in bench/ (callgrind:
// the signed BCD position decode 91 instead of 88, scaling/to_raw 0.001 units 28 instead of 27).
template <class T, class E>
struct result_storage<T, E, 0> {
  static constexpr int layout = 0;
  template <class... A>
  constexpr explicit result_storage(std::in_place_t, A &&...a) noexcept(
      std::conjunction_v<std::is_nothrow_constructible<T, A...>,
                         std::is_nothrow_default_constructible<E>>)
      : value_(std::forward<A>(a)...), error_(), has_(true) {}
  template <class... A>
  constexpr explicit result_storage(unexpect_t, A &&...a) noexcept(
      std::conjunction_v<std::is_nothrow_constructible<E, A...>,
                         std::is_nothrow_default_constructible<T>>)
      : value_(), error_(std::forward<A>(a)...), has_(false) {}
  T value_;
  E error_;
  alignas(alignof(T) > alignof(E) ? alignof(T) : alignof(E)) bool has_;
};

// result<void, E>: no value member at all (status stays two bytes).
template <class E>
struct result_storage<unit, E, 0> {
  static constexpr int layout = 3;
  constexpr explicit result_storage(std::in_place_t) noexcept(
      std::is_nothrow_default_constructible_v<E>)
      : error_(), has_(true) {}
  template <class... A>
  constexpr explicit result_storage(unexpect_t,
                                    A &&...a) noexcept(std::is_nothrow_constructible_v<E, A...>)
      : error_(std::forward<A>(a)...), has_(false) {}
  E error_;
  bool has_;
};

template <class T, class E>
struct result_storage<T, E, 1> {
  static constexpr int layout = 1;
  template <class... A>
  constexpr explicit result_storage(std::in_place_t,
                                    A &&...a) noexcept(std::is_nothrow_constructible_v<T, A...>)
      : value_(std::forward<A>(a)...), has_(true) {}
  template <class... A>
  constexpr explicit result_storage(unexpect_t,
                                    A &&...a) noexcept(std::is_nothrow_constructible_v<E, A...>)
      : error_(std::forward<A>(a)...), has_(false) {}
  union {
    T value_;
    E error_;
  };
  bool has_;
};

// Placement new for the one operation constant evaluation cannot do without <memory>'s
// std::construct_at (switching an owning result between value and error by assignment).
// <memory> would double the parse time of every file that includes this header.
template <class U, class A>
void construct_in_place(U *p, A &&a) noexcept(std::is_nothrow_constructible_v<U, A>) {
  ::new (static_cast<void *>(p)) U(std::forward<A>(a));
}

// The union of layout 2. Its destructor does nothing: result_storage destroys the active member.
template <class T, class E>
union owning_union {
  template <class... A>
  constexpr explicit owning_union(std::in_place_t,
                                  A &&...a) noexcept(std::is_nothrow_constructible_v<T, A...>)
      : value_(std::forward<A>(a)...) {}
  template <class... A>
  constexpr explicit owning_union(unexpect_t,
                                  A &&...a) noexcept(std::is_nothrow_constructible_v<E, A...>)
      : error_(std::forward<A>(a)...) {}
  owning_union(const owning_union &) = delete;
  owning_union &operator=(const owning_union &) = delete;
  constexpr ~owning_union() {}
  T value_;
  E error_;
};

template <class T, class E>
struct result_storage<T, E, 2> {
  static constexpr int layout = 2;
  using union_type = owning_union<T, E>;

  template <class... A>
  constexpr explicit result_storage(std::in_place_t,
                                    A &&...a) noexcept(std::is_nothrow_constructible_v<T, A...>)
      : u_(std::in_place, std::forward<A>(a)...), has_(true) {}
  template <class... A>
  constexpr explicit result_storage(unexpect_t,
                                    A &&...a) noexcept(std::is_nothrow_constructible_v<E, A...>)
      : u_(unexpect, std::forward<A>(a)...), has_(false) {}

  // The member to build is chosen by a conditional of two prvalues, which initialises u_
  // directly (no copy of the union): constexpr without std::construct_at.
  constexpr result_storage(const result_storage &o) noexcept(
      std::conjunction_v<std::is_nothrow_copy_constructible<T>,
                         std::is_nothrow_copy_constructible<E>>)
      : u_(o.has_ ? union_type(std::in_place, o.u_.value_) : union_type(unexpect, o.u_.error_)),
        has_(o.has_) {}
  constexpr result_storage(result_storage &&o) noexcept(
      std::conjunction_v<std::is_nothrow_move_constructible<T>,
                         std::is_nothrow_move_constructible<E>>)
      : u_(o.has_ ? union_type(std::in_place, std::move(o.u_.value_))
                  : union_type(unexpect, std::move(o.u_.error_))),
        has_(o.has_) {}
  constexpr result_storage &operator=(const result_storage &o) {
    assign(o);
    return *this;
  }
  constexpr result_storage &operator=(result_storage &&o) noexcept(
      std::conjunction_v<std::is_nothrow_move_assignable<T>, std::is_nothrow_move_assignable<E>,
                         std::is_nothrow_move_constructible<T>,
                         std::is_nothrow_move_constructible<E>>) {
    assign(std::move(o));
    return *this;
  }
  constexpr ~result_storage() {
    if (has_) {
      u_.value_.~T();
    } else {
      u_.error_.~E();
    }
  }

  // Value to value and error to error assign (constexpr). Switching between them builds the new
  // member first (a throwing copy leaves *this unchanged), then destroys the old one and moves
  // the new one in (moves of T and E do not throw: result's assignment requires it); that
  // switch is not available in constant evaluation.
  template <class O>
  constexpr void assign(O &&o) {
    if (has_ && o.has_) {
      u_.value_ = std::forward<O>(o).u_.value_;
    } else if (!has_ && !o.has_) {
      u_.error_ = std::forward<O>(o).u_.error_;
    } else if (o.has_) {
      T tmp(std::forward<O>(o).u_.value_);
      u_.error_.~E();
      construct_in_place(__builtin_addressof(u_.value_), std::move(tmp));
      has_ = true;
    } else {
      E tmp(std::forward<O>(o).u_.error_);
      u_.value_.~T();
      construct_in_place(__builtin_addressof(u_.error_), std::move(tmp));
      has_ = false;
    }
  }

  union_type u_;
  bool has_;
};

// The value and the error of a storage, with the storage's value category (T&, const T&, T&&).
template <class S>
[[nodiscard]] constexpr decltype(auto) value_of(S &&s) noexcept {
  if constexpr (std::remove_cvref_t<S>::layout == 2) {
    return (std::forward<S>(s).u_.value_);
  } else {
    return (std::forward<S>(s).value_);
  }
}
template <class S>
[[nodiscard]] constexpr decltype(auto) error_of(S &&s) noexcept {
  if constexpr (std::remove_cvref_t<S>::layout == 2) {
    return (std::forward<S>(s).u_.error_);
  } else {
    return (std::forward<S>(s).error_);
  }
}

// Empty bases that delete result's copy/move constructors and assignments when T or E cannot
// do them (a non-trivial storage declares all of them, so they must be switched off here).
template <bool Copy, bool Move>
struct ctor_control {}; // <true, *>: everything implicit
template <>
struct ctor_control<false, true> {
  ctor_control() = default;
  ctor_control(const ctor_control &) = delete;
  ctor_control(ctor_control &&) = default;
  ctor_control &operator=(const ctor_control &) = default;
  ctor_control &operator=(ctor_control &&) = default;
};
template <>
struct ctor_control<false, false> {
  ctor_control() = default;
  ctor_control(const ctor_control &) = delete;
  ctor_control(ctor_control &&) = delete;
  ctor_control &operator=(const ctor_control &) = default;
  ctor_control &operator=(ctor_control &&) = default;
};
template <bool Copy, bool Move>
struct assign_control {};
template <>
struct assign_control<false, true> {
  assign_control() = default;
  assign_control(const assign_control &) = default;
  assign_control(assign_control &&) = default;
  assign_control &operator=(const assign_control &) = delete;
  assign_control &operator=(assign_control &&) = default;
};
template <>
struct assign_control<false, false> {
  assign_control() = default;
  assign_control(const assign_control &) = default;
  assign_control(assign_control &&) = default;
  assign_control &operator=(const assign_control &) = delete;
  assign_control &operator=(assign_control &&) = delete;
};

template <class T, class E>
inline constexpr bool copyable_v =
    std::conjunction_v<std::is_copy_constructible<T>, std::is_copy_constructible<E>>;
template <class T, class E>
inline constexpr bool movable_v =
    std::conjunction_v<std::is_move_constructible<T>, std::is_move_constructible<E>>;
// Assignment across value/error needs a move that does not throw (see result_storage<…, 2>).
template <class T, class E>
inline constexpr bool assign_safe_v =
    storage_kind<T, E> != 2 || std::conjunction_v<std::is_nothrow_move_constructible<T>,
                                                  std::is_nothrow_move_constructible<E>>;
template <class T, class E>
inline constexpr bool copy_assignable_v =
    std::conjunction_v<std::is_copy_assignable<T>, std::is_copy_assignable<E>,
                       std::bool_constant<copyable_v<T, E>>,
                       std::bool_constant<assign_safe_v<T, E>>>;
template <class T, class E>
inline constexpr bool move_assignable_v =
    std::conjunction_v<std::is_move_assignable<T>, std::is_move_assignable<E>,
                       std::bool_constant<movable_v<T, E>>,
                       std::bool_constant<assign_safe_v<T, E>>>;
template <class T, class E>
using ctor_control_for = ctor_control<copyable_v<T, E>, movable_v<T, E>>;
template <class T, class E>
using assign_control_for = assign_control<copy_assignable_v<T, E>, move_assignable_v<T, E>>;

template <class U>
inline constexpr bool is_tag_v = std::is_same_v<std::remove_cvref_t<U>, std::in_place_t> ||
                                 std::is_same_v<std::remove_cvref_t<U>, unexpect_t>;

// A converting constructor from some other type U builds the value only for class types T
// (`result<std::string> r = "text"`, unique_ptr<Derived> → unique_ptr<Base>) and only when U
// is not also an error: arithmetic conversions go through result(const T&), so the compiler
// diagnoses narrowing at the call site.
template <class T, class E, class U>
concept value_from = std::is_class_v<T> && !std::is_same_v<std::remove_cvref_t<U>, T> &&
                     !is_result_v<std::remove_cvref_t<U>> && !is_tag_v<U> &&
                     std::is_constructible_v<T, U> && !std::is_convertible_v<U, E>;
template <class T, class E, class G>
concept error_from =
    !std::is_same_v<std::remove_cvref_t<G>, E> && !is_result_v<std::remove_cvref_t<G>> &&
    !is_tag_v<G> && std::is_convertible_v<G, E> && !std::is_convertible_v<G, T>;

// Errors that are cheap to copy (errc, a small struct with context) are taken and given out by
// value, as plain errc always was: one constructor and one error() per result type, which
// keeps firmware small (GCC -Os emits the functions it does not inline once per overload).
template <class E>
inline constexpr bool by_value_v = std::is_trivially_copyable_v<E>;

template <class R, class Self>
concept exactly = std::is_same_v<R, Self>;

// What a result<T, E> compares with as a value: anything T compares with, except results and
// errors.
template <class U, class T, class E>
concept value_comparable = !is_result_v<U> && !std::is_same_v<U, errc> && !std::is_same_v<U, E> &&
                           requires(const T &t, const U &u) {
  { t == u } -> std::convertible_to<bool>;
};
} // namespace detail

/// A T or an error E. See the top of this file.
template <class T, class E>
class [[nodiscard]] result : private detail::ctor_control_for<T, E>,
                             private detail::assign_control_for<T, E> {
  static_assert(std::is_object_v<T> && !std::is_array_v<T>, "result<T>: T is a plain value type");
  static_assert(std::is_object_v<E> && !std::is_array_v<E> && !std::is_const_v<E>,
                "result<T, E>: E is a plain value type");
  static_assert(!std::is_same_v<std::remove_cv_t<T>, E>, "result<E, E> is ambiguous");
  static_assert(!std::is_convertible_v<const E &, T> && !std::is_convertible_v<const T &, E>,
                "result<T, E>: T and E must not convert into each other (a return statement "
                "must say unambiguously whether it returns a value or an error)");
  static_assert(!detail::is_tag_v<T> && !detail::is_result_v<std::remove_cv_t<T>>,
                "result<T>: T cannot be a tag or a result");

  // Layout 2 keeps its members in a named union, the others as plain members. The accessors
  // name the member directly: a helper function in between kept GCC -Os from passing a status
  // to an out-of-line error() in registers (IPA-SRA), ~100 bytes more in the firmware example.
  static constexpr bool owning_ = detail::storage_kind<T, E> == 2;

public:
  using value_type = T;
  using error_type = E;
  template <class U>
  using rebind = result<U, E>;

  // ---- construction ------------------------------------------------------------------------
  constexpr result(const T &v) noexcept(std::is_nothrow_copy_constructible_v<T>)
      : s_(std::in_place, v) {}
  constexpr result(T &&v) noexcept(std::is_nothrow_move_constructible_v<T>)
      : s_(std::in_place, std::move(v)) {}
  template <class U>
  requires detail::value_from<T, E, U>
  constexpr explicit(!std::is_convertible_v<U, T>)
      result(U &&v) noexcept(std::is_nothrow_constructible_v<T, U>)
      : s_(std::in_place, std::forward<U>(v)) {}
  template <class... A>
  constexpr explicit result(std::in_place_t,
                            A &&...a) noexcept(std::is_nothrow_constructible_v<T, A...>)
      : s_(std::in_place, std::forward<A>(a)...) {}

  constexpr result(E e) noexcept requires detail::by_value_v<E> : s_(unexpect, e) {}
  constexpr result(const E &e) noexcept(std::is_nothrow_copy_constructible_v<E>) requires(
      !detail::by_value_v<E>)
      : s_(unexpect, e) {}
  constexpr result(E &&e) noexcept(std::is_nothrow_move_constructible_v<E>) requires(
      !detail::by_value_v<E>)
      : s_(unexpect, std::move(e)) {}
  template <class G>
  requires detail::error_from<T, E, G>
  constexpr result(G &&g) noexcept(std::is_nothrow_constructible_v<E, G>)
      : s_(unexpect, std::forward<G>(g)) {}
  template <class... A>
  constexpr explicit result(unexpect_t, A &&...a) noexcept(std::is_nothrow_constructible_v<E, A...>)
      : s_(unexpect, std::forward<A>(a)...) {}

  // ---- observers ---------------------------------------------------------------------------
  [[nodiscard]] constexpr bool has_value() const noexcept { return s_.has_; }
  [[nodiscard]] constexpr explicit operator bool() const noexcept { return s_.has_; }

  /// The value. Traps (or fails to compile in a constant expression) on an error.
  [[nodiscard]] constexpr const T &value() const &noexcept {
    if (!s_.has_) detail::bad_result_access();
    if constexpr (owning_)
      return s_.u_.value_;
    else
      return s_.value_;
  }
  [[nodiscard]] constexpr T &value() &noexcept {
    if (!s_.has_) detail::bad_result_access();
    if constexpr (owning_)
      return s_.u_.value_;
    else
      return s_.value_;
  }
  /// From a temporary: the value moved out (by value, so it cannot dangle).
  [[nodiscard]] constexpr T value() &&noexcept(std::is_nothrow_move_constructible_v<T>) {
    if (!s_.has_) detail::bad_result_access();
    if constexpr (owning_)
      return std::move(s_.u_.value_);
    else
      return std::move(s_.value_);
  }
  [[nodiscard]] constexpr const T &operator*() const &noexcept { return value(); }
  [[nodiscard]] constexpr T &operator*() &noexcept { return value(); }
  [[nodiscard]] constexpr T operator*() &&noexcept(std::is_nothrow_move_constructible_v<T>) {
    return std::move(*this).value();
  }
  [[nodiscard]] constexpr const T *operator->() const noexcept {
    return __builtin_addressof(value());
  }
  [[nodiscard]] constexpr T *operator->() noexcept { return __builtin_addressof(value()); }

  /// The error. Traps (or fails to compile in a constant expression) on a value.
  [[nodiscard]] constexpr E error() const &noexcept requires detail::by_value_v<E> {
    if (s_.has_) detail::bad_result_access();
    if constexpr (owning_)
      return s_.u_.error_;
    else
      return s_.error_;
  }
  [[nodiscard]] constexpr const E &error() const &noexcept requires(!detail::by_value_v<E>) {
    if (s_.has_) detail::bad_result_access();
    if constexpr (owning_)
      return s_.u_.error_;
    else
      return s_.error_;
  }
  [[nodiscard]] constexpr E &error() &noexcept requires(!detail::by_value_v<E>) {
    if (s_.has_) detail::bad_result_access();
    if constexpr (owning_)
      return s_.u_.error_;
    else
      return s_.error_;
  }
  [[nodiscard]] constexpr E
  error() &&noexcept(std::is_nothrow_move_constructible_v<E>) requires(!detail::by_value_v<E>) {
    if (s_.has_) detail::bad_result_access();
    if constexpr (owning_)
      return std::move(s_.u_.error_);
    else
      return std::move(s_.error_);
  }

  /// The value, or `fallback` on an error.
  [[nodiscard]] constexpr T value_or(T fallback) const & {
    if (!s_.has_) return fallback;
    if constexpr (owning_)
      return s_.u_.value_;
    else
      return s_.value_;
  }
  [[nodiscard]] constexpr T value_or(T fallback) && {
    if (!s_.has_) return fallback;
    if constexpr (owning_)
      return std::move(s_.u_.value_);
    else
      return std::move(s_.value_);
  }

  /// True when this holds an error whose errc is `e` (E is errc or carries one).
  [[nodiscard]] constexpr bool is(errc e) const noexcept requires carries_errc<E> {
    if (s_.has_) return false;
    if constexpr (owning_)
      return errc_of(s_.u_.error_) == e;
    else
      return errc_of(s_.error_) == e;
  }

  // ---- monadic operations (like std::expected) ---------------------------------------------
  /// result<U, E> with U = f(value); an error passes through unchanged.
  template <class F>
  constexpr auto transform(F &&f) & {
    return transform_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto transform(F &&f) const & {
    return transform_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto transform(F &&f) && {
    return transform_(std::move(*this), std::forward<F>(f));
  }
  /// f(value), which returns a result<U, E>; an error passes through unchanged.
  template <class F>
  constexpr auto and_then(F &&f) & {
    return and_then_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto and_then(F &&f) const & {
    return and_then_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto and_then(F &&f) && {
    return and_then_(std::move(*this), std::forward<F>(f));
  }
  /// f(error), which returns a result<T, G> (a recovery or another error); a value passes
  /// through unchanged.
  template <class F>
  constexpr auto or_else(F &&f) & {
    return or_else_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto or_else(F &&f) const & {
    return or_else_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto or_else(F &&f) && {
    return or_else_(std::move(*this), std::forward<F>(f));
  }
  /// result<T, G> with G = f(error); a value passes through unchanged.
  template <class F>
  constexpr auto transform_error(F &&f) & {
    return transform_error_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto transform_error(F &&f) const & {
    return transform_error_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto transform_error(F &&f) && {
    return transform_error_(std::move(*this), std::forward<F>(f));
  }

  // ---- comparison --------------------------------------------------------------------------
  // Templates over the exact result type: nothing converts into a result to be compared (a T
  // would, and `t == x` could then call these again).
  /// Both hold equal values or equal errors.
  template <detail::exactly<result> R>
  friend constexpr bool operator==(const R &a, const R &b) {
    if (a.s_.has_ != b.s_.has_) return false;
    return a.s_.has_ ? static_cast<bool>(detail::value_of(a.s_) == detail::value_of(b.s_))
                     : static_cast<bool>(detail::error_of(a.s_) == detail::error_of(b.s_));
  }
  /// Holds an error whose errc is `e`.
  template <detail::exactly<result> R>
  requires carries_errc<E>
  friend constexpr bool operator==(const R &a, errc e) noexcept { return a.is(e); }
  /// Holds a value equal to `v`.
  template <detail::exactly<result> R, detail::value_comparable<T, E> U>
  friend constexpr bool operator==(const R &a, const U &v) {
    return a.s_.has_ && static_cast<bool>(detail::value_of(a.s_) == v);
  }

private:
  template <class Self, class F>
  static constexpr auto transform_(Self &&self, F &&f) {
    using V = decltype((detail::value_of(std::forward<Self>(self).s_)));
    using U = std::remove_cvref_t<decltype(std::forward<F>(f)(std::declval<V>()))>;
    using R = result<U, E>;
    if (!self.s_.has_) return R(unexpect, detail::error_of(std::forward<Self>(self).s_));
    if constexpr (std::is_void_v<U>) {
      std::forward<F>(f)(detail::value_of(std::forward<Self>(self).s_));
      return R();
    } else {
      return R(std::in_place, std::forward<F>(f)(detail::value_of(std::forward<Self>(self).s_)));
    }
  }
  template <class Self, class F>
  static constexpr auto and_then_(Self &&self, F &&f) {
    using V = decltype((detail::value_of(std::forward<Self>(self).s_)));
    using R = std::remove_cvref_t<decltype(std::forward<F>(f)(std::declval<V>()))>;
    static_assert(detail::is_result_v<R>, "and_then: f must return a result");
    static_assert(std::is_same_v<typename R::error_type, E>,
                  "and_then: f must return a result with the same error type");
    if (!self.s_.has_) return R(unexpect, detail::error_of(std::forward<Self>(self).s_));
    return std::forward<F>(f)(detail::value_of(std::forward<Self>(self).s_));
  }
  template <class Self, class F>
  static constexpr auto or_else_(Self &&self, F &&f) {
    using EV = decltype((detail::error_of(std::forward<Self>(self).s_)));
    using R = std::remove_cvref_t<decltype(std::forward<F>(f)(std::declval<EV>()))>;
    static_assert(detail::is_result_v<R>, "or_else: f must return a result");
    static_assert(std::is_same_v<typename R::value_type, T>,
                  "or_else: f must return a result with the same value type");
    if (self.s_.has_) return R(std::in_place, detail::value_of(std::forward<Self>(self).s_));
    return std::forward<F>(f)(detail::error_of(std::forward<Self>(self).s_));
  }
  template <class Self, class F>
  static constexpr auto transform_error_(Self &&self, F &&f) {
    using EV = decltype((detail::error_of(std::forward<Self>(self).s_)));
    using G = std::remove_cvref_t<decltype(std::forward<F>(f)(std::declval<EV>()))>;
    using R = result<T, G>;
    if (self.s_.has_) return R(std::in_place, detail::value_of(std::forward<Self>(self).s_));
    return R(unexpect, std::forward<F>(f)(detail::error_of(std::forward<Self>(self).s_)));
  }

  detail::result_storage<T, E> s_;
};

/// Success or an error E, without a value.
template <class E>
class [[nodiscard]] result<void, E> : private detail::ctor_control_for<detail::unit, E>,
                                      private detail::assign_control_for<detail::unit, E> {
  static_assert(std::is_object_v<E> && !std::is_array_v<E> && !std::is_const_v<E>,
                "result<void, E>: E is a plain value type");

  static constexpr bool owning_ = detail::storage_kind<detail::unit, E> == 2;

public:
  using value_type = void;
  using error_type = E;
  template <class U>
  using rebind = result<U, E>;

  /// Success.
  constexpr result() noexcept(std::is_nothrow_default_constructible_v<E>) : s_(std::in_place) {}
  constexpr explicit result(std::in_place_t) noexcept(std::is_nothrow_default_constructible_v<E>)
      : s_(std::in_place) {}
  constexpr result(E e) noexcept requires detail::by_value_v<E> : s_(unexpect, e) {}
  constexpr result(const E &e) noexcept(std::is_nothrow_copy_constructible_v<E>) requires(
      !detail::by_value_v<E>)
      : s_(unexpect, e) {}
  constexpr result(E &&e) noexcept(std::is_nothrow_move_constructible_v<E>) requires(
      !detail::by_value_v<E>)
      : s_(unexpect, std::move(e)) {}
  template <class G>
  requires detail::error_from<detail::unit, E, G>
  constexpr result(G &&g) noexcept(std::is_nothrow_constructible_v<E, G>)
      : s_(unexpect, std::forward<G>(g)) {}
  template <class... A>
  constexpr explicit result(unexpect_t, A &&...a) noexcept(std::is_nothrow_constructible_v<E, A...>)
      : s_(unexpect, std::forward<A>(a)...) {}

  [[nodiscard]] constexpr bool has_value() const noexcept { return s_.has_; }
  [[nodiscard]] constexpr explicit operator bool() const noexcept { return s_.has_; }
  /// Traps (or fails to compile in a constant expression) on an error.
  constexpr void value() const noexcept {
    if (!s_.has_) detail::bad_result_access();
  }
  constexpr void operator*() const noexcept { value(); }

  [[nodiscard]] constexpr E error() const &noexcept requires detail::by_value_v<E> {
    if (s_.has_) detail::bad_result_access();
    if constexpr (owning_)
      return s_.u_.error_;
    else
      return s_.error_;
  }
  [[nodiscard]] constexpr const E &error() const &noexcept requires(!detail::by_value_v<E>) {
    if (s_.has_) detail::bad_result_access();
    if constexpr (owning_)
      return s_.u_.error_;
    else
      return s_.error_;
  }
  [[nodiscard]] constexpr E &error() &noexcept requires(!detail::by_value_v<E>) {
    if (s_.has_) detail::bad_result_access();
    if constexpr (owning_)
      return s_.u_.error_;
    else
      return s_.error_;
  }
  [[nodiscard]] constexpr E
  error() &&noexcept(std::is_nothrow_move_constructible_v<E>) requires(!detail::by_value_v<E>) {
    if (s_.has_) detail::bad_result_access();
    if constexpr (owning_)
      return std::move(s_.u_.error_);
    else
      return std::move(s_.error_);
  }

  [[nodiscard]] constexpr bool is(errc e) const noexcept requires carries_errc<E> {
    if (s_.has_) return false;
    if constexpr (owning_)
      return errc_of(s_.u_.error_) == e;
    else
      return errc_of(s_.error_) == e;
  }

  /// result<U, E> with U = f(); an error passes through unchanged.
  template <class F>
  constexpr auto transform(F &&f) const & {
    return transform_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto transform(F &&f) && {
    return transform_(std::move(*this), std::forward<F>(f));
  }
  /// f(), which returns a result<U, E>; an error passes through unchanged.
  template <class F>
  constexpr auto and_then(F &&f) const & {
    return and_then_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto and_then(F &&f) && {
    return and_then_(std::move(*this), std::forward<F>(f));
  }
  /// f(error), which returns a result<void, G>; success passes through unchanged.
  template <class F>
  constexpr auto or_else(F &&f) const & {
    return or_else_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto or_else(F &&f) && {
    return or_else_(std::move(*this), std::forward<F>(f));
  }
  /// result<void, G> with G = f(error); success passes through unchanged.
  template <class F>
  constexpr auto transform_error(F &&f) const & {
    return transform_error_(*this, std::forward<F>(f));
  }
  template <class F>
  constexpr auto transform_error(F &&f) && {
    return transform_error_(std::move(*this), std::forward<F>(f));
  }

  template <detail::exactly<result> R>
  friend constexpr bool operator==(const R &a, const R &b) {
    if (a.s_.has_ != b.s_.has_) return false;
    return a.s_.has_ || static_cast<bool>(detail::error_of(a.s_) == detail::error_of(b.s_));
  }
  template <detail::exactly<result> R>
  requires carries_errc<E>
  friend constexpr bool operator==(const R &a, errc e) noexcept { return a.is(e); }

private:
  template <class Self, class F>
  static constexpr auto transform_(Self &&self, F &&f) {
    using U = std::remove_cvref_t<decltype(std::forward<F>(f)())>;
    using R = result<U, E>;
    if (!self.s_.has_) return R(unexpect, detail::error_of(std::forward<Self>(self).s_));
    if constexpr (std::is_void_v<U>) {
      std::forward<F>(f)();
      return R();
    } else {
      return R(std::in_place, std::forward<F>(f)());
    }
  }
  template <class Self, class F>
  static constexpr auto and_then_(Self &&self, F &&f) {
    using R = std::remove_cvref_t<decltype(std::forward<F>(f)())>;
    static_assert(detail::is_result_v<R>, "and_then: f must return a result");
    static_assert(std::is_same_v<typename R::error_type, E>,
                  "and_then: f must return a result with the same error type");
    if (!self.s_.has_) return R(unexpect, detail::error_of(std::forward<Self>(self).s_));
    return std::forward<F>(f)();
  }
  template <class Self, class F>
  static constexpr auto or_else_(Self &&self, F &&f) {
    using EV = decltype((detail::error_of(std::forward<Self>(self).s_)));
    using R = std::remove_cvref_t<decltype(std::forward<F>(f)(std::declval<EV>()))>;
    static_assert(detail::is_result_v<R>, "or_else: f must return a result");
    static_assert(std::is_void_v<typename R::value_type>,
                  "or_else: f must return a result<void, G>");
    if (self.s_.has_) return R();
    return std::forward<F>(f)(detail::error_of(std::forward<Self>(self).s_));
  }
  template <class Self, class F>
  static constexpr auto transform_error_(Self &&self, F &&f) {
    using EV = decltype((detail::error_of(std::forward<Self>(self).s_)));
    using G = std::remove_cvref_t<decltype(std::forward<F>(f)(std::declval<EV>()))>;
    using R = result<void, G>;
    if (self.s_.has_) return R();
    return R(unexpect, std::forward<F>(f)(detail::error_of(std::forward<Self>(self).s_)));
  }

  detail::result_storage<detail::unit, E> s_;
};

/// Success or an errc.
using status = result<void>;

} // namespace fieldcodec

#define FIELDCODEC_TRY_CAT2_(a, b) a##b
#define FIELDCODEC_TRY_CAT_(a, b) FIELDCODEC_TRY_CAT2_(a, b)

/// Propagate an error from an expression of type result<...>; otherwise continue.
///   FIELDCODEC_TRY_STATUS(w.write_u8(code));
#define FIELDCODEC_TRY_STATUS(expr)                                                                \
  do {                                                                                             \
    if (auto fieldcodec_try_r_ = (expr); !fieldcodec_try_r_)                                       \
      return std::move(fieldcodec_try_r_).error();                                                 \
  } while (false)

/// Evaluate `expr` (a result<T, E>); on an error, return the error from the enclosing function;
/// otherwise declare `decl` initialised with the value (moved out):
///   FIELDCODEC_TRY(const decimal d, parse_decimal(text));
/// It expands to several statements (a hidden result, the check, the declaration): write it as
/// a statement of its own, never as the unbraced body of an if or a loop; at most one per line.
#define FIELDCODEC_TRY(decl, expr)                                                                 \
  FIELDCODEC_TRY_IMPL_(decl, expr, FIELDCODEC_TRY_CAT_(fieldcodec_try_, __LINE__))
#define FIELDCODEC_TRY_IMPL_(decl, expr, tmp)                                                      \
  auto tmp = (expr);                                                                               \
  if (!tmp) return std::move(tmp).error();                                                         \
  decl = *std::move(tmp)
