// fieldcodec — COMPAX Nx commands as program text, the way the manual writes them
// ("POSA 250", "IF E5=1 GOTO 12", "POSR 100 SPEED 50 ACCEL 200", "P12=V3+5").
//
// Text form (one space between words, no spaces inside an operand expression):
//   NOP  SETS  END  RETURN  VALIDP|VALIDC|VALIDF  SETC n
//   POSA|POSR|SPEED|SETM x      x = decimal with up to 3 places (in the command's unit), Pn,
//                               Vn; POSA HOME, POSR CAM, SPEED SYNC
//   ACCEL|WAIT|REPEAT|LOOP x    x = integer 0..65535, Pn, Vn; WAIT START
//   GOTO n|EXT  GOSUB n|EXT
//   IF Ex=y… GOTO|GOSUB n   IF ERROR …   IF STOP …   IF <o1><cmp><o2> GOTO|GOSUB n
//   OUTPUT Ax=y…   Pn=<o1>[<ari><o2>]   Vn=<o1>[<ari><o2>]
//   POSA x WAIT y   POSR x SPEED y [ACCEL z]   POSR x WAIT y   POSR x OUTPUT Ax=y…
//   SPEED x WAIT y   WAIT POSA x   WAIT POSR x
// Operands: Pn, Sn, Vn or a decimal constant; comparisons = < > <= >= <>; arithmetic
// + - * / \ %. DSP values print with the fewest decimals (at most 3) that show them, a raw DSP
// value on the 0.001 grid (nx::dsp_raw) as the decimal it stands for; one off the grid has no
// program text: format_command says not_representable instead of printing a rounded number.
#pragma once

#include <fieldcodec/compax/dsp_number.hpp>
#include <fieldcodec/compax/nx.hpp>
#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::compax::nx {

/// A buffer this size holds the text of every command.
inline constexpr std::size_t text_max = 64;

namespace detail {

struct text_writer {
  std::span<char> out;
  std::size_t pos = 0;
  errc error = errc::truncated; ///< meaningful only when `failed`
  bool failed = false;

