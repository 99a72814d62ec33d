// The C++ blocks of docs/xenax.md, compiled as written, with the results the document states
// asserted; a last test case checks that the document's blocks are exactly these.
#include "doc_blocks.hpp"

#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/dictionaries/xenax_ethercat_pdos.hpp>
#include <fieldcodec/xenax/bus.hpp>
#include <fieldcodec/xenax/units.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <string>

using fieldcodec::errc;

TEST_CASE("docs/xenax.md: using the dictionaries and helpers") {
  namespace xenax = fieldcodec::xenax;
  namespace pdo = fieldcodec::canopen::pdo;
  namespace xcan = fieldcodec::dictionaries::xenax_canopen;

  // The CAN TxPDO 2 the XENAX sends (9.1.16): statusword + actual position, from the dictionary
  const auto tx2 = pdo::default_mapping(xcan::dictionary, 0x1A01).value();
  const auto map = pdo::make_mapping(xcan::dictionary, pdo::direction::tpdo, tx2.entries()).value();
  const std::array<std::uint8_t, 6> frame{0x37, 0x06, 0x18, 0xFC, 0xFF, 0xFF};
  const auto position = map.get<std::int32_t>(frame, 1); // position.value() == -1000

  // 6.1.2: an ELAX (12 x 10 mA ~ 1 N) limited to 4 N writes 48 to 6073h
  const auto limit = xenax::current_limit_for(xenax::newtons{{4, 0}}, xenax::motor::elax_ex_f20);
  // limit.value() == 48

  // 4.2.23: 1 000 000 inc/s² of feed-forward is 60B2h = 20 on EtherCAT
  const auto offset = xenax::torque_offset_from_acceleration(1'000'000, xenax::bus::ethercat);
  // offset.value() == 20; on CANopen the same acceleration does not fit 60B2h: overflow

  // a LINAX with LARES = 1 000 000 inc/m: 2.5 mm is 2500 increments
  const auto inc = xenax::to_increments({25, 1}, xenax::linear_resolution{1'000'000});
  // inc.value() == 2500

  CHECK(position.value() == -1000);
  CHECK(map.get(frame, 0).value() == 0x0637);
  CHECK(limit.value() == 48);
  CHECK(offset.value() == 20);
  CHECK(xenax::torque_offset_from_acceleration(1'000'000, xenax::bus::canopen) == errc::overflow);
  CHECK(inc.value() == 2500);
}

TEST_CASE("docs/xenax.md: the EtherCAT PDO layouts generated from the ESI") {
  // statusword 0x0637, position -1000, following error -2, current 150 mA, PSR 9
  const std::array<std::uint8_t, 16> process_image{0x37, 0x06, 0x18, 0xFC, 0xFF, 0xFF, 0xFE, 0xFF,
                                                   0xFF, 0xFF, 0x96, 0x00, 0x09, 0x00, 0x00, 0x00};
  namespace ec = fieldcodec::dictionaries::xenax_ethercat::pdos; // the manual's, generated here
  // 7.1.2: TxPDO 21 (1A13h) — statusword, position, following error, current, PSR: 16 bytes
  static_assert(ec::txpdo_1a13.bytes() == 16);
  const auto position = ec::txpdo_1a13.get<std::int32_t>(process_image, 1); // 6064h

  CHECK(position.value() == -1000);
}

TEST_CASE("docs/xenax.md: every C++ block is one of the blocks compiled above") {
  const auto blocks = doc_blocks::cpp_blocks(doc_blocks::beside(__FILE__, "../../docs/xenax.md"));
  CHECK(blocks.size() == 2);
  const std::string source = doc_blocks::read_file(__FILE__);
  for (const auto &block : blocks) {
    CAPTURE(block);
    CHECK(doc_blocks::holds(source, block));
  }
}
