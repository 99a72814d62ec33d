// od/engineering.hpp and od/value_text.hpp: the one checked path from a value a person means
// (or types) to an entry's bytes and back (issue 26, section 1).
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/od/engineering.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/value_text.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace od = fieldcodec::od;
using fieldcodec::errc;
namespace dpq = fieldcodec::dictionaries::dpq_parameters;

namespace {

using bytes = std::vector<std::uint8_t>;

// The descriptor of `s`; its packed columns stay alive for the whole test run.
od::descriptor described(const od::entry_spec &s) {
  static std::deque<std::string> kept;
  std::string &b = kept.emplace_back(od::packed_size(s), '\0');
  REQUIRE(od::pack(s, std::span<char>(b.data(), b.size())));
  return od::descriptor{od::make_entry(s, b.data())};
}

struct parsed {
  bool ok = false;
  bytes value;
  od::value_error error{};
};

parsed parse(const od::descriptor &d, std::string_view text, od::value_options o = {}) {
  std::array<std::uint8_t, 256> out{};
  auto r = od::parse_value(d, text, out, o);
  parsed p;
  if (r) {
    p.ok = true;
    p.value.assign(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(r.value()));
  } else {
    p.error = r.error();
  }
  return p;
}

std::string format(const od::descriptor &d, const bytes &in, od::value_options o = {}) {
  std::array<char, 600> out{};
  auto r = od::format_value(d, in, out, o);
  if (!r) return "<" + std::string(fieldcodec::to_string(r.error())) + ">";
  return std::string(out.data(), r.value());
}

// constexpr: the integer, scaled and string paths run in a constant expression
constexpr std::size_t parsed_size(const od::descriptor &d, std::string_view text,
                                  od::value_options o = {}) {
  std::array<std::uint8_t, 16> out{};
  auto r = od::parse_value(d, text, out, o);
  return r ? r.value() : 0U;
}
constexpr std::int64_t parsed_raw(const od::descriptor &d, std::string_view text,
                                  od::value_options o = {}) {
  std::array<std::uint8_t, 16> out{};
  auto r = od::parse_value(d, text, out, o);
  if (!r) return -1;
  return fieldcodec::load_signed(std::span<const std::uint8_t>(out.data(), r.value()),
                                 static_cast<unsigned>(r.value()), fieldcodec::byte_order::little)
      .value_or(-1);
}
constexpr od::value_error parse_error(const od::descriptor &d, std::string_view text,
                                      od::value_options o = {}) {
  std::array<std::uint8_t, 16> out{};
  auto r = od::parse_value(d, text, out, o);
  return r ? od::value_error{} : r.error();
}

// DPQ manual RE 30146-02-Z, 3.3: Inj. P Limit 1, 4.0 at scale 327.67 → 1311 (0x051F)
static_assert(parsed_raw(dpq::inj_p_limit_1, "4.0") == 1311);
static_assert(parsed_raw(dpq::inj_p_limit_1, "4") == 1311);
static_assert(parsed_raw(dpq::inj_p_limit_1, "4.001") == 1311);
static_assert(parsed_size(dpq::inj_p_limit_1, "4.0") == 4);
// the printed range 0…5000 (engineering units), refused with the limit named
static_assert(parse_error(dpq::inj_p_limit_1, "6000").issue == od::value_issue::high_limit);
static_assert(parse_error(dpq::inj_p_limit_1, "6000").limit.to_int64().value() == 5000);
static_assert(parse_error(dpq::inj_p_limit_1, "-0.01").issue == od::value_issue::low_limit);
// hex is a raw spelling: refused in engineering units, taken with value_unit::raw
static_assert(parse_error(dpq::inj_p_limit_1, "0x10").issue == od::value_issue::hex_is_raw);
static_assert(parsed_raw(dpq::inj_p_limit_1, "0x10", {.unit = od::value_unit::raw}) == 16);
static_assert(parsed_raw(dpq::inj_p_limit_1, "16", {.unit = od::value_unit::raw}) == 16);
static_assert(parsed_raw(dpq::inj_p_limit_1, "16") == 5243); // 16 × 327.67 = 5242.72

} // namespace

