// COMPAX Nx binary program records (manual 000, 2.11.2): every row of the "set memory command
// code table" encoded from a typed command, decoded back, and through program text.
#include <fieldcodec/compax/nx.hpp>
#include <fieldcodec/compax/nx_text.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace cx = fieldcodec::compax;
namespace nx = fieldcodec::compax::nx;
using fieldcodec::decimal;
using fieldcodec::errc;
using bytes = std::vector<std::uint8_t>;

namespace {

constexpr cx::dsp_number mm(std::int64_t thousandths) {
  return cx::dsp_number::from_thousandths(thousandths).value();
}

bytes content(const nx::command &c) {
  std::array<std::uint8_t, nx::content_max> b{};
  auto n = nx::encode_content(c, b);
  REQUIRE(n.has_value());
  return bytes(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(n.value()));
}

std::string text(const nx::command &c) {
  std::array<char, nx::text_max> t{};
  auto n = nx::format_command(c, t);
  REQUIRE(n.has_value());
  return std::string(t.data(), n.value());
}

// bytes ⇄ command ⇄ text ⇄ record, all four ways
void round_trip(const nx::command &c, const bytes &expected, std::string_view program) {
  CAPTURE(program);
  const bytes b = content(c);
  CHECK(b == expected);
  auto back = nx::decode_content(b);
  REQUIRE(back.has_value());
  CHECK(back.value() == c);
  CHECK(text(c) == program);
  auto parsed = nx::parse_command(program);
  REQUIRE(parsed.has_value());
  CHECK(parsed.value() == c);
  auto rec = nx::encode_record(c);
  REQUIRE(rec.has_value());
  CHECK(rec.value()[0] == b.size());
  for (std::size_t i = 1 + b.size(); i < nx::record_size; ++i) CHECK(rec.value()[i] == 0);
  CHECK(nx::decode_record(rec.value()).value() == c);
}

bytes dsp_bytes(cx::dsp_number n) {
  std::array<std::uint8_t, 6> b{};
  REQUIRE(cx::encode_dsp(n, b).has_value());
  return bytes(b.begin(), b.end());
}
bytes cat(std::initializer_list<bytes> parts) {
  bytes out;
  for (const auto &p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

} // namespace

// DSP number format (assumption, docs/compax.md): 24.24 two's complement, NL first.
static_assert(cx::dsp_number::from_thousandths(1000).value().raw == 0x01000000);
static_assert(cx::dsp_number::from_thousandths(-1000).value().raw == -0x01000000);
static_assert(cx::dsp_number::from_thousandths(500).value().raw == 0x00800000);
static_assert(cx::dsp_number::from_thousandths(250'000).value().to_thousandths() == 250'000);
static_assert(cx::dsp_number::from_thousandths(-4'000'000'000).value().to_thousandths() ==
              -4'000'000'000);
static_assert(cx::dsp_number::from_thousandths(8'388'608'000).error() == errc::overflow);
static_assert(cx::dsp_number::from_thousandths(-8'388'608'001).error() == errc::overflow);
static_assert(cx::dsp_number::from_thousandths(-8'388'608'000).value().raw ==
              cx::dsp_format::raw_min);
static_assert(cx::dsp_number{cx::dsp_format::raw_max}.to_thousandths() == 8'388'607'999);

// Records and text work in constant expressions.
static_assert(nx::encode_record(nx::make(nx::op::posa, nx::special())).value() ==
              nx::record{7, 0x41, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF});
static_assert(nx::decode_record(nx::record{3, 0x47, 0x00, 0x0C}).value() ==
              nx::make(nx::op::goto_, nx::integer(12)));
// The combined positioning record (decode_record reads it by a straight path, issue 18): POSR
// 250.5 (on the grid: 250.5 · 2^24 = 0x00FA8000_00 raw), SPEED raw 3 (off it), ACCEL 256.
static_assert(nx::decode_record(nx::record{17, 0x52, 0x00, 0x00, 0x80, 0xFA, 0x00, 0x00, 0x53, 0x03,
                                           0x00, 0x00, 0x00, 0x00, 0x00, 0x4C, 0x01, 0x00})
                  .value() == nx::then(nx::then(nx::make(nx::op::posr, nx::value(decimal{2505, 1})),
                                                nx::op::speed, nx::dsp_raw(3)),
                                       nx::op::accel, nx::integer(256)));
static_assert(nx::parse_command("IF E5=1 GOTO 12").value() ==
              nx::make_if_input(5, nx::pattern{1, {1}}, nx::jump::goto_, 12));
// Numbers carry the command's unit: POSA 250 is 250 mm however it is written (issue 13).
static_assert(nx::parse_command("POSA 250").value() == nx::make(nx::op::posa, nx::integer(250)));
static_assert(nx::make(nx::op::posa, nx::integer(250)) ==
              nx::make(nx::op::posa, nx::value(decimal{250000, 3})));
static_assert(nx::make(nx::op::posa, nx::integer(250)) ==
              nx::make(nx::op::posa, nx::dsp_raw(250 * cx::dsp_format::one)));
static_assert(nx::make(nx::op::posa, nx::integer(250)) != nx::make(nx::op::posa, nx::dsp_raw(250)));

// Integer arguments: any integer type (core/integer.hpp integer_argument), not a character.
template <class T>
constexpr bool integer_accepts = requires(T v) {
  nx::integer(v);
};
static_assert(integer_accepts<long long> && integer_accepts<std::uint8_t> &&
              integer_accepts<bool> && !integer_accepts<char> && !integer_accepts<double>);

// On the 0.001 grid or not (what decoding keeps as a decimal or as a raw value).
static_assert(cx::dsp_number{250 * cx::dsp_format::one}.exact_thousandths().value() == 250'000);
static_assert(mm(1).exact_thousandths().value() == 1);
static_assert(cx::dsp_number{250}.exact_thousandths().error() == errc::not_representable);
static_assert(cx::dsp_number{cx::dsp_format::raw_max + 1}.exact_thousandths().error() ==
              errc::overflow);
// The DSP number of an argument.
static_assert(nx::dsp_of(nx::integer(250)).value().raw == 250 * cx::dsp_format::one);
static_assert(nx::dsp_of(nx::value(decimal{-15, 1})).value() == mm(-1'500));
static_assert(nx::dsp_of(nx::dsp_raw(3)).value().raw == 3);
static_assert(nx::dsp_of(nx::arg{nx::arg_kind::dsp_raw, 0, std::int64_t{1} << 47}).error() ==
              errc::overflow);
static_assert(nx::dsp_of(nx::arg{nx::arg_kind::dsp_raw, 0, -(std::int64_t{1} << 47)}).value().raw ==
              -(std::int64_t{1} << 47));
static_assert(nx::dsp_of(nx::parameter(3)).error() == errc::type_mismatch);
static_assert(nx::dsp_of(nx::special()).error() == errc::type_mismatch);
static_assert(nx::dsp_of(nx::value(decimal{1, 4})).error() == errc::not_representable);
static_assert(nx::dsp_of(nx::integer(8'388'608)).error() == errc::overflow);

TEST_CASE("DSP number bytes: NL NM NH VL VM VH") {
  CHECK(dsp_bytes(mm(250'000)) == bytes{0x00, 0x00, 0x00, 0xFA, 0x00, 0x00});
  CHECK(dsp_bytes(mm(1'500)) == bytes{0x00, 0x00, 0x80, 0x01, 0x00, 0x00});
  CHECK(dsp_bytes(mm(-1'000)) == bytes{0x00, 0x00, 0x00, 0xFF, 0xFF, 0xFF});
  CHECK(dsp_bytes(mm(4'000'000'000)) == bytes{0x00, 0x00, 0x00, 0x00, 0x09, 0x3D});
  CHECK(cx::decode_dsp(bytes{0x00, 0x00, 0x80, 0x01, 0x00, 0x00}).value() == mm(1'500));
  CHECK(cx::decode_dsp(bytes{0x00, 0x00, 0x80, 0x01, 0x00}).error() == errc::truncated);
  // 0.001 steps survive the trip
  for (std::int64_t t = -3000; t <= 3000; ++t) {
    CHECK(cx::dsp_number::from_thousandths(t).value().to_thousandths() == t);
  }
}

TEST_CASE("Nx set-memory table: simple commands, value / parameter / variable forms") {
  using nx::op;
  round_trip(nx::make(op::nop), {0x20}, "NOP");
  round_trip(nx::make_valid('P'), {0x01, 0x56, 0x50}, "VALIDP");
  round_trip(nx::make_valid('C'), {0x01, 0x56, 0x43}, "VALIDC");
  round_trip(nx::make_valid('F'), {0x01, 0x56, 0x46}, "VALIDF");
  round_trip(nx::make(op::end), {0x45, 0x00}, "END");
  round_trip(nx::make(op::return_), {0x55, 0x00}, "RETURN");
  round_trip(nx::make(op::sets), {0x51}, "SETS");
  round_trip(nx::make(op::setc, nx::integer(7)), {0x43, 0x00, 0x07}, "SETC 7");
  // ACCEL / LOOP / REPEAT / WAIT: 2-byte value MSB LSB, parameter | 0x20, variable | 0x80
  round_trip(nx::make(op::accel, nx::integer(1000)), {0x4C, 0x03, 0xE8}, "ACCEL 1000");
  round_trip(nx::make(op::accel, nx::parameter(6)), {0x6C, 0x00, 0x06}, "ACCEL P6");
  round_trip(nx::make(op::accel, nx::variable(12)), {0xCC, 0x00, 0x0C}, "ACCEL V12");
  round_trip(nx::make(op::loop, nx::integer(300)), {0x4B, 0x01, 0x2C}, "LOOP 300");
  round_trip(nx::make(op::loop, nx::parameter(40)), {0x6B, 0x00, 0x28}, "LOOP P40");
  round_trip(nx::make(op::loop, nx::variable(10)), {0xCB, 0x00, 0x0A}, "LOOP V10");
  round_trip(nx::make(op::repeat, nx::integer(5)), {0x54, 0x00, 0x05}, "REPEAT 5");
  round_trip(nx::make(op::repeat, nx::parameter(41)), {0x74, 0x00, 0x29}, "REPEAT P41");
  round_trip(nx::make(op::repeat, nx::variable(3)), {0xD4, 0x00, 0x03}, "REPEAT V3");
  round_trip(nx::make(op::wait, nx::integer(500)), {0x57, 0x01, 0xF4}, "WAIT 500");
  round_trip(nx::make(op::wait, nx::parameter(8)), {0x77, 0x00, 0x08}, "WAIT P8");
  round_trip(nx::make(op::wait, nx::variable(9)), {0xD7, 0x00, 0x09}, "WAIT V9");
  round_trip(nx::make(op::wait, nx::special()), {0x57, 0x00, 0x00}, "WAIT START");
  round_trip(nx::make(op::goto_, nx::integer(12)), {0x47, 0x00, 0x0C}, "GOTO 12");
  round_trip(nx::make(op::goto_, nx::integer(302)), {0x47, 0x01, 0x2E}, "GOTO 302");
  round_trip(nx::make(op::goto_, nx::special()), {0x47, 0x00, 0x00}, "GOTO EXT");
  round_trip(nx::make(op::gosub, nx::integer(200)), {0x42, 0x00, 0xC8}, "GOSUB 200");
  round_trip(nx::make(op::gosub, nx::special()), {0x42, 0x00, 0x00}, "GOSUB EXT");
  // POSA / POSR / SPEED / SETM: 6-byte DSP value, parameter/variable number + 4 zero bytes
  round_trip(nx::make(op::posa, nx::value(decimal{250'000, 3})),
             cat({{0x41}, dsp_bytes(mm(250'000))}), "POSA 250");
  round_trip(nx::make(op::posa, nx::value(decimal{-12'345, 3})),
             cat({{0x41}, dsp_bytes(mm(-12'345))}), "POSA -12.345");
  round_trip(nx::make(op::posa, nx::parameter(12)), {0x61, 0x00, 0x0C, 0, 0, 0, 0}, "POSA P12");
  round_trip(nx::make(op::posa, nx::variable(3)), {0xC1, 0x00, 0x03, 0, 0, 0, 0}, "POSA V3");
  round_trip(nx::make(op::posa, nx::special()), {0x41, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF},
             "POSA HOME");
  round_trip(nx::make(op::posr, nx::value(decimal{15'800, 3})),
             cat({{0x52}, dsp_bytes(mm(15'800))}), "POSR 15.8");
  round_trip(nx::make(op::posr, nx::parameter(40)), {0x72, 0x00, 0x28, 0, 0, 0, 0}, "POSR P40");
  round_trip(nx::make(op::posr, nx::variable(10)), {0xD2, 0x00, 0x0A, 0, 0, 0, 0}, "POSR V10");
  round_trip(nx::make(op::posr, nx::special()), {0x52, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF},
             "POSR CAM");
  round_trip(nx::make(op::speed, nx::value(decimal{75'000, 3})),
             cat({{0x53}, dsp_bytes(mm(75'000))}), "SPEED 75");
  round_trip(nx::make(op::speed, nx::parameter(2)), {0x73, 0x00, 0x02, 0, 0, 0, 0}, "SPEED P2");
  round_trip(nx::make(op::speed, nx::variable(7)), {0xD3, 0x00, 0x07, 0, 0, 0, 0}, "SPEED V7");
  round_trip(nx::make(op::speed, nx::special()), {0x53, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF},
             "SPEED SYNC");
  round_trip(nx::make(op::setm, nx::value(decimal{1'250, 3})), cat({{0x4D}, dsp_bytes(mm(1'250))}),
             "SETM 1.25");
  round_trip(nx::make(op::setm, nx::parameter(30)), {0x6D, 0x00, 0x1E, 0, 0, 0, 0}, "SETM P30");
  round_trip(nx::make(op::setm, nx::variable(31)), {0xCD, 0x00, 0x1F, 0, 0, 0, 0}, "SETM V31");
}

TEST_CASE("Nx set-memory table: IF, OUTPUT, assignments") {
  using nx::jump;
  const auto p1 = nx::pattern{1, {1}};
  // manual text example: IF E5=1 GOTO 12
  round_trip(nx::make_if_input(5, p1, jump::goto_, 12), {0x49, 0x00, 0x05, 0x31, 0x47, 0x00, 0x0C},
             "IF E5=1 GOTO 12");
  round_trip(nx::make_if_input(5, nx::pattern{1, {0}}, jump::gosub, 40),
             {0x49, 0x00, 0x05, 0x30, 0x42, 0x00, 0x28}, "IF E5=0 GOSUB 40");
  round_trip(nx::make_if_input(9, nx::pattern{2, {1, 0}}, jump::gosub, 40),
             {0x49, 0x00, 0x09, 0x31, 0x30, 0x42, 0x00, 0x28}, "IF E9=10 GOSUB 40");
  round_trip(nx::make_if_input(1, nx::pattern{8, {1, 0, 1, 1, 0, 0, 1, 0}}, jump::goto_, 250),
             {0x49, 0x00, 0x01, 0x31, 0x30, 0x31, 0x31, 0x30, 0x30, 0x31, 0x30, 0x47, 0x00, 0xFA},
             "IF E1=10110010 GOTO 250");
  round_trip(nx::make_if_error(jump::gosub, 200), {0x49, 0x00, 0xFF, 0x31, 0x42, 0x00, 0xC8},
             "IF ERROR GOSUB 200");
  round_trip(nx::make_if_stop(jump::gosub, 201), {0x49, 0x00, 0xFE, 0x31, 0x42, 0x00, 0xC9},
             "IF STOP GOSUB 201");
  // IF <operand> <comparison> <operand>: 19 bytes, the longest record
  round_trip(
      nx::make_if_compare(nx::operand_of(nx::operand_type::variable, 1), nx::comparison::ge,
                          nx::operand_of(nx::operand_type::parameter, 5), jump::goto_, 7),
      {0x4A, 0x56, 0x00, 0x01, 0, 0, 0, 0, 0xBE, 0x50, 0x00, 0x05, 0, 0, 0, 0, 0x47, 0x00, 0x07},
      "IF V1>=P5 GOTO 7");
  round_trip(nx::make_if_compare(nx::operand_of(nx::operand_type::status, 1), nx::comparison::lt,
                                 nx::constant(decimal{100'500, 3}), jump::gosub, 9),
             cat({{0x4A, 0x53, 0x00, 0x01, 0, 0, 0, 0, 0x3C, 0x20},
                  dsp_bytes(mm(100'500)),
                  {0x42, 0x00, 0x09}}),
             "IF S1<100.5 GOSUB 9");
  struct cmp_case {
    nx::comparison cmp;
    std::string_view sym;
    int code;
  };
  for (auto [cmp, sym, code] :
       {cmp_case{nx::comparison::eq, "=", 0x3D}, cmp_case{nx::comparison::gt, ">", 0x3E},
        cmp_case{nx::comparison::le, "<=", 0xBC}, cmp_case{nx::comparison::ne, "<>", 0xBB}}) {
    const auto c = nx::make_if_compare(nx::operand_of(nx::operand_type::variable, 2), cmp,
                                       nx::constant(decimal{-3'000, 3}), jump::goto_, 1);
    CHECK(content(c)[8] == code);
    CHECK(text(c) == "IF V2" + std::string(sym) + "-3 GOTO 1");
    CHECK(nx::parse_command(text(c)).value() == c);
  }
  // OUTPUT Ax=y…
  round_trip(nx::make_output(5, p1), {0x4F, 0x00, 0x05, 0x31}, "OUTPUT A5=1");
  round_trip(nx::make_output(9, nx::pattern{3, {1, 0, 1}}), {0x4F, 0x00, 0x09, 0x31, 0x30, 0x31},
             "OUTPUT A9=101");
  round_trip(nx::make_output(1, nx::pattern{8, {1, 1, 1, 1, 0, 0, 0, 0}}),
             {0x4F, 0x00, 0x01, 0x31, 0x31, 0x31, 0x31, 0x30, 0x30, 0x30, 0x30},
             "OUTPUT A1=11110000");
  round_trip(nx::make_output(0, nx::pattern{1, {2}}), {0x4F, 0x00, 0x00, 0x32}, "OUTPUT A0=2");
  // Pn= / Vn=
  round_trip(
      nx::make_assign(nx::op::assign_p, 12, nx::operand_of(nx::operand_type::variable, 3),
                      nx::arithmetic::add, nx::constant(decimal{5'000, 3})),
      cat({{0x50, 0x00, 0x0C, 0x56, 0x00, 0x03, 0, 0, 0, 0, 0x2B, 0x20}, dsp_bytes(mm(5'000))}),
      "P12=V3+5");
  round_trip(
      nx::make_assign(nx::op::assign_v, 1, nx::operand_of(nx::operand_type::status, 2),
                      nx::arithmetic::mul, nx::constant(decimal{500, 3})),
      cat({{0x56, 0x00, 0x01, 0x53, 0x00, 0x02, 0, 0, 0, 0, 0x2A, 0x20}, dsp_bytes(mm(500))}),
      "V1=S2*0.5");
  round_trip(nx::make_assign(nx::op::assign_v, 4, nx::constant(decimal{-7'000, 3})),
             cat({{0x56, 0x00, 0x04, 0x20}, dsp_bytes(mm(-7'000))}), "V4=-7");
  round_trip(
      nx::make_assign(nx::op::assign_v, 4, nx::operand_of(nx::operand_type::variable, 4),
                      nx::arithmetic::sub, nx::constant(decimal{-1'000, 3})),
      cat({{0x56, 0x00, 0x04, 0x56, 0x00, 0x04, 0, 0, 0, 0, 0x2D, 0x20}, dsp_bytes(mm(-1'000))}),
      "V4=V4--1");
  struct ari_case {
    nx::arithmetic ari;
    char sym;
    int code;
  };
  for (auto [ari, sym, code] :
       {ari_case{nx::arithmetic::sub, '-', 0x2D}, ari_case{nx::arithmetic::div, '/', 0x2F},
        ari_case{nx::arithmetic::int_div, '\\', 0x5C}, ari_case{nx::arithmetic::mod, '%', 0x25}}) {
    const auto c =
        nx::make_assign(nx::op::assign_p, 7, nx::operand_of(nx::operand_type::parameter, 8), ari,
                        nx::operand_of(nx::operand_type::variable, 9));
    CHECK(content(c)[10] == code);
    CHECK(text(c) == std::string("P7=P8") + sym + "V9");
    CHECK(nx::parse_command(text(c)).value() == c);
  }
}

TEST_CASE("Nx set-memory table: combined commands") {
  using nx::op;
  const auto posr = nx::make(op::posr, nx::value(decimal{100'000, 3}));
  round_trip(
      nx::then(nx::make(op::posa, nx::value(decimal{250'000, 3})), op::wait, nx::integer(500)),
      cat({{0x41}, dsp_bytes(mm(250'000)), {0x57, 0x01, 0xF4}}), "POSA 250 WAIT 500");
  round_trip(nx::then(nx::make(op::posa, nx::variable(1)), op::wait, nx::variable(2)),
             {0xC1, 0x00, 0x01, 0, 0, 0, 0, 0xD7, 0x00, 0x02}, "POSA V1 WAIT V2");
  round_trip(nx::then(nx::make(op::posa, nx::value(decimal{1'000, 3})), op::wait, nx::variable(12)),
             cat({{0x41}, dsp_bytes(mm(1'000)), {0xD7, 0x00, 0x0C}}), "POSA 1 WAIT V12");
  round_trip(nx::then_output(posr, 3, nx::pattern{1, {1}}),
             cat({{0x52}, dsp_bytes(mm(100'000)), {0x4F, 0x00, 0x03, 0x31}}),
             "POSR 100 OUTPUT A3=1");
  round_trip(nx::then_output(nx::make(op::posr, nx::parameter(40)), 4, nx::pattern{1, {0}}),
             {0x72, 0x00, 0x28, 0, 0, 0, 0, 0x4F, 0x00, 0x04, 0x30}, "POSR P40 OUTPUT A4=0");
  round_trip(nx::then_output(nx::make(op::posr, nx::variable(10)), 4, nx::pattern{1, {1}}),
             {0xD2, 0x00, 0x0A, 0, 0, 0, 0, 0x4F, 0x00, 0x04, 0x31}, "POSR V10 OUTPUT A4=1");
  round_trip(nx::then(posr, op::speed, nx::value(decimal{50'000, 3})),
             cat({{0x52}, dsp_bytes(mm(100'000)), {0x53}, dsp_bytes(mm(50'000))}),
             "POSR 100 SPEED 50");
  round_trip(nx::then(nx::make(op::posr, nx::variable(1)), op::speed, nx::variable(2)),
             {0xD2, 0x00, 0x01, 0, 0, 0, 0, 0xD3, 0x00, 0x02, 0, 0, 0, 0}, "POSR V1 SPEED V2");
  // POSR … SPEED … ACCEL …: the ACCEL word MSB first (decision against the printed LSB…MSB row)
  round_trip(
      nx::then(nx::then(posr, op::speed, nx::value(decimal{50'000, 3})), op::accel,
               nx::integer(0x0102)),
      cat({{0x52}, dsp_bytes(mm(100'000)), {0x53}, dsp_bytes(mm(50'000)), {0x4C, 0x01, 0x02}}),
      "POSR 100 SPEED 50 ACCEL 258");
  round_trip(nx::then(nx::then(nx::make(op::posr, nx::variable(1)), op::speed, nx::variable(2)),
                      op::accel, nx::variable(3)),
             {0xD2, 0x00, 0x01, 0, 0, 0, 0, 0xD3, 0x00, 0x02, 0, 0, 0, 0, 0xCC, 0x00, 0x03},
             "POSR V1 SPEED V2 ACCEL V3");
  round_trip(
      nx::then(nx::then(posr, op::speed, nx::variable(12)), op::accel, nx::parameter(41)),
      cat({{0x52}, dsp_bytes(mm(100'000)), {0xD3, 0x00, 0x0C, 0, 0, 0, 0, 0x6C, 0x00, 0x29}}),
      "POSR 100 SPEED V12 ACCEL P41");
  round_trip(nx::then(posr, op::wait, nx::integer(20)),
             cat({{0x52}, dsp_bytes(mm(100'000)), {0x57, 0x00, 0x14}}), "POSR 100 WAIT 20");
  round_trip(nx::then(nx::make(op::posr, nx::variable(5)), op::wait, nx::variable(6)),
             {0xD2, 0x00, 0x05, 0, 0, 0, 0, 0xD7, 0x00, 0x06}, "POSR V5 WAIT V6");
  round_trip(
      nx::then(nx::make(op::speed, nx::value(decimal{10'000, 3})), op::wait, nx::integer(100)),
      cat({{0x53}, dsp_bytes(mm(10'000)), {0x57, 0x00, 0x64}}), "SPEED 10 WAIT 100");
  round_trip(nx::then(nx::make(op::speed, nx::variable(1)), op::wait, nx::variable(2)),
             {0xD3, 0x00, 0x01, 0, 0, 0, 0, 0xD7, 0x00, 0x02}, "SPEED V1 WAIT V2");
  round_trip(nx::then(nx::make(op::wait, nx::special()), op::posa, nx::value(decimal{100'000, 3})),
             cat({{0x57, 0x00, 0x00, 0x41}, dsp_bytes(mm(100'000))}), "WAIT POSA 100");
  round_trip(nx::then(nx::make(op::wait, nx::special()), op::posr, nx::value(decimal{-5'000, 3})),
             cat({{0x57, 0x00, 0x00, 0x52}, dsp_bytes(mm(-5'000))}), "WAIT POSR -5");
}

TEST_CASE("Nx bad input: codes, lengths, truncation, digits") {
  using nx::op;
  // unknown command codes, including the nibble-swapped variable codes of the other tables
  for (std::uint8_t code :
       {std::uint8_t{0x00}, std::uint8_t{0x1C}, std::uint8_t{0x2D}, std::uint8_t{0x3D},
        std::uint8_t{0x7D}, std::uint8_t{0x63}, std::uint8_t{0xFF}, std::uint8_t{0x44}}) {
    CAPTURE(code);
    const bytes b{code, 0x00, 0x01, 0, 0, 0, 0};
    CHECK(nx::decode_content(b).error() == errc::unknown_command);
  }
  // 0x4D is SETM value (not REPEAT variable): 7 bytes
  CHECK(nx::decode_content(bytes{0x4D, 0x00, 0x03}).error() == errc::truncated);
  // truncated records
  CHECK(nx::decode_content(bytes{0x41, 0, 0, 0, 0, 0}).error() == errc::truncated);
  CHECK(nx::decode_content(bytes{0x4C, 0x03}).error() == errc::truncated);
  CHECK(nx::decode_content(bytes{0x49, 0x00, 0x05, 0x31, 0x47, 0x00}).error() == errc::truncated);
  CHECK(nx::decode_content(bytes{0x49, 0x00, 0x05}).error() == errc::truncated);
  CHECK(nx::decode_content(bytes{0x4F, 0x00, 0x05}).error() == errc::truncated);
  CHECK(nx::decode_content(bytes{}).error() == errc::truncated);
  CHECK(nx::decode_record(bytes{}).error() == errc::truncated);
  CHECK(nx::decode_record(bytes{0x03, 0x4C, 0x03}).error() == errc::truncated);
  // lengths that disagree with the content
  CHECK(nx::decode_record(bytes{0x02, 0x4C, 0x03, 0xE8}).error() == errc::bad_length);
  CHECK(nx::decode_record(bytes{0x04, 0x4C, 0x03, 0xE8, 0x00}).error() == errc::bad_length);
  CHECK(nx::decode_record(bytes{0x00, 0x20}).error() == errc::bad_length);
  CHECK(nx::decode_record(bytes{0x14, 0x20}).error() == errc::bad_length);
  CHECK(nx::decode_record(bytes(21, 0x01)).error() == errc::too_long);
  CHECK(nx::decode_content(bytes{0x45, 0x00, 0x00}).error() == errc::bad_length);
  CHECK(nx::decode_content(bytes{0x47, 0x00, 0x01, 0x45, 0x00}).error() == errc::bad_length);
  // a third command after POSR … WAIT …
  CHECK(nx::decode_content(bytes{0xD2, 0, 1, 0, 0, 0, 0, 0xD7, 0, 2, 0x4C, 0, 1}).error() ==
        errc::bad_length);
  CHECK(nx::decode_record(bytes{0x03, 0x4C, 0x03, 0xE8, 0x77, 0x77}).value() ==
        nx::make(op::accel, nx::integer(1000))); // padding is ignored
  // y digits other than 0x30/0x31
  CHECK(nx::decode_content(bytes{0x49, 0x00, 0x05, 0x32, 0x47, 0x00, 0x0C}).error() ==
        errc::bad_digit);
  CHECK(nx::decode_content(bytes{0x49, 0x00, 0x05, 0x01, 0x47, 0x00, 0x0C}).error() ==
        errc::bad_digit);
  CHECK(nx::decode_content(bytes{0x4F, 0x00, 0x05, 0x31, 0x20}).error() == errc::bad_digit);
  CHECK(nx::decode_content(bytes{0x4F, 0x00, 0x00, 0x31, 0x31}).error() == errc::bad_length);
  CHECK(nx::decode_content(
            bytes{0x4F, 0x00, 0x01, 0x31, 0x31, 0x31, 0x31, 0x31, 0x31, 0x31, 0x31, 0x31})
            .error() == errc::bad_length);
  // IF ERROR with a pattern other than "1"
  CHECK(nx::decode_content(bytes{0x49, 0x00, 0xFF, 0x30, 0x42, 0x00, 0x01}).error() ==
        errc::out_of_range);
  // operand type, comparison and arithmetic codes
  CHECK(nx::decode_content(bytes{0x56, 0x00, 0x01, 0x51, 0, 1, 0, 0, 0, 0}).error() ==
        errc::unknown_command);
  CHECK(nx::decode_content(
            bytes{0x56, 0x00, 0x01, 0x56, 0, 1, 0, 0, 0, 0, 0x2C, 0x56, 0, 1, 0, 0, 0, 0})
            .error() == errc::unknown_command);
  CHECK(nx::decode_content(
            bytes{0x4A, 0x56, 0, 1, 0, 0, 0, 0, 0x3F, 0x56, 0, 1, 0, 0, 0, 0, 0x47, 0, 1})
            .error() == errc::unknown_command);
  CHECK(nx::decode_content(
            bytes{0x4A, 0x56, 0, 1, 0, 0, 0, 0, 0x3D, 0x56, 0, 1, 0, 0, 0, 0, 0x48, 0, 1})
            .error() == errc::unknown_command);
  // non-zero padding in a parameter form
  CHECK(nx::decode_content(bytes{0x61, 0x00, 0x0C, 0, 0, 1, 0}).error() == errc::out_of_range);
  // combinations the table does not have: bytes after a command that takes no follower
  CHECK(nx::decode_content(bytes{0x4C, 0x03, 0xE8, 0x57, 0x00, 0x01}).error() == errc::bad_length);
  CHECK(nx::decode_content(bytes{0x57, 0x00, 0x05, 0x41, 0, 0, 0, 1, 0, 0}).error() ==
        errc::bad_length);
  // … and a follower the table does not list
  CHECK(nx::decode_content(bytes{0x41, 0, 0, 0, 1, 0, 0, 0x4C, 0x03, 0xE8}).error() ==
        errc::unknown_command);
  CHECK(nx::decode_content(bytes{0x41, 0, 0, 0, 1, 0, 0, 0x4F, 0x00, 0x01, 0x31}).error() ==
        errc::unknown_command);
  // SETM has no special form
  CHECK(nx::decode_content(bytes{0x4D, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF}).error() ==
        errc::out_of_range);
  CHECK(nx::decode_content(bytes{0x01, 0x56, 0x51}).error() == errc::unknown_command);
}

TEST_CASE("Nx encoder refuses what it cannot write") {
  using nx::op;
  std::array<std::uint8_t, nx::content_max> b{};
  CHECK(nx::encode_content(nx::make(op::setc, nx::parameter(1)), b).error() == errc::type_mismatch);
  CHECK(nx::encode_content(nx::make(op::setm, nx::special()), b).error() == errc::type_mismatch);
  CHECK(nx::encode_content(nx::make(op::wait, nx::integer(0)), b).error() == errc::out_of_range);
  CHECK(nx::encode_content(nx::make(op::goto_, nx::integer(0)), b).error() == errc::out_of_range);
  CHECK(nx::encode_content(nx::make(op::loop, nx::integer(65536)), b).error() ==
        errc::out_of_range);
  CHECK(nx::encode_content(nx::make(op::posa, nx::dsp_raw(-1)), b).error() == errc::out_of_range);
  CHECK(nx::encode_content(nx::make(op::end, nx::integer(1)), b).error() == errc::invalid_argument);
  CHECK(
      nx::encode_content(nx::then(nx::make(op::accel, nx::integer(1)), op::wait, nx::integer(1)), b)
          .error() == errc::invalid_argument);
  CHECK(nx::encode_content(nx::make_valid('X'), b).error() == errc::invalid_argument);
  CHECK(nx::encode_content(nx::make_output(3, nx::pattern{1, {2}}), b).error() == errc::bad_digit);
  CHECK(nx::encode_content(nx::make_output(3, nx::pattern{0, {}}), b).error() == errc::bad_length);
  CHECK(nx::encode_content(nx::make(op::none), b).error() == errc::unknown_command);
  std::array<std::uint8_t, 3> small{};
  CHECK(nx::encode_content(nx::make(op::posa, nx::special()), small).error() ==
        errc::buffer_too_small);
}

TEST_CASE("Nx: DSP extremes through text") {
  // the smallest 48-bit value is -8388608 exactly: on the 0.001 grid
  const bytes lowest{0x41, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80};
  auto c = nx::decode_content(lowest);
  REQUIRE(c.has_value());
  CHECK(c.value().argument == nx::integer(-8388608));
  CHECK(text(c.value()) == "POSA -8388608");
  CHECK(nx::parse_command("POSA -8388608").value() == c.value());
  // the largest is 2^23 - 2^-24: between two thousandths, so it stays a raw value and has no
  // program text (not printed rounded)
  const bytes highest{0x41, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x7F};
  auto h = nx::decode_content(highest);
  REQUIRE(h.has_value());
  CHECK(h.value().argument.kind == nx::arg_kind::dsp_raw);
  CHECK(content(h.value()) == highest);
  std::array<char, nx::text_max> t{};
  CHECK(nx::format_command(h.value(), t).error() == errc::not_representable);
  CHECK(text(nx::make(nx::op::posa, nx::dsp_raw(cx::dsp_number{cx::dsp_format::raw_min}))) ==
        "POSA -8388608");
}

// Issue 13: nx::make(op::posa, nx::integer(250)) encoded 250 raw DSP units (250 / 2^24 mm) and
// printed back as "POSA 0". Numbers now carry the command's unit; the raw form is dsp_raw().
TEST_CASE("Nx operands carry their unit; the raw DSP form is explicit") {
  using nx::op;
  // 2.11.1 N example: record 5 = "POSA 250", i.e. 250 mm; the Nx record of the same command
  const auto posa = nx::make(op::posa, nx::integer(250));
  CHECK(content(posa) == cat({{0x41}, dsp_bytes(mm(250'000))}));
  CHECK(content(posa) == bytes{0x41, 0x00, 0x00, 0x00, 0xFA, 0x00, 0x00});
  CHECK(text(posa) == "POSA 250");
  CHECK(nx::parse_command("POSA 250").value() == posa);
  // 2.4.11 COMMAND example: "POSR15.8" travels 15.8 mm relative
  const auto posr = nx::make(op::posr, nx::value(decimal{158, 1}));
  CHECK(content(posr) == cat({{0x52}, dsp_bytes(mm(15'800))}));
  CHECK(text(posr) == "POSR 15.8");
  // every integer type means the same number; negative positions are positions
  CHECK(nx::make(op::posa, nx::integer(std::int8_t{-5})) ==
        nx::make(op::posa, nx::value(decimal{-5, 0})));
  CHECK(content(nx::make(op::posa, nx::integer(250ULL))) == content(posa));
  CHECK(content(nx::make(op::posa, nx::integer(-1))) == cat({{0x41}, dsp_bytes(mm(-1'000))}));
  // 2-byte commands: the number itself (ms, count, record)
  CHECK(content(nx::make(op::accel, nx::integer(std::uint64_t{200}))) == bytes{0x4C, 0x00, 0xC8});
  CHECK(content(nx::make(op::goto_, nx::integer(short{12}))) == bytes{0x47, 0x00, 0x0C});
  // the raw form, spelled explicitly: 250 raw units are 250 / 2^24 mm
  const auto raw = nx::make(op::posa, nx::dsp_raw(250));
  CHECK(raw.argument.kind == nx::arg_kind::dsp_raw);
  CHECK(content(raw) == bytes{0x41, 0xFA, 0x00, 0x00, 0x00, 0x00, 0x00});
  CHECK(nx::decode_content(content(raw)).value() == raw);
  std::array<char, nx::text_max> t{};
  CHECK(nx::format_command(raw, t).error() == errc::not_representable); // not "POSA 0"
  // a raw value on the 0.001 grid is the decimal it stands for
  CHECK(nx::dsp_raw(mm(1'500)) == nx::value(decimal{15, 1}));
  CHECK(nx::constant_raw(mm(1'500)) == nx::constant(decimal{15, 1}));
  CHECK(nx::constant_raw(cx::dsp_number{3}).raw);
  // constants of IF and assignments carry their unit too
  const auto v = nx::make_assign(op::assign_v, 4, nx::constant(-7));
  CHECK(content(v) == cat({{0x56, 0x00, 0x04, 0x20}, dsp_bytes(mm(-7'000))}));
  CHECK(text(v) == "V4=-7");
  const auto raw_constant = nx::make_assign(op::assign_v, 4, nx::constant_raw(cx::dsp_number{3}));
  CHECK(nx::decode_content(content(raw_constant)).value() == raw_constant);
  CHECK(nx::format_command(raw_constant, t).error() == errc::not_representable);
}

// Issue 18, round 6: nx::dsp_raw keeps a raw value raw (kind dsp_raw, as its name says), also
// on the 0.001 grid; until round 5 an on-grid raw value became a decimal (kind value) when it
// was built. What it stands for did not change: it compares equal to that decimal and to what
// decode_record gives for its bytes, prints as that decimal and encodes to the same bytes.
static_assert(nx::dsp_raw(250 * cx::dsp_format::one).kind == nx::arg_kind::dsp_raw);
static_assert(nx::dsp_raw(250 * cx::dsp_format::one).number == 250 * cx::dsp_format::one);
static_assert(nx::dsp_raw(cx::dsp_number{3}) == nx::arg{nx::arg_kind::dsp_raw, 0, 3});
static_assert(nx::dsp_raw(~std::uint64_t{0}).number == INT64_MAX); // saturated, never wrapped
static_assert(nx::dsp_raw(250 * cx::dsp_format::one) == nx::integer(250));
static_assert(nx::integer(250) == nx::dsp_raw(250 * cx::dsp_format::one));
static_assert(nx::normalized(nx::dsp_raw(250 * cx::dsp_format::one)) ==
              nx::arg{nx::arg_kind::value, 0, 250});
static_assert(nx::normalized(nx::dsp_raw(mm(1'500))) == nx::arg{nx::arg_kind::value, 1, 15});
static_assert(nx::normalized(nx::dsp_raw(3)) == nx::arg{nx::arg_kind::dsp_raw, 0, 3});
static_assert(nx::normalized(nx::parameter(3)) == nx::arg{nx::arg_kind::parameter, 0, 3});
static_assert(nx::dsp_raw(mm(1'500)) != nx::value(decimal{15, 2}));
static_assert(nx::dsp_raw(mm(1'500).raw + 1) != nx::value(decimal{15, 1})); // next to the grid
static_assert(nx::dsp_raw(3) != nx::parameter(3) && nx::dsp_raw(0) != nx::special());
// places of a raw argument are not part of it (dsp_of and the encoder ignore them)
static_assert(nx::arg{nx::arg_kind::dsp_raw, 2, 3} == nx::dsp_raw(3));
static_assert(nx::arg{nx::arg_kind::dsp_raw, 2, 250 * cx::dsp_format::one} == nx::integer(250));
// a decimal set by hand and not normalized stays what it was: compared member by member
static_assert(nx::arg{nx::arg_kind::value, 1, 2500} != nx::integer(250));

TEST_CASE("Nx: dsp_raw keeps a raw value raw and stands for the decimal on the grid") {
  using nx::op;
  const auto raw = nx::make(op::posr, nx::dsp_raw(mm(250'500)));
  const auto dec = nx::make(op::posr, nx::value(decimal{2505, 1}));
  CHECK(raw.argument.kind == nx::arg_kind::dsp_raw);
  CHECK(raw == dec);
  CHECK(content(raw) == content(dec));
  CHECK(content(raw) == cat({{0x52}, dsp_bytes(mm(250'500))}));
  CHECK(text(raw) == "POSR 250.5");
  // the decoder gives the decimal form, equal to the raw argument the record was built from
  const auto back = nx::decode_content(content(raw));
  REQUIRE(back.has_value());
  CHECK(back.value().argument.kind == nx::arg_kind::value);
  CHECK(back.value() == raw);
  CHECK(back.value().argument == nx::normalized(raw.argument));
  // the combined positioning record: the same bytes as with decimals, read back equal
  const auto posr = nx::then(
      nx::then(nx::make(op::posr, nx::dsp_raw(mm(-12'345))), op::speed, nx::dsp_raw(mm(50'000))),
      op::accel, nx::integer(200));
  const auto posr_dec = nx::then(
      nx::then(nx::make(op::posr, nx::value(decimal{-12345, 3})), op::speed, nx::integer(50)),
      op::accel, nx::integer(200));
  CHECK(nx::encode_record(posr).value() == nx::encode_record(posr_dec).value());
  CHECK(nx::decode_record(nx::encode_record(posr).value()).value() == posr);
  CHECK(text(posr) == "POSR -12.345 SPEED 50 ACCEL 200");
  CHECK(nx::parse_command("POSR -12.345 SPEED 50 ACCEL 200").value() == posr);
  // a 2-byte field takes a raw value on the grid as the number it stands for, as before
  CHECK(content(nx::make(op::accel, nx::dsp_raw(200 * cx::dsp_format::one))) ==
        bytes{0x4C, 0x00, 0xC8});
  CHECK(text(nx::make(op::accel, nx::dsp_raw(200 * cx::dsp_format::one))) == "ACCEL 200");
  std::array<std::uint8_t, nx::content_max> b{};
  CHECK(nx::encode_content(nx::make(op::accel, nx::dsp_raw(mm(1'500))), b).error() ==
        errc::not_representable);
  CHECK(nx::encode_content(nx::make(op::wait, nx::dsp_raw(0)), b).error() == errc::out_of_range);
  CHECK(nx::encode_content(nx::make(op::nop, nx::dsp_raw(0)), b).value() == 1U); // NOP 0 = NOP
  CHECK(nx::encode_content(nx::make(op::nop, nx::dsp_raw(1)), b).error() == errc::type_mismatch);
  CHECK(nx::encode_content(nx::make(op::end, nx::dsp_raw(mm(1'000))), b).error() ==
        errc::invalid_argument);
  // off the grid: raw everywhere, no program text
  const auto off = nx::make(op::posr, nx::dsp_raw(mm(250'500).raw + 1));
  CHECK(nx::normalized(off.argument).kind == nx::arg_kind::dsp_raw);
  CHECK(nx::decode_content(content(off)).value() == off);
  std::array<char, nx::text_max> t{};
  CHECK(nx::format_command(off, t).error() == errc::not_representable);
  // the DSP number is the raw value either way
  CHECK(nx::dsp_of(raw.argument).value() == mm(250'500));
  CHECK(nx::dsp_of(raw.argument).value() == nx::dsp_of(dec.argument).value());
}

// Issue 13 "Nothing narrows silently": every number argument takes any integer type and the
// encoder checks it against its field; nothing wraps.
TEST_CASE("Nx numbers of any integer type are checked, not wrapped") {
  using nx::op;
  std::array<std::uint8_t, nx::content_max> b{};
  const auto refused = [&b](const nx::command &c) { return nx::encode_content(c, b).error(); };
  // 65537 would wrap to 1 in a 16-bit field
  CHECK(refused(nx::make(op::posa, nx::parameter(65537))) == errc::out_of_range);
  CHECK(refused(nx::make(op::accel, nx::variable(65537L))) == errc::out_of_range);
  CHECK(refused(nx::make(op::accel, nx::parameter(-1))) == errc::out_of_range);
  CHECK(refused(nx::make(op::loop, nx::integer(65537))) == errc::out_of_range);
  CHECK(refused(nx::make(op::loop, nx::integer(-65535))) == errc::out_of_range);
  CHECK(refused(nx::make(op::loop, nx::integer(~std::uint64_t{0}))) == errc::out_of_range);
  CHECK(refused(nx::make(op::posa, nx::integer(~std::uint64_t{0}))) == errc::overflow);
  CHECK(refused(nx::make(op::posa, nx::integer(8'388'608))) == errc::overflow);
  CHECK(refused(nx::make(op::posa, nx::value(decimal{10005, 4}))) == errc::not_representable);
  CHECK(refused(nx::make(op::accel, nx::value(decimal{15, 1}))) == errc::not_representable);
  CHECK(refused(nx::make(op::accel, nx::dsp_raw(1))) == errc::type_mismatch);
  CHECK(refused(nx::make(op::posa, nx::dsp_raw(std::int64_t{1} << 47))) == errc::overflow);
  CHECK(refused(nx::make_if_input(65537, nx::pattern{1, {1}}, nx::jump::goto_, 1)) ==
        errc::out_of_range);
  CHECK(refused(nx::make_if_input(5, nx::pattern{1, {1}}, nx::jump::goto_, 65537U)) ==
        errc::out_of_range);
  CHECK(refused(nx::make_if_error(nx::jump::goto_, -1)) == errc::out_of_range);
  CHECK(refused(nx::make_output(65536LL, nx::pattern{1, {1}})) == errc::out_of_range);
  CHECK(refused(nx::then_output(nx::make(op::posr, nx::integer(1)), 70000, nx::pattern{1, {1}})) ==
        errc::out_of_range);
  CHECK(refused(nx::make_assign(op::assign_p, 65537, nx::constant(1))) == errc::out_of_range);
  CHECK(
      refused(nx::make_assign(op::assign_p, 1, nx::operand_of(nx::operand_type::status, 65537))) ==
      errc::out_of_range);
  CHECK(refused(nx::make_assign(op::assign_p, 1, nx::constant(decimal{1, 4}))) ==
        errc::not_representable);
  CHECK(refused(nx::make_assign(op::assign_p, 1, nx::constant(9'000'000))) == errc::overflow);
  // the widest argument types work where the value fits
  CHECK(content(nx::make_if_input(std::uint64_t{5}, nx::pattern{1, {1}}, nx::jump::goto_,
                                  std::int64_t{12})) ==
        bytes{0x49, 0x00, 0x05, 0x31, 0x47, 0x00, 0x0C});
}

TEST_CASE("Nx text bad input") {
  CHECK(nx::parse_command("").error() == errc::bad_syntax);
  CHECK(nx::parse_command("JUMP 5").error() == errc::unknown_command);
  CHECK(nx::parse_command("POSA").error() == errc::bad_syntax);
  CHECK(nx::parse_command("POSA 1.0005").error() == errc::not_representable);
  CHECK(nx::parse_command("POSA 9000000").error() == errc::overflow);
  CHECK(nx::parse_command("POSA 1x").error() == errc::bad_digit);
  CHECK(nx::parse_command("ACCEL 70000").error() == errc::out_of_range);
  CHECK(nx::parse_command("WAIT 0").error() == errc::out_of_range);
  CHECK(nx::parse_command("END 5").error() == errc::bad_length);
  CHECK(nx::parse_command("POSA 1 SPEED 5").error() == errc::invalid_argument);
  CHECK(nx::parse_command("IF E5=2 GOTO 3").error() == errc::bad_digit);
  CHECK(nx::parse_command("IF E5=1 JUMP 3").error() == errc::bad_syntax);
  CHECK(nx::parse_command("IF V1=>P2 GOTO 3").error() == errc::bad_digit);
  CHECK(nx::parse_command("IF V1 GOTO 3").error() == errc::bad_syntax);
  CHECK(nx::parse_command("POSR 1 SPEED 2 ACCEL 3 WAIT 4").error() == errc::bad_length);
  CHECK(nx::parse_command("POSR 1 SPEED 2 JUMP 3").error() == errc::unknown_command);
  CHECK(nx::parse_command("OUTPUT B5=1").error() == errc::bad_syntax);
  CHECK(nx::parse_command("P1=V2^3").error() == errc::bad_syntax);
  CHECK(nx::parse_command("IF E5=101010101 GOTO 3").error() == errc::bad_length);
  std::array<char, 5> tiny{};
  CHECK(nx::format_command(nx::make(nx::op::posa, nx::special()), tiny).error() ==
        errc::buffer_too_small);
}

TEST_CASE("Nx: whatever decodes re-encodes to the same bytes and survives text") {
  // deterministic pseudo-random contents built from the table's codes and byte values
  std::uint32_t x = 12345;
  auto rnd = [&x] {
    x = x * 1664525U + 1013904223U;
    return x >> 8U;
  };
  constexpr std::array<std::uint8_t, 40> codes{
      0x20, 0x01, 0x41, 0x42, 0x43, 0x45, 0x47, 0x49, 0x4A, 0x4B, 0x4C, 0x4D, 0x4F, 0x50,
      0x51, 0x52, 0x53, 0x54, 0x55, 0x56, 0x57, 0x61, 0x6B, 0x6C, 0x6D, 0x72, 0x73, 0x74,
      0x77, 0xC1, 0xCB, 0xCC, 0xCD, 0xD2, 0xD3, 0xD4, 0xD7, 0x30, 0x31, 0xFF};
  std::size_t decoded = 0;
  std::size_t printed = 0;
  for (int i = 0; i < 200000; ++i) {
    bytes b(1 + rnd() % nx::content_max);
    for (auto &v : b) {
      const auto r = rnd();
      v = (r % 3U == 0U) ? codes[(r >> 4U) % codes.size()]
                         : static_cast<std::uint8_t>((r % 5U == 0U) ? 0U : (r >> 8U) & 0xFFU);
    }
    auto c = nx::decode_content(b);
    if (!c) continue;
    ++decoded;
    CAPTURE(b);
    CHECK(content(c.value()) == b);
    std::array<char, nx::text_max> t{};
    auto n = nx::format_command(c.value(), t);
    if (!n) {
      // only a raw DSP value off the 0.001 grid has no text
      CHECK(n.error() == errc::not_representable);
      continue;
    }
    ++printed;
    auto p = nx::parse_command(std::string_view{t.data(), n.value()});
    REQUIRE(p.has_value());
    CHECK(p.value() == c.value()); // text is exact for everything it can print
  }
  CHECK(decoded > 1000);
  CHECK(printed > 1000);
  // values on the 0.001 grid (what program text and nx::value() give) survive every trip
  for (int i = 0; i < 20000; ++i) {
    const auto t = static_cast<std::int64_t>(rnd() % 16'000'000'001U) - 8'000'000'000;
    const auto c = nx::then(nx::make(nx::op::posr, nx::value(decimal{t, 3})), nx::op::speed,
                            nx::value(decimal{static_cast<std::int64_t>(rnd() % 600'000U), 3}));
    CAPTURE(t);
    const bytes b = content(c);
    CHECK(nx::decode_content(b).value() == c);
    CHECK(nx::parse_command(text(c)).value() == c);
  }
}
