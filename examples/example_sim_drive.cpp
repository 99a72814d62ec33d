// A simulated XENAX CANopen drive (examples/sim_drive.hpp: a fieldcodec node + CiA 402 + an
// axis model), driven two ways:
//
//   example_sim_drive             a master made of fieldcodec pieces (NMT, SDO client,
//                                 ds402::power_sequencer, PDOs checked against the XENAX
//                                 dictionary) runs it over an in-memory bus: boot-up, SDO
//                                 configuration, enable, one profile position move; the trace
//                                 is printed and the exit status says whether the axis arrived.
//   example_sim_drive --stdio [N] the drive as node N (default 1) on standard input/output, one
//                                 frame per line in the cansend/candump compact form
//                                 `ID#DATA` (hex; `ID#R` or `ID#Rn` for a remote frame), so
//                                 that another program — python canopen over python-can's
//                                 virtual bus (examples/sim_drive_python.py), a socat bridge to a
//                                 real CAN interface, a test harness — can drive it. Lines it
//                                 cannot read are reported on standard error and skipped.
#include "sim_drive.hpp"

#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/host/clock.hpp>

#include <cstdio>
#include <cstring>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#if defined(__unix__)
#include <poll.h>
#include <unistd.h>
#endif

namespace co = fieldcodec::canopen;
namespace pdo = fieldcodec::canopen::pdo;
namespace sdo = fieldcodec::canopen::sdo;
namespace ds402 = fieldcodec::ds402;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;