namespace docs_block {
namespace dpq = fieldcodec::dictionaries::dpq_parameters;
namespace od = fieldcodec::od;

constexpr std::array<std::uint8_t, 4> inj_p_limit_1_bytes(std::string_view text,
                                                          od::value_options o = {}) {
  std::array<std::uint8_t, 4> out{};
  auto n = od::parse_value(dpq::inj_p_limit_1, text, out, o);
  return n ? out : std::array<std::uint8_t, 4>{0xEE, 0xEE, 0xEE, 0xEE};
}
// 4.0 (engineering units, scale 327.67) → raw 1311 → 1F 05 00 00 (DPQ manual, 3.3)
static_assert(inj_p_limit_1_bytes("4.0") == std::array<std::uint8_t, 4>{0x1F, 0x05, 0x00, 0x00});
// hex spells a raw value: refused in engineering units, taken with value_unit::raw
static_assert(inj_p_limit_1_bytes("0x10")[0] == 0xEE);
static_assert(inj_p_limit_1_bytes("0x10", {.unit = od::value_unit::raw})[0] == 0x10);
// 6000 is above the printed maximum 5000: refused, nothing written
static_assert(inj_p_limit_1_bytes("6000")[0] == 0xEE);
} // namespace docs_block

TEST_CASE("od value text: a scaled DPQ parameter in engineering units and raw") {
  const auto &d = dpq::inj_p_limit_1;
  CHECK(od::eu_places(d).value() == 3);
  auto p = parse(d, "4.0");
  REQUIRE(p.ok);
  CHECK(p.value == bytes{0x1F, 0x05, 0x00, 0x00});
  CHECK(format(d, p.value) == "4.001");
  CHECK(parse(d, format(d, p.value)).value == p.value);
  CHECK(format(d, p.value, {.unit = od::value_unit::raw}) == "1311");
  CHECK(format(d, p.value, {.unit = od::value_unit::raw, .integers = od::radix::hex}) ==
        "0x0000051F");
  // 6000 is above 5000: refused, nothing sent
  p = parse(d, "6000");
  CHECK_FALSE(p.ok);
  CHECK(p.error.code == errc::out_of_range);
  CHECK(p.error.issue == od::value_issue::high_limit);
  CHECK(p.error.limit.to_int64().value() == 5000);
  // the same limit in raw units: round(5000 × 327.67) = 1638350
  p = parse(d, "1638351", {.unit = od::value_unit::raw});
  CHECK(p.error.issue == od::value_issue::high_limit);
  CHECK(p.error.limit == od::unsigned_number(1638350));
  CHECK(parse(d, "1638350", {.unit = od::value_unit::raw}).ok);
  // a spelling never changes the meaning: "0x10" is refused, not taken as raw 16
  p = parse(d, "0x10");
  CHECK(p.error.code == errc::bad_syntax);
  CHECK(p.error.issue == od::value_issue::hex_is_raw);
  CHECK(parse(d, "0x10", {.unit = od::value_unit::raw}).value == bytes{0x10, 0, 0, 0});
  CHECK(parse(d, "abc").error.issue == od::value_issue::syntax);
  CHECK(parse(d, "").error.code == errc::bad_syntax);
}

TEST_CASE("od value text: a unit after the number; raw values of a scaled entry have none") {
  // a XENAX-style unit: 10 mA per raw step (raw = EU × 0.1), limits 0…20000 mA
  od::descriptor d = described({.index = 0x6073,
                                .type = od::data_type::unsigned16,
                                .flags = od::flag::scaled,
                                .low = od::signed_number(0),
                                .high = od::signed_number(20000)});
  d.info.unit = "mA";
  d.scale = {{1, 1}, {0, 0}};
  CHECK(format(d, {0x96, 0x00}) == "1500 mA");
  CHECK(format(d, {0x96, 0x00}, {.unit_suffix = false}) == "1500");
  CHECK(format(d, {0x96, 0x00}, {.unit = od::value_unit::raw}) == "150");
  CHECK(parse(d, "1500 mA").value == bytes{0x96, 0x00});
  CHECK(parse(d, "1500mA").value == bytes{0x96, 0x00});
  CHECK(parse(d, "1500").value == bytes{0x96, 0x00});
  CHECK(parse(d, "1505").value == bytes{0x97, 0x00}); // 150.5 → 151, half away from zero
  CHECK(parse(d, "150", {.unit = od::value_unit::raw}).value == bytes{0x96, 0x00});
  auto p = parse(d, "1500 A");
  CHECK(p.error.issue == od::value_issue::unit);
  CHECK(p.error.position == 5);
  CHECK(parse(d, "150 mA", {.unit = od::value_unit::raw}).error.issue == od::value_issue::unit);
  p = parse(d, "20010");
  CHECK(p.error.issue == od::value_issue::high_limit);
  CHECK(p.error.limit.to_int64().value() == 20000);
}

