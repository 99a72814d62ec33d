// DPQ parameters by descriptor (dpq/parameter.hpp over od::descriptor). The descriptors below
// hold what fieldcodec-gen emits for rows of dictionaries/dpq_parameters.csv.
#include <fieldcodec/dpq/parameter.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>

namespace fc = fieldcodec;
namespace dpq = fieldcodec::dpq;
namespace od = fieldcodec::od;
using fc::decimal;
using fc::errc;

namespace {
// 4.100
constexpr od::entry_spec inj_p_limit_1_spec{.index = 0x2023,
                                            .type = od::data_type::unsigned32,
                                            .access_type = od::access::rw,
                                            .flags = od::flag::signedness_guess | od::flag::scaled,
                                            .low = od::decimal_number(0, 0),
                                            .high = od::decimal_number(5000, 0)};
constexpr od::descriptor inj_p_limit_1{od::entry_of<inj_p_limit_1_spec>,
                                       {.name = "Inj. P Limit 1", .section = "4.100"},
                                       {{32767, 2}, {0, 0}}};
// 4.197 (offset 1)
constexpr od::entry_spec program_block_spec{.index = 0x2F25,
                                            .type = od::data_type::integer16,
                                            .access_type = od::access::ro,
                                            .flags = od::flag::signedness_guess | od::flag::scaled,
                                            .low = od::decimal_number(0, 0),
                                            .high = od::decimal_number(32, 0)};
constexpr od::descriptor program_block{od::entry_of<program_block_spec>,
                                       {.name = "Program Block", .section = "4.197"},
                                       {{1, 0}, {1, 0}}};
// 4.35 (range_exceeds_field)
constexpr od::entry_spec decompres_limit_minus_spec{
    .index = 0x2FA5,
    .type = od::data_type::integer16,
    .access_type = od::access::rw,
    .flags = od::flag::signedness_guess | od::flag::range_exceeds_field | od::flag::scaled,
    .low = od::decimal_number(-100, 0),
    .high = od::decimal_number(100, 0)};
constexpr od::descriptor decompres_limit_minus{od::entry_of<decompres_limit_minus_spec>,
                                               {.name = "Decompres.: Limit-", .section = "4.35"},
                                               {{3277, 1}, {0, 0}}};

constexpr bool payload_is(fc::result<dpq::payload> p, std::array<std::uint8_t, 4> b,
                          std::uint8_t n) {
  if (!p.has_value() || p.value().size != n) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (p.value().bytes[i] != b[i]) return false;
  }
  return true;
}
} // namespace

// The shape: inj_p_limit_1.to_raw(4.0) → 1311, bytes 1F 05 00 00, and back.
static_assert(inj_p_limit_1.to_raw(4.0).value() == 1311);
static_assert(payload_is(dpq::to_bytes(inj_p_limit_1, 4.0), {0x1F, 0x05, 0x00, 0x00}, 4));
static_assert(dpq::raw_from_bytes(inj_p_limit_1, std::array<std::uint8_t, 4>{0x1F, 0x05, 0, 0})
                  .value() == 1311);
static_assert(dpq::from_bytes(inj_p_limit_1, std::array<std::uint8_t, 4>{0x1F, 0x05, 0, 0})
                  .value()
                  .mantissa == 4001);

TEST_CASE("dpq parameter: Inj. P Limit 1, 4.0 -> 1311 -> 1F 05 00 00 -> 4.001") {
  CHECK(inj_p_limit_1.to_raw(4.0).value() == 1311);
  auto p = dpq::to_bytes(inj_p_limit_1, 4.0);
  REQUIRE(p.has_value());
  CHECK(payload_is(p, {0x1F, 0x05, 0x00, 0x00}, 4));
  auto w = dpq::write_bytes(inj_p_limit_1, decimal{40, 1});
  CHECK(w == p);
  auto back = dpq::from_bytes(inj_p_limit_1, p.value().span());
  REQUIRE(back.has_value());
  CHECK(back.value().mantissa == 4001);
  CHECK(back.value().places == 3);
  CHECK(inj_p_limit_1.to_raw(back.value()).value() == 1311);
  CHECK(dpq::to_eu_decimal(inj_p_limit_1, 1311).value().mantissa == 4001);
  CHECK(inj_p_limit_1.to_eu(1311) == doctest::Approx(4.000976592303232));
  // Limits and errors.
  CHECK(dpq::to_bytes(inj_p_limit_1, 5000.0).has_value());
  CHECK(dpq::to_bytes(inj_p_limit_1, 5000.01).error() == errc::out_of_range);
  CHECK(dpq::to_bytes(inj_p_limit_1, -1.0).error() == errc::out_of_range);
  CHECK(dpq::raw_to_bytes(inj_p_limit_1, 1'638'351).error() == errc::out_of_range);
  CHECK(dpq::raw_to_bytes(inj_p_limit_1, -1).error() == errc::out_of_range);
  const std::array<std::uint8_t, 2> short_in{0x1F, 0x05};
  const std::array<std::uint8_t, 5> long_in{0x1F, 0x05, 0, 0, 0};
  CHECK(dpq::from_bytes(inj_p_limit_1, short_in).error() == errc::truncated);
  CHECK(dpq::from_bytes(inj_p_limit_1, long_in).error() == errc::bad_length);
}

