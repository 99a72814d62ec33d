#include "text.hpp"

#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/utf8.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstring>
#include <limits>

namespace fieldcodec::gen {

std::string to_upper(std::string_view s) {
  std::string r(s);
  for (char &c : r) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return r;
}

std::string to_lower(std::string_view s) {
  std::string r(s);
  for (char &c : r) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return r;
}

bool iequals(std::string_view a, std::string_view b) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i];
    char y = b[i];
    if (x >= 'a' && x <= 'z') x = static_cast<char>(x - 'a' + 'A');
    if (y >= 'a' && y <= 'z') y = static_cast<char>(y - 'a' + 'A');
    if (x != y) return false;
  }
  return true;
}

std::size_t utf8_invalid_at(std::string_view s) noexcept {
  std::size_t i = 0;
  while (i < s.size()) {
    // ASCII (nearly every byte of a dictionary) eight bytes at a time
    while (i + 8U <= s.size()) {
      std::uint64_t w = 0;
      std::memcpy(&w, s.data() + i, 8);
      if ((w & 0x8080808080808080U) != 0U) break;
      i += 8U;
    }
    if (i >= s.size()) break;
    if (static_cast<unsigned char>(s[i]) < 0x80U) {
      ++i;
      continue;
    }
    if (!utf8::next(s, i)) return i; // core/utf8: the one UTF-8 reader
  }
  return std::string_view::npos;
}

bool valid_utf8(std::string_view s) noexcept {
  return utf8_invalid_at(s) == std::string_view::npos;
}

void append_utf8(std::string &out, std::uint32_t cp) {
  if (cp < 0x80U) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800U) {
    out += static_cast<char>(0xC0U | (cp >> 6U));
    out += static_cast<char>(0x80U | (cp & 0x3FU));
  } else if (cp < 0x10000U) {
    out += static_cast<char>(0xE0U | (cp >> 12U));
    out += static_cast<char>(0x80U | ((cp >> 6U) & 0x3FU));
    out += static_cast<char>(0x80U | (cp & 0x3FU));
  } else {
    out += static_cast<char>(0xF0U | (cp >> 18U));
    out += static_cast<char>(0x80U | ((cp >> 12U) & 0x3FU));
    out += static_cast<char>(0x80U | ((cp >> 6U) & 0x3FU));
    out += static_cast<char>(0x80U | (cp & 0x3FU));
  }
}

namespace {

// Windows-1252 0x80..0x9F (0 = unassigned, kept as the Latin-1 control code point)
constexpr std::array<std::uint16_t, 32> cp1252{
    0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
    0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
    0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};

} // namespace

std::string latin1_to_utf8(std::string_view bytes, bool windows_1252) {
  std::string out;
  out.reserve(bytes.size() + bytes.size() / 8U);
  for (const char ch : bytes) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x80U) {
      out += ch;
    } else if (windows_1252 && c < 0xA0U && cp1252[c - 0x80U] != 0U) {
      append_utf8(out, cp1252[c - 0x80U]);
    } else {
      append_utf8(out, c);
    }
  }
  return out;
}

