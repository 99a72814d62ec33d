// DPQ emergency error codes and error register bits (manual 004, 3.5 "Emergency telegram").
#include <fieldcodec/dpq/emergency.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <set>
#include <string_view>

namespace dpq = fieldcodec::dpq;
namespace reg = fieldcodec::dpq::error_register;

static_assert(dpq::is_documented(0x8302));
static_assert(!dpq::is_documented(0x8303));
static_assert(dpq::describe_emcy(0x6010) == "watchdog reset");
static_assert(dpq::describe_emcy(0x1234).empty());
static_assert(dpq::implied_register_bit(0x3422) == reg::voltage);
static_assert(dpq::implied_register_bit(0x8100) == reg::communication);

TEST_CASE("dpq emcy: the 18 documented codes, ascending, each with a text") {
  // The manual's table, in its order (which is ascending).
  constexpr std::array<std::uint16_t, 18> printed{0x0000, 0x1000, 0x3400, 0x3422, 0x5230, 0x5235,
                                                  0x5236, 0x6000, 0x6010, 0x6100, 0x6200, 0x6300,
                                                  0x6310, 0x6320, 0x8100, 0x8300, 0x8301, 0x8302};
  REQUIRE(dpq::emcy_codes.size() == printed.size());
  std::set<std::string_view> texts;
  for (std::size_t i = 0; i < printed.size(); ++i) {
    CHECK(static_cast<std::uint16_t>(dpq::emcy_codes[i]) == printed[i]);
    CHECK(dpq::is_documented(printed[i]));
    CHECK(!dpq::describe_emcy(printed[i]).empty());
    texts.insert(dpq::describe_emcy(printed[i]));
    if (i > 0) CHECK(printed[i - 1] < printed[i]);
  }
  CHECK(texts.size() == printed.size()); // every text distinct
  CHECK(dpq::describe(dpq::emcy_code::no_error) == "no error (all errors cleared)");
  CHECK(dpq::describe(dpq::emcy_code::pressure_monitor) == "pressure monitor tripped");
  std::size_t with_text = 0;
  for (std::uint32_t c = 0; c <= 0xFFFF; ++c) {
    const auto code = static_cast<std::uint16_t>(c);
    if (!dpq::describe_emcy(code).empty()) ++with_text;
  }
  CHECK(with_text == printed.size()); // no other code has a text
}

TEST_CASE("dpq emcy: error register bits") {
  CHECK(reg::generic == 0x01);
  CHECK(reg::current == 0x02);
  CHECK(reg::voltage == 0x04);
  CHECK(reg::temperature == 0x08);
  CHECK(reg::communication == 0x10);
  CHECK(reg::device_profile == 0x20);
  CHECK(reg::reserved == 0x40);
  CHECK(reg::manufacturer == 0x80);
  CHECK(reg::describe_bit(0) == "generic error");
  CHECK(reg::describe_bit(7) == "manufacturer-specific");
  CHECK(reg::describe_bit(8).empty());
  std::array<std::string_view, 8> out{};
  CHECK(reg::describe(0x00, out) == 0);
  REQUIRE(reg::describe(0x95, out) == 4); // generic, voltage, communication, manufacturer
  CHECK(out[0] == "generic error");
  CHECK(out[1] == "voltage");
  CHECK(out[2] == "communication");
  CHECK(out[3] == "manufacturer-specific");
  CHECK(reg::describe(0xFF, out) == 8);
  CHECK(reg::has_reserved_bit(0x40));
  CHECK(!reg::has_reserved_bit(0xBF));
}

TEST_CASE("dpq emcy: register bit implied by the code class") {
  CHECK(dpq::implied_register_bit(0x0000) == 0);
  CHECK(dpq::implied_register_bit(0x1000) == 0); // generic: bit 0 is set for every error anyway
  CHECK(dpq::implied_register_bit(0x3400) == reg::voltage); // cable break, listed under 3xxx
  CHECK(dpq::implied_register_bit(0x2310) == reg::current);
  CHECK(dpq::implied_register_bit(0x4210) == reg::temperature);
  CHECK(dpq::implied_register_bit(0x5230) == 0);
  CHECK(dpq::implied_register_bit(0x8200) == reg::communication);
  CHECK(dpq::implied_register_bit(0x8300) == 0);
  CHECK(dpq::implied_register_bit(0xFF01) == reg::manufacturer);
  CHECK(dpq::implied_register_bit(0xF001) == 0);
}
