// COMPAX objects by dictionary entry (compax/objects.hpp) and the DRIVECOM wrappers over ds402
// (compax/drivecom.hpp). Entries are written here like the generated ones; when the generated
// dictionary exists the manual's examples are also checked by name.
#include <fieldcodec/compax/columns.hpp>
#include <fieldcodec/compax/drivecom.hpp>
#include <fieldcodec/compax/object_channel.hpp>
#include <fieldcodec/compax/objects.hpp>
#include <fieldcodec/od/columns.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#if __has_include(<fieldcodec/dictionaries/compax_objects.hpp>)
#include <fieldcodec/dictionaries/compax_objects.hpp>
#define FIELDCODEC_HAVE_COMPAX_DICTIONARY 1
#endif

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace cx = fieldcodec::compax;
namespace od = fieldcodec::od;
using fieldcodec::decimal;
using fieldcodec::errc;
using bytes = std::vector<std::uint8_t>;

namespace {

constexpr od::descriptor lage_ziel{
    {.index = 0x607A, .type = od::data_type::integer32, .flags = od::flag::scaled},
    {.name = "LAGE_ZIEL"},
    {{1000, 0}, {0, 0}}};
// entries with a capacity or limits: written as specs, packed by od::table
constexpr od::entry_spec specs[] = {
    {.index = 0x5FEA,
     .type = od::data_type::unsigned16,
     .low = od::signed_number(0),
     .high = od::signed_number(65000)},
    {.index = 0x5FED, .type = od::data_type::octet_string, .size = 3},
    {.index = 0x5FE6, .type = od::data_type::visible_string, .size = 20},
    {.index = 0x5FF0, .type = od::data_type::octet_string, .flags = od::flag::scaled, .size = 6},
};
constexpr od::table_of<specs> table{specs};
constexpr od::descriptor posa{table[3], {.name = "POSA"}, {{1000, 0}, {0, 0}}};
constexpr od::descriptor posr0speed{table[1], {.name = "POSR0SPEED"}};
constexpr od::descriptor speed{
    {.index = 0x5FEC, .type = od::data_type::integer16, .flags = od::flag::scaled},
    {.name = "SPEED"},
    {{64, 0}, {0, 0}}};
constexpr od::descriptor out_enable{{.index = 0x5FFF, .type = od::data_type::boolean},
                                    {.name = "OUT_ENABLE"}};
constexpr od::descriptor accel_pos{table[0], {.name = "ACCEL_POS"}};
constexpr std::array<od::entry, 3> px_entries{{
    {.index = 0x5FD4, .sub = 11, .type = od::data_type::integer32, .flags = od::flag::scaled},
    {.index = 0x5FD4, .sub = 21, .type = od::data_type::integer32, .flags = od::flag::scaled},
    {.index = 0x5FD4, .sub = 100, .type = od::data_type::integer32, .flags = od::flag::scaled},
}};
constexpr std::array<od::entry_info, 3> px_infos{{{.name = "Px"}, {.name = "Px"}, {.name = "Px"}}};
constexpr std::array<fieldcodec::scaling::linear, 3> px_scales{
    {{{1000, 0}, {0, 0}}, {{1000000, 0}, {0, 0}}, {{1, 0}, {0, 0}}}};
constexpr od::dictionary px_dict{px_entries, px_infos, px_scales};
static_assert(px_dict.is_valid());

bytes enc(const od::descriptor &e, decimal v) {
  std::array<std::uint8_t, 8> b{};
  auto n = cx::encode_object(e, v, b);
  REQUIRE(n.has_value());
  return bytes(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(n.value()));
}

} // namespace

