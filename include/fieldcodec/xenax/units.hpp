// fieldcodec — XENAX units: current in 10 mA steps (6073h), force constants (manual 6.1.2),
// force objects in mN, synchronous cycle time (60C2h), process status register (2006h) and the
// direct commands of 5000h.
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>

#include <cstdint>
#include <string_view>

namespace fieldcodec::xenax {

// ---------------------------------------------------------------------------------------------
// Current and force

/// 6073h Limit I_Force: UNSIGNED16 in 10 mA, 0..2000 (20 A); 0 = no limit.
inline constexpr std::uint16_t max_current_limit = 2000;

/// mA → 6073h steps, rounded half away from zero. Errors: out_of_range (negative or > 20 A).
[[nodiscard]] constexpr result<std::uint16_t> current_limit_from_ma(decimal ma) noexcept {
  auto raw = scaling::to_raw(ma, scaling::linear{{1, 1}, {0, 0}}, scaling::field{2, false});
  if (!raw) return raw.error() == errc::overflow ? errc::out_of_range : raw.error();
  if (raw.value() > max_current_limit) return errc::out_of_range;
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

/// Force (N, linear motors) or torque (in units of 0.01 Nm, ROTAX) → 6073h steps:
/// round(force × constant), half away from zero. Errors: out_of_range (negative, or above
/// 20 A), invalid_argument (bad decimal).
[[nodiscard]] constexpr result<std::uint16_t> current_limit_for_force(decimal force,
                                                                      motor m) noexcept {
  auto raw =
      scaling::to_raw(force, scaling::linear{force_constant(m), {0, 0}}, scaling::field{2, false});
  if (!raw) return raw.error() == errc::overflow ? errc::out_of_range : raw.error();
  if (raw.value() > max_current_limit) return errc::out_of_range;
  return static_cast<std::uint16_t>(raw.value());
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
// 5000h direct commands (value written to 5000h)

enum class direct_command : std::uint32_t {
  reference = 0x1000,                    ///< REF
  limit_stop = 0x1020,                   ///< RSTO
  mechanical_limit_calibration = 0x1030, ///< MLC
  auto_reference = 0x1050,               ///< AREF1
  power = 0x2000,                        ///< PW
  power_continue = 0x2010,               ///< PWC
  power_reset = 0x2020,                  ///< PWR
  power_quit = 0x2030,                   ///< PQ
  go_position = 0x3000,                  ///< GP
  go_way = 0x3010,                       ///< GW
  jog_positive = 0x3020,                 ///< JP
  jog_negative = 0x3030,                 ///< JN
  stop_motion = 0x3040,                  ///< SM
  go_z_mark = 0x3050,                    ///< GZ
  force_calibration = 0x4000,            ///< FC
  reset = 0x5000,                        ///< RES
  start_force_monitoring = 0x6000,
  finish_force_monitoring = 0x6001,
  touch_position_sector_offset = 0x6002, ///< TPSO
};

} // namespace fieldcodec::xenax
