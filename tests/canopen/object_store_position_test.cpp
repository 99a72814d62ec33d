// The object store by position (co::positioned_store, issue 18 round 4): position() once, then
// read_at / write_at do what read / write of the address do; the slot flags a layout carries
// (access, byte string, "any bits valid") say what read() and write() would have found in the
// entry; and the writes that skip od::decode for "any bits valid" entries skip only what
// od::decode could not have refused.
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/value.hpp>

#include <doctest/doctest.h>

#include "xorshift.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
using fieldcodec::byte_order;
using sdo::abort_code;

namespace {

constexpr od::entry_spec scaled_u16() {
  od::entry_spec e{.index = 0x2007, .type = od::data_type::unsigned16};
  e.flags = od::flag::scaled;
  return e;
}

constexpr od::entry_spec entries_spec[] = {
    {.index = 0x1008,
     .type = od::data_type::visible_string,
     .access_type = od::access::constant,
     .size = 8,
     .default_text = "node"},
    {.index = 0x2000, .type = od::data_type::unsigned16},
    {.index = 0x2001, .type = od::data_type::integer32, .access_type = od::access::wo},
    {.index = 0x2002,
     .type = od::data_type::integer8,
     .low = od::signed_number(-5),
     .high = od::signed_number(5)},
    {.index = 0x2003, .type = od::data_type::boolean},
    {.index = 0x2004, .type = od::data_type::real32},
    {.index = 0x2005, .type = od::data_type::unsigned8, .access_type = od::access::ro},
    {.index = 0x2006, .type = od::data_type::octet_string, .size = 3},
    scaled_u16(),
    {.index = 0x2008, .type = od::data_type::integer24},
    {.index = 0x2009, .type = od::data_type::unsigned64},
    {.index = 0x200A, .type = od::data_type::time_of_day},
};
constexpr auto entries = od::entries_of<entries_spec>;
constexpr od::dictionary dict{entries};
constexpr auto layout = co::make_layout<std::size(entries)>(dict);

using co::slot_flag::any_bits;
using co::slot_flag::byte_string;
using co::slot_flag::readable;
using co::slot_flag::writable;
// what a store tests of each entry, at every access
static_assert(co::slot_flags(entries[0]) == (readable | byte_string));
static_assert(co::slot_flags(entries[1]) == (readable | writable | any_bits));
static_assert(co::slot_flags(entries[2]) == (writable | any_bits));
static_assert(co::slot_flags(entries[3]) == (readable | writable)); // limits: checked
static_assert(co::slot_flags(entries[4]) == (readable | writable)); // BOOLEAN: only 0 and 1
static_assert(co::slot_flags(entries[5]) == (readable | writable)); // REAL32: NaN refused
static_assert(co::slot_flags(entries[6]) == (readable | any_bits));
static_assert(co::slot_flags(entries[7]) == (readable | writable | byte_string));
static_assert(co::slot_flags(entries[8]) ==
              (readable | writable)); // scaled: its limits need the scale
static_assert(co::slot_flags(entries[9]) == (readable | writable | any_bits));
static_assert(co::slot_flags(entries[10]) == (readable | writable | any_bits));
static_assert(co::slot_flags(entries[11]) == (readable | writable)); // TIME_OF_DAY: reserved bits

struct rng : fieldcodec::test::xorshift {
  using xorshift::xorshift;
};

} // namespace

TEST_CASE("store by position: position, address_at, and no_position") {
  std::vector<std::uint8_t> storage(layout.storage_size());
  co::dictionary_store<> store{dict, layout, storage};
  for (std::size_t i = 0; i < std::size(entries); ++i) {
    const od::address a{entries[i].index, entries[i].sub};
    CHECK(store.position(a) == i);
    CHECK(store.address_at(i) == a);
  }
  CHECK(store.position({0x2000, 1}) == co::no_position);
  CHECK(store.position({0x3000, 0}) == co::no_position);
  std::array<std::uint8_t, 4> out{};
  std::size_t total = 0;
  CHECK(store.read_at(co::no_position, 0, out, total) == abort_code::no_object);
  CHECK(store.read_at(std::size(entries), 0, out, total) == abort_code::no_object);
  CHECK(store.write_at(co::no_position, 0, out, true) == abort_code::no_object);
  // a store whose storage does not fit its layout answers general_error, by position as well
  std::vector<std::uint8_t> small(4);
  co::dictionary_store<> broken{dict, layout, small};
  CHECK(broken.read_at(1, 0, out, total) == abort_code::general_error);
  CHECK(broken.write_at(1, 0, std::span<const std::uint8_t>(out).first(2), true) ==
        abort_code::general_error);
}

