// fieldcodec — COMPAX Nx binary program records (object 0x5FD5, manual 000, 2.11.2).
//
// A record is 20 bytes: data byte 1 = record length (number of content bytes, 1..19), then the
// content, then padding (written as 0x00, ignored when read: the manual calls only the first
// "record length" bytes relevant). The content is one command: a 1-byte command code and its
// operands, possibly followed by the second and third command of a combined record
// (POSR … SPEED … ACCEL …, … WAIT …, … OUTPUT …, WAIT POSA/POSR …).
//
// Numbers carry their unit, as the program text writes them: nx::integer(250) and
// nx::value(decimal{2505, 1}) are 250 and 250.5 in the command's unit (mm or inch for POSA,
// POSR; % for SPEED; ms for ACCEL and WAIT; a count or record number otherwise). The 6-byte
// fields of POSA/POSR/SPEED/SETM and of IF/assignment constants hold such a number in the DSP
// format (dsp_number.hpp); a raw DSP value is spelled explicitly: nx::dsp_raw(…).
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
#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

// The path of one to three single-argument commands (POSR … SPEED … ACCEL …) is inlined where
// it is called (issue 18): an encoder's caller knows the operations, and the table look-ups, the
// combination check and the shape dispatch fold away; a decoder's caller reads the fields it
// wants without a copy of the whole command. decode_record reads the combined positioning
// record POSR v SPEED v ACCEL v by a straight path and leaves every other record to a general
// reader kept out of line (FIELDCODEC_NX_OUTLINE), so that the straight path stays small where
// it is inlined (issue 18, round 4). Built for size (-Os, firmware) the compiler decides and
// keeps one copy, and the straight path is not compiled.
#if defined(__OPTIMIZE_SIZE__) || !defined(__GNUC__)
#define FIELDCODEC_NX_INLINE
#define FIELDCODEC_NX_OUTLINE
#else
#define FIELDCODEC_NX_INLINE [[gnu::always_inline]]
#define FIELDCODEC_NX_OUTLINE [[gnu::noinline]]
#endif

namespace fieldcodec::compax::nx {

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
  dsp_raw,   ///< a raw DSP value (POSA/POSR/SPEED/SETM): raw / 2^24 of the command's unit
  parameter, ///< P<number>
  variable,  ///< V<number>
  special,   ///< POSA HOME, POSR CAM, SPEED SYNC, WAIT START, GOTO EXT, GOSUB EXT
};

/// The argument of a single-argument command. `number` is, by kind: the number in the
/// command's unit times 10^places (value()), the raw DSP integer (`places` is ignored), the
/// parameter or variable number, or 0 for a special; `places` is 0 except for a value. Build it
/// with the functions below (value() keeps a normalized decimal). Arguments compare by what
/// they stand for: a raw DSP value on the 0.001 grid equals the decimal it encodes
/// (nx::dsp_raw(250 * 2^24) == nx::integer(250)); nx::normalized() gives that decimal form.
struct arg {
  arg_kind kind = arg_kind::value;
  std::uint8_t places = 0;
  std::int64_t number = 0;

  /// `number` × 10^-places: for kind value the number in the command's unit, for a parameter or
  /// variable its number; for dsp_raw the raw integer (normalized(a).value() is the decimal of a
  /// raw value on the grid).
  [[nodiscard]] constexpr decimal value() const noexcept { return {number, places}; }
};

