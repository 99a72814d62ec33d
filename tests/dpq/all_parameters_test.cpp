// Every one of the 221 DPQ parameters (dictionaries/dpq_parameters.csv, manual 004 chapter 4):
// printed minimum, maximum and a mid value convert to the raw value an independent exact
// computation gives, encode to bytes and read back to a value that converts to the same raw
// value; exact halves round away from zero in both signs; every range flagged
// range_exceeds_field is refused with overflow exactly at the ends that do not fit.
#include "dpq_csv.hpp"

#include <fieldcodec/dpq/parameter.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>

namespace fc = fieldcodec;
namespace dpq = fieldcodec::dpq;
using fc::decimal;
using fc::errc;

namespace {

__extension__ typedef __int128 i128; // test-only reference arithmetic, independent of core/

i128 pow10(unsigned n) {
  i128 p = 1;
  for (unsigned i = 0; i < n; ++i) p *= 10;
  return p;
}

// Reference: round((eu − offset) × scale) half away from zero, with plain 128-bit integers.
i128 reference_raw(decimal eu, decimal offset, decimal scale) {
  const unsigned p = eu.places > offset.places ? eu.places : offset.places;
  const i128 diff =
      i128{eu.mantissa} * pow10(p - eu.places) - i128{offset.mantissa} * pow10(p - offset.places);
  const i128 num = diff * scale.mantissa;
  const i128 den = pow10(p + scale.places);
  const i128 mag = num < 0 ? -num : num;
  i128 q = mag / den;
  if (2 * (mag % den) >= den) ++q;
  return num < 0 ? -q : q;
}

bool fits(i128 raw, const dpq_test::row &r) {
  const unsigned bits = 8U * static_cast<unsigned>(r.bytes);
  const i128 lo = r.is_signed() ? -(i128{1} << (bits - 1U)) : 0;
  const i128 hi = r.is_signed() ? (i128{1} << (bits - 1U)) - 1 : (i128{1} << bits) - 1;
  return raw >= lo && raw <= hi;
}

// (a + b) / 2 exactly.
decimal midpoint(decimal a, decimal b) {
  const unsigned p = a.places > b.places ? a.places : b.places;
  const std::int64_t s = a.mantissa * static_cast<std::int64_t>(pow10(p - a.places)) +
                         b.mantissa * static_cast<std::int64_t>(pow10(p - b.places));
  if (s % 2 == 0) return {s / 2, static_cast<std::uint8_t>(p)};
  return {s * 5, static_cast<std::uint8_t>(p + 1)};
}

decimal add(decimal a, decimal b) {
  const unsigned p = a.places > b.places ? a.places : b.places;
  return {a.mantissa * static_cast<std::int64_t>(pow10(p - a.places)) +
              b.mantissa * static_cast<std::int64_t>(pow10(p - b.places)),
          static_cast<std::uint8_t>(p)};
}

// The smallest positive h with h × scale = g / 2 for an odd integer g (an exact half), as a
// decimal: scale = m·10^-s, m = 2^a·5^b·g with g coprime to 10 → h = 10^s / (2^(a+1)·5^b).
// Also returns g.
decimal half_step(decimal scale, std::int64_t &g) {
  std::int64_t m = scale.mantissa;
  unsigned a = 0, b = 0;
  while (m % 2 == 0) m /= 2, ++a;
  while (m % 5 == 0) m /= 5, ++b;
  g = m;
  // 1 / (2^(a+1)·5^b) = 5^(a+1)·2^b / 10^(a+1+b)
  std::int64_t mant = 1;
  for (unsigned i = 0; i < a + 1U; ++i) mant *= 5;
  for (unsigned i = 0; i < b; ++i) mant *= 2;
  int places = static_cast<int>(a + 1U + b) - static_cast<int>(scale.places);
  while (places < 0) mant *= 10, ++places;
  return {mant, static_cast<std::uint8_t>(places)};
}

bool in_range(decimal v, const dpq_test::row &r) {
  return fc::compare(v, r.low) >= 0 && fc::compare(v, r.high) <= 0;
}

std::string what(const dpq_test::row &r) { return r.section + " " + r.index + " " + r.name; }

// One value: to_raw must agree with the reference (or refuse with overflow when the reference
// does not fit), bytes and read-back must round-trip.
void check_value(const dpq_test::row &r, decimal eu, std::size_t &converted, std::size_t &refused) {
  const fieldcodec::od::descriptor c = r.descriptor();
  const i128 want = reference_raw(eu, r.offset, r.scale);
  auto raw = c.to_raw(eu);
  if (!fits(want, r)) {
    CHECK_MESSAGE(raw.is(errc::overflow), what(r));
    CHECK_MESSAGE(dpq::to_bytes(c, eu).is(errc::overflow), what(r));
    ++refused;
    return;
  }
  REQUIRE_MESSAGE(raw.has_value(), what(r));
  CHECK_MESSAGE(i128{raw.value()} == want, what(r));
  auto bytes = dpq::to_bytes(c, eu);
  REQUIRE_MESSAGE(bytes.has_value(), what(r));
  CHECK(bytes.value().size == r.bytes);
  // Little-endian, two's complement for signed fields, zero padded.
  const auto u = static_cast<std::uint64_t>(raw.value());
  for (std::size_t i = 0; i < static_cast<std::size_t>(r.bytes); ++i) {
    CHECK_MESSAGE(bytes.value().bytes[i] == static_cast<std::uint8_t>(u >> (8U * i)), what(r));
  }
  auto back_raw = dpq::raw_from_bytes(c, bytes.value().span());
  REQUIRE(back_raw.has_value());
  CHECK(back_raw.value() == raw.value());
  auto back = dpq::from_bytes(c, bytes.value().span());
  REQUIRE_MESSAGE(back.has_value(), what(r));
  // The read-back EU converts to the same raw value (round trip), and lies within half a
  // count of the value sent: |back − eu| × scale ≤ ½ ⇔ reference_raw(back) == raw.
  CHECK_MESSAGE(reference_raw(back.value(), r.offset, r.scale) == want, what(r));
  // Without a range check (read-back of a printed limit may round outside it by < 1 count).
  fieldcodec::od::descriptor open = c;
  open.flags = static_cast<std::uint16_t>(
      open.flags & ~(fieldcodec::od::flag::has_low | fieldcodec::od::flag::has_high));
  CHECK_MESSAGE(open.to_raw(back.value()).value() == raw.value(), what(r));
  // The double path agrees for values with ≤ 15 significant digits.
  CHECK_MESSAGE(
      c.to_eu(raw.value()) ==
          doctest::Approx(
              static_cast<double>(raw.value()) / (static_cast<double>(r.scale.mantissa) /
                                                  static_cast<double>(pow10(r.scale.places))) +
              static_cast<double>(r.offset.mantissa) / static_cast<double>(pow10(r.offset.places))),
      what(r));
  ++converted;
}

} // namespace

