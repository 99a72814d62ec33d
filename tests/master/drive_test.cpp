// master::drive, the CiA 402 drive helper, against the scripted drive of sim_drive.hpp; the
// vendor rules come in as drive profiles (plain CiA 402, the XENAX's, and one made up here).
#include "sim_drive.hpp"

#include <fieldcodec/master/drive.hpp>
#include <fieldcodec/xenax/drive_profile.hpp>
#include <fieldcodec/xenax/error_code.hpp>
#include <fieldcodec/xenax/homing.hpp>

#include <array>
#include <cstdint>

#include <doctest/doctest.h>

#include <algorithm>

namespace master = fieldcodec::master;
namespace ds402 = fieldcodec::ds402;
namespace xenax = fieldcodec::xenax;
using fieldcodec::errc;
using master::drive_failure;
using master::drive_state;

namespace {

/// Enabled in `mode` (switched by SDO), ready for a motion command.
void enable_in(sim::bench &b, std::int8_t mode) {
  REQUIRE(b.axis.switch_mode(mode, b.now));
  b.run();
  REQUIRE(b.axis.state() == drive_state::idle);
  REQUIRE(b.axis.enable(b.now));
  b.run();
  REQUIRE(b.axis.state() == drive_state::enabled);
  b.cycle();
}

int rising_edges(const std::vector<std::uint16_t> &cws, std::uint16_t bit) {
  int n = 0;
  for (std::size_t i = 1; i < cws.size(); ++i) {
    if ((cws[i] & bit) != 0U && (cws[i - 1] & bit) == 0U) ++n;
  }
  return n;
}

} // namespace

TEST_CASE("drive: enable walks switch on disabled -> operation enabled with 0x06, 0x0F") {
  sim::bench b;
  b.cycle();
  CHECK(b.last.controlword == 0x0000);
  REQUIRE(b.axis.enable(b.now));
  auto s = b.cycle();
  CHECK(s.controlword == 0x0006);
  CHECK(s.state == drive_state::enabling);
  REQUIRE(s.deadline);
  s = b.cycle();
  CHECK(s.controlword == 0x000F); // ready to switch on -> 3 + 4 at once
  s = b.cycle();
  CHECK(s.state == drive_state::enabled);
  CHECK(s.controlword == 0x000F);
  CHECK_FALSE(s.deadline);
  CHECK(b.dev.st == ds402::state::operation_enabled);
  CHECK_FALSE(b.axis.error());
}

TEST_CASE("drive: enable times out when the drive stays not ready to switch on") {
  sim::bench b({.enable_timeout_ms = 100});
  b.dev.st = ds402::state::not_ready_to_switch_on;
  REQUIRE(b.axis.enable(b.now));
  b.run();
  CHECK(b.axis.state() == drive_state::failed);
  REQUIRE(b.axis.error());
  CHECK(b.axis.error()->failure == drive_failure::enable_timeout);
  CHECK(b.axis.error()->is(errc::timeout));
  CHECK(b.axis.error()->seen == ds402::state::not_ready_to_switch_on);
  CHECK(b.controlwords.back() == 0x0000);
}

TEST_CASE("drive: the enable timeout works across the wrap-around of the counter") {
  sim::bench b({.enable_timeout_ms = 100});
  b.now = 0xFFFF'FFC0U;
  b.dev.st = ds402::state::not_ready_to_switch_on;
  REQUIRE(b.axis.enable(b.now));
  const int cycles = b.run();
  CHECK(cycles == 11); // 100 ms at 10 ms per cycle, not immediately and not never
  CHECK(b.axis.error()->failure == drive_failure::enable_timeout);
}

