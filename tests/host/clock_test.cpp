// host::steady_ms, the one steady-clock-to-milliseconds conversion of the host side, and
// host::time_left, the one "milliseconds until a deadline" of the adapters.
#include <fieldcodec/host/clock.hpp>
#include <fieldcodec/host/deadline.hpp>

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

TEST_CASE("host::time_left: whole milliseconds until a deadline, never negative") {
  const auto now = std::chrono::steady_clock::now();
  CHECK(host::time_left(now - 5s) == 0ms);      // passed long ago
  CHECK(host::time_left(now - 1ms) == 0ms);     // just passed
  CHECK(host::time_left(now + 500us) == 0ms);   // less than one whole millisecond left
  const auto left = host::time_left(now + 10s); // rounded down, measured a moment later
  CHECK(left <= 10s);
  CHECK(left > 9s);
}

TEST_CASE("host::time_of_day: the system clock as CiA 301's TIME_OF_DAY") {
  using std::chrono::system_clock;
  const auto at = [](std::int64_t unix_ms) {
    return system_clock::time_point(
        std::chrono::duration_cast<system_clock::duration>(std::chrono::milliseconds(unix_ms)));
  };
  // 1984-01-01 00:00:00.000 UTC = 441 763 200 s after 1970 (python canopen's OFFSET too)
  CHECK(host::time_of_day(at(441'763'200'000)).value() == fieldcodec::od::time_value{0, 0});
  // 2024-01-01 12:34:56.789: day 14610, 45 296 789 ms
  CHECK(host::time_of_day(at(1'704'112'496'789)).value() ==
        fieldcodec::od::time_value{45'296'789U, 14610});
  // the last millisecond of a day, the rest of a millisecond dropped
  CHECK(host::time_of_day(at(441'763'200'000 + 86'399'999) + 999us).value() ==
        fieldcodec::od::time_value{86'399'999U, 0});
  // outside days 0..65535
  CHECK(host::time_of_day(at(441'763'199'999)) == fieldcodec::errc::out_of_range);
  CHECK(host::time_of_day(at(-1)) == fieldcodec::errc::out_of_range);
  CHECK(host::time_of_day(at(441'763'200'000 + 65'535LL * 86'400'000)).value().days == 65535U);
  CHECK(host::time_of_day(at(441'763'200'000 + 65'536LL * 86'400'000)) ==
        fieldcodec::errc::out_of_range);
}
