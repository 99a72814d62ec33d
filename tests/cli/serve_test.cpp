// `fieldcodec serve`: a node simulated from an EDS loaded at run time, on host::network, answering
// python canopen's RemoteNode over an slcan pseudo-terminal pair (boot-up, heartbeat, SDO reads
// and writes with the EDS's limits, NMT start/stop); values set from standard input through the
// one value path; bad input (unknown object, value out of limits, bad node-ID, unreadable EDS).
#include "cli_support.hpp"
#include "host/peers.hpp"
#include "python_support.hpp"
#include "skip.hpp"

#include <doctest/doctest.h>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <future>
#include <iterator>
#include <string>
#include <vector>

namespace t = fieldcodec::test;

namespace {

/// Lines of `text`.
std::vector<std::string> lines_of(const std::string &text) {
  std::vector<std::string> out;
  std::size_t at = 0;
  for (std::size_t nl; (nl = text.find('\n', at)) != std::string::npos; at = nl + 1U) {
    out.push_back(text.substr(at, nl - at));
  }
  return out;
}

} // namespace

TEST_CASE("cli serve: python canopen's RemoteNode reads, writes and commands the served node") {
  if (!t::python_ready()) {
    FIELDCODEC_SKIP_TEST("python", "python-canopen peer ("
                                       << t::peer_dir
                                       << ") or /usr/bin/python3 with python-can and pyserial "
                                          "not available (Debian: python3-can python3-serial)");
  }
  t::pty_pair python_side, serve_side;
  t::pump joined{python_side, serve_side};
  t::python_peer peer{python_side.path(), "cli/serve_node.eds", "cli/serve_peer.py"};
  REQUIRE(python_side.ok());
  REQUIRE(serve_side.ok());
  REQUIRE(peer.line(20000) == "ready");
  // standard input: a comment, a value in the form `sdo read` prints, one refused (above
  // HighLimit), an unknown object, a string, a query
  const std::string input = "# set before the master reads\n"
                            "2000 1800\n"
                            "2000 2001\n"
                            "2002 5\n"
                            "2001 \"axis one\"\n"
                            "2000\n";
  auto served = std::async(std::launch::async, [&] {
    return t::run_cli({"serve", "5", "--dict", "cli/serve_node.eds", "--slcan", serve_side.path(),
                       "--slcan-no-answers", "--duration", "8"},
                      input);
  });
  std::vector<std::string> seen;
  for (std::string l; (l = peer.line(15000)) != "done" && !l.empty();) seen.push_back(l);
  const std::vector<std::string> expected = {
      "boot-up",
      "heartbeat PRE-OPERATIONAL",
      "vendor 0x12e",
      "name fieldcodec served node",
      "limit 1800",
      "label axis one",
      "limit 1999",
      "label axis two",
      "abort Current Limit 0x06090031", // value too high
      "abort Label 0x06070012",         // data type does not match, length too high
      "abort 2002 0x06020000",          // object does not exist
      "heartbeat OPERATIONAL",
      "heartbeat STOPPED",
      "stopped: no SDO answer",
      "heartbeat PRE-OPERATIONAL",
      "limit 1999",
  };
  CHECK(seen == expected);
  const auto r = served.get();
  CHECK(r.code == 2); // a refused input line
  CHECK(r.err ==
        "fieldcodec: serve: input line 3: 2000h:00 Current Limit: '2001': above the high "
        "limit 2000 (not set)\n"
        "fieldcodec: serve: input line 4: 2002h:00: not in cli/serve_node.eds (not set)\n");
  const std::vector<std::string> out = lines_of(r.out);
  const std::vector<std::string> expected_out = {
      "NMT: pre-operational",
      "2000h:00 Current Limit = 1800",
      "2001h:00 Label = \"axis one\"",
      "2000h:00 Current Limit = 1800",
      "written: 2000h:00 Current Limit = 1999",
      "written: 2001h:00 Label = \"axis two\"",
      "NMT: operational",
      "NMT: stopped",
      "NMT: pre-operational",
  };
  CHECK(out == expected_out);
  t::check_golden("serve.txt", r.out); // quoted by docs/cli.md
}

