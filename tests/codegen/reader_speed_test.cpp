// Generator speed-ups of issue 18 (identifiers built in one buffer, the keyword test by binary
// search, string literals written in runs, files mapped instead of copied, known keys found by
// length with a presence mask) change no output: each replaced function is compared with the
// code it replaced, kept here as the reference, and the reader's key handling is tested where
// the new code takes other paths (many unknown keys, merged sections, keys in any case).
#include "readers.hpp"
#include "text.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace gen = fieldcodec::gen;

namespace {

// is_cpp_keyword before issue 18: a linear search of the same words.
bool reference_is_keyword(std::string_view s) {
  static constexpr std::array<std::string_view, 97> kw{
      "alignas",       "alignof",     "and",
      "and_eq",        "asm",         "auto",
      "bitand",        "bitor",       "bool",
      "break",         "case",        "catch",
      "char",          "char8_t",     "char16_t",
      "char32_t",      "class",       "compl",
      "concept",       "const",       "consteval",
      "constexpr",     "constinit",   "const_cast",
      "continue",      "co_await",    "co_return",
      "co_yield",      "decltype",    "default",
      "delete",        "do",          "double",
      "dynamic_cast",  "else",        "enum",
      "explicit",      "export",      "extern",
      "false",         "float",       "for",
      "friend",        "goto",        "if",
      "inline",        "int",         "long",
      "mutable",       "namespace",   "new",
      "noexcept",      "not",         "not_eq",
      "nullptr",       "operator",    "or",
      "or_eq",         "private",     "protected",
      "public",        "register",    "reinterpret_cast",
      "requires",      "return",      "short",
      "signed",        "sizeof",      "static",
      "static_assert", "static_cast", "struct",
      "switch",        "template",    "this",
      "thread_local",  "throw",       "true",
      "try",           "typedef",     "typeid",
      "typename",      "union",       "unsigned",
      "using",         "virtual",     "void",
      "volatile",      "wchar_t",     "while",
      "xor",           "xor_eq",      "final",
      "override",      "import",      "module",
      "assert"};
  return std::find(kw.begin(), kw.end(), s) != kw.end();
}

bool reference_sign_minus(std::string_view name, std::size_t i) {
  std::size_t j = i + 1U;
  while (j < name.size() && (name[j] == ' ' || name[j] == '.' || name[j] == ':')) ++j;
  if (j == name.size()) return true;
  const bool digit_next = i + 1U < name.size() && name[i + 1U] >= '0' && name[i + 1U] <= '9';
  const bool word_before = i > 0U && ((name[i - 1U] >= 'a' && name[i - 1U] <= 'z') ||
                                      (name[i - 1U] >= 'A' && name[i - 1U] <= 'Z') ||
                                      (name[i - 1U] >= '0' && name[i - 1U] <= '9'));
  return digit_next && !word_before;
}

// make_identifier before issue 18, verbatim but for the names.
std::string reference_make_identifier(std::string_view name) {
  static constexpr char lower_table[] = "abcdefghijklmnopqrstuvwxyz";
  std::string out;
  out.reserve(name.size() + 4U);
  bool pending_sep = false;
  auto put = [&](std::string_view t) {
    if (pending_sep && !out.empty()) out += '_';
    pending_sep = false;
    out += t;
  };
  for (std::size_t i = 0; i < name.size(); ++i) {
    const auto c = static_cast<unsigned char>(name[i]);
    if (c >= 'A' && c <= 'Z') {
      put(std::string_view(&lower_table[c - 'A'], 1));
    } else if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) {
      put(std::string_view(&name[i], 1));
    } else if (c == 0xC3U && i + 1U < name.size()) {
      const auto d = static_cast<unsigned char>(name[i + 1U]);
      ++i;
      switch (d) {
      case 0xA4:
      case 0x84: put("ae"); break;
      case 0xB6:
      case 0x96: put("oe"); break;
      case 0xBC:
      case 0x9C: put("ue"); break;
      case 0x9F: put("ss"); break;
      default: pending_sep = true; break;
      }
    } else if (c >= 0x80U) {
      while (i + 1U < name.size() && (static_cast<unsigned char>(name[i + 1U]) & 0xC0U) == 0x80U) {
        ++i;
      }
      pending_sep = true;
    } else if (c == '+') {
      pending_sep = true;
      put("plus");
      pending_sep = true;
    } else if (c == '-' && !out.empty() && reference_sign_minus(name, i)) {
      pending_sep = true;
      put("minus");
      pending_sep = true;
    } else {
      pending_sep = true;
    }
  }
  if (out.empty()) return out;
  if (out.front() >= '0' && out.front() <= '9') out = "n_" + out;
  if (reference_is_keyword(out)) out += '_';
  return out;
}

