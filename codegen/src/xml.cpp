// fieldcodec-gen — the XML reader and writer (xml.hpp).
#include "xml.hpp"

#include "text.hpp"

#include <fieldcodec/core/ascii.hpp>

#include <algorithm>
#include <cstring>
#include <utility>

namespace fieldcodec::gen::xml {

document::document() : store(std::make_unique<storage>()) {}
document::document(document &&) noexcept = default;
document &document::operator=(document &&) noexcept = default;
document::~document() = default;

const attribute *element::find_attribute(std::string_view local_name,
                                         bool any_prefix) const noexcept {
  for (const auto &a : attributes) {
    if (a.local == local_name && (any_prefix || a.name.size() == a.local.size())) return &a;
  }
  return nullptr;
}

const element *element::find_child(std::string_view local_name) const noexcept {
  for (const auto &c : children) {
    if (c.local == local_name) return &c;
  }
  return nullptr;
}

std::vector<const element *> element::children_named(std::string_view local_name) const {
  std::vector<const element *> out;
  for (const auto &c : children) {
    if (c.local == local_name) out.push_back(&c);
  }
  return out;
}

namespace {

constexpr std::string_view xml_ns = "http://www.w3.org/XML/1998/namespace";
constexpr std::string_view xmlns_ns = "http://www.w3.org/2000/xmlns/";

bool is_space(char c) noexcept { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool name_start(char ch) noexcept {
  const auto c = static_cast<unsigned char>(ch);
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == ':' || c >= 0x80U;
}
bool name_char(char ch) noexcept {
  return name_start(ch) || (ch >= '0' && ch <= '9') || ch == '-' || ch == '.';
}
// XML 1.0 Char, for character references
bool xml_char(std::uint32_t cp) noexcept {
  return cp == 0x9U || cp == 0xAU || cp == 0xDU || (cp >= 0x20U && cp <= 0xD7FFU) ||
         (cp >= 0xE000U && cp <= 0xFFFDU) || (cp >= 0x10000U && cp <= 0x10FFFFU);
}

// Encoding names as the declaration may write them, compared in upper case without '-', '_'.
std::string encoding_key(std::string_view name) {
  std::string k;
  for (char c : name) {
    if (c == '-' || c == '_') continue;
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    k += c;
  }
  return k;
}

enum class byte_encoding { utf8, latin1, windows_1252, ascii, utf16, unknown };

byte_encoding classify_encoding(std::string_view name) {
  const std::string k = encoding_key(name);
  if (k == "UTF8") return byte_encoding::utf8;
  if (k == "ISO88591" || k == "ISO885911987" || k == "LATIN1" || k == "L1" || k == "CP819" ||
      k == "IBM819" || k == "ISOIR100" || k == "CSISOLATIN1") {
    return byte_encoding::latin1;
  }
  if (k == "WINDOWS1252" || k == "CP1252") return byte_encoding::windows_1252;
  if (k == "USASCII" || k == "ASCII" || k == "ANSIX3.41968" || k == "ISO646US") {
    return byte_encoding::ascii;
  }
  if (k == "UTF16" || k == "UTF16LE" || k == "UTF16BE" || k == "ISO10646UCS2" || k == "UCS2") {
    return byte_encoding::utf16;
  }
  return byte_encoding::unknown;
}

// The value of the encoding pseudo-attribute of an XML declaration at the start of `t` (bytes,
// ASCII as far as the declaration goes), and where it is. Empty when there is none.
std::pair<std::string_view, std::size_t> sniff_encoding(std::string_view t) {
  if (t.size() < 6 || t.substr(0, 5) != "<?xml" || !is_space(t[5])) return {{}, 0};
  const auto end = t.find("?>");
  const std::string_view decl = t.substr(0, end == std::string_view::npos ? t.size() : end);
  auto at = decl.find("encoding");
  while (at != std::string_view::npos) {
    std::size_t i = at + 8U;
    while (i < decl.size() && is_space(decl[i])) ++i;
    if (i < decl.size() && decl[i] == '=') {
      ++i;
      while (i < decl.size() && is_space(decl[i])) ++i;
      if (i < decl.size() && (decl[i] == '"' || decl[i] == '\'')) {
        const auto close = decl.find(decl[i], i + 1U);
        if (close != std::string_view::npos) return {decl.substr(i + 1U, close - i - 1U), i + 1U};
      }
      return {{}, 0};
    }
    at = decl.find("encoding", at + 1U);
  }
  return {{}, 0};
}

// Positions: line and column of a byte offset of UTF-8 text, counted forward from the last
// offset asked for (a reader asks in document order; going back recounts from the start).
class tracker {
public:
  explicit tracker(std::string_view t) : t_(t) {}
  position at(std::size_t off) {
    if (off < off_) {
      off_ = 0;
      line_ = 1;
      col_ = 0;
    }
    off = std::min(off, t_.size());
    for (; off_ < off; ++off_) {
      const char c = t_[off_];
      if (c == '\n') {
        ++line_;
        col_ = 0;
      } else if (c == '\r') {
        if (off_ + 1U < t_.size() && t_[off_ + 1U] == '\n') continue;
        ++line_;
        col_ = 0;
      } else if ((static_cast<unsigned char>(c) & 0xC0U) != 0x80U) {
        ++col_;
      }
    }
    return {line_, col_ + 1};
  }

private:
  std::string_view t_;
  std::size_t off_ = 0;
  int line_ = 1;
  int col_ = 0;
};

struct ns_binding {
  std::string_view prefix;
  std::string_view uri;
  std::size_t depth;
};

class parser {
public:
  parser(const std::string &file, diagnostics &diag, const limits &lim)
      : file_(file), diag_(diag), lim_(lim), pos_({}) {}

  std::optional<document> run(std::string_view bytes) {
    document doc;
    if (!decode(bytes, doc)) return std::nullopt;
    t_ = doc.store->text;
    pos_ = tracker(t_);
    store_ = doc.store.get();
    if (!check_characters()) return std::nullopt;
    if (!prolog(doc)) return std::nullopt;
    if (!root(doc)) return std::nullopt;
    if (!epilog()) return std::nullopt;
    doc.element_count = elements_;
    return doc;
  }

private:
  // ---- diagnostics --------------------------------------------------------------------------
  bool fail_at(position p, std::string msg) {
    diag_.error(file_, p.line, p.column, std::move(msg));
    return false;
  }
  bool fail(std::size_t off, std::string msg) { return fail_at(pos_.at(off), std::move(msg)); }

  // ---- decoding -----------------------------------------------------------------------------
  bool decode(std::string_view bytes, document &doc) {
    if (bytes.size() > lim_.max_bytes) {
      diag_.error(file_, 0, 0,
                  "file of " + std::to_string(bytes.size()) +
                      " bytes is larger than the limit of " + std::to_string(lim_.max_bytes) +
                      " bytes of the XML reader");
      return false;
    }
    const auto b = [&](std::size_t i) {
      return i < bytes.size() ? static_cast<unsigned char>(bytes[i]) : 0x100U;
    };
    if ((b(0) == 0xFFU && b(1) == 0xFEU && b(2) == 0U && b(3) == 0U) ||
        (b(0) == 0U && b(1) == 0U && b(2) == 0xFEU && b(3) == 0xFFU)) {
      diag_.error(file_, 1, 1, "UTF-32 (byte-order mark) is not supported; use UTF-8 or UTF-16");
      return false;
    }
    if (b(0) == 0xFFU && b(1) == 0xFEU) return decode_utf16(bytes.substr(2), true, true, doc);
    if (b(0) == 0xFEU && b(1) == 0xFFU) return decode_utf16(bytes.substr(2), false, true, doc);
    if (b(0) == 0x3CU && b(1) == 0U && b(2) == 0x3FU && b(3) == 0U) {
      return decode_utf16(bytes, true, false, doc);
    }
    if (b(0) == 0U && b(1) == 0x3CU && b(2) == 0U && b(3) == 0x3FU) {
      return decode_utf16(bytes, false, false, doc);
    }
    if (b(0) == 0x4CU && b(1) == 0x6FU && b(2) == 0xA7U && b(3) == 0x94U) {
      diag_.error(file_, 1, 1, "EBCDIC is not supported; use UTF-8");
      return false;
    }
    bool bom = false;
    if (b(0) == 0xEFU && b(1) == 0xBBU && b(2) == 0xBFU) {
      bom = true;
      bytes.remove_prefix(3);
    }
    doc.byte_order_mark = bom;
    const auto [declared, declared_at] = sniff_encoding(bytes);
    doc.declared_encoding = std::string(declared);
    byte_encoding enc = declared.empty() ? byte_encoding::utf8 : classify_encoding(declared);
    tracker raw(bytes);
    if (enc == byte_encoding::unknown) {
      return fail_at(raw.at(declared_at),
                     "encoding '" + std::string(declared) +
                         "' is not supported (UTF-8, UTF-16, ISO-8859-1, Windows-1252 and "
                         "US-ASCII are)");
    }
    if (enc == byte_encoding::utf16) {
      return fail_at(raw.at(declared_at), "the declaration names encoding '" +
                                              std::string(declared) +
                                              "' but the file is not UTF-16 (no byte-order mark)");
    }
    if (bom && enc != byte_encoding::utf8) {
      return fail_at(raw.at(declared_at), "the declaration names encoding '" +
                                              std::string(declared) +
                                              "' but the file starts with a UTF-8 byte-order mark");
    }
    std::string &out = doc.store->text;
    switch (enc) {
    case byte_encoding::utf8: {
      const std::size_t bad = utf8_invalid_at(bytes);
      if (bad != std::string_view::npos) {
        return fail_at(
            raw.at(bad),
            "byte 0x" + hex(static_cast<unsigned char>(bytes[bad]), 2) + " is not UTF-8" +
                (declared.empty()
                     ? " (the declaration names no encoding, so the file "
                       "must be UTF-8)"
                     : " (the declaration names encoding '" + std::string(declared) + "')"));
      }
      out.assign(bytes);
      doc.encoding = "UTF-8";
      break;
    }
    case byte_encoding::ascii: {
      for (std::size_t i = 0; i < bytes.size(); ++i) {
        if (static_cast<unsigned char>(bytes[i]) >= 0x80U) {
          return fail_at(raw.at(i), "byte 0x" + hex(static_cast<unsigned char>(bytes[i]), 2) +
                                        " is not US-ASCII (the declaration names encoding '" +
                                        std::string(declared) + "')");
        }
      }
      out.assign(bytes);
      doc.encoding = "US-ASCII";
      break;
    }
    case byte_encoding::latin1:
    case byte_encoding::windows_1252:
      out = latin1_to_utf8(bytes, enc == byte_encoding::windows_1252);
      doc.encoding = enc == byte_encoding::latin1 ? "ISO-8859-1" : "Windows-1252";
      break;
    default: break;
    }
    return true;
  }

  bool decode_utf16(std::string_view bytes, bool little, bool bom, document &doc) {
    doc.byte_order_mark = bom;
    doc.encoding = little ? "UTF-16LE" : "UTF-16BE";
    std::string &out = doc.store->text;
    out.reserve(bytes.size() / 2U);
    const auto unit = [&](std::size_t i) -> std::uint32_t {
      const auto lo = static_cast<unsigned char>(bytes[little ? i : i + 1U]);
      const auto hi = static_cast<unsigned char>(bytes[little ? i + 1U : i]);
      return lo | (static_cast<std::uint32_t>(hi) << 8U);
    };
    const auto here = [&] {
      tracker t(out);
      return t.at(out.size());
    };
    std::size_t i = 0;
    for (; i + 1U < bytes.size(); i += 2U) {
      std::uint32_t u = unit(i);
      if (u >= 0xD800U && u < 0xDC00U) {
        const std::uint32_t lo = i + 3U < bytes.size() ? unit(i + 2U) : 0U;
        if (lo < 0xDC00U || lo >= 0xE000U) {
          return fail_at(here(), "unpaired UTF-16 surrogate 0x" + hex(u, 4));
        }
        u = 0x10000U + ((u - 0xD800U) << 10U) + (lo - 0xDC00U);
        i += 2U;
      } else if (u >= 0xDC00U && u < 0xE000U) {
        return fail_at(here(), "unpaired UTF-16 surrogate 0x" + hex(u, 4));
      }
      append_utf8(out, u);
    }
    if (i < bytes.size()) {
      return fail_at(here(), "odd number of bytes in a UTF-16 file (the last character is cut)");
    }
    const auto [declared, declared_at] = sniff_encoding(out);
    doc.declared_encoding = std::string(declared);
    if (!declared.empty()) {
      const std::string k = encoding_key(declared);
      if (classify_encoding(declared) != byte_encoding::utf16 || (k == "UTF16LE" && !little) ||
          (k == "UTF16BE" && little)) {
        tracker t(out);
        return fail_at(t.at(declared_at), "the declaration names encoding '" +
                                              std::string(declared) + "' but the file is " +
                                              doc.encoding);
      }
    }
    return true;
  }

  // Characters XML 1.0 does not allow anywhere: C0 controls other than TAB, LF and CR, and the
  // non-characters U+FFFE and U+FFFF.
  bool check_characters() {
    for (std::size_t i = 0; i < t_.size(); ++i) {
      // eight bytes at a time: (w - 0x20..) & ~w & 0x80.. flags a byte below 0x20; the bytes
      // 0xEF (U+FFFE/U+FFFF start) are looked at one by one
      while (i + 8U <= t_.size()) {
        std::uint64_t w = 0;
        std::memcpy(&w, t_.data() + i, 8);
        if (((w - 0x2020202020202020U) & ~w & 0x8080808080808080U) != 0U) break;
        if (std::memchr(t_.data() + i, 0xEF, 8) != nullptr) break;
        i += 8U;
      }
      if (i >= t_.size()) break;
      const auto c = static_cast<unsigned char>(t_[i]);
      if (c < 0x20U && c != '\t' && c != '\n' && c != '\r') {
        return fail(i, "character U+" + hex(c, 4) + " is not allowed in XML" +
                           (c == 0U ? " (binary data, or UTF-16 without a byte-order mark?)" : ""));
      }
      if (c == 0xEFU && i + 2U < t_.size() && t_[i + 1U] == '\xBF' &&
          (t_[i + 2U] == '\xBE' || t_[i + 2U] == '\xBF')) {
        return fail(i, std::string("character U+") + (t_[i + 2U] == '\xBE' ? "FFFE" : "FFFF") +
                           " is not allowed in XML");
      }
    }
    return true;
  }

  // ---- lexing helpers -----------------------------------------------------------------------
  bool at_end() const noexcept { return p_ >= t_.size(); }
  bool looking_at(std::string_view s) const noexcept { return t_.substr(p_, s.size()) == s; }
  void skip_space() noexcept {
    while (p_ < t_.size() && is_space(t_[p_])) ++p_;
  }
  std::string quoted(std::size_t off) const {
    if (off >= t_.size()) return "the end of the file";
    std::size_t n = 1;
    while (off + n < t_.size() && (static_cast<unsigned char>(t_[off + n]) & 0xC0U) == 0x80U) ++n;
    const std::string_view c = t_.substr(off, n);
    if (c == "\n" || c == "\r") return "a line end";
    return "'" + std::string(c) + "'";
  }
  bool expect(char c, const char *what) {
    if (p_ < t_.size() && t_[p_] == c) {
      ++p_;
      return true;
    }
    return fail(p_, std::string("expected ") + what + ", got " + quoted(p_));
  }
  // A Name at p_ (advances over it); empty after an error.
  std::string_view name(const char *what) {
    if (at_end() || !name_start(t_[p_])) {
      fail(p_, std::string("expected ") + what + ", got " + quoted(p_));
      return {};
    }
    const std::size_t start = p_;
    while (p_ < t_.size() && name_char(t_[p_])) ++p_;
    return t_.substr(start, p_ - start);
  }

  // A reference at p_ ('&'): its text appended to `out`. False after an error.
  bool reference(std::string &out) {
    const std::size_t amp = p_;
    ++p_;
    if (p_ < t_.size() && t_[p_] == '#') {
      ++p_;
      unsigned base = 10;
      if (p_ < t_.size() && t_[p_] == 'x') {
        base = 16;
        ++p_;
      }
      std::uint32_t cp = 0;
      const std::size_t digits = p_;
      while (p_ < t_.size() && t_[p_] != ';') {
        const char c = t_[p_];
        const int digit = base == 16 ? ascii::hex_value(c) : (ascii::is_digit(c) ? c - '0' : -1);
        if (digit < 0) {
          return fail(p_, std::string("expected ") +
                              (base == 16 ? "a hexadecimal digit" : "a digit") +
                              " or ';' in a character reference, got " + quoted(p_));
        }
        if (cp > 0x10FFFFU) cp = 0x110000U; // stays out of range, no overflow
        cp = cp * base + static_cast<std::uint32_t>(digit);
        ++p_;
      }
      if (at_end()) return fail(amp, "character reference without ';'");
      if (p_ == digits) return fail(p_, "expected digits in a character reference");
      if (!xml_char(cp)) {
        return fail(amp, "character reference '" + std::string(t_.substr(amp, p_ + 1U - amp)) +
                             "' is not an XML character");
      }
      ++p_;
      append_utf8(out, cp);
      return true;
    }
    const std::size_t start = p_;
    while (p_ < t_.size() && name_char(t_[p_])) ++p_;
    const std::string_view n = t_.substr(start, p_ - start);
    if (at_end() || t_[p_] != ';' || n.empty()) {
      return fail(amp, "'&' must start a reference such as '&amp;' (write a literal '&' as "
                       "'&amp;')");
    }
    ++p_;
    if (n == "lt") {
      out += '<';
    } else if (n == "gt") {
      out += '>';
    } else if (n == "amp") {
      out += '&';
    } else if (n == "apos") {
      out += '\'';
    } else if (n == "quot") {
      out += '"';
    } else {
      return fail(amp, "unknown entity '&" + std::string(n) +
                           ";' (only &lt; &gt; &amp; &apos; &quot; and character references; "
                           "the reader reads no DTD)");
    }
    return true;
  }

  // ---- prolog, misc, epilog ----------------------------------------------------------------
  bool prolog(document &doc) {
    if (looking_at("<?xml") && p_ + 5U < t_.size() && is_space(t_[p_ + 5U])) {
      if (!declaration(doc)) return false;
    }
    return misc(true);
  }

  // <?xml version="1.0" encoding="…" standalone="yes|no"?>
  bool declaration(document &doc) {
    (void)doc;
    const std::size_t start = p_;
    p_ += 5U;
    const std::string_view keys[] = {"version", "encoding", "standalone"};
    std::size_t next = 0;
    for (;;) {
      const std::size_t before = p_;
      skip_space();
      if (looking_at("?>")) {
        p_ += 2U;
        break;
      }
      if (at_end()) return fail(start, "XML declaration without '?>'");
      if (p_ == before)
        return fail(p_, "expected white space in the XML declaration, got " + quoted(p_));
      const std::size_t key_at = p_;
      const std::string_view k = name("a pseudo-attribute of the XML declaration");
      if (k.empty()) return false;
      std::size_t i = next;
      while (i < std::size(keys) && keys[i] != k) ++i;
      if (i == std::size(keys)) {
        return fail(key_at, "unexpected '" + std::string(k) +
                                "' in the XML declaration (version, encoding, standalone in this "
                                "order)");
      }
      if (next == 0 && i != 0) return fail(key_at, "the XML declaration must start with version");
      next = i + 1U;
      skip_space();
      if (!expect('=', "'='")) return false;
      skip_space();
      if (at_end() || (t_[p_] != '"' && t_[p_] != '\'')) {
        return fail(p_, "expected a quoted value, got " + quoted(p_));
      }
      const char q = t_[p_++];
      const std::size_t v0 = p_;
      while (p_ < t_.size() && t_[p_] != q) ++p_;
      if (at_end()) return fail(v0, "unterminated value in the XML declaration");
      const std::string_view v = t_.substr(v0, p_ - v0);
      ++p_;
      if (k == "version" && (v.size() < 3 || v.substr(0, 2) != "1.")) {
        return fail(v0, "XML version '" + std::string(v) + "' is not supported (1.x is)");
      }
      if (k == "standalone" && v != "yes" && v != "no") {
        return fail(v0, "expected standalone 'yes' or 'no', got '" + std::string(v) + "'");
      }
    }
    if (next == 0) return fail(start, "the XML declaration must give the version");
    return true;
  }

  // Comments, processing instructions and white space (before or after the root element).
  bool misc(bool before_root) {
    for (;;) {
      skip_space();
      if (at_end()) return true;
      if (looking_at("<!--")) {
        if (!comment()) return false;
      } else if (looking_at("<?")) {
        if (!processing_instruction()) return false;
      } else if (looking_at("<!DOCTYPE")) {
        return fail(p_, "document type declarations (<!DOCTYPE …>) are not supported: the reader "
                        "reads no DTD");
      } else if (t_[p_] == '<' && before_root) {
        return true;
      } else if (t_[p_] == '<') {
        return fail(p_, "a second root element (a document has one)");
      } else {
        return fail(p_, std::string(before_root ? "expected '<' to start the root element"
                                                : "text after the root element") +
                            ", got " + quoted(p_));
      }
    }
  }

  bool epilog() { return misc(false); }

  bool comment() {
    const std::size_t start = p_;
    p_ += 4U;
    const auto end = t_.find("--", p_);
    if (end == std::string_view::npos) return fail(start, "comment without '-->'");
    if (end + 2U >= t_.size() || t_[end + 2U] != '>') {
      return fail(end, "'--' inside a comment (XML allows it only in the closing '-->')");
    }
    p_ = end + 3U;
    return true;
  }

  bool processing_instruction() {
    const std::size_t start = p_;
    p_ += 2U;
    const std::string_view target = name("a processing instruction target");
    if (target.empty()) return false;
    if (target.size() == 3 && encoding_key(target) == "XML") {
      return fail(start, "an XML declaration is allowed only at the very start of the file");
    }
    const auto end = t_.find("?>", p_);
    if (end == std::string_view::npos) return fail(start, "processing instruction without '?>'");
    if (end != p_ && !is_space(t_[p_])) {
      return fail(p_, "expected white space after the processing instruction target, got " +
                          quoted(p_));
    }
    p_ = end + 2U;
    return true;
  }

  // ---- elements -----------------------------------------------------------------------------
  std::string_view intern(std::string_view uri) {
    if (uri == xml_ns) return xml_ns;
    auto it = store_->uris.find(uri);
    if (it == store_->uris.end()) it = store_->uris.emplace(uri).first;
    return *it;
  }

  // The URI of `prefix` in scope (empty view when unbound; "" prefix: the default namespace).
  bool lookup(std::string_view prefix, std::string_view &uri) const {
    if (prefix == "xml") {
      uri = xml_ns;
      return true;
    }
    for (auto it = scope_.rbegin(); it != scope_.rend(); ++it) {
      if (it->prefix == prefix) {
        uri = it->uri;
        return !uri.empty() || prefix.empty();
      }
    }
    uri = {};
    return prefix.empty();
  }

  static std::string_view prefix_of(std::string_view qname) {
    const auto colon = qname.find(':');
    return colon == std::string_view::npos ? std::string_view{} : qname.substr(0, colon);
  }
  static std::string_view local_of(std::string_view qname) {
    const auto colon = qname.find(':');
    return colon == std::string_view::npos ? qname : qname.substr(colon + 1U);
  }

  // A start tag at p_ ('<'): the element is appended to `parent` (or is the root). Returns
  // nullptr after an error; `empty` tells an empty-element tag.
  element *start_tag(element *parent, document &doc, bool &empty) {
    if (++elements_ > lim_.max_elements) {
      fail(p_, "more than " + std::to_string(lim_.max_elements) +
                   " elements (the limit of the XML reader)");
      return nullptr;
    }
    if (stack_.size() >= lim_.max_depth) {
      fail(p_, "elements nested deeper than " + std::to_string(lim_.max_depth) +
                   " levels (the limit of the XML reader)");
      return nullptr;
    }
    const position at = pos_.at(p_);
    ++p_;
    const std::string_view qname = name("an element name");
    if (qname.empty()) return nullptr;
    element &e = parent == nullptr ? doc.root : parent->children.emplace_back();
    e.name = qname;
    e.at = at;
    const std::size_t depth = stack_.size() + 1U;
    // attributes
    for (;;) {
      const std::size_t before = p_;
      skip_space();
      if (at_end()) {
        fail_at(at, "start tag '<" + std::string(qname) + "' without '>'");
        return nullptr;
      }
      if (t_[p_] == '>' || looking_at("/>")) break;
      if (p_ == before) {
        fail(p_, "expected white space, '>' or '/>' in the start tag '<" + std::string(qname) +
                     "', got " + quoted(p_));
        return nullptr;
      }
      if (!attribute_of(e, depth)) return nullptr;
    }
    empty = t_[p_] == '/';
    p_ += empty ? 2U : 1U;
    // namespaces of the element and its attributes
    if (!lookup(prefix_of(qname), e.ns)) {
      fail_at(at, "undeclared namespace prefix '" + std::string(prefix_of(qname)) + "' in '<" +
                      std::string(qname) + ">'");
      return nullptr;
    }
    e.local = local_of(qname);
    if (prefix_of(qname) == "xmlns") {
      fail_at(at, "the prefix 'xmlns' cannot name an element");
      return nullptr;
    }
    for (std::size_t i = 0; i < e.attributes.size(); ++i) {
      attribute &a = e.attributes[i];
      const std::string_view pre = prefix_of(a.name);
      a.local = local_of(a.name);
      if (!pre.empty() && !lookup(pre, a.ns)) {
        fail_at(a.at, "undeclared namespace prefix '" + std::string(pre) + "' in attribute '" +
                          std::string(a.name) + "'");
        return nullptr;
      }
      for (std::size_t j = 0; j < i; ++j) {
        const attribute &b = e.attributes[j];
        if (!a.ns.empty() && a.ns == b.ns && a.local == b.local) {
          fail_at(a.at, "attribute '" + std::string(a.name) + "' is the same as '" +
                            std::string(b.name) + "' (namespace " + std::string(a.ns) + ")");
          return nullptr;
        }
      }
    }
    return &e;
  }

  // One attribute at p_ of element `e` (its start tag at nesting `depth`).
  bool attribute_of(element &e, std::size_t depth) {
    const std::size_t name_at = p_;
    const position at = pos_.at(p_);
    const std::string_view qname = name("an attribute name");
    if (qname.empty()) return false;
    skip_space();
    if (!expect('=', ("'=' after attribute '" + std::string(qname) + "'").c_str())) return false;
    skip_space();
    if (at_end() || (t_[p_] != '"' && t_[p_] != '\'')) {
      return fail(p_, "expected a quoted value for attribute '" + std::string(qname) + "', got " +
                          quoted(p_));
    }
    const char q = t_[p_++];
    const position value_at = pos_.at(p_);
    std::string value;
    for (;;) {
      const std::size_t start = p_;
      while (p_ < t_.size() && t_[p_] != q && t_[p_] != '&' && t_[p_] != '<' && t_[p_] != '\t' &&
             t_[p_] != '\n' && t_[p_] != '\r') {
        ++p_;
      }
      value.append(t_.substr(start, p_ - start));
      if (at_end())
        return fail_at(value_at,
                       "value of attribute '" + std::string(qname) + "' without its closing quote");
      const char c = t_[p_];
      if (c == q) {
        ++p_;
        break;
      }
      if (c == '<') {
        return fail(p_, "'<' in the value of attribute '" + std::string(qname) +
                            "' (write it as '&lt;')");
      }
      if (c == '&') {
        if (!reference(value)) return false;
        continue;
      }
      // white space normalisation (XML 1.0 3.3.3): TAB, LF, CR and CR LF become one space
      if (c == '\r' && p_ + 1U < t_.size() && t_[p_ + 1U] == '\n') ++p_;
      value += ' ';
      ++p_;
    }
    for (const auto &a : e.attributes) {
      if (a.name == qname) {
        return fail_at(at, "attribute '" + std::string(qname) + "' appears twice in '<" +
                               std::string(e.name) + ">' (first at line " +
                               std::to_string(a.at.line) + ", column " +
                               std::to_string(a.at.column) + ")");
      }
    }
    // namespace declarations go into scope, not into the attributes
    if (qname == "xmlns" || qname.substr(0, 6) == "xmlns:") {
      const std::string_view prefix = qname.size() > 5 ? qname.substr(6) : std::string_view{};
      if (prefix == "xmlns" || (prefix == "xml" && value != xml_ns) ||
          (prefix != "xml" && (value == xml_ns || value == xmlns_ns))) {
        return fail_at(at, "reserved namespace declaration '" + std::string(qname) + "=\"" + value +
                               "\"'");
      }
      if (!prefix.empty() && value.empty()) {
        return fail_at(value_at, "namespace prefix '" + std::string(prefix) +
                                     "' bound to an empty URI (XML namespaces 1.0 forbids it)");
      }
      if (qname.size() == 6) return fail(name_at, "expected a prefix after 'xmlns:'");
      for (const auto &b : scope_) {
        if (b.depth == depth && b.prefix == prefix) {
          return fail_at(at, "namespace declaration '" + std::string(qname) +
                                 "' appears twice in '<" + std::string(e.name) + ">'");
        }
      }
      scope_.push_back({prefix, intern(value), depth});
      e.namespaces.emplace_back(prefix, scope_.back().uri);
      return true;
    }
    if (e.attributes.size() >= lim_.max_attributes) {
      return fail_at(at, "more than " + std::to_string(lim_.max_attributes) +
                             " attributes in one element (the limit of the XML reader)");
    }
    attribute &a = e.attributes.emplace_back();
    a.name = qname;
    a.value = std::move(value);
    a.at = at;
    a.value_at = value_at;
    return true;
  }

  // Character data from p_ up to the next '<' into e.text.
  bool char_data(element &e) {
    std::string &out = e.text;
    while (p_ < t_.size() && t_[p_] != '<') {
      const std::size_t start = p_;
      while (p_ < t_.size() && t_[p_] != '<' && t_[p_] != '&' && t_[p_] != '\r' && t_[p_] != ']') {
        ++p_;
      }
      note_text(e, start, p_);
      out.append(t_.substr(start, p_ - start));
      if (at_end() || t_[p_] == '<') break;
      const char c = t_[p_];
      if (c == '&') {
        note_text(e, p_, p_ + 1U);
        if (!reference(out)) return false;
      } else if (c == '\r') {
        if (p_ + 1U < t_.size() && t_[p_ + 1U] == '\n') ++p_;
        out += '\n';
        ++p_;
      } else { // ']'
        if (looking_at("]]>")) return fail(p_, "']]>' in character data (write '>' as '&gt;')");
        note_text(e, p_, p_ + 1U);
        out += ']';
        ++p_;
      }
    }
    return true;
  }

  // Remembers where the element's text starts: its first character that is not white space.
  void note_text(element &e, std::size_t from, std::size_t to) {
    if (e.text_at.line != 0) return;
    for (std::size_t i = from; i < to; ++i) {
      if (!is_space(t_[i])) {
        e.text_at = pos_.at(i);
        return;
      }
    }
  }

  bool cdata(element &e) {
    const std::size_t start = p_;
    p_ += 9U;
    const auto end = t_.find("]]>", p_);
    if (end == std::string_view::npos) return fail(start, "CDATA section without ']]>'");
    const std::string_view body = t_.substr(p_, end - p_);
    note_text(e, p_, end);
    for (std::size_t i = 0; i < body.size(); ++i) { // line ends as LF
      if (body[i] == '\r') {
        if (i + 1U < body.size() && body[i + 1U] == '\n') continue;
        e.text += '\n';
      } else {
        e.text += body[i];
      }
    }
    p_ = end + 3U;
    return true;
  }

  bool end_tag(element &e) {
    const std::size_t start = p_;
    p_ += 2U;
    const std::string_view n = name("an element name in the end tag");
    if (n.empty()) return false;
    if (n != e.name) {
      return fail(start, "end tag '</" + std::string(n) + ">' does not match '<" +
                             std::string(e.name) + ">' (line " + std::to_string(e.at.line) +
                             ", column " + std::to_string(e.at.column) + ")");
    }
    skip_space();
    return expect('>', ("'>' to end '</" + std::string(n) + "'").c_str());
  }

  // An element is complete: text that is only white space beside child elements is dropped.
  static void finish(element &e) {
    if (!e.children.empty() &&
        std::all_of(e.text.begin(), e.text.end(), [](char c) { return is_space(c); })) {
      e.text.clear();
      e.text_at = {};
    }
  }

  void close_scope(std::size_t depth) {
    while (!scope_.empty() && scope_.back().depth >= depth) scope_.pop_back();
  }

  bool root(document &doc) {
    if (at_end()) return fail(p_, "expected the root element, got the end of the file");
    bool empty = false;
    element *r = start_tag(nullptr, doc, empty);
    if (r == nullptr) return false;
    if (empty) {
      close_scope(1);
      finish(*r);
      return true;
    }
    stack_.push_back(r);
    while (!stack_.empty()) {
      element &e = *stack_.back();
      if (!char_data(e)) return false;
      if (at_end()) {
        return fail_at(e.at, "element '<" + std::string(e.name) +
                                 ">' is not closed (the file "
                                 "ends before '</" +
                                 std::string(e.name) + ">')");
      }
      if (looking_at("</")) {
        if (!end_tag(e)) return false;
        finish(e);
        close_scope(stack_.size());
        stack_.pop_back();
      } else if (looking_at("<!--")) {
        if (!comment()) return false;
      } else if (looking_at("<![CDATA[")) {
        if (!cdata(e)) return false;
      } else if (looking_at("<?")) {
        if (!processing_instruction()) return false;
      } else if (looking_at("<!")) {
        return fail(p_, looking_at("<!DOCTYPE")
                            ? "document type declarations are not supported (and belong before "
                              "the root element)"
                            : "expected '<!--' or '<![CDATA[' after '<!'");
      } else {
        element *child = start_tag(&e, doc, empty);
        if (child == nullptr) return false;
        if (empty) {
          close_scope(stack_.size() + 1U);
          finish(*child);
        } else {
          stack_.push_back(child);
        }
      }
    }
    return true;
  }

  const std::string &file_;
  diagnostics &diag_;
  const limits &lim_;
  std::string_view t_;
  document::storage *store_ = nullptr;
  tracker pos_;
  std::size_t p_ = 0;
  std::size_t elements_ = 0;
  std::vector<element *> stack_;
  std::vector<ns_binding> scope_;
};

} // namespace

std::optional<document> parse(std::string_view bytes, const std::string &file, diagnostics &diag,
                              const limits &lim) {
  parser p(file, diag, lim);
  return p.run(bytes);
}

// ---- writer ---------------------------------------------------------------------------------

writer::writer() { out_ = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"; }

void writer::append_escaped(std::string &out, std::string_view s, bool attribute) {
  for (const char c : s) {
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"':
      if (attribute) {
        out += "&quot;";
      } else {
        out += c;
      }
      break;
    case '\r': out += "&#13;"; break;
    case '\n':
      if (attribute) {
        out += "&#10;";
      } else {
        out += c;
      }
      break;
    case '\t':
      if (attribute) {
        out += "&#9;";
      } else {
        out += c;
      }
      break;
    default: out += c;
    }
  }
}

void writer::finish_start_tag() {
  if (in_start_tag_) {
    out_ += '>';
    in_start_tag_ = false;
  }
}

void writer::comment(std::string_view text) {
  finish_start_tag();
  if (!stack_.empty()) {
    stack_.back().has_children = true;
    out_ += '\n';
    out_.append(2U * stack_.size(), ' ');
  }
  out_ += "<!-- ";
  for (std::size_t i = 0; i < text.size(); ++i) {
    out_ += text[i];
    if (text[i] == '-' && (i + 1U == text.size() || text[i + 1U] == '-')) out_ += ' ';
  }
  out_ += " -->";
  if (stack_.empty()) out_ += '\n';
}

void writer::open(std::string_view name) {
  finish_start_tag();
  if (!stack_.empty()) {
    open_element &parent = stack_.back();
    parent.has_children = true;
    if (!parent.has_text) {
      out_ += '\n';
      out_.append(2U * stack_.size(), ' ');
    }
  }
  out_ += '<';
  out_ += name;
  in_start_tag_ = true;
  stack_.push_back({std::string(name), false, false});
}

void writer::attribute(std::string_view name, std::string_view value) {
  out_ += ' ';
  out_ += name;
  out_ += "=\"";
  append_escaped(out_, value, true);
  out_ += '"';
}

void writer::text(std::string_view value) {
  if (value.empty()) return;
  finish_start_tag();
  stack_.back().has_text = true;
  append_escaped(out_, value, false);
}

void writer::close() {
  const open_element top = std::move(stack_.back());
  stack_.pop_back();
  if (in_start_tag_) {
    out_ += "/>";
    in_start_tag_ = false;
  } else {
    if (top.has_children && !top.has_text) {
      out_ += '\n';
      out_.append(2U * stack_.size(), ' ');
    }
    out_ += "</";
    out_ += top.name;
    out_ += '>';
  }
  if (stack_.empty()) out_ += '\n';
}

void writer::leaf(std::string_view name, std::string_view value) {
  open(name);
  text(value);
  close();
}

} // namespace fieldcodec::gen::xml
