// node::device over a store with positions (sdo::dictionary_store: its PDO engine reads and
// writes mapped objects by position, through the device's rules) and over a user-written store
// that models only the address interface (node_store without positions: by address, as before)
// sends, answers and stores the same: random RPDOs, SYNCs, RTRs, application values, and
// remappings over SDO while operational.
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
static_assert(node::node_store<address_only> && !sdo::positioned_store<address_only>);
static_assert(device_type::pdo_type::by_position);
static_assert(!node::device<address_only, caps>::pdo_type::by_position);

struct rng : fieldcodec::test::xorshift {
  using xorshift::xorshift;
  std::uint32_t below(std::uint32_t n) { return static_cast<std::uint32_t>(next() % n); }
};

struct plain_rig {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(layout5.storage_size());
  std::vector<std::uint8_t> staging = std::vector<std::uint8_t>(4000);
  store_type store{dict5, layout5, storage, staging};
  address_only view{store};
  node::device<address_only, caps> dev;
  plain_rig() : dev(init(store, view), 5) {}
  static address_only &init(store_type &s, address_only &v) {
    REQUIRE(s.init_defaults(5).has_value());
    return v;
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
    std::uint32_t now = 0;
    const auto same = [&](const auto &a, const auto &b) {
      REQUIRE(a.send.size() == b.send.size());
      for (std::size_t i = 0; i < a.send.size(); ++i) CHECK(a.send[i] == b.send[i]);
      CHECK(a.deadline == b.deadline);
      CHECK(fast.storage == plain.storage);
    };
    same(fast.dev.start(now).value(), plain.dev.start(now).value());
    const auto feed = [&](const co::can_frame &f) {
      same(fast.dev.on_frame(f, now), plain.dev.on_frame(f, now));
    };
    feed(F(0, {0x01, 5}));
    std::size_t rpdos = 0;
    for (int step = 0; step < 600; ++step) {
      now += r.below(3);
      const std::uint32_t op = r.below(10);
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
        CHECK(fast.dev.set({0x2100, 0}, b) == plain.dev.set({0x2100, 0}, b));
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
      } else {
        same(fast.dev.poll(now), plain.dev.poll(now));
      }
    }
    CHECK(rpdos > 100U);
  }
}