TEST_CASE("drive: disable, quick stop and halt") {
  sim::bench b;
  REQUIRE(b.axis.enable(b.now));
  b.run();
  REQUIRE(b.axis.state() == drive_state::enabled);

  SUBCASE("disable to switch on disabled") {
    REQUIRE(b.axis.disable(b.now));
    b.run();
    CHECK(b.axis.state() == drive_state::idle);
    CHECK(b.dev.st == ds402::state::switch_on_disabled);
    CHECK(b.controlwords.back() == 0x0000);
  }
  SUBCASE("disable to switched on") {
    REQUIRE(b.axis.disable(b.now, ds402::state::switched_on));
    b.run();
    CHECK(b.dev.st == ds402::state::switched_on);
    CHECK(b.controlwords.back() == 0x0007);
    b.cycle();
    CHECK(b.last.controlword == 0x0007); // held
  }
  SUBCASE("disable refuses other targets") {
    CHECK(b.axis.disable(b.now, ds402::state::operation_enabled).error() == errc::invalid_argument);
    CHECK(b.axis.disable(b.now, ds402::state::fault).error() == errc::invalid_argument);
  }
  SUBCASE("quick stop") {
    b.axis.quick_stop(b.now);
    b.run();
    CHECK(b.axis.state() == drive_state::idle);
    CHECK(b.dev.st == ds402::state::quick_stop_active);
    CHECK(b.controlwords.back() == 0x0002);
    b.cycle();
    CHECK(b.last.controlword == 0x0002);
    REQUIRE(b.axis.enable(b.now)); // transition 16
    b.run();
    CHECK(b.dev.st == ds402::state::operation_enabled);
  }
  SUBCASE("halt sets bit 8 on top of the command") {
    b.axis.halt(true);
    CHECK(b.cycle().controlword == 0x010F);
    b.axis.halt(false);
    CHECK(b.cycle().controlword == 0x000F);
  }
}

TEST_CASE("drive: the drive leaving operation enabled by itself is reported") {
  sim::bench b;
  REQUIRE(b.axis.enable(b.now));
  b.run();
  b.dev.st = ds402::state::switch_on_disabled;
  b.cycle();
  CHECK(b.axis.state() == drive_state::failed);
  CHECK(b.axis.error()->failure == drive_failure::left_operation_enabled);
  CHECK(b.axis.error()->seen == ds402::state::switch_on_disabled);
}

TEST_CASE("drive: a statusword that matches no state") {
  sim::bench b;
  (void)b.axis.cycle(0x0001, b.now);
  CHECK(b.axis.state() == drive_state::failed);
  CHECK(b.axis.error()->failure == drive_failure::bad_statusword);
  CHECK(b.axis.error()->statusword == 0x0001);
}

TEST_CASE("drive: switch mode by SDO, confirmed by reading 6061h") {
  sim::bench b;
  b.dev.mode_delay = 3;
  REQUIRE(b.axis.switch_mode(ds402::mode::profile_position, b.now));
  b.run();
  CHECK(b.axis.state() == drive_state::idle);
  CHECK(b.axis.mode() == std::int8_t{1});
  REQUIRE(b.dev.requests.size() >= 2U);
  CHECK(b.dev.requests[0] == master::write_request({0x6060, 0}, 1, 1));
  CHECK(b.dev.requests[1] == master::read_request({0x6061, 0}));
  // 6061h is read again until it follows
  CHECK(std::count(b.dev.requests.begin(), b.dev.requests.end(),
                   master::read_request({0x6061, 0})) >= 2);
}

TEST_CASE("drive: switch mode with 6061h in a PDO reads nothing by SDO") {
  sim::bench b;
  b.mode_in_pdo = true;
  b.dev.mode_delay = 2;
  REQUIRE(b.axis.switch_mode(ds402::mode::homing, b.now));
  b.run();
  CHECK(b.axis.state() == drive_state::idle);
  CHECK(b.axis.mode() == std::int8_t{6});
  REQUIRE(b.dev.requests.size() == 1U);
  CHECK(b.dev.requests[0] == master::write_request({0x6060, 0}, 6, 1));
}

TEST_CASE("drive: a mode the drive never confirms") {
  sim::bench b({.mode_timeout_ms = 200});
  b.dev.follows_mode = false;
  REQUIRE(b.axis.switch_mode(ds402::mode::profile_velocity, b.now));
  b.run();
  CHECK(b.axis.state() == drive_state::failed);
  CHECK(b.axis.error()->failure == drive_failure::mode_not_confirmed);
  CHECK(b.axis.error()->is(errc::timeout));
  CHECK(b.axis.error()->mode == 0); // what 6061h showed
}

