// master::boot started from the master's CiA 302 objects (slave_objects: 1F81h, 1F84h..1F88h,
// 1F22h, 1016h, 1F55h, 1F26h/1F27h, 1F8Ah), against the simulated XENAX of sim_device.hpp: the
// boot slave process of CiA 302-2 and each of its error status letters 'A'...'O'.
#include "boot_harness.hpp"

#include "master/generated/master_slaves.hpp"
#include "master/generated/xenax_axis_config.hpp"

#include <fieldcodec/master/boot.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

namespace master = fieldcodec::master;
namespace co = fieldcodec::canopen;
namespace csdo = fieldcodec::canopen::sdo;
namespace axis_config = fieldcodec::dictionaries::xenax_axis::config;
namespace master_dcf = fieldcodec::dictionaries::master::slaves;
namespace bit = fieldcodec::master::assignment_bit;
using fieldcodec::errc;
using fieldcodec::od::address;
using master::boot_failure;
using master::boot_state;
using master::boot_status;

namespace {

constexpr std::uint32_t device_type = 0x00020192U; // the XENAX's 1000h
constexpr std::uint32_t vendor = 0x21BU;           // what make_identity sets

struct harness : sim::boot_harness {
  harness(std::uint8_t node, master::boot_options o) : boot_harness(node, o) {
    dev.set_u32({0x1018, 1}, vendor);
  }
  using boot_harness::run;
  void run(const master::slave_objects &o) {
    auto s = machine.start(o, now);
    REQUIRE(s);
    run(s.value());
  }
};

/// The XENAX axis of the fixture DCF, as a master DCF would describe it for node 5: a slave to
/// boot, its identity, the concise DCF of its configuration, a heartbeat consumer time.
master::slave_objects axis_objects() {
  master::slave_objects o;
  o.assignment = bit::slave | bit::boot;
  o.expected = {device_type, vendor, 0, 0, 0};
  o.concise_dcf = axis_config::concise_dcf;
  return o;
}

} // namespace

TEST_CASE("boot from 1F81h/1F84h../1F22h: reset, identity, concise DCF, heartbeat, start") {
  harness h(5, {});
  h.heartbeats = true;
  auto o = axis_objects();
  o.consumer_time_ms = 500;
  auto s = h.machine.start(o, h.now);
  REQUIRE(s);
  REQUIRE(s.value().send.size() == 1U);
  CHECK(s.value().send[0] == co::nmt::encode(co::nmt::command::reset_communication, 5).value());
  h.run(s.value());
  CHECK(h.machine.state() == boot_state::done);
  CHECK(h.machine.status() == boot_status::ok);
  CHECK_FALSE(h.machine.error());
  CHECK(h.dev.get({0x6065, 0}) == 500U); // the concise DCF's entries arrived
  CHECK(h.dev.get({0x6098, 0}) == 12U);
  CHECK(h.dev.get({0x1800, 1}) == 0x185U);
  CHECK(h.requests_for({0x1000, 0}) == 1);
  CHECK(h.requests_for({0x1018, 1}) == 1);
  CHECK(h.requests_for({0x1018, 2}) == 0); // expected 0: not read
  CHECK(h.nmt(co::nmt::command::start) == 1);
  CHECK(h.dev.nmt == co::nmt::state::operational);
  CHECK(h.machine.heartbeat_entry() == co::node::consumer_entry{5, 500});
}

