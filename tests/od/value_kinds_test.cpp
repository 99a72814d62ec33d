// od::value_kinds and od::check_value<Kinds> (od/value_kinds.hpp, od/value.hpp): the kinds a
// dictionary has; the integer comparisons in the entry's width give what od::decode with its
// limits gives (differential, every integer width, limits in the width and node-ID-relative,
// every node); a check made for fewer kinds refuses what it was not made for.
#include "xorshift.hpp"

#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/value.hpp>
#include <fieldcodec/od/value_kinds.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace od = fieldcodec::od;
using od::data_type;

namespace {

constexpr od::value_kinds none{false, false, false, false, false, false, false, false};
/// What an integer-only dictionary with limits relative to the node-ID needs (32 bits).
constexpr od::value_kinds int32_limits{.strings = false,
                                       .real = false,
                                       .time = false,
                                       .wide = false,
                                       .limits = true,
                                       .node_limits = true,
                                       .scaled = false,
                                       .numbers = false};
constexpr od::value_kinds int64_limits = [] {
  auto k = int32_limits;
  k.wide = true;
  return k;
}();

constexpr od::entry_spec kinds_specs[] = {
    {.index = 0x1000, .type = data_type::unsigned32, .default_value = od::unsigned_number(1)},
    {.index = 0x1008, .type = data_type::visible_string, .size = 4},
    {.index = 0x1200,
     .sub = 1,
     .type = data_type::unsigned32,
     .flags = od::flag::low_nodeid,
     .low = od::unsigned_number(0x600)},
    {.index = 0x2000, .type = data_type::real32},
    {.index = 0x2001, .type = data_type::integer64},
    {.index = 0x2002, .type = data_type::time_of_day},
    {.index = 0x2003,
     .type = data_type::integer16,
     .flags = od::flag::scaled,
     .high = od::decimal_number(15, 1)},
};
constexpr auto kinds_entries = od::entries_of<kinds_specs>;

static_assert(od::kinds_of(kinds_entries[0]) == none);
static_assert(od::kinds_of(kinds_entries.first(1)) == none);
static_assert(od::kinds_of(kinds_entries[1]) ==
              od::value_kinds{true, false, false, false, false, false, false, false});
static_assert(od::kinds_of(kinds_entries[2]).limits && od::kinds_of(kinds_entries[2]).node_limits);
static_assert(od::kinds_of(kinds_entries[3]).real);
static_assert(od::kinds_of(kinds_entries[4]).wide);
static_assert(od::kinds_of(kinds_entries[5]).time);
static_assert(od::kinds_of(kinds_entries[6]).scaled && od::kinds_of(kinds_entries[6]).numbers);
static_assert(od::kinds_of(kinds_entries) == od::all_kinds);
static_assert(od::covers(od::all_kinds, od::kinds_of(kinds_entries)));
static_assert(!od::covers(int64_limits, od::kinds_of(kinds_entries)));
static_assert(od::covers(int32_limits, od::kinds_of(kinds_entries.first(1))));
static_assert(od::covers(none, none) && !od::covers(none, int32_limits));

// What the generator wrote is what the entries have.
static_assert(od::kinds_of(fieldcodec::dictionaries::xenax_canopen::entries) ==
              fieldcodec::dictionaries::xenax_canopen::kinds);
static_assert(od::kinds_of(fieldcodec::dictionaries::dpq_parameters::entries) ==
              fieldcodec::dictionaries::dpq_parameters::kinds);
static_assert(fieldcodec::dictionaries::dpq_parameters::kinds.scaled &&
              !fieldcodec::dictionaries::dpq_parameters::kinds.real);

constexpr fieldcodec::scaling::linear identity{};

/// The value bytes of `v` in `w` bytes, little-endian.
std::array<std::uint8_t, 8> le(std::uint64_t v) {
  std::array<std::uint8_t, 8> b{};
  for (std::size_t i = 0; i < 8; ++i) b[i] = static_cast<std::uint8_t>(v >> (8U * i));
  return b;
}

} // namespace