TEST_CASE("drive: the drive aborts the write of 6060h") {
  sim::bench b;
  b.dev.abort_next = fieldcodec::canopen::sdo::abort_code::value_too_high;
  REQUIRE(b.axis.switch_mode(std::int8_t{5}, b.now));
  b.run();
  CHECK(b.axis.state() == drive_state::failed);
  REQUIRE(b.axis.error());
  CHECK(b.axis.error()->failure == drive_failure::sdo_failed);
  CHECK(b.axis.error()->is(errc::aborted));
  REQUIRE(b.axis.error()->sdo);
  CHECK(b.axis.error()->sdo->abort == fieldcodec::canopen::sdo::abort_code::value_too_high);
  CHECK(b.axis.error()->sdo->address == fieldcodec::od::address{0x6060, 0});
}

TEST_CASE("drive: a drive that changes its mode by itself") {
  sim::bench b;
  b.mode_in_pdo = true;
  enable_in(b, 1);
  REQUIRE(b.axis.move_to(1000, b.now));
  b.cycle();
  b.dev.mode = 3; // the drive switches to profile velocity on its own
  b.cycle();
  CHECK(b.axis.state() == drive_state::failed);
  CHECK(b.axis.error()->failure == drive_failure::mode_changed);
  CHECK(b.axis.error()->mode == 3);
  CHECK((b.last.controlword & 0x0070U) == 0U);                // mode bits dropped
  CHECK(b.axis.move_to(0, b.now).error() == errc::bad_state); // pp is no longer the mode
}

TEST_CASE("drive: profile position set-point handshake, absolute and relative") {
  sim::bench b;
  b.mode_in_pdo = true;
  enable_in(b, 1);
  const auto first = b.controlwords.size();
  REQUIRE(b.axis.move_to(5000, b.now));
  b.run();
  CHECK(b.axis.state() == drive_state::enabled);
  CHECK(b.dev.position == 5000);
  // bit 4 raised once, held until the acknowledge, then released; target reached ends the move
  std::vector<std::uint16_t> cws(b.controlwords.begin() + static_cast<std::ptrdiff_t>(first),
                                 b.controlwords.end());
  REQUIRE(cws.size() >= 3U);
  CHECK(cws[0] == 0x001F);
  CHECK(cws[1] == 0x000F);
  CHECK(rising_edges(b.controlwords, 0x10) == 1);

  REQUIRE(b.axis.move_to(-300, b.now, true));
  CHECK(b.cycle().controlword == 0x005F); // relative
  b.run();
  CHECK(b.dev.position == 4700);

  REQUIRE(b.axis.move_to(100, b.now, false, true));
  CHECK(b.cycle().controlword == 0x003F); // change set immediately
  b.run();
  CHECK(b.dev.position == 100);
}

TEST_CASE("drive: a new move while one runs waits for the acknowledge to drop") {
  sim::bench b;
  b.mode_in_pdo = true;
  b.dev.move_cycles = 10;
  enable_in(b, 1);
  REQUIRE(b.axis.move_to(5000, b.now));
  b.cycle(); // 0x1F
  b.cycle(); // acknowledged, released
  REQUIRE(b.axis.move_to(7000, b.now, false, true));
  b.run();
  CHECK(b.dev.position == 7000);
  CHECK(rising_edges(b.controlwords, 0x10) == 2);
}

TEST_CASE("drive: profile position target written by SDO") {
  sim::bench b({.target_over_sdo = true});
  enable_in(b, 1);
  b.dev.requests.clear();
  REQUIRE(b.axis.move_to(-1234, b.now));
  auto s = b.cycle();
  REQUIRE(s.sdo);
  CHECK(*s.sdo == master::write_request({0x607A, 0}, static_cast<std::uint32_t>(-1234), 4));
  CHECK((s.controlword & 0x10U) == 0U); // bit 4 only after the write completed
  b.run();
  CHECK(b.dev.position == -1234);
}

TEST_CASE("drive: a set-point that is never acknowledged") {
  sim::bench b({.set_point_timeout_ms = 100});
  enable_in(b, 1);
  b.dev.never_ack = true;
  REQUIRE(b.axis.move_to(5000, b.now));
  b.run();
  CHECK(b.axis.state() == drive_state::failed);
  CHECK(b.axis.error()->failure == drive_failure::set_point_not_acknowledged);
  CHECK(b.axis.error()->is(errc::timeout));
  b.cycle();
  CHECK(b.last.controlword == 0x000F); // bit 4 dropped, still enabled
  CHECK(b.dev.st == ds402::state::operation_enabled);
}

