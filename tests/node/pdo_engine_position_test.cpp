// The PDO engine by position (issue 18, round 4): over a store that models
// sdo::positioned_store the engine looks each mapped object up once, when a mapping is loaded
// (reload, or a write of mapping sub 0), and then reads and writes it with read_at / write_at.
// A store that models only the address interface (read / begin_write / write) still works, by
// address, as before. The differential test runs both on the same random configurations,
// remappings, values and traffic and compares every frame, event, answer and stored byte: the
// address path is the reference (it is the engine's code before the change, kept for such
// stores).
#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/canopen/node/pdo_engine.hpp>
#include <fieldcodec/canopen/object_store.hpp>

#include <doctest/doctest.h>

#include "node_test_util.hpp"

#include "xorshift.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

namespace {

namespace co = fieldcodec::canopen;
namespace node = fieldcodec::canopen::node;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
using sdo::abort_code;

constexpr od::number U(std::uint64_t v) { return {od::number_kind::unsigned_, 0, v}; }

constexpr od::entry var(std::uint16_t index, std::uint8_t sub, od::data_type t, od::access a,
                        std::uint64_t def, od::pdo_mapping p = od::pdo_mapping::no) {
  return {
      .index = index, .sub = sub, .type = t, .access_type = a, .pdo = p, .default_value = U(def)};
}
constexpr od::entry limited(std::uint16_t index, od::data_type t, std::uint64_t low,
                            std::uint64_t high) {
  od::entry e = var(index, 0, t, od::access::rw, low, od::pdo_mapping::yes);
  e.low = U(low);
  e.high = U(high);
  return e;
}
constexpr od::entry bytes(std::uint16_t index, od::data_type t, std::uint32_t size) {
  od::entry e = var(index, 0, t, od::access::rw, 0, od::pdo_mapping::yes);
  e.size = size;
  return e;
}

using od::data_type;
constexpr auto rw = od::access::rw;
constexpr auto yes = od::pdo_mapping::yes;

/// Two RPDOs and two TPDOs of up to 8 entries, and application objects of every kind a mapping
/// can meet: integers of each width and sign, BOOLEAN, limits, strings, a REAL32 (NaN is
/// refused), read-only, write-only, not mappable, mappable in one direction only.
constexpr std::size_t n_entries = 2 * (5 + 9) + 2 * (6 + 9) + 17;
constexpr std::array<od::entry, n_entries> make_entries() {
  std::array<od::entry, n_entries> e{};
  std::size_t i = 0;
  const auto u8 = data_type::unsigned8;
  const auto u16 = data_type::unsigned16;
  const auto u32 = data_type::unsigned32;
  for (std::uint16_t k = 0; k < 2; ++k) {
    const auto comm = static_cast<std::uint16_t>(0x1400U + k);
    e[i++] = var(comm, 0, u8, od::access::ro, 5);
    e[i++] = var(comm, 1, u32, rw, 0x201U + k);
    e[i++] = var(comm, 2, u8, rw, 255);
    e[i++] = var(comm, 3, u16, rw, 0);
    e[i++] = var(comm, 5, u16, rw, 0);
  }
  for (std::uint16_t k = 0; k < 2; ++k) {
    const auto map = static_cast<std::uint16_t>(0x1600U + k);
    e[i++] = var(map, 0, u8, rw, k == 0U ? 2U : 0U);
    for (std::uint8_t s = 1; s <= 8; ++s) {
      e[i++] = var(map, s, u32, rw,
                   k == 0U && s == 1U   ? 0x2001'0010U
                   : k == 0U && s == 2U ? 0x2002'0020U
                                        : 0U);
    }
  }
  for (std::uint16_t k = 0; k < 2; ++k) {
    const auto comm = static_cast<std::uint16_t>(0x1800U + k);
    e[i++] = var(comm, 0, u8, od::access::ro, 6);
    e[i++] = var(comm, 1, u32, rw, 0x181U + k);
    e[i++] = var(comm, 2, u8, rw, k == 0U ? 1U : 254U);
    e[i++] = var(comm, 3, u16, rw, 0);
    e[i++] = var(comm, 5, u16, rw, 0);
    e[i++] = var(comm, 6, u8, rw, 0);
  }
  for (std::uint16_t k = 0; k < 2; ++k) {
    const auto map = static_cast<std::uint16_t>(0x1A00U + k);
    e[i++] = var(map, 0, u8, rw, k == 0U ? 3U : 0U);
    for (std::uint8_t s = 1; s <= 8; ++s) {
      e[i++] = var(map, s, u32, rw,
                   k == 0U && s == 1U   ? 0x2006'0001U
                   : k == 0U && s == 2U ? 0x2003'0008U
                   : k == 0U && s == 3U ? 0x2005'0020U
                                        : 0U);
    }
  }
  e[i++] = var(0x2000, 0, u8, rw, 0, yes);
  e[i++] = var(0x2001, 0, u16, rw, 0, yes);
  e[i++] = var(0x2002, 0, u32, rw, 0, yes);
  e[i++] = var(0x2003, 0, data_type::integer8, rw, 0, yes);
  e[i++] = var(0x2004, 0, data_type::integer16, rw, 0, yes);
  e[i++] = var(0x2005, 0, data_type::integer32, rw, 0, yes);
  e[i++] = var(0x2006, 0, data_type::boolean, rw, 0, yes);
  e[i++] = var(0x2007, 0, data_type::unsigned64, rw, 0, yes);
  e[i++] = var(0x2008, 0, data_type::integer24, rw, 0, yes);
  e[i++] = limited(0x2009, u16, 10, 1000);
  e[i++] = bytes(0x200A, data_type::visible_string, 4);
  e[i++] = bytes(0x200B, data_type::octet_string, 3);
  e[i++] = var(0x200C, 0, u8, od::access::ro, 7, yes);
  e[i++] = var(0x200D, 0, u16, od::access::wo, 0, yes);
  e[i++] = var(0x200E, 0, u32, rw, 0);
  e[i++] = var(0x200F, 0, data_type::real32, rw, 0, yes);
  e[i++] = var(0x2010, 0, u8, rw, 0, od::pdo_mapping::rx);
  return e;
}
constexpr std::array<od::entry, n_entries> entries = [] {
  auto e = make_entries();
  for (std::size_t i = 1; i < e.size(); ++i) { // insertion sort by (index, sub)
    for (std::size_t k = i; k > 0 && (e[k].index < e[k - 1].index ||
                                      (e[k].index == e[k - 1].index && e[k].sub < e[k - 1].sub));
         --k) {
      const od::entry t = e[k];
      e[k] = e[k - 1];
      e[k - 1] = t;
    }
  }
  return e;
}();
constexpr od::dictionary dict{entries};
static_assert(dict.is_valid());
constexpr auto layout = sdo::make_layout<n_entries>(dict);

/// The application's write hook: refuses 2001h = 0x..42 (RPDO data like SDO data).
struct refuse_42 {
  [[nodiscard]] constexpr abort_code operator()(const od::entry &e,
                                                std::span<const std::uint8_t> v) const noexcept {
    return e.index == 0x2001U && !v.empty() && v[0] == 0x42U ? abort_code::invalid_value
                                                             : abort_code::none;
  }
};
using store_type = sdo::dictionary_store<refuse_42>;

/// A user-written store that models only the address interface: the engine must use it by
/// address.
using address_only = test_node::address_only_store<store_type>;

static_assert(sdo::positioned_store<store_type>);
static_assert(sdo::positioned_store<sdo::dictionary_store<>>);
static_assert(sdo::object_store<address_only> && !sdo::positioned_store<address_only>);

using fast_engine = node::pdo_engine<store_type, 2, 2, 8>;
using address_engine = node::pdo_engine<address_only, 2, 2, 8>;
static_assert(fast_engine::by_position);
static_assert(!address_engine::by_position);
// node::device hands its store's positions on to its engine
static_assert(node::device<store_type>::pdo_type::by_position);

struct rng : fieldcodec::test::xorshift {
  using xorshift::xorshift;
  std::uint32_t below(std::uint32_t n) { return static_cast<std::uint32_t>(next() % n); }
  bool one_in(std::uint32_t n) { return below(n) == 0U; }
};

std::array<std::uint8_t, 4> le32(std::uint32_t v) {
  return {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8U),
          static_cast<std::uint8_t>(v >> 16U), static_cast<std::uint8_t>(v >> 24U)};
}

