// master::boot against the simulated XENAX of sim_device.hpp: reset, boot-up, identity,
// configuration list, heartbeat, NMT start, and what each failure reports.
#include "boot_harness.hpp"

#include "master/generated/xenax_axis_config.hpp"

#include <fieldcodec/master/boot.hpp>

#include <doctest/doctest.h>

namespace master = fieldcodec::master;
namespace co = fieldcodec::canopen;
namespace csdo = fieldcodec::canopen::sdo;
namespace axis_config = fieldcodec::dictionaries::xenax_axis::config;
using fieldcodec::errc;
using master::boot_failure;
using master::boot_state;

namespace {

/// A device that matches the fixture DCF's identity.
void make_identity(sim::device &d) { d.set_u32({0x1018, 1}, 0x21B); }

using harness = sim::boot_harness;

} // namespace

TEST_CASE("boot: reset, boot-up, identity, configuration, heartbeat, start") {
  harness h(5, {.heartbeat_timeout_ms = 500});
  h.heartbeats = true;
  make_identity(h.dev);
  h.dev.nmt = co::nmt::state::operational; // running before the master resets it
  auto s = h.machine.start(axis_config::configuration, h.now);
  REQUIRE(s);
  REQUIRE(s.value().send.size() == 1U);
  CHECK(s.value().send[0] == co::nmt::encode(co::nmt::command::reset_communication, 5).value());
  CHECK(s.value().state == boot_state::waiting_boot_up);
  h.run(s.value());
  CHECK(h.machine.state() == boot_state::done);
  CHECK_FALSE(h.machine.error());
  CHECK(h.dev.nmt == co::nmt::state::operational);
  CHECK(h.sent.back() == co::nmt::encode(co::nmt::command::start, 5).value());
  CHECK(h.dev.get({0x6065, 0}) == 500U); // configured
  CHECK(h.machine.read_identity_values().vendor_id == 0x21BU);
  CHECK(h.machine.read_identity_values().device_type == 0x00020192U);
  CHECK(h.machine.read_identity_values().product_code == 0U); // not checked: not read
}

TEST_CASE("boot: without reset, only the boot-up is awaited; start can be left out") {
  harness h(5, {.reset_communication = false, .start = false});
  make_identity(h.dev);
  auto s = h.machine.start(axis_config::configuration, h.now);
  REQUIRE(s);
  CHECK(s.value().send.empty());
  // the device powers up
  s = h.machine.on_frame(co::nmt::encode_boot_up(5).value(), h.now);
  h.run(s.value());
  CHECK(h.machine.state() == boot_state::done);
  CHECK(h.dev.nmt == co::nmt::state::pre_operational);
  // a heartbeat of another node or a boot-up of another node does nothing
  harness other(5, {.reset_communication = false});
  REQUIRE(other.machine.start(axis_config::configuration, other.now));
  CHECK(other.machine.on_frame(co::nmt::encode_boot_up(6).value(), other.now).state ==
        boot_state::waiting_boot_up);
}

TEST_CASE("boot: a wrong identity names the field") {
  harness h(5, {});
  h.dev.set_u32({0x1018, 1}, 0x999);
  h.run(h.machine.start(axis_config::configuration, h.now).value());
  CHECK(h.machine.state() == boot_state::failed);
  REQUIRE(h.machine.error());
  const auto e = *h.machine.error();
  CHECK(e.failure == boot_failure::identity_mismatch);
  CHECK(e.field == master::identity_field::vendor_id);
  CHECK(e.expected == 0x21BU);
  CHECK(e.actual == 0x999U);
  CHECK(e.is(errc::out_of_range));
  CHECK(master::to_string(e.field) == "vendor-ID (1018h sub 1)");
  CHECK(h.dev.get({0x6065, 0}) == 2000U); // nothing configured
  CHECK(h.dev.nmt == co::nmt::state::pre_operational);

  SUBCASE("revision") {
    harness r(5, {});
    make_identity(r.dev);
    r.dev.set_u32({0x1018, 3}, 0x20000);
    r.run(r.machine.start(axis_config::configuration, r.now).value());
    CHECK(r.machine.error()->field == master::identity_field::revision);
    CHECK(r.machine.error()->actual == 0x20000U);
  }
}

