// The lean core entry, its parallel tables (infos, scales), od::descriptor, od::object views and
// the dictionary's lookups by position (issue 14 "The descriptor").
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/object.hpp>
#include <fieldcodec/od/value.hpp>

#if __has_include(<fieldcodec/dictionaries/xenax_canopen.hpp>)
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#define FIELDCODEC_HAVE_GENERATED 1
#endif

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

namespace fc = fieldcodec;
namespace od = fieldcodec::od;
using fc::errc;

namespace {

// The core descriptor stays lean: 80 bytes on a 64-bit host (72 on Cortex-M; it was 296 with
// the descriptive columns and the scale inside, docs/performance.md).
static_assert(sizeof(void *) != 8 || sizeof(od::entry) <= 80);

constexpr std::array<od::entry_spec, 6> entries_spec{{
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
     .sub = 4,
     .object = od::object_code::record,
     .type = od::data_type::unsigned32,
     .access_type = od::access::ro},
    {.index = 0x1400,
     .sub = 1,
     .object = od::object_code::record,
     .type = od::data_type::unsigned32,
     .flags = od::flag::default_nodeid | od::flag::parameter_nodeid,
     .default_value = od::unsigned_number(0x200)},
    {.index = 0x2023,
     .type = od::data_type::unsigned32,
     .flags = od::flag::scaled,
     .low = od::signed_number(0),
     .high = od::signed_number(5000)},
    {.index = 0x2100,
     .object = od::object_code::array,
     .type = od::data_type::integer16,
     .flags = od::flag::scaled,
     .low = od::signed_number(-10),
     .high = od::signed_number(10)},
}};
constexpr auto entries = od::entries_of<entries_spec>;
constexpr std::array<od::entry_info, 6> infos{{
    {.name = "Number of entries"},
    {.name = "Vendor-ID"},
    {.name = "Serial number"},
    {.name = "COB-ID", .parameter_value = od::unsigned_number(0x200)},
    {.name = "Inj. P Limit 1", .unit = "bar", .section = "4.100"},
    {.name = "Gain", .unit = "%"},
}};
constexpr std::array<fc::scaling::linear, 6> scales{
    {{}, {}, {}, {}, {{32767, 2}, {0, 0}}, {{100, 0}, {0, 0}}}};
constexpr od::dictionary dict{entries, infos, scales};
static_assert(dict.is_valid());

// Parallel tables must have one element per entry; a scaled entry needs a scale table.
static_assert(!od::dictionary{entries, std::span(infos).first(5)}.is_valid());
static_assert(!od::dictionary{entries, infos, std::span(scales).first(5)}.is_valid());
static_assert(!od::dictionary{entries, infos}.is_valid());             // scaled, no scales
static_assert(od::dictionary{std::span(entries).first(4)}.is_valid()); // no infos: fine

// Lookups by address and by (index, sub).
static_assert(dict.find(od::address{0x1018, 4}) == &entries[2]);
static_assert(dict.find(0x1018, 4) == &entries[2]);
static_assert(dict.find(0x1018, 2) == nullptr);
static_assert(dict.lookup(od::address{0x2023, 0}).value() == &entries[4]);
static_assert(dict.lookup(0x2023, 1).error() == errc::unknown_object);
static_assert(dict.contains(od::address{0x1400, 1}) && !dict.contains(0x1400, 0));
static_assert(dict.position(entries[3]) == 3);
// By position: what a constant expression tests under g++ -fsanitize=undefined (docs/od.md).
static_assert(dict.position(od::address{0x1018, 4}) == 2);
static_assert(dict.position(od::address{0x1018, 2}) == dict.size());
static_assert(dict.position(od::address{0xFFFF, 0xFF}) == dict.size());

// info / scale / describe by position.
static_assert(dict.info(entries[1]).name == "Vendor-ID");
static_assert(dict.scale(entries[4]).scale.mantissa == 32767);
static_assert(dict.describe(entries[4]).value().info.unit == "bar");
static_assert(dict.at(0x2023, 0).value().to_raw(4.0).value() == 1311);
static_assert(dict.at(0x2023, 0).value().info.section == "4.100");
static_assert(dict.at(od::address{0x1018, 2}).error() == errc::unknown_object);

