#include <fieldcodec/core/ieee754.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>

namespace ieee = fieldcodec::ieee754;
using fieldcodec::byte_order;
using fieldcodec::errc;
using b4 = std::array<std::uint8_t, 4>;

// PA-CONTROL manual (001) 5.2.4.13: 10.0 → 4120 0000 (big-endian on Profibus).
static_assert(ieee::encode_float32(10.0F, byte_order::big).value() == b4{0x41, 0x20, 0x00, 0x00});
static_assert(ieee::encode_float32(10.0F, byte_order::little).value() ==
              b4{0x00, 0x00, 0x20, 0x41});
// 111.111 → 42DE 38D5 (5.2.4.14).
static_assert(ieee::to_bits(111.111F) == 0x42DE38D5U);
static_assert(ieee::decode_float32(b4{0x42, 0xDE, 0x38, 0xD5}, byte_order::big).value() ==
              111.111F);
static_assert(ieee::to_bits(-1.0F) == 0xBF800000U);
static_assert(ieee::to_bits(1.0) == 0x3FF0000000000000U);
static_assert(ieee::encode_float64(-2.0, byte_order::big).value()[0] == 0xC0);

// Non-finite values.
static_assert(ieee::encode_float32(std::numeric_limits<float>::infinity(), byte_order::big)
                  .error() == errc::not_representable);
static_assert(ieee::encode_float32(std::numeric_limits<float>::quiet_NaN(), byte_order::big)
                  .error() == errc::not_representable);
static_assert(ieee::encode_float32(std::numeric_limits<float>::infinity(), byte_order::big,
                                   ieee::nonfinite::allow)
                  .value() == b4{0x7F, 0x80, 0x00, 0x00});
static_assert(ieee::decode_float32(b4{0x7F, 0xC0, 0x00, 0x00}, byte_order::big).error() ==
              errc::not_representable);
static_assert(ieee::decode_float32(b4{0xFF, 0x80, 0x00, 0x00}, byte_order::big).error() ==
              errc::not_representable);
static_assert(ieee::decode_float32(b4{0x7F, 0x7F, 0xFF, 0xFF}, byte_order::big).value() ==
              std::numeric_limits<float>::max());
static_assert(ieee::decode_float32(b4{0x00, 0x00, 0x00, 0x01}, byte_order::big).value() ==
              std::numeric_limits<float>::denorm_min());

TEST_CASE("float32 truncated input and NaN pass-through") {
  const std::array<std::uint8_t, 3> three{0x41, 0x20, 0x00};
  CHECK(ieee::decode_float32(three, byte_order::big).error() == errc::truncated);
  auto nan =
      ieee::decode_float32(b4{0x7F, 0xC0, 0x00, 0x01}, byte_order::big, ieee::nonfinite::allow);
  REQUIRE(nan);
  CHECK(std::isnan(nan.value()));
  CHECK(ieee::to_bits(nan.value()) == 0x7FC00001U);
}

TEST_CASE("float64 both orders and bad input") {
  auto be = ieee::encode_float64(1516.95, byte_order::big).value();
  auto le = ieee::encode_float64(1516.95, byte_order::little).value();
  for (std::size_t i = 0; i < 8; ++i) CHECK(be[i] == le[7 - i]);
  CHECK(ieee::decode_float64(be, byte_order::big).value() == 1516.95);
  CHECK(ieee::decode_float64(le, byte_order::little).value() == 1516.95);
  CHECK(ieee::decode_float64(std::span(be).first(7), byte_order::big).error() == errc::truncated);
  const std::array<std::uint8_t, 8> inf{0x7F, 0xF0, 0, 0, 0, 0, 0, 0};
  CHECK(ieee::decode_float64(inf, byte_order::big).error() == errc::not_representable);
  CHECK(std::isinf(ieee::decode_float64(inf, byte_order::big, ieee::nonfinite::allow).value()));
  CHECK(ieee::encode_float64(std::nan(""), byte_order::big).error() == errc::not_representable);
}
