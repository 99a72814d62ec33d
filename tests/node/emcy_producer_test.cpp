// EMCY producer: active errors, error register, pre-defined error field, inhibit time, COB-ID;
// and 1001h/1003h/1014h/1015h in the device.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/emcy_producer.hpp>

using namespace test_node;
namespace reg = co::emcy::reg;

namespace {
constexpr bool raise_and_clear() {
  node::emcy_producer<4, 4, 2> e(5);
  auto s = e.raise(0x2310, 0); // current, device output side
  if (!s || s.value().send.size() != 1) return false;
  const auto f = s.value().send[0];
  if (f != co::make_frame(0x85, {0x10, 0x23, 0x03, 0, 0, 0, 0, 0}).value()) return false;
  if (e.error_register() != (reg::generic | reg::current)) return false;
  auto c = e.clear(0x2310, 1);
  return c && c.value().send.size() == 1 &&
         c.value().send[0] == co::make_frame(0x85, {0, 0, 0, 0, 0, 0, 0, 0}).value() &&
         e.error_register() == 0;
}
static_assert(raise_and_clear());

static_assert(node::register_bit(0x2310) == reg::current);
static_assert(node::register_bit(0x3210) == reg::voltage);
static_assert(node::register_bit(0x4210) == reg::temperature);
static_assert(node::register_bit(0x8110) == reg::communication);
static_assert(node::register_bit(0x8210) == reg::communication);
static_assert(node::register_bit(0x8611) == 0); // monitoring, not communication
static_assert(node::register_bit(0x1000) == 0); // generic: bit 0 comes with every error
} // namespace

TEST_CASE("emcy producer: register_bit by the first digit agrees with emcy::classify") {
  // register_bit reads the first digit only; the classes of CiA 301 (emcy::classify) decide
  using cls = co::emcy::error_class;
  int differ = 0;
  for (std::uint32_t c = 0; c <= 0xFFFFU; ++c) {
    const auto code = static_cast<std::uint16_t>(c);
    std::uint8_t expected = 0;
    switch (co::emcy::classify(code)) {
    case cls::current: expected = reg::current; break;
    case cls::voltage: expected = reg::voltage; break;
    case cls::temperature: expected = reg::temperature; break;
    case cls::monitoring:
      expected = (code >> 8U) == 0x81U || (code >> 8U) == 0x82U ? reg::communication : 0U;
      break;
    default: break;
    }
    if (node::register_bit(code) != expected) ++differ;
  }
  CHECK(differ == 0);
}

