// fieldcodec CLI — small text helpers.
#include "util.hpp"

#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/utf8.hpp>

#include <charconv>
#include <cstdio>

namespace fieldcodec::cli {

void json_object::key(std::string_view k) {
  if (!body_.empty()) body_ += ',';
  body_ += json_string(k);
  body_ += ':';
}
json_object &json_object::str(std::string_view k, std::string_view v) {
  key(k);
  body_ += json_string(v);
  return *this;
}
json_object &json_object::num(std::string_view k, std::int64_t v) {
  key(k);
  body_ += std::to_string(v);
  return *this;
}
json_object &json_object::unum(std::string_view k, std::uint64_t v) {
  key(k);
  body_ += std::to_string(v);
  return *this;
}
json_object &json_object::dec(std::string_view k, decimal v) {
  key(k);
  body_ += decimal_text(v);
  return *this;
}
json_object &json_object::real(std::string_view k, double v) {
  key(k);
  // JSON has no NaN or infinity: those go as strings
  if (v != v || v > 1.7976931348623157e308 || v < -1.7976931348623157e308) {
    body_ += json_string(real_text(v));
  } else {
    body_ += real_text(v);
  }
  return *this;
}
json_object &json_object::boolean(std::string_view k, bool v) {
  key(k);
  body_ += v ? "true" : "false";
  return *this;
}
json_object &json_object::raw(std::string_view k, std::string_view json) {
  key(k);
  body_ += json;
  return *this;
}

std::string json_string(std::string_view s) {
  std::string out = "\"";
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80U) {
      const std::size_t n = utf8::sequence_length(s, i);
      if (n != 0U) {
        out.append(s.substr(i, n));
        i += n;
      } else {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04X", static_cast<unsigned>(u));
        out += buf;
        ++i;
      }
      continue;
    }
    switch (c) {
    case '"': out += "\\\""; break;
    case '\\': out += "\\\\"; break;
    case '\n': out += "\\n"; break;
    case '\r': out += "\\r"; break;
    case '\t': out += "\\t"; break;
    default:
      if (u < 0x20U || u == 0x7FU) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04X", static_cast<unsigned>(u));
        out += buf;
      } else {
        out += c;
      }
    }
    ++i;
  }
  out += '"';
  return out;
}

std::string capped(std::string_view s, std::size_t max) {
  if (s.size() <= max) return std::string(s);
  return std::string(s.substr(0, max)) + "… (" + std::to_string(s.size()) + " characters)";
}

std::string hex_bytes(std::span<const std::uint8_t> b, std::string_view sep) {
  static constexpr char digits[] = "0123456789ABCDEF";
  std::string out;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (i != 0U) out += sep;
    out += digits[b[i] >> 4U];
    out += digits[b[i] & 0xFU];
  }
  return out;
}

std::string hex(std::uint64_t v, int digits) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%0*llX", digits, static_cast<unsigned long long>(v));
  return buf;
}

std::string address_text(od::address a) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04Xh:%02X", static_cast<unsigned>(a.index),
                static_cast<unsigned>(a.sub));
  return buf;
}

std::string decimal_text(decimal d) {
  char buf[48]{};
  auto n = format_decimal(d, buf);
  if (!n) return "?";
  return std::string(buf, n.value());
}

std::string real_text(double v) {
  if (v != v) return "NaN";
  if (v > 1.7976931348623157e308) return "Infinity";
  if (v < -1.7976931348623157e308) return "-Infinity";
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

bool parse_uint(std::string_view s, std::uint64_t max, std::uint64_t &out) {
  bool hex = false;
  if (s.size() > 2U && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    s.remove_prefix(2);
    hex = true;
  } else if (s.size() > 1U && (s.back() == 'h' || s.back() == 'H')) {
    s.remove_suffix(1);
    hex = true;
  }
  const auto v = hex ? ascii::parse_hex(s) : ascii::parse_unsigned(s);
  if (!v || v.value() > max) return false;
  out = v.value();
  return true;
}

bool parse_address(std::string_view s, od::address &out) {
  std::string_view index = s;
  std::string_view sub = "0";
  if (const auto c = s.find(':'); c != std::string_view::npos) {
    index = s.substr(0, c);
    sub = s.substr(c + 1U);
  } else if (const auto k = s.find("sub"); k != std::string_view::npos) {
    index = s.substr(0, k);
    sub = s.substr(k + 3U);
  }
  // the index is always hex; "0x" or "h" may be written
  std::string idx(index);
  if (idx.size() > 2U && idx[0] == '0' && (idx[1] == 'x' || idx[1] == 'X')) idx = idx.substr(2);
  if (!idx.empty() && (idx.back() == 'h' || idx.back() == 'H')) idx.pop_back();
  std::uint64_t i = 0;
  std::uint64_t n = 0;
  if (!parse_uint("0x" + idx, 0xFFFF, i)) return false;
  // a sub-index with "0x"/"h" is hex, otherwise hex too when written with two digits as in
  // "1018h:01"; plain decimal digits are read as hex as well (CANopen tools write sub-indices in
  // hex): "1018:10" is sub-index 16
  std::string sb(sub);
  if (sb.size() > 2U && sb[0] == '0' && (sb[1] == 'x' || sb[1] == 'X')) sb = sb.substr(2);
  if (!sb.empty() && (sb.back() == 'h' || sb.back() == 'H')) sb.pop_back();
  if (!parse_uint("0x" + sb, 0xFF, n)) return false;
  out = {static_cast<std::uint16_t>(i), static_cast<std::uint8_t>(n)};
  return true;
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> out;
  while (!text.empty()) {
    const auto nl = text.find('\n');
    std::string_view l = text.substr(0, nl);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    out.push_back(l);
    if (nl == std::string_view::npos) break;
    text.remove_prefix(nl + 1U);
  }
  return out;
}

} // namespace fieldcodec::cli