// append_cpp_string before issue 18, verbatim but for the names.
void reference_append_cpp_string(std::string &out, std::string_view s) {
  out += '"';
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '?' && i + 1U < s.size() && s[i + 1U] == '?') {
      out += "?\\";
    } else if (c < 0x20U || c == 0x7FU) {
      constexpr char digits[] = "01234567";
      out += '\\';
      out += digits[(c >> 6U) & 7U];
      out += digits[(c >> 3U) & 7U];
      out += digits[c & 7U];
    } else {
      out += static_cast<char>(c);
    }
  }
  out += '"';
}

// Text made of the pieces that take the different paths of the functions above.
std::string random_text(std::mt19937 &rng, std::size_t max_pieces) {
  static const std::vector<std::string> pieces{"a",
                                               "Z",
                                               "q",
                                               "0",
                                               "9",
                                               " ",
                                               "_",
                                               "-",
                                               "+",
                                               ".",
                                               ":",
                                               "?",
                                               "??",
                                               "\"",
                                               "\\",
                                               "\t",
                                               "\n",
                                               "\x7F",
                                               "\x01",
                                               "\xC3\xA4",
                                               "\xC3\x84",
                                               "\xC3\xB6",
                                               "\xC3\x96",
                                               "\xC3\xBC",
                                               "\xC3\x9C",
                                               "\xC3\x9F",
                                               "\xC3\xA9",
                                               "\xC3",
                                               "\xE2\x82\xAC",
                                               "\x80",
                                               "\xFF",
                                               "delete",
                                               "int",
                                               "Limit",
                                               "1st",
                                               "do",
                                               "n_",
                                               "%",
                                               "(",
                                               ")",
                                               "/",
                                               "jog",
                                               "Pos-FB"};
  std::uniform_int_distribution<std::size_t> count(0, max_pieces);
  std::uniform_int_distribution<std::size_t> pick(0, pieces.size() - 1U);
  std::string s;
  for (std::size_t n = count(rng); n > 0U; --n) s += pieces[pick(rng)];
  return s;
}

std::vector<std::string> diagnostics_of(const std::string &text) {
  gen::diagnostics d;
  auto dict = gen::read_eds(text, "t.eds", d);
  std::vector<std::string> out;
  for (const auto &x : d.all()) out.push_back(gen::diagnostics::format(x));
  return out;
}

bool has(const std::vector<std::string> &v, const std::string &s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

} // namespace

TEST_CASE("make_identifier and is_cpp_keyword: as before issue 18, for every kind of name") {
  for (const std::string_view w :
       {"delete", "int", "reinterpret_cast", "do", "assert", "module", "xor_eq", "co_await"}) {
    CHECK(gen::is_cpp_keyword(w));
    CHECK_FALSE(gen::is_cpp_keyword(std::string(w) + "_"));
    CHECK_FALSE(gen::is_cpp_keyword("x" + std::string(w)));
    CHECK(gen::make_identifier(w) == reference_make_identifier(w));
  }
  CHECK_FALSE(gen::is_cpp_keyword(""));
  CHECK_FALSE(gen::is_cpp_keyword("reinterpret_casts"));
  std::mt19937 rng(18);
  for (int i = 0; i < 200000; ++i) {
    const std::string s = random_text(rng, 8);
    INFO("name '" << s << "'");
    REQUIRE(gen::make_identifier(s) == reference_make_identifier(s));
    REQUIRE(gen::is_cpp_keyword(s) == reference_is_keyword(s));
  }
}

TEST_CASE("append_cpp_string: as before issue 18") {
  std::mt19937 rng(1818);
  for (int i = 0; i < 100000; ++i) {
    const std::string s = random_text(rng, 10);
    std::string a = "prefix ";
    std::string b = a;
    gen::append_cpp_string(a, s);
    reference_append_cpp_string(b, s);
    INFO("text '" << s << "'");
    REQUIRE(a == b);
  }
  // every byte value alone and between two others
  for (unsigned c = 0; c < 256U; ++c) {
    for (const std::string &s :
         {std::string(1, static_cast<char>(c)), "x" + std::string(1, static_cast<char>(c)) + "?"}) {
      std::string a;
      std::string b;
      gen::append_cpp_string(a, s);
      reference_append_cpp_string(b, s);
      CHECK(a == b);
    }
  }
}

