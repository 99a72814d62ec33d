// Fuzz harness for the XENAX vendor layer (xenax/): 603Fh error codes, 6098h reference
// methods, 6060h/6061h modes, mode-specific statusword decoding, 6073h current limits, force
// and torque units, LARES/ENC position units, 60B2h per-bus scaling, node-IDs, 5000h direct
// commands and the 60C2h cycle time. The input is a sequence of 8-byte records; every record
// goes through every codec.
//
// Properties: what decodes re-encodes to the same value (error code, method byte, mode, direct
// command); a XENAX mode is also a CiA 402 mode (standard or manufacturer-specific);
// decode_status agrees with ds402::decode_state and reads exactly the bits the mode gives a
// meaning; current limits round-trip through mA; mN → N → mN is exact; mA → N (or Nm) → mA is
// exact at a resolution finer than the motor's constant; a force or torque for the wrong kind of
// motor is refused; increments → mm / degrees → increments is exact at 9 decimal places;
// 60B2h → acceleration → 60B2h is exact on every bus and an acceleration is never more than half
// a scaling step from its 60B2h; node_id accepts exactly 1..99; a cycle time re-encodes to its
// canonical (shortest: base without trailing zeros) form, which decodes to the same number of
// microseconds, and every encodable number of microseconds decodes back.
#include "check.hpp"

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/ds402/modes.hpp>
#include <fieldcodec/ds402/statusword.hpp>
#include <fieldcodec/xenax/bus.hpp>
#include <fieldcodec/xenax/error_code.hpp>
#include <fieldcodec/xenax/homing.hpp>
#include <fieldcodec/xenax/modes.hpp>
#include <fieldcodec/xenax/units.hpp>

#include <cstddef>
#include <cstdint>

namespace fc = fieldcodec;
namespace xe = fieldcodec::xenax;
using fc::errc;

