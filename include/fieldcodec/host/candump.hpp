// fieldcodec — host adapters: candump's output (can-utils), read and written.
//
//   (1700000000.123456) can0 605#2B00180564000000     log line: time, interface, frame
//   605#2B00180564000000                               compact frame (cansend notation)
//   705#R  705#R1                                      remote frame (optional requested length)
//   12345678#00FF                                      extended (29-bit) frame: 8 hex digits
//   20000004#0004000000000000                          error frame (8 digits, bit 29 set)
//     can0  605   [8]  2B 00 18 05 64 00 00 00         candump's display (also with -t, -x, -a)
//
// Identifiers are 3 hex digits (base frame, at most 7FF) or 8 (extended, or an error frame when
// 0x20000000 is set); data are 0..8 pairs of hex digits, optionally separated by '.'. CAN FD
// frames ("##", "[NN]") are not CANopen CiA 301 frames and are refused. The timestamp is kept
// exactly (seconds, fraction and its number of digits), so a log read and written again is
// unchanged. A line that is no frame gets a reason and a column (line_error). Pure text: the
// caller reads and writes the lines.
#pragma once

#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/core/calendar.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/host/frame_record.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>

namespace fieldcodec::host::candump {

/// Why a line is not a frame: the errc, a short reason naming the problem, and the column
/// (0-based offset in the line) where it was found.
struct line_error {
  errc code = errc::bad_syntax;
  const char *reason = ""; ///< a string literal ("11-bit identifier above 7FF", …)
  std::uint32_t column = 0;

