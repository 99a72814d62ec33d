// The python canopen peer as a child process on one side of two joined pseudo-terminals (the
// other side is the CLI's slcan port): shared by tests/cli/python_peer_test.cpp and
// tests/cli/serve_test.cpp.
#pragma once

#include "host/peers.hpp"

#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

extern char **environ;

namespace fieldcodec::test {

inline const std::string peer_dir = std::string(FIELDCODEC_SHARED_DIR) + "/peers/python-canopen";

inline bool python_ready() {
  if (::access((peer_dir + "/canopen/__init__.py").c_str(), R_OK) != 0) return false;
  const std::string cmd = "PYTHONPATH=" + peer_dir +
                          " /usr/bin/python3 -c 'import can, serial, canopen' >/dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

/// Copies bytes between the masters of two pseudo-terminals: what one slave writes, the other
/// reads, as over a null-modem cable.
class pump {
public:
  pump(pty_pair &a, pty_pair &b) : a_(a), b_(b), thread_([this] { run(); }) {}
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
  pty_pair &a_;
  pty_pair &b_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

/// The python peer as a child process with pipes for its standard input and output.
class python_peer {
public:
  /// `script` (a path under tests/) with the arguments PORT EDS 5 [MODE] (`mode` when given).
  python_peer(const std::string &port, const std::string &eds,
              const std::string &script = "cli/canopen_peer.py", const std::string &mode = {}) {
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
    std::vector<const char *> argv = {"/usr/bin/python3", script.c_str(), port.c_str(), eds.c_str(),
                                      "5"};
    if (!mode.empty()) argv.push_back(mode.c_str());
    argv.push_back(nullptr);
    if (::posix_spawn(&pid_, "/usr/bin/python3", &fa, nullptr, const_cast<char **>(argv.data()),
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

} // namespace fieldcodec::test
