// A node over the generated XENAX CAN dictionary: capacity counted from it, the PDOs it
// declares, and a capacity that is too small.
#include "node_test_util.hpp"

#include <fieldcodec/dictionaries/xenax_canopen.hpp>

using namespace test_node;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;

namespace {
constexpr auto xlayout = co::make_layout<xcan::dictionary.size()>(xcan::dictionary);
constexpr node::capacity xcaps = node::capacity_for(xcan::dictionary);
// XENAX CAN bus manual 9.1: RPDO/TPDO 1, 2 and 17..24; 1016h, 1003h and extra SDO channels are
// not in the dictionary
static_assert(xcaps.rpdos == 10 && xcaps.tpdos == 10);
static_assert(xcaps.heartbeat_consumers == 0 && xcaps.error_history == 0);
static_assert(xcaps.sdo_servers == 1 && xcaps.sdo_clients == 0);
} // namespace

TEST_CASE("device over the XENAX dictionary: PDOs 1 and 2 valid, 17..24 disabled") {
  std::vector<std::uint8_t> storage(xlayout.storage_size());
  store_type store{xcan::dictionary, xlayout, storage};
  REQUIRE(store.init_defaults(1).has_value());
  node::device<store_type, xcaps> dev(store, 1);
  REQUIRE(dev.start(0));
  CHECK(dev.configuration().has_value());
  const auto &p = dev.pdo();
  REQUIRE(p.rpdo_count() == 10);
  CHECK(p.rpdo(0).valid());
  CHECK(p.rpdo(0).id() == 0x201);
  CHECK(p.rpdo(1).id() == 0x301);
  CHECK(p.rpdo(1).bytes == 6); // controlword + target position
  CHECK(p.rpdo(2).number == 17);
  CHECK_FALSE(p.rpdo(2).valid());
  CHECK(p.tpdo(1).entries().size() == 2);
  // 1017h is read-only on the XENAX: no heartbeat can be configured
  const auto ch = sdo::channel::default_for(1).value();
  const std::array<std::uint8_t, 2> period{100, 0};
  auto s = dev.on_frame(ch.request(sdo::expedited_download({0x1017, 0}, period).value()), 1);
  REQUIRE(s.send.size() == 1);
  CHECK(sdo::decode(s.send[0].data, sdo::direction::to_client).value().abort ==
        abort_code::write_read_only);
  // 1003h is not there: errors still go out as EMCY (1014h: 0x80 + node)
  auto e = dev.raise(0xFF32, 2); // XENAX error 50: following error
  REQUIRE(e);
  CHECK(e.value().send[0] == F(0x81, {0x32, 0xFF, 0x01, 0, 0, 0, 0, 0}));
}

TEST_CASE("device over the XENAX dictionary with room for 4 + 4 PDOs: served as far as it fits") {
  std::vector<std::uint8_t> storage(xlayout.storage_size());
  store_type store{xcan::dictionary, xlayout, storage};
  REQUIRE(store.init_defaults(1).has_value());
  node::device<store_type, node::capacity{.rpdos = 4, .tpdos = 4}> dev(store, 1);
  REQUIRE(dev.start(0));
  CHECK(dev.configuration() == errc::too_long);
  CHECK(dev.pdo().rpdo_count() == 4);
  // RPDO 1 works
  (void)dev.on_frame(F(0, {0x01, 1}), 0);
  (void)dev.on_frame(F(0x201, {0x06, 0x00}), 1);
  CHECK(dev.value({0x6040, 0}).value()[0] == 0x06);
}
