// `sdo read` / `sdo write` through od's one value path (issue 26, section 1): what read prints,
// write accepts in the same unit and sends as the same bytes; limits (node-ID-relative ones for
// the target node), string capacity and VISIBLE_STRING characters are refused before any frame
// exists (exit 2, naming the limit); hex is never a silent raw spelling; --raw is.
// The node is a fieldcodec XENAX node behind an slcan pseudo-terminal (tests/host/peers.hpp);
// node.log() proves what reached the bus.
#include "cli_support.hpp"
#include "host/peers.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

namespace t = fieldcodec::test;

namespace {
const std::string xenax_eds = "../dictionaries/xenax_canopen.eds";
const std::string dpq_csv = "../dictionaries/dpq_parameters.csv";

/// The frames the node saw that are SDO requests to it (0x605).
std::size_t requests(t::slcan_node &node) {
  std::size_t n = 0;
  for (const auto &l : node.log()) n += l.rfind("605#", 0) == 0 ? 1U : 0U;
  return n;
}
} // namespace

TEST_CASE("sdo write takes back what sdo read prints, in the same unit (6073h in mA)") {
  t::slcan_node node;
  REQUIRE(node.ok());
  const std::string port = node.path();
  const std::uint8_t limit[] = {0x96, 0x00}; // raw 150 = 1500 mA
  node.set({0x6073, 0}, limit);
  auto r = t::run_cli({"sdo", "read", "5", "6073", "--slcan", port, "--dict", xenax_eds});
  CHECK(r.code == 0);
  CHECK(r.out == "6073h:00 Limit I_Force = 1500 mA (raw 150)\n");
  // today's defect: "1500" was sent as raw 1500 (15 A); now it is 1500 mA = raw 150
  r = t::run_cli({"sdo", "write", "5", "6073", "1500", "--slcan", port, "--dict", xenax_eds});
  CHECK(r.code == 0);
  CHECK(r.err == "");
  CHECK(r.out == "6073h:00 Limit I_Force = 1500 mA (raw 150)\n"); // what was sent
  CHECK(node.value({0x6073, 0}) == std::vector<std::uint8_t>{0x96, 0x00});
  // the unit may be written; a value between steps is rounded and the line says so
  r = t::run_cli({"sdo", "write", "5", "6073", "1205 mA", "--slcan", port, "--dict", xenax_eds});
  CHECK(r.out == "6073h:00 Limit I_Force = 1210 mA (raw 121)\n");
  t::check_golden("sdo-write.txt", r.out);
  CHECK(node.value({0x6073, 0}) == std::vector<std::uint8_t>{0x79, 0x00});
  // --raw: the raw number, both ways
  r = t::run_cli(
      {"sdo", "write", "5", "6073", "150", "--raw", "--slcan", port, "--dict", xenax_eds});
  CHECK(r.code == 0);
  CHECK(r.out == "6073h:00 Limit I_Force = 150\n");
  CHECK(node.value({0x6073, 0}) == std::vector<std::uint8_t>{0x96, 0x00});
  r = t::run_cli({"sdo", "read", "5", "6073", "--raw", "--slcan", port, "--dict", xenax_eds});
  CHECK(r.out == "6073h:00 Limit I_Force = 150\n");
  r = t::run_cli(
      {"sdo", "write", "5", "6073", "1500", "--slcan", port, "--dict", xenax_eds, "--json"});
  CHECK(r.out == "{\"node\":5,\"index\":24691,\"sub\":0,\"name\":\"Limit I_Force\",\"value\":1500,"
                 "\"raw\":150,\"unit\":\"mA\",\"sent\":\"9600\"}\n");
}

TEST_CASE("sdo write refuses values outside the limits before any frame exists") {
  t::slcan_node node;
  REQUIRE(node.ok());
  const std::string port = node.path();
  const std::size_t before = requests(node);
  // 6073h HighLimit 0x7D0 = 20000 mA
  auto r = t::run_cli({"sdo", "write", "5", "6073", "20010", "--slcan", port, "--dict", xenax_eds});
  CHECK(r.code == 2);
  CHECK(r.out == "");
  CHECK(r.err == "fieldcodec: sdo write: node 5, 6073h:00 Limit I_Force: '20010': above the high "
                 "limit 20000 mA (nothing sent)\n");
  r = t::run_cli(
      {"sdo", "write", "5", "6073", "2001", "--raw", "--slcan", port, "--dict", xenax_eds});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: sdo write: node 5, 6073h:00 Limit I_Force: '2001': above the high "
                 "limit 2000 (nothing sent)\n");
  // 6081h LowLimit 0xA
  r = t::run_cli({"sdo", "write", "5", "6081", "5", "--slcan", port, "--dict", xenax_eds});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: sdo write: node 5, 6081h:00 Speed: '5': below the low limit 10 "
                 "inc/s (nothing sent)\n");
  // DPQ 2023h: 0…5000 (manual 4.100)
  r = t::run_cli({"sdo", "write", "5", "2023", "6000", "--slcan", port, "--dict", dpq_csv});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: sdo write: node 5, 2023h:00 Inj. P Limit 1: '6000': above the high "
                 "limit 5000 (nothing sent)\n");
  // a node-ID-relative limit is the target node's: 1200h:01 is $NODEID+0x600 for node 5 only
  r = t::run_cli({"sdo", "write", "5", "1400:1", "0x206", "--slcan", port, "--dict",
                  "cli/relative_limits.eds"});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: sdo write: node 5, 1400h:01 RPDO1 communication: RPDO1 COB-ID: "
                 "'0x206': above the high limit 0x00000205 (nothing sent)\n");
  r = t::run_cli({"sdo", "write", "6", "1400:1", "0x206", "--slcan", port, "--dict",
                  "cli/relative_limits.eds"});
  CHECK(r.err.find("(nothing sent)") == std::string::npos); // node 6's limit; node 6 is absent
  CHECK(r.code == 1);
  // nothing of this reached the bus
  CHECK(requests(node) == before);
}

