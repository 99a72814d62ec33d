// fieldcodec — an entry's value as text, both ways, on top of od/engineering.hpp: what a tool
// prints for a value is exactly what it accepts back, in the same unit, and gives the same
// bytes (format_value → parse_value round-trips for every value the entry's limits allow).
//
//   // p::pressure_limit: UNSIGNED32 in bar, scale 327.67, limits 0..5000 (od/engineering.hpp)
//   char text[64];
//   od::format_value(p::pressure_limit, bytes, text)  → "4.001"        (EU, round trip places)
//   od::parse_value(p::pressure_limit, "4.0", out)    → raw 1311 in 4 bytes
//   od::parse_value(p::pressure_limit, "0x10", out)   → value_error{bad_syntax, hex_is_raw}
//   od::parse_value(p::pressure_limit, "0x10", out, {.unit = od::value_unit::raw}) → raw 16
//   od::parse_value(limit_i_force_in_ma, "1500 mA", out) → raw 150 (a scale of 0.1, unit "mA")
//
// The text of a value (docs/od.md, "Values as text"):
// * integers: decimal ("-20000"), or "0x…" hex digits (upper or lower case) where hex means the
//   same number — an entry that is not scaled, or any entry with value_unit::raw. A scaled
//   entry in engineering units takes decimals only ("4.001"): hex spells a raw value there,
//   and an input's meaning must not change with its spelling (value_issue::hex_is_raw). A
//   fraction is allowed for a scaled entry and rounded half away from zero; for any other
//   integer it must be zero ("5.0"). The entry's unit may follow the number ("1500 mA",
//   "1500mA"); another unit is refused (value_issue::unit).
// * REAL32 / REAL64: the shortest text that reads back as the same float / double ("0.1",
//   "1e+20", "-0", "inf"); parsing rounds correctly to the type.
// * BOOLEAN: true / false (1 / 0 accepted).
// * TIME_OF_DAY: "2024-05-01T12:34:56.789" (days after 1984-01-01 as a date; the hours go past
//   23 only for a millisecond count beyond one day); TIME_DIFFERENCE: "3d 01:02:03.004".
// * VISIBLE_STRING: in double quotes with \" \\ and \xHH escapes ("\"Drive \\x01\""); unquoted
//   text is taken as it is. UNICODE_STRING: the same with \uXXXX for a UTF-16 unit (unquoted:
//   UTF-8). OCTET_STRING / DOMAIN: hex bytes "2B 00 18" (separators ' ', '.', ':' optional), or
//   a quoted string; the empty value is "".
// Reading never applies a string's capacity (a device's value is shown as it is); writing does.
#pragma once

#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/core/calendar.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/utf8.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/engineering.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/value.hpp>

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <system_error>

namespace fieldcodec::od {

/// Characters format_number writes at most, without the unit suffix.
inline constexpr std::size_t number_text_max = 40;

namespace detail {

/// Appends to a span of characters; remembers when it ran out of room.
struct text_writer {
  std::span<char> out;
  std::size_t n = 0;
  bool full = false;

