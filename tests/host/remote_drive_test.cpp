// host::remote_drive: the CiA 402 helper that sets itself up, against the simulated XENAX of
// the examples (examples/sim_drive.hpp in the same process, tests/host/sim_bus.hpp): the words
// in the drive's own PDO mapping (RPDO 1 6040h, TPDO 1 6041h), or by SDO when no valid PDO
// carries them; enable, profile position, disable. Bad input: a target outside 607Ah's limits,
// a command before setup, a command the machine refuses, a fault with its EMCY.
// And the guide's example (examples/move_axis.hpp, docs/host.md).
#include "../../examples/move_axis.hpp"
#include "sim_bus.hpp"

#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/host/remote_drive.hpp>
#include <fieldcodec/xenax/canopen_units.hpp>

#include <doctest/doctest.h>

namespace co = fieldcodec::canopen;
namespace ds402 = fieldcodec::ds402;
namespace host = fieldcodec::host;
namespace od = fieldcodec::od;
namespace x = fieldcodec::dictionaries::xenax_canopen;
using fieldcodec::errc;
using namespace std::chrono_literals;

TEST_CASE("remote_drive: the words in the drive's PDOs; enable, profile position, disable") {
  fieldcodec::test::sim_bus bus(5);
  host::remote_node node(bus, 5, x::dictionary, fieldcodec::xenax::canopen_units);
  host::remote_drive axis(node);

  auto early = axis.enable(); // before setup
  REQUIRE_FALSE(early);
  CHECK(early.error().code == errc::bad_state);

  auto s = axis.setup();
  REQUIRE_MESSAGE(s, s.error().what);
  CHECK(axis.channels().controlword_rpdo == 1);
  CHECK(axis.channels().statusword_tpdo == 1);
  CHECK(axis.channels().position_rpdo == 2); // the XENAX default: RPDO 2 = 6040h, 607Ah
  CHECK(axis.channels().mode_display_tpdo == 0);
  CHECK(bus.count(0x000) == 1); // NMT start: PDOs run in operational

  auto e = axis.enable();
  REQUIRE_MESSAGE(e, e.error().what);
  CHECK(bus.drive().state() == ds402::state::operation_enabled);
  CHECK(bus.count(0x205) >= 2); // controlwords in RPDO 1
  const std::size_t sdo_writes = bus.count(0x605);

  auto m = axis.switch_mode(ds402::mode::profile_position);
  REQUIRE_MESSAGE(m, m.error().what);
  CHECK(axis.machine().mode() == 1);

  // outside 607Ah's limits: refused before anything is sent
  const std::size_t frames = bus.sent.size();
  auto big = axis.move_to(od::signed_number(std::int64_t{1} << 31));
  REQUIRE_FALSE(big);
  CHECK(big.error().code == errc::out_of_range);
  REQUIRE(big.error().node);
  CHECK(big.error().node->value.issue == od::value_issue::high_limit);
  CHECK(bus.sent.size() == frames);

  auto mv = axis.move_to(od::signed_number(2000));
  REQUIRE_MESSAGE(mv, mv.error().what);
  CHECK(bus.drive().position() == doctest::Approx(2000));
  CHECK((axis.last_statusword() & ds402::sw::target_reached) != 0);
  auto back = axis.move_to(od::signed_number(-500), true); // relative
  REQUIRE_MESSAGE(back, back.error().what);
  CHECK(bus.drive().position() == doctest::Approx(1500));
  CHECK(bus.count(0x605) > sdo_writes); // 6060h by SDO
  CHECK(bus.count(0x305) > 0);          // 607Ah in RPDO 2

  auto d = axis.disable();
  REQUIRE_MESSAGE(d, d.error().what);
  CHECK(bus.drive().state() == ds402::state::switch_on_disabled);
  // the machine refuses a move when not enabled
  auto refused = axis.move_to(od::signed_number(10));
  REQUIRE_FALSE(refused);
  CHECK(refused.error().code == errc::bad_state);
}

