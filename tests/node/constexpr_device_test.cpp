// The whole node in a constant expression: a device over a small dictionary boots, is
// started, takes an SDO download and an RPDO, and sends its TPDO — all at compile time.
#include "node_test_util.hpp"

using namespace test_node;

namespace {
constexpr od::entry_spec tiny_entries_spec[] = {
    var(0x1000, 0, data_type::unsigned32, access::ro, 0x191),
    var(0x1001, 0, data_type::unsigned8, access::ro, 0),
    var(0x1017, 0, data_type::unsigned16, access::rw, 0),
    var(0x1400, 0, data_type::unsigned8, access::ro, 2),
    var(0x1400, 1, data_type::unsigned32, access::rw, 0x20A),
    var(0x1400, 2, data_type::unsigned8, access::rw, 255),
    var(0x1600, 0, data_type::unsigned8, access::rw, 1),
    var(0x1600, 1, data_type::unsigned32, access::rw, 0x2000'0010U),
    var(0x1800, 0, data_type::unsigned8, access::ro, 2),
    var(0x1800, 1, data_type::unsigned32, access::rw, 0x18A),
    var(0x1800, 2, data_type::unsigned8, access::rw, 255),
    var(0x1A00, 0, data_type::unsigned8, access::rw, 1),
    var(0x1A00, 1, data_type::unsigned32, access::rw, 0x2000'0010U),
    var(0x2000, 0, data_type::unsigned16, access::rw, 0, pdo_mapping::yes),
};
constexpr auto tiny_entries = od::entries_of<tiny_entries_spec>;
constexpr od::dictionary tiny{tiny_entries};
constexpr auto tiny_layout = co::make_layout<std::size(tiny_entries)>(tiny);
constexpr node::capacity tiny_caps = [] {
  auto c = node::capacity_for(tiny);
  c.sdo_buffer = 16;
  return c;
}();

constexpr bool whole_node() {
  std::array<std::uint8_t, tiny_layout.storage_size()> storage{};
  co::dictionary_store<> store{tiny, tiny_layout, storage};
  if (!store.init_defaults(10)) return false;
  node::device<co::dictionary_store<>, tiny_caps> dev(store, 10);
  auto boot = dev.start(0);
  if (!boot || boot.value().send.size() != 1 || boot.value().send[0].id != 0x70A) return false;
  // SDO: 1017h = 100 ms
  const auto ch = sdo::channel::default_for(10).value();
  const std::array<std::uint8_t, 2> period{100, 0};
  auto r = dev.on_frame(ch.request(sdo::expedited_download({0x1017, 0}, period).value()), 1);
  if (r.send.size() != 1 || r.send[0].data[0] != 0x60) return false;
  // operational: the event-driven TPDO goes out with the first poll
  (void)dev.on_frame(co::make_frame(0, {0x01, 10}).value(), 2);
  auto t = dev.poll(2);
  if (t.send.size() != 1 || t.send[0].id != 0x18A) return false;
  // RPDO 0x20A writes 2000h, which the TPDO maps: sent again
  (void)dev.on_frame(co::make_frame(0x20A, {0x34, 0x12}).value(), 3);
  t = dev.poll(3);
  if (t.send.size() != 1 || t.send[0].data[0] != 0x34 || t.send[0].data[1] != 0x12) return false;
  // the heartbeat 100 ms after the write of 1017h
  t = dev.poll(101);
  return t.send.size() == 1 && t.send[0] == co::make_frame(0x70A, {0x05}).value();
}
static_assert(whole_node());

/// device::on_frames in a constant expression: a frame for nobody, an SDO request (through the
/// run for the server), an NMT start.
constexpr bool batch_node() {
  std::array<std::uint8_t, tiny_layout.storage_size()> storage{};
  co::dictionary_store<> store{tiny, tiny_layout, storage};
  if (!store.init_defaults(10)) return false;
  node::device<co::dictionary_store<>, tiny_caps> dev(store, 10);
  if (!dev.start(0)) return false;
  const auto ch = sdo::channel::default_for(10).value();
  const std::array<std::uint8_t, 2> period{100, 0};
  const std::array<co::can_frame, 3> rx{
      co::make_frame(0x123, {1}).value(),
      ch.request(sdo::expedited_download({0x1017, 0}, period).value()),
      co::make_frame(0, {0x01, 10}).value()};
  auto b = dev.on_frames(rx, 1);
  if (b.consumed != 2U || b.last.send.size() != 1U || b.last.send[0].data[0] != 0x60) return false;
  b = dev.on_frames(std::span(rx).subspan(2), 1);
  return b.consumed == 1U && b.last.state == co::nmt::state::operational &&
         dev.events().size() == 1U && store.value({0x1017, 0}).value()[0] == 100U;
}
static_assert(batch_node());
} // namespace

TEST_CASE("device: the same sequence at run time") {
  CHECK(whole_node());
  CHECK(batch_node());
}
