// A simulated XENAX Xvi CANopen drive: a fieldcodec node (canopen/node/device.hpp) over the
// generated XENAX CAN dictionary, a CiA 402 power state machine that follows the controlword
// (ds402::apply), and a trivial axis model for profile position mode (6060h = 1).
//
// Host code for the examples (it uses double arithmetic for the axis); the node and the state
// machine are the firmware pieces. Time is the caller's millisecond counter, as everywhere.
//
// What the drive does:
// * boot: NMT boot-up, CiA 402 "switch on disabled" (transitions 0 and 1 done at power-on);
// * every controlword (6040h, by SDO or RPDO) goes through ds402::apply; the statusword
//   (6041h) shows the state, voltage enabled, remote, target reached, set-point acknowledge;
// * profile position: a rising edge of controlword bit 4 (new set-point) in operation enabled
//   takes 607Ah (absolute, or relative with bit 6) and moves there with 6081h (speed, units/s)
//   and 6083h (acceleration, units/s²) in a trapezoid; bit 12 acknowledges the set-point while
//   bit 4 is held; bit 10 (target reached) is set when the position equals the target; halt
//   (bit 8) decelerates to standstill;
// * quick stop decelerates with 6085h; leaving operation enabled stops the axis at once;
// * 6064h (position actual) and 606Ch (velocity actual) follow the axis; 6061h shows 6060h when
//   the XENAX supports the mode (xenax::decode_mode), 0 otherwise.
#pragma once

#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/ds402/controlword.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/ds402/statusword.hpp>
#include <fieldcodec/xenax/modes.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

namespace sim {

namespace co = fieldcodec::canopen;
namespace node = fieldcodec::canopen::node;
namespace sdo = fieldcodec::canopen::sdo;
namespace ds402 = fieldcodec::ds402;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;

inline constexpr auto layout = co::make_layout<xcan::dictionary.size()>(xcan::dictionary);
inline constexpr node::capacity capacity = node::capacity_for(xcan::dictionary);

class drive {
public:
  using store_type = co::dictionary_store<>;
  using device_type = node::device<store_type, capacity>;
  using step = device_type::step;

  explicit drive(std::uint8_t node_id)
      : store_{xcan::dictionary, layout, storage_}, dev_(store_, node_id) {
    (void)store_.init_defaults(node_id); // the power-on values: the dictionary's defaults
  }
  drive(const drive &) = delete;
  drive &operator=(const drive &) = delete;

  /// Power-on: boot-up message, CiA 402 switch on disabled.
  step start(std::uint32_t now) {
    last_ = now;
    state_ = ds402::state::switch_on_disabled; // transitions 0 and 1
    auto s = dev_.start(now);
    publish();
    return s ? s.value() : step{};
  }
  /// A frame from the bus.
  step on_frame(const co::can_frame &f, std::uint32_t now) {
    auto s = dev_.on_frame(f, now);
    for (const auto &e : dev_.events()) {
      if (e.what == node::event::kind::reset_application) reset_application();
    }
    follow_controlword();
    publish();
    return s;
  }
  /// Time: the axis moves, then the node sends what changed.
  step poll(std::uint32_t now) {
    advance(now);
    publish();
    auto s = dev_.poll(now);
    if (moving_) s.deadline = now + 1; // the axis model runs every millisecond while moving
    return s;
  }

  [[nodiscard]] ds402::state state() const { return state_; }
  [[nodiscard]] double position() const { return pos_; }
  [[nodiscard]] bool moving() const { return moving_; }
  [[nodiscard]] device_type &device() { return dev_; }

private:
  std::int64_t read_i(std::uint16_t index, std::uint8_t sub) const {
    auto v = dev_.value({index, sub});
    if (!v) return 0;
    const auto b = v.value();
    std::uint64_t r = 0;
    for (std::size_t i = b.size(); i-- > 0;) r = (r << 8U) | b[i];
    if (!b.empty() && b.size() < 8 && (b.back() & 0x80U) != 0U)
      r |= ~std::uint64_t{0} << (8U * b.size());
    return static_cast<std::int64_t>(r);
  }
  std::uint64_t read_u(std::uint16_t index, std::uint8_t sub) const {
    auto v = dev_.value({index, sub});
    if (!v) return 0;
    std::uint64_t r = 0;
    for (std::size_t i = v.value().size(); i-- > 0;) r = (r << 8U) | v.value()[i];
    return r;
  }
  void write(std::uint16_t index, std::uint64_t value, std::size_t width) {
    std::array<std::uint8_t, 8> b{};
    for (std::size_t i = 0; i < width; ++i) b[i] = static_cast<std::uint8_t>(value >> (8U * i));
    (void)dev_.set({index, 0}, std::span<const std::uint8_t>(b).first(width));
  }

  void reset_application() {
    state_ = ds402::state::switch_on_disabled;
    previous_cw_ = 0;
    moving_ = false;
    halted_ = false;
    vel_ = 0;
  }

