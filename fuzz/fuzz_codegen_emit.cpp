// Fuzz harness for the generator's C++ header emitter (codegen/src/emit_header.cpp) on every
// dictionary the readers accept (fuzz_codegen covers the readers and the EDS writer). Like
// fuzz_codegen it compiles the generator's sources into itself (FIELDCODEC_BUILD_CODEGEN=OFF in
// the fuzz build): text.cpp, checks.cpp, the two readers and emit_header.cpp.
//
// Input: byte 0 bit 0 selects the reader (0 EDS/DCF, 1 CSV). With bit 1 set, the low 5 bits of
// byte 1 are the length n of a file name taken from the next n bytes (any bytes but '/' and NUL,
// as a file system allows; ".eds" / ".csv" is appended), otherwise the file is "fuzz.eds" /
// "fuzz.csv". The rest is the file's text. The file name and its stem are set as read_file()
// sets them (source_name, stem_identifier).
//
// The emitted header is read back with a small C++ lexer written here (not the emitter's code),
// and these properties are checked:
// * Deterministic: emitting twice gives the same bytes, and the piecewise form (the sink that
//   fieldcodec-gen uses) gives them too, in non-empty pieces.
// * Line 1 is the "Generated from" comment, whatever the file name holds.
// * Lexically sound: the header is valid UTF-8 (docs/generator.md: texts are held as UTF-8) and
//   has no control byte but LF; no `/*`; no `//` comment ends in a backslash (a line splice would
//   comment out the next line); every string literal is terminated on its line, has only valid
//   escapes (an octal escape has exactly three digits, so a digit after it can never be read
//   into it), and no `??` (a trigraph before C++17, and a surprise for readers since);
//   braces, brackets and parentheses balance.
// * Texts survive: every entry's line in `entries` and `infos` has its index, sub-index, type
//   and flags, its packed columns (`.extra = "…"`, od/entry.hpp) unpack through od::entry's
//   accessors to the capacity, limits, default and default text the model holds (an integer in
//   the entry's width comes back in the kind of the entry's signedness, reals as the same double,
//   everything else exactly), with no byte left over; the DCF value is printed as the number the
//   model holds, and every text (name, unit, ..., DCF byte strings) as a literal that decodes to
//   the model's bytes, with the written length `{"…", n}` equal to the decoded length; an
//   object view's name literal (`"…"sv`) decodes to the object's name; `source_file` decodes to
//   the file name; `node_id` is the DCF's node-ID (1..127), declared exactly when it has one.
//   The manufacturers' column tables (`dpq_columns`, `compax_columns`) have one row per entry
//   with such a column, in entry order, with the model's values, and are absent without one.
//   Command tables: codes, names and texts of every command.
// * Identifiers: every declared constant (descriptors, object views, command references, the
//   namespace) is a valid C++ identifier (ASCII letter or '_' then letters, digits, '_'; no
//   leading '_', no "__" — both reserved to the implementation —, not a keyword), unique in the
//   namespace (so different from the header's own entries, infos, dictionary, ...), not one of
//   the names the header uses unqualified (od, std, fieldcodec, scaling, detail, dpq, compax); a
//   descriptor's comment names the index of the table row it copies.
#include "check.hpp"

#include "../codegen/src/text.cpp"

#include "../codegen/src/checks.cpp"
#include "../codegen/src/csv_reader.cpp"
#include "../codegen/src/eds_reader.cpp"
#include "../codegen/src/emit_header.cpp"

#include <fieldcodec/core/utf8.hpp>

#include <bit>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace gen = fieldcodec::gen;
namespace od = fieldcodec::od;
namespace dpq = fieldcodec::dpq;

