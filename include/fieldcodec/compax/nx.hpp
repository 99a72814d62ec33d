// fieldcodec — COMPAX Nx binary program records (object 0x5FD5, manual 000, 2.11.2).
//
// A record is 20 bytes: data byte 1 = record length (number of content bytes, 1..19), then the
// content, then padding (written as 0x00, ignored when read). The content is one command: a
// 1-byte command code and its operands, possibly followed by a second and third command of a
// combined record (POSR … SPEED … ACCEL …, … WAIT …, … OUTPUT …, WAIT POSA/POSR …).
//
// Code-table decisions (the manual's three tables disagree; evidence in docs/compax.md):
// * Value / parameter / variable forms: parameter code = value code | 0x20, variable code =
//   value code | 0x80 (POSA 0x41/0x61/0xC1, POSR 0x52/0x72/0xD2, SPEED 0x53/0x73/0xD3, SETM
//   0x4D/0x6D/0xCD, ACCEL 0x4C/0x6C/0xCC, LOOP 0x4B/0x6B/0xCB, REPEAT 0x54/0x74/0xD4, WAIT
//   0x57/0x77/0xD7), as the list sorted by code prints every one of them. The nibble-swapped
//   0x1C, 0x2D, 0x3D, 0x4D, 0x7D of the other tables are not accepted (0x4D is SETM value).
// * Digits y of IF Ex=y… / OUTPUT Ax=y… are ASCII: 0x30 = "0", 0x31 = "1" (the key prints the
//   reverse, but IF ERROR / IF STOP are encoded with 0x31, i.e. "=1").
// * Every 2-byte integer is MSB first, also the ACCEL of a combined record (its row prints
//   LSB … MSB, a layout slip against every other row and the bus's byte order).
// * POSA/POSR/SPEED/SETM parameter and variable forms carry the number in 2 bytes followed by
//   four 0x00 (6 operand bytes like the value form); ACCEL/LOOP/REPEAT/WAIT carry 2 bytes.
// * DSP values: dsp_number.hpp.
#pragma once

#include <fieldcodec/compax/dsp_number.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::compax::nx {

inline constexpr std::size_t record_size = 20;
inline constexpr std::size_t content_max = record_size - 1U;

using record = std::array<std::uint8_t, record_size>;

/// Command operations. `none` marks an unused second/third part of a record.
enum class op : std::uint8_t {
  none,
  nop,        ///< 0x20 empty instruction
  valid,      ///< 0x01 VALIDP / VALIDC / VALIDF
  posa,       ///< 0x41 value / HOME, 0x61 parameter, 0xC1 variable
  posr,       ///< 0x52 value / CAM, 0x72, 0xD2
  speed,      ///< 0x53 value / SYNC, 0x73, 0xD3
  setm,       ///< 0x4D value, 0x6D, 0xCD
  accel,      ///< 0x4C value, 0x6C, 0xCC
  wait,       ///< 0x57 value / START, 0x77, 0xD7
  repeat,     ///< 0x54 value, 0x74, 0xD4
  loop,       ///< 0x4B value, 0x6B, 0xCB
  setc,       ///< 0x43 n
  sets,       ///< 0x51
  gosub,      ///< 0x42 n / EXT
  goto_,      ///< 0x47 n / EXT
  end,        ///< 0x45 0x00
  return_,    ///< 0x55 0x00
  if_input,   ///< 0x49 IF Ex=y… / IF ERROR / IF STOP … GOTO/GOSUB n
  if_compare, ///< 0x4A IF <operand> <comparison> <operand> GOTO/GOSUB n
  output,     ///< 0x4F OUTPUT Ax=y…
  assign_p,   ///< 0x50 Pn=<operand> [<arithmetic> <operand>]
  assign_v,   ///< 0x56 Vn=<operand> [<arithmetic> <operand>]
};

/// Form of a command's argument.
enum class arg_kind : std::uint8_t {
  value,     ///< a number (DSP raw value for POSA/POSR/SPEED/SETM, an integer otherwise)
  parameter, ///< P<number>
  variable,  ///< V<number>
  special,   ///< POSA HOME, POSR CAM, SPEED SYNC, WAIT START, GOTO EXT, GOSUB EXT
};

