// The COMPAX Nx codec rework of issue 18 (writes at known offsets, unchecked reads after one
// length check, the off-grid filter of from_dsp, one multiplication in scaled_to, look-ups by
// position) changes no result: every function is compared with the code it replaced, kept in
// nx_reference.hpp as the reference, over every op and code byte, every argument kind (and
// values outside the enums), random numbers in and out of range, truncated, overlong and damaged
// records.
//
// Round 6 changed one contract: nx::dsp_raw(raw) keeps the raw value raw (kind dsp_raw) where
// the reference's dsp_raw turned a raw value on the 0.001 grid into the decimal it stands for.
// An argument of kind dsp_raw therefore means what the reference's dsp_raw of its number meant
// (to_ref); the encoded bytes, the errors, the comparisons and the text must be the same as the
// reference's for that normalized argument. Decoded commands are compared member by member
// (to_ref_exact): the decoder still gives the decimal form for a value on the grid.
#include "nx_reference.hpp"
#include "short_runs.hpp"

#include <fieldcodec/compax/nx.hpp>
#include <fieldcodec/compax/nx_text.hpp>

#include <doctest/doctest.h>

#include "xorshift.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace fc = fieldcodec;
namespace nx = fieldcodec::compax::nx;
namespace ref = fieldcodec::compax::nx_reference;
using fieldcodec::errc;