TEST_CASE("drive: a move that never reaches its target") {
  sim::bench b({.move_timeout_ms = 100});
  enable_in(b, 1);
  b.dev.move_cycles = 1000;
  REQUIRE(b.axis.move_to(5000, b.now));
  b.run();
  CHECK(b.axis.error()->failure == drive_failure::move_timeout);
}

TEST_CASE("drive: following error during a move") {
  sim::bench b;
  enable_in(b, 1);
  b.dev.move_cycles = 10;
  REQUIRE(b.axis.move_to(5000, b.now));
  b.cycle();
  b.cycle();
  b.dev.following_error = true;
  b.cycle();
  CHECK(b.axis.error()->failure == drive_failure::following_error);
}

TEST_CASE("drive: a fault in the middle of a move reports 603Fh and the EMCY (XENAX)") {
  sim::bench b({.profile = xenax::profile});
  enable_in(b, 1);
  b.dev.move_cycles = 20;
  REQUIRE(b.axis.move_to(5000, b.now));
  b.cycle();
  b.cycle();
  b.cycle();
  // the drive faults with XENAX error 50 and sends its EMCY first
  b.dev.fault(0xFF32);
  b.axis.on_emcy({0xFF32, 0x81, {}});
  b.dev.requests.clear();
  auto s = b.cycle();
  CHECK(s.state == drive_state::fault);
  CHECK(s.controlword == 0x0000);
  REQUIRE(b.dev.requests.size() == 1U);
  CHECK(b.dev.requests[0] == master::read_request({0x603F, 0}));
  const auto e = b.axis.error();
  REQUIRE(e);
  CHECK(e->failure == drive_failure::fault);
  CHECK(e->seen == ds402::state::fault);
  CHECK(e->error_code == 0xFF32);
  REQUIRE(e->emcy);
  CHECK(e->emcy->error_code == 0xFF32);
  CHECK(e->emcy->error_register == 0x81);
  REQUIRE(e->error_code_read);
  CHECK(xenax::decode_error_code(e->error_code).value() == xenax::error_following);
  CHECK(b.axis.move_to(0, b.now).error() == errc::bad_state);
  CHECK(b.axis.enable(b.now).error() == errc::bad_state);

  // reset, enable again
  REQUIRE(b.axis.reset_fault(b.now));
  b.run();
  CHECK(b.axis.state() == drive_state::idle);
  CHECK(b.dev.st == ds402::state::switch_on_disabled);
  REQUIRE(b.axis.enable(b.now));
  b.run();
  CHECK(b.axis.state() == drive_state::enabled);
}

TEST_CASE("drive: an EMCY after the fault is attached; a non-XENAX code is not a XENAX error") {
  sim::bench b;
  REQUIRE(b.axis.enable(b.now));
  b.run();
  b.dev.fault(0x8611);
  b.cycle();
  b.axis.on_emcy({0x8611, 0x01, {1, 2, 3, 4, 5}});
  REQUIRE(b.axis.error()->emcy);
  CHECK(b.axis.error()->emcy->manufacturer[4] == 5);
  CHECK(b.axis.error()->error_code == 0x8611);
  CHECK(b.axis.error()->error_code_read);
  CHECK(xenax::decode_error_code(b.axis.error()->error_code).error() == errc::out_of_range);
}

TEST_CASE("drive: fault reset gives a rising edge and retries a bounded number of times") {
  SUBCASE("the second edge works") {
    sim::bench b({.reset_timeout_ms = 50, .reset_attempts = 3});
    b.dev.fault(0x1000);
    b.cycle();
    REQUIRE(b.axis.state() == drive_state::fault);
    b.dev.reset_refusals = 1;
    REQUIRE(b.axis.reset_fault(b.now));
    b.run();
    CHECK(b.axis.state() == drive_state::idle);
    CHECK(b.dev.st == ds402::state::switch_on_disabled);
    CHECK(rising_edges(b.controlwords, 0x80) == 2);
  }
  SUBCASE("all attempts refused") {
    sim::bench b({.reset_timeout_ms = 50, .reset_attempts = 3});
    b.dev.fault(0x1000);
    b.cycle();
    b.dev.reset_refusals = 100;
    REQUIRE(b.axis.reset_fault(b.now));
    b.run();
    CHECK(b.axis.state() == drive_state::failed);
    CHECK(b.axis.error()->failure == drive_failure::fault_reset_failed);
    CHECK(b.axis.error()->is(errc::timeout));
    CHECK(rising_edges(b.controlwords, 0x80) == 3);
    CHECK(b.controlwords.back() == 0x0000);
  }
  SUBCASE("reset outside fault is refused") {
    sim::bench b;
    b.cycle();
    CHECK(b.axis.reset_fault(b.now).error() == errc::bad_state);
  }
}