/// One store and one engine over it: the engine by position (Fast) or by address.
template <bool Fast>
struct side {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(layout.storage_size());
  store_type store{dict, layout, storage};
  address_only view{store};
  std::conditional_t<Fast, fast_engine, address_engine> engine = make();

  side() { REQUIRE(store.init_defaults(1).has_value()); }
  auto make() {
    if constexpr (Fast) {
      return fast_engine(store, dict);
    } else {
      return address_engine(view, dict);
    }
  }
  /// A parameter write the way node::device makes it: check, store, follow.
  abort_code param(od::address a, std::span<const std::uint8_t> v, std::uint32_t now) {
    if (const auto c = engine.check_write(a, v); c != abort_code::none) return c;
    const auto c = store.write(a, 0, v, true);
    if (c == abort_code::none) engine.written(a, v, now);
    return c;
  }
};

/// What the random runs exercised (checked at the end: the inputs must keep reaching every path).
struct coverage {
  std::size_t frames = 0;    ///< TPDOs sent
  std::size_t received = 0;  ///< RPDOs written with every object taken
  std::size_t refused = 0;   ///< RPDOs with objects the store refused
  std::size_t too_short = 0; ///< RPDOs shorter than their mapping
  std::size_t remapped = 0;  ///< mappings of one entry or more taken while running
  std::size_t off_byte = 0;  ///< PDOs served with an entry off byte boundaries
};
coverage seen;

