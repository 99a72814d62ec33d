// Heartbeat producer (1017h), consumer (1016h) and life guarding (100Ch/100Dh), alone and in
// the device.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/heartbeat.hpp>

using namespace test_node;
using co::nmt::state;
using hb_kind = node::heartbeat_event::kind;

namespace {
constexpr bool producer_walk() {
  node::heartbeat_producer p(3);
  if (!p.poll(1000, state::operational).send.empty()) return false; // off
  p.configure(100, 0);
  if (!p.poll(99, state::operational).send.empty()) return false;
  auto s = p.poll(100, state::operational);
  if (s.send.size() != 1 || s.send[0] != co::make_frame(0x703, {0x05}).value()) return false;
  if (s.deadline != 200U) return false;
  // late by more than a period: one heartbeat, the next a period after now
  s = p.poll(450, state::stopped);
  return s.send.size() == 1 && s.send[0].data[0] == 0x04 && s.deadline == 550U;
}
static_assert(producer_walk());

static_assert(node::decode_consumer_entry(0x0003'01F4).value() == node::consumer_entry{3, 500});
static_assert(node::decode_consumer_entry(0x0100'0000) == errc::invalid_argument);
static_assert(node::decode_consumer_entry(0x0080'0001) == errc::invalid_argument); // node 128
static_assert(!node::decode_consumer_entry(0x0000'01F4).value().active());
} // namespace

TEST_CASE("heartbeat producer: wrap-around of the millisecond counter") {
  node::heartbeat_producer p(1);
  p.configure(50, 0xFFFF'FFF0U);
  CHECK(p.deadline() == 0x22U); // 0xFFFFFFF0 + 50, modulo 2^32
  CHECK(p.poll(0xFFFF'FFFFU, state::operational).send.empty());
  CHECK(p.poll(0x21U, state::operational).send.empty());
  CHECK(p.poll(0x22U, state::operational).send.size() == 1);
  CHECK(p.deadline() == 0x54U);
}

TEST_CASE("heartbeat consumer: start, state change, boot-up, loss, resume") {
  node::heartbeat_consumer<2> c;
  CHECK(c.configure(0, 0x0003'0064, 0) == abort_code::none); // node 3, 100 ms
  CHECK(c.configure(1, 0x0004'00C8, 0) == abort_code::none); // node 4, 200 ms
  CHECK(c.state(0) == node::monitor_state::waiting);
  // no heartbeat yet: no timeout, no deadline
  CHECK(c.poll(10'000).state == node::consumer_summary{0, 0});
  CHECK(c.events().empty());
  CHECK_FALSE(c.deadline(10'000));

  auto s = c.on_frame(F(0x703, {0x7F}), 10'000);
  REQUIRE(c.events().size() == 1);
  CHECK(c.events()[0] == node::heartbeat_event{hb_kind::started, 0, 3, state::pre_operational});
  CHECK(s.state.active == 1);
  CHECK(s.deadline == 10'100U);
  (void)c.on_frame(F(0x703, {0x7F}), 10'050);
  CHECK(c.events().empty());
  (void)c.on_frame(F(0x703, {0x05}), 10'100);
  REQUIRE(c.events().size() == 1);
  CHECK(c.events()[0].what == hb_kind::state_changed);
  CHECK(c.events()[0].s == state::operational);
  // not yet lost at 10'199, lost at 10'200 (100 ms after the last heartbeat)
  CHECK(c.poll(10'199).state.lost == 0);
  s = c.poll(10'200);
  REQUIRE(c.events().size() == 1);
  CHECK(c.events()[0] == node::heartbeat_event{hb_kind::lost, 0, 3, state::operational});
  CHECK(s.state == node::consumer_summary{0, 1});
  CHECK(c.any_lost());
  (void)c.poll(20'000); // one event per loss
  CHECK(c.events().empty());
  (void)c.on_frame(F(0x703, {0x05}), 20'000);
  REQUIRE(c.events().size() == 1);
  CHECK(c.events()[0].what == hb_kind::resumed);
  CHECK_FALSE(c.any_lost());
  // boot-up: the node was reset, the monitor waits for its first heartbeat again
  (void)c.on_frame(F(0x703, {0x00}), 20'010);
  REQUIRE(c.events().size() == 1);
  CHECK(c.events()[0].what == hb_kind::boot_up);
  CHECK(c.state(0) == node::monitor_state::waiting);
  (void)c.poll(30'000);
  CHECK(c.events().empty());
}

TEST_CASE("heartbeat consumer: bad frames and entries") {
  node::heartbeat_consumer<2> c;
  CHECK(c.configure(0, 0x0003'0064, 0) == abort_code::none);
  // CiA 301 7.5.2.17: a second active entry for the same node is refused with 0x06040043
  CHECK(c.check(1, 0x0003'0032) == abort_code::parameter_incompatible);
  CHECK(c.configure(1, 0x0003'0032, 0) == abort_code::parameter_incompatible);
  CHECK(c.entry(1) == node::consumer_entry{});
  CHECK(c.check(1, 0x0003'0000) == abort_code::none);          // time 0: off, no conflict
  CHECK(c.check(0, 0x0003'0032) == abort_code::none);          // the same entry may change its time
  CHECK(c.check(1, 0x0100'0001) == abort_code::invalid_value); // reserved bits
  CHECK(c.check(1, 0x0080'0001) == abort_code::invalid_value); // node 128
  CHECK(c.check(2, 0x0005'0001) == abort_code::no_sub_index);
  // frames that are not heartbeats of node 3
  (void)c.on_frame(F(0x703, {0x05, 0x00}), 0); // DLC 2
  CHECK(c.error() == errc::bad_length);
  (void)c.on_frame(F(0x703, {0x85}), 0); // guarding response (toggle bit)
  CHECK(c.error() == errc::out_of_range);
  (void)c.on_frame(F(0x703, {0x06}), 0); // undefined state
  CHECK(c.error() == errc::out_of_range);
  (void)c.on_frame(R(0x703, 1), 0);      // guarding request
  (void)c.on_frame(F(0x704, {0x05}), 0); // a node nobody watches
  CHECK(c.events().empty());
  CHECK(c.state(0) == node::monitor_state::waiting);
  // disabled (stopped): heartbeats are not taken
  c.enable(false);
  (void)c.on_frame(F(0x703, {0x05}), 0);
  CHECK(c.state(0) == node::monitor_state::waiting);
}

TEST_CASE("life guarding: starts with the first request, lost after the life time") {
  node::life_guard g;
  CHECK(g.state() == node::guard_state::off);
  g.configure(100, 3); // life time 300 ms
  CHECK(g.state() == node::guard_state::waiting);
  CHECK(g.poll(10'000).state == node::guard_state::waiting); // never guarded: no event
  CHECK(g.on_request(10'000).deadline == 10'300U);
  CHECK(g.poll(10'299).state == node::guard_state::active);
  CHECK(g.poll(10'300).state == node::guard_state::lost);
  CHECK(g.on_request(10'400).state == node::guard_state::active);
  g.configure(100, 0);
  CHECK(g.state() == node::guard_state::off);
}

TEST_CASE("device: heartbeat producer follows 1017h") {
  rig<> r;
  (void)r.start();
  CHECK(r.tick(5000).empty());
  CHECK(r.sdo_write(0x1017, 0, 200, 2) == abort_code::none);
  CHECK(r.dev.poll(r.now).deadline == r.now + 200);
  CHECK(r.tick(199).empty());
  CHECK(r.tick(1) == std::vector{F(0x705, {0x7F})});
  (void)r.feed(F(0, {0x02, 5}));
  CHECK(r.tick(200) == std::vector{F(0x705, {0x04})});  // stopped: heartbeat goes on
  const auto ch = sdo::channel::default_for(5).value(); // no SDO in stopped
  CHECK(r.feed(ch.request(
                   sdo::expedited_download({0x1017, 0}, std::array<std::uint8_t, 2>{}).value()))
            .empty());
  CHECK(r.read_u(0x1017, 0) == 200);
}

TEST_CASE("device: heartbeat consumer, EMCY 8130h while a node is lost") {
  rig<> r;
  (void)r.start();
  CHECK(r.sdo_write(0x1016, 1, 0x0003'0064, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1016, 2, 0x0003'0050, 4) == abort_code::parameter_incompatible);
  CHECK(r.sdo_write(0x1016, 2, 0x0103'0050, 4) == abort_code::invalid_value);
  CHECK(r.read_u(0x1016, 2) == 0);
  (void)r.feed(F(0x703, {0x7F}));
  REQUIRE(r.dev.events().size() == 1);
  CHECK(r.dev.events()[0].what == node::event::kind::heartbeat);
  CHECK(r.dev.events()[0].heartbeat.what == hb_kind::started);
  auto out = r.tick(100);
  REQUIRE(out.size() == 1);
  // generic + communication; the first manufacturer-specific byte names the lost node (3)
  CHECK(out[0] == F(0x085, {0x30, 0x81, 0x11, 3, 0, 0, 0, 0}));
  CHECK(r.read_u(0x1001, 0) == 0x11);
  CHECK(r.read_u(0x1003, 0) == 1);
  CHECK(r.read_u(0x1003, 1) == 0x0003'8130); // bits 16..23: the first manufacturer byte
  out = r.feed(F(0x703, {0x7F}));
  CHECK(out == std::vector{F(0x085, {0, 0, 0, 0, 0, 0, 0, 0})}); // error reset
  CHECK(r.read_u(0x1001, 0) == 0);
  // stopped: the consumer rests (no loss reported while stopped)
  (void)r.feed(F(0, {0x02, 5}));
  CHECK(r.tick(1000).empty());
  CHECK(r.dev.consumer().state(0) == node::monitor_state::waiting);
}

TEST_CASE("device: EMCY 8130h names the node whose loss raised it") {
  rig<> r;
  (void)r.start();
  CHECK(r.sdo_write(0x1016, 1, 0x0003'0064, 4) == abort_code::none); // node 3, 100 ms
  CHECK(r.sdo_write(0x1016, 2, 0x0009'0032, 4) == abort_code::none); // node 9, 50 ms
  (void)r.feed(F(0x703, {0x7F}));
  (void)r.feed(F(0x709, {0x7F}));
  auto out = r.tick(50); // node 9 is lost first (the second entry)
  CHECK(out == std::vector{F(0x085, {0x30, 0x81, 0x11, 9, 0, 0, 0, 0})});
  CHECK(r.dev.consumer().lost_node() == 9);
  out = r.tick(50); // node 3 too: 8130h is active already, nothing more is sent
  CHECK(out.empty());
  CHECK(r.dev.consumer().lost_node() == 3); // the first lost entry
  out = r.feed(F(0x709, {0x7F}));
  CHECK(out.empty()); // node 3 is still lost: 8130h stays active
  out = r.feed(F(0x703, {0x7F}));
  CHECK(out == std::vector{F(0x085, {0, 0, 0, 0, 0, 0, 0, 0})});
  // both lost again: a new EMCY with the first entry's node (3)
  out = r.tick(100);
  REQUIRE(on(out, 0x085).size() == 1);
  CHECK(on(out, 0x085)[0] == F(0x085, {0x30, 0x81, 0x11, 3, 0, 0, 0, 0}));
}

TEST_CASE("device: life guarding from 100Ch/100Dh, EMCY 8130h") {
  rig<> r;
  (void)r.start();
  CHECK(r.sdo_write(0x100C, 0, 100, 2) == abort_code::none);
  CHECK(r.sdo_write(0x100D, 0, 2, 1) == abort_code::none);
  CHECK(r.dev.guarding().life_time_ms() == 200);
  CHECK(r.tick(1000).empty()); // not guarded yet
  CHECK(r.feed(R(0x705, 1)) == std::vector{F(0x705, {0x7F})});
  CHECK(r.feed(R(0x705, 1)) == std::vector{F(0x705, {0xFF})});
  CHECK(r.tick(199).empty());
  auto out = r.tick(1);
  REQUIRE(r.dev.events().size() == 1);
  CHECK(r.dev.events()[0].what == node::event::kind::life_guard_lost);
  CHECK(out == std::vector{F(0x085, {0x30, 0x81, 0x11, 0, 0, 0, 0, 0})});
  out = r.feed(R(0x705, 1));
  CHECK(r.dev.events()[0].what == node::event::kind::life_guard_resumed);
  CHECK(out == std::vector{F(0x705, {0x7F}), F(0x085, {0, 0, 0, 0, 0, 0, 0, 0})});
  // a guarding request for another node is not ours
  CHECK(r.feed(R(0x706, 1)).empty());
}