std::string to_utf8(std::string_view bytes, bool &converted) {
  converted = false;
  if (bytes.size() >= 3 && bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
  if (valid_utf8(bytes)) return std::string(bytes);
  converted = true;
  return latin1_to_utf8(bytes, true);
}

std::string_view as_utf8(std::string_view bytes, std::string &storage, bool &converted) {
  converted = false;
  if (bytes.size() >= 3 && bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
  if (valid_utf8(bytes)) return bytes;
  storage = to_utf8(bytes, converted);
  return storage;
}

int_parse parse_int(std::string_view s, int_syntax syntax) {
  int_parse r;
  s = trim(s);
  const bool eds = syntax == int_syntax::eds;
  if (s.empty()) {
    r.error = "expected a number, got nothing";
    return r;
  }
  const std::size_t start = 0;
  std::size_t i = start;
  bool neg = false;
  if (s[i] == '-' || s[i] == '+') {
    neg = s[i] == '-';
    ++i;
  }
  // C integer suffixes (0x1234LL): accepted with a note
  std::size_t end = s.size();
  while (eds && end > i + 1U) {
    const char c = s[end - 1U];
    if (c == 'L' || c == 'l' || c == 'U' || c == 'u') {
      --end;
      r.suffix = true;
    } else {
      break;
    }
  }
  unsigned base = 10;
  if (end - i >= 2U && s[i] == '0' && (s[i + 1U] == 'x' || s[i + 1U] == 'X')) {
    base = 16;
    i += 2;
  } else if (!eds && end - i >= 2U && s[i] == '#' && (s[i + 1U] == 'x' || s[i + 1U] == 'X')) {
    base = 16; // ETG.2000 (ESI) hex
    i += 2;
  } else if (eds && end - i >= 2U && s[i] == '0') {
    base = 8;
    ++i;
  }
  if (i >= end) {
    r.error = "expected digits after '" + std::string(s.substr(0, i)) + "'";
    r.error_pos = i;
    return r;
  }
  std::uint64_t v = 0;
  for (std::size_t k = i; k < end; ++k) {
    const char c = s[k];
    const int hex = ascii::hex_value(c);
    const unsigned d = hex < 0 ? 99U : static_cast<unsigned>(hex);
    if (d >= base) {
      const char *what = base == 16  ? "a hexadecimal digit"
                         : base == 8 ? "an octal digit"
                                     : "a digit";
      // the whole character (core/utf8), so that the message stays UTF-8 (fuzz F23)
      const std::size_t n = utf8::sequence_length(s, k);
      r.error = std::string("expected ") + what + ", got '" +
                (n == 0U ? "\\x" + gen::hex(static_cast<std::uint8_t>(c), 2)
                         : std::string(s.substr(k, n))) +
                "' in '" + std::string(s) + "'";
      r.error_pos = k;
      r.suffix = false;
      return r;
    }
    if (v > (std::numeric_limits<std::uint64_t>::max() - d) / base) {
      r.error = "number '" + std::string(s) + "' does not fit 64 bits";
      r.error_pos = start;
      return r;
    }
    v = v * base + d;
  }
  if (neg) {
    if (v > std::uint64_t{1} << 63U) {
      r.error = "number '" + std::string(s) + "' does not fit 64 bits";
      return r;
    }
    r.value = od::signed_number(static_cast<std::int64_t>(std::uint64_t{0} - v));
  } else if (base == 10 &&
             v <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
    r.value = od::signed_number(static_cast<std::int64_t>(v));
  } else {
    r.value = od::unsigned_number(v);
  }
  r.ok = true;
  return r;
}

bool fits(od::data_type t, od::number n) {
  if (t == od::data_type::boolean) {
    auto u = n.to_uint64();
    return u && u.value() <= 1U;
  }
  const unsigned w = od::fixed_size(t);
  if (od::is_signed_integer(t)) {
    auto i = n.to_int64();
    return i && i.value() >= signed_min(w) && i.value() <= signed_max(w);
  }
  auto u = n.to_uint64();
  return u && u.value() <= unsigned_max(w);
}

std::optional<od::number> plus_node(od::number n, std::uint8_t node) {
  if (n.kind == od::number_kind::unsigned_) {
    if (n.bits > ~std::uint64_t{0} - node) return std::nullopt;
    return od::unsigned_number(n.bits + node);
  }
  auto i = n.to_int64();
  if (!i || i.value() > std::numeric_limits<std::int64_t>::max() - node) return std::nullopt;
  return od::signed_number(i.value() + node);
}

od::number integer_for_type(od::number n, od::data_type type) {
  // a signed type written as its two's complement bit pattern (LowLimit=0x80000000)
  if (od::is_signed_integer(type) && n.kind == od::number_kind::unsigned_) {
    const unsigned w = od::fixed_size(type);
    if (n.bits <= unsigned_max(w) && n.bits > static_cast<std::uint64_t>(signed_max(w))) {
      std::uint64_t b = n.bits;
      if (w < 8U) b |= ~detail::width_mask(w);
      return od::signed_number(static_cast<std::int64_t>(b));
    }
    if (n.bits <= static_cast<std::uint64_t>(signed_max(w))) {
      return od::signed_number(static_cast<std::int64_t>(n.bits));
    }
    return n;
  }
  if ((od::is_integer(type) || type == od::data_type::boolean) &&
      n.kind == od::number_kind::signed_ && static_cast<std::int64_t>(n.bits) >= 0 &&
      od::is_unsigned_integer(type)) {
    return od::unsigned_number(n.bits);
  }
  return n;
}

std::optional<double> parse_real(std::string_view s) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  double d = 0;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), d);
  if (ec != std::errc{} || p != s.data() + s.size()) return std::nullopt;
  if (d != d || d > std::numeric_limits<double>::max() || d < -std::numeric_limits<double>::max()) {
    return std::nullopt;
  }
  return d;
}

