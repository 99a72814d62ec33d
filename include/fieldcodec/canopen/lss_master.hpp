// fieldcodec — the LSS master (CiA 305): one service at a time towards the LSS slaves on the
// bus, as a machine of the step shape (no I/O, no clock: frames and the caller's milliseconds).
//
//   lss::master m;                                   // answers within 1000 ms, probes 100 ms
//   send(m.switch_selective({vendor, product, revision, serial}, now).value());
//   on every frame: send(m.on_frame(frame, now));   at the deadline: send(m.poll(now));
//   when m.state() is done: m.error_code(), m.value(), m.found() say what came back
//
// Services: switch state global (no answer), switch state selective (answer 44h), configure
// node-ID, configure bit timing, store configuration (answer: error code and the manufacturer's
// code), activate bit timing (no answer), inquire vendor-ID / product code / revision / serial
// number / node-ID (value()), identify non-configured remote slave (found(): any 50h within
// the probe time) and fastscan (found(), address(): the LSS address of the slave without
// node-ID with the lowest one; that slave is then in LSS configuration). An answer that does
// not fit the service is ignored (not taken, unexpected_frame in frame_error()); no answer
// within the time: state failed, error() timeout. A service while another runs: bad_state.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/lss.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <optional>

namespace fieldcodec::canopen::lss {

enum class master_state : std::uint8_t {
  idle,    ///< no service started yet
  waiting, ///< a service waits for its answer (or, probing, for the probe time to pass)
  done,    ///< the last service is complete
  failed,  ///< the last service got no answer in time (error())
};

struct master_options {
  std::uint32_t timeout_ms = 1000; ///< for the answer of a confirmed service
  /// How long a probe (identify non-configured, each fastscan step) waits: silence means
  /// "no slave matches".
  std::uint32_t probe_ms = 100;
};

class master {
public:
  using step = canopen::step<master_state>;

  constexpr explicit master(master_options o = {}) noexcept : o_(o) {}

  /// Switch state global: 0 waiting, 1 configuration (no answer: done at once).
  [[nodiscard]] constexpr result<step> switch_global(std::uint8_t mode,
                                                     std::uint32_t now) noexcept {
    if (mode > 1U) return errc::invalid_argument;
    return unconfirmed(command_frame(command::switch_global, mode), now);
  }
  /// Switch state selective by an LSS address: the four frames, then 44h from the slave.
  [[nodiscard]] constexpr result<step> switch_selective(const address &a,
                                                        std::uint32_t now) noexcept {
    if (busy()) return errc::bad_state;
    for (std::uint8_t i = 0; i < 4U; ++i) {
      four_[i] = value_frame(static_cast<command>(0x40U + i), a.part(i));
    }
    begin(command::switch_selective_response, now, o_.timeout_ms);
    return make(frames(std::span<const can_frame>(four_)));
  }
  /// Configure node-ID (1..127, or lss::unconfigured); error_code() is the slave's answer.
  [[nodiscard]] constexpr result<step> configure_node_id(std::uint8_t node,
                                                         std::uint32_t now) noexcept {
    if (!((node >= 1U && node <= 127U) || node == unconfigured)) return errc::invalid_argument;
    return confirmed(command_frame(command::configure_node_id, node), now);
  }
  /// Configure bit timing: table 0 is CiA 305's standard table (standard_bit_rate).
  [[nodiscard]] constexpr result<step> configure_bit_timing(std::uint8_t table, std::uint8_t index,
                                                            std::uint32_t now) noexcept {
    return confirmed(command_frame(command::configure_bit_timing, table, index), now);
  }
  /// Activate bit timing after `delay_ms` (no answer: done at once).
  [[nodiscard]] constexpr result<step> activate_bit_timing(std::uint16_t delay_ms,
                                                           std::uint32_t now) noexcept {
    message m;
    m.cs = command::activate_bit_timing;
    m.value = delay_ms;
    return unconfirmed(encode(m), now);
  }
  [[nodiscard]] constexpr result<step> store(std::uint32_t now) noexcept {
    return confirmed(command_frame(command::store_configuration), now);
  }
  /// Inquire: command::inquire_vendor … inquire_serial (value() the 32-bit value) or
  /// inquire_node_id (value() the node-ID). Errors: invalid_argument for any other command.
  [[nodiscard]] constexpr result<step> inquire(command what, std::uint32_t now) noexcept {
    const auto cs = static_cast<std::uint8_t>(what);
    if (cs < 0x5AU || cs > 0x5EU) return errc::invalid_argument;
    return confirmed(command_frame(what), now);
  }
  /// Identify non-configured remote slave: found() when any slave answers 50h within probe_ms.
  [[nodiscard]] constexpr result<step> identify_non_configured(std::uint32_t now) noexcept {
    if (busy()) return errc::bad_state;
    found_ = false;
    begin(command::identify_non_configured_slave, now, o_.probe_ms);
    probing_ = true;
    return make(command_frame(command::identify_non_configured));
  }
  /// Fastscan: finds the LSS address of a slave without node-ID (found(), address()).
  [[nodiscard]] constexpr result<step> fastscan(std::uint32_t now) noexcept {
    if (busy()) return errc::bad_state;
    found_ = false;
    scan_ = {};
    sub_ = 0;
    bit_ = reset_probe;
    begin(command::identify_slave, now, o_.probe_ms);
    scanning_ = true;
    return make(probe());
  }

