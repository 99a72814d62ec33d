// fieldcodec — the CiA 402 drive helper of a master: one machine per axis, called by the cyclic
// task with the statusword it received (TPDO) and returning the controlword to send (RPDO), the
// target value of the active mode and, when needed, one SDO transfer for the caller to run.
//
//   master::drive axis({.profile = profile});   // ds402::cia402_profile or a vendor's
//   (void)axis.enable(now);
//   every cycle:
//     auto out = axis.cycle(statusword, now, mode_display);   // mode_display: 6061h if mapped
//     rpdo.set(controlword, out.controlword); rpdo.set(target, out.target);
//     if (out.sdo) run it with the SDO client, then axis.sdo_done(value, now) / sdo_failed(e, now)
//   on an EMCY of the axis: axis.on_emcy(message)
//
// Pure: no heap, no I/O, no clock (now is the caller's millisecond counter, wrap-around safe).
// It knows words, not frames: the caller's PDO mapping puts them on the bus (docs/master.md).
// It knows CiA 402 and no vendor: what a drive family does beyond CiA 402 (bits a cyclic mode
// needs, manufacturer motions such as a jog) comes in as a ds402::drive_profile the vendor's
// folder supplies; the default is plain CiA 402.
#pragma once

#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/sdo_transfer.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/ds402/controlword.hpp>
#include <fieldcodec/ds402/drive_profile.hpp>
#include <fieldcodec/ds402/modes.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/ds402/statusword.hpp>
#include <fieldcodec/od/address.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace fieldcodec::master {

/// One SDO transfer the caller runs for a machine (through its `sdo::client`): a download of
/// 1..4 bytes (little-endian) or an upload.
struct sdo_request {
  enum class kind : std::uint8_t { download, upload };
  kind what = kind::download;
  od::address address{};
  std::array<std::uint8_t, 4> data{};
  std::uint8_t size = 0; ///< download: bytes of `data` to send
  [[nodiscard]] constexpr std::span<const std::uint8_t> bytes() const noexcept {
    return std::span<const std::uint8_t>(data).first(size);
  }
  friend constexpr bool operator==(const sdo_request &, const sdo_request &) = default;
};

/// The request for a download of `size` bytes of `value` (little-endian) to `a` (a request the
/// caller's SDO client carries out; host::sdo_write is a transfer itself).
[[nodiscard]] constexpr sdo_request write_request(od::address a, std::uint32_t value,
                                                  std::uint8_t size) noexcept {
  sdo_request r{sdo_request::kind::download, a, {}, size};
  for (std::size_t i = 0; i < 4U; ++i) r.data[i] = static_cast<std::uint8_t>(value >> (8U * i));
  return r;
}
/// The request for an upload of `a`.
[[nodiscard]] constexpr sdo_request read_request(od::address a) noexcept {
  return {sdo_request::kind::upload, a, {}, 0};
}

/// Objects the drive helper reads or writes over SDO (CiA 402).
namespace obj {
inline constexpr od::address error_code{0x603F, 0};
inline constexpr od::address modes_of_operation{0x6060, 0};
inline constexpr od::address modes_of_operation_display{0x6061, 0};
inline constexpr od::address target_position{0x607A, 0};
inline constexpr od::address homing_method{0x6098, 0};
inline constexpr od::address target_velocity{0x60FF, 0};
inline constexpr od::address target_torque{0x6071, 0};
} // namespace obj

/// What the machine is doing.
enum class drive_state : std::uint8_t {
  idle,           ///< nothing commanded yet, or disabled / quick-stopped as asked
  enabling,       ///< walking to operation enabled
  enabled,        ///< operation enabled, no motion command running
  disabling,      ///< walking to the state disable() asked for
  quick_stopping, ///< quick stop sent, waiting for quick stop active / switch on disabled
  resetting,      ///< fault reset: rising edge of bit 7, bounded retries
  switching_mode, ///< 6060h written, waiting for 6061h
  moving,         ///< profile position: set-point handshake, then until target reached
  homing,         ///< homing started, until attained or error
  running,        ///< profile velocity / cyclic synchronous / a manufacturer motion: runs
                  ///< until told otherwise
  stopping,       ///< a manufacturer motion stopped, waiting for its stopped bits
  fault,          ///< the drive is in fault (error() says which, 603Fh and the EMCY)
  failed,         ///< the last command failed (error() says why); the drive may still be enabled
};

