// fieldcodec-gen — small text helpers shared by the readers and writers.
#pragma once

#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/number.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace fieldcodec::gen {

/// `s` without leading and trailing blanks (space, TAB). Inline: it runs several times per line.
[[nodiscard]] inline std::string_view trim(std::string_view s) noexcept {
  std::size_t b = 0;
  std::size_t e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t')) ++b;
  while (e > b && (s[e - 1U] == ' ' || s[e - 1U] == '\t')) --e;
  return s.substr(b, e - b);
}
[[nodiscard]] std::string to_upper(std::string_view s);
[[nodiscard]] std::string to_lower(std::string_view s);
[[nodiscard]] bool iequals(std::string_view a, std::string_view b) noexcept;

/// Whether `s` is valid UTF-8 (no overlong forms, no surrogates, nothing beyond U+10FFFF).
[[nodiscard]] bool valid_utf8(std::string_view s) noexcept;
/// Where `s` stops being valid UTF-8: the offset of the first byte of the first invalid
/// sequence, std::string_view::npos when all of it is valid.
[[nodiscard]] std::size_t utf8_invalid_at(std::string_view s) noexcept;
/// Appends code point `cp` (at most U+10FFFF) as UTF-8.
void append_utf8(std::string &out, std::uint32_t cp);
/// Text as UTF-8: a UTF-8 byte-order mark is dropped, valid UTF-8 is kept, anything else is
/// taken as Windows-1252 / Latin-1 and converted (`converted` tells).
[[nodiscard]] std::string to_utf8(std::string_view bytes, bool &converted);
/// Bytes of ISO-8859-1 (every byte its code point) or, with `windows_1252`, of Windows-1252
/// (0x80..0x9F its printable characters where it assigns them) as UTF-8.
[[nodiscard]] std::string latin1_to_utf8(std::string_view bytes, bool windows_1252);
/// The same without a copy when `bytes` are UTF-8 already: a view of `bytes` (without a
/// byte-order mark), or of `storage`, which receives the converted text.
[[nodiscard]] std::string_view as_utf8(std::string_view bytes, std::string &storage,
                                       bool &converted);

/// Integer syntaxes: `eds` as EDS files write them (optional sign, `0x` hex, leading-0 octal,
/// decimal; C suffixes U, L, LL, UL accepted and reported in `suffix`); `xml` as XDD and ESI
/// files write them (optional sign, `0x` or `#x` hex, decimal with leading zeros, no suffixes).
enum class int_syntax : std::uint8_t { eds, xml };
struct int_parse {
  bool ok = false;
  od::number value;  ///< signed_number for negatives and signed decimals, unsigned_number otherwise
  std::string error; ///< "expected ..." text when !ok
  std::size_t error_pos = 0;
  bool suffix = false;
};
[[nodiscard]] int_parse parse_int(std::string_view s, int_syntax syntax = int_syntax::eds);

/// Whether the integer `n` is a value of the integer or BOOLEAN type `t`.
[[nodiscard]] bool fits(od::data_type t, od::number n);
/// `n + node` as an integer number (nothing when it overflows 64 bits).
[[nodiscard]] std::optional<od::number> plus_node(od::number n, std::uint8_t node);
/// An integer read for a field of `type` as the model keeps it: a signed type's value written as
/// its two's complement bit pattern (0x80000000 for INTEGER32) becomes the negative value, other
/// values of signed types become signed numbers, non-negative values of unsigned types unsigned
/// numbers. Anything else is returned as it is.
[[nodiscard]] od::number integer_for_type(od::number n, od::data_type type);

/// A real number: decimal with optional exponent (std::from_chars, C locale).
[[nodiscard]] std::optional<double> parse_real(std::string_view s);

/// A REAL32 / REAL64 value as dictionaries write it: `0x…` is the IEEE 754 bit pattern (how lely
/// and other tools write a float exactly: REAL32 0x40490FDB is 3.14159274…), anything else a
/// decimal number (`3.14`, `-1e3`, `10`). NaN and infinities are refused.
struct real_parse {
  bool ok = false;
  double value = 0;
  std::string error; ///< "expected ..." text when !ok
  std::size_t error_pos = 0;
};
[[nodiscard]] real_parse parse_real_value(std::string_view s, od::data_type type);

