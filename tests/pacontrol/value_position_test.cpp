// PA-CONTROL dates and positions: float text styles, IEEE-754 (big-endian) and ×1000 integers.
// IEEE examples from manual 001 (4.2 / 6.1 tables and the command descriptions of 5.2); where
// the printed pattern is wrong the test asserts real IEEE-754 and cites docs/errata.md,
// "PA-CONTROL (001) / IEEE-754 examples".
#include <fieldcodec/pacontrol/position.hpp>
#include <fieldcodec/pacontrol/value.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <limits>

namespace fc = fieldcodec;
namespace pac = fc::pacontrol;
using fc::decimal;
using fc::errc;
using pac::float_style;
using pac::position_format;

namespace {

constexpr bool is(fc::result<decimal> r, std::int64_t m, unsigned p) {
  return r && r.value().mantissa == m && r.value().places == p;
}

constexpr std::uint32_t bits_of(float v) {
  const auto b = pac::encode_position(v, position_format::ieee_float).value();
  return (std::uint32_t{b[0]} << 24U) | (std::uint32_t{b[1]} << 16U) | (std::uint32_t{b[2]} << 8U) |
         b[3];
}

constexpr std::array<std::uint8_t, 4> be32(std::uint32_t v) {
  return {static_cast<std::uint8_t>(v >> 24U), static_cast<std::uint8_t>(v >> 16U),
          static_cast<std::uint8_t>(v >> 8U), static_cast<std::uint8_t>(v)};
}

constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();
constexpr float inf_f = std::numeric_limits<float>::infinity();

} // namespace

// --- Float text: masters send the shortest form (3.4.3 "5552.0"), the device prints seven
// significant digits (3.4.2 "640.0000", 3.4.3 "1255.000", "1516.950", "2634.750", "5552.000").
static_assert(is(pac::float_to_decimal(5552.0F, float_style::master), 55520, 1));
static_assert(is(pac::float_to_decimal(0.1F, float_style::master), 1, 1));
static_assert(is(pac::float_to_decimal(-12.345F, float_style::master), -12345, 3));
static_assert(is(pac::float_to_decimal(0.0F, float_style::master), 0, 1));
static_assert(is(pac::float_to_decimal(16777216.0F, float_style::master), 167772160, 1));
static_assert(is(pac::float_to_decimal(640.0F, float_style::device), 6400000, 4));
static_assert(is(pac::float_to_decimal(1255.0F, float_style::device), 1255000, 3));
static_assert(is(pac::float_to_decimal(1516.95F, float_style::device), 1516950, 3));
static_assert(is(pac::float_to_decimal(2634.75F, float_style::device), 2634750, 3));
static_assert(is(pac::float_to_decimal(5552.0F, float_style::device), 5552000, 3));
static_assert(is(pac::float_to_decimal(0.5F, float_style::device), 500000, 6));
static_assert(is(pac::float_to_decimal(-111.111F, float_style::device), -1111110, 4));
static_assert(is(pac::float_to_decimal(12345678.0F, float_style::device), 123456780, 1));
static_assert(pac::float_to_decimal(nan_f, float_style::master).error() == errc::not_representable);
static_assert(pac::float_to_decimal(inf_f, float_style::device).error() == errc::not_representable);
static_assert(pac::float_to_decimal(-inf_f, float_style::master).error() ==
              errc::not_representable);

// Typed values.
static_assert(pac::value::of_int(-5).value().as_int().value() == -5);
static_assert(pac::value::of_float(5552.0F).value().as_int().error() == errc::type_mismatch);
static_assert(pac::value::of_float(5552.0F).value().as_float() == 5552.0F);
static_assert(pac::value::of_float(nan_f).error() == errc::not_representable);
static_assert(pac::value::of_real(decimal{1, 19}).error() == errc::invalid_argument);
static_assert(pac::validate(pac::value{fc::od::command_value::integer, decimal{1, 1}}).error() ==
              errc::type_mismatch);
static_assert(pac::validate(pac::value{fc::od::command_value::integer, decimal{-2147483649, 0}})
                  .error() == errc::overflow);
static_assert(pac::validate(pac::value{fc::od::command_value::none, decimal{}}).error() ==
              errc::invalid_argument);
static_assert(pac::validate(pac::value{static_cast<fc::od::command_value>(3), decimal{}}).error() ==
              errc::invalid_argument);

