// PA-CONTROL RS232 frames: the 17 frames of manual 001, section 3.4, built from their field
// tables. Where the printed bytes are wrong the test asserts what the protocol produces and
// names the entry in docs/errata.md, "PA-CONTROL (001) / Serial frames (3.4)".
#include <fieldcodec/pacontrol/serial_decoder.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>

#include "pac_test_util.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>

namespace fc = fieldcodec;
namespace serial = fc::pacontrol::serial;
using fc::decimal;
using fc::errc;
using fc::pacontrol::value;
using pactest::hex;
using serial::acknowledgement;
using serial::check_mode;
using serial::check_rule;
using serial::request;

namespace {

constexpr value real(std::int64_t mantissa, std::uint8_t places) {
  return value::of_real(decimal{mantissa, places}).value();
}

constexpr pactest::bytes encode(const request &r, check_rule rule = check_rule::body,
                                check_mode mode = check_mode::computed) {
  std::array<std::uint8_t, serial::max_frame_size> buf{};
  auto n = serial::encode_request(r, buf, rule, mode);
  pactest::bytes b;
  if (!n) return b;
  for (std::size_t i = 0; i < n.value(); ++i) b.data[b.size++] = buf[i];
  return b;
}

constexpr pactest::bytes encode(const acknowledgement &a,
                                check_rule rule = check_rule::body_and_etx,
                                check_mode mode = check_mode::computed) {
  std::array<std::uint8_t, serial::max_frame_size> buf{};
  auto n = serial::encode_acknowledgement(a, buf, rule, mode);
  pactest::bytes b;
  if (!n) return b;
  for (std::size_t i = 0; i < n.value(); ++i) b.data[b.size++] = buf[i];
  return b;
}

constexpr bool same(const pactest::bytes &a, const pactest::bytes &b) { return a == b.span(); }

// --- The 17 frames, fields as in the manual's tables, bytes as the protocol produces them ---

// 1: 3.4.1 write N5 = 12345 (l. 1211-1220). Printed CHECK 7 is wrong: errata serial frame 1.
constexpr request f1{0x0906, 5, value::of_int(12345).value()};
constexpr auto f1_bytes = hex("01 02 30 39 30 36 3B 35 3B 30 3B 31 32 33 34 35 03 30 04");
constexpr auto f1_printed = hex("01 02 30 39 30 36 3B 35 3B 30 3B 31 32 33 34 35 03 37 04");
// 2: its acknowledgement (l. 1224-1241), correct as printed.
constexpr acknowledgement f2{0, true, 1, 0, value::of_int(12345).value()};
constexpr auto f2_bytes = hex("01 02 30 3B 31 3B 31 3B 30 3B 30 3B 31 32 33 34 35 03 35 37 04");
// 3: 3.4.2 cmd 1, read input 5 (l. 1258-1265), correct.
constexpr request f3{0x1900, 5, value::of_int(0).value()};
constexpr auto f3_bytes = hex("01 02 31 39 30 30 3B 35 3B 30 3B 30 03 36 04");
// 4: its acknowledgement, input 5 = 1 (l. 1273-1280), correct.
constexpr acknowledgement f4{0, true, 1, 0, value::of_int(1).value()};
constexpr auto f4_bytes = hex("01 02 30 3B 31 3B 31 3B 30 3B 30 3B 31 03 35 37 04");
// 5: 3.4.2 cmd 2, read N2 (l. 1288-1295). Printed CMD "1960" and CHECK 6: errata frame 2.
constexpr request f5{0x1906, 2, value::of_int(0).value()};
constexpr auto f5_bytes = hex("01 02 31 39 30 36 3B 32 3B 30 3B 30 03 37 04");
constexpr auto f5_printed = hex("01 02 31 39 36 30 3B 32 3B 30 3B 30 03 36 04");
// 6: its acknowledgement, N2 = 222 (l. 1303-1310), correct.
constexpr acknowledgement f6{0, true, 1, 0, value::of_int(222).value()};
constexpr auto f6_bytes = hex("01 02 30 3B 31 3B 31 3B 30 3B 30 3B 32 32 32 03 35 38 04");
// 7: 3.4.2 cmd 3, write N3 = 333 (l. 1318-1325), correct.
constexpr request f7{0x0906, 3, value::of_int(333).value()};
constexpr auto f7_bytes = hex("01 02 30 39 30 36 3B 33 3B 30 3B 33 33 33 03 34 04");
// 8: its acknowledgement (l. 1333-1340), correct.
constexpr acknowledgement f8{0, true, 1, 0, value::of_int(333).value()};
constexpr auto f8_bytes = hex("01 02 30 3B 31 3B 31 3B 30 3B 30 3B 33 33 33 03 35 39 04");
// 9: 3.4.2 cmd 4, read R1 (l. 1348-1355). Printed body "1971;3;0;0": errata frame 3.
constexpr request f9{0x1907, 1, real(0, 0)};
constexpr auto f9_bytes = hex("01 02 31 39 30 37 3B 31 3B 31 3B 30 03 34 04");
constexpr auto f9_printed = hex("01 02 31 39 37 31 3B 33 3B 30 3B 30 03 36 04");
// 10: its acknowledgement, R1 = 640.0000 (l. 1368-1375), correct.
constexpr acknowledgement f10{0, true, 1, 0, real(6400000, 4)};
constexpr auto f10_bytes =
    hex("01 02 30 3B 31 3B 31 3B 30 3B 31 3B 36 34 30 2E 30 30 30 30 03 32 31 04");
// 11: 3.4.3 cmd 1, start online (l. 1395-1402). Printed CMD byte 0x41 ("0A03"): errata 4.
constexpr request f11{0x0603, 0, value::of_int(0).value()};
constexpr auto f11_bytes = hex("01 02 30 36 30 33 3B 30 3B 30 3B 30 03 31 34 04");
constexpr auto f11_printed = hex("01 02 30 41 30 33 3B 30 3B 30 3B 30 03 31 34 04");
// 12: its acknowledgement, status 31 (l. 1410-1417). Printed CHECK 8 (request rule): errata 5.
constexpr acknowledgement f12{0, true, 31, 0, value::of_int(0).value()};
constexpr auto f12_bytes = hex("01 02 30 3B 31 3B 33 31 3B 30 3B 30 3B 30 03 31 31 04");
constexpr auto f12_printed = hex("01 02 30 3B 31 3B 33 31 3B 30 3B 30 3B 30 03 38 04");
// 13: 3.4.3 cmd 2, axis 2 absolute to 5552.0 (l. 1429-1436). Printed CHECK 14: errata 6.
constexpr request f13{0x0A87, 2, real(55520, 1)};
constexpr auto f13_bytes = hex("01 02 30 41 38 37 3B 32 3B 31 3B 35 35 35 32 2E 30 03 39 35 04");
constexpr auto f13_printed = hex("01 02 30 41 38 37 3B 32 3B 31 3B 35 35 35 32 2E 30 03 31 34 04");
// 14: its acknowledgement, started at 1255.000 (l. 1447-1454), correct.
constexpr acknowledgement f14{0, false, 31, 0, real(1255000, 3)};
constexpr auto f14_bytes =
    hex("01 02 30 3B 30 3B 33 31 3B 30 3B 31 3B 31 32 35 35 2E 30 30 30 03 33 38 04");
// 15: after the 1st poll, 1516.950 (l. 1462-1469), correct.
constexpr acknowledgement f15{0, false, 31, 0, real(1516950, 3)};
constexpr auto f15_bytes =
    hex("01 02 30 3B 30 3B 33 31 3B 30 3B 31 3B 31 35 31 36 2E 39 35 30 03 34 32 04");
// 16: after the 2nd poll, 2634.750 (l. 1477-1484), correct.
constexpr acknowledgement f16{0, false, 31, 0, real(2634750, 3)};
constexpr auto f16_bytes =
    hex("01 02 30 3B 30 3B 33 31 3B 30 3B 31 3B 32 36 33 34 2E 37 35 30 03 33 36 04");
// 17: after the 3rd poll, done at 5552.000 (l. 1492-1499), correct.
constexpr acknowledgement f17{0, true, 31, 0, real(5552000, 3)};
constexpr auto f17_bytes =
    hex("01 02 30 3B 31 3B 33 31 3B 30 3B 31 3B 35 35 35 32 2E 30 30 30 03 33 35 04");

// Encoding at compile time.
static_assert(same(encode(f1), f1_bytes));
static_assert(same(encode(f2), f2_bytes));
static_assert(same(encode(f3), f3_bytes));
static_assert(same(encode(f4), f4_bytes));
static_assert(same(encode(f5), f5_bytes));
static_assert(same(encode(f6), f6_bytes));
static_assert(same(encode(f7), f7_bytes));
static_assert(same(encode(f8), f8_bytes));
static_assert(same(encode(f9), f9_bytes));
static_assert(same(encode(f10), f10_bytes));
static_assert(same(encode(f11), f11_bytes));
static_assert(same(encode(f12), f12_bytes));
static_assert(same(encode(f13), f13_bytes));
static_assert(same(encode(f14), f14_bytes));
static_assert(same(encode(f15), f15_bytes));
static_assert(same(encode(f16), f16_bytes));
static_assert(same(encode(f17), f17_bytes));

// Decoding at compile time.
constexpr bool decodes(const pactest::bytes &b, const request &r) {
  auto d = serial::decode_frame(b.span());
  return d && d.value().kind == serial::frame_kind::request && d.value().req == r &&
         d.value().req.date.same_text(r.date); // the digits as sent, not only the number
}
constexpr bool decodes(const pactest::bytes &b, const acknowledgement &a) {
  auto d = serial::decode_frame(b.span());
  return d && d.value().kind == serial::frame_kind::acknowledgement && d.value().ack == a &&
         d.value().ack.date.same_text(a.date);
}
static_assert(decodes(f1_bytes, f1));
static_assert(decodes(f2_bytes, f2));
static_assert(decodes(f3_bytes, f3));
static_assert(decodes(f4_bytes, f4));
static_assert(decodes(f5_bytes, f5));
static_assert(decodes(f6_bytes, f6));
static_assert(decodes(f7_bytes, f7));
static_assert(decodes(f8_bytes, f8));
static_assert(decodes(f9_bytes, f9));
static_assert(decodes(f10_bytes, f10));
static_assert(decodes(f11_bytes, f11));
static_assert(decodes(f12_bytes, f12));
static_assert(decodes(f13_bytes, f13));
static_assert(decodes(f14_bytes, f14));
static_assert(decodes(f15_bytes, f15));
static_assert(decodes(f16_bytes, f16));
static_assert(decodes(f17_bytes, f17));

constexpr errc decode_error(const pactest::bytes &b, serial::decoder_options o = {}) {
  auto d = serial::decode_frame(b.span(), o);
  return d ? errc{} : d.error();
}

} // namespace