TEST_CASE("od value text: integers, hex with the same meaning, limits, fields") {
  namespace x = fieldcodec::dictionaries::xenax_canopen;
  const od::descriptor limit = x::dictionary.at({0x6073, 0}).value(); // raw 0…0x7D0
  CHECK(parse(limit, "2000").value == bytes{0xD0, 0x07});
  CHECK(parse(limit, "0x7D0").value == bytes{0xD0, 0x07});
  auto p = parse(limit, "2001");
  CHECK(p.error.issue == od::value_issue::high_limit);
  CHECK(p.error.limit == od::unsigned_number(0x7D0));
  const od::descriptor speed = x::dictionary.at({0x6081, 0}).value(); // low 0xA
  p = parse(speed, "5");
  CHECK(p.error.issue == od::value_issue::low_limit);
  CHECK(p.error.limit == od::unsigned_number(10));
  const od::descriptor target = x::dictionary.at({0x607A, 0}).value();
  CHECK(parse(target, "-20000").value == bytes{0xE0, 0xB1, 0xFF, 0xFF});
  CHECK(format(target, {0xE0, 0xB1, 0xFF, 0xFF}) == "-20000");
  CHECK(parse(target, "-20000.0").ok);
  CHECK(parse(target, "1.5").error.issue == od::value_issue::not_integer);
  // 0xFFFFFFFF is 4294967295, never -1: above the high limit 0x7FFFFFFF of the EDS
  CHECK(parse(target, "0xFFFFFFFF").error.issue == od::value_issue::high_limit);
  od::descriptor i32{}; // no limits: the field refuses it
  i32.type = od::data_type::integer32;
  CHECK(parse(i32, "0xFFFFFFFF").error.issue == od::value_issue::field);
  CHECK(parse(i32, "2147483648").error.issue == od::value_issue::field);
  CHECK(parse(i32, "-2147483648").value == bytes{0, 0, 0, 0x80});
  const od::descriptor vendor = x::dictionary.at({0x1018, 1}).value();
  CHECK(format(vendor, {0x2E, 0x01, 0, 0}, {.integers = od::radix::hex}) == "0x0000012E");
  CHECK(parse(vendor, "0x0000012E").value == bytes{0x2E, 0x01, 0, 0});
  CHECK(parse(vendor, "0x12e").value == bytes{0x2E, 0x01, 0, 0});
  CHECK(parse(vendor, "-0x1").error.code == errc::bad_digit);
  // UNSIGNED64 beyond 18 digits
  od::descriptor u64{};
  u64.type = od::data_type::unsigned64;
  CHECK(parse(u64, "18446744073709551615").value == bytes(8, 0xFF));
  CHECK(format(u64, bytes(8, 0xFF)) == "18446744073709551615");
  CHECK(parse(u64, "18446744073709551616").error.code == errc::overflow);
}

TEST_CASE("od value text: node-ID-relative limits are the target node's") {
  const od::descriptor d = described({.index = 0x1400,
                                      .sub = 1,
                                      .type = od::data_type::unsigned32,
                                      .flags = od::flag::low_nodeid | od::flag::high_nodeid,
                                      .low = od::unsigned_number(0x200),
                                      .high = od::unsigned_number(0x200)});
  CHECK(parse(d, "0x205", {.node = 5}).ok);
  auto p = parse(d, "0x206", {.node = 5});
  CHECK(p.error.issue == od::value_issue::high_limit);
  CHECK(p.error.limit == od::unsigned_number(0x205));
  CHECK(parse(d, "0x206", {.node = 6}).ok);
  CHECK(parse(d, "0x206").ok); // any node: 0x201…0x27F
}

