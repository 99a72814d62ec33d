// host::remote_node as a network machine: the node's heartbeat (state, boot-up, loss), EMCY and
// TPDOs as events; its PDOs by name, read from the device's mapping by SDO or configured through
// master::plan_pdo, decoded and encoded through od's one value path. The device is the
// simulated XENAX of the examples (tests/host/sim_bus.hpp). Bad input: malformed heartbeat and
// EMCY frames, a short TPDO, unknown and ambiguous names, values outside the limits or the
// mapped bits, a mapping the dictionary refuses.
#include "sim_bus.hpp"

#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/ds402/statusword.hpp>
#include <fieldcodec/host/network.hpp>
#include <fieldcodec/host/remote_node.hpp>
#include <fieldcodec/xenax/canopen_units.hpp>

#include <doctest/doctest.h>

namespace co = fieldcodec::canopen;
namespace host = fieldcodec::host;
namespace od = fieldcodec::od;
namespace x = fieldcodec::dictionaries::xenax_canopen;
using fieldcodec::errc;
using kind = host::node_event::kind;
using namespace std::chrono_literals;

namespace {

/// Events until `k` (or none within `ms`); the ones before it are returned in `skipped`.
std::optional<host::node_event> until(host::remote_node &n, kind k, std::chrono::milliseconds ms,
                                      std::vector<host::node_event> *skipped = nullptr) {
  const auto end = std::chrono::steady_clock::now() + ms;
  while (std::chrono::steady_clock::now() < end) {
    auto e = n.wait_event(std::chrono::duration_cast<std::chrono::milliseconds>(
        end - std::chrono::steady_clock::now()));
    if (!e) return std::nullopt;
    if (e->what == k) return e;
    if (skipped != nullptr) skipped->push_back(*e);
  }
  return std::nullopt;
}

} // namespace

TEST_CASE("remote_node events: boot-up, NMT state, heartbeat lost and resumed, EMCY") {
  fieldcodec::test::sim_bus bus(5);
  host::remote_node drive(bus, 5, x::dictionary, fieldcodec::xenax::canopen_units);
  auto boot = drive.wait_event(200ms); // the drive's boot-up at power-on
  REQUIRE(boot);
  CHECK(boot->what == kind::boot_up);
  CHECK(drive.nmt_state() == co::nmt::state::boot_up);

  // heartbeats (the XENAX's 1017h is read-only 0: another node's producer, injected)
  drive.watch_heartbeat(40);
  bus.inject("705#7F");
  auto first = until(drive, kind::state, 200ms);
  REQUIRE(first);
  CHECK(first->state == co::nmt::state::pre_operational);
  bus.inject("705#7F"); // the same state: no event
  bus.inject("705#05");
  auto op = until(drive, kind::state, 200ms);
  REQUIRE(op);
  CHECK(op->state == co::nmt::state::operational);
  CHECK(drive.nmt_state() == co::nmt::state::operational);
  CHECK(drive.pending_events() == 0);

  // no heartbeat for 40 ms: lost, once; the next one: resumed
  auto lost = drive.wait_event(300ms);
  REQUIRE(lost);
  CHECK(lost->what == kind::heartbeat_lost);
  CHECK(lost->state == co::nmt::state::operational);
  CHECK_FALSE(drive.wait_event(60ms));
  bus.inject("705#05");
  auto resumed = drive.wait_event(100ms);
  REQUIRE(resumed);
  CHECK(resumed->what == kind::heartbeat_resumed);

  // reset node: boot-up again
  REQUIRE(drive.send_nmt(co::nmt::command::reset_node));
  auto again = until(drive, kind::boot_up, 300ms);
  REQUIRE(again);
  CHECK(drive.nmt_state() == co::nmt::state::boot_up);

  // EMCY from the bus (canopen::emcy's decoder): 2310h, register 03h, manufacturer bytes
  bus.inject("085#1023030102030405");
  auto emcy = until(drive, kind::emcy, 100ms);
  REQUIRE(emcy);
  CHECK(emcy->emcy.error_code == 0x2310);
  CHECK(emcy->emcy.error_register == 0x03);
  CHECK(emcy->emcy.manufacturer == std::array<std::uint8_t, 5>{1, 2, 3, 4, 5});
  CHECK(drive.last_emcy()->error_code == 0x2310);
  bus.inject("086#1023030102030405"); // node 6's: not this node's
  bus.inject("085#0000000000000000"); // error reset
  auto reset = until(drive, kind::emcy, 100ms);
  REQUIRE(reset);
  CHECK(reset->emcy.error_code == 0);
}

