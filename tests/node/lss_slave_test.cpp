// The LSS slave (CiA 305; node/lss_slave.hpp) alone and in the device (capacity::lss): every
// command, the services by LSS state, node-IDs pending and active, the unconfigured node that
// waits in initialising, and bad input.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/lss.hpp>
#include <fieldcodec/canopen/node/lss_slave.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>

#include <algorithm>

using namespace test_node;
using co::nmt::state;
namespace lss = fieldcodec::canopen::lss;
using lss::command;
using node::lss_event;
using node::lss_mode;

namespace {

/// A master's command on 7E5h: cs and bytes 1..7.
co::can_frame M(std::uint8_t cs, std::initializer_list<std::uint8_t> rest = {}) {
  std::array<std::uint8_t, 8> d{cs};
  std::copy(rest.begin(), rest.end(), d.begin() + 1);
  return co::make_frame(lss::master_id, d).value();
}
/// A command with a 32-bit value in bytes 1..4.
co::can_frame M32(std::uint8_t cs, std::uint32_t v) {
  return M(cs, {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8U),
                static_cast<std::uint8_t>(v >> 16U), static_cast<std::uint8_t>(v >> 24U)});
}
co::can_frame fastscan(std::uint32_t id, std::uint8_t bit, std::uint8_t sub, std::uint8_t next) {
  return M(0x51, {static_cast<std::uint8_t>(id), static_cast<std::uint8_t>(id >> 8U),
                  static_cast<std::uint8_t>(id >> 16U), static_cast<std::uint8_t>(id >> 24U), bit,
                  sub, next});
}
/// A slave's answer on 7E4h.
co::can_frame S(std::uint8_t cs, std::initializer_list<std::uint8_t> rest = {}) {
  std::array<std::uint8_t, 8> d{cs};
  std::copy(rest.begin(), rest.end(), d.begin() + 1);
  return co::make_frame(lss::slave_id, d).value();
}

constexpr lss::address identity{0x0000'0F1CU, 0x0000'0001U, 0x0001'0000U, 0x1234'5678U};

node::lss_slave slave_of(std::uint8_t node, node::lss_options o = {}) {
  node::lss_slave s(node, o);
  s.written({0x1018, 1}, identity.vendor, 0);
  s.written({0x1018, 2}, identity.product, 0);
  s.written({0x1018, 3}, identity.revision, 0);
  s.written({0x1018, 4}, identity.serial, 0);
  return s;
}

std::optional<co::can_frame> answer(node::lss_slave &s, const co::can_frame &f) {
  return s.on_frame(f).answer;
}

/// Switch state selective with `a`: the answer of the serial number.
std::optional<co::can_frame> select(node::lss_slave &s, const lss::address &a) {
  CHECK_FALSE(answer(s, M32(0x40, a.vendor)));
  CHECK_FALSE(answer(s, M32(0x41, a.product)));
  CHECK_FALSE(answer(s, M32(0x42, a.revision)));
  return answer(s, M32(0x43, a.serial));
}

/// The master's side of fastscan as CiA 305 runs it (python canopen's LssMaster.fast_scan does
/// the same): nullopt when no slave answers the reset or a part's confirmation.
template <class Send>
std::optional<lss::address> scan(Send send) {
  std::array<std::uint32_t, 4> id{};
  if (!send(fastscan(0, 0x80, 0, 0))) return std::nullopt;
  for (std::uint8_t sub = 0; sub < 4U; ++sub) {
    for (int bit = 31; bit >= 0; --bit) {
      if (!send(fastscan(id[sub], static_cast<std::uint8_t>(bit), sub, sub))) {
        id[sub] |= 1U << static_cast<unsigned>(bit);
      }
    }
    const auto next = static_cast<std::uint8_t>((sub + 1U) & 3U);
    if (!send(fastscan(id[sub], 0, sub, next))) return std::nullopt;
  }
  return lss::address{id[0], id[1], id[2], id[3]};
}

} // namespace

// ----- the codec: the slave's answers as frames --------------------------------------------

