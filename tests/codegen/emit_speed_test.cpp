// The header emitter of issue 18's second round (one reserved string written through a pointer,
// names built in place, symbols in an open-addressing set) changes no output: it is compared
// with the emitter it replaced, kept as the reference in emit_reference.hpp, on every dictionary
// of the repository and the shared corpus and on random dictionaries that reach every column,
// every kind of number and every escape, and name collisions of every kind.
#include "emit_reference.hpp"
#include "readers.hpp"
#include "text.hpp"

#include "skip.hpp"
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace gen = fieldcodec::gen;
namespace od = fieldcodec::od;

namespace {

// Names that collide (after make_identifier), are keywords or reserved, have no identifier,
// start with a digit, carry signs, umlauts, quotes, backslashes, trigraphs and control bytes.
const std::vector<std::string> names{"",
                                     "Device type",
                                     "device-type",
                                     "DEVICE TYPE",
                                     "delete",
                                     "entries",
                                     "od",
                                     "1st value",
                                     "Limit+",
                                     "Limit-",
                                     "Jog -1",
                                     "\xC3\x9C"
                                     "berlast \xC3\x9F",
                                     "---",
                                     "object_1000",
                                     "x",
                                     "x_1000",
                                     "x_1000_2",
                                     "Highest sub-index supported",
                                     "say \"hi\" \\ ?\?= ?",
                                     std::string("nul\0byte\ttab\x7F", 14),
                                     "sub1",
                                     "A rather long parameter name that is well over the small "
                                     "string size of any library"};

struct random_dictionaries {
  std::mt19937_64 rng{0x1850EEDULL};