TEST_CASE("store: a layout whose slots are not the entries' does not fit") {
  // a layout of another dictionary with as many entries (a hand-made one, a stale one): refused
  // as a whole, rather than a slot too small for its value
  auto shifted = layout;
  for (std::size_t i = 2; i < shifted.offsets.size(); ++i)
    shifted.offsets[i] += 1; // 2000h: 3 bytes
  std::vector<std::uint8_t> storage(shifted.storage_size());
  co::dictionary_store<> store{dict, shifted, storage};
  CHECK(store.init_defaults(3).error() == fieldcodec::errc::buffer_too_small);
  std::array<std::uint8_t, 4> out{};
  std::size_t total = 0;
  CHECK(store.read({0x2000, 0}, 0, out, total) == abort_code::general_error);
  CHECK(store.write({0x2000, 0}, 0, std::span<const std::uint8_t>(out).first(2), true) ==
        abort_code::general_error);
  // offsets that go backwards
  auto backwards = layout;
  backwards.offsets[2] = backwards.offsets[1] - 1U;
  co::dictionary_store<> store2{dict, backwards, storage};
  CHECK(store2.read({0x2000, 0}, 0, out, total) == abort_code::general_error);
  // a dictionary with a kind of value the store is not made for (an integer-only store and a
  // dictionary with REAL32, limits, a scale and strings): refused the same way
  using integers_only =
      co::dictionary_store<co::accept_writes, od::value_kinds{.strings = false,
                                                              .real = false,
                                                              .time = false,
                                                              .wide = false,
                                                              .limits = false,
                                                              .node_limits = false,
                                                              .scaled = false,
                                                              .numbers = false}>;
  integers_only narrow{dict, layout, storage};
  CHECK(narrow.read({0x2000, 0}, 0, out, total) == abort_code::general_error);
  CHECK(narrow.init_defaults(3).error() == fieldcodec::errc::buffer_too_small);
  // the kinds of this dictionary exactly: it fits
  co::dictionary_store<co::accept_writes, od::kinds_of(entries)> exact{dict, layout, storage};
  CHECK(exact.init_defaults(3).has_value());
  // make_layout's own layout fits
  co::dictionary_store<> good{dict, layout, storage};
  CHECK(good.init_defaults(3).has_value());
}

TEST_CASE("store by position: read_at / write_at == read / write, random values and parts") {
  std::vector<std::uint8_t> s1(layout.storage_size());
  std::vector<std::uint8_t> s2(layout.storage_size());
  std::array<std::uint8_t, 8> staging1{};
  std::array<std::uint8_t, 8> staging2{};
  co::dictionary_store<> by_address{dict, layout, s1, staging1};
  co::dictionary_store<> by_position{dict, layout, s2, staging2};
  REQUIRE(by_address.init_defaults(3).has_value());
  REQUIRE(by_position.init_defaults(3).has_value());
  rng r{0x5eed};
  std::size_t accepted = 0;
  std::size_t refused = 0;
  for (int round = 0; round < 20000; ++round) {
    const std::size_t i = r.next() % std::size(entries);
    const od::address a{entries[i].index, entries[i].sub};
    std::array<std::uint8_t, 9> v{};
    for (auto &b : v) b = static_cast<std::uint8_t>(r.next());
    if (r.next() % 3U == 0U) v[0] = static_cast<std::uint8_t>(v[0] & 1U); // valid BOOLEANs too
    const std::size_t n = r.next() % 10U;
    const auto value = std::span<const std::uint8_t>(v).first(n);
    if (r.next() % 4U == 0U && n >= 2U) { // in two parts, through the staging area
      const std::size_t half = n / 2U;
      CHECK(by_address.write(a, 0, value.first(half), false) ==
            by_position.write_at(i, 0, value.first(half), false));
      const auto c1 = by_address.write(a, half, value.subspan(half), true);
      CHECK(c1 == by_position.write_at(i, half, value.subspan(half), true));
      ++(c1 == abort_code::none ? accepted : refused);
    } else {
      const auto c1 = by_address.write(a, 0, value, true);
      CHECK(c1 == by_position.write_at(i, 0, value, true));
      ++(c1 == abort_code::none ? accepted : refused);
    }
    const std::size_t offset = r.next() % 3U;
    std::array<std::uint8_t, 9> o1{};
    std::array<std::uint8_t, 9> o2{};
    std::size_t t1 = 99;
    std::size_t t2 = 99;
    const std::size_t size = r.next() % 10U;
    CHECK(by_address.read(a, offset, std::span<std::uint8_t>(o1).first(size), t1) ==
          by_position.read_at(i, offset, std::span<std::uint8_t>(o2).first(size), t2));
    CHECK(o1 == o2);
    CHECK(t1 == t2);
    CHECK(s1 == s2);
  }
  CHECK(accepted > 1000U);
  CHECK(refused > 1000U);
}

