// Regression tests for inputs found by fuzz/fuzz_xenax.cpp (see fuzz/FINDINGS.md).
// A test marked may_fail reproduces an OPEN finding: it reports the failure without failing the
// suite. Whoever fixes the finding removes the decorator (and the finding's status says fixed).
#include <fieldcodec/xenax/units.hpp>

#include <doctest/doctest.h>

namespace xe = fieldcodec::xenax;

// F7 (2026-11-21, fuzz_xenax): decode_cycle_time({base 0, any exponent}) returns 0 µs, but
// encode_cycle_time(0) refuses 0 with out_of_range: a 60C2h value read from a drive does not
// write back. Either decode refuses base 0 (out_of_range) or encode accepts 0.
TEST_CASE("fuzz F7: a decoded cycle time re-encodes") {
  // Fixed: base 0 is refused on both sides.
  CHECK(xe::decode_cycle_time({0, -3}).error() == fieldcodec::errc::out_of_range);
  CHECK(xe::encode_cycle_time(0).error() == fieldcodec::errc::out_of_range);
  auto us = xe::decode_cycle_time({5, -4});
  auto back = xe::encode_cycle_time(us.value());
  REQUIRE(back.has_value());
  CHECK(xe::decode_cycle_time(back.value()).value() == us.value());
}

// F17 (fuzz_xenax, issue 13 helpers): a force (or current) so small that it rounds to 0 steps
// gave 6073h = 0, which the XENAX takes as "no limitation" (6.1.2, l. 1849): asking for a
// 0.04 N limit on an ELAX removed the limit. Input: corpus regression_f17_limit_rounds_to_zero
// (ELAX, 0.04 N = 0.48 steps).
TEST_CASE("fuzz F17: a current limit never rounds to 0 (= no limit)") {
  using fieldcodec::errc;
  CHECK(xe::current_limit_for(xe::newtons{{4, 2}}, xe::motor::elax_ex_f20).error() ==
        errc::out_of_range);
  CHECK(xe::current_limit_from_ma({4, 0}).error() == errc::out_of_range);
  CHECK(xe::current_limit_for(xe::newtons{{5, 2}}, xe::motor::elax_ex_f20).value() == 1);
}