  constexpr void put(char c) noexcept {
    if (n < out.size()) {
      out[n++] = c;
    } else {
      full = true;
    }
  }
  constexpr void put(std::string_view s) noexcept {
    for (const char c : s) put(c);
  }
  /// `v` in decimal, at least `width` digits.
  constexpr void number(std::uint64_t v, std::size_t width = 1) noexcept {
    char tmp[20]{};
    auto r = ascii::format_unsigned(v, tmp);
    const std::size_t len = r ? r.value() : 0U;
    for (std::size_t i = len; i < width; ++i) put('0');
    put(std::string_view(tmp, len));
  }
  [[nodiscard]] constexpr result<std::size_t> done() const noexcept {
    if (full) return errc::buffer_too_small;
    return n;
  }
};

[[nodiscard]] constexpr bool is_space(char c) noexcept { return c == ' ' || c == '\t'; }

[[nodiscard]] constexpr bool has_hex_prefix(std::string_view s) noexcept {
  return s.size() >= 2U && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
}

/// `text` without the entry's unit after it ("1500 mA", "1500mA" → "1500"). Errors:
/// bad_syntax / unit when a word follows the number that is not the unit.
[[nodiscard]] constexpr result<std::string_view, value_error>
strip_unit(std::string_view text, std::string_view unit) noexcept {
  if (has_hex_prefix(text)) return text; // hex spells a raw number: no unit ("0x1A" is no "A")
  if (!unit.empty() && text.size() > unit.size() &&
      text.substr(text.size() - unit.size()) == unit) {
    text.remove_suffix(unit.size());
    if (!text.empty() && is_space(text.back())) text.remove_suffix(1);
    return text;
  }
  // "1500 A": a word after the number that is not the entry's unit
  if (const auto sp = text.rfind(' '); sp != std::string_view::npos && sp + 1U < text.size()) {
    value_error e{errc::bad_syntax, value_issue::unit};
    e.position = static_cast<std::uint32_t>(sp + 1U);
    return e;
  }
  return text;
}

/// The first offset in `s` that is no digit, sign or point (for a syntax error's position).
[[nodiscard]] constexpr std::uint32_t bad_position(std::string_view s) noexcept {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (!ascii::is_digit(c) && c != '-' && c != '.') return static_cast<std::uint32_t>(i);
  }
  return static_cast<std::uint32_t>(s.size());
}

[[nodiscard]] constexpr value_error syntax_error(errc c, std::uint32_t position) noexcept {
  value_error e{c, value_issue::syntax};
  e.position = position;
  return e;
}

/// An integer ("-12", "18446744073709551615", "5.000", "0x1F"). Hex only when allowed.
[[nodiscard]] constexpr result<number, value_error> parse_integer(std::string_view s,
                                                                  bool hex_allowed) noexcept {
  if (has_hex_prefix(s)) {
    if (!hex_allowed) return value_error{errc::bad_syntax, value_issue::hex_is_raw};
    auto h = ascii::parse_hex(s.substr(2));
    if (!h) return syntax_error(h.error(), 2U);
    return unsigned_number(h.value());
  }
  if (s.find('.') == std::string_view::npos) {
    if (!s.empty() && s.front() == '-') {
      auto v = ascii::parse_signed(s);
      if (!v) return syntax_error(v.error(), bad_position(s));
      return signed_number(v.value());
    }
    auto v = ascii::parse_unsigned(s);
    if (!v) return syntax_error(v.error(), bad_position(s));
    return unsigned_number(v.value());
  }
  auto d = parse_decimal(s);
  if (!d) return syntax_error(d.error(), bad_position(s));
  auto i = to_fixed(d.value(), 0);
  if (!i) {
    return i.error() == errc::not_representable
               ? value_error{errc::not_representable, value_issue::not_integer}
               : value_error{i.error()};
  }
  return signed_number(i.value());
}

/// "HH:MM:SS[.mmm]" → milliseconds (the hours may exceed 23). Errors: bad_syntax, out_of_range.
[[nodiscard]] constexpr result<std::uint64_t> parse_clock(std::string_view s) noexcept {
  const auto c1 = s.find(':');
  if (c1 == std::string_view::npos) return errc::bad_syntax;
  const auto c2 = s.find(':', c1 + 1U);
  if (c2 == std::string_view::npos || c2 != c1 + 3U) return errc::bad_syntax;
  const auto dot = s.find('.', c2 + 1U);
  const std::string_view secs =
      s.substr(c2 + 1U, dot == std::string_view::npos ? s.npos : dot - c2 - 1U);
  if (secs.size() != 2U) return errc::bad_syntax;
  FIELDCODEC_TRY(const std::uint64_t h, ascii::parse_unsigned(s.substr(0, c1)));
  FIELDCODEC_TRY(const std::uint64_t m, ascii::parse_unsigned(s.substr(c1 + 1U, 2)));
  FIELDCODEC_TRY(const std::uint64_t sec, ascii::parse_unsigned(secs));
  std::uint64_t ms = 0;
  if (dot != std::string_view::npos) {
    const std::string_view frac = s.substr(dot + 1U);
    if (frac.empty() || frac.size() > 3U) return errc::bad_syntax;
    FIELDCODEC_TRY(const std::uint64_t f, ascii::parse_unsigned(frac));
    ms = f * (frac.size() == 1U ? 100U : frac.size() == 2U ? 10U : 1U);
  }
  if (m > 59U || sec > 59U || h > 1000U) return errc::out_of_range;
  return ((h * 60U + m) * 60U + sec) * 1000U + ms;
}

[[nodiscard]] constexpr result<number, value_error> parse_time(data_type type,
                                                               std::string_view s) noexcept {
  std::uint64_t days = 0;
  std::string_view clock;
  if (type == data_type::time_of_day) {
    // YYYY-MM-DDTHH:MM:SS.mmm (or a space for the T)
    if (s.size() < 11U || s[4] != '-' || s[7] != '-' || (s[10] != 'T' && s[10] != ' ')) {
      return syntax_error(errc::bad_syntax, 0);
    }
    auto y = ascii::parse_unsigned(s.substr(0, 4));
    auto mo = ascii::parse_unsigned(s.substr(5, 2));
    auto dd = ascii::parse_unsigned(s.substr(8, 2));
    if (!y || !mo || !dd) return syntax_error(errc::bad_digit, 0);
    auto n = calendar::to_days(calendar::date{static_cast<std::int32_t>(y.value()),
                                              static_cast<std::uint8_t>(mo.value()),
                                              static_cast<std::uint8_t>(dd.value())});
    if (!n) return value_error{errc::out_of_range};
    const std::int64_t after = n.value() - calendar::cia301_epoch;
    if (after < 0 || after > 0xFFFF) return value_error{errc::out_of_range};
    days = static_cast<std::uint64_t>(after);
    clock = s.substr(11);
  } else {
    // Nd HH:MM:SS.mmm
    const auto d = s.find('d');
    if (d == std::string_view::npos) return syntax_error(errc::bad_syntax, 0);
    auto n = ascii::parse_unsigned(s.substr(0, d));
    if (!n) return syntax_error(n.error(), 0);
    if (n.value() > 0xFFFFU) return value_error{errc::out_of_range};
    days = n.value();
    clock = s.substr(d + 1U);
    if (!clock.empty() && clock.front() == ' ') clock.remove_prefix(1);
  }
  auto ms = parse_clock(clock);
  if (!ms) return syntax_error(ms.error(), static_cast<std::uint32_t>(s.size() - clock.size()));
  if (ms.value() > time_ms_max) return value_error{errc::out_of_range};
  return to_number(
      time_value{static_cast<std::uint32_t>(ms.value()), static_cast<std::uint16_t>(days)});
}

/// A REAL32 / REAL64 from text, rounded correctly to the type (run time only: <charconv>).
[[nodiscard]] inline result<number, value_error> parse_real(std::string_view s,
                                                            bool single) noexcept {
  const char *first = s.data();
  const char *last = s.data() + s.size();
  if (!s.empty() && s.front() == '+') return syntax_error(errc::bad_syntax, 0);
  std::from_chars_result r{};
  double v = 0;
  if (single) {
    float f = 0;
    r = std::from_chars(first, last, f);
    v = static_cast<double>(f);
  } else {
    r = std::from_chars(first, last, v);
  }
  if (r.ec == std::errc::result_out_of_range)
    return value_error{errc::overflow, value_issue::field};
  if (r.ec != std::errc{} || r.ptr != last) {
    return syntax_error(errc::bad_syntax, static_cast<std::uint32_t>(r.ptr - first));
  }
  return real_number(v);
}

[[nodiscard]] inline result<std::size_t> format_real(double v, bool single,
                                                     text_writer &w) noexcept {
  char buf[64];
  const auto r = single ? std::to_chars(buf, buf + sizeof buf, static_cast<float>(v))
                        : std::to_chars(buf, buf + sizeof buf, v);
  if (r.ec != std::errc{}) return errc::buffer_too_small;
  w.put(std::string_view(buf, static_cast<std::size_t>(r.ptr - buf)));
  return w.n;
}

constexpr void put_clock(text_writer &w, std::uint32_t ms) noexcept {
  w.number(ms / 3600000U, 2);
  w.put(':');
  w.number(ms / 60000U % 60U, 2);
  w.put(':');
  w.number(ms / 1000U % 60U, 2);
  w.put('.');
  w.number(ms % 1000U, 3);
}

/// Appends a UTF-16LE encoding of `cp` to `out` at `n`.
constexpr bool put_utf16(std::uint32_t cp, std::span<std::uint8_t> out, std::size_t &n) noexcept {
  auto unit = [&](std::uint32_t u) {
    if (n + 2U > out.size()) return false;
    out[n++] = static_cast<std::uint8_t>(u & 0xFFU);
    out[n++] = static_cast<std::uint8_t>(u >> 8U);
    return true;
  };
  if (cp >= 0x10000U) {
    cp -= 0x10000U;
    return unit(0xD800U + (cp >> 10U)) && unit(0xDC00U + (cp & 0x3FFU));
  }
  return unit(cp);
}

/// The bytes a byte-string text stands for (see the top of the file), unchecked against the
/// entry's capacity and characters. Errors: bad_syntax / syntax, bad_digit / syntax,
/// bad_character / character (bad UTF-8), buffer_too_small.
[[nodiscard]] constexpr result<std::size_t, value_error>
parse_bytes(data_type type, std::string_view text, std::span<std::uint8_t> out) noexcept {
  std::size_t n = 0;
  auto put = [&](std::uint32_t b) {
    if (n >= out.size()) return false;
    out[n++] = static_cast<std::uint8_t>(b);
    return true;
  };
  const bool unicode = type == data_type::unicode_string;
  if (!text.empty() && text.front() == '"') {
    if (text.size() < 2U || text.back() != '"') {
      return syntax_error(errc::bad_syntax, static_cast<std::uint32_t>(text.size()));
    }
    const std::string_view body = text.substr(1, text.size() - 2U);
    std::size_t i = 0;
    while (i < body.size()) {
      const char c = body[i];
      const auto at = static_cast<std::uint32_t>(i + 1U);
      if (c == '"') return syntax_error(errc::bad_syntax, at);
      if (c != '\\') {
        if (unicode) {
          auto cp = utf8::next(body, i);
          if (!cp) {
            value_error e{errc::bad_character, value_issue::character};
            e.position = at;
            return e;
          }
          if (!put_utf16(cp.value(), out, n)) return value_error{errc::buffer_too_small};
        } else {
          if (!put(static_cast<unsigned char>(c))) return value_error{errc::buffer_too_small};
          ++i;
        }
        continue;
      }
      if (i + 1U >= body.size()) return syntax_error(errc::bad_syntax, at);
      const char k = body[i + 1U];
      if (k == '"' || k == '\\') {
        if (unicode ? !put_utf16(static_cast<unsigned char>(k), out, n)
                    : !put(static_cast<unsigned char>(k))) {
          return value_error{errc::buffer_too_small};
        }
        i += 2U;
      } else if (k == 'x' && !unicode) {
        auto v = ascii::parse_hex(body.substr(i + 2U, 2));
        if (!v || i + 4U > body.size()) return syntax_error(errc::bad_digit, at);
        if (!put(static_cast<std::uint32_t>(v.value()))) return value_error{errc::buffer_too_small};
        i += 4U;
      } else if (k == 'u' && unicode) {
        auto v = ascii::parse_hex(body.substr(i + 2U, 4));
        if (!v || i + 6U > body.size()) return syntax_error(errc::bad_digit, at);
        if (!put_utf16(static_cast<std::uint32_t>(v.value()), out, n)) {
          return value_error{errc::buffer_too_small};
        }
        i += 6U;
      } else {
        return syntax_error(errc::bad_syntax, at);
      }
    }
    return n;
  }
  if (type == data_type::visible_string) {
    for (const char c : text) {
      if (!put(static_cast<unsigned char>(c))) return value_error{errc::buffer_too_small};
    }
    return n;
  }
  if (unicode) {
    std::size_t i = 0;
    while (i < text.size()) {
      const auto at = static_cast<std::uint32_t>(i);
      auto cp = utf8::next(text, i);
      if (!cp) {
        value_error e{errc::bad_character, value_issue::character};
        e.position = at;
        return e;
      }
      if (!put_utf16(cp.value(), out, n)) return value_error{errc::buffer_too_small};
    }
    return n;
  }
  // OCTET_STRING, DOMAIN: hex bytes
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == ' ' || c == '.' || c == ':') {
      ++i;
      continue;
    }
    const int hi = ascii::hex_value(c);
    const int lo = i + 1U < text.size() ? ascii::hex_value(text[i + 1U]) : -1;
    if (hi < 0 || lo < 0) {
      return syntax_error(i + 1U < text.size() || hi < 0 ? errc::bad_digit : errc::truncated,
                          static_cast<std::uint32_t>(hi < 0 ? i : i + 1U));
    }
    if (!put(static_cast<std::uint32_t>(hi * 16 + lo))) return value_error{errc::buffer_too_small};
    i += 2U;
  }
  return n;
}

