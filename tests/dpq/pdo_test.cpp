// The PDO example of manual 004, 3.4 ("Example of a PDO configuration"): every parameter it
// names exists in the generated dictionary with the size the example gives, is selectable in
// the Bus Manager, and has the access its direction needs; TPDO1 packed with canopen/pdo and
// read back through the DPQ conversion; the printed 4-byte TPDO frame is refused (errata
// DPQ-F3).
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/columns.hpp>
#include <fieldcodec/dpq/parameter.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace fc = fieldcodec;
namespace co = fieldcodec::canopen;
namespace dpq = fieldcodec::dpq;
namespace od = fieldcodec::od;
namespace p = fieldcodec::dictionaries::dpq_parameters;
using fc::errc;

namespace {
struct listed {
  std::string_view name; // as the example names it (the dictionary's Name line)
  std::uint32_t bytes;
};
// "Transmission to the DPQ" and "Transmission from the DPQ", in the example's order.
constexpr std::array<listed, 9> to_dpq{{{"Inj. Position 2", 4},
                                        {"Inj. Position 3", 4},
                                        {"Inj. Velocity 1", 2},
                                        {"Inj. Velocity 2", 2},
                                        {"Inj. Velocity 3", 2},
                                        {"Inj. Velocity 4", 2},
                                        {"Holding: Time 3", 4},
                                        {"Transfer Position", 4},
                                        {"Shot Size Position", 4}}};
constexpr std::array<listed, 6> from_dpq{{{"Position FB :", 4},
                                          {"Pressure FB :", 4},
                                          {"Valve Output 1 :", 4},
                                          {"Program Block", 2},
                                          {"Status", 2},
                                          {"Discrete Outputs", 2}}};

const od::entry *by_name(std::string_view name) {
  for (const od::entry &e : p::entries) {
    if (p::dictionary.info(e).name == name) return &e;
  }
  return nullptr;
}

// Consecutive 8-byte PDOs in the example's order, a value never split across two PDOs.
std::vector<std::vector<const od::entry *>> layout(const std::vector<const od::entry *> &list) {
  std::vector<std::vector<const od::entry *>> pdos(1);
  std::uint32_t used = 0;
  for (const od::entry *e : list) {
    if (used + e->width() > 8U) {
      pdos.emplace_back();
      used = 0;
    }
    pdos.back().push_back(e);
    used += e->width();
  }
  return pdos;
}
} // namespace

TEST_CASE("dpq pdo: the example's parameters against the dictionary") {
  std::vector<const od::entry *> rx, tx;
  std::uint32_t rx_bytes = 0, tx_bytes = 0;
  for (const auto &l : to_dpq) {
    const od::entry *e = by_name(l.name);
    REQUIRE_MESSAGE(e != nullptr, l.name);
    CHECK_MESSAGE(e->width() == l.bytes, l.name);
    CHECK_MESSAGE(dpq::columns_of(p::dpq_columns, *e).bus == dpq::bus_manager::available, l.name);
    CHECK_MESSAGE(od::writable(e->access_type), l.name);
    rx.push_back(e);
    rx_bytes += e->width();
  }
  for (const auto &l : from_dpq) {
    const od::entry *e = by_name(l.name);
    REQUIRE_MESSAGE(e != nullptr, l.name);
    CHECK_MESSAGE(e->width() == l.bytes, l.name);
    CHECK_MESSAGE(dpq::columns_of(p::dpq_columns, *e).bus == dpq::bus_manager::available, l.name);
    CHECK_MESSAGE(od::readable(e->access_type), l.name);
    tx.push_back(e);
    tx_bytes += e->width();
  }
  // Both fit the Bus Manager's 32-byte areas, i.e. the four PDOs of each direction.
  CHECK(rx_bytes == 28);
  CHECK(tx_bytes == 18);
  CHECK(layout(rx).size() == 4); // 4+4 | 2+2+2+2 | 4+4 | 4
  CHECK(layout(tx).size() == 3); // 4+4 | 4+2+2 | 2
  CHECK(layout(tx)[0][0]->index == p::position_fb.index);
  CHECK(layout(tx)[0][1]->index == p::pressure_fb.index);
}

TEST_CASE("dpq pdo: TPDO1 of the example (Position FB, Pressure FB)") {
  const std::array<co::pdo::mapping_entry, 2> map{{{0x2F07, 0, 32}, {0x2F11, 0, 32}}};
  CHECK(p::position_fb.index == 0x2F07);
  CHECK(p::pressure_fb.index == 0x2F11);
  // 100.0 mm → 32767, 50.0 bar → 16383.5 → 16384.
  const auto pos = p::position_fb.to_raw(100.0);
  const auto prs = p::pressure_fb.to_raw(50.0);
  REQUIRE(pos.has_value());
  REQUIRE(prs.has_value());
  const std::array<std::uint64_t, 2> raws{static_cast<std::uint64_t>(pos.value()),
                                          static_cast<std::uint64_t>(prs.value())};
  std::array<std::uint8_t, 8> data{};
  auto n = co::pdo::pack_all(map, raws, data);
  REQUIRE(n.has_value());
  CHECK(n.value() == 8);
  const std::array<std::uint8_t, 8> want{0xFF, 0x7F, 0x00, 0x00, 0x00, 0x40, 0x00, 0x00};
  CHECK(data == want);
  std::array<std::uint64_t, 2> back{};
  REQUIRE(co::pdo::unpack_all(map, data, back).has_value());
  CHECK(dpq::from_bytes(p::position_fb, std::span<const std::uint8_t>(data).first(4))
            .value()
            .mantissa == 100000);
  CHECK(dpq::from_bytes(p::pressure_fb, std::span<const std::uint8_t>(data).subspan(4))
            .value()
            .mantissa == 50002);
  // The printed frame "0x185: 0x00 0x12 0x23 0x11" has 4 bytes: the mapping needs 8.
  const std::array<std::uint8_t, 4> printed{0x00, 0x12, 0x23, 0x11};
  CHECK(co::pdo::unpack_all(map, printed, back).error() == errc::truncated);
}

TEST_CASE("PDO mappability follows the Bus Manager column") {
  // dictionaries/dpq_parameters.csv: bus_manager "available" → pdo_mapping yes (read/write)
  // or tx (read-only); "not available" → no. The example's parameters validate as mappings.
  for (const od::entry &e : p::entries) {
    const bool available = dpq::columns_of(p::dpq_columns, e).bus == dpq::bus_manager::available;
    CHECK(od::mappable_tx(e.pdo) == available);
    CHECK(od::mappable_rx(e.pdo) == (available && od::writable(e.access_type)));
  }
  const std::array<co::pdo::mapping_entry, 2> rx{{
      co::pdo::mapping_entry{p::inj_velocity_1.index, 0, 16},
      co::pdo::mapping_entry{p::inj_position_2.index, 0, 32},
  }};
  CHECK(co::pdo::validate(p::dictionary, co::pdo::direction::rpdo,
                          std::span<const co::pdo::mapping_entry>(rx))
            .value() == 48);
  const std::array<co::pdo::mapping_entry, 1> not_available{{
      co::pdo::mapping_entry{p::analog_vel_max.index, 0, 32},
  }};
  CHECK(co::pdo::validate(p::dictionary, co::pdo::direction::tpdo,
                          std::span<const co::pdo::mapping_entry>(not_available))
            .error() == errc::access_denied);
}