TEST_CASE("dpq all parameters: table shape") {
  const auto rows = dpq_test::load_parameters();
  REQUIRE(rows.size() == 221);
  std::set<std::string> indices;
  std::map<std::string, int> types;
  int exceeds = 0, anomalies = 0, offsets = 0, guesses = 0, signed_guesses = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto &r = rows[i];
    CHECK(r.section == "4." + std::to_string(i + 1));
    indices.insert(r.index);
    ++types[r.data_type];
    CHECK((r.bytes == 2 || r.bytes == 4));
    CHECK(((r.data_type.find("16") != std::string::npos) == (r.bytes == 2)));
    CHECK((r.access == "rw" || r.access == "ro"));
    // signedness_guess exactly where the printed range leaves the signedness open: both raw
    // ends non-negative and within the signed type of the width (docs/dpq.md, "Data types
    // and signedness"); elsewhere a negative end forces signed, a 2-byte end above 32767
    // forces unsigned, and the type must be the forced one.
    const i128 raw_lo = reference_raw(r.low, r.offset, r.scale);
    const i128 raw_hi = reference_raw(r.high, r.offset, r.scale);
    const i128 signed_max = r.bytes == 2 ? 32767 : 2147483647;
    const bool open = raw_lo >= 0 && raw_hi <= signed_max;
    CHECK_MESSAGE(r.has_flag("signedness_guess") == open, what(r));
    if (!open) {
      CHECK_MESSAGE((r.data_type.rfind("INTEGER", 0) == 0) == (raw_lo < 0), what(r));
    }
    guesses += open ? 1 : 0;
    signed_guesses += open && r.data_type.rfind("INTEGER", 0) == 0 ? 1 : 0;
    exceeds += r.has_flag("range_exceeds_field") ? 1 : 0;
    anomalies += r.has_flag("index_anomaly") ? 1 : 0;
    offsets += r.offset.mantissa != 0 ? 1 : 0;
  }
  CHECK(indices.size() == 221);
  CHECK(types["INTEGER16"] == 50);
  CHECK(types["UNSIGNED16"] == 53);
  CHECK(types["INTEGER32"] == 73);
  CHECK(types["UNSIGNED32"] == 45);
  CHECK(exceeds == 22);
  CHECK(anomalies == 18);
  CHECK(offsets == 1);
  CHECK(guesses == 82);        // 45 UNSIGNED32, 27 UNSIGNED16, 10 INTEGER32
  CHECK(signed_guesses == 10); // the exceptions listed in docs/dpq.md
}

