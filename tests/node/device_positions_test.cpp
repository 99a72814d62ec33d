// node::device over a store that shows its plain values (co::dictionary_store: its PDO engine
// copies a TPDO's plain objects from the store's bytes, and reads and writes the others by
// position, RPDO objects always through the device's rules), over a user-written store with
// positions only, and over one that models only the address interface (node_store without
// positions: by address, as before), and a device with capacity::pdo_copies off (one by one)
// sends, answers and stores the same: random RPDOs, SYNCs,
// RTRs, application values, SDO writes of mapped objects, and remappings of RPDOs and TPDOs
// over SDO while operational.
#include "node_test_util.hpp"

#include "xorshift.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

using namespace test_node;

namespace {

/// A node_store over a dictionary_store that offers only what node_store asks for.
using address_only = address_only_store<store_type>;
static_assert(node::node_store<address_only> && !co::positioned_store<address_only>);
static_assert(device_type::pdo_type::by_position);
static_assert(!node::device<address_only, caps>::pdo_type::by_position);
using positions_only = positions_only_store<store_type>;
static_assert(device_type::pdo_type::by_copy);
static_assert(node::device<positions_only, caps>::pdo_type::by_position &&
              !node::device<positions_only, caps>::pdo_type::by_copy);
/// capacity::pdo_copies off: the same store, its mapped objects one by one (by position).
inline constexpr node::capacity one_by_one_caps = [] {
  node::capacity c = caps;
  c.pdo_copies = false;
  return c;
}();
static_assert(node::device<store_type, one_by_one_caps>::pdo_type::by_position &&
              !node::device<store_type, one_by_one_caps>::pdo_type::by_copy);

struct rng : fieldcodec::test::xorshift {
  using xorshift::xorshift;
  std::uint32_t below(std::uint32_t n) { return static_cast<std::uint32_t>(next() % n); }
};

/// A device over a view `View` of a dictionary_store.
template <class View>
struct view_rig {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(layout5.storage_size());
  std::vector<std::uint8_t> staging = std::vector<std::uint8_t>(4000);
  store_type store{dict5, layout5, storage, staging};
  View view{store};
  node::device<View, caps> dev;
  view_rig() : dev(init(store, view), 5) {}
  static View &init(store_type &s, View &v) {
    REQUIRE(s.init_defaults(5).has_value());
    return v;
  }
};
using plain_rig = view_rig<address_only>;

/// A device with capacity::pdo_copies off over a dictionary_store.
struct one_by_one_rig {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(layout5.storage_size());
  std::vector<std::uint8_t> staging = std::vector<std::uint8_t>(4000);
  store_type store{dict5, layout5, storage, staging};
  node::device<store_type, one_by_one_caps> dev;
  one_by_one_rig() : dev(init(store), 5) {}
  static store_type &init(store_type &s) {
    REQUIRE(s.init_defaults(5).has_value());
    return s;
  }
};

/// An SDO expedited download request to node 5.
co::can_frame sdo_write(std::uint16_t index, std::uint8_t sub, std::uint32_t value,
                        std::size_t width) {
  std::array<std::uint8_t, 4> b{};
  for (std::size_t i = 0; i < width; ++i) b[i] = static_cast<std::uint8_t>(value >> (8U * i));
  const auto ch = sdo::channel::default_for(5).value();
  return ch.request(
      sdo::expedited_download({index, sub}, std::span<const std::uint8_t>(b).first(width)).value());
}

} // namespace

