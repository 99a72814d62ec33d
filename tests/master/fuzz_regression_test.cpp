// Regression tests for inputs found by fuzz/fuzz_master.cpp (see fuzz/FINDINGS.md).
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/master/drive.hpp>

#include <doctest/doctest.h>

namespace master = fieldcodec::master;
namespace ds402 = fieldcodec::ds402;
using master::drive_state;

namespace {
// statuswords of the CiA 402 states (bit 5 quick stop set where the state has it)
constexpr std::uint16_t switch_on_disabled = 0x0040;
constexpr std::uint16_t ready_to_switch_on = 0x0021;
constexpr std::uint16_t switched_on = 0x0023;
constexpr std::uint16_t operation_enabled = 0x0027;
constexpr std::uint16_t not_ready = 0x0000;
constexpr std::uint16_t fault_reaction_active = 0x000F;
constexpr std::uint16_t fault = 0x0008;
} // namespace

// F26 (fuzz_master, drive): after a failure the machine kept the last controlword of its walk
// to operation enabled. An enable that timed out, or a drive that left operation enabled by
// itself, left 0x0F on the bus: a drive in ready to switch on or switched on was switched on
// and enabled again (transitions 3 + 4, 4) although the machine reported `failed`; the cycle
// that failed sent the walk's command too.
TEST_CASE("fuzz F26: a failed drive helper holds the drive, it never powers it up") {
  master::drive_options o;
  o.enable_timeout_ms = 100;
  master::drive d(o);
  REQUIRE(d.enable(0));
  CHECK(d.cycle(switch_on_disabled, 10).controlword == 0x06);
  CHECK(d.cycle(ready_to_switch_on, 20).controlword == 0x0F); // 3 + 4 asked for: enable()
  // the drive drops back instead and the timeout passes: failed, and no 0x0F any more
  auto s = d.cycle(ready_to_switch_on, 200);
  CHECK(s.state == drive_state::failed);
  CHECK(s.controlword == 0x06); // holds ready to switch on, in the failing cycle already
  CHECK(d.cycle(switched_on, 210).controlword == 0x07);
  CHECK(d.cycle(ready_to_switch_on, 220).controlword == 0x06);
  CHECK(d.cycle(switch_on_disabled, 230).controlword == 0x00);
  CHECK(d.cycle(not_ready, 240).controlword == 0x00);

  // enabled, then the drive leaves operation enabled by itself: reported, not re-enabled
  master::drive e;
  REQUIRE(e.enable(0));
  (void)e.cycle(ready_to_switch_on, 10);
  REQUIRE(e.cycle(operation_enabled, 20).state == drive_state::enabled);
  s = e.cycle(switched_on, 30);
  CHECK(s.state == drive_state::failed);
  CHECK(e.error()->failure == master::drive_failure::left_operation_enabled);
  CHECK(s.controlword == 0x07); // holds switched on (0x0F would be transition 4)
  CHECK(ds402::apply(ds402::state::switched_on, s.controlword, 0x0F).transition ==
        ds402::no_transition);
  CHECK(e.cycle(switched_on, 40).controlword == 0x07);
  // only a new command powers it up
  REQUIRE(e.enable(50));
  CHECK(e.cycle(switched_on, 60).controlword == 0x0F);
}

// F27 (fuzz_master, drive): a fault reset that waited — for a cycle with bit 7 low before a new
// edge, or while the drive showed fault reaction active — kept the deadline of the previous
// edge, already past: the step asked to be polled at a time before `now`.
TEST_CASE("fuzz F27: a fault reset's deadline is never in the past") {
  master::drive_options o;
  o.reset_timeout_ms = 50;
  o.reset_attempts = 3;
  o.read_error_code = false;
  master::drive d(o);
  (void)d.cycle(fault, 0);
  REQUIRE(d.state() == drive_state::fault);
  REQUIRE(d.reset_fault(0));
  auto s = d.cycle(fault, 10); // the edge
  CHECK(s.controlword == 0x80);
  REQUIRE(s.deadline);
  CHECK(*s.deadline == 60);
  s = d.cycle(fault, 100); // the attempt timed out: bit 7 low for a cycle
  CHECK(s.controlword == 0x00);
  CHECK_FALSE(s.deadline.has_value());
  s = d.cycle(fault, 110); // the next edge, with its own deadline
  CHECK(s.controlword == 0x80);
  REQUIRE(s.deadline);
  CHECK(*s.deadline == 160);
  s = d.cycle(fault_reaction_active, 300); // the drive reacts again: wait without a deadline
  CHECK(s.controlword == 0x00);
  CHECK_FALSE(s.deadline.has_value());
  s = d.cycle(fault, 310);
  CHECK(s.controlword == 0x80);
  REQUIRE(s.deadline);
  CHECK(*s.deadline == 360);
  CHECK(d.cycle(switch_on_disabled, 320).state == drive_state::idle);
}
