// ds402/error_code.hpp (CiA 402 error codes by name) and ds402::mode_bits (the statusword's
// mode-specific bits 12 and 13).
#include <fieldcodec/ds402/error_code.hpp>
#include <fieldcodec/ds402/statusword.hpp>

#include <doctest/doctest.h>

namespace ds402 = fieldcodec::ds402;

static_assert(ds402::describe_error_code(0x8611) == "following error");
static_assert(ds402::describe_error_code(0x2310) == "continuous over current");
static_assert(ds402::describe_error_code(0x3210) == "DC link over-voltage");
static_assert(ds402::describe_error_code(0x8130).empty()); // CiA 301's, not 402's
static_assert(ds402::describe_error_code(0xFF01).empty()); // manufacturer-specific
static_assert(ds402::mode_bits(1).bit12 == "set-point acknowledge");
static_assert(ds402::mode_bits(1).bit13 == "following error");
static_assert(ds402::mode_bits(6).bit12 == "homing attained");
static_assert(ds402::mode_bits(-1).bit12.empty()); // manufacturer-specific mode
static_assert(ds402::mode_bits(4).bit12.empty());  // profile torque: reserved

TEST_CASE("ds402: the error code table is sorted and every text is set") {
  for (std::size_t i = 0; i < ds402::error_codes.size(); ++i) {
    CHECK_FALSE(ds402::error_codes[i].text.empty());
    if (i > 0U) CHECK(ds402::error_codes[i - 1U].code < ds402::error_codes[i].code);
    CHECK(ds402::describe_error_code(ds402::error_codes[i].code) == ds402::error_codes[i].text);
  }
}
