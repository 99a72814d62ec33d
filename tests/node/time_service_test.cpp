// TIME (CiA 301 7.2.6, 1012h "COB-ID time stamp"): the service alone (the rules of 1012h, the
// frame both ways, bad frames) and in the device (the `time` event, produce_time, NMT states,
// reset, pay-for-use).
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/time_service.hpp>

using namespace test_node;
using co::nmt::state;

namespace {

// 2024-01-01 12:34:56.789: day 14610 after 1984-01-01, 45 296 789 ms = 02B32C95h after midnight
constexpr od::time_value noon{12U * 3'600'000U + 34U * 60'000U + 56'789U, 14610};
const std::initializer_list<std::uint8_t> noon_bytes = {0x95, 0x2C, 0xB3, 0x02, 0x12, 0x39};

} // namespace

TEST_CASE("time service alone: the rules of 1012h") {
  node::time_service t;
  const od::address a{0x1012, 0};
  CHECK_FALSE(t.consumer());
  CHECK_FALSE(t.producer());
  CHECK(t.cob_id() == 0x100);
  // the default and both bits
  CHECK(t.check_write(a, 0x100) == abort_code::none);
  CHECK(t.check_write(a, 0xC000'0100U) == abort_code::none);
  // a 29-bit identifier, bits 11..28
  CHECK(t.check_write(a, 0x2000'0100U) == abort_code::invalid_value);
  CHECK(t.check_write(a, 0x8000'0900U) == abort_code::invalid_value);
  CHECK(t.check_write(a, 0x1000'0100U) == abort_code::invalid_value);
  // a restricted CAN-ID: only while neither consuming nor producing
  CHECK(t.check_write(a, 0x8000'0000U) == abort_code::invalid_value); // 0: NMT
  CHECK(t.check_write(a, 0x4000'0101U) == abort_code::invalid_value);
  CHECK(t.check_write(a, 0x8000'0701U) == abort_code::invalid_value);
  CHECK(t.check_write(a, 0x0000'0701U) == abort_code::none);
  // another CAN-ID while active and staying active: refused; the same value, other bits: taken
  t.written(a, 0x8000'0100U, 0);
  CHECK(t.consumer());
  CHECK_FALSE(t.producer());
  CHECK(t.check_write(a, 0x8000'0181U) == abort_code::invalid_value);
  CHECK(t.check_write(a, 0x4000'0181U) == abort_code::invalid_value);
  CHECK(t.check_write(a, 0x8000'0100U) == abort_code::none);
  CHECK(t.check_write(a, 0xC000'0100U) == abort_code::none);
  CHECK(t.check_write(a, 0x0000'0181U) == abort_code::none); // leaving both bits: may change
  t.written(a, 0x0000'0181U, 0);
  CHECK(t.check_write(a, 0xC000'0181U) == abort_code::none);
  CHECK(t.check_write(a, 0xC000'0182U) == abort_code::none); // was inactive
  // other objects are not its own
  CHECK(t.check_write({0x1013, 0}, 0xFFFF'FFFFU) == abort_code::none);
  CHECK(t.check_write({0x1012, 1}, 0xFFFF'FFFFU) == abort_code::none);
}

TEST_CASE("time service alone: producing and consuming frames, bad frames") {
  node::time_service t;
  const od::address a{0x1012, 0};
  CHECK(t.produce(noon) == errc::bad_state); // bit 30 clear
  t.written(a, 0xC000'0100U, 0);
  CHECK(t.produce(noon).value() == F(0x100, noon_bytes));
  CHECK(t.produce({86'399'999U, 0}).has_value());
  CHECK(t.produce({86'400'000U, 0}) == errc::out_of_range); // not a time of day
  CHECK(t.produce({0x1000'0000U, 0}) == errc::out_of_range);
  // consuming: the time, kept as received()
  CHECK(t.received() == std::nullopt);
  CHECK(t.takes(F(0x100, noon_bytes)));
  CHECK_FALSE(t.takes(R(0x100, 6)));
  CHECK_FALSE(t.takes(F(0x101, noon_bytes)));
  CHECK(t.on_frame(F(0x100, noon_bytes)).value() == noon);
  CHECK(t.received() == noon);
  CHECK(t.error() == std::nullopt);
  // bad frames are ignored: received() stays, error() says why
  CHECK(t.on_frame(F(0x100, {0x95, 0x2C, 0xB3, 0x02, 0x12})) == errc::bad_length);
  CHECK(t.error() == errc::bad_length);
  CHECK(t.on_frame(F(0x100, {0x95, 0x2C, 0xB3, 0x02, 0x12, 0x39, 0})) == errc::bad_length);
  CHECK(t.on_frame(F(0x100, {})) == errc::bad_length);
  CHECK(t.on_frame(F(0x100, {0x95, 0x2C, 0xB3, 0x12, 0x12, 0x39})) == errc::out_of_range);
  CHECK(t.error() == errc::out_of_range); // a reserved bit (28) of the milliseconds
  CHECK(t.on_frame(F(0x100, {0x00, 0x5C, 0x26, 0x05, 0, 0})) == errc::out_of_range); // 24:00
  CHECK(t.received() == noon);
  CHECK(t.on_frame(F(0x100, {0xFF, 0x5B, 0x26, 0x05, 0, 0})).value() ==
        od::time_value{86'399'999U, 0});
  CHECK(t.error() == std::nullopt);
  // another CAN-ID both ways
  t.written(a, 0xC000'0181U, 0);
  CHECK(t.produce(noon).value() == F(0x181, noon_bytes));
  CHECK(t.takes(F(0x181, noon_bytes)));
  CHECK_FALSE(t.takes(F(0x100, noon_bytes)));
  CHECK(t.on_frame(F(0x181, noon_bytes)).value() == noon);
  // consumer off: takes nothing
  t.written(a, 0x4000'0181U, 0);
  CHECK_FALSE(t.takes(F(0x181, noon_bytes)));
}

TEST_CASE("device: TIME consumer reports a `time` event") {
  rig<> r;
  (void)r.start();
  REQUIRE(r.read_u(0x1012, 0) == 0x100); // default: neither consumer nor producer
  CHECK(r.feed(F(0x100, noon_bytes)).empty());
  CHECK(r.dev.events().empty());
  CHECK(r.sdo_write(0x1012, 0, 0x8000'0100U, 4) == abort_code::none);
  CHECK(r.feed(F(0x100, noon_bytes)).empty());
  REQUIRE(r.dev.events().size() == 1);
  CHECK(r.dev.events()[0].what == node::event::kind::time);
  CHECK(to_string(node::event::kind::time) == "TIME received");
  CHECK(r.dev.time().received() == noon);
  // a bad TIME: no event, no EMCY, the last time stays
  CHECK(r.feed(F(0x100, {1, 2, 3})).empty());
  CHECK(r.dev.events().empty());
  CHECK(r.dev.time().error() == errc::bad_length);
  CHECK(r.feed(F(0x100, {0, 0, 0, 0xF0, 0, 0})).empty());
  CHECK(r.dev.events().empty());
  CHECK(r.dev.time().error() == errc::out_of_range);
  CHECK(r.dev.time().received() == noon);
  CHECK(r.feed(R(0x100, 6)).empty()); // a remote frame is no TIME
  CHECK(r.dev.events().empty());
  // operational: taken; stopped: ignored (CiA 301 Table 48)
  (void)r.feed(F(0, {0x01, 5}));
  (void)r.feed(F(0x100, {0, 0, 0, 0, 1, 0}));
  REQUIRE(r.dev.events().size() == 1);
  CHECK(r.dev.time().received() == od::time_value{0, 1});
  (void)r.feed(F(0, {0x02, 5}));
  (void)r.feed(F(0x100, noon_bytes));
  CHECK(r.dev.events().empty());
  CHECK(r.dev.time().received() == od::time_value{0, 1});
  // the consumer on another CAN-ID (only after clearing bit 31)
  (void)r.feed(F(0, {0x80, 5}));
  CHECK(r.sdo_write(0x1012, 0, 0x8000'0181U, 4) == abort_code::invalid_value);
  CHECK(r.read_u(0x1012, 0) == 0x8000'0100U);
  CHECK(r.sdo_write(0x1012, 0, 0x0000'0181U, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1012, 0, 0x8000'0181U, 4) == abort_code::none);
  (void)r.feed(F(0x100, noon_bytes));
  CHECK(r.dev.events().empty());
  (void)r.feed(F(0x181, noon_bytes));
  REQUIRE(r.dev.events().size() == 1);
  CHECK(r.dev.time().received() == noon);
  // refused values of 1012h by SDO
  CHECK(r.sdo_write(0x1012, 0, 0x2000'0181U, 4) == abort_code::invalid_value);
  CHECK(r.sdo_write(0x1012, 0, 0x0000'0981U, 4) == abort_code::invalid_value);
  CHECK(r.read_u(0x1012, 0) == 0x8000'0181U);
  // reset communication: 1012h back to 100h, nothing received
  (void)r.feed(F(0, {0x82, 5}));
  CHECK(r.read_u(0x1012, 0) == 0x100);
  CHECK_FALSE(r.dev.time().consumer());
  CHECK(r.dev.time().received() == std::nullopt);
}

TEST_CASE("device: produce_time sends the application's time") {
  rig<> r;
  CHECK(r.dev.produce_time(noon, 0) == errc::bad_state); // not started
  (void)r.start();
  CHECK(r.dev.produce_time(noon, 0) == errc::bad_state); // 1012h bit 30 clear
  CHECK(r.set_u(0x1012, 0, 0x4000'0100U, 4) == abort_code::none);
  auto s = r.dev.produce_time(noon, 10);
  REQUIRE(s.has_value());
  CHECK(list(s.value().send) == std::vector{F(0x100, noon_bytes)});
  CHECK(r.dev.produce_time({86'400'000U, 0}, 10) == errc::out_of_range);
  // the producer does not consume its own identifier: a TIME from another node is no event
  (void)r.feed(F(0x100, noon_bytes));
  CHECK(r.dev.events().empty());
  // operational: sent; stopped: refused
  (void)r.feed(F(0, {0x01, 5}));
  CHECK(list(r.dev.produce_time({0, 0}, 20).value().send) ==
        std::vector{F(0x100, {0, 0, 0, 0, 0, 0})});
  (void)r.feed(F(0, {0x02, 5}));
  CHECK(r.dev.produce_time(noon, 30) == errc::bad_state);
  // reset node: 1012h back to 100h, no producer
  (void)r.feed(F(0, {0x81, 5}));
  CHECK(r.dev.produce_time(noon, 40) == errc::bad_state);
}

namespace {
// the test dictionary without 1012h: no TIME in the device
constexpr auto specs_without_time = [] {
  std::array<od::entry_spec, entry_count - 1U> out{};
  std::size_t n = 0;
  for (const auto &e : specs5) {
    if (e.index != 0x1012U) out[n++] = e;
  }
  return out;
}();
constexpr auto entries_without_time = od::entries_of<specs_without_time>;
constexpr od::dictionary dict_without_time{entries_without_time};
constexpr node::capacity caps_without_time = node::capacity_for(dict_without_time);
using device_without_time = node::device<store_type, caps_without_time>;
template <class D>
concept produces_time = requires(D &d) {
  d.produce_time(noon, 0U);
};
template <class D>
concept has_time = requires(const D &d) {
  d.time();
};
} // namespace

TEST_CASE("a dictionary without 1012h: no TIME service, frames on 100h as before") {
  static_assert(!caps_without_time.time);
  static_assert(!node::capacity{}.time);
  static_assert(!produces_time<device_without_time> && !has_time<device_without_time>);
  static_assert(produces_time<device_type> && has_time<device_type>);
  static_assert(sizeof(device_without_time) < sizeof(device_type));
  constexpr auto layout = co::make_layout<entry_count - 1U>(dict_without_time);
  std::vector<std::uint8_t> storage(layout.storage_size());
  store_type store{dict_without_time, layout, storage};
  REQUIRE(store.init_defaults(5).has_value());
  device_without_time dev(store, 5);
  (void)dev.start(0).value();
  const auto s = dev.on_frame(F(0x100, noon_bytes), 1);
  CHECK(s.send.empty());
  CHECK(dev.events().empty());
}