TEST_CASE("dpq all parameters: range_exceeds_field is set exactly where the range does not fit") {
  const auto rows = dpq_test::load_parameters();
  REQUIRE(rows.size() == 221);
  for (const auto &r : rows) {
    const i128 lo = reference_raw(r.low, r.offset, r.scale);
    const i128 hi = reference_raw(r.high, r.offset, r.scale);
    const bool fit = fits(lo, r) && fits(hi, r);
    CHECK_MESSAGE(fit != r.has_flag("range_exceeds_field"), what(r));
    // An unsigned type is only used where the raw range has no negative value.
    if (!r.is_signed()) CHECK_MESSAGE(lo >= 0, what(r));
  }
}

TEST_CASE("dpq all parameters: min, max and mid convert exactly and round-trip") {
  const auto rows = dpq_test::load_parameters();
  REQUIRE(rows.size() == 221);
  std::size_t converted = 0, refused = 0;
  for (const auto &r : rows) {
    check_value(r, r.low, converted, refused);
    check_value(r, r.high, converted, refused);
    check_value(r, midpoint(r.low, r.high), converted, refused);
    // Just outside the printed range: out_of_range, also where the field would hold it.
    const fieldcodec::od::descriptor c = r.descriptor();
    CHECK_MESSAGE(c.to_raw(add(r.high, decimal{1, 6})).is(errc::out_of_range), what(r));
    CHECK_MESSAGE(c.to_raw(add(r.low, decimal{-1, 6})).is(errc::out_of_range), what(r));
  }
  // 221 × 3 values; the 22 flagged rows refuse both ends (16 × 2 for ±100, the four OUT2 rows
  // −100…0 refuse only the minimum; their mid −50 fits), the rest convert.
  CHECK(refused == 18 * 2 + 4);
  CHECK(converted + refused == 221 * 3);
}

TEST_CASE("dpq all parameters: exact halves round away from zero, both signs") {
  const auto rows = dpq_test::load_parameters();
  REQUIRE(rows.size() == 221);
  std::size_t positive = 0, negative = 0, none = 0;
  for (const auto &r : rows) {
    const fieldcodec::od::descriptor c = r.descriptor();
    std::int64_t g = 0;
    const decimal h = half_step(r.scale, g); // (offset ± h) × scale hits ±g/2 exactly
    bool any = false;
    // Odd multiples k·h give raw ±k·g/2; try k = 1 and the largest odd k that stays in range.
    for (std::int64_t k : {std::int64_t{1}, std::int64_t{3}, std::int64_t{101}}) {
      for (int sign : {1, -1}) {
        const decimal step{sign * k * h.mantissa, h.places};
        const decimal eu = add(r.offset, step);
        if (!in_range(eu, r)) continue;
        const i128 want = sign * (k * g + 1) / 2; // |k·g/2| rounded up
        auto raw = c.to_raw(eu);
        if (!fits(want, r)) {
          CHECK_MESSAGE(raw.is(errc::overflow), what(r));
          continue;
        }
        REQUIRE_MESSAGE(raw.has_value(), what(r));
        CHECK_MESSAGE(i128{raw.value()} == want, what(r));
        CHECK_MESSAGE(reference_raw(eu, r.offset, r.scale) == want, what(r));
        any = true;
        (sign > 0 ? positive : negative)++;
      }
    }
    if (!any) {
      // 4.34 Cyl. Area Ratio (scale 1024.01, ±31.9) and 4.146 Output Mode (327.67, 0…32):
      // the first exact half of their scale is at EU 50, outside the printed range.
      CHECK_MESSAGE((r.section == "4.34" || r.section == "4.146"), what(r));
      ++none;
    }
  }
  CHECK(none == 2);
  CHECK(positive > 0);
  CHECK(negative > 0);
  MESSAGE("exact halves tested: ", positive, " positive, ", negative, " negative");
}

TEST_CASE("dpq all parameters: every field boundary refuses one count beyond") {
  const auto rows = dpq_test::load_parameters();
  REQUIRE(rows.size() == 221);
  for (const auto &r : rows) {
    fieldcodec::od::descriptor c = r.descriptor();
    c.flags = static_cast<std::uint16_t>(
        c.flags & ~(fieldcodec::od::flag::has_low | fieldcodec::od::flag::has_high));
    const std::int64_t max = c.raw_field().value().max();
    const std::int64_t min = c.raw_field().value().min();
    CHECK(dpq::raw_to_bytes(c, max).has_value());
    CHECK(dpq::raw_to_bytes(c, min).has_value());
    CHECK(dpq::raw_to_bytes(c, max + 1).is(errc::overflow));
    CHECK(dpq::raw_to_bytes(c, min - 1).is(errc::overflow));
  }
}
