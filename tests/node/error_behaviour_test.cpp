// The error behaviour (1029h, CiA 301): the NMT state the node enters on a communication error
// (heartbeat consumer timeout, life guarding loss, bus-off reported by the driver) and on the
// application's error classes; alone and in the device.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/error_behaviour.hpp>

using namespace test_node;
using co::nmt::state;

TEST_CASE("error behaviour alone: values, defaults, targets") {
  node::error_behaviour<2> e;
  // the default (0): pre-operational, only from operational
  CHECK(e.target(1, state::operational) == state::pre_operational);
  CHECK(e.target(1, state::pre_operational) == std::nullopt);
  CHECK(e.target(1, state::stopped) == std::nullopt);
  CHECK(e.target(9, state::operational) == state::pre_operational); // a class 1029h lacks
  CHECK(e.check_write({0x1029, 1}, 0) == abort_code::none);
  CHECK(e.check_write({0x1029, 1}, 1) == abort_code::none);
  CHECK(e.check_write({0x1029, 1}, 2) == abort_code::none);
  CHECK(e.check_write({0x1029, 1}, 3) == abort_code::invalid_value);
  CHECK(e.check_write({0x1029, 2}, 0x80) == abort_code::invalid_value);
  CHECK(e.check_write({0x1029, 0}, 7) == abort_code::none); // sub 0: the store's (read-only)
  CHECK(e.check_write({0x1028, 1}, 7) == abort_code::none); // not its object
  e.written({0x1029, 1}, 1, 0);
  CHECK(e.reaction(1) == node::error_reaction::no_change);
  CHECK(e.target(1, state::operational) == std::nullopt);
  e.written({0x1029, 2}, 2, 0);
  CHECK(e.target(2, state::operational) == state::stopped);
  CHECK(e.target(2, state::pre_operational) == state::stopped);
  CHECK(e.target(2, state::stopped) == std::nullopt);
  CHECK(e.target(2, state::boot_up) == std::nullopt);
  // no 1029h at all: every class enters pre-operational from operational
  node::error_behaviour<0> none;
  CHECK(none.target(1, state::operational) == state::pre_operational);
  CHECK(none.target(1, state::pre_operational) == std::nullopt);
}

