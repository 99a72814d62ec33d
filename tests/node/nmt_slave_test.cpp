// NMT slave: states, commands, boot-up, resets and what they restore, services per state.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/nmt_slave.hpp>

using namespace test_node;
using co::nmt::state;
using node::service;

namespace {
constexpr co::can_frame nmt_frame(std::uint8_t cs, std::uint8_t n) {
  return co::make_frame(0, {cs, n}).value();
}

// The whole life of a slave in a constant expression: boot, start, stop, pre-op, reset.
constexpr bool slave_walk() {
  node::nmt_slave s(5);
  if (s.state() != state::boot_up) return false;
  if (s.on_frame(nmt_frame(0x01, 5), 0).state != state::boot_up) return false; // not booted
  auto b = s.boot();
  if (b.send.size() != 1 || b.send[0] != co::make_frame(0x705, {0}).value()) return false;
  if (s.state() != state::pre_operational) return false;
  if (s.on_frame(nmt_frame(0x01, 5), 0).state != state::operational) return false;
  if (s.on_frame(nmt_frame(0x02, 0), 0).state != state::stopped) return false; // broadcast
  if (s.on_frame(nmt_frame(0x80, 6), 0).state != state::stopped) return false; // other node
  if (s.on_frame(nmt_frame(0x80, 5), 0).state != state::pre_operational) return false;
  (void)s.on_frame(nmt_frame(0x82, 5), 0);
  if (s.pending_reset() != node::reset::communication || s.state() != state::boot_up) {
    return false;
  }
  (void)s.boot();
  return s.pending_reset() == node::reset::none && s.state() == state::pre_operational;
}
static_assert(slave_walk());

// CiA 301 Table 48
static_assert(!node::allowed(state::boot_up, service::nmt));
static_assert(node::allowed(state::pre_operational, service::sdo));
static_assert(node::allowed(state::pre_operational, service::emcy));
static_assert(node::allowed(state::pre_operational, service::sync));
static_assert(!node::allowed(state::pre_operational, service::pdo));
static_assert(node::allowed(state::operational, service::pdo));
static_assert(node::allowed(state::stopped, service::error_control));
static_assert(node::allowed(state::stopped, service::nmt));
static_assert(!node::allowed(state::stopped, service::sdo));
static_assert(!node::allowed(state::stopped, service::emcy));
static_assert(!node::allowed(state::stopped, service::sync));
static_assert(!node::allowed(state::stopped, service::time));
static_assert(!node::allowed(state::stopped, service::pdo));

static_assert(node::restored(node::reset::communication).first == 0x1000);
static_assert(node::restored(node::reset::communication).last == 0x1FFF);
static_assert(node::restored(node::reset::application).first == 0x2000);
static_assert(node::restored(node::reset::application).last == 0xFFFF);
} // namespace

TEST_CASE("nmt_slave: bad NMT frames are ignored with a reason") {
  node::nmt_slave s(5);
  (void)s.boot();
  CHECK(s.on_frame(F(0, {0x01}), 0).state == state::pre_operational); // DLC 1
  CHECK(s.error() == errc::bad_length);
  CHECK(s.on_frame(F(0, {0x01, 5, 0}), 0).state == state::pre_operational); // DLC 3
  CHECK(s.error() == errc::bad_length);
  CHECK(s.on_frame(F(0, {0x03, 5}), 0).state == state::pre_operational); // unknown command
  CHECK(s.error() == errc::unknown_command);
  CHECK(s.on_frame(F(0, {0x01, 0x80}), 0).state == state::pre_operational); // node 128
  CHECK(s.error() == errc::invalid_argument);
  CHECK(s.on_frame(R(0, 2), 0).state == state::pre_operational); // remote frame
  CHECK(s.error() == errc::unexpected_frame);
  CHECK(s.on_frame(F(0x080, {0x01, 5}), 0).state == state::pre_operational); // not COB-ID 0
  CHECK(s.on_frame(F(0, {0x01, 5}), 0).state == state::operational);
  CHECK_FALSE(s.error());
}

TEST_CASE("nmt_slave: reset node stays the larger reset; local state changes") {
  node::nmt_slave s(7);
  CHECK(s.enter(state::operational) == errc::bad_state); // not booted
  (void)s.boot(true);
  CHECK(s.state() == state::operational); // self start
  (void)s.on_frame(nmt_frame(0x81, 0), 0);
  (void)s.on_frame(nmt_frame(0x82, 7), 0); // ignored while initialising
  CHECK(s.pending_reset() == node::reset::application);
  CHECK(s.error() == errc::bad_state);
  (void)s.boot();
  CHECK(s.enter(state::stopped).has_value());
  CHECK(s.state() == state::stopped);
  CHECK(s.enter(state::boot_up) == errc::invalid_argument);
  // a node-ID outside 1..127 cannot boot
  node::nmt_slave bad(0);
  CHECK(bad.boot().send.empty());
  CHECK(bad.state() == state::boot_up);
  CHECK(bad.error() == errc::invalid_argument);
}

