// Each node service owns its communication objects (docs/canopen.md, "Services and their
// objects"): check_write refuses what CiA 301 refuses for its objects and nothing for others'
// objects, written follows a stored value, load reads them all from a store. Here without
// node::device, one service at a time, over the test dictionary's store (the device's own
// tests run the same through SDO writes).
#include "node_test_util.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

using namespace test_node;

namespace {

/// A store of the test dictionary (node 5) with its power-on values.
struct store_rig {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(layout5.storage_size());
  store_type store{dict5, layout5, storage};
  store_rig() { REQUIRE(store.init_defaults(5).has_value()); }
  void put(std::uint16_t index, std::uint8_t sub, std::uint32_t v, std::size_t width) {
    REQUIRE(store.set({index, sub}, node::encode_le(v, width).span()) == abort_code::none);
  }
  [[nodiscard]] std::uint32_t get(std::uint16_t index, std::uint8_t sub) const {
    return node::read_u32(store, {index, sub}).value();
  }
};

co::can_frame sync_frame(std::initializer_list<std::uint8_t> b) { return F(0x80, b); }

} // namespace

TEST_CASE("sync_consumer owns 1005h, 1007h and 1019h") {
  node::sync_consumer s;
  // 1005h: bit 30 (this node produces no SYNC), bit 29 and bits 11..28 are refused
  CHECK(s.check_write({0x1005, 0}, 0x4000'0080U) == abort_code::invalid_value);
  CHECK(s.check_write({0x1005, 0}, 0x2000'0080U) == abort_code::invalid_value);
  CHECK(s.check_write({0x1005, 0}, 0x0000'0880U) == abort_code::invalid_value);
  CHECK(s.check_write({0x1005, 0}, 0x8000'0081U) == abort_code::none);
  // 1019h: 0 or 2..240
  CHECK(s.check_write({0x1019, 0}, 1) == abort_code::invalid_value);
  CHECK(s.check_write({0x1019, 0}, 241) == abort_code::invalid_value);
  CHECK(s.check_write({0x1019, 0}, 240) == abort_code::none);
  CHECK(s.check_write({0x1019, 0}, 0) == abort_code::none);
  // not its objects
  CHECK(s.check_write({0x1014, 0}, 0x4000'0080U) == abort_code::none);
  CHECK(s.check_write({0x1017, 0}, 0xFFFF'FFFFU) == abort_code::none);

  s.written({0x1005, 0}, 0x81, 0);
  CHECK(s.cob_id() == 0x81);
  s.written({0x1007, 0}, 1500, 0); // 1.5 ms: a window of 2 ms
  REQUIRE(s.on_frame(F(0x81, {}), 10).state.received);
  CHECK(s.inside_window(11));
  CHECK_FALSE(s.inside_window(12));
  s.written({0x1019, 0}, 8, 0); // a counter is expected from now on
  CHECK_FALSE(s.on_frame(F(0x81, {}), 13).state.received);
  CHECK(s.length_error());

  store_rig r;
  r.put(0x1005, 0, 0x90, 4);
  r.put(0x1019, 0, 8, 1);
  REQUIRE(s.load(r.store, 20).has_value());
  CHECK(s.cob_id() == 0x90);
  CHECK_FALSE(s.length_error());                           // a fresh start
  CHECK_FALSE(s.on_frame(F(0x90, {}), 21).state.received); // 1019h = 8: DLC 1
  CHECK(s.on_frame(F(0x90, {3}), 22).state.counter == std::optional<std::uint8_t>(3));
  CHECK_FALSE(s.on_frame(sync_frame({}), 23).state.received); // 0x80 is not the SYNC now
}

TEST_CASE("emcy_producer owns 1003h, 1014h and 1015h, and writes 1001h and 1003h itself") {
  node::emcy_producer<8, 4, 4> e(5);
  CHECK(e.check_write({0x1003, 0}, 1) == abort_code::invalid_value);
  CHECK(e.check_write({0x1003, 0}, 0) == abort_code::none);
  CHECK(e.check_write({0x1003, 1}, 7) == abort_code::none); // read-only: the store refuses
  CHECK(e.check_write({0x1014, 0}, 0x4000'0085U) == abort_code::invalid_value); // reserved
  CHECK(e.check_write({0x1014, 0}, 0x0000'0086U) == abort_code::invalid_value); // valid → valid
  CHECK(e.check_write({0x1014, 0}, 0x8000'0086U) == abort_code::none);
  CHECK(e.check_write({0x1005, 0}, 0x4000'0080U) == abort_code::none); // not its object

  store_rig r;
  r.put(0x1015, 0, 20, 2); // 2 ms
  REQUIRE(e.load(r.store, 0).has_value());
  REQUIRE(e.raise_error(0x2310, 100).has_value());
  REQUIRE(e.sent().size() == 1U);
  CHECK(e.sent()[0].id == 0x85);
  REQUIRE(e.raise_error(0x3210, 101).has_value());
  CHECK(e.sent().empty()); // within the inhibit time
  e.publish(r.store);
  CHECK(r.get(0x1001, 0) == 0x07U); // generic, current, voltage
  CHECK(r.get(0x1003, 0) == 2U);
  CHECK(r.get(0x1003, 1) == 0x3210U); // newest first
  CHECK(r.get(0x1003, 2) == 0x2310U);
  CHECK(r.get(0x1003, 3) == 0U);

  e.written({0x1003, 0}, 0, 102); // the history emptied
  e.publish(r.store);
  CHECK(r.get(0x1003, 0) == 0U);
  CHECK(r.get(0x1003, 1) == 0U);
  CHECK(r.get(0x1001, 0) == 0x07U); // the errors are still active

  REQUIRE(e.poll(110).send.size() == 1U);    // the message the inhibit time held back
  e.written({0x1014, 0}, 0x8000'0085U, 110); // EMCY off: errors are kept, nothing is sent
  REQUIRE(e.raise_error(0x4210, 200).has_value());
  CHECK(e.sent().empty());
  e.written({0x1014, 0}, 0x0000'0095U, 300);
  REQUIRE(e.raise_error(0x5000, 400).has_value());
  REQUIRE(e.sent().size() == 1U);
  CHECK(e.sent()[0].id == 0x95);

  // load starts afresh: no errors, empty history, the stored COB-ID
  r.put(0x1014, 0, 0x0000'00A5U, 4);
  REQUIRE(e.load(r.store, 500).has_value());
  CHECK(e.active().empty());
  CHECK(e.history().empty());
  e.publish(r.store);
  CHECK(r.get(0x1001, 0) == 0U);
  REQUIRE(e.raise_error(0x6000, 600).has_value());
  REQUIRE(e.sent().size() == 1U);
  CHECK(e.sent()[0].id == 0xA5);
}

TEST_CASE("heartbeat_consumer owns 1016h") {
  node::heartbeat_consumer<3> c;
  CHECK(c.check_write({0x1016, 1}, 0x0003'01F4U) == abort_code::none);
  c.written({0x1016, 1}, 0x0003'01F4U, 0);
  CHECK(c.entry(0) == node::consumer_entry{3, 500});
  CHECK(c.state(0) == node::monitor_state::waiting);
  CHECK(c.check_write({0x1016, 2}, 0x0003'0100U) == abort_code::parameter_incompatible);
  CHECK(c.check_write({0x1016, 1}, 0x0100'01F4U) == abort_code::invalid_value); // reserved
  CHECK(c.check_write({0x1016, 1}, 0x0080'01F4U) == abort_code::invalid_value); // node 128
  CHECK(c.check_write({0x1016, 4}, 0x0004'0100U) == abort_code::device_incompatible);
  CHECK(c.check_write({0x1016, 4}, 0) == abort_code::none);
  CHECK(c.check_write({0x1016, 0}, 9) == abort_code::none); // sub 0: the store decides
  CHECK(c.check_write({0x1017, 0}, 0x0003'0100U) == abort_code::none);

  store_rig r;
  r.put(0x1016, 2, 0x0007'0064U, 4);
  REQUIRE(c.load(r.store, 0).has_value());
  CHECK(c.entry(0) == node::consumer_entry{}); // sub 1 is 0 in the store
  CHECK(c.entry(1) == node::consumer_entry{7, 100});
  CHECK(c.state(1) == node::monitor_state::waiting);

  // more entries than monitors: too_long, the first are served
  node::heartbeat_consumer<1> small;
  CHECK(small.load(r.store, 0) == errc::too_long);
  CHECK(small.entry(0) == node::consumer_entry{});
}

TEST_CASE("heartbeat_producer owns 1017h, life_guard 100Ch and 100Dh") {
  node::heartbeat_producer p(5);
  CHECK(p.check_write({0x1017, 0}, 0xFFFF) == abort_code::none);
  p.written({0x1017, 0}, 100, 5);
  CHECK(p.period() == 100U);
  CHECK(p.deadline() == std::optional<std::uint32_t>(105));
  p.written({0x1016, 1}, 7, 5); // not its object
  CHECK(p.period() == 100U);

  node::life_guard g;
  g.written({0x100C, 0}, 200, 0);
  CHECK(g.life_time_ms() == 0U); // factor 0: off
  CHECK(g.state() == node::guard_state::off);
  g.written({0x100D, 0}, 3, 0);
  CHECK(g.life_time_ms() == 600U);
  CHECK(g.state() == node::guard_state::waiting);
  g.written({0x100C, 0}, 100, 0); // the factor stays
  CHECK(g.life_time_ms() == 300U);

  store_rig r;
  r.put(0x1017, 0, 50, 2);
  r.put(0x100C, 0, 10, 2);
  r.put(0x100D, 0, 2, 1);
  REQUIRE(p.load(r.store, 1000).has_value());
  CHECK(p.deadline() == std::optional<std::uint32_t>(1050));
  REQUIRE(g.load(r.store, 1000).has_value());
  CHECK(g.life_time_ms() == 20U);
}

// A default PDO configuration is an unloaded PDO: never valid (its members start as zeros).
static_assert(!node::pdo_config<8>{}.valid());
static_assert(!node::pdo_config<8>{}.usable);
