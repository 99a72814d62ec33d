// DPQ emergency error codes and error register bits (manual 004, 3.5 "Emergency telegram").
#include <fieldcodec/dpq/emergency.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <set>
#include <span>
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

// Error history, object 1003h (manual 004, 3.5 "Error code": count in sub 0, the newest error
// at sub 1, at most 4; a field is CiA 301's code in bits 0–15, information in bits 16–31).
static_assert(dpq::error_history_address(0) == fieldcodec::od::address{0x1003, 0});
static_assert(dpq::error_history_address(1) == fieldcodec::od::address{0x1003, 1});
static_assert(dpq::decode_error_field(0x00428302U) ==
              dpq::error_field{.code = 0x8302, .info = 0x0042});
static_assert(dpq::decode_error_field(0x00428302U).text() == "pressure monitor tripped");

TEST_CASE("dpq error history: decoded newest first with the DPQ's texts") {
  // Two errors: sub 1 (newest) pressure monitor, sub 2 control undervoltage with info 0x1234;
  // sub 3 holds a stale value that count 2 excludes.
  constexpr std::array<std::uint32_t, 3> subs{0x00008302U, 0x12343422U, 0x00006010U};
  constexpr auto h = dpq::decode_error_history(2, subs);
  static_assert(h.has_value());
  REQUIRE(h.has_value());
  const auto present = h.value().present();
  REQUIRE(present.size() == 2);
  CHECK(!h.value().empty());
  CHECK(present[0].code == static_cast<std::uint16_t>(dpq::emcy_code::pressure_monitor));
  CHECK(present[0].info == 0);
  CHECK(present[0].text() == "pressure monitor tripped");
  CHECK(present[0].documented());
  CHECK(present[1].code == 0x3422);
  CHECK(present[1].info == 0x1234);
  CHECK(present[1].text() == "control supply undervoltage");
  CHECK(present[1].register_bit() == reg::voltage);
}

TEST_CASE("dpq error history: empty, full, undocumented code") {
  auto empty = dpq::decode_error_history(0, {});
  REQUIRE(empty.has_value());
  CHECK(empty.value().empty());
  CHECK(empty.value().present().empty());
  constexpr std::array<std::uint32_t, 4> four{0x1000U, 0x6010U, 0x8100U, 0xBEEF7777U};
  auto full = dpq::decode_error_history(4, four);
  REQUIRE(full.has_value());
  REQUIRE(full.value().present().size() == 4);
  // An undocumented code is kept as the card sent it, with no text.
  CHECK(full.value().present()[3].code == 0x7777);
  CHECK(full.value().present()[3].info == 0xBEEF);
  CHECK(!full.value().present()[3].documented());
  CHECK(full.value().present()[3].text().empty());
}

TEST_CASE("dpq error history: bad input") {
  constexpr std::array<std::uint32_t, 5> five{0x1000U, 0x1000U, 0x1000U, 0x1000U, 0x1000U};
  CHECK(dpq::decode_error_history(5, five).error() == fieldcodec::errc::out_of_range);
  CHECK(dpq::decode_error_history(255, five).error() == fieldcodec::errc::out_of_range);
  CHECK(dpq::decode_error_history(3, std::span(five).first(2)).error() ==
        fieldcodec::errc::truncated);
  constexpr std::array<std::uint32_t, 2> zero{0x8302U, 0x00010000U}; // code 0000 counted
  CHECK(dpq::decode_error_history(2, zero).error() == fieldcodec::errc::invalid_argument);
  CHECK(dpq::decode_error_history(1, zero).has_value());
}
