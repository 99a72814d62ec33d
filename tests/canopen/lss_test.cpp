// canopen/lss.hpp: CiA 305 messages on 7E5h / 7E4h.
#include <fieldcodec/canopen/lss.hpp>

#include <doctest/doctest.h>

namespace co = fieldcodec::canopen;
namespace lss = fieldcodec::canopen::lss;
using fieldcodec::errc;

namespace {
constexpr co::can_frame frame(std::uint16_t id, std::array<std::uint8_t, 8> d) {
  return co::make_frame(id, d).value();
}
} // namespace

static_assert(lss::decode(frame(0x7E5, {0x11, 5})).value().cs == lss::command::configure_node_id);
static_assert(lss::decode(frame(0x7E5, {0x11, 5})).value().b1 == 5);
static_assert(lss::decode(frame(0x7E4, {0x5A, 0x2E, 0x01})).value().value == 0x12EU);
static_assert(!lss::decode(frame(0x7E4, {0x5A, 0x2E, 0x01})).value().from_master);
static_assert(lss::decode(frame(0x7E5, {0x40, 0x78, 0x56, 0x34, 0x12})).value().value ==
              0x12345678U);
static_assert(lss::decode(frame(0x7E5, {0x15, 0xE8, 0x03})).value().value == 1000U);
static_assert(lss::decode(frame(0x7E5, {0x51, 1, 2, 3, 4, 0x80, 2, 3})).value().bit_checked ==
              0x80);
static_assert(lss::decode(frame(0x7E5, {0x44})).error() == errc::unknown_command); // an answer
static_assert(lss::decode(frame(0x7E4, {0x04})).error() == errc::unknown_command); // a command
static_assert(lss::decode(frame(0x7E6, {0x04})).error() == errc::unexpected_frame);
static_assert(lss::standard_bit_rate(2) == 500);
static_assert(lss::standard_bit_rate(5) == 0);
static_assert(lss::standard_bit_rate(9) == 0xFFFF);

TEST_CASE("lss: bad frames, every command named") {
  co::can_frame f = frame(0x7E5, {0x04, 1});
  f.dlc = 2;
  CHECK(lss::decode(f).error() == errc::bad_length);
  f.dlc = 8;
  f.rtr = true;
  CHECK(lss::decode(f).error() == errc::unexpected_frame);
  for (unsigned cs = 0; cs < 256U; ++cs) {
    const auto c = static_cast<std::uint8_t>(cs);
    if (!lss::is_master_command(c) && !lss::is_slave_answer(c)) continue;
    CHECK(lss::to_string(static_cast<lss::command>(c)) != "?");
  }
}
