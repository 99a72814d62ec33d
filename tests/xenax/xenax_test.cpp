// XENAX vendor layer: modes, mode-specific bits, reference methods, error codes, units.
#include <fieldcodec/ds402/statusword.hpp>
#include <fieldcodec/xenax/error_code.hpp>
#include <fieldcodec/xenax/homing.hpp>
#include <fieldcodec/xenax/modes.hpp>
#include <fieldcodec/xenax/units.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <type_traits>

namespace xenax = fieldcodec::xenax;
namespace ds402 = fieldcodec::ds402;
using fieldcodec::decimal;
using fieldcodec::errc;

// Manual 5.2.1 / 5.2.3 / 5.4.1 controlwords.
static_assert(xenax::pp_start(xenax::positioning::absolute) == 0x1F);
static_assert(xenax::pp_start(xenax::positioning::relative) == 0x5F);
static_assert(xenax::pp_halt == 0x10F);
static_assert(xenax::jog_start(xenax::jog_direction::negative) == 0x1F);
static_assert(xenax::jog_start(xenax::jog_direction::positive) == 0x5F);
static_assert(xenax::jog_stop == 0x11F);
static_assert(xenax::reference_start == 0x1F);
// Manual 4.2.1 (errata 22): error 50 -> 0xFF32.
static_assert(xenax::encode_error_code(50).value() == 0xFF32);
// Manual 6.1.2 example (l. 1897-1901): ELAX, 4 N -> 48 x 10 mA.
static_assert(xenax::current_limit_for(xenax::newtons{{4, 0}}, xenax::motor::elax_ex_f20).value() ==
              48);
// Manual 5.3.1: 500 us = 5 x 10^-4 s (60C2h sub 1 = 0x05, sub 2 = 0xFC).
static_assert(xenax::encode_cycle_time(500).value() == xenax::cycle_time{5, -4});

TEST_CASE("XENAX modes of operation (4.2.4, 4.2.29)") {
  CHECK(xenax::decode_mode(-1).value() == xenax::mode::jog);
  CHECK(xenax::decode_mode(0).value() == xenax::mode::no_mode);
  CHECK(xenax::decode_mode(1).value() == xenax::mode::profile_position);
  CHECK(xenax::decode_mode(6).value() == xenax::mode::reference);
  CHECK(xenax::decode_mode(8).value() == xenax::mode::cyclic_sync_position);
  for (std::int8_t v : {std::int8_t{-2}, std::int8_t{2}, std::int8_t{3}, std::int8_t{7},
                        std::int8_t{9}, std::int8_t{10}, std::int8_t{-128}}) {
    CHECK(xenax::decode_mode(v) == errc::out_of_range);
  }
  static_assert(std::is_same_v<std::underlying_type_t<xenax::mode>, std::int8_t>);
  CHECK(xenax::is_supported(xenax::supported_modes, xenax::mode::profile_position));
  CHECK(xenax::is_supported(xenax::supported_modes, xenax::mode::reference));
  CHECK(xenax::is_supported(xenax::supported_modes, xenax::mode::cyclic_sync_position));
  CHECK(xenax::is_supported(xenax::supported_modes, xenax::mode::jog));
  CHECK(!xenax::is_supported(xenax::supported_modes, xenax::mode::vendor_reserved));
  CHECK(!xenax::is_supported(0, xenax::mode::jog));
  CHECK(xenax::to_string(xenax::mode::jog) == "jog (Jenny Science)");
  // the ds402 layer hands negative modes to the vendor as manufacturer-specific (issue 13)
  const auto generic = ds402::decode_mode(-1).value();
  CHECK(ds402::is_manufacturer_mode(generic));
  CHECK(xenax::decode_mode(static_cast<std::int8_t>(generic)).value() == xenax::mode::jog);
}

TEST_CASE("statusword bits by mode, soft limit bit 11") {
  using xenax::mode;
  // PP after a move (5.2.1): operation enabled, bit 10 = 1, bit 12 = 0
  auto pp = xenax::decode_status(0x0627, mode::profile_position).value();
  CHECK(pp.state == ds402::state::operation_enabled);
  CHECK(pp.remote);
  CHECK(pp.target_reached);
  CHECK(!pp.set_point_acknowledge);
  CHECK(!pp.soft_limit_reached);
  auto ack = xenax::decode_status(0x1227, mode::profile_position).value();
  CHECK(ack.set_point_acknowledge);
  CHECK(!ack.target_reached);
  auto fe = xenax::decode_status(0x2227, mode::profile_position).value();
  CHECK(fe.following_error);
  auto soft = xenax::decode_status(0x0827, mode::cyclic_sync_position).value();
  CHECK(soft.soft_limit_reached);
  CHECK(!soft.target_used);
  CHECK(xenax::decode_status(0x1227, mode::cyclic_sync_position).value().target_used);
  // jog (5.4.1): running: bit 10 = 1, bit 12 = 0; stopped: both 1
  auto run = xenax::decode_status(0x0627, mode::jog).value();
  CHECK(run.constant_speed);
  CHECK(!run.speed_zero);
  auto stop = xenax::decode_status(0x1627, mode::jog).value();
  CHECK(stop.speed_zero);
  CHECK(!stop.target_reached); // bit 10 means constant speed in jog, not target reached
  // reference (5.1.2): bit 12 achieved, bit 13 error
  auto ref = xenax::decode_status(0x1627, mode::reference).value();
  CHECK(ref.reference_achieved);
  CHECK(ref.reference_performed);
  CHECK(!ref.reference_error);
  CHECK(xenax::decode_status(0x2627, mode::reference).value().reference_error);
  CHECK(!xenax::decode_status(0x2627, mode::reference).value().following_error);
  CHECK(xenax::decode_status(0x0001, mode::jog) == errc::bad_state);
  auto none = xenax::decode_status(0x1E40, mode::no_mode).value();
  CHECK(none.state == ds402::state::switch_on_disabled);
  CHECK(none.soft_limit_reached);
  CHECK(!none.target_reached);
  CHECK(!none.speed_zero);
}