TEST_CASE("cli serve --storage: python canopen's store() and restore() keep values over resets") {
  if (!t::python_ready()) {
    FIELDCODEC_SKIP_TEST("python", "python-canopen peer ("
                                       << t::peer_dir
                                       << ") or /usr/bin/python3 with python-can and pyserial "
                                          "not available (Debian: python3-can python3-serial)");
  }
  const std::string file = "serve_storage_test.par";
  std::remove(file.c_str());
  t::pty_pair python_side, serve_side;
  t::pump joined{python_side, serve_side};
  t::python_peer peer{python_side.path(), "cli/serve_node.eds", "cli/serve_peer.py", "storage"};
  REQUIRE(python_side.ok());
  REQUIRE(serve_side.ok());
  REQUIRE(peer.line(20000) == "ready");
  auto served = std::async(std::launch::async, [&] {
    return t::run_cli({"serve", "5", "--dict", "cli/serve_node.eds", "--slcan", serve_side.path(),
                       "--slcan-no-answers", "--duration", "5", "--storage", file});
  });
  std::vector<std::string> seen;
  for (std::string l; (l = peer.line(15000)) != "done" && !l.empty();) seen.push_back(l);
  const std::vector<std::string> expected = {
      "boot-up",
      "capability 01000000", // 1010h sub 1: saves on command
      "stored",
      "reset 1999 stored", // the saved values, not the defaults nor the unsaved 1200
      "load 1999 stored",  // "load" changes no current value
      "reset 1500 axis",   // the defaults after the next reset
      "abort evas 0x08000020",
  };
  CHECK(seen == expected);
  const auto r = served.get();
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(r.out.rfind("storage: 0 saved values set from serve_storage_test.par\n", 0) == 0);
  // "load" took every line out again
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text ==
        "# fieldcodec parameter file: INDEX SUB BYTES (hex; bytes as an SDO carries them)\n");
  // a malformed file: refused before the node starts
  t::write_text(file, "2000 00 CF0\n");
  auto bad = t::run_cli(
      {"serve", "5", "--dict", "cli/serve_node.eds", "--slcan", "/dev/null", "--storage", file});
  CHECK(bad.code == 3);
  CHECK(bad.err == "fieldcodec: serve: serve_storage_test.par:1: odd number of hex digits in the "
                   "value\n");
  // a value the dictionary refuses: said, and the default stays
  t::write_text(file, "2000 00 D107\n1017 00 C800\n");
  auto pty = t::pty_pair{};
  bad = t::run_cli({"serve", "5", "--dict", "cli/serve_node.eds", "--slcan", pty.path(),
                    "--slcan-no-answers", "--duration", "1", "--storage", file});
  CHECK(bad.code == 0);
  CHECK(bad.err ==
        "fieldcodec: serve: saved values not set (the defaults stay):\n"
        "serve_storage_test.par: 2000 00: value too high (download only) (0x06090031)\n");
  CHECK(bad.out.rfind("NMT: pre-operational\n", 0) == 0);
  bad = t::run_cli({"serve", "5", "--dict", "cli/serve_node.eds", "--slcan", "/dev/null",
                    "--storage", file, "--storage", file});
  CHECK(bad.code == 2);
  std::remove(file.c_str());
}

