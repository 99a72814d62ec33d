// Serving a CANopen node on host::network: node 5 with the XENAX CANopen dictionary (the header
// fieldcodec-gen made from its EDS) on any CAN bus, for `how_long`. docs/host.md shows and
// counts these lines; examples/example_serve_node.cpp runs them on SocketCAN or slcan
// (against python canopen in tests/cli/serve_test.cpp), tests/host/network_test.cpp on an
// in-memory bus.
#pragma once

#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/host/network.hpp>

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>

namespace fieldcodec::examples {

namespace host = fieldcodec::host;
namespace node = fieldcodec::canopen::node;
namespace x = fieldcodec::dictionaries::xenax_canopen;
using store_t = fieldcodec::canopen::dictionary_store<>;
inline constexpr auto layout = fieldcodec::canopen::make_layout<x::entries.size()>(x::dictionary);

inline int serve(host::can_bus &bus, std::chrono::milliseconds how_long) {
  std::array<std::uint8_t, layout.storage_size()> storage{};
  store_t store{x::dictionary, layout, storage};
  if (!store.init_defaults(5)) return 1;
  node::device<store_t, node::capacity_for(x::dictionary)> dev(store, 5);
  host::network net(bus);
  if (!net.send(net.add(dev), dev.start(net.now()))) return 1;
  auto r = net.run_for(how_long);
  return r ? 0 : (std::puts(r.error().what.c_str()), 1);
}

} // namespace fieldcodec::examples