// A dictionary without infos or scales answers od::no_info and the identity.
constexpr od::dictionary bare{std::span(entries).first(4)};
static_assert(bare.info(entries[1]).name.empty());
static_assert(bare.scale(entries[1]).scale.mantissa == 1);
static_assert(bare.at(0x1018, 1).value().info.name.empty());

// The node-ID-relative default and DCF parameter value.
static_assert(dict.at(0x1400, 1).value().default_for(5).value() == od::unsigned_number(0x205));
static_assert(dict.at(0x1400, 1).value().parameter_for(5).value() == od::unsigned_number(0x205));
static_assert(dict.at(0x2023, 0).value().parameter_for(5).error() == errc::unknown_object);

// Flags.
static_assert(entries[3].has(od::flag::default_nodeid));
static_assert(entries[3].has(od::flag::default_nodeid | od::flag::parameter_nodeid));
static_assert(!entries[3].has(od::flag::default_nodeid | od::flag::scaled));
static_assert(!entries[0].has(od::flag::scaled));

// object(index): a view with the same shape (entries, infos, scales); [sub] is the sub-index.
constexpr od::object identity = dict.object(0x1018);
static_assert(identity.index == 0x1018 && identity.code == od::object_code::record);
static_assert(identity.size() == 3 && identity.infos.size() == 3 && identity.scales.size() == 3);
static_assert(identity[4].info.name == "Serial number"); // sub 4 (position 2)
static_assert(identity.at(4).value().index == 0x1018);
static_assert(identity.at(2).error() == errc::unknown_object);
static_assert(identity.find(2) == nullptr);
static_assert(identity.contains(4) && !identity.contains(2) && !identity.contains(0xFF));
static_assert(identity.position(4) == 2 && identity.position(2) == identity.size());
static_assert(identity.lookup(1).value() == &entries[1]);
static_assert(identity.info(entries[1]).name == "Vendor-ID");
static_assert(identity.info(entries[4]).name.empty()); // not one of its entries
static_assert(identity.describe(entries[4]).error() == errc::unknown_object);
static_assert(dict.object(0x1019).empty() && dict.object(0x1019).code == od::object_code::var);
static_assert(dict.object(0x2100)[0].scale.scale.mantissa == 100);

} // namespace

TEST_CASE("od descriptor: by position at run time") {
  for (std::size_t i = 0; i < entries.size(); ++i) {
    CHECK(dict.position(entries[i]) == i);
    CHECK(dict.info(entries[i]).name == infos[i].name);
    const auto d = dict.describe(entries[i]);
    REQUIRE(d.has_value());
    CHECK(d.value().index == entries[i].index);
    CHECK(d.value().sub == entries[i].sub);
    CHECK(d.value().scale.scale.mantissa == scales[i].scale.mantissa);
  }
  // an entry that is not an element of the dictionary: a copy, or an element of another table
  const od::entry copy = entries[1];
  CHECK(dict.position(copy) == dict.size());
  CHECK(dict.info(copy).name.empty());
  CHECK(dict.scale(copy).scale.mantissa == 1);
  CHECK(dict.describe(copy).error() == errc::unknown_object);
  const od::dictionary other{std::span(entries).subspan(1)};
  CHECK(other.position(entries[0]) == other.size());
  CHECK(other.position(entries[1]) == 0);
}

