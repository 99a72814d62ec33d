// fieldcodec — PA-CONTROL RS232 command frames: field layout, check rules, encoder, and the
// parser of a complete frame body.
//
//   request          SOH STX CMD ; PAR_1 ; TYP_PAR_2 ; PAR_2 ETX CHECK EOT
//   acknowledgement  SOH STX QUIT ; BE ; STATUS ; ERROR ; TYP_QUIT ; Q_PAR ETX CHECK EOT
//   poll             EOT
//
// SOH = 0x01, STX = 0x02, ETX = 0x03, EOT = 0x04. CMD is four upper-case hex digits; every
// other field is decimal. CHECK is the decimal text (1–3 digits) of an XOR over the bytes
// between STX and ETX; the manual's acknowledgements also fold in the ETX byte (XOR ^ 0x03),
// its requests do not. "0" in CHECK means "not checked" (see docs/pacontrol.md).
#pragma once

#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/core/checksum.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/command.hpp>
#include <fieldcodec/pacontrol/value.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>

namespace fieldcodec::pacontrol::serial {

inline constexpr std::uint8_t soh = 0x01;
inline constexpr std::uint8_t stx = 0x02;
inline constexpr std::uint8_t etx = 0x03;
inline constexpr std::uint8_t eot = 0x04;
inline constexpr char separator = ';';

/// Longest field the decoder accepts and the encoder writes: the longest text of a valid date
/// (a real with an int64 mantissa and up to 18 places, e.g. "-0.000000000000000001" or
/// "-922337203685477580.8", is 21 characters; an int32 needs 11).
inline constexpr std::size_t max_field_chars = 21;
/// Fields of a request and of an acknowledgement.
inline constexpr std::size_t request_fields = 4;
inline constexpr std::size_t acknowledgement_fields = 6;
/// Longest body (between STX and ETX): six full fields and five separators.
inline constexpr std::size_t max_body_chars =
    acknowledgement_fields * max_field_chars + acknowledgement_fields - 1U;
/// Longest CHECK text.
inline constexpr std::size_t max_check_chars = 3;
/// A buffer of this size holds any frame the encoder writes or the decoder accepts.
inline constexpr std::size_t max_frame_size = 2U + max_body_chars + 1U + max_check_chars + 1U;

/// Which bytes the XOR check covers.
enum class check_rule : std::uint8_t {
  body,         ///< the bytes strictly between STX and ETX (the manual's requests)
  body_and_etx, ///< those bytes and the ETX byte, i.e. XOR ^ 0x03 (its acknowledgements)
};

/// The rule that is not `r`.
[[nodiscard]] constexpr check_rule other_rule(check_rule r) noexcept {
  return r == check_rule::body ? check_rule::body_and_etx : check_rule::body;
}

/// Whether the encoder writes the real check or "0" (not checked).
enum class check_mode : std::uint8_t { computed, unchecked };

/// The check value of a body under a rule.
[[nodiscard]] constexpr std::uint8_t compute_check(std::span<const char> body,
                                                   check_rule rule) noexcept {
  return checksum::xor8(body, rule == check_rule::body_and_etx ? etx : std::uint8_t{0});
}

/// A command from the master (3.3).
struct request {
  std::uint16_t code = 0;      ///< CMD, the command code, e.g. 0x0A87
  std::uint16_t parameter = 0; ///< PAR_1: axis, register, input number …
  value date{};                ///< TYP_PAR_2 and PAR_2

  /// Same fields; dates compare as numbers (see value::same_text for the text).
  friend constexpr bool operator==(const request &, const request &) noexcept = default;
};

/// The PA-CONTROL's answer to a request or a poll (3.3.1).
struct acknowledgement {
  std::uint16_t command_error_number = 0;    ///< QUIT: command error number, 0 = no error
  bool end_of_processing = false;            ///< BE: the command has finished
  std::uint16_t operating_status = 0;        ///< STATUS (operating_status_codes in codes.hpp)
  std::uint16_t controller_error_number = 0; ///< ERROR: PA-CONTROL error number (Exxx), 0 = none
  value date{};                              ///< TYP_QUIT and Q_PAR