constexpr void put_hex_byte(text_writer &w, std::uint8_t b) noexcept {
  constexpr char digits[] = "0123456789ABCDEF";
  w.put(digits[b >> 4U]);
  w.put(digits[b & 0x0FU]);
}

/// A byte-string value as text (see the top of the file). Errors: bad_length (a UNICODE_STRING
/// of odd length), buffer_too_small.
[[nodiscard]] constexpr result<std::size_t>
format_bytes(data_type type, std::span<const std::uint8_t> in, std::span<char> out) noexcept {
  text_writer w{out};
  if (type == data_type::octet_string || type == data_type::domain) {
    if (in.empty()) {
      w.put("\"\"");
      return w.done();
    }
    for (std::size_t i = 0; i < in.size(); ++i) {
      if (i != 0U) w.put(' ');
      put_hex_byte(w, in[i]);
    }
    return w.done();
  }
  if (type == data_type::unicode_string) {
    if (in.size() % 2U != 0U) return errc::bad_length;
    w.put('"');
    for (std::size_t i = 0; i < in.size(); i += 2U) {
      const auto u = static_cast<std::uint32_t>(in[i] | (in[i + 1U] << 8U));
      if (u == '"' || u == '\\') {
        w.put('\\');
        w.put(static_cast<char>(u));
      } else if (u >= 0x20U && u <= 0x7EU) {
        w.put(static_cast<char>(u));
      } else {
        w.put("\\u");
        put_hex_byte(w, static_cast<std::uint8_t>(u >> 8U));
        put_hex_byte(w, static_cast<std::uint8_t>(u & 0xFFU));
      }
    }
    w.put('"');
    return w.done();
  }
  // VISIBLE_STRING: trailing NULs are padding (od::decode_bytes)
  std::size_t n = in.size();
  while (n > 0U && in[n - 1U] == 0U) --n;
  w.put('"');
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t b = in[i];
    if (b == '"' || b == '\\') {
      w.put('\\');
      w.put(static_cast<char>(b));
    } else if (b >= 0x20U && b <= 0x7EU) {
      w.put(static_cast<char>(b));
    } else {
      w.put("\\x");
      put_hex_byte(w, b);
    }
  }
  w.put('"');
  return w.done();
}

} // namespace detail

