// sdo::upload_value<T>: the value of an expedited upload response as a C++ type, never narrowed
// (od::number_as<T> of the od::number upload_value gives).
#include <fieldcodec/canopen/sdo_object.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <doctest/doctest.h>

#include <bit>
#include <cstdint>
#include <limits>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
using fieldcodec::errc;

namespace {
constexpr od::entry e_bool{.index = 0x2000, .type = od::data_type::boolean};
constexpr od::entry e_i8{.index = 0x2001, .type = od::data_type::integer8};
constexpr od::entry e_u8{.index = 0x2002, .type = od::data_type::unsigned8};
constexpr od::entry e_i16{.index = 0x2003, .type = od::data_type::integer16};
constexpr od::entry e_u16{.index = 0x2004, .type = od::data_type::unsigned16};
constexpr od::entry e_i24{.index = 0x2005, .type = od::data_type::integer24};
constexpr od::entry e_i32{.index = 0x2006, .type = od::data_type::integer32};
constexpr od::entry e_u32{.index = 0x2007, .type = od::data_type::unsigned32};
constexpr od::entry e_r32{.index = 0x2008, .type = od::data_type::real32};
constexpr od::entry_spec e_limited_spec{.index = 0x2009,
                                        .type = od::data_type::unsigned8,
                                        .low = od::unsigned_number(10),
                                        .high = od::unsigned_number(20)};
constexpr const od::entry &e_limited = od::entry_of<e_limited_spec>;

/// The expedited upload response (size indicated) of entry `e` carrying the low bytes of `bits`.
constexpr sdo::payload response(const od::entry &e, std::uint32_t bits) {
  const auto n = static_cast<unsigned>(od::fixed_size(e.type));
  sdo::payload p{static_cast<std::uint8_t>(0x43U | ((4U - n) << 2U)),
                 static_cast<std::uint8_t>(e.index & 0xFFU),
                 static_cast<std::uint8_t>(e.index >> 8U),
                 e.sub,
                 0,
                 0,
                 0,
                 0};
  for (unsigned i = 0; i < n; ++i) p[4U + i] = static_cast<std::uint8_t>(bits >> (8U * i));
  return p;
}

enum class mode : std::int8_t { jog = -1, none = 0, profile_position = 1 };
enum class small_code : std::uint8_t { a = 1 };
} // namespace

// The typed form is usable in constant expressions, like the number form.
static_assert(sdo::upload_value<std::int16_t>(e_i16, response(e_i16, 0xFFFFU)).value() == -1);
static_assert(sdo::upload_value<std::uint8_t>(e_u16, response(e_u16, 0x0100U)) == errc::overflow);

TEST_CASE("upload_value<T>: a T wider than the object takes every value") {
  CHECK(sdo::upload_value<std::int64_t>(e_i32, response(e_i32, 0x80000000U)).value() ==
        std::numeric_limits<std::int32_t>::min());
  CHECK(sdo::upload_value<std::uint64_t>(e_u32, response(e_u32, 0xFFFFFFFFU)).value() ==
        0xFFFFFFFFU);
  CHECK(sdo::upload_value<std::int32_t>(e_i24, response(e_i24, 0x800000U)).value() == -8388608);
  CHECK(sdo::upload_value<double>(e_u32, response(e_u32, 0xFFFFFFFFU)).value() == 4294967295.0);
  CHECK(sdo::upload_value<double>(e_i32, response(e_i32, 0x80000001U)).value() == -2147483647.0);
}