TEST_CASE("pacontrol serial: the 17 frames of 3.4 encode and decode (manual 001, 3.4)") {
  struct req_case {
    const request *r;
    const pactest::bytes *b;
  };
  struct ack_case {
    const acknowledgement *a;
    const pactest::bytes *b;
  };
  const req_case reqs[] = {{&f1, &f1_bytes},  {&f3, &f3_bytes}, {&f5, &f5_bytes},
                           {&f7, &f7_bytes},  {&f9, &f9_bytes}, {&f11, &f11_bytes},
                           {&f13, &f13_bytes}};
  const ack_case acks[] = {{&f2, &f2_bytes},   {&f4, &f4_bytes},   {&f6, &f6_bytes},
                           {&f8, &f8_bytes},   {&f10, &f10_bytes}, {&f12, &f12_bytes},
                           {&f14, &f14_bytes}, {&f15, &f15_bytes}, {&f16, &f16_bytes},
                           {&f17, &f17_bytes}};
  for (const auto &c : reqs) {
    CHECK(same(encode(*c.r), *c.b));
    auto d = serial::decode_frame(c.b->span());
    REQUIRE(d);
    CHECK(d.value().kind == serial::frame_kind::request);
    CHECK(d.value().req == *c.r);
  }
  for (const auto &c : acks) {
    CHECK(same(encode(*c.a), *c.b));
    auto d = serial::decode_frame(c.b->span());
    REQUIRE(d);
    CHECK(d.value().kind == serial::frame_kind::acknowledgement);
    CHECK(d.value().ack == *c.a);
  }
}