struct arg {
  arg_kind kind = arg_kind::value;
  std::int64_t value = 0; ///< DSP raw, integer, or parameter/variable number; 0 when special
  friend constexpr bool operator==(const arg &, const arg &) = default;
};

[[nodiscard]] constexpr arg integer(std::int64_t v) noexcept { return {arg_kind::value, v}; }
[[nodiscard]] constexpr arg number(dsp_number n) noexcept { return {arg_kind::value, n.raw}; }
[[nodiscard]] constexpr arg parameter(std::uint16_t n) noexcept { return {arg_kind::parameter, n}; }
[[nodiscard]] constexpr arg variable(std::uint16_t n) noexcept { return {arg_kind::variable, n}; }
[[nodiscard]] constexpr arg special() noexcept { return {arg_kind::special, 0}; }

/// IF / assignment operands (7 bytes: type + 6 data bytes).
enum class operand_type : std::uint8_t {
  constant = 0x20,  ///< DSP number
  parameter = 0x50, ///< P<n>
  status = 0x53,    ///< S<n>
  variable = 0x56,  ///< V<n>
};

struct operand {
  operand_type type = operand_type::constant;
  std::uint16_t number = 0; ///< parameter / status / variable number
  dsp_number constant{};    ///< the constant
  friend constexpr bool operator==(const operand &, const operand &) = default;
};

[[nodiscard]] constexpr operand constant(dsp_number n) noexcept {
  return {operand_type::constant, 0, n};
}
[[nodiscard]] constexpr operand operand_of(operand_type t, std::uint16_t n) noexcept {
  return {t, n, {}};
}

enum class comparison : std::uint8_t {
  eq = 0x3D, ///< =
  lt = 0x3C, ///< <
  gt = 0x3E, ///< >
  le = 0xBC, ///< <=
  ge = 0xBE, ///< >=
  ne = 0xBB, ///< <>
};

enum class arithmetic : std::uint8_t {
  none = 0x00, ///< no second operand
  add = 0x2B,
  sub = 0x2D,
  mul = 0x2A,
  div = 0x2F,
  int_div = 0x5C, ///< whole-number division "\"
  mod = 0x25,
};

enum class jump : std::uint8_t { goto_ = 0x47, gosub = 0x42 };

/// Input numbers of IF ERROR and IF STOP (x = 0x00FF / 0x00FE with y = "1").
inline constexpr std::uint16_t input_error = 0x00FF;
inline constexpr std::uint16_t input_stop = 0x00FE;

/// The y digits of IF Ex=y… and OUTPUT Ax=y… (1..8 digits; 0/1, and 2 for OUTPUT A0).
struct pattern {
  std::uint8_t count = 0;
  std::array<std::uint8_t, 8> digits{};
  friend constexpr bool operator==(const pattern &, const pattern &) = default;
};

/// One Nx command. Which members are used depends on `code`; unused ones stay zero so that
/// equal commands compare equal.
struct command {
  op code = op::nop;
  arg a{};             ///< argument of a single-argument command
  op code2 = op::none; ///< combined record: second command (SPEED, WAIT, OUTPUT, POSA, POSR)
  arg b{};
  op code3 = op::none; ///< combined record: third command (ACCEL after POSR … SPEED …)
  arg c{};
  std::uint16_t number = 0; ///< Ex, Ax, Pn, Vn
  pattern pat{};            ///< IF Ex / OUTPUT Ax digits (also the OUTPUT of POSR … OUTPUT)
  jump jmp = jump::goto_;   ///< IF …
  std::uint16_t target = 0; ///< IF … GOTO/GOSUB target record
  operand o1{};
  comparison cmp = comparison::eq;
  arithmetic ari = arithmetic::none;
  operand o2{};
  char letter = 0; ///< VALID: 'P', 'C' or 'F'
  friend constexpr bool operator==(const command &, const command &) = default;
};

// ------------------------------------------------------------------ builders