  std::uint64_t below(std::uint64_t n) { return rng() % n; }
  bool chance(unsigned percent) { return below(100) < percent; }
  const std::string &name() { return names[below(names.size())]; }
  std::string bytes() {
    std::string s(below(12), '\0');
    for (char &c : s) c = static_cast<char>(below(256));
    return s;
  }
  std::string text() { return chance(50) ? std::string() : chance(70) ? name() : bytes(); }
  od::number number() {
    switch (below(9)) {
    case 0: return {};
    case 1: return od::signed_number(std::numeric_limits<std::int64_t>::min());
    case 2: return od::signed_number(static_cast<std::int64_t>(rng()));
    case 3: return od::signed_number(-static_cast<std::int64_t>(below(1000)));
    case 4: return od::unsigned_number(chance(50) ? rng() : below(70000));
    case 5: return od::real_number(static_cast<double>(static_cast<std::int64_t>(rng())) / 3.0);
    case 6: {
      const double pick[] = {0.0, -0.0, 3.0, 1e300, 1e-300, 0.1, -2.5, 1e16, 123456789.0};
      return od::real_number(pick[below(std::size(pick))]);
    }
    case 7:
      return od::decimal_number(static_cast<std::int64_t>(rng()),
                                static_cast<std::uint8_t>(below(19)));
    default: return od::decimal_number(-static_cast<std::int64_t>(below(100000)), 2);
    }
  }
  gen::entry entry(std::uint16_t index, std::uint8_t sub) {
    constexpr od::data_type types[] = {
        od::data_type::boolean,      od::data_type::integer8,       od::data_type::integer32,
        od::data_type::unsigned16,   od::data_type::unsigned64,     od::data_type::integer64,
        od::data_type::real32,       od::data_type::real64,         od::data_type::visible_string,
        od::data_type::octet_string, od::data_type::unicode_string, od::data_type::domain,
        od::data_type::time_of_day};
    constexpr od::object_code codes[] = {od::object_code::var, od::object_code::var,
                                         od::object_code::domain, od::object_code::array,
                                         od::object_code::record};
    gen::entry e;
    e.index = index;
    e.sub = sub;
    e.object = codes[below(std::size(codes))];
    e.type = types[below(std::size(types))];
    e.access = static_cast<od::access>(below(6));
    e.pdo = static_cast<od::pdo_mapping>(below(4));
    e.flags = static_cast<std::uint8_t>(below(8));
    e.size = chance(30) ? static_cast<std::uint32_t>(rng()) : 0U;
    e.name = name();
    if (chance(10)) e.symbol = name();
    e.low = number();
    e.high = number();
    e.default_value = number();
    e.parameter_value = chance(30) ? number() : od::number{};
    e.low_nodeid = chance(10);
    e.high_nodeid = chance(10);
    e.default_nodeid = chance(10);
    e.parameter_nodeid = chance(10);
    e.default_text = chance(30) ? text() : std::string();
    e.parameter_text = chance(20) ? text() : std::string();
    e.denotation = chance(20) ? text() : std::string();
    e.unit = chance(20) ? text() : std::string();
    e.alt_name = chance(10) ? text() : std::string();
    if (chance(10)) e.acceptance = static_cast<fieldcodec::dpq::acceptance>(1U + below(2));
    e.section = chance(10) ? text() : std::string();
    e.remark = chance(10) ? text() : std::string();
    e.scaled = chance(10);
    if (chance(10)) {
      e.scale = {static_cast<std::int64_t>(rng()), static_cast<std::uint8_t>(below(19))};
      e.offset = {-static_cast<std::int64_t>(below(1000)), static_cast<std::uint8_t>(below(3))};
    }
    if (chance(10)) e.pointer = static_cast<std::uint8_t>(below(128));
    e.bus = static_cast<fieldcodec::dpq::bus_manager>(below(3));
    e.has_obj_flags = chance(20);
    e.obj_flags = chance(50) ? static_cast<std::uint32_t>(rng()) : 0U;
    return e;
  }
  gen::dictionary objects(std::size_t count, std::uint64_t max_step = 0x800) {
    constexpr od::object_code codes[] = {
        od::object_code::var,     od::object_code::var,       od::object_code::domain,
        od::object_code::deftype, od::object_code::null,      od::object_code::array,
        od::object_code::record,  od::object_code::defstruct, od::object_code::array};
    gen::dictionary d;
    d.source_name = chance(50) ? "bench \"x\".dcf" : "t.eds";
    d.stem = "t";
    d.node_id = static_cast<int>(below(130)) - 2;
    auto index = static_cast<std::uint32_t>(below(0x20));
    for (std::size_t o = 0; o < count && index <= 0xFFFFU; ++o) {
      const auto i = static_cast<std::uint16_t>(index);
      gen::object_info info;
      info.index = i;
      info.code = codes[below(std::size(codes))];
      info.name = name();
      if (chance(15)) info.symbol = name();
      // a single object mostly has one entry, sometimes none or several (a view then)
      std::size_t subs = info.code == od::object_code::var || info.code == od::object_code::null
                             ? (chance(90) ? 1U : below(3))
                             : below(8);
      unsigned sub = chance(80) ? 0U : static_cast<unsigned>(below(4));
      for (std::size_t k = 0; k < subs && sub <= 0xFFU; ++k) {
        d.entries.push_back(entry(i, static_cast<std::uint8_t>(sub)));
        sub += chance(80) ? 1U : static_cast<unsigned>(1U + below(200));
      }
      if (chance(95)) d.objects.emplace(i, info); // else: entries without an object
      index += static_cast<std::uint32_t>(chance(50) ? 1U : 1U + below(max_step));
    }
    return d;
  }
  gen::dictionary commands(std::size_t count) {
    gen::dictionary d;
    d.is_command_table = true;
    d.source_name = "cmds.csv";
    d.stem = "cmds";
    auto code = static_cast<std::uint32_t>(below(4));
    for (std::size_t k = 0; k < count && code <= 0xFFFFU; ++k) {
      gen::command c;
      c.code = static_cast<std::uint16_t>(code);
      c.name = name();
      if (chance(15)) c.symbol = name();
      c.section = text();
      c.title = text();
      c.parameter = text();
      c.date = text();
      c.reply = text();
      c.modes = text();
      c.remark = text();
      c.parameter_min = number();
      c.parameter_max = number();
      c.date_min = number();
      c.date_max = number();
      c.parameter_packing = static_cast<od::packing>(below(3));
      c.date_packing = static_cast<od::packing>(below(3));
      c.date_type = static_cast<od::command_value>(below(3));
      c.reply_type = static_cast<od::command_value>(below(3));
      d.commands.push_back(c);
      code += static_cast<std::uint32_t>(1U + below(300));
    }
    return d;
  }
};

std::size_t compare_files(const std::filesystem::path &dir) {
  std::size_t n = 0;
  for (const auto &f : std::filesystem::recursive_directory_iterator(dir)) {
    const auto ext = f.path().extension();
    if (!f.is_regular_file() || (ext != ".eds" && ext != ".dcf" && ext != ".csv")) continue;
    gen::diagnostics diag;
    auto d = gen::read_file(f.path().string(), diag);
    if (!d) continue; // a malformed fixture: nothing to emit
    d->stem = gen::stem_identifier(f.path().stem().string());
    d->source_name = f.path().filename().string();
    INFO(f.path().string());
    CHECK(gen::emit_header(*d) == emit_reference::emit_header(*d));
    ++n;
  }
  return n;
}

} // namespace