TEST_CASE("emcy producer: register, history newest first, manufacturer bytes") {
  node::emcy_producer<3, 2, 4> e(9);
  auto s = e.raise(0x4210, 0, reg::device_profile, {0xAA, 0xBB, 1, 2, 3});
  REQUIRE(s);
  CHECK(list(s.value().send) == std::vector{F(0x89, {0x10, 0x42, 0x29, 0xAA, 0xBB, 1, 2, 3})});
  CHECK(s.value().state == (reg::generic | reg::temperature | reg::device_profile));
  // the same code again: nothing new
  CHECK(e.raise(0x4210, 1).value().send.empty());
  REQUIRE(e.raise(0x3100, 2));
  REQUIRE(e.raise(0xFF01, 3, reg::manufacturer));
  CHECK(e.error_register() ==
        (reg::generic | reg::temperature | reg::device_profile | reg::voltage | reg::manufacturer));
  // full
  CHECK(e.raise(0x5000, 4) == errc::buffer_too_small);
  // history: 2 entries, newest first, the first two manufacturer bytes above the code
  REQUIRE(e.history().size() == 2);
  CHECK(e.history()[0] == 0x0000'FF01U);
  CHECK(e.history()[1] == 0x0000'3100U);
  CHECK(e.raise(0, 5) == errc::invalid_argument); // 0000h is "no error"
  CHECK(e.clear(0x1234, 5) == errc::unknown_object);
  // clearing one of several: no message (report_each_reset off), register shrinks
  CHECK(e.clear(0x4210, 6).value().send.empty());
  CHECK(e.error_register() == (reg::generic | reg::voltage | reg::manufacturer));
  e.report_each_reset(true);
  auto c = e.clear(0x3100, 7);
  CHECK(list(c.value().send) == std::vector{F(0x89, {0, 0, 0x81, 0, 0, 0, 0, 0})});
  auto all = e.clear_all(8);
  CHECK(list(all.send) == std::vector{F(0x89, {0, 0, 0, 0, 0, 0, 0, 0})});
  CHECK(e.active().empty());
  CHECK(e.clear_all(9).send.empty());
  e.clear_history();
  CHECK(e.history().empty());
}

TEST_CASE("emcy producer: inhibit time holds messages back, a full queue drops") {
  node::emcy_producer<8, 8, 2> e(1);
  e.set_inhibit(25); // 2.5 ms: 3 ms on a millisecond clock
  CHECK(e.raise(0x1000, 100).value().send.size() == 1);
  auto s = e.raise(0x2000, 101);
  CHECK(s.value().send.empty());
  CHECK(s.value().deadline == 103U);
  CHECK(e.raise(0x3000, 101).value().send.empty());
  CHECK(e.raise(0x4000, 102).value().send.empty()); // queue of 2 full: dropped
  CHECK(e.dropped() == 1);
  CHECK(e.is_active(0x4000)); // the error is still recorded
  CHECK(e.poll(102).send.empty());
  auto p = e.poll(103);
  REQUIRE(p.send.size() == 1);
  CHECK(p.send[0].data[1] == 0x20);
  CHECK(p.deadline == 106U);
  CHECK(e.poll(106).send[0].data[1] == 0x30);
  CHECK_FALSE(e.poll(200).deadline);
  // disabled (NMT stopped): not sent, counted
  e.enable(false);
  CHECK(e.raise(0x5000, 300).value().send.empty());
  CHECK(e.dropped() == 2);
}

TEST_CASE("emcy producer: COB-ID rules (1014h)") {
  node::emcy_producer<2, 2, 2> e(5);
  CHECK(e.cob_id_value() == 0x85);
  CHECK(e.check_cob_id(0x86) == abort_code::invalid_value);         // change while valid
  CHECK(e.check_cob_id(0x4000'0085U) == abort_code::invalid_value); // reserved bit 30
  CHECK(e.check_cob_id(0x2000'0085U) == abort_code::invalid_value); // 29-bit
  CHECK(e.check_cob_id(0x0000'0885U) == abort_code::invalid_value); // bit 11
  CHECK(e.set_cob_id(0x8000'0085U) == abort_code::none);            // invalid first
  CHECK(e.raise(0x1000, 0).value().send.empty());                   // no EMCY object
  CHECK(e.dropped() == 0);
  CHECK(e.check_cob_id(0x0000'0701U) == abort_code::invalid_value); // restricted
  CHECK(e.set_cob_id(0x0000'00A0U) == abort_code::none);            // then a new one
  CHECK(list(e.clear(0x1000, 0).value().send) == std::vector{F(0xA0, {0, 0, 0, 0, 0, 0, 0, 0})});
}

TEST_CASE("device: 1001h and 1003h follow the errors; writing 1003h sub 0") {
  rig<> r;
  (void)r.start();
  auto s = r.dev.raise(0x2310, 0, 0, {1, 2, 0, 0, 0});
  REQUIRE(s);
  CHECK(list(s.value().send) == std::vector{F(0x85, {0x10, 0x23, 0x03, 1, 2, 0, 0, 0})});
  REQUIRE(r.dev.raise(0x3210, 0));
  CHECK(r.read_u(0x1001, 0) == 0x07);
  CHECK(r.read_u(0x1003, 0) == 2);
  CHECK(r.read_u(0x1003, 1) == 0x3210);
  CHECK(r.read_u(0x1003, 2) == 0x0201'2310U);
  // CiA 301: only 0 may be written to sub 0 (clears the history); other values 0x06090030;
  // the entries are read-only
  CHECK(r.sdo_write(0x1003, 0, 1, 1) == abort_code::invalid_value);
  CHECK(r.sdo_write(0x1003, 1, 0, 4) == abort_code::write_read_only);
  CHECK(r.read_u(0x1003, 0) == 2);
  CHECK(r.sdo_write(0x1003, 0, 0, 1) == abort_code::none);
  CHECK(r.read_u(0x1003, 0) == 0);
  CHECK(r.read_u(0x1003, 1) == 0);
  CHECK(r.read_u(0x1001, 0) == 0x07); // the errors are still active
  CHECK(r.sdo_write(0x1001, 0, 0, 1) == abort_code::write_read_only);
  // the history holds 4 (1003h sub 1..4): the oldest falls off
  for (const std::uint16_t c : std::array<std::uint16_t, 5>{0x5001, 0x5002, 0x5003, 0x5004, 0x5005})
    REQUIRE(r.dev.raise(c, 0));
  CHECK(r.read_u(0x1003, 0) == 4);
  CHECK(r.read_u(0x1003, 1) == 0x5005);
  CHECK(r.read_u(0x1003, 4) == 0x5002);
  // the last error clears: error reset, register 0
  for (const std::uint16_t c :
       std::array<std::uint16_t, 6>{0x2310, 0x3210, 0x5001, 0x5002, 0x5003, 0x5004}) {
    CHECK(r.dev.clear(c, 0).value().send.empty());
  }
  CHECK(list(r.dev.clear(0x5005, 0).value().send) ==
        std::vector{F(0x85, {0, 0, 0, 0, 0, 0, 0, 0})});
  CHECK(r.read_u(0x1001, 0) == 0);
  CHECK(r.dev.clear(0x5005, 0) == errc::unknown_object);
}

TEST_CASE("device: EMCY COB-ID and inhibit time by SDO; no EMCY in stopped") {
  rig<> r;
  (void)r.start();
  CHECK(r.sdo_write(0x1014, 0, 0x95, 4) == abort_code::invalid_value);
  CHECK(r.sdo_write(0x1014, 0, 0x8000'0085U, 4) == abort_code::none);
  CHECK(r.dev.raise(0x1000, 0).value().send.empty());
  CHECK(r.sdo_write(0x1014, 0, 0x95, 4) == abort_code::none);
  CHECK(list(r.dev.clear(0x1000, 0).value().send) ==
        std::vector{F(0x95, {0, 0, 0, 0, 0, 0, 0, 0})});
  CHECK(r.sdo_write(0x1015, 0, 100, 2) == abort_code::none); // 10 ms
  CHECK(r.dev.raise(0x1000, 0).value().send.size() == 1);
  auto held = r.dev.raise(0x2000, 1).value();
  CHECK(held.send.empty());
  CHECK(held.deadline == 10U);
  r.now = 10;
  CHECK(r.tick().size() == 1);
  (void)r.feed(F(0, {0x02, 5}));
  CHECK(r.dev.raise(0x3000, 20).value().send.empty());
  CHECK(r.dev.emcy().dropped() == 1);
  CHECK(r.read_u(0x1001, 0) == 0x07); // 1000h, 2000h, 3000h: still recorded
}