namespace {

// --- lexer ------------------------------------------------------------------------------------

enum class tok : std::uint8_t { ident, number, string, punct };

struct token {
  tok kind;
  std::string text;   ///< identifier, number or punctuator as written; a string's decoded bytes
  std::string suffix; ///< a string literal's ud-suffix ("sv")
  int line;
};

bool is_ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_ident_char(char c) { return is_ident_start(c) || (c >= '0' && c <= '9'); }
bool is_octal(char c) { return c >= '0' && c <= '7'; }

/// Whether `s` is valid UTF-8 (no overlongs, no surrogates, at most U+10FFFF).
bool valid_utf8(std::string_view s) { return fieldcodec::utf8::valid(s); }

/// The tokens of the header outside comments and preprocessor lines; checks the lexical
/// properties on the way.
std::vector<token> lex(std::string_view h) {
  FUZZ_CHECK(valid_utf8(h));
  std::vector<token> out;
  int line = 1;
  std::size_t i = 0;
  bool line_start = true;
  while (i < h.size()) {
    const char c = h[i];
    const auto uc = static_cast<unsigned char>(c);
    FUZZ_CHECK(c == '\n' || (uc >= 0x20U && uc != 0x7FU)); // no control byte but LF
    if (c == '\n') {
      ++line;
      ++i;
      line_start = true;
      continue;
    }
    if (c == ' ') {
      ++i;
      continue;
    }
    if (line_start && c == '#') { // #pragma, #include <...>
      const std::size_t e = h.find('\n', i);
      FUZZ_CHECK(e != std::string_view::npos);
      FUZZ_CHECK(h[e - 1U] != '\\');
      i = e;
      continue;
    }
    line_start = false;
    FUZZ_CHECK(!(c == '/' && i + 1U < h.size() && h[i + 1U] == '*'));
    if (c == '/' && i + 1U < h.size() && h[i + 1U] == '/') {
      const std::size_t e = h.find('\n', i);
      FUZZ_CHECK(e != std::string_view::npos);
      FUZZ_CHECK(h[e - 1U] != '\\'); // a splice would continue the comment
      i = e;
      continue;
    }
    if (is_ident_start(c)) {
      std::size_t e = i;
      while (e < h.size() && is_ident_char(h[e])) ++e;
      out.push_back({tok::ident, std::string(h.substr(i, e - i)), {}, line});
      i = e;
      continue;
    }
    if (c >= '0' && c <= '9') { // pp-number
      std::size_t e = i;
      while (e < h.size() &&
             (is_ident_char(h[e]) || h[e] == '.' ||
              ((h[e] == '+' || h[e] == '-') && (h[e - 1U] == 'e' || h[e - 1U] == 'E')))) {
        ++e;
      }
      out.push_back({tok::number, std::string(h.substr(i, e - i)), {}, line});
      i = e;
      continue;
    }
    if (c == '"') {
      std::string v;
      std::size_t k = i + 1U;
      for (;;) {
        FUZZ_CHECK(k < h.size());
        const char d = h[k];
        const auto ud = static_cast<unsigned char>(d);
        FUZZ_CHECK(d != '\n' && ud >= 0x20U && ud != 0x7FU); // terminated, no raw control byte
        if (d == '"') {
          ++k;
          break;
        }
        if (d == '?') FUZZ_CHECK(k + 1U >= h.size() || h[k + 1U] != '?'); // no "??"
        if (d != '\\') {
          v += d;
          ++k;
          continue;
        }
        FUZZ_CHECK(k + 1U < h.size());
        const char x = h[k + 1U];
        if (is_octal(x)) { // up to three digits are read: the emitter writes all three
          unsigned value = 0;
          std::size_t n = 0;
          while (n < 3U && k + 1U + n < h.size() && is_octal(h[k + 1U + n])) {
            value = value * 8U + static_cast<unsigned>(h[k + 1U + n] - '0');
            ++n;
          }
          FUZZ_CHECK(n == 3U);
          FUZZ_CHECK(value <= 0xFFU);
          v += static_cast<char>(value);
          k += 1U + n;
          continue;
        }
        switch (x) {
        case '"':
        case '\\':
        case '?':
        case '\'': v += x; break;
        case 'n': v += '\n'; break;
        case 't': v += '\t'; break;
        case 'r': v += '\r'; break;
        default: FUZZ_CHECK(false && "unknown escape");
        }
        k += 2U;
      }
      std::size_t e = k;
      while (e < h.size() && is_ident_char(h[e])) ++e;
      out.push_back({tok::string, std::move(v), std::string(h.substr(k, e - k)), line});
      i = e;
      continue;
    }
    if (c == ':' && i + 1U < h.size() && h[i + 1U] == ':') {
      out.push_back({tok::punct, "::", {}, line});
      i += 2U;
      continue;
    }
    FUZZ_CHECK(std::string_view("{}[]()<>,;=.-+*&|").find(c) != std::string_view::npos);
    out.push_back({tok::punct, std::string(1, c), {}, line});
    ++i;
  }
  // brackets balance, in order
  std::string stack;
  for (const token &t : out) {
    if (t.kind != tok::punct || t.text.size() != 1U) continue;
    const char c = t.text[0];
    if (c == '{' || c == '(' || c == '[') stack += c;
    if (c == '}' || c == ')' || c == ']') {
      FUZZ_CHECK(!stack.empty());
      const char open = stack.back();
      FUZZ_CHECK((c == '}' && open == '{') || (c == ')' && open == '(') ||
                 (c == ']' && open == '['));
      stack.pop_back();
    }
  }
  FUZZ_CHECK(stack.empty());
  return out;
}

// --- reading values back ----------------------------------------------------------------------

/// A cursor over the tokens.
struct reader {
  const std::vector<token> &t;
  std::size_t i = 0;
  [[nodiscard]] const token &at(std::size_t k = 0) const {
    FUZZ_CHECK(i + k < t.size());
    return t[i + k];
  }
  bool is(std::string_view p, std::size_t k = 0) const {
    return i + k < t.size() && t[i + k].kind != tok::string && t[i + k].text == p;
  }
  void expect(std::string_view p) {
    FUZZ_CHECK(is(p));
    ++i;
  }
  std::string ident() {
    FUZZ_CHECK(at().kind == tok::ident);
    return t[i++].text;
  }
  std::uint64_t unsigned_number() {
    FUZZ_CHECK(at().kind == tok::number);
    std::string s = t[i++].text;
    int base = 10;
    std::size_t b = 0;
    if (s.size() > 2U && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
      base = 16;
      b = 2;
    }
    if (!s.empty() && s.back() == 'U') s.pop_back();
    std::uint64_t v = 0;
    const auto [p, ec] = std::from_chars(s.data() + b, s.data() + s.size(), v, base);
    FUZZ_CHECK(ec == std::errc{} && p == s.data() + s.size());
    return v;
  }
  /// [-]integer, or "-9223372036854775807 - 1"
  std::int64_t signed_number() {
    const bool neg = is("-");
    if (neg) ++i;
    const std::uint64_t m = unsigned_number();
    if (neg && is("-")) { // INT64_MIN as an expression
      ++i;
      FUZZ_CHECK(m == 9223372036854775807U && unsigned_number() == 1U);
      return std::numeric_limits<std::int64_t>::min();
    }
    FUZZ_CHECK(m <= (neg ? std::uint64_t{1} << 63U : std::uint64_t{0x7FFFFFFFFFFFFFFF}));
    return neg ? static_cast<std::int64_t>(std::uint64_t{0} - m) : static_cast<std::int64_t>(m);
  }
  /// od::…_number(…) or {}
  od::number number() {
    if (is("{")) {
      expect("{");
      expect("}");
      return {};
    }
    expect("od");
    expect("::");
    const std::string f = ident();
    expect("(");
    od::number n;
    if (f == "signed_number") {
      n = od::signed_number(signed_number());
    } else if (f == "unsigned_number") {
      FUZZ_CHECK(at().text.back() == 'U'); // an unsigned literal: never a signed constant
      n = od::unsigned_number(unsigned_number());
    } else if (f == "real_number") {
      const bool neg = is("-");
      if (neg) ++i;
      FUZZ_CHECK(at().kind == tok::number);
      const std::string &s = t[i++].text;
      FUZZ_CHECK(s.find_first_of(".e") != std::string::npos); // a double literal, not an int
      double d = 0;
      const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), d);
      FUZZ_CHECK(ec == std::errc{} && p == s.data() + s.size());
      n = od::real_number(neg ? -d : d);
    } else if (f == "decimal_number") {
      const std::int64_t m = signed_number();
      expect(",");
      const std::uint64_t p = unsigned_number();
      FUZZ_CHECK(p <= 0xFFU);
      n = od::decimal_number(m, static_cast<std::uint8_t>(p));
    } else {
      FUZZ_CHECK(false && "unknown number factory");
    }
    expect(")");
    return n;
  }
  /// {"…", n}: the decoded bytes, n checked against them.
  std::string text() {
    expect("{");
    FUZZ_CHECK(at().kind == tok::string && at().suffix.empty());
    std::string v = t[i++].text;
    expect(",");
    FUZZ_CHECK(unsigned_number() == v.size());
    expect("}");
    return v;
  }
  /// "…"sv
  std::string view() {
    FUZZ_CHECK(at().kind == tok::string && at().suffix == "sv");
    return t[i++].text;
  }
  /// Skips to just after the matching close of the bracket at the cursor.
  void skip_group() {
    int depth = 0;
    do {
      const token &x = at();
      if (x.kind == tok::punct && (x.text == "{" || x.text == "(" || x.text == "[")) ++depth;
      if (x.kind == tok::punct && (x.text == "}" || x.text == ")" || x.text == "]")) --depth;
      ++i;
    } while (depth > 0);
  }
  /// Moves to just after `inline constexpr std::array<type, N> name{{` (a command table) or
  /// `inline constexpr type name[N]{` (an object dictionary's C-array table, in namespace
  /// detail); returns N. `table_braces` is then the number of braces that close the table.
  std::size_t find_table(std::string_view name) {
    for (; i + 2U < t.size(); ++i) {
      if (t[i].kind == tok::ident && t[i].text == name && t[i + 1U].text == "{" &&
          t[i + 2U].text == "{" && i >= 2U && t[i - 1U].text == ">") {
        std::size_t k = i - 2U;
        FUZZ_CHECK(t[k].kind == tok::number);
        reader r{t, k};
        const std::uint64_t n = r.unsigned_number();
        i += 3U;
        table_braces = 2;
        return n;
      }
      if (t[i].kind == tok::ident && t[i].text == name && i + 4U < t.size() &&
          t[i + 1U].text == "[" && t[i + 3U].text == "]" && t[i + 4U].text == "{") {
        reader r{t, i + 2U};
        const std::uint64_t n = r.unsigned_number();
        i += 5U;
        table_braces = 1;
        return n;
      }
    }
    FUZZ_CHECK(false && "table not found");
    return 0;
  }
  int table_braces = 0;
};

