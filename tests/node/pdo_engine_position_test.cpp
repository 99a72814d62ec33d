// The PDO engine by position (issue 18, round 4): over a store that models
// co::positioned_store the engine looks each mapped object up once, when a mapping is loaded
// (reload, or a write of mapping sub 0), and then reads and writes it with read_at / write_at.
// A store that models only the address interface (read / begin_write / write) still works, by
// address, as before. The differential test runs both on the same random configurations,
// remappings, values and traffic and compares every frame, event, answer and stored byte: the
// address path is the reference (it is the engine's code before the change, kept for such
// stores). Since round 6 it runs a fourth engine, the round-5 engine as it was
// (pdo_engine_r5_reference.hpp), which scans every PDO's parameters on every SYNC and frame where
// the engine now tests what reindex() derived from them; random writes of every communication
// parameter between the steps would show a stale derivation as a difference, and every engine's
// derived_current() is checked after every step.
#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/canopen/node/pdo_engine.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <doctest/doctest.h>

#include "node_test_util.hpp"
#include "pdo_engine_r5_reference.hpp"

#include "xorshift.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

namespace {

namespace co = fieldcodec::canopen;
namespace node = fieldcodec::canopen::node;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
namespace pdo = fieldcodec::canopen::pdo;
using sdo::abort_code;

constexpr od::number U(std::uint64_t v) { return {od::number_kind::unsigned_, 0, v}; }

constexpr od::entry_spec var(std::uint16_t index, std::uint8_t sub, od::data_type t, od::access a,
                             std::uint64_t def, od::pdo_mapping p = od::pdo_mapping::no) {
  return {
      .index = index, .sub = sub, .type = t, .access_type = a, .pdo = p, .default_value = U(def)};
}
constexpr od::entry_spec limited(std::uint16_t index, od::data_type t, std::uint64_t low,
                                 std::uint64_t high) {
  od::entry_spec e = var(index, 0, t, od::access::rw, low, od::pdo_mapping::yes);
  e.low = U(low);
  e.high = U(high);
  return e;
}
constexpr od::entry_spec bytes(std::uint16_t index, od::data_type t, std::uint32_t size) {
  od::entry_spec e = var(index, 0, t, od::access::rw, 0, od::pdo_mapping::yes);
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
constexpr std::array<od::entry_spec, n_entries> make_entries() {
  std::array<od::entry_spec, n_entries> e{};
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
constexpr std::array<od::entry_spec, n_entries> entry_specs = [] {
  auto e = make_entries();
  for (std::size_t i = 1; i < e.size(); ++i) { // insertion sort by (index, sub)
    for (std::size_t k = i; k > 0 && (e[k].index < e[k - 1].index ||
                                      (e[k].index == e[k - 1].index && e[k].sub < e[k - 1].sub));
         --k) {
      const od::entry_spec t = e[k];
      e[k] = e[k - 1];
      e[k - 1] = t;
    }
  }
  return e;
}();
constexpr auto entries = od::entries_of<entry_specs>;
constexpr od::dictionary dict{entries};
static_assert(dict.is_valid());
constexpr auto layout = co::make_layout<n_entries>(dict);

/// The application's write hook: refuses 2001h = 0x..42 (RPDO data like SDO data).
struct refuse_42 {
  [[nodiscard]] constexpr abort_code operator()(const od::entry &e,
                                                std::span<const std::uint8_t> v) const noexcept {
    return e.index == 0x2001U && !v.empty() && v[0] == 0x42U ? abort_code::invalid_value
                                                             : abort_code::none;
  }
};
using store_type = co::dictionary_store<refuse_42>;
/// A store without a write hook: RPDO objects that take any bits are copied, not written.
using plain_type = co::dictionary_store<>;

/// A user-written store that models only the address interface: the engine must use it by
/// address.
using address_only = test_node::address_only_store<store_type>;

static_assert(co::positioned_store<store_type>);
static_assert(co::positioned_store<co::dictionary_store<>>);
static_assert(co::object_store<address_only> && !co::positioned_store<address_only>);
static_assert(co::plain_store<store_type> && co::plain_store<plain_type>);
static_assert(co::positioned_store<test_node::positions_only_store<store_type>> &&
              !co::plain_store<test_node::positions_only_store<store_type>>);

using fast_engine = node::pdo_engine<store_type, 2, 2, 8>;
using address_engine = node::pdo_engine<address_only, 2, 2, 8>;
using position_engine = node::pdo_engine<test_node::positions_only_store<store_type>, 2, 2, 8>;
static_assert(fast_engine::by_position && fast_engine::by_copy);
static_assert(position_engine::by_position && !position_engine::by_copy);
static_assert(!address_engine::by_position && !address_engine::by_copy);
// node::device hands its store's positions on to its engine, and its plain values (read only)
static_assert(node::device<store_type>::pdo_type::by_position);
static_assert(node::device<store_type>::pdo_type::by_copy);

struct rng : fieldcodec::test::xorshift {
  using xorshift::xorshift;
  std::uint32_t below(std::uint32_t n) { return static_cast<std::uint32_t>(next() % n); }
  bool one_in(std::uint32_t n) { return below(n) == 0U; }
};

std::array<std::uint8_t, 4> le32(std::uint32_t v) {
  return {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8U),
          static_cast<std::uint8_t>(v >> 16U), static_cast<std::uint8_t>(v >> 24U)};
}

/// How an engine reaches the mapped objects: compiled copies (the store itself, a plain_store),
/// by position (a store that offers positions only), by address (a store without positions:
/// the engine's code before round 4, the reference).
enum class path { copy, position, address };

/// One store and one engine over it, reaching the store by path P; the store's write hook Hook.
/// Round5: the round-5 engine (the reference for what the engine derives from its parameters).
template <path P, class Hook = refuse_42, bool Round5 = false>
struct side {
  using store_t = co::dictionary_store<Hook>;
  using view_t = std::conditional_t<P == path::address, test_node::address_only_store<store_t>,
                                    test_node::positions_only_store<store_t>>;
  using reached_t = std::conditional_t<P == path::copy, store_t, view_t>;
  using engine_t = std::conditional_t<Round5, node::r5::pdo_engine<reached_t, 2, 2, 8>,
                                      node::pdo_engine<reached_t, 2, 2, 8>>;
  static_assert(engine_t::by_copy == (P == path::copy));
  static_assert(engine_t::by_position == (P != path::address));

  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(layout.storage_size());
  store_t store{dict, layout, storage};
  view_t view{store};
  engine_t engine = make();

  side() { REQUIRE(store.init_defaults(1).has_value()); }
  engine_t make() {
    if constexpr (P == path::copy) {
      return engine_t(store, dict);
    } else {
      return engine_t(view, dict);
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

/// The three engines over three stores that start alike, and the round-5 engine (compiled).
template <class Hook>
struct trio {
  side<path::copy, Hook> c;
  side<path::position, Hook> p;
  side<path::address, Hook> a;
  side<path::copy, Hook, true> r5;
};

/// What the random runs exercised (checked at the end: the inputs must keep reaching every path).
struct coverage {
  std::size_t frames = 0;      ///< TPDOs sent
  std::size_t received = 0;    ///< RPDOs written with every object taken
  std::size_t refused = 0;     ///< RPDOs with objects the store refused
  std::size_t too_short = 0;   ///< RPDOs shorter than their mapping
  std::size_t remapped = 0;    ///< mappings of one entry or more taken while running
  std::size_t off_byte = 0;    ///< PDOs served with an entry off byte boundaries
  std::size_t tx_copied = 0;   ///< entries of sent TPDOs the compiled engine copied
  std::size_t rx_copied = 0;   ///< entries of received RPDOs the compiled engine copied
  std::size_t tx_object = 0;   ///< entries of sent TPDOs read by position
  std::size_t rx_object = 0;   ///< entries of received RPDOs written by position
  std::size_t mixed = 0;       ///< PDOs served with copies and per-object entries together
  std::size_t merged = 0;      ///< PDOs served with adjacent plain entries (one run)
  std::size_t sent_copied = 0; ///< TPDOs sent whose every entry was copied
};
coverage seen;

/// Whether PDO k maps two plain entries one after the other, adjacent in the store's bytes:
/// the engine copies them as one run (a model of compile(), for the coverage count only).
bool has_run(const auto &side, pdo::direction d, std::size_t k) {
  const auto &c = d == pdo::direction::rpdo ? side.engine.rpdo(k) : side.engine.tpdo(k);
  std::size_t bit = 0;
  std::optional<co::plain_slot> last;
  for (const auto &m : c.entries()) {
    const std::size_t at = side.store.position({m.index, m.sub});
    const auto p = at == co::no_position ? co::plain_slot{} : side.store.plain_at(at);
    const bool plain = !m.is_dummy() && bit % 8U == 0U && m.bits % 8U == 0U && p.size != 0U &&
                       p.size * 8U == m.bits &&
                       (d == pdo::direction::rpdo ? p.writable : p.readable);
    if (plain && last && last->offset + last->size == p.offset) return true;
    last = plain ? std::optional<co::plain_slot>(p) : std::nullopt;
    bit += m.bits;
  }
  return false;
}

void count_plan(const auto &side, pdo::direction d, std::size_t k, std::size_t &copied,
                std::size_t &object) {
  const auto plan = side.engine.compiled_plan(d, k);
  copied += plan.copied;
  object += plan.per_object;
  if (plan.copied != 0U && plan.per_object != 0U) ++seen.mixed;
  if (has_run(side, d, k)) ++seen.merged;
}

/// The engines did the same: frames, step state and deadline, events, stored bytes.
template <class Hook>
void compare(const auto &sc, const auto &sp, const auto &sa, const auto &sr, const trio<Hook> &t,
             std::uint32_t now) {
  const auto &e = t.c.engine;
  seen.frames += sc.send.size();
  for (const auto &f : sc.send) {
    for (std::size_t k = 0; k < 2; ++k) {
      if (e.tpdo(k).valid() && e.tpdo(k).id() == f.id) {
        count_plan(t.c, pdo::direction::tpdo, k, seen.tx_copied, seen.tx_object);
        const auto plan = e.compiled_plan(pdo::direction::tpdo, k);
        if (plan.per_object == 0U && plan.copied != 0U) ++seen.sent_copied;
      }
    }
  }
  for (const auto &ev : e.events()) {
    if (ev.what == node::pdo_event::kind::received) {
      ++(ev.refused == 0U ? seen.received : seen.refused);
      count_plan(t.c, pdo::direction::rpdo, ev.number - 1U, seen.rx_copied, seen.rx_object);
    }
    if (ev.what == node::pdo_event::kind::too_short) ++seen.too_short;
  }
  for (std::size_t k = 0; k < 2; ++k) {
    for (const auto *c : {&e.rpdo(k), &e.tpdo(k)}) {
      std::size_t bits = 0;
      for (const auto &m : c->entries()) bits += m.bits;
      if (c->valid() && bits % 8U != 0U && !sc.send.empty()) ++seen.off_byte;
    }
  }
  // the step's deadline is the engine's (a step need not scan for it when nothing is timed)
  CHECK(sc.deadline == e.deadline(now));
  for (const auto *other : {&sp, &sa, &sr}) {
    REQUIRE(sc.send.size() == other->send.size());
    for (std::size_t i = 0; i < sc.send.size(); ++i) CHECK(sc.send[i] == other->send[i]);
    CHECK(sc.state == other->state);
    CHECK(sc.deadline == other->deadline);
  }
  const auto ce = e.events();
  for (const auto ref : {t.p.engine.events(), t.a.engine.events(), t.r5.engine.events()}) {
    REQUIRE(ce.size() == ref.size());
    for (std::size_t i = 0; i < ce.size(); ++i) CHECK(ce[i] == ref[i]);
  }
  CHECK(t.c.storage == t.p.storage);
  CHECK(t.c.storage == t.a.storage);
  CHECK(t.c.storage == t.r5.storage);
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

/// f on each side; every side answers the same.
template <class Hook, class F>
void all(trio<Hook> &t, F f) {
  const auto a = f(t.c);
  CHECK(a == f(t.p));
  CHECK(a == f(t.a));
  CHECK(a == f(t.r5));
}

/// One step on every engine, compared; the compiled engine's step.
template <class Hook, class F>
auto step_all(trio<Hook> &t, std::uint32_t now, F f) {
  const auto sc = f(t.c.engine);
  const auto sp = f(t.p.engine);
  const auto sa = f(t.a.engine);
  const auto sr = f(t.r5.engine);
  compare(sc, sp, sa, sr, t, now);
  return sc;
}

/// What the random runs did to the communication parameters (checked at the end).
struct param_coverage {
  std::size_t taken = 0;      ///< writes accepted
  std::size_t refused = 0;    ///< writes refused (CiA 301 rules)
  std::size_t shared_id = 0;  ///< RPDO frames that two valid RPDOs took (the same COB-ID)
  std::size_t sync_start = 0; ///< TPDOs that waited for their SYNC start value and were sent
};
param_coverage params_seen;

/// A random write of one communication parameter of one PDO, outside the remapping sequence:
/// COB-IDs (valid or not, RTR bit, another PDO's identifier, bits the rules refuse),
/// transmission types (0, 1..240, the reserved 241..251, 252..255), SYNC start values (and
/// ones above 240), inhibit times and event timers — while operational or not.
template <class Hook>
void write_param(rng &r, trio<Hook> &t, std::uint32_t now) {
  const bool rx = r.one_in(2);
  const auto k = static_cast<std::uint16_t>(r.below(2));
  const auto comm = static_cast<std::uint16_t>((rx ? 0x1400U : 0x1800U) + k);
  std::uint8_t sub = 1;
  std::uint32_t v = 0;
  std::size_t len = 4;
  switch (r.below(6)) {
  case 0:
  case 1: {
    // the PDO's own identifier, the other PDO's, or the other direction's
    const std::uint32_t ids[] = {(rx ? 0x201U : 0x181U) + k, (rx ? 0x201U : 0x181U) + (1U - k),
                                 (rx ? 0x181U : 0x201U) + k, 0x300U + r.below(4)};
    v = ids[r.below(4)];
    if (r.one_in(2)) v |= 0x8000'0000U;                 // invalid
    if (!rx && r.one_in(4)) v |= 0x4000'0000U;          // no RTR
    if (r.one_in(25)) v |= 0x0000'1000U << r.below(17); // bits 11..29 / 28: refused
    break;
  }
  case 2: {
    sub = 2;
    len = 1;
    const std::uint32_t pick = r.below(6);
    v = pick == 0U   ? 0U
        : pick == 1U ? 1U + r.below(4)
        : pick == 2U ? 1U + r.below(240)
        : pick == 3U ? 241U + r.below(11)
                     : 252U + r.below(4);
    break;
  }
  case 3:
    sub = 3;
    len = 2;
    v = r.below(30);
    break;
  case 4:
    sub = 5;
    len = 2;
    v = r.below(3) == 0U ? 0U : r.below(25);
    break;
  default:
    sub = 6; // RPDOs have none: the store refuses
    len = 1;
    v = r.one_in(10) ? 241U + r.below(15) : r.below(5);
    break;
  }
  const auto b = le32(v);
  const auto s = std::span<const std::uint8_t>(b).first(len);
  abort_code answer = abort_code::none;
  all(t, [&](auto &side) { return answer = side.param({comm, sub}, s, now); });
  ++(answer == abort_code::none ? params_seen.taken : params_seen.refused);
}

/// Remap PDO `k` (0, 1) of direction `rx` in the CiA 301 sequence (with random deviations) on
/// every side, comparing every answer.
template <class Hook>
void remap(rng &r, trio<Hook> &t, bool rx, std::uint16_t k, std::uint32_t now) {
  const auto comm = static_cast<std::uint16_t>((rx ? 0x1400U : 0x1800U) + k);
  const auto map = static_cast<std::uint16_t>((rx ? 0x1600U : 0x1A00U) + k);
  const std::uint32_t id = (rx ? 0x201U : 0x181U) + k;
  auto w = [&](od::address a, std::uint32_t v, std::size_t len) {
    const auto b = le32(v);
    const auto s = std::span<const std::uint8_t>(b).first(len);
    all(t, [&](auto &side) { return side.param(a, s, now); });
  };
  if (!r.one_in(10)) w({comm, 1}, id | 0x8000'0000U, 4);
  if (!r.one_in(10)) w({map, 0}, 0, 1);
  const std::uint32_t n = r.below(9);
  for (std::uint32_t s = 1; s <= n; ++s) w({map, static_cast<std::uint8_t>(s)}, random_entry(r), 4);
  w({map, 0}, r.one_in(10) ? r.below(10) : n, 1);
  const auto &c = rx ? t.c.engine.rpdo(k) : t.c.engine.tpdo(k);
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
template <class Hook>
void set_values(rng &r, trio<Hook> &t) {
  for (std::uint16_t index = 0x2000; index <= 0x2010; ++index) {
    if (!r.one_in(3)) continue;
    const od::entry *e = dict.find(index, 0);
    REQUIRE(e != nullptr);
    std::array<std::uint8_t, 8> v{};
    for (auto &b : v) b = static_cast<std::uint8_t>(r.next());
    if (e->type == data_type::boolean) v[0] = static_cast<std::uint8_t>(v[0] & 1U);
    const std::size_t n = od::is_byte_string(e->type) ? r.below(e->capacity() + 1U) : e->width();
    const auto s = std::span<const std::uint8_t>(v).first(n);
    all(t, [&](auto &side) { return side.store.set({index, 0}, s); });
    all(t, [&](auto &side) {
      side.engine.mark({index, 0});
      return 0;
    });
  }
}

template <class Hook>
void run(std::uint64_t seed, std::size_t steps) {
  rng r{seed};
  trio<Hook> t;
  all(t, [](auto &side) { return side.engine.reload(); });
  std::uint32_t now = 0;
  for (std::size_t i = 0; i < steps; ++i) {
    now += r.below(4);
    const std::uint32_t op = r.below(100);
    if (op < 10) {
      // one draw after the other: the order in which a call's arguments are evaluated is
      // unspecified (g++ on x86-64 and on s390x differ), which made the stream host-dependent
      const auto k = static_cast<std::uint16_t>(r.below(2));
      const bool rx = r.one_in(2);
      remap(r, t, rx, k, now);
    } else if (op < 16) {
      write_param(r, t, now);
    } else if (op < 30) {
      set_values(r, t);
    } else if (op < 50) {
      std::optional<std::uint8_t> counter;
      if (r.one_in(2)) counter = static_cast<std::uint8_t>(1U + r.below(4));
      const auto sc = step_all(t, now, [&](auto &e) { return e.on_sync(counter, now); });
      for (std::size_t k = 0; counter && k < 2; ++k) {
        const auto &c = t.c.engine.tpdo(k);
        if (!c.valid() || c.type == 0U || c.type > 240U || c.sync_start != *counter) continue;
        for (const auto &f : sc.send) {
          if (f.id == c.id()) ++params_seen.sync_start;
        }
      }
    } else if (op < 80) {
      co::can_frame f;
      // mostly the RPDOs' own identifiers, some that write_param gives them, some anything
      const std::uint32_t pick = r.below(10);
      f.id = static_cast<std::uint16_t>(pick == 0U   ? r.below(0x800)
                                        : pick == 1U ? 0x300U + r.below(4)
                                        : pick == 2U ? 0x181U + r.below(2)
                                                     : 0x201U + r.below(2));
      f.dlc = static_cast<std::uint8_t>(r.one_in(4) ? r.below(9) : 8U);
      for (std::size_t k = 0; k < f.dlc; ++k) f.data[k] = static_cast<std::uint8_t>(r.next());
      if (r.one_in(8)) f.data[0] = 0x42; // the hook refuses 2001h = 0x..42
      const bool window = !r.one_in(8);
      step_all(t, now, [&](auto &e) { return e.on_frame(f, now, window); });
      const auto &r0 = t.c.engine.rpdo(0);
      const auto &r1 = t.c.engine.rpdo(1);
      if (r0.valid() && r1.valid() && r0.id() == f.id && r1.id() == f.id) ++params_seen.shared_id;
    } else if (op < 86) {
      co::can_frame f;
      f.id = static_cast<std::uint16_t>(0x181U + r.below(2));
      f.rtr = true;
      step_all(t, now, [&](auto &e) { return e.on_frame(f, now); });
    } else if (op < 96) {
      step_all(t, now, [&](auto &e) { return e.poll(now); });
    } else if (op < 98) {
      const bool on = !r.one_in(4);
      all(t, [&](auto &side) {
        side.engine.set_operational(on, now);
        return 0;
      });
    } else {
      all(t, [](auto &side) { return side.engine.reload(); });
    }
    CHECK(t.c.storage == t.p.storage);
    CHECK(t.c.storage == t.a.storage);
    CHECK(t.c.storage == t.r5.storage);
    // what each engine derived from the parameters is what the parameters say now
    CHECK(t.c.engine.derived_current());
    CHECK(t.p.engine.derived_current());
    CHECK(t.a.engine.derived_current());
    for (std::size_t k = 0; k < 2; ++k) {
      for (const auto *o : {&t.p.engine.rpdo(k), &t.a.engine.rpdo(k), &t.r5.engine.rpdo(k)}) {
        CHECK(t.c.engine.rpdo(k).count == o->count);
        CHECK(t.c.engine.rpdo(k).valid() == o->valid());
        CHECK(t.c.engine.rpdo(k).cob == o->cob);
        CHECK(t.c.engine.rpdo(k).type == o->type);
      }
      for (const auto *o : {&t.p.engine.tpdo(k), &t.a.engine.tpdo(k), &t.r5.engine.tpdo(k)}) {
        CHECK(t.c.engine.tpdo(k).count == o->count);
        CHECK(t.c.engine.tpdo(k).valid() == o->valid());
        CHECK(t.c.engine.tpdo(k).cob == o->cob);
        CHECK(t.c.engine.tpdo(k).type == o->type);
      }
    }
  }
}

} // namespace

TEST_CASE("pdo engine compiled == by position == by address: random mappings, remaps, values, "
          "traffic") {
  // with the write hook (RPDO objects by position, TPDO objects copied) and without (RPDO
  // objects that take any bits copied too)
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    CAPTURE(seed);
    run<refuse_42>(seed * 0x9E3779B97F4A7C15ULL, 2500);
    run<co::accept_writes>(seed * 0xD1B54A32D192ED03ULL, 2500);
  }
  MESSAGE("frames ", seen.frames, ", received ", seen.received, ", with refusals ", seen.refused,
          ", too short ", seen.too_short, ", remapped ", seen.remapped, ", off byte boundaries ",
          seen.off_byte, "; entries copied / by position: TPDO ", seen.tx_copied, " / ",
          seen.tx_object, ", RPDO ", seen.rx_copied, " / ", seen.rx_object, "; mixed PDOs ",
          seen.mixed, ", with runs of adjacent entries ", seen.merged, ", TPDOs all copied ",
          seen.sent_copied);
  CHECK(seen.frames > 1000U);
  CHECK(seen.received > 1000U);
  CHECK(seen.refused > 100U);
  CHECK(seen.too_short > 100U);
  CHECK(seen.remapped > 200U);
  CHECK(seen.off_byte > 100U);
  CHECK(seen.tx_copied > 1000U);
  CHECK(seen.rx_copied > 1000U);
  CHECK(seen.tx_object > 500U);
  CHECK(seen.rx_object > 500U);
  CHECK(seen.mixed > 500U);
  CHECK(seen.merged > 50U);
  CHECK(seen.sent_copied > 100U);
  MESSAGE("parameter writes taken ", params_seen.taken, ", refused ", params_seen.refused,
          "; RPDO frames taken by two RPDOs ", params_seen.shared_id,
          "; TPDOs sent at their SYNC start value ", params_seen.sync_start);
  CHECK(params_seen.taken > 1000U);
  CHECK(params_seen.refused > 1000U);
  CHECK(params_seen.shared_id > 20U);
  CHECK(params_seen.sync_start > 20U);
}

TEST_CASE_TEMPLATE("pdo engine compiled: remapping while operational uses the new mapping", Hook,
                   refuse_42, co::accept_writes) {
  side<path::copy, Hook> s;
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
  using plan = typename std::remove_cvref_t<decltype(s.engine)>::plan;
  constexpr bool plain_rx = std::is_same_v<Hook, co::accept_writes>; // no hook to ask
  // the BOOLEAN of 1 bit and the two entries it puts off byte boundaries: by position
  CHECK(s.engine.compiled_plan(pdo::direction::tpdo, 0) == plan{0, 0, 3});
  // RPDO 1: 2001h u16 and 2002h u32, adjacent in storage and frame: a run of 6 bytes, copied
  // as 4 + 2
  CHECK(s.engine.compiled_plan(pdo::direction::rpdo, 0) ==
        (plain_rx ? plan{2, 2, 0} : plan{0, 0, 2}));
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
  CHECK(s.engine.compiled_plan(pdo::direction::tpdo, 0) == plan{2, 2, 0});
  // a new value of a copied object is in the next TPDO
  REQUIRE(s.store.set({0x2003, 0}, std::array<std::uint8_t, 1>{0x99}) == abort_code::none);
  REQUIRE(s.store.write({0x2000, 0}, 0, std::array<std::uint8_t, 1>{0x55}, true) ==
          abort_code::none); // as an SDO download does
  st = s.engine.on_sync(std::nullopt, 3);
  REQUIRE(st.send.size() == 1);
  CHECK(st.send[0] == co::can_frame{0x181, false, 2, {0x55, 0x99}});
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
  // in the other order the storage is not in frame order: two runs, 4 and 2 bytes
  CHECK(s.engine.compiled_plan(pdo::direction::rpdo, 0) ==
        (plain_rx ? plan{2, 2, 0} : plan{0, 0, 2}));
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
  std::array<od::entry, n_entries> small_entries{};
  std::size_t n = 0;
  for (const auto &e : entries) {
    if (e.index != 0x2002U) small_entries[n++] = e;
  }
  const od::dictionary small{std::span<const od::entry>(small_entries).first(n)};
  std::vector<std::uint8_t> storage(store_type::storage_size(small));
  REQUIRE(n == n_entries - 1U);
  const auto lay = co::make_layout<n_entries - 1U>(small);
  store_type store{small, lay, storage};
  REQUIRE(store.init_defaults(1).has_value());
  CHECK(store.position({0x2002, 0}) == co::no_position);
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

TEST_CASE("pdo engine compiled: adjacent objects are one copy, odd lengths are cut, an object "
          "mapped twice into an RPDO is written entry by entry") {
  side<path::copy, co::accept_writes> s;
  using plan = decltype(s.engine)::plan;
  REQUIRE(s.engine.reload().has_value());
  s.engine.set_operational(true, 0);
  const auto w = [&](od::address a, std::uint32_t v, std::size_t len) {
    const auto b = le32(v);
    return s.param(a, std::span<const std::uint8_t>(b).first(len), 1);
  };
  const auto map = [&](std::uint16_t comm, std::uint32_t id,
                       std::initializer_list<std::uint32_t> objects) {
    const auto m = static_cast<std::uint16_t>(comm + 0x200U);
    REQUIRE(w({comm, 1}, id | 0x8000'0000U, 4) == abort_code::none);
    REQUIRE(w({m, 0}, 0, 1) == abort_code::none);
    std::uint8_t sub = 0;
    for (const std::uint32_t e : objects) REQUIRE(w({m, ++sub}, e, 4) == abort_code::none);
    REQUIRE(w({m, 0}, sub, 1) == abort_code::none);
    REQUIRE(w({comm, 1}, id, 4) == abort_code::none);
  };
  // 2000h u8, 2001h u16, 2002h u32, 2003h i8 lie one after the other in the storage, as in the
  // frame: one copy of 8 bytes
  map(0x1800, 0x181, {0x2000'0008U, 0x2001'0010U, 0x2002'0020U, 0x2003'0008U});
  CHECK(s.engine.compiled_plan(pdo::direction::tpdo, 0) == plan{4, 1, 0});
  REQUIRE(s.store.set({0x2000, 0}, std::array<std::uint8_t, 1>{0x10}) == abort_code::none);
  REQUIRE(s.store.set({0x2001, 0}, std::array<std::uint8_t, 2>{0x21, 0x22}) == abort_code::none);
  REQUIRE(s.store.set({0x2002, 0}, std::array<std::uint8_t, 4>{0x31, 0x32, 0x33, 0x34}) ==
          abort_code::none);
  REQUIRE(s.store.set({0x2003, 0}, std::array<std::uint8_t, 1>{0x40}) == abort_code::none);
  auto st = s.engine.on_sync(std::nullopt, 2);
  REQUIRE(st.send.size() == 1);
  CHECK(st.send[0] ==
        co::can_frame{0x181, false, 8, {0x10, 0x21, 0x22, 0x31, 0x32, 0x33, 0x34, 0x40}});
  // INTEGER24 (3 bytes) after a dummy byte: a copy of 2 and one of 1
  map(0x1800, 0x181, {0x0005'0008U, 0x2008'0018U});
  CHECK(s.engine.compiled_plan(pdo::direction::tpdo, 0) == plan{1, 2, 0});
  REQUIRE(s.store.set({0x2008, 0}, std::array<std::uint8_t, 3>{0xA1, 0xA2, 0xA3}) ==
          abort_code::none);
  st = s.engine.on_sync(std::nullopt, 3);
  REQUIRE(st.send.size() == 1);
  CHECK(st.send[0] == co::can_frame{0x181, false, 4, {0, 0xA1, 0xA2, 0xA3}});
  // RPDO 1 maps 2000h twice, around 2003h: written entry by entry, the later 2000h wins
  map(0x1400, 0x201, {0x2000'0008U, 0x2003'0008U, 0x2000'0008U});
  CHECK(s.engine.compiled_plan(pdo::direction::rpdo, 0) == plan{0, 0, 3});
  (void)s.engine.on_frame(co::can_frame{0x201, false, 3, {0x01, 0x02, 0x03}}, 4);
  CHECK(s.store.value({0x2000, 0}).value()[0] == 0x03);
  CHECK(s.store.value({0x2003, 0}).value()[0] == 0x02);
  // without the second 2000h: two copies of one byte each
  map(0x1400, 0x201, {0x2000'0008U, 0x2003'0008U});
  CHECK(s.engine.compiled_plan(pdo::direction::rpdo, 0) == plan{2, 2, 0});
  (void)s.engine.on_frame(co::can_frame{0x201, false, 2, {0x0A, 0x0B}}, 5);
  CHECK(s.store.value({0x2000, 0}).value()[0] == 0x0A);
  CHECK(s.store.value({0x2003, 0}).value()[0] == 0x0B);
}

namespace {
/// The compiled engine in a constant expression: an RPDO copied into the store, a TPDO copied
/// out of it (dictionary_store without a hook: both directions are copies).
constexpr bool compiled_at_compile_time() {
  std::array<std::uint8_t, layout.storage_size()> storage{};
  plain_type store{dict, layout, storage};
  if (!store.init_defaults(1)) return false;
  node::pdo_engine<plain_type, 2, 2, 8> e(store, dict);
  if (!e.reload()) return false;
  e.set_operational(true, 0);
  // RPDO 1: 2001h u16, 2002h u32 (one run of 6 bytes: a copy of 4 and one of 2)
  if (e.compiled_plan(pdo::direction::rpdo, 0) != decltype(e)::plan{2, 2, 0}) return false;
  (void)e.on_frame(co::can_frame{0x201, false, 6, {0x01, 0x02, 0x03, 0x04, 0x05, 0x06}}, 1);
  const auto v1 = store.value({0x2001, 0});
  const auto v2 = store.value({0x2002, 0});
  if (!v1 || !v2 || v1.value()[0] != 0x01 || v1.value()[1] != 0x02 || v2.value()[0] != 0x03 ||
      v2.value()[3] != 0x06) {
    return false;
  }
  // TPDO 1 (type 1): the 1-bit BOOLEAN puts 2003h and 2005h off byte boundaries (by position)
  if (e.compiled_plan(pdo::direction::tpdo, 0) != decltype(e)::plan{0, 0, 3}) return false;
  const auto st = e.on_sync(std::nullopt, 2);
  return st.send.size() == 1 && st.send[0].id == 0x181U && st.send[0].dlc == 6U;
}
static_assert(compiled_at_compile_time());
} // namespace

TEST_CASE("pdo engine compiled: the same at run time") { CHECK(compiled_at_compile_time()); }

TEST_CASE("pdo engine compiled: a plain slot past the store's plain_storage is not copied") {
  // a store whose plain_storage() ends after 2001h: 2002h's slot (4 bytes after it) lies
  // beyond, so RPDO 1 (2001h, 2002h) copies 2001h and writes 2002h by position
  std::vector<std::uint8_t> storage(layout.storage_size());
  plain_type store{dict, layout, storage};
  REQUIRE(store.init_defaults(1).has_value());
  const auto s2001 = store.plain_at(store.position({0x2001, 0}));
  const auto s2002 = store.plain_at(store.position({0x2002, 0}));
  REQUIRE(s2002.offset == s2001.offset + 2U);
  using short_store = test_node::short_plain_store<plain_type>;
  static_assert(co::plain_store<short_store>);
  short_store view{store, s2001.offset + 2U + 3U}; // 2002h would need one byte more
  node::pdo_engine<short_store, 2, 2, 8> e(view, dict);
  REQUIRE(e.reload().has_value());
  e.set_operational(true, 0);
  CHECK(e.compiled_plan(pdo::direction::rpdo, 0) == decltype(e)::plan{1, 1, 1});
  (void)e.on_frame(co::can_frame{0x201, false, 6, {0x11, 0x22, 0x33, 0x44, 0x55, 0x66}}, 1);
  CHECK(store.value({0x2001, 0}).value()[1] == 0x22);
  CHECK(store.value({0x2002, 0}).value()[3] == 0x66);
  REQUIRE(e.events().size() == 1);
  CHECK(e.events()[0].refused == 0);
  // with room for it, one run
  short_store enough{store, s2001.offset + 6U};
  node::pdo_engine<short_store, 2, 2, 8> e2(enough, dict);
  REQUIRE(e2.reload().has_value());
  CHECK(e2.compiled_plan(pdo::direction::rpdo, 0) == decltype(e2)::plan{2, 2, 0});
}

namespace {

/// A dictionary whose store puts 2001h (UNSIGNED16) in the last two bytes a compiled mapping's
/// 16-bit offsets reach and 2002h (UNSIGNED32) just past them: a 1F00h octet string fills the
/// bytes before.
constexpr std::array<od::entry_spec, 13> far_entries(std::uint32_t big) {
  const auto u8 = data_type::unsigned8;
  const auto u32 = data_type::unsigned32;
  std::array<od::entry_spec, 13> e{
      {var(0x1400, 0, u8, od::access::ro, 2), var(0x1400, 1, u32, rw, 0x201U),
       var(0x1400, 2, u8, rw, 255), var(0x1600, 0, u8, rw, 2),
       var(0x1600, 1, u32, rw, 0x2001'0010U), var(0x1600, 2, u32, rw, 0x2002'0020U),
       var(0x1800, 0, u8, od::access::ro, 2), var(0x1800, 1, u32, rw, 0x181U),
       var(0x1800, 2, u8, rw, 1), var(0x1A00, 0, u8, rw, 2), var(0x1A00, 1, u32, rw, 0x2002'0020U),
       var(0x1A00, 2, u32, rw, 0x2001'0010U), bytes(0x1F00, data_type::octet_string, big)}};
  return e;
}
constexpr auto far_probe = far_entries(1);
constexpr std::uint32_t far_big = [] {
  // 2001h follows 1F00h: with 1F00h of 1 byte it would start at offsets[13] (the total)
  const auto l = co::make_layout<13>(od::dictionary{od::entries_of<far_probe>});
  return 0xFFFEU - (l.offsets[13] - 1U);
}();
constexpr auto far_base = far_entries(far_big);
constexpr std::array<od::entry_spec, 15> far_specs = [] {
  std::array<od::entry_spec, 15> e{};
  for (std::size_t i = 0; i < 13; ++i) e[i] = far_base[i];
  e[13] = var(0x2001, 0, data_type::unsigned16, rw, 0, yes);
  e[14] = var(0x2002, 0, data_type::unsigned32, rw, 0, yes);
  return e;
}();
constexpr auto far_list = od::entries_of<far_specs>;
constexpr od::dictionary far_dict{far_list};
static_assert(far_dict.is_valid());
constexpr auto far_layout = co::make_layout<15>(far_dict);
static_assert(far_layout.offsets[13] == 0xFFFEU && far_layout.offsets[14] == 0x10000U);

} // namespace

TEST_CASE("pdo engine compiled: a value past the first 64 kB of the store goes by position") {
  // the compiled mapping keeps 16-bit storage offsets: 2001h (0xFFFE..0xFFFF) is copied, 2002h
  // (from 0x10000) is read and written by position; the frames and values are the same
  std::vector<std::uint8_t> storage(far_layout.storage_size());
  co::dictionary_store<> store{far_dict, far_layout, storage};
  REQUIRE(store.init_defaults(1).has_value());
  REQUIRE(store.plain_at(store.position({0x2002, 0})).offset == 0x10000U);
  node::pdo_engine<co::dictionary_store<>, 1, 1, 8> e(store, far_dict);
  REQUIRE(e.reload().has_value());
  e.set_operational(true, 0);
  using plan = decltype(e)::plan;
  CHECK(e.compiled_plan(pdo::direction::rpdo, 0) == plan{1, 1, 1});
  CHECK(e.compiled_plan(pdo::direction::tpdo, 0) == plan{1, 1, 1});
  (void)e.on_frame(co::can_frame{0x201, false, 6, {0x11, 0x22, 0x33, 0x44, 0x55, 0x66}}, 1);
  REQUIRE(e.events().size() == 1);
  CHECK(e.events()[0].refused == 0);
  CHECK(storage[0xFFFE] == 0x11);
  CHECK(storage[0xFFFF] == 0x22);
  CHECK(storage[0x10000] == 0x33);
  CHECK(storage[0x10003] == 0x66);
  const auto s = e.on_sync(std::nullopt, 2);
  REQUIRE(s.send.size() == 1U);
  CHECK(s.send[0] == co::can_frame{0x181, false, 6, {0x33, 0x44, 0x55, 0x66, 0x11, 0x22}});
}