  /// A frame from the bus (only 7E4h answers are looked at).
  [[nodiscard]] constexpr step on_frame(const can_frame &f, std::uint32_t now) noexcept {
    if (state_ != master_state::waiting || f.id != slave_id) return make({});
    const auto m = decode(f);
    if (!m || m.value().cs != expect_) {
      frame_error_ = m ? errc::unexpected_frame : m.error();
      return make({});
    }
    frame_error_ = errc{};
    if (scanning_) return make(scan_next(true, now));
    if (probing_) {
      found_ = true; // the probe time still runs: one answer or many
      return make({});
    }
    error_code_ = m.value().b1;
    manufacturer_ = m.value().b2;
    value_ = expect_ == command::inquire_node_id ? m.value().b1 : m.value().value;
    state_ = master_state::done;
    return make({});
  }
  /// Time: a confirmed service fails without answer; a probe ends.
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    if (state_ != master_state::waiting || !reached(due_, now)) return make({});
    if (scanning_) return make(scan_next(false, now));
    if (probing_) {
      probing_ = false;
      state_ = master_state::done;
      return make({});
    }
    error_ = errc::timeout;
    state_ = master_state::failed;
    return make({});
  }

  [[nodiscard]] constexpr master_state state() const noexcept { return state_; }
  [[nodiscard]] constexpr bool busy() const noexcept { return state_ == master_state::waiting; }
  /// Why the last service failed (timeout), empty otherwise.
  [[nodiscard]] constexpr std::optional<errc> error() const noexcept {
    if (state_ != master_state::failed) return std::nullopt;
    return error_;
  }
  /// Why the last frame was not taken as the answer.
  [[nodiscard]] constexpr std::optional<errc> frame_error() const noexcept {
    if (frame_error_ == errc{}) return std::nullopt;
    return frame_error_;
  }
  /// Configure and store: the slave's error code (error_code::none …) and manufacturer's code.
  [[nodiscard]] constexpr std::uint8_t error_code() const noexcept { return error_code_; }
  [[nodiscard]] constexpr std::uint8_t manufacturer_code() const noexcept { return manufacturer_; }
  /// Inquire: the value.
  [[nodiscard]] constexpr std::uint32_t value() const noexcept { return value_; }
  /// Identify non-configured, fastscan: a slave answered / was found.
  [[nodiscard]] constexpr bool found() const noexcept { return found_; }
  /// Fastscan: the LSS address found.
  [[nodiscard]] constexpr address found_address() const noexcept {
    return {scan_[0], scan_[1], scan_[2], scan_[3]};
  }

private:
  static constexpr std::uint8_t reset_probe = 0xFF;   ///< bit_: the reset probe (bit_checked 80h)
  static constexpr std::uint8_t confirm_probe = 0xFE; ///< bit_: the part's confirmation