  constexpr line_error() noexcept = default;
  constexpr line_error(errc c) noexcept : code(c) {} // NOLINT: plain errors propagate
  constexpr line_error(errc c, const char *why, std::size_t at) noexcept
      : code(c), reason(why), column(static_cast<std::uint32_t>(at)) {}
  friend constexpr bool operator==(const line_error &a, errc b) noexcept { return a.code == b; }
};

namespace detail {
[[nodiscard]] constexpr bool is_blank(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}
[[nodiscard]] constexpr std::string_view trim(std::string_view s) noexcept {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}
/// Offset of `part` (a view into `whole`) in `whole`.
[[nodiscard]] constexpr std::size_t column(std::string_view whole, std::string_view part) noexcept {
  return static_cast<std::size_t>(part.data() - whole.data());
}
/// The next blank-separated token of `s` (removed from `s`); empty at the end.
[[nodiscard]] constexpr std::string_view next_token(std::string_view &s) noexcept {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  std::size_t n = 0;
  while (n < s.size() && !is_blank(s[n])) ++n;
  const std::string_view t = s.substr(0, n);
  s.remove_prefix(n);
  return t;
}

/// "seconds.fraction" (the inside of "(…)"). Errors: bad_syntax, bad_digit, overflow,
/// too_long (fraction > 9 digits).
[[nodiscard]] constexpr result<timestamp> parse_seconds(std::string_view s) noexcept {
  const std::size_t dot = s.find('.');
  if (dot == std::string_view::npos || dot == 0U || dot + 1U == s.size()) return errc::bad_syntax;
  timestamp t;
  for (std::size_t i = 0; i < dot; ++i) {
    const char c = s[i];
    if (!ascii::is_digit(c)) return errc::bad_digit;
    if (t.seconds > (std::numeric_limits<std::int64_t>::max() - (c - '0')) / 10) {
      return errc::overflow;
    }
    t.seconds = t.seconds * 10 + (c - '0');
  }
  const std::string_view frac = s.substr(dot + 1U);
  if (frac.size() > 9U) return errc::too_long;
  for (const char c : frac) {
    if (!ascii::is_digit(c)) return errc::bad_digit;
    t.fraction = t.fraction * 10U + static_cast<std::uint32_t>(c - '0');
  }
  t.digits = static_cast<std::uint8_t>(frac.size());
  return t;
}

/// "YYYY-MM-DD hh:mm:ss.fraction" (candump -tA). Errors: bad_syntax, bad_digit, out_of_range.
[[nodiscard]] constexpr result<timestamp> parse_date(std::string_view s) noexcept {
  if (s.size() < 21U || s[4] != '-' || s[7] != '-' || s[10] != ' ' || s[13] != ':' ||
      s[16] != ':') {
    return errc::bad_syntax;
  }
  FIELDCODEC_TRY(const std::uint64_t y, ascii::parse_unsigned(s.substr(0, 4)));
  FIELDCODEC_TRY(const std::uint64_t mo, ascii::parse_unsigned(s.substr(5, 2)));
  FIELDCODEC_TRY(const std::uint64_t d, ascii::parse_unsigned(s.substr(8, 2)));
  FIELDCODEC_TRY(const std::uint64_t h, ascii::parse_unsigned(s.substr(11, 2)));
  FIELDCODEC_TRY(const std::uint64_t mi, ascii::parse_unsigned(s.substr(14, 2)));
  FIELDCODEC_TRY(timestamp t, parse_seconds(s.substr(17)));
  if (h > 23U || mi > 59U || t.seconds > 60) return errc::out_of_range;
  FIELDCODEC_TRY(const std::int64_t days,
                 calendar::to_days({static_cast<std::int32_t>(y), static_cast<std::uint8_t>(mo),
                                    static_cast<std::uint8_t>(d)}));
  t.seconds += days * 86400 + static_cast<std::int64_t>(h * 3600U + mi * 60U);
  t.date = true;
  return t;
}

/// The time inside "(…)": seconds (log, -ta, -td, -tz) or a date (-tA).
[[nodiscard]] constexpr result<timestamp> parse_time(std::string_view s) noexcept {
  if (s.size() >= 5U && s[4] == '-') return parse_date(s);
  return parse_seconds(s);
}

/// The long display's frame: ID "[N]" then N hex bytes, "remote request", or more after the
/// data that candump adds (ERRORFRAME, -a's 'ascii'). `line` is the whole line (for columns).
[[nodiscard]] constexpr result<frame_record, line_error>
parse_long(std::string_view line, std::string_view rest) noexcept {
  const std::string_view id = next_token(rest);
  if (id.empty()) return line_error{errc::bad_syntax, "no identifier", line.size()};
  if (id.size() != 3U && id.size() != 8U) {
    return line_error{errc::bad_syntax,
                      "identifier of 3 hex digits (11-bit) or 8 (29-bit) expected",
                      column(line, id)};
  }
  frame_record r;
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < id.size(); ++i) {
    const int v = ascii::hex_value(id[i]);
    if (v < 0) return line_error{errc::bad_digit, "not a hex digit", column(line, id) + i};
    value = value * 16U + static_cast<std::uint32_t>(v);
  }
  if (id.size() == 3U) {
    if (value > 0x7FFU) {
      return line_error{errc::invalid_argument, "11-bit identifier above 7FF", column(line, id)};
    }
    r.id = value;
  } else {
    if ((value & 0xC0000000U) != 0U) {
      return line_error{errc::invalid_argument, "29-bit identifier with bit 30 or 31 set",
                        column(line, id)};
    }
    r.error = (value & 0x20000000U) != 0U;
    r.extended = !r.error;
    r.id = value & 0x1FFFFFFFU;
  }
  const std::string_view dlc = next_token(rest);
  if (dlc.size() == 4U && dlc.front() == '[' && dlc.back() == ']') {
    return line_error{errc::unexpected_frame, "CAN FD frame ([NN]): not a CiA 301 frame",
                      column(line, dlc)};
  }
  if (dlc.size() != 3U || dlc.front() != '[' || dlc.back() != ']' || !ascii::is_digit(dlc[1])) {
    return line_error{errc::bad_syntax,
                      "the length \"[0]\" … \"[8]\" expected after the identifier",
                      dlc.empty() ? line.size() : column(line, dlc)};
  }
  if (dlc[1] > '8') return line_error{errc::bad_length, "length above 8", column(line, dlc) + 1U};
  r.dlc = static_cast<std::uint8_t>(dlc[1] - '0');
  std::string_view after = rest;
  if (next_token(after) == "remote" && next_token(after) == "request") {
    if (r.error) return line_error{errc::bad_syntax, "an error frame is no remote frame", 0};
    r.rtr = true;
    rest = after;
  } else {
    for (std::size_t i = 0; i < r.dlc; ++i) {
      const std::string_view b = next_token(rest);
      if (b.empty()) {
        return line_error{errc::truncated, "fewer data bytes than the length says", line.size()};
      }
      const int byte = b.size() == 2U ? ascii::hex_byte(b[0], b[1]) : -1;
      if (byte < 0) {
        return line_error{errc::bad_digit, "a data byte of two hex digits expected",
                          column(line, b)};
      }
      r.data[i] = static_cast<std::uint8_t>(byte);
    }
  }
  // what candump writes after the data: ERRORFRAME (an error frame), 'ASCII' (-a)
  const std::string_view tail = trim(rest);
  if (tail.empty() || (r.error && tail == "ERRORFRAME") || tail.front() == '\'') return r;
  return line_error{errc::bad_syntax, "unexpected text after the data", column(line, tail)};
}
} // namespace detail