TEST_CASE("device: a store with positions and one without do the same") {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    CAPTURE(seed);
    rng r{seed * 0x9E3779B97F4A7C15ULL};
    rig<> fast;
    plain_rig plain;
    view_rig<positions_only> pos;
    one_by_one_rig one;
    std::uint32_t now = 0;
    std::size_t tpdos = 0;
    const auto same = [&](const auto &a, const auto &b, const auto &c, const auto &d) {
      REQUIRE(a.send.size() == b.send.size());
      REQUIRE(a.send.size() == c.send.size());
      REQUIRE(a.send.size() == d.send.size());
      for (std::size_t i = 0; i < a.send.size(); ++i) {
        CHECK(a.send[i] == b.send[i]);
        CHECK(a.send[i] == c.send[i]);
        CHECK(a.send[i] == d.send[i]);
        if (a.send[i].id == 0x185U || a.send[i].id == 0x285U) ++tpdos;
      }
      CHECK(a.deadline == b.deadline);
      CHECK(a.deadline == c.deadline);
      CHECK(a.deadline == d.deadline);
      CHECK(fast.storage == plain.storage);
      CHECK(fast.storage == pos.storage);
      CHECK(fast.storage == one.storage);
    };
    same(fast.dev.start(now).value(), plain.dev.start(now).value(), pos.dev.start(now).value(),
         one.dev.start(now).value());
    const auto feed = [&](const co::can_frame &f) {
      same(fast.dev.on_frame(f, now), plain.dev.on_frame(f, now), pos.dev.on_frame(f, now),
           one.dev.on_frame(f, now));
    };
    feed(F(0, {0x01, 5}));
    std::size_t rpdos = 0;
    for (int step = 0; step < 600; ++step) {
      now += r.below(3);
      const std::uint32_t op = r.below(13);
      if (op < 4) { // an RPDO (1: 2000h u32 + 2001h u16; 2: 6040h u16, synchronous)
        co::can_frame f;
        f.id = r.below(2) == 0U ? 0x205 : 0x305;
        f.dlc = static_cast<std::uint8_t>(r.below(4) == 0U ? r.below(9) : 6U);
        for (std::size_t k = 0; k < f.dlc; ++k) f.data[k] = static_cast<std::uint8_t>(r.next());
        feed(f);
        ++rpdos;
      } else if (op < 6) {
        feed(F(0x80, {}));
      } else if (op < 7) {
        feed(R(0x185, 6));
      } else if (op < 8) { // the application changes a mapped object
        const std::uint32_t v = static_cast<std::uint32_t>(r.next());
        const std::array<std::uint8_t, 4> b{
            static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8U),
            static_cast<std::uint8_t>(v >> 16U), static_cast<std::uint8_t>(v >> 24U)};
        const auto c = fast.dev.set({0x2100, 0}, b);
        CHECK(c == plain.dev.set({0x2100, 0}, b));
        CHECK(c == pos.dev.set({0x2100, 0}, b));
        CHECK(c == one.dev.set({0x2100, 0}, b));
      } else if (op < 9) { // remap RPDO 1 over SDO while operational (the CiA 301 sequence)
        const std::uint32_t objects[] = {0x2000'0020U, 0x2001'0010U, 0x2003'0008U,
                                         0x2004'0020U, 0x2002'0008U, 0x6040'0010U};
        const std::uint32_t n = 1U + r.below(3);
        feed(sdo_write(0x1400, 1, 0x8000'0205U, 4));
        feed(sdo_write(0x1600, 0, 0, 1));
        for (std::uint32_t k = 1; k <= n; ++k) {
          feed(sdo_write(0x1600, static_cast<std::uint8_t>(k), objects[r.below(6)], 4));
        }
        feed(sdo_write(0x1600, 0, n, 1));
        feed(sdo_write(0x1400, 1, 0x205U, 4));
      } else if (op < 11) { // an SDO write of an object a TPDO may map
        const std::uint16_t objects[] = {0x2100, 0x2101, 0x2103, 0x2004, 0x2003, 0x2002};
        const std::size_t widths[] = {4, 2, 1, 4, 1, 1};
        const std::size_t k = r.below(6);
        feed(sdo_write(objects[k], 0, static_cast<std::uint32_t>(r.next()) % 300U, widths[k]));
      } else if (op < 12) { // remap TPDO 2 (synchronous) over SDO while operational
        const std::uint32_t objects[] = {0x6041'0010U, 0x2100'0020U, 0x2101'0010U, 0x2102'0008U,
                                         0x2103'0008U, 0x2003'0001U, 0x2004'0020U, 0x2002'0008U};
        const std::uint32_t n = 1U + r.below(4);
        feed(sdo_write(0x1801, 1, 0x8000'0285U, 4));
        feed(sdo_write(0x1A01, 0, 0, 1));
        for (std::uint32_t k = 1; k <= n; ++k) {
          feed(sdo_write(0x1A01, static_cast<std::uint8_t>(k), objects[r.below(8)], 4));
        }
        feed(sdo_write(0x1A01, 0, n, 1));
        feed(sdo_write(0x1801, 1, 0x285U, 4));
      } else {
        same(fast.dev.poll(now), plain.dev.poll(now), pos.dev.poll(now), one.dev.poll(now));
      }
    }
    CHECK(rpdos > 100U);
    CHECK(tpdos > 100U);
  }
}

TEST_CASE("device: a TPDO remapped over SDO while operational copies the new objects, and an "
          "SDO write of a mapped object is in the next TPDO") {
  rig<> n;
  std::uint32_t now = 0;
  REQUIRE(n.dev.start(now).has_value());
  const auto feed = [&](const co::can_frame &f) { return list(n.dev.on_frame(f, ++now).send); };
  (void)feed(F(0, {0x01, 5}));
  // TPDO 2 (synchronous): 6041h → 2101h u16, 2100h u32
  CHECK(feed(sdo_write(0x1801, 1, 0x8000'0285U, 4)).size() == 1U); // the SDO answers
  (void)feed(sdo_write(0x1A01, 0, 0, 1));
  (void)feed(sdo_write(0x1A01, 1, 0x2101'0010U, 4));
  (void)feed(sdo_write(0x1A01, 2, 0x2100'0020U, 4));
  (void)feed(sdo_write(0x1A01, 0, 2, 1));
  (void)feed(sdo_write(0x1801, 1, 0x285U, 4));
  (void)feed(sdo_write(0x2100, 0, 0x1122'3344U, 4));
  (void)feed(sdo_write(0x2101, 0, 0xBEEFU, 2));
  auto sent = feed(F(0x80, {}));
  std::optional<co::can_frame> tpdo2;
  for (const auto &f : sent) {
    if (f.id == 0x285U) tpdo2 = f;
  }
  REQUIRE(tpdo2.has_value());
  CHECK(*tpdo2 == co::can_frame{0x285, false, 6, {0xEF, 0xBE, 0x44, 0x33, 0x22, 0x11}});
  // the next value, the next SYNC
  (void)feed(sdo_write(0x2100, 0, 0x0A0B'0C0DU, 4));
  sent = feed(F(0x80, {}));
  tpdo2.reset();
  for (const auto &f : sent) {
    if (f.id == 0x285U) tpdo2 = f;
  }
  REQUIRE(tpdo2.has_value());
  CHECK(*tpdo2 == co::can_frame{0x285, false, 6, {0xEF, 0xBE, 0x0D, 0x0C, 0x0B, 0x0A}});
}