/// The number `text` stands for as a value of `d` in `o.unit` (not yet checked against the
/// limits: encode_value does that). See the top of the file for the spellings.
/// Errors (code / issue): bad_syntax, bad_digit / syntax (position set), bad_syntax /
/// hex_is_raw, bad_syntax / unit, not_representable / not_integer, overflow (beyond 64 bits),
/// type_mismatch / type (a byte-string entry), out_of_range (a date or time field).
[[nodiscard]] constexpr result<number, value_error>
parse_number(const descriptor &d, std::string_view text, value_options o = {}) noexcept {
  if (is_byte_string(d.type)) return value_error{errc::type_mismatch, value_issue::type};
  if (d.type == data_type::boolean) {
    if (text == "true" || text == "1") return unsigned_number(1);
    if (text == "false" || text == "0") return unsigned_number(0);
    return detail::syntax_error(errc::bad_syntax, 0);
  }
  if (is_time(d.type)) return detail::parse_time(d.type, text);
  // a scaled entry's raw value has no unit: "150 mA" is refused with value_unit::raw
  const bool raw_of_scaled = is_scaled(d) && o.unit == value_unit::raw;
  FIELDCODEC_TRY(const std::string_view s,
                 detail::strip_unit(text, raw_of_scaled ? std::string_view{} : d.info.unit.view()));
  if (s.empty()) return detail::syntax_error(errc::bad_syntax, 0);
  if (is_real(d.type)) {
    if (detail::has_hex_prefix(s) ||
        (s.size() > 2U && s[0] == '-' && s[1] == '0' && (s[2] == 'x' || s[2] == 'X'))) {
      return detail::syntax_error(errc::bad_syntax, 0);
    }
    return detail::parse_real(s, d.type == data_type::real32);
  }
  if (is_scaled(d) && o.unit == value_unit::engineering) {
    if (detail::has_hex_prefix(s)) return value_error{errc::bad_syntax, value_issue::hex_is_raw};
    auto v = parse_decimal(s);
    if (!v) return detail::syntax_error(v.error(), detail::bad_position(s));
    return decimal_number(v.value());
  }
  return detail::parse_integer(s, true);
}