/// A `$NODEID` expression as CiA 306 writes node-ID relative values: `$NODEID`,
/// `$NODEID+<number>` or `<number>+$NODEID`, any case, blanks around the parts.
struct nodeid_expr {
  bool present = false;     ///< the text names $NODEID
  bool ok = false;          ///< in one of the accepted forms
  std::string_view operand; ///< the number added, as written (empty: plain `$NODEID`)
  std::size_t operand_pos = 0;
};
[[nodiscard]] nodeid_expr split_nodeid(std::string_view s) noexcept;

/// The value of a byte string as written in a dictionary → the bytes a store holds:
/// VISIBLE_STRING as is (surrounding double quotes removed), UNICODE_STRING UTF-8 → UTF-16LE,
/// OCTET_STRING and DOMAIN hex digit pairs (blanks between pairs allowed) → bytes. Nothing when
/// an OCTET_STRING / DOMAIN value is not hex digit pairs.
[[nodiscard]] std::optional<std::string> byte_string_value(od::data_type type,
                                                           std::string_view text);
/// The inverse: bytes → text as an EDS writes it (hex digit pairs in upper case; UTF-16LE →
/// UTF-8, an unpaired surrogate as U+FFFD).
[[nodiscard]] std::string byte_string_text(od::data_type type, std::string_view bytes);

/// A C++ identifier derived from `name`: lower case ASCII letters, digits and '_', German
/// umlauts transliterated, other characters become '_', runs of '_' collapse, a leading digit
/// gets the prefix "n_", keywords get a trailing '_'. Empty when nothing is left.
[[nodiscard]] std::string make_identifier(std::string_view name);
/// The room make_identifier's identifier of an `n`-byte name may need: every byte gives at most
/// "_minus", plus a "n_" prefix and a keyword's '_'.
[[nodiscard]] constexpr std::size_t identifier_capacity(std::size_t n) noexcept {
  return 2U + n * 6U + 1U;
}
/// make_identifier written at `out`, which has room for identifier_capacity(name.size()) bytes
/// (no allocation; the emitter builds names in place). Returns the identifier's length.
std::size_t write_identifier(char *out, std::string_view name) noexcept;
[[nodiscard]] bool is_cpp_keyword(std::string_view s) noexcept;
[[nodiscard]] bool is_identifier(std::string_view s) noexcept;

/// A C++ string literal of `s` (UTF-8 kept, control characters and quotes escaped).
[[nodiscard]] std::string cpp_string(std::string_view s);
void append_cpp_string(std::string &out, std::string_view s);
/// The room a string literal of `n` bytes may need (every byte a 3-digit octal escape, quotes).
[[nodiscard]] constexpr std::size_t cpp_string_capacity(std::size_t n) noexcept {
  return 4U * n + 2U;
}
/// append_cpp_string written at `out`, which has room for cpp_string_capacity(s.size()) bytes;
/// returns the end of what was written.
char *write_cpp_string(char *out, std::string_view s) noexcept;
/// `"…"` of arbitrary bytes, every byte outside printable ASCII (and `"`, `\`, `?`) as a 3-digit
/// octal escape (the literal of append_cpp_value_text's OCTET_STRING / UNICODE_STRING / DOMAIN
/// values); room for cpp_string_capacity(bytes.size()) bytes; returns the end.
char *write_cpp_bytes(char *out, std::string_view bytes) noexcept;

/// The value of a byte-string entry as C++: VISIBLE_STRING text as a string literal; the bytes
/// of an OCTET_STRING / UNICODE_STRING / DOMAIN (any byte, NUL included) as
/// `std::string_view{"\310=\273", 3}`, every byte outside printable ASCII as a 3-digit octal
/// escape.
void append_cpp_value_text(std::string &out, od::data_type type, std::string_view bytes);

[[nodiscard]] std::string hex(std::uint64_t v, int digits);

} // namespace fieldcodec::gen
