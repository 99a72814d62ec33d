// A device whose SDO servers compute the block transfer CRC by table (capacity::sdo_crc_table,
// crc::ccitt16_with_table): block downloads and uploads with a client that computes it without
// one, and a changed segment found by the CRC.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/core/crc.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <deque>
#include <type_traits>
#include <utility>
#include <vector>

using namespace test_node;
namespace crc = fieldcodec::crc;

namespace {

constexpr node::capacity table_caps = [] {
  node::capacity c = caps;
  c.sdo_crc_table = true;
  return c;
}();
using table_device = node::device<store_type, table_caps>;

template <class>
struct crc_of {};
template <class S, class C>
struct crc_of<sdo::server<S, C>> {
  using type = C;
};
template <class Device>
using server_crc = typename crc_of<
    std::remove_cvref_t<decltype(std::declval<const Device &>().sdo().server(0))>>::type;

// the option picks the servers' CRC; the clients stay sdo::client
static_assert(std::is_same_v<server_crc<table_device>, crc::ccitt16_with_table>);
static_assert(std::is_same_v<server_crc<device_type>, crc::ccitt16_no_table>);
static_assert(
    std::is_same_v<std::remove_cvref_t<decltype(std::declval<table_device &>().client(0))>,
                   sdo::client>);

struct table_rig {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(layout5.storage_size());
  std::vector<std::uint8_t> staging = std::vector<std::uint8_t>(4000);
  store_type store{dict5, layout5, storage, staging};
  table_device dev;
  sdo::client client{5, 100};
  std::uint32_t now = 0;
  std::deque<co::can_frame> to_node, to_client;
  bool corrupt_next_burst = false;

  table_rig() : dev(init(store), 5) {
    REQUIRE(dev.start(now));
    (void)dev.on_frame(F(0, {0x01, 5}), now); // operational
  }
  static store_type &init(store_type &s) {
    REQUIRE(s.init_defaults(5).has_value());
    return s;
  }
  void to(std::deque<co::can_frame> &q, const co::frames &fs, std::uint16_t id) {
    const std::size_t first = q.size();
    for (const auto &f : fs) {
      if (f.id == id) q.push_back(f);
    }
    if (fs.is_burst() && corrupt_next_burst && q.size() > first + 2U) {
      q[first + 2U].data[5] ^= 0x01U;
      corrupt_next_burst = false;
    }
  }
  void run(const sdo::step &first) {
    to(to_node, first.send, 0x605);
    for (int guard = 0; guard < 100000; ++guard) {
      if (!to_node.empty()) {
        const auto f = to_node.front();
        to_node.pop_front();
        to(to_client, dev.on_frame(f, now).send, 0x585);
      } else if (!to_client.empty()) {
        const auto f = to_client.front();
        to_client.pop_front();
        to(to_node, client.on_frame(f, now).send, 0x605);
      } else {
        return;
      }
    }
    FAIL("the transfer never settled");
  }
};

std::vector<std::uint8_t> pattern(std::size_t n) {
  std::vector<std::uint8_t> v(n);
  std::uint32_t x = 99;
  for (auto &b : v) {
    x = x * 1103515245U + 12345U;
    b = static_cast<std::uint8_t>(x >> 16U);
  }
  return v;
}

} // namespace

TEST_CASE("device with sdo_crc_table: block download and upload with CRC, against a client "
          "without the table") {
  for (const std::size_t n : {0U, 6U, 7U, 100U, 889U, 890U, 4000U}) {
    CAPTURE(n);
    table_rig r;
    const auto v = pattern(n);
    r.run(r.client.block_download({0x2005, 0}, v, r.now).value());
    REQUIRE(r.client.state() == sdo::transfer_state::done);
    const auto stored = r.store.value({0x2005, 0}).value();
    CHECK(std::vector<std::uint8_t>(stored.begin(), stored.end()) == v);
    std::vector<std::uint8_t> back(4000);
    r.run(r.client.block_upload({0x2005, 0}, back, r.now).value());
    REQUIRE(r.client.state() == sdo::transfer_state::done);
    CHECK(std::vector<std::uint8_t>(r.client.received().begin(), r.client.received().end()) == v);
  }
}

TEST_CASE("device with sdo_crc_table: a segment changed on the way fails the CRC both ways") {
  const auto v = pattern(300);
  {
    table_rig r; // download: the node's server finds it (05040004)
    r.corrupt_next_burst = true;
    r.run(r.client.block_download({0x2005, 0}, v, r.now).value());
    CHECK(r.client.state() == sdo::transfer_state::failed);
    REQUIRE(r.client.error().has_value());
    CHECK(r.client.error()->abort == abort_code::crc_error);
    CHECK(r.dev.sdo().server(0).error()->abort == abort_code::crc_error);
  }
  {
    table_rig r; // upload: the client finds it in the CRC the node's server computed
    r.run(r.client.block_download({0x2005, 0}, v, r.now).value());
    REQUIRE(r.client.state() == sdo::transfer_state::done);
    r.corrupt_next_burst = true;
    std::vector<std::uint8_t> back(4000);
    r.run(r.client.block_upload({0x2005, 0}, back, r.now).value());
    CHECK(r.client.state() == sdo::transfer_state::failed);
    REQUIRE(r.client.error().has_value());
    CHECK(r.client.error()->abort == abort_code::crc_error);
  }
}
