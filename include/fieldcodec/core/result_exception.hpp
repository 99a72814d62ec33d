// fieldcodec — host only: an exception or a message out of a result, on request.
//
// Nothing else in fieldcodec throws. A host program that prefers exceptions to checking every
// result asks for one at the call site:
//
//   #include <fieldcodec/core/result_exception.hpp>
//   auto raw = fieldcodec::value_or_throw(entry.to_raw(4.0));   // throws bad_result on error
//   std::puts(fieldcodec::describe(r).c_str());                   // "ok" or the error's text
//
// Built with -fno-exceptions (firmware), this header declares nothing: a call does not compile
// instead of failing at run time, and no firmware build pulls in <string> or <stdexcept> by
// including a codec.
#pragma once

#include <fieldcodec/core/result.hpp>

#if defined(__cpp_exceptions)

#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace fieldcodec {

/// What value_or_throw throws (catch this one): the errc and its text as what().
class bad_result : public std::runtime_error {
public:
  bad_result(errc code, const std::string &message) : std::runtime_error(message), code_(code) {}
  [[nodiscard]] errc code() const noexcept { return code_; }

private:
  errc code_;
};

/// The exception actually thrown for a result<T, E>: also carries the whole error (an error
/// with context keeps its abort code, object, …).
template <class E>
class bad_result_of : public bad_result {
public:
  bad_result_of(E error, const std::string &message)
      : bad_result(errc_of(error), message), error_(std::move(error)) {}
  [[nodiscard]] const E &error() const noexcept { return error_; }

private:
  E error_;
};

/// The text of an error: to_string(errc) as a std::string.
[[nodiscard]] inline std::string describe(errc e) { return std::string(to_string(e)); }

/// The text of an error with context: the text of its errc. An error type declares its own
/// `std::string describe(const E&)` next to it (found by argument-dependent lookup) to say more.
template <class E>
requires(carries_errc<E> && !std::is_same_v<E, errc>) [[nodiscard]] std::string
    describe(const E &e) {
  return describe(errc_of(e));
}

/// "ok" for a value, otherwise the text of the error.
template <class T, class E>
[[nodiscard]] std::string describe(const result<T, E> &r) {
  if (r.has_value()) return "ok";
  return describe(r.error());
}

/// The value of `r` (a reference into an lvalue, the value itself from a temporary); throws
/// bad_result_of<E> (a bad_result) when `r` holds an error. For result<void, E>, returns nothing.
template <class R>
requires(detail::is_result_v<std::remove_cvref_t<R>>
             &&carries_errc<typename std::remove_cvref_t<R>::error_type>) decltype(auto)
    value_or_throw(R &&r) {
  using E = typename std::remove_cvref_t<R>::error_type;
  if (!r.has_value()) {
    const E &e = r.error();
    throw bad_result_of<E>(e, describe(e));
  }
  return std::forward<R>(r).value();
}

} // namespace fieldcodec

#endif // __cpp_exceptions
