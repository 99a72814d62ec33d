// Typed values never narrow (issue 13): every integer width and signedness against every integer
// data type, enumerations by their underlying type, exact integers for REAL types, and
// node-ID-relative limits (issue 12 #4).
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/value.hpp>

#include <doctest/doctest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <span>
#include <string>

namespace fc = fieldcodec;
namespace od = fieldcodec::od;
using fc::errc;

namespace {

__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

constexpr std::array<od::data_type, 16> integer_types{
    od::data_type::integer8,   od::data_type::integer16,  od::data_type::integer24,
    od::data_type::integer32,  od::data_type::integer40,  od::data_type::integer48,
    od::data_type::integer56,  od::data_type::integer64,  od::data_type::unsigned8,
    od::data_type::unsigned16, od::data_type::unsigned24, od::data_type::unsigned32,
    od::data_type::unsigned40, od::data_type::unsigned48, od::data_type::unsigned56,
    od::data_type::unsigned64};

// The range of a data type, computed here independently of the library.
constexpr i128 type_min(od::data_type t) {
  if (!od::is_signed_integer(t)) return 0;
  return -(i128{1} << (8U * od::fixed_size(t) - 1U));
}
constexpr i128 type_max(od::data_type t) {
  const unsigned bits = 8U * od::fixed_size(t) - (od::is_signed_integer(t) ? 1U : 0U);
  return (i128{1} << bits) - 1;
}

// The value bytes a correct encoder writes (little-endian two's complement).
bool bytes_are(std::span<const std::uint8_t> b, i128 v) {
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b[i] != static_cast<std::uint8_t>(static_cast<u128>(v) >> (8U * i))) {
      return false;
    }
  }
  return true;
}

template <class T>
std::string what(T v, od::data_type t) {
  return std::string(od::name(t)) + " <- " + std::to_string(static_cast<long long>(v)) +
         (std::is_signed_v<T> ? " (signed " : " (unsigned ") + std::to_string(sizeof(T)) + ")";
}

// Every value of T worth trying against type t: T's extremes, 0, ±1, and t's edges ± 1 where T
// holds them.
template <class T>
void check_type(od::data_type t, std::size_t &accepted, std::size_t &refused) {
  const od::entry e{.type = t};
  const i128 tmin = std::numeric_limits<T>::min();
  const i128 tmax = std::numeric_limits<T>::max();
  i128 candidates[] = {
      tmin,     tmax,    0, 1, -1, type_min(t), type_min(t) - 1, type_max(t), type_max(t) + 1,
      tmin + 1, tmax - 1};
  for (const i128 c : candidates) {
    if (c < tmin || c > tmax) continue; // not a value of T
    const T v = static_cast<T>(c);
    std::array<std::uint8_t, 8> out{};
    auto n = od::encode(e, v, out);
    const bool fits = c >= type_min(t) && c <= type_max(t);
    if (fits) {
      REQUIRE_MESSAGE(n.has_value(), what(v, t));
      CHECK_MESSAGE(n.value() == od::fixed_size(t), what(v, t));
      CHECK_MESSAGE(bytes_are(std::span<const std::uint8_t>(out).first(n.value()), c), what(v, t));
      auto back = od::decode<T>(e, std::span<const std::uint8_t>(out).first(n.value()));
      REQUIRE_MESSAGE(back.has_value(), what(v, t));
      CHECK_MESSAGE(back.value() == v, what(v, t));
      ++accepted;
    } else {
      CHECK_MESSAGE(n.is(errc::overflow), what(v, t)); // never a wrapped value
      ++refused;
    }
  }
}

template <class T>
void check_all(std::size_t &accepted, std::size_t &refused) {
  for (const od::data_type t : integer_types) check_type<T>(t, accepted, refused);
}

enum class mode : std::int8_t { vendor = -1, profile_position = 1, homing = 6 };
enum class big : std::uint32_t { huge = 0xFFFF'FFFFU };
enum plain : unsigned char { plain_one = 1 };

// Scoped enumerations are their underlying values, at compile time too.
constexpr bool mode_byte(mode m, std::uint8_t want) {
  const od::entry e{.type = od::data_type::integer8};
  std::array<std::uint8_t, 1> out{};
  auto n = od::encode(e, m, out);
  return n && n.value() == 1 && out[0] == want;
}
static_assert(mode_byte(mode::vendor, 0xFF));
static_assert(mode_byte(mode::homing, 0x06));
static_assert(od::value_type<mode> && od::value_type<plain> && od::value_type<bool>);
static_assert(!od::value_type<long double> && !od::value_type<od::number>);

} // namespace