[[nodiscard]] constexpr std::string_view to_string(drive_state s) noexcept {
  switch (s) {
  case drive_state::idle: return "idle";
  case drive_state::enabling: return "enabling";
  case drive_state::enabled: return "enabled";
  case drive_state::disabling: return "disabling";
  case drive_state::quick_stopping: return "quick stopping";
  case drive_state::resetting: return "resetting fault";
  case drive_state::switching_mode: return "switching mode";
  case drive_state::moving: return "moving";
  case drive_state::homing: return "homing";
  case drive_state::running: return "running";
  case drive_state::stopping: return "stopping";
  case drive_state::fault: return "fault";
  case drive_state::failed: return "failed";
  }
  return "?";
}

/// Why a command failed or the drive left what it was told to do.
enum class drive_failure : std::uint8_t {
  bad_statusword,             ///< the statusword matches no CiA 402 state
  enable_timeout,             ///< operation enabled not reached in time
  disable_timeout,            ///< the disable target not reached in time
  quick_stop_timeout,         ///< quick stop active / switch on disabled not reached in time
  fault,                      ///< the drive went to fault (603Fh and EMCY in the error)
  fault_reset_failed,         ///< still in fault after all reset attempts
  mode_not_confirmed,         ///< 6061h did not show the requested mode in time
  mode_changed,               ///< 6061h changed without being asked to
  set_point_not_acknowledged, ///< pp: bit 12 did not follow bit 4 in time
  following_error,            ///< pp / csp: bit 13
  move_timeout,               ///< pp: target not reached in time
  homing_error,               ///< homing: bit 13
  homing_timeout,             ///< homing not attained in time
  left_operation_enabled,     ///< the drive left operation enabled without a fault
  sdo_failed,                 ///< an SDO transfer the machine asked for failed
  stop_timeout,               ///< a manufacturer motion did not show its stopped bits in time
};

[[nodiscard]] constexpr std::string_view to_string(drive_failure f) noexcept {
  switch (f) {
  case drive_failure::bad_statusword: return "statusword matches no state";
  case drive_failure::enable_timeout: return "operation enabled not reached in time";
  case drive_failure::disable_timeout: return "disable target not reached in time";
  case drive_failure::quick_stop_timeout: return "quick stop not reached in time";
  case drive_failure::fault: return "drive fault";
  case drive_failure::fault_reset_failed: return "fault reset failed";
  case drive_failure::mode_not_confirmed: return "mode of operation not confirmed (6061h)";
  case drive_failure::mode_changed: return "mode of operation changed by the drive";
  case drive_failure::set_point_not_acknowledged: return "set-point not acknowledged";
  case drive_failure::following_error: return "following error";
  case drive_failure::move_timeout: return "target not reached in time";
  case drive_failure::homing_error: return "homing error";
  case drive_failure::homing_timeout: return "homing not attained in time";
  case drive_failure::left_operation_enabled: return "drive left operation enabled";
  case drive_failure::sdo_failed: return "SDO transfer failed";
  case drive_failure::stop_timeout: return "motion not stopped in time";
  }
  return "?";
}

/// The reason of a failure, with context.
struct drive_error {
  drive_failure failure = drive_failure::fault;
  errc code = errc::bad_state;  ///< timeout for the timeouts, aborted/... for SDO failures
  ds402::state seen{};          ///< the drive's state when it happened
  std::uint16_t statusword = 0; ///< the statusword when it happened
  std::uint16_t error_code = 0; ///< 603Fh (fault; 0 until read; a manufacturer-specific code
                                ///< is decoded by the vendor's module)
  bool error_code_read = false; ///< 603Fh was read
  std::optional<canopen::emcy::message> emcy{};      ///< the EMCY that came with a fault
  std::optional<canopen::sdo::transfer_error> sdo{}; ///< sdo_failed: the transfer's error
  std::int8_t mode = 0;                              ///< mode failures: the mode 6061h showed

  [[nodiscard]] constexpr bool is(errc e) const noexcept { return code == e; }
};

struct drive_options {
  /// What the drive does beyond CiA 402 (ds402/drive_profile.hpp): plain CiA 402 by default; a
  /// vendor's folder supplies its own.
  ds402::drive_profile profile = ds402::cia402_profile;
  std::uint32_t enable_timeout_ms = 1000;
  std::uint32_t disable_timeout_ms = 1000;
  std::uint32_t reset_timeout_ms = 500; ///< per attempt, from the rising edge
  std::uint8_t reset_attempts = 3;      ///< rising edges before fault_reset_failed (≥ 1)
  std::uint32_t mode_timeout_ms = 1000;
  std::uint32_t set_point_timeout_ms = 200;
  std::uint32_t move_timeout_ms = 0; ///< 0: a move may take as long as it takes
  std::uint32_t homing_timeout_ms = 60000;
  bool target_over_sdo = false; ///< write targets (607Ah, 60FFh) by SDO, not only in `target`
  bool read_error_code = true;  ///< on a fault, read 603Fh
};