namespace {

void check_codes(std::uint16_t code, std::uint8_t b) {
  if (auto n = xe::decode_error_code(code)) {
    auto back = xe::encode_error_code(n.value());
    FUZZ_CHECK(back.has_value() && back.value() == code);
  } else {
    FUZZ_CHECK(n.is(errc::out_of_range));
  }
  if (auto e = xe::encode_error_code(b)) {
    FUZZ_CHECK(xe::decode_error_code(e.value()).value() == b);
  } else {
    FUZZ_CHECK(b > xe::max_error_number);
  }
  const auto v = static_cast<std::int8_t>(b);
  if (auto m = xe::decode_reference_method(v)) {
    FUZZ_CHECK(xe::method_byte(m.value()) == b);
    FUZZ_CHECK(xe::allows_jog(m.value()) == !xe::is_gantry(m.value()));
  }
  if (auto m = xe::decode_mode(v)) {
    FUZZ_CHECK(static_cast<std::int8_t>(m.value()) == v);
    auto generic = fc::ds402::decode_mode(v);
    FUZZ_CHECK(generic.has_value() && static_cast<std::int8_t>(generic.value()) == v);
  }
  if (auto n = xe::node_id(static_cast<int>(code) - 300)) {
    FUZZ_CHECK(n.value() >= 1U && n.value() <= 99U && n.value() == static_cast<int>(code) - 300);
  } else {
    FUZZ_CHECK(static_cast<int>(code) - 300 < 1 || static_cast<int>(code) - 300 > 99);
  }
  const std::uint32_t command = std::uint32_t{code} | (std::uint32_t{b & 0x7FU} << 16U);
  if (auto c = xe::decode_direct_command(command)) {
    FUZZ_CHECK(static_cast<std::uint32_t>(c.value()) == command);
    FUZZ_CHECK(xe::to_string(c.value()) != "?");
  } else {
    FUZZ_CHECK(c.is(errc::unknown_command));
  }
}

void check_status(std::uint16_t statusword, std::uint8_t mode_byte) {
  const auto m = static_cast<xe::mode>(static_cast<std::int8_t>(mode_byte % 4U == 0U   ? -1
                                                                : mode_byte % 4U == 1U ? 1
                                                                : mode_byte % 4U == 2U ? 6
                                                                                       : 8));
  auto s = xe::decode_status(statusword, m);
  auto st = fc::ds402::decode_state(statusword);
  FUZZ_CHECK(s.has_value() == st.has_value());
  if (!s) {
    FUZZ_CHECK(s.is(errc::bad_state));
    return;
  }
  const auto &v = s.value();
  FUZZ_CHECK(v.state == st.value());
  FUZZ_CHECK(v.soft_limit_reached == ((statusword & xe::sw::soft_limit) != 0U));
  const bool b10 = (statusword & xe::sw::bit10) != 0U;
  const bool b12 = (statusword & xe::sw::bit12) != 0U;
  // each of bits 10 and 12 has at most one meaning in a given mode
  FUZZ_CHECK(static_cast<int>(v.target_reached) + static_cast<int>(v.constant_speed) +
                 static_cast<int>(v.reference_performed) <=
             (b10 ? 1 : 0));
  FUZZ_CHECK(static_cast<int>(v.set_point_acknowledge) + static_cast<int>(v.target_used) +
                 static_cast<int>(v.speed_zero) + static_cast<int>(v.reference_achieved) <=
             (b12 ? 1 : 0));
}

void check_units(const std::uint8_t *r) {
  const auto steps = static_cast<std::uint16_t>(r[0] | (r[1] << 8U));
  const auto ma = xe::current_limit_to_ma(steps);
  auto back = xe::current_limit_from_ma(fc::decimal{static_cast<std::int64_t>(ma), 0});
  if (steps != xe::no_current_limit && steps <= xe::max_current_limit) {
    FUZZ_CHECK(back.has_value() && back.value() == steps);
  } else {
    FUZZ_CHECK(back.is(errc::out_of_range));
  }
  const auto mn = static_cast<std::int32_t>(
      static_cast<std::uint32_t>(r[2]) | static_cast<std::uint32_t>(r[3]) << 8U |
      static_cast<std::uint32_t>(r[4]) << 16U | static_cast<std::uint32_t>(r[5]) << 24U);
  auto n = xe::force_n_to_mn(xe::force_mn_to_n(mn));
  FUZZ_CHECK(n.has_value() && n.value() == mn);
  const auto motor = static_cast<xe::motor>(r[6] % 10U);
  const fc::decimal force{static_cast<std::int8_t>(r[7]), static_cast<std::uint8_t>(r[6] % 4U)};
  const bool rotary = xe::is_rotary(motor);
  auto lim_n = xe::current_limit_for(xe::newtons{force}, motor);
  auto lim_t = xe::current_limit_for(xe::newton_metres{force}, motor);
  FUZZ_CHECK((rotary ? lim_n : lim_t).is(errc::invalid_argument));
  auto lim = rotary ? lim_t : lim_n;
  if (lim) {
    // never 0 (= no limit) and never from a negative force
    FUZZ_CHECK(lim.value() >= 1U && lim.value() <= xe::max_current_limit && force.mantissa > 0);
  } else {
    FUZZ_CHECK(lim.is(errc::out_of_range));
  }
  // mA -> force -> mA at a resolution finer than the constant (10 k mA/N, 1000 k mA/Nm)
  if (rotary) {
    auto t = xe::to_newton_metres(mn, motor, 6);
    FUZZ_CHECK(t.has_value() && xe::to_ma(t.value(), motor).value() == mn);
    FUZZ_CHECK(xe::to_newtons(mn, motor).is(errc::invalid_argument));
  } else {
    auto f = xe::to_newtons(mn, motor, 3);
    FUZZ_CHECK(f.has_value() && xe::to_ma(f.value(), motor).value() == mn);
    FUZZ_CHECK(xe::to_newton_metres(mn, motor).is(errc::invalid_argument));
  }
  // increments -> mm / degrees -> increments
  const std::int32_t resolution = static_cast<std::int32_t>(
      (static_cast<std::uint32_t>(r[0]) | static_cast<std::uint32_t>(r[1]) << 8U |
       static_cast<std::uint32_t>(r[7] & 0x7FU) << 24U) +
      1U);
  const xe::linear_resolution lares{resolution};
  // (9 decimal places of a huge value may not fit an int64 mantissa: overflow, never a wrong value)
  if (auto mm = xe::to_mm(mn, lares, 9)) {
    FUZZ_CHECK(xe::to_increments(mm.value(), lares).value() == mn);
  } else {
    FUZZ_CHECK(mm.is(errc::overflow));
    FUZZ_CHECK(xe::to_mm(mn, lares, 0).has_value());
  }
  const xe::rotary_resolution enc{resolution};
  if (auto deg = xe::to_degrees(mn, enc, 9)) {
    if (auto inc = xe::to_increments(deg.value(), enc)) {
      FUZZ_CHECK(inc.value() == mn);
    } else {
      FUZZ_CHECK(inc.is(errc::overflow)); // 17+ significant decimal places after normalising
    }
  } else {
    FUZZ_CHECK(deg.is(errc::overflow));
    FUZZ_CHECK(xe::to_degrees(mn, enc, 0).has_value());
  }
  FUZZ_CHECK(xe::to_mm(mn, xe::linear_resolution{-resolution}).is(errc::invalid_argument));
  // 60B2h per bus
  const auto offset = static_cast<std::int16_t>(r[2] | (r[3] << 8U));
  for (const xe::bus b : {xe::bus::canopen, xe::bus::ethercat, xe::bus::powerlink}) {
    const std::int32_t acc = xe::acceleration_from_torque_offset(offset, b);
    FUZZ_CHECK(xe::torque_offset_from_acceleration(acc, b).value() == offset);
    if (auto raw = xe::torque_offset_from_acceleration(mn, b)) {
      const std::int64_t diff =
          std::int64_t{mn} - std::int64_t{xe::acceleration_from_torque_offset(raw.value(), b)};
      FUZZ_CHECK(2 * (diff < 0 ? -diff : diff) <= xe::acceleration_scaling(b));
    } else {
      FUZZ_CHECK(raw.is(errc::overflow));
    }
  }

  // cycle time
  const xe::cycle_time t{r[0], static_cast<std::int8_t>(r[1])};
  if (auto us = xe::decode_cycle_time(t)) {
    // F7 (fixed): base 0 is refused, so every decoded time re-encodes (canonical form: the
    // shortest base, i.e. not a multiple of 10).
    auto canon = xe::encode_cycle_time(us.value());
    FUZZ_CHECK(us.value() != 0U && canon.has_value());
    FUZZ_CHECK(canon.value().base % 10U != 0U);
    FUZZ_CHECK(xe::decode_cycle_time(canon.value()).value() == us.value());
  } else if (t.base == 0U) {
    FUZZ_CHECK(xe::decode_cycle_time(t).is(errc::out_of_range));
  }
  const auto us = static_cast<std::uint32_t>(r[2]) | static_cast<std::uint32_t>(r[3]) << 8U |
                  static_cast<std::uint32_t>(r[4]) << 16U;
  if (auto e = xe::encode_cycle_time(us)) {
    FUZZ_CHECK(xe::decode_cycle_time(e.value()).value() == us);
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  for (std::size_t at = 0; at + 8 <= size; at += 8) {
    const std::uint8_t *r = data + at;
    const auto w = static_cast<std::uint16_t>(r[0] << 8U | r[1]);
    check_codes(w, r[2]);
    check_status(static_cast<std::uint16_t>(r[3] << 8U | r[4]), r[5]);
    check_units(r);
  }
  return 0;
}
