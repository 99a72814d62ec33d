// The CLI's `sdo read` / `sdo write` against another implementation: a python-canopen
// LocalNode (../shared/peers/python-canopen) on python-can's slcan interface. The two slcan
// hosts are joined by two pseudo-terminals and a byte pump; neither answers the other's
// adapter commands, so the CLI runs with --slcan-no-answers. Skipped with a message when the
// peer or python-can/pyserial are missing.
#include "cli_support.hpp"
#include "host/peers.hpp"
#include "model.hpp"
#include "od_tables.hpp"
#include "python_support.hpp"
#include "readers.hpp"
#include "skip.hpp"

#include <fieldcodec/host/remote_node.hpp>
#include <fieldcodec/host/slcan.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace t = fieldcodec::test;
namespace gen = fieldcodec::gen;
namespace host = fieldcodec::host;

namespace {

using t::peer_dir;
using t::pump;
using t::python_peer;
using t::python_ready;

/// The python peer (node 5, cli/peer_node.eds) on one pseudo-terminal, the CLI on the other.
struct python_session {
  t::pty_pair python_side, cli_side;
  pump joined{python_side, cli_side};
  python_peer peer{python_side.path(), "cli/peer_node.eds"};

  [[nodiscard]] bool ready() {
    return python_side.ok() && cli_side.ok() && peer.line(20000) == "ready";
  }
  [[nodiscard]] std::string port() const { return cli_side.path(); }
  /// The CLI with the link options and the peer's dictionary appended.
  t::cli_result cli(std::vector<std::string> args) const {
    for (const std::string &a : {std::string("--slcan"), port(), std::string("--slcan-no-answers"),
                                 std::string("--dict"), std::string("cli/peer_node.eds")}) {
      args.push_back(a);
    }
    return t::run_cli(args);
  }
};

} // namespace

TEST_CASE("cli: sdo read and write against python-canopen over slcan") {
  if (!python_ready()) {
    FIELDCODEC_SKIP_TEST("python", "python-canopen peer ("
                                       << peer_dir
                                       << ") or /usr/bin/python3 with python-can and pyserial "
                                          "not available (Debian: python3-can python3-serial)");
  }
  python_session session;
  REQUIRE(session.ready());
  python_peer &peer = session.peer;
  const std::string port = session.port();
  auto cli = [&session](std::vector<std::string> args) { return session.cli(std::move(args)); };

  auto r = cli({"sdo", "read", "5", "1018:1"});
  CHECK(r.err == "");
  CHECK(r.code == 0);
  CHECK(r.out == "1018h:01 Identity Object: Vendor Id = 0x0000012E\n");
  // a segmented upload of the EDS default
  r = cli({"sdo", "read", "5", "1008"});
  CHECK(r.err == "");
  CHECK(r.out == "1008h:00 Manufacturer Device Name = \"fieldcodec python peer node\"\n");
  // expedited download: the peer reports what it stored
  r = cli({"sdo", "write", "5", "6040", "0x000F"});
  CHECK(r.err == "");
  CHECK(r.code == 0);
  CHECK(peer.line(5000) == "write 6040:00 0f00");
  r = cli({"sdo", "read", "5", "6040"});
  CHECK(r.out == "6040h:00 Controlword = 0x000F (enable operation)\n");
  r = cli({"sdo", "write", "5", "607A", "-20000"});
  CHECK(r.code == 0);
  CHECK(peer.line(5000) == "write 607a:00 e0b1ffff");
  // the peer's abort, spelled out
  r = cli({"sdo", "read", "5", "6060:0"});
  CHECK(r.out == "6060h:00 Modes of Operation = 1 (profile position)\n");
  r = cli({"sdo", "read", "5", "6041"});
  CHECK(r.out == "6041h:00 Statusword = 0x0250 (switch on disabled)\n");
  // python-canopen answers every block upload with a normal upload (CiA 301 allows that only
  // for objects up to the client's protocol switch threshold): refused with threshold 0 ...
  r = cli({"sdo", "read", "5", "1008", "--block"});
  CHECK(r.code == 1);
  CHECK(r.err == "fieldcodec: sdo read: node 5, 1008h:00: unexpected frame (sent SDO abort "
                 "05040001h: client/server command specifier invalid or unknown) (with --block: "
                 "the node may not support block transfer, or answers a block upload with a "
                 "normal upload; try without --block, or allow the switch with "
                 "--switch-threshold 127)\n");
  // ... and followed when the client allows the switch
  r = cli({"sdo", "read", "5", "1008", "--block", "--switch-threshold", "127"});
  CHECK(r.err == "");
  CHECK(r.out == "1008h:00 Manufacturer Device Name = \"fieldcodec python peer node\"\n");
  r = t::run_cli({"sdo", "read", "5", "1234", "--slcan", port, "--slcan-no-answers"});
  CHECK(r.code == 1);
  CHECK(r.err == "fieldcodec: sdo read: node 5, 1234h:00: SDO abort 06020000h: object not in the "
                 "object dictionary\n");
}