bool same_number(const od::number &a, const od::number &b) {
  if (a.kind != b.kind) return false;
  if (a.kind == od::number_kind::real) { // printed shortest round trip: the same double
    return std::bit_cast<std::uint64_t>(a.to_double()) ==
           std::bit_cast<std::uint64_t>(b.to_double());
  }
  return a == b;
}

/// Designated initialisers `{.field = value, ...}` of one row; `value` reads one field's value
/// at the cursor and returns false for a field it does not know.
template <class F>
void fields(reader &r, F &&value) {
  r.expect("{");
  std::set<std::string> seen;
  while (!r.is("}")) {
    r.expect(".");
    const std::string f = r.ident();
    FUZZ_CHECK(seen.insert(f).second);
    r.expect("=");
    if (!value(f)) { // a value this harness does not read: up to the next field
      while (!r.is(",") && !r.is("}")) {
        if (r.is("{") || r.is("(")) {
          r.skip_group();
        } else {
          ++r.i;
        }
      }
    }
    if (r.is(",")) ++r.i;
  }
  r.expect("}");
}

/// The number a packed column gives back for the model's `v`: the same, or for an integer in
/// the entry's width the same value in the kind of the entry's signedness.
bool same_packed(const od::number &got, const od::number &v, bool as_number) {
  if (as_number || !v ||
      (v.kind != od::number_kind::signed_ && v.kind != od::number_kind::unsigned_)) {
    return same_number(got, v);
  }
  if (got.kind != od::number_kind::signed_ && got.kind != od::number_kind::unsigned_) return false;
  const bool neg_got =
      got.kind == od::number_kind::signed_ && static_cast<std::int64_t>(got.bits) < 0;
  const bool neg_v = v.kind == od::number_kind::signed_ && static_cast<std::int64_t>(v.bits) < 0;
  return neg_got == neg_v && got.bits == v.bits;
}

