// core/result_exception.hpp: exceptions and messages on request, for host programs.
//
// This file is also compiled with -fno-exceptions (tests/CMakeLists.txt,
// fieldcodec_result_exception_absent): there the header must declare nothing, which the
// static_asserts at the bottom prove (a call that does not compile, not one that fails).
#include <fieldcodec/core/result_exception.hpp>

#include <cstdint>
#include <string>
#include <utility>

// value_or_throw is found by argument-dependent lookup on the result when it is declared.
template <class R>
concept can_throw = requires(R r) {
  value_or_throw(r);
};
template <class R>
concept can_describe = requires(const R &r) {
  describe(r);
};

#if defined(__cpp_exceptions)

#include <doctest/doctest.h>

#include <memory>
#include <stdexcept>
#include <type_traits>

using fieldcodec::errc;
using fieldcodec::result;

namespace ctx {
/// An error with context, with its own description next to it.
struct transfer_error {
  errc code;
  std::uint32_t abort = 0;
};
std::string describe(const transfer_error &e) {
  return std::string(fieldcodec::to_string(e.code)) + " (abort code " + std::to_string(e.abort) +
         ")";
}
/// An error with context and no description of its own.
struct bare_error {
  errc code;
  int detail = 0;
};
} // namespace ctx

static_assert(can_throw<result<int>>);
static_assert(can_throw<fieldcodec::status>);
static_assert(can_throw<result<int, ctx::transfer_error>>);
static_assert(can_describe<result<int>>);

namespace {
struct text_error {
  const char *text;
};
} // namespace
// an error that carries no errc has no exception to become
static_assert(!can_throw<result<int, text_error>>);

TEST_CASE("value_or_throw gives the value or throws bad_result with the errc and its text") {
  CHECK(fieldcodec::value_or_throw(result<int>(7)) == 7);
  result<int> lvalue = 8;
  fieldcodec::value_or_throw(lvalue) = 9; // a reference into an lvalue
  CHECK(lvalue.value() == 9);
  static_assert(std::is_same_v<decltype(fieldcodec::value_or_throw(lvalue)), int &>);
  static_assert(std::is_same_v<decltype(fieldcodec::value_or_throw(result<int>(1))), int>);

  const result<int> bad = errc::out_of_range;
  CHECK_THROWS_AS((void)fieldcodec::value_or_throw(bad), fieldcodec::bad_result);
  CHECK_THROWS_AS((void)fieldcodec::value_or_throw(bad), std::exception);
  CHECK_THROWS_WITH((void)fieldcodec::value_or_throw(bad), "value out of range");
  try {
    (void)fieldcodec::value_or_throw(bad);
    FAIL("did not throw");
  } catch (const fieldcodec::bad_result &e) {
    CHECK(e.code() == errc::out_of_range);
    CHECK(std::string(e.what()) == "value out of range");
  }

  fieldcodec::value_or_throw(fieldcodec::status{}); // nothing to return, nothing thrown
  CHECK_THROWS_WITH(fieldcodec::value_or_throw(fieldcodec::status{errc::timeout}), "timeout");

  // owning and move-only values come out of a temporary
  auto p = fieldcodec::value_or_throw(result<std::unique_ptr<int>>(std::make_unique<int>(3)));
  CHECK(*p == 3);
  CHECK(fieldcodec::value_or_throw(result<std::string>("text")) == "text");
}

TEST_CASE("an error with context is thrown whole and described by its own describe") {
  const result<int, ctx::transfer_error> r = ctx::transfer_error{errc::aborted, 0x06020000U};
  try {
    (void)fieldcodec::value_or_throw(r);
    FAIL("did not throw");
  } catch (const fieldcodec::bad_result_of<ctx::transfer_error> &e) {
    CHECK(e.code() == errc::aborted);
    CHECK(e.error().abort == 0x06020000U);
    CHECK(std::string(e.what()) == "aborted by peer (abort code 100794368)");
  }
  // the base class catches it too
  CHECK_THROWS_AS((void)fieldcodec::value_or_throw(r), fieldcodec::bad_result);

  const result<int, ctx::bare_error> b = ctx::bare_error{errc::timeout, 4};
  CHECK_THROWS_WITH((void)fieldcodec::value_or_throw(b), "timeout");
}

TEST_CASE("describe says ok or what went wrong") {
  CHECK(fieldcodec::describe(result<int>(1)) == "ok");
  CHECK(fieldcodec::describe(fieldcodec::status{}) == "ok");
  CHECK(fieldcodec::describe(result<int>(errc::bad_checksum)) == "bad checksum");
  CHECK(fieldcodec::describe(fieldcodec::status{errc::bad_length}) == "bad length");
  CHECK(fieldcodec::describe(errc::overflow) == "value does not fit the field");
  CHECK(fieldcodec::describe(result<int, ctx::transfer_error>(
            ctx::transfer_error{errc::aborted, 5})) == "aborted by peer (abort code 5)");
  CHECK(fieldcodec::describe(result<int, ctx::bare_error>(ctx::bare_error{errc::timeout})) ==
        "timeout");
}

#else // compiled with -fno-exceptions: nothing is declared

static_assert(!can_throw<fieldcodec::result<int>>);
static_assert(!can_throw<fieldcodec::status>);
static_assert(!can_describe<fieldcodec::result<int>>);

#endif
