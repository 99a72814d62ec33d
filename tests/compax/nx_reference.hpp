// The COMPAX Nx record codec as it was before issue 18 (byte_writer / byte_reader, a command
// built and copied whole, table scans answering with pointers), kept verbatim but for the
// namespace (nx_reference) as the reference of tests/compax/nx_speed_test.cpp. Not part of the
// library.
#pragma once

#include <fieldcodec/compax/dsp_number.hpp>
#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::compax::nx_reference {

inline constexpr std::size_t record_size = 20;
inline constexpr std::size_t content_max = record_size - 1U;

using record = std::array<std::uint8_t, record_size>;

/// Command operations. `none` marks an unused second or third command of a record.
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
  value,     ///< a number in the command's unit, as the program text writes it
  dsp_raw,   ///< a raw DSP value off the 0.001 grid (POSA/POSR/SPEED/SETM only): raw / 2^24
  parameter, ///< P<number>
  variable,  ///< V<number>
  special,   ///< POSA HOME, POSR CAM, SPEED SYNC, WAIT START, GOTO EXT, GOSUB EXT
};

/// The argument of a single-argument command. `number` is, by kind: the number in the
/// command's unit times 10^places (value()), the raw DSP integer, the parameter or variable
/// number, or 0 for a special; `places` is 0 except for a value. Build it with the functions
/// below; they keep one representation per argument (a normalized decimal) so that equal
/// arguments compare equal.
struct arg {
  arg_kind kind = arg_kind::value;
  std::uint8_t places = 0;
  std::int64_t number = 0;

  /// The number as a decimal (kind value: in the command's unit).
  [[nodiscard]] constexpr decimal value() const noexcept { return {number, places}; }
  friend constexpr bool operator==(const arg &, const arg &) = default;
};

namespace detail {
/// A DSP number as an argument value: on the 0.001 grid it is the decimal it stands for
/// (kind value), otherwise the raw integer (kind dsp_raw).
[[nodiscard]] constexpr arg from_dsp(dsp_number n) noexcept {
  auto t = n.exact_thousandths();
  if (!t) return arg{arg_kind::dsp_raw, 0, n.raw};
  // the normalized decimal of t / 1000 (at most 3 trailing zeros to drop)
  std::int64_t v = t.value();
  std::uint8_t places = 3;
  while (places > 0U && v % 10 == 0) {
    v /= 10;
    --places;
  }
  return arg{arg_kind::value, places, v};
}

/// number × 10^-places in units of 10^-target. Errors: not_representable (a non-zero digit
/// beyond `target` places), overflow (outside int64).
[[nodiscard]] constexpr result<std::int64_t> scaled_to(std::int64_t number, std::uint8_t places,
                                                       std::uint8_t target) noexcept {
  for (; places > target; --places) {
    if (number % 10 != 0) return errc::not_representable;
    number /= 10;
  }
  for (; places < target; ++places) {
    if (__builtin_mul_overflow(number, 10, &number)) return errc::overflow;
  }
  return number;
}
} // namespace detail

/// The whole number `v` in the command's unit: nx::make(op::posa, nx::integer(250)) is
/// POSA 250 (mm), nx::make(op::accel, nx::integer(200)) is ACCEL 200 (ms). Any integer type; a
/// value the field cannot hold is refused by the encoder (out_of_range / overflow), never
/// wrapped.
template <integer_argument T>
[[nodiscard]] constexpr arg integer(T v) noexcept {
  return {arg_kind::value, 0, compax::detail::saturate_i64(v)};
}
/// An exact decimal in the command's unit: nx::value(decimal{2505, 1}) is 250.5. The 6-byte DSP
/// fields take at most 3 decimal places (the program's resolution), the 2-byte fields whole
/// numbers; the encoder says not_representable otherwise.
[[nodiscard]] constexpr arg value(decimal d) noexcept {
  const decimal n = normalize(d);
  return {arg_kind::value, n.places, n.mantissa};
}
/// A raw DSP value (value = raw / 2^24 of the unit), for the 6-byte fields only. A raw value on
/// the 0.001 grid is kept as the decimal it stands for (kind value).
[[nodiscard]] constexpr arg dsp_raw(dsp_number n) noexcept { return detail::from_dsp(n); }
template <integer_argument T>
[[nodiscard]] constexpr arg dsp_raw(T raw) noexcept {
  return detail::from_dsp(dsp_number{compax::detail::saturate_i64(raw)});
}
/// P<n> / V<n>, n = 0..65535 (checked by the encoder).
template <integer_argument T>
[[nodiscard]] constexpr arg parameter(T n) noexcept {
  return {arg_kind::parameter, 0, compax::detail::saturate_i64(n)};
}
template <integer_argument T>
[[nodiscard]] constexpr arg variable(T n) noexcept {
  return {arg_kind::variable, 0, compax::detail::saturate_i64(n)};
}
[[nodiscard]] constexpr arg special() noexcept { return {arg_kind::special, 0, 0}; }

