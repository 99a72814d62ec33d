// `fieldcodec lss` (docs/cli.md) against the library's own node as an LSS slave
// (node::device with capacity::lss over the XENAX dictionary) behind an slcan adapter on a
// pseudo-terminal: scan, set-node, set-bitrate, activate, store, inquire, waiting, and bad
// input. (python canopen has no LSS slave; interop_lss tests the node against its LssMaster.)
#include "cli_support.hpp"
#include "host/peers.hpp"

#include <fieldcodec/canopen/lss.hpp>
#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/host/slcan.hpp>

#include <doctest/doctest.h>

#include <atomic>
#include <mutex>
#include <string>
#include <thread>

namespace t = fieldcodec::test;
namespace co = fieldcodec::canopen;
namespace node = fieldcodec::canopen::node;
namespace host = fieldcodec::host;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;

namespace {

/// The node behind an slcan adapter (answers the adapter's commands with CR).
class lss_node {
public:
  using store_t = co::dictionary_store<>;
  using device_t = node::device<store_t, node::capacity_for(xcan::dictionary, {.lss = true})>;

  explicit lss_node(std::uint8_t id) {
    storage_.resize(store_t::storage_size(xcan::dictionary));
    store_.emplace(xcan::dictionary, t::xenax_layout, storage_);
    (void)store_->init_defaults(id);
    const std::array<std::array<std::uint8_t, 4>, 4> address{
        {{0x11, 0, 0, 0}, {0x22, 0, 0, 0}, {0x03, 0, 0, 0}, {0x44, 0x33, 0, 0}}};
    for (std::uint8_t i = 0; i < 4U; ++i)
      (void)store_->set({0x1018, std::uint8_t(i + 1U)}, address[i]);
    node::lss_options l;
    l.bit_rates = 0x001F; // 1000..125 kbit/s
    l.context = this;
    l.store = [](void *self, std::uint8_t n, std::optional<node::lss_bit_timing> b) noexcept {
      auto *me = static_cast<lss_node *>(self);
      me->stored_node_ = n;
      me->stored_timing_ = b;
      return node::lss_store_result{};
    };
    dev_.emplace(*store_, id, node::options{}, l);
    (void)dev_->start(clock_.now());
    thread_ = std::thread([this] { run(); });
  }
  ~lss_node() {
    stop_ = true;
    thread_.join();
  }
  lss_node(const lss_node &) = delete;
  lss_node &operator=(const lss_node &) = delete;
  [[nodiscard]] const std::string &path() const { return pty_.path(); }

  template <class F>
  auto with(F f) {
    std::lock_guard<std::mutex> lock(mutex_);
    return f(*dev_);
  }
  std::optional<std::uint8_t> stored_node() {
    std::lock_guard<std::mutex> lock(mutex_);
    return stored_node_;
  }
  std::optional<node::lss_bit_timing> stored_timing() {
    std::lock_guard<std::mutex> lock(mutex_);
    return stored_timing_;
  }
  std::vector<co::can_frame> sent() {
    std::lock_guard<std::mutex> lock(mutex_);
    return sent_;
  }

private:
  void send(const device_t::step &s) {
    for (const co::can_frame &f : s.send) {
      sent_.push_back(f);
      pty_.write_master(host::slcan::encode(f).value().view());
    }
  }
  void run() {
    std::string buffer;
    while (!stop_) {
      const std::string in = pty_.read_master(5);
      std::lock_guard<std::mutex> lock(mutex_);
      for (const char c : in) {
        if (c != '\r') {
          buffer += c;
          continue;
        }
        auto d = host::slcan::decode(buffer);
        buffer.clear();
        if (!d || d.value().kind != host::slcan::line_kind::frame) {
          pty_.write_master("\r");
          continue;
        }
        pty_.write_master("z\r");
        if (auto f = host::to_canopen(d.value().record))
          send(dev_->on_frame(f.value(), clock_.now()));
      }
      send(dev_->poll(clock_.now()));
    }
  }

  t::pty_pair pty_;
  std::vector<std::uint8_t> storage_;
  std::optional<store_t> store_;
  std::optional<device_t> dev_;
  std::optional<std::uint8_t> stored_node_;
  std::optional<node::lss_bit_timing> stored_timing_;
  std::vector<co::can_frame> sent_;
  std::mutex mutex_;
  std::atomic<bool> stop_{false};
  host::steady_ms clock_;
  std::thread thread_;
};

} // namespace