TEST_CASE("od values: every integer type against every integer data type, no narrowing") {
  std::size_t accepted = 0;
  std::size_t refused = 0;
  check_all<signed char>(accepted, refused);
  check_all<unsigned char>(accepted, refused);
  check_all<short>(accepted, refused);
  check_all<unsigned short>(accepted, refused);
  check_all<int>(accepted, refused);
  check_all<unsigned>(accepted, refused);
  check_all<long>(accepted, refused);
  check_all<unsigned long>(accepted, refused);
  check_all<long long>(accepted, refused);
  check_all<unsigned long long>(accepted, refused);
  check_all<std::int8_t>(accepted, refused);
  check_all<std::uint64_t>(accepted, refused);
  CHECK(accepted > 1000);
  CHECK(refused > 300);
  // bool is 0 or 1 in any integer type
  std::array<std::uint8_t, 8> out{};
  CHECK(od::encode(od::entry{.type = od::data_type::integer16}, true, out).value() == 2);
  CHECK(out[0] == 1);
}

TEST_CASE("od values: enumerations by their underlying type") {
  std::array<std::uint8_t, 4> out{};
  const od::entry i8{.type = od::data_type::integer8};
  const od::entry u8{.type = od::data_type::unsigned8};
  const od::entry u32{.type = od::data_type::unsigned32};
  CHECK(od::encode(i8, mode::vendor, out).value() == 1);
  CHECK(out[0] == 0xFF);
  CHECK(od::encode(u8, mode::vendor, out).error() == errc::overflow); // −1 is not an UNSIGNED8
  CHECK(od::encode(u8, mode::profile_position, out).value() == 1);
  CHECK(od::encode(u8, big::huge, out).error() == errc::overflow);
  CHECK(od::encode(u32, big::huge, out).value() == 4);
  CHECK(od::encode(u8, plain_one, out).value() == 1);
  const std::array<std::uint8_t, 1> ff{0xFF};
  CHECK(od::decode<mode>(i8, ff).value() == mode::vendor);
  CHECK(od::decode<mode>(u8, ff).error() == errc::overflow); // 255 is no int8 value
  // limits apply to the value
  static constexpr od::entry_spec modes_spec{
      .type = od::data_type::integer8, .low = od::signed_number(-1), .high = od::signed_number(10)};
  static constexpr const od::entry &modes = od::entry_of<modes_spec>;
  CHECK(od::encode(modes, mode::homing, out).value() == 1);
  CHECK(od::check_limits(modes, od::signed_number(11)).error() == errc::out_of_range);
}

TEST_CASE("od values: REAL types take floats as they are and integers only when exact") {
  std::array<std::uint8_t, 8> out{};
  const od::entry r32{.type = od::data_type::real32};
  const od::entry r64{.type = od::data_type::real64};
  // a float is written with its own bits (no detour through a 15-digit decimal)
  REQUIRE(od::encode(r32, 90.73F, out).value() == 4);
  const auto bits = std::bit_cast<std::uint32_t>(90.73F);
  CHECK(out[0] == static_cast<std::uint8_t>(bits));
  CHECK(out[3] == static_cast<std::uint8_t>(bits >> 24U));
  CHECK(od::decode<float>(r32, std::span<const std::uint8_t>(out).first(4)).value() == 90.73F);
  // integers: exactly representable or refused (24 / 53 significant bits)
  CHECK(od::encode(r32, 16'777'216, out).value() == 4);
  CHECK(od::encode(r32, 16'777'217, out).error() == errc::not_representable);
  CHECK(od::encode(r32, std::int64_t{1} << 60, out).value() == 4); // one significant bit
  CHECK(od::encode(r32, -16'777'217, out).error() == errc::not_representable);
  CHECK(od::encode(r64, (std::int64_t{1} << 53) + 1, out).error() == errc::not_representable);
  CHECK(od::encode(r64, std::int64_t{1} << 53, out).value() == 8);
  CHECK(od::encode(r64, std::numeric_limits<std::uint64_t>::max(), out).error() ==
        errc::not_representable);
  CHECK(od::encode(r64, -3, out).value() == 8);
  CHECK(od::decode<double>(r64, std::span<const std::uint8_t>(out).first(8)).value() == -3.0);
  CHECK(od::encode(r32, 1e39, out).error() == errc::overflow);
}

