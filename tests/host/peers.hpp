// Test peers behind pseudo-terminals (openpty): a fieldcodec CANopen node (the XENAX dictionary
// in a dictionary_store behind an SDO server) that speaks slcan like a USB adapter with a
// device on its bus, and a scripted PA-CONTROL on an RS232 line. Each runs in its own thread;
// the code under test opens the pty's slave side by its path, like a real serial port.
// Shared by tests/host and tests/cli.
#pragma once

#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/clock.hpp>
#include <fieldcodec/host/slcan.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace fieldcodec::test {

/// A pseudo-terminal pair in raw mode. The slave stays open here too, so that the master never
/// sees a hang-up while the code under test opens and closes the slave by its path.
class pty_pair {
public:
  pty_pair() {
    char name[128]{};
    if (::openpty(&master_, &slave_, name, nullptr, nullptr) != 0) return;
    path_ = name;
    termios t{};
    ::tcgetattr(slave_, &t);
    ::cfmakeraw(&t);
    ::tcsetattr(slave_, TCSANOW, &t);
    ::fcntl(master_, F_SETFL, ::fcntl(master_, F_GETFL) | O_NONBLOCK);
  }
  pty_pair(const pty_pair &) = delete;
  pty_pair &operator=(const pty_pair &) = delete;
  ~pty_pair() {
    if (master_ >= 0) ::close(master_);
    if (slave_ >= 0) ::close(slave_);
  }
  [[nodiscard]] bool ok() const { return master_ >= 0; }
  [[nodiscard]] int master() const { return master_; }
  [[nodiscard]] const std::string &path() const { return path_; }

  /// Bytes that arrived at the master within `ms` (empty when none).
  std::string read_master(int ms) {
    pollfd p{master_, POLLIN, 0};
    if (::poll(&p, 1, ms) <= 0) return {};
    char buf[512];
    const ssize_t n = ::read(master_, buf, sizeof buf);
    return n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
  }
  void write_master(std::string_view s) {
    std::size_t done = 0;
    while (done < s.size()) {
      const ssize_t n = ::write(master_, s.data() + done, s.size() - done);
      if (n > 0) {
        done += static_cast<std::size_t>(n);
      } else {
        pollfd p{master_, POLLOUT, 0};
        ::poll(&p, 1, 10);
      }
    }
  }

private:
  int master_ = -1;
  int slave_ = -1;
  std::string path_;
};

inline constexpr auto xenax_layout =
    canopen::make_layout<dictionaries::xenax_canopen::entries.size()>(
        dictionaries::xenax_canopen::dictionary);

/// A CANopen node with the XENAX CANopen dictionary behind an slcan adapter: answers the
/// adapter commands (CR, or BEL for a bit rate it refuses), feeds frames to its SDO server and
/// answers NMT node guarding; keeps a candump log of every frame on its bus.
class slcan_node {
public:
  struct options {
    std::uint8_t node = 5;
    bool answer_commands = true; ///< false: behave like a silent line
    bool refuse_bitrate = false; ///< answer BEL to "Sn"
    bool server_block = true;
  };

  explicit slcan_node(options o) : o_(o) {
    storage_.resize(store_t::storage_size(dict()));
    staging_.resize(4096);
    store_.emplace(dict(), xenax_layout, storage_, staging_);
    (void)store_->init_defaults(o_.node);
    server_.emplace(o_.node, *store_, buffer_, 1000,
                    canopen::sdo::server_options{o_.server_block, true});
    thread_ = std::thread([this] { run(); });
  }
  slcan_node() : slcan_node(options{}) {}
  ~slcan_node() {
    stop_ = true;
    thread_.join();
  }
  slcan_node(const slcan_node &) = delete;
  slcan_node &operator=(const slcan_node &) = delete;

  [[nodiscard]] const std::string &path() const { return pty_.path(); }
  [[nodiscard]] bool ok() const { return pty_.ok(); }

  /// The application writes a value (no SDO): e.g. the vendor-ID 1018h:01.
  void set(od::address a, std::span<const std::uint8_t> bytes) {
    std::lock_guard<std::mutex> lock(mutex_);
    (void)store_->set(a, bytes);
  }
  /// The current value of `a`.
  std::vector<std::uint8_t> value(od::address a) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto v = store_->value(a);
    if (!v) return {};
    return {v.value().begin(), v.value().end()};
  }
  /// The commands (lines that are not frames) the adapter got, in order.
  std::vector<std::string> commands() {
    std::lock_guard<std::mutex> lock(mutex_);
    return commands_;
  }
  /// The bus traffic as candump compact lines (requests and responses).
  std::vector<std::string> log() {
    std::lock_guard<std::mutex> lock(mutex_);
    return log_;
  }
  /// Send a frame onto the bus (as if another node sent it): the host side receives it.
  void inject(const canopen::can_frame &f) {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_.push_back(f);
  }
  /// Send raw text to the host side.
  void inject_text(std::string s) {
    std::lock_guard<std::mutex> lock(mutex_);
    raw_.push_back(std::move(s));
  }
  [[nodiscard]] std::optional<canopen::nmt::command> last_nmt() {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_nmt_;
  }

