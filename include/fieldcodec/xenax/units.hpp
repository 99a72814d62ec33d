// fieldcodec — XENAX units: current in 10 mA steps (6073h), force and torque ↔ motor current
// with the force constants of the manual (6.1.2), force objects in mN, positions of linear
// axes (LARES) and rotary axes (ENC), synchronous cycle time (60C2h), process status register
// (2006h) and the direct commands of 5000h.
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>

#include <cstdint>
#include <limits>
#include <string_view>

namespace fieldcodec::xenax {

// ---------------------------------------------------------------------------------------------
// Current and force

/// 6073h Limit I_Force: UNSIGNED16 in 10 mA, 0..2000 (20 A).
inline constexpr std::uint16_t max_current_limit = 2000;
/// 6073h = 0 switches force limitation off ("No limitation occurs when the value is set to
/// zero", 6.1.2, l. 1849). Write it explicitly: no conversion below ever returns 0.
inline constexpr std::uint16_t no_current_limit = 0;

/// mA → 6073h steps, rounded half away from zero. Errors: out_of_range (negative, above 20 A,
/// or so small that it rounds to 0 steps, which the XENAX would take as "no limit").
[[nodiscard]] constexpr result<std::uint16_t> current_limit_from_ma(decimal ma) noexcept {
  auto raw = scaling::to_raw(ma, scaling::linear{{1, 1}, {0, 0}}, scaling::field{2, false});
  if (!raw) return raw.error() == errc::overflow ? errc::out_of_range : raw.error();
  if (raw.value() == 0 || raw.value() > max_current_limit) return errc::out_of_range;
  return static_cast<std::uint16_t>(raw.value());
}
/// 6073h steps → mA.
[[nodiscard]] constexpr std::uint32_t current_limit_to_ma(std::uint16_t steps) noexcept {
  return std::uint32_t{steps} * 10U;
}

/// Motors with a force (N) or torque (0.01 Nm) constant in the manual's table (6.1.2).
enum class motor : std::uint8_t {
  linax_lxc_f04,
  linax_lxc_f08,
  linax_lxc_f10,
  linax_lxc_f40,
  linax_lxe_f40,
  linax_lxu_lxs_f60,
  elax_ex_f20,
  rotax_rxhq_110_50_t1_5,
  rotax_rxhq_50_12_t0_3,
  rotax_rxvp_t0_04,
};

/// 10 mA steps per newton (linear motors) or per 0.01 Nm (ROTAX).
[[nodiscard]] constexpr decimal force_constant(motor m) noexcept {
  switch (m) {
  case motor::linax_lxc_f04: return {50, 0};
  case motor::linax_lxc_f08: return {32, 0};
  case motor::linax_lxc_f10: return {28, 0};
  case motor::linax_lxc_f40: return {11, 0};
  case motor::linax_lxe_f40: return {11, 0};
  case motor::linax_lxu_lxs_f60: return {10, 0};
  case motor::elax_ex_f20: return {12, 0};
  case motor::rotax_rxhq_110_50_t1_5: return {25, 1};
  case motor::rotax_rxhq_50_12_t0_3: return {8, 0};
  case motor::rotax_rxvp_t0_04: return {23, 0};
  }
  return {0, 0};
}
[[nodiscard]] constexpr bool is_rotary(motor m) noexcept {
  return m == motor::rotax_rxhq_110_50_t1_5 || m == motor::rotax_rxhq_50_12_t0_3 ||
         m == motor::rotax_rxvp_t0_04;
}

/// A force in newtons (LINAX, ELAX), exact.
struct newtons {
  decimal value;
};
/// A torque in newton-metres (ROTAX), exact.
struct newton_metres {
  decimal value;
};

/// Motor current per unit of force (mA/N, linear motors) or torque (mA/Nm, ROTAX): the table
/// prints "k × 10 mA ~ 1 N" and "k × 10 mA ~ 0.01 Nm", i.e. 10·k mA/N and 1000·k mA/Nm
/// (ELAX: 12 × 10 mA ~ 1 N → 120 mA/N; ROTAX Rxhq 110-50T1.5: 2.5 × 10 mA ~ 0.01 Nm →
/// 2500 mA/Nm).
[[nodiscard]] constexpr decimal current_per_force(motor m) noexcept {
  const decimal k = force_constant(m);
  const std::int64_t factor = is_rotary(m) ? 1000 : 10;
  return normalize(decimal{k.mantissa * factor, k.places});
}

namespace detail {
/// force (N or Nm) → mA as an INTEGER32, rounded half away from zero.
[[nodiscard]] constexpr result<std::int32_t> to_ma(decimal force, motor m) noexcept {
  FIELDCODEC_TRY(const std::int64_t raw,
                 scaling::to_raw(force, scaling::linear{current_per_force(m), {0, 0}},
                                 scaling::field{4, true}));
  return static_cast<std::int32_t>(raw);
}
/// force (N or Nm) → 6073h steps of 10 mA in one rounding (k steps/N, 100·k steps/Nm).
/// Errors: out_of_range (negative, above 20 A, or rounding to 0 = "no limit").
[[nodiscard]] constexpr result<std::uint16_t> limit_steps(decimal force, motor m) noexcept {
  const decimal k = force_constant(m);
  const decimal per_unit = normalize(decimal{k.mantissa * (is_rotary(m) ? 100 : 1), k.places});
  auto raw = scaling::to_raw(force, scaling::linear{per_unit, {0, 0}}, scaling::field{2, false});
  if (!raw) return raw.error() == errc::overflow ? errc::out_of_range : raw.error();
  if (raw.value() == 0 || raw.value() > max_current_limit) return errc::out_of_range;
  return static_cast<std::uint16_t>(raw.value());
}
} // namespace detail

/// Force → motor current in mA (the unit of 2005h I_Force actual), rounded half away from zero.
/// Negative forces give negative currents. Errors: invalid_argument (a ROTAX: give a torque),
/// overflow (outside INTEGER32).
[[nodiscard]] constexpr result<std::int32_t> to_ma(newtons f, motor m) noexcept {
  if (is_rotary(m)) return errc::invalid_argument;
  return detail::to_ma(f.value, m);
}
/// Torque → motor current in mA. Errors: invalid_argument (a linear motor: give a force),
/// overflow.
[[nodiscard]] constexpr result<std::int32_t> to_ma(newton_metres t, motor m) noexcept {
  if (!is_rotary(m)) return errc::invalid_argument;
  return detail::to_ma(t.value, m);
}

/// Motor current in mA (2005h, 6078h) → force in N, rounded half away from zero to `places`
/// decimal places (the table's resolutions need at most 2). Errors: invalid_argument (a ROTAX,
/// or places > 18).
[[nodiscard]] constexpr result<newtons> to_newtons(std::int32_t ma, motor m,
                                                   unsigned places = 3) noexcept {
  if (is_rotary(m)) return errc::invalid_argument;
  FIELDCODEC_TRY(const decimal f,
                 scaling::to_eu_decimal(ma, scaling::linear{current_per_force(m), {0, 0}}, places));
  return newtons{f};
}
/// Motor current in mA → torque in Nm, rounded to `places` decimal places.
/// Errors: invalid_argument (a linear motor, or places > 18).
[[nodiscard]] constexpr result<newton_metres> to_newton_metres(std::int32_t ma, motor m,
                                                               unsigned places = 4) noexcept {
  if (!is_rotary(m)) return errc::invalid_argument;
  FIELDCODEC_TRY(const decimal t,
                 scaling::to_eu_decimal(ma, scaling::linear{current_per_force(m), {0, 0}}, places));
  return newton_metres{t};
}

/// Force → 6073h Limit I_Force (10 mA steps): the manual's example (6.1.2, l. 1897-1901)
/// limits an ELAX to 4 N with 48. One rounding, half away from zero, from the exact value.
/// Errors: invalid_argument (a ROTAX), out_of_range (negative, above 20 A, or a force so small
/// that it rounds to 0 steps: 0 would switch limitation off, see no_current_limit).
[[nodiscard]] constexpr result<std::uint16_t> current_limit_for(newtons f, motor m) noexcept {
  if (is_rotary(m)) return errc::invalid_argument;
  return detail::limit_steps(f.value, m);
}
/// Torque → 6073h steps. Errors: invalid_argument (a linear motor), out_of_range.
[[nodiscard]] constexpr result<std::uint16_t> current_limit_for(newton_metres t, motor m) noexcept {
  if (!is_rotary(m)) return errc::invalid_argument;
  return detail::limit_steps(t.value, m);
}

// 2005h I_Force actual: INTEGER32 mA. 6078h motor current: INTEGER16 mA (±20000).
// 2009h limit force and 200Ah actual force: INTEGER32 mN (Xvi 75V8S with Signateq).

/// mN (2009h / 200Ah) → N as an exact decimal.
[[nodiscard]] constexpr decimal force_mn_to_n(std::int32_t mn) noexcept { return {mn, 3}; }
/// N → mN for 2009h. Errors: overflow (outside INTEGER32), invalid_argument.
[[nodiscard]] constexpr result<std::int32_t> force_n_to_mn(decimal n) noexcept {
  auto raw = scaling::to_raw(n, scaling::linear{{1000, 0}, {0, 0}}, scaling::field{4, true});
  if (!raw) return raw.error();
  return static_cast<std::int32_t>(raw.value());
}

// ---------------------------------------------------------------------------------------------
// Positions, speeds and accelerations in engineering units. The XENAX counts encoder
// increments (6064h, 607Ah: inc; 6081h: inc/s; 6083h: inc/s²). A linear axis reports its
// resolution in 5001h sub 43 (LARES, "linear axis resolution in [inc/m]", l. 851); a rotary
// axis (ROTAX, third-party motors) has ENC increments per turn of the motor shaft (5004h
// sub 2, default 0x5DC0 = 24 000, limits 10..10 000 000, l. 1005). The same factor converts
// speeds and accelerations (mm/s ↔ inc/s, °/s² ↔ inc/s²).

/// LARES of a linear axis: increments per metre (5001h sub 43).
struct linear_resolution {
  std::int32_t inc_per_m = 0;
};
/// ENC of a rotary axis: increments per turn (5004h sub 2).
struct rotary_resolution {
  std::int32_t inc_per_turn = 0;
};

namespace detail {
/// Increments per mm: LARES / 1000, an exact decimal.
[[nodiscard]] constexpr result<scaling::linear> per_mm(linear_resolution r) noexcept {
  if (r.inc_per_m <= 0) return errc::invalid_argument;
  return scaling::linear{decimal{r.inc_per_m, 3}, {0, 0}};
}
/// a × b exactly. Errors: overflow (beyond int64).
[[nodiscard]] constexpr result<std::int64_t> product(std::int64_t a, std::int64_t b) noexcept {
  return scaling::scale_to_raw(decimal{a, 0}, scaling::linear{decimal{b, 0}, {0, 0}});
}
/// num / den rounded half away from zero to `places` (den > 0). Errors: overflow.
[[nodiscard]] constexpr result<decimal> quotient(std::int64_t num, std::int64_t den,
                                                 unsigned places) noexcept {
  return scaling::to_eu_decimal(num, scaling::linear{decimal{den, 0}, {0, 0}}, places);
}
[[nodiscard]] constexpr result<std::int32_t> to_int32(result<decimal> d) noexcept {
  FIELDCODEC_TRY(const decimal q, d);
  const std::int64_t v = q.mantissa;
  if (v < std::numeric_limits<std::int32_t>::min() ||
      v > std::numeric_limits<std::int32_t>::max()) {
    return errc::overflow;
  }
  return static_cast<std::int32_t>(v);
}
} // namespace detail

/// mm (mm/s, mm/s²) → increments (inc/s, inc/s²) for 6064h/607Ah/6081h/6083h:
/// round(mm × LARES / 1000), half away from zero. Errors: invalid_argument (LARES not
/// positive), overflow (outside INTEGER32).
[[nodiscard]] constexpr result<std::int32_t> to_increments(decimal mm,
                                                           linear_resolution r) noexcept {
  FIELDCODEC_TRY(const scaling::linear s, detail::per_mm(r));
  FIELDCODEC_TRY(const std::int64_t raw, scaling::to_raw(mm, s, scaling::field{4, true}));
  return static_cast<std::int32_t>(raw);
}
/// Increments → mm: inc × 1000 / LARES, exact, rounded half away from zero to `places`.
/// Errors: invalid_argument (LARES not positive, places > 18), overflow.
[[nodiscard]] constexpr result<decimal> to_mm(std::int64_t inc, linear_resolution r,
                                              unsigned places = 3) noexcept {
  FIELDCODEC_TRY(const scaling::linear s, detail::per_mm(r));
  return scaling::to_eu_decimal(inc, s, places);
}

/// Degrees (°/s, °/s²) → increments: round(degrees × ENC / 360), half away from zero, with a
/// single rounding (ENC / 360 is rarely a finite decimal: 24 000 / 360 = 66.6…).
/// Errors: invalid_argument (ENC not positive), overflow (outside INTEGER32, or more than 16
/// decimal places).
[[nodiscard]] constexpr result<std::int32_t> to_increments(decimal degrees,
                                                           rotary_resolution r) noexcept {
  if (r.inc_per_turn <= 0) return errc::invalid_argument;
  const decimal d = normalize(degrees);
  if (d.places > 16U) return errc::overflow; // 360 × 10^places must fit int64
  std::int64_t den = 360;
  for (unsigned i = 0; i < d.places; ++i) den *= 10;
  FIELDCODEC_TRY(const std::int64_t num, detail::product(d.mantissa, r.inc_per_turn));
  return detail::to_int32(detail::quotient(num, den, 0));
}
/// Increments → degrees: inc × 360 / ENC, exact, rounded half away from zero to `places`.
/// Errors: invalid_argument (ENC not positive, places > 18), overflow.
[[nodiscard]] constexpr result<decimal> to_degrees(std::int64_t inc, rotary_resolution r,
                                                   unsigned places = 3) noexcept {
  if (r.inc_per_turn <= 0) return errc::invalid_argument;
  FIELDCODEC_TRY(const std::int64_t num, detail::product(inc, 360));
  return detail::quotient(num, r.inc_per_turn, places);
}

// ---------------------------------------------------------------------------------------------
// 60C2h synchronous cycle time = base × 10^exponent seconds (sub 1 UNSIGNED8, sub 2 INTEGER8)

struct cycle_time {
  std::uint8_t base;
  std::int8_t exponent;
  friend constexpr bool operator==(const cycle_time &, const cycle_time &) = default;
};

/// µs → the shortest (base, exponent) form, e.g. 500 → {5, -4}, 1000 → {1, -3}, 250 → {25, -5}.
/// Errors: out_of_range (0, or no base <= 255 with exponent >= -6 represents it).
[[nodiscard]] constexpr result<cycle_time> encode_cycle_time(std::uint32_t us) noexcept {
  if (us == 0U) return errc::out_of_range;
  int exponent = -6;
  while (us % 10U == 0U) {
    us /= 10U;
    ++exponent;
  }
  if (us > 255U) return errc::out_of_range;
  return cycle_time{static_cast<std::uint8_t>(us), static_cast<std::int8_t>(exponent)};
}
/// (base, exponent) → µs. Errors: out_of_range (base 0: no cycle, which encode_cycle_time
/// refuses too — fuzz F7), not_representable (not a whole number of µs), overflow.
[[nodiscard]] constexpr result<std::uint32_t> decode_cycle_time(cycle_time t) noexcept {
  if (t.base == 0U) return errc::out_of_range;
  std::uint64_t v = t.base;
  int e = t.exponent + 6;
  if (e < 0) {
    while (e < 0) {
      if (v % 10U != 0U) return errc::not_representable;
      v /= 10U;
      ++e;
    }
  }
  for (; e > 0; --e) {
    v *= 10U;
    if (v > 0xFFFF'FFFFU) return errc::overflow;
  }
  return static_cast<std::uint32_t>(v);
}

// ---------------------------------------------------------------------------------------------
// 2006h process status register (bits)

namespace psr {
inline constexpr std::uint32_t error = 1U << 0U;
inline constexpr std::uint32_t reference = 1U << 1U;
inline constexpr std::uint32_t in_motion = 1U << 2U;
inline constexpr std::uint32_t in_position = 1U << 3U;
inline constexpr std::uint32_t end_of_program = 1U << 4U;
inline constexpr std::uint32_t in_force = 1U << 5U;
inline constexpr std::uint32_t in_sector = 1U << 6U;
inline constexpr std::uint32_t force_in_sector = 1U << 7U;
inline constexpr std::uint32_t inverter_voltage = 1U << 8U;
inline constexpr std::uint32_t end_of_gantry_init = 1U << 9U;
inline constexpr std::uint32_t negative_limit_switch = 1U << 10U;
inline constexpr std::uint32_t positive_limit_switch = 1U << 11U;
inline constexpr std::uint32_t emergency_exit_1 = 1U << 12U;
inline constexpr std::uint32_t emergency_exit = 1U << 13U;
inline constexpr std::uint32_t force_calibration_active = 1U << 14U;
inline constexpr std::uint32_t i_force_limit_reached = 1U << 15U;
inline constexpr std::uint32_t sto = 1U << 16U;
inline constexpr std::uint32_t ss1 = 1U << 17U;
inline constexpr std::uint32_t ss2_primed = 1U << 18U;
inline constexpr std::uint32_t ss2_hit = 1U << 19U;
inline constexpr std::uint32_t sls_primed = 1U << 20U;
inline constexpr std::uint32_t sls_speed_hit = 1U << 21U;
inline constexpr std::uint32_t sls_position_hit = 1U << 22U;
inline constexpr std::uint32_t warning = 1U << 23U;
inline constexpr std::uint32_t information = 1U << 24U;
inline constexpr std::uint32_t phasing_done = 1U << 25U;
inline constexpr std::uint32_t i_force_drift_compensation_active = 1U << 26U;
inline constexpr std::uint32_t force_limit_reached = 1U << 27U;
inline constexpr std::uint32_t unused_mask = 0xF000'0000U;
} // namespace psr

// ---------------------------------------------------------------------------------------------
// 5000h direct commands (3.4.1, l. 758-798): the value written to 5000h (UNSIGNED32) is the
// command. All of the table; 0x1040 and 0x3060 are printed "reserved" and are not commands.

enum class direct_command : std::uint32_t {
  // Ref/Power
  reference = 0x1000,                    ///< reference / power-on program (phasing, position)
  limit_stop = 0x1020,                   ///< RSTO, mechanical reference for LINAX
  mechanical_limit_calibration = 0x1030, ///< MLC
  auto_reference = 0x1050,               ///< AREF1, reference when entering mode 6
  // Power
  power = 0x2000,          ///< PW, power on (rotary motors only)
  power_continue = 0x2010, ///< PWC, continue at the actual position (after error 50 or PQ)
  power_reset = 0x2020,    ///< PWR, search the electrical angle again (for test only)
  power_quit = 0x2030,     ///< PQ
  // Motion
  go_position = 0x3000,  ///< GP
  go_way = 0x3010,       ///< GW
  jog_positive = 0x3020, ///< JP
  jog_negative = 0x3030, ///< JN
  stop_motion = 0x3040,  ///< SM
  go_z_mark = 0x3050,    ///< GZ, rotate to the Z-mark
  // Cogging
  force_calibration = 0x4000,                    ///< FC (distance parameter WA)
  force_calibration_test_on = 0x4001,            ///< FCT1, with active compensation
  force_calibration_test_off = 0x4002,           ///< FCT0, position controller active
  force_calibration_test_uncompensated = 0x4003, ///< FCT2, without active compensation
  i_force_drift_compensation_positive = 0x4010,  ///< IFDCP
  i_force_drift_compensation_negative = 0x4011,  ///< IFDCN
  // Init
  reset = 0x5000,                      ///< RES
  reset_motor_settings = 0x5001,       ///< RESM
  clear_captured_positions = 0x5010,   ///< CLCP
  capture_input_on = 0x5015,           ///< CP12 on (Xvi75V8/75V8S), CP4 on (Xvi48V8)
  capture_input_off = 0x5016,          ///< CP12 off (Xvi75V8/75V8S), CP4 off (Xvi48V8)
  clear_position_counter = 0x5020,     ///< CLPO (rotary motors only)
  deactivate_motion_blocking = 0x5030, ///< DMBUS, motion blocking by an unconfigured SMU
  // Force control
  start_force_monitoring = 0x6000,       ///< in cyclic synchronous position mode
  finish_force_monitoring = 0x6001,      ///< analyse the move since 0x6000 (PSR bit 7 valid)
  touch_position_sector_offset = 0x6002, ///< TPSO, take the position as sector offset
  clear_force_offset = 0x6010,           ///< CLFO
  // Bootloader, VARAN only: not accepted over CANopen, EtherCAT or POWERLINK
  prepare_bootloader = 0x7000, ///< first value
  start_bootloader = 0x7001,   ///< second value
};

/// The table's commands in value order.
inline constexpr direct_command direct_commands[] = {
    direct_command::reference,
    direct_command::limit_stop,
    direct_command::mechanical_limit_calibration,
    direct_command::auto_reference,
    direct_command::power,
    direct_command::power_continue,
    direct_command::power_reset,
    direct_command::power_quit,
    direct_command::go_position,
    direct_command::go_way,
    direct_command::jog_positive,
    direct_command::jog_negative,
    direct_command::stop_motion,
    direct_command::go_z_mark,
    direct_command::force_calibration,
    direct_command::force_calibration_test_on,
    direct_command::force_calibration_test_off,
    direct_command::force_calibration_test_uncompensated,
    direct_command::i_force_drift_compensation_positive,
    direct_command::i_force_drift_compensation_negative,
    direct_command::reset,
    direct_command::reset_motor_settings,
    direct_command::clear_captured_positions,
    direct_command::capture_input_on,
    direct_command::capture_input_off,
    direct_command::clear_position_counter,
    direct_command::deactivate_motion_blocking,
    direct_command::start_force_monitoring,
    direct_command::finish_force_monitoring,
    direct_command::touch_position_sector_offset,
    direct_command::clear_force_offset,
    direct_command::prepare_bootloader,
    direct_command::start_bootloader,
};

/// The terminal mnemonic the table prints for the command (empty where it prints none:
/// 0x1000, 0x6000, 0x6001, 0x7000, 0x7001). 0x5015/0x5016 give the Xvi75V8 name, CP12.
[[nodiscard]] constexpr std::string_view mnemonic(direct_command c) noexcept {
  switch (c) {
  case direct_command::limit_stop: return "RSTO";
  case direct_command::mechanical_limit_calibration: return "MLC";
  case direct_command::auto_reference: return "AREF1";
  case direct_command::power: return "PW";
  case direct_command::power_continue: return "PWC";
  case direct_command::power_reset: return "PWR";
  case direct_command::power_quit: return "PQ";
  case direct_command::go_position: return "GP";
  case direct_command::go_way: return "GW";
  case direct_command::jog_positive: return "JP";
  case direct_command::jog_negative: return "JN";
  case direct_command::stop_motion: return "SM";
  case direct_command::go_z_mark: return "GZ";
  case direct_command::force_calibration: return "FC";
  case direct_command::force_calibration_test_on: return "FCT1";
  case direct_command::force_calibration_test_off: return "FCT0";
  case direct_command::force_calibration_test_uncompensated: return "FCT2";
  case direct_command::i_force_drift_compensation_positive: return "IFDCP";
  case direct_command::i_force_drift_compensation_negative: return "IFDCN";
  case direct_command::reset: return "RES";
  case direct_command::reset_motor_settings: return "RESM";
  case direct_command::clear_captured_positions: return "CLCP";
  case direct_command::capture_input_on:
  case direct_command::capture_input_off: return "CP12";
  case direct_command::clear_position_counter: return "CLPO";
  case direct_command::deactivate_motion_blocking: return "DMBUS";
  case direct_command::touch_position_sector_offset: return "TPSO";
  case direct_command::clear_force_offset: return "CLFO";
  case direct_command::reference:
  case direct_command::start_force_monitoring:
  case direct_command::finish_force_monitoring:
  case direct_command::prepare_bootloader:
  case direct_command::start_bootloader: return "";
  }
  return "";
}

/// What the command does, in a few words.
[[nodiscard]] constexpr std::string_view to_string(direct_command c) noexcept {
  switch (c) {
  case direct_command::reference: return "reference";
  case direct_command::limit_stop: return "limit stop (mechanical reference)";
  case direct_command::mechanical_limit_calibration: return "mechanical limit calibration";
  case direct_command::auto_reference: return "automatic reference on entering mode 6";
  case direct_command::power: return "power on";
  case direct_command::power_continue: return "power continue at the actual position";
  case direct_command::power_reset: return "power reset";
  case direct_command::power_quit: return "power quit";
  case direct_command::go_position: return "go position";
  case direct_command::go_way: return "go way";
  case direct_command::jog_positive: return "jog positive";
  case direct_command::jog_negative: return "jog negative";
  case direct_command::stop_motion: return "stop motion";
  case direct_command::go_z_mark: return "rotate to Z-mark";
  case direct_command::force_calibration: return "force calibration";
  case direct_command::force_calibration_test_on: return "force calibration test mode on";
  case direct_command::force_calibration_test_off: return "force calibration test mode off";
  case direct_command::force_calibration_test_uncompensated:
    return "force calibration test mode on, without compensation";
  case direct_command::i_force_drift_compensation_positive:
    return "I_Force drift compensation drive, positive";
  case direct_command::i_force_drift_compensation_negative:
    return "I_Force drift compensation drive, negative";
  case direct_command::reset: return "reset";
  case direct_command::reset_motor_settings: return "reset motor specific settings";
  case direct_command::clear_captured_positions: return "clear all captured positions";
  case direct_command::capture_input_on: return "captured position input on";
  case direct_command::capture_input_off: return "captured position input off";
  case direct_command::clear_position_counter: return "clear position counter";
  case direct_command::deactivate_motion_blocking:
    return "deactivate motion blocking by unconfigured SMU";
  case direct_command::start_force_monitoring: return "start force monitoring";
  case direct_command::finish_force_monitoring: return "finish force monitoring";
  case direct_command::touch_position_sector_offset: return "take position as sector offset";
  case direct_command::clear_force_offset: return "clear force offset";
  case direct_command::prepare_bootloader: return "prepare bootloader activation (VARAN)";
  case direct_command::start_bootloader: return "start bootloader (VARAN)";
  }
  return "?";
}

/// The bootloader commands exist only on VARAN, which this library does not speak.
[[nodiscard]] constexpr bool is_varan_only(direct_command c) noexcept {
  return c == direct_command::prepare_bootloader || c == direct_command::start_bootloader;
}

/// The command a 5000h value names. Errors: unknown_command (0, the reserved 0x1040 and
/// 0x3060, anything not in the table).
[[nodiscard]] constexpr result<direct_command> decode_direct_command(std::uint32_t v) noexcept {
  for (const direct_command c : direct_commands) {
    if (static_cast<std::uint32_t>(c) == v) return c;
  }
  return errc::unknown_command;
}

} // namespace fieldcodec::xenax
