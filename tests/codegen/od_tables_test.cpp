// gen::od_tables: a dictionary read at run time as od tables — lookups, names, capacities and
// vendor units as the CLI (and a host remote node) use them.
#include "od_tables.hpp"
#include "readers.hpp"

#include <fieldcodec/od/value_text.hpp>
#include <fieldcodec/xenax/canopen_units.hpp>

#include <doctest/doctest.h>

#include <array>
#include <string>
#include <string_view>
#include <utility>

namespace gen = fieldcodec::gen;
namespace od = fieldcodec::od;
using fieldcodec::errc;

namespace {
gen::dictionary xenax() {
  gen::diagnostics diag;
  auto d = gen::read_file("../dictionaries/xenax_canopen.eds", diag);
  REQUIRE(d.has_value());
  return *d;
}
} // namespace

TEST_CASE("od_tables: entries, names and lookups of a dictionary read at run time") {
  const gen::dictionary d = xenax();
  const gen::od_tables t(d);
  CHECK(t.view().is_valid());
  CHECK(t.view().size() >= d.entries.size());
  CHECK(t.display_name({0x1018, 1}) == "Identity Object: Vendor Id");
  CHECK(t.display_name({0x6073, 0}) == "Limit I_Force");
  CHECK(t.display_name({0x2999, 0}).empty());
  CHECK(t.address_of("Identity Object", "Vendor Id").value() == od::address{0x1018, 1});
  CHECK(t.address_of("Limit I_Force").value() == od::address{0x6073, 0});
  CHECK(t.address_of("Identity Object").error() == errc::unknown_object);
  CHECK(t.address_of("limit i_force").error() == errc::unknown_object);
  // a capacity only where the file declares one (5011h Size=30), not from a default's length
  CHECK(t.at({0x5011, 0}).value().capacity() == 30U);
  CHECK(t.at({0x1008, 0}).value().capacity() == 0U);
  const gen::od_tables firmware(d, {.capacity_from_default = true});
  CHECK(firmware.at({0x1008, 0}).value().capacity() == 30U);
}

TEST_CASE("od_tables: vendor units make 6073h a scaled entry in mA") {
  const gen::dictionary d = xenax();
  gen::od_tables t(d, {.units = fieldcodec::xenax::canopen_units});
  CHECK(t.unit_failures().empty());
  const od::descriptor limit = t.at({0x6073, 0}).value();
  CHECK(od::is_scaled(limit));
  CHECK(limit.info.unit == "mA");
  std::array<std::uint8_t, 2> out{};
  CHECK(od::parse_value(limit, "1500 mA", out).value() == 2U);
  CHECK(out == std::array<std::uint8_t, 2>{0x96, 0x00});
  // the tables stay valid when moved (the infos point into their own storage)
  gen::od_tables moved = std::move(t);
  CHECK(moved.at({0x6073, 0}).value().info.unit == "mA");
  // its limits are packed anew in engineering units (HighLimit 0x7D0 raw = 20000 mA)
  CHECK(moved.at({0x6073, 0}).value().high() == od::decimal_number(20000, 0));
  CHECK(moved.display_name({0x1018, 1}) == "Identity Object: Vendor Id");
}
