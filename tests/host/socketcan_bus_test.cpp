// SocketCAN bus (host/socketcan_bus.hpp). The traffic test needs a virtual CAN interface: it
// uses $FIELDCODEC_VCAN (default vcan0), tries to create it (`ip link add … type vcan`, needs
// root and the vcan module) and is skipped with a message where that is impossible (CI machines
// have no vcan, .ci/run lets it skip there; slcan and the candump reader cover the shared code).
#include <fieldcodec/host/socketcan_bus.hpp>

#include "skip.hpp"
#include <doctest/doctest.h>

#ifdef FIELDCODEC_HAS_SOCKETCAN
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/host/sdo.hpp>

#include <cstdlib>
#include <string>

namespace co = fieldcodec::canopen;
namespace host = fieldcodec::host;
using fieldcodec::errc;
using namespace std::chrono_literals;

namespace {
std::string vcan_name() {
  const char *env = std::getenv("FIELDCODEC_VCAN");
  return env != nullptr && *env != '\0' ? env : "vcan0";
}
bool have_vcan(const std::string &name) {
  if (::if_nametoindex(name.c_str()) != 0U) return true;
  const std::string cmd = "ip link add dev " + name +
                          " type vcan >/dev/null 2>&1 && ip link set up " + name +
                          " >/dev/null 2>&1";
  (void)std::system(cmd.c_str());
  return ::if_nametoindex(name.c_str()) != 0U;
}
} // namespace

TEST_CASE("SocketCAN bus: failures name the interface") {
  host::socketcan_bus bus;
  CHECK(bus.open("nosuchcan9") == errc::invalid_argument);
  CHECK(bus.last_error().what == "nosuchcan9: no such network interface");
  CHECK(bus.open("a-name-far-too-long") == errc::too_long);
  CHECK(bus.open("can 0") == errc::bad_character);
  CHECK_FALSE(bus.is_open());
  CHECK(bus.send(co::make_frame(0x80, {}).value()) == errc::bad_state);
  CHECK(bus.receive(10ms) == errc::bad_state);
  CHECK(bus.set_filters({}) == errc::bad_state);
  // "lo" exists but is no CAN interface: the socket or the bind fails
  CHECK(bus.open("lo") == errc::bad_state);
}

TEST_CASE("SocketCAN bus over vcan: send, receive, filters, timeout") {
  const std::string name = vcan_name();
  if (!have_vcan(name)) {
    FIELDCODEC_SKIP_TEST("vcan", "no virtual CAN interface '"
                                     << name << "' (needs the vcan module and root)");
  }
  host::socketcan_bus a, b;
  REQUIRE(a.open(name));
  REQUIRE(b.open(name));
  const auto f = co::make_frame(0x605, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0}).value();
  REQUIRE(a.send(f));
  auto r = b.receive(500ms);
  REQUIRE(r);
  CHECK(r.value().frame == f);
  CHECK(r.value().time.known());
  auto rec = b.receive_record(50ms);
  CHECK(rec == errc::timeout);
  REQUIRE(b.set_filters({{0x585, 0x7FF}}));
  REQUIRE(a.send(f));
  const auto answer = co::make_frame(0x585, {0x43, 0x18, 0x10, 0x01, 1, 2, 3, 4}).value();
  REQUIRE(a.send(answer));
  r = b.receive(500ms);
  REQUIRE(r);
  CHECK(r.value().frame == answer);
  // an SDO read that nobody answers times out with the node named
  const auto why = host::sdo_read(a, 9, {0x1018, 1}, 100ms);
  CHECK(why == errc::timeout);
  CHECK(why.error().what.find("node 9, 1018h:01: timeout") == 0);
}
#endif
