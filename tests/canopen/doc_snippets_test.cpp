// The C++ blocks of docs/canopen.md, as written there, and what their comments state.
// tests/docs_check/run.cmake fails when a block of the page and its copy here differ.
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

// clang-format off
namespace doc_dpq_examples { // "### The DPQ examples (004, CANopen chapter)"
namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
constexpr auto ch = sdo::channel::default_for(5).value(); // node 5: 0x605 / 0x585
constexpr std::array<std::uint8_t, 2> ms100{0x64, 0x00}; // 100 as UNSIGNED16, LSB first
constexpr auto frame = [](std::uint16_t id, std::array<std::uint8_t, 8> b, std::uint8_t dlc = 8) {
  return co::can_frame{id, false, dlc, b};
};
// event timer of TPDO1 (1800h sub 5) = 100 ms, its confirmation, and reading it back
static_assert(ch.request(sdo::expedited_download({0x1800, 5}, ms100)).value() ==
              frame(0x605, {0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}));
static_assert(ch.response(sdo::download_response({0x1800, 5})) ==
              frame(0x585, {0x60, 0x00, 0x18, 0x05, 0x00, 0x00, 0x00, 0x00}));
static_assert(ch.response(sdo::expedited_upload_response({0x1800, 5}, ms100)).value() ==
              frame(0x585, {0x4B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}));
// start node 5
static_assert(co::nmt::encode(co::nmt::command::start, 5).value() == frame(0x000, {0x01, 0x05}, 2));
} // namespace doc_dpq_examples

namespace doc_step { // "## Machines: the step"
using fieldcodec::canopen::can_frame;
std::vector<can_frame> sent;
std::optional<std::uint32_t> woken_at;
void transmit(const can_frame &f) { sent.push_back(f); }
void wake_me_at(std::uint32_t t) { woken_at = t; }

template <class Machine>
void on_receive(Machine &client, const can_frame &frame, std::uint32_t now) {
  auto s = client.on_frame(frame, now);            // or poll(now), or a start call
  for (const can_frame &f : s.send) transmit(f);   // 0, 1 or a burst of frames
  if (s.deadline) wake_me_at(*s.deadline);         // then call poll(now)
}
} // namespace doc_step
// clang-format on

TEST_CASE("docs/canopen: the step block drives a client through a segmented upload") {
  namespace sdo = fieldcodec::canopen::sdo;
  const auto ch = sdo::channel::default_for(5).value();
  sdo::client c(5, 100);
  std::array<std::uint8_t, 16> buffer{};
  REQUIRE(c.upload({0x1008, 0}, buffer, 1000).has_value());
  // the server announces 3 bytes, segmented: the client asks for the first segment and waits
  doc_step::on_receive(c, ch.response(sdo::upload_response({0x1008, 0}, 3)), 1010);
  REQUIRE(doc_step::sent.size() == 1);
  CHECK(doc_step::sent[0] == ch.request(sdo::upload_segment_request(false)));
  REQUIRE(doc_step::woken_at.has_value());
  CHECK(*doc_step::woken_at == 1110); // the timeout counts from the last frame
  // the last segment: nothing to send, no deadline any more
  doc_step::woken_at.reset();
  const std::array<std::uint8_t, 3> abc{'a', 'b', 'c'};
  doc_step::on_receive(c, ch.response(sdo::upload_segment(false, abc, true)).value(), 1020);
  CHECK(doc_step::sent.size() == 1);
  CHECK_FALSE(doc_step::woken_at.has_value());
  CHECK(c.state() == sdo::transfer_state::done);
  CHECK(c.received().size() == 3);
}
