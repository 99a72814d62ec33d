// The object store: O(1) layout, values in parts, staging (never half-visible), the write
// hook, strings and domains with their capacity, default text and written length.
#include "xorshift.hpp"

#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/dictionaries/xenax_ethercat.hpp>
#include <fieldcodec/dictionaries/xenax_powerlink.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
using fieldcodec::errc;
using sdo::abort_code;

namespace {
constexpr od::entry_spec entries_spec[] = {
    {.index = 0x1008,
     .type = od::data_type::visible_string,
     .access_type = od::access::constant,
     .size = 20,
     .default_text = "XENAX Xvi 75V8S"},
    {.index = 0x2000,
     .type = od::data_type::unsigned16,
     .default_value = od::unsigned_number(0x1234)},
    {.index = 0x2001, .type = od::data_type::domain, .size = 300},
    {.index = 0x2002,
     .type = od::data_type::integer8,
     .low = od::signed_number(-5),
     .high = od::signed_number(5)},
    {.index = 0x2003, .type = od::data_type::octet_string, .size = 4, .default_text = "too long"},
};
constexpr auto entries = od::entries_of<entries_spec>;
constexpr od::dictionary dict{entries};
constexpr auto layout = co::make_layout<std::size(entries)>(dict);

// The layout is computed at compile time: byte strings take a 4-byte length and their
// capacity, numbers their width.
static_assert(layout.offsets[0] == 0);
static_assert(layout.offsets[1] == 4 + 20);
static_assert(layout.offsets[2] == 24 + 2);
static_assert(layout.offsets[3] == 26 + 4 + 300);
static_assert(layout.offsets[4] == 330 + 1);
static_assert(layout.storage_size() == 331 + 4 + 4);
static_assert(layout.storage_size() == co::dictionary_store<>::storage_size(dict));

std::string_view text(std::span<const std::uint8_t> b) {
  return {reinterpret_cast<const char *>(b.data()), b.size()};
}

/// A hook that records what was written and refuses the value 3 for 2002h.
struct recorder {
  std::vector<od::address> *seen;
  abort_code operator()(const od::entry &e, std::span<const std::uint8_t> v) const {
    seen->push_back({e.index, e.sub});
    if (e.index == 0x2002 && v.size() == 1 && v[0] == 3)
      return abort_code::cannot_store_device_state;
    return abort_code::none;
  }
};
} // namespace

TEST_CASE("store: defaults, strings with their default text, reads in parts") {
  std::vector<std::uint8_t> storage(layout.storage_size());
  co::dictionary_store<> s{dict, layout, storage};
  // a default text longer than its capacity is cut and reported
  CHECK(s.init_defaults(5) == errc::too_long);
  CHECK(s.node() == 5);
  CHECK(text(s.value({0x1008, 0}).value()) == "XENAX Xvi 75V8S");
  CHECK(text(s.value({0x2003, 0}).value()) == "too ");
  CHECK(s.value({0x2001, 0}).value().empty()); // a domain without default: 0 bytes
  CHECK(s.value({0x2000, 0}).value()[0] == 0x34);
  CHECK(s.value({0x3000, 0}) == errc::unknown_object);
  // partial reads: offset + chunk, total is the value's length
  std::array<std::uint8_t, 4> out{};
  std::size_t total = 0;
  CHECK(s.read({0x1008, 0}, 6, out, total) == abort_code::none);
  CHECK(total == 15);
  CHECK(text(out) == "Xvi ");
  CHECK(s.read({0x1008, 0}, 13, out, total) == abort_code::none); // the last 2 bytes
  CHECK(out[0] == '8');
  CHECK(out[1] == 'S');
  CHECK(s.read({0x1008, 0}, 16, out, total) == abort_code::general_error);
  CHECK(s.read({0x1009, 0}, 0, out, total) == abort_code::no_object);
  CHECK(s.read({0x2000, 1}, 0, out, total) == abort_code::no_sub_index);
  // a storage too small for the layout
  std::vector<std::uint8_t> small(10);
  co::dictionary_store<> t{dict, layout, small};
  CHECK(t.init_defaults(5) == errc::buffer_too_small);
  CHECK(t.read({0x2000, 0}, 0, out, total) == abort_code::general_error);
}