TEST_CASE("boot 302 from the generated slaves of a master DCF (fieldcodec-gen --nmt-slaves)") {
  // tests/master/fixtures/master.dcf: node 5 with the axis's concise DCF as an UploadFile, node 6
  // kept alive with a concise DCF in the DCF, node 7 listed with 0
  REQUIRE(master_dcf::slaves.size() == 2U);
  CHECK(master::find_slave(master_dcf::slaves, 7) == nullptr);
  CHECK(master::find_slave(master_dcf::slaves, 1) == nullptr);
  const auto *five = master::find_slave(master_dcf::slaves, 5);
  REQUIRE(five != nullptr);
  CHECK(five->objects.assignment == (bit::slave | bit::boot));
  CHECK(five->objects.consumer_time_ms == 500U);
  CHECK(std::equal(five->objects.concise_dcf.begin(), five->objects.concise_dcf.end(),
                   std::begin(axis_config::concise_dcf), std::end(axis_config::concise_dcf)));
  harness h(5, {});
  h.heartbeats = true;
  h.run(five->objects);
  CHECK(h.machine.status() == boot_status::ok);
  CHECK(h.dev.get({0x6065, 0}) == 500U);
  CHECK(h.dev.nmt == co::nmt::state::operational);
  CHECK(h.machine.heartbeat_entry() == co::node::consumer_entry{5, 500});

  const auto *six = master::find_slave(master_dcf::slaves, 6);
  REQUIRE(six != nullptr);
  harness k(6, {});
  k.dev.nmt = co::nmt::state::operational;
  k.run(six->objects); // keep-alive, no consumer time: node guarding, not answered
  CHECK(k.machine.status() == boot_status::no_guarding_state);
  k.dev.answers_guarding = true;
  k.run(six->objects);
  CHECK(k.machine.status() == boot_status::initially_operational);
  harness p(6, {});
  p.dev.answers_guarding = true; // pre-operational: reset, then its two entries
  p.run(six->objects);
  CHECK(p.machine.status() == boot_status::ok);
  CHECK(p.dev.get({0x6081, 0}) == 1000U);
  CHECK(p.dev.get({0x6083, 0}) == 40000U);
}

TEST_CASE("boot 302: the device type is read even when 1F84h is 0 (it tells the device is there)") {
  harness h(5, {});
  auto o = axis_objects();
  o.expected = {};
  h.run(o);
  CHECK(h.machine.state() == boot_state::done);
  CHECK(h.requests_for({0x1000, 0}) == 1);
  CHECK(h.machine.read_identity_values().device_type == device_type);
  // the C++ configuration path reads only what it checks
  harness c(5, {});
  master::configuration cfg = axis_config::configuration;
  cfg.expected = {};
  c.run(c.machine.start(cfg, c.now).value());
  CHECK(c.machine.state() == boot_state::done);
  CHECK(c.requests_for({0x1000, 0}) == 0);
}

TEST_CASE("boot 302 A: a node that is not in the network list (1F81h bit 0)") {
  harness h(5, {});
  auto o = axis_objects();
  o.assignment = bit::boot;
  auto s = h.machine.start(o, h.now);
  REQUIRE(s);
  CHECK(s.value().send.empty());
  CHECK(s.value().state == boot_state::failed);
  CHECK(h.machine.status() == boot_status::not_in_network_list);
  CHECK(master::code(h.machine.status()) == 'A');
  CHECK(h.machine.error()->failure == boot_failure::not_assigned);
}

TEST_CASE("boot 302: without bit 2 only error control and start") {
  harness h(5, {});
  h.heartbeats = true;
  master::slave_objects o;
  o.assignment = bit::slave;
  o.consumer_time_ms = 200;
  h.run(o);
  CHECK(h.machine.state() == boot_state::done);
  CHECK(h.nmt(co::nmt::command::reset_communication) == 0);
  CHECK(h.requests_for({0x1000, 0}) == 0);
  CHECK(h.nmt(co::nmt::command::start) == 1);
}

TEST_CASE("boot 302 B: no answer for the device type, retried on timeout") {
  SUBCASE("silent device") {
    harness h(5, {.reset_communication = false, .wait_boot_up = false, .read_retries = 2});
    h.dev.silent = 100;
    h.run(axis_objects());
    CHECK(h.machine.status() == boot_status::no_device_type);
    CHECK(h.machine.error()->failure == boot_failure::identity_read_failed);
    CHECK(h.machine.error()->is(errc::timeout));
    CHECK(h.requests_for({0x1000, 0}) == 3); // the first and two retries
  }
  SUBCASE("a retry that succeeds") {
    harness h(5, {.reset_communication = false, .wait_boot_up = false, .read_retries = 2});
    h.dev.silent = 1;
    h.run(axis_objects());
    CHECK(h.machine.state() == boot_state::done);
    CHECK(h.requests_for({0x1000, 0}) == 2);
  }
  SUBCASE("no boot-up after the reset") {
    harness h(5, {.boot_timeout_ms = 300});
    h.dev.boots_on_reset = false;
    h.run(axis_objects());
    CHECK(h.machine.status() == boot_status::no_device_type);
    CHECK(h.machine.error()->failure == boot_failure::no_boot_up);
  }
}

