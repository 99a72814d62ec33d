// master::configurator and master/config.hpp against the SDO server of a simulated XENAX.
#include "sim_device.hpp"

#include <fieldcodec/master/configurator.hpp>

#include <doctest/doctest.h>

#include <string_view>

namespace master = fieldcodec::master;
namespace csdo = fieldcodec::canopen::sdo;
using fieldcodec::errc;
using master::config_state;

namespace {

constexpr std::uint8_t node = 5;

// following error window 6065h = 5000, producer heartbeat 1017h = 100 (read-only in the XENAX
// EDS: the server refuses it), TPDO 1 COB-ID $NODEID+0x180 disabled then enabled, a string.
constexpr std::uint8_t v_window[] = {0x88, 0x13, 0x00, 0x00};
constexpr std::uint8_t v_cob_off[] = {0x80, 0x01, 0x00, 0x80};
constexpr std::uint8_t v_cob_on[] = {0x80, 0x01, 0x00, 0x00};
constexpr std::uint8_t v_type[] = {0x01};
constexpr std::uint8_t v_method[] = {0x0C};
constexpr std::uint8_t v_heartbeat[] = {0x64, 0x00};

constexpr master::config_item items[] = {
    {{0x6065, 0}, v_window, 0, "Following Position Error Window"},
    {{0x1800, 1}, v_cob_off, master::config_flag::node_relative, "TPDO 1 COB-ID"},
    {{0x1800, 2}, v_type, 0, "TPDO 1 transmission type"},
    {{0x1800, 1}, v_cob_on, master::config_flag::node_relative, "TPDO 1 COB-ID"},
    {{0x6098, 0}, v_method, 0, "Reference Methods"},
};
constexpr master::configuration config{items, {}, node};

/// Runs the configurator against the device until it stops; returns the number of frames sent.
int run(master::configurator &c, sim::device &d, master::configurator::step s, std::uint32_t &now,
        bool drop_all = false) {
  int sent = 0;
  for (int guard = 0; guard < 1000 && c.busy(); ++guard) {
    std::vector<fieldcodec::canopen::can_frame> replies;
    for (const auto &f : s.send) {
      ++sent;
      if (drop_all) continue;
      for (const auto &r : d.receive(f)) replies.push_back(r);
    }
    if (!replies.empty()) {
      for (const auto &r : replies) s = c.on_frame(r, now);
      continue;
    }
    REQUIRE(s.deadline);
    now = *s.deadline;
    s = c.poll(now);
  }
  for (const auto &f : s.send) {
    ++sent;
    if (!drop_all) (void)d.receive(f);
  }
  return sent;
}

} // namespace

TEST_CASE("config: node-relative values are resolved for the node, concise DCF bytes") {
  std::array<std::uint8_t, 8> scratch{};
  auto v = master::resolved_value(items[1], 5, scratch);
  REQUIRE(v);
  CHECK(v.value().size() == 4U);
  CHECK(v.value()[0] == 0x85);
  CHECK(v.value()[3] == 0x80);
  CHECK(master::resolved_value(items[1], 0, scratch).error() == errc::invalid_argument);
  CHECK(master::resolved_value(items[1], 128, scratch).error() == errc::invalid_argument);
  CHECK(master::resolved_value(items[0], 0, scratch).value().data() == v_window);
  static constexpr std::uint8_t full[] = {0xFE};
  constexpr master::config_item over{{0x2000, 0}, full, master::config_flag::node_relative, ""};
  CHECK(master::resolved_value(over, 2, scratch).error() == errc::overflow);
  CHECK(master::resolved_value(over, 1, scratch).value()[0] == 0xFF);

  // 1F22h format: count, then index, sub, size, data
  std::array<std::uint8_t, 64> out{};
  const master::configuration two{std::span(items).first(2), {}, node};
  CHECK(master::concise_dcf_size(two) == 4U + 11U + 11U);
  auto n = master::write_concise_dcf(two, 7, out);
  REQUIRE(n);
  CHECK(n.value() == 26U);
  const std::uint8_t expect[] = {2, 0, 0,    0,    0x65, 0x60, 0x00, 4, 0, 0,    0,    0x88, 0x13,
                                 0, 0, 0x00, 0x18, 0x01, 4,    0,    0, 0, 0x87, 0x01, 0x00, 0x80};
  CHECK(std::equal(std::begin(expect), std::end(expect), out.begin()));
  CHECK(master::write_concise_dcf(two, 7, std::span(out).first(25)).error() ==
        errc::buffer_too_small);
  CHECK(master::write_concise_dcf(two, 0, out).error() == errc::invalid_argument);
}