void check_entries(reader &r, const gen::dictionary &d) {
  if (d.entries.empty()) return; // no C array of length 0: `span<const od::entry, 0> entries{}`
  FUZZ_CHECK(r.find_table("entries") == d.entries.size());
  for (const gen::entry &e : d.entries) {
    std::uint64_t sub = 0;
    od::entry got;
    std::string extra;
    bool index_seen = false;
    bool type_seen = false;
    fields(r, [&](const std::string &f) {
      if (f == "index") {
        FUZZ_CHECK(r.at().text.starts_with("0x"));
        FUZZ_CHECK(r.unsigned_number() == e.index);
        index_seen = true;
      } else if (f == "sub") {
        sub = r.unsigned_number();
      } else if (f == "type") {
        r.expect("od");
        r.expect("::");
        r.expect("data_type");
        r.expect("::");
        const std::string t = r.ident();
        bool found = false;
        for (const auto &row : od::data_types) {
          if (row.identifier == t) {
            got.type = row.type;
            found = true;
          }
        }
        FUZZ_CHECK(found);
        type_seen = true;
      } else if (f == "flags") {
        static constexpr std::pair<std::string_view, std::uint16_t> names[] = {
            {"range_exceeds_field", od::flag::range_exceeds_field},
            {"index_anomaly", od::flag::index_anomaly},
            {"signedness_guess", od::flag::signedness_guess},
            {"scaled", od::flag::scaled},
            {"default_nodeid", od::flag::default_nodeid},
            {"low_nodeid", od::flag::low_nodeid},
            {"high_nodeid", od::flag::high_nodeid},
            {"parameter_nodeid", od::flag::parameter_nodeid},
            {"has_default", od::flag::has_default},
            {"has_low", od::flag::has_low},
            {"has_high", od::flag::has_high},
            {"default_number", od::flag::default_number},
            {"limits_number", od::flag::limits_number},
            {"has_size", od::flag::has_size},
            {"has_text", od::flag::has_text}};
        for (;;) {
          r.expect("od");
          r.expect("::");
          r.expect("flag");
          r.expect("::");
          const std::string n = r.ident();
          std::uint16_t bit = 0;
          for (const auto &[name, b] : names) {
            if (name == n) bit = b;
          }
          FUZZ_CHECK(bit != 0U && (got.flags & bit) == 0U); // known, each once
          got.flags = static_cast<std::uint16_t>(got.flags | bit);
          if (!r.is("|")) break;
          r.expect("|");
        }
      } else if (f == "extra") {
        FUZZ_CHECK(r.at().kind == tok::string && r.at().suffix.empty());
        extra = r.t[r.i++].text;
        FUZZ_CHECK(!extra.empty()); // no packed columns: no `.extra`
      } else {
        return false;
      }
      return true;
    });
    FUZZ_CHECK(index_seen && type_seen && got.type == e.type);
    FUZZ_CHECK(sub == e.sub);
    // the flags the model gives, and packed columns exactly as long as the flags say
    FUZZ_CHECK(got.has(od::flag::scaled) == e.scaled);
    FUZZ_CHECK(got.has(od::flag::default_nodeid) == e.default_nodeid);
    FUZZ_CHECK(got.has(od::flag::low_nodeid) == e.low_nodeid);
    FUZZ_CHECK(got.has(od::flag::high_nodeid) == e.high_nodeid);
    FUZZ_CHECK(got.has(od::flag::parameter_nodeid) == e.parameter_nodeid);
    FUZZ_CHECK((got.flags & 0x07U) == (e.flags & 0x07U));
    got.extra = extra.data();
    const od::entry_spec back = od::spec_of(got);
    FUZZ_CHECK(od::packed_size(back) == extra.size());
    FUZZ_CHECK(got.capacity() == (od::is_byte_string(e.type) ? e.size : 0U));
    FUZZ_CHECK(same_packed(got.low(), e.low, got.has(od::flag::limits_number)));
    FUZZ_CHECK(same_packed(got.high(), e.high, got.has(od::flag::limits_number)));
    FUZZ_CHECK(
        same_packed(got.default_value(), e.default_value, got.has(od::flag::default_number)));
    FUZZ_CHECK(std::string_view(got.default_text()) == e.default_text.str());
    r.expect(",");
  }
  FUZZ_CHECK(r.table_braces == 1); // object tables are C arrays
  r.expect("}");
}