/// What one cycle produced.
struct drive_step {
  std::uint16_t controlword = 0;
  std::int32_t target = 0;          ///< the active mode's target (607Ah, 60FFh, 6071h ...)
  std::optional<sdo_request> sdo{}; ///< a transfer to start now (reported back with sdo_done)
  drive_state state = drive_state::idle;
  std::optional<std::uint32_t> deadline{}; ///< the running timeout, if any
};

/// The machine.
class drive {
public:
  constexpr drive() noexcept = default;
  constexpr explicit drive(drive_options o) noexcept : opt_(o) {
    if (opt_.reset_attempts == 0U) opt_.reset_attempts = 1;
  }

  // ----- commands (they take effect in the next cycle) ------------------------------------

  /// Walk to operation enabled. Errors: bad_state (fault: reset first, or a command runs).
  [[nodiscard]] constexpr status enable(std::uint32_t now) noexcept {
    if (state_ == drive_state::fault || in_fault()) return errc::bad_state;
    start(drive_state::enabling, now, opt_.enable_timeout_ms);
    emcy_.reset();
    return {};
  }
  /// Walk to `target` (switch on disabled, ready to switch on or switched on) from any state
  /// but fault. Errors: invalid_argument (other targets), bad_state (fault).
  [[nodiscard]] constexpr status
  disable(std::uint32_t now, ds402::state target = ds402::state::switch_on_disabled) noexcept {
    if (target != ds402::state::switch_on_disabled && target != ds402::state::ready_to_switch_on &&
        target != ds402::state::switched_on) {
      return errc::invalid_argument;
    }
    if (state_ == drive_state::fault || in_fault()) return errc::bad_state;
    disable_target_ = target;
    mode_bits_ = 0;
    start(drive_state::disabling, now, opt_.disable_timeout_ms);
    return {};
  }
  /// Quick stop (controlword 0x02): operation enabled → quick stop active; from the other
  /// powered states the drive goes to switch on disabled. Always accepted (also in fault,
  /// where it is the command the drive will see after the reset).
  constexpr void quick_stop(std::uint32_t now) noexcept {
    mode_bits_ = 0;
    start(drive_state::quick_stopping, now, opt_.disable_timeout_ms);
  }
  /// Set or clear the halt bit (8): pp, pv, homing stop on the ramp and keep their state.
  constexpr void halt(bool on) noexcept { halt_ = on; }
  /// Fault reset: 0x00, then the rising edge 0x80 held until the drive leaves fault; after
  /// reset_timeout_ms without success a new edge, at most reset_attempts edges. Errors:
  /// bad_state (the drive is not in fault).
  [[nodiscard]] constexpr status reset_fault(std::uint32_t now) noexcept {
    if (!in_fault() && state_ != drive_state::fault) return errc::bad_state;
    attempts_ = 0;
    edge_ = false;
    mode_bits_ = 0;
    start(drive_state::resetting, now, opt_.reset_timeout_ms);
    return {};
  }
  /// Write 6060h and wait until 6061h shows `m` (from `mode_display` in cycle(), or by SDO
  /// reads when the caller passes none). Errors: bad_state (fault or a motion command runs).
  [[nodiscard]] constexpr status switch_mode(std::int8_t m, std::uint32_t now) noexcept {
    if (state_ == drive_state::fault || in_motion()) return errc::bad_state;
    requested_mode_ = m;
    mode_bits_ = 0;
    start(drive_state::switching_mode, now, opt_.mode_timeout_ms);
    request(write_request(obj::modes_of_operation, static_cast<std::uint8_t>(m), 1),
            purpose::write_mode);
    return {};
  }
  /// The same with a mode enum: `ds402::mode` or a vendor's (any scoped enum over int8_t).
  template <ds402::int8_enum Mode>
  [[nodiscard]] constexpr status switch_mode(Mode m, std::uint32_t now) noexcept {
    return switch_mode(static_cast<std::int8_t>(m), now);
  }