TEST_CASE("cli serve: bad command lines, unreadable dictionaries, a port that cannot be opened") {
  auto r = t::run_cli({"serve", "0", "--dict", "cli/serve_node.eds", "--slcan", "/dev/null"});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: serve: bad node '0' (1..127) (try 'fieldcodec serve --help')\n");
  r = t::run_cli({"serve", "128", "--dict", "cli/serve_node.eds", "--slcan", "/dev/null"});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: serve: bad node '128' (1..127) (try 'fieldcodec serve --help')\n");
  r = t::run_cli({"serve", "5", "--slcan", "/dev/null"});
  CHECK(r.code == 2);
  CHECK(r.err ==
        "fieldcodec: serve: give the dictionary: --dict FILE (try 'fieldcodec serve --help')\n");
  r = t::run_cli({"serve", "5", "--dict", "cli/serve_node.eds", "--dict", "cli/peer_node.eds",
                  "--slcan", "/dev/null"});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: serve: --dict given twice (try 'fieldcodec serve --help')\n");
  r = t::run_cli({"serve", "5", "--dict", "cli/serve_node.eds"});
  CHECK(r.code == 2);
  CHECK(r.err ==
        "fieldcodec: serve: give one of --can IFACE or --slcan PORT (try 'fieldcodec serve "
        "--help')\n");
  r = t::run_cli(
      {"serve", "5", "--dict", "cli/serve_node.eds", "--slcan", "/dev/null", "--duration", "0"});
  CHECK(r.code == 2);
  r = t::run_cli({"serve", "5", "--dict", "cli/no_such_file.eds", "--slcan", "/dev/null"});
  CHECK(r.code == 5);
  CHECK(r.err == "fieldcodec: serve: cli/no_such_file.eds: error: cannot open file\n");
  const std::string bad = "serve_unterminated.eds";
  t::write_text(bad, "[1000\nParameterName=Device Type\n");
  r = t::run_cli({"serve", "5", "--dict", bad, "--slcan", "/dev/null"});
  CHECK(r.code == 5);
  CHECK(r.err.find("serve_unterminated.eds:1:6: error: expected ']'") != std::string::npos);
  std::remove(bad.c_str());
  r = t::run_cli({"serve", "5", "--dict", "cli/serve_node.eds", "--slcan", "/dev/no_such_port"});
  CHECK(r.code == 3);
  CHECK(r.err == "fieldcodec: serve: /dev/no_such_port: open: No such file or directory\n");
  r = t::run_cli({"serve", "--help"});
  CHECK(r.code == 0);
  CHECK(r.out.find("INDEX[:SUB] VALUE") != std::string::npos);
}

TEST_CASE("examples/example_serve_node: python canopen's RemoteNode reads and writes its node") {
  if (!t::python_ready()) {
    FIELDCODEC_SKIP_TEST("python", "python-canopen peer ("
                                       << t::peer_dir
                                       << ") or /usr/bin/python3 with python-can and pyserial "
                                          "not available (Debian: python3-can python3-serial)");
  }
  const std::string example = std::string(FIELDCODEC_BINARY_DIR) + "/examples/example_serve_node";
  if (::access(example.c_str(), X_OK) != 0) {
    FIELDCODEC_SKIP_TEST("examples", example << " not built (-DFIELDCODEC_BUILD_EXAMPLES=ON)");
  }
  t::pty_pair python_side, serve_side;
  t::pump joined{python_side, serve_side};
  t::python_peer peer{python_side.path(),
                      std::string(FIELDCODEC_SOURCE_DIR) + "/dictionaries/xenax_canopen.eds",
                      "cli/serve_peer.py", "example"};
  REQUIRE(peer.line(20000) == "ready");
  const char *argv[] = {example.c_str(), "--slcan-peer", serve_side.path().c_str(), "5", nullptr};
  pid_t pid = -1;
  REQUIRE(::posix_spawn(&pid, example.c_str(), nullptr, nullptr, const_cast<char **>(argv),
                        environ) == 0);
  std::vector<std::string> seen;
  for (std::string l; (l = peer.line(15000)) != "done" && !l.empty();) seen.push_back(l);
  const std::vector<std::string> expected = {
      "boot-up", "device type 0x20192", "6073 123", "abort 6073 0x06090031", "6073 123",
  };
  CHECK(seen == expected);
  int status = -1;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0); // served its 5 seconds, the bus never failed
}