void check_infos(reader &r, const gen::dictionary &d) {
  if (d.entries.empty()) return;
  FUZZ_CHECK(r.find_table("infos") == d.entries.size());
  for (const gen::entry &e : d.entries) {
    std::string name, unit, alt_name, section, remark, denotation, parameter_text;
    od::number parameter;
    fields(r, [&](const std::string &f) {
      std::string *t = f == "name"             ? &name
                       : f == "unit"           ? &unit
                       : f == "alt_name"       ? &alt_name
                       : f == "section"        ? &section
                       : f == "remark"         ? &remark
                       : f == "denotation"     ? &denotation
                       : f == "parameter_text" ? &parameter_text
                                               : nullptr;
      if (t != nullptr) {
        *t = r.text();
        FUZZ_CHECK(!t->empty()); // empty texts are left out
        return true;
      }
      if (f == "parameter_value") {
        parameter = r.number();
        return true;
      }
      return false;
    });
    FUZZ_CHECK(name == e.name);
    FUZZ_CHECK(unit == e.unit.str());
    FUZZ_CHECK(alt_name == e.alt_name.str());
    FUZZ_CHECK(section == e.section.str());
    FUZZ_CHECK(remark == e.remark.str());
    FUZZ_CHECK(denotation == e.denotation);
    FUZZ_CHECK(parameter_text == e.parameter_text.str());
    FUZZ_CHECK(same_number(parameter, e.parameter_value));
    r.expect(",");
  }
  FUZZ_CHECK(r.table_braces == 1); // object tables are C arrays
  r.expect("}");
}

