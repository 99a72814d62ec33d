// master::plan_pdo: the SDO sequence that maps objects into a PDO, checked against the XENAX
// dictionary first, and run by the configurator against the simulated XENAX.
#include "sim_device.hpp"

#include <fieldcodec/master/configurator.hpp>
#include <fieldcodec/master/pdo_config.hpp>

#include <doctest/doctest.h>

#include <vector>

namespace master = fieldcodec::master;
namespace pdo = fieldcodec::canopen::pdo;
namespace csdo = fieldcodec::canopen::sdo;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;
using fieldcodec::errc;
using fieldcodec::od::address;

namespace {

std::vector<std::pair<address, std::uint32_t>> writes(const master::pdo_sequence &s) {
  std::vector<std::pair<address, std::uint32_t>> r;
  for (const auto &i : s.items()) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < i.value.size(); ++k) v |= std::uint32_t{i.value[k]} << (8U * k);
    r.emplace_back(i.address, v);
  }
  return r;
}

} // namespace

TEST_CASE("pdo config: RPDO 2 of node 5 with controlword and target position") {
  constexpr pdo::mapping_entry rx[] = {{0x6040, 0, 16}, {0x607A, 0, 32}};
  master::pdo_sequence seq;
  auto n = master::plan_pdo(
      xcan::dictionary,
      {.dir = pdo::direction::rpdo, .number = 2, .node = 5, .entries = rx, .transmission_type = 1},
      seq);
  REQUIRE(n);
  const std::vector<std::pair<address, std::uint32_t>> expect{
      {{0x1401, 1}, 0x80000305U},                                                // invalid first
      {{0x1401, 2}, 1U},                                                         // on every SYNC
      {{0x1401, 5}, 0U},                                                         // event timer
      {{0x1601, 0}, 0U},                                                         // mapping off
      {{0x1601, 1}, 0x60400010U}, {{0x1601, 2}, 0x607A0020U}, {{0x1601, 0}, 2U}, // mapping on
      {{0x1401, 1}, 0x00000305U},                                                // valid
  };
  CHECK(writes(seq) == expect);
  CHECK(n.value() == expect.size());
  CHECK(seq.items()[0].value.size() == 4U);
  CHECK(seq.items()[3].value.size() == 1U);

  // and the configurator writes it into the device
  sim::device d(5);
  csdo::client client(5, 100);
  master::configurator c(client, {.verify = true});
  auto s = c.start(seq.list(), 0);
  REQUIRE(s);
  auto step = s.value();
  for (int guard = 0; guard < 200 && c.busy(); ++guard) {
    std::vector<fieldcodec::canopen::can_frame> replies;
    for (const auto &f : step.send) {
      for (const auto &r : d.receive(f)) replies.push_back(r);
    }
    REQUIRE_FALSE(replies.empty());
    for (const auto &r : replies) step = c.on_frame(r, 0);
  }
  CHECK(c.state() == master::config_state::done);
  CHECK(d.get({0x1601, 0}) == 2U);
  CHECK(d.get({0x1601, 2}) == 0x607A0020U);
  CHECK(d.get({0x1401, 1}) == 0x305U);
}

TEST_CASE("pdo config: TPDO 1 with an explicit COB-ID and inhibit time") {
  constexpr pdo::mapping_entry tx[] = {{0x6041, 0, 16}};
  master::pdo_sequence seq;
  auto n = master::plan_pdo(xcan::dictionary,
                            {.dir = pdo::direction::tpdo,
                             .number = 1,
                             .entries = tx,
                             .cob_id = 0x1A5,
                             .inhibit_time = 10},
                            seq);
  REQUIRE(n);
  const std::vector<std::pair<address, std::uint32_t>> expect{
      {{0x1800, 1}, 0x800001A5U}, {{0x1800, 2}, 255U},  {{0x1800, 3}, 10U},
      {{0x1800, 5}, 0U},          {{0x1A00, 0}, 0U},    {{0x1A00, 1}, 0x60410010U},
      {{0x1A00, 0}, 1U},          {{0x1800, 1}, 0x1A5U}};
  CHECK(writes(seq) == expect);
}