TEST_CASE("drive: homing with a XENAX reference method") {
  sim::bench b({.profile = xenax::profile});
  b.mode_in_pdo = true;
  enable_in(b, 6);
  b.dev.position = 777;
  b.dev.requests.clear();
  REQUIRE(b.axis.home(b.now, xenax::reference_method::linear_negative));
  auto s = b.cycle();
  REQUIRE(s.sdo);
  CHECK(*s.sdo == master::write_request({0x6098, 0}, 2, 1));
  // the attained bit left over from an earlier run does not end this one
  s = b.cycle();
  CHECK(s.controlword == 0x001F);
  CHECK(s.state == drive_state::homing);
  b.run();
  CHECK(b.axis.state() == drive_state::enabled);
  CHECK(b.dev.homing_method == 2);
  CHECK(b.dev.position == 0);
  CHECK(b.last.controlword == 0x000F);
}

TEST_CASE("drive: homing error and homing timeout") {
  SUBCASE("error") {
    sim::bench b;
    enable_in(b, 6);
    b.dev.homing_error_next = true;
    REQUIRE(b.axis.home(b.now));
    b.run();
    CHECK(b.axis.error()->failure == drive_failure::homing_error);
  }
  SUBCASE("timeout") {
    sim::bench b({.homing_timeout_ms = 100});
    enable_in(b, 6);
    b.dev.homing_cycles = 1000;
    REQUIRE(b.axis.home(b.now));
    b.run();
    CHECK(b.axis.error()->failure == drive_failure::homing_timeout);
    CHECK(b.axis.error()->is(errc::timeout));
  }
  SUBCASE("not in homing mode") {
    sim::bench b;
    enable_in(b, 1);
    CHECK(b.axis.home(b.now).error() == errc::bad_state);
  }
}

TEST_CASE("drive: profile velocity and cyclic synchronous targets") {
  SUBCASE("pv") {
    sim::bench b;
    enable_in(b, 3);
    REQUIRE(b.axis.run_velocity(2500, b.now));
    auto s = b.cycle();
    CHECK(s.state == drive_state::running);
    CHECK(s.target == 2500);
    CHECK(s.controlword == 0x000F);
    b.axis.halt(true);
    CHECK(b.cycle().controlword == 0x010F);
    b.axis.halt(false);
    REQUIRE(b.axis.run_velocity(-100, b.now)); // a new velocity while running
    CHECK(b.cycle().target == -100);
    b.axis.stop_running();
    CHECK(b.cycle().state == drive_state::enabled);
  }
  SUBCASE("csp, CiA 402") {
    sim::bench b;
    enable_in(b, 8);
    REQUIRE(b.axis.start_cyclic(10, b.now));
    for (std::int32_t t = 10; t < 60; t += 10) {
      b.axis.set_target(t);
      auto s = b.cycle();
      CHECK(s.target == t);
      CHECK(s.controlword == 0x000F);
    }
  }
  SUBCASE("csp, XENAX needs bit 4") {
    sim::bench b({.profile = xenax::profile});
    enable_in(b, 8);
    REQUIRE(b.axis.start_cyclic(10, b.now));
    CHECK(b.cycle().controlword == 0x001F);
  }
  SUBCASE("csv of a XENAX: no extra bit") {
    sim::bench b({.profile = xenax::profile});
    enable_in(b, 9);
    REQUIRE(b.axis.start_cyclic(10, b.now));
    CHECK(b.cycle().controlword == 0x000F);
  }
  SUBCASE("not in a cyclic mode") {
    sim::bench b;
    enable_in(b, 1);
    CHECK(b.axis.start_cyclic(0, b.now).error() == errc::bad_state);
    CHECK(b.axis.run_velocity(0, b.now).error() == errc::bad_state);
  }
}

