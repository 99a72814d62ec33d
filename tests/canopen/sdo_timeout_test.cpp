// The SDO timeout is the deadline the machine reports: poll(now) fails a transfer exactly when
// canopen::reached(step.deadline, now), modulo 2^32 like every deadline of a step. Found by the
// interoperability test (tests/interop/): a `now` one millisecond older than the one a transfer
// started with aborted it at once with 05040000, although its deadline was 2 s ahead.
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/canopen/step.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;

TEST_CASE("sdo client: the timeout is the reported deadline, not an unsigned difference") {
  for (const std::uint32_t start : {1000U, 0U, 0xFFFF'FF00U}) {
    CAPTURE(start);
    sdo::client c(5, 2000);
    std::array<std::uint8_t, 16> buffer{};
    auto s = c.upload({0x1008, 0}, buffer, start);
    REQUIRE(s.has_value());
    REQUIRE(s.value().deadline.has_value());
    const std::uint32_t deadline = *s.value().deadline;
    CHECK(deadline == start + 2000U);
    // a time sampled just before the start (another path of the caller's loop)
    auto early = c.poll(start - 1U);
    CHECK(early.send.empty());
    CHECK(c.state() == sdo::transfer_state::busy);
    CHECK_FALSE(co::reached(deadline, start + 1999U));
    CHECK(c.poll(start + 1999U).send.empty());
    CHECK(c.state() == sdo::transfer_state::busy);
    auto late = c.poll(start + 2000U);
    CHECK(late.send.size() == 1U); // the abort 05040000
    CHECK(c.state() == sdo::transfer_state::failed);
    REQUIRE(c.error().has_value());
    CHECK(c.error()->abort == sdo::abort_code::timeout);
  }
}

TEST_CASE("sdo server: the timeout is the reported deadline, not an unsigned difference") {
  struct no_store {
    [[nodiscard]] constexpr sdo::abort_code read(fieldcodec::od::address, std::size_t,
                                                 std::span<std::uint8_t> out,
                                                 std::size_t &total) const noexcept {
      total = 20;
      for (auto &b : out) b = 0x41;
      return sdo::abort_code::none;
    }
    [[nodiscard]] constexpr sdo::abort_code begin_write(fieldcodec::od::address,
                                                        std::optional<std::uint32_t>) noexcept {
      return sdo::abort_code::none;
    }
    [[nodiscard]] constexpr sdo::abort_code write(fieldcodec::od::address, std::size_t,
                                                  std::span<const std::uint8_t>, bool) noexcept {
      return sdo::abort_code::none;
    }
  };
  no_store store;
  std::array<std::uint8_t, 64> buffer{};
  sdo::server<no_store> srv(5, store, buffer, 2000);
  const std::uint32_t start = 500;
  // an upload of 20 bytes: segmented, the server waits for segment requests
  auto s = srv.on_frame(co::make_frame(0x605, {0x40, 0x08, 0x10, 0, 0, 0, 0, 0}).value(), start);
  REQUIRE(s.send.size() == 1U);
  REQUIRE(s.deadline.has_value());
  CHECK(srv.poll(start - 1U).send.empty());
  CHECK(srv.state() == sdo::transfer_state::busy);
  CHECK(srv.poll(*s.deadline).send.size() == 1U);
  CHECK(srv.state() == sdo::transfer_state::failed);
}