real_parse parse_real_value(std::string_view s, od::data_type type) {
  real_parse r;
  const std::string_view t = trim(s);
  std::string_view digits = t;
  const bool sign = !digits.empty() && (digits.front() == '-' || digits.front() == '+');
  if (sign) digits.remove_prefix(1);
  if (digits.size() >= 2U && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
    const bool single = type == od::data_type::real32;
    if (sign) {
      r.error = "expected a " + std::string(od::name(type)) + " bit pattern without a sign, got '" +
                std::string(t) + "'";
      return r;
    }
    const int_parse p = parse_int(t);
    if (!p.ok || p.suffix) {
      r.error = p.ok ? "expected hexadecimal digits, got '" + std::string(t) + "'" : p.error;
      r.error_pos = p.error_pos;
      return r;
    }
    const std::uint64_t bits = p.value.bits;
    if (single && bits > 0xFFFF'FFFFU) {
      r.error = "expected a REAL32 bit pattern of at most 8 hexadecimal digits, got '" +
                std::string(t) + "'";
      return r;
    }
    const double d =
        single ? static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(bits)))
               : std::bit_cast<double>(bits);
    if (d != d || d > std::numeric_limits<double>::max() ||
        d < -std::numeric_limits<double>::max()) {
      r.error = "expected a finite " + std::string(od::name(type)) + ", got '" + std::string(t) +
                "' (" + (d != d ? "NaN" : "infinity") + ")";
      return r;
    }
    r.value = d;
    r.ok = true;
    return r;
  }
  if (auto d = parse_real(t)) {
    r.value = *d;
    r.ok = true;
    return r;
  }
  const int_parse p = parse_int(t);
  if (p.ok) {
    r.value = p.value.to_double();
    r.ok = true;
    return r;
  }
  r.error = "expected a real number, got '" + std::string(t) + "'";
  return r;
}

nodeid_expr split_nodeid(std::string_view s) noexcept {
  nodeid_expr x;
  constexpr std::string_view word = "$NODEID";
  std::size_t at = std::string_view::npos;
  for (std::size_t i = 0; i + word.size() <= s.size(); ++i) {
    if (iequals(s.substr(i, word.size()), word)) {
      at = i;
      break;
    }
  }
  if (at == std::string_view::npos) return x;
  x.present = true;
  const std::string_view before = trim(s.substr(0, at));
  const std::string_view after = trim(s.substr(at + word.size()));
  auto operand_of = [&](std::string_view part) {
    x.operand = trim(part);
    x.operand_pos = x.operand.empty() ? 0U : static_cast<std::size_t>(x.operand.data() - s.data());
    x.ok = !x.operand.empty();
  };
  if (before.empty() && after.empty()) {
    x.ok = true;
  } else if (before.empty() && after.front() == '+') {
    operand_of(after.substr(1));
  } else if (after.empty() && before.back() == '+') {
    operand_of(before.substr(0, before.size() - 1U));
  }
  return x;
}