/// `<name>[N]{ {.index = 0xIIII[, .sub = S], ...}, ... }` at namespace scope: one row per entry
/// that `has`, in entry order; `value` reads a field other than index and sub for entry `e`.
/// No table at all when no entry has the columns.
template <class Has, class Value>
void check_vendor_table(const std::vector<token> &t, const gen::dictionary &d,
                        std::string_view name, Has has, Value value) {
  std::size_t n = 0;
  for (const gen::entry &e : d.entries) n += has(e) ? 1U : 0U;
  if (n == 0U) {
    for (const token &x : t) FUZZ_CHECK(!(x.kind == tok::ident && x.text == name));
    return;
  }
  reader r{t};
  FUZZ_CHECK(r.find_table(name) == n);
  for (const gen::entry &e : d.entries) {
    if (!has(e)) continue;
    std::uint64_t index = 0x10000;
    std::uint64_t sub = 0;
    fields(r, [&](const std::string &f) {
      if (f == "index") {
        index = r.unsigned_number();
      } else if (f == "sub") {
        sub = r.unsigned_number();
        FUZZ_CHECK(sub != 0U); // sub-index 0 is left out
      } else {
        FUZZ_CHECK(value(r, f, e));
      }
      return true;
    });
    FUZZ_CHECK(index == e.index && sub == e.sub);
    r.expect(",");
  }
  r.expect("}");
}

/// `a :: b :: <ident>`: the identifier after the qualification.
std::string qualified(reader &r, std::string_view a, std::string_view b) {
  r.expect(a);
  r.expect("::");
  r.expect(b);
  r.expect("::");
  return r.ident();
}

/// The manufacturers' column tables beside the dictionary (dpq_columns, compax_columns).
void check_vendor_columns(const std::vector<token> &t, const gen::dictionary &d) {
  check_vendor_table(
      t, d, "dpq_columns",
      [](const gen::entry &e) {
        return e.acceptance != dpq::acceptance::unknown || e.bus != dpq::bus_manager::unspecified;
      },
      [](reader &r, const std::string &f, const gen::entry &e) {
        if (f == "value_acceptance") {
          const std::string v = qualified(r, "dpq", "acceptance");
          return (v == "only_when_disabled" &&
                  e.acceptance == dpq::acceptance::only_when_disabled) ||
                 (v == "also_when_enabled" && e.acceptance == dpq::acceptance::also_when_enabled);
        }
        if (f == "bus") {
          const std::string v = qualified(r, "dpq", "bus_manager");
          return (v == "available" && e.bus == dpq::bus_manager::available) ||
                 (v == "not_available" && e.bus == dpq::bus_manager::not_available);
        }
        return false;
      });
  check_vendor_table(
      t, d, "compax_columns", [](const gen::entry &e) { return e.pointer.has_value(); },
      [](reader &r, const std::string &f, const gen::entry &e) {
        return f == "pointer" && r.unsigned_number() == *e.pointer;
      });
}

void check_commands(reader &r, const gen::dictionary &d) {
  FUZZ_CHECK(r.find_table("commands") == d.commands.size());
  for (const gen::command &c : d.commands) {
    std::string name, section, title, parameter, date, reply, modes, remark;
    std::uint64_t code = 0x10000;
    fields(r, [&](const std::string &f) {
      std::string *t = f == "name"        ? &name
                       : f == "section"   ? &section
                       : f == "title"     ? &title
                       : f == "parameter" ? &parameter
                       : f == "date"      ? &date
                       : f == "reply"     ? &reply
                       : f == "modes"     ? &modes
                       : f == "remark"    ? &remark
                                          : nullptr;
      if (t != nullptr) {
        *t = r.view();
        return true;
      }
      if (f == "code") {
        code = r.unsigned_number();
        return true;
      }
      return false;
    });
    FUZZ_CHECK(code == c.code);
    FUZZ_CHECK(name == c.name && section == c.section && title == c.title &&
               parameter == c.parameter && date == c.date && reply == c.reply && modes == c.modes &&
               remark == c.remark);
    r.expect(",");
  }
}

/// A name the generated header may declare: an identifier not reserved to the implementation.
bool good_identifier(std::string_view s) {
  if (s.empty() || !is_ident_start(s[0]) || s[0] == '_') return false;
  for (const char c : s) {
    if (!is_ident_char(c)) return false;
  }
  if (s.find("__") != std::string_view::npos || gen::is_cpp_keyword(s)) return false;
  // the namespaces and names the header uses unqualified (docs/generator.md "Identifiers")
  for (const std::string_view used :
       {"od", "std", "fieldcodec", "scaling", "detail", "dpq", "compax"}) {
    if (s == used) return false;
  }
  return true;
}