/// True for a line that holds no frame: empty, blanks only, a comment starting with '#', or a
/// line of candump -e's explanation of an error frame (it starts with a tab).
[[nodiscard]] constexpr bool is_blank_or_comment(std::string_view line) noexcept {
  if (!line.empty() && line.front() == '\t') return true;
  const std::string_view t = detail::trim(line);
  return t.empty() || t.front() == '#';
}

/// The frame notation "ID#DATA" / "ID#R[len]" (no time, no interface).
/// Errors: bad_syntax (no '#', an identifier of neither 3 nor 8 digits, stray characters),
/// bad_digit (not a hex digit), invalid_argument (a 3-digit identifier above 7FF, or an
/// 8-digit one with bits 30/31 set), too_long (more than 8 data bytes), truncated (an odd
/// number of data digits), bad_length (remote length above 8), unexpected_frame (CAN FD "##");
/// each with its reason and column.
[[nodiscard]] constexpr result<frame_record, line_error> parse_frame(std::string_view s) noexcept {
  const std::string_view whole = s;
  s = detail::trim(s);
  const std::size_t hash = s.find('#');
  if (hash == std::string_view::npos) {
    return line_error{errc::bad_syntax, "no frame: ID#DATA expected", detail::column(whole, s)};
  }
  const std::string_view id = s.substr(0, hash);
  std::string_view rest = s.substr(hash + 1U);
  const std::size_t at = detail::column(whole, s);
  if (id.size() != 3U && id.size() != 8U) {
    return line_error{errc::bad_syntax,
                      "identifier of 3 hex digits (11-bit) or 8 (29-bit) expected", at};
  }
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < id.size(); ++i) {
    const int v = ascii::hex_value(id[i]);
    if (v < 0) return line_error{errc::bad_digit, "not a hex digit", at + i};
    value = value * 16U + static_cast<std::uint32_t>(v);
  }
  frame_record r;
  if (id.size() == 3U) {
    if (value > 0x7FFU) {
      return line_error{errc::invalid_argument, "11-bit identifier above 7FF", at};
    }
    r.id = value;
  } else {
    if ((value & 0xC0000000U) != 0U) {
      return line_error{errc::invalid_argument, "29-bit identifier with bit 30 or 31 set", at};
    }
    r.error = (value & 0x20000000U) != 0U;
    r.extended = !r.error;
    r.id = value & 0x1FFFFFFFU;
  }
  const std::size_t data_at = at + hash + 1U;
  if (!rest.empty() && rest.front() == '#') {
    return line_error{errc::unexpected_frame, "CAN FD frame (##): not a CiA 301 frame", at + hash};
  }
  if (!rest.empty() && (rest.front() == 'R' || rest.front() == 'r')) {
    if (r.error) return line_error{errc::bad_syntax, "an error frame is no remote frame", data_at};
    r.rtr = true;
    rest.remove_prefix(1);
    if (rest.size() > 1U) {
      return line_error{errc::bad_syntax, "one digit of length after R", data_at + 1U};
    }
    if (rest.size() == 1U) {
      if (!ascii::is_digit(rest[0])) {
        return line_error{errc::bad_digit, "a length digit expected after R", data_at + 1U};
      }
      if (rest[0] > '8') return line_error{errc::bad_length, "length above 8", data_at + 1U};
      r.dlc = static_cast<std::uint8_t>(rest[0] - '0');
    }
    return r;
  }
  std::size_t n = 0;
  std::size_t i = 0;
  while (i < rest.size()) {
    if (rest[i] == '.' && n > 0U && i + 1U < rest.size()) {
      ++i;
      continue;
    }
    const int hi = ascii::hex_value(rest[i]);
    if (hi < 0) {
      return rest[i] == '.' ? line_error{errc::bad_syntax, "misplaced '.'", data_at + i}
                            : line_error{errc::bad_digit, "not a hex digit", data_at + i};
    }
    if (i + 1U >= rest.size()) {
      return line_error{errc::truncated, "odd number of data digits", data_at + i};
    }
    const int lo = ascii::hex_value(rest[i + 1U]);
    if (lo < 0) return line_error{errc::bad_digit, "not a hex digit", data_at + i + 1U};
    if (n == 8U) return line_error{errc::too_long, "more than 8 data bytes", data_at + i};
    r.data[n++] = static_cast<std::uint8_t>(hi * 16 + lo);
    i += 2U;
  }
  r.dlc = static_cast<std::uint8_t>(n);
  return r;
}

