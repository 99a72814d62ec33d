// XENAX helpers of issue 13: per-bus 60B2h scaling, node-ID range, force/torque <-> motor
// current, LARES/ENC position units and the complete 5000h direct-command table. Vectors are
// from the manual (../shared/seeds/003_*.txt, line numbers as in docs/xenax.md) where it
// prints one; the others are derived from the printed formulas and say so.
#include <fieldcodec/xenax/bus.hpp>
#include <fieldcodec/xenax/units.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <set>

namespace xenax = fieldcodec::xenax;
using fieldcodec::decimal;
using fieldcodec::errc;
using xenax::bus;
using xenax::motor;

namespace {
bool same(decimal a, decimal b) { return fieldcodec::compare(a, b) == 0; }
} // namespace

// 4.2.23 (l. 1385-1410): acceleration = 60B2h x 50 000 on EtherCAT, x 1 on the other buses.
static_assert(xenax::acceleration_scaling(bus::ethercat) == 50'000);
static_assert(xenax::acceleration_scaling(bus::canopen) == 1);
static_assert(xenax::acceleration_scaling(bus::powerlink) == 1);
static_assert(xenax::torque_offset_from_acceleration(1'000'000, bus::ethercat).value() == 20);
// 2.5 (l. 310-312): CI, the node-ID, 1-99
static_assert(xenax::node_id(99).value() == 99);
static_assert(xenax::node_id(100).error() == errc::out_of_range);

TEST_CASE("60B2h torque offset scales per bus (4.2.23)") {
  // 6083h's default acceleration 0xF4240 = 1 000 000 inc/s² (l. 1328): 20 on EtherCAT, and
  // beyond INTEGER16 on CANopen and POWERLINK, where 60B2h carries inc/s² unscaled.
  CHECK(xenax::torque_offset_from_acceleration(1'000'000, bus::ethercat).value() == 20);
  CHECK(xenax::torque_offset_from_acceleration(1'000'000, bus::canopen) == errc::overflow);
  CHECK(xenax::torque_offset_from_acceleration(1'000'000, bus::powerlink) == errc::overflow);
  CHECK(xenax::torque_offset_from_acceleration(32'767, bus::canopen).value() == 32767);
  CHECK(xenax::torque_offset_from_acceleration(-32'768, bus::powerlink).value() == -32768);
  CHECK(xenax::torque_offset_from_acceleration(-32'769, bus::powerlink) == errc::overflow);
  // EtherCAT rounds to the nearest 50 000, half away from zero; the limits 0x8000..0x7FFF
  // (l. 1410) are the INTEGER16 range
  CHECK(xenax::torque_offset_from_acceleration(24'999, bus::ethercat).value() == 0);
  CHECK(xenax::torque_offset_from_acceleration(25'000, bus::ethercat).value() == 1);
  CHECK(xenax::torque_offset_from_acceleration(-25'000, bus::ethercat).value() == -1);
  CHECK(xenax::torque_offset_from_acceleration(1'638'374'999, bus::ethercat).value() == 32767);
  CHECK(xenax::torque_offset_from_acceleration(1'638'375'000, bus::ethercat) == errc::overflow);
  CHECK(xenax::torque_offset_from_acceleration(-1'638'400'000, bus::ethercat).value() == -32768);
  CHECK(xenax::acceleration_from_torque_offset(20, bus::ethercat) == 1'000'000);
  CHECK(xenax::acceleration_from_torque_offset(20, bus::canopen) == 20);
  CHECK(xenax::acceleration_from_torque_offset(-32768, bus::ethercat) == -1'638'400'000);
  CHECK(xenax::acceleration_from_torque_offset(32767, bus::ethercat) == 1'638'350'000);
  for (std::int32_t raw = -32768; raw <= 32767; raw += 97) {
    const auto r = static_cast<std::int16_t>(raw);
    for (bus b : {bus::canopen, bus::ethercat, bus::powerlink}) {
      REQUIRE(
          xenax::torque_offset_from_acceleration(xenax::acceleration_from_torque_offset(r, b), b)
              .value() == r);
    }
  }
  CHECK(xenax::to_string(bus::powerlink) == "POWERLINK");
}

TEST_CASE("XENAX node-ID 1-99 (2.5, CI)") {
  for (int v = -300; v <= 300; ++v) {
    const auto n = xenax::node_id(v);
    CHECK(n.has_value() == (v >= 1 && v <= 99));
    if (n) {
      CHECK(n.value() == v);
    } else {
      CHECK(n == errc::out_of_range);
    }
  }
  CHECK(xenax::node_id(std::uint8_t{127}) == errc::out_of_range); // CiA 301 allows it, XENAX not
  CHECK(xenax::node_id(std::uint64_t{0x1'0000'0001}) == errc::out_of_range); // no wrap to 1
  CHECK(xenax::node_id(std::int64_t{-1}) == errc::out_of_range);
  CHECK(xenax::node_id(std::uint16_t{1}).value() == 1);
  static_assert(xenax::min_node_id == 1 && xenax::max_node_id == 99);
}

TEST_CASE("force and torque <-> motor current (6.1.2, l. 1875-1901)") {
  // the constants as mA per N (10 k) or per Nm (1000 k)
  CHECK(same(xenax::current_per_force(motor::elax_ex_f20), {120, 0}));
  CHECK(same(xenax::current_per_force(motor::linax_lxc_f04), {500, 0}));
  CHECK(same(xenax::current_per_force(motor::rotax_rxhq_110_50_t1_5), {2500, 0}));
  CHECK(same(xenax::current_per_force(motor::rotax_rxvp_t0_04), {23000, 0}));
  // the manual's example: ELAX, 12 x 10 mA ~ 1 N, so 4 N = 48 x 10 mA = 480 mA
  CHECK(xenax::to_ma(xenax::newtons{{4, 0}}, motor::elax_ex_f20).value() == 480);
  CHECK(xenax::current_limit_for(xenax::newtons{{4, 0}}, motor::elax_ex_f20).value() == 48);
  CHECK(same(xenax::to_newtons(480, motor::elax_ex_f20).value().value, {4, 0}));
  // table rows: "k x 10 mA ~ 1 N" / "k x 10 mA ~ 0.01 Nm"
  CHECK(xenax::to_ma(xenax::newtons{{1, 0}}, motor::linax_lxc_f04).value() == 500);
  CHECK(xenax::to_ma(xenax::newtons{{1, 0}}, motor::linax_lxu_lxs_f60).value() == 100);
  CHECK(xenax::to_ma(xenax::newton_metres{{1, 2}}, motor::rotax_rxhq_110_50_t1_5).value() == 25);
  CHECK(xenax::to_ma(xenax::newton_metres{{1, 2}}, motor::rotax_rxhq_50_12_t0_3).value() == 80);
  CHECK(xenax::to_ma(xenax::newton_metres{{1, 2}}, motor::rotax_rxvp_t0_04).value() == 230);
  // nominal torques from the model names (T1.5, T0.04), derived
  CHECK(xenax::current_limit_for(xenax::newton_metres{{15, 1}}, motor::rotax_rxhq_110_50_t1_5)
            .value() == 375);
  CHECK(xenax::current_limit_for(xenax::newton_metres{{4, 2}}, motor::rotax_rxvp_t0_04).value() ==
        92);
  CHECK(same(xenax::to_newton_metres(920, motor::rotax_rxvp_t0_04).value().value, {400, 4}));
  // negative forces give negative currents (2005h is signed); a limit is never negative
  CHECK(xenax::to_ma(xenax::newtons{{-4, 0}}, motor::elax_ex_f20).value() == -480);
  CHECK(same(xenax::to_newtons(-140, motor::linax_lxc_f10).value().value, {-500, 3}));
  CHECK(xenax::current_limit_for(xenax::newtons{{-1, 0}}, motor::elax_ex_f20) ==
        errc::out_of_range);
  // one rounding, half away from zero: 0.002 Nm on the Rxhq 110 is 0.5 steps and 5 mA
  CHECK(xenax::current_limit_for(xenax::newton_metres{{2, 3}}, motor::rotax_rxhq_110_50_t1_5)
            .value() == 1);
  CHECK(xenax::to_ma(xenax::newton_metres{{2, 4}}, motor::rotax_rxhq_110_50_t1_5).value() == 1);
  // 1.145 N on an Lxu/Lxs F60 (10 steps/N) is 11.45 steps: 11, not 114.5 -> 115 mA -> 12
  CHECK(xenax::current_limit_for(xenax::newtons{{1145, 3}}, motor::linax_lxu_lxs_f60).value() ==
        11);
  CHECK(xenax::to_ma(xenax::newtons{{1145, 3}}, motor::linax_lxu_lxs_f60).value() == 115);
  // 6078h's ±20 000 mA (errata 17) on an ELAX: 166.667 N
  CHECK(same(xenax::to_newtons(20000, motor::elax_ex_f20).value().value, {166667, 3}));
  CHECK(same(xenax::to_newtons(20000, motor::elax_ex_f20, 0).value().value, {167, 0}));
  // a limit never comes out as 0, which the XENAX takes as "no limitation" (l. 1849): a force
  // or current that rounds to 0 steps is refused; switching off is written as no_current_limit
  CHECK(xenax::current_limit_for(xenax::newtons{{0, 0}}, motor::elax_ex_f20) == errc::out_of_range);
  CHECK(xenax::current_limit_for(xenax::newtons{{4, 2}}, motor::elax_ex_f20) ==
        errc::out_of_range); // 0.04 N x 12 = 0.48 steps
  CHECK(xenax::current_limit_for(xenax::newtons{{5, 2}}, motor::elax_ex_f20).value() == 1);
  CHECK(xenax::current_limit_for(xenax::newton_metres{{1, 3}}, motor::rotax_rxhq_110_50_t1_5) ==
        errc::out_of_range); // 0.001 Nm = 0.25 steps
  CHECK(xenax::current_limit_from_ma({4, 0}) == errc::out_of_range);
  CHECK(xenax::current_limit_from_ma({0, 0}) == errc::out_of_range);
  CHECK(xenax::current_limit_from_ma({5, 0}).value() == 1);
  static_assert(xenax::no_current_limit == 0);
  // 20 A (6073h maximum 2000) is the limit
  CHECK(xenax::current_limit_for(xenax::newtons{{166, 0}}, motor::elax_ex_f20).value() == 1992);
  CHECK(xenax::current_limit_for(xenax::newtons{{167, 0}}, motor::elax_ex_f20) ==
        errc::out_of_range);
  // a force for a ROTAX or a torque for a linear motor is a mistake, not a conversion
  CHECK(xenax::to_ma(xenax::newtons{{1, 0}}, motor::rotax_rxvp_t0_04) == errc::invalid_argument);
  CHECK(xenax::to_ma(xenax::newton_metres{{1, 0}}, motor::elax_ex_f20) == errc::invalid_argument);
  CHECK(xenax::current_limit_for(xenax::newtons{{1, 0}}, motor::rotax_rxvp_t0_04) ==
        errc::invalid_argument);
  CHECK(xenax::current_limit_for(xenax::newton_metres{{1, 0}}, motor::elax_ex_f20) ==
        errc::invalid_argument);
  CHECK(xenax::to_newtons(1, motor::rotax_rxvp_t0_04) == errc::invalid_argument);
  CHECK(xenax::to_newton_metres(1, motor::elax_ex_f20) == errc::invalid_argument);
  CHECK(xenax::to_newtons(1, motor::elax_ex_f20, 19) == errc::invalid_argument);
  CHECK(xenax::to_ma(xenax::newtons{{20'000'000, 0}}, motor::linax_lxc_f04) == errc::overflow);
  // every motor: N -> mA -> N gives the force back at the table's resolution
  for (motor m :
       {motor::linax_lxc_f04, motor::linax_lxc_f08, motor::linax_lxc_f10, motor::linax_lxc_f40,
        motor::linax_lxe_f40, motor::linax_lxu_lxs_f60, motor::elax_ex_f20}) {
    for (std::int64_t n = -50; n <= 50; ++n) {
      const auto ma = xenax::to_ma(xenax::newtons{{n, 0}}, m).value();
      CHECK(same(xenax::to_newtons(ma, m, 0).value().value, {n, 0}));
    }
  }
}

TEST_CASE("LARES: increments <-> mm on a linear axis (5001h sub 43)") {
  // Derived: LARES = 1 000 000 inc/m (1 µm per increment); 6081h's default 0x186A0 =
  // 100 000 inc/s (l. 1323) is then 100 mm/s.
  const xenax::linear_resolution um{1'000'000};
  CHECK(same(xenax::to_mm(100'000, um).value(), {100'000, 3}));
  CHECK(xenax::to_increments({100, 0}, um).value() == 100'000);
  CHECK(xenax::to_increments({25, 1}, um).value() == 2'500);
  CHECK(same(xenax::to_mm(-1, um, 3).value(), {-1, 3}));
  CHECK(same(xenax::to_mm(-1, um, 2).value(), {0, 2})); // -0.001 rounds to -0.00
  // 0.5 µm per increment: 0.00025 mm is half an increment, rounded away from zero
  const xenax::linear_resolution half_um{2'000'000};
  CHECK(xenax::to_increments({25, 5}, half_um).value() == 1);
  CHECK(xenax::to_increments({-25, 5}, half_um).value() == -1);
  CHECK(xenax::to_increments({24, 5}, half_um).value() == 0);
  CHECK(same(xenax::to_mm(3, half_um, 4).value(), {15, 4}));
  // a resolution that is not a power of ten: 4 096 000 inc/m
  const xenax::linear_resolution odd{4'096'000};
  CHECK(same(xenax::to_mm(4096, odd, 6).value(), {1, 0}));
  CHECK(same(xenax::to_mm(1, odd, 6).value(), {244, 6})); // 0.000244140625
  // errors
  CHECK(xenax::to_increments({3'000'000, 0}, um) == errc::overflow); // 3 km: beyond INTEGER32
  CHECK(xenax::to_increments({1, 0}, xenax::linear_resolution{0}) == errc::invalid_argument);
  CHECK(xenax::to_mm(1, xenax::linear_resolution{-1}) == errc::invalid_argument);
  CHECK(xenax::to_mm(1, um, 19) == errc::invalid_argument);
}

TEST_CASE("ENC: increments <-> degrees on a rotary axis (5004h sub 2)") {
  // ENC's default 0x5DC0 = 24 000 increments per turn (l. 1005)
  const xenax::rotary_resolution enc{0x5DC0};
  CHECK(xenax::to_increments({90, 0}, enc).value() == 6000);
  CHECK(xenax::to_increments({360, 0}, enc).value() == 24000);
  CHECK(xenax::to_increments({-90, 0}, enc).value() == -6000);
  CHECK(xenax::to_increments({1, 0}, enc).value() == 67); // 66.67
  CHECK(xenax::to_increments({75, 4}, enc).value() == 1); // 0.0075° = half an increment
  CHECK(xenax::to_increments({-75, 4}, enc).value() == -1);
  CHECK(xenax::to_increments({74, 4}, enc).value() == 0);
  CHECK(same(xenax::to_degrees(1, enc).value(), {15, 3}));
  CHECK(same(xenax::to_degrees(6000, enc, 0).value(), {90, 0}));
  // ROTAX Rxhq after power-on: 0 .. 119 999 inc (5.1.8, l. 1647), one turn of 120 000
  const xenax::rotary_resolution rxhq{120'000};
  CHECK(same(xenax::to_degrees(119'999, rxhq, 3).value(), {359'997, 3}));
  CHECK(xenax::to_increments({359'997, 3}, rxhq).value() == 119'999);
  // round trip at the increment's resolution
  for (std::int64_t inc = -30'000; inc <= 30'000; inc += 7) {
    const auto deg = xenax::to_degrees(inc, enc, 6).value();
    REQUIRE(xenax::to_increments(deg, enc).value() == inc);
  }
  // errors
  CHECK(xenax::to_increments({1, 0}, xenax::rotary_resolution{0}) == errc::invalid_argument);
  CHECK(xenax::to_degrees(1, xenax::rotary_resolution{-5}) == errc::invalid_argument);
  CHECK(xenax::to_increments({1'000'000, 0}, xenax::rotary_resolution{10'000'000}) ==
        errc::overflow);
  CHECK(xenax::to_increments({1, 17}, enc) == errc::overflow);
  CHECK(xenax::to_increments({10, 17}, enc).value() == 0); // normalised to 1e-16 first
  CHECK(xenax::to_degrees(INT64_MAX, enc) == errc::overflow);
}

TEST_CASE("5000h direct commands: the whole table (3.4.1, l. 758-798)") {
  // 4.2.7 / 5.1.1: PWC = 0x2010 written to 5000h (errata 24)
  CHECK(xenax::decode_direct_command(0x2010).value() == xenax::direct_command::power_continue);
  CHECK(xenax::mnemonic(xenax::direct_command::power_continue) == "PWC");
  CHECK(xenax::decode_direct_command(0x4001).value() ==
        xenax::direct_command::force_calibration_test_on);
  CHECK(xenax::mnemonic(xenax::direct_command::force_calibration_test_on) == "FCT1");
  CHECK(xenax::mnemonic(xenax::direct_command::force_calibration_test_off) == "FCT0");
  CHECK(xenax::mnemonic(xenax::direct_command::force_calibration_test_uncompensated) == "FCT2");
  CHECK(xenax::decode_direct_command(0x4011).value() ==
        xenax::direct_command::i_force_drift_compensation_negative);
  CHECK(xenax::decode_direct_command(0x5030).value() ==
        xenax::direct_command::deactivate_motion_blocking);
  CHECK(xenax::decode_direct_command(0x6010).value() == xenax::direct_command::clear_force_offset);
  CHECK(xenax::is_varan_only(xenax::direct_command::start_bootloader));
  CHECK(!xenax::is_varan_only(xenax::direct_command::reset));
  // printed "reserved": not commands
  CHECK(xenax::decode_direct_command(0x1040) == errc::unknown_command);
  CHECK(xenax::decode_direct_command(0x3060) == errc::unknown_command);
  CHECK(xenax::decode_direct_command(0) == errc::unknown_command);
  CHECK(xenax::decode_direct_command(0x7002) == errc::unknown_command);
  // the table holds 33 commands (35 rows minus 2 reserved), all distinct, in value order
  std::set<std::uint32_t> values;
  std::set<std::string_view> texts;
  std::uint32_t previous = 0;
  int without_mnemonic = 0;
  for (auto c : xenax::direct_commands) {
    const auto v = static_cast<std::uint32_t>(c);
    CHECK(v > previous);
    previous = v;
    values.insert(v);
    texts.insert(xenax::to_string(c));
    CHECK(xenax::decode_direct_command(v).value() == c);
    if (xenax::mnemonic(c).empty()) ++without_mnemonic;
  }
  CHECK(values.size() == 33);
  CHECK(texts.size() == 33);
  CHECK(without_mnemonic == 5); // 0x1000, 0x6000, 0x6001, 0x7000, 0x7001
}