  /// Profile position: go to `target` (absolute or relative). The set-point handshake: bit 4
  /// set → wait for set-point acknowledge (bit 12) → bit 4 released → until target reached
  /// (bit 10) with bit 12 clear. `immediately` sets bit 5 (change set immediately); a new move
  /// is accepted while one runs. Errors: bad_state (not enabled, or the mode is not pp).
  [[nodiscard]] constexpr status move_to(std::int32_t target, std::uint32_t now,
                                         bool relative = false, bool immediately = false) noexcept {
    if (!ready_for_motion(ds402::mode::profile_position) && state_ != drive_state::moving) {
      return errc::bad_state;
    }
    target_ = target;
    relative_ = relative;
    immediately_ = immediately;
    phase_ = 0;
    mode_bits_ = 0;
    start(drive_state::moving, now, opt_.set_point_timeout_ms);
    if (opt_.target_over_sdo) {
      request(write_request(obj::target_position, static_cast<std::uint32_t>(target), 4),
              purpose::write_target);
    }
    return {};
  }

  /// Profile velocity: run at `velocity` (60FFh) until told otherwise. Errors: bad_state.
  [[nodiscard]] constexpr status run_velocity(std::int32_t velocity, std::uint32_t now) noexcept {
    if (!ready_for_motion(ds402::mode::profile_velocity) && state_ != drive_state::running) {
      return errc::bad_state;
    }
    target_ = velocity;
    mode_bits_ = 0;
    start(drive_state::running, now, 0);
    if (opt_.target_over_sdo) {
      request(write_request(obj::target_velocity, static_cast<std::uint32_t>(velocity), 4),
              purpose::write_target);
    }
    return {};
  }

  /// Homing: optionally write the method (6098h) first, then start (bit 4) and wait for homing
  /// attained (bit 12) with target reached (bit 10); bit 13 is a homing error.
  /// Errors: bad_state (not enabled in homing mode).
  [[nodiscard]] constexpr status home(std::uint32_t now,
                                      std::optional<std::int8_t> method = {}) noexcept {
    if (!ready_for_motion(ds402::mode::homing)) return errc::bad_state;
    phase_ = 0;
    mode_bits_ = 0;
    start(drive_state::homing, now, opt_.homing_timeout_ms);
    if (method) {
      request(write_request(obj::homing_method, static_cast<std::uint8_t>(*method), 1),
              purpose::write_method);
    }
    return {};
  }
  /// The same with a vendor's method enum (any scoped enum over int8_t).
  template <ds402::int8_enum Method>
  [[nodiscard]] constexpr status home(std::uint32_t now, Method m) noexcept {
    return home(now, std::optional<std::int8_t>(static_cast<std::int8_t>(m)));
  }

  /// Cyclic synchronous position / velocity / torque: start sending `target` every cycle (set
  /// a new one with set_target), with the bits the profile asks for in that mode (e.g. CSP with
  /// bit 4, 0x1F). Errors: bad_state (not enabled in a cyclic synchronous mode).
  [[nodiscard]] constexpr status start_cyclic(std::int32_t target, std::uint32_t now) noexcept {
    if (state_ != drive_state::enabled || !mode_ ||
        (*mode_ != 8 && *mode_ != 9 && *mode_ != 10 && *mode_ != 11)) {
      return errc::bad_state;
    }
    target_ = target;
    mode_bits_ = opt_.profile.cyclic_bits_for(*mode_);
    start(drive_state::running, now, 0);
    return {};
  }
  /// The target of this cycle (cyclic synchronous modes; also updates pv without SDO).
  constexpr void set_target(std::int32_t target) noexcept { target_ = target; }

  /// A motion of a manufacturer-specific mode the profile offers (a jog): its start bits
  /// until stop_motion(). Errors: invalid_argument (not one of the profile's motions), bad_state
  /// (not enabled in the motion's mode).
  [[nodiscard]] constexpr status start_motion(const ds402::manufacturer_motion &m,
                                              std::uint32_t now) noexcept {
    if (!opt_.profile.offers(m) || !m.valid()) return errc::invalid_argument;
    if (!ready_for_motion(m.mode)) return errc::bad_state;
    start(drive_state::running, now, 0);
    motion_ = m;
    mode_bits_ = m.start_bits;
    return {};
  }
  /// Stop the manufacturer motion: its stop bits until the statusword shows its stopped bits,
  /// then back to enabled (`stop_timeout` after disable_timeout_ms). Errors: bad_state (no
  /// manufacturer motion runs).
  [[nodiscard]] constexpr status stop_motion(std::uint32_t now) noexcept {
    if (state_ != drive_state::running || !motion_) return errc::bad_state;
    mode_bits_ = motion_->stop_bits;
    start(drive_state::stopping, now, opt_.disable_timeout_ms);
    return {};
  }
  /// Leave pv / cyclic mode / a manufacturer motion running: back to enabled at once (mode bits
  /// cleared, halt untouched). stop_motion() stops a manufacturer motion the profile's way and
  /// waits until it has stopped.
  constexpr void stop_running() noexcept {
    if (state_ == drive_state::running) {
      motion_.reset();
      mode_bits_ = 0;
      state_ = drive_state::enabled;
      deadline_.reset();
    }
  }