std::optional<std::string> byte_string_value(od::data_type type, std::string_view text) {
  switch (type) {
  case od::data_type::visible_string:
  case od::data_type::unicode_string: {
    if (text.size() >= 2U && text.front() == '"' && text.back() == '"') {
      text = text.substr(1, text.size() - 2U);
    }
    if (type == od::data_type::visible_string) return std::string(text);
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) { // the text is UTF-8 (the readers convert every file)
      auto next = utf8::next(text, i);
      // not UTF-8 (a reader let it through): the byte as the code point it is in Latin-1
      std::uint32_t cp = next ? next.value() : static_cast<unsigned char>(text[i++]);
      auto unit = [&](std::uint32_t u) {
        out += static_cast<char>(u & 0xFFU);
        out += static_cast<char>((u >> 8U) & 0xFFU);
      };
      if (cp >= 0x10000U) {
        cp -= 0x10000U;
        unit(0xD800U + (cp >> 10U));
        unit(0xDC00U + (cp & 0x3FFU));
      } else {
        unit(cp);
      }
    }
    return out;
  }
  case od::data_type::octet_string:
  case od::data_type::domain: {
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) {
      if (text[i] == ' ' || text[i] == '\t') {
        ++i;
        continue;
      }
      if (i + 1U >= text.size()) return std::nullopt;
      const int hi = ascii::hex_value(text[i]);
      const int lo = ascii::hex_value(text[i + 1U]);
      if (hi < 0 || lo < 0) return std::nullopt;
      out += static_cast<char>(hi * 16 + lo);
      i += 2;
    }
    return out;
  }
  default: return std::string(text);
  }
}

std::string byte_string_text(od::data_type type, std::string_view bytes) {
  switch (type) {
  case od::data_type::octet_string:
  case od::data_type::domain: {
    std::string out;
    for (const char c : bytes) out += hex(static_cast<unsigned char>(c), 2);
    return out;
  }
  case od::data_type::unicode_string: {
    std::string out;
    for (std::size_t i = 0; i + 1U < bytes.size(); i += 2) {
      std::uint32_t u =
          static_cast<unsigned char>(bytes[i]) |
          (static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1U])) << 8U);
      if (u >= 0xD800U && u < 0xDC00U && i + 3U < bytes.size()) {
        const std::uint32_t lo =
            static_cast<unsigned char>(bytes[i + 2U]) |
            (static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 3U])) << 8U);
        if (lo >= 0xDC00U && lo < 0xE000U) {
          u = 0x10000U + ((u - 0xD800U) << 10U) + (lo - 0xDC00U);
          i += 2;
        }
      }
      if (u >= 0xD800U && u < 0xE000U) u = 0xFFFDU;
      append_utf8(out, u);
    }
    return out;
  }
  default: return std::string(bytes);
  }
}

bool is_cpp_keyword(std::string_view s) noexcept {
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
  // sorted at compile time: a binary search of 97 words (every generated name is tested)
  static constexpr std::array<std::string_view, kw.size()> sorted = [] {
    auto a = kw;
    std::sort(a.begin(), a.end());
    return a;
  }();
  if (s.size() < 2U || s.size() > 16U) return false; // "do" .. "reinterpret_cast"
  return std::binary_search(sorted.begin(), sorted.end(), s);
}

bool is_identifier(std::string_view s) noexcept {
  if (s.empty()) return false;
  if (s.front() >= '0' && s.front() <= '9') return false;
  for (const char c : s) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) return false;
  }
  if (s.find("__") != std::string_view::npos) return false;
  if (s.front() == '_') return false;
  return !is_cpp_keyword(s);
}