/// IF / assignment operands (7 bytes: type + 6 data bytes).
enum class operand_type : std::uint8_t {
  constant = 0x20,  ///< a number in DSP format
  parameter = 0x50, ///< P<n>
  status = 0x53,    ///< S<n>
  variable = 0x56,  ///< V<n>
};

/// One operand. `number` is, by type: the constant times 10^places (value(); or the raw DSP
/// integer when `raw`), or the parameter / status / variable number (places 0).
struct operand {
  operand_type type = operand_type::constant;
  std::uint8_t places = 0;
  bool raw = false; ///< a constant given as a raw DSP value off the 0.001 grid
  std::int64_t number = 0;

  /// The constant as a decimal (meaningful for a constant that is not `raw`).
  [[nodiscard]] constexpr decimal value() const noexcept { return {number, places}; }
  friend constexpr bool operator==(const operand &, const operand &) = default;
};

/// The constant `v` (IF V1>=5: constant(5)); at most 3 decimal places (encoder:
/// not_representable), DSP range (overflow).
template <integer_argument T>
[[nodiscard]] constexpr operand constant(T v) noexcept {
  return {operand_type::constant, 0, false, compax::detail::saturate_i64(v)};
}
[[nodiscard]] constexpr operand constant(decimal d) noexcept {
  const decimal n = normalize(d);
  return {operand_type::constant, n.places, false, n.mantissa};
}
/// A constant given as a raw DSP value (kept as the decimal it stands for when on the grid).
[[nodiscard]] constexpr operand constant_raw(dsp_number n) noexcept {
  const arg a = detail::from_dsp(n);
  return {operand_type::constant, a.places, a.kind == arg_kind::dsp_raw, a.number};
}
/// P<n>, S<n> or V<n> (n = 0..65535, checked by the encoder).
template <integer_argument T>
[[nodiscard]] constexpr operand operand_of(operand_type t, T n) noexcept {
  return {t, 0, false, compax::detail::saturate_i64(n)};
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

/// One Nx command. Which members are used depends on `operation`; unused ones stay at their
/// defaults so that equal commands compare equal (the encoder refuses a command that sets
/// members its operation does not use). Numbers are kept as given (any integer type through
/// the builders) and range-checked by the encoder.
struct command {
  op operation = op::nop;                    ///< the command (the first one of a combined record)
  op second_operation = op::none;            ///< combined record: SPEED, WAIT, OUTPUT, POSA or POSR
  op third_operation = op::none;             ///< combined record: ACCEL after POSR … SPEED …
  jump jump_kind = jump::goto_;              ///< IF …: GOTO or GOSUB
  comparison comparison_op = comparison::eq; ///< IF <left><comparison_op><right> …
  arithmetic arithmetic_op = arithmetic::none; ///< Pn=/Vn=: none, or the operator before `right`
  char valid_letter = 0;                       ///< VALID: 'P', 'C' or 'F'
  arg argument{};          ///< the argument of `operation` (single-argument commands)
  arg second_argument{};   ///< the argument of `second_operation`
  arg third_argument{};    ///< the argument of `third_operation`
  std::int64_t number = 0; ///< x of IF Ex=… / OUTPUT Ax=… (also POSR … OUTPUT), n of Pn= / Vn=
  std::int64_t target = 0; ///< IF …: the record jumped to
  pattern io_pattern{};    ///< the y digits of IF Ex=y… / OUTPUT Ax=y…
  operand left{};          ///< IF: the operand before the comparison; Pn=/Vn=: the first operand
  operand right{};         ///< IF: the operand after the comparison; Pn=/Vn=: the second operand

  friend constexpr bool operator==(const command &, const command &) = default;
};

// ------------------------------------------------------------------ builders

/// A single command with one argument (POSA, POSR, SPEED, SETM, ACCEL, WAIT, REPEAT, LOOP,
/// SETC, GOTO, GOSUB) or none (NOP, SETS, END, RETURN).
[[nodiscard]] constexpr command make(op o, arg a = {}) noexcept {
  command c{};
  c.operation = o;
  c.argument = a;
  return c;
}
/// Append the second (or, when there is one, the third) command of a combined record.
[[nodiscard]] constexpr command then(command c, op o, arg a) noexcept {
  if (c.second_operation == op::none) {
    c.second_operation = o;
    c.second_argument = a;
  } else {
    c.third_operation = o;
    c.third_argument = a;
  }
  return c;
}
[[nodiscard]] constexpr command make_valid(char letter) noexcept {
  command c{};
  c.operation = op::valid;
  c.valid_letter = letter;
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
/// IF E<input>=<p> GOTO|GOSUB <target> (input and target 0..65535, checked by the encoder).
template <integer_argument X, integer_argument N>
[[nodiscard]] constexpr command make_if_input(X input, pattern p, jump j, N target) noexcept {
  command c{};
  c.operation = op::if_input;
  c.number = compax::detail::saturate_i64(input);
  c.io_pattern = p;
  c.jump_kind = j;
  c.target = compax::detail::saturate_i64(target);
  return c;
}
template <integer_argument N>
[[nodiscard]] constexpr command make_if_error(jump j, N target) noexcept {
  return make_if_input(input_error, pattern{1, {1}}, j, target);
}
template <integer_argument N>
[[nodiscard]] constexpr command make_if_stop(jump j, N target) noexcept {
  return make_if_input(input_stop, pattern{1, {1}}, j, target);
}
/// IF <left><cmp><right> GOTO|GOSUB <target>.
template <integer_argument N>
[[nodiscard]] constexpr command make_if_compare(operand left, comparison cmp, operand right, jump j,
                                                N target) noexcept {
  command c{};
  c.operation = op::if_compare;
  c.left = left;
  c.comparison_op = cmp;
  c.right = right;
  c.jump_kind = j;
  c.target = compax::detail::saturate_i64(target);
  return c;
}
/// OUTPUT A<output>=<p> (output 0..65535, checked by the encoder).
template <integer_argument X>
[[nodiscard]] constexpr command make_output(X output, pattern p) noexcept {
  command c{};
  c.operation = op::output;
  c.number = compax::detail::saturate_i64(output);
  c.io_pattern = p;
  return c;
}
/// POSR … OUTPUT A<output>=<p>.
template <integer_argument X>
[[nodiscard]] constexpr command then_output(command c, X output, pattern p) noexcept {
  c.second_operation = op::output;
  c.number = compax::detail::saturate_i64(output);
  c.io_pattern = p;
  return c;
}
/// P<n>=<value> (assignment = op::assign_p) or V<n>=<value> (op::assign_v); n = 0..65535.
template <integer_argument N>
[[nodiscard]] constexpr command make_assign(op assignment, N n, operand value) noexcept {
  command c{};
  c.operation = assignment;
  c.number = compax::detail::saturate_i64(n);
  c.left = value;
  return c;
}
/// P<n>=<left><ari><right> / V<n>=<left><ari><right>.
template <integer_argument N>
[[nodiscard]] constexpr command make_assign(op assignment, N n, operand left, arithmetic ari,
                                            operand right) noexcept {
  command c = make_assign(assignment, n, left);
  c.arithmetic_op = ari;
  c.right = right;
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
inline constexpr std::uint8_t code_valid = 0x01;
inline constexpr std::uint8_t valid_marker = 0x56; ///< "V" of VALIDP / VALIDC / VALIDF
inline constexpr std::uint8_t code_if_input = 0x49;
inline constexpr std::uint8_t code_if_compare = 0x4A;
inline constexpr std::uint8_t code_output = 0x4F;
inline constexpr std::uint8_t code_assign_p = 0x50;
inline constexpr std::uint8_t code_assign_v = 0x56;
inline constexpr std::uint8_t digit_zero = 0x30; ///< ASCII "0"

inline constexpr std::uint8_t no_family = 0xFF;
inline constexpr std::size_t op_count = static_cast<std::size_t>(op::assign_v) + 1U;
static_assert(families.size() < 64U, "code_index packs a family position into 6 bits");

/// op → position in `families` of the first family of that op (no_family: none), built at
/// compile time from the table, so that find_family is one load (issue 18).
inline constexpr std::array<std::uint8_t, op_count> family_index = [] {
  std::array<std::uint8_t, op_count> t{};
  for (std::size_t o = 0; o < op_count; ++o) {
    t[o] = no_family;
    for (std::size_t i = 0; i < families.size(); ++i) {
      if (static_cast<std::size_t>(families[i].o) == o) {
        t[o] = static_cast<std::uint8_t>(i);
        break;
      }
    }
  }
  return t;
}();

// Built for size (-Os, firmware), the two lookups scan `families` as before instead: the tables
// cost 280 bytes of flash, the scan finds the same entry (tests/compax/nx_lookup_test.cpp).
[[nodiscard]] constexpr const family *find_family(op o) noexcept {
#ifdef __OPTIMIZE_SIZE__
  for (const auto &f : families) {
    if (f.o == o) return &f;
  }
  return nullptr;
#endif
  const auto k = static_cast<std::size_t>(o);
  if (k >= op_count) return nullptr;
  const std::uint8_t i = family_index[k];
  return i == no_family ? nullptr : &families[i];
}

struct decoded_code {
  const family *f;
  arg_kind kind;
};

/// Command code → (family position) | (argument form << 6), no_family for an unknown code: the
/// first match of the table scan below, for every code byte, computed at compile time.
inline constexpr std::array<std::uint8_t, 256> code_index = [] {
  std::array<std::uint8_t, 256> t{};
  for (unsigned code = 0; code < 256U; ++code) {
    t[code] = no_family;
    for (std::size_t i = 0; i < families.size(); ++i) {
      const family &f = families[i];
      unsigned form = 4; // none
      if (code == f.code) {
        form = 0;
      } else if (f.has_forms && code == (f.code | parameter_flag)) {
        form = 1;
      } else if (f.has_forms && code == (f.code | variable_flag)) {
        form = 2;
      }
      if (form != 4U) {
        t[code] = static_cast<std::uint8_t>(i | (form << 6U));
        break;
      }
    }
  }
  return t;
}();

/// Command code → family and argument form (for the single-argument families), in one load.
[[nodiscard]] constexpr result<decoded_code> find_code(std::uint8_t code) noexcept {
#ifdef __OPTIMIZE_SIZE__
  for (const auto &f : families) {
    if (code == f.code) return decoded_code{&f, arg_kind::value};
    if (f.has_forms && code == (f.code | parameter_flag)) {
      return decoded_code{&f, arg_kind::parameter};
    }
    if (f.has_forms && code == (f.code | variable_flag)) {
      return decoded_code{&f, arg_kind::variable};
    }
  }
  return errc::unknown_command;
#endif
  const std::uint8_t e = code_index[code];
  if (e == no_family) return errc::unknown_command;
  constexpr arg_kind forms[3] = {arg_kind::value, arg_kind::parameter, arg_kind::variable};
  return decoded_code{&families[e & 0x3FU], forms[e >> 6U]};
}

/// May c.second_operation follow c.operation in a combined record (and c.third_operation
/// follow both)?
[[nodiscard]] constexpr bool combination_allowed(const command &c) noexcept {
  if (c.second_operation == op::none) return c.third_operation == op::none;
  bool ok = false;
  switch (c.operation) {
  case op::posa: ok = c.second_operation == op::wait; break;
  case op::posr:
    ok = c.second_operation == op::speed || c.second_operation == op::wait ||
         c.second_operation == op::output;
    break;
  case op::speed: ok = c.second_operation == op::wait; break;
  case op::wait:
    ok = c.argument.kind == arg_kind::special &&
         (c.second_operation == op::posa || c.second_operation == op::posr);
    break;
  default: break;
  }
  if (!ok) return false;
  if (c.third_operation == op::none) return true;
  return c.operation == op::posr && c.second_operation == op::speed &&
         c.third_operation == op::accel;
}

/// Can a further command follow the `parts` (1 or 2) commands already in `c`?
[[nodiscard]] constexpr bool can_continue(const command &c, int parts) noexcept {
  if (parts == 1) {
    return c.operation == op::posa || c.operation == op::posr || c.operation == op::speed ||
           (c.operation == op::wait && c.argument.kind == arg_kind::special);
  }
  return parts == 2 && c.operation == op::posr && c.second_operation == op::speed;
}

[[nodiscard]] constexpr status check_pattern(const pattern &p, std::int64_t x,
                                             bool is_output) noexcept {
  if (p.count < 1U || p.count > 8U) return errc::bad_length;
  const bool a0 = is_output && x == 0;
  if (a0 && p.count != 1U) return errc::bad_length;
  for (std::size_t i = 0; i < p.count; ++i) {
    if (p.digits[i] > (a0 ? 2U : 1U)) return errc::bad_digit;
  }
  for (std::size_t i = p.count; i < p.digits.size(); ++i) {
    if (p.digits[i] != 0U) return errc::invalid_argument;
  }
  return {};
}

/// A number of a 2-byte field (numbers of P, S, V, E, A, records; 2-byte values).
/// Errors: out_of_range (not 0..65535).
[[nodiscard]] constexpr result<std::uint16_t> field16(std::int64_t v) noexcept {
  auto u = checked_narrow<std::uint16_t>(v);
  if (!u) return errc::out_of_range;
  return u;
}

/// A number of a 2-byte field, MSB first. Errors: out_of_range (not 0..65535).
[[nodiscard]] constexpr status write_word(byte_writer &w, std::int64_t v) noexcept {
  auto u = field16(v);
  if (!u) return u.error();
  return w.write(u.value(), byte_order::big);
}

/// A whole number from a value argument. Errors: not_representable (decimal places).
[[nodiscard]] constexpr result<std::int64_t> whole(decimal d) noexcept {
  return scaled_to(d.mantissa, d.places, 0);
}

/// A value or raw DSP number → its DSP number.
/// Errors: not_representable (more than 3 places), overflow (outside the DSP range).
[[nodiscard]] constexpr result<dsp_number> to_dsp(decimal v, bool raw) noexcept {
  if (raw) {
    const dsp_number n{v.mantissa};
    if (n.raw < dsp_format::raw_min || n.raw > dsp_format::raw_max) return errc::overflow;
    return n;
  }
  auto t = scaled_to(v.mantissa, v.places, 3);
  if (!t) return t.error();
  return dsp_number::from_thousandths(t.value());
}

} // namespace detail

/// The DSP number a 6-byte field carries for a value or raw argument (value = raw / 2^24).
/// Errors: type_mismatch (parameter, variable or special), not_representable (a value with more
/// than 3 decimal places), overflow (outside the DSP range).
[[nodiscard]] constexpr result<dsp_number> dsp_of(const arg &a) noexcept {
  if (a.kind != arg_kind::value && a.kind != arg_kind::dsp_raw) return errc::type_mismatch;
  return detail::to_dsp(a.value(), a.kind == arg_kind::dsp_raw);
}

namespace detail {

/// Code and operands of one single-argument command.
[[nodiscard]] constexpr status write_simple(byte_writer &w, op o, const arg &a) noexcept {
  const family *f = find_family(o);
  if (f == nullptr) return errc::unknown_command;
  std::uint8_t code = f->code;
  if (a.kind == arg_kind::parameter || a.kind == arg_kind::variable) {
    if (!f->has_forms) return errc::type_mismatch;
    code = static_cast<std::uint8_t>(
        code | (a.kind == arg_kind::parameter ? parameter_flag : variable_flag));
  }
  if (a.kind == arg_kind::special && !f->has_special) return errc::type_mismatch;
  if (a.kind == arg_kind::dsp_raw && f->s != shape::dsp) return errc::type_mismatch;
  if ((f->s == shape::none || f->s == shape::zero) && a != arg{}) return errc::invalid_argument;
  if (a.kind == arg_kind::parameter || a.kind == arg_kind::variable) {
    // check the number before anything is written
    if (auto n = detail::field16(a.number); !n) return n.error();
  }
  FIELDCODEC_TRY_STATUS(w.write_u8(code));
  switch (f->s) {
  case shape::none: return {};
  case shape::zero: return w.write_u8(0);
  case shape::dsp: {
    if (a.kind == arg_kind::special) return w.pad(6, 0xFF);
    if (a.kind == arg_kind::parameter || a.kind == arg_kind::variable) {
      FIELDCODEC_TRY_STATUS(write_word(w, a.number));
      return w.pad(4, 0);
    }
    auto n = to_dsp(a.value(), a.kind == arg_kind::dsp_raw);
    if (!n) return n.error();
    if (n.value().raw == -1) return errc::out_of_range; // FF FF FF FF FF FF is the special form
    std::array<std::uint8_t, 6> b{};
    FIELDCODEC_TRY_STATUS(encode_dsp(n.value(), b));
    return w.write_bytes(b);
  }
  case shape::word:
  case shape::word_only: {
    if (a.kind == arg_kind::special) return w.write(std::uint16_t{0}, byte_order::big);
    if (a.kind != arg_kind::value) return write_word(w, a.number);
    auto v = whole(a.value());
    if (!v) return v.error();
    // value 0 of WAIT / GOTO / GOSUB would read back as START / EXT
    if (v.value() == 0 && f->has_special) return errc::out_of_range;
    return write_word(w, v.value());
  }
  }
  return {};
}

[[nodiscard]] constexpr status write_operand(byte_writer &w, const operand &o) noexcept {
  switch (o.type) {
  case operand_type::constant: {
    auto n = to_dsp(o.value(), o.raw);
    if (!n) return n.error();
    FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(o.type)));
    std::array<std::uint8_t, 6> b{};
    FIELDCODEC_TRY_STATUS(encode_dsp(n.value(), b));
    return w.write_bytes(b);
  }
  case operand_type::parameter:
  case operand_type::status:
  case operand_type::variable:
    if (o.raw || o.places != 0U) return errc::invalid_argument;
    if (auto n = detail::field16(o.number); !n) return n.error();
    FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(o.type)));
    FIELDCODEC_TRY_STATUS(write_word(w, o.number));
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

[[nodiscard]] constexpr status write_jump(byte_writer &w, jump j, std::int64_t target) noexcept {
  if (j != jump::goto_ && j != jump::gosub) return errc::invalid_argument;
  auto t = detail::field16(target);
  if (!t) return t.error();
  FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(j)));
  return w.write(t.value(), byte_order::big);
}