  constexpr void fail(errc e) noexcept {
    if (!failed) error = e;
    failed = true;
  }
  constexpr void put(char c) noexcept {
    if (pos < out.size()) {
      out[pos++] = c;
    } else {
      fail(errc::buffer_too_small);
    }
  }
  constexpr void put(std::string_view s) noexcept {
    for (const char c : s) put(c);
  }
  constexpr void put_unsigned(std::uint64_t v) noexcept {
    char tmp[20]{};
    auto n = ascii::format_unsigned(v, tmp);
    put(std::string_view{tmp, n.value()});
  }
  constexpr void put_decimal(decimal d) noexcept {
    char tmp[32]{};
    auto n = format_decimal(normalize(d), tmp);
    if (!n) {
      fail(n.error());
      return;
    }
    put(std::string_view{tmp, n.value()});
  }
};

struct names {
  op o;
  std::string_view word;
  std::string_view special;
};
inline constexpr std::array<names, 14> op_names{{
    {op::nop, "NOP", ""},
    {op::posa, "POSA", "HOME"},
    {op::posr, "POSR", "CAM"},
    {op::speed, "SPEED", "SYNC"},
    {op::setm, "SETM", ""},
    {op::accel, "ACCEL", ""},
    {op::wait, "WAIT", "START"},
    {op::repeat, "REPEAT", ""},
    {op::loop, "LOOP", ""},
    {op::setc, "SETC", ""},
    {op::sets, "SETS", ""},
    {op::gosub, "GOSUB", "EXT"},
    {op::goto_, "GOTO", "EXT"},
    {op::end, "END", ""},
}};

// The lookups answer with a copy, op::none when nothing matches, not with a pointer into the
// table: g++ cannot constant-evaluate a comparison of such a pointer with nullptr under
// -fsanitize=undefined (issue 12).
inline constexpr names no_names{op::none, "", ""};
[[nodiscard]] constexpr names find_names(op o) noexcept {
  for (const auto &n : op_names) {
    if (n.o == o) return n;
  }
  return no_names;
}
[[nodiscard]] constexpr names find_names(std::string_view w) noexcept {
  for (const auto &n : op_names) {
    if (n.word == w) return n;
  }
  return no_names;
}

[[nodiscard]] constexpr bool is_dsp_op(op o) noexcept {
  return o == op::posa || o == op::posr || o == op::speed || o == op::setm;
}

/// The argument as text (the command was validated by encode_content first, so numbers are in
/// range and values have the places their field allows).
constexpr void put_arg(text_writer &w, op o, const arg &given) noexcept {
  const arg a = normalized(given); // a raw value on the 0.001 grid prints as its decimal
  switch (a.kind) {
  case arg_kind::special: w.put(find_names(o).special); return;
  case arg_kind::parameter:
    w.put('P');
    w.put_decimal(a.value());
    return;
  case arg_kind::variable:
    w.put('V');
    w.put_decimal(a.value());
    return;
  case arg_kind::value: w.put_decimal(a.value()); return;
  case arg_kind::dsp_raw: w.fail(errc::not_representable); return;
  }
}

constexpr void put_simple(text_writer &w, op o, const arg &a) noexcept {
  w.put(find_names(o).word);
  const shape s = families[family_position(o)].s;
  if (s == shape::none || s == shape::zero) return;
  w.put(' ');
  put_arg(w, o, a);
}

constexpr void put_operand(text_writer &w, const operand &o) noexcept {
  switch (o.type) {
  case operand_type::constant:
    if (o.raw) {
      w.fail(errc::not_representable);
    } else {
      w.put_decimal(o.value());
    }
    return;
  case operand_type::parameter: w.put('P'); break;
  case operand_type::status: w.put('S'); break;
  case operand_type::variable: w.put('V'); break;
  }
  w.put_decimal(o.value());
}

[[nodiscard]] constexpr std::string_view symbol(comparison c) noexcept {
  switch (c) {
  case comparison::eq: return "=";
  case comparison::lt: return "<";
  case comparison::gt: return ">";
  case comparison::le: return "<=";
  case comparison::ge: return ">=";
  case comparison::ne: return "<>";
  }
  return "";
}
[[nodiscard]] constexpr char symbol(arithmetic a) noexcept {
  switch (a) {
  case arithmetic::add: return '+';
  case arithmetic::sub: return '-';
  case arithmetic::mul: return '*';
  case arithmetic::div: return '/';
  case arithmetic::int_div: return '\\';
  case arithmetic::mod: return '%';
  case arithmetic::none: break;
  }
  return '?';
}

constexpr void put_pattern(text_writer &w, char letter, std::int64_t x, const pattern &p) noexcept {
  w.put(letter);
  w.put_unsigned(static_cast<std::uint64_t>(x));
  w.put('=');
  for (std::size_t i = 0; i < p.count; ++i) w.put(static_cast<char>('0' + p.digits[i]));
}

constexpr void put_jump(text_writer &w, jump j, std::int64_t target) noexcept {
  w.put(j == jump::gosub ? " GOSUB " : " GOTO ");
  w.put_unsigned(static_cast<std::uint64_t>(target));
}

} // namespace detail

