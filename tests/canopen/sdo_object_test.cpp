// SDO frames for dictionary entries (against the generated XENAX CAN dictionary).
#include <fieldcodec/canopen/sdo_object.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>

#include <doctest/doctest.h>

#include <cstdint>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace x = fieldcodec::dictionaries::xenax_canopen;
using fieldcodec::errc;

// XENAX 5.4.1: 6060h := 0xFF (-1, jog) on node 1.
static_assert(sdo::download(1, x::modes_of_operation_requested, -1).value() ==
              co::make_frame(0x601, {0x2F, 0x60, 0x60, 0x00, 0xFF, 0x00, 0x00, 0x00}).value());

TEST_CASE("typed SDO download and upload of dictionary entries") {
  CHECK(sdo::download(1, x::controlword, 0x0F).value() ==
        co::make_frame(0x601, {0x2B, 0x40, 0x60, 0x00, 0x0F, 0x00, 0x00, 0x00}).value());
  CHECK(sdo::download(1, x::target_position, -2).value() ==
        co::make_frame(0x601, {0x23, 0x7A, 0x60, 0x00, 0xFE, 0xFF, 0xFF, 0xFF}).value());
  CHECK(sdo::download(1, x::modes_of_operation_requested, 11) == errc::out_of_range);
  CHECK(sdo::download(1, x::modes_of_operation_requested, -3) == errc::out_of_range);
  CHECK(sdo::download(1, x::controlword, 70000) == errc::out_of_range); // limit 0..65535
  CHECK(sdo::download(1, x::statusword, 1) == errc::access_denied);
  CHECK(sdo::download(0, x::controlword, 1) == errc::invalid_argument);
  CHECK(sdo::download(1, x::manufacturer_device_name, 1) == errc::access_denied);
  CHECK(sdo::upload(1, x::statusword).value() ==
        co::make_frame(0x601, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0}).value());
  const auto rsp = co::make_frame(0x581, {0x4B, 0x41, 0x60, 0x00, 0x37, 0x12, 0, 0}).value();
  CHECK(sdo::upload_value(x::statusword, rsp).value().to_uint64().value() == 0x1237);
  CHECK(sdo::upload_value(x::controlword, rsp) == errc::unexpected_frame); // other object
  const auto pos = co::make_frame(0x581, {0x43, 0x64, 0x60, 0x00, 0xFF, 0xFF, 0xFF, 0xFF}).value();
  CHECK(sdo::upload_value(x::position_actual_value, pos).value().to_int64().value() == -1);
  const auto wrong = co::make_frame(0x581, {0x4F, 0x41, 0x60, 0x00, 0x37, 0, 0, 0}).value();
  CHECK(sdo::upload_value(x::statusword, wrong) == errc::bad_length);
  const auto ab = co::make_frame(0x581, {0x80, 0x41, 0x60, 0x00, 0, 0, 2, 6}).value();
  CHECK(sdo::upload_value(x::statusword, ab) == errc::aborted);
  const auto seg = co::make_frame(0x581, {0x41, 0x41, 0x60, 0x00, 2, 0, 0, 0}).value();
  CHECK(sdo::upload_value(x::statusword, seg) == errc::unexpected_frame);
  const auto unsized = co::make_frame(0x581, {0x42, 0x41, 0x60, 0x00, 0x37, 0x12, 0, 0}).value();
  CHECK(sdo::upload_value(x::statusword, unsized).value().to_uint64().value() == 0x1237);
}

namespace {
namespace od = fieldcodec::od;
constexpr od::entry e_i8{.index = 0x2000, .type = od::data_type::integer8};
constexpr od::entry e_u8{.index = 0x2001, .type = od::data_type::unsigned8};
constexpr od::entry e_i16{.index = 0x2002, .type = od::data_type::integer16};
constexpr od::entry e_u16{.index = 0x2003, .type = od::data_type::unsigned16};
constexpr od::entry e_i32{.index = 0x2004, .type = od::data_type::integer32};
constexpr od::entry e_u32{.index = 0x2005, .type = od::data_type::unsigned32};
constexpr od::entry e_u24{.index = 0x2006, .type = od::data_type::unsigned24};

/// The value bytes of a download, or the error.
template <class T>
fieldcodec::result<std::uint64_t> sent(const od::entry &e, T v) {
  auto p = sdo::download(e, v);
  if (!p) return p.error();
  const auto m = sdo::decode(p.value(), sdo::direction::to_server).value();
  REQUIRE(m.expedited);
  return std::uint64_t{m.value};
}
} // namespace

// Issue 13: a typed download takes any integer type as the number it is and checks it against
// the entry's field; nothing narrows or wraps (0xFF as a uint8_t is 255, not -1).
TEST_CASE("typed SDO downloads never narrow: every argument width against every field") {
  // int8_t, uint8_t
  CHECK(sent(e_i8, std::int8_t{-1}).value() == 0xFF);
  CHECK(sent(e_i8, std::uint8_t{0xFF}) == errc::overflow);
  CHECK(sent(e_u8, std::uint8_t{0xFF}).value() == 0xFF);
  CHECK(sent(e_u8, std::int8_t{-1}) == errc::overflow);
  // int16_t, uint16_t
  CHECK(sent(e_i8, std::int16_t{127}).value() == 0x7F);
  CHECK(sent(e_i8, std::int16_t{128}) == errc::overflow);
  CHECK(sent(e_i8, std::int16_t{-129}) == errc::overflow);
  CHECK(sent(e_u8, std::uint16_t{256}) == errc::overflow);
  CHECK(sent(e_i16, std::uint16_t{0x8000}) == errc::overflow);
  CHECK(sent(e_u16, std::uint16_t{0xFFFF}).value() == 0xFFFF);
  CHECK(sent(e_u16, std::int16_t{-1}) == errc::overflow);
  // int32_t, uint32_t
  CHECK(sent(e_i16, std::int32_t{-32768}).value() == 0x8000);
  CHECK(sent(e_i16, std::int32_t{40000}) == errc::overflow);
  CHECK(sent(e_u16, std::uint32_t{65536}) == errc::overflow);
  CHECK(sent(e_u24, std::uint32_t{0xFFFFFF}).value() == 0xFFFFFF);
  CHECK(sent(e_u24, std::uint32_t{0x1000000}) == errc::overflow);
  CHECK(sent(e_i32, std::uint32_t{0x80000000U}) == errc::overflow);
  CHECK(sent(e_u32, std::uint32_t{0xFFFFFFFFU}).value() == 0xFFFFFFFFU);
  CHECK(sent(e_u32, std::int32_t{-1}) == errc::overflow);
  // int64_t, uint64_t, long long, unsigned long
  CHECK(sent(e_i32, std::int64_t{-2147483648LL}).value() == 0x80000000U);
  CHECK(sent(e_i32, std::int64_t{2147483648LL}) == errc::overflow);
  CHECK(sent(e_u32, std::uint64_t{0x1'0000'0000ULL}) == errc::overflow);
  CHECK(sent(e_u8, std::uint64_t{~0ULL}) == errc::overflow);
  CHECK(sent(e_u32, 4000000000ULL).value() == 4000000000ULL);
  CHECK(sent(e_i8, -5LL).value() == 0xFB);
  CHECK(sent(e_u16, 1000UL).value() == 1000);
  // bool and char-sized types
  CHECK(sent(e_u8, true).value() == 1);
  CHECK(sent(e_u8, 'A').value() == 0x41);
}