// --- IEEE-754 examples that the manual prints correctly.
static_assert(bits_of(10.0F) == 0x41200000U);    // l. 1726, 2727, 3118, 3470, 3528 …
static_assert(bits_of(200.0F) == 0x43480000U);   // l. 1727, 2277, 2942, 3045, 3419 …
static_assert(bits_of(0.0F) == 0x00000000U);     // l. 2316, 3709
static_assert(bits_of(50000.0F) == 0x47435000U); // l. 2343
static_assert(bits_of(7000.0F) == 0x45DAC000U);  // l. 2376
static_assert(bits_of(111.111F) == 0x42DE38D5U); // l. 2758
static_assert(bits_of(10000.0F) == 0x461C4000U); // l. 3081
static_assert(bits_of(640.5F) == 0x44202000U);   // l. 3614
// --- Printed wrongly (errata table "IEEE-754 examples"): the correct pattern, and what the
// printed pattern really is.
static_assert(bits_of(0.34375F) == 0x3EB00000U); // l. 1725/3915 print 4016 0000 …
static_assert(bits_of(2.34375F) == 0x40160000U); // … which is 2.34375
static_assert(bits_of(640.0F) == 0x44200000U);   // l. 1728/3918/1751/3589 print 4420 2000 …
static_assert(bits_of(20480.0F) == 0x46A00000U); // l. 1729/3919 print 44A8 0000 = 1344.0,
static_assert(bits_of(1344.0F) == 0x44A80000U);  //  l. 3503/3509/3639/3763 47A8 0000 = 86016.0
static_assert(bits_of(86016.0F) == 0x47A80000U);
static_assert(bits_of(5000.0F) == 0x459C4000U); // l. 2892 prints 4548 0000 = 3200.0
static_assert(bits_of(4500.0F) == 0x458CA000U); // l. 2917 prints 4548 0000 = 3200.0
static_assert(bits_of(3200.0F) == 0x45480000U);
static_assert(bits_of(40.03F) == 0x42201EB8U); // l. 3150 prints 4220 0000 = 40.0
static_assert(bits_of(40.0F) == 0x42200000U);
static_assert(bits_of(160.0F) == 0x43200000U); // l. 3451/3663 print 4320 0000 for 10.0

// --- ×1000 integers (2.5.3.2, l. 600-606): 12345 ↔ 12.345, 25.045 ↔ 25045.
static_assert(pac::to_milli(decimal{12345, 3}).value() == 12345);
static_assert(pac::to_milli(25.045F).value() == 25045);
static_assert(pac::to_milli(25.045).value() == 25045);
static_assert(is(pac::from_milli(12345), 12345, 3));
// Rounding: half away from zero on the exact decimal.
static_assert(pac::to_milli(decimal{20005, 4}).value() == 2001);
static_assert(pac::to_milli(decimal{-20005, 4}).value() == -2001);
static_assert(pac::to_milli(decimal{200049, 5}).value() == 2000);
static_assert(pac::to_milli(2.0005F).value() == 2001); // shortest form "2.0005"
static_assert(pac::to_milli(-2.0005F).value() == -2001);
static_assert(pac::to_milli(0.0004F).value() == 0);
static_assert(pac::to_milli(-0.0005F).value() == -1);
static_assert(pac::to_milli(1.0005).value() == 1001); // 15 significant digits of the double
// Limits of int32.
static_assert(pac::to_milli(decimal{2147483647, 3}).value() == 2147483647);
static_assert(pac::to_milli(decimal{-2147483648, 3}).value() == -2147483647 - 1);
static_assert(pac::to_milli(decimal{21474836475, 4}).error() == errc::overflow); // rounds up
static_assert(pac::to_milli(decimal{21474836474, 4}).value() == 2147483647);
static_assert(pac::to_milli(decimal{-21474836485, 4}).error() == errc::overflow);
static_assert(pac::to_milli(decimal{-21474836484, 4}).value() == -2147483647 - 1);
static_assert(pac::to_milli(2147483.647).value() == 2147483647);
static_assert(pac::to_milli(2147483.648).error() == errc::overflow);
static_assert(pac::to_milli(-2147483.648).value() == -2147483647 - 1);
static_assert(pac::to_milli(-2147483.649).error() == errc::overflow);
static_assert(pac::to_milli(2147483.5F).value() == 2147483500);
static_assert(pac::to_milli(2147483.75F).error() == errc::overflow);
static_assert(pac::to_milli(1.0e30F).error() == errc::overflow);
static_assert(pac::to_milli(-1.0e300).error() == errc::overflow);
static_assert(pac::to_milli(nan_f).error() == errc::not_representable);
static_assert(pac::to_milli(inf_f).error() == errc::not_representable);
static_assert(pac::to_milli(-std::numeric_limits<double>::infinity()).error() ==
              errc::not_representable);
static_assert(pac::to_milli(decimal{1, 19}).error() == errc::invalid_argument);

