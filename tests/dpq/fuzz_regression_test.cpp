// Regression tests for inputs found by fuzz/fuzz_dpq.cpp (see fuzz/FINDINGS.md).
// A test marked may_fail reproduces an OPEN finding: it reports the failure without failing the
// suite. Whoever fixes the finding removes the decorator (and the finding's status says fixed).
//
// F3 is undefined behaviour (int64 overflow), so calling the function at run time would trap
// under the sanitizer preset. The test asks the compiler instead: a constant expression with
// undefined behaviour is not a constant expression, so `evaluable` is false while F3 is open.
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/dpq/conversion.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <limits>
#include <type_traits>

namespace fc = fieldcodec;

namespace {

template <std::int64_t ScaleMantissa, std::uint8_t OffsetPlaces>
concept round_trip_places_evaluable = requires {
  typename std::integral_constant<unsigned, fieldcodec::dpq::round_trip_places(fc::scaling::linear{
                                                {ScaleMantissa, 0}, {0, OffsetPlaces}})>;
};

constexpr auto int64_min = std::numeric_limits<std::int64_t>::min();

} // namespace

// Sanity: the ordinary cases are constant expressions.
static_assert(round_trip_places_evaluable<32767, 0>);
static_assert(round_trip_places_evaluable<1, 18>);

// F3 (2026-11-21, fuzz_dpq, conversion mode): dpq::round_trip_places(scale) computes 10^p in an
// int64 — an offset with more than 18 places (invalid, but a conversion is a plain struct)
// overflows it (10^18 × 10), and a scale mantissa of INT64_MIN overflows its negation. Reached
// through conversion::to_eu_decimal(raw) and conversion::decode(bytes) before
// scaling::to_eu_decimal can refuse the arguments with invalid_argument.
TEST_CASE("fuzz F3: round_trip_places is defined for every scale" * doctest::may_fail()) {
  CHECK(round_trip_places_evaluable<1, 19>);
  CHECK(round_trip_places_evaluable<int64_min, 0>);
}