static_assert(lss::encode(lss::answer(command::inquire_node_id, 5)).data[1] == 5);
static_assert(lss::encode(lss::answer(command::inquire_node_id, 5)).id == lss::slave_id);
static_assert(lss::decode(lss::encode(lss::answer(command::configure_node_id, 1))).value().b1 == 1);
static_assert([] {
  lss::message m = lss::answer(command::inquire_serial);
  m.value = 0x1234'5678U;
  const auto f = lss::encode(m);
  return f.data[1] == 0x78 && f.data[4] == 0x12 && lss::decode(f).value().value == m.value;
}());
static_assert([] {
  lss::message m;
  m.cs = command::fastscan;
  m.value = 0xCAFE'F00DU;
  m.bit_checked = 7;
  m.lss_sub = 2;
  m.lss_next = 3;
  const auto d = lss::decode(lss::encode(m)).value();
  return d.value == m.value && d.bit_checked == 7 && d.lss_sub == 2 && d.lss_next == 3;
}());
static_assert([] {
  lss::message m;
  m.cs = command::activate_bit_timing;
  m.value = 1000;
  return lss::decode(lss::encode(m)).value().value == 1000U;
}());
static_assert(!node::lss_node_id(0) && node::lss_node_id(1) && node::lss_node_id(127) &&
              !node::lss_node_id(128) && !node::lss_node_id(0xFE) && node::lss_node_id(0xFF));

// ----- the machine alone -------------------------------------------------------------------

TEST_CASE("lss slave: switch state global and selective, inquire") {
  auto s = slave_of(5);
  CHECK(s.mode() == lss_mode::waiting);
  // inquire is for the configuration state only
  CHECK_FALSE(answer(s, M(0x5E)));
  CHECK(s.error() == errc::bad_state);
  // switch global: no answer, an event
  auto r = s.on_frame(M(0x04, {1}));
  CHECK_FALSE(r.answer);
  REQUIRE(r.event);
  CHECK(r.event->what == lss_event::kind::mode);
  CHECK(r.event->mode == lss_mode::configuration);
  CHECK_FALSE(r.boot);
  CHECK(answer(s, M(0x5A)) == S(0x5A, {0x1C, 0x0F, 0, 0}));
  CHECK(answer(s, M(0x5B)) == S(0x5B, {0x01, 0, 0, 0}));
  CHECK(answer(s, M(0x5C)) == S(0x5C, {0, 0, 0x01, 0}));
  CHECK(answer(s, M(0x5D)) == S(0x5D, {0x78, 0x56, 0x34, 0x12}));
  CHECK(answer(s, M(0x5E)) == S(0x5E, {5}));
  // switch selective is for the waiting state only
  CHECK_FALSE(answer(s, M32(0x40, identity.vendor)));
  CHECK(s.error() == errc::bad_state);
  // the same mode again: no event
  CHECK_FALSE(s.on_frame(M(0x04, {1})).event);
  r = s.on_frame(M(0x04, {0}));
  REQUIRE(r.event);
  CHECK(r.event->mode == lss_mode::waiting);
  // a mode other than 0/1
  CHECK_FALSE(s.on_frame(M(0x04, {2})).event);
  CHECK(s.error() == errc::invalid_argument);
  CHECK(s.mode() == lss_mode::waiting);

  // selective: all four equal → 44h, configuration
  CHECK(select(s, identity) == S(0x44));
  CHECK(s.mode() == lss_mode::configuration);
  (void)s.on_frame(M(0x04, {0}));
  // one part different: no answer, still waiting
  auto other = identity;
  other.revision = 2;
  CHECK_FALSE(select(s, other));
  CHECK(s.mode() == lss_mode::waiting);
  // the serial alone (no sequence before it) does not select
  CHECK_FALSE(answer(s, M32(0x43, identity.serial)));
  CHECK(s.mode() == lss_mode::waiting);
  // a vendor starts the sequence afresh: a wrong product in between spoils it
  CHECK_FALSE(answer(s, M32(0x40, identity.vendor)));
  CHECK_FALSE(answer(s, M32(0x41, 99)));
  CHECK_FALSE(answer(s, M32(0x42, identity.revision)));
  CHECK_FALSE(answer(s, M32(0x43, identity.serial)));
  CHECK(s.mode() == lss_mode::waiting);
}