TEST_CASE("pacontrol positions: IEEE-754 big-endian both ways") {
  constexpr std::array<std::uint8_t, 4> r1{0x44, 0x20, 0x00, 0x00}; // 640.0, errata l. 1751
  CHECK(pac::encode_position(640.0F, position_format::ieee_float).value() == r1);
  CHECK(pac::decode_position(r1, position_format::ieee_float).value() == 640.0F);
  constexpr std::array<std::uint8_t, 4> printed{0x44, 0x20, 0x20, 0x00};
  CHECK(pac::decode_position(printed, position_format::ieee_float).value() == 640.5F);
  CHECK(pac::decode_position(be32(0x42DE38D5U), position_format::ieee_float).value() == 111.111F);
  auto d = pac::decode_position_decimal(be32(0x42DE38D5U), position_format::ieee_float);
  REQUIRE(d);
  CHECK(d.value().mantissa == 111111);
  CHECK(d.value().places == 3);
  // Extremes of binary32.
  CHECK(bits_of(std::numeric_limits<float>::max()) == 0x7F7FFFFFU);
  CHECK(bits_of(std::numeric_limits<float>::lowest()) == 0xFF7FFFFFU);
  CHECK(bits_of(std::numeric_limits<float>::denorm_min()) == 0x00000001U);
  CHECK(bits_of(-0.0F) == 0x80000000U);
  // NaN and infinity refused both ways.
  CHECK(pac::encode_position(nan_f, position_format::ieee_float).error() ==
        errc::not_representable);
  CHECK(pac::encode_position(-inf_f, position_format::ieee_float).error() ==
        errc::not_representable);
  CHECK(pac::encode_position(nan_f, position_format::milli_integer).error() ==
        errc::not_representable);
  CHECK(pac::decode_position(be32(0x7FC00000U), position_format::ieee_float).error() ==
        errc::not_representable);
  CHECK(pac::decode_position(be32(0x7F800000U), position_format::ieee_float).error() ==
        errc::not_representable);
  CHECK(pac::decode_position(be32(0xFF800001U), position_format::ieee_float).error() ==
        errc::not_representable);
  CHECK(pac::decode_position_decimal(be32(0x7F800000U), position_format::ieee_float).error() ==
        errc::not_representable);
  // Decimal inputs beyond float range.
  CHECK(pac::encode_position(decimal{4, 0}, position_format::ieee_float).value() ==
        be32(0x40800000U));
  const std::array<std::uint8_t, 3> short_in{0x44, 0x20, 0x00};
  CHECK(pac::decode_position(short_in, position_format::ieee_float).error() == errc::truncated);
  CHECK(pac::decode_position(short_in, position_format::milli_integer).error() == errc::truncated);
}

TEST_CASE("pacontrol positions: ×1000 integers both ways") {
  CHECK(pac::encode_position(12.345F, position_format::milli_integer).value() == be32(12345U));
  CHECK(pac::encode_position(-12.345F, position_format::milli_integer).value() ==
        be32(static_cast<std::uint32_t>(-12345)));
  // A double is not read through a float (the float nearest 1234567.891 is 1234567.875,
  // shortest text 1234567.9); an integer is whole units.
  CHECK(pac::encode_position(1234567.891, position_format::milli_integer).value() ==
        be32(1234567891U));
  CHECK(pac::encode_position(1234567.891F, position_format::milli_integer).value() ==
        be32(1234567900U));
  CHECK(pac::encode_position(640.0, position_format::ieee_float).value() ==
        pac::encode_position(640.0F, position_format::ieee_float).value());
  CHECK(pac::encode_position(1.0e39, position_format::ieee_float).error() ==
        errc::not_representable);
  CHECK(pac::encode_position(5, position_format::milli_integer).value() == be32(5000U));
  CHECK(pac::encode_position(std::uint8_t{5}, position_format::ieee_float).value() ==
        pac::encode_position(5.0F, position_format::ieee_float).value());
  CHECK(pac::encode_position(2147484, position_format::milli_integer).error() == errc::overflow);
  CHECK(pac::encode_position(std::numeric_limits<std::uint64_t>::max(),
                             position_format::milli_integer)
            .error() == errc::overflow);
  CHECK(pac::encode_position(decimal{25045, 3}, position_format::milli_integer).value() ==
        be32(25045U));
  CHECK(pac::decode_position(be32(12345U), position_format::milli_integer).value() == 12.345F);
  auto d = pac::decode_position_decimal(be32(0x80000000U), position_format::milli_integer);
  REQUIRE(d);
  CHECK(d.value().mantissa == -2147483648LL);
  CHECK(d.value().places == 3);
  // Near the int32 limits the nearest float (2147483.75) would not encode again: decoding gives
  // the nearest float towards zero instead (fuzz F2); the exact value is decode_position_decimal.
  CHECK(pac::decode_position(be32(0x7FFFFFFFU), position_format::milli_integer).value() ==
        2147483.5F);
  CHECK(pac::decode_position(be32(0x80000000U), position_format::milli_integer).value() ==
        -2147483.5F);
  CHECK(pac::decode_position(be32(0x7FFFF000U), position_format::milli_integer).value() ==
        2147479.552F); // away from the limits: the nearest float, as before
  CHECK(pac::encode_position(2147483.75F, position_format::milli_integer).error() ==
        errc::overflow);
  CHECK(pac::encode_position(decimal{2147483648, 3}, position_format::milli_integer).error() ==
        errc::overflow);
  CHECK(pac::encode_position(decimal{1, 30}, position_format::milli_integer).error() ==
        errc::invalid_argument);
  // Every float with three decimals in a useful range survives the trip exactly.
  for (std::int32_t raw = -200000; raw <= 200000; raw += 7) {
    const float f = pac::to_float(pac::from_milli(raw));
    REQUIRE(pac::to_milli(f).value() == raw);
  }
}