TEST_CASE("store: writes in parts become visible only when complete") {
  std::vector<std::uint8_t> storage(layout.storage_size());
  std::vector<std::uint8_t> staging(300);
  co::dictionary_store<> s{dict, layout, storage, staging};
  (void)s.init_defaults(1);
  const std::array<std::uint8_t, 5> a{1, 2, 3, 4, 5};
  CHECK(s.begin_write({0x2001, 0}, 10) == abort_code::none);
  CHECK(s.write({0x2001, 0}, 0, a, false) == abort_code::none);
  CHECK(s.value({0x2001, 0}).value().empty()); // not yet
  CHECK(s.write({0x2001, 0}, 5, a, true) == abort_code::none);
  CHECK(s.value({0x2001, 0}).value().size() == 10);
  // parts out of order are refused; the value stays
  CHECK(s.write({0x2001, 0}, 0, a, false) == abort_code::none);
  CHECK(s.write({0x2001, 0}, 7, a, true) == abort_code::general_error);
  CHECK(s.value({0x2001, 0}).value().size() == 10);
  // a part beyond the capacity
  CHECK(s.begin_write({0x2001, 0}, 301) == abort_code::length_too_high);
  std::vector<std::uint8_t> big(299);
  CHECK(s.write({0x2001, 0}, 0, big, false) == abort_code::none);
  CHECK(s.write({0x2001, 0}, 299, a, true) == abort_code::length_too_high);
  // without a staging area, a value in parts is refused with out of memory
  std::vector<std::uint8_t> storage2(layout.storage_size());
  co::dictionary_store<> t{dict, layout, storage2};
  (void)t.init_defaults(1);
  CHECK(t.write({0x2001, 0}, 0, a, false) == abort_code::out_of_memory);
  CHECK(t.write({0x2001, 0}, 0, a, true) == abort_code::none); // one part: fine
  // begin_write checks access and length early
  CHECK(s.begin_write({0x1008, 0}, 3) == abort_code::write_read_only);
  CHECK(s.begin_write({0x2000, 0}, 3) == abort_code::length_too_high);
  CHECK(s.begin_write({0x2000, 0}, 1) == abort_code::length_too_low);
  CHECK(s.begin_write({0x2000, 0}, std::nullopt) == abort_code::none);
  CHECK(s.begin_write({0x2004, 0}, 1) == abort_code::no_object);
  // the application sets read-only objects and gets the same value checks
  const std::array<std::uint8_t, 3> abc{'a', 'b', 'c'};
  CHECK(s.set({0x1008, 0}, abc) == abort_code::none);
  CHECK(text(s.value({0x1008, 0}).value()) == "abc");
  const std::array<std::uint8_t, 1> bad{0x07};
  CHECK(s.set({0x1008, 0}, bad) == abort_code::invalid_value); // not a visible character
  const std::array<std::uint8_t, 1> nine{9};
  CHECK(s.set({0x2002, 0}, nine) == abort_code::value_too_high);
}

TEST_CASE("store: the write hook sees every SDO write and may refuse it") {
  std::vector<std::uint8_t> storage(layout.storage_size());
  std::vector<od::address> seen;
  co::dictionary_store<recorder> s{dict, layout, storage, {}, recorder{&seen}};
  (void)s.init_defaults(1);
  std::vector<std::uint8_t> buffer(64);
  sdo::server<co::dictionary_store<recorder>> srv(1, s, buffer);
  sdo::client c(1);
  auto talk = [&](sdo::step st) {
    for (int i = 0; i < 100 && !st.send.empty(); ++i) {
      auto r = srv.on_frame(st.send[0], 0);
      if (r.send.empty()) break;
      st = c.on_frame(r.send[0], 0);
    }
  };
  const std::array<std::uint8_t, 1> two{2}, three{3};
  talk(c.download({0x2002, 0}, two, 0).value());
  CHECK(c.state() == sdo::transfer_state::done);
  REQUIRE(seen.size() == 1);
  CHECK(seen[0] == od::address{0x2002, 0});
  talk(c.download({0x2002, 0}, three, 0).value());
  CHECK(c.state() == sdo::transfer_state::failed);
  CHECK(c.error() ==
        sdo::transfer_error{errc::aborted, abort_code::cannot_store_device_state, {0x2002, 0}});
  CHECK(s.value({0x2002, 0}).value()[0] == 2); // refused: the old value stays
  // a value the checks refuse never reaches the hook
  const std::array<std::uint8_t, 1> nine{9};
  talk(c.download({0x2002, 0}, nine, 0).value());
  CHECK(c.error()->abort == abort_code::value_too_high);
  CHECK(seen.size() == 2);
  // the application's own writes do not call the hook
  CHECK(s.set({0x2002, 0}, three) == abort_code::none);
  CHECK(seen.size() == 2);
}