TEST_CASE("objects by entry: integers, BCD, boolean") {
  CHECK(enc(lage_ziel, decimal{-1000, 0}) == bytes{0xFF, 0xF0, 0xBD, 0xC0});
  CHECK(fieldcodec::equal(cx::decode_object(lage_ziel, bytes{0xFF, 0xF0, 0xBD, 0xC0}).value(),
                          decimal{-1000, 0}));
  CHECK(cx::decode_object(lage_ziel, bytes{0x80, 0, 0, 0}).error() == errc::overflow);
  CHECK(cx::decode_object(lage_ziel, bytes{0x80, 0, 0}).error() == errc::truncated);
  std::array<std::uint8_t, 4> b4{};
  CHECK(cx::encode_object(lage_ziel, decimal{-2147483648, 3}, b4).error() == errc::overflow);
  CHECK(cx::encode_object(lage_ziel, decimal{2147484, 0}, b4).error() == errc::overflow);
  CHECK(enc(posa, decimal{735015, 2}) == bytes{0x00, 0x00, 0x07, 0x35, 0x01, 0x50});
  CHECK(
      fieldcodec::equal(cx::decode_object(posa, bytes{0xFF, 0x00, 0x37, 0x89, 0x12, 0x10}).value(),
                        decimal{-3789121, 2}));
  CHECK(cx::decode_object(posa, bytes{0x01, 0, 0, 0, 0, 0}).error() == errc::bad_sign);
  CHECK(enc(posa, decimal{10005, 4}) == bytes{0x00, 0x00, 0x00, 0x00, 0x10, 0x01});
  std::array<std::uint8_t, 6> b6{};
  CHECK(cx::encode_object(posa, decimal{4000001, 0}, b6).error() == errc::out_of_range);
  CHECK(enc(posr0speed, decimal{35, 0}) == bytes{0x03, 0x50, 0x00});
  CHECK(cx::encode_object(posr0speed, decimal{-1, 0}, b4).error() == errc::out_of_range);
  CHECK(enc(speed, decimal{75, 0}) == bytes{0x12, 0xC0});
  CHECK(fieldcodec::equal(cx::decode_object(speed, bytes{0x12, 0xC0}).value(), decimal{75, 0}));
  CHECK(enc(out_enable, decimal{1, 0}) == bytes{0xFF});
  CHECK(cx::encode_object(out_enable, decimal{2, 0}, b4).error() == errc::out_of_range);
  CHECK(cx::decode_object(out_enable, bytes{0x01}).error() == errc::out_of_range);
  CHECK(enc(accel_pos, decimal{1000, 0}) == bytes{0x03, 0xE8});
  CHECK(cx::encode_object(accel_pos, decimal{65001, 0}, b4).error() == errc::out_of_range);
  std::array<std::uint8_t, 1> b1{};
  CHECK(cx::encode_object(lage_ziel, decimal{1, 0}, b1).error() == errc::buffer_too_small);
  const od::descriptor text{table[2]};
  CHECK(cx::encode_object(text, decimal{1, 0}, b4).error() == errc::type_mismatch);
}

TEST_CASE("Px in engineering units with the resolution of its row") {
  std::array<std::uint8_t, 4> b{};
  // 2.4.13 example: P11 = 5000 → 00 4C 4B 40
  REQUIRE(cx::encode_px(px_dict, 11, decimal{5000, 0}, b).value() == 4);
  CHECK(b == std::array<std::uint8_t, 4>{0x00, 0x4C, 0x4B, 0x40});
  CHECK(fieldcodec::equal(cx::decode_px(px_dict, 11, b).value(), decimal{5000, 0}));
  REQUIRE(cx::encode_px(px_dict, 21, decimal{1, 6}, b).has_value());
  CHECK(b == std::array<std::uint8_t, 4>{0, 0, 0, 1});
  REQUIRE(cx::encode_px(px_dict, 100, decimal{15, 1}, b).has_value()); // rounded half away
  CHECK(b == std::array<std::uint8_t, 4>{0, 0, 0, 2});
  CHECK(cx::encode_px(px_dict, 12, decimal{1, 0}, b).error() == errc::unknown_object);
}