/// Both engines did the same: frames, step state and deadline, events, stored bytes.
void compare(const auto &f, const auto &a, const side<true> &fast, const side<false> &ref) {
  seen.frames += f.send.size();
  for (const auto &ev : fast.engine.events()) {
    if (ev.what == node::pdo_event::kind::received)
      ++(ev.refused == 0U ? seen.received : seen.refused);
    if (ev.what == node::pdo_event::kind::too_short) ++seen.too_short;
  }
  for (std::size_t k = 0; k < 2; ++k) {
    for (const auto *c : {&fast.engine.rpdo(k), &fast.engine.tpdo(k)}) {
      std::size_t bits = 0;
      for (const auto &m : c->entries()) bits += m.bits;
      if (c->valid() && bits % 8U != 0U && !f.send.empty()) ++seen.off_byte;
    }
  }
  REQUIRE(f.send.size() == a.send.size());
  for (std::size_t i = 0; i < f.send.size(); ++i) CHECK(f.send[i] == a.send[i]);
  CHECK(f.state == a.state);
  CHECK(f.deadline == a.deadline);
  const auto fe = fast.engine.events();
  const auto re = ref.engine.events();
  REQUIRE(fe.size() == re.size());
  for (std::size_t i = 0; i < fe.size(); ++i) CHECK(fe[i] == re[i]);
  CHECK(fast.storage == ref.storage);
}

/// A random mapping entry: mostly valid ones, some of a wrong length, unknown or not mappable
/// objects, dummies, BOOLEANs of 1 bit (which put the entries after them off byte boundaries).
std::uint32_t random_entry(rng &r) {
  struct candidate {
    std::uint16_t index;
    std::uint8_t bits;
  };
  static constexpr std::array<candidate, 22> c{
      {{0x2000, 8},  {0x2001, 16}, {0x2002, 32}, {0x2003, 8},  {0x2004, 16}, {0x2005, 32},
       {0x2006, 1},  {0x2006, 8},  {0x2007, 64}, {0x2008, 24}, {0x2009, 16}, {0x200A, 32},
       {0x200A, 16}, {0x200B, 24}, {0x200B, 8},  {0x200C, 8},  {0x200D, 16}, {0x200E, 32},
       {0x200F, 32}, {0x2010, 8},  {0x0005, 8},  {0x0001, 1}}};
  if (r.one_in(12)) return static_cast<std::uint32_t>(r.next()); // anything at all
  const candidate k = c[r.below(c.size())];
  const std::uint32_t bits = r.one_in(15) ? r.below(40) : k.bits;
  const std::uint32_t index = r.one_in(20) ? 0x2011U : k.index;
  return (index << 16U) | bits;
}

template <class F>
void both(side<true> &fast, side<false> &ref, F f) {
  const auto a = f(fast);
  const auto b = f(ref);
  CHECK(a == b);
}

