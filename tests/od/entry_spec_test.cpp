// The lean od::entry and its packed columns (od/entry.hpp, od/entry_spec.hpp): what each column
// packs to, in the entry's own width or as a number; accessors; round trips through pack and
// spec_of for every type and random values; od::table at compile time and at run time.
#include "xorshift.hpp"

#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/number.hpp>

#include <doctest/doctest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace od = fieldcodec::od;
using od::data_type;

namespace {

constexpr od::number U(std::uint64_t v) { return od::unsigned_number(v); }
constexpr od::number I(std::int64_t v) { return od::signed_number(v); }

// The issue asked for at most 16 bytes on a 32-bit target: 12 (index, sub, object, type, access,
// PDO, flags and a pointer), 16 with 64-bit pointers.
static_assert(sizeof(od::entry) == (sizeof(void *) == 4 ? 12U : 16U));

/// The packed bytes of `s`.
std::string bytes_of(const od::entry_spec &s) {
  std::string b(od::packed_size(s), '\0');
  REQUIRE(od::pack(s, std::span<char>(b.data(), b.size())).value() == b.size());
  return b;
}

// --- what the columns pack to ------------------------------------------------------------------

constexpr od::entry_spec u8_default{.index = 0x1400, .sub = 2, .default_value = U(255)};
static_assert(od::entry_of<u8_default>.flags == od::flag::has_default);
static_assert(od::entry_of<u8_default>.default_value() == U(255));
static_assert(od::entry_of<u8_default>.low() == od::number{});
static_assert(od::entry_of<u8_default>.capacity() == 0U);

// An INTEGER16 range -5..5 with default -1: six bytes, the default's kind made signed.
constexpr od::entry_spec i16{.index = 0x2000,
                             .type = data_type::integer16,
                             .low = I(-5),
                             .high = U(5),
                             .default_value = I(-1)};
static_assert(od::packed_size(i16) == 6U);
static_assert(od::entry_of<i16>.flags ==
              (od::flag::has_default | od::flag::has_low | od::flag::has_high));
static_assert(od::entry_of<i16>.high() == I(5)); // written unsigned, read in the entry's kind
static_assert(od::entry_of<i16>.low() == I(-5) && od::entry_of<i16>.default_value() == I(-1));

// A scaled entry's engineering limits are numbers (10 bytes each); its raw default is not.
constexpr od::entry_spec scaled{.index = 0x2023,
                                .type = data_type::unsigned32,
                                .flags = od::flag::scaled | od::flag::signedness_guess,
                                .low = od::decimal_number(0, 0),
                                .high = od::decimal_number(50005, 1),
                                .default_value = U(1311)};
static_assert(od::packed_size(scaled) == 4U + 2U * od::packed_number_size);
static_assert(od::entry_of<scaled>.has(od::flag::limits_number) &&
              !od::entry_of<scaled>.has(od::flag::default_number));
static_assert(od::entry_of<scaled>.high() == od::decimal_number(50005, 1));
static_assert(od::entry_of<scaled>.has(od::flag::scaled | od::flag::signedness_guess));

// A string: capacity, then the default text's length and bytes (NULs kept).
constexpr od::entry_spec octets{.index = 0x5FF5,
                                .type = data_type::octet_string,
                                .size = 2,
                                .default_text = od::text{"\0\0", 2}};
static_assert(od::packed_size(octets) == 4U + 4U + 2U);
static_assert(od::entry_of<octets>.capacity() == 2U && od::entry_of<octets>.width() == 2U);
static_assert(od::entry_of<octets>.default_text() == std::string_view("\0\0", 2));

// Nothing to pack: no bytes, no pointer.
constexpr od::entry_spec bare{.index = 0x6041, .type = data_type::unsigned16};
static_assert(od::packed_size(bare) == 0U && od::entry_of<bare>.flags == 0U);
static_assert(od::entry_of<bare>.default_value() == od::number{});

TEST_CASE("od::pack: the bytes of each column, little-endian in the entry's width") {
  CHECK(bytes_of(u8_default) == std::string("\xFF", 1));
  CHECK(bytes_of(i16) == std::string("\xFF\xFF\xFB\xFF\x05\x00", 6)); // default, low, high
  // REAL32 1.5 is its float bits; REAL64 2.5 its double bits
  CHECK(bytes_of({.type = data_type::real32, .default_value = od::real_number(1.5)}) ==
        std::string("\x00\x00\xC0\x3F", 4));
  CHECK(bytes_of({.type = data_type::real64, .low = od::real_number(2.5)}) ==
        std::string("\x00\x00\x00\x00\x00\x00\x04\x40", 8));
  // TIME_OF_DAY: ms (4 bytes), days (2)
  CHECK(bytes_of({.type = data_type::time_of_day,
                  .default_value = U(std::uint64_t{1000} | std::uint64_t{3} << 32U)}) ==
        std::string("\xE8\x03\x00\x00\x03\x00", 6));
  // UNSIGNED24 and INTEGER40 take 3 and 5 bytes
  CHECK(bytes_of({.type = data_type::unsigned24, .default_value = U(0x123456)}) ==
        std::string("\x56\x34\x12", 3));
  CHECK(bytes_of({.type = data_type::integer40, .default_value = I(-2)}) ==
        std::string("\xFE\xFF\xFF\xFF\xFF", 5));
  // a string's capacity, then its default (length, bytes)
  CHECK(bytes_of({.type = data_type::visible_string, .size = 16, .default_text = "ab"}) ==
        std::string("\x10\x00\x00\x00\x02\x00\x00\x00"
                    "ab",
                    10));
}

TEST_CASE("od::pack: what the width cannot hold exactly is a number") {
  const auto number_form = [](const od::entry_spec &s) {
    return od::make_entry(s, nullptr).flags & (od::flag::default_number | od::flag::limits_number);
  };
  // beyond the field (the DPQ's printed ranges that do not fit their 2 bytes)
  CHECK(number_form({.type = data_type::integer16, .high = I(40000)}) == od::flag::limits_number);
  CHECK(number_form({.type = data_type::unsigned8, .low = I(-1)}) == od::flag::limits_number);
  CHECK(number_form({.type = data_type::unsigned8, .default_value = U(256)}) ==
        od::flag::default_number);
  CHECK(number_form({.type = data_type::unsigned8, .default_value = U(255)}) == 0U);
  CHECK(number_form({.type = data_type::integer8, .default_value = I(-128)}) == 0U);
  CHECK(number_form({.type = data_type::integer8, .default_value = U(128)}) ==
        od::flag::default_number);
  // a fraction, or a real for an integer entry
  CHECK(number_form({.type = data_type::integer32, .low = od::decimal_number(15, 1)}) ==
        od::flag::limits_number);
  CHECK(number_form({.type = data_type::integer32, .default_value = od::real_number(2.0)}) ==
        od::flag::default_number);
  // a REAL32 that is no float (0.1 as a double), an integer for a REAL, a decimal for a REAL
  CHECK(number_form({.type = data_type::real32, .high = od::real_number(0.1)}) ==
        od::flag::limits_number);
  CHECK(number_form({.type = data_type::real32, .high = od::real_number(0.5)}) == 0U);
  CHECK(number_form({.type = data_type::real64, .default_value = I(3)}) ==
        od::flag::default_number);
  CHECK(number_form({.type = data_type::real64, .default_value = od::decimal_number(15, 1)}) ==
        od::flag::default_number);
  // one limit beyond the field makes both numbers (they share the form)
  const od::entry_spec mixed{.type = data_type::unsigned16, .low = U(1), .high = U(70000)};
  CHECK(number_form(mixed) == od::flag::limits_number);
  CHECK(od::packed_size(mixed) == 2U * od::packed_number_size);
  // a byte string's numbers (COMPAX prints ranges for octet strings): numbers
  CHECK(number_form({.type = data_type::octet_string, .low = I(0), .high = I(9)}) ==
        od::flag::limits_number);
  // the packing bits of a spec are od::pack's, not the caller's
  const od::entry lied = od::make_entry(
      {.type = data_type::unsigned8, .flags = od::flag::has_low | od::flag::scaled}, nullptr);
  CHECK(lied.flags == od::flag::scaled);
}

// --- round trips --------------------------------------------------------------------------------

/// A number of a random kind and value (sometimes none).
od::number random_number(fieldcodec::test::xorshift &r) {
  const std::uint64_t v = r.next();
  switch (r.next() % 6U) {
  case 0: return {};
  case 1: return I(static_cast<std::int64_t>(v) >> (r.next() % 64U));
  case 2: return U(v >> (r.next() % 64U));
  case 3: return od::real_number(static_cast<double>(static_cast<std::int32_t>(v)) / 8.0);
  case 4:
    return od::decimal_number(static_cast<std::int64_t>(v) >> 40U,
                              static_cast<std::uint8_t>(r.next() % 6U));
  default: return I(static_cast<std::int8_t>(v)); // small: fits most widths
  }
}

bool same_value(const od::number &got, const od::number &want, bool in_width) {
  if (!in_width ||
      (want.kind != od::number_kind::signed_ && want.kind != od::number_kind::unsigned_))
    return got == want;
  const bool neg =
      want.kind == od::number_kind::signed_ && static_cast<std::int64_t>(want.bits) < 0;
  const bool got_neg =
      got.kind == od::number_kind::signed_ && static_cast<std::int64_t>(got.bits) < 0;
  return (got.kind == od::number_kind::signed_ || got.kind == od::number_kind::unsigned_) &&
         got.bits == want.bits && neg == got_neg;
}

TEST_CASE("od::pack and the accessors: every column of every type comes back") {
  fieldcodec::test::xorshift r{0x27'0D'0E'11};
  for (int n = 0; n < 20000; ++n) {
    const auto &row = od::data_types[r.next() % od::data_types.size()];
    od::entry_spec s;
    s.index = static_cast<std::uint16_t>(r.next());
    s.type = row.type;
    s.flags = static_cast<std::uint16_t>(r.next() & 0xFFU); // source flags, packing bits off
    s.low = random_number(r);
    s.high = random_number(r);
    s.default_value = random_number(r);
    std::string text;
    if (od::is_byte_string(s.type)) {
      s.size = static_cast<std::uint32_t>(r.next() % 300U);
      text.assign(r.next() % 20U, '\0');
      for (char &c : text) c = static_cast<char>(r.next());
      s.default_text = od::text(text.data(), text.size());
    }
    const std::string b = bytes_of(s);
    const od::entry e = od::make_entry(s, b.data());
    CAPTURE(row.name);
    CHECK((e.flags & ~od::flag::packed) == s.flags);
    CHECK(e.capacity() == (od::is_byte_string(s.type) ? s.size : 0U));
    CHECK(same_value(e.default_value(), s.default_value, !e.has(od::flag::default_number)));
    CHECK(same_value(e.low(), s.low, !e.has(od::flag::limits_number)));
    CHECK(same_value(e.high(), s.high, !e.has(od::flag::limits_number)));
    CHECK(std::string_view(e.default_text()) == text);
    // and packing what came back gives the same bytes
    CHECK(bytes_of(od::spec_of(e)) == b);
  }
}

// --- tables -------------------------------------------------------------------------------------

constexpr od::entry_spec specs[] = {
    {.index = 0x1000, .type = data_type::unsigned32, .default_value = U(0x191)},
    {.index = 0x1008, .type = data_type::visible_string, .size = 8, .default_text = "io"},
    {.index = 0x2000, .type = data_type::integer8, .low = I(-3), .high = I(3)},
};
constexpr auto entries = od::entries_of<specs>;
constexpr od::dictionary dict{entries};
static_assert(dict.is_valid() && entries.size() == 3U);
static_assert(dict.lookup(0x2000, 0).value()->high() == I(3));
static_assert(dict.at({0x1008, 0}).value().default_text() == "io");
// one table per spec array: the same entries however often they are named
static_assert(&od::entries_of<specs>[0] == &entries[0]);

TEST_CASE("od::table: at run time, its entries point into it") {
  std::array<od::entry_spec, 2> run{{{.index = 1, .type = data_type::unsigned16, .low = U(7)},
                                     {.index = 2, .type = data_type::domain, .size = 4000}}};
  run[0].high = U(9); // made at run time
  const od::table<2, 2U + 2U + 4U> t{run};
  REQUIRE(t.ok());
  CHECK(t[0].low() == U(7));
  CHECK(t[0].high() == U(9));
  CHECK(t[1].capacity() == 4000U);
  CHECK(t.dictionary().lookup(2, 0).value()->width() == 4000U);
  // too few bytes: not ok, an empty dictionary (never an entry pointing past its table)
  const od::table<2, 3> small{run};
  CHECK_FALSE(small.ok());
  CHECK(small.dictionary().empty());
}

TEST_CASE("od::descriptor of a packed entry: scaling and limits as before") {
  static constexpr od::descriptor d{
      od::entry_of<scaled>, {.name = "Inj. P Limit 1"}, {{32767, 2}, {0, 0}}};
  static_assert(d.to_raw(4.0).value() == 1311);
  CHECK(d.to_raw(fieldcodec::decimal{50005, 1}).has_value()); // the high limit itself
  CHECK(d.to_raw(fieldcodec::decimal{50006, 1}).error() == fieldcodec::errc::out_of_range);
  CHECK(d.default_value() == U(1311));
}

} // namespace