/// Write the program text of `c` into `out`; returns the number of characters.
/// Errors: those of encode_content (the command is validated first), not_representable (a raw
/// DSP value off the 0.001 grid: the program text has no spelling for it), buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> format_command(const command &c,
                                                           std::span<char> out) noexcept {
  std::array<std::uint8_t, content_max> scratch{};
  if (auto e = encode_content(c, scratch); !e) return e.error();
  detail::text_writer w{out};
  switch (c.operation) {
  case op::valid:
    w.put("VALID");
    w.put(c.valid_letter);
    break;
  case op::return_: w.put("RETURN"); break;
  case op::if_input:
    w.put("IF ");
    if (c.number == input_error) {
      w.put("ERROR");
    } else if (c.number == input_stop) {
      w.put("STOP");
    } else {
      detail::put_pattern(w, 'E', c.number, c.io_pattern);
    }
    detail::put_jump(w, c.jump_kind, c.target);
    break;
  case op::if_compare:
    w.put("IF ");
    detail::put_operand(w, c.left);
    w.put(detail::symbol(c.comparison_op));
    detail::put_operand(w, c.right);
    detail::put_jump(w, c.jump_kind, c.target);
    break;
  case op::output:
    w.put("OUTPUT ");
    detail::put_pattern(w, 'A', c.number, c.io_pattern);
    break;
  case op::assign_p:
  case op::assign_v:
    w.put(c.operation == op::assign_p ? 'P' : 'V');
    w.put_unsigned(static_cast<std::uint64_t>(c.number));
    w.put('=');
    detail::put_operand(w, c.left);
    if (c.arithmetic_op != arithmetic::none) {
      w.put(detail::symbol(c.arithmetic_op));
      detail::put_operand(w, c.right);
    }
    break;
  default:
    if (c.operation == op::wait && c.second_operation != op::none) {
      w.put("WAIT"); // WAIT POSA x / WAIT POSR x: the START is implied
    } else {
      detail::put_simple(w, c.operation, c.argument);
    }
    if (c.second_operation == op::output) {
      w.put(" OUTPUT ");
      detail::put_pattern(w, 'A', c.number, c.io_pattern);
    } else if (c.second_operation != op::none) {
      w.put(' ');
      detail::put_simple(w, c.second_operation, c.second_argument);
    }
    if (c.third_operation != op::none) {
      w.put(' ');
      detail::put_simple(w, c.third_operation, c.third_argument);
    }
    break;
  }
  if (w.failed) return w.error;
  return w.pos;
}

namespace detail {

struct tokens {
  std::string_view rest;
  /// The next space-separated word ("" at the end).
  constexpr std::string_view next() noexcept {
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    std::size_t n = 0;
    while (n < rest.size() && rest[n] != ' ') ++n;
    const std::string_view t = rest.substr(0, n);
    rest.remove_prefix(n);
    return t;
  }
  constexpr bool done() noexcept {
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    return rest.empty();
  }
};

[[nodiscard]] constexpr result<std::uint16_t> parse_u16(std::string_view s) noexcept {
  auto v = ascii::parse_unsigned(s);
  if (!v) return v.error();
  if (v.value() > 0xFFFFU) return errc::out_of_range;
  return static_cast<std::uint16_t>(v.value());
}

/// A DSP number as the program writes it: a decimal with at most 3 places in the command's
/// unit. Errors: those of parse_fixed (not_representable for a 4th place), overflow (DSP range).
[[nodiscard]] constexpr result<decimal> parse_dsp(std::string_view s) noexcept {
  auto t = parse_fixed(s, 3);
  if (!t) return t.error();
  if (auto n = dsp_number::from_thousandths(t.value()); !n) return n.error();
  return normalize(decimal{t.value(), 3});
}

[[nodiscard]] constexpr result<arg> parse_arg(op o, std::string_view s) noexcept {
  if (s.empty()) return errc::bad_syntax;
  const names n = find_names(o);
  if (!n.special.empty() && s == n.special) return special();
  if (s.front() == 'P' || s.front() == 'V') {
    auto num = parse_u16(s.substr(1));
    if (!num) return num.error();
    return s.front() == 'P' ? parameter(num.value()) : variable(num.value());
  }
  if (is_dsp_op(o)) {
    auto d = parse_dsp(s);
    if (!d) return d.error();
    return value(d.value());
  }
  auto v = parse_u16(s);
  if (!v) return v.error();
  return integer(v.value());
}

/// Length of a leading operand in `s`: Pn / Sn / Vn or a decimal constant (optional '-').
[[nodiscard]] constexpr std::size_t operand_length(std::string_view s) noexcept {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == 'P' || s[i] == 'S' || s[i] == 'V')) {
    ++i;
  } else if (i < s.size() && s[i] == '-') {
    ++i;
  }
  while (i < s.size() && (ascii::is_digit(s[i]) || s[i] == '.')) ++i;
  return i;
}

