// Regression tests for inputs found by the fuzz harnesses in core/ code (see fuzz/FINDINGS.md).
// A test marked may_fail reproduces an OPEN finding: it reports the failure without failing the
// suite. Whoever fixes the finding removes the decorator (and the finding's status says fixed).
//
// F4 is undefined behaviour (int64 negation overflow), so calling the function at run time
// would trap under the sanitizer preset. The test asks the compiler instead: a constant
// expression with undefined behaviour is not a constant expression.
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/scaling.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <limits>
#include <type_traits>

namespace fc = fieldcodec;

namespace {

constexpr auto int64_min = std::numeric_limits<std::int64_t>::min();

// (eu − offset) × 1 with offset = INT64_MIN: −1 − INT64_MIN = INT64_MAX exactly.
template <std::int64_t Eu>
concept scale_to_raw_evaluable = requires {
  typename std::integral_constant<bool, fc::scaling::scale_to_raw(
                                            fc::decimal{Eu, 0},
                                            fc::scaling::linear{{1, 0}, {int64_min, 0}})
                                            .has_value()>;
};

} // namespace

// F4 (2026-11-21, fuzz_dpq, conversion mode, found in core/scaling.hpp): scale_to_raw negates
// the offset mantissa (`-s.offset.mantissa`) in its 128-bit path, undefined for INT64_MIN. The
// int64 fast path handles −1 − INT64_MIN = INT64_MAX (passes); 0 − INT64_MIN overflows int64,
// so the 128-bit path runs and negates INT64_MIN (fails; the answer should be overflow).
// Reached from every to_raw (dpq::conversion, od::entry, pacontrol ×1000).
TEST_CASE("fuzz F4: scale_to_raw with an INT64_MIN offset") {
  CHECK(scale_to_raw_evaluable<-1>);
  CHECK(scale_to_raw_evaluable<0>);
}
