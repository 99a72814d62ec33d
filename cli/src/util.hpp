// fieldcodec CLI — small text helpers: JSON lines, hex, addresses.
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/od/address.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::cli {

/// One JSON object, written in the order the fields are added.
class json_object {
public:
  json_object &str(std::string_view key, std::string_view value);
  json_object &num(std::string_view key, std::int64_t value);
  json_object &unum(std::string_view key, std::uint64_t value);
  json_object &dec(std::string_view key, decimal value); ///< exact, as a JSON number
  json_object &real(std::string_view key, double value); ///< shortest round trip
  json_object &boolean(std::string_view key, bool value);
  json_object &raw(std::string_view key, std::string_view json); ///< already JSON
  [[nodiscard]] std::string text() const { return "{" + body_ + "}"; }
  [[nodiscard]] bool empty() const { return body_.empty(); }

private:
  void key(std::string_view k);
  std::string body_;
};

/// The JSON string literal of `s` (quotes included; control characters escaped). Always valid
/// JSON: valid UTF-8 passes, every byte of `s` that is not part of valid UTF-8 is written as
/// \u00XX (its Latin-1 reading), so no input can make an output line invalid.
[[nodiscard]] std::string json_string(std::string_view s);
/// At most `max` characters of `s` (of an input line echoed in a message), with
/// "… (N characters)" when it was longer.
[[nodiscard]] std::string capped(std::string_view s, std::size_t max = 120);

/// "2B 00 18 05" (separator " ") or "2B001805" (separator "").
[[nodiscard]] std::string hex_bytes(std::span<const std::uint8_t> b, std::string_view sep = " ");
/// "0x" + `digits` upper-case hex digits.
[[nodiscard]] std::string hex(std::uint64_t v, int digits);
/// "1018h:01".
[[nodiscard]] std::string address_text(od::address a);
/// A decimal as text ("4.001", "-12").
[[nodiscard]] std::string decimal_text(decimal d);
/// The shortest text that reads back as `v` ("0.1", "1e+20").
[[nodiscard]] std::string real_text(double v);

/// Parses "5", "0x1F", "1018h" style numbers. Returns false on bad text or overflow of `max`.
[[nodiscard]] bool parse_uint(std::string_view s, std::uint64_t max, std::uint64_t &out);
/// Parses "1018:1", "0x1018:1", "1018h:01", "1018sub1" → address (index hex, sub hex or
/// decimal with 0x/h). Returns false on bad text.
[[nodiscard]] bool parse_address(std::string_view s, od::address &out);

/// Splits text into lines (LF, CR LF); the last line may lack its LF.
[[nodiscard]] std::vector<std::string_view> split_lines(std::string_view text);

} // namespace fieldcodec::cli
