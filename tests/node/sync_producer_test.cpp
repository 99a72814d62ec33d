// The SYNC producer (1005h bit 30, 1006h, 1019h; CiA 301): alone and in the device, where the
// node's own SYNC drives its synchronous PDOs.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/sync_producer.hpp>

using namespace test_node;
using co::nmt::state;

static_assert(caps.sync_producer); // the test dictionary has 1006h

TEST_CASE("sync producer alone: period, counter, late polls, COB-ID") {
  node::sync_producer p;
  CHECK_FALSE(p.active());
  CHECK(p.poll(1000) == std::nullopt);
  p.written({0x1006, 0}, 10'000, 0); // 10 ms, not generating yet
  CHECK_FALSE(p.active());
  CHECK(p.deadline() == std::nullopt);
  p.written({0x1005, 0}, 0x4000'0080U, 0);
  REQUIRE(p.active());
  CHECK(p.deadline() == 10U);
  CHECK(p.poll(9) == std::nullopt);
  CHECK(p.poll(10) == F(0x80, {}));
  CHECK(p.deadline() == 20U);
  CHECK(p.poll(23) == F(0x80, {})); // 3 ms late: the cycle stays (next at 30)
  CHECK(p.deadline() == 30U);
  CHECK(p.poll(55) == F(0x80, {})); // more than a period late: one SYNC, then from now
  CHECK(p.deadline() == 65U);
  // the same value again changes nothing; a new one starts afresh
  p.written({0x1005, 0}, 0x4000'0080U, 60);
  CHECK(p.deadline() == 65U);
  p.written({0x1005, 0}, 0x4000'0081U, 60);
  CHECK(p.deadline() == 70U);
  CHECK(p.poll(70) == F(0x81, {}));
  // a counter 1..3
  p.written({0x1019, 0}, 3, 70);
  std::vector<std::uint8_t> counters;
  for (std::uint32_t t = 80; t <= 120; t += 10) counters.push_back(p.poll(t).value().data[0]);
  CHECK(counters == std::vector<std::uint8_t>{1, 2, 3, 1, 2});
  p.restart_counter();
  CHECK(p.poll(130).value().data[0] == 1);
  // 1006h in µs, rounded up to the ms clock; 0 stops it
  p.written({0x1006, 0}, 1500, 130);
  CHECK(p.period_ms() == 2);
  p.written({0x1006, 0}, 0, 130);
  CHECK_FALSE(p.active());
  CHECK(p.poll(1000) == std::nullopt);
}

TEST_CASE("device: 1005h bit 30 makes the node the SYNC producer") {
  rig<> r;
  (void)r.start();
  // 1005h with bit 30 is taken and reads back; the same value again too
  CHECK(r.sdo_write(0x1005, 0, 0x4000'0080U, 4) == abort_code::none);
  CHECK(r.read_u(0x1005, 0) == 0x4000'0080U);
  CHECK(r.sdo_write(0x1005, 0, 0x4000'0080U, 4) == abort_code::none);
  // another identifier while it stays generating: refused
  CHECK(r.sdo_write(0x1005, 0, 0x4000'0081U, 4) == abort_code::invalid_value);
  CHECK(r.tick(1000).empty()); // 1006h = 0: nothing
  CHECK(r.sdo_write(0x1006, 0, 10'000, 4) == abort_code::none);
  CHECK(r.deadline == r.now + 10);
  CHECK(r.tick(9).empty());
  CHECK(on(r.tick(1), 0x80) == std::vector{F(0x80, {})}); // pre-operational: SYNC is allowed
  REQUIRE(!r.dev.events().empty());
  CHECK(r.dev.events()[0].what == node::event::kind::sync);
  // 1019h only with 1006h = 0; then SYNCs with a counter
  CHECK(r.sdo_write(0x1019, 0, 2, 1) == abort_code::cannot_store_device_state);
  CHECK(r.sdo_write(0x1006, 0, 0, 4) == abort_code::none);
  CHECK(r.tick(100).empty());
  CHECK(r.sdo_write(0x1019, 0, 2, 1) == abort_code::none);
  CHECK(r.sdo_write(0x1006, 0, 5'000, 4) == abort_code::none);
  std::vector<co::can_frame> syncs;
  for (int i = 0; i < 3; ++i) {
    for (const auto &f : on(r.tick(5), 0x80)) syncs.push_back(f);
  }
  CHECK(syncs == std::vector{F(0x80, {1}), F(0x80, {2}), F(0x80, {1})});
  // the node's own SYNC drives its synchronous TPDO (2: every SYNC) in operational, after it
  CHECK(r.set_u(0x6041, 0, 0x0237, 2) == abort_code::none);
  (void)r.feed(F(0, {0x01, 5})); // operational: the counter restarts at 1
  (void)r.tick();
  const auto out = r.tick(5);
  REQUIRE(out.size() >= 2);
  CHECK(on(out, 0x80) == std::vector{F(0x80, {1})});
  CHECK(on(out, 0x285) == std::vector{F(0x285, {0x37, 0x02})});
  std::size_t sync_at = 0;
  std::size_t tpdo_at = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out[i].id == 0x80) sync_at = i;
    if (out[i].id == 0x285) tpdo_at = i;
  }
  CHECK(sync_at < tpdo_at);
  // stopped: no SYNC
  (void)r.feed(F(0, {0x02, 5}));
  CHECK(on(r.tick(50), 0x80).empty());
  // bit 30 cleared: the identifier may change, and nothing is produced
  (void)r.feed(F(0, {0x80, 5}));
  CHECK(r.sdo_write(0x1005, 0, 0x0000'0081U, 4) == abort_code::none);
  CHECK(on(r.tick(50), 0x80).empty());
  // reset communication: back to the defaults (1005h 80h, consumer)
  (void)r.feed(F(0, {0x82, 5}));
  CHECK(r.read_u(0x1005, 0) == 0x80);
  CHECK(on(r.tick(50), 0x80).empty());
}

TEST_CASE("sync consumer without a producer refuses bit 30") {
  node::sync_consumer s;
  CHECK(s.check_write({0x1005, 0}, 0x4000'0080U) == abort_code::invalid_value);
  s.allow_producer(true);
  CHECK(s.check_write({0x1005, 0}, 0x4000'0080U) == abort_code::none);
  static_assert(!node::capacity{}.sync_producer);
}