TEST_CASE("DRIVECOM profile 22 over ds402") {
  using fieldcodec::ds402::state;
  CHECK(cx::drivecom_state(cx::statuswort{0x0040}).value() == state::switch_on_disabled);
  CHECK(cx::drivecom_state(cx::statuswort{0x0027}).value() == state::operation_enabled);
  CHECK(cx::drivecom_state(cx::statuswort{0x0008}).value() == state::fault);
  // COMPAX bits of the previous word survive (FreezePAD, relative)
  const auto prev =
      cx::steuerwort{}.with(cx::steuerwort_bit::freeze_pad).with(cx::steuerwort_bit::relative);
  const auto next = cx::next_steuerwort(cx::statuswort{0x0040}, state::operation_enabled, prev);
  REQUIRE(next.has_value());
  CHECK(next.value().raw == (0x0006 | 0x0100 | 0x0040));
  CHECK(cx::next_steuerwort(cx::statuswort{0x0021}, state::operation_enabled, prev).value().raw ==
        (0x000F | 0x0100 | 0x0040));
  // fault: rising edge of bit 7
  CHECK(cx::next_steuerwort(cx::statuswort{0x0008}, state::operation_enabled, cx::steuerwort{})
            .value()
            .test(cx::steuerwort_bit::fault_reset));
}

#ifdef FIELDCODEC_HAVE_COMPAX_DICTIONARY
TEST_CASE("generated COMPAX dictionary: manual examples by name") {
  namespace d = fieldcodec::dictionaries::compax_objects;
  CHECK(enc(d::lage_ziel, decimal{-1000, 0}) == bytes{0xFF, 0xF0, 0xBD, 0xC0});
  CHECK(enc(d::realnull, decimal{-500, 0}) == bytes{0xFF, 0xF8, 0x5E, 0xE0});
  CHECK(enc(d::posa, decimal{735015, 2}) == bytes{0x00, 0x00, 0x07, 0x35, 0x01, 0x50});
  CHECK(enc(d::posr, decimal{-3789121, 2}) == bytes{0xFF, 0x00, 0x37, 0x89, 0x12, 0x10});
  CHECK(enc(d::posr0speed, decimal{35, 0}) == bytes{0x03, 0x50, 0x00});
  CHECK(enc(d::speed, decimal{75, 0}) == bytes{0x12, 0xC0});
  CHECK(enc(d::override_, decimal{50, 0}) == bytes{0x80});
  CHECK(enc(d::geschw_max, decimal{95, 0}) == bytes{0x00, 0x01, 0x73, 0x18});
  CHECK(enc(d::nennmoment, decimal{52, 1}) == bytes{0x00, 0x34});
  CHECK(enc(d::nennstrom, decimal{51, 1}) == bytes{0x00, 0x33});
  CHECK(enc(d::rampe_ref, decimal{733, 0}) == bytes{0x00, 0x00, 0x02, 0xDD});
  std::array<std::uint8_t, 4> b{};
  REQUIRE(cx::encode_px(d::dictionary, 11, decimal{5000, 0}, b).has_value());
  CHECK(b == std::array<std::uint8_t, 4>{0x00, 0x4C, 0x4B, 0x40});
  // every Px row has a resolution of 1, 0.001 or 0.000001
  for (unsigned n = 1; n <= 250; ++n) {
    auto e = d::dictionary.lookup(cx::index::px, static_cast<std::uint8_t>(n));
    REQUIRE(e.has_value());
    CHECK(e.value()->has(od::flag::scaled));
  }
  // pointers for OBJECT_REQ: the COMPAX column table beside the dictionary (compax/columns.hpp)
  CHECK(cx::index_pointer(d::compax_columns, d::lage_ist) == 67);
  CHECK(cx::index_pointer(d::compax_columns, d::speed) == 38);
  CHECK(cx::index_pointer(d::compax_columns, fieldcodec::od::address{0x5FC7, 0}) == 1);
  // an object without a pointer (OBJECT_REQ itself) and an address nobody has
  CHECK(cx::index_pointer(d::compax_columns, fieldcodec::od::address{0x5FC5, 0}) ==
        fieldcodec::errc::unknown_object);
  CHECK(cx::index_pointer(d::compax_columns, fieldcodec::od::address{0xFFFF, 255}) ==
        fieldcodec::errc::unknown_object);
  CHECK(cx::index_pointer({}, d::speed) == fieldcodec::errc::unknown_object);
  // sorted, each row an entry of the dictionary, each pointer one OBJECT_REQ can send
  CHECK(fieldcodec::od::rows_sorted(std::span<const cx::object_columns>(d::compax_columns)));
  for (const auto &row : d::compax_columns) {
    CHECK(d::dictionary.contains({row.index, row.sub}));
    CHECK(row.pointer <= cx::object_pointer_max);
  }
}

