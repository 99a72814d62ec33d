// host::steady_ms, the one steady-clock-to-milliseconds conversion of the host side.
#include <fieldcodec/host/clock.hpp>

#include <doctest/doctest.h>

#include <chrono>
#include <cstdint>

namespace host = fieldcodec::host;
using namespace std::chrono_literals;

TEST_CASE("host::steady_ms counts milliseconds since construction, modulo 2^32") {
  const host::steady_ms clock;
  CHECK(clock.at(clock.start()) == 0U);
  CHECK(clock.at(clock.start() + 1500ms) == 1500U);
  CHECK(clock.at(clock.start() + 999us) == 0U); // whole milliseconds, truncated
  // the machines' counter wraps after 2^32 ms; they handle the wrap
  CHECK(clock.at(clock.start() + std::chrono::milliseconds(std::int64_t{1} << 32U)) == 0U);
  CHECK(clock.at(clock.start() + std::chrono::milliseconds((std::int64_t{1} << 32U) + 7)) == 7U);
  const std::uint32_t a = clock.now();
  const std::uint32_t b = clock.now();
  CHECK(b >= a);
  CHECK(a < 60000U); // a fresh clock starts near 0
}