  // ----- inputs ---------------------------------------------------------------------------

  /// One cycle: the statusword received, the caller's counter, and 6061h when the caller has it
  /// in a PDO (then the machine never reads it by SDO and notices a mode the drive changed by
  /// itself).
  [[nodiscard]] constexpr drive_step cycle(std::uint16_t statusword, std::uint32_t now,
                                           std::optional<std::int8_t> mode_display = {}) noexcept {
    statusword_ = statusword;
    auto st = ds402::decode_state(statusword);
    if (!st) {
      if (state_ != drive_state::failed || error_->failure != drive_failure::bad_statusword) {
        fail(drive_failure::bad_statusword, errc::bad_state);
      }
      return make();
    }
    seen_ = st.value();
    if (mode_display) observe_mode(*mode_display, true);
    if (in_fault() && state_ != drive_state::resetting && state_ != drive_state::fault &&
        state_ != drive_state::quick_stopping) {
      enter_fault();
    }
    switch (state_) {
    case drive_state::idle:
    case drive_state::failed: hold_command(); break;
    case drive_state::fault: command_ = 0; break;
    case drive_state::enabling: walk(ds402::state::operation_enabled, now); break;
    case drive_state::disabling: walk(disable_target_, now); break;
    case drive_state::quick_stopping: quick_stopping(now); break;
    case drive_state::resetting: resetting(now); break;
    case drive_state::enabled: check_enabled(); break;
    case drive_state::switching_mode: switching(now); break;
    case drive_state::moving: moving(now); break;
    case drive_state::homing: homing(now); break;
    case drive_state::running: check_enabled(); break;
    case drive_state::stopping: stopping(now); break;
    }
    return make();
  }

  /// The SDO transfer this machine asked for completed; `value` holds an upload's bytes.
  constexpr void sdo_done(std::span<const std::uint8_t> value, std::uint32_t) noexcept {
    if (!outstanding_) return;
    const purpose p = outstanding_purpose_;
    outstanding_ = false;
    switch (p) {
    case purpose::read_error_code:
      if (error_ && value.size() >= 2U) {
        error_->error_code = static_cast<std::uint16_t>(value[0] | (value[1] << 8U));
        error_->error_code_read = true;
      }
      break;
    case purpose::read_mode:
      if (!value.empty()) observe_mode(static_cast<std::int8_t>(value[0]), false);
      break;
    case purpose::write_mode: // switching() reads 6061h unless a PDO brings it
    case purpose::write_target:
    case purpose::write_method:
    case purpose::none: break;
    }
    if (error_read_queued_) {
      error_read_queued_ = false;
      request(read_request(obj::error_code), purpose::read_error_code);
    }
  }
  /// The SDO transfer this machine asked for failed.
  constexpr void sdo_failed(const canopen::sdo::transfer_error &e, std::uint32_t) noexcept {
    if (!outstanding_) return;
    outstanding_ = false;
    if (outstanding_purpose_ == purpose::read_error_code) return; // the fault stays reported
    if (state_ == drive_state::fault) return;
    fail(drive_failure::sdo_failed, e.code);
    error_->sdo = e;
  }
  /// An EMCY of this axis: kept and attached to the next fault (error code 0 = error reset
  /// clears it).
  constexpr void on_emcy(const canopen::emcy::message &m) noexcept {
    if (m.error_code == 0U) {
      emcy_.reset();
      return;
    }
    emcy_ = m;
    if (state_ == drive_state::fault && error_ && !error_->emcy) error_->emcy = m;
  }

  // ----- getters --------------------------------------------------------------------------