TEST_CASE("server: an object larger than its buffer, through the store's staging") {
  std::vector<std::uint8_t> storage(layout.storage_size());
  std::vector<std::uint8_t> staging(300);
  co::dictionary_store<> s{dict, layout, storage, staging};
  (void)s.init_defaults(1);
  std::vector<std::uint8_t> buffer(16); // far smaller than the 300-byte domain
  sdo::server<co::dictionary_store<>> srv(1, s, buffer);
  sdo::client c(1);
  std::vector<std::uint8_t> v(300);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::uint8_t>(i * 7);
  auto talk = [&](sdo::step st) {
    std::size_t exchanges = 0;
    while (!st.send.empty() && exchanges < 1000) {
      ++exchanges;
      auto r = srv.on_frame(st.send[0], 0);
      if (r.send.empty()) break;
      st = c.on_frame(r.send[0], 0);
    }
  };
  talk(c.download({0x2001, 0}, v, 0).value());
  CHECK(c.state() == sdo::transfer_state::done);
  const auto stored = s.value({0x2001, 0}).value();
  CHECK(std::vector<std::uint8_t>(stored.begin(), stored.end()) == v);
  // and back, read from the store in parts of the buffer's size
  std::vector<std::uint8_t> back(400);
  talk(c.upload({0x2001, 0}, back, 0).value());
  CHECK(c.state() == sdo::transfer_state::done);
  CHECK(std::vector<std::uint8_t>(c.received().begin(), c.received().end()) == v);

  SUBCASE("a transfer that stops half-way leaves the old value") {
    std::vector<std::uint8_t> w(300, 0xEE);
    auto st = c.download({0x2001, 0}, w, 0).value();
    for (int i = 0; i < 20; ++i) { // 20 of 43 segments, then the client gives up
      auto r = srv.on_frame(st.send[0], 0);
      st = c.on_frame(r.send[0], 0);
    }
    (void)srv.on_frame(c.cancel().send[0], 0);
    CHECK(srv.state() == sdo::transfer_state::failed);
    const auto kept = s.value({0x2001, 0}).value();
    CHECK(std::vector<std::uint8_t>(kept.begin(), kept.end()) == v);
  }
}

// Issue 12 #1: every string object of the XENAX dictionaries (CANopen, EtherCAT, POWERLINK) is
// readable over SDO with its EDS default as the initial value, and writable where the dictionary
// says rw: a value up to the capacity is stored and read back with its length, one byte more is
// refused with 06070012h, a read-only string refuses every write with 06010002h. The capacity is
// the generated `entry.size`: the EDS's `Size=` (printed lengths, or fieldcodec's choice where
// the manual prints none, docs/xenax.md) or the default's length.
namespace {
struct sdo_pair {
  sdo::server<co::dictionary_store<>> &srv;
  sdo::client c{1};