TEST_CASE("remote_node events: malformed heartbeat and EMCY frames are reported, not taken") {
  fieldcodec::test::sim_bus bus(5);
  host::remote_node drive(bus, 5, x::dictionary);
  REQUIRE(until(drive, kind::boot_up, 200ms));
  bus.inject("085#102303"); // EMCY of 3 bytes
  bus.inject("705#0500");   // heartbeat of 2 bytes
  bus.inject("705#03");     // state 3: not a CiA 301 state
  bus.inject("705#85");     // bit 7: a guarding toggle, no heartbeat
  bus.inject("705#R");      // a guarding request (the master's): ignored
  for (const errc want :
       {errc::bad_length, errc::bad_length, errc::out_of_range, errc::out_of_range}) {
    auto e = drive.wait_event(100ms);
    REQUIRE(e);
    CHECK(e->what == kind::bad_frame);
    CHECK(e->code == want);
  }
  CHECK_FALSE(drive.last_emcy());
  CHECK(drive.nmt_state() == co::nmt::state::boot_up); // unchanged
  CHECK_FALSE(drive.wait_event(20ms));
}

TEST_CASE("remote_node PDOs by name: the device's mapping, TPDO values, RPDOs checked") {
  fieldcodec::test::sim_bus bus(5);
  host::remote_node drive(bus, 5, x::dictionary, fieldcodec::xenax::canopen_units);
  REQUIRE(until(drive, kind::boot_up, 200ms));
  auto r = drive.read_pdos();
  REQUIRE_MESSAGE(r, r.error().what);
  const host::remote_pdo *t1 = drive.pdo(co::pdo::direction::tpdo, 1);
  REQUIRE(t1 != nullptr);
  CHECK(t1->cob_id == 0x185);
  CHECK(t1->valid);
  REQUIRE(t1->map.size() == 1);
  CHECK(t1->map[0].index == 0x6041);
  CHECK(drive.mapping_of(co::pdo::direction::rpdo, {0x6040, 0})->number == 1);
  CHECK(drive.pdo_object("Statusword").value() == od::address{0x6041, 0});
  CHECK(drive.pdo_object("controlword").value() == od::address{0x6040, 0}); // case ignored
  CHECK(drive.pdo_object("6064h:00").value() == od::address{0x6064, 0});

  // not received yet
  auto early = drive.received("Statusword");
  REQUIRE_FALSE(early);
  CHECK(early.error().code == errc::bad_state);

  REQUIRE(drive.send_nmt(co::nmt::command::start));
  // shutdown (6) in RPDO 1: the drive goes to ready to switch on and sends TPDO 1
  REQUIRE(drive.set_pdo("Controlword", od::unsigned_number(6)));
  REQUIRE(drive.send_pdo(1));
  std::uint16_t sw = 0;
  for (int i = 0; i < 20 && sw != 0x0621; ++i) { // ready to switch on, remote, target reached
    auto e = until(drive, kind::pdo, 200ms);
    REQUIRE(e);
    if (e->pdo != 1) continue;
    auto v = drive.received("Statusword", {.unit = od::value_unit::raw});
    REQUIRE(v);
    sw = static_cast<std::uint16_t>(v.value().to_uint64().value());
  }
  CHECK(fieldcodec::ds402::decode_state(sw).value() ==
        fieldcodec::ds402::state::ready_to_switch_on);
  CHECK(bus.count(0x205) == 1);
  CHECK(drive.received_text("Statusword").value() == "1569"); // 0x0621

  // configure RPDO 2 with 6073h (mA by the vendor's rule) and 607Ah: by name, checked
  const co::pdo::mapping_entry rx2[] = {{0x6073, 0, 16}, {0x607A, 0, 32}};
  auto c = drive.configure_pdo({.dir = co::pdo::direction::rpdo, .number = 2, .entries = rx2});
  REQUIRE_MESSAGE(c, c.error().what);
  REQUIRE(drive.set_pdo("Limit I_Force", "1500 mA"));
  REQUIRE(drive.set_pdo(od::address{0x607A, 0}, od::signed_number(-2)));
  REQUIRE(drive.send_pdo(2));
  CHECK(bus.sent.back().id == 0x305);
  CHECK(bus.sent.back().dlc == 6);
  CHECK(bus.sent.back().data[0] == 150); // raw 150 = 1500 mA
  CHECK(bus.sent.back().data[2] == 0xFE);
  CHECK(bus.sent.back().data[5] == 0xFF);

  // refused, nothing changed
  const auto before = drive.pdo(co::pdo::direction::rpdo, 2)->data;
  auto high = drive.set_pdo("Limit I_Force", "20010 mA");
  REQUIRE_FALSE(high);
  CHECK(high.error().value.issue == od::value_issue::high_limit);
  CHECK(high.error().what == "node 5, 6073h:00: '20010 mA' refused: above the high limit 20000 mA");
  auto unknown = drive.set_pdo("Torque Actual", od::signed_number(1));
  REQUIRE_FALSE(unknown);
  CHECK(unknown.error().code == errc::unknown_object);
  CHECK(unknown.error().what == "node 5, 'Torque Actual': no PDO of the node maps it");
  auto tpdo_only = drive.set_pdo("Statusword", od::unsigned_number(1)); // in a TPDO, no RPDO
  REQUIRE_FALSE(tpdo_only);
  CHECK(tpdo_only.error().code == errc::unknown_object);
  auto not_in_tpdo = drive.received("Controlword");
  REQUIRE_FALSE(not_in_tpdo);
  CHECK(not_in_tpdo.error().code == errc::unknown_object);
  CHECK(drive.pdo(co::pdo::direction::rpdo, 2)->data == before);
  auto no_pdo = drive.send_pdo(9);
  REQUIRE_FALSE(no_pdo);
  CHECK(no_pdo.error().code == errc::unknown_object);

  // a mapping the dictionary refuses: nothing sent
  const std::size_t frames = bus.sent.size();
  const co::pdo::mapping_entry bad[] = {{0x6041, 0, 16}}; // read-only into an RPDO
  auto refused =
      drive.configure_pdo({.dir = co::pdo::direction::rpdo, .number = 2, .entries = bad});
  REQUIRE_FALSE(refused);
  CHECK(refused.error().code == errc::access_denied);
  CHECK(bus.sent.size() == frames);

  // a TPDO shorter than its mapping: reported, not taken
  bus.inject("185#31");
  auto e = until(drive, kind::bad_frame, 100ms);
  REQUIRE(e);
  CHECK(e->code == errc::bad_length);
  CHECK(drive.received("Statusword", {.unit = od::value_unit::raw}).value().to_uint64().value() ==
        0x0621);
}