TEST_CASE("fieldcodec lss: scan, set-node, store, waiting give a node without node-ID one") {
  lss_node n(co::lss::unconfigured);
  const std::string port = n.path();
  auto r = t::run_cli({"lss", "scan", "--slcan", port, "--probe", "20"});
  CHECK(r.err == "");
  REQUIRE(r.code == 0);
  CHECK(r.out == "address 0x00000011,0x00000022,0x00000003,0x00003344\n");
  CHECK(n.with([](auto &d) { return d.lss().mode(); }) == node::lss_mode::configuration);
  r = t::run_cli({"lss", "inquire", "--slcan", port});
  CHECK(r.code == 0);
  CHECK(r.out == "address 0x00000011,0x00000022,0x00000003,0x00003344\nnode-ID none (255)\n");
  CHECK(t::run_cli({"lss", "set-node", "33", "--slcan", port}).code == 0);
  CHECK(t::run_cli({"lss", "set-bitrate", "250", "--slcan", port}).code == 0);
  CHECK(t::run_cli({"lss", "store", "--slcan", port}).code == 0);
  CHECK(n.stored_node() == 33);
  CHECK(n.stored_timing() == node::lss_bit_timing{0, 3});
  r = t::run_cli({"lss", "set-bitrate", "250", "--slcan", port, "--address", "1,2,3,4"});
  CHECK(r.code == 1); // nobody has that address
  CHECK(r.err == "fieldcodec: lss: switch state selective: no answer (is a node in LSS "
                 "configuration?)\n");
  CHECK(t::run_cli({"lss", "activate", "20", "--slcan", port}).code == 0);
  // no answer to wait for: the node takes the frame when its thread reads it
  for (int i = 0; i < 200 && n.with([](auto &d) { return d.lss().last_event().what; }) !=
                                 node::lss_event::kind::activate_bit_timing;
       ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  CHECK(n.with([](auto &d) { return d.lss().last_event().what; }) ==
        node::lss_event::kind::activate_bit_timing);
  CHECK(t::run_cli({"lss", "waiting", "--slcan", port}).code == 0);
  // the node boots with node-ID 33 (boot-up 721h)
  for (int i = 0; i < 200 && n.with([](auto &d) { return d.node_id(); }) != 33; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  CHECK(n.with([](auto &d) { return d.state(); }) == co::nmt::state::pre_operational);
  bool booted = false;
  for (const auto &f : n.sent()) booted = booted || (f.id == 0x721 && f.dlc == 1 && f.data[0] == 0);
  CHECK(booted);
  // a configured node: scan finds nobody; selected by its address it answers inquire
  r = t::run_cli({"lss", "scan", "--slcan", port, "--probe", "20"});
  CHECK(r.code == 1);
  CHECK(r.err == "fieldcodec: lss: no node without node-ID answered\n");
  r = t::run_cli({"lss", "inquire", "--slcan", port, "--address",
                  "0x00000011,0x00000022,0x00000003,0x00003344"});
  CHECK(r.code == 0);
  CHECK(r.out == "address 0x00000011,0x00000022,0x00000003,0x00003344\nnode-ID 33\n");
  // the node refuses a bit rate its controller cannot run (lss_options::bit_rates): error code 1
  r = t::run_cli({"lss", "set-bitrate", "50", "--slcan", port});
  CHECK(r.code == 1);
  CHECK(r.err == "fieldcodec: lss: the node refused: bit rate not supported (error code 1)\n");
  r = t::run_cli({"lss", "set-node", "255", "--slcan", port}); // none from its next reset
  CHECK(r.code == 0);
  CHECK(n.with([](auto &d) { return d.lss().pending_node(); }) == 255);
  CHECK(t::run_cli({"lss", "configuration", "--slcan", port}).code == 0);
}

TEST_CASE("fieldcodec lss: bad command lines are refused before the bus") {
  const auto usage = [](std::vector<std::string> a) {
    a.insert(a.begin(), "lss");
    a.insert(a.end(), {"--slcan", "/nonexistent"});
    return t::run_cli(a);
  };
  auto r = usage({"set-node", "0"});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: lss: bad node-ID '0' (1..127, or 255: none) (try 'fieldcodec lss "
                 "--help')\n");
  CHECK(usage({"set-node", "128"}).code == 2);
  CHECK(usage({"set-node", "254"}).code == 2);
  CHECK(usage({"set-node", "x"}).code == 2);
  CHECK(usage({"set-node"}).code == 2);
  r = usage({"set-bitrate", "100"});
  CHECK(r.code == 2);
  CHECK(r.err.find("bad bit rate '100' kbit/s (1000, 800, 500, 250, 125, 50, 20, 10)") !=
        std::string::npos);
  CHECK(usage({"set-bitrate", "0"}).code == 2);
  CHECK(usage({"activate", "70000"}).code == 2);
  CHECK(usage({"scan", "1"}).code == 2);
  CHECK(usage({"frobnicate"}).code == 2);
  CHECK(usage({}).code == 2);
  CHECK(usage({"scan", "--address", "1,2,3"}).code == 2);
  CHECK(usage({"scan", "--address", "1,2,3,4,5"}).code == 2);
  CHECK(usage({"scan", "--address", "1,2,3,0x100000000"}).code == 2);
  CHECK(usage({"scan", "--timeout", "0"}).code == 2);
  CHECK(usage({"scan", "--probe", "60001"}).code == 2);
  CHECK(t::run_cli({"lss", "--help"}).out.find("usage: fieldcodec lss SERVICE") == 0);
}
