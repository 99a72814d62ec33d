// A bus with the simulated XENAX drive of the examples (examples/sim_drive.hpp) on it, in the
// same process: what is sent reaches the drive at once; receive() runs the drive's clock (real
// milliseconds, as host programs have) and gives what it sends. Frames can be injected before
// the drive's (a malformed EMCY, a short PDO). For tests of host::remote_node and
// host::remote_drive that need a device that behaves like one (PDOs, CiA 402, heartbeat).
#pragma once

#include "../../examples/sim_drive.hpp"

#include <fieldcodec/host/bus.hpp>
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/clock.hpp>

#include <chrono>
#include <deque>
#include <thread>
#include <vector>

namespace fieldcodec::test {

class sim_bus final : public host::can_bus {
public:
  explicit sim_bus(std::uint8_t node) : drive_(node) {
    name_ = "sim0";
    take(drive_.start(clock_.now()));
  }
  status send(const canopen::can_frame &f) override {
    if (broken) return fail(errc::bad_state, 5, "write");
    sent.push_back(f);
    take(drive_.on_frame(f, clock_.now()));
    return {};
  }
  result<host::frame_record> receive_record(std::chrono::milliseconds t) override {
    const auto end = std::chrono::steady_clock::now() + t;
    if (broken) return fail(errc::bad_state, 5, "read");
    for (;;) {
      if (!queue.empty()) {
        auto r = queue.front();
        queue.pop_front();
        return r;
      }
      // polled every millisecond: what the drive's application changed after a frame (its
      // statusword, a TPDO) goes out at the next poll, not at the step's deadline
      take(drive_.poll(clock_.now()));
      if (!queue.empty()) continue;
      if (std::chrono::steady_clock::now() >= end)
        return fail(errc::timeout, 0, "no frame in time");
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  /// A frame from "another node" (candump notation), received before the drive's next frames.
  void inject(const char *candump) { queue.push_back(host::candump::parse_line(candump).value()); }
  [[nodiscard]] sim::drive &drive() { return drive_; }
  [[nodiscard]] std::size_t count(std::uint16_t id) const {
    std::size_t n = 0;
    for (const auto &f : sent) n += f.id == id ? 1U : 0U;
    return n;
  }

  std::deque<host::frame_record> queue;
  std::vector<canopen::can_frame> sent;
  bool broken = false; ///< every send and receive fails (EIO)

private:
  template <class Step>
  void take(const Step &s) {
    for (const canopen::can_frame &f : s.send) {
      queue.push_back(host::to_record(f));
    }
  }

  host::steady_ms clock_{};
  sim::drive drive_;
};

} // namespace fieldcodec::test