  /// Same fields; dates compare as numbers (see value::same_text for the text).
  friend constexpr bool operator==(const acknowledgement &,
                                   const acknowledgement &) noexcept = default;
};

/// The TYP field of a date type: 0 integer, 1 real. Errors: invalid_argument (none).
[[nodiscard]] constexpr result<char> typ_field(od::command_value type) noexcept {
  switch (type) {
  case od::command_value::integer: return '0';
  case od::command_value::real: return '1';
  case od::command_value::none: break;
  }
  return errc::invalid_argument;
}

namespace detail {

/// Appends characters to a bounded text buffer.
struct text_writer {
  std::span<std::uint8_t> out;
  std::size_t n = 0;

  constexpr status put(char c) noexcept {
    if (n >= out.size()) return errc::buffer_too_small;
    out[n++] = static_cast<std::uint8_t>(c);
    return {};
  }
  constexpr status put_byte(std::uint8_t b) noexcept {
    if (n >= out.size()) return errc::buffer_too_small;
    out[n++] = b;
    return {};
  }
  /// Appends characters. When they do not all fit, those that do are written, then
  /// buffer_too_small (as one put() per character would).
  constexpr status put_text(std::span<const char> text) noexcept {
    if (out.size() - n >= text.size()) { // one check for the whole text
      for (const char c : text) out[n++] = static_cast<std::uint8_t>(c);
      return {};
    }
    for (const char c : text) FIELDCODEC_TRY_STATUS(put(c));
    return {};
  }
  /// Appends `v` in decimal (as ascii::format_unsigned writes it).
  constexpr status put_unsigned(std::uint64_t v) noexcept {
    char tmp[20]{}; // the digits, least significant first
    std::size_t len = 0;
    do {
      tmp[len++] = static_cast<char>('0' + static_cast<int>(v % 10U));
      v /= 10U;
    } while (v != 0U);
    if (out.size() - n < len) { // the digits that fit, then the error
      for (std::size_t i = len; i-- > 0;) FIELDCODEC_TRY_STATUS(put(tmp[i]));
    }
    for (std::size_t i = len; i-- > 0;) out[n++] = static_cast<std::uint8_t>(tmp[i]);
    return {};
  }
  /// Appends `v` as four upper-case hex digits (as ascii::format_hex(v, 4, …, true)).
  constexpr status put_hex4(std::uint16_t v) noexcept {
    constexpr char digits[] = "0123456789ABCDEF";
    const std::array<char, 4> text{digits[(v >> 12U) & 0xFU], digits[(v >> 8U) & 0xFU],
                                   digits[(v >> 4U) & 0xFU], digits[v & 0xFU]};
    return put_text(text);
  }
  constexpr status put_value(const value &v) noexcept {
    char tmp[48]{};
    auto len = format_decimal(v.number, tmp);
    if (!len) return len.error();
    if (len.value() > max_field_chars) return errc::too_long; // cannot happen for valid dates
    return put_text(std::span<const char>(tmp, len.value()));
  }
};

/// Writes SOH STX body ETX CHECK EOT, the body produced by `write_body`.
template <class F>
constexpr result<std::size_t> write_frame(std::span<std::uint8_t> out, check_rule rule,
                                          check_mode mode, F &&write_body) noexcept {
  text_writer w{out};
  FIELDCODEC_TRY_STATUS(w.put_byte(soh));
  FIELDCODEC_TRY_STATUS(w.put_byte(stx));
  const std::size_t body_start = w.n;
  FIELDCODEC_TRY_STATUS(write_body(w));
  std::uint8_t check = rule == check_rule::body_and_etx ? etx : std::uint8_t{0};
  check = checksum::xor8(std::span<const std::uint8_t>(out.data() + body_start, w.n - body_start),
                         check);
  FIELDCODEC_TRY_STATUS(w.put_byte(etx));
  FIELDCODEC_TRY_STATUS(w.put_unsigned(mode == check_mode::computed ? check : 0U));
  FIELDCODEC_TRY_STATUS(w.put_byte(eot));
  return w.n;
}

} // namespace detail

/// Writes a request frame into `out`; returns its length.
/// Errors: buffer_too_small; those of validate(value) (overflow, type_mismatch,
/// invalid_argument).
[[nodiscard]] constexpr result<std::size_t>
encode_request(const request &r, std::span<std::uint8_t> out, check_rule rule = check_rule::body,
               check_mode mode = check_mode::computed) noexcept {
  FIELDCODEC_TRY_STATUS(validate(r.date));
  return detail::write_frame(out, rule, mode, [&](detail::text_writer &w) -> status {
    FIELDCODEC_TRY_STATUS(w.put_hex4(r.code));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put_unsigned(r.parameter));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put(typ_field(r.date.type).value())); // validated above
    FIELDCODEC_TRY_STATUS(w.put(separator));
    return w.put_value(r.date);
  });
}

