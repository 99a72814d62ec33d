// xenax::canopen_units (docs/xenax.md, decision 15) through od::with_unit: the XENAX's units as
// data on the generic value path (od/engineering.hpp, od/value_text.hpp).
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/dictionaries/xenax_ethercat.hpp>
#include <fieldcodec/dictionaries/xenax_powerlink.hpp>
#include <fieldcodec/od/value_text.hpp>
#include <fieldcodec/xenax/canopen_units.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <string_view>

namespace od = fieldcodec::od;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;
using fieldcodec::errc;

namespace {
constexpr od::unit_descriptor with_units(od::address a) {
  return od::with_unit(xcan::dictionary.at(a).value(), fieldcodec::xenax::canopen_units).value();
}
// 6073h: 10 mA per raw step, HighLimit 0x7D0 = 20000 mA. (The unit_descriptor is made inside
// each constant expression: g++ 12 refuses a constexpr variable whose entry points into itself.)
constexpr od::address limit{0x6073, 0};
static_assert(od::is_scaled(with_units(limit)));
static_assert(with_units(limit).info.unit == "mA");
static_assert(with_units(limit).high() == od::decimal_number(20000, 0));
static_assert(with_units(limit).low() == od::decimal_number(0, 0));
constexpr std::int64_t raw_of(od::address a, std::string_view text) {
  const od::unit_descriptor d = with_units(a);
  std::array<std::uint8_t, 8> out{};
  auto n = od::parse_value(d, text, out);
  return n ? static_cast<std::int64_t>(out[0] | (out[1] << 8U)) : -1;
}
static_assert(raw_of(limit, "1500 mA") == 150);
static_assert(raw_of(limit, "20000") == 2000);
static_assert(raw_of(limit, "20010") == -1);
// positions only get their unit
static_assert(!od::is_scaled(with_units({0x607A, 0})));
static_assert(with_units({0x607A, 0}).info.unit == "inc");
// sub-index 0 of an ARRAY counts its entries: no unit; the entries get theirs
static_assert(with_units({0x607D, 0}).info.unit.empty());
static_assert(with_units({0x607D, 1}).info.unit == "inc");
// 5003h: only the current subs 0Ch and 13h
static_assert(with_units({0x5003, 0x0C}).info.unit == "mA");
} // namespace

TEST_CASE("xenax::canopen_units: 6073h in mA through od's value path") {
  std::array<char, 64> text{};
  const std::array<std::uint8_t, 2> raw150{0x96, 0x00};
  const od::unit_descriptor d = with_units(limit);
  auto n = od::format_value(d, raw150, text);
  REQUIRE(n);
  CHECK(std::string_view(text.data(), n.value()) == "1500 mA");
  // a rule with a scale for an entry that cannot take it
  od::descriptor s{};
  s.index = 0x6073;
  s.type = od::data_type::real32;
  CHECK(od::with_unit(s, fieldcodec::xenax::canopen_units).error() == errc::invalid_argument);
  // the dictionary's own unit wins
  od::descriptor own = xcan::dictionary.at({0x6073, 0}).value();
  own.info.unit = "A";
  CHECK(od::with_unit(own, fieldcodec::xenax::canopen_units).value().info.unit == "A");
  // every rule names an object of one of the XENAX dictionaries
  for (const od::unit_rule &r : fieldcodec::xenax::canopen_units) {
    CAPTURE(r.index);
    CHECK(xcan::dictionary.object(r.index).size() +
              fieldcodec::dictionaries::xenax_ethercat::dictionary.object(r.index).size() +
              fieldcodec::dictionaries::xenax_powerlink::dictionary.object(r.index).size() >
          0U);
  }
}