/// A single command with one argument (POSA, POSR, SPEED, SETM, ACCEL, WAIT, REPEAT, LOOP,
/// SETC, GOTO, GOSUB) or none (NOP, SETS, END, RETURN).
[[nodiscard]] constexpr command make(op o, arg a = {}) noexcept {
  command c{};
  c.code = o;
  c.a = a;
  return c;
}
/// Append the second / third command of a combined record.
[[nodiscard]] constexpr command then(command c, op o, arg a) noexcept {
  if (c.code2 == op::none) {
    c.code2 = o;
    c.b = a;
  } else {
    c.code3 = o;
    c.c = a;
  }
  return c;
}
[[nodiscard]] constexpr command make_valid(char letter) noexcept {
  command c{};
  c.code = op::valid;
  c.letter = letter;
  return c;
}
[[nodiscard]] constexpr result<pattern>
make_pattern(std::span<const std::uint8_t> digits) noexcept {
  if (digits.empty() || digits.size() > 8U) return errc::bad_length;
  pattern p{};
  p.count = static_cast<std::uint8_t>(digits.size());
  for (std::size_t i = 0; i < digits.size(); ++i) p.digits[i] = digits[i];
  return p;
}
[[nodiscard]] constexpr command make_if_input(std::uint16_t input, pattern p, jump j,
                                              std::uint16_t target) noexcept {
  command c{};
  c.code = op::if_input;
  c.number = input;
  c.pat = p;
  c.jmp = j;
  c.target = target;
  return c;
}
[[nodiscard]] constexpr command make_if_error(jump j, std::uint16_t target) noexcept {
  return make_if_input(input_error, pattern{1, {1}}, j, target);
}
[[nodiscard]] constexpr command make_if_stop(jump j, std::uint16_t target) noexcept {
  return make_if_input(input_stop, pattern{1, {1}}, j, target);
}
[[nodiscard]] constexpr command make_if_compare(operand a, comparison cmp, operand b, jump j,
                                                std::uint16_t target) noexcept {
  command c{};
  c.code = op::if_compare;
  c.o1 = a;
  c.cmp = cmp;
  c.o2 = b;
  c.jmp = j;
  c.target = target;
  return c;
}
[[nodiscard]] constexpr command make_output(std::uint16_t output, pattern p) noexcept {
  command c{};
  c.code = op::output;
  c.number = output;
  c.pat = p;
  return c;
}
/// POSR … OUTPUT Ax=y…
[[nodiscard]] constexpr command then_output(command c, std::uint16_t output, pattern p) noexcept {
  c.code2 = op::output;
  c.number = output;
  c.pat = p;
  return c;
}
/// Pn=… (is_variable = false) or Vn=… with one operand.
[[nodiscard]] constexpr command make_assign(bool is_variable, std::uint16_t n, operand a) noexcept {
  command c{};
  c.code = is_variable ? op::assign_v : op::assign_p;
  c.number = n;
  c.o1 = a;
  return c;
}
[[nodiscard]] constexpr command make_assign(bool is_variable, std::uint16_t n, operand a,
                                            arithmetic ari, operand b) noexcept {
  command c = make_assign(is_variable, n, a);
  c.ari = ari;
  c.o2 = b;
  return c;
}

// ------------------------------------------------------------------ code table