/// A value of `d` (a number as decode_value gives it, in `o.unit`) as text: see the top of the
/// file. Returns the number of characters written. Errors: buffer_too_small, type_mismatch (a
/// byte-string entry, no value), not_representable (a number the type cannot show).
[[nodiscard]] constexpr result<std::size_t>
format_number(const descriptor &d, number v, std::span<char> out, value_options o = {}) noexcept {
  detail::text_writer w{out};
  if (is_byte_string(d.type) || !v) return errc::type_mismatch;
  if (d.type == data_type::boolean) {
    w.put(v.bits != 0U ? "true" : "false");
    return w.done();
  }
  if (is_time(d.type)) {
    FIELDCODEC_TRY(const time_value t, to_time(v));
    if (d.type == data_type::time_of_day) {
      const calendar::date day = calendar::from_days(calendar::cia301_epoch + t.days);
      w.number(static_cast<std::uint64_t>(day.year), 4);
      w.put('-');
      w.number(day.month, 2);
      w.put('-');
      w.number(day.day, 2);
      w.put('T');
    } else {
      w.number(t.days);
      w.put("d ");
    }
    detail::put_clock(w, t.ms);
    return w.done();
  }
  const bool show_unit =
      o.unit_suffix && !d.info.unit.empty() && !(is_scaled(d) && o.unit == value_unit::raw);
  if (is_real(d.type)) {
    if (auto r = detail::format_real(v.to_double(), d.type == data_type::real32, w); !r) {
      return r.error();
    }
  } else if (v.kind == number_kind::decimal_) {
    char buf[48]{};
    FIELDCODEC_TRY(const std::size_t n,
                   format_decimal(decimal{static_cast<std::int64_t>(v.bits), v.places}, buf));
    w.put(std::string_view(buf, n));
  } else if (v.kind == number_kind::signed_ && static_cast<std::int64_t>(v.bits) < 0) {
    char buf[24]{};
    FIELDCODEC_TRY(const std::size_t n,
                   ascii::format_signed(static_cast<std::int64_t>(v.bits), buf));
    w.put(std::string_view(buf, n));
  } else if (v.kind == number_kind::signed_ || v.kind == number_kind::unsigned_) {
    if (o.integers == radix::hex && !(is_scaled(d) && o.unit == value_unit::engineering)) {
      char buf[20]{};
      FIELDCODEC_TRY(const std::size_t n, ascii::format_hex(v.bits, 2U * fixed_size(d.type), buf));
      w.put("0x");
      w.put(std::string_view(buf, n));
      return w.done(); // hex spells a raw number: no unit
    }
    w.number(v.bits);
  } else {
    return errc::not_representable;
  }
  if (show_unit) {
    w.put(' ');
    w.put(d.info.unit.view());
  }
  return w.done();
}