[[nodiscard]] constexpr status write_pattern(byte_writer &w, const pattern &p) noexcept {
  for (std::size_t i = 0; i < p.count; ++i) {
    FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(digit_zero + p.digits[i])));
  }
  return {};
}

/// OUTPUT A<number>=<io_pattern> (the code and its operands).
[[nodiscard]] constexpr status write_output(byte_writer &w, const command &c) noexcept {
  FIELDCODEC_TRY_STATUS(check_pattern(c.io_pattern, c.number, true));
  auto x = detail::field16(c.number);
  if (!x) return x.error();
  FIELDCODEC_TRY_STATUS(w.write_u8(code_output));
  FIELDCODEC_TRY_STATUS(w.write(x.value(), byte_order::big));
  return write_pattern(w, c.io_pattern);
}

} // namespace detail

/// The content bytes of `c` (without the length byte) into `out`; returns their number.
/// Errors: unknown_command, type_mismatch (a form the command does not have), invalid_argument
/// (combination not in the table, members set that the command does not use), out_of_range
/// (a number beyond its field: P/S/V/E/A/record numbers and 2-byte values 0..65535;
/// WAIT/GOTO/GOSUB 0; a DSP value that reads as the special form), not_representable (a DSP
/// value with more than 3 decimal places, a 2-byte value with any), overflow (DSP range),
/// bad_digit / bad_length (pattern), buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> encode_content(const command &c,
                                                           std::span<std::uint8_t> out) noexcept {
  byte_writer w{out};
  switch (c.operation) {
  case op::if_input: {
    const bool special = c.number == input_error || c.number == input_stop;
    if (special && c.io_pattern != pattern{1, {1}}) return errc::invalid_argument;
    FIELDCODEC_TRY_STATUS(detail::check_pattern(c.io_pattern, c.number, false));
    auto x = detail::field16(c.number);
    if (!x) return x.error();
    FIELDCODEC_TRY_STATUS(w.write_u8(detail::code_if_input));
    FIELDCODEC_TRY_STATUS(w.write(x.value(), byte_order::big));
    FIELDCODEC_TRY_STATUS(detail::write_pattern(w, c.io_pattern));
    FIELDCODEC_TRY_STATUS(detail::write_jump(w, c.jump_kind, c.target));
    return w.size();
  }
  case op::if_compare:
    if (!detail::known(c.comparison_op)) return errc::invalid_argument;
    FIELDCODEC_TRY_STATUS(w.write_u8(detail::code_if_compare));
    FIELDCODEC_TRY_STATUS(detail::write_operand(w, c.left));
    FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(c.comparison_op)));
    FIELDCODEC_TRY_STATUS(detail::write_operand(w, c.right));
    FIELDCODEC_TRY_STATUS(detail::write_jump(w, c.jump_kind, c.target));
    return w.size();
  case op::output: FIELDCODEC_TRY_STATUS(detail::write_output(w, c)); return w.size();
  case op::assign_p:
  case op::assign_v: {
    auto n = detail::field16(c.number);
    if (!n) return n.error();
    FIELDCODEC_TRY_STATUS(
        w.write_u8(c.operation == op::assign_p ? detail::code_assign_p : detail::code_assign_v));
    FIELDCODEC_TRY_STATUS(w.write(n.value(), byte_order::big));
    FIELDCODEC_TRY_STATUS(detail::write_operand(w, c.left));
    if (c.arithmetic_op != arithmetic::none) {
      if (!detail::known(c.arithmetic_op)) return errc::invalid_argument;
      FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(c.arithmetic_op)));
      FIELDCODEC_TRY_STATUS(detail::write_operand(w, c.right));
    } else if (c.right != operand{}) {
      return errc::invalid_argument;
    }
    return w.size();
  }
  case op::valid:
    if (c.valid_letter != 'P' && c.valid_letter != 'C' && c.valid_letter != 'F') {
      return errc::invalid_argument;
    }
    FIELDCODEC_TRY_STATUS(w.write_u8(detail::code_valid));
    FIELDCODEC_TRY_STATUS(w.write_u8(detail::valid_marker));
    FIELDCODEC_TRY_STATUS(w.write_u8(static_cast<std::uint8_t>(c.valid_letter)));
    return w.size();
  case op::none: return errc::unknown_command;
  default: break;
  }
  if (!detail::combination_allowed(c)) return errc::invalid_argument;
  FIELDCODEC_TRY_STATUS(detail::write_simple(w, c.operation, c.argument));
  if (c.second_operation == op::output) {
    FIELDCODEC_TRY_STATUS(detail::write_output(w, c));
    return w.size();
  }
  if (c.number != 0 || c.io_pattern != pattern{}) return errc::invalid_argument;
  if (c.second_operation != op::none) {
    FIELDCODEC_TRY_STATUS(detail::write_simple(w, c.second_operation, c.second_argument));
  }
  if (c.third_operation != op::none) {
    FIELDCODEC_TRY_STATUS(detail::write_simple(w, c.third_operation, c.third_argument));
  }
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