TEST_CASE("store: an 'any bits' entry takes every value od::decode takes, without asking it") {
  // the premise of skipping od::decode: for these entries it accepts every bit pattern of the
  // right length (integers of each width, signed and unsigned, no limits, no scale)
  rng r{42};
  std::size_t checked = 0;
  for (const auto &e : fieldcodec::dictionaries::xenax_canopen::dictionary) {
    if ((co::slot_flags(e) & any_bits) == 0U) continue;
    for (int k = 0; k < 64; ++k) {
      std::array<std::uint8_t, 8> v{};
      for (auto &b : v) b = static_cast<std::uint8_t>(r.next());
      if (k == 0) v.fill(0xFF);
      if (k == 1) v.fill(0x00);
      const auto bytes = std::span<const std::uint8_t>(v).first(e.width());
      CHECK(od::decode(e, bytes, byte_order::little, od::limits::check, 1).has_value());
      CHECK(od::decode(e, bytes, byte_order::little, od::limits::check, od::any_node).has_value());
      ++checked;
    }
  }
  CHECK(checked > 64U * 20U);
  // and the store checks the others as before: limits, BOOLEAN, NaN
  std::vector<std::uint8_t> storage(layout.storage_size());
  co::dictionary_store<> store{dict, layout, storage};
  REQUIRE(store.init_defaults(1).has_value());
  CHECK(store.write_at(3, 0, std::array<std::uint8_t, 1>{6}, true) == abort_code::value_too_high);
  CHECK(store.write_at(4, 0, std::array<std::uint8_t, 1>{2}, true) == abort_code::invalid_value);
  CHECK(store.write_at(5, 0, std::array<std::uint8_t, 4>{0, 0, 0xC0, 0x7F}, true) ==
        abort_code::invalid_value);
  CHECK(store.write_at(1, 0, std::array<std::uint8_t, 2>{0xFF, 0xFF}, true) == abort_code::none);
  CHECK(store.write_at(1, 0, std::array<std::uint8_t, 3>{1, 2, 3}, true) ==
        abort_code::length_too_high);
  CHECK(store.write_at(1, 0, std::array<std::uint8_t, 1>{1}, true) == abort_code::length_too_low);
  CHECK(store.write_at(6, 0, std::array<std::uint8_t, 1>{1}, true) == abort_code::write_read_only);
  std::array<std::uint8_t, 4> out{};
  std::size_t total = 0;
  CHECK(store.read_at(2, 0, out, total) == abort_code::read_write_only);
}

namespace {
/// A write hook that takes every value (but is not accept_writes: the store must ask it).
struct counting_hook {
  std::size_t *calls = nullptr;
  [[nodiscard]] constexpr abort_code operator()(const od::entry &,
                                                std::span<const std::uint8_t>) const noexcept {
    ++*calls;
    return abort_code::none;
  }
};
} // namespace

