// PDO engine in the device: transmission types, RPDOs into the store, lengths, the SYNC window,
// deadline monitoring, and the CiA 301 rules for communication and mapping parameters.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/pdo_engine.hpp>

using namespace test_node;
using pdo_kind = node::pdo_event::kind;

namespace {
constexpr co::can_frame sync0() { return co::make_frame(0x80, {}).value(); }
co::can_frame sync_n(std::uint8_t c) { return F(0x80, {c}); }

std::vector<node::pdo_event> pdo_events(const device_type &d) {
  std::vector<node::pdo_event> v;
  for (const auto &e : d.events()) {
    if (e.what == node::event::kind::pdo) v.push_back(e.pdo);
  }
  return v;
}

static_assert(node::mapping_abort(co::pdo::mapping_problem::no_object) == abort_code::no_object);
static_assert(node::mapping_abort(co::pdo::mapping_problem::not_mappable) ==
              abort_code::not_mappable);
static_assert(node::mapping_abort(co::pdo::mapping_problem::no_access) == abort_code::not_mappable);
static_assert(node::mapping_abort(co::pdo::mapping_problem::length_mismatch) ==
              abort_code::not_mappable);
static_assert(node::mapping_abort(co::pdo::mapping_problem::too_long) == abort_code::pdo_too_long);
static_assert(node::is_restricted_can_id(0x000) && node::is_restricted_can_id(0x07F));
static_assert(!node::is_restricted_can_id(0x080) && !node::is_restricted_can_id(0x100));
static_assert(node::is_restricted_can_id(0x101) && node::is_restricted_can_id(0x180));
static_assert(!node::is_restricted_can_id(0x181) && !node::is_restricted_can_id(0x57F));
static_assert(node::is_restricted_can_id(0x581) && node::is_restricted_can_id(0x67F));
static_assert(!node::is_restricted_can_id(0x680) && !node::is_restricted_can_id(0x6DF));
static_assert(node::is_restricted_can_id(0x6E0) && node::is_restricted_can_id(0x7FF));
} // namespace

TEST_CASE("pdo: configuration read from the store") {
  rig<> r;
  (void)r.start();
  const auto &p = r.dev.pdo();
  REQUIRE(p.rpdo_count() == 2);
  REQUIRE(p.tpdo_count() == 2);
  CHECK(p.rpdo(0).number == 1);
  CHECK(p.rpdo(0).id() == 0x205);
  CHECK(p.rpdo(0).bytes == 6);
  CHECK(p.rpdo(1).type == 1);
  CHECK(p.tpdo(0).id() == 0x185);
  CHECK(p.tpdo(1).entries().size() == 1);
  CHECK(p.tpdo(1).entries()[0] == co::pdo::mapping_entry{0x6041, 0, 16});
  CHECK(r.dev.configuration().has_value());
}