  void talk(sdo::step st) {
    for (int i = 0; i < 200 && !st.send.empty(); ++i) {
      auto r = srv.on_frame(st.send[0], 0);
      if (r.send.empty()) break;
      st = c.on_frame(r.send[0], 0);
    }
  }
  std::string read(od::address a, std::size_t capacity) {
    std::vector<std::uint8_t> out(capacity + 8);
    talk(c.upload(a, out, 0).value());
    REQUIRE(c.state() == sdo::transfer_state::done);
    return std::string(text(c.received()));
  }
  abort_code write(od::address a, std::string_view v) {
    std::vector<std::uint8_t> in(v.begin(), v.end());
    talk(c.download(a, in, 0).value());
    if (c.state() == sdo::transfer_state::done) return abort_code::none;
    REQUIRE(c.error().has_value());
    return c.error()->abort;
  }
};

template <const auto &Dictionary>
void check_xenax_strings(std::size_t expected_strings) {
  constexpr auto xl = co::make_layout<Dictionary.size()>(Dictionary);
  std::vector<std::uint8_t> storage(xl.storage_size());
  co::dictionary_store<> s{Dictionary, xl, storage};
  REQUIRE(s.init_defaults(1).has_value());
  std::vector<std::uint8_t> buffer(256);
  sdo::server<co::dictionary_store<>> srv(1, s, buffer);
  sdo_pair p{srv};
  std::size_t strings = 0, writable = 0;
  for (const auto &e : Dictionary) {
    if (!od::is_byte_string(e.type)) continue;
    ++strings;
    CAPTURE(e.index);
    CAPTURE(e.sub);
    REQUIRE(e.capacity() > 0);
    REQUIRE(od::readable(e.access_type));
    const od::address a{e.index, e.sub};
    CHECK(e.default_text().size() <= e.capacity());
    CHECK(p.read(a, e.capacity()) == e.default_text());
    if (!od::writable(e.access_type)) {
      CHECK(p.write(a, "x") == abort_code::write_read_only);
      CHECK(p.read(a, e.capacity()) == e.default_text());
      continue;
    }
    ++writable;
    const std::string full(e.capacity(), 'Q');
    CHECK(p.write(a, full) == abort_code::none);
    CHECK(p.read(a, e.capacity()) == full);
    CHECK(p.write(a, "LX-44") == abort_code::none); // shorter: its own length, no padding
    CHECK(p.read(a, e.capacity()) == "LX-44");
    CHECK(p.write(a, full + "Q") == abort_code::length_too_high);
    CHECK(p.read(a, e.capacity()) == "LX-44"); // the refused write left the value
  }
  MESSAGE("XENAX strings: " << strings << ", writable: " << writable);
  CHECK(strings == expected_strings);
  CHECK(writable > 0);
}
} // namespace

TEST_CASE("XENAX dictionaries: every string is served with its default text and its capacity") {
  namespace dict = fieldcodec::dictionaries;
  // 1008h, 1009h, 100Ah, 2008h, 5011h, 5012h, 5020h, 5021h, 6505h
  SUBCASE("CANopen") { check_xenax_strings<dict::xenax_canopen::dictionary>(9); }
  SUBCASE("EtherCAT") { check_xenax_strings<dict::xenax_ethercat::dictionary>(9); }
  // and 1030h sub 2, 5, 6, 1F9Ah
  SUBCASE("POWERLINK") { check_xenax_strings<dict::xenax_powerlink::dictionary>(13); }
}

TEST_CASE("store: node-ID-relative limits and scaled limits (issue 12 #4, issue 14)") {
  // LowLimit = HighLimit = $NODEID+0x600: the server's own COB-ID and nothing else
  static constexpr std::array<od::entry_spec, 2> rel_spec{{
      {.index = 0x1200,
       .sub = 1,
       .object = od::object_code::record,
       .type = od::data_type::unsigned32,
       .flags = od::flag::low_nodeid | od::flag::high_nodeid | od::flag::default_nodeid,
       .low = od::unsigned_number(0x600),
       .high = od::unsigned_number(0x600),
       .default_value = od::unsigned_number(0x600)},
      // scaled: 0..100 % at scale 10 → raw 0..1000
      {.index = 0x2100,
       .type = od::data_type::unsigned16,
       .flags = od::flag::scaled,
       .low = od::signed_number(0),
       .high = od::signed_number(100)},
  }};
  static constexpr auto rel = od::entries_of<rel_spec>;
  static constexpr std::array<fieldcodec::scaling::linear, 2> scales{{{}, {{10, 0}, {0, 0}}}};
  static constexpr od::dictionary d{rel, {}, scales};
  static_assert(d.is_valid());
  constexpr auto l = co::make_layout<2>(d);
  std::vector<std::uint8_t> storage(l.storage_size());
  co::dictionary_store<> s{d, l, storage};
  REQUIRE(s.init_defaults(1) == fieldcodec::status{});
  CHECK(s.value({0x1200, 1}).value()[0] == 0x01); // default 0x601 stored: within its limits
  const std::array<std::uint8_t, 4> own{0x01, 0x06, 0, 0};
  const std::array<std::uint8_t, 4> other{0x02, 0x06, 0, 0};
  CHECK(s.set({0x1200, 1}, own) == abort_code::none);
  CHECK(s.set({0x1200, 1}, other) == abort_code::value_too_high);
  const std::array<std::uint8_t, 2> raw1000{0xE8, 0x03};
  const std::array<std::uint8_t, 2> raw1001{0xE9, 0x03};
  CHECK(s.set({0x2100, 0}, raw1000) == abort_code::none);
  CHECK(s.set({0x2100, 0}, raw1001) == abort_code::invalid_value); // scaled: no high/low code
}