TEST_CASE("boot 302 C, D, M, N, O: the identity field that differs") {
  struct row {
    address a;
    master::identity expected;
    boot_status status;
    master::identity_field field;
  };
  const row rows[] = {
      {{0x1000, 0},
       {0x00020191U, 0, 0, 0, 0},
       boot_status::device_type_mismatch,
       master::identity_field::device_type},
      {{0x1018, 1},
       {0, 0x999, 0, 0, 0},
       boot_status::vendor_id_mismatch,
       master::identity_field::vendor_id},
      {{0x1018, 2},
       {0, 0, 0x1234, 0, 0},
       boot_status::product_code_mismatch,
       master::identity_field::product_code},
      {{0x1018, 3},
       {0, 0, 0, 0x20000, 0},
       boot_status::revision_mismatch,
       master::identity_field::revision},
      {{0x1018, 4}, {0, 0, 0, 0, 77}, boot_status::serial_mismatch, master::identity_field::serial},
  };
  for (const auto &r : rows) {
    CAPTURE(master::code(r.status));
    harness h(5, {});
    auto o = axis_objects();
    o.expected = r.expected;
    h.run(o);
    CHECK(h.machine.status() == r.status);
    CHECK(h.machine.error()->failure == boot_failure::identity_mismatch);
    CHECK(h.machine.error()->field == r.field);
    CHECK(h.machine.error()->actual != h.machine.error()->expected);
    CHECK(h.dev.get({0x6065, 0}) == 2000U); // nothing configured
  }
  SUBCASE("a vendor-ID that cannot be read is D as well") {
    harness h(5, {});
    h.dev.abort_at = address{0x1018, 1};
    h.dev.aborts = 1;
    h.run(axis_objects());
    CHECK(h.machine.status() == boot_status::vendor_id_mismatch);
    CHECK(h.machine.error()->failure == boot_failure::identity_read_failed);
    REQUIRE(h.machine.error()->sdo);
  }
}

TEST_CASE("boot 302 with keep-alive (1F81h bit 4)") {
  SUBCASE("operational, heartbeat: it keeps running, L") {
    harness h(5, {});
    h.heartbeats = true;
    h.dev.nmt = co::nmt::state::operational;
    auto o = axis_objects();
    o.assignment |= bit::keep_alive;
    o.consumer_time_ms = 300;
    h.run(o);
    CHECK(h.machine.state() == boot_state::done);
    CHECK(h.machine.status() == boot_status::initially_operational);
    CHECK(master::code(h.machine.status()) == 'L');
    CHECK_FALSE(h.machine.error());
    CHECK(h.dev.resets == 0);
    CHECK(h.nmt(co::nmt::command::start) == 0);
    CHECK(h.dev.get({0x6065, 0}) == 2000U);  // not reconfigured
    CHECK(h.requests_for({0x1000, 0}) == 1); // the identity is still checked
  }
  SUBCASE("pre-operational: reset communication, then the whole boot") {
    harness h(5, {});
    h.heartbeats = true;
    auto o = axis_objects();
    o.assignment |= bit::keep_alive;
    o.consumer_time_ms = 300;
    h.run(o);
    CHECK(h.machine.status() == boot_status::ok);
    CHECK(h.dev.resets == 1);
    CHECK(h.dev.get({0x6065, 0}) == 500U);
    CHECK(h.nmt(co::nmt::command::start) == 1);
  }
  SUBCASE("operational, node guarding (no consumer time): L") {
    harness h(5, {});
    h.dev.nmt = co::nmt::state::operational;
    h.dev.answers_guarding = true;
    auto o = axis_objects();
    o.assignment |= bit::keep_alive;
    h.run(o);
    CHECK(h.machine.status() == boot_status::initially_operational);
    CHECK(std::count_if(h.sent.begin(), h.sent.end(),
                        [](const co::can_frame &f) { return f.rtr && f.id == 0x705U; }) == 1);
  }
  SUBCASE("no heartbeat: E") {
    harness h(5, {});
    auto o = axis_objects();
    o.assignment |= bit::keep_alive;
    o.consumer_time_ms = 300;
    h.run(o);
    CHECK(h.machine.status() == boot_status::no_heartbeat_state);
    CHECK(h.machine.error()->failure == boot_failure::no_node_state);
    CHECK(h.dev.resets == 0);
  }
  SUBCASE("no guarding answer: F") {
    harness h(5, {.guard_wait_ms = 50});
    auto o = axis_objects();
    o.assignment |= bit::keep_alive;
    const auto start = h.now;
    h.run(o);
    CHECK(h.machine.status() == boot_status::no_guarding_state);
    CHECK(h.now - start >= 50U);
  }
}

