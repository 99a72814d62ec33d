// The generated DPQ dictionary (include/fieldcodec/dictionaries/dpq_parameters.hpp, written by
// fieldcodec-gen from dictionaries/dpq_parameters.csv) against the CSV, and the
// parameter-level API on its named descriptors. Compiled only once the header exists.
#if __has_include(<fieldcodec/dictionaries/dpq_parameters.hpp>)

#include "dpq_csv.hpp"

#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/parameter.hpp>
#include <fieldcodec/dpq/sdo.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace fc = fieldcodec;
namespace dpq = fieldcodec::dpq;
namespace od = fieldcodec::od;
namespace p = fieldcodec::dictionaries::dpq_parameters;
using fc::decimal;
using fc::errc;

// The example on the generated descriptor, at compile time.
static_assert(p::inj_p_limit_1.index == 0x2023);
static_assert(p::inj_p_limit_1.to_raw(4.0).value() == 1311);
static_assert(dpq::to_bytes(p::inj_p_limit_1, 4.0).value().size == 4);
static_assert(dpq::to_bytes(p::inj_p_limit_1, 4.0).value().bytes[0] == 0x1F);
static_assert(dpq::to_bytes(p::inj_p_limit_1, 4.0).value().bytes[1] == 0x05);
static_assert(dpq::to_bytes(p::inj_p_limit_1, 4.0).value().bytes[2] == 0x00);
static_assert(dpq::to_bytes(p::inj_p_limit_1, 4.0).value().bytes[3] == 0x00);

TEST_CASE("dpq generated: the issue's example by name") {
  CHECK(p::inj_p_limit_1.to_raw(4.0).value() == 1311);
  auto b = dpq::to_bytes(p::inj_p_limit_1, 4.0);
  REQUIRE(b.has_value());
  CHECK(b.value().size == 4);
  CHECK(b.value().bytes[0] == 0x1F);
  CHECK(b.value().bytes[1] == 0x05);
  CHECK(b.value().bytes[2] == 0x00);
  CHECK(b.value().bytes[3] == 0x00);
  auto eu = dpq::from_bytes(p::inj_p_limit_1, b.value().span());
  REQUIRE(eu.has_value());
  CHECK(eu.value().mantissa == 4001);
  CHECK(eu.value().places == 3);
  auto f = dpq::write_request(5, p::inj_p_limit_1, 4.0);
  REQUIRE(f.has_value());
  const std::array<std::uint8_t, 8> want{0x23, 0x23, 0x20, 0x00, 0x1F, 0x05, 0x00, 0x00};
  CHECK(f.value().id == 0x605);
  CHECK(f.value().data == want);
  // Offset parameter and read-only refusal.
  CHECK(p::program_block.to_raw(0.0).value() == -1);
  CHECK(dpq::write_request(5, p::program_block, 1.0).error() == errc::access_denied);
  // An overflowing range (4.35 Decompres.: Limit-; looked up by index, its symbol depends on how
  // the generator spells the '-').
  const auto limit_minus = p::dictionary.at(0x2FA5, 0);
  REQUIRE(limit_minus.has_value());
  CHECK(dpq::to_bytes(limit_minus.value(), 100.0).error() == errc::overflow);
  CHECK(dpq::to_bytes(limit_minus.value(), 99.99).has_value());
}

// An empty CSV number is absent in the generated entry; a given one is the same raw value.
static bool same_number(const od::number &n, const std::string &text) {
  if (text.empty()) return !n.has_value();
  bool ok = true;
  const decimal d = dpq_test::parse(text, ok);
  return ok && n.has_value() && fc::equal(n.to_decimal().value(), d);
}

TEST_CASE("dpq generated: every entry agrees with the CSV and converts the same way") {
  const auto rows = dpq_test::load();
  // 221 bus parameters (chapter 4) + 19 communication objects (chapter 3)
  REQUIRE(rows.size() == 240);
  REQUIRE(p::entries.size() == 240);
  REQUIRE(p::dictionary.size() == 240);
  std::size_t parameters = 0;
  for (const auto &r : rows) {
    const auto index = static_cast<std::uint16_t>(std::stoul(r.index, nullptr, 16));
    const auto sub = static_cast<std::uint8_t>(std::stoul(r.subindex));
    const auto found = p::dictionary.at(index, sub);
    REQUIRE_MESSAGE(found.has_value(), r.section);
    const od::descriptor *e = &found.value();
    CHECK_MESSAGE(e->info.name == r.name, r.section);
    CHECK_MESSAGE(od::name(e->type) == r.data_type, r.section);
    CHECK_MESSAGE(e->width() == static_cast<std::uint32_t>(r.bytes), r.section);
    CHECK_MESSAGE(od::name(e->access_type) == r.access, r.section);
    CHECK_MESSAGE(e->info.unit == r.unit, r.section);
    CHECK_MESSAGE(e->info.section == r.section, r.section);
    CHECK_MESSAGE(od::name(e->object) == (r.object_code.empty() ? "VAR" : r.object_code),
                  r.section);
    CHECK_MESSAGE(same_number(e->default_value(), r.default_text), r.section);
    if (!r.is_parameter()) {
      // a communication object: raw values, no scale, no DPQ flags
      CHECK_MESSAGE(!e->has(od::flag::scaled), r.section);
      CHECK_MESSAGE((e->flags & ~od::flag::packed) == 0, r.section);
      CHECK_MESSAGE(r.scale_text.empty(), r.section);
      CHECK_MESSAGE(same_number(e->low(), r.low_text), r.section);
      CHECK_MESSAGE(same_number(e->high(), r.high_text), r.section);
      continue;
    }
    ++parameters;
    CHECK_MESSAGE(e->has(od::flag::scaled), r.section);
    CHECK_MESSAGE(fc::equal(e->scale.scale, r.scale), r.section);
    CHECK_MESSAGE(fc::equal(e->scale.offset, r.offset), r.section);
    CHECK_MESSAGE(fc::equal(e->low().to_decimal().value(), r.low), r.section);
    CHECK_MESSAGE(fc::equal(e->high().to_decimal().value(), r.high), r.section);
    CHECK_MESSAGE(((e->flags & od::flag::range_exceeds_field) != 0) ==
                      r.has_flag("range_exceeds_field"),
                  r.section);
    CHECK_MESSAGE(((e->flags & od::flag::index_anomaly) != 0) == r.has_flag("index_anomaly"),
                  r.section);
    CHECK_MESSAGE(((e->flags & od::flag::signedness_guess) != 0) == r.has_flag("signedness_guess"),
                  r.section);
    // Same results through the generated descriptor and through one built from the CSV here.
    const od::descriptor c = r.descriptor();
    for (const decimal eu : {r.low, r.high, decimal{r.low.mantissa + 1, r.low.places}}) {
      const auto a = e->to_raw(eu);
      const auto b = c.to_raw(eu);
      CHECK_MESSAGE(a == b, r.section);
      if (a) {
        CHECK_MESSAGE(dpq::to_bytes(*e, eu) == dpq::to_bytes(c, eu), r.section);
        const auto bytes = dpq::to_bytes(c, eu).value();
        CHECK_MESSAGE(dpq::from_bytes(*e, bytes.span()).value().mantissa ==
                          dpq::from_bytes(c, bytes.span()).value().mantissa,
                      r.section);
      }
    }
  }
  CHECK(parameters == 221);
}

#endif