TEST_CASE("configurator: writes every item in order, node-relative for the run-time node") {
  sim::device d(9);
  csdo::client client(9, 200);
  master::configurator c(client);
  std::uint32_t now = 100;
  auto s = c.start(config, now, 9);
  REQUIRE(s);
  CHECK(s.value().state == config_state::writing);
  run(c, d, s.value(), now);
  CHECK(c.state() == config_state::done);
  CHECK_FALSE(c.error());
  CHECK(c.completed() == 5U);
  CHECK(d.get({0x6065, 0}) == 5000U);
  CHECK(d.get({0x1800, 1}) == 0x189U); // enabled, for node 9
  CHECK(d.get({0x1800, 2}) == 1U);
  CHECK(d.get({0x6098, 0}) == 12U);
  // the order on the bus: window, COB-ID disabled, type, COB-ID enabled, method
  std::vector<fieldcodec::od::address> order;
  for (const auto &f : d.seen) {
    auto m = csdo::decode(f, csdo::direction::to_server);
    if (m && m.value().type == csdo::message_type::initiate_download_request) {
      order.push_back(m.value().address);
    }
  }
  const std::vector<fieldcodec::od::address> expect{
      {0x6065, 0}, {0x1800, 1}, {0x1800, 2}, {0x1800, 1}, {0x6098, 0}};
  CHECK(order == expect);
  CHECK(c.start(config, now).has_value()); // may run again
}

TEST_CASE("configurator: an abort is retried, then reported with the object's name") {
  sim::device d(node);
  csdo::client client(node, 200);
  std::uint32_t now = 0;
  SUBCASE("retry succeeds") {
    master::configurator c(client, {.retries = 2});
    d.abort_at = fieldcodec::od::address{0x1800, 2};
    d.aborts = 2;
    run(c, d, c.start(config, now).value(), now);
    CHECK(c.state() == config_state::done);
  }
  SUBCASE("all attempts aborted") {
    master::configurator c(client, {.retries = 2});
    d.abort_at = fieldcodec::od::address{0x1800, 2};
    d.abort_code = csdo::abort_code::value_too_high;
    d.aborts = 10;
    run(c, d, c.start(config, now).value(), now);
    CHECK(c.state() == config_state::failed);
    REQUIRE(c.error());
    const auto e = *c.error();
    CHECK(e.failure == master::config_failure::transfer_failed);
    CHECK(e.is(errc::aborted));
    CHECK(e.abort == csdo::abort_code::value_too_high);
    CHECK(e.item == 2U);
    CHECK(e.address == fieldcodec::od::address{0x1800, 2});
    CHECK(e.name == "TPDO 1 transmission type");
    CHECK(e.attempts == 3U);
    CHECK(c.completed() == 2U);
    CHECK(d.get({0x6098, 0}) == 1U); // nothing after the failed item was written
  }
  SUBCASE("a read-only object: the server's abort is the report") {
    constexpr master::config_item ro[] = {{{0x1017, 0}, v_heartbeat, 0, "Producer Heartbeat"}};
    master::configurator c(client, {.retries = 0});
    run(c, d, c.start({ro, {}, node}, now).value(), now);
    REQUIRE(c.error());
    CHECK(c.error()->abort == csdo::abort_code::write_read_only);
    CHECK(c.error()->attempts == 1U);
    CHECK(c.error()->name == "Producer Heartbeat");
  }
}

TEST_CASE("configurator: per-transfer timeout, retries, then timeout reported") {
  sim::device d(node);
  csdo::client client(node, 10000); // the client's own timeout is longer
  std::uint32_t now = 0xFFFF'FF00U; // across the wrap-around
  SUBCASE("one request lost") {
    master::configurator c(client, {.retries = 1, .timeout_ms = 50});
    d.silent = 1;
    const auto start = now;
    run(c, d, c.start(config, now).value(), now);
    CHECK(c.state() == config_state::done);
    CHECK(now - start == 50U); // one timeout, not the client's 10 s
    // the lost request was aborted (0x80 with 0x05040000) before the retry
    bool abort_seen = false;
    for (const auto &f : d.seen) {
      auto m = csdo::decode(f, csdo::direction::to_server);
      if (m && m.value().type == csdo::message_type::abort) {
        abort_seen = m.value().abort == csdo::abort_code::timeout;
      }
    }
    CHECK(abort_seen);
  }
  SUBCASE("nobody answers") {
    master::configurator c(client, {.retries = 2, .timeout_ms = 50});
    const auto start = now;
    run(c, d, c.start(config, now).value(), now, true);
    CHECK(c.state() == config_state::failed);
    CHECK(c.error()->is(errc::timeout));
    CHECK(c.error()->abort == csdo::abort_code::timeout);
    CHECK(c.error()->item == 0U);
    CHECK(c.error()->attempts == 3U);
    CHECK(now - start == 150U);
  }
}

