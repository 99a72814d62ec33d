// The LSS master (canopen/lss_master.hpp) against the node's LSS slave (node::device with
// capacity::lss): every service over a simulated bus, timeouts, answers that do not fit.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/lss.hpp>
#include <fieldcodec/canopen/lss_master.hpp>

#include <memory>

using namespace test_node;
namespace lss = fieldcodec::canopen::lss;
using lss::master_state;

namespace {

constexpr node::capacity lss_caps = node::capacity_for(dict5, {.lss = true});
using lss_device = node::device<store_type, lss_caps>;

/// A bus with the master and `n` devices (nodes `ids`); frames go to every other party.
struct bus {
  std::vector<std::vector<std::uint8_t>> storages;
  std::vector<std::unique_ptr<store_type>> stores;
  std::vector<std::unique_ptr<lss_device>> devs;
  lss::master m;
  std::uint32_t now = 0;
  std::vector<co::can_frame> seen; // every frame on the bus

  explicit bus(std::initializer_list<std::uint8_t> ids, lss::master_options o = {}) : m(o) {
    std::uint32_t serial = 1;
    for (const std::uint8_t id : ids) {
      storages.emplace_back(layout5.storage_size());
      stores.push_back(std::make_unique<store_type>(dict5, layout5, storages.back()));
      (void)stores.back()->init_defaults(id);
      const std::array<std::uint8_t, 4> s{static_cast<std::uint8_t>(serial++), 0, 0, 0};
      REQUIRE(stores.back()->set({0x1018, 4}, s) == abort_code::none);
      devs.push_back(std::make_unique<lss_device>(*stores.back(), id));
      REQUIRE(devs.back()->start(now));
    }
  }
  /// Deliver the master's frames to every device, and their answers to the master.
  void deliver(const lss::master::step &s) {
    std::vector<co::can_frame> out(s.send.begin(), s.send.end());
    while (!out.empty()) {
      std::vector<co::can_frame> next;
      for (const auto &f : out) {
        seen.push_back(f);
        if (f.id == lss::master_id) {
          for (auto &d : devs) {
            const auto r = d->on_frame(f, now);
            next.insert(next.end(), r.send.begin(), r.send.end());
          }
        } else {
          const auto r = m.on_frame(f, now);
          next.insert(next.end(), r.send.begin(), r.send.end());
        }
      }
      out = std::move(next);
    }
  }
  /// Run a service to its end (answers, then time in 10 ms steps).
  void run(fieldcodec::result<lss::master::step> started) {
    REQUIRE(started);
    deliver(started.value());
    for (int i = 0; i < 100000 && m.busy(); ++i) {
      now += 10;
      deliver(m.poll(now));
    }
    REQUIRE_FALSE(m.busy());
  }
};

} // namespace

TEST_CASE("lss master: switch selective, inquire, configure, store against the node") {
  bus b({5});
  const lss::address a{0x0F1C, 1, 0x0001'0000U, 1};
  b.run(b.m.switch_selective(a, b.now));
  CHECK(b.m.state() == master_state::done);
  CHECK(b.devs[0]->lss().mode() == node::lss_mode::configuration);
  b.run(b.m.inquire(lss::command::inquire_vendor, b.now));
  CHECK(b.m.value() == 0x0F1C);
  b.run(b.m.inquire(lss::command::inquire_serial, b.now));
  CHECK(b.m.value() == 1);
  b.run(b.m.inquire(lss::command::inquire_node_id, b.now));
  CHECK(b.m.value() == 5);
  b.run(b.m.configure_node_id(9, b.now));
  CHECK(b.m.error_code() == lss::error_code::none);
  CHECK(b.devs[0]->lss().pending_node() == 9);
  b.run(b.m.configure_bit_timing(0, 5, b.now));
  CHECK(b.m.error_code() == lss::error_code::not_supported);
  b.run(b.m.configure_bit_timing(0, 2, b.now));
  CHECK(b.m.error_code() == lss::error_code::none);
  b.run(b.m.activate_bit_timing(50, b.now));
  CHECK(b.devs[0]->events().size() == 1);
  b.run(b.m.store(b.now));
  CHECK(b.m.error_code() == lss::error_code::not_supported); // the node has no store hook
  b.run(b.m.switch_global(0, b.now));
  CHECK(b.devs[0]->lss().mode() == node::lss_mode::waiting);
  // a wrong address: nobody answers, the service fails by timeout
  b.run(b.m.switch_selective({1, 2, 3, 4}, b.now));
  CHECK(b.m.state() == master_state::failed);
  CHECK(b.m.error() == errc::timeout);
  // bad arguments and a second service while one runs
  CHECK(b.m.configure_node_id(0, b.now).error() == errc::invalid_argument);
  CHECK(b.m.configure_node_id(0x80, b.now).error() == errc::invalid_argument);
  CHECK(b.m.switch_global(2, b.now).error() == errc::invalid_argument);
  CHECK(b.m.inquire(lss::command::store_configuration, b.now).error() == errc::invalid_argument);
  REQUIRE(b.m.inquire(lss::command::inquire_node_id, b.now));
  CHECK(b.m.store(b.now).error() == errc::bad_state);
  // an answer that does not fit is not taken
  (void)b.m.on_frame(co::make_frame(lss::slave_id, {0x11, 0, 0, 0, 0, 0, 0, 0}).value(), b.now);
  CHECK(b.m.busy());
  CHECK(b.m.frame_error() == errc::unexpected_frame);
  co::can_frame short_answer = co::make_frame(lss::slave_id, {0x5E, 5}).value();
  (void)b.m.on_frame(short_answer, b.now);
  CHECK(b.m.frame_error() == errc::bad_length);
  CHECK(b.m.busy());
}

TEST_CASE("lss master: fastscan finds the unconfigured node among configured ones") {
  bus b({5, lss::unconfigured, 7});
  b.run(b.m.identify_non_configured(b.now));
  CHECK(b.m.found());
  b.run(b.m.fastscan(b.now));
  REQUIRE(b.m.found());
  CHECK(b.m.found_address() == lss::address{0x0F1C, 1, 0x0001'0000U, 2});
  CHECK(b.devs[1]->lss().mode() == node::lss_mode::configuration);
  CHECK(b.devs[0]->lss().mode() == node::lss_mode::waiting);
  b.run(b.m.configure_node_id(0x30, b.now));
  CHECK(b.m.error_code() == 0);
  b.seen.clear();
  b.run(b.m.switch_global(0, b.now));
  CHECK(on(b.seen, 0x730).size() == 1); // its boot-up
  CHECK(b.devs[1]->node_id() == 0x30);
  // nobody without node-ID any more
  b.run(b.m.identify_non_configured(b.now));
  CHECK_FALSE(b.m.found());
  b.run(b.m.fastscan(b.now));
  CHECK_FALSE(b.m.found());
  CHECK(b.m.state() == master_state::done);
}