namespace {
/// Random writes (whole values, every length around the width, random bytes) to every entry of
/// `Dictionary`, through a store made for the dictionary's own kinds and one made for all: the
/// same answers and the same stored values, after the same defaults.
template <const od::dictionary &Dictionary, od::value_kinds Kinds>
void check_same_as_all_kinds(std::uint64_t seed) {
  static_assert(od::covers(Kinds, od::kinds_of(Dictionary.entries())));
  constexpr auto layout_k = co::make_layout<Dictionary.size()>(Dictionary);
  // and the same with offsets of 16 bits (every dictionary here takes less than 64 kB)
  constexpr auto layout_16 = co::make_layout<Dictionary.size(), std::uint16_t>(Dictionary);
  static_assert(layout_16.storage_size() == layout_k.storage_size());
  std::vector<std::uint8_t> a(layout_k.storage_size()), b(layout_k.storage_size()),
      c(layout_k.storage_size());
  co::dictionary_store<co::accept_writes, Kinds> lean{Dictionary, layout_k, a};
  co::dictionary_store<> full{Dictionary, layout_k, b};
  co::dictionary_store<co::accept_writes, Kinds, std::uint16_t> narrow{Dictionary, layout_16, c};
  for (const std::uint8_t node : {std::uint8_t{1}, std::uint8_t{0x22}, std::uint8_t{127}}) {
    REQUIRE(lean.init_defaults(node) == full.init_defaults(node));
    REQUIRE(narrow.init_defaults(node) == full.init_defaults(node));
    CHECK(a == b);
    CHECK(c == b);
  }
  fieldcodec::test::xorshift r{seed};
  std::array<std::uint8_t, 16> v{};
  for (int n = 0; n < 30000; ++n) {
    const od::entry &e = Dictionary.entries()[r.next() % Dictionary.size()];
    for (auto &x : v) x = static_cast<std::uint8_t>(r.next());
    std::size_t len = e.width() + (r.next() % 3U) - 1U; // one short, exact, one long
    if (len > v.size()) len = r.next() % v.size();
    const auto value = std::span<const std::uint8_t>(v).first(len);
    const od::address at{e.index, e.sub};
    CAPTURE(e.index);
    CAPTURE(e.sub);
    CHECK(lean.write(at, 0, value, true) == full.write(at, 0, value, true));
    CHECK(lean.set(at, value) == full.set(at, value));
    CHECK(narrow.write(at, 0, value, true) == lean.write(at, 0, value, true));
    CHECK(narrow.set(at, value) == lean.set(at, value));
  }
  CHECK(a == b);
  CHECK(c == b);
}
} // namespace

TEST_CASE("store: made for the dictionary's kinds, it answers as the store for every kind") {
  namespace gen = fieldcodec::dictionaries;
  check_same_as_all_kinds<gen::xenax_canopen::dictionary, gen::xenax_canopen::kinds>(0x27A);
  check_same_as_all_kinds<gen::xenax_powerlink::dictionary, gen::xenax_powerlink::kinds>(0x27B);
  check_same_as_all_kinds<gen::dpq_parameters::dictionary, gen::dpq_parameters::kinds>(0x27C);
  check_same_as_all_kinds<dict, od::kinds_of(entries)>(0x27D);
}