/// The text a user typed for entry `d` as the bytes to send, at the front of `out`: numbers
/// through parse_number and encode_value (limits of node o.node, field, scale), byte strings
/// through their spellings and encode_bytes_value (capacity, characters). `out` holds the value
/// only when the result is a value (a refused number writes nothing; a refused string may have
/// been spelled out into `out` before its checks). Errors: those of parse_number, encode_value
/// and encode_bytes_value, buffer_too_small.
[[nodiscard]] constexpr result<std::size_t, value_error>
parse_value(const descriptor &d, std::string_view text, std::span<std::uint8_t> out,
            value_options o = {}) noexcept {
  if (is_byte_string(d.type)) {
    // parsed into `out` itself, then checked; on an error the caller must not use `out`
    FIELDCODEC_TRY(const std::size_t n, detail::parse_bytes(d.type, text, out));
    return encode_bytes_value(d, out.first(n), out);
  }
  FIELDCODEC_TRY(const number v, parse_number(d, text, o));
  return encode_value(d, v, out, o);
}

/// The bytes of entry `d` as text: decode_value then format_number; a byte string by its
/// spelling (capacity not applied). Errors: those of decode_value, format_number and
/// detail::format_bytes.
[[nodiscard]] constexpr result<std::size_t> format_value(const descriptor &d,
                                                         std::span<const std::uint8_t> in,
                                                         std::span<char> out,
                                                         value_options o = {}) noexcept {
  if (is_byte_string(d.type)) return detail::format_bytes(d.type, in, out);
  FIELDCODEC_TRY(const number v, decode_value(d, in, o));
  return format_number(d, v, out, o);
}

/// Characters format_value needs at most for `in` bytes of `d` (a buffer this long suffices).
[[nodiscard]] constexpr std::size_t format_size(const descriptor &d, std::size_t in) noexcept {
  if (is_byte_string(d.type)) return 4U * in + 2U; // "\xHH" per byte and the quotes
  return number_text_max + 1U + d.info.unit.size();
}

} // namespace fieldcodec::od