TEST_CASE("emit_header: as before issue 18's second round, on the repository's dictionaries") {
  CHECK(compare_files("codegen/fixtures") >= 3U);
  CHECK(compare_files("master/fixtures") >= 1U);
  CHECK(compare_files("../dictionaries") >= 6U);
}

TEST_CASE("emit_header: as before issue 18's second round, on the shared corpus") {
  const std::filesystem::path corpus =
      std::filesystem::path(fieldcodec::test::shared_dir) / "eds-corpus";
  if (!std::filesystem::is_directory(corpus)) {
    FIELDCODEC_SKIP_TEST("corpus", "EDS corpus not found at " << corpus.string());
  }
  CHECK(compare_files(corpus) >= 20U);
}

TEST_CASE("emit_header: as before issue 18's second round, on random dictionaries") {
  random_dictionaries r;
  for (int run = 0; run < 300; ++run) {
    const gen::dictionary d = r.objects(1U + r.below(60));
    const std::string got = gen::emit_header(d);
    REQUIRE(got == emit_reference::emit_header(d));
  }
  for (int run = 0; run < 100; ++run) {
    const gen::dictionary d = r.commands(r.below(30));
    REQUIRE(gen::emit_header(d) == emit_reference::emit_header(d));
  }
  // names taken two and more times: object names get the index, sub-objects "subN", then _2, _3
  gen::dictionary same = r.objects(0);
  for (std::uint16_t i = 0x2000; i < 0x2010; ++i) {
    gen::object_info info;
    info.index = i;
    info.code = i % 2U == 0U ? od::object_code::record : od::object_code::array;
    info.name = i < 0x2008 ? "r" : "R 2000";
    same.objects.emplace(i, info);
    for (std::uint8_t sub = 0; sub < 3; ++sub) {
      gen::entry e = r.entry(i, sub);
      e.symbol = sub == 2U ? std::string() : "x";
      e.name = "r";
      same.entries.push_back(e);
    }
  }
  const std::string h = gen::emit_header(same);
  CHECK(h == emit_reference::emit_header(same));
  CHECK(h.find(" x_sub1_8{") != std::string::npos);
  CHECK(h.find(" r_2000_200a_r{") != std::string::npos);
  CHECK(h.find(" x_sub1_16{") != std::string::npos);
  // a big one: the header grows past its reservation, the symbol set rehashes
  gen::dictionary big = r.objects(3000, 4);
  for (auto &e : big.entries) e.unit = std::string(300, 'u');
  CHECK(big.entries.size() > 4000U);
  const std::string whole = gen::emit_header(big);
  CHECK(whole == emit_reference::emit_header(big));
  // in pieces: the same bytes; a piece is handed on when the next text does not fit in 64 kB,
  // so every piece but the last is nearly full, and a text longer than that is in one piece
  big.entries[7].unit = std::string(200000, 'v'); // one text longer than a piece
  const std::string with_long = gen::emit_header(big);
  std::string joined;
  std::vector<std::size_t> sizes;
  gen::emit_header(big, [&](std::string_view piece) {
    joined.append(piece);
    sizes.push_back(piece.size());
  });
  CHECK(joined == with_long);
  REQUIRE(sizes.size() > 3U);
  for (const std::size_t n : sizes) CHECK(n > 0U);
  CHECK(*std::max_element(sizes.begin(), sizes.end()) > 200000U);
  for (std::size_t k = 0; k + 1U < sizes.size(); ++k) {
    CHECK((sizes[k] > 60000U || sizes[k + 1U] > 65536U)); // (or handed on before the long text)
  }
}