[[nodiscard]] constexpr result<operand> parse_operand(std::string_view s) noexcept {
  if (s.empty()) return errc::bad_syntax;
  const char t = s.front();
  if (t == 'P' || t == 'S' || t == 'V') {
    auto n = parse_u16(s.substr(1));
    if (!n) return n.error();
    const operand_type ty = t == 'P'   ? operand_type::parameter
                            : t == 'S' ? operand_type::status
                                       : operand_type::variable;
    return operand_of(ty, n.value());
  }
  auto d = parse_dsp(s);
  if (!d) return d.error();
  return constant(d.value());
}

[[nodiscard]] constexpr result<pattern> parse_pattern(std::string_view s) noexcept {
  if (s.empty() || s.size() > 8U) return errc::bad_length;
  pattern p{};
  for (const char ch : s) {
    if (!ascii::is_digit(ch)) return errc::bad_digit;
    p.digits[p.count++] = static_cast<std::uint8_t>(ch - '0');
  }
  return p;
}

/// "E5=101" / "A3=1" → number and pattern.
[[nodiscard]] constexpr status parse_io(std::string_view s, char letter, command &c) noexcept {
  if (s.size() < 2U || s.front() != letter) return errc::bad_syntax;
  const auto eq = s.find('=');
  if (eq == std::string_view::npos) return errc::bad_syntax;
  auto x = parse_u16(s.substr(1, eq - 1U));
  if (!x) return x.error();
  auto p = parse_pattern(s.substr(eq + 1U));
  if (!p) return p.error();
  c.number = x.value();
  c.io_pattern = p.value();
  return {};
}

[[nodiscard]] constexpr status parse_jump(tokens &t, command &c) noexcept {
  const auto j = t.next();
  if (j == "GOTO") {
    c.jump_kind = jump::goto_;
  } else if (j == "GOSUB") {
    c.jump_kind = jump::gosub;
  } else {
    return errc::bad_syntax;
  }
  auto n = parse_u16(t.next());
  if (!n) return n.error();
  c.target = n.value();
  return {};
}

[[nodiscard]] constexpr result<comparison> parse_comparison(std::string_view &s) noexcept {
  constexpr std::array<comparison, 6> order{comparison::le, comparison::ge, comparison::ne,
                                            comparison::eq, comparison::lt, comparison::gt};
  for (const comparison c : order) {
    const auto sym = symbol(c);
    if (s.substr(0, sym.size()) == sym) {
      s.remove_prefix(sym.size());
      return c;
    }
  }
  return errc::bad_syntax;
}

[[nodiscard]] constexpr result<command> parse_if(tokens &t) noexcept {
  const auto cond = t.next();
  command c{};
  if (cond == "ERROR" || cond == "STOP") {
    c = make_if_input(cond == "ERROR" ? input_error : input_stop, pattern{1, {1}}, jump::goto_, 0);
  } else if (!cond.empty() && cond.front() == 'E') {
    c.operation = op::if_input;
    FIELDCODEC_TRY_STATUS(parse_io(cond, 'E', c));
  } else {
    c.operation = op::if_compare;
    std::string_view s = cond;
    const std::size_t n1 = operand_length(s);
    auto a = parse_operand(s.substr(0, n1));
    if (!a) return a.error();
    s.remove_prefix(n1);
    auto cmp = parse_comparison(s);
    if (!cmp) return cmp.error();
    auto b = parse_operand(s);
    if (!b) return b.error();
    c.left = a.value();
    c.comparison_op = cmp.value();
    c.right = b.value();
  }
  FIELDCODEC_TRY_STATUS(parse_jump(t, c));
  return c;
}