TEST_CASE("file_bytes / read_bytes: a file whole, mapped or read; failures named") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "fieldcodec_reader_speed_test";
  fs::create_directories(dir);
  // bigger than read_bytes' first block, not a multiple of a page
  std::string content;
  for (int i = 0; content.size() < 200000U; ++i) content += "Line" + std::to_string(i) + "=x\r\n";
  content += '\0';
  content += "end";
  const fs::path big = dir / "big.eds";
  std::ofstream(big, std::ios::binary) << content;
  const fs::path empty = dir / "empty.eds";
  std::ofstream(empty, std::ios::binary).flush();

  gen::file_bytes mapped;
  REQUIRE(mapped.load(big.string()) == nullptr);
  CHECK(mapped.view() == content);
  std::string read;
  REQUIRE(gen::read_bytes(big.string(), read) == nullptr);
  CHECK(read == content);

  gen::file_bytes none;
  REQUIRE(none.load(empty.string()) == nullptr);
  CHECK(none.view().empty());
  CHECK(gen::read_bytes(empty.string(), read) == nullptr);
  CHECK(read.empty());

  gen::file_bytes missing;
  CHECK(std::string_view(missing.load((dir / "nosuch.eds").string())) == "cannot open file");
  CHECK(std::string_view(gen::read_bytes((dir / "nosuch.eds").string(), read)) ==
        "cannot open file");
  gen::file_bytes directory;
  CHECK(std::string_view(directory.load(dir.string())) == "cannot read file");

  gen::diagnostics d;
  CHECK_FALSE(gen::read_file(dir.string() + "/", d));
  REQUIRE(d.all().size() == 1U);
  CHECK(gen::diagnostics::format(d.all()[0]).find("error: cannot read file") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("eds: keys in any case, repeated keys, many unknown keys, merged sections") {
  const std::string head = "[FileInfo]\nFileName=t.eds\n[DeviceInfo]\nVendorName=v\n";
  // known keys in any case; a repeated known key in another case is found (presence mask)
  auto a =
      diagnostics_of(head + "[1000]\nparametername=Device type\nOBJECTTYPE=0x7\n"
                            "DataType=0x0007\naccesstype=ro\nDefaultValue=1\n"
                            "DEFAULTVALUE=2\n[MandatoryObjects]\nSupportedObjects=1\n1=0x1000\n");
  CHECK(has(a,
            "t.eds:11:1: warning: key 'DEFAULTVALUE' appears again in [1000] (first at line 10); "
            "the last value is used"));
  CHECK(a.size() == 1U);
  // more than 16 unknown keys: found through the map, in any case
  std::string many = head + "[Tool1]\n";
  for (int i = 0; i < 20; ++i) many += "Key" + std::to_string(i) + "=" + std::to_string(i) + "\n";
  many += "KEY7=again\nkey19=again\nNew=1\n[1000]\nParameterName=x\nDataType=0x7\n"
          "AccessType=ro\n[MandatoryObjects]\nSupportedObjects=1\n1=0x1000\n";
  auto b = diagnostics_of(many);
  CHECK(has(b, "t.eds:26:1: warning: key 'KEY7' appears again in [Tool1] (first at line 13); the "
               "last value is used"));
  CHECK(has(b, "t.eds:27:1: warning: key 'key19' appears again in [Tool1] (first at line 25); "
               "the last value is used"));
  CHECK(b.size() == 2U);
  // fewer: compared one by one, in any case
  auto c =
      diagnostics_of(head + "[Tool1]\nAbc=1\nabc=2\n[1000]\nParameterName=x\nDataType=0x7\n"
                            "AccessType=ro\n[MandatoryObjects]\nSupportedObjects=1\n1=0x1000\n");
  CHECK(has(c, "t.eds:7:1: warning: key 'abc' appears again in [Tool1] (first at line 6); the "
               "last value is used"));
  CHECK(c.size() == 1U);
  // a section written twice: its keys are merged, a key of both is a repetition
  gen::diagnostics d;
  auto dict = gen::read_eds(head + "[Comments]\nLines=1\nline1=first\n[1000]\nParameterName=x\n"
                                   "DataType=0x7\nAccessType=ro\n[MandatoryObjects]\n"
                                   "SupportedObjects=1\n1=0x1000\n[comments]\nLINE2=second\n",
                            "t.eds", d);
  REQUIRE(dict);
  CHECK(dict->comments == std::vector<std::string>{"first", "second"});
  std::vector<std::string> m;
  for (const auto &x : d.all()) m.push_back(gen::diagnostics::format(x));
  CHECK(has(m, "t.eds:15:2: warning: section [comments] appears again (first at line 5); keys "
               "are merged"));
}
