// The boot tests' bench: a master::boot against the simulated device of sim_device.hpp, the
// frames passed back and forth until the machine ends, time jumping to each deadline.
#pragma once

#include "sim_device.hpp"

#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/master/boot.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace sim {

struct boot_harness {
  device dev;
  csdo::client client;
  fieldcodec::master::boot machine;
  std::uint32_t now = 5000;
  /// The device sends a heartbeat of its state whenever the master waits for one (also for the
  /// node state of a keep-alive slave).
  bool heartbeats = false;
  std::vector<co::can_frame> sent{};

  boot_harness(std::uint8_t node, fieldcodec::master::boot_options o)
      : dev(node), client(node, 100), machine(node, client, o) {}

  void run(fieldcodec::master::boot::step s) {
    using fieldcodec::master::boot_state;
    for (int guard = 0; guard < 1000 && machine.busy(); ++guard) {
      std::vector<co::can_frame> replies;
      for (const auto &f : s.send) {
        sent.push_back(f);
        for (const auto &r : dev.receive(f)) replies.push_back(r);
      }
      if (!replies.empty()) {
        for (const auto &r : replies) s = machine.on_frame(r, now);
        continue;
      }
      if (heartbeats && (machine.state() == boot_state::waiting_heartbeat ||
                         machine.state() == boot_state::checking_node_state)) {
        now += 10;
        s = machine.on_frame(co::nmt::encode_heartbeat(dev.node, dev.nmt).value(), now);
        continue;
      }
      REQUIRE(s.deadline);
      now = *s.deadline;
      s = machine.poll(now);
    }
    for (const auto &f : s.send) {
      sent.push_back(f);
      (void)dev.receive(f);
    }
  }

  /// SDO requests the master sent for `a` (initiate upload or download).
  [[nodiscard]] int requests_for(fieldcodec::od::address a) const {
    return static_cast<int>(std::count_if(sent.begin(), sent.end(), [&](const co::can_frame &f) {
      return f.id == 0x600U + dev.node && (f.data[0] == 0x40U || (f.data[0] & 0xE0U) == 0x20U) &&
             f.data[1] == static_cast<std::uint8_t>(a.index) &&
             f.data[2] == static_cast<std::uint8_t>(a.index >> 8U) && f.data[3] == a.sub;
    }));
  }
  /// NMT commands `c` the master sent to the device.
  [[nodiscard]] int nmt(co::nmt::command c) const {
    return static_cast<int>(std::count_if(sent.begin(), sent.end(), [&](const co::can_frame &f) {
      return f == co::nmt::encode(c, dev.node).value();
    }));
  }
};

} // namespace sim