namespace detail {

/// Argument shape of a command family.
enum class shape : std::uint8_t {
  none,      ///< code only
  dsp,       ///< 6 bytes: DSP value / number + 4 zeros / 6 × 0xFF special
  word,      ///< 2 bytes: MSB LSB value / number / 0x0000 special
  word_only, ///< 2 bytes, value form only (SETC)
  zero,      ///< one 0x00 (END, RETURN)
};

struct family {
  op o;
  std::uint8_t code; ///< value-form code
  shape s;
  bool has_special; ///< HOME / CAM / SYNC / START / EXT
  bool has_forms;   ///< parameter (| 0x20) and variable (| 0x80) forms exist
};

inline constexpr std::array<family, 16> families{{
    {op::nop, 0x20, shape::none, false, false},
    {op::posa, 0x41, shape::dsp, true, true},
    {op::posr, 0x52, shape::dsp, true, true},
    {op::speed, 0x53, shape::dsp, true, true},
    {op::setm, 0x4D, shape::dsp, false, true},
    {op::accel, 0x4C, shape::word, false, true},
    {op::wait, 0x57, shape::word, true, true},
    {op::repeat, 0x54, shape::word, false, true},
    {op::loop, 0x4B, shape::word, false, true},
    {op::setc, 0x43, shape::word_only, false, false},
    {op::sets, 0x51, shape::none, false, false},
    {op::gosub, 0x42, shape::word, true, false},
    {op::goto_, 0x47, shape::word, true, false},
    {op::end, 0x45, shape::zero, false, false},
    {op::return_, 0x55, shape::zero, false, false},
    {op::valid, 0x01, shape::none, false, false},
}};

inline constexpr std::uint8_t parameter_flag = 0x20;
inline constexpr std::uint8_t variable_flag = 0x80;
inline constexpr std::uint8_t code_if_input = 0x49;
inline constexpr std::uint8_t code_if_compare = 0x4A;
inline constexpr std::uint8_t code_output = 0x4F;
inline constexpr std::uint8_t code_assign_p = 0x50;
inline constexpr std::uint8_t code_assign_v = 0x56;
inline constexpr std::uint8_t digit_zero = 0x30; ///< ASCII "0"

[[nodiscard]] constexpr const family *find_family(op o) noexcept {
  for (const auto &f : families) {
    if (f.o == o) return &f;
  }
  return nullptr;
}

struct decoded_code {
  const family *f;
  arg_kind kind;
};

/// Command code → family and argument form (for the single-argument families).
[[nodiscard]] constexpr result<decoded_code> find_code(std::uint8_t code) noexcept {
  for (const auto &f : families) {
    if (code == f.code) return decoded_code{&f, arg_kind::value};
    if (f.has_forms && code == (f.code | parameter_flag))
      return decoded_code{&f, arg_kind::parameter};
    if (f.has_forms && code == (f.code | variable_flag))
      return decoded_code{&f, arg_kind::variable};
  }
  return errc::unknown_command;
}

/// May `second` follow `first` in a combined record (and `third` after both)?
[[nodiscard]] constexpr bool combination_allowed(const command &c) noexcept {
  if (c.code2 == op::none) return c.code3 == op::none;
  bool ok = false;
  switch (c.code) {
  case op::posa: ok = c.code2 == op::wait; break;
  case op::posr: ok = c.code2 == op::speed || c.code2 == op::wait || c.code2 == op::output; break;
  case op::speed: ok = c.code2 == op::wait; break;
  case op::wait:
    ok = c.a.kind == arg_kind::special && (c.code2 == op::posa || c.code2 == op::posr);
    break;
  default: break;
  }
  if (!ok) return false;
  if (c.code3 == op::none) return true;
  return c.code == op::posr && c.code2 == op::speed && c.code3 == op::accel;
}

/// Can a further command follow the `parts` (1 or 2) commands already in `c`?
[[nodiscard]] constexpr bool can_continue(const command &c, int parts) noexcept {
  if (parts == 1) {
    return c.code == op::posa || c.code == op::posr || c.code == op::speed ||
           (c.code == op::wait && c.a.kind == arg_kind::special);
  }
  return parts == 2 && c.code == op::posr && c.code2 == op::speed;
}

[[nodiscard]] constexpr status check_pattern(const pattern &p, std::uint16_t x,
                                             bool is_output) noexcept {
  if (p.count < 1U || p.count > 8U) return errc::bad_length;
  const bool a0 = is_output && x == 0U;
  if (a0 && p.count != 1U) return errc::bad_length;
  for (std::size_t i = 0; i < p.count; ++i) {
    if (p.digits[i] > (a0 ? 2U : 1U)) return errc::bad_digit;
  }
  for (std::size_t i = p.count; i < p.digits.size(); ++i) {
    if (p.digits[i] != 0U) return errc::invalid_argument;
  }
  return {};
}

[[nodiscard]] constexpr status write_word(byte_writer &w, std::int64_t v) noexcept {
  if (v < 0 || v > 0xFFFF) return errc::out_of_range;
  return w.write(static_cast<std::uint16_t>(v), byte_order::big);
}

/// Code and operands of one single-argument command.
[[nodiscard]] constexpr status write_simple(byte_writer &w, op o, const arg &a) noexcept {
  const family *f = find_family(o);
  if (f == nullptr) return errc::unknown_command;
  std::uint8_t code = f->code;
  if (a.kind == arg_kind::parameter || a.kind == arg_kind::variable) {
    if (!f->has_forms) return errc::type_mismatch;
    if (a.value < 0 || a.value > 0xFFFF) return errc::out_of_range;
    code = static_cast<std::uint8_t>(
        code | (a.kind == arg_kind::parameter ? parameter_flag : variable_flag));
  }
  if (a.kind == arg_kind::special && !f->has_special) return errc::type_mismatch;
  if ((f->s == shape::none || f->s == shape::zero) && a != arg{}) return errc::invalid_argument;
  FIELDCODEC_TRY_STATUS(w.write_u8(code));
  switch (f->s) {
  case shape::none: return {};
  case shape::zero: return w.write_u8(0);
  case shape::dsp:
    if (a.kind == arg_kind::special) return w.pad(6, 0xFF);
    if (a.kind == arg_kind::value) {
      if (a.value == -1) return errc::out_of_range; // FF FF FF FF FF FF is the special form
      std::array<std::uint8_t, 6> b{};
      FIELDCODEC_TRY_STATUS(encode_dsp(dsp_number{a.value}, b));
      return w.write_bytes(b);
    }
    FIELDCODEC_TRY_STATUS(w.write(static_cast<std::uint16_t>(a.value), byte_order::big));
    return w.pad(4, 0);
  case shape::word:
  case shape::word_only:
    if (a.kind == arg_kind::special) return w.write(std::uint16_t{0}, byte_order::big);
    // value 0 of WAIT / GOTO / GOSUB would read back as START / EXT
    if (a.kind == arg_kind::value && a.value == 0 && f->has_special) return errc::out_of_range;
    return write_word(w, a.value);
  }
  return {};
}

[[nodiscard]] constexpr status write_operand(byte_writer &w, const operand &o) noexcept {
  switch (o.type) {
  case operand_type::constant: {
    if (o.number != 0U) return errc::invalid_argument;
    FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(o.type)));
    std::array<std::uint8_t, 6> b{};
    FIELDCODEC_TRY_STATUS(encode_dsp(o.constant, b));
    return w.write_bytes(b);
  }
  case operand_type::parameter:
  case operand_type::status:
  case operand_type::variable:
    if (o.constant != dsp_number{}) return errc::invalid_argument;
    FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(o.type)));
    FIELDCODEC_TRY_STATUS(w.write(o.number, byte_order::big));
    return w.pad(4, 0);
  }
  return errc::invalid_argument;
}