/// Every declaration of the namespace: `inline constexpr <type> NAME{` / `= ...`, and of its
/// namespace detail (the C-array tables `inline constexpr <type> NAME[N]{`).
void check_names(const std::vector<token> &t, const gen::dictionary &d) {
  std::set<std::string> names;
  std::set<std::string> detail_names;
  std::size_t descriptors = 0, objects = 0, commands = 0;
  int detail_depth = -1; // brace depth inside `namespace detail {`, -1 outside
  for (std::size_t i = 0; i + 1U < t.size(); ++i) {
    if (detail_depth < 0 && t[i].kind == tok::ident && t[i].text == "namespace" &&
        t[i + 1U].text == "detail") {
      FUZZ_CHECK(i + 2U < t.size() && t[i + 2U].text == "{");
      detail_depth = 0;
      continue;
    }
    if (detail_depth >= 0 && t[i].kind == tok::punct) {
      if (t[i].text == "{") ++detail_depth;
      if (t[i].text == "}" && --detail_depth == 0) detail_depth = -1;
    }
    if (t[i].kind == tok::ident && t[i].text == "namespace" && t[i + 1U].text == "fieldcodec") {
      // namespace fieldcodec::dictionaries::<stem> {
      FUZZ_CHECK(i + 5U < t.size() && t[i + 3U].text == "dictionaries");
      FUZZ_CHECK(t[i + 5U].kind == tok::ident && t[i + 5U].text == d.stem);
      FUZZ_CHECK(good_identifier(d.stem) && d.stem != "od" && d.stem != "std" &&
                 d.stem != "detail");
    }
    if (!(t[i].kind == tok::ident && t[i].text == "inline" && t[i + 1U].text == "constexpr")) {
      continue;
    }
    // the declared name: the last identifier before the initialiser
    std::size_t k = i + 2U;
    int angle = 0;
    std::string type;
    while (k < t.size() && !(angle == 0 && (t[k].text == "{" || t[k].text == "="))) {
      if (t[k].text == "<") ++angle;
      if (t[k].text == ">") --angle;
      if (angle == 0 && t[k].kind == tok::ident) type += t[k].text + " ";
      ++k;
    }
    if (detail_depth >= 0) { // namespace detail: `type name[N]{` only
      FUZZ_CHECK(k >= 4U && k < t.size() && t[k].text == "{" && t[k - 1U].text == "]" &&
                 t[k - 3U].text == "[" && t[k - 4U].kind == tok::ident);
      FUZZ_CHECK(detail_names.insert(t[k - 4U].text).second);
      continue;
    }
    if (k >= 4U && k < t.size() && t[k - 1U].text == "]") { // a manufacturer's column table
      FUZZ_CHECK(t[k].text == "{" && t[k - 3U].text == "[" && t[k - 4U].kind == tok::ident);
      const std::string &table = t[k - 4U].text;
      FUZZ_CHECK(table == "dpq_columns" || table == "compax_columns");
      FUZZ_CHECK(names.insert(table).second);
      continue;
    }
    FUZZ_CHECK(k < t.size() && t[k - 1U].kind == tok::ident);
    const std::string &name = t[k - 1U].text;
    FUZZ_CHECK(good_identifier(name));
    FUZZ_CHECK(names.insert(name).second); // unique in the namespace
    if (type == "od descriptor " + name + " ") {
      ++descriptors;
      // {detail::entries[k], detail::infos[k] ...}; // 0xIIII [sub S]
      reader r{t, k};
      r.expect("{");
      r.expect("detail");
      r.expect("::");
      r.expect("entries");
      r.expect("[");
      const std::uint64_t row = r.unsigned_number();
      FUZZ_CHECK(row < d.entries.size());
      r.expect("]");
      r.expect(",");
      r.expect("detail");
      r.expect("::");
      r.expect("infos");
      r.expect("[");
      FUZZ_CHECK(r.unsigned_number() == row);
    } else if (type == "od object " + name + " ") {
      ++objects;
      // {0xIIII, od::object_code::x, "name"sv, ...}
      reader r{t, k};
      r.expect("{");
      const std::uint64_t index = r.unsigned_number();
      const auto it = d.objects.find(static_cast<std::uint16_t>(index));
      FUZZ_CHECK(index <= 0xFFFFU && it != d.objects.end());
      r.expect(",");
      r.expect("od");
      r.expect("::");
      r.expect("object_code");
      r.expect("::");
      (void)r.ident();
      r.expect(",");
      FUZZ_CHECK(r.view() == it->second.name);
    } else if (type == "const od command " + name + " ") {
      ++commands;
    } else if (name == "source_file") {
      FUZZ_CHECK(t[k + 1U].kind == tok::string && t[k + 1U].text == d.source_name);
    } else if (name == "node_id") { // std::uint8_t node_id = N: the DCF's node-ID, 1..127
      reader r{t, k};
      r.expect("=");
      FUZZ_CHECK(d.node_id >= 1 && d.node_id <= 127 &&
                 r.unsigned_number() == static_cast<std::uint64_t>(d.node_id));
    }
  }
  if (d.is_command_table) {
    FUZZ_CHECK(commands == d.commands.size());
    FUZZ_CHECK(names.contains("commands") && names.contains("table"));
  } else {
    FUZZ_CHECK(descriptors + objects > 0U || d.entries.empty());
    FUZZ_CHECK(names.contains("entries") && names.contains("infos") &&
               names.contains("dictionary"));
    // the tables in namespace detail, published under the same names as spans
    if (d.entries.empty()) {
      FUZZ_CHECK(detail_names.empty());
    } else {
      FUZZ_CHECK(detail_names.contains("entries") && detail_names.contains("infos"));
      FUZZ_CHECK(detail_names.size() == (names.contains("scales") ? 3U : 2U));
    }
  }
  FUZZ_CHECK(names.contains("source_file"));
  FUZZ_CHECK(names.contains("node_id") == (!d.is_command_table && d.node_id > 0));
}