TEST_CASE("pacontrol serial: the frames printed wrongly in 3.4 (errata serial frames 1-6)") {
  // 1 (l. 1220): CHECK 7 matches no rule for "0906;5;0;12345" (XOR 0).
  CHECK(decode_error(f1_printed) == errc::bad_checksum);
  CHECK(serial::compute_check(std::string_view("0906;5;0;12345"), check_rule::body) == 0);
  CHECK(serial::compute_check(std::string_view("0906;5;0;12345"), check_rule::body_and_etx) == 3);
  // 2 (l. 1295): "1960" with CHECK 6; the XOR of "1960;2;0;0" is 7 either way round.
  CHECK(decode_error(f5_printed) == errc::bad_checksum);
  // 3 (l. 1355): "1971;3;0;0" CHECK 6 is self-consistent: it decodes, but to the wrong command.
  auto p9 = serial::decode_frame(f9_printed.span());
  REQUIRE(p9);
  CHECK(p9.value().req.code == 0x1971);
  CHECK(p9.value().req.parameter == 3);
  CHECK(p9.value().req.date.type == fc::od::command_value::integer);
  CHECK_FALSE(p9.value().req == f9);
  // 4 (l. 1402): "0A03" with the CHECK of "0603" (14; "0A03" would need 121).
  CHECK(decode_error(f11_printed) == errc::bad_checksum);
  CHECK(serial::compute_check(std::string_view("0A03;0;0;0"), check_rule::body) == 121);
  // 5 (l. 1410): CHECK 8 follows the request rule; it fails under the acknowledgement
  // default and passes only when that direction is switched to check_rule::body.
  CHECK(decode_error(f12_printed) == errc::bad_checksum);
  serial::decoder_options body_rule{};
  body_rule.check.acknowledgement = check_rule::body;
  auto p12 = serial::decode_frame(f12_printed.span(), body_rule);
  REQUIRE(p12);
  CHECK(p12.value().ack == f12);
  CHECK(same(encode(f12, check_rule::body), f12_printed));
  // 6 (l. 1436): CHECK 14 copied from the previous request; the real one is 95.
  CHECK(decode_error(f13_printed) == errc::bad_checksum);
}