[[nodiscard]] constexpr bool known(comparison c) noexcept {
  return c == comparison::eq || c == comparison::lt || c == comparison::gt || c == comparison::le ||
         c == comparison::ge || c == comparison::ne;
}
[[nodiscard]] constexpr bool known(arithmetic a) noexcept {
  return a == arithmetic::add || a == arithmetic::sub || a == arithmetic::mul ||
         a == arithmetic::div || a == arithmetic::int_div || a == arithmetic::mod;
}

[[nodiscard]] constexpr status write_jump(byte_writer &w, jump j, std::uint16_t target) noexcept {
  if (j != jump::goto_ && j != jump::gosub) return errc::invalid_argument;
  FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(j)));
  return w.write(target, byte_order::big);
}

[[nodiscard]] constexpr status write_pattern(byte_writer &w, const pattern &p) noexcept {
  for (std::size_t i = 0; i < p.count; ++i) {
    FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(digit_zero + p.digits[i])));
  }
  return {};
}

} // namespace detail

/// The content bytes of `c` (without the length byte) into `out`; returns their number.
/// Errors: unknown_command, type_mismatch (a form the command does not have), invalid_argument
/// (combination not in the table, members set that the command does not use), out_of_range
/// (number beyond its field, WAIT/GOTO/GOSUB 0, a DSP value that reads as the special form),
/// bad_digit / bad_length (pattern), overflow (DSP value), buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> encode_content(const command &c,
                                                           std::span<std::uint8_t> out) noexcept {
  byte_writer w{out};
  switch (c.code) {
  case op::if_input: {
    const bool special = c.number == input_error || c.number == input_stop;
    if (special && c.pat != pattern{1, {1}}) return errc::invalid_argument;
    FIELDCODEC_TRY_STATUS(detail::check_pattern(c.pat, c.number, false));
    FIELDCODEC_TRY_STATUS(w.write_u8(detail::code_if_input));
    FIELDCODEC_TRY_STATUS(w.write(c.number, byte_order::big));
    FIELDCODEC_TRY_STATUS(detail::write_pattern(w, c.pat));
    FIELDCODEC_TRY_STATUS(detail::write_jump(w, c.jmp, c.target));
    return w.size();
  }
  case op::if_compare:
    if (!detail::known(c.cmp)) return errc::invalid_argument;
    FIELDCODEC_TRY_STATUS(w.write_u8(detail::code_if_compare));
    FIELDCODEC_TRY_STATUS(detail::write_operand(w, c.o1));
    FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(c.cmp)));
    FIELDCODEC_TRY_STATUS(detail::write_operand(w, c.o2));
    FIELDCODEC_TRY_STATUS(detail::write_jump(w, c.jmp, c.target));
    return w.size();
  case op::output:
    FIELDCODEC_TRY_STATUS(detail::check_pattern(c.pat, c.number, true));
    FIELDCODEC_TRY_STATUS(w.write_u8(detail::code_output));
    FIELDCODEC_TRY_STATUS(w.write(c.number, byte_order::big));
    FIELDCODEC_TRY_STATUS(detail::write_pattern(w, c.pat));
    return w.size();
  case op::assign_p:
  case op::assign_v:
    FIELDCODEC_TRY_STATUS(
        w.write_u8(c.code == op::assign_p ? detail::code_assign_p : detail::code_assign_v));
    FIELDCODEC_TRY_STATUS(w.write(c.number, byte_order::big));
    FIELDCODEC_TRY_STATUS(detail::write_operand(w, c.o1));
    if (c.ari != arithmetic::none) {
      if (!detail::known(c.ari)) return errc::invalid_argument;
      FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(c.ari)));
      FIELDCODEC_TRY_STATUS(detail::write_operand(w, c.o2));
    } else if (c.o2 != operand{}) {
      return errc::invalid_argument;
    }
    return w.size();
  case op::valid:
    if (c.letter != 'P' && c.letter != 'C' && c.letter != 'F') return errc::invalid_argument;
    FIELDCODEC_TRY_STATUS(w.write_u8(0x01));
    FIELDCODEC_TRY_STATUS(w.write_u8(0x56)); // "V"
    FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(c.letter)));
    return w.size();
  case op::none: return errc::unknown_command;
  default: break;
  }
  if (!detail::combination_allowed(c)) return errc::invalid_argument;
  FIELDCODEC_TRY_STATUS(detail::write_simple(w, c.code, c.a));
  if (c.code2 == op::output) {
    FIELDCODEC_TRY_STATUS(detail::check_pattern(c.pat, c.number, true));
    FIELDCODEC_TRY_STATUS(w.write_u8(detail::code_output));
    FIELDCODEC_TRY_STATUS(w.write(c.number, byte_order::big));
    FIELDCODEC_TRY_STATUS(detail::write_pattern(w, c.pat));
    return w.size();
  }
  if (c.number != 0U || c.pat != pattern{}) return errc::invalid_argument;
  if (c.code2 != op::none) FIELDCODEC_TRY_STATUS(detail::write_simple(w, c.code2, c.b));
  if (c.code3 != op::none) FIELDCODEC_TRY_STATUS(detail::write_simple(w, c.code3, c.c));
  return w.size();
}

