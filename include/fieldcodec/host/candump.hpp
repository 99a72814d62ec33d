// fieldcodec — host adapters: candump log lines (can-utils), read and written.
//
//   (1700000000.123456) can0 605#2B00180564000000     log line: time, interface, frame
//   605#2B00180564000000                               compact frame (cansend notation)
//   705#R  705#R1                                      remote frame (optional requested length)
//   12345678#00FF                                      extended (29-bit) frame: 8 hex digits
//   20000004#0004000000000000                          error frame (8 digits, bit 29 set)
//
// Identifiers are 3 hex digits (base frame, at most 7FF) or 8 (extended, or an error frame when
// 0x20000000 is set); data are 0..8 pairs of hex digits, optionally separated by '.'. CAN FD
// frames ("##") are not CANopen CiA 301 frames and are refused. The timestamp is kept exactly
// (seconds, fraction and its number of digits), so a log read and written again is unchanged.
// Pure text: the caller reads and writes the lines.
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/host/frame_record.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace fieldcodec::host::candump {

namespace detail {
[[nodiscard]] constexpr int hex_value(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}
[[nodiscard]] constexpr bool is_blank(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}
[[nodiscard]] constexpr std::string_view trim(std::string_view s) noexcept {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

/// "(seconds.fraction)". Errors: bad_syntax, bad_digit, overflow, too_long (fraction > 9).
[[nodiscard]] constexpr result<timestamp> parse_time(std::string_view s) noexcept {
  if (s.size() < 4U || s.front() != '(' || s.back() != ')') return errc::bad_syntax;
  s = s.substr(1, s.size() - 2U);
  const std::size_t dot = s.find('.');
  if (dot == std::string_view::npos || dot == 0U || dot + 1U == s.size()) return errc::bad_syntax;
  timestamp t;
  for (std::size_t i = 0; i < dot; ++i) {
    const char c = s[i];
    if (c < '0' || c > '9') return errc::bad_digit;
    if (t.seconds > (std::numeric_limits<std::int64_t>::max() - (c - '0')) / 10) {
      return errc::overflow;
    }
    t.seconds = t.seconds * 10 + (c - '0');
  }
  const std::string_view frac = s.substr(dot + 1U);
  if (frac.size() > 9U) return errc::too_long;
  for (const char c : frac) {
    if (c < '0' || c > '9') return errc::bad_digit;
    t.fraction = t.fraction * 10U + static_cast<std::uint32_t>(c - '0');
  }
  t.digits = static_cast<std::uint8_t>(frac.size());
  return t;
}
} // namespace detail

/// True for a line that holds no frame: empty, blanks only, or a comment starting with '#'.
[[nodiscard]] constexpr bool is_blank_or_comment(std::string_view line) noexcept {
  const std::string_view t = detail::trim(line);
  return t.empty() || t.front() == '#';
}

/// The frame notation "ID#DATA" / "ID#R[len]" (no time, no interface).
/// Errors: bad_syntax (no '#', an identifier of neither 3 nor 8 digits, stray characters),
/// bad_digit (not a hex digit), invalid_argument (a 3-digit identifier above 7FF, or an
/// 8-digit one with bits 30/31 set), too_long (more than 8 data bytes), truncated (an odd
/// number of data digits), bad_length (remote length above 8), unexpected_frame (CAN FD "##").
[[nodiscard]] constexpr result<frame_record> parse_frame(std::string_view s) noexcept {
  s = detail::trim(s);
  const std::size_t hash = s.find('#');
  if (hash == std::string_view::npos) return errc::bad_syntax;
  const std::string_view id = s.substr(0, hash);
  std::string_view rest = s.substr(hash + 1U);
  if (id.size() != 3U && id.size() != 8U) return errc::bad_syntax;
  std::uint32_t value = 0;
  for (const char c : id) {
    const int v = detail::hex_value(c);
    if (v < 0) return errc::bad_digit;
    value = value * 16U + static_cast<std::uint32_t>(v);
  }
  frame_record r;
  if (id.size() == 3U) {
    if (value > 0x7FFU) return errc::invalid_argument;
    r.id = value;
  } else {
    if ((value & 0xC0000000U) != 0U) return errc::invalid_argument;
    r.error = (value & 0x20000000U) != 0U;
    r.extended = !r.error;
    r.id = value & 0x1FFFFFFFU;
  }
  if (!rest.empty() && rest.front() == '#') return errc::unexpected_frame;
  if (!rest.empty() && (rest.front() == 'R' || rest.front() == 'r')) {
    if (r.error) return errc::bad_syntax;
    r.rtr = true;
    rest.remove_prefix(1);
    if (rest.size() > 1U) return errc::bad_syntax;
    if (rest.size() == 1U) {
      if (rest[0] < '0' || rest[0] > '9') return errc::bad_digit;
      if (rest[0] > '8') return errc::bad_length;
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
    const int hi = detail::hex_value(rest[i]);
    if (hi < 0) return rest[i] == '.' ? errc::bad_syntax : errc::bad_digit;
    if (i + 1U >= rest.size()) return errc::truncated;
    const int lo = detail::hex_value(rest[i + 1U]);
    if (lo < 0) return errc::bad_digit;
    if (n == 8U) return errc::too_long;
    r.data[n++] = static_cast<std::uint8_t>(hi * 16 + lo);
    i += 2U;
  }
  r.dlc = static_cast<std::uint8_t>(n);
  return r;
}

/// A log line "(time) iface frame" or a compact frame "ID#DATA". The interface "-" is "not
/// given" (an empty interface_name), as format_line writes it.
/// Errors: those of parse_frame; for the time: bad_syntax, bad_digit, overflow, too_long;
/// bad_syntax when a time is not followed by an interface and a frame; those of
/// interface_name::make.
[[nodiscard]] constexpr result<frame_record> parse_line(std::string_view line) noexcept {
  std::string_view s = detail::trim(line);
  if (s.empty() || s.front() != '(') return parse_frame(s);
  const std::size_t close = s.find(')');
  if (close == std::string_view::npos) return errc::bad_syntax;
  auto t = detail::parse_time(s.substr(0, close + 1U));
  if (!t) return t.error();
  s = detail::trim(s.substr(close + 1U));
  std::size_t sp = 0;
  while (sp < s.size() && !detail::is_blank(s[sp])) ++sp;
  if (sp == 0U || sp == s.size()) return errc::bad_syntax;
  // "-" is how format_line writes "no interface" (a bus that names none, e.g. slcan): read
  // back as none, so that a written log reads back identical (fuzz/FINDINGS.md F21).
  const std::string_view name = s.substr(0, sp);
  auto iface = name == "-" ? result<interface_name>{interface_name{}} : interface_name::make(name);
  if (!iface) return iface.error();
  auto r = parse_frame(s.substr(sp));
  if (!r) return r.error();
  frame_record out = r.value();
  out.time = t.value();
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

/// A log line: "(1700000000.123456) can0 605#2B…" when the record has a time and an interface
/// (a missing interface is written as "-"), the compact frame otherwise.
[[nodiscard]] inline std::string format_line(const frame_record &r) {
  if (!r.time.known()) return format_frame(r);
  std::string frac = std::to_string(r.time.fraction);
  if (frac.size() < r.time.digits) frac.insert(0, r.time.digits - frac.size(), '0');
  std::string out(1, '(');
  out += std::to_string(r.time.seconds);
  out += '.';
  out += frac;
  out += ") ";
  out += r.iface.empty() ? std::string_view("-") : r.iface.view();
  out += ' ';
  out += format_frame(r);
  return out;
}

} // namespace fieldcodec::host::candump