TEST_CASE("pdo config: precise errors before anything is sent") {
  master::pdo_sequence seq;
  const auto plan = [&seq](pdo::direction d, std::uint16_t n,
                           std::span<const pdo::mapping_entry> e) {
    return master::plan_pdo(xcan::dictionary, {.dir = d, .number = n, .node = 5, .entries = e},
                            seq);
  };
  SUBCASE("wrong direction: the statusword into an RPDO") {
    constexpr pdo::mapping_entry e[] = {{0x6040, 0, 16}, {0x6041, 0, 16}};
    auto r = plan(pdo::direction::rpdo, 2, e);
    REQUIRE_FALSE(r);
    CHECK(r.error().is(errc::access_denied));
    CHECK(r.error().problem == pdo::mapping_problem::no_access);
    CHECK(r.error().entry == 1U);
    CHECK(r.error().object == address{0x6041, 0});
  }
  SUBCASE("not mappable") {
    constexpr pdo::mapping_entry e[] = {{0x6098, 0, 8}};
    auto r = plan(pdo::direction::rpdo, 1, e);
    CHECK(r.error().problem == pdo::mapping_problem::not_mappable);
    CHECK(r.error().object == address{0x6098, 0});
  }
  SUBCASE("too long: more than 64 bits") {
    constexpr pdo::mapping_entry e[] = {{0x607A, 0, 32}, {0x607A, 0, 32}, {0x6040, 0, 16}};
    auto r = plan(pdo::direction::rpdo, 2, e);
    CHECK(r.error().is(errc::too_long));
    CHECK(r.error().problem == pdo::mapping_problem::too_long);
    CHECK(r.error().entry == 2U);
  }
  SUBCASE("more entries than the device's mapping object has") {
    constexpr pdo::mapping_entry e[] = {{0x6040, 0, 16}, {0x6060, 0, 8}};
    auto r = plan(pdo::direction::rpdo, 1, e); // 1600h has one entry on the XENAX
    CHECK(r.error().is(errc::too_long));
    CHECK(r.error().problem == pdo::mapping_problem::too_many_entries);
    CHECK(r.error().entry == 1U);
    CHECK(r.error().object == address{0x1600, 2});
  }
  SUBCASE("wrong length") {
    constexpr pdo::mapping_entry e[] = {{0x607A, 0, 16}};
    CHECK(plan(pdo::direction::rpdo, 2, e).error().problem ==
          pdo::mapping_problem::length_mismatch);
  }
  SUBCASE("unknown object") {
    constexpr pdo::mapping_entry e[] = {{0x6FFF, 0, 16}};
    CHECK(plan(pdo::direction::rpdo, 2, e).error().is(errc::unknown_object));
  }
  SUBCASE("a PDO the device does not have") {
    constexpr pdo::mapping_entry e[] = {{0x6040, 0, 16}};
    auto r = master::plan_pdo(
        xcan::dictionary, {.dir = pdo::direction::rpdo, .number = 3, .entries = e, .cob_id = 0x400},
        seq);
    CHECK(r.error().is(errc::unknown_object));
    CHECK(r.error().object == address{0x1402, 1});
  }
  SUBCASE("PDO number, COB-ID and transmission type") {
    constexpr pdo::mapping_entry e[] = {{0x6040, 0, 16}};
    CHECK(plan(pdo::direction::rpdo, 0, e).error().is(errc::invalid_argument));
    CHECK(plan(pdo::direction::rpdo, 513, e).error().is(errc::invalid_argument));
    CHECK(master::plan_pdo(xcan::dictionary, {.number = 5, .node = 5, .entries = e}, seq)
              .error()
              .is(errc::invalid_argument)); // PDO 5: no predefined COB-ID
    CHECK(master::plan_pdo(xcan::dictionary, {.number = 1, .entries = e}, seq)
              .error()
              .is(errc::invalid_argument)); // no node
    CHECK(master::plan_pdo(xcan::dictionary, {.number = 1, .entries = e, .cob_id = 0x800}, seq)
              .error()
              .is(errc::invalid_argument));
    CHECK(master::plan_pdo(xcan::dictionary,
                           {.number = 1, .node = 5, .entries = e, .transmission_type = 252}, seq)
              .error()
              .is(errc::out_of_range)); // RTR type on an RPDO
  }
  CHECK(seq.items().empty()); // nothing planned after an error
}