TEST_CASE("pacontrol serial: check rules and CHECK 0") {
  // Requests under the acknowledgement rule and vice versa.
  CHECK(same(encode(f3, check_rule::body_and_etx),
             hex("01 02 31 39 30 30 3B 35 3B 30 3B 30 03 35 04")));
  CHECK(same(encode(f2, check_rule::body),
             hex("01 02 30 3B 31 3B 31 3B 30 3B 30 3B 31 32 33 34 35 03 35 38 04")));
  // Unchecked frames carry "0" and pass while zero_means_unchecked is set.
  const auto unchecked = encode(f13, check_rule::body, check_mode::unchecked);
  CHECK(same(unchecked, hex("01 02 30 41 38 37 3B 32 3B 31 3B 35 35 35 32 2E 30 03 30 04")));
  auto d = serial::decode_frame(unchecked.span());
  REQUIRE(d);
  CHECK(d.value().req == f13);
  serial::decoder_options strict{};
  strict.check.zero_means_unchecked = false;
  CHECK(decode_error(unchecked, strict) == errc::bad_checksum);
  // Frame 1 has a genuine XOR of 0: it passes under both settings.
  CHECK(serial::decode_frame(f1_bytes.span(), strict));
  // Swapping the rules of both directions makes every manual frame fail except frame 1,
  // whose body-and-ETX check (3) differs from its body check (0) as well.
  serial::decoder_options swapped{};
  swapped.check = {check_rule::body_and_etx, check_rule::body, false};
  CHECK(decode_error(f1_bytes, swapped) == errc::bad_checksum);
  CHECK(decode_error(f3_bytes, swapped) == errc::bad_checksum);
  CHECK(decode_error(f2_bytes, swapped) == errc::bad_checksum);
}

TEST_CASE("pacontrol serial: encoder limits") {
  std::array<std::uint8_t, serial::max_frame_size> buf{};
  // Buffer too small at every length below the frame's.
  for (std::size_t n = 0; n < f13_bytes.size; ++n) {
    CHECK(serial::encode_request(f13, std::span<std::uint8_t>(buf.data(), n)).error() ==
          errc::buffer_too_small);
  }
  CHECK(serial::encode_request(f13, std::span<std::uint8_t>(buf.data(), f13_bytes.size)));
  std::array<std::uint8_t, 0> none{};
  CHECK(serial::encode_poll(none).error() == errc::buffer_too_small);
  std::array<std::uint8_t, 1> one{};
  CHECK(serial::encode_poll(one).value() == 1);
  CHECK(one[0] == 0x04);
  // Values that break the value invariants.
  const request bad_int{0x0906, 1, value{fc::od::command_value::integer, decimal{1, 1}}};
  CHECK(serial::encode_request(bad_int, buf).error() == errc::type_mismatch);
  const request too_big{0x0906, 1, value{fc::od::command_value::integer, decimal{2147483648, 0}}};
  CHECK(serial::encode_request(too_big, buf).error() == errc::overflow);
  // Extremes fit max_frame_size.
  const request r_min{0xFFFF, 65535, value::of_int(INT32_MIN).value()};
  auto n = serial::encode_request(r_min, buf);
  REQUIRE(n);
  auto d = serial::decode_frame(std::span<const std::uint8_t>(buf.data(), n.value()));
  REQUIRE(d);
  CHECK(d.value().req == r_min);
  const acknowledgement a_max{65535, true, 65535, 65535, value::of_int(INT32_MAX).value()};
  n = serial::encode_acknowledgement(a_max, buf);
  REQUIRE(n);
  d = serial::decode_frame(std::span<const std::uint8_t>(buf.data(), n.value()));
  REQUIRE(d);
  CHECK(d.value().ack == a_max);
  // Lower-case hex is never written.
  const request lc{0x0a8d, 1, real(100, 1)};
  CHECK(same(encode(lc), pactest::frame("0A8D;1;1;10.0", "41")));
}