TEST_CASE("boot 302 G, H, I: the software version (1F81h bit 5, 1F55h, 1F56h sub 1)") {
  SUBCASE("1F55h not configured: G") {
    harness h(5, {});
    auto o = axis_objects();
    o.assignment |= bit::verify_software;
    h.run(o);
    CHECK(h.machine.status() == boot_status::software_not_configured);
    CHECK(h.requests_for({0x1F56, 1}) == 0);
  }
  SUBCASE("1F56h cannot be read: G") {
    harness h(5, {});
    auto o = axis_objects();
    o.assignment |= bit::verify_software;
    o.software_version = 0x0102;
    h.run(o);
    CHECK(h.machine.status() == boot_status::software_not_configured);
    CHECK(h.machine.error()->failure == boot_failure::software_not_checked);
    REQUIRE(h.machine.error()->sdo);
    CHECK(h.machine.error()->sdo->abort == csdo::abort_code::no_object);
  }
  SUBCASE("a match goes on") {
    harness h(5, {});
    h.dev.extra[{0x1F56, 1}] = 0x0102;
    auto o = axis_objects();
    o.assignment |= bit::verify_software;
    o.software_version = 0x0102;
    h.run(o);
    CHECK(h.machine.status() == boot_status::ok);
    CHECK(h.dev.get({0x6065, 0}) == 500U);
  }
  SUBCASE("a mismatch: H, or I when an update was allowed") {
    for (const bool update : {false, true}) {
      harness h(5, {});
      h.dev.extra[{0x1F56, 1}] = 0x0101;
      auto o = axis_objects();
      o.assignment |= bit::verify_software | (update ? bit::update_software : 0U);
      o.software_version = 0x0102;
      h.run(o);
      CHECK(h.machine.status() ==
            (update ? boot_status::software_update_failed : boot_status::software_mismatch));
      CHECK(h.machine.error()->failure == boot_failure::software_mismatch);
      CHECK(h.machine.error()->expected == 0x0102U);
      CHECK(h.machine.error()->actual == 0x0101U);
      CHECK(h.dev.get({0x6065, 0}) == 2000U);
    }
  }
}

TEST_CASE("boot 302: restore defaults before the configuration (1F81h bit 7, 1F8Ah)") {
  for (const std::uint8_t sub : {std::uint8_t{1}, std::uint8_t{2}, std::uint8_t{3}}) {
    CAPTURE(sub);
    harness h(5, {});
    h.dev.extra[{0x1011, sub}] = 0;
    auto o = axis_objects();
    o.assignment |= bit::restore;
    o.restore_sub = sub;
    h.run(o);
    CHECK(h.machine.status() == boot_status::ok);
    CHECK(h.dev.extra[{0x1011, sub}] == 0x64616F6CU); // "load"
    // communication parameters: reset communication; the others: reset node
    CHECK(h.nmt(sub == 2U ? co::nmt::command::reset_communication : co::nmt::command::reset_node) ==
          (sub == 2U ? 2 : 1));
    CHECK(h.dev.resets == 2);
    CHECK(h.dev.get({0x6065, 0}) == 500U);
  }
  SUBCASE("a refused restore: J") {
    harness h(5, {});
    auto o = axis_objects();
    o.assignment |= bit::restore;
    o.restore_sub = 1; // 1011h is not in the device: abort
    h.run(o);
    CHECK(h.machine.status() == boot_status::configuration_failed);
    REQUIRE(h.machine.error()->sdo);
    CHECK(h.machine.error()->sdo->address == address{0x1011, 1});
  }
  SUBCASE("restore without a sub-index in 1F8Ah: nothing is restored") {
    harness h(5, {});
    auto o = axis_objects();
    o.assignment |= bit::restore;
    h.run(o);
    CHECK(h.machine.status() == boot_status::ok);
    CHECK(h.requests_for({0x1011, 1}) == 0);
  }
}