TEST_CASE("configurator: verify reads every item back and reports a mismatch") {
  sim::device d(node);
  csdo::client client(node, 200);
  std::uint32_t now = 0;
  SUBCASE("all kept") {
    master::configurator c(client, {.verify = true});
    run(c, d, c.start(config, now).value(), now);
    CHECK(c.state() == config_state::done);
    int uploads = 0;
    for (const auto &f : d.seen) {
      auto m = csdo::decode(f, csdo::direction::to_server);
      if (m && m.value().type == csdo::message_type::initiate_upload_request) ++uploads;
    }
    CHECK(uploads == 5);
  }
  SUBCASE("the device changes a value") {
    master::configurator c(client, {.verify = true});
    d.tamper_at = fieldcodec::od::address{0x6065, 0};
    run(c, d, c.start(config, now).value(), now);
    CHECK(c.state() == config_state::failed);
    CHECK(c.error()->failure == master::config_failure::verify_mismatch);
    CHECK(c.error()->is(errc::out_of_range));
    CHECK(c.error()->name == "Following Position Error Window");
  }
}

TEST_CASE("configurator: refusals") {
  sim::device d(node);
  csdo::client client(node, 200);
  master::configurator c(client);
  std::uint32_t now = 0;
  SUBCASE("node-relative items need a node-ID") {
    run(c, d, c.start({items, {}, 0}, now).value(), now);
    CHECK(c.state() == config_state::failed);
    CHECK(c.error()->failure == master::config_failure::bad_item);
    CHECK(c.error()->is(errc::invalid_argument));
    CHECK(c.error()->item == 1U);
  }
  SUBCASE("busy") {
    REQUIRE(c.start(config, now));
    CHECK(c.start(config, now).error() == errc::bad_state);
  }
  SUBCASE("an empty list is done at once") {
    auto s = c.start({}, now);
    CHECK(s.value().state == config_state::done);
    CHECK(s.value().send.empty());
  }
}

// The list fieldcodec-gen wrote from tests/master/fixtures/xenax_axis.dcf (kept current by the
// codegen test "the fixture of the master tests matches its checked-in header").
#include "master/generated/xenax_axis_config.hpp"

namespace axis_config = fieldcodec::dictionaries::xenax_axis::config;

TEST_CASE("configurator: the generated list of a DCF brings the device to the DCF's values") {
  static_assert(axis_config::node_id == 5);
  static_assert(axis_config::identity.vendor_id == 0x21BU);
  static_assert(axis_config::items.size() == 8U);
  // the concise DCF the generator wrote is what write_concise_dcf makes for node 5
  std::array<std::uint8_t, sizeof axis_config::concise_dcf> concise{};
  REQUIRE(master::write_concise_dcf(axis_config::configuration, 5, concise).value() ==
          concise.size());
  CHECK(std::equal(concise.begin(), concise.end(), std::begin(axis_config::concise_dcf)));

  for (const std::uint8_t n : {std::uint8_t{5}, std::uint8_t{9}}) {
    CAPTURE(n);
    sim::device d(n);
    csdo::client client(n, 200);
    master::configurator c(client, {.verify = true});
    std::uint32_t now = 0;
    run(c, d, c.start(axis_config::configuration, now, n).value(), now);
    CHECK(c.state() == config_state::done);
    CHECK(d.get({0x1800, 1}) == 0x180U + n);
    CHECK(d.get({0x1800, 2}) == 1U);
    CHECK(d.get({0x1A00, 0}) == 1U);
    CHECK(d.get({0x1A00, 1}) == 0x60640020U);
    CHECK(d.get({0x6065, 0}) == 500U);
    CHECK(d.get({0x6098, 0}) == 12U);
  }
}
