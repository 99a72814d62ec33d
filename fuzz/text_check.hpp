// Checks of text the host tools print, for the fuzz harnesses: well-formed UTF-8 and one JSON
// value per RFC 8259 (strict: no trailing commas, no NaN, no control characters in strings,
// escapes as the RFC lists them, surrogate pairs paired), nothing but blanks after it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace fuzz_text {

/// Well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF).
inline bool valid_utf8(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80U) {
      ++i;
      continue;
    }
    std::size_t n = 0;
    std::uint32_t cp = 0;
    std::uint32_t min = 0;
    if ((c & 0xE0U) == 0xC0U) {
      n = 1;
      cp = c & 0x1FU;
      min = 0x80U;
    } else if ((c & 0xF0U) == 0xE0U) {
      n = 2;
      cp = c & 0x0FU;
      min = 0x800U;
    } else if ((c & 0xF8U) == 0xF0U) {
      n = 3;
      cp = c & 0x07U;
      min = 0x10000U;
    } else {
      return false;
    }
    if (i + n >= s.size()) return false; // the sequence is cut
    for (std::size_t k = 1; k <= n; ++k) {
      const auto d = static_cast<unsigned char>(s[i + k]);
      if ((d & 0xC0U) != 0x80U) return false;
      cp = (cp << 6U) | (d & 0x3FU);
    }
    if (cp < min || cp > 0x10FFFFU || (cp >= 0xD800U && cp <= 0xDFFFU)) return false;
    i += n + 1U;
  }
  return true;
}

/// A strict JSON parser that only says whether the text is one JSON value.
class json_checker {
public:
  explicit json_checker(std::string_view s) : s_(s) {}

  /// One value, blanks around it, nothing else; depth at most `max_depth`.
  bool document() {
    blanks();
    if (!value(0)) return false;
    blanks();
    return at_ == s_.size();
  }
  /// The same, and the value is an object.
  bool object_document() {
    blanks();
    if (at_ >= s_.size() || s_[at_] != '{') return false;
    return document();
  }

private:
  static constexpr int max_depth = 64;

  bool value(int depth) {
    if (depth > max_depth || at_ >= s_.size()) return false;
    switch (s_[at_]) {
    case '{': return object(depth);
    case '[': return array(depth);
    case '"': return string();
    case 't': return word("true");
    case 'f': return word("false");
    case 'n': return word("null");
    default: return number();
    }
  }
  bool object(int depth) {
    ++at_; // {
    blanks();
    if (peek('}')) return true;
    for (;;) {
      blanks();
      if (at_ >= s_.size() || s_[at_] != '"' || !string()) return false;
      blanks();
      if (!peek(':')) return false;
      blanks();
      if (!value(depth + 1)) return false;
      blanks();
      if (peek('}')) return true;
      if (!peek(',')) return false;
    }
  }
  bool array(int depth) {
    ++at_; // [
    blanks();
    if (peek(']')) return true;
    for (;;) {
      blanks();
      if (!value(depth + 1)) return false;
      blanks();
      if (peek(']')) return true;
      if (!peek(',')) return false;
    }
  }
  bool string() {
    ++at_; // "
    std::size_t start = at_;
    while (at_ < s_.size()) {
      const auto c = static_cast<unsigned char>(s_[at_]);
      if (c == '"') {
        const bool ok = valid_utf8(s_.substr(start, at_ - start));
        ++at_;
        return ok;
      }
      if (c < 0x20U) return false;
      if (c != '\\') {
        ++at_;
        continue;
      }
      if (!valid_utf8(s_.substr(start, at_ - start))) return false;
      ++at_;
      if (at_ >= s_.size()) return false;
      const char e = s_[at_++];
      if (e == 'u') {
        std::uint32_t u = 0;
        if (!hex4(u)) return false;
        if (u >= 0xD800U && u <= 0xDBFFU) { // a high surrogate: a low one must follow
          if (at_ + 2U > s_.size() || s_[at_] != '\\' || s_[at_ + 1U] != 'u') return false;
          at_ += 2U;
          std::uint32_t lo = 0;
          if (!hex4(lo) || lo < 0xDC00U || lo > 0xDFFFU) return false;
        } else if (u >= 0xDC00U && u <= 0xDFFFU) {
          return false;
        }
      } else if (std::string_view("\"\\/bfnrt").find(e) == std::string_view::npos) {
        return false;
      }
      start = at_;
    }
    return false;
  }
  bool hex4(std::uint32_t &u) {
    if (at_ + 4U > s_.size()) return false;
    for (int k = 0; k < 4; ++k) {
      const char c = s_[at_++];
      int d = -1;
      if (c >= '0' && c <= '9') d = c - '0';
      if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
      if (c >= 'A' && c <= 'F') d = c - 'A' + 10;
      if (d < 0) return false;
      u = u * 16U + static_cast<std::uint32_t>(d);
    }
    return true;
  }
  bool number() {
    (void)peek('-');
    if (at_ >= s_.size()) return false;
    if (s_[at_] == '0') {
      ++at_;
    } else if (digit()) {
      while (digit()) {
      }
    } else {
      return false;
    }
    if (peek('.')) {
      if (!digit()) return false;
      while (digit()) {
      }
    }
    if (at_ < s_.size() && (s_[at_] == 'e' || s_[at_] == 'E')) {
      ++at_;
      if (!peek('+')) {
        (void)peek('-');
      }
      if (!digit()) return false;
      while (digit()) {
      }
    }
    return true;
  }
  bool digit() {
    if (at_ < s_.size() && s_[at_] >= '0' && s_[at_] <= '9') {
      ++at_;
      return true;
    }
    return false;
  }
  bool word(std::string_view w) {
    if (s_.substr(at_, w.size()) != w) return false;
    at_ += w.size();
    return true;
  }
  bool peek(char c) {
    if (at_ < s_.size() && s_[at_] == c) {
      ++at_;
      return true;
    }
    return false;
  }
  void blanks() {
    while (at_ < s_.size() &&
           (s_[at_] == ' ' || s_[at_] == '\t' || s_[at_] == '\n' || s_[at_] == '\r')) {
      ++at_;
    }
  }

  std::string_view s_;
  std::size_t at_ = 0;
};

/// `s` is one JSON object (and valid UTF-8).
inline bool valid_json_object(std::string_view s) {
  return valid_utf8(s) && json_checker(s).object_document();
}

} // namespace fuzz_text