namespace {

// ------------------------------------------------------------ conversions to the reference

template <class To, class From>
constexpr To as(From e) {
  return static_cast<To>(static_cast<std::uint8_t>(e));
}

/// The argument member by member.
ref::arg to_ref_exact(const nx::arg &a) { return {as<ref::arg_kind>(a.kind), a.places, a.number}; }
/// What the argument stands for in the reference: a raw value is what the reference's dsp_raw
/// built for it (the decimal on the grid), anything else member by member.
ref::arg to_ref(const nx::arg &a) {
  if (a.kind == nx::arg_kind::dsp_raw) return ref::dsp_raw(a.number);
  return to_ref_exact(a);
}
ref::operand to_ref(const nx::operand &o) {
  return {as<ref::operand_type>(o.type), o.places, o.raw, o.number};
}
template <class ArgToRef>
ref::command to_ref(const nx::command &c, ArgToRef arg_to_ref) {
  ref::command r;
  r.operation = as<ref::op>(c.operation);
  r.second_operation = as<ref::op>(c.second_operation);
  r.third_operation = as<ref::op>(c.third_operation);
  r.jump_kind = as<ref::jump>(c.jump_kind);
  r.comparison_op = as<ref::comparison>(c.comparison_op);
  r.arithmetic_op = as<ref::arithmetic>(c.arithmetic_op);
  r.valid_letter = c.valid_letter;
  r.argument = arg_to_ref(c.argument);
  r.second_argument = arg_to_ref(c.second_argument);
  r.third_argument = arg_to_ref(c.third_argument);
  r.number = c.number;
  r.target = c.target;
  r.io_pattern.count = c.io_pattern.count;
  r.io_pattern.digits = c.io_pattern.digits;
  r.left = to_ref(c.left);
  r.right = to_ref(c.right);
  return r;
}
ref::command to_ref(const nx::command &c) {
  return to_ref(c, [](const nx::arg &a) { return to_ref(a); });
}
ref::command to_ref_exact(const nx::command &c) {
  return to_ref(c, [](const nx::arg &a) { return to_ref_exact(a); });
}

/// The reference's command as a command of the codec, member by member.
nx::arg from_ref(const ref::arg &a) { return {as<nx::arg_kind>(a.kind), a.places, a.number}; }
nx::operand from_ref(const ref::operand &o) {
  return {as<nx::operand_type>(o.type), o.places, o.raw, o.number};
}
nx::command from_ref(const ref::command &r) {
  nx::command c;
  c.operation = as<nx::op>(r.operation);
  c.second_operation = as<nx::op>(r.second_operation);
  c.third_operation = as<nx::op>(r.third_operation);
  c.jump_kind = as<nx::jump>(r.jump_kind);
  c.comparison_op = as<nx::comparison>(r.comparison_op);
  c.arithmetic_op = as<nx::arithmetic>(r.arithmetic_op);
  c.valid_letter = r.valid_letter;
  c.argument = from_ref(r.argument);
  c.second_argument = from_ref(r.second_argument);
  c.third_argument = from_ref(r.third_argument);
  c.number = r.number;
  c.target = r.target;
  c.io_pattern.count = r.io_pattern.count;
  c.io_pattern.digits = r.io_pattern.digits;
  c.left = from_ref(r.left);
  c.right = from_ref(r.right);
  return c;
}

// ------------------------------------------------------------ random commands

struct rng : fieldcodec::test::xorshift {
  explicit rng(std::uint64_t seed) : xorshift(seed | 1U) {}
  std::uint64_t below(std::uint64_t n) { return next() % n; }
  bool chance(unsigned percent) { return below(100) < percent; }
  std::uint8_t byte() { return static_cast<std::uint8_t>(next()); }
};

/// A number from the edges the codec checks (0, 0xFFFF, the DSP range, −1, int64 ends) or random.
std::int64_t pick_number(rng &g) {
  static constexpr std::array<std::int64_t, 18> edges{0,
                                                      1,
                                                      -1,
                                                      2,
                                                      0xFFFF,
                                                      0x10000,
                                                      -0x10000,
                                                      (std::int64_t{1} << 47) - 1,
                                                      -(std::int64_t{1} << 47),
                                                      std::int64_t{1} << 47,
                                                      -(std::int64_t{1} << 47) - 1,
                                                      (std::int64_t{1} << 23) * 1000 - 1,
                                                      -(std::int64_t{1} << 23) * 1000,
                                                      (std::int64_t{1} << 23) * 1000,
                                                      INT64_MAX,
                                                      INT64_MIN,
                                                      INT64_MAX / 10 + 1,
                                                      1000};
  switch (g.below(6)) {
  case 0: return edges[g.below(edges.size())];
  case 1: return static_cast<std::int64_t>(g.below(0x10000));
  case 2: return static_cast<std::int64_t>(g.below(20'000'000)) - 10'000'000;
  case 3: { // on the 0.001 grid of a DSP value, or next to it
    const auto t = static_cast<std::int64_t>(g.below(16'000'000'000)) - 8'000'000'000;
    return fc::compax::dsp_number::from_thousandths(t).value().raw +
           static_cast<std::int64_t>(g.below(3)) - 1;
  }
  case 4: return static_cast<std::int64_t>(g.next() >> (1U + g.below(63)));
  default: return static_cast<std::int64_t>(g.next());
  }
}

nx::op pick_op(rng &g) {
  // mostly real ops, sometimes none or a value outside the enum
  if (g.chance(5)) return static_cast<nx::op>(g.below(256));
  return static_cast<nx::op>(g.below(static_cast<unsigned>(nx::op::assign_v) + 1U));
}

nx::arg pick_arg(rng &g) {
  nx::arg a;
  switch (g.below(12)) {
  case 0: return nx::special();
  case 1: return nx::parameter(pick_number(g));
  case 2: return nx::variable(pick_number(g));
  case 3: return nx::dsp_raw(pick_number(g));
  case 4: return nx::integer(pick_number(g));
  case 5: return nx::value(fc::decimal{pick_number(g), static_cast<std::uint8_t>(g.below(6))});
  case 6: // a raw argument (not normalized: the encoder must cope)
    a.kind = static_cast<nx::arg_kind>(g.below(6));
    a.places = static_cast<std::uint8_t>(g.below(g.chance(10) ? 256 : 5));
    a.number = pick_number(g);
    return a;
  case 7: return nx::arg{};
  default: return nx::integer(static_cast<std::int64_t>(g.below(3000)));
  }
}

nx::operand pick_operand(rng &g) {
  switch (g.below(7)) {
  case 0: return nx::constant(pick_number(g));
  case 1: return nx::constant(fc::decimal{pick_number(g), static_cast<std::uint8_t>(g.below(5))});
  case 2: return nx::constant_raw(fc::compax::dsp_number{pick_number(g)});
  case 3: {
    constexpr std::array<nx::operand_type, 3> t{
        nx::operand_type::parameter, nx::operand_type::status, nx::operand_type::variable};
    return nx::operand_of(t[g.below(3)], g.chance(80) ? static_cast<std::int64_t>(g.below(0x10000))
                                                      : pick_number(g));
  }
  case 4: {
    nx::operand o;
    o.type = static_cast<nx::operand_type>(g.chance(50) ? 0x20U + g.below(0x40) : g.below(256));
    o.places = static_cast<std::uint8_t>(g.below(5));
    o.raw = g.chance(30);
    o.number = pick_number(g);
    return o;
  }
  case 5: return nx::operand{};
  default: return nx::operand_of(nx::operand_type::variable, g.below(100));
  }
}

nx::pattern pick_pattern(rng &g) {
  nx::pattern p;
  if (g.chance(10)) return p;
  p.count = static_cast<std::uint8_t>(g.chance(90) ? 1U + g.below(8) : g.below(12));
  for (std::size_t i = 0; i < p.digits.size(); ++i) {
    if (i < p.count || g.chance(3)) {
      p.digits[i] = static_cast<std::uint8_t>(g.chance(90) ? g.below(2) : g.below(5));
    }
  }
  return p;
}

/// A command that is valid more often than not, with a member wrong now and then.
nx::command pick_command(rng &g) {
  nx::command c;
  c.operation = pick_op(g);
  c.argument = pick_arg(g);
  const unsigned extra = static_cast<unsigned>(g.below(10));
  if (extra < 4) { // a combined record
    constexpr std::array<nx::op, 6> seconds{nx::op::speed, nx::op::wait, nx::op::output,
                                            nx::op::posa,  nx::op::posr, nx::op::accel};
    c.second_operation = g.chance(90) ? seconds[g.below(seconds.size())] : pick_op(g);
    c.second_argument = pick_arg(g);
    if (extra < 2) {
      c.third_operation = g.chance(80) ? nx::op::accel : pick_op(g);
      c.third_argument = pick_arg(g);
    }
  }
  if (c.second_operation == nx::op::output || c.operation == nx::op::output ||
      c.operation == nx::op::if_input || g.chance(5)) {
    c.number = g.chance(70) ? static_cast<std::int64_t>(g.below(300)) : pick_number(g);
    if (g.chance(10)) c.number = g.chance(50) ? nx::input_error : nx::input_stop;
    c.io_pattern = pick_pattern(g);
  }
  if (c.operation == nx::op::assign_p || c.operation == nx::op::assign_v) {
    c.number = g.chance(80) ? static_cast<std::int64_t>(g.below(0x10000)) : pick_number(g);
  }
  constexpr std::array<std::uint8_t, 6> cmps{0x3D, 0x3C, 0x3E, 0xBC, 0xBE, 0xBB};
  c.comparison_op = static_cast<nx::comparison>(g.chance(90) ? cmps[g.below(6)] : g.byte());
  constexpr std::array<std::uint8_t, 7> aris{0x00, 0x2B, 0x2D, 0x2A, 0x2F, 0x5C, 0x25};
  c.arithmetic_op = static_cast<nx::arithmetic>(g.chance(90) ? aris[g.below(7)] : g.byte());
  c.jump_kind = g.chance(90) ? (g.chance(50) ? nx::jump::goto_ : nx::jump::gosub)
                             : static_cast<nx::jump>(g.byte());
  c.target = g.chance(80) ? static_cast<std::int64_t>(g.below(0x10000)) : pick_number(g);
  if (c.operation == nx::op::if_compare || c.operation == nx::op::assign_p ||
      c.operation == nx::op::assign_v || g.chance(3)) {
    c.left = pick_operand(g);
    if (c.arithmetic_op != nx::arithmetic::none || g.chance(10)) c.right = pick_operand(g);
  }
  if (c.operation == nx::op::valid || g.chance(2)) {
    constexpr std::array<char, 5> letters{'P', 'C', 'F', 'X', 0};
    c.valid_letter = letters[g.below(letters.size())];
  }
  return c;
}

// ------------------------------------------------------------ comparisons

/// `c` and the reference's form of it brought back (raw arguments on the grid as decimals,
/// as the round-5 dsp_raw built them) compare equal and give the same text or error.
void check_same_meaning(const nx::command &c) {
  const nx::command old_form = from_ref(to_ref(c));
  CHECK(c == old_form);
  CHECK(old_form == c);
  std::array<char, nx::text_max> t{};
  std::array<char, nx::text_max> rt{};
  const auto n = nx::format_command(c, t);
  const auto rn = nx::format_command(old_form, rt);
  REQUIRE(n.has_value() == rn.has_value());
  if (!n) {
    CHECK(n.error() == rn.error());
  } else {
    CHECK(std::string_view(t.data(), n.value()) == std::string_view(rt.data(), rn.value()));
  }
}

void check_encode(const nx::command &c) {
  const auto got = nx::encode_record(c);
  const auto want = ref::encode_record(to_ref(c));
  REQUIRE(got.has_value() == want.has_value());
  if (!got) {
    CHECK(got.error() == want.error());
  } else {
    CHECK(got.value() == want.value());
  }
  // encode_content with room for the longest content gives the reference's result and bytes
  std::array<std::uint8_t, nx::content_max> b{};
  std::array<std::uint8_t, nx::content_max> rb{};
  const auto n = nx::encode_content(c, b);
  const auto rn = ref::encode_content(to_ref(c), rb);
  REQUIRE(n.has_value() == rn.has_value());
  if (!n) {
    CHECK(n.error() == rn.error());
    return;
  }
  CHECK(n.value() == rn.value());
  CHECK(b == rb);
  // a buffer one byte short: buffer_too_small in both, and nothing written here
  if (n.value() > 0U) {
    std::array<std::uint8_t, nx::content_max> small{};
    const auto s = nx::encode_content(c, std::span{small}.first(n.value() - 1U));
    const auto rs = ref::encode_content(to_ref(c), std::span{rb}.first(n.value() - 1U));
    CHECK(s.error() == errc::buffer_too_small);
    CHECK(rs.error() == errc::buffer_too_small);
    CHECK(small == std::array<std::uint8_t, nx::content_max>{});
  }
  check_same_meaning(c);
}

void check_decode(std::span<const std::uint8_t> in) {
  const auto got = nx::decode_record(in);
  const auto want = ref::decode_record(in);
  REQUIRE(got.has_value() == want.has_value());
  if (!got) {
    CHECK(got.error() == want.error());
  } else {
    CHECK(to_ref_exact(got.value()) == want.value());
  }
  if (in.size() > 1U) {
    const auto content = in.subspan(1);
    const auto gc = nx::decode_content(content);
    const auto wc = ref::decode_content(content);
    REQUIRE(gc.has_value() == wc.has_value());
    if (!gc) {
      CHECK(gc.error() == wc.error());
    } else {
      CHECK(to_ref_exact(gc.value()) == wc.value());
    }
  }
}

} // namespace

TEST_CASE("nx: dsp_raw, constant_raw, dsp_of and scaled_to give the reference's results") {
  rng g(18);
  for (int i = 0; i < 300'000; ++i) {
    const std::int64_t raw = pick_number(g);
    INFO("raw ", raw);
    // round 6: dsp_raw keeps the raw value; its normalized form is the reference's dsp_raw
    REQUIRE(to_ref_exact(nx::dsp_raw(raw)) == ref::arg{ref::arg_kind::dsp_raw, 0, raw});
    REQUIRE(to_ref_exact(nx::normalized(nx::dsp_raw(raw))) == ref::dsp_raw(raw));
    REQUIRE(nx::dsp_raw(raw) == from_ref(ref::dsp_raw(raw)));
    REQUIRE(to_ref(nx::constant_raw(fc::compax::dsp_number{raw})) ==
            ref::constant_raw(fc::compax::dsp_number{raw}));
    const auto places = static_cast<std::uint8_t>(g.below(g.chance(5) ? 256 : 24));
    // dsp_of (round 4 tests dsp_raw first): every kind, also outside the enum
    const nx::arg a{static_cast<nx::arg_kind>(g.below(g.chance(5) ? 256 : 5)),
                    g.chance(50) ? std::uint8_t{0} : places, raw};
    const auto d = nx::dsp_of(a);
    const auto rd = ref::dsp_of(to_ref(a));
    REQUIRE(d.has_value() == rd.has_value());
    if (d) {
      REQUIRE(d.value() == rd.value());
    } else {
      REQUIRE(d.error() == rd.error());
    }
    const auto target = static_cast<std::uint8_t>(g.below(4));
    const auto s = nx::detail::scaled_to(raw, places, target);
    const auto rs = ref::detail::scaled_to(raw, places, target);
    REQUIRE(s.has_value() == rs.has_value());
    if (s) {
      REQUIRE(s.value() == rs.value());
    } else {
      REQUIRE(s.error() == rs.error());
    }
  }
  // every raw value on the grid passes the filter: t = ±1 … ±5000 thousandths and the ends
  for (std::int64_t t = -5000; t <= 5000; ++t) {
    const auto raw = fc::compax::dsp_number::from_thousandths(t).value().raw;
    REQUIRE(nx::detail::may_be_on_grid(raw));
    REQUIRE(nx::dsp_raw(raw).kind == nx::arg_kind::dsp_raw);
    REQUIRE(nx::normalized(nx::dsp_raw(raw)).kind == nx::arg_kind::value);
  }
  for (const auto t :
       {fc::compax::dsp_number::max_thousandths, fc::compax::dsp_number::min_thousandths}) {
    const auto raw = fc::compax::dsp_number::from_thousandths(t).value().raw;
    CHECK(nx::detail::may_be_on_grid(raw));
    CHECK(to_ref_exact(nx::normalized(nx::dsp_raw(raw))) == ref::dsp_raw(raw));
  }
}

TEST_CASE("nx: encode_record / encode_content give the reference's result for random commands") {
  rng g(0x5FD5);
  int ok = 0;
  for (int i = 0; i < 200'000; ++i) {
    const nx::command c = pick_command(g);
    INFO("command #", i, " op ", static_cast<unsigned>(c.operation));
    check_encode(c);
    ok += nx::encode_record(c).has_value() ? 1 : 0;
  }
  CHECK(ok > 20'000); // the valid ones are not rare
}

/// An argument whose number comes from a few values near one another, in every form, so that
/// equal pairs are frequent: whole numbers, decimals, raw values on the grid and next to it,
/// members set by hand (decimals not normalized, raw values with places, kinds outside the enum).
nx::arg pick_close_arg(rng &g) {
  static constexpr std::array<std::int64_t, 9> thousandths{0,
                                                           1,
                                                           -1,
                                                           500,
                                                           1500,
                                                           250'000,
                                                           -250'000,
                                                           (std::int64_t{1} << 23) * 1000 - 1,
                                                           -(std::int64_t{1} << 23) * 1000};
  const std::int64_t t = thousandths[g.below(thousandths.size())];
  const std::int64_t raw = fc::compax::dsp_number::from_thousandths(t).value().raw +
                           (g.chance(20) ? static_cast<std::int64_t>(g.below(3)) - 1 : 0);
  const auto places = static_cast<std::uint8_t>(g.below(4));
  switch (g.below(9)) {
  case 0: return nx::integer(t / 1000);
  case 1: return nx::value(fc::decimal{t, 3});
  case 2: return nx::dsp_raw(raw);
  case 3: return nx::dsp_raw(fc::compax::dsp_number{raw});
  case 4: return nx::arg{nx::arg_kind::dsp_raw, places, raw};
  case 5: return nx::arg{nx::arg_kind::value, places, t % 1000 == 0 ? t / 1000 : t};
  case 6: return g.chance(50) ? nx::parameter(t % 3) : nx::variable(t % 3);
  case 7: return nx::special();
  default:
    return nx::arg{static_cast<nx::arg_kind>(g.below(7)), places,
                   g.chance(50) ? t % 3 : raw}; // also kinds outside the enum
  }
}

TEST_CASE("nx: arguments and commands compare as the reference's normalized ones") {
  rng g(0x3D3D);
  int equal = 0;
  int equal_across_kinds = 0;
  for (int i = 0; i < fieldcodec_test::runs(300'000); ++i) {
    const nx::arg a = pick_close_arg(g);
    const nx::arg b = pick_close_arg(g);
    INFO("a ", static_cast<unsigned>(a.kind), " ", static_cast<unsigned>(a.places), " ", a.number,
         " b ", static_cast<unsigned>(b.kind), " ", static_cast<unsigned>(b.places), " ", b.number);
    const bool eq = a == b;
    REQUIRE(eq == (to_ref(a) == to_ref(b)));
    REQUIRE(eq == (b == a));
    REQUIRE(eq != (a != b));
    REQUIRE(a == a);
    REQUIRE(eq == (nx::normalized(a) == nx::normalized(b)));
    equal += eq ? 1 : 0;
    equal_across_kinds += eq && a.kind != b.kind ? 1 : 0;
    // in a command, alone and in the combined positioning record
    const nx::command ca = nx::make(nx::op::posa, a);
    const nx::command cb = nx::make(nx::op::posa, b);
    REQUIRE((ca == cb) == (to_ref(ca) == to_ref(cb)));
    const auto posr = [](nx::arg x, nx::arg y) {
      return nx::then(nx::then(nx::make(nx::op::posr, x), nx::op::speed, y), nx::op::accel,
                      nx::integer(200));
    };
    REQUIRE((posr(a, b) == posr(b, a)) == eq);
    check_encode(ca);
    check_encode(nx::make(nx::op::accel, a));
    check_encode(posr(a, b));
  }
  CHECK(equal > fieldcodec_test::runs(10'000));
  // a raw value equal to a decimal, not only to itself
  CHECK(equal_across_kinds > fieldcodec_test::runs(1'000));
}

TEST_CASE("nx: every op with every argument kind, alone and as the second and third command") {
  rng g(7);
  constexpr std::array<nx::arg_kind, 5> kinds{nx::arg_kind::value, nx::arg_kind::dsp_raw,
                                              nx::arg_kind::parameter, nx::arg_kind::variable,
                                              nx::arg_kind::special};
  for (unsigned o = 0; o < 40; ++o) {
    for (const auto k : kinds) {
      for (int i = 0; i < 200; ++i) {
        nx::arg a{k, 0, i < 20 ? i - 2 : pick_number(g)};
        if (k == nx::arg_kind::special) a.number = 0;
        if (k == nx::arg_kind::value && g.chance(30))
          a.places = static_cast<std::uint8_t>(g.below(5));
        check_encode(nx::make(static_cast<nx::op>(o), a));
        check_encode(nx::then(nx::make(nx::op::posr, nx::integer(5)), static_cast<nx::op>(o), a));
        check_encode(nx::then(nx::make(nx::op::wait, nx::special()), static_cast<nx::op>(o), a));
        check_encode(nx::then(
            nx::then(nx::make(nx::op::posr, nx::integer(5)), nx::op::speed, nx::integer(50)),
            static_cast<nx::op>(o), a));
      }
    }
  }
}

TEST_CASE("nx: the longest content of each shape fits the record") {
  // IF <operand> <cmp> <operand> GOTO n: 1 + 7 + 1 + 7 + 3 = 19 content bytes
  constexpr auto longest =
      nx::make_if_compare(nx::constant(fc::decimal{-12345, 3}), nx::comparison::ge,
                          nx::operand_of(nx::operand_type::status, 65535), nx::jump::gosub, 65535);
  static_assert(nx::encode_record(longest).value()[0] == 19U);
  check_encode(longest);
  // POSR … OUTPUT A…=8 digits: 7 + 3 + 8 = 18; POSR SPEED ACCEL: 7 + 7 + 3 = 17
  const std::array<std::uint8_t, 8> eight{1, 0, 1, 1, 0, 0, 1, 0};
  const auto out = nx::then_output(nx::make(nx::op::posr, nx::integer(-4000000)), 65535,
                                   nx::make_pattern(eight).value());
  CHECK(nx::encode_record(out).value()[0] == 18U);
  check_encode(out);
  // Pn = <operand> <ari> <operand>: 1 + 2 + 7 + 1 + 7 = 18
  const auto assign =
      nx::make_assign(nx::op::assign_v, 65535, nx::constant(8388607), nx::arithmetic::int_div,
                      nx::operand_of(nx::operand_type::parameter, 65535));
  CHECK(nx::encode_record(assign).value()[0] == 18U);
  check_encode(assign);
  // IF E…=8 digits GOSUB n: 1 + 2 + 8 + 3 = 14
  const auto ifin = nx::make_if_input(65535, nx::make_pattern(eight).value(), nx::jump::gosub, 1);
  CHECK(nx::encode_record(ifin).value()[0] == 14U);
  check_encode(ifin);
}

TEST_CASE(
    "nx: decode_record gives the reference's result for every code byte and damaged records") {
  rng g(0xD2);
  // every first code byte, followed by random bytes, every content length
  for (unsigned code = 0; code < 256U; ++code) {
    for (int i = 0; i < 400; ++i) {
      std::array<std::uint8_t, nx::record_size> r{};
      for (auto &b : r) b = g.chance(50) ? g.byte() : static_cast<std::uint8_t>(g.below(3));
      r[1] = static_cast<std::uint8_t>(code);
      r[0] = static_cast<std::uint8_t>(g.chance(95) ? g.below(nx::record_size) : g.byte());
      const std::size_t size = g.chance(80) ? nx::record_size : g.below(nx::record_size + 1U);
      INFO("code ", code, " length ", static_cast<unsigned>(r[0]), " size ", size);
      check_decode(std::span<const std::uint8_t>{r}.first(size));
    }
  }
  // valid records of random commands, then damaged: one byte changed, truncated, the length
  // byte off by one, a byte too many
  int valid = 0;
  for (int i = 0; i < 200'000; ++i) {
    const auto e = nx::encode_record(pick_command(g));
    if (!e) continue;
    ++valid;
    auto r = e.value();
    check_decode(r);
    std::vector<std::uint8_t> longer(r.begin(), r.end());
    longer.push_back(0);
    check_decode(longer);
    const std::size_t n = r[0];
    check_decode(std::span<const std::uint8_t>{r}.first(1U + g.below(n + 1U)));
    auto damaged = r;
    damaged[1U + g.below(n)] = g.byte();
    check_decode(damaged);
    auto relength = r;
    relength[0] = static_cast<std::uint8_t>(g.chance(50) ? n - 1U : n + 1U);
    check_decode(relength);
  }
  CHECK(valid > 20'000);
  check_decode(std::span<const std::uint8_t>{});
}

TEST_CASE("nx: decode_record's straight path for POSR SPEED ACCEL reads what the reference reads") {
  // Issue 18, round 4: decode_record reads a 17-byte POSR v SPEED v ACCEL v content without the
  // table look-ups. Every such record, and every record one byte away from taking the path
  // (other code bytes, lengths and sizes), is compared with the reference.
  rng g(0x52534C);
  const auto put_field = [&](std::array<std::uint8_t, nx::record_size> &r, std::size_t at) {
    std::int64_t raw = 0;
    switch (g.below(5)) {
    case 0: raw = -1; break; // six 0xFF: CAM / SYNC
    case 1: raw = pick_number(g); break;
    case 2: { // on the grid or next to it
      const auto t = static_cast<std::int64_t>(g.below(16'000'000'000)) - 8'000'000'000;
      raw = fc::compax::dsp_number::from_thousandths(t).value().raw +
            static_cast<std::int64_t>(g.below(3)) - 1;
      break;
    }
    case 3: raw = g.chance(50) ? (std::int64_t{1} << 47) - 1 : -(std::int64_t{1} << 47); break;
    default: raw = static_cast<std::int64_t>(g.next()); break; // the field keeps 48 bits
    }
    const auto u = static_cast<std::uint64_t>(raw);
    for (std::size_t i = 0; i < 6U; ++i) r[at + i] = static_cast<std::uint8_t>(u >> (8U * i));
  };
  constexpr std::array<std::uint8_t, 9> near_codes{0x52, 0x53, 0x4C, 0x72, 0xD2,
                                                   0x73, 0xD3, 0x6C, 0xCC};
  int on_path = 0;
  for (int i = 0; i < 300'000; ++i) {
    std::array<std::uint8_t, nx::record_size> r{};
    for (auto &b : r) b = g.byte(); // padding too
    r[0] = 17;
    r[1] = 0x52;
    put_field(r, 2);
    r[8] = 0x53;
    put_field(r, 9);
    r[15] = 0x4C;
    if (g.chance(10)) {
      r[16] = 0;
      r[17] = g.chance(50) ? 0 : 0xFF; // ACCEL 0 (no special form) and 0x00FF
    }
    std::size_t size = nx::record_size;
    switch (g.below(8)) {
    case 0: r[1 + 7 * g.below(3)] = near_codes[g.below(near_codes.size())]; break;
    case 1: r[0] = static_cast<std::uint8_t>(14U + g.below(6)); break;
    case 2: size = 16U + g.below(5); break; // 16, 17 truncated; 18..20 whole
    default: ++on_path; break;
    }
    INFO("record #", i);
    check_decode(std::span<const std::uint8_t>{r}.first(size));
  }
  CHECK(on_path > 100'000);
  // the special forms and ACCEL 0 by hand: POSR CAM SPEED SYNC ACCEL 0
  constexpr std::array<std::uint8_t, 18> special{17,   0x52, 0xFF, 0xFF, 0xFF, 0xFF,
                                                 0xFF, 0xFF, 0x53, 0xFF, 0xFF, 0xFF,
                                                 0xFF, 0xFF, 0xFF, 0x4C, 0x00, 0x00};
  const auto c = nx::decode_record(special);
  REQUIRE(c);
  CHECK(c.value() ==
        nx::then(nx::then(nx::make(nx::op::posr, nx::special()), nx::op::speed, nx::special()),
                 nx::op::accel, nx::integer(0)));
  check_decode(special);
}