TEST_CASE("remote_node on a host::network: events without blocking calls") {
  fieldcodec::test::sim_bus bus(5);
  host::remote_node drive(bus, 5, x::dictionary);
  host::network net(bus);
  net.add(drive);
  REQUIRE(net.run_until([&] { return drive.pending_events() > 0; }, 200ms));
  CHECK(drive.next_event()->what == kind::boot_up);
  bus.inject("085#1023030102030405");
  REQUIRE(net.run_until([&] { return drive.pending_events() > 0; }, 200ms));
  CHECK(drive.next_event()->emcy.error_code == 0x2310);
}

TEST_CASE("docs/host.md: PDOs by name") {
  fieldcodec::test::sim_bus bus(5);
  host::remote_node drive(bus, 5, x::dictionary, fieldcodec::xenax::canopen_units);
  auto pdos = drive.read_pdos();                                   // by SDO, checked
  auto started = drive.send_nmt(co::nmt::command::start);          // PDOs run in operational
  auto set = drive.set_pdo("Controlword", od::unsigned_number(6)); // shutdown
  auto sent = drive.send_pdo(1);                                   // 205h [06 00]
  while (auto e = drive.wait_event(100ms)) {
    if (e->what == host::node_event::kind::pdo) break; // TPDO 1 (185h) arrived
  }
  auto sw = drive.received_text("Statusword"); // "1569": 0621h, ready to switch on
  auto refused = drive.set_pdo("Statusword", od::unsigned_number(1)); // unknown_object: no RPDO
  CHECK(pdos);
  CHECK(started);
  CHECK(set);
  CHECK(sent);
  CHECK(bus.count(0x205) == 1);
  REQUIRE(sw);
  CHECK(sw.value() == "1569");
  REQUIRE_FALSE(refused);
  CHECK(refused.error().code == errc::unknown_object);
}

TEST_CASE("remote_node: a bus that fails stops listen, send_pdo and send_nmt with its line") {
  fieldcodec::test::sim_bus bus(5);
  host::remote_node drive(bus, 5, x::dictionary);
  REQUIRE(drive.read_pdos());
  bus.broken = true;
  auto l = drive.listen(20ms);
  REQUIRE_FALSE(l);
  CHECK(l.error().bus_failed);
  CHECK(l.error().what == "node 5: sim0: read: Input/output error");
  while (drive.next_event()) {
  }                                    // the boot-up, taken in before
  CHECK_FALSE(drive.wait_event(20ms)); // no event, no hang
  auto p = drive.send_pdo(1);
  REQUIRE_FALSE(p);
  CHECK(p.error().what == "node 5: sim0: write: Input/output error");
  CHECK_FALSE(drive.send_nmt(co::nmt::command::start));
}
