// Regression tests for inputs found by the node and master fuzz harnesses
// (fuzz/fuzz_node_device.cpp, fuzz/fuzz_master.cpp; see fuzz/FINDINGS.md).
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace canopen = fieldcodec::canopen;
namespace od = fieldcodec::od;

// F25 (fuzz_node_device, XENAX CAN dictionary): 5002h:01 (CO Clear Output Number, write-only,
// limits 1..8, no default) was filled with 0 by init_defaults: the store held a value its own
// checks refuse, which value() handed to the application (and a TPDO could map).
namespace {
constexpr od::entry_spec f25_specs[] = {
    {.index = 0x2000,
     .type = od::data_type::unsigned8,
     .access_type = od::access::wo,
     .low = od::unsigned_number(1),
     .high = od::unsigned_number(8)},
    {.index = 0x2001,
     .type = od::data_type::integer16,
     .access_type = od::access::rw,
     .low = od::signed_number(-10),
     .high = od::signed_number(-5)},
    {.index = 0x2002,
     .type = od::data_type::integer16,
     .access_type = od::access::rw,
     .low = od::signed_number(-10),
     .high = od::signed_number(10)},
    {.index = 0x2003,
     .type = od::data_type::unsigned8,
     .access_type = od::access::rw,
     .low = od::unsigned_number(1),
     .high = od::unsigned_number(8),
     .default_value = od::unsigned_number(20)}, // a default outside the limits
    {.index = 0x2004,
     .type = od::data_type::unsigned8,
     .access_type = od::access::rw,
     .low = od::unsigned_number(1),
     .high = od::unsigned_number(8),
     .default_value = od::unsigned_number(3)},
};
constexpr auto f25_entries = od::entries_of<f25_specs>;
} // namespace

TEST_CASE("fuzz F25: a value without a valid default starts within its limits") {
  static constexpr auto &entries = f25_entries;
  static constexpr od::dictionary dict{entries};
  static_assert(dict.is_valid());
  constexpr auto layout = canopen::make_layout<entries.size()>(dict);
  std::vector<std::uint8_t> storage(layout.storage_size(), 0xEE);
  canopen::dictionary_store<> s{dict, layout, storage};
  REQUIRE(s.init_defaults(5) == fieldcodec::status{});
  CHECK(s.value({0x2000, 0}).value()[0] == 1);     // the low limit, nearest to zero
  const auto v2001 = s.value({0x2001, 0}).value(); // the high limit, nearest to zero
  CHECK(static_cast<std::int16_t>(v2001[0] | v2001[1] << 8U) == -5);
  CHECK(s.value({0x2002, 0}).value()[0] == 0); // zero is allowed: zero
  CHECK(s.value({0x2002, 0}).value()[1] == 0);
  CHECK(s.value({0x2003, 0}).value()[0] == 1); // the refused default: as without one
  CHECK(s.value({0x2004, 0}).value()[0] == 3); // a valid default as before
  for (const od::entry &e : entries) {
    CHECK(od::decode(e, s.value({e.index, e.sub}).value()).has_value());
  }
}
