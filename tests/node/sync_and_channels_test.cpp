// SYNC consumer (1005h, 1007h, 1019h) and SDO channels (1200h–12FFh), alone and in the device;
// routing and bad frames of the device.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/sdo_channels.hpp>
#include <fieldcodec/canopen/node/sync_consumer.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>

using namespace test_node;

namespace {
constexpr bool sync_walk() {
  node::sync_consumer s;
  if (s.set_overflow(3) != abort_code::none) return false;
  s.set_window_us(1500); // 2 ms
  auto a = s.on_frame(co::make_frame(0x80, {2}).value(), 100);
  if (!a.state.received || a.state.counter != 2 || !a.state.in_window) return false;
  if (a.deadline != 102U) return false;
  if (!s.inside_window(101) || s.inside_window(102)) return false;
  return s.window_passed(102) && !s.poll(102).state.in_window;
}
static_assert(sync_walk());
} // namespace

TEST_CASE("sync consumer: lengths against 1019h, counters, COB-ID") {
  node::sync_consumer s;
  // no 1019h: both lengths are right
  CHECK(s.on_frame(F(0x80, {}), 0).state.received);
  CHECK(s.on_frame(F(0x80, {7}), 0).state.counter == 7);
  CHECK_FALSE(s.on_frame(F(0x80, {0}), 0).state.received); // counter 0
  CHECK(s.error() == errc::out_of_range);
  CHECK_FALSE(s.on_frame(F(0x80, {241}), 0).state.received);
  CHECK_FALSE(s.length_error());
  CHECK_FALSE(s.on_frame(F(0x80, {1, 2}), 0).state.received); // DLC 2
  CHECK(s.length_error());
  CHECK(s.error() == errc::bad_length);
  CHECK(s.on_frame(F(0x80, {}), 0).state.received);
  CHECK_FALSE(s.length_error());
  // 1019h = 4: a counter is expected
  CHECK(s.set_overflow(1) == abort_code::invalid_value);
  CHECK(s.set_overflow(241) == abort_code::invalid_value);
  CHECK(s.set_overflow(4) == abort_code::none);
  CHECK_FALSE(s.on_frame(F(0x80, {}), 0).state.received);
  CHECK(s.length_error());
  CHECK(s.on_frame(F(0x80, {1}), 0).state.received);
  CHECK_FALSE(s.length_error());
  CHECK(s.set_overflow(0) == abort_code::none);
  CHECK_FALSE(s.on_frame(F(0x80, {1}), 0).state.received);
  // remote frames and other identifiers are not SYNC
  CHECK_FALSE(s.on_frame(R(0x80, 0), 0).state.received);
  CHECK_FALSE(s.on_frame(F(0x81, {}), 0).state.received);
  // 1005h: bit 30 (generate) refused: this node is no SYNC producer
  CHECK(s.set_cob_id(0x4000'0080U) == abort_code::invalid_value);
  CHECK(s.set_cob_id(0x2000'0080U) == abort_code::invalid_value);
  CHECK(s.set_cob_id(0x0000'0880U) == abort_code::invalid_value);
  CHECK(s.set_cob_id(0x0000'0090U) == abort_code::none);
  CHECK(s.on_frame(F(0x90, {}), 0).state.received);
  CHECK_FALSE(s.on_frame(F(0x80, {}), 0).state.received);
}

TEST_CASE("device: SYNC COB-ID, EMCY 8240h for an unexpected SYNC length") {
  rig<> r;
  r.operational();
  (void)r.tick();
  CHECK(r.sdo_write(0x1005, 0, 0x2000'0080U, 4) == abort_code::invalid_value); // 29-bit
  CHECK(r.sdo_write(0x1019, 0, 1, 1) == abort_code::invalid_value);
  CHECK(r.sdo_write(0x1019, 0, 16, 1) == abort_code::none);
  auto out = r.feed(F(0x80, {}));
  CHECK(on(out, 0x85) == std::vector{F(0x85, {0x40, 0x82, 0x11, 0, 0, 0, 0, 0})});
  CHECK(on(out, 0x285).empty()); // not a SYNC: no synchronous TPDO
  out = r.feed(F(0x80, {1}));
  CHECK(on(out, 0x285).size() == 1);
  CHECK(on(out, 0x85) == std::vector{F(0x85, {0, 0, 0, 0, 0, 0, 0, 0})});
  REQUIRE(r.dev.events().size() >= 1);
  CHECK(r.dev.events()[0].what == node::event::kind::sync);
  CHECK(r.dev.events()[0].counter == 1);
  CHECK(r.sdo_write(0x1005, 0, 0x81, 4) == abort_code::none);
  CHECK(on(r.feed(F(0x80, {2})), 0x285).empty());
  CHECK(on(r.feed(F(0x81, {2})), 0x285).size() == 1);
}

TEST_CASE("device: 1019h is writable only while 1006h is 0 (CiA 301, abort 0800 0022h)") {
  rig<> r;
  r.operational();
  CHECK(r.sdo_write(0x1019, 0, 8, 1) == abort_code::none);
  CHECK(r.sdo_write(0x1006, 0, 10'000, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1019, 0, 16, 1) == abort_code::cannot_store_device_state);
  CHECK(r.read_u(0x1019, 0) == 8);
  CHECK(r.sdo_write(0x1019, 0, 8, 1) == abort_code::cannot_store_device_state); // the same too
  CHECK(r.set_u(0x1019, 0, 16, 1) == abort_code::cannot_store_device_state);    // and set()
  CHECK(r.sdo_write(0x1019, 0, 1, 1) == abort_code::cannot_store_device_state);
  // a reset communication brings 1006h back to its default 0: writable again
  (void)r.feed(F(0, {0x82, 5}));
  CHECK(r.sdo_write(0x1019, 0, 16, 1) == abort_code::none);
  CHECK(r.sdo_write(0x1006, 0, 1000, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1006, 0, 0, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1019, 0, 0, 1) == abort_code::none);
  CHECK(r.read_u(0x1019, 0) == 0);
  // the rule alone, and a 1006h loaded from the store
  node::sync_consumer s;
  s.written({0x1006, 0}, 500, 0);
  CHECK(s.check_write({0x1019, 0}, 4) == abort_code::cannot_store_device_state);
  s.written({0x1006, 0}, 0, 0);
  CHECK(s.check_write({0x1019, 0}, 4) == abort_code::none);
  rig<> q;
  REQUIRE(q.store.set({0x1006, 0}, std::array<std::uint8_t, 4>{0xE8, 0x03, 0, 0}) ==
          abort_code::none);
  q.operational();
  CHECK(q.dev.sync().period_us() == 1000);
  CHECK(q.sdo_write(0x1019, 0, 4, 1) == abort_code::cannot_store_device_state);
}

TEST_CASE("sdo channels: the default channel without 1200h, one more server, a client") {
  static constexpr od::entry_spec entries_spec[] = {
      var(0x1000, 0, data_type::unsigned32, access::ro, 0x1234),
      var(0x1201, 0, data_type::unsigned8, access::ro, 2),
      var(0x1201, 1, data_type::unsigned32, access::rw, 0x640),
      var(0x1201, 2, data_type::unsigned32, access::rw, 0x5C0),
      var(0x1280, 0, data_type::unsigned8, access::ro, 3),
      var(0x1280, 1, data_type::unsigned32, access::rw, 0x603),
      var(0x1280, 2, data_type::unsigned32, access::rw, 0x583),
      var(0x1280, 3, data_type::unsigned8, access::rw, 3),
  };
  static constexpr auto entries = od::entries_of<entries_spec>;
  static constexpr od::dictionary dict{entries};
  constexpr auto layout = co::make_layout<std::size(entries)>(dict);
  std::vector<std::uint8_t> storage(layout.storage_size());
  store_type store{dict, layout, storage};
  REQUIRE(store.init_defaults(9).has_value());
  node::sdo_channels<store_type, 2, 1, 16> ch(store, 9);
  REQUIRE(ch.reload(dict).has_value());
  CHECK(ch.server(0).connection() == sdo::channel{0x609, 0x589}); // predefined
  CHECK(ch.server(1).connection() == sdo::channel{0x640, 0x5C0});
  CHECK(ch.client(0).connection() == sdo::channel{0x603, 0x583});
  CHECK(ch.client_server_node(0) == 3);
  // both servers answer, each on its own identifiers
  auto a = ch.on_frame(sdo::channel{0x609, 0x589}.request(sdo::initiate_upload({0x1000, 0})), 0);
  REQUIRE(a);
  CHECK(a->send[0].id == 0x589);
  auto b = ch.on_frame(sdo::channel{0x640, 0x5C0}.request(sdo::initiate_upload({0x1000, 0})), 0);
  REQUIRE(b);
  CHECK(b->send[0].id == 0x5C0);
  CHECK(b->send[0].data[4] == 0x34);
  CHECK_FALSE(ch.on_frame(F(0x641, {0x40, 0, 0x10, 0, 0, 0, 0, 0}), 0));
  // the client: a transfer, its response routed back, its timeout
  std::array<std::uint8_t, 4> buf{};
  auto s = ch.client(0).upload({0x1000, 0}, buf, 0);
  REQUIRE(s);
  CHECK(s.value().send[0].id == 0x603);
  CHECK(ch.busy());
  CHECK(ch.poll(0).state == node::channels_state::transferring);
  CHECK(ch.deadline(0) == 1000U);
  auto t = ch.poll(1000);
  REQUIRE(t.send.size() == 1);
  CHECK(t.state == node::channels_state::idle); // the timeout ended it
  CHECK(to_string(t.state) == "no SDO transfer");
  CHECK(t.send[0].id == 0x603); // abort: timeout
  CHECK(ch.client(0).error()->abort == abort_code::timeout);
  // COB-ID rules for 1201h / 1280h
  const std::array<std::uint8_t, 4> moved{0x41, 0x06, 0, 0};
  CHECK(ch.check_write({0x1201, 1}, moved) == abort_code::invalid_value); // valid → valid
  const std::array<std::uint8_t, 4> off{0x40, 0x06, 0, 0x80};
  CHECK(ch.check_write({0x1201, 1}, off) == abort_code::none);
  CHECK(store.write({0x1201, 1}, 0, off, true) == abort_code::none);
  ch.written({0x1201, 1});
  CHECK_FALSE(ch.server_valid(1));
  CHECK_FALSE(
      ch.on_frame(sdo::channel{0x640, 0x5C0}.request(sdo::initiate_upload({0x1000, 0})), 0));
  CHECK(ch.check_write({0x1201, 1}, moved) == abort_code::none);
  const std::array<std::uint8_t, 4> bit29{0x41, 0x06, 0, 0x20};
  CHECK(ch.check_write({0x1280, 1}, bit29) == abort_code::invalid_value);
  CHECK(ch.check_write({0x1280, 3}, bit29) == abort_code::none); // sub 3: the node-ID
}

TEST_CASE("device: an SDO client talks to another device; additional server by SDO") {
  rig<5> a;
  rig<3> b;
  (void)a.start();
  (void)b.start();
  CHECK(a.dev.sdo().server_valid(0));
  CHECK_FALSE(a.dev.sdo().server_valid(1));
  CHECK_FALSE(a.dev.sdo().client_valid(0));
  // configure a's client for node 3 by SDO (as a configuration tool would)
  CHECK(a.sdo_write(0x1280, 1, 0x603, 4) == abort_code::none);
  CHECK(a.sdo_write(0x1280, 2, 0x583, 4) == abort_code::none);
  CHECK(a.sdo_write(0x1280, 3, 3, 1) == abort_code::none);
  CHECK(a.dev.sdo().client_valid(0));
  std::array<std::uint8_t, 16> buf{};
  auto s = a.dev.client(0).upload({0x1008, 0}, buf, 0);
  REQUIRE(s);
  std::vector<co::can_frame> to_b = list(s.value().send);
  for (int round = 0; round < 10 && !to_b.empty(); ++round) {
    std::vector<co::can_frame> to_a;
    for (const auto &f : to_b) {
      for (const auto &g : b.feed(f)) to_a.push_back(g);
    }
    to_b.clear();
    for (const auto &f : to_a) {
      for (const auto &g : a.feed(f)) to_b.push_back(g);
    }
  }
  REQUIRE(a.dev.client(0).state() == sdo::transfer_state::done);
  const auto got = a.dev.client(0).received();
  CHECK(std::string_view(reinterpret_cast<const char *>(got.data()), got.size()) ==
        "fieldcodec node");
  // an additional server on b, opened by SDO: 1201h
  CHECK(b.sdo_write(0x1201, 1, 0x650, 4) == abort_code::none);
  CHECK(b.sdo_write(0x1201, 2, 0x5D0, 4) == abort_code::none);
  CHECK(b.dev.sdo().server_valid(1));
  auto out = b.feed(F(0x650, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}));
  REQUIRE(out.size() == 1);
  CHECK(out[0] == F(0x5D0, {0x43, 0x00, 0x10, 0x00, 0x91, 0x01, 0x0F, 0x00}));
  CHECK(b.sdo_write(0x1201, 1, 0x651, 4) == abort_code::invalid_value); // valid: no change
  CHECK(b.sdo_write(0x1200, 1, 0x604, 4) == abort_code::write_read_only);
}

TEST_CASE("device: bad and foreign frames are ignored") {
  rig<> r;
  r.operational();
  (void)r.tick();
  co::can_frame big = F(0x205, {1, 2, 3});
  big.dlc = 9;
  CHECK(r.feed(big).empty());
  co::can_frame wide = F(0x205, {1});
  wide.id = 0x800;
  CHECK(r.feed(wide).empty());
  CHECK(r.feed(F(0x100, {0, 0, 0, 0, 0, 0})).empty());             // TIME: not used
  CHECK(r.feed(F(0x081, {0, 0, 0, 0, 0, 0, 0, 0})).empty());       // another node's EMCY
  CHECK(r.feed(F(0x186, {1})).empty());                            // another node's TPDO
  CHECK(r.feed(F(0x606, {0x40, 0, 0x10, 0, 0, 0, 0, 0})).empty()); // SDO for node 6
  CHECK(r.feed(F(0x605, {0x40, 0, 0x10, 0})).empty());             // SDO with DLC 4
  CHECK(r.dev.sdo().server(0).error()->code == errc::bad_length);
  CHECK(r.feed(F(0x705, {0x05})).empty()); // our own heartbeat id: not a request
  CHECK(r.read_u(0x2000, 0) == 0);
  CHECK(r.dev.lost() == 0);
}
