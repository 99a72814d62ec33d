// Regression tests for inputs found by fuzz/fuzz_dpq.cpp (see fuzz/FINDINGS.md).
// A test marked may_fail reproduces an OPEN finding: it reports the failure without failing the
// suite. Whoever fixes the finding removes the decorator (and the finding's status says fixed).
//
// F3 is undefined behaviour (int64 overflow), so calling the function at run time would trap
// under the sanitizer preset. The test asks the compiler instead: a constant expression with
// undefined behaviour is not a constant expression, so `evaluable` is false while F3 is open.
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/dpq/parameter.hpp>
#include <fieldcodec/od/descriptor.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <limits>
#include <type_traits>

namespace fc = fieldcodec;

namespace {

template <std::int64_t ScaleMantissa, std::uint8_t OffsetPlaces>
concept round_trip_places_evaluable = requires {
  typename std::integral_constant<bool,
                                  fieldcodec::dpq::round_trip_places(
                                      fc::scaling::linear{{ScaleMantissa, 0}, {0, OffsetPlaces}})
                                      .has_value()>;
};

constexpr auto int64_min = std::numeric_limits<std::int64_t>::min();

} // namespace

// Sanity: the ordinary cases are constant expressions.
static_assert(round_trip_places_evaluable<32767, 0>);
static_assert(round_trip_places_evaluable<1, 18>);

// F3 (2026-11-21, fuzz_dpq, conversion mode): dpq::round_trip_places(scale) computes 10^p in an
// int64 — an offset with more than 18 places (invalid, but a conversion is a plain struct)
// overflows it (10^18 × 10), and a scale mantissa of INT64_MIN overflows its negation. Reached
// through conversion::to_eu_decimal(raw) and conversion::decode(bytes) (today
// dpq::to_eu_decimal(descriptor, raw) and dpq::from_bytes) before
// scaling::to_eu_decimal can refuse the arguments with invalid_argument.
TEST_CASE("fuzz F3: round_trip_places is defined for every scale") {
  CHECK(round_trip_places_evaluable<1, 19>);
  CHECK(round_trip_places_evaluable<int64_min, 0>);
  // Fixed: too many offset places is invalid_argument; INT64_MIN has no power of ten >= it.
  CHECK(fieldcodec::dpq::round_trip_places({{1, 0}, {0, 19}}).error() ==
        fc::errc::invalid_argument);
  CHECK(fieldcodec::dpq::round_trip_places({{int64_min, 0}, {0, 0}}).error() ==
        fc::errc::not_representable);
  CHECK(fieldcodec::dpq::round_trip_places({{-32767, 2}, {0, 0}}).value() == 3);
}

// F8 (2026-11-21, fuzz_dpq, conversion mode): conversion::to_eu_decimal(raw) (today
// dpq::to_eu_decimal(descriptor, raw)) promises that the
// EU it returns converts back to `raw`. round_trip_places needs 10^p >= |scale|; for a scale
// above 10^18 no p <= 18 does, it returns 18 anyway, and the read-back is off by one. Either an
// error (not_representable) or a correct round trip fixes it.
TEST_CASE("fuzz F8: to_eu_decimal(raw) refuses scales that cannot round-trip") {
  const fieldcodec::od::descriptor c{
      {.type = fieldcodec::od::data_type::integer64, .flags = fieldcodec::od::flag::scaled},
      {},
      {{1'508'283'684'162'011'643, 0}, {0, 1}}};
  const std::int64_t raw = 2'387'286'014'124'100'095;
  // Fixed: no p <= 18 satisfies 10^p >= |scale|, so the promise cannot be kept: refused.
  CHECK(fieldcodec::dpq::to_eu_decimal(c, raw).error() == fc::errc::not_representable);
  // An explicit precision is still available and honest about its rounding.
  CHECK(c.to_eu_decimal(raw, 18).has_value());
}