namespace {
// Node-ID-relative limits and defaults near the ends of 8, 16 and 32-bit fields (a default that
// leaves its field for a high node stays zero; a limit past the field constrains nothing or
// everything), in a dictionary of integers only: a store made for it compares in 32 bits.
constexpr od::entry_spec relative_specs[] = {
    {.index = 0x1014,
     .type = od::data_type::unsigned32,
     .flags = od::flag::default_nodeid,
     .default_value = od::unsigned_number(0x80)},
    {.index = 0x2000,
     .type = od::data_type::unsigned8,
     .flags = od::flag::low_nodeid | od::flag::high_nodeid | od::flag::default_nodeid,
     .low = od::unsigned_number(0x80),
     .high = od::unsigned_number(0xF0),
     .default_value = od::unsigned_number(0x90)},
    {.index = 0x2001,
     .type = od::data_type::integer16,
     .flags = od::flag::high_nodeid | od::flag::default_nodeid,
     .high = od::signed_number(32700),
     .default_value = od::signed_number(32700)},
    {.index = 0x2002,
     .type = od::data_type::unsigned32,
     .flags = od::flag::low_nodeid,
     .low = od::unsigned_number(0xFFFF'FFF0U)},
    {.index = 0x2003,
     .type = od::data_type::integer32,
     .flags = od::flag::low_nodeid | od::flag::high_nodeid,
     .low = od::signed_number(-10),
     .high = od::signed_number(2147483600)},
    {.index = 0x2004, .type = od::data_type::boolean, .default_value = od::unsigned_number(1)},
};
constexpr od::dictionary relative_dict{od::entries_of<relative_specs>};
} // namespace

TEST_CASE("store: node-ID-relative limits and defaults in 32-bit comparisons, as for every kind") {
  static_assert(!od::kinds_of(relative_dict.entries()).wide &&
                !od::kinds_of(relative_dict.entries()).numbers);
  check_same_as_all_kinds<relative_dict, od::kinds_of(relative_dict.entries())>(0x27E);
  // the defaults for node 0x22: 0xA2, 32734 (0x7FDE), and 0x90 + 0x22 = 0xB2 within 0xA2..0x112
  constexpr auto l = co::make_layout<std::size(relative_specs)>(relative_dict);
  std::vector<std::uint8_t> storage(l.storage_size());
  co::dictionary_store<co::accept_writes, od::kinds_of(relative_dict.entries())> s{relative_dict, l,
                                                                                   storage};
  REQUIRE(s.init_defaults(0x22).has_value());
  CHECK(s.value({0x1014, 0}).value()[0] == 0xA2);
  CHECK(s.value({0x2000, 0}).value()[0] == 0xB2);
  CHECK(s.value({0x2001, 0}).value()[0] == 0xDE);
  CHECK(s.value({0x2004, 0}).value()[0] == 1);
  // node 127: 32700 + 127 leaves INTEGER16: the default stays zero
  REQUIRE(s.init_defaults(127).has_value());
  CHECK(s.value({0x2001, 0}).value()[0] == 0);
  CHECK(s.value({0x2001, 0}).value()[1] == 0);
  // 2002h: low 0xFFFFFFF0 + node lies beyond UNSIGNED32: every value is too low
  const std::array<std::uint8_t, 4> max{0xFF, 0xFF, 0xFF, 0xFF};
  CHECK(s.set({0x2002, 0}, max) == abort_code::value_too_low);
  // 2003h: high 2147483600 + 127 lies beyond INTEGER32: no value is too high
  CHECK(s.set({0x2003, 0}, std::array<std::uint8_t, 4>{0xFF, 0xFF, 0xFF, 0x7F}) ==
        abort_code::none);
  // and its low is -10 + 127 = 117 (75h)
  CHECK(s.set({0x2003, 0}, std::array<std::uint8_t, 4>{0x74, 0x00, 0x00, 0x00}) ==
        abort_code::value_too_low);
  CHECK(s.set({0x2003, 0}, std::array<std::uint8_t, 4>{0x75, 0x00, 0x00, 0x00}) ==
        abort_code::none);
}

namespace {
// values of 64 kB and more (1 + 4 + 0xFFFB bytes = 0x10000): no layout of 16-bit offsets; one
// byte less fits
constexpr od::entry_spec large_specs[] = {
    {.index = 0x2000, .type = od::data_type::unsigned8},
    {.index = 0x2001, .type = od::data_type::domain, .size = 0xFFFB},
};
constexpr od::dictionary large_dict{od::entries_of<large_specs>};
constexpr od::entry_spec fits_specs[] = {
    {.index = 0x2000, .type = od::data_type::unsigned8},
    {.index = 0x2001, .type = od::data_type::domain, .size = 0xFFFA},
};
constexpr od::dictionary fits_dict{od::entries_of<fits_specs>};
} // namespace

TEST_CASE("store: 16-bit offsets only for values of less than 64 kB") {
  constexpr auto wide = co::make_layout<2>(large_dict);
  static_assert(wide.storage_size() == 0x10000U);
  constexpr auto narrow = co::make_layout<2, std::uint16_t>(large_dict);
  static_assert(narrow.storage_size() == 0U); // left empty
  std::vector<std::uint8_t> storage(wide.storage_size());
  co::dictionary_store<co::accept_writes, od::all_kinds, std::uint16_t> s{large_dict, narrow,
                                                                          storage};
  CHECK(s.init_defaults(1) == errc::buffer_too_small);
  std::array<std::uint8_t, 1> out{};
  std::size_t total = 0;
  CHECK(s.read({0x2000, 0}, 0, out, total) == abort_code::general_error);
  // at run time: false, every offset zero
  std::array<std::uint16_t, 3> offsets{1, 2, 3};
  CHECK_FALSE(co::make_layout(large_dict, std::span<std::uint16_t>(offsets)));
  CHECK(offsets == std::array<std::uint16_t, 3>{});
  // one byte less fits
  constexpr auto last = co::make_layout<2, std::uint16_t>(fits_dict);
  static_assert(last.storage_size() == 0xFFFFU);
  std::vector<std::uint8_t> storage2(last.storage_size());
  co::dictionary_store<co::accept_writes, od::all_kinds, std::uint16_t> t{fits_dict, last,
                                                                          storage2};
  REQUIRE(t.init_defaults(1).has_value());
  REQUIRE(t.set({0x2000, 0}, std::array<std::uint8_t, 1>{7}) == abort_code::none);
  CHECK(t.value({0x2000, 0}).value()[0] == 7);
}

TEST_CASE("store: a layout made at run time (a dictionary loaded at run time)") {
  namespace x = fieldcodec::dictionaries::xenax_canopen;
  constexpr auto fixed = co::make_layout<x::entries.size()>(x::dictionary);
  std::vector<std::uint32_t> offsets(x::dictionary.size() + 1U);
  REQUIRE(co::make_layout(x::dictionary, offsets));
  CHECK(std::equal(offsets.begin(), offsets.end(), fixed.offsets.begin()));
  std::vector<std::uint32_t> wrong(x::dictionary.size());
  CHECK_FALSE(co::make_layout(x::dictionary, wrong)); // one short: nothing written
  CHECK(std::all_of(wrong.begin(), wrong.end(), [](std::uint32_t o) { return o == 0U; }));

  std::vector<std::uint8_t> storage(fixed.storage_size());
  co::dictionary_store<> store{x::dictionary, std::span<const std::uint32_t>(offsets), storage};
  REQUIRE(store.init_defaults(5));
  CHECK(store.value({0x1000, 0}).value().size() == 4U);
  REQUIRE(store.set({0x6073, 0}, std::array<std::uint8_t, 2>{150, 0}) == abort_code::none);
  CHECK(store.value({0x6073, 0}).value()[0] == 150);
  // offsets of another dictionary, or too little storage: the store does not fit
  offsets[1] += 1U;
  co::dictionary_store<> bad{x::dictionary, std::span<const std::uint32_t>(offsets), storage};
  CHECK(bad.init_defaults(5) == errc::buffer_too_small);
  offsets[1] -= 1U;
  std::vector<std::uint8_t> small(fixed.storage_size() - 1U);
  co::dictionary_store<> tight{x::dictionary, std::span<const std::uint32_t>(offsets), small};
  CHECK(tight.init_defaults(5) == errc::buffer_too_small);
}
