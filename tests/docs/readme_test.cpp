// The C++ blocks of README.md, as written there, and the results their comments state.
// tests/docs_check/run.cmake fails when a block of the page and its copy here differ.
#include <array>
#include <cstdint>
#include <cstdio>
#include <fieldcodec/core/bcd.hpp>
#include <fieldcodec/core/result_exception.hpp>
#include <fieldcodec/core/scaling.hpp>

#include <doctest/doctest.h>

// clang-format off
namespace readme_quick_look { // "Quick look"
// COMPAX POSA 7350.150 mm (0.001 mm steps) → 00 00 07 35 01 50, checked at compile time
constexpr auto posa = fieldcodec::bcd::encode_signed<6>(7'350'150);
static_assert(posa.value() == std::array<std::uint8_t, 6>{0x00, 0x00, 0x07, 0x35, 0x01, 0x50});

// DPQ Inj. P Limit 1: 4.0 bar at scale 327.67 → 1311 (0x051F)
constexpr fieldcodec::scaling::linear pressure{{32767, 2}, {0, 0}};
static_assert(fieldcodec::scaling::to_raw(4.0, pressure, {4, false}).value() == 1311);
} // namespace readme_quick_look

namespace readme_error_model { // "Error model"
void host_side() {
  constexpr fieldcodec::scaling::linear pressure{{32767, 2}, {0, 0}};
  const auto r = fieldcodec::scaling::to_raw(250.0, pressure, {2, false});
  std::puts(fieldcodec::describe(r).c_str()); // "value does not fit the field" ("ok" if fine)
  const auto raw = fieldcodec::value_or_throw(fieldcodec::scaling::to_raw(4.0, pressure,
                                                                          {2, false})); // 1311
  std::printf("%lld\n", static_cast<long long>(raw));
  (void)fieldcodec::value_or_throw(r); // throws fieldcodec::bad_result: code() is
                                       // errc::overflow, what() its text
}
} // namespace readme_error_model
// clang-format on

TEST_CASE("README: the error model's host_side states its results") {
  using namespace fieldcodec;
  constexpr scaling::linear pressure{{32767, 2}, {0, 0}};
  const auto r = scaling::to_raw(250.0, pressure, {2, false});
  CHECK(describe(r) == "value does not fit the field");
  CHECK(describe(scaling::to_raw(4.0, pressure, {2, false})) == "ok");
  CHECK(value_or_throw(scaling::to_raw(4.0, pressure, {2, false})) == 1311);
  try {
    readme_error_model::host_side();
    FAIL("host_side did not throw");
  } catch (const bad_result &e) {
    CHECK(e.code() == errc::overflow);
    CHECK(std::string(e.what()) == "value does not fit the field");
  }
}