/// One line of candump's output, in any of its forms:
///   (1700000000.123456) can0 605#2B00180564000000         log (-l, -L); "R"/"T" after it (-x)
///   605#2B00180564000000, 705#R                            compact notation (cansend)
///     can0  605   [8]  2B 00 18 05 64 00 00 00             default display
///    (1700000000.123456)  can0  605   [8]  2B 00 …          -ta; -td/-tz: (000.000250)
///    (2024-05-01 12:34:56.123456)  can0  605   [8]  …       -tA (local time, kept as a date)
///     can0  RX - -  605   [8]  …                           -x; -a's 'ASCII' and ERRORFRAME
///     can0  705   [1]  remote request                      are read and dropped
/// CAN FD frames ("##", "[NN]") are refused (unexpected_frame).
/// The interface "-" is "not given" (an empty interface_name), as format_line writes it.
/// Errors: those of parse_frame; for the time: bad_syntax, bad_digit, overflow, too_long,
/// out_of_range; bad_syntax when a time is not followed by an interface and a frame; those of
/// interface_name::make; bad_syntax for a line that starts with a tab (is_blank_or_comment's
/// continuation line); each with its reason and column.
[[nodiscard]] constexpr result<frame_record, line_error>
parse_line(std::string_view line) noexcept {
  // what is_blank_or_comment calls a continuation line (candump -e and -a indent their details
  // with a tab) is no frame, whatever follows the tab
  if (!line.empty() && line.front() == '\t') {
    return line_error{errc::bad_syntax, "a line that starts with a tab continues the line before",
                      0};
  }
  std::string_view s = detail::trim(line);
  timestamp t{};
  if (!s.empty() && s.front() == '(') {
    const std::size_t close = s.find(')');
    if (close == std::string_view::npos) {
      return line_error{errc::bad_syntax, "the time has no ')'", detail::column(line, s)};
    }
    auto parsed = detail::parse_time(s.substr(1, close - 1U));
    if (!parsed) {
      return line_error{parsed.error(), "not a time (seconds.fraction or a date)",
                        detail::column(line, s) + 1U};
    }
    t = parsed.value();
    s = s.substr(close + 1U);
  } else {
    // no time: the compact notation, or the display without -t
    std::string_view probe = s;
    const std::string_view first = detail::next_token(probe);
    if (first.find('#') != std::string_view::npos || first.empty()) {
      if (!detail::trim(probe).empty()) {
        return line_error{errc::bad_syntax, "unexpected text after the frame",
                          detail::column(line, detail::trim(probe))};
      }
      return parse_frame(line);
    }
  }
  if (!t.known()) {
    // one word without '#' ("garbage", "605"): no frame at all
    std::string_view probe = s;
    (void)detail::next_token(probe);
    if (detail::trim(probe).empty()) return parse_frame(line);
  }
  const std::string_view name = detail::next_token(s);
  if (name.empty()) {
    return line_error{errc::bad_syntax, "a time must be followed by an interface and a frame",
                      line.size()};
  }
  // "-" is how format_line writes "no interface" (a bus that names none, e.g. slcan): read
  // back as none, so that a written log reads back identical (fuzz/FINDINGS.md F21).
  auto iface = name == "-" ? result<interface_name>{interface_name{}} : interface_name::make(name);
  if (!iface) {
    return line_error{iface.error(),
                      iface.error() == errc::too_long ? "interface name longer than 15 characters"
                                                      : "not an interface name",
                      detail::column(line, name)};
  }
  std::string_view probe = s;
  const std::string_view second = detail::next_token(probe);
  if (second.empty()) {
    return line_error{errc::bad_syntax, "an interface must be followed by a frame", line.size()};
  }
  frame_record out;
  if (second.find('#') != std::string_view::npos) {
    // log format; candump -x adds the direction (R, T) after the frame
    const std::string_view extra = detail::trim(probe);
    if (!extra.empty() && extra != "R" && extra != "T") {
      return line_error{errc::bad_syntax, "unexpected text after the frame",
                        detail::column(line, extra)};
    }
    auto r = parse_frame(second);
    if (!r) {
      line_error e = r.error();
      e.column += static_cast<std::uint32_t>(detail::column(line, second));
      return e;
    }
    out = r.value();
  } else {
    if (second == "RX" || second == "TX") { // -x: direction and two flags (BRS, ESI)
      s = probe;
      (void)detail::next_token(s);
      (void)detail::next_token(s);
    }
    auto r = detail::parse_long(line, s);
    if (!r) return r.error();
    out = r.value();
  }
  out.time = t;
  out.iface = iface.value();
  return out;
}