TEST_CASE("lss slave: configure node-ID, pending and active") {
  auto s = slave_of(5);
  // configure node-ID in waiting: ignored
  CHECK_FALSE(answer(s, M(0x11, {7})));
  CHECK(s.error() == errc::bad_state);
  CHECK(s.pending_node() == 5);
  (void)s.on_frame(M(0x04, {1}));
  // out of range: error code 1, nothing pending
  for (const std::uint8_t bad : std::initializer_list<std::uint8_t>{0, 128, 0x81, 0xC0, 0xFE}) {
    CAPTURE(int{bad});
    CHECK(answer(s, M(0x11, {bad})) == S(0x11, {1}));
    CHECK(s.pending_node() == 5);
  }
  auto r = s.on_frame(M(0x11, {7}));
  CHECK(r.answer == S(0x11, {0}));
  REQUIRE(r.event);
  CHECK(r.event->what == lss_event::kind::node_id);
  CHECK(r.event->node_id == 7);
  CHECK(s.pending_node() == 7);
  CHECK(s.active_node() == 5);
  CHECK(answer(s, M(0x5E)) == S(0x5E, {5})); // the active one until the reset
  // back to waiting: a configured node does not boot by itself
  CHECK_FALSE(s.on_frame(M(0x04, {0})).boot);
  CHECK(s.activate() == 7);
  CHECK(s.active_node() == 7);
  CHECK(s.mode() == lss_mode::waiting);
  // FFh: the node becomes unconfigured at its next reset
  (void)s.on_frame(M(0x04, {1}));
  CHECK(answer(s, M(0x11, {0xFF})) == S(0x11, {0}));
  CHECK_FALSE(s.unconfigured()); // still active 7
  CHECK(s.activate() == 0xFF);
  CHECK(s.unconfigured());
}

TEST_CASE("lss slave: an unconfigured node boots when switched back to waiting") {
  auto s = slave_of(lss::unconfigured);
  CHECK(s.unconfigured());
  (void)s.on_frame(M(0x04, {1}));
  CHECK(answer(s, M(0x5E)) == S(0x5E, {0xFF}));
  // back to waiting without a node-ID: nothing
  CHECK_FALSE(s.on_frame(M(0x04, {0})).boot);
  (void)s.on_frame(M(0x04, {1}));
  CHECK(answer(s, M(0x11, {0x20})) == S(0x11, {0}));
  CHECK_FALSE(s.unconfigured());              // a pending node-ID
  CHECK_FALSE(s.on_frame(M(0x04, {1})).boot); // staying in configuration
  CHECK(s.on_frame(M(0x04, {0})).boot);
}

TEST_CASE("lss slave: bit timing, activate, store") {
  struct saved {
    int calls = 0;
    std::uint8_t node = 0;
    std::optional<node::lss_bit_timing> timing;
    node::lss_store_result result{};
  } keep;
  node::lss_options o;
  o.bit_rates = 0x001F; // 1000..125 kbit/s
  o.context = &keep;
  o.store = [](void *c, std::uint8_t n, std::optional<node::lss_bit_timing> t) noexcept {
    auto *k = static_cast<saved *>(c);
    ++k->calls;
    k->node = n;
    k->timing = t;
    return k->result;
  };
  auto s = slave_of(5, o);
  // every one of them is for the configuration state only
  CHECK_FALSE(answer(s, M(0x13, {0, 3})));
  CHECK(s.error() == errc::bad_state);
  CHECK_FALSE(answer(s, M(0x17)));
  CHECK(s.error() == errc::bad_state);
  CHECK(keep.calls == 0);
  (void)s.on_frame(M(0x04, {1}));
  // activate before any configure: nothing to activate
  CHECK_FALSE(s.on_frame(M(0x15, {0x64, 0})).event);
  CHECK(s.error() == errc::bad_state);
  // store without a bit timing
  CHECK(answer(s, M(0x17)) == S(0x17, {0}));
  CHECK(keep.calls == 1);
  CHECK(keep.node == 5);
  CHECK(keep.timing == std::nullopt);
  // unsupported: another table, a reserved index, a rate the controller cannot run, auto (9)
  CHECK(answer(s, M(0x13, {1, 3})) == S(0x13, {1}));
  CHECK(answer(s, M(0x13, {0, 5})) == S(0x13, {1}));
  CHECK(answer(s, M(0x13, {0, 6})) == S(0x13, {1}));
  CHECK(answer(s, M(0x13, {0, 9})) == S(0x13, {1}));
  CHECK(answer(s, M(0x13, {0, 200})) == S(0x13, {1}));
  CHECK(s.pending_bit_timing() == std::nullopt);
  auto r = s.on_frame(M(0x13, {0, 3})); // 250 kbit/s
  CHECK(r.answer == S(0x13, {0}));
  REQUIRE(r.event);
  CHECK(r.event->what == lss_event::kind::bit_timing);
  CHECK(r.event->timing == node::lss_bit_timing{0, 3});
  // activate: no answer, the application switches after the delay (little-endian ms)
  r = s.on_frame(M(0x15, {0xE8, 0x03}));
  CHECK_FALSE(r.answer);
  REQUIRE(r.event);
  CHECK(r.event->what == lss_event::kind::activate_bit_timing);
  CHECK(r.event->delay_ms == 1000);
  CHECK(r.event->timing == node::lss_bit_timing{0, 3});
  // store: the pending node-ID and bit timing
  (void)s.on_frame(M(0x11, {9}));
  r = s.on_frame(M(0x17));
  CHECK(r.answer == S(0x17, {0}));
  REQUIRE(r.event);
  CHECK(r.event->what == lss_event::kind::stored);
  CHECK(r.event->code == 0);
  CHECK(keep.node == 9);
  CHECK(keep.timing == node::lss_bit_timing{0, 3});
  // the hook's failure goes to the master: media error, manufacturer's code
  keep.result = {lss::error_code::storage_access, 0x55};
  CHECK(answer(s, M(0x17)) == S(0x17, {2, 0}));
  keep.result = {lss::error_code::manufacturer, 0x55};
  CHECK(answer(s, M(0x17)) == S(0x17, {0xFF, 0x55}));

  // without a hook: error code 1, "store configuration not supported"
  auto plain = slave_of(5);
  (void)plain.on_frame(M(0x04, {1}));
  r = plain.on_frame(M(0x17));
  CHECK(r.answer == S(0x17, {1}));
  REQUIRE(r.event);
  CHECK(r.event->code == 1);
  // the default bit rates: every rate of the table
  for (std::uint8_t i = 0; i < 10U; ++i) {
    CAPTURE(int{i});
    const bool ok = i != 5U && i != 9U;
    CHECK(answer(plain, M(0x13, {0, i})) == S(0x13, {static_cast<std::uint8_t>(ok ? 0 : 1)}));
  }
}