TEST_CASE("upload_value<T>: a T narrower than the object, at both ends of T") {
  // UNSIGNED16 into uint8_t / int8_t
  CHECK(sdo::upload_value<std::uint8_t>(e_u16, response(e_u16, 0x00FFU)).value() == 0xFF);
  CHECK(sdo::upload_value<std::uint8_t>(e_u16, response(e_u16, 0x0100U)) == errc::overflow);
  CHECK(sdo::upload_value<std::int8_t>(e_u16, response(e_u16, 0x007FU)).value() == 127);
  CHECK(sdo::upload_value<std::int8_t>(e_u16, response(e_u16, 0x0080U)) == errc::overflow);
  // INTEGER16 into int8_t
  CHECK(sdo::upload_value<std::int8_t>(e_i16, response(e_i16, 0xFF80U)).value() == -128);
  CHECK(sdo::upload_value<std::int8_t>(e_i16, response(e_i16, 0xFF7FU)) == errc::overflow);
  CHECK(sdo::upload_value<std::int8_t>(e_i16, response(e_i16, 0x0080U)) == errc::overflow);
  // INTEGER32 into int16_t
  CHECK(sdo::upload_value<std::int16_t>(e_i32, response(e_i32, 0x00007FFFU)).value() == 32767);
  CHECK(sdo::upload_value<std::int16_t>(e_i32, response(e_i32, 0x00008000U)) == errc::overflow);
  CHECK(sdo::upload_value<std::int16_t>(e_i32, response(e_i32, 0xFFFF8000U)).value() == -32768);
  CHECK(sdo::upload_value<std::int16_t>(e_i32, response(e_i32, 0xFFFF7FFFU)) == errc::overflow);
}

TEST_CASE("upload_value<T>: signedness mismatches never flip a sign") {
  // a negative INTEGER into any unsigned T
  CHECK(sdo::upload_value<std::uint32_t>(e_i32, response(e_i32, 0xFFFFFFFFU)) == errc::overflow);
  CHECK(sdo::upload_value<std::uint64_t>(e_i32, response(e_i32, 0xFFFFFFFFU)) == errc::overflow);
  CHECK(sdo::upload_value<std::uint8_t>(e_i8, response(e_i8, 0xFFU)) == errc::overflow);
  CHECK(sdo::upload_value<std::uint8_t>(e_i8, response(e_i8, 0x7FU)).value() == 127);
  // an UNSIGNED beyond the signed T of the same width
  CHECK(sdo::upload_value<std::int32_t>(e_u32, response(e_u32, 0x80000000U)) == errc::overflow);
  CHECK(sdo::upload_value<std::int32_t>(e_u32, response(e_u32, 0x7FFFFFFFU)).value() ==
        std::numeric_limits<std::int32_t>::max());
  CHECK(sdo::upload_value<std::int8_t>(e_u8, response(e_u8, 0x80U)) == errc::overflow);
  CHECK(sdo::upload_value<std::int64_t>(e_u32, response(e_u32, 0x80000000U)).value() == 0x80000000);
}

TEST_CASE("upload_value<T>: REAL32 and floating-point T") {
  const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
  CHECK(sdo::upload_value<float>(e_r32, response(e_r32, bits(90.73F))).value() == 90.73F);
  CHECK(sdo::upload_value<double>(e_r32, response(e_r32, bits(90.73F))).value() ==
        static_cast<double>(90.73F));
  CHECK(sdo::upload_value<float>(e_r32, response(e_r32, bits(-0.0F))).value() == 0.0F);
  CHECK(sdo::upload_value<float>(e_r32, response(e_r32, bits(std::numeric_limits<float>::max())))
            .value() == std::numeric_limits<float>::max());
  // REAL32 into an integer T: not an integer's value, whatever the number (3.0 included)
  CHECK(sdo::upload_value<std::int32_t>(e_r32, response(e_r32, bits(3.0F))) ==
        errc::not_representable);
  CHECK(sdo::upload_value<std::uint8_t>(e_r32, response(e_r32, bits(0.5F))) ==
        errc::not_representable);
  CHECK(sdo::upload_value<bool>(e_r32, response(e_r32, bits(1.0F))) == errc::not_representable);
  // NaN is refused by the decoder already
  CHECK(sdo::upload_value<float>(e_r32, response(e_r32, 0x7FC00000U)) == errc::not_representable);
  // an integer into float: exactly (24 significant bits) or not at all
  CHECK(sdo::upload_value<float>(e_u32, response(e_u32, 0x01000000U)).value() == 16777216.0F);
  CHECK(sdo::upload_value<float>(e_u32, response(e_u32, 0x01000001U)) == errc::not_representable);
  CHECK(sdo::upload_value<float>(e_u32, response(e_u32, 0xFFFFFF00U)).value() == 4294967040.0F);
  CHECK(sdo::upload_value<float>(e_u32, response(e_u32, 0xFFFFFFFFU)) == errc::not_representable);
  CHECK(sdo::upload_value<float>(e_i32, response(e_i32, 0x80000000U)).value() == -2147483648.0F);
  CHECK(sdo::upload_value<float>(e_i32, response(e_i32, 0x80000001U)) == errc::not_representable);
  CHECK(sdo::upload_value<float>(e_i16, response(e_i16, 0x8000U)).value() == -32768.0F);
}