private:
  using store_t = canopen::dictionary_store<>;
  static constexpr od::dictionary dict() { return dictionaries::xenax_canopen::dictionary; }

  std::uint32_t now() const { return clock_.now(); }

  void send_frames(const canopen::sdo::step &s) {
    for (const canopen::can_frame &f : s.send) {
      log_.push_back(host::candump::format_frame(host::to_record(f)));
      pty_.write_master(host::slcan::encode(f).value().view());
    }
  }

  void on_line(const std::string &line) {
    auto d = host::slcan::decode(line);
    if (!d || d.value().kind != host::slcan::line_kind::frame) {
      commands_.push_back(line);
      if (!o_.answer_commands) return;
      if (!line.empty() && line[0] == 'S' && o_.refuse_bitrate) {
        pty_.write_master("\a");
      } else if (!line.empty()) {
        pty_.write_master("\r");
      }
      return;
    }
    if (o_.answer_commands) pty_.write_master("z\r"); // transmitted
    auto f = host::to_canopen(d.value().record);
    if (!f) return;
    log_.push_back(host::candump::format_frame(d.value().record));
    if (auto n = canopen::nmt::decode(f.value());
        n && (n.value().node == 0 || n.value().node == o_.node)) {
      last_nmt_ = n.value().cs;
      return;
    }
    send_frames(server_->on_frame(f.value(), now()));
  }

  void run() {
    std::string buffer;
    while (!stop_) {
      std::string in = pty_.read_master(5);
      std::lock_guard<std::mutex> lock(mutex_);
      for (const char c : in) {
        if (c == '\r') {
          on_line(buffer);
          buffer.clear();
        } else {
          buffer += c;
        }
      }
      for (const auto &f : pending_) {
        log_.push_back(host::candump::format_frame(host::to_record(f)));
        pty_.write_master(host::slcan::encode(f).value().view());
      }
      pending_.clear();
      for (const auto &s : raw_) pty_.write_master(s);
      raw_.clear();
      send_frames(server_->poll(now()));
    }
  }

  options o_;
  pty_pair pty_;
  std::vector<std::uint8_t> storage_, staging_;
  std::array<std::uint8_t, 1024> buffer_{};
  std::optional<store_t> store_;
  std::optional<canopen::sdo::server<store_t>> server_;
  std::mutex mutex_;
  std::vector<std::string> commands_, log_, raw_;
  std::vector<canopen::can_frame> pending_;
  std::optional<canopen::nmt::command> last_nmt_;
  std::atomic<bool> stop_{false};
  host::steady_ms clock_;
  std::thread thread_;
};

/// A scripted PA-CONTROL on an RS232 line: decodes each request and answers with what the
/// script returns (the bytes of an acknowledgement, or nothing).
class pacontrol_peer {
public:
  using script = std::function<std::string(const pacontrol::serial::decoded_frame &)>;
  explicit pacontrol_peer(script s) : script_(std::move(s)) {
    thread_ = std::thread([this] { run(); });
  }
  ~pacontrol_peer() {
    stop_ = true;
    thread_.join();
  }
  pacontrol_peer(const pacontrol_peer &) = delete;
  pacontrol_peer &operator=(const pacontrol_peer &) = delete;
  [[nodiscard]] const std::string &path() const { return pty_.path(); }
  [[nodiscard]] bool ok() const { return pty_.ok(); }
  /// Every byte the peer received.
  std::string received() {
    std::lock_guard<std::mutex> lock(mutex_);
    return received_;
  }

  /// The bytes of an acknowledgement (check over body and ETX, as the manual's).
  static std::string ack(const pacontrol::serial::acknowledgement &a) {
    std::array<std::uint8_t, pacontrol::serial::max_frame_size> out{};
    const auto n = pacontrol::serial::encode_acknowledgement(a, out).value();
    return {reinterpret_cast<const char *>(out.data()), n};
  }

private:
  void run() {
    pacontrol::serial::decoder dec({{}, pacontrol::serial::accept::requests});
    while (!stop_) {
      const std::string in = pty_.read_master(5);
      for (const char c : in) {
        {
          std::lock_guard<std::mutex> lock(mutex_);
          received_ += c;
        }
        auto k = dec.push(static_cast<std::uint8_t>(c));
        if (!k || k.value() == pacontrol::serial::frame_kind::none) continue;
        pacontrol::serial::decoded_frame f{k.value(), dec.request(), dec.acknowledgement()};
        const std::string answer = script_(f);
        if (!answer.empty()) pty_.write_master(answer);
      }
    }
  }

  script script_;
  pty_pair pty_;
  std::mutex mutex_;
  std::string received_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

} // namespace fieldcodec::test
