// Enabling a CiA 402 drive and moving it in profile position from a host program: node 5 with
// the XENAX CANopen dictionary (the header fieldcodec-gen made from its EDS) on any CAN bus.
// host::remote_drive finds the PDOs that carry the words in the drive's own mapping (or uses
// SDO), enables the drive, switches to profile position and moves to `target` (607Ah in its
// unit, checked against its limits). docs/host.md shows and counts these lines;
// tests/host/remote_drive_test.cpp runs them against the simulated drive
// (examples/sim_drive.hpp), tests/interop/interop_remote.py against python canopen's LocalNode.
#pragma once

#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/ds402/modes.hpp>
#include <fieldcodec/host/remote_drive.hpp>
#include <fieldcodec/xenax/canopen_units.hpp>

#include <cstdint>
#include <cstdio>

namespace fieldcodec::examples {

namespace host = fieldcodec::host;
namespace ds402 = fieldcodec::ds402;
namespace od = fieldcodec::od;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;

inline int move_axis(host::can_bus &bus, std::int32_t target) {
  host::remote_node node(bus, 5, xcan::dictionary, fieldcodec::xenax::canopen_units);
  host::remote_drive axis(node);
  auto r = axis.setup();
  if (r) r = axis.enable();
  if (r) r = axis.switch_mode(ds402::mode::profile_position);
  if (r) r = axis.move_to(od::signed_number(target));
  if (!r) std::puts(r.error().what.c_str());
  return r ? 0 : 1;
}

} // namespace fieldcodec::examples
