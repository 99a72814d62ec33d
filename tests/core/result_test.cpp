#include <fieldcodec/core/result.hpp>

#include <doctest/doctest.h>

#include <set>
#include <string_view>

using fieldcodec::errc;
using fieldcodec::result;

namespace {
constexpr result<int> half(int v) {
  if (v % 2 != 0) return errc::bad_digit;
  return v / 2;
}
} // namespace

static_assert(half(8).value() == 4);
static_assert(!half(7).has_value());
static_assert(half(7).error() == errc::bad_digit);
static_assert(half(7).value_or(-1) == -1);
static_assert(half(7) == errc::bad_digit);
static_assert(half(8) == result<int>(4));
static_assert(half(8).and_then(half).value() == 2);
static_assert(half(6).and_then(half).error() == errc::bad_digit);
static_assert(half(8).transform([](int v) { return v * 10; }).value() == 40);
static_assert(fieldcodec::status{}.has_value());
static_assert(fieldcodec::status{errc::overflow}.is(errc::overflow));

TEST_CASE("result holds a value or an error") {
  auto ok = half(10);
  REQUIRE(ok);
  CHECK(*ok == 5);
  CHECK(ok.value() == 5);
  CHECK_FALSE(ok.is(errc::bad_digit));

  auto bad = half(3);
  REQUIRE_FALSE(bad);
  CHECK(bad.error() == errc::bad_digit);
  CHECK(bad.value_or(99) == 99);
  CHECK(bad != result<int>(errc::truncated));
}

TEST_CASE("every errc has a distinct, stable text") {
  std::set<std::string_view> texts;
  for (int v = 1; v <= static_cast<int>(errc::bad_character); ++v) {
    const auto e = static_cast<errc>(v);
    const auto t = fieldcodec::to_string(e);
    CHECK(t != "unknown error");
    CHECK(texts.insert(t).second);
  }
  // The texts are part of the interface: spot-check that they do not change.
  CHECK(fieldcodec::to_string(errc::truncated) == "truncated input");
  CHECK(fieldcodec::to_string(errc::bad_checksum) == "bad checksum");
  CHECK(fieldcodec::to_string(errc::overflow) == "value does not fit the field");
  CHECK(fieldcodec::to_string(static_cast<errc>(0)) == "unknown error");
  // The numeric values are stable too.
  CHECK(static_cast<int>(errc::truncated) == 1);
  CHECK(static_cast<int>(errc::bad_checksum) == 5);
  CHECK(static_cast<int>(errc::bad_character) == 22);
}

namespace {
fieldcodec::status forward(bool fail) {
  FIELDCODEC_TRY_STATUS(fail ? fieldcodec::status{errc::timeout} : fieldcodec::status{});
  return {};
}
} // namespace

TEST_CASE("FIELDCODEC_TRY_STATUS propagates the error") {
  CHECK(forward(false).has_value());
  CHECK(forward(true).is(errc::timeout));
}