TEST_CASE("check_value: integer limits in the entry's width, as decode checks them") {
  fieldcodec::test::xorshift r{0x1C4EC4};
  static constexpr data_type types[] = {
      data_type::integer8,   data_type::integer16,  data_type::integer24,  data_type::integer32,
      data_type::integer40,  data_type::integer48,  data_type::integer56,  data_type::integer64,
      data_type::unsigned8,  data_type::unsigned16, data_type::unsigned24, data_type::unsigned32,
      data_type::unsigned40, data_type::unsigned48, data_type::unsigned56, data_type::unsigned64};
  int narrow = 0;
  for (int n = 0; n < 200000; ++n) {
    od::entry_spec s;
    s.type = types[r.next() % std::size(types)];
    const std::size_t w = od::fixed_size(s.type);
    const bool is_signed = od::is_signed_integer(s.type);
    // limits near the ends of the field (where node-ID additions overflow) or anywhere in it
    const auto limit = [&]() -> od::number {
      std::uint64_t v = r.next() & fieldcodec::unsigned_max(w);
      if (r.next() % 3U == 0U) { // just below the largest value
        v = (is_signed ? static_cast<std::uint64_t>(fieldcodec::signed_max(w))
                       : fieldcodec::unsigned_max(w)) -
            (r.next() % 200U);
        v &= fieldcodec::unsigned_max(w);
      }
      if (is_signed) {
        const std::uint64_t sign = std::uint64_t{1} << (8U * w - 1U);
        return od::signed_number(static_cast<std::int64_t>((v ^ sign) - sign));
      }
      return od::unsigned_number(v);
    };
    if (r.next() % 4U != 0U) s.low = limit();
    if (r.next() % 4U != 0U) s.high = limit();
    if (r.next() % 3U == 0U) s.flags |= od::flag::low_nodeid;
    if (r.next() % 3U == 0U) s.flags |= od::flag::high_nodeid;
    std::array<char, 16> bytes{};
    REQUIRE(od::pack(s, bytes).has_value());
    const od::entry e = od::make_entry(s, bytes.data());
    REQUIRE_FALSE(e.has(od::flag::limits_number)); // the limits fit the width
    // a value near a limit or anywhere
    std::uint64_t v = r.next();
    if (r.next() % 2U == 0U && (s.low || s.high)) {
      const od::number near = s.low && (!s.high || r.next() % 2U == 0U) ? s.low : s.high;
      v = near.bits + (r.next() % 260U) - 130U;
    }
    const auto value_bytes = le(v); // kept alive: `in` is a view into it
    const auto in = std::span<const std::uint8_t>(value_bytes).first(w);
    const auto node = static_cast<std::uint8_t>(r.next() % 129U); // 0: any node
    CAPTURE(od::name(s.type));
    CAPTURE(v);
    CAPTURE(int{node});
    const od::value_check want = od::detail::check_any(e, identity, in, node);
    CHECK(od::check_value(e, identity, in, node) == want);
    CHECK(od::check_value<int64_limits>(e, identity, in, node) == want);
    if (w <= 4U) {
      CHECK(od::check_value<int32_limits>(e, identity, in, node) == want);
      ++narrow;
    } else if (s.low || s.high) { // limits of a wide integer: not for 32-bit comparisons
      CHECK(od::check_value<int32_limits>(e, identity, in, node) == od::value_check::invalid);
    } else { // every bit pattern is a value
      CHECK(od::check_value<int32_limits>(e, identity, in, node) == od::value_check::ok);
    }
  }
  CHECK(narrow > 50000);
}