  [[nodiscard]] constexpr drive_state state() const noexcept { return state_; }
  [[nodiscard]] constexpr bool busy() const noexcept {
    switch (state_) {
    case drive_state::enabling:
    case drive_state::disabling:
    case drive_state::quick_stopping:
    case drive_state::resetting:
    case drive_state::switching_mode:
    case drive_state::moving:
    case drive_state::homing:
    case drive_state::stopping: return true;
    default: return false;
    }
  }
  [[nodiscard]] constexpr std::optional<drive_error> error() const noexcept { return error_; }
  /// The mode 6061h showed last (empty until known).
  [[nodiscard]] constexpr std::optional<std::int8_t> mode() const noexcept { return mode_; }
  /// The drive's state from the last statusword.
  [[nodiscard]] constexpr ds402::state drive_status() const noexcept { return seen_; }
  /// The controlword of the last cycle.
  [[nodiscard]] constexpr std::uint16_t controlword() const noexcept { return controlword_; }
  /// An SDO transfer is outstanding.
  [[nodiscard]] constexpr bool sdo_pending() const noexcept { return outstanding_; }

private:
  enum class purpose : std::uint8_t {
    none,
    write_mode,
    read_mode,
    write_target,
    write_method,
    read_error_code
  };

  [[nodiscard]] constexpr bool in_fault() const noexcept {
    return seen_ == ds402::state::fault || seen_ == ds402::state::fault_reaction_active;
  }
  [[nodiscard]] constexpr bool in_motion() const noexcept {
    return state_ == drive_state::moving || state_ == drive_state::homing ||
           state_ == drive_state::running || state_ == drive_state::stopping;
  }
  [[nodiscard]] constexpr bool ready_for_motion(std::int8_t m) const noexcept {
    return state_ == drive_state::enabled && seen_ == ds402::state::operation_enabled &&
           mode_ == m && !outstanding_;
  }
  [[nodiscard]] constexpr bool ready_for_motion(ds402::mode m) const noexcept {
    return ready_for_motion(static_cast<std::int8_t>(m));
  }
  [[nodiscard]] constexpr bool reached(std::uint32_t now) const noexcept {
    return deadline_ && canopen::reached(*deadline_, now);
  }