/// The frame notation of a record: "605#2B00180564000000", "705#R", "705#R1",
/// "12345678#00FF", error frames as 8 digits with 0x20000000 set (upper-case hex, as candump).
[[nodiscard]] inline std::string format_frame(const frame_record &r) {
  static constexpr char digits[] = "0123456789ABCDEF";
  std::string out;
  const auto hex = [&out](std::uint32_t v, int n) {
    for (int i = n - 1; i >= 0; --i) out += digits[(v >> (4 * i)) & 0xFU];
  };
  if (r.error) {
    hex((r.id & 0x1FFFFFFFU) | 0x20000000U, 8);
  } else if (r.extended) {
    hex(r.id & 0x1FFFFFFFU, 8);
  } else {
    hex(r.id & 0x7FFU, 3);
  }
  out += '#';
  if (r.rtr) {
    out += 'R';
    if (r.dlc != 0U) out += static_cast<char>('0' + (r.dlc > 8U ? 8U : r.dlc));
    return out;
  }
  for (std::size_t i = 0; i < r.dlc && i < 8U; ++i) hex(r.data[i], 2);
  return out;
}

/// A time as it was read: "1700000000.123456" (the fraction with its digits), or for a date
/// (candump -tA) "2024-05-01 12:34:56.123456". Empty when no time is known.
[[nodiscard]] inline std::string format_time(const timestamp &t) {
  if (!t.known()) return {};
  std::string frac = std::to_string(t.fraction);
  if (frac.size() < t.digits) frac.insert(0, t.digits - frac.size(), '0');
  if (!t.date) return std::to_string(t.seconds) + "." + frac;
  const std::int64_t day = t.seconds >= 0 ? t.seconds / 86400 : (t.seconds - 86399) / 86400;
  const std::int64_t in_day = t.seconds - day * 86400;
  const calendar::date d = calendar::from_days(day);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%04d-%02u-%02u %02u:%02u:%02u.", static_cast<int>(d.year),
                static_cast<unsigned>(d.month), static_cast<unsigned>(d.day),
                static_cast<unsigned>(in_day / 3600), static_cast<unsigned>(in_day / 60 % 60),
                static_cast<unsigned>(in_day % 60));
  return buf + frac;
}

/// A log line: "(1700000000.123456) can0 605#2B…" when the record has a time (a missing
/// interface is written as "-"), "can0 605#2B…" when it has an interface and no time (candump's
/// display without -t), the compact frame when it has neither. parse_line reads each back.
[[nodiscard]] inline std::string format_line(const frame_record &r) {
  if (!r.time.known()) {
    if (r.iface.empty()) return format_frame(r);
    return std::string(r.iface.view()) + ' ' + format_frame(r);
  }
  std::string out(1, '(');
  out += format_time(r.time);
  out += ") ";
  out += r.iface.empty() ? std::string_view("-") : r.iface.view();
  out += ' ';
  out += format_frame(r);
  return out;
}

} // namespace fieldcodec::host::candump