TEST_CASE("od descriptor: values of an object's sub-object") {
  std::array<std::uint8_t, 4> out{};
  const od::object gain = dict.object(0x2100);
  // sub 0 of the ARRAY is scaled: −10..10 % at scale 100 → raw −1000..1000
  CHECK(od::encode(gain, 0, std::int16_t{1000}, out).value() == 2);
  CHECK(out[0] == 0xE8);
  CHECK(out[1] == 0x03);
  CHECK(od::encode(gain, 0, std::int16_t{1001}, out).error() == errc::out_of_range);
  CHECK(od::encode(gain, 1, std::int16_t{0}, out).error() == errc::unknown_object);
  CHECK(od::decode(gain, 0, std::span<const std::uint8_t>(out).first(2)).value() ==
        od::signed_number(1000));
  CHECK(od::decode<int>(gain, 0, std::span<const std::uint8_t>(out).first(2)).value() == 1000);
  CHECK(od::decode(gain, 2, std::span<const std::uint8_t>(out).first(2)).error() ==
        errc::unknown_object);
  CHECK(od::encode(gain[0], 1001.0, out).error() == errc::out_of_range); // values are raw
  CHECK(gain[0].to_raw(10.0).value() == 1000);                           // EU 10 → raw 1000
}

#ifdef FIELDCODEC_HAVE_GENERATED
TEST_CASE("od descriptor: generated headers") {
  namespace xc = fieldcodec::dictionaries::xenax_canopen;
  namespace dpq = fieldcodec::dictionaries::dpq_parameters;
  // a named VAR object is a standalone descriptor: equal to its table row, not the row itself
  const od::entry *row = xc::dictionary.find(0x1000, 0);
  REQUIRE(row != nullptr);
  CHECK(static_cast<const od::entry *>(&xc::device_type) != row);
  CHECK(xc::device_type.index == row->index);
  CHECK(xc::device_type.default_value() == row->default_value());
  CHECK(xc::device_type.info.name == xc::dictionary.info(*row).name);
  CHECK(dpq::inj_p_limit_1.scale.scale.mantissa == 32767);
  CHECK(dpq::inj_p_limit_1.info.unit ==
        dpq::dictionary.info(*dpq::dictionary.find(0x2023, 0)).unit);
  // an ARRAY/RECORD object is a view: [sub] gives the descriptor
  CHECK(xc::identity_object.index == 0x1018);
  CHECK(xc::identity_object[1].info.name ==
        xc::dictionary.info(*xc::dictionary.find(0x1018, 1)).name);
  CHECK(xc::identity_object.at(0x7F).error() == errc::unknown_object);
  CHECK(xc::dictionary.object(0x1018).size() == xc::identity_object.size());
  // named sub-objects of a RECORD are standalone descriptors too
  static_assert(std::is_same_v<decltype(xc::identity_object_vendor_id), const od::descriptor>);
  CHECK(xc::identity_object_vendor_id.sub == 1);
  CHECK(xc::identity_object_vendor_id.info.name == xc::identity_object[1].info.name);
  // every generated string has exactly its length (the {"…", n} literals keep embedded NULs and
  // never count the terminator)
  for (const od::entry &e : xc::dictionary) {
    const auto &i = xc::dictionary.info(e);
    CHECK(i.name.view().find('\0') == std::string_view::npos);
    CHECK(!i.name.empty());
  }
}
#endif

TEST_CASE("od descriptor: a negative scale turns the engineering limits around") {
  // 0..10 EU at scale −1 is raw −10..0; with only the low end, raw ≤ 0
  static constexpr od::entry_spec both_spec{.type = od::data_type::integer16,
                                            .flags = od::flag::scaled,
                                            .low = od::signed_number(0),
                                            .high = od::signed_number(10)};
  const od::descriptor both{od::entry_of<both_spec>, {}, {{-1, 0}, {0, 0}}};
  std::array<std::uint8_t, 2> out{};
  CHECK(od::encode(both, -10, out).value() == 2);
  CHECK(od::encode(both, 0, out).value() == 2);
  CHECK(od::encode(both, 1, out).error() == errc::out_of_range);
  CHECK(od::encode(both, -11, out).error() == errc::out_of_range);
  CHECK(both.to_raw(fc::decimal{10, 0}).value() == -10);
  od::descriptor low_only = both;
  low_only.flags = static_cast<std::uint16_t>(low_only.flags & ~od::flag::has_high);
  CHECK(od::encode(low_only, -30000, out).value() == 2);
  CHECK(od::encode(low_only, 1, out).error() == errc::out_of_range);
}
