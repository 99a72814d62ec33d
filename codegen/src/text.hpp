// fieldcodec-gen — small text helpers shared by the readers and writers.
#pragma once

#include <fieldcodec/od/number.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace fieldcodec::gen {

[[nodiscard]] std::string_view trim(std::string_view s) noexcept;
[[nodiscard]] std::string to_upper(std::string_view s);
[[nodiscard]] std::string to_lower(std::string_view s);
[[nodiscard]] bool iequals(std::string_view a, std::string_view b) noexcept;

/// Text as UTF-8: a UTF-8 byte-order mark is dropped, valid UTF-8 is kept, anything else is
/// taken as Windows-1252 / Latin-1 and converted (`converted` tells).
[[nodiscard]] std::string to_utf8(std::string_view bytes, bool &converted);

/// An integer as EDS files write them: optional sign, `0x` hex, leading-0 octal, decimal.
/// C suffixes (U, L, LL, UL) are accepted and reported in `suffix`.
struct int_parse {
  bool ok = false;
  od::number value;  ///< signed_number for negatives and signed decimals, unsigned_number otherwise
  std::string error; ///< "expected ..." text when !ok
  std::size_t error_pos = 0;
  bool suffix = false;
};
[[nodiscard]] int_parse parse_int(std::string_view s);

/// A real number: decimal with optional exponent (std::from_chars, C locale).
[[nodiscard]] std::optional<double> parse_real(std::string_view s);

/// A C++ identifier derived from `name`: lower case ASCII letters, digits and '_', German
/// umlauts transliterated, other characters become '_', runs of '_' collapse, a leading digit
/// gets the prefix "n_", keywords get a trailing '_'. Empty when nothing is left.
[[nodiscard]] std::string make_identifier(std::string_view name);
[[nodiscard]] bool is_cpp_keyword(std::string_view s) noexcept;
[[nodiscard]] bool is_identifier(std::string_view s) noexcept;

/// A C++ string literal of `s` (UTF-8 kept, control characters and quotes escaped).
[[nodiscard]] std::string cpp_string(std::string_view s);
void append_cpp_string(std::string &out, std::string_view s);

[[nodiscard]] std::string hex(std::uint64_t v, int digits);

} // namespace fieldcodec::gen