namespace {

// ----- the line format -------------------------------------------------------------------

std::string format_frame(const co::can_frame &f) {
  char buf[32];
  int n = std::snprintf(buf, sizeof buf, "%03X#", f.id);
  if (f.rtr) {
    n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "R%u", f.dlc);
  } else {
    for (std::size_t i = 0; i < f.dlc; ++i) {
      n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "%02X", f.data[i]);
    }
  }
  return {buf, static_cast<std::size_t>(n)};
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::optional<co::can_frame> parse_frame(std::string_view line) {
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
  const auto hash = line.find('#');
  if (hash == 0 || hash == std::string_view::npos || hash > 3) return std::nullopt;
  unsigned id = 0;
  for (char c : line.substr(0, hash)) {
    const int d = hex_digit(c);
    if (d < 0) return std::nullopt;
    id = id * 16U + static_cast<unsigned>(d);
  }
  if (id > co::max_can_id) return std::nullopt;
  auto rest = line.substr(hash + 1);
  if (!rest.empty() && (rest[0] == 'R' || rest[0] == 'r')) {
    unsigned dlc = 0;
    if (rest.size() == 2 && rest[1] >= '0' && rest[1] <= '8')
      dlc = static_cast<unsigned>(rest[1] - '0');
    else if (rest.size() != 1)
      return std::nullopt;
    auto f = co::make_remote_frame(static_cast<std::uint16_t>(id), static_cast<std::uint8_t>(dlc));
    if (!f) return std::nullopt;
    return f.value();
  }
  if (rest.size() % 2 != 0 || rest.size() > 16) return std::nullopt;
  std::vector<std::uint8_t> bytes;
  for (std::size_t i = 0; i < rest.size(); i += 2) {
    const int hi = hex_digit(rest[i]);
    const int lo = hex_digit(rest[i + 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    bytes.push_back(static_cast<std::uint8_t>(hi * 16 + lo));
  }
  auto f = co::make_frame(static_cast<std::uint16_t>(id), bytes);
  if (!f) return std::nullopt;
  return f.value();
}

// ----- --stdio: the drive on standard input and output -------------------------------------

#if defined(__unix__)
int run_stdio(std::uint8_t node_id) {
  sim::drive drive(node_id);
  const fieldcodec::host::steady_ms clock;
  auto now = [&clock] { return clock.now(); };
  auto emit = [](const sim::drive::step &s) {
    for (const co::can_frame &f : s.send) std::printf("%s\n", format_frame(f).c_str());
    std::fflush(stdout);
    return s.deadline;
  };
  std::optional<std::uint32_t> deadline = emit(drive.start(now()));
  std::string pending;
  for (;;) {
    int timeout = -1;
    if (deadline) {
      const auto t = now();
      timeout = co::reached(*deadline, t) ? 0 : static_cast<int>(*deadline - t);
    }
    pollfd p{STDIN_FILENO, POLLIN, 0};
    const int r = ::poll(&p, 1, timeout);
    if (r < 0) return 1;
    if (r > 0) {
      char buf[4096];
      const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
      if (n <= 0) return 0; // end of input: the bus is gone
      pending.append(buf, static_cast<std::size_t>(n));
      std::size_t eol;
      while ((eol = pending.find('\n')) != std::string::npos) {
        const std::string line = pending.substr(0, eol);
        pending.erase(0, eol + 1);
        if (line.empty()) continue;
        auto f = parse_frame(line);
        if (!f) {
          std::fprintf(stderr, "example_sim_drive: not a frame: '%s'\n", line.c_str());
          continue;
        }
        deadline = emit(drive.on_frame(*f, now()));
      }
    }
    deadline = emit(drive.poll(now()));
  }
}
#endif

// ----- the demo: a master made of fieldcodec pieces ------------------------------------------

constexpr pdo::mapping_entry rpdo2_entries[] = {{0x6040, 0, 16}, {0x607A, 0, 32}};
constexpr auto rpdo2 =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::rpdo, rpdo2_entries);
constexpr pdo::mapping_entry tpdo2_entries[] = {{0x6041, 0, 16}, {0x6064, 0, 32}};
constexpr auto tpdo2 =
    pdo::make_static_mapping(xcan::dictionary, pdo::direction::tpdo, tpdo2_entries);

class demo {
public:
  static constexpr std::uint8_t node_id = 1;

  int run() {
    deliver_drive(drive_.start(now_).send); // power-on: boot-up
    step(1);
    print("NMT reset node");
    booted_ = false;
    to_drive(co::nmt::encode(co::nmt::command::reset_node, node_id).value());
    wait([&] { return booted_; }, 100, "boot-up");

    // configuration by SDO: profile position, speed, acceleration (XENAX 5.2.1)
    sdo_write({0x6060, 0}, {1});
    sdo_write({0x6081, 0}, le32(50'000));
    sdo_write({0x6083, 0}, le32(400'000));
    print("NMT start");
    to_drive(co::nmt::encode(co::nmt::command::start, node_id).value());
    wait([&] { return drive_.device().state() == co::nmt::state::operational; }, 10, "start");

    // enable the drive through RPDO 2 (controlword + target), watch TPDO 2
    ds402::power_sequencer walker;
    std::uint16_t cw = 0;
    for (int cycle = 0; cycle < 50 && state() != ds402::state::operation_enabled; ++cycle) {
      cw = walker.next(statusword_, ds402::state::operation_enabled).value_or(0);
      send_rpdo2(cw, 0);
      step(2);
    }
    if (state() != ds402::state::operation_enabled) return fail("not enabled");
    print("operation enabled");

    // one move: target 25000 with a new set-point
    const std::int32_t target = 25'000;
    send_rpdo2(static_cast<std::uint16_t>(cw | ds402::cw::pp_new_set_point), target);
    wait([&] { return (statusword_ & ds402::sw::pp_set_point_acknowledge) != 0U; }, 20,
         "set-point acknowledge");
    send_rpdo2(cw, target);
    const std::uint32_t start = now_;
    wait([&] { return (statusword_ & ds402::sw::target_reached) != 0U && position_ == target; },
         2000, "target reached");
    std::printf("[%5u ms] target reached: position %d after %u ms, %zu TPDO 2 frames\n", now_,
                position_, now_ - start, tpdo_frames_);
    return failed_ ? 1 : 0;
  }

private:
  static std::vector<std::uint8_t> le32(std::uint32_t v) {
    return {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8U),
            static_cast<std::uint8_t>(v >> 16U), static_cast<std::uint8_t>(v >> 24U)};
  }
  [[nodiscard]] ds402::state state() const {
    return ds402::decode_state(statusword_).value_or(ds402::state::not_ready_to_switch_on);
  }
  void print(const char *what) const { std::printf("[%5u ms] %s\n", now_, what); }
  int fail(const char *what) {
    std::printf("FAILED: %s\n", what);
    failed_ = true;
    return 1;
  }

  template <class Frames>
  void deliver_drive(const Frames &frames) {
    for (const co::can_frame &f : frames) from_drive_.push_back(f);
  }
  void to_drive(const co::can_frame &f) { deliver_drive(drive_.on_frame(f, now_).send); }

  /// Frames from the drive reach the master.
  void take(const co::can_frame &f) {
    if (f.id == 0x700 + node_id && f.dlc == 1 && f.data[0] == 0) booted_ = true;
    if (f.id == 0x280 + node_id && f.dlc == tpdo2.bytes()) {
      ++tpdo_frames_;
      const auto sw = tpdo2.get(f.payload(), 0).value_or(0);
      if (sw != statusword_) {
        std::printf("[%5u ms] statusword %04X: %s\n", now_, static_cast<unsigned>(sw),
                    std::string(ds402::to_string(ds402::decode_state(static_cast<std::uint16_t>(sw))
                                                     .value_or(ds402::state::fault)))
                        .c_str());
      }
      statusword_ = static_cast<std::uint16_t>(sw);
      position_ = static_cast<std::int32_t>(tpdo2.get_signed(f.payload(), 1).value_or(0));
    }
    if (client_.busy()) {
      for (const co::can_frame &g : client_.on_frame(f, now_).send) to_drive(g);
    }
  }
  void step(std::uint32_t ms) {
    for (std::uint32_t i = 0; i < ms; ++i) {
      ++now_;
      deliver_drive(drive_.poll(now_).send);
      for (const co::can_frame &g : client_.poll(now_).send) to_drive(g);
      while (!from_drive_.empty()) {
        const co::can_frame f = from_drive_.front();
        from_drive_.pop_front();
        take(f);
      }
    }
  }
  template <class Done>
  void wait(Done done, std::uint32_t limit_ms, const char *what) {
    for (std::uint32_t t = 0; t < limit_ms && !done(); ++t) step(1);
    if (!done()) (void)fail(what);
  }
  void sdo_write(fieldcodec::od::address a, std::vector<std::uint8_t> bytes) {
    data_ = std::move(bytes);
    auto s = client_.download(a, data_, now_);
    if (!s) {
      (void)fail("SDO client busy");
      return;
    }
    for (const co::can_frame &f : s.value().send) to_drive(f);
    wait([&] { return !client_.busy(); }, 2000, "SDO download");
    std::printf("[%5u ms] SDO %04X:%u <- %zu bytes: %s\n", now_, a.index, a.sub, data_.size(),
                client_.state() == sdo::transfer_state::done ? "done" : "FAILED");
    if (client_.state() != sdo::transfer_state::done) (void)fail("SDO download");
  }
  void send_rpdo2(std::uint16_t cw, std::int32_t target) {
    std::array<std::uint8_t, 8> bytes{};
    (void)rpdo2.set(bytes, 0, cw);
    (void)rpdo2.set(bytes, 1, static_cast<std::uint64_t>(static_cast<std::int64_t>(target)));
    to_drive(
        co::make_frame(0x300 + node_id, std::span<const std::uint8_t>(bytes).first(rpdo2.bytes()))
            .value());
  }

  sim::drive drive_{node_id};
  sdo::client client_{node_id, 500};
  std::deque<co::can_frame> from_drive_;
  std::vector<std::uint8_t> data_;
  std::uint32_t now_ = 0;
  std::uint16_t statusword_ = 0;
  std::int32_t position_ = 0;
  std::size_t tpdo_frames_ = 0;
  bool booted_ = false;
  bool failed_ = false;
};

} // namespace

int main(int argc, char **argv) {
  if (argc >= 2 && std::strcmp(argv[1], "--stdio") == 0) {
#if defined(__unix__)
    const long n = argc >= 3 ? std::strtol(argv[2], nullptr, 0) : 1;
    if (n < 1 || n > 127) {
      std::fprintf(stderr, "example_sim_drive: node-ID 1..127\n");
      return 2;
    }
    return run_stdio(static_cast<std::uint8_t>(n));
#else
    std::fprintf(stderr, "example_sim_drive: --stdio needs a POSIX system\n");
    return 2;
#endif
  }
  return demo{}.run();
}