  constexpr void start(drive_state s, std::uint32_t now, std::uint32_t timeout_ms) noexcept {
    if (s != drive_state::stopping) motion_.reset(); // start_motion sets it after this
    state_ = s;
    error_.reset();
    started_ = now;
    deadline_.reset();
    if (timeout_ms != 0U) deadline_ = now + timeout_ms;
  }
  constexpr void request(const sdo_request &r, purpose p) noexcept {
    pending_ = r;
    pending_purpose_ = p;
  }
  /// The machine stops in `s` with the error `f`: what the drive showed, no mode bits, no
  /// motion, no deadline.
  constexpr void stop_with(drive_state s, drive_failure f, errc e) noexcept {
    error_ = drive_error{f, e, seen_, statusword_, 0, false, {}, {}, mode_.value_or(0)};
    state_ = s;
    mode_bits_ = 0;
    motion_.reset();
    deadline_.reset();
  }
  constexpr void fail(drive_failure f, errc e) noexcept {
    stop_with(drive_state::failed, f, e);
    hold_command(); // already in the cycle that fails: not the walk's last command (F26)
    if (pending_purpose_ != purpose::read_error_code) pending_.reset();
  }
  constexpr void enter_fault() noexcept {
    stop_with(drive_state::fault, drive_failure::fault, errc::bad_state);
    error_->emcy = emcy_;
    if (opt_.read_error_code) {
      if (outstanding_) {
        error_read_queued_ = true;
      } else {
        request(read_request(obj::error_code), purpose::read_error_code);
      }
    }
  }
  constexpr void observe_mode(std::int8_t m, bool from_pdo) noexcept {
    if (from_pdo) mode_from_pdo_ = true;
    const bool changed = mode_ && *mode_ != m;
    mode_ = m;
    if (state_ == drive_state::switching_mode) {
      if (m == requested_mode_ && !outstanding_ && !pending_) {
        state_ =
            seen_ == ds402::state::operation_enabled ? drive_state::enabled : drive_state::idle;
        deadline_.reset();
      }
      return;
    }
    if (changed && state_ != drive_state::fault) fail(drive_failure::mode_changed, errc::bad_state);
  }
  /// The command that keeps the drive in the state it shows (idle, failed, enabled, mode
  /// switch): never one that moves it. The command of the last walk, kept until now, powered a
  /// drive up again after a failure (0x0F to a drive that had dropped to ready to switch on:
  /// transitions 3 + 4 nobody asked for; fuzz/FINDINGS.md F26).
  constexpr void hold_command() noexcept {
    using ds402::command;
    switch (seen_) {
    case ds402::state::operation_enabled:
      command_ = ds402::command_bits(command::enable_operation);
      break;
    case ds402::state::quick_stop_active:
      command_ = ds402::command_bits(command::quick_stop);
      break;
    case ds402::state::switched_on: command_ = ds402::command_bits(command::switch_on); break;
    case ds402::state::ready_to_switch_on: command_ = ds402::command_bits(command::shutdown); break;
    default: command_ = ds402::command_bits(command::disable_voltage); break;
    }
  }
  constexpr void walk(ds402::state target, std::uint32_t now) noexcept {
    if (seen_ == target) {
      state_ = target == ds402::state::operation_enabled ? drive_state::enabled : drive_state::idle;
      deadline_.reset();
      hold_command();
      return;
    }
    if (reached(now)) {
      fail(target == ds402::state::operation_enabled ? drive_failure::enable_timeout
                                                     : drive_failure::disable_timeout,
           errc::timeout);
      return;
    }
    command_ = ds402::next_controlword(statusword_, target, command_).value_or(0);
  }
  constexpr void check_enabled() noexcept {
    hold_command();
    if (seen_ != ds402::state::operation_enabled) {
      fail(drive_failure::left_operation_enabled, errc::bad_state);
    }
  }
  constexpr void quick_stopping(std::uint32_t now) noexcept {
    command_ = ds402::command_bits(ds402::command::quick_stop);
    if (seen_ == ds402::state::quick_stop_active || seen_ == ds402::state::switch_on_disabled ||
        in_fault()) {
      state_ = drive_state::idle;
      deadline_.reset();
      if (in_fault()) enter_fault();
      return;
    }
    if (reached(now)) fail(drive_failure::quick_stop_timeout, errc::timeout);
  }
  constexpr void resetting(std::uint32_t now) noexcept {
    if (!in_fault()) { // left fault: reset done
      state_ = drive_state::idle;
      deadline_.reset();
      command_ = 0;
      emcy_.reset();
      return;
    }
    // No timeout runs while the machine waits for the drive or for a cycle with bit 7 low: a
    // deadline kept from before would be in the past (fuzz/FINDINGS.md F27); the next edge
    // sets its own.
    if (seen_ == ds402::state::fault_reaction_active) { // wait (an edge now would be lost)
      command_ = 0;
      edge_ = false;
      deadline_.reset();
      return;
    }
    if (!edge_) {
      if ((command_ & ds402::cw::fault_reset) != 0U) { // bit 7 was high: one cycle low first
        command_ = 0;
        deadline_.reset();
        return;
      }
      command_ = ds402::command_bits(ds402::command::fault_reset);
      edge_ = true;
      ++attempts_;
      deadline_ = now + opt_.reset_timeout_ms;
      return;
    }
    if (reached(now)) {
      if (attempts_ >= opt_.reset_attempts) {
        fail(drive_failure::fault_reset_failed, errc::timeout);
        command_ = 0;
        return;
      }
      edge_ = false;
      command_ = 0; // low for a cycle, the next cycle gives the new edge
      deadline_.reset();
    }
  }
  constexpr void switching(std::uint32_t now) noexcept {
    hold_command();
    if (reached(now)) {
      fail(drive_failure::mode_not_confirmed, errc::timeout);
      if (mode_) error_->mode = *mode_;
      return;
    }
    if (!outstanding_ && !pending_ && mode_ == requested_mode_) {
      state_ = seen_ == ds402::state::operation_enabled ? drive_state::enabled : drive_state::idle;
      deadline_.reset();
    } else if (!outstanding_ && !pending_ && !mode_from_pdo_) {
      request(read_request(obj::modes_of_operation_display), purpose::read_mode);
    }
  }
  constexpr void moving(std::uint32_t now) noexcept {
    check_enabled();
    if (state_ != drive_state::moving) return;
    const bool ack = (statusword_ & ds402::sw::pp_set_point_acknowledge) != 0U;
    if ((statusword_ & ds402::sw::pp_following_error) != 0U) {
      fail(drive_failure::following_error, errc::bad_state);
      return;
    }
    switch (phase_) {
    case 0: // wait: target being written, bit 4 still high (an edge is needed), or the
            // previous set-point still acknowledged
      if (outstanding_ || pending_ || ack || (controlword_ & ds402::cw::pp_new_set_point) != 0U) {
        if (reached(now)) fail(drive_failure::set_point_not_acknowledged, errc::timeout);
        break;
      }
      mode_bits_ = static_cast<std::uint16_t>(
          ds402::cw::pp_new_set_point | (immediately_ ? ds402::cw::pp_change_set_immediately : 0U) |
          (relative_ ? ds402::cw::pp_relative : 0U));
      phase_ = 1;
      deadline_ = now + opt_.set_point_timeout_ms;
      break;
    case 1: // bit 4 high, waiting for the acknowledge
      if (ack) {
        mode_bits_ = static_cast<std::uint16_t>(mode_bits_ & ~ds402::cw::pp_new_set_point);
        phase_ = 2;
        deadline_.reset();
        if (opt_.move_timeout_ms != 0U) deadline_ = now + opt_.move_timeout_ms;
      } else if (reached(now)) {
        fail(drive_failure::set_point_not_acknowledged, errc::timeout);
      }
      break;
    default: // released: until the drive drops the acknowledge and shows target reached
      if (!ack && (statusword_ & ds402::sw::target_reached) != 0U) {
        state_ = drive_state::enabled;
        mode_bits_ = 0;
        deadline_.reset();
      } else if (reached(now)) {
        fail(drive_failure::move_timeout, errc::timeout);
      }
      break;
    }
  }
  constexpr void homing(std::uint32_t now) noexcept {
    check_enabled();
    if (state_ != drive_state::homing) return;
    if (phase_ == 0) {
      if (outstanding_ || pending_) return;
      mode_bits_ = ds402::cw::hm_start;
      phase_ = 1;
      return;
    }
    if (phase_ == 1) { // attained and error only count once the drive has shown homing in
                       // progress (bit 12 clear): bits left over from the last run are ignored
      if ((statusword_ & ds402::sw::hm_attained) == 0U) phase_ = 2;
    }
    if (phase_ == 2 && (statusword_ & ds402::sw::hm_error) != 0U) {
      fail(drive_failure::homing_error, errc::bad_state);
      return;
    }
    if (phase_ == 2 && (statusword_ & ds402::sw::hm_attained) != 0U &&
        (statusword_ & ds402::sw::target_reached) != 0U) {
      state_ = drive_state::enabled;
      mode_bits_ = 0;
      deadline_.reset();
      return;
    }
    if (reached(now)) fail(drive_failure::homing_timeout, errc::timeout);
  }
  constexpr void stopping(std::uint32_t now) noexcept {
    check_enabled();
    if (state_ != drive_state::stopping) return;
    if ((statusword_ & motion_->stopped_bits) == motion_->stopped_bits) {
      state_ = drive_state::enabled;
      motion_.reset();
      mode_bits_ = 0;
      deadline_.reset();
    } else if (reached(now)) {
      fail(drive_failure::stop_timeout, errc::timeout);
    }
  }