TEST_CASE("sdo write: hex is never a silent raw spelling, strings within capacity") {
  t::slcan_node node;
  REQUIRE(node.ok());
  const std::string port = node.path();
  const std::size_t before = requests(node);
  // DPQ 2023h is scaled: "0x10" used to write raw 16 (0.049), "16" writes 16 (raw 5243)
  auto r = t::run_cli({"sdo", "write", "5", "2023", "0x10", "--slcan", port, "--dict", dpq_csv});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: sdo write: node 5, 2023h:00 Inj. P Limit 1: '0x10': hex spells a raw "
                 "value; this object is scaled, give it in engineering units, or the raw value "
                 "with --raw (nothing sent)\n");
  // docs/cli.md quotes both refusals
  const auto limit =
      t::run_cli({"sdo", "write", "5", "6073", "20010", "--slcan", port, "--dict", xenax_eds});
  t::check_golden("sdo-write-refused.txt", limit.err + r.err);
  // 5011h Size=30
  r = t::run_cli(
      {"sdo", "write", "5", "5011", std::string(31, 'A'), "--slcan", port, "--dict", xenax_eds});
  CHECK(r.code == 2);
  CHECK(r.err.find("longer than the 30 bytes the object holds (nothing sent)") !=
        std::string::npos);
  r = t::run_cli({"sdo", "write", "5", "5011",
                  "Stra\xC3\x9F"
                  "e",
                  "--slcan", port, "--dict", xenax_eds});
  CHECK(r.code == 2);
  CHECK(r.err.find("character 5 is not a visible ASCII character") != std::string::npos);
  r = t::run_cli({"sdo", "write", "5", "5011", "a\tb", "--slcan", port, "--dict", xenax_eds});
  CHECK(r.code == 2);
  CHECK(requests(node) == before);
  // 30 characters go through, and read back as written
  r = t::run_cli(
      {"sdo", "write", "5", "5011", std::string(30, 'A'), "--slcan", port, "--dict", xenax_eds});
  CHECK(r.code == 0);
  CHECK(r.out ==
        "5011h:00 Signateq Sensor Model Type (SQSMT) = \"" + std::string(30, 'A') + "\"\n");
  // raw hex for the scaled entry is explicit: --raw (refused by the XENAX node, which has no
  // 2023h: the CLI sent it)
  r = t::run_cli(
      {"sdo", "write", "5", "2023", "0x10", "--raw", "--slcan", port, "--dict", dpq_csv});
  CHECK(r.code == 1);
  CHECK(r.err.find("SDO abort 06020000h") != std::string::npos);
}

TEST_CASE("sdo: --dict with --type, --timeout 0, a repeated --dict, an unknown --type") {
  t::slcan_node node;
  REQUIRE(node.ok());
  const std::string port = node.path();
  auto r = t::run_cli(
      {"sdo", "read", "5", "1018:1", "--slcan", port, "--dict", xenax_eds, "--type", "u32"});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: sdo read: --dict and --type both give the object's type: give one "
                 "(try 'fieldcodec sdo read --help')\n");
  r = t::run_cli({"sdo", "read", "5", "1018:1", "--slcan", port, "--timeout", "0"});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: sdo read: bad --timeout 0 (1..3600000 ms) (try 'fieldcodec sdo "
                 "read --help')\n");
  r = t::run_cli({"decode", "--dict", "12=" + xenax_eds, "--dict", "12=" + dpq_csv}, "");
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: decode: --dict 12= given twice (try 'fieldcodec decode --help')\n");
  r = t::run_cli({"sdo", "write", "5", "6040", "1", "--slcan", port, "--type", "u24"});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: sdo write: unknown type 'u24' (u8 u16 u32 u64 i8 i16 i32 i64 f32 "
                 "f64 bool str hex) (try 'fieldcodec sdo write --help')\n");
}