namespace {
/// The value in a `sdo read` line: after " = ", a quoted string whole, else up to the first
/// " (" (annotations: the raw number, a CiA 402 command) or " [".
std::string value_of(const std::string &line) {
  std::string v = line.substr(line.find(" = ") + 3U);
  if (!v.empty() && v.back() == '\n') v.pop_back();
  if (!v.empty() && v.front() == '"') {
    std::size_t i = 1;
    while (i < v.size() && v[i] != '"') i += v[i] == '\\' ? 2U : 1U;
    return v.substr(0, i + 1U);
  }
  return v.substr(0, std::min(v.find(" ("), v.find(" [")));
}
/// A field of a JSON line ("bytes":"0102" → 0102).
std::string json_field(const std::string &line, const std::string &key) {
  const auto at = line.find("\"" + key + "\":\"");
  if (at == std::string::npos) return {};
  const auto start = at + key.size() + 4U;
  return line.substr(start, line.find('"', start) - start);
}
std::string lower(std::string s) {
  for (char &c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}
} // namespace

TEST_CASE("cli: what sdo read prints, sdo write sends back to python-canopen as the same bytes") {
  if (!python_ready()) {
    FIELDCODEC_SKIP_TEST("python", "python-canopen peer ("
                                       << peer_dir
                                       << ") or /usr/bin/python3 with python-can and pyserial "
                                          "not available (Debian: python3-can python3-serial)");
  }
  python_session session;
  REQUIRE(session.ready());
  python_peer &peer = session.peer;
  auto cli = [&session](std::vector<std::string> args) { return session.cli(std::move(args)); };
  // every writable object of the EDS: read, write back the printed text, compare the bytes
  for (const std::string object :
       {"2000", "2001", "2002", "2003", "2004", "2005", "6040", "6060", "607A"}) {
    CAPTURE(object);
    const auto text = cli({"sdo", "read", "5", object});
    REQUIRE(text.code == 0);
    const auto json = cli({"sdo", "read", "5", object, "--json"});
    const std::string bytes = json_field(json.out, "bytes");
    REQUIRE_FALSE(bytes.empty());
    const std::string value = value_of(text.out);
    CAPTURE(value);
    const auto w = cli({"sdo", "write", "5", object, value, "--json"});
    CHECK(w.err == "");
    CHECK(w.code == 0);
    CHECK(json_field(w.out, "sent") == bytes);
    const std::string seen = peer.line(5000); // "write 2000:00 dc05"
    CHECK(seen.substr(seen.rfind(' ') + 1U) == lower(bytes));
  }
  // refused before any frame: the peer reports no write (the next line is the valid one's)
  auto r = cli({"sdo", "write", "5", "2000", "2001"});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: sdo write: node 5, 2000h:00 Current Limit: '2001': above the high "
                 "limit 2000 (nothing sent)\n");
  r = cli({"sdo", "write", "5", "2001", "seventeen chars!!"});
  CHECK(r.code == 2);
  CHECK(r.err.find("longer than the 16 bytes the object holds") != std::string::npos);
  r = cli({"sdo", "write", "5", "2000", "0x7D0"});
  CHECK(r.code == 0);
  CHECK(r.out == "2000h:00 Current Limit = 2000\n");
  CHECK(peer.line(5000) == "write 2000:00 d007");
}

TEST_CASE("host::remote_node against python-canopen: objects by name, values both ways") {
  if (!python_ready()) {
    FIELDCODEC_SKIP_TEST("python", "python-canopen peer ("
                                       << peer_dir
                                       << ") or /usr/bin/python3 with python-can and pyserial "
                                          "not available (Debian: python3-can python3-serial)");
  }
  python_session session;
  REQUIRE(session.ready());
  python_peer &peer = session.peer;
  // the peer's EDS loaded at run time (the generator's reader), objects found by their names
  gen::diagnostics diag;
  auto model = gen::read_file("cli/peer_node.eds", diag);
  REQUIRE(model);
  const gen::od_tables eds(*model);
  host::slcan_bus bus;
  REQUIRE(bus.open(session.port(), 500000, {.check_answers = false}));
  host::remote_node node(bus, 5, eds.view());

  const auto vendor = eds.address_of("Identity Object", "Vendor Id");
  REQUIRE(vendor);
  auto v = node.read(vendor.value());
  REQUIRE(v);
  CHECK(v.value().to_int64().value() == 0x12E);
  CHECK(node.read_text(eds.address_of("Manufacturer Device Name").value()).value() ==
        "\"fieldcodec python peer node\"");

  // every writable object: what read_text shows, write takes back as the same bytes
  for (const char *name : {"Current Limit", "Label", "Gain", "Enabled", "Counter", "Key"}) {
    CAPTURE(name);
    const auto a = eds.address_of(name);
    REQUIRE(a);
    auto text = node.read_text(a.value());
    REQUIRE(text);
    auto bytes = node.read_bytes(eds.at(a.value()).value());
    REQUIRE(bytes);
    std::string hex;
    for (const std::uint8_t b : bytes.value()) {
      const char digits[] = "0123456789abcdef";
      hex += digits[b >> 4U];
      hex += digits[b & 0xFU];
    }
    REQUIRE(node.write(a.value(), text.value()));
    const std::string seen = peer.line(5000); // "write 2000:00 dc05"
    CHECK(seen.substr(seen.rfind(' ') + 1U) == hex);
  }
  // a number in, checked against the EDS's limits before any frame
  const auto limit = eds.address_of("Current Limit").value();
  REQUIRE(node.write(limit, fieldcodec::od::unsigned_number(1999)));
  CHECK(peer.line(5000) == "write 2000:00 cf07");
  auto high = node.write(limit, fieldcodec::od::unsigned_number(2001));
  REQUIRE_FALSE(high);
  CHECK(high.error().what == "node 5, 2000h:00: refused: above the high limit 2000");
  auto label = node.write(eds.address_of("Label").value(), "seventeen chars!!");
  REQUIRE_FALSE(label);
  CHECK(label.error().value.issue == fieldcodec::od::value_issue::capacity);
  CHECK(node.read(limit).value().to_int64().value() == 1999); // the refused values never left
  // the peer's abort for an object it does not have
  auto missing = node.sdo().read({0x1234, 0});
  REQUIRE_FALSE(missing);
  CHECK(missing.error().what ==
        "node 5, 1234h:00: SDO abort 06020000h: object not in the object dictionary");
}