TEST_CASE("boot 302: 1020h showing 1F26h/1F27h skips the download") {
  const auto with_date = [](std::uint32_t date, std::uint32_t time) {
    auto o = axis_objects();
    o.configuration_date = date;
    o.configuration_time = time;
    return o;
  };
  SUBCASE("both match: kept") {
    harness h(5, {});
    h.dev.extra[{0x1020, 1}] = 12000;
    h.dev.extra[{0x1020, 2}] = 3600000;
    h.run(with_date(12000, 3600000));
    CHECK(h.machine.status() == boot_status::ok);
    CHECK(h.dev.get({0x6065, 0}) == 2000U);
    CHECK(h.requests_for({0x6065, 0}) == 0);
  }
  SUBCASE("the time differs: downloaded") {
    harness h(5, {});
    h.dev.extra[{0x1020, 1}] = 12000;
    h.dev.extra[{0x1020, 2}] = 1;
    h.run(with_date(12000, 3600000));
    CHECK(h.dev.get({0x6065, 0}) == 500U);
  }
  SUBCASE("no 1020h in the device: downloaded") {
    harness h(5, {});
    h.run(with_date(12000, 3600000));
    CHECK(h.machine.status() == boot_status::ok);
    CHECK(h.dev.get({0x6065, 0}) == 500U);
  }
  SUBCASE("only a date: always downloaded, 1020h not read") {
    harness h(5, {});
    h.run(with_date(12000, 0));
    CHECK(h.requests_for({0x1020, 1}) == 0);
    CHECK(h.dev.get({0x6065, 0}) == 500U);
  }
}

TEST_CASE("boot 302 J and K: the download fails, the heartbeat does not come") {
  SUBCASE("J: an entry of the concise DCF is refused") {
    harness h(5, {.config = {.retries = 0}});
    h.dev.abort_at = address{0x6065, 0};
    h.dev.abort_code = csdo::abort_code::value_too_high;
    h.dev.aborts = 5;
    h.run(axis_objects());
    CHECK(h.machine.status() == boot_status::configuration_failed);
    CHECK(master::code(h.machine.status()) == 'J');
    const auto e = *h.machine.error();
    REQUIRE(e.config);
    CHECK(e.config->item == 6U); // the seventh entry of the concise DCF
    CHECK(e.config->address == address{0x6065, 0});
    CHECK(e.config->name.empty()); // a concise DCF has no names
    CHECK(e.config->abort == csdo::abort_code::value_too_high);
    CHECK(h.nmt(co::nmt::command::start) == 0);
  }
  SUBCASE("K: no heartbeat within the consumer time") {
    harness h(5, {});
    auto o = axis_objects();
    o.consumer_time_ms = 250;
    h.run(o);
    CHECK(h.machine.status() == boot_status::no_heartbeat);
    CHECK(h.machine.error()->failure == boot_failure::no_heartbeat);
    CHECK(h.nmt(co::nmt::command::start) == 0);
  }
  SUBCASE("an empty concise DCF: nothing to download") {
    harness h(5, {});
    auto o = axis_objects();
    o.concise_dcf = {};
    h.run(o);
    CHECK(h.machine.status() == boot_status::ok);
    CHECK(h.dev.get({0x6065, 0}) == 2000U);
  }
}