TEST_CASE("dpq parameter: read-only and offset (Program Block)") {
  CHECK(dpq::write_bytes(program_block, 1.0).error() == errc::access_denied);
  auto p = dpq::to_bytes(program_block, 0.0); // conversion itself is allowed
  REQUIRE(p.has_value());
  CHECK(payload_is(p, {0xFF, 0xFF, 0, 0}, 2));
  auto eu = dpq::from_bytes(program_block, p.value().span());
  REQUIRE(eu.has_value());
  CHECK(eu.value().mantissa == 0);
  const std::array<std::uint8_t, 2> raw31{0x1F, 0x00};
  CHECK(dpq::from_bytes(program_block, raw31).value().mantissa == 32);
  // A read-back value outside the printed range still decodes (actual value).
  const std::array<std::uint8_t, 2> raw99{0x63, 0x00};
  CHECK(dpq::from_bytes(program_block, raw99).value().mantissa == 100);
}

TEST_CASE("dpq parameter: range that exceeds the field (Decompres.: Limit-)") {
  CHECK(dpq::to_bytes(decompres_limit_minus, 100.0).error() == errc::overflow);
  CHECK(dpq::to_bytes(decompres_limit_minus, -100.0).error() == errc::overflow);
  CHECK(dpq::to_bytes(decompres_limit_minus, 100.1).error() == errc::out_of_range);
  auto p = dpq::to_bytes(decompres_limit_minus, -99.99);
  REQUIRE(p.has_value());
  CHECK(payload_is(p, {0x01, 0x80, 0, 0}, 2)); // −99.99 × 327.7 = −32766.723 → −32767 = 0x8001
}

TEST_CASE("dpq parameter: every kind of engineering value, each as the number it is") {
  // decimal, double, float (its shortest decimal) and integers give the same raw value
  const auto want = dpq::to_bytes(inj_p_limit_1, decimal{4, 0});
  REQUIRE(want.has_value());
  CHECK(dpq::to_bytes(inj_p_limit_1, 4.0) == want);
  CHECK(dpq::to_bytes(inj_p_limit_1, 4.0F) == want);
  CHECK(dpq::to_bytes(inj_p_limit_1, 4) == want);
  CHECK(dpq::to_bytes(inj_p_limit_1, std::uint16_t{4}) == want);
  CHECK(dpq::write_bytes(inj_p_limit_1, 4U) == want);
  // 90.73 as a PLC REAL: 29729.4991 → 29729 (widened to double first it would be 29730)
  CHECK(inj_p_limit_1.to_raw(90.73F).value() == 29729);
  CHECK(dpq::to_bytes(inj_p_limit_1, 90.73F).value().bytes[0] == (29729 & 0xFF));
  static_assert(!dpq::engineering_value<bool>);
  static_assert(dpq::engineering_value<float> && dpq::engineering_value<long long>);
}

TEST_CASE("dpq parameter: types and fields") {
  static constexpr od::entry_spec text_spec{
      .index = 0x1008, .type = od::data_type::visible_string, .size = 8};
  const od::descriptor text{od::entry_of<text_spec>};
  CHECK(text.to_raw(1.0).error() == errc::type_mismatch);
  CHECK(dpq::to_bytes(text, 1.0).error() == errc::type_mismatch);
  CHECK(dpq::raw_to_bytes(text, 1).error() == errc::type_mismatch);
  CHECK(dpq::raw_from_bytes(text, std::array<std::uint8_t, 1>{0}).error() == errc::type_mismatch);
  const od::descriptor open{{.index = 0x2000, .type = od::data_type::integer16}};
  CHECK(open.to_raw(decimal{32767, 0}).value() == 32767); // no range: only the field
  CHECK(open.to_raw(decimal{32768, 0}).error() == errc::overflow);
  CHECK(dpq::round_trip_places(inj_p_limit_1.scale).value() == 3);
}

TEST_CASE("dpq parameter: a scaled entry without its scale refuses to check its limits") {
  // The engineering limits of a scaled entry need the scale; a plain od::entry (here the
  // descriptor seen through its base) cannot turn them into raw limits.
  const od::entry &plain = inj_p_limit_1;
  std::array<std::uint8_t, 4> out{};
  CHECK(od::encode(plain, 1311, out).error() == errc::invalid_argument);
  CHECK(od::encode(inj_p_limit_1, 1311, out).value() == 4);
  CHECK(od::decode(plain, out).error() == errc::invalid_argument);
  CHECK(od::decode(plain, out, fc::byte_order::little, od::limits::ignore).value() ==
        od::unsigned_number(1311));
  CHECK(od::decode(inj_p_limit_1, out).value() == od::unsigned_number(1311));
}