/// A full 20-byte record: length byte, content, zero padding. Errors: those of
/// encode_content (a content above 19 bytes is buffer_too_small, which the table never needs).
[[nodiscard]] constexpr result<record> encode_record(const command &c) noexcept {
  record r{};
  auto n = encode_content(c, std::span<std::uint8_t>{r}.subspan(1));
  if (!n) return n.error();
  r[0] = static_cast<std::uint8_t>(n.value());
  return r;
}

namespace detail {

[[nodiscard]] constexpr result<arg> read_simple_arg(byte_reader &rd, const family &f,
                                                    arg_kind kind) noexcept {
  switch (f.s) {
  case shape::none: return arg{};
  case shape::zero: {
    auto z = rd.read_u8();
    if (!z) return z.error();
    if (z.value() != 0U) return errc::out_of_range;
    return arg{};
  }
  case shape::dsp: {
    auto b = rd.read_bytes(6);
    if (!b) return b.error();
    const auto d = b.value();
    if (kind == arg_kind::value) {
      bool all_ff = true;
      for (const auto x : d) all_ff = all_ff && x == 0xFFU;
      if (all_ff) {
        if (!f.has_special) return errc::out_of_range;
        return special();
      }
      return arg{arg_kind::value, decode_dsp(d).value().raw};
    }
    if (d[2] != 0U || d[3] != 0U || d[4] != 0U || d[5] != 0U) return errc::out_of_range;
    return arg{kind, static_cast<std::int64_t>((d[0] << 8U) | d[1])};
  }
  case shape::word:
  case shape::word_only: {
    auto v = rd.read<std::uint16_t>(byte_order::big);
    if (!v) return v.error();
    if (kind == arg_kind::value && v.value() == 0U && f.has_special) return special();
    return arg{kind, v.value()};
  }
  }
  return errc::unknown_command;
}

[[nodiscard]] constexpr result<operand> read_operand(byte_reader &rd) noexcept {
  auto t = rd.read_u8();
  if (!t) return t.error();
  auto b = rd.read_bytes(6);
  if (!b) return b.error();
  const auto d = b.value();
  switch (t.value()) {
  case static_cast<std::uint8_t>(operand_type::constant): return constant(decode_dsp(d).value());
  case static_cast<std::uint8_t>(operand_type::parameter):
  case static_cast<std::uint8_t>(operand_type::status):
  case static_cast<std::uint8_t>(operand_type::variable):
    if (d[2] != 0U || d[3] != 0U || d[4] != 0U || d[5] != 0U) return errc::out_of_range;
    return operand_of(static_cast<operand_type>(t.value()),
                      static_cast<std::uint16_t>((d[0] << 8U) | d[1]));
  default: return errc::unknown_command;
  }
}

[[nodiscard]] constexpr status read_jump(byte_reader &rd, command &c) noexcept {
  auto j = rd.read_u8();
  if (!j) return j.error();
  if (j.value() != static_cast<std::uint8_t>(jump::goto_) &&
      j.value() != static_cast<std::uint8_t>(jump::gosub)) {
    return errc::unknown_command;
  }
  auto t = rd.read<std::uint16_t>(byte_order::big);
  if (!t) return t.error();
  c.jmp = static_cast<jump>(j.value());
  c.target = t.value();
  return {};
}

/// Digits until the end of the content (OUTPUT) or until a non-digit byte (IF).
[[nodiscard]] constexpr status read_pattern(byte_reader &rd, pattern &p, bool to_end) noexcept {
  p = pattern{};
  while (!rd.empty()) {
    const std::uint8_t b = rd.rest()[0];
    if (!to_end && (b == static_cast<std::uint8_t>(jump::goto_) ||
                    b == static_cast<std::uint8_t>(jump::gosub))) {
      break;
    }
    if (b < digit_zero || b > digit_zero + 9U) return errc::bad_digit;
    if (p.count == 8U) return errc::bad_length;
    p.digits[p.count++] = static_cast<std::uint8_t>(b - digit_zero);
    (void)rd.skip(1);
  }
  if (p.count == 0U) return errc::truncated;
  return {};
}

[[nodiscard]] constexpr result<command> read_content(byte_reader &rd) noexcept {
  auto code = rd.read_u8();
  if (!code) return code.error();
  command c{};
  switch (code.value()) {
  case code_if_input: {
    c.code = op::if_input;
    auto x = rd.read<std::uint16_t>(byte_order::big);
    if (!x) return x.error();
    c.number = x.value();
    FIELDCODEC_TRY_STATUS(read_pattern(rd, c.pat, false));
    FIELDCODEC_TRY_STATUS(check_pattern(c.pat, c.number, false));
    if ((c.number == input_error || c.number == input_stop) && c.pat != pattern{1, {1}}) {
      return errc::out_of_range;
    }
    FIELDCODEC_TRY_STATUS(read_jump(rd, c));
    return c;
  }
  case code_if_compare: {
    c.code = op::if_compare;
    auto a = read_operand(rd);
    if (!a) return a.error();
    auto cmp = rd.read_u8();
    if (!cmp) return cmp.error();
    c.cmp = static_cast<comparison>(cmp.value());
    if (!known(c.cmp)) return errc::unknown_command;
    auto b = read_operand(rd);
    if (!b) return b.error();
    c.o1 = a.value();
    c.o2 = b.value();
    FIELDCODEC_TRY_STATUS(read_jump(rd, c));
    return c;
  }
  case code_output: {
    c.code = op::output;
    auto x = rd.read<std::uint16_t>(byte_order::big);
    if (!x) return x.error();
    c.number = x.value();
    FIELDCODEC_TRY_STATUS(read_pattern(rd, c.pat, true));
    FIELDCODEC_TRY_STATUS(check_pattern(c.pat, c.number, true));
    return c;
  }
  case code_assign_p:
  case code_assign_v: {
    c.code = code.value() == code_assign_p ? op::assign_p : op::assign_v;
    auto n = rd.read<std::uint16_t>(byte_order::big);
    if (!n) return n.error();
    c.number = n.value();
    auto a = read_operand(rd);
    if (!a) return a.error();
    c.o1 = a.value();
    if (rd.empty()) return c;
    auto ari = rd.read_u8();
    c.ari = static_cast<arithmetic>(ari.value());
    if (!known(c.ari)) return errc::unknown_command;
    auto b = read_operand(rd);
    if (!b) return b.error();
    c.o2 = b.value();
    return c;
  }
  case 0x01: {
    c.code = op::valid;
    auto v = rd.read_u8();
    auto l = rd.read_u8();
    if (!v || !l) return errc::truncated;
    if (v.value() != 0x56U) return errc::unknown_command;
    if (l.value() != 'P' && l.value() != 'C' && l.value() != 'F') return errc::unknown_command;
    c.letter = static_cast<char>(l.value());
    return c;
  }
  default: break;
  }
  auto d = find_code(code.value());
  if (!d) return d.error();
  c.code = d.value().f->o;
  auto a = read_simple_arg(rd, *d.value().f, d.value().kind);
  if (!a) return a.error();
  c.a = a.value();
  for (int part = 0; part < 2 && !rd.empty() && can_continue(c, part + 1); ++part) {
    auto next = rd.read_u8();
    if (next.value() == code_output && part == 0) {
      c.code2 = op::output;
      auto x = rd.read<std::uint16_t>(byte_order::big);
      if (!x) return x.error();
      c.number = x.value();
      FIELDCODEC_TRY_STATUS(read_pattern(rd, c.pat, true));
      FIELDCODEC_TRY_STATUS(check_pattern(c.pat, c.number, true));
      break;
    }
    auto nd = find_code(next.value());
    if (!nd) return nd.error();
    auto na = read_simple_arg(rd, *nd.value().f, nd.value().kind);
    if (!na) return na.error();
    if (part == 0) {
      c.code2 = nd.value().f->o;
      c.b = na.value();
    } else {
      c.code3 = nd.value().f->o;
      c.c = na.value();
    }
  }
  if (!combination_allowed(c)) return errc::unknown_command;
  return c;
}

} // namespace detail

