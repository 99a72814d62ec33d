#include <fieldcodec/od/command.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/value.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>

namespace fc = fieldcodec;
namespace od = fieldcodec::od;
using fc::errc;

namespace {

constexpr std::array<od::entry_spec, 7> test_entries_spec{{
    {.index = 0x1000, .type = od::data_type::unsigned32, .access_type = od::access::ro},
    {.index = 0x1014,
     .type = od::data_type::unsigned32,
     .flags = od::flag::default_nodeid,
     .default_value = od::unsigned_number(0x80)},
    {.index = 0x1018,
     .object = od::object_code::record,
     .access_type = od::access::ro,
     .default_value = od::unsigned_number(2)},
    {.index = 0x1018,
     .sub = 1,
     .object = od::object_code::record,
     .type = od::data_type::unsigned32,
     .access_type = od::access::ro},
    {.index = 0x1018,
     .sub = 3,
     .object = od::object_code::record,
     .type = od::data_type::unsigned32,
     .access_type = od::access::ro},
    {.index = 0x2023,
     .type = od::data_type::unsigned32,
     .flags = od::flag::scaled,
     .low = od::signed_number(0),
     .high = od::signed_number(5000)},
    {.index = 0x6060,
     .type = od::data_type::integer8,
     .pdo = od::pdo_mapping::yes,
     .low = od::signed_number(-1),
     .high = od::signed_number(10)},
}};
constexpr auto test_entries = od::entries_of<test_entries_spec>;
constexpr std::array<od::entry_info, 7> test_infos{{
    {.name = "Device type"},
    {.name = "COB-ID EMCY"},
    {.name = "Number of entries"},
    {.name = "Vendor-ID"},
    {.name = "Revision"},
    {.name = "Inj. P Limit 1", .unit = "bar"},
    {.name = "Modes of operation"},
}};
constexpr std::array<fc::scaling::linear, 7> test_scales{
    {{}, {}, {}, {}, {}, {{32767, 2}, {0, 0}}, {}}};
constexpr od::dictionary dict{test_entries, test_infos, test_scales};
static_assert(dict.is_valid());
static_assert(dict.size() == 7);
static_assert(dict.object_count() == 5);
static_assert(dict.info(*dict.find(0x1018, 1)).name == "Vendor-ID");
static_assert(dict.find(0x1018, 2) == nullptr); // gap in the sub-indices
static_assert(dict.lookup(0x1018, 2).error() == errc::unknown_object);
static_assert(dict.lookup(0x0FFF, 0).error() == errc::unknown_object);
static_assert(dict.lookup(0xFFFF, 0xFF).error() == errc::unknown_object);
static_assert(dict.lookup(od::address{0x1018, 3}).value() == &test_entries[4]);
static_assert(dict.object(0x1018).size() == 3);
static_assert(dict.object(0x1019).empty());
static_assert(dict.object(0x6060).size() == 1);

constexpr od::descriptor inj = dict.at(0x2023, 0).value();
// DPQ manual 004 chapter 3: 4.0 bar × 327.67 = 1310.68 → 1311.
static_assert(inj.to_raw(4.0).value() == 1311);
static_assert(inj.to_raw(5000.001).error() == errc::out_of_range);
static_assert(inj.to_raw(-0.5).error() == errc::out_of_range);
static_assert(inj.info.unit == "bar");
static_assert(dict.at(0x1000, 0).value().to_raw(1.0).value() == 1); // identity scale
static_assert(od::descriptor{{.type = od::data_type::real32}}.to_raw(1.0).error() ==
              errc::type_mismatch);
static_assert(test_entries[1].default_for(5).value() == od::unsigned_number(0x85));
static_assert(test_entries[0].default_for(5).error() == errc::unknown_object);

template <std::size_t N>
constexpr std::array<std::uint8_t, N> enc(const od::entry &e, od::number v) {
  std::array<std::uint8_t, N> out{};
  auto n = od::encode(e, v, out);
  if (!n || n.value() != N) return {0xEE};
  return out;
}
static_assert(enc<1>(test_entries[6], od::signed_number(-1)) == std::array<std::uint8_t, 1>{0xFF});
static_assert(enc<4>(test_entries[0], od::unsigned_number(0x00020192)) ==
              std::array<std::uint8_t, 4>{0x92, 0x01, 0x02, 0x00});

template <class T>
constexpr bool round_trips(od::data_type t, T v) {
  const od::entry e{.type = t};
  std::array<std::uint8_t, 8> buf{};
  auto n = od::encode(e, v, buf);
  if (!n) return false;
  auto back = od::decode<T>(e, std::span<const std::uint8_t>(buf).first(n.value()));
  return back && back.value() == v;
}
static_assert(round_trips(od::data_type::boolean, true));
static_assert(round_trips(od::data_type::integer8, std::int8_t{-128}));
static_assert(round_trips(od::data_type::integer16, std::int16_t{-2}));
static_assert(round_trips(od::data_type::integer24, std::int32_t{-8388608}));
static_assert(round_trips(od::data_type::integer32, std::int32_t{-2147483647 - 1}));
static_assert(round_trips(od::data_type::integer40, std::int64_t{-549755813888}));
static_assert(round_trips(od::data_type::integer48, std::int64_t{140737488355327}));
static_assert(round_trips(od::data_type::integer56, std::int64_t{-1}));
static_assert(round_trips(od::data_type::integer64, std::int64_t{-9223372036854775807 - 1}));
static_assert(round_trips(od::data_type::unsigned8, std::uint8_t{255}));
static_assert(round_trips(od::data_type::unsigned16, std::uint16_t{65535}));
static_assert(round_trips(od::data_type::unsigned24, std::uint32_t{0xFFFFFF}));
static_assert(round_trips(od::data_type::unsigned32, std::uint32_t{0xFFFFFFFF}));
static_assert(round_trips(od::data_type::unsigned40, std::uint64_t{0xFF'FFFFFFFF}));
static_assert(round_trips(od::data_type::unsigned48, std::uint64_t{0xFFFF'FFFFFFFF}));
static_assert(round_trips(od::data_type::unsigned56, std::uint64_t{0xFFFFFF'FFFFFFFF}));
static_assert(round_trips(od::data_type::unsigned64, std::uint64_t{0xFFFFFFFF'FFFFFFFF}));
static_assert(round_trips(od::data_type::real32, 1.5F));
static_assert(round_trips(od::data_type::real64, -2.25));

constexpr std::array<od::command, 2> cmds{{
    {.code = 0x0600, .name = "cmd_stop", .modes = "automatic;online"},
    {.code = 0x0700,
     .name = "cmd_set_system_parameter",
     .parameter_min = od::signed_number(1),
     .parameter_max = od::signed_number(65535),
     .date_type = od::command_value::integer},
}};
constexpr od::command_table table{cmds};
static_assert(table.is_valid());
static_assert(table.find(0x0700)->name == "cmd_set_system_parameter");
static_assert(table.find(0x0600) == &cmds[0]);
static_assert(table.find(0x0650) == nullptr);
static_assert(table.find(0x0800) == nullptr);
static_assert(table.lookup(0x0601).error() == errc::unknown_command);
static_assert(cmds[0].allowed_in("online") && !cmds[0].allowed_in("home"));
static_assert(cmds[1].check_parameter(0).error() == errc::out_of_range);
static_assert(cmds[1].check_parameter(65535));

} // namespace

TEST_CASE("od: data type properties") {
  CHECK(od::fixed_size(od::data_type::integer24) == 3);
  CHECK(od::fixed_size(od::data_type::time_of_day) == 6);
  CHECK(od::fixed_size(od::data_type::visible_string) == 0);
  CHECK(od::name(od::data_type::unsigned56) == "UNSIGNED56");
  CHECK(od::is_data_type(0x1B));
  CHECK_FALSE(od::is_data_type(0x0E));
  CHECK_FALSE(od::is_data_type(0x17));
  CHECK_FALSE(od::is_data_type(0x1C));
  CHECK(od::writable(od::access::rww));
  CHECK_FALSE(od::writable(od::access::constant));
  CHECK_FALSE(od::readable(od::access::wo));
  CHECK(od::mappable_rx(od::pdo_mapping::rx));
  CHECK_FALSE(od::mappable_tx(od::pdo_mapping::rx));
}

TEST_CASE("od: lookup") {
  for (const od::entry &e : dict) {
    auto r = dict.lookup(e.index, e.sub);
    REQUIRE(r);
    CHECK(r.value() == &e);
  }
  CHECK(dict.info(*dict.object(0x1018).find(3)).name == "Revision");
  CHECK(dict.object(0x1018)[3].info.name == "Revision"); // [sub], not [position]
  CHECK_FALSE(od::dictionary{}.contains(0, 0));
  constexpr std::array<od::entry, 2> unsorted{{{.index = 2}, {.index = 1}}};
  CHECK_FALSE(od::dictionary{unsorted}.is_valid());
  constexpr std::array<od::entry, 2> dup{{{.index = 1}, {.index = 1}}};
  CHECK_FALSE(od::dictionary{dup}.is_valid());
  // the key is (index, sub): the sub-index orders entries of one index only
  constexpr std::array<od::entry, 2> subs_down{{{.index = 1, .sub = 2}, {.index = 1, .sub = 1}}};
  static_assert(!od::dictionary{subs_down}.is_valid());
  constexpr std::array<od::entry, 3> by_index{
      {{.index = 1, .sub = 5}, {.index = 2}, {.index = 2, .sub = 0xFF}}};
  static_assert(od::dictionary{by_index}.is_valid());
  static_assert(od::dictionary{}.is_valid());
  constexpr std::array<od::entry, 3> last_out{{{.index = 1}, {.index = 3}, {.index = 2}}};
  static_assert(!od::dictionary{last_out}.is_valid());
}

TEST_CASE("od: encode range checks") {
  std::array<std::uint8_t, 8> buf{};
  const od::entry &mode = test_entries[6];
  CHECK(od::encode(mode, std::int8_t{10}, buf).value() == 1);
  CHECK(od::encode(mode, 11, buf).error() == errc::out_of_range);
  CHECK(od::encode(mode, -2, buf).error() == errc::out_of_range);
  CHECK(od::encode(mode, 1.5, buf).error() == errc::not_representable);
  CHECK(od::encode(mode, 3.0, buf).value() == 1);
  const od::entry u8{.type = od::data_type::unsigned8};
  CHECK(od::encode(u8, 256, buf).error() == errc::overflow);
  CHECK(od::encode(u8, -1, buf).error() == errc::overflow);
  const od::entry i16{.type = od::data_type::integer16};
  CHECK(od::encode(i16, 32768, buf).error() == errc::overflow);
  CHECK(od::encode(i16, -32769, buf).error() == errc::overflow);
  CHECK(od::encode(i16, 1, std::span<std::uint8_t>(buf).first(1)).error() ==
        errc::buffer_too_small);
  const od::entry b{.type = od::data_type::boolean};
  CHECK(od::encode(b, 2, buf).error() == errc::out_of_range);
  const od::entry r32{.type = od::data_type::real32};
  CHECK(od::encode(r32, 1e39, buf).error() == errc::overflow);
  CHECK(od::encode(r32, std::numeric_limits<double>::quiet_NaN(), buf).error() ==
        errc::not_representable);
  CHECK(od::encode(r32, od::number{}, buf).error() == errc::type_mismatch);
  static constexpr od::entry_spec vs_spec{.type = od::data_type::visible_string, .size = 4};
  static constexpr const od::entry &vs = od::entry_of<vs_spec>;
  CHECK(od::encode(vs, 1, buf).error() == errc::type_mismatch);
  // scaled entry: raw limits are round(low × scale), round(high × scale)
  CHECK(od::encode(inj, std::uint32_t{1638350}, buf).value() == 4);
  CHECK(od::encode(inj, std::uint32_t{1638351}, buf).error() == errc::out_of_range);
  // ... which a plain entry cannot know
  CHECK(od::encode(test_entries[5], std::uint32_t{1}, buf).error() == errc::invalid_argument);
}

TEST_CASE("od: decode") {
  const od::entry i24{.type = od::data_type::integer24};
  const std::array<std::uint8_t, 3> m1{0xFF, 0xFF, 0xFF};
  CHECK(od::decode<std::int32_t>(i24, m1).value() == -1);
  CHECK(od::decode<std::int8_t>(i24, m1).value() == -1);
  const std::array<std::uint8_t, 3> big{0x00, 0x00, 0x80};
  CHECK(od::decode<std::int16_t>(i24, big).error() == errc::overflow);
  CHECK(od::decode<std::uint32_t>(i24, m1).error() == errc::overflow);
  CHECK(od::decode(i24, std::span<const std::uint8_t>(m1).first(2)).error() == errc::truncated);
  const std::array<std::uint8_t, 4> four{};
  CHECK(od::decode(i24, four).error() == errc::bad_length);
  const od::entry &mode = test_entries[6];
  const std::array<std::uint8_t, 1> eleven{11};
  CHECK(od::decode(mode, eleven).error() == errc::out_of_range);
  CHECK(od::decode(mode, eleven, fc::byte_order::little, od::limits::ignore).value() ==
        od::signed_number(11));
  const od::entry b{.type = od::data_type::boolean};
  const std::array<std::uint8_t, 1> two{2};
  CHECK(od::decode(b, two).error() == errc::out_of_range);
  const od::entry u16{.type = od::data_type::unsigned16};
  const std::array<std::uint8_t, 2> be{0x12, 0x34};
  CHECK(od::decode<std::uint16_t>(u16, be, fc::byte_order::big).value() == 0x1234);
  CHECK(od::decode<std::uint16_t>(u16, be).value() == 0x3412);
  const od::entry r32{.type = od::data_type::real32};
  const std::array<std::uint8_t, 4> nan{0x00, 0x00, 0xC0, 0x7F};
  CHECK(od::decode(r32, nan).error() == errc::not_representable);
  CHECK(od::decode<int>(r32, std::array<std::uint8_t, 4>{0, 0, 0x80, 0x3F}).error() ==
        errc::not_representable);
}

TEST_CASE("od: time values") {
  const od::entry t{.type = od::data_type::time_of_day};
  std::array<std::uint8_t, 6> buf{};
  const od::time_value v{.ms = 0x0ABCDEF, .days = 0x1234};
  REQUIRE(od::encode(t, od::to_number(v), buf).value() == 6);
  CHECK(buf == std::array<std::uint8_t, 6>{0xEF, 0xCD, 0xAB, 0x00, 0x34, 0x12});
  CHECK(od::to_time(od::decode(t, buf).value()).value() == v);
  CHECK(od::encode(t, od::to_number({.ms = od::time_ms_max + 1U}), buf).error() ==
        errc::out_of_range);
  buf[3] = 0x10; // ms beyond 28 bits
  CHECK(od::decode(t, buf).error() == errc::out_of_range);
}

TEST_CASE("od: byte strings") {
  static constexpr od::entry_spec vs_spec{.type = od::data_type::visible_string, .size = 4};
  static constexpr const od::entry &vs = od::entry_of<vs_spec>;
  std::array<std::uint8_t, 8> buf{};
  const std::array<std::uint8_t, 3> abc{'a', 'b', 'c'};
  CHECK(od::encode_bytes(vs, abc, buf).value() == 3);
  const std::array<std::uint8_t, 5> five{'a', 'b', 'c', 'd', 'e'};
  CHECK(od::encode_bytes(vs, five, buf).error() == errc::too_long);
  const std::array<std::uint8_t, 2> ctl{'a', 0x07};
  CHECK(od::encode_bytes(vs, ctl, buf).error() == errc::bad_character);
  CHECK(od::encode_bytes(vs, abc, std::span<std::uint8_t>(buf).first(2)).error() ==
        errc::buffer_too_small);
  const std::array<std::uint8_t, 4> padded{'a', 'b', 0, 0};
  CHECK(od::decode_bytes(vs, padded).value().size() == 2);
  const od::entry us{.type = od::data_type::unicode_string};
  CHECK(od::decode_bytes(us, abc).error() == errc::bad_length);
  const od::entry os{.type = od::data_type::octet_string};
  CHECK(od::decode_bytes(os, ctl).value().size() == 2);
  CHECK(od::encode_bytes(test_entries[0], abc, buf).error() == errc::type_mismatch);
}

TEST_CASE("od: numbers") {
  CHECK(od::decimal_number(32767, 2).to_double() == doctest::Approx(327.67));
  CHECK(od::unsigned_number(~std::uint64_t{0}).to_int64().error() == errc::overflow);
  CHECK(od::real_number(2.5).to_int64().error() == errc::not_representable);
  CHECK(od::real_number(2.0).to_int64().value() == 2);
  CHECK(od::signed_number(-1).to_uint64().error() == errc::overflow);
  CHECK(od::number{}.to_decimal().error() == errc::unknown_object);
  CHECK_FALSE(od::number{});
}