namespace detail {
/// Can `raw` lie on the 0.001 grid? A raw value on it is r = ±round(t·2^24 / 1000) for a whole t,
/// so |1000·r − (±t·2^24)| <= 500 and 1000·raw + 500 lies in [0, 1000] modulo 2^24 (both
/// signs). Almost every other raw value fails this in four instructions, so the exact test
/// (two divisions) runs only for the few that pass (issue 18; tests/compax/nx_speed_test.cpp).
[[nodiscard]] constexpr bool may_be_on_grid(std::int64_t raw) noexcept {
  constexpr std::uint64_t mask = static_cast<std::uint64_t>(dsp_format::one) - 1U;
  return ((static_cast<std::uint64_t>(raw) * 1000U + 500U) & mask) <= 1000U;
}

/// The argument of a raw value that passed may_be_on_grid: the decimal it stands for (kind
/// value) when it is on the grid, else the raw integer (kind dsp_raw).
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr arg from_dsp_near_grid(dsp_number n) noexcept {
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
/// The same, out of line: a reader whose caller then branches on the argument keeps fewer
/// values in registers when the rare case is a call (issue 18, round 4: decode_record's
/// straight path 100 -> 87 Ir). An encoder inlines it: there the call cost 15 Ir.
FIELDCODEC_NX_OUTLINE [[nodiscard]] constexpr arg from_dsp_near_grid_call(dsp_number n) noexcept {
  return from_dsp_near_grid(n);
}

/// A DSP number as an argument value: on the 0.001 grid it is the decimal it stands for
/// (kind value), otherwise the raw integer (kind dsp_raw).
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr arg from_dsp(dsp_number n) noexcept {
  if (!may_be_on_grid(n.raw)) return arg{arg_kind::dsp_raw, 0, n.raw};
  return from_dsp_near_grid(n);
}

/// number × 10^-places in units of 10^-target. Errors: not_representable (a non-zero digit
/// beyond `target` places), overflow (outside int64).
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr result<std::int64_t>
scaled_to(std::int64_t number, std::uint8_t places, std::uint8_t target) noexcept {
  for (; places > target; --places) {
    if (number % 10 != 0) return errc::not_representable;
    number /= 10;
  }
  if (places == target) return number;
  // one multiplication: it overflows exactly when one of the steps by 10 would
  const unsigned k = static_cast<unsigned>(target - places);
  if (k > decimal_max_places) { // 10^k is beyond int64: only 0 scales
    if (number != 0) return errc::overflow;
    return number;
  }
  if (__builtin_mul_overflow(number, fieldcodec::detail::pow10_i64(k), &number)) {
    return errc::overflow;
  }
  return number;
}
} // namespace detail

/// The one form of an argument, the form decode_record gives: a raw DSP value (kind dsp_raw)
/// on the 0.001 grid becomes the decimal it stands for (kind value, normalized), one off the
/// grid stays dsp_raw (places 0); every other argument is returned as it is. A raw value is
/// kept raw by dsp_raw() (issue 18, round 6); this is where it is read as a decimal.
[[nodiscard]] constexpr arg normalized(const arg &a) noexcept {
  if (a.kind != arg_kind::dsp_raw) return a;
  return detail::from_dsp(dsp_number{a.number});
}

/// Equal when they stand for the same argument: compared in their normalized() forms, so a raw
/// DSP value on the grid equals the decimal it encodes and the argument decode_record gives
/// for its bytes. (For any other pair this is the comparison of the three members.)
[[nodiscard]] constexpr bool operator==(const arg &a, const arg &b) noexcept {
  if (a.kind == b.kind && a.places == b.places && a.number == b.number) return true;
  if (a.kind != arg_kind::dsp_raw && b.kind != arg_kind::dsp_raw) return false;
  const arg x = normalized(a);
  const arg y = normalized(b);
  return x.kind == y.kind && x.places == y.places && x.number == y.number;
}

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
/// A raw DSP value (value = raw / 2^24 of the unit), for the 6-byte fields only; any integer
/// type (a value outside int64 saturates, the encoder says overflow). The argument is kept raw
/// (kind dsp_raw), also on the 0.001 grid: it still compares equal to the decimal it stands
/// for, prints as that decimal and encodes to the same bytes; normalized() gives the decimal
/// form (what decode_record returns). Until round 6 an on-grid raw value had kind value.
[[nodiscard]] constexpr arg dsp_raw(dsp_number n) noexcept { return {arg_kind::dsp_raw, 0, n.raw}; }
template <integer_argument T>
[[nodiscard]] constexpr arg dsp_raw(T raw) noexcept {
  return {arg_kind::dsp_raw, 0, compax::detail::saturate_i64(raw)};
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
  friend constexpr bool operator==(const family &, const family &) = default;
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
static_assert(static_cast<unsigned>(arg_kind::variable) < 4U, "and an argument kind into 2");

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

/// Position in `families` of the family of `o`, no_family when it has none. The lookups answer
/// with positions, not pointers into the table: g++ cannot constant-evaluate a comparison of
/// such a pointer with nullptr under -fsanitize=undefined (issue 12).
// Built for size (-Os, firmware), the lookups scan `families` as before instead: the tables
// cost 280 bytes of flash, the scan finds the same entry (tests/compax/nx_lookup_test.cpp).
[[nodiscard]] constexpr std::uint8_t family_position(op o) noexcept {
#ifdef __OPTIMIZE_SIZE__
  for (std::size_t i = 0; i < families.size(); ++i) {
    if (families[i].o == o) return static_cast<std::uint8_t>(i);
  }
  return no_family;
#endif
  const auto k = static_cast<std::size_t>(o);
  return k < op_count ? family_index[k] : no_family;
}

/// The family of `o`. Errors: unknown_command (no single-argument command).
[[nodiscard]] constexpr result<family> find_family(op o) noexcept {
  const std::uint8_t i = family_position(o);
  if (i == no_family) return errc::unknown_command;
  return families[i];
}

struct decoded_code {
  family f;
  arg_kind kind;
};

/// Command code → (family position) | (argument kind << 6: value 0, parameter 2, variable 3),
/// no_family for an unknown code: the first match of the table scan below, for every code byte,
/// computed at compile time.
inline constexpr std::array<std::uint8_t, 256> code_index = [] {
  std::array<std::uint8_t, 256> t{};
  for (unsigned code = 0; code < 256U; ++code) {
    t[code] = no_family;
    for (std::size_t i = 0; i < families.size(); ++i) {
      const family &f = families[i];
      arg_kind kind = arg_kind::special; // none
      if (code == f.code) {
        kind = arg_kind::value;
      } else if (f.has_forms && code == (f.code | parameter_flag)) {
        kind = arg_kind::parameter;
      } else if (f.has_forms && code == (f.code | variable_flag)) {
        kind = arg_kind::variable;
      }
      if (kind != arg_kind::special) {
        t[code] = static_cast<std::uint8_t>(i | (static_cast<unsigned>(kind) << 6U));
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
    if (code == f.code) return decoded_code{f, arg_kind::value};
    if (f.has_forms && code == (f.code | parameter_flag)) {
      return decoded_code{f, arg_kind::parameter};
    }
    if (f.has_forms && code == (f.code | variable_flag)) {
      return decoded_code{f, arg_kind::variable};
    }
  }
  return errc::unknown_command;
#endif
  const std::uint8_t e = code_index[code];
  if (e == no_family) return errc::unknown_command;
  return decoded_code{families[e & 0x3FU], static_cast<arg_kind>(e >> 6U)};
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
  if (v < 0 || v > 0xFFFF) return errc::out_of_range;
  return static_cast<std::uint16_t>(v);
}

/// A whole number from a value argument. Errors: not_representable (decimal places).
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr result<std::int64_t> whole(decimal d) noexcept {
  return scaled_to(d.mantissa, d.places, 0);
}

/// A value or raw DSP number → its DSP number.
/// Errors: not_representable (more than 3 places), overflow (outside the DSP range).
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr result<dsp_number> to_dsp(decimal v,
                                                                       bool raw) noexcept {
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
  if (a.kind == arg_kind::dsp_raw) return detail::to_dsp(a.value(), true);
  if (a.kind != arg_kind::value) return errc::type_mismatch;
  return detail::to_dsp(a.value(), false);
}

// ------------------------------------------------------------------ encoder

namespace detail {

/// The content of a record under construction is written at known offsets: a writer takes the
/// position of its first byte and returns the position after its last. The longest command of
/// the table has 19 content bytes (IF <operand><cmp><operand> GOTO n: 1 + 7 + 1 + 7 + 3), every
/// write below comes after the checks that select one of those shapes, and a record has room
/// for 19 after its length byte, so no write needs a bounds check (issue 18: the checked
/// byte_writer paid one per byte). tests/compax/nx_speed_test.cpp encodes the longest form of
/// every shape. Positions are passed by value, not kept in a writer object: a byte store may
/// alias any object in memory, which made the compiler reload a writer's position after each.
constexpr std::size_t put_u16(record &r, std::size_t at, std::uint16_t v) noexcept {
  r[at] = static_cast<std::uint8_t>(v >> 8U); // MSB first
  r[at + 1U] = static_cast<std::uint8_t>(v);
  return at + 2U;
}
FIELDCODEC_NX_INLINE constexpr std::size_t put_dsp(record &r, std::size_t at,
                                                   std::int64_t raw) noexcept {
  const auto u = static_cast<std::uint64_t>(raw); // NL NM NH VL VM VH: least significant first
  // On a little-endian host the six bytes are the first six of u in memory: copied from a
  // bit_cast they become one 4-byte and one 2-byte store; the shift loop below (any host, the
  // same bytes) left the two high bytes to a shift and a store each (issue 18, round 6: 6 Ir
  // of the combined positioning record).
  if constexpr (std::endian::native == std::endian::little) {
    const auto b = std::bit_cast<std::array<std::uint8_t, sizeof u>>(u);
    for (std::size_t i = 0; i < dsp_format::size; ++i) r[at + i] = b[i];
    return at + dsp_format::size;
  }
  for (std::size_t i = 0; i < dsp_format::size; ++i) {
    r[at + i] = static_cast<std::uint8_t>(u >> (8U * i));
  }
  return at + dsp_format::size;
}
/// A number form of a 6-byte field: 2 bytes MSB first, then four 0x00.
constexpr std::size_t put_number_form(record &r, std::size_t at, std::uint16_t v) noexcept {
  return put_dsp(r, at, static_cast<std::int64_t>((v >> 8U) | ((v & 0xFFU) << 8U)));
}

/// Code and operands of one single-argument command at r[at…]; returns the next position.
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr result<std::size_t>
write_simple(record &r, std::size_t at, op o, arg a) noexcept {
  const std::uint8_t i = family_position(o);
  if (i == no_family) return errc::unknown_command;
  const family &f = families[i];
  if (a.kind == arg_kind::dsp_raw && f.s != shape::dsp) {
    // a raw value on the grid is the decimal it stands for (ACCEL dsp_raw(250 * 2^24) is
    // ACCEL 250); the 6-byte fields write a raw value as it is
    a = normalized(a);
    if (a.kind == arg_kind::dsp_raw) return errc::type_mismatch;
  }
  std::uint8_t code = f.code;
  const bool numbered = a.kind == arg_kind::parameter || a.kind == arg_kind::variable;
  if (numbered) {
    if (!f.has_forms) return errc::type_mismatch;
    code = static_cast<std::uint8_t>(
        code | (a.kind == arg_kind::parameter ? parameter_flag : variable_flag));
  }
  if (a.kind == arg_kind::special && !f.has_special) return errc::type_mismatch;
  // a == arg{} member by member (a is not dsp_raw here: the comparison need not normalize)
  if ((f.s == shape::none || f.s == shape::zero) &&
      (a.kind != arg_kind::value || a.places != 0U || a.number != 0)) {
    return errc::invalid_argument;
  }
  // numbers are checked before anything is written
  if (numbered && (a.number < 0 || a.number > 0xFFFF)) return errc::out_of_range;
  switch (f.s) {
  case shape::none: r[at] = code; return at + 1U;
  case shape::zero:
    r[at] = code;
    r[at + 1U] = 0;
    return at + 2U;
  case shape::dsp: {
    r[at] = code;
    if (numbered) return put_number_form(r, at + 1U, static_cast<std::uint16_t>(a.number));
    std::int64_t raw = -1; // special: FF FF FF FF FF FF
    if (a.kind == arg_kind::dsp_raw) {
      raw = a.number;
      if (raw < dsp_format::raw_min || raw > dsp_format::raw_max) return errc::overflow;
      if (raw == -1) return errc::out_of_range; // it would read as the special form
    } else if (a.kind != arg_kind::special) {
      auto n = to_dsp(a.value(), false);
      if (!n) return n.error();
      raw = n.value().raw;
      if (raw == -1) return errc::out_of_range;
    }
    return put_dsp(r, at + 1U, raw);
  }
  case shape::word:
  case shape::word_only: {
    std::int64_t v = 0; // special: 0x0000
    if (numbered) {
      v = a.number;
    } else if (a.kind != arg_kind::special) {
      if (a.kind == arg_kind::value) {
        auto n = whole(a.value());
        if (!n) return n.error();
        v = n.value();
        // value 0 of WAIT / GOTO / GOSUB would read back as START / EXT
        // (the family's constant first: tested after v, GCC 12 kept a test of v == 0 for ACCEL)
        if (f.has_special && v == 0) return errc::out_of_range;
      } else {
        v = a.number;
      }
      if (v < 0 || v > 0xFFFF) return errc::out_of_range;
    }
    r[at] = code;
    return put_u16(r, at + 1U, static_cast<std::uint16_t>(v));
  }
  }
  return at;
}

[[nodiscard]] constexpr result<std::size_t> write_operand(record &r, std::size_t at,
                                                          operand o) noexcept {
  switch (o.type) {
  case operand_type::constant: {
    auto n = to_dsp(o.value(), o.raw);
    if (!n) return n.error();
    r[at] = static_cast<std::uint8_t>(o.type);
    return put_dsp(r, at + 1U, n.value().raw);
  }
  case operand_type::parameter:
  case operand_type::status:
  case operand_type::variable: {
    if (o.raw || o.places != 0U) return errc::invalid_argument;
    auto n = field16(o.number);
    if (!n) return n.error();
    r[at] = static_cast<std::uint8_t>(o.type);
    return put_number_form(r, at + 1U, n.value());
  }
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

[[nodiscard]] constexpr result<std::size_t> write_jump(record &r, std::size_t at, jump j,
                                                       std::int64_t target) noexcept {
  if (j != jump::goto_ && j != jump::gosub) return errc::invalid_argument;
  auto t = field16(target);
  if (!t) return t.error();
  r[at] = static_cast<std::uint8_t>(j);
  return put_u16(r, at + 1U, t.value());
}

constexpr std::size_t write_pattern(record &r, std::size_t at, const pattern &p) noexcept {
  for (std::size_t i = 0; i < p.count; ++i) {
    r[at + i] = static_cast<std::uint8_t>(digit_zero + p.digits[i]);
  }
  return at + p.count;
}

/// OUTPUT A<number>=<io_pattern> (the code and its operands).
[[nodiscard]] constexpr result<std::size_t> write_output(record &r, std::size_t at,
                                                         const command &c) noexcept {
  FIELDCODEC_TRY_STATUS(check_pattern(c.io_pattern, c.number, true));
  auto x = field16(c.number);
  if (!x) return x.error();
  r[at] = code_output;
  return write_pattern(r, put_u16(r, at + 1U, x.value()), c.io_pattern);
}

/// The commands that are not one to three single-argument commands, into r[1…]; returns the
/// position after the content.
[[nodiscard]] constexpr result<std::size_t> write_compound(const command &c, record &r) noexcept {
  std::size_t at = 1;
  switch (c.operation) {
  case op::if_input: {
    const bool special = c.number == input_error || c.number == input_stop;
    if (special && c.io_pattern != pattern{1, {1}}) return errc::invalid_argument;
    FIELDCODEC_TRY_STATUS(check_pattern(c.io_pattern, c.number, false));
    auto x = field16(c.number);
    if (!x) return x.error();
    r[at] = code_if_input;
    at = write_pattern(r, put_u16(r, at + 1U, x.value()), c.io_pattern);
    return write_jump(r, at, c.jump_kind, c.target);
  }
  case op::if_compare: {
    if (!known(c.comparison_op)) return errc::invalid_argument;
    r[at] = code_if_compare;
    FIELDCODEC_TRY(at, write_operand(r, at + 1U, c.left));
    r[at] = static_cast<std::uint8_t>(c.comparison_op);
    FIELDCODEC_TRY(at, write_operand(r, at + 1U, c.right));
    return write_jump(r, at, c.jump_kind, c.target);
  }
  case op::output: return write_output(r, at, c);
  case op::assign_p:
  case op::assign_v: {
    auto n = field16(c.number);
    if (!n) return n.error();
    r[at] = c.operation == op::assign_p ? code_assign_p : code_assign_v;
    FIELDCODEC_TRY(at, write_operand(r, put_u16(r, at + 1U, n.value()), c.left));
    if (c.arithmetic_op != arithmetic::none) {
      if (!known(c.arithmetic_op)) return errc::invalid_argument;
      r[at] = static_cast<std::uint8_t>(c.arithmetic_op);
      return write_operand(r, at + 1U, c.right);
    }
    if (c.right != operand{}) return errc::invalid_argument;
    return at;
  }
  case op::valid:
    if (c.valid_letter != 'P' && c.valid_letter != 'C' && c.valid_letter != 'F') {
      return errc::invalid_argument;
    }
    r[1] = code_valid;
    r[2] = valid_marker;
    r[3] = static_cast<std::uint8_t>(c.valid_letter);
    return std::size_t{4};
  default: return errc::unknown_command;
  }
}

/// p == pattern{}, spelled field by field: the defaulted comparison compares the digits as
/// memory, and a command whose address is taken that way cannot be kept in registers.
[[nodiscard]] constexpr bool unset(const pattern &p) noexcept {
  const auto &d = p.digits;
  return (p.count | d[0] | d[1] | d[2] | d[3] | d[4] | d[5] | d[6] | d[7]) == 0U;
}

/// The content of `c` into r[1…]; returns its length (the length byte is left to the caller).
/// One to three single-argument commands (POSR … SPEED … ACCEL …) are written here, small
/// enough to be inlined, so that a compiler that knows the operations folds the table look-ups;
/// the rest is write_compound.
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr result<std::size_t> write_content(const command &c,
                                                                               record &r) noexcept {
  switch (c.operation) {
  case op::if_input:
  case op::if_compare:
  case op::output:
  case op::assign_p:
  case op::assign_v:
  case op::valid:
  case op::none: {
    auto end = write_compound(c, r);
    if (!end) return end.error();
    return end.value() - 1U;
  }
  default: break;
  }
  if (!combination_allowed(c)) return errc::invalid_argument;
  FIELDCODEC_TRY(std::size_t at, write_simple(r, 1, c.operation, c.argument));
  if (c.second_operation == op::output) {
    FIELDCODEC_TRY(at, write_output(r, at, c));
    return at - 1U;
  }
  if (c.number != 0 || !unset(c.io_pattern)) return errc::invalid_argument;
  if (c.second_operation != op::none) {
    FIELDCODEC_TRY(at, write_simple(r, at, c.second_operation, c.second_argument));
  }
  if (c.third_operation != op::none) {
    FIELDCODEC_TRY(at, write_simple(r, at, c.third_operation, c.third_argument));
  }
  return at - 1U;
}

} // namespace detail

/// The content bytes of `c` (without the length byte) into `out`; returns their number. The
/// command is checked completely before its size is compared with `out`, and `out` is written
/// only when the whole content fits.
/// Errors: unknown_command, type_mismatch (a form the command does not have), invalid_argument
/// (combination not in the table, members set that the command does not use), out_of_range
/// (a number beyond its field: P/S/V/E/A/record numbers and 2-byte values 0..65535;
/// WAIT/GOTO/GOSUB 0; a DSP value that reads as the special form), not_representable (a DSP
/// value with more than 3 decimal places, a 2-byte value with any), overflow (DSP range),
/// bad_digit / bad_length (pattern), buffer_too_small (a valid command longer than `out`).
[[nodiscard]] constexpr result<std::size_t> encode_content(const command &c,
                                                           std::span<std::uint8_t> out) noexcept {
  record r{};
  auto n = detail::write_content(c, r);
  if (!n) return n.error();
  if (n.value() > out.size()) return errc::buffer_too_small;
  for (std::size_t i = 0; i < n.value(); ++i) out[i] = r[1U + i];
  return n;
}

/// A full 20-byte record: length byte, content, zero padding. Errors: those of
/// encode_content (no valid command is longer than a record).
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr result<record>
encode_record(const command &c) noexcept {
  result<record> out{record{}}; // written in place: one return object, no copy of the record
  auto n = detail::write_content(c, out.value());
  if (n) {
    out.value()[0] = static_cast<std::uint8_t>(n.value());
  } else {
    out = n.error();
  }
  return out;
}

// ------------------------------------------------------------------ decoder

namespace detail {

/// The content of a record being read: `need(k)` checks once that k more bytes are there, the
/// reads after it are unchecked (issue 18: byte_reader checked and wrapped every byte).
struct content_reader {
  std::span<const std::uint8_t> in;
  std::size_t at = 0;

  [[nodiscard]] constexpr bool need(std::size_t k) const noexcept { return in.size() - at >= k; }
  [[nodiscard]] constexpr bool empty() const noexcept { return at == in.size(); }
  [[nodiscard]] constexpr std::uint8_t peek() const noexcept { return in[at]; }
  constexpr std::uint8_t u8() noexcept { return in[at++]; }
  constexpr std::uint16_t u16() noexcept { // MSB first
    const auto v = static_cast<std::uint16_t>((in[at] << 8U) | in[at + 1U]);
    at += 2U;
    return v;
  }
  /// Six bytes NL … VH, sign-extended from 48 bits. Written as a 4-byte and a 2-byte
  /// little-endian word, which compilers read with one load each.
  constexpr std::int64_t dsp() noexcept {
    const std::uint32_t lo = static_cast<std::uint32_t>(in[at]) |
                             (static_cast<std::uint32_t>(in[at + 1U]) << 8U) |
                             (static_cast<std::uint32_t>(in[at + 2U]) << 16U) |
                             (static_cast<std::uint32_t>(in[at + 3U]) << 24U);
    const std::uint32_t hi =
        static_cast<std::uint32_t>(in[at + 4U]) | (static_cast<std::uint32_t>(in[at + 5U]) << 8U);
    const std::uint64_t u = lo | (std::uint64_t{hi} << 32U);
    at += dsp_format::size;
    // sign extension from 48 bits by an arithmetic shift (C++20): a shift pair instead of an
    // exclusive or and a subtraction of a 64-bit constant
    return static_cast<std::int64_t>(u << 16U) >> 16U;
  }
};

/// The number of a P/S/V form: 2 bytes MSB first, then four 0x00 (6 bytes, checked by the
/// caller). Errors: out_of_range (non-zero padding).
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr result<std::uint16_t>
read_number_form(content_reader &rd) noexcept {
  const std::uint16_t n = rd.u16();
  const bool padded = (rd.u8() | rd.u8() | rd.u8() | rd.u8()) == 0U;
  if (!padded) return errc::out_of_range;
  return n;
}

FIELDCODEC_NX_INLINE [[nodiscard]] constexpr result<arg>
read_simple_arg(content_reader &rd, const family &f, arg_kind kind) noexcept {
  switch (f.s) {
  case shape::none: return arg{};
  case shape::zero:
    if (!rd.need(1)) return errc::truncated;
    if (rd.u8() != 0U) return errc::out_of_range;
    return arg{};
  case shape::dsp: {
    if (!rd.need(dsp_format::size)) return errc::truncated;
    if (kind != arg_kind::value) {
      auto n = read_number_form(rd);
      if (!n) return n.error();
      return arg{kind, 0, n.value()};
    }
    const std::int64_t raw = rd.dsp();
    if (raw == -1) { // all six bytes 0xFF
      if (!f.has_special) return errc::out_of_range;
      return special();
    }
    return from_dsp(dsp_number{raw});
  }
  case shape::word:
  case shape::word_only: {
    if (!rd.need(2)) return errc::truncated;
    const std::uint16_t v = rd.u16();
    if (kind == arg_kind::value && v == 0U && f.has_special) return special();
    return arg{kind, 0, v};
  }
  }
  return errc::unknown_command;
}

[[nodiscard]] constexpr result<operand> read_operand(content_reader &rd) noexcept {
  if (!rd.need(1 + dsp_format::size)) return errc::truncated;
  const std::uint8_t t = rd.u8();
  switch (t) {
  case static_cast<std::uint8_t>(operand_type::constant): return constant_raw(dsp_number{rd.dsp()});
  case static_cast<std::uint8_t>(operand_type::parameter):
  case static_cast<std::uint8_t>(operand_type::status):
  case static_cast<std::uint8_t>(operand_type::variable): {
    auto n = read_number_form(rd);
    if (!n) return n.error();
    return operand_of(static_cast<operand_type>(t), n.value());
  }
  default: return errc::unknown_command;
  }
}

[[nodiscard]] constexpr status read_jump(content_reader &rd, command &c) noexcept {
  if (!rd.need(1)) return errc::truncated;
  const std::uint8_t j = rd.u8();
  if (j != static_cast<std::uint8_t>(jump::goto_) && j != static_cast<std::uint8_t>(jump::gosub)) {
    return errc::unknown_command;
  }
  if (!rd.need(2)) return errc::truncated;
  c.jump_kind = static_cast<jump>(j);
  c.target = rd.u16();
  return {};
}

/// Digits until the end of the content (OUTPUT) or until a GOTO/GOSUB code (IF).
[[nodiscard]] constexpr status read_pattern(content_reader &rd, pattern &p, bool to_end) noexcept {
  p = pattern{};
  while (!rd.empty()) {
    const std::uint8_t b = rd.peek();
    if (!to_end && (b == static_cast<std::uint8_t>(jump::goto_) ||
                    b == static_cast<std::uint8_t>(jump::gosub))) {
      break;
    }
    if (b < digit_zero || b > digit_zero + 9U) return errc::bad_digit;
    if (p.count == 8U) return errc::bad_length;
    p.digits[p.count++] = static_cast<std::uint8_t>(b - digit_zero);
    ++rd.at;
  }
  if (p.count == 0U) return errc::truncated;
  return {};
}

struct output_part {
  std::uint16_t number = 0;
  pattern io_pattern{};
};

/// x and y… of OUTPUT Ax=y… after its code; they end the content. (Reader and command are
/// passed by value and returned: an object whose address goes to a function that is not
/// inlined must stay in memory, and every byte read would load and store the position.)
[[nodiscard]] constexpr result<output_part> read_output(content_reader rd) noexcept {
  if (!rd.need(2)) return errc::truncated;
  output_part o;
  o.number = rd.u16();
  FIELDCODEC_TRY_STATUS(read_pattern(rd, o.io_pattern, true));
  FIELDCODEC_TRY_STATUS(check_pattern(o.io_pattern, o.number, true));
  return o;
}

/// The commands after `code` that are not one to three single-argument commands; every byte
/// must be used.
[[nodiscard]] constexpr result<command> read_compound(content_reader rd,
                                                      std::uint8_t code) noexcept {
  command c{};
  switch (code) {
  case code_if_input: {
    c.operation = op::if_input;
    if (!rd.need(2)) return errc::truncated;
    c.number = rd.u16();
    FIELDCODEC_TRY_STATUS(read_pattern(rd, c.io_pattern, false));
    FIELDCODEC_TRY_STATUS(check_pattern(c.io_pattern, c.number, false));
    if ((c.number == input_error || c.number == input_stop) && c.io_pattern != pattern{1, {1}}) {
      return errc::out_of_range;
    }
    FIELDCODEC_TRY_STATUS(read_jump(rd, c));
    break;
  }
  case code_if_compare: {
    c.operation = op::if_compare;
    auto a = read_operand(rd);
    if (!a) return a.error();
    if (!rd.need(1)) return errc::truncated;
    c.comparison_op = static_cast<comparison>(rd.u8());
    if (!known(c.comparison_op)) return errc::unknown_command;
    auto b = read_operand(rd);
    if (!b) return b.error();
    c.left = a.value();
    c.right = b.value();
    FIELDCODEC_TRY_STATUS(read_jump(rd, c));
    break;
  }
  case code_output: {
    c.operation = op::output;
    FIELDCODEC_TRY(const output_part o, read_output(rd));
    c.number = o.number;
    c.io_pattern = o.io_pattern;
    rd.at = rd.in.size(); // the pattern runs to the end
    break;
  }
  case code_assign_p:
  case code_assign_v: {
    c.operation = code == code_assign_p ? op::assign_p : op::assign_v;
    if (!rd.need(2)) return errc::truncated;
    c.number = rd.u16();
    auto a = read_operand(rd);
    if (!a) return a.error();
    c.left = a.value();
    if (rd.empty()) break;
    c.arithmetic_op = static_cast<arithmetic>(rd.u8());
    if (!known(c.arithmetic_op)) return errc::unknown_command;
    auto b = read_operand(rd);
    if (!b) return b.error();
    c.right = b.value();
    break;
  }
  case code_valid: {
    c.operation = op::valid;
    if (!rd.need(2)) return errc::truncated;
    const std::uint8_t v = rd.u8();
    const std::uint8_t l = rd.u8();
    if (v != valid_marker) return errc::unknown_command;
    if (l != 'P' && l != 'C' && l != 'F') return errc::unknown_command;
    c.valid_letter = static_cast<char>(l);
    break;
  }
  default: return errc::unknown_command;
  }
  if (!rd.empty()) return errc::bad_length;
  return c;
}

/// Content → `c` (which starts as command{}); every byte must be used.
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr status read_content(content_reader &rd,
                                                                 command &c) noexcept {
  if (!rd.need(1)) return errc::truncated;
  const std::uint8_t code = rd.u8();
  switch (code) {
  case code_if_input:
  case code_if_compare:
  case code_output:
  case code_assign_p:
  case code_assign_v:
  case code_valid: {
    auto k = read_compound(rd, code);
    if (!k) return k.error();
    c = k.value();
    return {};
  }
  default: {
    auto d = find_code(code);
    if (!d) return d.error();
    c.operation = d.value().f.o;
    auto a = read_simple_arg(rd, d.value().f, d.value().kind);
    if (!a) return a.error();
    c.argument = a.value();
    for (int part = 0; part < 2 && !rd.empty() && can_continue(c, part + 1); ++part) {
      const std::uint8_t next = rd.u8();
      if (next == code_output && part == 0) {
        c.second_operation = op::output;
        auto o = read_output(rd);
        if (!o) return o.error();
        c.number = o.value().number;
        c.io_pattern = o.value().io_pattern;
        rd.at = rd.in.size(); // the pattern runs to the end
        break;
      }
      auto nd = find_code(next);
      if (!nd) return nd.error();
      auto na = read_simple_arg(rd, nd.value().f, nd.value().kind);
      if (!na) return na.error();
      if (part == 0) {
        c.second_operation = nd.value().f.o;
        c.second_argument = na.value();
      } else {
        c.third_operation = nd.value().f.o;
        c.third_argument = na.value();
      }
    }
    if (!combination_allowed(c)) return errc::unknown_command;
    break;
  }
  }
  if (!rd.empty()) return errc::bad_length;
  return {};
}

inline constexpr std::uint8_t code_posr = 0x52;
inline constexpr std::uint8_t code_speed = 0x53;
inline constexpr std::uint8_t code_accel = 0x4C;
static_assert(families[2] == family{op::posr, code_posr, shape::dsp, true, true} &&
                  families[3] == family{op::speed, code_speed, shape::dsp, true, true} &&
                  families[5] == family{op::accel, code_accel, shape::word, false, true},
              "decode_record's straight path reads the value forms of these three families");

/// The argument a value-form 6-byte field of a family with a special form (POSA, POSR, SPEED)
/// reads as: six 0xFF bytes are the special, anything else a value or raw DSP number (as
/// read_simple_arg reads it).
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr arg dsp_or_special(std::int64_t raw) noexcept {
  if (raw == -1) return special();
  if (!may_be_on_grid(raw)) return arg{arg_kind::dsp_raw, 0, raw};
  return from_dsp_near_grid_call(dsp_number{raw});
}

/// decode_record's general reader (the content after the length byte). Out of line, so that a
/// caller that inlines decode_record keeps the straight path small: inlined, this code's
/// registers were saved and restored on every call (issue 18, round 4).
FIELDCODEC_NX_OUTLINE [[nodiscard]] constexpr result<command>
read_record_content(std::span<const std::uint8_t> content) noexcept {
  command c{};
  content_reader rd{content};
  if (auto s = read_content(rd, c); !s) {
    if (s.error() == errc::truncated) return errc::bad_length; // length too short for it
    return s.error();
  }
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
  command c{};
  detail::content_reader rd{in};
  if (auto s = detail::read_content(rd, c); !s) return s.error();
  return c;
}

/// A record (length byte + content [+ padding], at most 20 bytes) → command.
/// Errors: truncated (fewer bytes than the length byte says, or empty), too_long (more than 20
/// bytes), bad_length (length 0 or above 19, or a length that disagrees with the content),
/// and those of decode_content.
FIELDCODEC_NX_INLINE [[nodiscard]] constexpr result<command>
decode_record(std::span<const std::uint8_t> in) noexcept {
  if (in.empty()) return errc::truncated;
  if (in.size() > record_size) return errc::too_long;
#ifndef __OPTIMIZE_SIZE__
  // Straight path for the combined positioning record, POSR v SPEED v ACCEL v (all value
  // forms; length byte 17, so the length checks below pass): three code bytes compared, three
  // fields read, no table look-up, no dispatch and no combination check (the combination is
  // allowed). It reads exactly what the general reader reads (tests/compax/nx_speed_test.cpp).
  // Built for size, only the general reader is kept.
  if (in[0] == 17U && in.size() >= 18U && in[1] == detail::code_posr &&
      in[8] == detail::code_speed && in[15] == detail::code_accel) {
    detail::content_reader rd{in, 2};
    command c{};
    c.operation = op::posr;
    c.argument = detail::dsp_or_special(rd.dsp());
    ++rd.at;
    c.second_operation = op::speed;
    c.second_argument = detail::dsp_or_special(rd.dsp());
    ++rd.at;
    c.third_operation = op::accel;
    c.third_argument = arg{arg_kind::value, 0, rd.u16()}; // ACCEL has no special form
    return c;
  }
#endif
  const std::size_t n = in[0];
  if (n == 0U || n > content_max) return errc::bad_length;
  if (in.size() < 1U + n) return errc::truncated;
  return detail::read_record_content(in.subspan(1, n));
}

} // namespace fieldcodec::compax::nx
