// The C++ blocks of docs/ds402.md, compiled as written, with the results the document states
// asserted; a last test case checks that the document's blocks are exactly these.
#include "doc_blocks.hpp"

#include <fieldcodec/ds402/modes.hpp>
#include <fieldcodec/ds402/state_machine.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <string>

using fieldcodec::errc;

TEST_CASE("docs/ds402.md: walking a drive to a state") {
  namespace ds402 = fieldcodec::ds402;
  const std::uint16_t statusword = 0x0640;  // switch on disabled
  const std::uint16_t previous_cw = 0x0000; // what was sent last cycle

  // stateless: the caller passes the controlword it sent last cycle
  const auto cw = ds402::next_controlword(statusword, ds402::state::operation_enabled, previous_cw);
  // cw.value() == 0x0006 (shutdown: towards ready to switch on)

  // or a tiny state object that remembers it and keeps the caller's mode bits
  ds402::power_sequencer seq;
  const auto next = seq.next(statusword, ds402::state::operation_enabled, /*mode_bits=*/0x0010);
  // next.value() == 0x0016 (shutdown + bit 4), seq.previous() == 0x0016

  CHECK(cw.value() == 0x0006);
  CHECK(next.value() == 0x0016);
  CHECK(seq.previous() == 0x0016);
}

TEST_CASE("docs/ds402.md: modes of operation") {
  namespace ds402 = fieldcodec::ds402;
  const auto csp = ds402::decode_mode(8);     // csp.value() == ds402::mode::cyclic_sync_position
  const auto vendor = ds402::decode_mode(-1); // a manufacturer-specific mode (XENAX: jog)
  const bool is_vendor = ds402::is_manufacturer_mode(vendor.value()); // true
  const auto reserved = ds402::decode_mode(5); // reserved.error() == errc::out_of_range
  // ds402::to_string(vendor.value()) == "manufacturer-specific"

  CHECK(csp.value() == ds402::mode::cyclic_sync_position);
  CHECK(is_vendor);
  CHECK(reserved.error() == errc::out_of_range);
  CHECK(ds402::to_string(vendor.value()) == "manufacturer-specific");
}

TEST_CASE("docs/ds402.md: every C++ block is one of the blocks compiled above") {
  const auto blocks = doc_blocks::cpp_blocks(doc_blocks::beside(__FILE__, "../../docs/ds402.md"));
  CHECK(blocks.size() == 2);
  const std::string source = doc_blocks::read_file(__FILE__);
  for (const auto &block : blocks) {
    CAPTURE(block);
    CHECK(doc_blocks::holds(source, block));
  }
}