/// Writes an acknowledgement frame into `out`; returns its length.
/// Errors: buffer_too_small; those of validate(value).
[[nodiscard]] constexpr result<std::size_t>
encode_acknowledgement(const acknowledgement &a, std::span<std::uint8_t> out,
                       check_rule rule = check_rule::body_and_etx,
                       check_mode mode = check_mode::computed) noexcept {
  FIELDCODEC_TRY_STATUS(validate(a.date));
  return detail::write_frame(out, rule, mode, [&](detail::text_writer &w) -> status {
    FIELDCODEC_TRY_STATUS(w.put_unsigned(a.command_error_number));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put(a.end_of_processing ? '1' : '0'));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put_unsigned(a.operating_status));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put_unsigned(a.controller_error_number));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put(typ_field(a.date.type).value())); // validated above
    FIELDCODEC_TRY_STATUS(w.put(separator));
    return w.put_value(a.date);
  });
}

/// Writes the poll command (EOT alone); returns 1. Errors: buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> encode_poll(std::span<std::uint8_t> out) noexcept {
  if (out.empty()) return errc::buffer_too_small;
  out[0] = eot;
  return std::size_t{1};
}

// ---------------------------------------------------------------------------------------------
// Parsing a body (the text between STX and ETX) into fields.

namespace detail {

/// Splits `body` at ';' into exactly `n` fields. Errors: bad_length (other count).
template <std::size_t N>
constexpr status split(std::string_view body, std::array<std::string_view, N> &fields) noexcept {
  std::size_t k = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= body.size(); ++i) {
    if (i == body.size() || body[i] == separator) {
      if (k == N) return errc::bad_length;
      fields[k++] = body.substr(start, i - start);
      start = i + 1U;
    }
  }
  if (k != N) return errc::bad_length;
  return {};
}

/// An unsigned decimal field of at most `max`. Errors: bad_syntax (empty), bad_sign
/// (leading '-'), bad_digit, overflow (> max).
constexpr result<std::uint64_t> parse_count(std::string_view f, std::uint64_t max) noexcept {
  if (!f.empty() && f.size() <= 4U) { // 1..4 digits cannot overflow: no check per digit
    std::uint64_t v = 0;
    bool digits = true;
    for (const char c : f) {
      const unsigned d = static_cast<unsigned char>(c) - unsigned{'0'};
      if (d > 9U) {
        digits = false;
        break;
      }
      v = v * 10U + d;
    }
    if (digits) {
      if (v > max) return errc::overflow;
      return v;
    }
  }
  if (!f.empty() && f.front() == '-') return errc::bad_sign;
  auto v = ascii::parse_unsigned(f);
  if (!v) return v.error();
  if (v.value() > max) return errc::overflow;
  return v;
}

/// A 0/1 field (BE, TYP). Errors: those of parse_count, out_of_range (> 1).
constexpr result<bool> parse_flag(std::string_view f) noexcept {
  auto v = parse_count(f, std::numeric_limits<std::uint64_t>::max());
  if (!v) return v.error();
  if (v.value() > 1U) return errc::out_of_range;
  return v.value() == 1U;
}

