// Regression tests for inputs found by the CANopen fuzz harnesses (see fuzz/FINDINGS.md).
// A test marked may_fail reproduces an OPEN finding: it reports the failure without failing the
// suite. Whoever fixes the finding removes the decorator (and the finding's status says fixed).
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/socketcan.hpp>

#include <doctest/doctest.h>

namespace candump = fieldcodec::host::candump;

// F21 (fuzz_host_candump): format_line writes a record with a time but no interface (what an
// slcan adapter delivers, `fieldcodec monitor --log`) as "(t) - ID#DATA", and parse_line read
// "-" back as an interface named "-": a written log did not read back identical.
TEST_CASE("fuzz F21: a log line without an interface reads back without one") {
  fieldcodec::host::frame_record r;
  r.id = 0x181;
  r.dlc = 1;
  r.data[0] = 0x01;
  r.time = {1, 5, 1};
  const std::string line = candump::format_line(r);
  CHECK(line == "(1.5) - 181#01");
  const auto back = candump::parse_line(line);
  REQUIRE(back);
  CHECK(back.value().iface.empty());
  CHECK(back.value() == r);
  // a real interface name is kept; "-" followed by more characters is a name
  CHECK(candump::parse_line("(1.5) can0 181#01").value().iface.view() == "can0");
  CHECK(candump::parse_line("(1.5) -x 181#01").value().iface.view() == "-x");
}

// F30 (fuzz_host_candump, CI's run): a line with an interface and no time (candump's display
// without -t: "705 355#11.11.33") was read with its interface, and format_line wrote the
// compact frame without it: the record did not read back identical.
TEST_CASE("fuzz F30: an interface without a time is written and read back") {
  const auto r = candump::parse_line("705 355#11.11.33 ");
  REQUIRE(r);
  CHECK(r.value().iface.view() == "705");
  CHECK_FALSE(r.value().time.known());
  const std::string line = candump::format_line(r.value());
  CHECK(line == "705 355#111133");
  const auto back = candump::parse_line(line);
  REQUIRE(back);
  CHECK(back.value() == r.value());
  // neither time nor interface: the compact frame, as before
  fieldcodec::host::frame_record bare = r.value();
  bare.iface = {};
  CHECK(candump::format_line(bare) == "355#111133");
}

// F31 (fuzz_host_candump, CI's run): is_blank_or_comment calls a line that starts with a tab a
// continuation (candump -e and -a print their details so), but parse_line trimmed the tab and
// read the frame after it: a line was both "no frame" and a frame.
TEST_CASE("fuzz F31: a line that starts with a tab is no frame") {
  CHECK(candump::is_blank_or_comment("\t\t705#R0"));
  const auto r = candump::parse_line("\t\t705#R0");
  REQUIRE_FALSE(r);
  CHECK(r.error().code == fieldcodec::errc::bad_syntax);
  // blanks before a frame are the display format's indentation: read as before
  CHECK(candump::parse_line("  705#R0").has_value());
}

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
