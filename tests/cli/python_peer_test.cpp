// The CLI's `sdo read` / `sdo write` against another implementation: a python-canopen
// LocalNode (../shared/peers/python-canopen) on python-can's slcan interface. The two slcan
// hosts are joined by two pseudo-terminals and a byte pump; neither answers the other's
// adapter commands, so the CLI runs with --slcan-no-answers. Skipped with a message when the
// peer or python-can/pyserial are missing.
#include "cli_support.hpp"
#include "host/peers.hpp"

#include "skip.hpp"
#include <doctest/doctest.h>

#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <string>
#include <thread>

extern char **environ;

namespace t = fieldcodec::test;

namespace {

const std::string peer_dir = std::string(t::shared_dir) + "/peers/python-canopen";

bool python_ready() {
  if (::access((peer_dir + "/canopen/__init__.py").c_str(), R_OK) != 0) return false;
  const std::string cmd = "PYTHONPATH=" + peer_dir +
                          " /usr/bin/python3 -c 'import can, serial, canopen' >/dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

/// Copies bytes between the masters of two pseudo-terminals: what one slave writes, the other
/// reads, as over a null-modem cable.
class pump {
public:
  pump(t::pty_pair &a, t::pty_pair &b) : a_(a), b_(b), thread_([this] { run(); }) {}
  ~pump() {
    stop_ = true;
    thread_.join();
  }

private:
  void run() {
    while (!stop_) {
      const std::string x = a_.read_master(5);
      if (!x.empty()) b_.write_master(x);
      const std::string y = b_.read_master(5);
      if (!y.empty()) a_.write_master(y);
    }
  }
  t::pty_pair &a_;
  t::pty_pair &b_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

/// The python peer as a child process with pipes for its standard input and output.
class python_peer {
public:
  python_peer(const std::string &port, const std::string &eds) {
    int in[2], out[2];
    if (::pipe(in) != 0 || ::pipe(out) != 0) return;
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, in[0], 0);
    posix_spawn_file_actions_adddup2(&fa, out[1], 1);
    posix_spawn_file_actions_addclose(&fa, in[1]);
    posix_spawn_file_actions_addclose(&fa, out[0]);
    const std::string pp = "PYTHONPATH=" + peer_dir;
    std::vector<char *> env;
    env.push_back(const_cast<char *>(pp.c_str()));
    for (char **e = environ; *e != nullptr; ++e) env.push_back(*e);
    env.push_back(nullptr);
    const char *argv[] = {
        "/usr/bin/python3", "cli/canopen_peer.py", port.c_str(), eds.c_str(), "5", nullptr};
    if (::posix_spawn(&pid_, "/usr/bin/python3", &fa, nullptr, const_cast<char **>(argv),
                      env.data()) != 0) {
      pid_ = -1;
    }
    posix_spawn_file_actions_destroy(&fa);
    ::close(in[0]);
    ::close(out[1]);
    stdin_ = in[1];
    stdout_ = out[0];
  }
  ~python_peer() {
    if (stdin_ >= 0) ::close(stdin_); // the peer ends when its input closes
    if (pid_ > 0) {
      int status = 0;
      for (int i = 0; i < 50 && ::waitpid(pid_, &status, WNOHANG) == 0; ++i) {
        ::usleep(100000);
        if (i == 49) {
          ::kill(pid_, SIGTERM);
          ::waitpid(pid_, &status, 0);
        }
      }
    }
    if (stdout_ >= 0) ::close(stdout_);
  }
  /// The next line the peer prints, or "" after `ms` milliseconds.
  std::string line(int ms) {
    for (;;) {
      if (const auto nl = buffer_.find('\n'); nl != std::string::npos) {
        std::string l = buffer_.substr(0, nl);
        buffer_.erase(0, nl + 1U);
        return l;
      }
      pollfd p{stdout_, POLLIN, 0};
      if (::poll(&p, 1, ms) <= 0) return {};
      char buf[256];
      const ssize_t n = ::read(stdout_, buf, sizeof buf);
      if (n <= 0) return {};
      buffer_.append(buf, static_cast<std::size_t>(n));
    }
  }

private:
  pid_t pid_ = -1;
  int stdin_ = -1, stdout_ = -1;
  std::string buffer_;
};

} // namespace

TEST_CASE("cli: sdo read and write against python-canopen over slcan") {
  if (!python_ready()) {
    FIELDCODEC_SKIP_TEST("python", "python-canopen peer ("
                                       << peer_dir
                                       << ") or /usr/bin/python3 with python-can and pyserial "
                                          "not available (Debian: python3-can python3-serial)");
  }
  t::pty_pair python_side, cli_side;
  REQUIRE(python_side.ok());
  REQUIRE(cli_side.ok());
  pump joined(python_side, cli_side);
  const std::string eds = "cli/peer_node.eds";
  python_peer peer(python_side.path(), eds);
  REQUIRE(peer.line(20000) == "ready");
  const std::string port = cli_side.path();
  const std::vector<std::string> link = {"--slcan", port, "--slcan-no-answers", "--dict", eds};
  auto cli = [&link](std::vector<std::string> args) {
    args.insert(args.end(), link.begin(), link.end());
    return t::run_cli(args);
  };

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
                 "05040001h: client/server command specifier invalid or unknown)\n");
  // ... and followed when the client allows the switch
  r = cli({"sdo", "read", "5", "1008", "--block", "--switch-threshold", "127"});
  CHECK(r.err == "");
  CHECK(r.out == "1008h:00 Manufacturer Device Name = \"fieldcodec python peer node\"\n");
  r = t::run_cli({"sdo", "read", "5", "1234", "--slcan", port, "--slcan-no-answers"});
  CHECK(r.code == 1);
  CHECK(r.err == "fieldcodec: sdo read: node 5, 1234h:00: SDO abort 06020000h: object not in the "
                 "object dictionary\n");
}