/// The descriptors' trailing comments: `// 0xIIII` or `// 0xIIII sub S` naming their row.
void check_descriptor_comments(std::string_view h, const gen::dictionary &d) {
  std::size_t p = 0;
  while ((p = h.find("inline constexpr od::descriptor ", p)) != std::string_view::npos) {
    const std::size_t eol = h.find('\n', p);
    const std::string_view line = h.substr(p, eol - p);
    const std::size_t row_at = line.find("{detail::entries[") + 17U;
    std::size_t row = 0;
    (void)std::from_chars(line.data() + row_at, line.data() + line.size(), row);
    FUZZ_CHECK(row < d.entries.size());
    const std::size_t c = line.find("}; // 0x");
    FUZZ_CHECK(c != std::string_view::npos);
    std::string want = "}; // 0x" + gen::hex(d.entries[row].index, 4);
    const std::string_view rest = line.substr(c);
    FUZZ_CHECK(rest == want || rest == want + " sub " + std::to_string(d.entries[row].sub));
    p = eol;
  }
}

void check_header(const gen::dictionary &d) {
  const std::string h = gen::emit_header(d);
  FUZZ_CHECK(gen::emit_header(d) == h);
  std::string pieces;
  gen::emit_header(d, [&](std::string_view piece) {
    FUZZ_CHECK(!piece.empty());
    pieces += piece;
  });
  FUZZ_CHECK(pieces == h);

  // line 1 names the file: as it is, or as a literal of its bytes (F20)
  const std::string_view first = std::string_view(h).substr(0, h.find('\n'));
  FUZZ_CHECK(first.starts_with("// Generated from "));
  FUZZ_CHECK(first.ends_with(" by fieldcodec-gen \xE2\x80\x94 do not edit."));

  const std::vector<token> t = lex(h);
  reader r{t};
  if (d.is_command_table) {
    check_commands(r, d);
  } else {
    check_entries(r, d);
    check_infos(r, d);
    check_vendor_columns(t, d);
    check_descriptor_comments(h, d);
  }
  check_names(t, d);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  const bool csv = (data[0] & 1U) != 0U;
  std::size_t at = 1;
  std::string base = "fuzz";
  if ((data[0] & 2U) != 0U) {
    if (size < 2U) return 0;
    const std::size_t n = data[1] & 0x1FU;
    if (size < 2U + n) return 0;
    base.assign(reinterpret_cast<const char *>(data + 2), n);
    if (base.empty() || base.find_first_of(std::string_view("/\0", 2)) != std::string::npos) {
      return 0;
    }
    at = 2U + n;
  }
  const std::string file = base + (csv ? ".csv" : ".eds");
  const std::string_view text(reinterpret_cast<const char *>(data + at), size - at);
  gen::diagnostics diag;
  auto d = csv ? gen::read_csv(text, file, diag) : gen::read_eds(text, file, diag);
  if (!d) return 0;
  d->source_name = file; // as read_file() does
  d->stem = gen::stem_identifier(base);
  check_header(*d);
  return 0;
}