TEST_CASE("remote_drive: no valid PDO carries the words: everything by SDO") {
  fieldcodec::test::sim_bus bus(5);
  host::remote_node node(bus, 5, x::dictionary, fieldcodec::xenax::canopen_units);
  // every RPDO and TPDO not valid (COB-ID bit 31), written through the value path
  for (std::uint16_t n = 0; n < 4; ++n) {
    for (const unsigned base : {0x1400U, 0x1800U}) {
      const od::address a{static_cast<std::uint16_t>(base + n), 1};
      if (!x::dictionary.contains(a)) continue;
      auto cob = node.read(a, {.unit = od::value_unit::raw});
      REQUIRE(cob);
      const auto v = cob.value().to_uint64().value() | 0x80000000U;
      REQUIRE(node.write(a, od::unsigned_number(v), {.unit = od::value_unit::raw}));
    }
  }
  host::remote_drive axis(node);
  REQUIRE(axis.setup());
  CHECK(axis.channels().controlword_rpdo == 0);
  CHECK(axis.channels().statusword_tpdo == 0);
  auto e = axis.enable();
  REQUIRE_MESSAGE(e, e.error().what);
  REQUIRE(axis.switch_mode(ds402::mode::profile_position));
  auto mv = axis.move_to(od::signed_number(300));
  REQUIRE_MESSAGE(mv, mv.error().what);
  CHECK(bus.drive().position() == doctest::Approx(300));
  CHECK(bus.count(0x205) == 0); // no RPDO
  CHECK(bus.count(0x305) == 0);
  CHECK(bus.count(0x000) == 0); // no NMT start either
}

TEST_CASE("remote_drive: a fault comes back with the drive's EMCY") {
  fieldcodec::test::sim_bus bus(5);
  host::remote_node node(bus, 5, x::dictionary, fieldcodec::xenax::canopen_units);
  host::remote_drive axis(node, {.command_timeout = 2000ms});
  REQUIRE(axis.setup());
  REQUIRE(axis.enable());
  // an EMCY, then a fault statusword in TPDO 1 (as another producer would put it on the bus)
  bus.inject("085#1023030000000000");
  bus.inject("185#0800");
  auto r = axis.cycle_for(50ms);
  REQUIRE_FALSE(r);
  REQUIRE(r.error().drive);
  CHECK(r.error().drive->failure == fieldcodec::master::drive_failure::fault);
  REQUIRE(r.error().drive->emcy);
  CHECK(r.error().drive->emcy->error_code == 0x2310);
  CHECK(r.error().what ==
        "node 5: drive fault (drive: fault, statusword 0008h), EMCY 2310h, 603Fh 0000h");
}

TEST_CASE("docs/host.md: enabling a drive and moving it (examples/move_axis.hpp)") {
  fieldcodec::test::sim_bus bus(5);
  CHECK(fieldcodec::examples::move_axis(bus, 1234) == 0);
  CHECK(bus.drive().position() == doctest::Approx(1234));
  CHECK(bus.drive().state() == ds402::state::operation_enabled);
}

TEST_CASE("remote_drive: a PDO on SYNC is not used (no SYNC producer runs)") {
  fieldcodec::test::sim_bus bus(5);
  host::remote_node node(bus, 5, x::dictionary, fieldcodec::xenax::canopen_units);
  // TPDO 1 (6041h) synchronous, every SYNC: TPDO 2 (6041h, 6064h; event-driven) is taken
  REQUIRE(node.write(od::address{0x1800, 2}, od::unsigned_number(1)));
  host::remote_drive axis(node);
  REQUIRE(axis.setup());
  CHECK(axis.channels().statusword_tpdo == 2);
  CHECK(axis.channels().controlword_rpdo == 1);
  auto e = axis.enable();
  REQUIRE_MESSAGE(e, e.error().what);
  CHECK(bus.drive().state() == ds402::state::operation_enabled);
}