TEST_CASE("upload_value<T>: bool and enumerations") {
  CHECK(sdo::upload_value<bool>(e_bool, response(e_bool, 1U)).value());
  CHECK_FALSE(sdo::upload_value<bool>(e_bool, response(e_bool, 0U)).value());
  CHECK(sdo::upload_value<bool>(e_bool, response(e_bool, 2U)) == errc::out_of_range); // decoder
  CHECK(sdo::upload_value<bool>(e_u8, response(e_u8, 1U)).value());
  CHECK(sdo::upload_value<bool>(e_u8, response(e_u8, 2U)) == errc::overflow);
  CHECK(sdo::upload_value<bool>(e_i8, response(e_i8, 0xFFU)) == errc::overflow);
  // an enumeration is its underlying type: int8_t
  CHECK(sdo::upload_value<mode>(e_i8, response(e_i8, 0xFFU)).value() == mode::jog);
  CHECK(sdo::upload_value<mode>(e_i16, response(e_i16, 0x0001U)).value() == mode::profile_position);
  CHECK(sdo::upload_value<mode>(e_i16, response(e_i16, 0x0080U)) == errc::overflow);
  CHECK(sdo::upload_value<mode>(e_u8, response(e_u8, 0xC8U)) == errc::overflow);
  CHECK(sdo::upload_value<small_code>(e_i8, response(e_i8, 0xFFU)) == errc::overflow);
}

TEST_CASE("upload_value<T>: the errors of upload_value come first, from a payload or a frame") {
  const auto frame = [](const sdo::payload &p) {
    return co::make_frame(0x581, {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]}).value();
  };
  CHECK(sdo::upload_value<std::int16_t>(e_i16, frame(response(e_i16, 0xFFFEU))).value() == -2);
  CHECK(sdo::upload_value<std::uint8_t>(e_u16, frame(response(e_u16, 0x0100U))) == errc::overflow);
  // another object
  CHECK(sdo::upload_value<std::int16_t>(e_i16, response(e_u16, 1U)) == errc::unexpected_frame);
  // an abort
  const sdo::payload abort{0x80, 0x03, 0x20, 0x00, 0x00, 0x00, 0x02, 0x06};
  CHECK(sdo::upload_value<std::int16_t>(e_i16, abort) == errc::aborted);
  // indicated size differs from the type's
  auto wrong = response(e_i16, 1U);
  wrong[0] = 0x4F;
  CHECK(sdo::upload_value<std::int16_t>(e_i16, wrong) == errc::bad_length);
  // a DLC other than 8
  CHECK(sdo::upload_value<std::int16_t>(e_i16, co::make_frame(0x581, {0x4B, 0x03, 0x20}).value()) ==
        errc::bad_length);
  // limits are not checked (the device reports what it has), T's range is
  CHECK(sdo::upload_value<std::uint8_t>(e_limited, response(e_limited, 200U)).value() == 200);
  CHECK(sdo::upload_value<std::int8_t>(e_limited, response(e_limited, 200U)) == errc::overflow);
}