TEST_CASE("boot 302: a malformed concise DCF is refused before anything is sent") {
  const std::vector<std::uint8_t> good(std::begin(axis_config::concise_dcf),
                                       std::end(axis_config::concise_dcf));
  auto truncated = good;
  truncated.pop_back();
  auto longer = good;
  longer.push_back(0);
  const std::vector<std::uint8_t> count_only{1, 0, 0};
  const std::vector<std::uint8_t> empty_entry{1, 0, 0, 0, 0x65, 0x60, 0, 0, 0, 0, 0};
  const std::vector<std::uint8_t> more_entries_than_bytes{2, 0, 0, 0, 0x65, 0x60, 0, 1, 0, 0, 0, 5};
  struct row {
    const std::vector<std::uint8_t> *dcf;
    errc e;
  };
  const row rows[] = {{&truncated, errc::truncated},
                      {&longer, errc::bad_length},
                      {&count_only, errc::truncated},
                      {&empty_entry, errc::bad_length},
                      {&more_entries_than_bytes, errc::truncated}};
  for (const auto &r : rows) {
    harness h(5, {});
    auto o = axis_objects();
    o.concise_dcf = *r.dcf;
    CHECK(h.machine.start(o, h.now).error() == r.e);
    CHECK(h.machine.state() == boot_state::idle);
    CHECK(master::check_concise_dcf(*r.dcf).error() == r.e);
  }
  CHECK(master::check_concise_dcf(good).value() == 8U);
}

TEST_CASE("boot 302: refusals") {
  csdo::client c(1);
  master::boot bad(0, c);
  CHECK(bad.start(axis_objects(), 0).error() == errc::invalid_argument);
  master::boot b(1, c);
  REQUIRE(b.start(axis_objects(), 0));
  CHECK(b.start(axis_objects(), 0).error() == errc::bad_state);
}

TEST_CASE("boot_status: the CiA 302-2 letters and their stable texts") {
  static_assert(master::code(boot_status::ok) == '\0');
  static_assert(master::code(boot_status::serial_mismatch) == 'O');
  const std::pair<boot_status, std::string_view> rows[] = {
      {boot_status::ok, "booted"},
      {boot_status::not_in_network_list, "A: not in the network list"},
      {boot_status::no_device_type, "B: no answer for the device type"},
      {boot_status::device_type_mismatch, "C: device type mismatch"},
      {boot_status::vendor_id_mismatch, "D: vendor-ID mismatch"},
      {boot_status::no_heartbeat_state, "E: no heartbeat for the node state"},
      {boot_status::no_guarding_state, "F: no guarding answer for the node state"},
      {boot_status::software_not_configured, "G: software version not configured"},
      {boot_status::software_mismatch, "H: software version mismatch"},
      {boot_status::software_update_failed, "I: software update failed"},
      {boot_status::configuration_failed, "J: configuration download failed"},
      {boot_status::no_heartbeat, "K: no heartbeat"},
      {boot_status::initially_operational, "L: initially operational"},
      {boot_status::product_code_mismatch, "M: product code mismatch"},
      {boot_status::revision_mismatch, "N: revision number mismatch"},
      {boot_status::serial_mismatch, "O: serial number mismatch"},
  };
  char letter = 'A';
  for (const auto &[s, text] : rows) {
    CHECK(master::to_string(s) == text);
    if (s != boot_status::ok) {
      CHECK(master::code(s) == letter);
      CHECK(text[0] == letter);
      ++letter;
    }
  }
  CHECK(letter == 'P');
  CHECK(master::to_string(static_cast<boot_status>('Z')) == "?");
  CHECK(master::retry_factor(0x01F40305U) == 3U);
  CHECK(master::guard_time_ms(0x01F40305U) == 500U);
}

TEST_CASE("configurator: a concise DCF runs like its configuration list") {
  csdo::client client(5, 100);
  sim::device dev(5);
  master::configurator run(client, {.verify = true});
  std::uint32_t now = 0;
  auto s = run.start_concise(axis_config::concise_dcf, now);
  REQUIRE(s);
  auto step = s.value();
  while (run.busy()) {
    std::vector<co::can_frame> replies;
    for (const auto &f : step.send) {
      for (const auto &r : dev.receive(f)) replies.push_back(r);
    }
    REQUIRE(replies.size() == 1U);
    step = run.on_frame(replies[0], ++now);
  }
  CHECK(run.state() == master::config_state::done);
  CHECK(run.completed() == 8U);
  CHECK(dev.get({0x6065, 0}) == 500U);
  CHECK(dev.get({0x1800, 1}) == 0x185U); // resolved for node 5 when the DCF was written
  CHECK(run.start_concise(std::span<const std::uint8_t>(axis_config::concise_dcf).first(10), now)
            .error() == errc::truncated);
}
