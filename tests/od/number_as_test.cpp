// od::number_as<T>: an od::number as a C++ type, never narrowed (the primitive under
// od::decode<T> and canopen::sdo::upload_value<T>).
#include <fieldcodec/od/value.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <limits>

namespace od = fieldcodec::od;
using fieldcodec::errc;

static_assert(od::number_as<std::int8_t>(od::signed_number(-128)).value() == -128);
static_assert(od::number_as<std::int8_t>(od::signed_number(-129)) == errc::overflow);

TEST_CASE("number_as: integers at the ends of every integer T") {
  constexpr auto i64min = std::numeric_limits<std::int64_t>::min();
  constexpr auto u64max = std::numeric_limits<std::uint64_t>::max();
  CHECK(od::number_as<std::int64_t>(od::signed_number(i64min)).value() == i64min);
  CHECK(od::number_as<std::int64_t>(od::unsigned_number(0x7FFFFFFFFFFFFFFFU)).value() ==
        std::numeric_limits<std::int64_t>::max());
  CHECK(od::number_as<std::int64_t>(od::unsigned_number(0x8000000000000000U)) == errc::overflow);
  CHECK(od::number_as<std::uint64_t>(od::unsigned_number(u64max)).value() == u64max);
  CHECK(od::number_as<std::uint64_t>(od::signed_number(-1)) == errc::overflow);
  CHECK(od::number_as<std::uint64_t>(od::signed_number(i64min)) == errc::overflow);
  CHECK(od::number_as<std::uint8_t>(od::signed_number(255)).value() == 255);
  CHECK(od::number_as<std::uint8_t>(od::signed_number(256)) == errc::overflow);
  CHECK(od::number_as<std::int16_t>(od::unsigned_number(32768)) == errc::overflow);
  CHECK(od::number_as<std::int16_t>(od::signed_number(-32768)).value() == -32768);
  CHECK(od::number_as<bool>(od::unsigned_number(1)).value());
  CHECK(od::number_as<bool>(od::signed_number(-1)) == errc::overflow);
}

TEST_CASE("number_as: no value, decimals and reals for an integer T") {
  CHECK(od::number_as<int>(od::number{}) == errc::unknown_object);
  CHECK(od::number_as<double>(od::number{}) == errc::unknown_object);
  // a decimal is its value, not its mantissa
  CHECK(od::number_as<int>(od::decimal_number(20, 1)).value() == 2);
  CHECK(od::number_as<int>(od::decimal_number(15, 1)) == errc::not_representable);
  CHECK(od::number_as<std::uint8_t>(od::decimal_number(2560, 1)) == errc::overflow);
  CHECK(od::number_as<std::uint8_t>(od::decimal_number(-10, 1)) == errc::overflow);
  CHECK(od::number_as<std::int64_t>(od::decimal_number(1000000000000000000, 18)).value() == 1);
  CHECK(od::number_as<std::int64_t>(od::decimal_number(0, 200)).value() == 0);
  CHECK(od::number_as<std::int64_t>(od::decimal_number(1, 30)) == errc::not_representable);
  CHECK(od::number_as<std::int64_t>(od::decimal_number(-1000, 2)).value() == -10);
  // a real is never an integer's value
  CHECK(od::number_as<int>(od::real_number(3.0)) == errc::not_representable);
}

TEST_CASE("number_as: floating-point T holds the value exactly or refuses it") {
  // integers: 24 / 53 significant bits
  CHECK(od::number_as<float>(od::unsigned_number(16777217)) == errc::not_representable);
  CHECK(od::number_as<float>(od::unsigned_number(16777218)).value() == 16777218.0F);
  CHECK(od::number_as<double>(od::unsigned_number(0x20000000000001U)) == errc::not_representable);
  CHECK(od::number_as<double>(od::unsigned_number(0x20000000000002U)).value() ==
        9007199254740994.0);
  CHECK(
      od::number_as<double>(od::signed_number(std::numeric_limits<std::int64_t>::min())).value() ==
      -9223372036854775808.0);
  // reals: a double into float only when it is a float value
  CHECK(od::number_as<float>(od::real_number(0.5)).value() == 0.5F);
  CHECK(od::number_as<float>(od::real_number(static_cast<double>(0.1F))).value() == 0.1F);
  CHECK(od::number_as<float>(od::real_number(0.1)) == errc::not_representable);
  CHECK(od::number_as<float>(od::real_number(1e39)) == errc::overflow);
  CHECK(od::number_as<float>(od::real_number(-1e39)) == errc::overflow);
  CHECK(od::number_as<double>(od::real_number(0.1)).value() == 0.1);
  CHECK(od::number_as<double>(od::real_number(std::numeric_limits<double>::quiet_NaN())) ==
        errc::not_representable);
  // a decimal is the nearest value (no exact binary form in general)
  CHECK(od::number_as<double>(od::decimal_number(1, 1)).value() == 0.1);
  CHECK(od::number_as<float>(od::decimal_number(1, 1)).value() == 0.1F);
}
