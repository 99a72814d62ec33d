// Command-line details of issue 26, section 2 ("smaller" items, dump of a silent node), each a
// regression test of a defect: dump stops when the node proves silent (it tried every object,
// wrote a DCF without values and exited 0), --device is case-insensitive, --timeout 0 is
// refused, monitor --log names the interface over slcan.
#include "cli_support.hpp"
#include "host/peers.hpp"

#include <doctest/doctest.h>

#include <string>
#include <thread>

namespace t = fieldcodec::test;
namespace co = fieldcodec::canopen;
using namespace std::chrono_literals;

namespace {
const std::string xenax_eds = "../dictionaries/xenax_canopen.eds";
}

TEST_CASE("dump of a node that never answers stops after three timeouts, exit 1, no DCF") {
  t::slcan_node node; // node 5; nobody is node 9
  REQUIRE(node.ok());
  const auto r = t::run_cli(
      {"dump", "9", "--dict", xenax_eds, "--slcan", node.path(), "--timeout", "30", "--quiet"});
  CHECK(r.code == 1);
  CHECK(r.out == "");
  CHECK(r.err == "fieldcodec: dump: node 9 does not answer: 3 SDO timeouts in a row, from "
                 "1000h:00 (0 of 447 objects read); no DCF written\n");
  // progress lines when standard error is no terminal and neither --progress nor --quiet
  const auto p =
      t::run_cli({"dump", "9", "--dict", xenax_eds, "--slcan", node.path(), "--timeout", "30"});
  CHECK(p.code == 1);
}

TEST_CASE("dump shows progress on a log (no terminal) at every tenth") {
  t::slcan_node node;
  REQUIRE(node.ok());
  const auto r = t::run_cli({"dump", "5", "--dict", xenax_eds, "--slcan", node.path()});
  CHECK(r.code == 0);
  CHECK(r.err.find("fieldcodec: dump: reading 44/447\n") != std::string::npos);
  CHECK(r.err.find("fieldcodec: dump: reading 440/447\n") != std::string::npos);
}

TEST_CASE("--device is case-insensitive") {
  const std::string log = "(1.000000) can0 185#3706\n";
  const auto lower = t::run_cli({"decode", "--device", "5=xenax"}, log);
  const auto upper = t::run_cli({"decode", "--device", "5=XENAX"}, log);
  CHECK(upper.code == 0);
  CHECK(upper.out == lower.out);
  CHECK(t::run_cli({"decode", "--device", "5=Ds402"}, log).code == 0);
}

TEST_CASE("monitor --log over slcan writes an interface name, not '-'") {
  t::slcan_node node;
  REQUIRE(node.ok());
  std::thread feeder([&node] {
    std::this_thread::sleep_for(300ms);
    node.inject(co::nmt::encode_heartbeat(5, co::nmt::state::operational).value());
  });
  const std::string log = "cli_monitor_log_test.log";
  const auto r = t::run_cli(
      {"monitor", "--slcan", node.path(), "--count", "1", "--duration", "10", "--log", log});
  feeder.join();
  CHECK(r.code == 0);
  const std::string text = t::read_text(log);
  std::remove(log.c_str());
  // "(seconds.micros) slcan0 705#05": candump's notation, which decode reads back
  CHECK(text.find(") slcan0 705#05\n") != std::string::npos);
  CHECK(t::run_cli({"decode"}, text).out.find(" slcan0 705 HEARTBEAT node 5: operational") !=
        std::string::npos);
}

TEST_CASE("--block against a server without block transfer: the error says what to try") {
  t::slcan_node::options o;
  o.server_block = false;
  t::slcan_node node(o);
  REQUIRE(node.ok());
  const auto r = t::run_cli({"sdo", "read", "5", "1008", "--block", "--slcan", node.path()});
  CHECK(r.code == 1);
  CHECK(r.err.find("SDO abort 05040001h") != std::string::npos);
  CHECK(r.err.find("(with --block: the node may not support block transfer, or answers a block "
                   "upload with a normal upload; try without --block, or allow the switch with "
                   "--switch-threshold 127)") != std::string::npos);
  const auto plain = t::run_cli({"sdo", "read", "5", "1008", "--slcan", node.path()});
  CHECK(plain.code == 0);
}
