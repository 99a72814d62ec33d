// fieldcodec — host adapters: the CAN bus interface every transport implements (SocketCAN,
// slcan), with one-line error context.
//
//   host::socketcan_bus bus;
//   if (!bus.open("can0")) { print(bus.last_error().what); }
//   bus.send(frame);
//   auto r = bus.receive(std::chrono::milliseconds(100));  // a CANopen frame, or why not
//
// Errors are errc values (result<T>); the bus keeps the context of the last failure in
// last_error(): the errc, the operating system's errno where one was involved, the decoded
// error frame, and one line of text naming the interface.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/host/deadline.hpp>
#include <fieldcodec/host/frame_record.hpp>

#include <chrono>
#include <cstring>
#include <string>
#include <string_view>

namespace fieldcodec::host {

/// The context of a failed call: what failed, in one line ("can0: bus-off", "/dev/ttyACM0:
/// open: No such file or directory").
struct bus_error {
  errc code = errc::bad_state;
  int sys_errno = 0; ///< errno of the failed system call, 0 when none
  can_error frame{}; ///< the error frame, when code is bad_state because of one
  bool from_error_frame = false;
  std::string what; ///< one line, starts with the interface or port name
};

/// A frame with the time it was received.
struct timed_frame {
  canopen::can_frame frame{};
  timestamp time{};
};

/// A CAN interface: send and receive frames. Not copyable (it owns an operating system handle).
class can_bus {
public:
  can_bus() = default;
  can_bus(const can_bus &) = delete;
  can_bus &operator=(const can_bus &) = delete;
  virtual ~can_bus() = default;

  /// Send one frame. Errors: invalid_argument / bad_length (not a valid frame), timeout (the
  /// transmit queue stayed full), bad_state (the interface is not open or failed; see
  /// last_error()).
  virtual status send(const canopen::can_frame &f) = 0;

  /// The next frame of any kind (base, extended, remote, error), waiting at most `timeout`.
  /// Errors: timeout (nothing arrived), bad_state (not open, read failed: last_error()).
  virtual result<frame_record> receive_record(std::chrono::milliseconds timeout) = 0;

  /// The next CANopen frame, waiting at most `timeout` overall. Extended (29-bit) frames are
  /// skipped. An error frame is an error: bad_state, with the decoded frame in last_error()
  /// (frame.is_bus_off(), frame.is_error_passive()). Errors: also those of receive_record.
  result<timed_frame> receive(std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      const auto left = time_left(end);
      auto r = receive_record(left);
      if (!r) return r.error();
      const frame_record &rec = r.value();
      if (rec.error) {
        bus_error e;
        e.code = errc::bad_state;
        e.frame = decode_error(rec).value();
        e.from_error_frame = true;
        e.what = std::string(name()) + ": " + describe(e.frame);
        error_ = std::move(e);
        return errc::bad_state;
      }
      auto f = to_canopen(rec);
      if (f) return timed_frame{f.value(), rec.time};
      if (left.count() == 0) return fail(errc::timeout, 0, "no frame in time");
    }
  }

  /// The context of the last failure.
  [[nodiscard]] const bus_error &last_error() const noexcept { return error_; }
  /// The interface or port name given to open().
  [[nodiscard]] std::string_view name() const noexcept { return name_; }

protected:
  /// Records a failure and returns its errc: "<name>: <what>[: <strerror(sys_errno)>]".
  errc fail(errc code, int sys_errno, std::string_view what) {
    bus_error e;
    e.code = code;
    e.sys_errno = sys_errno;
    e.what = name_.empty() ? std::string(what) : name_ + ": " + std::string(what);
    if (sys_errno != 0) {
      e.what += ": ";
      e.what += std::strerror(sys_errno);
    }
    error_ = std::move(e);
    return code;
  }
  /// Records a failure whose context is complete (e.g. a serial port's).
  errc fail(bus_error e) {
    const errc code = e.code;
    error_ = std::move(e);
    return code;
  }
  std::string name_;

private:
  bus_error error_{};
};

} // namespace fieldcodec::host