TEST_CASE("od values: node-ID-relative limits (LowLimit=$NODEID+0x600)") {
  // an EDS's SDO server COB-ID: both limits are $NODEID+0x600
  static constexpr od::entry_spec cob_spec{.index = 0x1200,
                                           .sub = 1,
                                           .type = od::data_type::unsigned32,
                                           .flags = od::flag::low_nodeid | od::flag::high_nodeid,
                                           .low = od::unsigned_number(0x600),
                                           .high = od::unsigned_number(0x600)};
  static constexpr const od::entry &cob = od::entry_of<cob_spec>;
  CHECK(cob.low_for(1).value() == od::unsigned_number(0x601));
  CHECK(cob.high_for(127).value() == od::unsigned_number(0x67F));
  std::array<std::uint8_t, 4> out{};
  // for a known node exactly its own value
  CHECK(od::encode(cob, 0x601U, out, fc::byte_order::little, 1).value() == 4);
  CHECK(od::encode(cob, 0x600U, out, fc::byte_order::little, 1).error() == errc::out_of_range);
  CHECK(od::encode(cob, 0x602U, out, fc::byte_order::little, 1).error() == errc::out_of_range);
  CHECK(od::check_limits(cob, od::unsigned_number(0x605), 5).has_value());
  CHECK(od::check_limits(cob, od::unsigned_number(0x605), 4).error() == errc::out_of_range);
  // without a node: what some node 1..127 accepts
  CHECK(od::encode(cob, 0x601U, out).value() == 4);
  CHECK(od::encode(cob, 0x67FU, out).value() == 4);
  CHECK(od::encode(cob, 0x600U, out).error() == errc::out_of_range);
  CHECK(od::encode(cob, 0x680U, out).error() == errc::out_of_range);
  // decode checks the same way
  const std::array<std::uint8_t, 4> b605{0x05, 0x06, 0, 0};
  CHECK(od::decode(cob, b605, fc::byte_order::little, od::limits::check, 5).has_value());
  CHECK(od::decode(cob, b605, fc::byte_order::little, od::limits::check, 6).error() ==
        errc::out_of_range);
  CHECK(od::decode(cob, b605).has_value());
  // one relative end only
  static constexpr od::entry_spec low_only_spec{.type = od::data_type::unsigned16,
                                                .flags = od::flag::low_nodeid,
                                                .low = od::unsigned_number(0x180),
                                                .high = od::unsigned_number(0x1FF)};
  static constexpr const od::entry &low_only = od::entry_of<low_only_spec>;
  CHECK(od::check_limits(low_only, od::unsigned_number(0x1FF), 127).has_value());
  CHECK(od::check_limits(low_only, od::unsigned_number(0x184), 5).error() == errc::out_of_range);
  // a relative value that overflows its number
  static constexpr od::entry_spec edge_spec{.type = od::data_type::unsigned64,
                                            .flags = od::flag::high_nodeid,
                                            .high = od::unsigned_number(~std::uint64_t{0})};
  static constexpr const od::entry &edge = od::entry_of<edge_spec>;
  CHECK(edge.high_for(1).error() == errc::overflow);
  // the descriptor checks engineering values against the widest node range
  const od::descriptor d{cob};
  CHECK(d.to_raw(fc::decimal{0x67F, 0}).value() == 0x67F);
  CHECK(d.to_raw(fc::decimal{0x680, 0}).error() == errc::out_of_range);
}

TEST_CASE("od values: floats are read as the floats they are (issue 13)") {
  // A PLC REAL of 90.73 at scale 327.67: 90.73 × 327.67 = 29729.4991 → 29729. Widening the float
  // to double first would read 90.7300033569336 and give 29730.
  const od::descriptor pct{
      {.type = od::data_type::unsigned16, .flags = od::flag::scaled}, {}, {{32767, 2}, {0, 0}}};
  CHECK(pct.to_raw(90.73F).value() == 29729);
  CHECK(pct.to_raw(static_cast<double>(90.73F)).value() == 29730); // what widening gives
  CHECK(pct.to_raw(90.73).value() == 29729);
  CHECK(pct.to_raw(std::numeric_limits<float>::quiet_NaN()).error() == errc::not_representable);
  // integers of any type, exactly
  CHECK(pct.to_raw(2).value() == 655); // 655.34 → 655
  CHECK(pct.to_raw(std::uint8_t{2}).value() == 655);
  CHECK(pct.to_raw(std::numeric_limits<std::uint64_t>::max()).error() == errc::not_representable);
  // od::encode: a float for an integer entry is its shortest decimal, and must be an integer
  std::array<std::uint8_t, 8> out{};
  const od::entry u16{.type = od::data_type::unsigned16};
  CHECK(od::encode(u16, 2.0F, out).value() == 2);
  CHECK(od::encode(u16, 0.1F, out).error() == errc::not_representable);
  // a float for a REAL64 is the double nearest its shortest decimal (90.73, not 90.73000336…)
  const od::entry r64{.type = od::data_type::real64};
  REQUIRE(od::encode(r64, 90.73F, out).value() == 8);
  CHECK(od::decode<double>(r64, out).value() == 90.73);
}