TEST_CASE("check_value: which end, the type's rules, and what the code was not made for") {
  static constexpr od::entry_spec s[] = {
      {.index = 1,
       .type = data_type::unsigned8,
       .low = od::unsigned_number(10),
       .high = od::unsigned_number(20)},
      {.index = 2, .type = data_type::boolean},
      {.index = 3, .type = data_type::real32, .high = od::real_number(1.5)},
      {.index = 4,
       .type = data_type::unsigned16,
       .flags = od::flag::scaled,
       .high = od::unsigned_number(100)},
      {.index = 5, .type = data_type::time_of_day},
      {.index = 6, .type = data_type::visible_string, .size = 4},
      {.index = 7,
       .type = data_type::unsigned32,
       .flags = od::flag::high_nodeid,
       .high = od::unsigned_number(0x600)},
  };
  static constexpr auto e = od::entries_of<s>;
  using od::value_check;
  const std::array<std::uint8_t, 1> b9{9}, b10{10}, b20{20}, b21{21}, b2{2}, b1{1};
  CHECK(od::check_value(e[0], identity, b9) == value_check::too_low);
  CHECK(od::check_value(e[0], identity, b10) == value_check::ok);
  CHECK(od::check_value(e[0], identity, b20) == value_check::ok);
  CHECK(od::check_value(e[0], identity, b21) == value_check::too_high);
  CHECK(od::check_value<int32_limits>(e[0], identity, b21) == value_check::too_high);
  // code without limits refuses an entry with limits, rather than skip them
  CHECK(od::check_value<none>(e[0], identity, b10) == value_check::invalid);
  // the wrong number of bytes
  CHECK(od::check_value(e[0], identity, std::array<std::uint8_t, 2>{10, 0}) ==
        value_check::invalid);
  // BOOLEAN: 0 or 1, with any kinds
  CHECK(od::check_value<none>(e[1], identity, b1) == value_check::ok);
  CHECK(od::check_value<none>(e[1], identity, b2) == value_check::invalid);
  // REAL32: 1.5 ok, 2.0 too high, NaN invalid; without `real` it is refused
  const std::array<std::uint8_t, 4> f15{0x00, 0x00, 0xC0, 0x3F}, f2{0x00, 0x00, 0x00, 0x40},
      nan{0x00, 0x00, 0xC0, 0x7F};
  CHECK(od::check_value(e[2], identity, f15) == value_check::ok);
  CHECK(od::check_value(e[2], identity, f2) == value_check::too_high);
  CHECK(od::check_value(e[2], identity, nan) == value_check::invalid);
  CHECK(od::check_value<int64_limits>(e[2], identity, f15) == value_check::invalid);
  // scaled: the limits are engineering units (scale 10: raw 0..1000); out of them: invalid
  const fieldcodec::scaling::linear ten{{10, 0}, {0, 0}};
  CHECK(od::check_value(e[3], ten, std::array<std::uint8_t, 2>{0xE8, 0x03}) == value_check::ok);
  CHECK(od::check_value(e[3], ten, std::array<std::uint8_t, 2>{0xE9, 0x03}) ==
        value_check::invalid);
  CHECK(od::check_value<int64_limits>(e[3], ten, std::array<std::uint8_t, 2>{0, 0}) ==
        value_check::invalid);
  // TIME_OF_DAY: the 4 reserved bits of the milliseconds
  CHECK(od::check_value(e[4], identity, std::array<std::uint8_t, 6>{0, 0, 0, 0x0F, 0, 0}) ==
        value_check::ok);
  CHECK(od::check_value(e[4], identity, std::array<std::uint8_t, 6>{0, 0, 0, 0x10, 0, 0}) ==
        value_check::invalid);
  // byte strings are decode_bytes' business
  CHECK(od::check_value(e[5], identity, std::array<std::uint8_t, 0>{}) == value_check::invalid);
  // node-ID relative: 0x600 + node; any node: up to 0x67F
  const auto u32 = [](std::uint32_t v) {
    return std::array<std::uint8_t, 4>{
        static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8U),
        static_cast<std::uint8_t>(v >> 16U), static_cast<std::uint8_t>(v >> 24U)};
  };
  CHECK(od::check_value(e[6], identity, u32(0x605), 5) == value_check::ok);
  CHECK(od::check_value(e[6], identity, u32(0x606), 5) == value_check::too_high);
  CHECK(od::check_value(e[6], identity, u32(0x67F)) == value_check::ok);
  CHECK(od::check_value(e[6], identity, u32(0x680)) == value_check::too_high);
  CHECK(od::check_value<int32_limits>(e[6], identity, u32(0x606), 5) == value_check::too_high);
  constexpr od::value_kinds no_node = [] {
    auto k = int32_limits;
    k.node_limits = false;
    return k;
  }();
  CHECK(od::check_value<no_node>(e[6], identity, u32(0x600), 5) == value_check::invalid);
}
