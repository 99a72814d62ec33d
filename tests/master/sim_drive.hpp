// A scripted CiA 402 drive for the master tests: applies controlwords with ds402::apply, shows
// the statusword, answers the SDO requests of master::drive, and can be told to misbehave
// (never acknowledge, refuse a fault reset, change its mode, fail, abort an SDO, never answer).
#pragma once

#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/master/drive.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace sim {

namespace ds402 = fieldcodec::ds402;
namespace master = fieldcodec::master;
namespace sdo = fieldcodec::canopen::sdo;

struct drive {
  ds402::state st = ds402::state::switch_on_disabled;
  std::uint16_t prev_cw = 0;
  std::int8_t mode = 0;         // 6061h
  std::int8_t mode_request = 0; // 6060h
  int mode_delay = 1;           // cycles until 6061h follows 6060h
  int mode_countdown = -1;
  bool follows_mode = true; // false: 6061h never follows
  // profile position
  bool ack = false;
  bool never_ack = false;
  bool reached = true;
  int move_cycles = 3;
  int countdown = -1;
  std::int32_t target = 0;
  std::int32_t position = 0;
  std::int32_t target_sdo = 0;
  bool relative = false;
  // homing
  bool homing_active = false;
  bool homing_attained = true; // left over from an earlier run
  bool homing_error_next = false;
  bool homing_error = false;
  int homing_cycles = 4;
  std::int8_t homing_method = 0;
  // jog (XENAX bit 12 speed zero)
  bool speed_zero = true;
  // faults
  int reset_refusals = 0; // fault resets ignored before one works
  std::uint16_t error_code = 0;
  // SDO
  std::optional<sdo::abort_code> abort_next{};
  bool sdo_silent = false;
  std::vector<master::sdo_request> requests{};
  bool following_error = false;
  std::uint16_t extra_status = 0; // statusword bits of a manufacturer mode, set by the test

  [[nodiscard]] std::uint16_t statusword() const {
    auto w = static_cast<std::uint16_t>(ds402::state_bits(st) | ds402::sw::voltage_enabled |
                                        ds402::sw::remote);
    const auto set = [&w](bool on, std::uint16_t bit) {
      if (on) w = static_cast<std::uint16_t>(w | bit);
    };
    if (mode == 1) {
      set(reached, ds402::sw::target_reached);
      set(ack, ds402::sw::pp_set_point_acknowledge);
      set(following_error, ds402::sw::pp_following_error);
    } else if (mode == 6) {
      set(!homing_active && homing_attained, ds402::sw::hm_attained);
      set(!homing_active && homing_attained, ds402::sw::target_reached);
      set(homing_error, ds402::sw::hm_error);
    } else if (mode == -1) {
      set(speed_zero, 1U << 12U);
    } else if (mode < 0) {
      w = static_cast<std::uint16_t>(w | extra_status);
    }
    return w;
  }

  void fault(std::uint16_t code) {
    st = ds402::state::fault;
    error_code = code;
    ack = false;
    countdown = -1;
    homing_active = false;
  }

  void apply(std::uint16_t cw) {
    const auto was = st;
    const auto r = ds402::apply(st, cw, prev_cw);
    if (r.transition == 15 && reset_refusals > 0) {
      --reset_refusals;
    } else {
      st = r.to;
      if (r.transition == 15) error_code = 0;
    }
    const bool rising4 = (cw & 0x10U) != 0U && (prev_cw & 0x10U) == 0U;
    prev_cw = cw;
    if (mode_countdown > 0 && --mode_countdown == 0) mode = mode_request;
    if (st != ds402::state::operation_enabled || was != ds402::state::operation_enabled) {
      return;
    }
    if (mode == 1) {
      if (rising4 && !ack && !never_ack) {
        ack = true;
        reached = false;
        relative = (cw & 0x40U) != 0U;
        target = relative ? position + target_sdo : target_sdo;
        countdown = move_cycles;
      }
      if ((cw & 0x10U) == 0U) ack = false;
      if (countdown > 0 && --countdown == 0) {
        position = target;
        reached = true;
      }
    } else if (mode == 6) {
      if (rising4) {
        homing_active = true;
        homing_attained = false;
        countdown = homing_cycles;
      }
      if (homing_active && countdown > 0 && --countdown == 0) {
        homing_active = false;
        if (homing_error_next) {
          homing_error = true;
        } else {
          homing_attained = true;
          position = 0;
        }
      }
    } else if (mode == -1) {
      speed_zero = (cw & 0x10U) == 0U || (cw & 0x100U) != 0U;
    }
  }

  /// Run one request; nullopt: no answer (the caller's SDO client would time out).
  std::optional<fieldcodec::result<std::vector<std::uint8_t>, sdo::transfer_error>>
  serve(const master::sdo_request &r) {
    requests.push_back(r);
    if (sdo_silent) return std::nullopt;
    if (abort_next) {
      const auto code = *abort_next;
      abort_next.reset();
      return sdo::transfer_error{fieldcodec::errc::aborted, code, r.address};
    }
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4U; ++i) v |= std::uint32_t{r.data[i]} << (8U * i);
    if (r.what == master::sdo_request::kind::download) {
      if (r.address == master::obj::modes_of_operation) {
        mode_request = static_cast<std::int8_t>(r.data[0]);
        if (follows_mode) mode_countdown = mode_delay;
      } else if (r.address == master::obj::target_position) {
        target_sdo = static_cast<std::int32_t>(v);
      } else if (r.address == master::obj::homing_method) {
        homing_method = static_cast<std::int8_t>(r.data[0]);
      }
      return std::vector<std::uint8_t>{};
    }
    if (r.address == master::obj::modes_of_operation_display) {
      return std::vector<std::uint8_t>{static_cast<std::uint8_t>(mode)};
    }
    if (r.address == master::obj::error_code) {
      return std::vector<std::uint8_t>{static_cast<std::uint8_t>(error_code),
                                       static_cast<std::uint8_t>(error_code >> 8U)};
    }
    return sdo::transfer_error{fieldcodec::errc::aborted, sdo::abort_code::no_object, r.address};
  }
};

/// The cyclic task: statusword in, controlword out, SDO requests served at once.
struct bench {
  master::drive axis;
  drive dev{};
  std::uint32_t now = 1000;
  bool mode_in_pdo = false;
  master::drive_step last{};
  std::vector<std::uint16_t> controlwords{};

  explicit bench(master::drive_options o = {}) : axis(o) {}

  master::drive_step cycle() {
    std::optional<std::int8_t> disp;
    if (mode_in_pdo) disp = dev.mode;
    last = axis.cycle(dev.statusword(), now, disp);
    if (last.sdo) {
      auto answer = dev.serve(*last.sdo);
      if (answer) {
        if (answer->has_value()) {
          axis.sdo_done(answer->value(), now);
        } else {
          axis.sdo_failed(answer->error(), now);
        }
      }
    }
    if (last.sdo && last.sdo->address == master::obj::target_position) {
      // nothing: the simulated drive took it from the SDO
    } else if (!axis.sdo_pending()) {
      dev.target_sdo = last.target; // the RPDO carries the target
    }
    controlwords.push_back(last.controlword);
    dev.apply(last.controlword);
    now += 10;
    return last;
  }
  /// Cycle until the machine is no longer busy (at most `limit` cycles).
  int run(int limit = 200) {
    int n = 0;
    do {
      cycle();
      ++n;
    } while (axis.busy() && n < limit);
    return n;
  }
};

} // namespace sim