namespace {
/// A '-' is a minus sign (not a separator) when nothing but spaces, dots and colons follow it
/// ("Limit-", "Limit- :") or when it stands before a digit after a non-alphanumeric ("jog -1").
bool sign_minus(std::string_view name, std::size_t i) {
  std::size_t j = i + 1U;
  while (j < name.size() && (name[j] == ' ' || name[j] == '.' || name[j] == ':')) ++j;
  if (j == name.size()) return true;
  const bool digit_next = i + 1U < name.size() && name[i + 1U] >= '0' && name[i + 1U] <= '9';
  const bool word_before = i > 0U && ((name[i - 1U] >= 'a' && name[i - 1U] <= 'z') ||
                                      (name[i - 1U] >= 'A' && name[i - 1U] <= 'Z') ||
                                      (name[i - 1U] >= '0' && name[i - 1U] <= '9'));
  return digit_next && !word_before;
}
} // namespace

std::size_t write_identifier(char *const out, std::string_view name) noexcept {
  // Written through a pointer into a buffer of the largest possible size (every input byte
  // gives at most "_minus" or "_plus"; the first two bytes are room for a "n_" prefix), no
  // capacity test per character.
  char *const start = out + 2;
  char *o = start;
  bool pending_sep = false;
  const auto put = [&](std::string_view t) {
    if (pending_sep && o != start) *o++ = '_';
    pending_sep = false;
    for (const char c : t) *o++ = c;
  };
  for (std::size_t i = 0; i < name.size(); ++i) {
    const auto c = static_cast<unsigned char>(name[i]);
    if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z')) {
      if (pending_sep && o != start) *o++ = '_';
      pending_sep = false;
      *o++ = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    } else if (c == 0xC3U && i + 1U < name.size()) { // UTF-8 Latin-1 supplement
      const auto d = static_cast<unsigned char>(name[i + 1U]);
      ++i;
      switch (d) {
      case 0xA4:
      case 0x84: put("ae"); break; // ä Ä
      case 0xB6:
      case 0x96: put("oe"); break; // ö Ö
      case 0xBC:
      case 0x9C: put("ue"); break; // ü Ü
      case 0x9F: put("ss"); break; // ß
      default: pending_sep = true; break;
      }
    } else if (c >= 0x80U) {
      // other non-ASCII: skip the whole UTF-8 sequence
      while (i + 1U < name.size() && (static_cast<unsigned char>(name[i + 1U]) & 0xC0U) == 0x80U) {
        ++i;
      }
      pending_sep = true;
    } else if (c == '+') {
      // "Limit+" and "Limit-" are different parameters: spell the signs out
      pending_sep = true;
      put("plus");
      pending_sep = true;
    } else if (c == '-' && o != start && sign_minus(name, i)) {
      pending_sep = true;
      put("minus");
      pending_sep = true;
    } else {
      pending_sep = true;
    }
  }
  if (o == start) return 0;
  auto n = static_cast<std::size_t>(o - start);
  if (*start >= '0' && *start <= '9') {
    out[0] = 'n';
    out[1] = '_';
    n += 2U;
  } else {
    std::memmove(out, start, n);
  }
  if (is_cpp_keyword(std::string_view(out, n))) out[n++] = '_';
  return n;
}

std::string make_identifier(std::string_view name) {
  std::string out(identifier_capacity(name.size()), '\0');
  out.resize(write_identifier(out.data(), name));
  return out;
}

std::string cpp_string(std::string_view s) {
  std::string out;
  append_cpp_string(out, s);
  return out;
}