TEST_CASE("boot: no boot-up message") {
  harness h(5, {.boot_timeout_ms = 300});
  h.dev.boots_on_reset = false;
  const auto start = h.now;
  h.run(h.machine.start(axis_config::configuration, h.now).value());
  CHECK(h.machine.error()->failure == boot_failure::no_boot_up);
  CHECK(h.machine.error()->is(errc::timeout));
  CHECK(h.now - start == 300U);
}

TEST_CASE("boot: reading the identity times out") {
  harness h(5, {});
  make_identity(h.dev);
  h.dev.silent = 100;
  h.run(h.machine.start(axis_config::configuration, h.now).value());
  CHECK(h.machine.error()->failure == boot_failure::identity_read_failed);
  CHECK(h.machine.error()->field == master::identity_field::device_type);
  REQUIRE(h.machine.error()->sdo);
  CHECK(h.machine.error()->sdo->abort == csdo::abort_code::timeout);
  CHECK(h.machine.error()->is(errc::timeout));
}

TEST_CASE("boot: an abort during configuration is reported with the item") {
  harness h(5, {.config = {.retries = 1}});
  make_identity(h.dev);
  h.dev.abort_at = fieldcodec::od::address{0x6065, 0};
  h.dev.abort_code = csdo::abort_code::value_too_high;
  h.dev.aborts = 5;
  h.run(h.machine.start(axis_config::configuration, h.now).value());
  CHECK(h.machine.state() == boot_state::failed);
  const auto e = *h.machine.error();
  CHECK(e.failure == boot_failure::configuration_failed);
  CHECK(e.is(errc::aborted));
  REQUIRE(e.config);
  CHECK(e.config->name == "Following Position Error Window");
  CHECK(e.config->abort == csdo::abort_code::value_too_high);
  CHECK(e.config->attempts == 2U);
  CHECK(h.dev.nmt == co::nmt::state::pre_operational); // never started
}

TEST_CASE("boot: no heartbeat after the configuration") {
  harness h(5, {.heartbeat_timeout_ms = 250});
  make_identity(h.dev);
  h.run(h.machine.start(axis_config::configuration, h.now).value());
  CHECK(h.machine.error()->failure == boot_failure::no_heartbeat);
  CHECK(h.dev.nmt == co::nmt::state::pre_operational);
}

TEST_CASE("boot: refusals") {
  csdo::client c(1);
  master::boot bad(0, c);
  CHECK(bad.start(axis_config::configuration, 0).error() == errc::invalid_argument);
  master::boot b(1, c);
  REQUIRE(b.start(axis_config::configuration, 0));
  CHECK(b.start(axis_config::configuration, 0).error() == errc::bad_state);
}

TEST_CASE("boot: the heartbeat entry starts the master's heartbeat consumer") {
  harness h(5, {.heartbeat_timeout_ms = 500, .consumer_time_ms = 150});
  h.heartbeats = true;
  make_identity(h.dev);
  h.run(h.machine.start(axis_config::configuration, h.now).value());
  REQUIRE(h.machine.state() == boot_state::done);
  const auto entry = h.machine.heartbeat_entry();
  CHECK(entry == fieldcodec::canopen::node::consumer_entry{5, 150});
  fieldcodec::canopen::node::heartbeat_consumer<2> consumer;
  CHECK(consumer.configure(0, entry.to_u32(), h.now) == csdo::abort_code::none);
  (void)consumer.on_frame(co::nmt::encode_heartbeat(5, co::nmt::state::operational).value(), h.now);
  REQUIRE(consumer.events().size() == 1U);
  CHECK(consumer.events()[0].what == fieldcodec::canopen::node::heartbeat_event::kind::started);
  (void)consumer.poll(h.now + 150);
  REQUIRE(consumer.events().size() == 1U);
  CHECK(consumer.events()[0].what == fieldcodec::canopen::node::heartbeat_event::kind::lost);
  // without a consumer time the entry is inactive
  harness none(5, {});
  CHECK_FALSE(none.machine.heartbeat_entry().active());
}
