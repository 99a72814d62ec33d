// COMPAX-M/S Interbus-S (manual 000): data types (1.7), BCD positions (2.7.1, 2.7.2, 2.7.4),
// POSR0SPEED (2.8.3) and device identification S31_S39 (2.3.2).
#include <fieldcodec/compax/identification.hpp>
#include <fieldcodec/compax/position.hpp>
#include <fieldcodec/compax/values.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <string>

namespace cx = fieldcodec::compax;
using fieldcodec::decimal;
using fieldcodec::errc;
using b1 = std::array<std::uint8_t, 1>;
using b2 = std::array<std::uint8_t, 2>;
using b3 = std::array<std::uint8_t, 3>;
using b4 = std::array<std::uint8_t, 4>;
using b5 = std::array<std::uint8_t, 5>;
using b6 = std::array<std::uint8_t, 6>;
using b7 = std::array<std::uint8_t, 7>;

// 1.7.1 Boolean: FALSE 0x00, TRUE 0xFF; anything else is not a boolean.
static_assert(cx::encode_boolean(true) == 0xFF);
static_assert(cx::encode_boolean(false) == 0x00);
static_assert(cx::decode_boolean(std::uint8_t{0xFF}).value());
static_assert(!cx::decode_boolean(std::uint8_t{0x00}).value());
static_assert(cx::decode_boolean(std::uint8_t{0x01}).error() == errc::out_of_range);
static_assert(cx::decode_boolean(std::uint8_t{0x80}).error() == errc::out_of_range);
static_assert(cx::decode_boolean(std::span<const std::uint8_t>{}).error() == errc::truncated);
static_assert(cx::decode_boolean(b2{0xFF, 0xFF}).error() == errc::bad_length);

// 1.7.2 Integers are big-endian two's complement; Integer32 0x80000000 means overflow.
static_assert(cx::encode_integer<std::int32_t>(-1'000'000).value() == b4{0xFF, 0xF0, 0xBD, 0xC0});
static_assert(cx::decode_integer<std::int32_t>(b4{0xFF, 0xF0, 0xBD, 0xC0}).value() == -1'000'000);
static_assert(cx::decode_integer<std::int32_t>(b4{0x80, 0x00, 0x00, 0x00}).error() ==
              errc::overflow);