TEST_CASE("drive: XENAX jog mode -1, a motion of its profile") {
  sim::bench b({.profile = xenax::profile});
  b.mode_in_pdo = true;
  enable_in(b, -1);
  REQUIRE(b.axis.start_motion(xenax::jog(xenax::jog_direction::positive), b.now));
  CHECK(b.cycle().controlword == 0x005F); // manual 5.4.1
  CHECK(b.axis.state() == drive_state::running);
  CHECK_FALSE(b.dev.speed_zero);
  REQUIRE(b.axis.stop_motion(b.now));
  auto s = b.cycle();
  CHECK(s.controlword == 0x011F); // manual 5.4.1: halt, as printed for both directions
  CHECK(s.state == drive_state::stopping);
  CHECK(to_string(s.state) == "stopping");
  b.run();
  CHECK(b.axis.state() == drive_state::enabled);
  CHECK(b.last.controlword == 0x000F);
  CHECK(b.dev.speed_zero);
  CHECK(b.axis.stop_motion(b.now).error() == errc::bad_state);

  REQUIRE(b.axis.start_motion(xenax::jog(xenax::jog_direction::negative), b.now));
  CHECK(b.cycle().controlword == 0x001F);
  b.axis.stop_running(); // drops the bits at once
  CHECK(b.cycle().controlword == 0x000F);
  CHECK(b.axis.state() == drive_state::enabled);
  CHECK(b.axis.stop_motion(b.now).error() == errc::bad_state);
}

TEST_CASE("drive: a motion the profile does not offer is refused") {
  SUBCASE("plain CiA 402 offers none") {
    sim::bench b;
    b.mode_in_pdo = true;
    enable_in(b, -1);
    CHECK(b.axis.start_motion(xenax::jog(xenax::jog_direction::negative), b.now).error() ==
          errc::invalid_argument);
    CHECK(b.cycle().controlword == 0x000F);
  }
  SUBCASE("the XENAX's profile, a motion it does not list") {
    sim::bench b({.profile = xenax::profile});
    b.mode_in_pdo = true;
    enable_in(b, -1);
    auto m = xenax::jog(xenax::jog_direction::positive);
    m.start_bits = 0x0070;
    CHECK(b.axis.start_motion(m, b.now).error() == errc::invalid_argument);
  }
  SUBCASE("not in the motion's mode") {
    sim::bench b({.profile = xenax::profile});
    enable_in(b, 1);
    CHECK(b.axis.start_motion(xenax::jog(xenax::jog_direction::positive), b.now).error() ==
          errc::bad_state);
  }
}

namespace {
// A made-up drive family: the generic machine takes any vendor's rules as data. Its CSV runs
// with manufacturer bit 11, and its mode -3 ("spindle") starts with bit 4, stops with bits 4 and
// 8 and reports standstill with statusword bits 12 and 14.
constexpr ds402::manufacturer_motion spindle{-3, 0x0010, 0x0110, 0x5000};
constexpr ds402::manufacturer_motion spindle_motions[] = {spindle};
constexpr ds402::drive_profile other_vendor{{0, 0x0800, 0, 0}, spindle_motions};
static_assert(other_vendor.valid());
static_assert(!ds402::manufacturer_motion{1, 0x10, 0x10, 0x1000}.valid());  // standard mode
static_assert(!ds402::manufacturer_motion{-3, 0x18, 0x10, 0x1000}.valid()); // command bit 3
static_assert(!ds402::manufacturer_motion{-3, 0x10, 0x10, 0}.valid());      // nothing to wait for
static_assert(ds402::cia402_profile.valid() && ds402::cia402_profile.motions.empty());
} // namespace