/// The number in a P/S/V form: 2 bytes MSB first, then four 0x00.
/// Errors: out_of_range (non-zero padding).
[[nodiscard]] constexpr result<std::uint16_t>
read_number_form(std::span<const std::uint8_t> d) noexcept {
  if (d[2] != 0U || d[3] != 0U || d[4] != 0U || d[5] != 0U) return errc::out_of_range;
  return load<std::uint16_t>(d, byte_order::big);
}

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
      auto n = decode_dsp(d);
      if (!n) return n.error();
      return from_dsp(n.value());
    }
    auto n = read_number_form(d);
    if (!n) return n.error();
    return arg{kind, 0, n.value()};
  }
  case shape::word:
  case shape::word_only: {
    auto v = rd.read<std::uint16_t>(byte_order::big);
    if (!v) return v.error();
    if (kind == arg_kind::value && v.value() == 0U && f.has_special) return special();
    return arg{kind, 0, v.value()};
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
  case static_cast<std::uint8_t>(operand_type::constant): {
    auto n = decode_dsp(d);
    if (!n) return n.error();
    return constant_raw(n.value());
  }
  case static_cast<std::uint8_t>(operand_type::parameter):
  case static_cast<std::uint8_t>(operand_type::status):
  case static_cast<std::uint8_t>(operand_type::variable): {
    auto n = read_number_form(d);
    if (!n) return n.error();
    return operand_of(static_cast<operand_type>(t.value()), n.value());
  }
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
  c.jump_kind = static_cast<jump>(j.value());
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

/// x and y… of OUTPUT Ax=y… after its code.
[[nodiscard]] constexpr status read_output(byte_reader &rd, command &c) noexcept {
  auto x = rd.read<std::uint16_t>(byte_order::big);
  if (!x) return x.error();
  c.number = x.value();
  FIELDCODEC_TRY_STATUS(read_pattern(rd, c.io_pattern, true));
  return check_pattern(c.io_pattern, c.number, true);
}

[[nodiscard]] constexpr result<command> read_content(byte_reader &rd) noexcept {
  auto code = rd.read_u8();
  if (!code) return code.error();
  command c{};
  switch (code.value()) {
  case code_if_input: {
    c.operation = op::if_input;
    auto x = rd.read<std::uint16_t>(byte_order::big);
    if (!x) return x.error();
    c.number = x.value();
    FIELDCODEC_TRY_STATUS(read_pattern(rd, c.io_pattern, false));
    FIELDCODEC_TRY_STATUS(check_pattern(c.io_pattern, c.number, false));
    if ((c.number == input_error || c.number == input_stop) && c.io_pattern != pattern{1, {1}}) {
      return errc::out_of_range;
    }
    FIELDCODEC_TRY_STATUS(read_jump(rd, c));
    return c;
  }
  case code_if_compare: {
    c.operation = op::if_compare;
    auto a = read_operand(rd);
    if (!a) return a.error();
    auto cmp = rd.read_u8();
    if (!cmp) return cmp.error();
    c.comparison_op = static_cast<comparison>(cmp.value());
    if (!known(c.comparison_op)) return errc::unknown_command;
    auto b = read_operand(rd);
    if (!b) return b.error();
    c.left = a.value();
    c.right = b.value();
    FIELDCODEC_TRY_STATUS(read_jump(rd, c));
    return c;
  }
  case code_output:
    c.operation = op::output;
    FIELDCODEC_TRY_STATUS(read_output(rd, c));
    return c;
  case code_assign_p:
  case code_assign_v: {
    c.operation = code.value() == code_assign_p ? op::assign_p : op::assign_v;
    auto n = rd.read<std::uint16_t>(byte_order::big);
    if (!n) return n.error();
    c.number = n.value();
    auto a = read_operand(rd);
    if (!a) return a.error();
    c.left = a.value();
    if (rd.empty()) return c;
    auto ari = rd.read_u8();
    c.arithmetic_op = static_cast<arithmetic>(ari.value());
    if (!known(c.arithmetic_op)) return errc::unknown_command;
    auto b = read_operand(rd);
    if (!b) return b.error();
    c.right = b.value();
    return c;
  }
  case code_valid: {
    c.operation = op::valid;
    auto v = rd.read_u8();
    auto l = rd.read_u8();
    if (!v || !l) return errc::truncated;
    if (v.value() != valid_marker) return errc::unknown_command;
    if (l.value() != 'P' && l.value() != 'C' && l.value() != 'F') return errc::unknown_command;
    c.valid_letter = static_cast<char>(l.value());
    return c;
  }
  default: break;
  }
  auto d = find_code(code.value());
  if (!d) return d.error();
  c.operation = d.value().f->o;
  auto a = read_simple_arg(rd, *d.value().f, d.value().kind);
  if (!a) return a.error();
  c.argument = a.value();
  for (int part = 0; part < 2 && !rd.empty() && can_continue(c, part + 1); ++part) {
    auto next = rd.read_u8();
    if (next.value() == code_output && part == 0) {
      c.second_operation = op::output;
      FIELDCODEC_TRY_STATUS(read_output(rd, c));
      break;
    }
    auto nd = find_code(next.value());
    if (!nd) return nd.error();
    auto na = read_simple_arg(rd, *nd.value().f, nd.value().kind);
    if (!na) return na.error();
    if (part == 0) {
      c.second_operation = nd.value().f->o;
      c.second_argument = na.value();
    } else {
      c.third_operation = nd.value().f->o;
      c.third_argument = na.value();
    }
  }
  if (!combination_allowed(c)) return errc::unknown_command;
  return c;
}

} // namespace detail

/// Content bytes (no length byte) → command. All bytes must be used. DSP values on the 0.001
/// grid come back as the decimal they stand for (kind value), others as dsp_raw.
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

} // namespace fieldcodec::compax::nx_reference