[[nodiscard]] constexpr result<command> parse_assign(std::string_view s) noexcept {
  command c{};
  c.operation = s.front() == 'P' ? op::assign_p : op::assign_v;
  const auto eq = s.find('=');
  if (eq == std::string_view::npos) return errc::bad_syntax;
  auto n = parse_u16(s.substr(1, eq - 1U));
  if (!n) return n.error();
  c.number = n.value();
  s.remove_prefix(eq + 1U);
  const std::size_t n1 = operand_length(s);
  auto a = parse_operand(s.substr(0, n1));
  if (!a) return a.error();
  c.left = a.value();
  s.remove_prefix(n1);
  if (s.empty()) return c;
  constexpr std::array<arithmetic, 6> ops{arithmetic::add, arithmetic::sub,     arithmetic::mul,
                                          arithmetic::div, arithmetic::int_div, arithmetic::mod};
  for (const arithmetic o : ops) {
    if (s.front() == symbol(o)) c.arithmetic_op = o;
  }
  if (c.arithmetic_op == arithmetic::none) return errc::bad_syntax;
  auto b = parse_operand(s.substr(1));
  if (!b) return b.error();
  c.right = b.value();
  return c;
}

[[nodiscard]] constexpr result<command> parse_words(tokens &t) noexcept {
  const auto w = t.next();
  if (w.empty()) return errc::bad_syntax;
  if (w == "IF") return parse_if(t);
  if (w == "OUTPUT") {
    command c{};
    c.operation = op::output;
    FIELDCODEC_TRY_STATUS(parse_io(t.next(), 'A', c));
    return c;
  }
  if (w == "RETURN") return make(op::return_);
  if (w == "VALIDP" || w == "VALIDC" || w == "VALIDF") return make_valid(w.back());
  if ((w.front() == 'P' || w.front() == 'V') && w.find('=') != std::string_view::npos) {
    return parse_assign(w);
  }
  const names n = find_names(w);
  if (n.o == op::none) return errc::unknown_command;
  command c = make(n.o);
  const shape s = families[family_position(n.o)].s;
  if (n.o == op::wait) {
    // WAIT POSA x / WAIT POSR x
    const auto save = t;
    const auto nw = t.next();
    if (nw == "POSA" || nw == "POSR") {
      c.argument = special();
      c.second_operation = nw == "POSA" ? op::posa : op::posr;
      auto b = parse_arg(c.second_operation, t.next());
      if (!b) return b.error();
      c.second_argument = b.value();
      return c;
    }
    t = save;
  }
  if (s != shape::none && s != shape::zero) {
    auto a = parse_arg(n.o, t.next());
    if (!a) return a.error();
    c.argument = a.value();
  }
  for (int part = 0; part < 2 && !t.done() && can_continue(c, part + 1); ++part) {
    const auto nw = t.next();
    if (nw == "OUTPUT" && part == 0) {
      c.second_operation = op::output;
      FIELDCODEC_TRY_STATUS(parse_io(t.next(), 'A', c));
      break;
    }
    const names nn = find_names(nw);
    if (nn.o == op::none) return errc::unknown_command;
    auto a = parse_arg(nn.o, t.next());
    if (!a) return a.error();
    c = then(c, nn.o, a.value());
  }
  return c;
}

[[nodiscard]] constexpr result<command> parse_text(std::string_view text) noexcept {
  tokens t{text};
  auto c = parse_words(t);
  if (!c) return c.error();
  if (!t.done()) return errc::bad_length;
  return c;
}

} // namespace detail

/// Program text → command. The result is validated like encode_content() would.
/// Errors: bad_syntax, unknown_command, bad_digit, out_of_range, not_representable (more than
/// 3 decimals), overflow, invalid_argument (combination not in the table), bad_length (text
/// left over, pattern length).
[[nodiscard]] constexpr result<command> parse_command(std::string_view text) noexcept {
  auto c = detail::parse_text(text);
  if (!c) return c.error();
  std::array<std::uint8_t, content_max> scratch{};
  if (auto e = encode_content(c.value(), scratch); !e) return e.error();
  return c;
}

} // namespace fieldcodec::compax::nx
