// Regression tests for inputs found by the CANopen fuzz harnesses (see fuzz/FINDINGS.md).
// A test marked may_fail reproduces an OPEN finding: it reports the failure without failing the
// suite. Whoever fixes the finding removes the decorator (and the finding's status says fixed).
#include <fieldcodec/host/socketcan.hpp>

#include <doctest/doctest.h>

#ifdef FIELDCODEC_HAS_SOCKETCAN

namespace co = fieldcodec::canopen;
namespace host = fieldcodec::host;

// F10 (2026-11-21, fuzz_canopen_frames): from_socketcan masks the identifier with CAN_SFF_MASK,
// so a struct can_frame without CAN_EFF_FLAG but with identifier bits 11..28 set (0x1605) is
// silently read as another CANopen frame (0x605, an SDO request to node 5) instead of being
// refused.
TEST_CASE("fuzz F10: from_socketcan refuses identifier bits above 11") {
  ::can_frame raw{};
  raw.can_id = 0x1605;
  raw.can_dlc = 8;
  auto f = host::from_socketcan(raw);
  REQUIRE_FALSE(f.has_value());
  CHECK(f.error() == fieldcodec::errc::invalid_argument);
  raw.can_id = 0x605; // the same frame with a proper 11-bit identifier
  CHECK(host::from_socketcan(raw).value().id == 0x605);
}

#endif