  void follow_controlword() {
    const auto cw = static_cast<std::uint16_t>(read_u(0x6040, 0));
    if (cw == previous_cw_) return;
    const auto s = ds402::apply(state_, cw, previous_cw_);
    const ds402::state before = state_;
    state_ = s.to;
    if (state_ != ds402::state::operation_enabled && state_ != ds402::state::quick_stop_active) {
      moving_ = false; // no power: the axis stops where it is
      vel_ = 0;
    }
    if (state_ == ds402::state::quick_stop_active && before == ds402::state::operation_enabled) {
      quick_stop_ = true;
    }
    const bool edge = (cw & ds402::cw::pp_new_set_point) != 0U &&
                      (previous_cw_ & ds402::cw::pp_new_set_point) == 0U;
    if (edge && state_ == ds402::state::operation_enabled && mode() == 1) {
      const auto t = static_cast<double>(read_i(0x607A, 0));
      target_ = (cw & ds402::cw::pp_relative) != 0U ? target_ + t : t;
      moving_ = target_ != pos_;
      acknowledged_ = true;
    }
    if ((cw & ds402::cw::pp_new_set_point) == 0U) acknowledged_ = false;
    halted_ = (cw & ds402::cw::halt) != 0U;
    previous_cw_ = cw;
  }

  [[nodiscard]] std::int8_t mode() const {
    const auto m = static_cast<std::int8_t>(read_i(0x6060, 0));
    return fieldcodec::xenax::decode_mode(m).has_value() ? m : std::int8_t{0};
  }

  void advance(std::uint32_t now) {
    const double dt = static_cast<double>(now - last_) / 1000.0;
    last_ = now;
    if (dt <= 0) return;
    const double accel = static_cast<double>(read_u(0x6083, 0));
    if (quick_stop_ || halted_) {
      const double decel = quick_stop_ ? static_cast<double>(read_u(0x6085, 0)) : accel;
      const double dv = decel * dt;
      const double dir = target_ >= pos_ ? 1.0 : -1.0;
      if (vel_ > dv) {
        pos_ += dir * (vel_ - dv / 2) * dt;
        vel_ -= dv;
      } else {
        vel_ = 0;
        moving_ = false;
        quick_stop_ = false;
        if (halted_) target_ = pos_;
      }
      return;
    }
    if (!moving_) return;
    const double speed = static_cast<double>(read_u(0x6081, 0));
    const double remaining = std::fabs(target_ - pos_);
    const double dir = target_ >= pos_ ? 1.0 : -1.0;
    const double braking = accel > 0 ? vel_ * vel_ / (2 * accel) : 0;
    if (remaining <= braking) {
      vel_ = std::max(vel_ - accel * dt, accel * dt); // never stall before the target
    } else {
      vel_ = std::min(vel_ + accel * dt, speed);
    }
    const double stepped = vel_ * dt;
    if (stepped >= remaining) {
      pos_ = target_;
      vel_ = 0;
      moving_ = false;
    } else {
      pos_ += dir * stepped;
    }
  }

  /// The objects the drive owns: statusword, mode display, position and velocity actual.
  void publish() {
    auto sw = static_cast<std::uint16_t>(ds402::state_bits(state_) | ds402::sw::remote);
    if (state_ == ds402::state::switched_on || state_ == ds402::state::operation_enabled ||
        state_ == ds402::state::quick_stop_active) {
      sw = static_cast<std::uint16_t>(sw | ds402::sw::voltage_enabled);
    }
    if (!moving_) sw = static_cast<std::uint16_t>(sw | ds402::sw::target_reached);
    if (acknowledged_) sw = static_cast<std::uint16_t>(sw | ds402::sw::pp_set_point_acknowledge);
    update(0x6041, sw, 2);
    update(0x6061, static_cast<std::uint8_t>(mode()), 1);
    update(0x6064, static_cast<std::uint32_t>(static_cast<std::int32_t>(std::lround(pos_))), 4);
    const double v = moving_ ? vel_ : 0.0;
    update(0x606C, static_cast<std::uint32_t>(static_cast<std::int32_t>(std::lround(v))), 4);
  }
  void update(std::uint16_t index, std::uint64_t value, std::size_t width) {
    if (read_u(index, 0) != value) write(index, value, width);
  }

  std::array<std::uint8_t, layout.storage_size()> storage_{};
  store_type store_;
  device_type dev_;
  ds402::state state_ = ds402::state::not_ready_to_switch_on;
  std::uint16_t previous_cw_ = 0;
  std::uint32_t last_ = 0;
  double pos_ = 0;
  double vel_ = 0;
  double target_ = 0;
  bool moving_ = false;
  bool acknowledged_ = false;
  bool halted_ = false;
  bool quick_stop_ = false;
};

} // namespace sim