TEST_CASE("device: NMT commands, events, and services per state") {
  rig<> r;
  CHECK(r.dev.poll(0).send.empty()); // nothing before start
  CHECK(r.feed(F(0, {0x01, 5})).empty());
  CHECK(r.dev.state() == state::boot_up);
  auto boot = r.start();
  REQUIRE(boot.size() == 1);
  CHECK(boot[0] == F(0x705, {0x00}));
  CHECK(r.dev.start(0) == errc::bad_state);
  // pre-operational: SDO answered, PDO not
  CHECK(r.sdo_write(0x2000, 0, 42, 4) == abort_code::none);
  CHECK(r.feed(F(0x205, {1, 0, 0, 0, 2, 0})).empty());
  CHECK(r.read_u(0x2000, 0) == 42);
  // start
  (void)r.feed(F(0, {0x01, 5}));
  REQUIRE(r.dev.events().size() == 1);
  CHECK(r.dev.events()[0].what == node::event::kind::nmt_state);
  CHECK(r.dev.events()[0].state == state::operational);
  (void)r.feed(F(0x205, {1, 0, 0, 0, 2, 0}));
  CHECK(r.read_u(0x2000, 0) == 1);
  // stopped: no SDO answer, no PDO, guarding still answered
  (void)r.feed(F(0, {0x02, 0}));
  CHECK(r.dev.state() == state::stopped);
  const auto ch = sdo::channel::default_for(5).value();
  CHECK(r.feed(ch.request(sdo::initiate_upload({0x1000, 0}))).empty());
  CHECK(r.feed(F(0x205, {9, 0, 0, 0, 2, 0})).empty());
  CHECK(r.read_u(0x2000, 0) == 1);
  CHECK(r.feed(R(0x705, 1)) == std::vector{F(0x705, {0x04})});
  CHECK(r.feed(R(0x705, 0)) == std::vector{F(0x705, {0x84})}); // DLC 0 request, toggle
  // other nodes' commands are ignored
  (void)r.feed(F(0, {0x80, 6}));
  CHECK(r.dev.state() == state::stopped);
  (void)r.feed(F(0, {0x80, 0}));
  CHECK(r.dev.state() == state::pre_operational);
  // a bad NMT frame changes nothing
  (void)r.feed(F(0, {0x01}));
  CHECK(r.dev.state() == state::pre_operational);
  CHECK(r.dev.nmt().error() == errc::bad_length);
  CHECK(r.dev.lost() == 0);
}

TEST_CASE("device: reset communication restores 1000h-1FFFh, reset node also 2000h-FFFFh") {
  rig<> r;
  (void)r.start();
  CHECK(r.sdo_write(0x1017, 0, 100, 2) == abort_code::none);
  CHECK(r.sdo_write(0x2000, 0, 0xCAFE, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1800, 1, 0x8000'0185U, 4) == abort_code::none);
  // the application's own value of a read-only object survives both resets
  CHECK(r.set_u(0x1018, 4, 0x00C0FFEE, 4) == abort_code::none);
  CHECK(r.set_u(0x6041, 0, 0x0237, 2) == abort_code::none);

  r.now = 10;
  auto out = r.feed(F(0, {0x82, 5}));
  CHECK(out == std::vector{F(0x705, {0x00})});
  REQUIRE(r.dev.events().size() == 2);
  CHECK(r.dev.events()[0].what == node::event::kind::reset_communication);
  CHECK(r.dev.events()[1].what == node::event::kind::nmt_state);
  CHECK(r.dev.events()[1].state == state::pre_operational);
  CHECK(r.read_u(0x1017, 0) == 0);          // restored
  CHECK(r.read_u(0x1800, 1) == 0x185);      // restored
  CHECK(r.read_u(0x2000, 0) == 0xCAFE);     // application area untouched
  CHECK(r.read_u(0x1018, 4) == 0x00C0FFEE); // read-only: kept
  CHECK(r.dev.producer().period() == 0);    // the heartbeat follows the restored 1017h
  CHECK(r.tick(1000).empty());

  CHECK(r.sdo_write(0x1017, 0, 100, 2) == abort_code::none);
  auto reset = r.feed(F(0, {0x81, 0}));
  CHECK(reset == std::vector{F(0x705, {0x00})});
  CHECK(r.dev.events()[0].what == node::event::kind::reset_application);
  CHECK(r.read_u(0x2000, 0) == 0);      // restored now
  CHECK(r.read_u(0x1017, 0) == 0);      // and the communication area
  CHECK(r.read_u(0x6041, 0) == 0x0237); // read-only: kept
  CHECK(r.read_u(0x1018, 4) == 0x00C0FFEE);
  CHECK(r.dev.state() == state::pre_operational);
}

TEST_CASE("device: self start and a local state change") {
  node::options o;
  o.self_start = true;
  rig<> r(o);
  (void)r.start();
  CHECK(r.dev.state() == state::operational);
  auto s = r.dev.enter(state::stopped, 0);
  REQUIRE(s.has_value());
  CHECK(s.value().state == state::stopped);
  CHECK(r.dev.enter(state::boot_up, 0) == errc::invalid_argument);
}
