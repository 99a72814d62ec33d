// The master side of the interoperability test `interop_master` (tests/interop/,
// docs/canopen.md "Interoperability", docs/master.md): fieldcodec's configurator and CiA 402
// drive helper against python canopen's LocalNode built from dictionaries/xenax_canopen.eds
// (tests/interop/interop_master.py plays the drive).
//
// usage: interop_master xenax NODE
//
// Standard input: candump-style frames (ID#DATA) from the bus, and commands ("!run", "!boot302
// ...", "!quit"). Standard output: frames to the bus, and after each command one line "= ok" or
// "= FAILED <step>: <why>". Progress lines ("ok  <step>: ...") go to standard error.
//
// What runs, after "!run":
//   1. configure   a configurator (verify on) writes 6081h = 50000, 6083h = 200000 and the
//                  event timer of TPDO 1 (1800h sub 5) = 100 ms by SDO, reading each one back;
//   2. statusword  the first statusword is read by SDO (6041h);
//   3. mode        drive.switch_mode(profile position): 6060h = 1 by SDO, 6061h read back;
//   4. enable      drive.enable(): controlwords in RPDO 1 (200h + node, the XENAX default
//                  mapping 6040h), statuswords from TPDO 1 (180h + node, 6041h);
//   5. move        drive.move_to(12345) with target_over_sdo: 607Ah by SDO, then the set-point
//                  handshake in the words, until target reached.
// The cyclic task runs every 10 ms; every step has a deadline (at most ~17 s in all when every
// step runs into its own).
//
// "!boot302 ASSIGNMENT CONSUMER DEVTYPE VENDOR PRODUCT REVISION SERIAL SOFTWARE DATE TIME
// RESTORE DCF" (hex numbers; DCF: the concise DCF in hex, "-" for none) boots the node with
// master::boot from these CiA 302 objects (1F81h, the 1016h consumer time, 1F84h..1F88h, 1F55h,
// 1F26h, 1F27h, 1F8Ah, 1F22h) and answers "= ok <status>" (booted, or L: initially
// operational) or "= FAILED <status>: <failure> ..." with the CiA 302-2 letter.
#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/ds402/statusword.hpp>
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/clock.hpp>
#include <fieldcodec/host/frame_record.hpp>
#include <fieldcodec/master/boot.hpp>
#include <fieldcodec/master/config.hpp>
#include <fieldcodec/master/configurator.hpp>
#include <fieldcodec/master/drive.hpp>
#include <fieldcodec/xenax/drive_profile.hpp>
#include <fieldcodec/xenax/modes.hpp>

#include <poll.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace ds402 = fieldcodec::ds402;
namespace master = fieldcodec::master;

constexpr std::uint32_t cycle_ms = 10;
constexpr std::int32_t move_target = 12345;

// The configuration list (what fieldcodec-gen --config-list writes from a DCF, written out):
// bytes on the bus, little-endian.
constexpr std::uint8_t v_speed[] = {0x50, 0xC3, 0x00, 0x00};        // 6081h = 50000
constexpr std::uint8_t v_acceleration[] = {0x40, 0x0D, 0x03, 0x00}; // 6083h = 200000
constexpr std::uint8_t v_event_timer[] = {0x64, 0x00};              // 1800h sub 5 = 100 ms
constexpr master::config_item items[] = {
    {{0x6081, 0}, v_speed, 0, "Speed"},
    {{0x6083, 0}, v_acceleration, 0, "Acceleration"},
    {{0x1800, 5}, v_event_timer, 0, "Transmit PDO Comm Param 1: Event Timer"},
};

std::uint32_t now_ms() {
  static const fieldcodec::host::steady_ms clock;
  return clock.now();
}

void put_line(const std::string &s) {
  std::fputs(s.c_str(), stdout);
  std::fputc('\n', stdout);
  std::fflush(stdout);
}

void progress(const std::string &s) {
  std::fputs(("ok  master " + s + "\n").c_str(), stderr);
  std::fflush(stderr);
}

void transmit(const co::can_frame &f) {
  put_line(fieldcodec::host::candump::format_frame(fieldcodec::host::to_record(f)));
}

template <class Frames>
void transmit_all(const Frames &fs) {
  for (const co::can_frame f : fs) transmit(f);
}