TEST_CASE("store plain_at: which values are plain, and that they are what read_at / write_at "
          "copy") {
  // (co::plain_store, round 5: the PDO engine copies plain values between storage and frames)
  std::vector<std::uint8_t> storage(layout.storage_size());
  co::dictionary_store<> store{dict, layout, storage};
  REQUIRE(store.init_defaults(3).has_value());
  std::size_t calls = 0;
  std::vector<std::uint8_t> hooked_storage(layout.storage_size());
  co::dictionary_store<counting_hook> hooked{
      dict, layout, hooked_storage, {}, counting_hook{&calls}};
  REQUIRE(hooked.init_defaults(3).has_value());
  CHECK(store.plain_storage().data() == storage.data());
  CHECK(store.plain_storage().size() == storage.size());
  // {offset, size, readable, writable} for each entry of the table above
  const std::array<co::plain_slot, std::size(entries)> expected{{
      {0, 0, false, false},                 // VISIBLE_STRING: a length, not plain
      {layout.offsets[1], 2, true, true},   // u16
      {layout.offsets[2], 4, false, true},  // i32 write-only
      {layout.offsets[3], 1, true, false},  // limits: written with a check
      {layout.offsets[4], 1, true, false},  // BOOLEAN: 0 and 1 only
      {layout.offsets[5], 4, true, false},  // REAL32: NaN refused
      {layout.offsets[6], 1, true, false},  // read-only
      {0, 0, false, false},                 // OCTET_STRING
      {layout.offsets[8], 2, true, false},  // scaled
      {layout.offsets[9], 3, true, true},   // INTEGER24
      {layout.offsets[10], 8, true, true},  // u64
      {layout.offsets[11], 6, true, false}, // TIME_OF_DAY
  }};
  for (std::size_t i = 0; i < std::size(entries); ++i) {
    CAPTURE(i);
    CHECK(store.plain_at(i) == expected[i]);
    // with a write hook nothing is written by a copy: the hook must see every value
    co::plain_slot h = expected[i];
    h.writable = false;
    CHECK(hooked.plain_at(i) == h);
  }
  CHECK(store.plain_at(co::no_position) == co::plain_slot{});
  CHECK(store.plain_at(std::size(entries)) == co::plain_slot{});
  std::vector<std::uint8_t> small(4);
  co::dictionary_store<> broken{dict, layout, small};
  CHECK(broken.plain_at(1) == co::plain_slot{});

  // the promise: a readable slot holds the bytes read_at copies (CANopen order on every host);
  // write_at of a writable slot's size stores the bytes there as they are and takes any value
  rng r{0x5EED'0005ULL};
  for (int round = 0; round < 2000; ++round) {
    const std::size_t i = r.next() % std::size(entries);
    const co::plain_slot p = store.plain_at(i);
    if (p.size == 0U) continue;
    std::array<std::uint8_t, 8> v{};
    for (auto &b : v) b = static_cast<std::uint8_t>(r.next());
    const auto value = std::span<const std::uint8_t>(v).first(p.size);
    const auto slot = std::span<const std::uint8_t>(storage).subspan(p.offset, p.size);
    if (p.writable) {
      REQUIRE(store.write_at(i, 0, value, true) == abort_code::none);
      CHECK(std::equal(slot.begin(), slot.end(), value.begin()));
      const std::size_t before = calls;
      CHECK(hooked.write_at(i, 0, value, true) == abort_code::none);
      CHECK(calls == before + 1U); // the hooked store asked its hook
    } else if (store.set(store.address_at(i), value) != abort_code::none) {
      continue; // a value the entry refuses (limits, BOOLEAN, NaN)
    }
    if (p.readable) {
      std::array<std::uint8_t, 8> out{};
      std::size_t total = 0;
      REQUIRE(store.read_at(i, 0, std::span<std::uint8_t>(out).first(p.size), total) ==
              abort_code::none);
      CHECK(total == p.size);
      CHECK(std::equal(slot.begin(), slot.end(), out.begin()));
      // and the number in it, read little-endian, is the value's
      CHECK(fieldcodec::load_unsigned(slot, p.size, byte_order::little).value() ==
            fieldcodec::load_unsigned(value, p.size, byte_order::little).value());
    }
  }
}
