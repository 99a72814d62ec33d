// The host side of the interoperability test `interop_remote` (tests/interop/interop_remote.py,
// docs/host.md): host::remote_node and host::remote_drive against python canopen's LocalNode
// built from dictionaries/xenax_canopen.eds, python playing the drive.
//
// usage: interop_remote xenax NODE
//
// Standard input: candump-style frames (ID#DATA) from the bus, and commands; standard output:
// frames to the bus, "= ..." answer lines. The bus is host::can_bus over these two streams, so
// the code under test is the library's, unchanged:
//   "!move TARGET"  examples::move_axis (docs/host.md): the PDOs read from the LocalNode by SDO,
//                   enable, profile position, move; "= ok" or "= FAILED <why>";
//   "!events MS"    a remote_node watching the heartbeat (MS), its events for up to 3 s, one
//                   "= event <kind> <detail>" line each, until "heartbeat lost"; then "= ok".
//   "!domain SIZE"  host::sdo_session::write_parts of SIZE bytes ((i * 7 + 3) & FFh) to 2FF0h
//                   (a DOMAIN python adds), then read_parts back, parts of 64 bytes: "= ok
//                   <bytes read> <parts>" or "= FAILED <why>".
//   "!quit"         ends.
#include "../../../examples/move_axis.hpp"

#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/host/bus.hpp>
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/remote_node.hpp>
#include <fieldcodec/host/sdo.hpp>

#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <string>

namespace {

namespace co = fieldcodec::canopen;
namespace host = fieldcodec::host;
using fieldcodec::errc;

/// The bus's and the answers' stream: the original standard output. Standard output itself goes
/// to standard error, where the example's own line about a failure (std::puts) is a log line.
std::FILE *wire = stdout;

/// A CAN bus on standard input and output, one candump-style line per frame; command lines
/// ("!...") are kept for the main loop.
class stdio_bus final : public host::can_bus {
public:
  stdio_bus() { name_ = "stdio"; }
  fieldcodec::status send(const co::can_frame &f) override {
    const std::string line = host::candump::format_frame(host::to_record(f)) + "\n";
    std::fputs(line.c_str(), wire);
    std::fflush(wire);
    return {};
  }
  fieldcodec::result<host::frame_record> receive_record(std::chrono::milliseconds t) override {
    const auto end = std::chrono::steady_clock::now() + t;
    for (;;) {
      if (!frames_.empty()) {
        auto r = frames_.front();
        frames_.pop_front();
        return r;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          end - std::chrono::steady_clock::now());
      if (closed) return fail(errc::bad_state, 0, "standard input closed");
      if (left.count() <= 0) return fail(errc::timeout, 0, "no frame in time");
      read_input(static_cast<int>(left.count()));
    }
  }
  /// Read what standard input has within `wait_ms`.
  void read_input(int wait_ms) {
    pollfd p{STDIN_FILENO, POLLIN, 0};
    if (::poll(&p, 1, wait_ms) <= 0) return;
    char buf[4096];
    const auto n = ::read(STDIN_FILENO, buf, sizeof buf);
    if (n <= 0) {
      closed = true;
      return;
    }
    pending_.append(buf, static_cast<std::size_t>(n));
    std::size_t eol = 0;
    while ((eol = pending_.find('\n')) != std::string::npos) {
      const std::string line = pending_.substr(0, eol);
      pending_.erase(0, eol + 1U);
      if (!line.empty() && line[0] == '!') {
        commands.push_back(line);
      } else if (!line.empty()) {
        auto r = host::candump::parse_frame(line);
        if (r) frames_.push_back(r.value());
      }
    }
  }
  std::deque<std::string> commands;
  bool closed = false;

private:
  std::deque<host::frame_record> frames_;
  std::string pending_;
};

void answer(const std::string &s) {
  std::fputs(("= " + s + "\n").c_str(), wire);
  std::fflush(wire);
}

std::string hex4(unsigned v) {
  char b[8];
  std::snprintf(b, sizeof b, "%04X", v);
  return b;
}

void events(stdio_bus &bus, std::uint8_t node, std::uint16_t watch_ms) {
  host::remote_node n(bus, node, fieldcodec::dictionaries::xenax_canopen::dictionary);
  n.watch_heartbeat(watch_ms);
  answer("listening"); // python sends its frames after this line
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (std::chrono::steady_clock::now() < end) {
    auto e = n.wait_event(std::chrono::milliseconds(100));
    if (!e) continue;
    std::string line = "event " + std::string(host::to_string(e->what));
    switch (e->what) {
    case host::node_event::kind::emcy:
      line += " " + hex4(e->emcy.error_code) + " " + hex4(e->emcy.error_register);
      break;
    case host::node_event::kind::bad_frame:
      line += " " + std::string(fieldcodec::to_string(e->code));
      break;
    default: line += " " + std::string(co::nmt::to_string(e->state)); break;
    }
    answer(line);
    if (e->what == host::node_event::kind::heartbeat_lost) return answer("ok");
  }
  answer("FAILED events: no heartbeat loss within 3 s");
}

void domain(stdio_bus &bus, std::uint8_t node, std::uint32_t size) {
  host::sdo_session s(bus, node, {.part_size = 64});
  const fieldcodec::od::address at{0x2FF0, 0};
  std::uint32_t next = 0;
  auto w = s.write_parts(at, size, [&](std::span<std::uint8_t> out) {
    std::size_t n = 0;
    for (; n < out.size() && next < size; ++n, ++next) {
      out[n] = static_cast<std::uint8_t>((next * 7U + 3U) & 0xFFU);
    }
    return n;
  });
  if (!w) return answer("FAILED write: " + w.error().what);
  std::uint32_t i = 0;
  std::size_t parts = 0;
  bool same = true;
  auto r = s.read_parts(at, [&](std::span<const std::uint8_t> p) {
    ++parts;
    for (const std::uint8_t b : p) same = same && b == ((i++ * 7U + 3U) & 0xFFU);
    return true;
  });
  if (!r) return answer("FAILED read: " + r.error().what);
  if (!same || i != size) return answer("FAILED read: not the bytes written");
  answer("ok " + std::to_string(r.value()) + " " + std::to_string(parts));
}

} // namespace

int main(int argc, char **argv) {
  if (argc != 3) return std::fputs("usage: interop_remote xenax NODE\n", stderr), 2;
  const auto node = static_cast<std::uint8_t>(std::atoi(argv[2]));
  const int out = ::dup(STDOUT_FILENO);
  if (out < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) return 1;
  wire = ::fdopen(out, "w");
  if (wire == nullptr) return 1;
  stdio_bus bus;
  for (;;) {
    while (bus.commands.empty() && !bus.closed) bus.read_input(100);
    if (bus.closed) return 0;
    const std::string c = bus.commands.front();
    bus.commands.pop_front();
    if (c == "!quit") return 0;
    if (c.rfind("!move ", 0) == 0) {
      const int r = fieldcodec::examples::move_axis(bus, std::atoi(c.c_str() + 6));
      answer(r == 0 ? "ok" : "FAILED move (its line is above)");
    } else if (c.rfind("!domain ", 0) == 0) {
      domain(bus, node, static_cast<std::uint32_t>(std::atol(c.c_str() + 8)));
    } else if (c.rfind("!events ", 0) == 0) {
      events(bus, node, static_cast<std::uint16_t>(std::atoi(c.c_str() + 8)));
    } else {
      answer("FAILED unknown command " + c);
    }
  }
}
