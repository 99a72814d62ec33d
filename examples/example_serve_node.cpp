// Serve node 5 (the XENAX CANopen dictionary) on a CAN bus with host::network: the node itself is
// examples/serve_node.hpp, eight lines (docs/host.md); this file opens the bus the command line
// names.
//
//   example_serve_node --can IFACE [SECONDS]        SocketCAN (can0, vcan0)
//   example_serve_node --slcan PORT [SECONDS]       an slcan adapter (/dev/ttyACM0)
//   example_serve_node --slcan-peer PORT [SECONDS]  slcan to a peer that sends no adapter
//                                                   answers (another slcan host on a null-modem
//                                                   line or pseudo-terminal)
//
// It serves for SECONDS (default 60). Exit status: 0, 1 when the bus failed, 2 a bad command line.
// Without arguments it prints this usage and exits 0 (the main CI job runs every example so).
// tests/cli/serve_test.cpp runs it against python canopen's RemoteNode.
#include "serve_node.hpp"

#include <fieldcodec/host/slcan.hpp>
#include <fieldcodec/host/socketcan_bus.hpp>

#include <charconv>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>

namespace {
constexpr const char *usage =
    "usage: example_serve_node (--can IFACE | --slcan PORT | --slcan-peer PORT) [SECONDS]\n";
}

int main(int argc, char **argv) {
  namespace host = fieldcodec::host;
  if (argc == 1) return std::fputs(usage, stdout), 0;
  const std::string how = argc >= 3 ? argv[1] : "";
  long seconds = 60;
  if (argc >= 4) { // a whole number of seconds, nothing else
    const std::string_view t = argv[3];
    const auto r = std::from_chars(t.data(), t.data() + t.size(), seconds);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size()) seconds = 0;
  }
  if ((how != "--can" && how != "--slcan" && how != "--slcan-peer") || argc > 4 || seconds <= 0) {
    std::fputs(usage, stderr);
    return 2;
  }
  std::unique_ptr<host::can_bus> bus;
  if (how == "--can") {
    auto can = std::make_unique<host::socketcan_bus>();
    if (!can->open(argv[2])) return std::puts(can->last_error().what.c_str()), 1;
    bus = std::move(can);
  } else {
    auto slcan = std::make_unique<host::slcan_bus>();
    if (!slcan->open(argv[2], 500000, {.check_answers = how == "--slcan"})) {
      return std::puts(slcan->last_error().what.c_str()), 1;
    }
    bus = std::move(slcan);
  }
  return fieldcodec::examples::serve(*bus, std::chrono::seconds(seconds));
}
