// SocketCAN conversions (host only).
#include <fieldcodec/host/socketcan.hpp>

#include <doctest/doctest.h>

#ifdef FIELDCODEC_HAS_SOCKETCAN
namespace co = fieldcodec::canopen;
namespace host = fieldcodec::host;
using fieldcodec::errc;

TEST_CASE("SocketCAN round trip") {
  const auto f = co::make_frame(0x605, {0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}).value();
  const auto s = host::to_socketcan(f).value();
  CHECK(s.can_id == 0x605U);
  CHECK(s.can_dlc == 8);
  CHECK(s.data[0] == 0x2B);
  CHECK(s.data[4] == 0x64);
  CHECK(host::from_socketcan(s).value() == f);

  const auto r = co::make_remote_frame(0x705, 1).value();
  const auto sr = host::to_socketcan(r).value();
  CHECK(sr.can_id == (0x705U | CAN_RTR_FLAG));
  CHECK(host::from_socketcan(sr).value() == r);

  ::can_frame bad{};
  bad.can_id = 0x1234567U | CAN_EFF_FLAG;
  CHECK(host::from_socketcan(bad) == errc::unexpected_frame);
  bad.can_id = CAN_ERR_FLAG | 0x4U;
  CHECK(host::from_socketcan(bad) == errc::unexpected_frame);
  bad.can_id = 0x100;
  bad.can_dlc = 9;
  CHECK(host::from_socketcan(bad) == errc::bad_length);
  co::can_frame big = f;
  big.id = 0x800;
  CHECK(host::to_socketcan(big) == errc::invalid_argument);
  big = f;
  big.dlc = 9;
  CHECK(host::to_socketcan(big) == errc::bad_length);
}
#endif