TEST_CASE("device: heartbeat consumer timeout with 1029h sub 1 = 0, 1, 2") {
  for (const std::uint32_t behaviour : {0U, 1U, 2U}) {
    CAPTURE(behaviour);
    rig<> r;
    r.operational();
    CHECK(r.sdo_write(0x1029, 1, behaviour, 1) == abort_code::none);
    CHECK(r.sdo_write(0x1017, 0, 50, 2) == abort_code::none);
    CHECK(r.sdo_write(0x1016, 1, 0x0003'0064, 4) == abort_code::none);
    (void)r.feed(F(0x703, {0x05}));
    (void)r.tick(99);
    REQUIRE(r.dev.state() == state::operational);
    const auto out = r.tick(1);
    // the EMCY goes out first, in every case (also before entering stopped)
    CHECK(on(out, 0x085) == std::vector{F(0x085, {0x30, 0x81, 0x11, 3, 0, 0, 0, 0})});
    const state want = behaviour == 0U   ? state::pre_operational
                       : behaviour == 1U ? state::operational
                                         : state::stopped;
    CHECK(r.dev.state() == want);
    bool changed = false;
    for (const auto &e : r.dev.events()) {
      if (e.what == node::event::kind::nmt_state) changed = e.state == want;
    }
    CHECK(changed == (behaviour != 1U));
    // the heartbeat says so: the next one carries the new state
    const auto hb = on(r.tick(50), 0x705);
    REQUIRE(hb.size() == 1);
    CHECK(hb[0].data[0] == static_cast<std::uint8_t>(want));
  }
}

TEST_CASE("device: default behaviour only from operational; 1029h values refused over SDO") {
  rig<> r;
  (void)r.start();
  CHECK(r.sdo_write(0x1029, 1, 3, 1) == abort_code::invalid_value);
  CHECK(r.sdo_write(0x1029, 2, 0xFF, 1) == abort_code::invalid_value);
  CHECK(r.set_u(0x1029, 1, 3, 1) == abort_code::invalid_value);
  CHECK(r.read_u(0x1029, 1) == 0);
  CHECK(r.sdo_write(0x1029, 0, 1, 1) != abort_code::none); // sub 0 is read-only
  // pre-operational stays pre-operational on a loss (0 acts only from operational)
  CHECK(r.sdo_write(0x1016, 1, 0x0003'0064, 4) == abort_code::none);
  (void)r.feed(F(0x703, {0x05}));
  (void)r.tick(100);
  CHECK(r.dev.consumer().any_lost());
  CHECK(r.dev.state() == state::pre_operational);
  // the value is followed after a reset communication: back to the default 0
  CHECK(r.sdo_write(0x1029, 1, 2, 1) == abort_code::none);
  CHECK(r.dev.errors().reaction(1) == node::error_reaction::stopped);
  (void)r.feed(F(0, {0x82, 5}));
  CHECK(r.dev.errors().reaction(1) == node::error_reaction::pre_operational);
}

TEST_CASE("device: life guarding loss and the driver's bus-off are communication errors") {
  rig<> r;
  r.operational();
  CHECK(r.sdo_write(0x100C, 0, 100, 2) == abort_code::none);
  CHECK(r.sdo_write(0x100D, 0, 2, 1) == abort_code::none);
  (void)r.feed(R(0x705, 1));
  (void)r.tick(199);
  CHECK(r.dev.state() == state::operational);
  const auto out = r.tick(1);
  CHECK(on(out, 0x085) == std::vector{F(0x085, {0x30, 0x81, 0x11, 0, 0, 0, 0, 0})});
  CHECK(r.dev.state() == state::pre_operational);

  // bus-off, reported by the driver: class 1
  rig<> b;
  b.operational();
  CHECK(b.sdo_write(0x1029, 1, 2, 1) == abort_code::none);
  auto s = b.dev.report_error(1, b.now);
  REQUIRE(s.has_value());
  CHECK(s.value().state == state::stopped);
  CHECK(b.dev.state() == state::stopped);
  REQUIRE(b.dev.events().size() == 1);
  CHECK(b.dev.events()[0].what == node::event::kind::nmt_state);
  // an application class (sub 2), default 0, from operational
  (void)b.feed(F(0, {0x01, 5}));
  REQUIRE(b.dev.state() == state::operational);
  CHECK(b.dev.report_error(2, b.now).value().state == state::pre_operational);
  // a class 1029h does not have: the default
  (void)b.feed(F(0, {0x01, 5}));
  CHECK(b.dev.report_error(7, b.now).value().state == state::pre_operational);
  // bad calls
  CHECK(b.dev.report_error(0, b.now).error() == errc::invalid_argument);
  rig<> idle;
  CHECK(idle.dev.report_error(1, 0).error() == errc::bad_state);
}

namespace {
// a node without 1029h: the communication error still enters pre-operational (CiA 301)
constexpr std::array<od::entry_spec, 7> bare_specs{{
    var(0x1000, 0, data_type::unsigned32, access::ro, 0x000F0191U),
    var(0x1001, 0, data_type::unsigned8, access::ro, 0),
    var(0x1016, 0, data_type::unsigned8, access::ro, 1),
    var(0x1016, 1, data_type::unsigned32, access::rw, 0x0003'0064U),
    var(0x1017, 0, data_type::unsigned16, access::rw, 0),
    var(0x1018, 0, data_type::unsigned8, access::ro, 1),
    var(0x1018, 1, data_type::unsigned32, access::ro, 0x0F1CU),
}};
constexpr auto bare_entries = od::entries_of<bare_specs>;
constexpr od::dictionary bare{bare_entries};
static_assert(bare.is_valid());
constexpr auto bare_layout = co::make_layout<bare_entries.size()>(bare);
} // namespace

TEST_CASE("device without 1029h: a heartbeat loss in operational enters pre-operational") {
  std::vector<std::uint8_t> storage(bare_layout.storage_size());
  store_type store{bare, bare_layout, storage};
  REQUIRE(store.init_defaults(5).has_value());
  node::device<store_type, node::capacity_for(bare)> dev(store, 5);
  REQUIRE(dev.start(0).has_value());
  (void)dev.on_frame(F(0, {0x01, 5}), 0);
  REQUIRE(dev.state() == state::operational);
  (void)dev.on_frame(F(0x703, {0x05}), 0);
  const auto s = dev.poll(100);
  CHECK(list(s.send) == std::vector{F(0x085, {0x30, 0x81, 0x11, 3, 0, 0, 0, 0})});
  CHECK(dev.state() == state::pre_operational);
  CHECK(dev.errors().reaction(1) == node::error_reaction::pre_operational);
}