TEST_CASE("od value text: strings, capacity and characters") {
  od::descriptor s =
      described({.index = 0x5011, .type = od::data_type::visible_string, .size = 30});
  CHECK(parse(s, "LINAX").value == bytes{'L', 'I', 'N', 'A', 'X'});
  CHECK(parse(s, "\"LINAX\"").value == bytes{'L', 'I', 'N', 'A', 'X'});
  CHECK(format(s, {'L', 'I', 'N', 'A', 'X', 0, 0}) == "\"LINAX\""); // NUL padding dropped
  auto p = parse(s, std::string(31, 'x'));
  CHECK(p.error.code == errc::too_long);
  CHECK(p.error.issue == od::value_issue::capacity);
  CHECK(p.error.capacity == 30);
  CHECK(parse(s, std::string(30, 'x')).ok);
  p = parse(s, "caf\xC3\xA9");
  CHECK(p.error.code == errc::bad_character);
  CHECK(p.error.position == 3);
  p = parse(s, "a\tb");
  CHECK(p.error.issue == od::value_issue::character);
  // escapes: what format prints, parse takes back
  const bytes odd = {'a', '"', 'b', '\\', 0x01, 0xFF};
  CHECK(format(s, odd) == "\"a\\\"b\\\\\\x01\\xFF\"");
  CHECK(parse(s, "\"a\\\"b\\\\\"").value == bytes{'a', '"', 'b', '\\'});
  CHECK(parse(s, "\"a\\x01\"").error.issue == od::value_issue::character); // not visible
  CHECK(parse(s, "\"abc").error.issue == od::value_issue::syntax);
  CHECK(parse(s, "\"a\\qb\"").error.issue == od::value_issue::syntax);
  // reading never applies the capacity
  CHECK(format(s, bytes(40, 'y')) == "\"" + std::string(40, 'y') + "\"");

  od::descriptor o{};
  o.type = od::data_type::octet_string;
  CHECK(format(o, {0x2B, 0x00, 0x18}) == "2B 00 18");
  CHECK(parse(o, "2B 00 18").value == bytes{0x2B, 0x00, 0x18});
  CHECK(parse(o, "2b0018").value == bytes{0x2B, 0x00, 0x18});
  CHECK(parse(o, "2B:00.18").value == bytes{0x2B, 0x00, 0x18});
  CHECK(format(o, {}) == "\"\"");
  CHECK(parse(o, "\"\"").value.empty());
  CHECK(parse(o, "\"AB\"").value == bytes{'A', 'B'});
  CHECK(parse(o, "2B0").error.code == errc::truncated);
  CHECK(parse(o, "2G").error.code == errc::bad_digit);

  od::descriptor u{};
  u.type = od::data_type::unicode_string;
  CHECK(parse(u, "A\xC3\xA9").value == bytes{'A', 0, 0xE9, 0});
  CHECK(format(u, {'A', 0, 0xE9, 0}) == "\"A\\u00E9\"");
  CHECK(parse(u, "\"A\\u00E9\"").value == bytes{'A', 0, 0xE9, 0});
  CHECK(parse(u, "\xFF").error.issue == od::value_issue::character);
  CHECK(format(u, {'A'}) == "<bad length>");
}

TEST_CASE("od value text: REAL, BOOLEAN, TIME") {
  od::descriptor f{};
  f.type = od::data_type::real32;
  auto p = parse(f, "0.1");
  REQUIRE(p.ok);
  CHECK(format(f, p.value) == "0.1");
  CHECK(parse(f, "1e39").error.code == errc::overflow);
  CHECK(parse(f, "0x10").error.code == errc::bad_syntax);
  CHECK(parse(f, "1.5 V").error.issue == od::value_issue::unit);
  f.info.unit = "V";
  CHECK(format(f, parse(f, "1.5 V").value) == "1.5 V");
  const od::entry_info unit_v = f.info;
  f = described({.type = od::data_type::real32,
                 .low = od::real_number(-10.0),
                 .high = od::real_number(10.0)});
  f.info = unit_v;
  CHECK(parse(f, "10.5").error.issue == od::value_issue::high_limit);
  od::descriptor g{};
  g.type = od::data_type::real64;
  p = parse(g, "0.30000000000000004");
  REQUIRE(p.ok);
  CHECK(format(g, p.value) == "0.30000000000000004");

  od::descriptor b{};
  b.type = od::data_type::boolean;
  CHECK(format(b, {1}) == "true");
  CHECK(parse(b, "true").value == bytes{1});
  CHECK(parse(b, "0").value == bytes{0});
  CHECK(parse(b, "yes").error.code == errc::bad_syntax);

  od::descriptor t{};
  t.type = od::data_type::time_of_day;
  // 2024-05-01 is day 14731 after 1984-01-01; 12:34:56.789 = 45296789 ms
  const bytes when = {0x95, 0x2C, 0xB3, 0x02, 0x8B, 0x39};
  CHECK(format(t, when) == "2024-05-01T12:34:56.789");
  CHECK(parse(t, "2024-05-01T12:34:56.789").value == when);
  CHECK(parse(t, "2024-05-01 12:34:56.789").value == when);
  CHECK(parse(t, "1983-12-31T00:00:00").error.code == errc::out_of_range);
  CHECK(parse(t, "2024-02-30T00:00:00").error.code == errc::out_of_range);
  od::descriptor dt{};
  dt.type = od::data_type::time_difference;
  CHECK(format(dt, {0x04, 0x00, 0x00, 0x00, 0x03, 0x00}) == "3d 00:00:00.004");
  CHECK(parse(dt, "3d 00:00:00.004").value == bytes{0x04, 0x00, 0x00, 0x00, 0x03, 0x00});
}
