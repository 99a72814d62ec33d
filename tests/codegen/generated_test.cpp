// The checked-in generated dictionaries: shapes other modules rely on.
#include <fieldcodec/dictionaries/compax_objects.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/od/value.hpp>

#include <doctest/doctest.h>

#include <array>
#include <span>

namespace dpq = fieldcodec::dictionaries::dpq_parameters;
namespace pac = fieldcodec::dictionaries::pacontrol_commands;
namespace xc = fieldcodec::dictionaries::xenax_canopen;
using fieldcodec::errc;

// DPQ manual 004, chapter 3: Inj. P Limit 1 = 4.0 bar with scale 327,67 → 1311 (0x051F).
static_assert(dpq::inj_p_limit_1.index == 0x2023);
static_assert(dpq::inj_p_limit_1.to_raw(4.0).value() == 1311);
static_assert(dpq::inj_p_limit_1.to_raw(5000.5).error() == errc::out_of_range);
// a named descriptor is a standalone copy of its table row (entry, info, scale)
static_assert(dpq::dictionary.info(*dpq::dictionary.lookup(0x2023, 0).value()).name ==
              dpq::inj_p_limit_1.info.name);
// 221 bus parameters of chapter 4 + 19 communication objects of chapter 3 (docs/dpq.md)
static_assert(dpq::dictionary.size() == 240);

static_assert(pac::table.find(0x0600) == &pac::cmd_stop);
static_assert(pac::cmd_stop.allowed_in("online"));

TEST_CASE("generated: xenax_canopen identity object") {
  const auto *e = xc::dictionary.find(0x1018, 1);
  REQUIRE(e != nullptr);
  CHECK(e->type == fieldcodec::od::data_type::unsigned32);
  CHECK(xc::dictionary.object(0x1018).size() >= 2);
}

// COMPAX manual 000, 2.10.4: OUTPUT_MASK (5FF5h, OCTET_STRING of 2 bytes) is 0 after power on.
// The CSV writes it as the hex digits 0000: the default is two zero bytes, not the text "0".
TEST_CASE("generated: an OCTET_STRING default is its bytes, NULs included") {
  const auto *e = fieldcodec::dictionaries::compax_objects::dictionary.find(0x5FF5, 0);
  REQUIRE(e != nullptr);
  CHECK(e->capacity() == 2);
  CHECK(e->default_text() == std::string_view("\0\0", 2));
}

TEST_CASE("generated: XENAX strings have a capacity (issue 12.1)") {
  const auto *e = xc::dictionary.find(0x1008, 0);
  REQUIRE(e != nullptr);
  CHECK(e->default_text() == "Servocontroller XENAX Xvi xxVx");
  CHECK(e->capacity() >= e->default_text().size()); // its default's length at least (30)
}

// The generated PDO layouts (fieldcodec-gen --pdo-header, issue 29): the XENAX EtherCAT PDOs of
// manual chapter 7 as compile-time layouts, checked against the dictionary by the compiler.
#include <fieldcodec/dictionaries/xenax_canopen_pdos.hpp>
#include <fieldcodec/dictionaries/xenax_ethercat_pdos.hpp>

namespace xe_pdos = fieldcodec::dictionaries::xenax_ethercat::pdos;
namespace xc_pdos = fieldcodec::dictionaries::xenax_canopen::pdos;
namespace pdo = fieldcodec::canopen::pdo;

// 7.1.2: TxPDO 21 (1A13h, TwinCAT): statusword, actual position, following error, actual
// current, process status register: 16 + 32 + 32 + 16 + 32 bits
static_assert(xe_pdos::txpdo_1a13.entries.size() == 5);
static_assert(xe_pdos::txpdo_1a13.entries[0] == pdo::mapping_entry{0x6041, 0, 16});
static_assert(xe_pdos::txpdo_1a13.entries[4] == pdo::mapping_entry{0x2006, 0, 32});
static_assert(xe_pdos::txpdo_1a13.bytes() == 16);
static_assert(xe_pdos::txpdo_1a13.signs[2] == pdo::signedness::signed_); // 60F4h INTEGER32
// 7.1.1: RxPDO 18 (1612h): nine entries, 34 bytes
static_assert(xe_pdos::rxpdo_1612.entries.size() == 9);
static_assert(xe_pdos::rxpdo_1612.bytes() == 34);
// 9.1.16: the CAN TxPDO 2 (1A01h): statusword + actual position
static_assert(xc_pdos::txpdo_1a01.entries[1] == pdo::mapping_entry{0x6064, 0, 32});

TEST_CASE("generated: the XENAX EtherCAT TxPDO 21 layout reads a process image (manual 7.1.2)") {
  // statusword 0x0637, position -1000, following error -2, current 150 mA, PSR 9
  const std::array<std::uint8_t, 16> image{0x37, 0x06, 0x18, 0xFC, 0xFF, 0xFF, 0xFE, 0xFF,
                                           0xFF, 0xFF, 0x96, 0x00, 0x09, 0x00, 0x00, 0x00};
  CHECK(xe_pdos::txpdo_1a13.get<std::uint16_t>(image, 0).value() == 0x0637U);
  CHECK(xe_pdos::txpdo_1a13.get<std::int32_t>(image, 1).value() == -1000);
  CHECK(xe_pdos::txpdo_1a13.get<std::int32_t>(image, 2).value() == -2);
  CHECK(xe_pdos::txpdo_1a13.get<std::int16_t>(image, 3).value() == 150);
  CHECK(xe_pdos::txpdo_1a13.get<std::int32_t>(image, 4).value() == 9);
  CHECK(xe_pdos::txpdo_1a13.get(std::span(image).first(15), 4) == errc::truncated);
  // the other way: a value of an object's type is packed, one that does not fit refused
  std::array<std::uint8_t, 34> out{};
  CHECK(xe_pdos::rxpdo_1612.set(out, 1, -5).has_value());
  CHECK(out[2] == 0xFB);
  CHECK(out[5] == 0xFF);
  CHECK(xe_pdos::rxpdo_1612.set(out, 0, 0x10000) == errc::overflow); // controlword is 16 bits
}