  [[nodiscard]] static constexpr can_frame command_frame(command cs, std::uint8_t b1 = 0,
                                                         std::uint8_t b2 = 0) noexcept {
    message m;
    m.cs = cs;
    m.b1 = b1;
    m.b2 = b2;
    return encode(m);
  }
  [[nodiscard]] static constexpr can_frame value_frame(command cs, std::uint32_t v) noexcept {
    message m;
    m.cs = cs;
    m.value = v;
    return encode(m);
  }
  [[nodiscard]] constexpr result<step> unconfirmed(const can_frame &f, std::uint32_t) noexcept {
    if (busy()) return errc::bad_state;
    state_ = master_state::done;
    one_ = f;
    return make(frames(one_));
  }
  [[nodiscard]] constexpr result<step> confirmed(const can_frame &f, std::uint32_t now) noexcept {
    if (busy()) return errc::bad_state;
    begin(static_cast<command>(f.data[0]), now, o_.timeout_ms);
    one_ = f;
    return make(frames(one_));
  }
  constexpr void begin(command expect, std::uint32_t now, std::uint32_t wait) noexcept {
    expect_ = expect;
    state_ = master_state::waiting;
    due_ = now + wait;
    error_code_ = 0;
    manufacturer_ = 0;
    value_ = 0;
    probing_ = false;
    scanning_ = false;
    frame_error_ = errc{};
  }

  /// The probe of the current fastscan step.
  [[nodiscard]] constexpr can_frame probe() const noexcept {
    message m;
    m.cs = command::fastscan;
    m.lss_sub = sub_;
    if (bit_ == reset_probe) {
      m.bit_checked = fastscan_reset;
    } else if (bit_ == confirm_probe) {
      m.value = scan_[sub_];
      m.lss_next = static_cast<std::uint8_t>((sub_ + 1U) & 3U);
    } else {
      m.value = scan_[sub_];
      m.bit_checked = bit_;
      m.lss_next = sub_;
    }
    return encode(m);
  }
  /// The next fastscan step after an answer (`yes`) or the probe time without one.
  [[nodiscard]] constexpr frames scan_next(bool yes, std::uint32_t now) noexcept {
    // probing bit k with the bit 0: silence means the slave's bit k is 1
    if (bit_ == reset_probe || bit_ == confirm_probe) {
      if (!yes) return finish(false);
      if (bit_ == confirm_probe) {
        if (sub_ == 3U) return finish(true);
        ++sub_;
      }
      bit_ = fastscan_last_bit;
    } else {
      if (!yes) scan_[sub_] |= 1U << bit_;
      bit_ = bit_ == 0U ? confirm_probe : static_cast<std::uint8_t>(bit_ - 1U);
    }
    due_ = now + o_.probe_ms;
    one_ = probe();
    return frames(one_);
  }
  [[nodiscard]] constexpr frames finish(bool found) noexcept {
    found_ = found;
    scanning_ = false;
    state_ = master_state::done;
    return {};
  }

  [[nodiscard]] constexpr step make(frames f) const noexcept {
    step s;
    s.send = f;
    s.state = state_;
    if (state_ == master_state::waiting) s.deadline = due_;
    return s;
  }

  master_options o_;
  std::array<can_frame, 4> four_{};
  can_frame one_{};
  std::array<std::uint32_t, 4> scan_{};
  std::uint32_t due_ = 0;
  std::uint32_t value_ = 0;
  command expect_ = command::switch_global;
  master_state state_ = master_state::idle;
  errc error_{};
  errc frame_error_{};
  std::uint8_t error_code_ = 0;
  std::uint8_t manufacturer_ = 0;
  std::uint8_t sub_ = 0;
  std::uint8_t bit_ = 0;
  bool found_ = false;
  bool probing_ = false;
  bool scanning_ = false;
};

} // namespace fieldcodec::canopen::lss