/// Remap PDO `k` (0, 1) of direction `rx` in the CiA 301 sequence (with random deviations) on
/// both sides, comparing every answer.
void remap(rng &r, side<true> &fast, side<false> &ref, bool rx, std::uint16_t k,
           std::uint32_t now) {
  const auto comm = static_cast<std::uint16_t>((rx ? 0x1400U : 0x1800U) + k);
  const auto map = static_cast<std::uint16_t>((rx ? 0x1600U : 0x1A00U) + k);
  const std::uint32_t id = (rx ? 0x201U : 0x181U) + k;
  auto w = [&](od::address a, std::uint32_t v, std::size_t len) {
    const auto b = le32(v);
    const auto s = std::span<const std::uint8_t>(b).first(len);
    both(fast, ref, [&](auto &side) { return side.param(a, s, now); });
  };
  if (!r.one_in(10)) w({comm, 1}, id | 0x8000'0000U, 4);
  if (!r.one_in(10)) w({map, 0}, 0, 1);
  const std::uint32_t n = r.below(9);
  for (std::uint32_t s = 1; s <= n; ++s) w({map, static_cast<std::uint8_t>(s)}, random_entry(r), 4);
  w({map, 0}, r.one_in(10) ? r.below(10) : n, 1);
  const auto &c = rx ? fast.engine.rpdo(k) : fast.engine.tpdo(k);
  if (c.count != 0U) ++seen.remapped;
  if (r.one_in(3)) {
    std::uint32_t type = 0;
    const std::uint32_t pick = r.below(6);
    if (pick == 0U)
      type = 0;
    else if (pick == 1U)
      type = 1U + r.below(3);
    else if (pick == 2U)
      type = rx ? 254U : 252U + r.below(2);
    else
      type = 254U + r.below(2);
    w({comm, 2}, type, 1);
  }
  if (r.one_in(4)) w({comm, 5}, r.below(20), 2);
  if (!rx && r.one_in(4)) w({comm, 3}, r.below(30), 2);
  if (!r.one_in(8)) w({comm, 1}, id | (!rx && r.one_in(4) ? 0x4000'0000U : 0U), 4);
}

/// Random application values into the objects a TPDO may map (set, like the application), and
/// mark them.
void set_values(rng &r, side<true> &fast, side<false> &ref) {
  for (std::uint16_t index = 0x2000; index <= 0x2010; ++index) {
    if (!r.one_in(3)) continue;
    const od::entry *e = dict.find(index, 0);
    REQUIRE(e != nullptr);
    std::array<std::uint8_t, 8> v{};
    for (auto &b : v) b = static_cast<std::uint8_t>(r.next());
    if (e->type == data_type::boolean) v[0] = static_cast<std::uint8_t>(v[0] & 1U);
    const std::size_t n = od::is_byte_string(e->type) ? r.below(e->size + 1U) : e->width();
    const auto s = std::span<const std::uint8_t>(v).first(n);
    both(fast, ref, [&](auto &side) { return side.store.set({index, 0}, s); });
    fast.engine.mark({index, 0});
    ref.engine.mark({index, 0});
  }
}

void run(std::uint64_t seed, std::size_t steps) {
  rng r{seed};
  side<true> fast;
  side<false> ref;
  both(fast, ref, [](auto &side) { return side.engine.reload(); });
  std::uint32_t now = 0;
  for (std::size_t i = 0; i < steps; ++i) {
    now += r.below(4);
    const std::uint32_t op = r.below(100);
    if (op < 12) {
      remap(r, fast, ref, r.one_in(2), static_cast<std::uint16_t>(r.below(2)), now);
    } else if (op < 30) {
      set_values(r, fast, ref);
    } else if (op < 50) {
      std::optional<std::uint8_t> counter;
      if (r.one_in(2)) counter = static_cast<std::uint8_t>(1U + r.below(4));
      const auto a = fast.engine.on_sync(counter, now);
      const auto b = ref.engine.on_sync(counter, now);
      compare(a, b, fast, ref);
    } else if (op < 80) {
      co::can_frame f;
      f.id = static_cast<std::uint16_t>(r.one_in(10) ? r.below(0x800) : 0x201U + r.below(2));
      f.dlc = static_cast<std::uint8_t>(r.one_in(4) ? r.below(9) : 8U);
      for (std::size_t k = 0; k < f.dlc; ++k) f.data[k] = static_cast<std::uint8_t>(r.next());
      if (r.one_in(8)) f.data[0] = 0x42; // the hook refuses 2001h = 0x..42
      const bool window = !r.one_in(8);
      const auto a = fast.engine.on_frame(f, now, window);
      const auto b = ref.engine.on_frame(f, now, window);
      compare(a, b, fast, ref);
    } else if (op < 86) {
      co::can_frame f;
      f.id = static_cast<std::uint16_t>(0x181U + r.below(2));
      f.rtr = true;
      const auto a = fast.engine.on_frame(f, now);
      const auto b = ref.engine.on_frame(f, now);
      compare(a, b, fast, ref);
    } else if (op < 96) {
      const auto a = fast.engine.poll(now);
      const auto b = ref.engine.poll(now);
      compare(a, b, fast, ref);
    } else if (op < 98) {
      const bool on = !r.one_in(4);
      fast.engine.set_operational(on, now);
      ref.engine.set_operational(on, now);
    } else {
      both(fast, ref, [](auto &side) { return side.engine.reload(); });
    }
    CHECK(fast.storage == ref.storage);
    for (std::size_t k = 0; k < 2; ++k) {
      CHECK(fast.engine.rpdo(k).count == ref.engine.rpdo(k).count);
      CHECK(fast.engine.tpdo(k).count == ref.engine.tpdo(k).count);
      CHECK(fast.engine.rpdo(k).valid() == ref.engine.rpdo(k).valid());
      CHECK(fast.engine.tpdo(k).valid() == ref.engine.tpdo(k).valid());
    }
  }
}

} // namespace

TEST_CASE("pdo engine by position == by address: random mappings, remaps, values, traffic") {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    CAPTURE(seed);
    run(seed * 0x9E3779B97F4A7C15ULL, 1500);
  }
  MESSAGE("frames ", seen.frames, ", received ", seen.received, ", with refusals ", seen.refused,
          ", too short ", seen.too_short, ", remapped ", seen.remapped, ", off byte boundaries ",
          seen.off_byte);
  CHECK(seen.frames > 1000U);
  CHECK(seen.received > 1000U);
  CHECK(seen.refused > 100U);
  CHECK(seen.too_short > 100U);
  CHECK(seen.remapped > 200U);
  CHECK(seen.off_byte > 100U);
}

TEST_CASE("pdo engine by position: remapping while operational uses the new mapping") {
  side<true> s;
  REQUIRE(s.engine.reload().has_value());
  s.engine.set_operational(true, 0);
  // TPDO 1 (type 1): BOOLEAN 1 bit, 2003h i8, 2005h i32
  REQUIRE(s.store.set({0x2003, 0}, std::array<std::uint8_t, 1>{0x11}) == abort_code::none);
  REQUIRE(s.store.set({0x2005, 0}, std::array<std::uint8_t, 4>{1, 2, 3, 4}) == abort_code::none);
  REQUIRE(s.store.set({0x2000, 0}, std::array<std::uint8_t, 1>{0x77}) == abort_code::none);
  auto st = s.engine.on_sync(std::nullopt, 1);
  REQUIRE(st.send.size() == 1);
  CHECK(st.send[0].dlc == 6);
  CHECK(st.send[0].data[0] == 0x22); // 0x11 << 1: the entries after the BOOLEAN are off by a bit
  // remap it to 2000h u8, then 2003h i8: every SYNC after the write of sub 0 sends the new data
  const auto w = [&](od::address a, std::uint32_t v, std::size_t len) {
    const auto b = le32(v);
    return s.param(a, std::span<const std::uint8_t>(b).first(len), 2);
  };
  REQUIRE(w({0x1800, 1}, 0x8000'0181U, 4) == abort_code::none);
  CHECK(s.engine.on_sync(std::nullopt, 2).send.empty()); // invalid: not sent
  REQUIRE(w({0x1A00, 0}, 0, 1) == abort_code::none);
  REQUIRE(w({0x1A00, 1}, 0x2000'0008U, 4) == abort_code::none);
  REQUIRE(w({0x1A00, 2}, 0x2003'0008U, 4) == abort_code::none);
  REQUIRE(w({0x1A00, 0}, 2, 1) == abort_code::none);
  REQUIRE(w({0x1800, 1}, 0x181U, 4) == abort_code::none);
  st = s.engine.on_sync(std::nullopt, 3);
  REQUIRE(st.send.size() == 1);
  CHECK(st.send[0] == co::can_frame{0x181, false, 2, {0x77, 0x11}});
  // the RPDO 1 (2001h u16, 2002h u32) remapped to 2002h u32, 2001h u16 while operational
  co::can_frame in{0x201, false, 6, {1, 0, 2, 0, 0, 0}};
  (void)s.engine.on_frame(in, 4);
  CHECK(s.store.value({0x2001, 0}).value()[0] == 1);
  CHECK(s.store.value({0x2002, 0}).value()[0] == 2);
  REQUIRE(w({0x1400, 1}, 0x8000'0201U, 4) == abort_code::none);
  REQUIRE(w({0x1600, 0}, 0, 1) == abort_code::none);
  REQUIRE(w({0x1600, 1}, 0x2002'0020U, 4) == abort_code::none);
  REQUIRE(w({0x1600, 2}, 0x2001'0010U, 4) == abort_code::none);
  REQUIRE(w({0x1600, 0}, 2, 1) == abort_code::none);
  REQUIRE(w({0x1400, 1}, 0x201U, 4) == abort_code::none);
  in = co::can_frame{0x201, false, 6, {5, 0, 0, 0, 6, 0}};
  (void)s.engine.on_frame(in, 5);
  CHECK(s.store.value({0x2002, 0}).value()[0] == 5);
  CHECK(s.store.value({0x2001, 0}).value()[0] == 6);
  REQUIRE(s.engine.events().size() == 1);
  CHECK(s.engine.events()[0].refused == 0);
}

TEST_CASE("pdo engine by position: an object the store lacks is refused / not sent") {
  // the engine checks mappings against its dictionary; a store over a smaller dictionary has no
  // position for 2002h: the RPDO counts it refused, the TPDO is not sent (as by address)
  auto small_entries = entries;
  std::size_t n = 0;
  for (const auto &e : entries) {
    if (e.index != 0x2002U) small_entries[n++] = e;
  }
  const od::dictionary small{std::span<const od::entry>(small_entries).first(n)};
  std::vector<std::uint8_t> storage(store_type::storage_size(small));
  REQUIRE(n == n_entries - 1U);
  const auto lay = sdo::make_layout<n_entries - 1U>(small);
  store_type store{small, lay, storage};
  REQUIRE(store.init_defaults(1).has_value());
  CHECK(store.position({0x2002, 0}) == sdo::no_position);
  fast_engine e(store, dict); // RPDO 1 maps 2001h and 2002h
  REQUIRE(e.reload().has_value());
  e.set_operational(true, 0);
  (void)e.on_frame(co::can_frame{0x201, false, 6, {3, 0, 4, 0, 0, 0}}, 1);
  REQUIRE(e.events().size() == 1);
  CHECK(e.events()[0].what == node::pdo_event::kind::received);
  CHECK(e.events()[0].refused == 1);
  CHECK(store.value({0x2001, 0}).value()[0] == 3);
  // TPDO 2 (type 254) mapped to 2002h after the fact
  const auto w = [&](od::address a, std::uint32_t v, std::size_t len) {
    const auto b = le32(v);
    const auto sp = std::span<const std::uint8_t>(b).first(len);
    REQUIRE(e.check_write(a, sp) == abort_code::none);
    REQUIRE(store.write(a, 0, sp, true) == abort_code::none);
    e.written(a, sp, 2);
  };
  w({0x1801, 1}, 0x8000'0182U, 4);
  w({0x1A01, 1}, 0x2002'0020U, 4);
  w({0x1A01, 0}, 1, 1);
  w({0x1801, 1}, 0x182U, 4);
  (void)e.poll(3);
  bool not_sent = false;
  for (const auto &ev : e.events()) {
    if (ev.what == node::pdo_event::kind::not_sent && ev.number == 2) not_sent = true;
  }
  CHECK(not_sent);
}