/// Reads standard input for at most `wait_ms`: frames go to `on_frame`; a command line ("!...",
/// not "!quit") goes to `command` when that is empty (the peer sends one command at a time and
/// waits for its answer). Returns false when standard input is closed or unreadable, or on
/// "!quit".
bool read_input(int wait_ms, const std::function<void(const co::can_frame &)> &on_frame,
                std::string &command, std::string &pending) {
  pollfd p{STDIN_FILENO, POLLIN, 0};
  const int ready = ::poll(&p, 1, wait_ms);
  if (ready < 0) return false;
  if (ready == 0) return true;
  char buf[4096];
  const auto n = ::read(STDIN_FILENO, buf, sizeof buf);
  if (n <= 0) return false;
  pending.append(buf, static_cast<std::size_t>(n));
  std::size_t eol = 0;
  while ((eol = pending.find('\n')) != std::string::npos) {
    const std::string line = pending.substr(0, eol);
    pending.erase(0, eol + 1U);
    if (line == "!quit") {
      return false;
    } else if (!line.empty() && line[0] == '!') {
      if (command.empty()) command = line;
    } else if (!line.empty()) {
      auto r = fieldcodec::host::candump::parse_frame(line);
      if (!r) continue;
      auto f = fieldcodec::host::to_canopen(r.value());
      if (f) on_frame(f.value());
    }
  }
  return true;
}

class session {
public:
  session(std::uint8_t node, std::string &pending)
      : node_(node), client_(node, 1000), pending_(pending) {}

  /// The whole run; the failing step and why, or nothing.
  std::optional<std::string> run() {
    if (auto e = configure()) return e;
    if (auto e = read_statusword()) return e;
    master::drive axis({.profile = fieldcodec::xenax::profile,
                        .enable_timeout_ms = 2000,
                        .mode_timeout_ms = 2000,
                        .set_point_timeout_ms = 2000,
                        .move_timeout_ms = 3000,
                        .target_over_sdo = true});
    axis_ = &axis;
    if (!axis.switch_mode(fieldcodec::xenax::mode::profile_position, now_ms())) {
      return "mode: switch_mode refused";
    }
    if (auto e = cycle_until_idle("mode")) return e;
    progress("mode: 6060h = 1 written, 6061h shows profile position");
    if (!axis.enable(now_ms())) return "enable: enable refused";
    if (auto e = cycle_until_idle("enable")) return e;
    if (axis.state() != master::drive_state::enabled ||
        axis.drive_status() != ds402::state::operation_enabled) {
      return "enable: the drive is " + std::string(ds402::to_string(axis.drive_status())) +
             ", the helper " + std::string(master::to_string(axis.state()));
    }
    progress("enable: operation enabled (statusword " + hex16(statusword_) + ")");
    if (!axis.move_to(move_target, now_ms())) return "move: move_to refused";
    const auto start = now_ms();
    if (auto e = cycle_until_idle("move")) return e;
    if (axis.state() != master::drive_state::enabled ||
        (statusword_ & 0x0400U) == 0U) { // target reached (bit 10)
      return "move: the helper is " + std::string(master::to_string(axis.state())) +
             ", statusword " + hex16(statusword_);
    }
    progress("move: 607Ah = " + std::to_string(move_target) +
             ", set-point acknowledged, target reached after " + std::to_string(now_ms() - start) +
             " ms (statusword " + hex16(statusword_) + ")");
    return std::nullopt;
  }