// Issue 13: arrays and records are od::object. Their elements are encoded by object and
// sub-index, and the single-value call does not compile for them (the difference is visible at
// the call site; `d::grenzen[1]` names the element's descriptor too).
template <class O>
constexpr bool encodes_without_sub = requires(const O &o, std::span<std::uint8_t> out) {
  cx::encode_object(o, decimal{}, out);
};
template <class O>
constexpr bool decodes_without_sub = requires(const O &o, std::span<const std::uint8_t> in) {
  cx::decode_object(o, in);
};
static_assert(encodes_without_sub<od::descriptor> && decodes_without_sub<od::descriptor>);
static_assert(!encodes_without_sub<od::object> && !decodes_without_sub<od::object>);

TEST_CASE("generated COMPAX dictionary: array elements by object and sub-index") {
  namespace d = fieldcodec::dictionaries::compax_objects;
  std::array<std::uint8_t, 4> b{};
  // 2.7.9 example (L1860-1866): negative limit −1650.000 mm = FF E6 D2 B0 (erratum CX-20)
  REQUIRE(cx::encode_object(d::grenzen, 1, decimal{-1650, 0}, b).value() == 4);
  CHECK(b == std::array<std::uint8_t, 4>{0xFF, 0xE6, 0xD2, 0xB0});
  CHECK(fieldcodec::equal(cx::decode_object(d::grenzen, 1, b).value(), decimal{-1650, 0}));
  CHECK(fieldcodec::equal(cx::decode_object(d::grenzen, std::uint64_t{2}, b).value(),
                          decimal{-1650, 0}));
  // the same as the descriptor the array holds
  CHECK(cx::encode_object(d::grenzen[2], decimal{1, 0}, b).value() == 4);
  CHECK(b == std::array<std::uint8_t, 4>{0x00, 0x00, 0x03, 0xE8});
  // sub-indices the array does not have, of any integer type, never wrapped
  CHECK(cx::encode_object(d::grenzen, 3, decimal{1, 0}, b).error() == errc::unknown_object);
  CHECK(cx::encode_object(d::grenzen, 257, decimal{1, 0}, b).error() == errc::unknown_object);
  CHECK(cx::encode_object(d::grenzen, -255, decimal{1, 0}, b).error() == errc::unknown_object);
  CHECK(cx::decode_object(d::grenzen, 0, b).error() == errc::unknown_object);
  // S7_S8 sub 2 (2.6.7): intermediate circuit voltage, 1 = 0.1 V
  const std::array<std::uint8_t, 2> volts{0x0F, 0xA0};
  CHECK(fieldcodec::equal(cx::decode_object(d::s7_s8, 2, volts).value(), decimal{400, 0}));
  // Px by number: any integer type; 267 is not parameter 11
  CHECK(cx::encode_px(d::dictionary, 267, decimal{5000, 0}, b).error() == errc::unknown_object);
  CHECK(cx::encode_px(d::dictionary, 11LL, decimal{5000, 0}, b).value() == 4);
  CHECK(cx::decode_px(d::dictionary, -1, b).error() == errc::unknown_object);
}

// Issue 12: CONTROL (2.4.10) takes command numbers 1..21; 22..24 are "not assigned".
TEST_CASE("generated COMPAX dictionary: CONTROL refuses 0 and 22") {
  namespace d = fieldcodec::dictionaries::compax_objects;
  std::array<std::uint8_t, 1> b{};
  CHECK(cx::encode_object(d::control, decimal{0, 0}, b).error() == errc::out_of_range);
  CHECK(cx::encode_object(d::control, decimal{22, 0}, b).error() == errc::out_of_range);
  CHECK(cx::encode_object(d::control, decimal{255, 0}, b).error() == errc::out_of_range);
  // 2.4.10 example: go to machine zero = command 1 → data byte 0x01
  CHECK(enc(d::control, decimal{1, 0}) == bytes{0x01});
  CHECK(enc(d::control, decimal{21, 0}) == bytes{0x15});
  CHECK(cx::decode_object(d::control, bytes{0x00}).has_value()); // a read is not refused
}
#endif