/// Content bytes (no length byte) → command. All bytes must be used.
/// Errors: truncated (content ends inside a command), bad_length (bytes left over),
/// unknown_command (command, operand, comparison or arithmetic code not in the table, or a
/// combination the table does not have), bad_digit (y not 0x30/0x31), out_of_range (non-zero
/// padding inside an operand).
[[nodiscard]] constexpr result<command> decode_content(std::span<const std::uint8_t> in) noexcept {
  byte_reader rd{in};
  auto c = detail::read_content(rd);
  if (!c) return c.error();
  if (!rd.empty()) return errc::bad_length;
  return c;
}

/// A record (length byte + content [+ padding], at most 20 bytes) → command.
/// Errors: truncated (fewer bytes than the length byte says, or empty), too_long (more than 20
/// bytes), bad_length (length 0 or above 19, or a length that disagrees with the content),
/// and those of decode_content.
[[nodiscard]] constexpr result<command> decode_record(std::span<const std::uint8_t> in) noexcept {
  if (in.empty()) return errc::truncated;
  if (in.size() > record_size) return errc::too_long;
  const std::size_t n = in[0];
  if (n == 0U || n > content_max) return errc::bad_length;
  if (in.size() < 1U + n) return errc::truncated;
  auto c = decode_content(in.subspan(1, n));
  if (!c && c.error() == errc::truncated) return errc::bad_length; // length too short for it
  return c;
}

} // namespace fieldcodec::compax::nx