  /// "!boot302 ...": master::boot from CiA 302 objects; the failure, or nothing.
  std::optional<std::string> boot302(const std::string &command, std::string &status) {
    std::istringstream in(command.substr(std::string("!boot302").size()));
    std::vector<std::uint32_t> v;
    std::string word;
    for (int i = 0; i < 11 && in >> word; ++i)
      v.push_back(static_cast<std::uint32_t>(std::stoul(word, nullptr, 16)));
    std::string hex;
    if (v.size() != 11U || !(in >> hex)) return "boot302: expected 11 numbers and the concise DCF";
    std::vector<std::uint8_t> dcf;
    for (std::size_t i = 0; hex != "-" && i + 1U < hex.size(); i += 2U) {
      dcf.push_back(static_cast<std::uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
    }
    master::slave_objects o;
    o.assignment = v[0];
    o.consumer_time_ms = static_cast<std::uint16_t>(v[1]);
    o.expected = {v[2], v[3], v[4], v[5], v[6]};
    o.software_version = v[7];
    o.configuration_date = v[8];
    o.configuration_time = v[9];
    o.restore_sub = static_cast<std::uint8_t>(v[10]);
    o.concise_dcf = dcf;
    master::boot b(node_, client_,
                   {.boot_timeout_ms = 2000,
                    .read_retries = 2,
                    .config = {.retries = 1, .timeout_ms = 1000, .verify = true}});
    auto s = b.start(o, now_ms());
    if (!s) return "boot302: start refused: " + std::string(fieldcodec::to_string(s.error()));
    transmit_all(s.value().send);
    if (auto e = run_machine(b, "boot302", 10000)) return e;
    status = std::string(master::to_string(b.status()));
    if (const auto e = b.error()) {
      std::string why = status + ": " + std::string(master::to_string(e->failure)) + " (" +
                        std::string(fieldcodec::to_string(e->code));
      if (e->failure == master::boot_failure::identity_mismatch) {
        char x[64];
        std::snprintf(x, sizeof x, ", %s expected %08X actual %08X",
                      std::string(master::to_string(e->field)).c_str(),
                      static_cast<unsigned>(e->expected), static_cast<unsigned>(e->actual));
        why += x;
      }
      if (e->config) why += ", entry " + std::to_string(e->config->item);
      return why + ")";
    }
    progress("boot302: " + status + " (" + std::to_string(dcf.size()) + " bytes of concise DCF)");
    return std::nullopt;
  }

  bool stopped() const { return stopped_; }

private:
  static std::string hex16(std::uint16_t v) {
    char b[8];
    std::snprintf(b, sizeof b, "%04Xh", static_cast<unsigned>(v));
    return b;
  }

  /// Feeds `m` (a machine with on_frame, poll and busy) the bus and its deadlines until it ends;
  /// the failure when it does not end within `limit_ms` or the peer goes.
  template <class Machine>
  std::optional<std::string> run_machine(Machine &m, const std::string &step,
                                         std::uint32_t limit_ms) {
    const auto deadline = now_ms() + limit_ms;
    while (m.busy()) {
      if (now_ms() - deadline < 0x80000000U) {
        return step + ": no end within " + std::to_string(limit_ms) + " ms";
      }
      if (!wait(5, [&](const co::can_frame &f) { transmit_all(m.on_frame(f, now_ms()).send); })) {
        return step + ": the peer has gone";
      }
      transmit_all(m.poll(now_ms()).send);
    }
    return std::nullopt;
  }

  /// Waits for input up to `wait_ms`; false when the peer has gone.
  bool wait(int wait_ms, const std::function<void(const co::can_frame &)> &on_frame) {
    std::string ignored; // the peer sends no command while one runs
    if (!read_input(wait_ms, on_frame, ignored, pending_)) {
      stopped_ = true;
      return false;
    }
    return true;
  }

  std::optional<std::string> configure() {
    master::configurator cfg(client_, {.retries = 1, .timeout_ms = 1000, .verify = true});
    const master::configuration c{items, {}, node_};
    auto s = cfg.start(c, now_ms());
    if (!s) return "configure: start refused: " + std::string(fieldcodec::to_string(s.error()));
    transmit_all(s.value().send);
    if (auto e = run_machine(cfg, "configure", 3000)) return e;
    if (cfg.state() != master::config_state::done) {
      const auto e = cfg.error().value_or(master::config_error{});
      char abort[12];
      std::snprintf(abort, sizeof abort, "%08X", static_cast<unsigned>(e.abort));
      return "configure: item " + std::to_string(e.item) + " (" + std::string(e.name) + ") " +
             std::string(fieldcodec::to_string(e.code)) + ", abort " + abort;
    }
    progress("configure: 3 items written and read back (6081h, 6083h, 1800h sub 5)");
    return std::nullopt;
  }

  /// One SDO upload of 6041h: the statusword before the first cycle.
  std::optional<std::string> read_statusword() {
    std::array<std::uint8_t, 4> buf{};
    auto s = client_.upload({0x6041, 0}, buf, now_ms());
    if (!s) return "statusword: upload refused";
    transmit_all(s.value().send);
    if (auto e = run_machine(client_, "statusword", 2000)) return e;
    if (client_.state() != sdo::transfer_state::done || client_.received().size() != 2U) {
      return "statusword: the upload of 6041h failed";
    }
    const auto r = client_.received();
    statusword_ = static_cast<std::uint16_t>(r[0] | (r[1] << 8U));
    progress("statusword: 6041h = " + hex16(statusword_) + " by SDO");
    return std::nullopt;
  }

  void on_cyclic_frame(const co::can_frame &f) {
    if (f.id == co::cob_id::tpdo(1, node_).value() && f.dlc >= 2U) {
      statusword_ = static_cast<std::uint16_t>(f.data[0] | (f.data[1] << 8U));
      return;
    }
    const auto now = now_ms();
    transmit_all(client_.on_frame(f, now).send);
    finish_sdo(now);
  }

  void finish_sdo(std::uint32_t now) {
    if (!axis_->sdo_pending()) return;
    if (client_.state() == sdo::transfer_state::done) {
      axis_->sdo_done(client_.received(), now);
    } else if (client_.state() == sdo::transfer_state::failed) {
      axis_->sdo_failed(*client_.error(), now);
    }
  }

  /// The cyclic task until the helper's command has ended (every command has its timeout).
  std::optional<std::string> cycle_until_idle(const std::string &step) {
    const auto start = now_ms();
    auto next = start;
    do {
      const auto now = now_ms();
      if (now - start > 4000U) return step + ": the helper still busy after 4 s";
      if (now - next < 0x80000000U) { // the cycle is due
        next += cycle_ms;
        const auto out = axis_->cycle(statusword_, now);
        if (out.sdo) {
          auto s = out.sdo->what == master::sdo_request::kind::download
                       ? client_.download(out.sdo->address, out.sdo->bytes(), now)
                       : client_.upload(out.sdo->address, sdo_buffer_, now);
          if (!s) return step + ": the SDO client is busy";
          transmit_all(s.value().send);
        }
        transmit(co::make_frame(co::cob_id::rpdo(1, node_).value(),
                                {static_cast<std::uint8_t>(out.controlword),
                                 static_cast<std::uint8_t>(out.controlword >> 8U)})
                     .value());
      }
      const auto left = next - now_ms();
      const int wait_ms = left < 0x80000000U ? static_cast<int>(left) : 0;
      if (!wait(wait_ms, [this](const co::can_frame &f) { on_cyclic_frame(f); })) {
        return step + ": the peer has gone";
      }
      transmit_all(client_.poll(now_ms()).send);
      finish_sdo(now_ms());
    } while (axis_->busy());
    if (const auto e = axis_->error()) {
      return step + ": " + std::string(master::to_string(e->failure)) + " (helper " +
             std::string(master::to_string(axis_->state())) + ", statusword " +
             hex16(e->statusword) + ")";
    }
    return std::nullopt;
  }

  std::uint8_t node_;
  sdo::client client_;
  std::string &pending_; ///< what main() read after "!run"
  master::drive *axis_ = nullptr;
  std::uint16_t statusword_ = 0;
  std::array<std::uint8_t, 4> sdo_buffer_{};
  bool stopped_ = false;
};

} // namespace

int main(int argc, char **argv) {
  if (argc != 3 || std::string(argv[1]) != "xenax") {
    std::fprintf(stderr, "usage: interop_master xenax NODE\n");
    return 2;
  }
  const auto node = static_cast<std::uint8_t>(std::atoi(argv[2]));
  now_ms();
  // One command after the other until "!quit" (frames between commands are not ours); the
  // bridge stays on the bus meanwhile (the peer may still read the drive's data).
  std::string pending;
  session s(node, pending);
  bool failed = false;
  while (!s.stopped()) {
    std::string command;
    if (!read_input(
            100, [](const co::can_frame &) {}, command, pending))
      break;
    if (command.empty()) continue;
    std::optional<std::string> failure;
    std::string status;
    if (command == "!run") {
      failure = s.run();
    } else if (command.rfind("!boot302 ", 0) == 0) {
      failure = s.boot302(command, status);
    } else {
      failure = "unknown command '" + command + "'";
    }
    failed = failed || failure.has_value();
    put_line(failure ? "= FAILED " + *failure : "= ok " + status);
  }
  return failed ? 1 : 0;
}