TEST_CASE("reference methods (4.2.19, 5.1.7)") {
  using xenax::reference_method;
  for (std::int8_t v = -5; v <= 20; ++v) {
    const bool valid = (v >= 1 && v <= 6) || (v >= 10 && v <= 15);
    auto m = xenax::decode_reference_method(v);
    CHECK(m.has_value() == valid);
    if (valid) {
      CHECK(xenax::method_byte(m.value()) == static_cast<std::uint8_t>(v));
      CHECK(!xenax::to_string(m.value()).empty());
    } else {
      CHECK(m == errc::out_of_range);
    }
  }
  CHECK(xenax::is_gantry(reference_method::gantry_same_positive));
  CHECK(xenax::is_gantry(reference_method::gantry_contrary_negative));
  CHECK(!xenax::is_gantry(reference_method::linear_negative));
  CHECK(xenax::is_rotary(reference_method::cw_sensor_ccw_zmark));
  CHECK(!xenax::is_rotary(reference_method::gantry_contrary_negative));
  CHECK(xenax::allows_jog(reference_method::linear_positive));
  CHECK(!xenax::allows_jog(reference_method::gantry_same_negative));
  CHECK(xenax::allows_jog(reference_method::ccw_sensor_cw_zmark)); // 5.1.6 offers jog (errata)
}

TEST_CASE("603Fh error codes") {
  CHECK(xenax::encode_error_code(0).value() == 0);
  CHECK(xenax::encode_error_code(1).value() == 0xFF01);
  CHECK(xenax::encode_error_code(99).value() == 0xFF63);
  CHECK(xenax::encode_error_code(100) == errc::out_of_range);
  CHECK(xenax::decode_error_code(0).value() == 0);
  CHECK(xenax::decode_error_code(0xFF32).value() == 50);
  CHECK(xenax::decode_error_code(0xFF63).value() == 99);
  CHECK(xenax::decode_error_code(0xFF00) == errc::out_of_range);
  CHECK(xenax::decode_error_code(0xFF64) == errc::out_of_range);
  CHECK(xenax::decode_error_code(0xFF99) == errc::out_of_range); // printed "0xFF01..99"
  CHECK(xenax::decode_error_code(0x8611) == errc::out_of_range);
  for (std::uint8_t n = 0; n <= 99; ++n) {
    CHECK(xenax::decode_error_code(xenax::encode_error_code(n).value()).value() == n);
  }
  CHECK(!xenax::error_text(50).empty());
  CHECK(xenax::error_text(0) == "no error");
  CHECK(xenax::error_text(17).empty());
  CHECK(!xenax::needs_reference_after(50)); // 5.1.1: PWC continues without a new reference
  CHECK(xenax::needs_reference_after(17));
}

TEST_CASE("current limit, force constants and force objects") {
  CHECK(xenax::current_limit_from_ma({480, 0}).value() == 48);
  CHECK(xenax::current_limit_from_ma({485, 0}).value() == 49); // half away from zero
  CHECK(xenax::current_limit_from_ma({484, 0}).value() == 48);
  CHECK(xenax::current_limit_from_ma({20000, 0}).value() == 2000);
  CHECK(xenax::current_limit_from_ma({20010, 0}) == errc::out_of_range);
  CHECK(xenax::current_limit_from_ma({-10, 0}) == errc::out_of_range);
  CHECK(xenax::current_limit_to_ma(2000) == 20000);
  using xenax::motor;
  CHECK(xenax::is_rotary(motor::rotax_rxvp_t0_04));
  CHECK(!xenax::is_rotary(motor::elax_ex_f20));
  CHECK(xenax::force_n_to_mn({1234, 3}).value() == 1234);
  CHECK(xenax::force_n_to_mn({-25, 1}).value() == -2500);
  CHECK(xenax::force_n_to_mn({3000000, 0}) == errc::overflow);
  CHECK(fieldcodec::compare(xenax::force_mn_to_n(-2500), decimal{-25, 1}) == 0);
}

TEST_CASE("60C2h synchronous cycle time") {
  CHECK(xenax::encode_cycle_time(1000).value() == xenax::cycle_time{1, -3}); // 4.2.24 default
  CHECK(xenax::encode_cycle_time(250).value() == xenax::cycle_time{25, -5});
  CHECK(xenax::encode_cycle_time(200).value() == xenax::cycle_time{2, -4});
  CHECK(xenax::encode_cycle_time(1).value() == xenax::cycle_time{1, -6});
  CHECK(xenax::encode_cycle_time(0) == errc::out_of_range);
  CHECK(xenax::encode_cycle_time(257) == errc::out_of_range);
  CHECK(xenax::decode_cycle_time({5, -4}).value() == 500);
  CHECK(xenax::decode_cycle_time({1, -3}).value() == 1000);
  CHECK(xenax::decode_cycle_time({1, 0}).value() == 1'000'000);
  CHECK(xenax::decode_cycle_time({5, -7}) == errc::not_representable);
  CHECK(xenax::decode_cycle_time({50, -7}).value() == 5);
  CHECK(xenax::decode_cycle_time({255, 3}) == errc::overflow);
}