namespace {
constexpr std::uint64_t byte_ones = 0x0101010101010101U;
constexpr std::uint64_t byte_highs = 0x8080808080808080U;
constexpr bool has_zero_byte(std::uint64_t v) noexcept {
  return ((v - byte_ones) & ~v & byte_highs) != 0U;
}
/// Whether one of eight bytes is written escaped in a string literal: below 0x20, 0x7F, '"',
/// '\\' or '?' (bytes from 0x80 up, UTF-8, are kept). Exact: each test finds whether a byte is
/// zero / below 0x20, not which one.
constexpr bool escape_in(std::uint64_t w) noexcept {
  return ((w - byte_ones * 0x20U) & ~w & byte_highs) != 0U ||
         has_zero_byte(w ^ (byte_ones * 0x7FU)) || has_zero_byte(w ^ (byte_ones * '"')) ||
         has_zero_byte(w ^ (byte_ones * '\\')) || has_zero_byte(w ^ (byte_ones * '?'));
}
/// Byte `i` of `s` as a string literal writes it.
char *write_literal_byte(char *o, std::string_view s, std::size_t i) noexcept {
  const auto c = static_cast<unsigned char>(s[i]);
  if (c >= 0x20U && c != 0x7FU && c != '"' && c != '\\' && c != '?') {
    *o++ = static_cast<char>(c);
  } else if (c == '"' || c == '\\') {
    *o++ = '\\';
    *o++ = static_cast<char>(c);
  } else if (c == '?') {
    *o++ = '?';
    if (i + 1U < s.size() && s[i + 1U] == '?') *o++ = '\\'; // never a trigraph
  } else {
    *o++ = '\\';
    *o++ = static_cast<char>('0' + ((c >> 6U) & 7U));
    *o++ = static_cast<char>('0' + ((c >> 3U) & 7U));
    *o++ = static_cast<char>('0' + (c & 7U));
  }
  return o;
}
} // namespace

char *write_cpp_string(char *o, std::string_view s) noexcept {
  *o++ = '"';
  // Eight bytes at a time: copied at once when none of them is escaped.
  std::size_t i = 0;
  while (i + 8U <= s.size()) {
    std::uint64_t w = 0;
    std::memcpy(&w, s.data() + i, 8);
    if (!escape_in(w)) {
      std::memcpy(o, &w, 8);
      o += 8;
      i += 8U;
      continue;
    }
    for (const std::size_t end = i + 8U; i < end; ++i) o = write_literal_byte(o, s, i);
  }
  for (; i < s.size(); ++i) o = write_literal_byte(o, s, i);
  *o++ = '"';
  return o;
}

void append_cpp_string(std::string &out, std::string_view s) {
  const std::size_t at = out.size();
  out.resize(at + cpp_string_capacity(s.size()));
  char *const end = write_cpp_string(out.data() + at, s);
  out.resize(static_cast<std::size_t>(end - out.data()));
}

char *write_cpp_bytes(char *o, std::string_view bytes) noexcept {
  *o++ = '"';
  for (const char ch : bytes) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20U && c < 0x7FU && c != '"' && c != '\\' && c != '?') {
      *o++ = static_cast<char>(c);
    } else {
      *o++ = '\\';
      *o++ = static_cast<char>('0' + ((c >> 6U) & 7U));
      *o++ = static_cast<char>('0' + ((c >> 3U) & 7U));
      *o++ = static_cast<char>('0' + (c & 7U));
    }
  }
  *o++ = '"';
  return o;
}

void append_cpp_value_text(std::string &out, od::data_type type, std::string_view bytes) {
  if (type == od::data_type::visible_string) {
    append_cpp_string(out, bytes);
    return;
  }
  out += "std::string_view{";
  const std::size_t at = out.size();
  out.resize(at + cpp_string_capacity(bytes.size()));
  char *const end = write_cpp_bytes(out.data() + at, bytes);
  out.resize(static_cast<std::size_t>(end - out.data()));
  out += ", " + std::to_string(bytes.size()) + "}";
}

std::string hex(std::uint64_t v, int digits) {
  static constexpr char h[] = "0123456789ABCDEF";
  std::string s;
  while (v != 0U || digits > 0) {
    s.insert(s.begin(), h[v & 0xFU]);
    v >>= 4U;
    --digits;
  }
  return s.empty() ? "0" : s;
}

} // namespace fieldcodec::gen