TEST_CASE("lss slave: identify remote slave and non-configured slave") {
  const auto identify = [](node::lss_slave &s, std::uint32_t v, std::uint32_t p, std::uint32_t rl,
                           std::uint32_t rh, std::uint32_t sl, std::uint32_t sh) {
    CHECK_FALSE(answer(s, M32(0x46, v)));
    CHECK_FALSE(answer(s, M32(0x47, p)));
    CHECK_FALSE(answer(s, M32(0x48, rl)));
    CHECK_FALSE(answer(s, M32(0x49, rh)));
    CHECK_FALSE(answer(s, M32(0x4A, sl)));
    return answer(s, M32(0x4B, sh)).has_value();
  };
  auto s = slave_of(5);
  const auto &a = identity;
  CHECK(identify(s, a.vendor, a.product, 0, 0xFFFF'FFFFU, 0, 0xFFFF'FFFFU));
  CHECK(answer(s, M32(0x4B, 0xFFFF'FFFFU)) == std::nullopt); // a part alone: no
  CHECK(identify(s, a.vendor, a.product, a.revision, a.revision, a.serial, a.serial));
  CHECK_FALSE(identify(s, a.vendor + 1U, a.product, 0, 0xFFFF'FFFFU, 0, 0xFFFF'FFFFU));
  CHECK_FALSE(identify(s, a.vendor, a.product + 1U, 0, 0xFFFF'FFFFU, 0, 0xFFFF'FFFFU));
  CHECK_FALSE(identify(s, a.vendor, a.product, a.revision + 1U, 0xFFFF'FFFFU, 0, 0xFFFF'FFFFU));
  CHECK_FALSE(identify(s, a.vendor, a.product, 0, a.revision - 1U, 0, 0xFFFF'FFFFU));
  CHECK_FALSE(identify(s, a.vendor, a.product, 0, 0xFFFF'FFFFU, a.serial + 1U, 0xFFFF'FFFFU));
  CHECK_FALSE(identify(s, a.vendor, a.product, 0, 0xFFFF'FFFFU, 0, a.serial - 1U));
  // in the configuration state too; the answer is 4Fh
  (void)s.on_frame(M(0x04, {1}));
  s.written({0x1018, 4}, a.serial, 0);
  CHECK_FALSE(answer(s, M32(0x46, a.vendor)));
  CHECK_FALSE(answer(s, M32(0x47, a.product)));
  CHECK_FALSE(answer(s, M32(0x48, 0)));
  CHECK_FALSE(answer(s, M32(0x49, 0xFFFF'FFFFU)));
  CHECK_FALSE(answer(s, M32(0x4A, 0)));
  CHECK(answer(s, M32(0x4B, 0xFFFF'FFFFU)) == S(0x4F));

  // non-configured: only a node without node-ID, active or pending
  CHECK_FALSE(answer(s, M(0x4C)));
  auto u = slave_of(lss::unconfigured);
  CHECK(answer(u, M(0x4C)) == S(0x50));
  (void)u.on_frame(M(0x04, {1}));
  CHECK(answer(u, M(0x4C)) == S(0x50)); // either state
  (void)u.on_frame(M(0x11, {3}));
  CHECK_FALSE(answer(u, M(0x4C))); // a pending node-ID
}

TEST_CASE("lss slave: fastscan finds the address of a node without node-ID") {
  auto s = slave_of(lss::unconfigured);
  int frames = 0;
  const auto send = [&](const co::can_frame &f) {
    ++frames;
    const auto a = answer(s, f);
    if (a) CHECK(*a == S(0x4F));
    return a.has_value();
  };
  const auto found = scan(send);
  REQUIRE(found);
  CHECK(*found == identity);
  CHECK(frames == 1 + 4 * 33);
  CHECK(s.mode() == lss_mode::configuration);
  // now it can be given a node-ID
  CHECK(answer(s, M(0x11, {0x22})) == S(0x11, {0}));
  CHECK(s.on_frame(M(0x04, {0})).boot);

  // a node with a node-ID does not take part
  auto c = slave_of(5);
  CHECK_FALSE(answer(c, fastscan(0, 0x80, 0, 0)));
  // fastscan is for the waiting state only
  auto w = slave_of(lss::unconfigured);
  (void)w.on_frame(M(0x04, {1}));
  CHECK_FALSE(answer(w, fastscan(0, 0x80, 0, 0)));
  CHECK(w.error() == errc::bad_state);
  // malformed probes: ignored
  auto m = slave_of(lss::unconfigured);
  CHECK_FALSE(answer(m, fastscan(0, 32, 0, 0)));
  CHECK(m.error() == errc::invalid_argument);
  CHECK_FALSE(answer(m, fastscan(0, 0x81, 0, 0)));
  CHECK_FALSE(answer(m, fastscan(0, 0x80, 4, 0)));
  CHECK_FALSE(answer(m, fastscan(0, 0x80, 0, 4)));
  // a probe for a part not yet reached: no answer
  CHECK(answer(m, fastscan(0, 0x80, 0, 0)));
  CHECK_FALSE(answer(m, fastscan(identity.product, 0, 1, 2)));
  // a wrong value for bits 31..k: no answer
  CHECK_FALSE(answer(m, fastscan(0x8000'0000U, 31, 0, 0)));
  CHECK(answer(m, fastscan(0, 31, 0, 0)));
}

TEST_CASE("lss slave: bad frames are ignored with a reason") {
  auto s = slave_of(5);
  (void)s.on_frame(M(0x04, {1}));
  co::can_frame f = M(0x5E);
  f.dlc = 7;
  CHECK_FALSE(answer(s, f));
  CHECK(s.error() == errc::bad_length);
  f.dlc = 8;
  f.rtr = true;
  CHECK_FALSE(answer(s, f));
  CHECK(s.error() == errc::unexpected_frame);
  for (const std::uint8_t cs :
       std::initializer_list<std::uint8_t>{0x00, 0x01, 0x12, 0x44, 0x4F, 0x50, 0x5F, 0x99, 0xFF}) {
    CAPTURE(int{cs});
    CHECK_FALSE(answer(s, M(cs)));
    CHECK(s.error() == errc::unknown_command);
  }
  // a slave's answer on 7E4h is not for a slave
  CHECK_FALSE(answer(s, S(0x5E)));
  CHECK(s.error() == errc::unexpected_frame);
  // a good frame clears the reason
  CHECK(answer(s, M(0x5E)) == S(0x5E, {5}));
  CHECK(s.error() == std::nullopt);
}

// ----- in the device -----------------------------------------------------------------------

namespace {

/// The test dictionary with its node-ID-relative defaults marked ($NODEID), as an EDS has them:
/// the entries whose default differs between node 0 and node 1.
constexpr auto relative_specs() {
  auto s = make_specs(0);
  const auto one = make_specs(1);
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i].default_value.bits != one[i].default_value.bits) {
      s[i].flags = static_cast<std::uint16_t>(s[i].flags | od::flag::default_nodeid);
    }
  }
  return s;
}
constexpr auto lss_specs = relative_specs();
constexpr auto lss_entries = od::entries_of<lss_specs>;
constexpr od::dictionary lss_dict{lss_entries};
constexpr auto lss_layout = co::make_layout<entry_count>(lss_dict);
constexpr node::capacity lss_caps = node::capacity_for(lss_dict, {.lss = true});
static_assert(lss_caps.lss && lss_caps.rpdos == 2);
static_assert(!caps.lss); // the other node tests: no LSS
using lss_device = node::device<store_type, lss_caps>;

/// A node with LSS over the relative dictionary, started as `node`.
struct lss_rig {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(lss_layout.storage_size());
  store_type store{lss_dict, lss_layout, storage};
  lss_device dev;
  std::uint32_t now = 0;
  explicit lss_rig(std::uint8_t node, node::options o = {}, node::lss_options l = {})
      : dev(init(store, node), node, o, l) {}
  static store_type &init(store_type &s, std::uint8_t node) {
    (void)s.init_defaults(node); // FFh: relative defaults that do not fit stay 0
    return s;
  }
  std::vector<co::can_frame> feed(const co::can_frame &f) {
    return list(dev.on_frame(f, now).send);
  }
  std::uint64_t u(std::uint16_t index, std::uint8_t sub) {
    auto v = store.value({index, sub}).value();
    std::uint64_t r = 0;
    for (std::size_t i = v.size(); i-- > 0;) r = (r << 8U) | v[i];
    return r;
  }
  std::vector<node::event::kind> kinds() const {
    std::vector<node::event::kind> k;
    for (const auto &e : dev.events()) k.push_back(e.what);
    return k;
  }
};

/// An SDO upload request of 1000h to node `n`.
co::can_frame sdo_read_1000(std::uint8_t n) {
  return F(static_cast<std::uint16_t>(0x600U + n), {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
}

} // namespace

TEST_CASE("device with LSS: an unconfigured node waits in initialising, then boots") {
  lss_rig r(lss::unconfigured);
  auto s = r.dev.start(r.now);
  REQUIRE(s);
  CHECK(s.value().send.empty()); // no boot-up
  CHECK(r.dev.state() == state::boot_up);
  CHECK(s.value().deadline == std::nullopt);
  // NMT, SDO, heartbeat: nothing answers
  CHECK(r.feed(F(0, {0x01, 0})).empty());
  CHECK(r.dev.state() == state::boot_up);
  CHECK(r.feed(F(0, {0x82, 0})).empty());
  r.now = 5000;
  CHECK(list(r.dev.poll(r.now).send).empty());
  // LSS answers in initialising
  CHECK(r.feed(M(0x4C)) == std::vector{S(0x50)});
  CHECK(r.feed(M(0x04, {1})).empty());
  REQUIRE(r.dev.events().size() == 1);
  CHECK(r.dev.events()[0].what == node::event::kind::lss);
  CHECK(r.dev.lss().last_event().mode == lss_mode::configuration);
  CHECK(r.feed(M(0x5E)) == std::vector{S(0x5E, {0xFF})});
  CHECK(r.feed(M(0x11, {0x20})) == std::vector{S(0x11, {0})});
  CHECK(r.dev.state() == state::boot_up);
  // back to waiting: it boots with node 20h
  const auto out = r.feed(M(0x04, {0}));
  CHECK(out == std::vector{F(0x720, {0})});
  CHECK(r.dev.state() == state::pre_operational);
  CHECK(r.dev.node_id() == 0x20);
  CHECK(r.kinds() == std::vector{node::event::kind::lss, node::event::kind::reset_communication,
                                 node::event::kind::nmt_state});
  // its node-ID-relative objects follow: the writable ones and the read-only 1200h
  CHECK(r.u(0x1014, 0) == 0xA0);
  CHECK(r.u(0x1200, 1) == 0x620);
  CHECK(r.u(0x1200, 2) == 0x5A0);
  CHECK(r.u(0x1800, 1) == 0x1A0);
  CHECK(r.u(0x1400, 1) == 0x220);
  // SDO on the new channel, NMT with the new ID, heartbeat/guarding as 20h
  const auto sdo = r.feed(sdo_read_1000(0x20));
  REQUIRE(sdo.size() == 1);
  CHECK(sdo[0].id == 0x5A0);
  CHECK(r.feed(F(0, {0x01, 0x20})).empty());
  CHECK(r.dev.state() == state::operational);
  CHECK(r.feed(R(0x720, 1)) == std::vector{F(0x720, {0x05})});
  CHECK(r.dev.lss().active_node() == 0x20);
  CHECK(r.dev.lss().mode() == lss_mode::waiting);
}

TEST_CASE("device with LSS: a configured node takes its new node-ID at reset communication") {
  lss_rig r(5);
  REQUIRE(r.dev.start(r.now));
  CHECK(r.dev.state() == state::pre_operational);
  // switch state selective by the node's identity (1018h of the store)
  CHECK(r.feed(M32(0x40, 0x0F1C)).empty());
  CHECK(r.feed(M32(0x41, 1)).empty());
  CHECK(r.feed(M32(0x42, 0x0001'0000U)).empty());
  CHECK(r.feed(M32(0x43, 0)) == std::vector{S(0x44)});
  CHECK(r.dev.lss().mode() == lss_mode::configuration);
  CHECK(r.feed(M(0x11, {7})) == std::vector{S(0x11, {0})});
  CHECK(r.feed(M(0x11, {0})) == std::vector{S(0x11, {1})});
  CHECK(r.feed(M(0x11, {0x80})) == std::vector{S(0x11, {1})});
  CHECK(r.feed(M(0x17)) == std::vector{S(0x17, {1})}); // no store hook
  CHECK(r.feed(M(0x04, {0})).empty());                 // no boot: it has a node-ID
  CHECK(r.dev.node_id() == 5);
  CHECK(r.feed(sdo_read_1000(5)).size() == 1); // still 5
  // NMT reset communication: boot-up as 7
  const auto out = r.feed(F(0, {0x82, 5}));
  CHECK(out == std::vector{F(0x707, {0})});
  CHECK(r.dev.node_id() == 7);
  CHECK(r.u(0x1014, 0) == 0x87);
  CHECK(r.u(0x1200, 1) == 0x607);
  CHECK(r.feed(sdo_read_1000(5)).empty());
  CHECK(r.feed(sdo_read_1000(7)).size() == 1);
  // EMCY from the new COB-ID
  auto e = r.dev.raise(0x5000, r.now);
  REQUIRE(e);
  REQUIRE(e.value().send.size() == 1);
  CHECK(e.value().send[0].id == 0x87);

  // FFh: at the next reset the node has none, and waits
  (void)r.feed(M(0x04, {1}));
  CHECK(r.feed(M(0x11, {0xFF})) == std::vector{S(0x11, {0})});
  (void)r.feed(M(0x04, {0}));
  CHECK(r.feed(F(0, {0x81, 0})).empty()); // reset node: no boot-up
  CHECK(r.dev.state() == state::boot_up);
  CHECK(r.dev.node_id() == 0xFF);
  CHECK(r.feed(M(0x4C)) == std::vector{S(0x50)});
}

TEST_CASE("device with LSS: the store hook and the bit timing event") {
  struct kept {
    std::uint8_t node = 0;
    std::optional<node::lss_bit_timing> timing;
  } keep;
  node::lss_options o;
  o.context = &keep;
  o.store = [](void *c, std::uint8_t n, std::optional<node::lss_bit_timing> t) noexcept {
    static_cast<kept *>(c)->node = n;
    static_cast<kept *>(c)->timing = t;
    return node::lss_store_result{};
  };
  lss_rig r(5, {}, o);
  REQUIRE(r.dev.start(r.now));
  (void)r.feed(M(0x04, {1}));
  CHECK(r.feed(M(0x13, {0, 2})) == std::vector{S(0x13, {0})});
  CHECK(r.feed(M(0x11, {0x33})) == std::vector{S(0x11, {0})});
  CHECK(r.feed(M(0x17)) == std::vector{S(0x17, {0})});
  CHECK(keep.node == 0x33);
  CHECK(keep.timing == node::lss_bit_timing{0, 2});
  CHECK(r.feed(M(0x15, {0x10, 0x00})).empty());
  REQUIRE(r.dev.events().size() == 1);
  CHECK(r.dev.events()[0].what == node::event::kind::lss);
  const lss_event &e = r.dev.lss().last_event();
  CHECK(e.what == lss_event::kind::activate_bit_timing);
  CHECK(e.delay_ms == 16);
  CHECK(lss::standard_bit_rate(e.timing.index) == 500);
  CHECK(node::to_string(r.dev.events()[0].what) == "LSS event");
  CHECK(node::to_string(e.what) == "LSS activate bit timing");
  CHECK(node::to_string(r.dev.lss().mode()) == "LSS configuration");
  // LSS answers in every NMT state
  (void)r.feed(F(0, {0x02, 0}));
  CHECK(r.dev.state() == state::stopped);
  CHECK(r.feed(M(0x5E)) == std::vector{S(0x5E, {5})});
  (void)r.feed(F(0, {0x01, 0}));
  CHECK(r.feed(M(0x5E)) == std::vector{S(0x5E, {5})});
}

TEST_CASE("device with LSS: fastscan finds the unconfigured node") {
  lss_rig r(lss::unconfigured);
  REQUIRE(r.dev.start(r.now));
  const auto found = scan([&](const co::can_frame &f) { return !r.feed(f).empty(); });
  REQUIRE(found);
  CHECK(*found == lss::address{0x0F1C, 1, 0x0001'0000U, 0});
  CHECK(r.dev.lss().mode() == lss_mode::configuration);
  CHECK(r.feed(M(0x11, {0x0A})) == std::vector{S(0x11, {0})});
  CHECK(r.feed(M(0x04, {0})) == std::vector{F(0x70A, {0})});
}

TEST_CASE("device without LSS: no unconfigured start, 7E5h is nobody's") {
  rig<> r;
  (void)r.start();
  CHECK(r.feed(M(0x04, {1})).empty());
  CHECK(r.feed(M(0x5E)).empty());
  std::vector<std::uint8_t> storage(layout5.storage_size());
  store_type store{dict5, layout5, storage};
  REQUIRE(store.init_defaults(5));
  device_type d(store, lss::unconfigured);
  CHECK(d.start(0).error() == errc::invalid_argument);
  lss_rig l(0);
  CHECK(l.dev.start(0).error() == errc::invalid_argument);
}

namespace {
void handle(const lss_event &) {}
/// The application's storage of the docs block: what store configuration kept.
struct flash_page {
  std::uint8_t node_id = 0;
  std::optional<node::lss_bit_timing> timing;
  node::lss_store_result keep(std::uint8_t n, std::optional<node::lss_bit_timing> t) noexcept {
    node_id = n;
    timing = t;
    return {};
  }
};
} // namespace

TEST_CASE("docs/canopen.md, LSS slave: the block, compiled and run") {
  namespace gen = fieldcodec::dictionaries::xenax_canopen;
  using Store = co::dictionary_store<>;
  static constexpr auto layout = co::make_layout<gen::entries.size()>(gen::dictionary);
  std::vector<std::uint8_t> storage(layout.storage_size());
  Store store{gen::dictionary, layout, storage};
  flash_page my_flash;
  const std::uint8_t stored_id = lss::unconfigured; // nothing stored yet
  (void)store.init_defaults(stored_id);

  node::lss_options l;
  l.store = [](void *flash, std::uint8_t node_id,
               std::optional<node::lss_bit_timing> timing) noexcept {
    // keep node_id (and timing) for the next power-on: {0}, or {2} when the media fails
    return static_cast<flash_page *>(flash)->keep(node_id, timing);
  };
  l.context = &my_flash;
  l.bit_rates = 0x001F; // the controller runs 1000..125 kbit/s (indices 0..4)
  node::device<Store, node::capacity_for(gen::dictionary, {.lss = true})> dev(store, stored_id, {},
                                                                              l);
  for (const node::event &e : dev.events()) {
    if (e.what == node::event::kind::lss) handle(dev.lss().last_event());
  }

  auto s = dev.start(0);
  REQUIRE(s);
  CHECK(s.value().send.empty());
  CHECK(list(dev.on_frame(M(0x04, {1}), 0).send).empty());
  CHECK(list(dev.on_frame(M(0x13, {0, 6}), 0).send) == std::vector{S(0x13, {1})}); // 50 kbit/s
  CHECK(list(dev.on_frame(M(0x13, {0, 4}), 0).send) == std::vector{S(0x13, {0})});
  CHECK(list(dev.on_frame(M(0x11, {0x0C}), 0).send) == std::vector{S(0x11, {0})});
  CHECK(list(dev.on_frame(M(0x17), 0).send) == std::vector{S(0x17, {0})});
  CHECK(my_flash.node_id == 0x0C);
  CHECK(my_flash.timing == node::lss_bit_timing{0, 4});
  CHECK(list(dev.on_frame(M(0x04, {0}), 0).send) == std::vector{F(0x70C, {0})});
}