TEST_CASE("write_cpp_string, write_cpp_bytes, write_identifier: within the stated room") {
  // every byte value, the longest escapes: the writers stay within the capacity they state
  std::string all;
  for (int c = 0; c < 256; ++c) all += static_cast<char>(c);
  all += "??????";
  std::string buf(gen::cpp_string_capacity(all.size()) + 16U, '#');
  char *end = gen::write_cpp_string(buf.data(), all);
  CHECK(static_cast<std::size_t>(end - buf.data()) <= gen::cpp_string_capacity(all.size()));
  CHECK(std::string(buf.data(), end) == emit_reference::cpp_string(all));
  std::fill(buf.begin(), buf.end(), '#');
  end = gen::write_cpp_bytes(buf.data(), all);
  // 92 printable bytes as they are, 164 other bytes and six '?' as \ooo, two quotes
  CHECK(static_cast<std::size_t>(end - buf.data()) == 2U + 92U + 4U * (164U + 6U));
  std::string ref;
  emit_reference::append_cpp_value_text(ref, od::data_type::octet_string, all);
  CHECK("std::string_view{" + std::string(buf.data(), end) + ", 262}" == ref);
  std::string via;
  gen::append_cpp_value_text(via, od::data_type::octet_string, all);
  CHECK(via == ref);
  // "-+-+" gives "_minus_plus_minus_plus"-like runs: the most an input byte can take
  const std::string signs = "a+-+-+-+-+-+delete";
  std::string id(gen::identifier_capacity(signs.size()), '#');
  const std::size_t n = gen::write_identifier(id.data(), signs);
  CHECK(n <= gen::identifier_capacity(signs.size()));
  CHECK(id.substr(0, n) == gen::make_identifier(signs));
  CHECK(gen::write_identifier(id.data(), "+") == 4U); // "plus"
  CHECK(id.substr(0, 4) == "plus");
  CHECK(gen::write_identifier(id.data(), "---") == 0U);
}

TEST_CASE("rare_text: reads like a std::string, copies deeply, empty without a string") {
  gen::rare_text a;
  CHECK(a.empty());
  CHECK(a.size() == 0U);
  CHECK(a.str().empty());
  a = "bar";
  const std::string &s = a;
  CHECK(s == "bar");
  CHECK(std::string_view(a) == "bar");
  gen::rare_text b = a; // a copy of its own
  a = std::string("mbar");
  CHECK(b.str() == "bar");
  CHECK(a.str() == "mbar");
  CHECK(a.size() == 4U);
  CHECK_FALSE(a == b);
  b = a;
  CHECK(a == b);
  a = ""; // empty: as never set
  CHECK(a.empty());
  CHECK(a == gen::rare_text{});
  gen::rare_text c = std::move(b);
  CHECK(c.str() == "mbar");
  CHECK(c == "mbar");
  CHECK_FALSE(c == "bar");
  CHECK(std::string(c.data(), c.size()) == "mbar");
  c.clear();
  CHECK(c.empty());
  CHECK(c == "");
  // an entry is smaller than with eight std::string columns (the point of rare_text)
  static_assert(sizeof(gen::rare_text) == sizeof(void *));
}
