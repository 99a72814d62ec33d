// fieldcodec — host adapters: od's value text (od/value_text.hpp) with std::string and
// std::vector, and the one-line message of a refused value.
//
//   auto bytes = host::parse_value(d, "1500 mA", {.node = 5});   // result<vector, value_error>
//   if (!bytes) puts(host::describe(bytes.error(), d).c_str());   // "above the high limit 20000
//   mA" auto text = host::format_value(d, bytes.value());              // "1500 mA"
#pragma once

#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/engineering.hpp>
#include <fieldcodec/od/value_text.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::host {

/// od::parse_value into a vector of the value's bytes.
[[nodiscard]] inline result<std::vector<std::uint8_t>, od::value_error>
parse_value(const od::descriptor &d, std::string_view text, od::value_options o = {}) {
  // a string needs at most its text's length in bytes (UTF-16: twice), a number 8
  std::vector<std::uint8_t> out(2U * text.size() + 8U);
  auto n = od::parse_value(d, text, out, o);
  if (!n) return n.error();
  out.resize(n.value());
  return out;
}

/// od::format_value into a string.
[[nodiscard]] inline result<std::string>
format_value(const od::descriptor &d, std::span<const std::uint8_t> in, od::value_options o = {}) {
  std::string out(od::format_size(d, in.size()), '\0');
  auto n = od::format_value(d, in, out, o);
  if (!n) return n.error();
  out.resize(n.value());
  return out;
}

/// od::format_number into a string.
[[nodiscard]] inline result<std::string> format_number(const od::descriptor &d, od::number v,
                                                       od::value_options o = {}) {
  std::string out(od::format_size(d, 8), '\0');
  auto n = od::format_number(d, v, out, o);
  if (!n) return n.error();
  out.resize(n.value());
  return out;
}

/// Why a value was refused, as a phrase for a message: "above the high limit 20000 mA",
/// "longer than the 30 bytes the object holds", "'0x10' is a raw value: …". `d` and `o` are
/// what the value was parsed with (the limit is written in the value's unit).
[[nodiscard]] inline std::string describe(const od::value_error &e, const od::descriptor &d,
                                          od::value_options o = {}) {
  const bool raw_of_scaled = od::is_scaled(d) && o.unit == od::value_unit::raw;
  auto limit_text = [&] {
    auto t = format_number(d, e.limit, o); // as the value is shown: hex for an identifier
    if (t) return t.value();
    auto dec = e.limit.to_decimal();
    if (!dec) return std::string("?");
    char buf[48]{};
    auto n = format_decimal(dec.value(), buf);
    return n ? std::string(buf, n.value()) : std::string("?");
  };
  switch (e.issue) {
  case od::value_issue::low_limit: return "below the low limit " + limit_text();
  case od::value_issue::high_limit: return "above the high limit " + limit_text();
  case od::value_issue::field:
    return "does not fit " + std::string(od::name(d.type)) +
           (raw_of_scaled || !od::is_scaled(d) ? std::string() : std::string(" after scaling"));
  case od::value_issue::capacity:
    return "longer than the " + std::to_string(e.capacity) + " bytes the object holds";
  case od::value_issue::character:
    return d.type == od::data_type::visible_string
               ? "character " + std::to_string(e.position + 1U) +
                     " is not a visible ASCII character (VISIBLE_STRING holds 20h..7Eh)"
               : "not UTF-8 at character " + std::to_string(e.position + 1U);
  case od::value_issue::not_integer:
    return "not an integer (" + std::string(od::name(d.type)) + ")";
  case od::value_issue::hex_is_raw:
    return "hex spells a raw value; this object is scaled, give it in engineering units" +
           (d.info.unit.empty() ? std::string() : " (" + std::string(d.info.unit.view()) + ")") +
           ", or the raw value with --raw";
  case od::value_issue::unit:
    return d.info.unit.empty() || raw_of_scaled
               ? std::string("a unit was given, but the value has none")
               : "the unit is not " + std::string(d.info.unit.view());
  case od::value_issue::type:
    return od::is_byte_string(d.type) ? "a " + std::string(od::name(d.type)) + " takes text"
                                      : "the object's type takes no such value";
  case od::value_issue::syntax:
    return std::string(to_string(e.code)) + " at character " + std::to_string(e.position + 1U);
  case od::value_issue::none: break;
  }
  return std::string(to_string(e.code));
}

} // namespace fieldcodec::host