TEST_CASE("tpdo 254/255: at operational, on change, inhibit time, event timer") {
  rig<> r;
  (void)r.start();
  CHECK(r.sdo_write(0x2100, 0, 0x11223344, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1800, 3, 50, 2) == abort_code::invalid_value); // inhibit: PDO valid
  CHECK(r.sdo_write(0x1800, 1, 0x8000'0185U, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1800, 3, 50, 2) == abort_code::none);  // 5 ms
  CHECK(r.sdo_write(0x1800, 5, 100, 2) == abort_code::none); // event timer 100 ms
  CHECK(r.sdo_write(0x1800, 1, 0x185, 4) == abort_code::none);
  CHECK(r.tick(1000).empty()); // pre-operational: no PDO
  (void)r.feed(F(0, {0x01, 5}));
  auto out = r.tick();
  CHECK(on(out, 0x185) == std::vector{F(0x185, {0x44, 0x33, 0x22, 0x11, 0, 0})});
  // a change of a mapped object: due, but inhibited for 5 ms
  CHECK(r.set_u(0x2101, 0, 0xBEEF, 2) == abort_code::none);
  CHECK(r.dev.poll(r.now).deadline == r.now + 5);
  CHECK(on(r.tick(4), 0x185).empty());
  CHECK(on(r.tick(1), 0x185) == std::vector{F(0x185, {0x44, 0x33, 0x22, 0x11, 0xEF, 0xBE})});
  // an object that is not mapped changes: nothing
  CHECK(r.set_u(0x2000, 0, 1, 4) == abort_code::none);
  CHECK(on(r.tick(10), 0x185).empty());
  // the event timer: 100 ms after the last transmission (at 1005)
  CHECK(on(r.tick(89), 0x185).empty());
  CHECK(r.now == 1104);
  CHECK(on(r.tick(1), 0x185).size() == 1);
  // the application's event
  CHECK(r.dev.request_tpdo(1).has_value());
  CHECK(on(r.tick(5), 0x185).size() == 1);
  CHECK(r.dev.request_tpdo(2) == errc::bad_state); // synchronous
  CHECK(r.dev.request_tpdo(9) == errc::unknown_object);
  // a value written by SDO marks the TPDO as well
  CHECK(r.sdo_write(0x2100, 0, 7, 4) == abort_code::none);
  CHECK(on(r.tick(5), 0x185) == std::vector{F(0x185, {7, 0, 0, 0, 0xEF, 0xBE})});
}

TEST_CASE("tpdo 1..240 and 0 on SYNC, SYNC start value") {
  rig<> r;
  (void)r.start();
  CHECK(r.set_u(0x6041, 0, 0x0237, 2) == abort_code::none);
  CHECK(r.sdo_write(0x1801, 1, 0x8000'0285U, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1801, 2, 3, 1) == abort_code::none); // every 3rd SYNC
  CHECK(r.sdo_write(0x1801, 1, 0x285, 4) == abort_code::none);
  (void)r.feed(F(0, {0x01, 5}));
  (void)r.tick();
  CHECK(on(r.feed(sync0()), 0x285).empty());
  CHECK(on(r.feed(sync0()), 0x285).empty());
  CHECK(on(r.feed(sync0()), 0x285) == std::vector{F(0x285, {0x37, 0x02})});
  CHECK(on(r.feed(sync0()), 0x285).empty());
  // SYNC start value 2 with a counter: first at the SYNC that carries 2, then every 3rd
  (void)r.feed(F(0, {0x80, 5}));
  CHECK(r.sdo_write(0x1801, 6, 241, 1) == abort_code::invalid_value);
  CHECK(r.sdo_write(0x1801, 6, 2, 1) == abort_code::invalid_value); // valid PDO
  CHECK(r.sdo_write(0x1801, 1, 0x8000'0285U, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1801, 6, 2, 1) == abort_code::none);
  CHECK(r.sdo_write(0x1801, 1, 0x285, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1019, 0, 5, 1) == abort_code::none);
  (void)r.feed(F(0, {0x01, 5}));
  (void)r.tick();
  CHECK(on(r.feed(sync_n(4)), 0x285).empty());
  CHECK(on(r.feed(sync_n(5)), 0x285).empty());
  CHECK(on(r.feed(sync_n(1)), 0x285).empty());
  CHECK(on(r.feed(sync_n(2)), 0x285).size() == 1);
  CHECK(on(r.feed(sync_n(3)), 0x285).empty());
  CHECK(on(r.feed(sync_n(4)), 0x285).empty());
  CHECK(on(r.feed(sync_n(5)), 0x285).size() == 1);
  // type 0: at the SYNC after an event only
  (void)r.feed(F(0, {0x80, 5}));
  CHECK(r.sdo_write(0x1801, 2, 0, 1) == abort_code::none);
  (void)r.feed(F(0, {0x01, 5}));
  CHECK(on(r.tick(), 0x285).empty());              // not before the SYNC
  CHECK(on(r.feed(sync_n(1)), 0x285).size() == 1); // the start is an event
  CHECK(on(r.feed(sync_n(2)), 0x285).empty());
  CHECK(r.set_u(0x6041, 0, 0x0231, 2) == abort_code::none);
  CHECK(on(r.tick(), 0x285).empty());
  CHECK(on(r.feed(sync_n(3)), 0x285) == std::vector{F(0x285, {0x31, 0x02})});
}

TEST_CASE("tpdo 252/253 and RTR") {
  rig<> r;
  (void)r.start();
  CHECK(r.set_u(0x6041, 0, 0x0001, 2) == abort_code::none);
  CHECK(r.sdo_write(0x1801, 2, 252, 1) == abort_code::none);
  CHECK(r.sdo_write(0x1800, 2, 253, 1) == abort_code::none);
  CHECK(r.set_u(0x2100, 0, 5, 4) == abort_code::none);
  (void)r.feed(F(0, {0x01, 5}));
  CHECK(r.tick().empty()); // RTR-only PDOs are not sent by themselves
  (void)r.feed(sync0());   // 252: sampled now
  CHECK(r.set_u(0x6041, 0, 0x0002, 2) == abort_code::none);
  CHECK(r.feed(R(0x285, 2)) == std::vector{F(0x285, {0x01, 0x00})}); // the SYNC's sample
  CHECK(r.feed(R(0x185, 6)) == std::vector{F(0x185, {5, 0, 0, 0, 0, 0})});
  // COB-ID bit 30: no RTR allowed
  (void)r.feed(F(0, {0x80, 5}));
  CHECK(r.sdo_write(0x1800, 1, 0x4000'0185U, 4) == abort_code::invalid_value); // while valid
  CHECK(r.sdo_write(0x1800, 1, 0xC000'0185U, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1800, 1, 0x4000'0185U, 4) == abort_code::none);
  (void)r.feed(F(0, {0x01, 5}));
  CHECK(r.feed(R(0x185, 6)).empty());
  // an RPDO's COB-ID as RTR: not a TPDO, nothing
  CHECK(r.feed(R(0x205, 6)).empty());
}

TEST_CASE("rpdo: written into the store, synchronous ones at the next SYNC") {
  rig<> r;
  r.operational();
  (void)r.tick();
  (void)r.feed(F(0x205, {0x78, 0x56, 0x34, 0x12, 0xCD, 0xAB}));
  CHECK(r.read_u(0x2000, 0) == 0x12345678);
  CHECK(r.read_u(0x2001, 0) == 0xABCD);
  auto ev = pdo_events(r.dev);
  REQUIRE(ev.size() == 1);
  CHECK(ev[0] == node::pdo_event{pdo_kind::received, co::pdo::direction::rpdo, 1, 0});
  // synchronous: held until the SYNC, the last one received counts
  (void)r.feed(F(0x305, {0x06, 0x00}));
  (void)r.feed(F(0x305, {0x0F, 0x00}));
  CHECK(r.read_u(0x6040, 0) == 0);
  (void)r.feed(sync0());
  CHECK(r.read_u(0x6040, 0) == 0x0F);
  (void)r.feed(sync0()); // nothing new: nothing applied
  CHECK(pdo_events(r.dev).empty());
}

TEST_CASE("rpdo: too short (EMCY 8210h), too long (8220h), error reset") {
  rig<> r;
  r.operational();
  (void)r.tick();
  auto out = r.feed(F(0x205, {1, 2, 3, 4, 5}));
  CHECK(r.read_u(0x2000, 0) == 0);
  REQUIRE(pdo_events(r.dev).size() == 1);
  CHECK(pdo_events(r.dev)[0].what == pdo_kind::too_short);
  CHECK(out == std::vector{F(0x85, {0x10, 0x82, 0x11, 0, 0, 0, 0, 0})});
  CHECK(r.feed(F(0x205, {1, 2, 3, 4})).empty()); // still too short: the error is active
  out = r.feed(F(0x205, {1, 0, 0, 0, 2, 0}));
  CHECK(r.read_u(0x2000, 0) == 1);
  CHECK(out == std::vector{F(0x85, {0, 0, 0, 0, 0, 0, 0, 0})});
  // too long: processed with the first bytes, EMCY 8220h
  out = r.feed(F(0x205, {9, 0, 0, 0, 8, 0, 0xFF, 0xFF}));
  CHECK(r.read_u(0x2000, 0) == 9);
  CHECK(r.read_u(0x2001, 0) == 8);
  CHECK(out == std::vector{F(0x85, {0x20, 0x82, 0x11, 0, 0, 0, 0, 0})});
  CHECK(r.read_u(0x1003, 1) == 0x8220);
  CHECK(r.read_u(0x1003, 2) == 0x8210);
  // too short again while too long is active: both codes active
  (void)r.feed(F(0x205, {1}));
  CHECK(r.read_u(0x1001, 0) == 0x11);
  CHECK(r.dev.emcy().active().size() == 2);

  node::options o;
  o.report_long_rpdo = false;
  rig<> q(o);
  q.operational();
  (void)q.tick();
  CHECK(q.feed(F(0x205, {9, 0, 0, 0, 8, 0, 0xFF, 0xFF})).empty());
  CHECK(q.read_u(0x2000, 0) == 9);
}

TEST_CASE("rpdo: synchronous window (1007h) and deadline monitoring (event timer)") {
  rig<> r;
  (void)r.start();
  CHECK(r.sdo_write(0x1007, 0, 2500, 4) == abort_code::none); // 2.5 ms: 3 ms
  CHECK(r.sdo_write(0x1400, 5, 100, 2) == abort_code::none);
  (void)r.feed(F(0, {0x01, 5}));
  (void)r.tick();
  (void)r.feed(sync0());
  (void)r.tick(2);
  (void)r.feed(F(0x305, {0x06, 0}));
  (void)r.tick(1);
  (void)r.feed(F(0x305, {0x07, 0})); // after the window: discarded
  REQUIRE(pdo_events(r.dev).size() == 1);
  CHECK(pdo_events(r.dev)[0].what == pdo_kind::outside_window);
  (void)r.feed(sync0());
  CHECK(r.read_u(0x6040, 0) == 0x06);
  // RPDO 1's event timer starts with its first reception
  CHECK(r.tick(1000).empty());
  (void)r.feed(F(0x205, {1, 0, 0, 0, 0, 0}));
  CHECK(r.tick(99).empty());
  auto out = r.tick(1);
  REQUIRE(pdo_events(r.dev).size() == 1);
  CHECK(pdo_events(r.dev)[0].what == pdo_kind::timeout);
  CHECK(out == std::vector{F(0x85, {0x50, 0x82, 0x11, 0, 0, 0, 0, 0})});
  out = r.feed(F(0x205, {2, 0, 0, 0, 0, 0}));
  CHECK(out == std::vector{F(0x85, {0, 0, 0, 0, 0, 0, 0, 0})});
}

TEST_CASE("pdo mapping: only through the CiA 301 sequence") {
  rig<> r;
  (void)r.start();
  // the PDO is valid: neither sub 0 nor an entry may change (0x06040043)
  CHECK(r.sdo_write(0x1A00, 0, 0, 1) == abort_code::parameter_incompatible);
  CHECK(r.sdo_write(0x1A00, 1, 0x2000'0020, 4) == abort_code::parameter_incompatible);
  // writing the values it already has is fine (configuration tools write whole DCFs)
  CHECK(r.sdo_write(0x1A00, 0, 2, 1) == abort_code::none);
  CHECK(r.sdo_write(0x1A00, 1, 0x2100'0020, 4) == abort_code::none);
  // 1. make the PDO invalid
  CHECK(r.sdo_write(0x1800, 1, 0x8000'0185U, 4) == abort_code::none);
  // entries may not change while sub 0 is not 0
  CHECK(r.sdo_write(0x1A00, 1, 0x2000'0020, 4) == abort_code::parameter_incompatible);
  // 2. sub 0 = 0
  CHECK(r.sdo_write(0x1A00, 0, 0, 1) == abort_code::none);
  // 3. entries, each checked
  CHECK(r.sdo_write(0x1A00, 1, 0x3000'0020, 4) == abort_code::no_object);
  CHECK(r.sdo_write(0x1A00, 1, 0x2008'0020, 4) == abort_code::not_mappable); // not mappable
  CHECK(r.sdo_write(0x1A00, 1, 0x2009'0020, 4) == abort_code::not_mappable); // write-only
  CHECK(r.sdo_write(0x1A00, 1, 0x2000'0010, 4) == abort_code::not_mappable); // 16 of 32 bits
  CHECK(r.sdo_write(0x1A00, 1, 0x2000'0000, 4) == abort_code::not_mappable); // 0 bits
  CHECK(r.sdo_write(0x1A00, 1, 0x2007'0020, 4) == abort_code::none);         // ro is fine (TPDO)
  CHECK(r.sdo_write(0x1A00, 2, 0x2003'0001, 4) == abort_code::none);         // a 1-bit boolean
  CHECK(r.sdo_write(0x1A00, 3, 0x0001'0007, 4) == abort_code::not_mappable); // BOOLEAN dummy: 1 bit
  CHECK(r.sdo_write(0x1A00, 3, 0x0001'0001, 4) == abort_code::none);         // a 1-bit gap
  CHECK(r.sdo_write(0x1A00, 4, 0x2102'0008, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1A00, 0, 5, 1) == abort_code::pdo_too_long); // only 4 entries exist
  // 4. sub 0 = n
  CHECK(r.sdo_write(0x1A00, 0, 4, 1) == abort_code::none);
  // the PDO is still invalid: entries are refused now that sub 0 is not 0
  CHECK(r.sdo_write(0x1A00, 4, 0x2101'0010, 4) == abort_code::parameter_incompatible);
  // 5. valid again
  CHECK(r.sdo_write(0x1800, 1, 0x185, 4) == abort_code::none);
  CHECK(r.dev.pdo().tpdo(0).bytes == 6); // 32 + 1 + 1 + 8 bits
  CHECK(r.set_u(0x2003, 0, 1, 1) == abort_code::none);
  CHECK(r.set_u(0x2102, 0, 0xFE, 1) == abort_code::none);
  (void)r.feed(F(0, {0x01, 5}));
  // 2007h, then bit 32 = 2003h, bit 33 = the gap, bits 34..41 = 2102h (0xFE)
  CHECK(on(r.tick(), 0x185) == std::vector{F(0x185, {0x78, 0x56, 0x34, 0x12, 0xF9, 0x03})});
}

TEST_CASE("pdo mapping: too long for 64 bits, RPDO access, sub 0 from a stored entry") {
  rig<> r;
  (void)r.start();
  CHECK(r.sdo_write(0x1400, 1, 0x8000'0205U, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1600, 0, 0, 1) == abort_code::none);
  CHECK(r.sdo_write(0x1600, 1, 0x2007'0020, 4) == abort_code::not_mappable); // ro into RPDO
  CHECK(r.sdo_write(0x1600, 1, 0x2000'0020, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1600, 2, 0x2004'0020, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1600, 3, 0x2001'0010, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1600, 0, 3, 1) == abort_code::pdo_too_long);   // 80 bits
  CHECK(r.sdo_write(0x1600, 3, 0x0005'0008, 4) == abort_code::none); // dummy UNSIGNED8
  CHECK(r.sdo_write(0x1600, 0, 3, 1) == abort_code::pdo_too_long);   // 72 bits
  CHECK(r.sdo_write(0x1600, 0, 2, 1) == abort_code::none);
  CHECK(r.sdo_write(0x1400, 1, 0x205, 4) == abort_code::none);
  (void)r.feed(F(0, {0x01, 5}));
  (void)r.feed(F(0x205, {1, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF}));
  CHECK(r.read_u(0x2004, 0) == 0xFFFF'FFFFU); // -1
  CHECK(r.dev.pdo().rpdo(0).bytes == 8);
}

TEST_CASE("pdo communication parameters: COB-ID and transmission type rules") {
  rig<> r;
  (void)r.start();
  CHECK(r.sdo_write(0x1400, 1, 0x206, 4) == abort_code::invalid_value);        // valid→valid
  CHECK(r.sdo_write(0x1400, 1, 0x0000'0A05U, 4) == abort_code::invalid_value); // bit 11
  CHECK(r.sdo_write(0x1400, 1, 0x2000'0205U, 4) == abort_code::invalid_value); // 29-bit
  CHECK(r.sdo_write(0x1400, 1, 0x8000'0000U, 4) == abort_code::none);          // invalid
  CHECK(r.sdo_write(0x1400, 1, 0x0000'0705U, 4) == abort_code::invalid_value); // restricted
  CHECK(r.sdo_write(0x1400, 1, 0x0000'0585U, 4) == abort_code::invalid_value); // restricted
  CHECK(r.sdo_write(0x1400, 1, 0x8000'0705U, 4) == abort_code::none);          // invalid: any id
  CHECK(r.sdo_write(0x1400, 1, 0x0000'0210U, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1400, 2, 241, 1) == abort_code::invalid_value);
  CHECK(r.sdo_write(0x1400, 2, 251, 1) == abort_code::invalid_value);
  CHECK(r.sdo_write(0x1400, 2, 252, 1) == abort_code::invalid_value); // RTR types: TPDO only
  CHECK(r.sdo_write(0x1400, 2, 253, 1) == abort_code::invalid_value);
  CHECK(r.sdo_write(0x1400, 2, 240, 1) == abort_code::none);
  CHECK(r.sdo_write(0x1800, 2, 252, 1) == abort_code::none);
  CHECK(r.sdo_write(0x1800, 2, 250, 1) == abort_code::invalid_value);
  // the valid bit is honoured: an invalid PDO is neither received nor sent
  (void)r.feed(F(0, {0x01, 5}));
  (void)r.feed(F(0x205, {1, 0, 0, 0, 0, 0}));
  CHECK(r.read_u(0x2000, 0) == 0);
  CHECK(r.sdo_write(0x1400, 2, 255, 1) == abort_code::none);
  (void)r.feed(F(0x210, {1, 0, 0, 0, 0, 0}));
  CHECK(r.read_u(0x2000, 0) == 1);
  CHECK(r.sdo_write(0x1800, 1, 0x8000'0185U, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1800, 2, 255, 1) == abort_code::none);
  CHECK(r.set_u(0x2100, 0, 3, 4) == abort_code::none);
  CHECK(on(r.tick(10), 0x185).empty());
}

namespace {
/// A write hook that refuses the value 0xBAD for 2000h and counts what it saw.
struct guard_hook {
  int *seen;
  abort_code operator()(const od::entry &e, std::span<const std::uint8_t> v) const {
    ++*seen;
    if (e.index == 0x2000 && v.size() == 4 && v[0] == 0xAD && v[1] == 0x0B) {
      return abort_code::cannot_store_device_state;
    }
    return abort_code::none;
  }
};
} // namespace

TEST_CASE("rpdo: the application's write hook sees RPDO data and may refuse one object") {
  std::vector<std::uint8_t> storage(layout5.storage_size());
  int seen = 0;
  co::dictionary_store<guard_hook> store{dict5, layout5, storage, {}, guard_hook{&seen}};
  REQUIRE(store.init_defaults(5).has_value());
  node::device<co::dictionary_store<guard_hook>, caps> dev(store, 5);
  (void)dev.start(0);
  (void)dev.on_frame(F(0, {0x01, 5}), 0);
  (void)dev.on_frame(F(0x205, {0xAD, 0x0B, 0, 0, 0x34, 0x12}), 0);
  CHECK(seen == 2);
  CHECK(store.value({0x2000, 0}).value()[0] == 0); // refused: the old value
  CHECK(store.value({0x2001, 0}).value()[0] == 0x34);
  REQUIRE(dev.events().size() == 1);
  CHECK(dev.events()[0].pdo.refused == 1);
}

TEST_CASE("device::set with now returns the event-driven TPDOs it makes due") {
  rig<> r;
  (void)r.start();
  (void)r.feed(F(0, {0x01, 5}));
  (void)r.tick(); // the event-driven TPDO 1 once on entering operational
  // TPDO 1 (255, no inhibit time) maps 2100h and 2101h: set() sends it
  CHECK(r.set_send(0x2100, 0, 0x11223344, 4) == abort_code::none);
  CHECK(r.set_frames == std::vector{F(0x185, {0x44, 0x33, 0x22, 0x11, 0, 0})});
  CHECK(on(r.tick(), 0x185).empty()); // sent once, not again by poll
  // both objects of the TPDO: the first without now (due, not sent), the last with it
  CHECK(r.set_u(0x2100, 0, 0x01020304, 4) == abort_code::none);
  CHECK(r.set_send(0x2101, 0, 0xBEEF, 2) == abort_code::none);
  CHECK(r.set_frames == std::vector{F(0x185, {4, 3, 2, 1, 0xEF, 0xBE})});
  // an object no TPDO maps: nothing
  CHECK(r.set_send(0x2000, 0, 1, 4) == abort_code::none);
  CHECK(r.set_frames.empty());
  // refused: nothing stored, nothing sent
  CHECK(r.set_send(0x1029, 1, 9, 1) == abort_code::invalid_value);
  CHECK(r.read_u(0x1029, 1) == 0);
  // with an inhibit time the step's deadline says when it goes out
  CHECK(r.sdo_write(0x1800, 1, 0x8000'0185U, 4) == abort_code::none);
  CHECK(r.sdo_write(0x1800, 3, 50, 2) == abort_code::none); // 5 ms
  CHECK(r.sdo_write(0x1800, 1, 0x185, 4) == abort_code::none);
  (void)r.tick(); // the TPDO that became valid
  CHECK(r.set_send(0x2101, 0, 0xCAFE, 2) == abort_code::none);
  CHECK(r.set_frames.empty());
  CHECK(r.deadline == r.now + 5);
  CHECK(on(r.tick(5), 0x185) == std::vector{F(0x185, {4, 3, 2, 1, 0xFE, 0xCA})});
  // a type 0 TPDO (acyclic synchronous) waits for the SYNC
  CHECK(r.sdo_write(0x1800, 2, 0, 1) == abort_code::none);
  CHECK(r.set_send(0x2100, 0, 5, 4) == abort_code::none);
  CHECK(on(r.set_frames, 0x185).empty());
  CHECK(on(r.feed(F(0x80, {})), 0x185) == std::vector{F(0x185, {5, 0, 0, 0, 0xFE, 0xCA})});
  // in pre-operational there are no PDOs
  (void)r.feed(F(0, {0x80, 5}));
  CHECK(r.sdo_write(0x1800, 2, 255, 1) == abort_code::none);
  CHECK(r.set_send(0x2100, 0, 6, 4) == abort_code::none);
  CHECK(r.set_frames.empty());
}