TEST_CASE("drive: another vendor's profile") {
  SUBCASE("its csv bit") {
    sim::bench b({.profile = other_vendor});
    enable_in(b, 9);
    REQUIRE(b.axis.start_cyclic(10, b.now));
    CHECK(b.cycle().controlword == 0x080F);
    b.axis.stop_running();
    CHECK(b.cycle().controlword == 0x000F);
  }
  SUBCASE("its spindle motion stops when both stopped bits show") {
    sim::bench b({.profile = other_vendor, .disable_timeout_ms = 100});
    b.mode_in_pdo = true;
    enable_in(b, -3);
    REQUIRE(b.axis.start_motion(spindle, b.now));
    CHECK(b.cycle().controlword == 0x001F);
    REQUIRE(b.axis.stop_motion(b.now));
    CHECK(b.cycle().controlword == 0x011F);
    b.dev.extra_status = 0x1000; // one of the two: still stopping
    b.cycle();
    CHECK(b.axis.state() == drive_state::stopping);
    b.dev.extra_status = 0x5000;
    b.cycle();
    CHECK(b.axis.state() == drive_state::enabled);
    CHECK(b.cycle().controlword == 0x000F);
  }
  SUBCASE("a spindle that never stops") {
    sim::bench b({.profile = other_vendor, .disable_timeout_ms = 100});
    b.mode_in_pdo = true;
    enable_in(b, -3);
    REQUIRE(b.axis.start_motion(spindle, b.now));
    b.cycle();
    REQUIRE(b.axis.stop_motion(b.now));
    b.run();
    CHECK(b.axis.state() == drive_state::failed);
    CHECK(b.axis.error()->failure == drive_failure::stop_timeout);
    CHECK(b.axis.error()->is(errc::timeout));
    CHECK(to_string(drive_failure::stop_timeout) == "motion not stopped in time");
    CHECK(b.axis.stop_motion(b.now).error() == errc::bad_state);
  }
  SUBCASE("a XENAX jog is not one of its motions") {
    sim::bench b({.profile = other_vendor});
    b.mode_in_pdo = true;
    enable_in(b, -1);
    CHECK(b.axis.start_motion(xenax::jog(xenax::jog_direction::positive), b.now).error() ==
          errc::invalid_argument);
  }
}

TEST_CASE("drive: an aborted target write fails the move; an EMCY with code 0 clears the last") {
  sim::bench b({.target_over_sdo = true});
  enable_in(b, 1);
  b.dev.abort_next = fieldcodec::canopen::sdo::abort_code::value_too_low;
  REQUIRE(b.axis.move_to(-5, b.now));
  b.run();
  CHECK(b.axis.state() == drive_state::failed);
  CHECK(b.axis.error()->failure == drive_failure::sdo_failed);
  CHECK(b.axis.error()->sdo->address == fieldcodec::od::address{0x607A, 0});
  CHECK(rising_edges(b.controlwords, 0x10) == 0); // bit 4 never raised

  b.axis.on_emcy({0x2310, 0x03, {}});
  b.axis.on_emcy({0x0000, 0x00, {}}); // error reset
  b.dev.fault(0x2310);
  b.cycle();
  CHECK(b.axis.state() == drive_state::fault);
  CHECK_FALSE(b.axis.error()->emcy);
}

TEST_CASE("drive: an SDO that never completes keeps motion commands waiting") {
  sim::bench b({.set_point_timeout_ms = 50, .target_over_sdo = true});
  enable_in(b, 1);
  b.dev.sdo_silent = true;
  REQUIRE(b.axis.move_to(100, b.now));
  b.run();
  // the caller's SDO client would report its timeout; without it the set-point times out
  CHECK(b.axis.error()->failure == drive_failure::set_point_not_acknowledged);
  CHECK(rising_edges(b.controlwords, 0x10) == 0);
  CHECK(b.axis.sdo_pending());
}

// docs/master.md, "Drive profiles" (the block as printed there)
namespace doc_jog {
namespace master = fieldcodec::master;
namespace xenax = fieldcodec::xenax;

// the controlwords of a XENAX jog; 6061h (-1) comes in a TPDO with the statusword
constexpr std::array<std::uint16_t, 3> jog_words() {
  master::drive axis({.profile = xenax::profile});
  (void)axis.switch_mode(xenax::mode::jog, 0);  // asks for the 6060h download
  (void)axis.cycle(0x1237, 1, std::int8_t{-1}); // operation enabled, speed zero; the SDO goes
  axis.sdo_done({}, 2);                         // the caller's client ran it
  (void)axis.cycle(0x1237, 3, std::int8_t{-1}); // 6061h shows jog: enabled
  (void)axis.start_motion(xenax::jog(xenax::jog_direction::positive), 4);
  const std::uint16_t run = axis.cycle(0x0237, 5, std::int8_t{-1}).controlword;
  (void)axis.stop_motion(6);
  const std::uint16_t stop = axis.cycle(0x0237, 7, std::int8_t{-1}).controlword;
  const std::uint16_t after = axis.cycle(0x1237, 8, std::int8_t{-1}).controlword; // speed zero
  return {run, stop, after};
}
static_assert(jog_words() == std::array<std::uint16_t, 3>{0x005F, 0x011F, 0x000F});
} // namespace doc_jog