  [[nodiscard]] constexpr drive_step make() noexcept {
    drive_step s;
    const std::uint16_t halt = halt_ ? ds402::cw::halt : std::uint16_t{0};
    controlword_ = static_cast<std::uint16_t>((command_ & ds402::cw::command_mask) |
                                              ((mode_bits_ | halt) & ~ds402::cw::command_mask));
    s.controlword = controlword_;
    s.target = target_;
    if (pending_ && !outstanding_) {
      s.sdo = pending_;
      outstanding_ = true;
      outstanding_purpose_ = pending_purpose_;
      pending_.reset();
    }
    s.state = state_;
    if (deadline_) s.deadline = *deadline_; // (a disengaged optional is not copied: constexpr)
    return s;
  }

  drive_options opt_{};
  drive_state state_ = drive_state::idle;
  ds402::state seen_ = ds402::state::not_ready_to_switch_on;
  std::uint16_t statusword_ = 0;
  std::uint16_t command_ = 0;   ///< command bits (0..3, 7) of the controlword
  std::uint16_t mode_bits_ = 0; ///< bits 4..6, 9 (and manufacturer bits)
  std::uint16_t controlword_ = 0;
  bool halt_ = false;
  std::int32_t target_ = 0;
  bool relative_ = false;
  bool immediately_ = false;
  std::uint8_t phase_ = 0;
  std::uint8_t attempts_ = 0;
  bool edge_ = false;
  ds402::state disable_target_ = ds402::state::switch_on_disabled;
  std::optional<std::int8_t> mode_{};
  std::int8_t requested_mode_ = 0;
  bool mode_from_pdo_ = false;
  std::uint32_t started_ = 0;
  std::optional<std::uint32_t> deadline_{};
  std::optional<ds402::manufacturer_motion> motion_{}; ///< running or stopping
  std::optional<drive_error> error_{};
  std::optional<canopen::emcy::message> emcy_{};
  std::optional<sdo_request> pending_{};
  purpose pending_purpose_ = purpose::none;
  bool outstanding_ = false;
  purpose outstanding_purpose_ = purpose::none;
  bool error_read_queued_ = false;
};

} // namespace fieldcodec::master