/// The date, real when `real` (TYP 1). Errors: bad_syntax, bad_digit, overflow (integer
/// outside int32), type_mismatch (a fraction in an integer date).
constexpr result<value> parse_value(bool real, std::string_view f) noexcept {
  if (!real) {
    // The usual integer date: an optional '-' and 1..10 digits with a value inside int32, which
    // parse_decimal reads as that integer with no places. Anything else (more digits, a point,
    // a bad character, a value beyond int32) takes the general path and its errors.
    const std::size_t sign = !f.empty() && f.front() == '-' ? 1U : 0U;
    if (f.size() > sign && f.size() - sign <= 10U) {
      std::int64_t v = 0;
      bool digits = true;
      for (std::size_t i = sign; i < f.size(); ++i) {
        const unsigned d = static_cast<unsigned char>(f[i]) - unsigned{'0'};
        if (d > 9U) {
          digits = false;
          break;
        }
        v = v * 10 + static_cast<std::int64_t>(d);
      }
      if (sign != 0U) v = -v;
      if (digits && v >= std::numeric_limits<std::int32_t>::min() &&
          v <= std::numeric_limits<std::int32_t>::max()) {
        return value{od::command_value::integer, decimal{v, 0}};
      }
    }
  }
  auto d = parse_decimal(f);
  if (!d) return d.error();
  if (real) return value{od::command_value::real, d.value()};
  if (d.value().places != 0U) return errc::type_mismatch;
  return value::of_int(d.value().mantissa);
}

} // namespace detail

/// Parses the body of a request ("0A87;2;1;5552.0").
/// Errors: bad_length (not 4 fields, CMD not 4 characters), bad_syntax (empty field),
/// bad_digit (lower-case or non-hex CMD, letters in decimal fields), bad_sign, overflow,
/// out_of_range (TYP not 0/1), type_mismatch (a fraction with TYP 0).
[[nodiscard]] constexpr result<request>
parse_request_fields(const std::array<std::string_view, request_fields> &f) noexcept;

[[nodiscard]] constexpr result<request> parse_request_body(std::string_view body) noexcept {
  std::array<std::string_view, request_fields> f{};
  FIELDCODEC_TRY_STATUS(detail::split(body, f));
  return parse_request_fields(f);
}

/// The same from the four fields of a body already split at ';' (the decoder splits while the
/// bytes arrive).
[[nodiscard]] constexpr result<request>
parse_request_fields(const std::array<std::string_view, request_fields> &f) noexcept {
  if (f[0].size() != 4U) return f[0].empty() ? errc::bad_syntax : errc::bad_length;
  auto cmd = ascii::parse_hex(f[0], ascii::hex_case::upper);
  if (!cmd) return cmd.error();
  auto par = detail::parse_count(f[1], std::numeric_limits<std::uint16_t>::max());
  if (!par) return par.error();
  auto typ = detail::parse_flag(f[2]);
  if (!typ) return typ.error();
  auto date = detail::parse_value(typ.value(), f[3]);
  if (!date) return date.error();
  return request{static_cast<std::uint16_t>(cmd.value()), static_cast<std::uint16_t>(par.value()),
                 date.value()};
}

/// Parses the body of an acknowledgement ("0;0;31;0;1;1516.950").
/// Errors: as parse_request_body (bad_length for not 6 fields; out_of_range for BE not 0/1).
[[nodiscard]] constexpr result<acknowledgement> parse_acknowledgement_fields(
    const std::array<std::string_view, acknowledgement_fields> &f) noexcept;

[[nodiscard]] constexpr result<acknowledgement>
parse_acknowledgement_body(std::string_view body) noexcept {
  std::array<std::string_view, acknowledgement_fields> f{};
  FIELDCODEC_TRY_STATUS(detail::split(body, f));
  return parse_acknowledgement_fields(f);
}

/// The same from the six fields of a body already split at ';'.
[[nodiscard]] constexpr result<acknowledgement> parse_acknowledgement_fields(
    const std::array<std::string_view, acknowledgement_fields> &f) noexcept {
  constexpr auto max16 = std::numeric_limits<std::uint16_t>::max();
  auto quit = detail::parse_count(f[0], max16);
  if (!quit) return quit.error();
  auto be = detail::parse_flag(f[1]);
  if (!be) return be.error();
  auto st = detail::parse_count(f[2], max16);
  if (!st) return st.error();
  auto err = detail::parse_count(f[3], max16);
  if (!err) return err.error();
  auto typ = detail::parse_flag(f[4]);
  if (!typ) return typ.error();
  auto date = detail::parse_value(typ.value(), f[5]);
  if (!date) return date.error();
  return acknowledgement{static_cast<std::uint16_t>(quit.value()), be.value(),
                         static_cast<std::uint16_t>(st.value()),
                         static_cast<std::uint16_t>(err.value()), date.value()};
}

} // namespace fieldcodec::pacontrol::serial