static_assert(cx::decode_integer<std::int32_t>(b4{0x80, 0x00, 0x00, 0x01}).value() ==
              -2'147'483'647);
static_assert(cx::encode_integer<std::int32_t>(INT32_MIN).error() == errc::overflow);
static_assert(cx::encode_integer<std::int32_t>(2'147'483'647).value() ==
              b4{0x7F, 0xFF, 0xFF, 0xFF});
// 0x80000000 is a normal value for the unsigned and narrower types.
static_assert(cx::decode_integer<std::uint32_t>(b4{0x80, 0, 0, 0}).value() == 0x80000000U);
static_assert(cx::decode_integer<std::int16_t>(b2{0x80, 0x00}).value() == -32768);
static_assert(cx::decode_integer<std::int16_t>(b2{0xFF, 0xFF}).value() == -1);
static_assert(cx::decode_integer<std::uint16_t>(b2{0x17, 0x70}).value() == 6000);
static_assert(cx::decode_integer<std::int32_t>(b3{0, 0, 0}).error() == errc::truncated);
static_assert(cx::decode_integer<std::int32_t>(b5{0, 0, 0, 0, 0}).error() == errc::bad_length);

// 2.7.1 POSA example: +7350.150 mm → 00 00 07 35 01 50
static_assert(cx::encode_bcd_position(7'350'150).value() == b6{0x00, 0x00, 0x07, 0x35, 0x01, 0x50});
static_assert(cx::encode_bcd_position(decimal{735015, 2}).value() ==
              b6{0x00, 0x00, 0x07, 0x35, 0x01, 0x50});
static_assert(cx::decode_bcd_position(b6{0x00, 0x00, 0x07, 0x35, 0x01, 0x50}).value() == 7'350'150);
// 2.7.2 POSR example: −37891.210 mm → FF 00 37 89 12 10
static_assert(cx::encode_bcd_position(-37'891'210).value() ==
              b6{0xFF, 0x00, 0x37, 0x89, 0x12, 0x10});
static_assert(cx::decode_bcd_position(b6{0xFF, 0x00, 0x37, 0x89, 0x12, 0x10}).value() ==
              -37'891'210);
// Range ±4 000 000.000 mm (erratum CX-14: the printed ±4 000 000 000 is in 0.001 mm).
static_assert(cx::encode_bcd_position(4'000'000'000).value() == b6{0x00, 0x40, 0, 0, 0, 0});
static_assert(cx::encode_bcd_position(-4'000'000'000).value() == b6{0xFF, 0x40, 0, 0, 0, 0});
static_assert(cx::encode_bcd_position(4'000'000'001).error() == errc::out_of_range);
static_assert(cx::encode_bcd_position(-4'000'000'001).error() == errc::out_of_range);
static_assert(cx::encode_bcd_position(decimal{40000001, 1}).error() == errc::out_of_range);
static_assert(cx::encode_bcd_position(decimal{10001, 4}).error() == errc::not_representable);
static_assert(cx::decode_bcd_position(b6{0x00, 0x40, 0, 0, 0, 1}).error() == errc::out_of_range);
static_assert(cx::decode_bcd_position(b6{0x00, 0x99, 0x99, 0x99, 0x99, 0x99}).error() ==
              errc::out_of_range);
// Bad input: sign bytes other than 00/FF, nibbles A–F, wrong lengths.
static_assert(cx::decode_bcd_position(b6{0x01, 0, 0, 0, 0, 0}).error() == errc::bad_sign);
static_assert(cx::decode_bcd_position(b6{0x80, 0, 0, 0, 0, 0}).error() == errc::bad_sign);
static_assert(cx::decode_bcd_position(b6{0xFE, 0, 0, 0, 0, 0}).error() == errc::bad_sign);
static_assert(cx::decode_bcd_position(b6{0x00, 0, 0, 0, 0, 0x0A}).error() == errc::bad_digit);
static_assert(cx::decode_bcd_position(b6{0x00, 0xF0, 0, 0, 0, 0}).error() == errc::bad_digit);
static_assert(cx::decode_bcd_position(b5{0x00, 0, 0, 0, 0}).error() == errc::truncated);
static_assert(cx::decode_bcd_position(b7{0x00, 0, 0, 0, 0, 0, 0}).error() == errc::bad_length);
// Negative zero decodes as zero; zero encodes positive.
static_assert(cx::decode_bcd_position(b6{0xFF, 0, 0, 0, 0, 0}).value() == 0);
static_assert(cx::encode_bcd_position(0).value() == b6{});

// 2.8.3 POSR0SPEED example: 35 % → 03 50 00 (BCD, 0.001 %)
static_assert(cx::encode_bcd_speed(35'000).value() == b3{0x03, 0x50, 0x00});
static_assert(cx::decode_bcd_speed(b3{0x03, 0x50, 0x00}).value() == 35'000);
static_assert(cx::encode_bcd_speed(600'000).value() == b3{0x60, 0x00, 0x00});
static_assert(cx::encode_bcd_speed(600'001).error() == errc::out_of_range);
static_assert(cx::encode_bcd_speed(0).error() == errc::out_of_range);
// Any integer type, checked, never wrapped (issue 13): 2^32 + 35 000 is not 35.000 %, and
// 2^64 − 1000 is not −1.000 mm.
static_assert(cx::encode_bcd_speed((std::int64_t{1} << 32) + 35'000).error() == errc::out_of_range);
static_assert(cx::encode_bcd_speed(-35'000).error() == errc::out_of_range);
static_assert(cx::encode_bcd_speed(std::uint64_t{35'000}).value() == b3{0x03, 0x50, 0x00});
static_assert(cx::encode_bcd_position(~std::uint64_t{0} - 999U).error() == errc::out_of_range);
static_assert(cx::encode_bcd_position(std::uint64_t{7'350'150}).value() ==
              std::array<std::uint8_t, 6>{0x00, 0x00, 0x07, 0x35, 0x01, 0x50});
static_assert(cx::encode_bcd_position(short{-1}).value() ==
              std::array<std::uint8_t, 6>{0xFF, 0x00, 0x00, 0x00, 0x00, 0x01});
static_assert(cx::encode_identification(-1).error() == errc::out_of_range);
static_assert(cx::encode_identification(1'000'000'000'000ULL).error() == errc::overflow);
static_assert(cx::decode_bcd_speed(b3{0x00, 0x00, 0x00}).error() == errc::out_of_range);
static_assert(cx::decode_bcd_speed(b3{0x60, 0x00, 0x01}).error() == errc::out_of_range);
static_assert(cx::decode_bcd_speed(b3{0x0B, 0x00, 0x00}).error() == errc::bad_digit);
static_assert(cx::decode_bcd_speed(b2{0x03, 0x50}).error() == errc::truncated);

// 2.3.2 S31_S39: 12 BCD digits; sub-indices 2 and 6 are day, month, year, version, identifier.
static_assert(cx::encode_identification(123'456'789'012).value() ==
              b6{0x12, 0x34, 0x56, 0x78, 0x90, 0x12});
static_assert(cx::decode_identification(b6{0x99, 0x99, 0x99, 0x99, 0x99, 0x99}).value() ==
              cx::identification_max);
static_assert(cx::encode_identification(1'000'000'000'000).error() == errc::overflow);
static_assert(cx::decode_identification(b6{0x12, 0x3C, 0, 0, 0, 0}).error() == errc::bad_digit);
static_assert(cx::decode_identification(b5{}).error() == errc::truncated);
constexpr cx::identification_date date{24, 12, 99, 521, 7};
static_assert(cx::encode_identification_date(date).value() ==
              b6{0x24, 0x12, 0x99, 0x05, 0x21, 0x07});
static_assert(cx::decode_identification_date(b6{0x24, 0x12, 0x99, 0x05, 0x21, 0x07}).value() ==
              date);
static_assert(cx::decode_identification_date(b6{0x32, 0x12, 0, 0, 0, 0}).error() ==
              errc::out_of_range);
static_assert(cx::decode_identification_date(b6{0x01, 0x13, 0, 0, 0, 0}).error() ==
              errc::out_of_range);
static_assert(cx::decode_identification_date(b6{0x01, 0x1F, 0, 0, 0, 0}).error() ==
              errc::bad_digit);
static_assert(cx::encode_identification_date({0, 1, 0, 0, 0}).error() == errc::out_of_range);
static_assert(cx::encode_identification_date({1, 1, 100, 0, 0}).error() == errc::out_of_range);
static_assert(cx::encode_identification_date({1, 1, 0, 10000, 0}).error() == errc::out_of_range);
static_assert(cx::is_date_item(cx::identification_item::software_date));
static_assert(cx::is_date_item(cx::identification_item::bus_option_date));
static_assert(!cx::is_date_item(cx::identification_item::device));

TEST_CASE("compax: BCD position round trip over the whole digit range") {
  for (std::int64_t v :
       {std::int64_t{0}, std::int64_t{1}, std::int64_t{-1}, std::int64_t{999},
        std::int64_t{123'456'789}, std::int64_t{-3'999'999'999}, std::int64_t{4'000'000'000}}) {
    auto b = cx::encode_bcd_position(v);
    REQUIRE(b.has_value());
    CHECK(cx::decode_bcd_position(b.value()).value() == v);
  }
  // every nibble A..F in every digit position is rejected
  for (std::size_t byte = 1; byte < 6; ++byte) {
    for (unsigned nib = 0xA; nib <= 0xF; ++nib) {
      b6 hi{};
      hi[byte] = static_cast<std::uint8_t>(nib << 4U);
      b6 lo{};
      lo[byte] = static_cast<std::uint8_t>(nib);
      CHECK(cx::decode_bcd_position(hi).error() == errc::bad_digit);
      CHECK(cx::decode_bcd_position(lo).error() == errc::bad_digit);
    }
  }
  for (unsigned s = 1; s < 0xFF; ++s) {
    b6 b{};
    b[0] = static_cast<std::uint8_t>(s);
    CHECK(cx::decode_bcd_position(b).error() == errc::bad_sign);
  }
}

TEST_CASE("compax: visible strings") {
  std::array<std::uint8_t, 20> buf{};
  REQUIRE(cx::encode_visible_string("POSR15.8", buf).has_value());
  CHECK(buf[0] == 0x50);
  CHECK(buf[7] == 0x38);
  CHECK(buf[8] == 0x20);
  CHECK(buf[19] == 0x20);
  auto t = cx::decode_visible_string(buf);
  REQUIRE(t.has_value());
  CHECK(t.value().size() == 8);
  CHECK(cx::encode_visible_string("012345678901234567890", buf).error() == errc::too_long);
  CHECK(cx::encode_visible_string("A\tB", buf).error() == errc::bad_character);
  buf[3] = 0x0A;
  CHECK(cx::decode_visible_string(buf).error() == errc::bad_character);
  buf[3] = 0x80;
  CHECK(cx::decode_visible_string(buf).error() == errc::bad_character);
}

// Issue 12: a drive may pad a string reply with NUL instead of spaces (docs/compax.md, "Visible
// strings"). The text ends at the first NUL; only NUL and space may follow it.
TEST_CASE("compax: visible strings padded with NUL") {
  const auto text = [](std::span<const std::uint8_t> in) {
    auto t = cx::decode_visible_string(in);
    REQUIRE(t.has_value());
    return std::string(t.value().begin(), t.value().end());
  };
  std::array<std::uint8_t, 12> buf{'P', '0', '0', '3', '=', '1', '.', '5'};
  CHECK(text(buf) == "P003=1.5"); // NUL padding
  buf[9] = ' ';
  CHECK(text(buf) == "P003=1.5"); // NUL and space mixed after the text
  buf[8] = ' ';
  buf[9] = 0;
  CHECK(text(buf) == "P003=1.5"); // spaces, then NUL
  const std::array<std::uint8_t, 4> empty{};
  CHECK(text(empty).empty());
  buf[10] = 'X'; // a character after the NUL is not padding
  CHECK(cx::decode_visible_string(buf).error() == errc::bad_character);
  const std::array<std::uint8_t, 4> inner{'A', 0, 'B', 0};
  CHECK(cx::decode_visible_string(inner).error() == errc::bad_character);
}
