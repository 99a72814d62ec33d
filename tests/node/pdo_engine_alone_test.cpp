// The PDO engine alone, over a plain store (no device): what a firmware that assembles its own
// node does.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/pdo_engine.hpp>

using namespace test_node;

TEST_CASE("pdo engine alone: reload, parameter rules, RPDO in, TPDO out") {
  std::vector<std::uint8_t> storage(layout5.storage_size());
  store_type store{dict5, layout5, storage};
  REQUIRE(store.init_defaults(5).has_value());
  node::pdo_engine<store_type, 2, 2, 4> pdo(store, dict5);
  REQUIRE(pdo.reload().has_value());
  CHECK(pdo.rpdo_count() == 2);
  CHECK(pdo.tpdo(0).id() == 0x185);
  // pre-operational: nothing is exchanged
  CHECK(pdo.on_frame(F(0x205, {1, 0, 0, 0, 2, 0}), 0).send.empty());
  CHECK(pdo.events().empty());
  CHECK_FALSE(pdo.deadline(0));
  CHECK(pdo.poll(0).state == node::pdo_state::not_operational);
  CHECK(to_string(pdo.poll(0).state) == "PDOs not exchanged");
  pdo.set_operational(true, 0);
  // the event-driven TPDO 1 is due at once
  auto s = pdo.poll(0);
  CHECK(s.state == node::pdo_state::operational);
  REQUIRE(s.send.size() == 1);
  CHECK(s.send[0] == F(0x185, {0, 0, 0, 0, 0, 0}));
  // an RPDO is written into the store
  (void)pdo.on_frame(F(0x205, {1, 0, 0, 0, 2, 0}), 1);
  CHECK(store.value({0x2000, 0}).value()[0] == 1);
  REQUIRE(pdo.events().size() == 1);
  CHECK(pdo.events()[0].what == node::pdo_event::kind::received);
  // a mapped object changes: the caller marks it
  const std::array<std::uint8_t, 4> v{9, 0, 0, 0};
  CHECK(store.set({0x2100, 0}, v) == abort_code::none);
  pdo.mark({0x2100, 0});
  CHECK(pdo.deadline(2) == 2U);
  s = pdo.poll(2);
  REQUIRE(s.send.size() == 1);
  CHECK(s.send[0].data[0] == 9);
  // the parameter rules, around a write the caller makes
  const std::array<std::uint8_t, 1> zero{0};
  CHECK(pdo.check_write({0x1A00, 0}, zero) == abort_code::parameter_incompatible);
  const std::array<std::uint8_t, 4> off{0x85, 0x01, 0, 0x80};
  CHECK(pdo.check_write({0x1800, 1}, off) == abort_code::none);
  REQUIRE(store.write({0x1800, 1}, 0, off, true) == abort_code::none);
  pdo.written({0x1800, 1}, off, 3);
  CHECK_FALSE(pdo.tpdo(0).valid());
  CHECK(pdo.check_write({0x1A00, 0}, zero) == abort_code::none);
  // objects outside 1400h-1BFFh are not the engine's
  CHECK(pdo.check_write({0x2000, 0}, zero) == abort_code::none);
  // a SYNC: the synchronous TPDO 2 (type 1) goes out
  s = pdo.on_sync(std::nullopt, 4);
  REQUIRE(s.send.size() == 1);
  CHECK(s.send[0].id == 0x285);
}

TEST_CASE("pdo engine alone: a stored configuration it cannot serve") {
  std::vector<std::uint8_t> storage(layout5.storage_size());
  store_type store{dict5, layout5, storage};
  REQUIRE(store.init_defaults(5).has_value());
  // a mapping naming an object that is not mappable, written past the rules
  const std::array<std::uint8_t, 4> bad{0x20, 0x00, 0x08, 0x20}; // 2008h, 32 bits
  REQUIRE(store.set({0x1A00, 1}, bad) == abort_code::none);
  node::pdo_engine<store_type, 2, 2, 4> pdo(store, dict5);
  CHECK(pdo.reload() == errc::bad_length);
  CHECK_FALSE(pdo.tpdo(0).usable);
  CHECK_FALSE(pdo.tpdo(0).valid());
  pdo.set_operational(true, 0);
  CHECK(pdo.poll(0).send.empty());
  // more PDOs in the dictionary than the engine holds: the first are served
  node::pdo_engine<store_type, 1, 1, 4> small(store, dict5);
  CHECK(small.reload() == errc::too_long);
  CHECK(small.rpdo_count() == 1);
}
