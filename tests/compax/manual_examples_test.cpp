// Every PCP example of the COMPAX-M/S Interbus-S manual (000) as a vector: the printed request
// fields (command code, parameter counter, index, sub-index, length, data bytes) against what
// the codecs produce from the example's value. L… = line in 000_b4c1e0d4025b123d.txt.
// Where the manual prints wrong bytes the test asserts the right ones (docs/errata.md, CX-…).
#include <fieldcodec/compax/control.hpp>
#include <fieldcodec/compax/identification.hpp>
#include <fieldcodec/compax/pcp.hpp>
#include <fieldcodec/compax/position.hpp>
#include <fieldcodec/compax/process_data.hpp>
#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/decimal.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string_view>
#include <vector>

namespace cx = fieldcodec::compax;
using fieldcodec::decimal;
using fieldcodec::errc;
using bytes = std::vector<std::uint8_t>;

namespace {

template <std::size_t N>
bytes v(const std::array<std::uint8_t, N> &a) {
  return bytes(a.begin(), a.end());
}
template <class T>
bytes be(T value) {
  return v(cx::encode_integer<T>(value).value());
}
bytes text(std::string_view s, std::size_t n) {
  bytes out(n);
  REQUIRE(cx::encode_visible_string(s, out).has_value());
  return out;
}

struct printed {
  int line;
  std::uint16_t service; // printed command code
  std::uint16_t counter; // printed param counter
  std::uint16_t index;
  std::uint8_t sub;
  int length; // printed length, -1 where a read prints none
  bytes data; // printed data bytes (empty for a read)
};

// A write example the manual prints correctly: our bytes = printed bytes, and the request we
// build has the printed counter and length.
void check_write(const printed &p, const bytes &ours) {
  CAPTURE(p.line);
  CHECK(ours == p.data);
  auto r = cx::pcp_write(p.index, p.sub, ours);
  REQUIRE(r.has_value());
  CHECK(static_cast<std::uint16_t>(r.value().service) == p.service);
  CHECK(r.value().param_counter == p.counter);
  CHECK(static_cast<int>(r.value().length) == p.length);
  CHECK(cx::check_pcp_request(r.value()).has_value());
  std::array<std::uint8_t, 80> wire{};
  auto n = cx::encode_pcp_request(r.value(), wire);
  REQUIRE(n.has_value());
  CHECK(n.value() == cx::pcp_request_size(r.value()));
  auto back = cx::decode_pcp_request(std::span<const std::uint8_t>{wire}.first(n.value()));
  REQUIRE(back.has_value());
  CHECK(back.value() == r.value());
}

void check_read(const printed &p) {
  CAPTURE(p.line);
  const auto r = cx::pcp_read(p.index, p.sub).value();
  CHECK(static_cast<std::uint16_t>(r.service) == p.service);
  CHECK(r.param_counter == p.counter);
  if (p.length >= 0) CHECK(static_cast<int>(r.length) == p.length);
  CHECK(cx::check_pcp_request(r).has_value());
}

} // namespace

TEST_CASE("manual 000 PCP read examples") {
  check_read({735, 0x8081, 3, 0x600F, 3, -1, {}});   // 2.3.1 FKT_GRUPPE, 3rd function group
  check_read({1451, 0x8081, 3, 0x5FE8, 23, -1, {}}); // 2.5.8 S, read S23
  check_read({1611, 0x8081, 3, 0x5FDD, 2, 0, {}});   // 2.6.7 S7_S8, DC link voltage
}

TEST_CASE("manual 000 PCP write examples: identification, control, ASCII, Px") {
  // 2.4.1 BETRIEBSART: target position input
  check_write({798, 0x8082, 4, 0x6060, 0, 2, {0x00, 0x01}},
              v(cx::encode_selection(cx::operating_mode::target_position)));
  // 2.4.10 CONTROL: go to machine zero
  check_write({1132, 0x8082, 4, 0x5FE9, 0, 1, {0x01}},
              {static_cast<std::uint8_t>(cx::control_command::go_to_machine_zero)});
  // 2.4.11 COMMAND "POSR15.8"
  check_write({1159, 0x8082, 13, 0x5FE6, 0, 20, text("POSR15.8", 20)}, text("POSR15.8", 20));
  CHECK(text("POSR15.8", 20) == bytes{0x50, 0x4F, 0x53, 0x52, 0x31, 0x35, 0x2E, 0x38, 0x20, 0x20,
                                      0x20, 0x20, 0x20, 0x20, 0x20, 0x20, 0x20, 0x20, 0x20, 0x20});
  // 2.4.12 P: P003=-1055.88
  check_write({1190, 0x8082, 19, 0x5FE7, 3, 32, text("P003=-1055.88", 32)},
              text("P003=-1055.88", 32));
  CHECK(text("P003=-1055.88", 32)[5] == 0x2D);
  // 2.4.13 Px: P11 = 5000, resolution 1 = 0.001 → 5 000 000
  check_write({1226, 0x8082, 5, 0x5FD4, 11, 4, {0x00, 0x4C, 0x4B, 0x40}},
              be<std::int32_t>(5'000'000));
}

TEST_CASE("manual 000 PCP write examples: torque, current, positions") {
  check_write({1478, 0x8082, 4, 0x6072, 0, 2, {0x01, 0x90}}, be<std::uint16_t>(400)); // ‰
  check_write({1504, 0x8082, 4, 0x6076, 0, 2, {0x00, 0x34}}, be<std::uint16_t>(52));  // 5.2 Nm
  check_write({1566, 0x8082, 4, 0x6075, 0, 2, {0x00, 0x33}}, be<std::uint16_t>(51));  // 5.1 A
  check_write({1646, 0x8082, 6, 0x5FF0, 0, 6, {0x00, 0x00, 0x07, 0x35, 0x01, 0x50}},
              v(cx::encode_bcd_position(decimal{7350150, 3}).value())); // POSA +7350.150
  check_write({1681, 0x8082, 6, 0x5FEF, 0, 6, {0xFF, 0x00, 0x37, 0x89, 0x12, 0x10}},
              v(cx::encode_bcd_position(decimal{-3789121, 2}).value())); // POSR −37891.210
  check_write({1725, 0x8082, 5, 0x607A, 0, 4, {0xFF, 0xF0, 0xBD, 0xC0}},
              be<std::int32_t>(-1'000'000)); // LAGE_ZIEL −1000.000 mm
  check_write({1830, 0x8082, 5, 0x607C, 0, 4, {0xFF, 0xF8, 0x5E, 0xE0}},
              be<std::int32_t>(-500'000)); // REALNULL −500.000 mm
  check_write({1892, 0x8082, 5, 0x6067, 0, 4, {0x00, 0x00, 0x3A, 0x98}},
              be<std::uint32_t>(15'000)); // POS_FENSTER 15 mm
  check_write({1921, 0x8082, 5, 0x6065, 0, 4, {0x00, 0x00, 0x27, 0x10}},
              be<std::uint32_t>(10'000)); // SCHLEPP_FEN 10 mm
  check_write({1968, 0x8082, 4, 0x607E, 0, 1, {0x80}}, {cx::encode_polarity(true)}); // CX-27
  check_write({2000, 0x8082, 4, 0x6098, 0, 2, {0x00, 0x08}},
              v(cx::encode_selection(cx::ref_mode::initiator_direction_1)));
  check_write({2051, 0x8082, 5, 0x5FE0, 0, 4, {0x00, 0x03, 0x20, 0xC8}},
              be<std::int32_t>(205'000)); // WAITPOSA 205 mm
}

TEST_CASE("manual 000 errata: GRENZEN, WAITPOSR, comparators, N, PE/PA_SELECT") {
  // CX-20, L1863: GRENZEN sub 1 = −1650.000 mm is FF E6 D2 B0, printed FF E6 D2 0B.
  const bytes grenzen = be<std::int32_t>(-1'650'000);
  CHECK(grenzen == bytes{0xFF, 0xE6, 0xD2, 0xB0});
  CHECK(grenzen != bytes{0xFF, 0xE6, 0xD2, 0x0B});
  // the printed bytes are −1650.165 mm
  CHECK(cx::decode_integer<std::int32_t>(std::array<std::uint8_t, 4>{0xFF, 0xE6, 0xD2, 0x0B})
            .value() == -1'650'165);
  check_write({1863, 0x8082, 5, 0x607D, 1, 4, {0xFF, 0xE6, 0xD2, 0xB0}}, grenzen);

  // CX-21, L2078: WAITPOSR 720.000 mm, printed Length 6; the object is 4 bytes.
  check_write({2078, 0x8082, 5, 0x5FE1, 0, 4, {0x00, 0x0A, 0xFC, 0x80}}, be<std::int32_t>(720'000));

  // CX-22, L2758: POSROUTPUTP sub 11 at 888 mm is 00 0D 8C C0; printed 00 04 65 00 (288 mm).
  check_write({2758, 0x8082, 5, 0x5FE2, 11, 4, {0x00, 0x0D, 0x8C, 0xC0}},
              be<std::int32_t>(888'000));
  CHECK(cx::decode_integer<std::int32_t>(std::array<std::uint8_t, 4>{0x00, 0x04, 0x65, 0x00})
            .value() == 288'000);
  // CX-23, L2791: POSROUTPUTN sub 11 at 1888 mm is 00 1C CF 00; printed 00 13 A7 40 (1288 mm).
  check_write({2791, 0x8082, 5, 0x5FE3, 11, 4, {0x00, 0x1C, 0xCF, 0x00}},
              be<std::int32_t>(1'888'000));
  CHECK(cx::decode_integer<std::int32_t>(std::array<std::uint8_t, 4>{0x00, 0x13, 0xA7, 0x40})
            .value() == 1'288'000);

  // CX-24, L2819: N record 5 "POSA 250", printed Length 20; the object is 32 bytes.
  check_write({2819, 0x8082, 19, 0x5FF1, 5, 32, text("POSA 250", 32)}, text("POSA 250", 32));

  // CX-25, L3741 / L3786: PE_SELECT sub 6 / PA_SELECT sub 4 (Unsigned16 index), printed
  // param counter 5 for 2 data bytes; the rule gives 4.
  CHECK(cx::pd_select_subindex_size(6).value() == 2);
  CHECK(cx::pd_select_subindex_size(4).value() == 2);
  check_write({3741, 0x8082, 4, 0x6000, 6, 2, {0x60, 0x64}}, be<std::uint16_t>(0x6064));
  check_write({3786, 0x8082, 4, 0x6001, 4, 2, {0x60, 0x7A}}, be<std::uint16_t>(0x607A));
  // the printed counters are rejected by the checker
  auto pe = cx::pcp_write(0x6000, 6, be<std::uint16_t>(0x6064)).value();
  pe.param_counter = 5;
  CHECK(cx::check_pcp_request(pe).error() == errc::bad_length);
  auto ws = cx::pcp_write(0x5FE1, 0, be<std::int32_t>(720'000)).value();
  ws.length = 6;
  CHECK(cx::check_pcp_request(ws).error() == errc::bad_length);
}

TEST_CASE("manual 000 PCP write examples: speed, ramps, I/O, programming, process data") {
  check_write({2113, 0x8082, 4, 0x5FEC, 0, 2, {0x12, 0xC0}}, be<std::int16_t>(75 * 64)); // SPEED
  // OVERRIDE 50 % → 0x80 (255 = 100 %, CX-13)
  check_write({2139, 0x8082, 4, 0x5FEE, 0, 1, {0x80}},
              {cx::encode_override(decimal{50, 0}).value()});
  check_write({2168, 0x8082, 5, 0x5FED, 0, 3, {0x03, 0x50, 0x00}},
              v(cx::encode_bcd_speed(35'000).value())); // POSR0SPEED 35 %
  {                                                     // POSRXSPEEDY 580 mm / 33 %
    bytes d = be<std::int32_t>(580'000);
    const bytes s = be<std::uint32_t>(33'000);
    d.insert(d.end(), s.begin(), s.end());
    check_write({2203, 0x8082, 7, 0x5FE4, 0, 8, {0x00, 0x08, 0xD9, 0xA0, 0x00, 0x00, 0x80, 0xE8}},
                d);
  }
  check_write({2266, 0x8082, 4, 0x6080, 0, 2, {0x17, 0x70}}, be<std::uint16_t>(6000));
  check_write({2292, 0x8082, 5, 0x607F, 0, 4, {0x00, 0x01, 0x73, 0x18}}, be<std::uint32_t>(95'000));
  check_write({2325, 0x8082, 5, 0x6081, 0, 4, {0x00, 0x01, 0x01, 0xD0}}, be<std::int32_t>(66'000));
  check_write({2390, 0x8082, 5, 0x6099, 0, 4, {0x00, 0x00, 0x4E, 0x20}}, be<std::uint32_t>(20'000));
  check_write({2420, 0x8082, 4, 0x6086, 0, 2, {0xFF, 0xFF}},
              v(cx::encode_selection(cx::ramp_form::square)));
  check_write({2452, 0x8082, 4, 0x5FEA, 0, 2, {0x03, 0xE8}}, be<std::uint16_t>(1000));
  check_write({2482, 0x8082, 4, 0x5FEB, 0, 2, {0x09, 0xC4}}, be<std::uint16_t>(2500));
  check_write({2514, 0x8082, 5, 0x6083, 0, 4, {0x00, 0x00, 0x01, 0xD6}}, be<std::uint32_t>(470));
  check_write({2547, 0x8082, 5, 0x6084, 0, 4, {0x00, 0x00, 0x05, 0xF5}}, be<std::uint32_t>(1525));
  check_write({2578, 0x8082, 5, 0x6085, 0, 4, {0x00, 0x00, 0x00, 0x7D}}, be<std::uint32_t>(125));
  check_write({2609, 0x8082, 5, 0x609A, 0, 4, {0x00, 0x00, 0x02, 0xDD}}, be<std::uint32_t>(733));
  // OUTPUT sub 13 = TRUE
  check_write({2695, 0x8082, 4, 0x5FF6, 13, 1, {0xFF}}, {cx::encode_boolean(true)});
  { // OUTPUT_MASK: outputs 9..16
    cx::io_word m{};
    for (unsigned n = 9; n <= 16; ++n) REQUIRE(m.set(n).has_value());
    check_write({2726, 0x8082, 4, 0x5FF5, 0, 2, {0xFF, 0x00}}, v(m.bytes()));
  }
  check_write({3135, 0x8082, 4, 0x5FF2, 0, 1, {0x12}}, {18}); // GOTO record 18
  check_write({3161, 0x8082, 4, 0x5FF4, 0, 1, {0x1A}}, {26}); // START_N 26
  check_write({3187, 0x8082, 4, 0x5FE5, 0, 1, {0x32}}, {50}); // START_N_GO 50
  check_write({3213, 0x8082, 4, 0x5FF3, 0, 1, {0x46}}, {70}); // TEACH_N 70
  { // PA_ENABLE: only the 3rd (5th) PA byte
    cx::pa_enable e{};
    e.set(cx::pa_enable_bit::pa_byte_3);
    check_write({3828, 0x8082, 4, 0x6002, 0, 1, {0x04}}, v(e.bytes()));
  }
  check_write({3863, 0x8082, 5, 0x5FD0, 4, 3, {0x5F, 0xF8, 0x00}},
              v(cx::encode_assignment({0x5FF8, 0}))); // PED_INI: INPUT_WORD
  check_write({3898, 0x8082, 5, 0x5FD1, 3, 3, {0x5F, 0xF7, 0x00}},
              v(cx::encode_assignment({0x5FF7, 0}))); // PAD_INI: OUTPUT_WORD
  check_write({3929, 0x8082, 5, 0x5FFD, 0, 3, {0x5F, 0xF8, 0x00}},
              v(cx::encode_assignment({0x5FF8, 0}))); // IN_SELECT
  check_write({3958, 0x8082, 5, 0x5FFE, 0, 3, {0x5F, 0xF7, 0x00}},
              v(cx::encode_assignment({0x5FF7, 0})));                               // OUT_SELECT
  check_write({3996, 0x8082, 4, 0x5FFF, 0, 1, {0xFF}}, {cx::encode_boolean(true)}); // OUT_ENABLE
}

TEST_CASE("manual 000 process-data parameter values (P135..P142, 2.12.1, 2.12.2)") {
  CHECK(cx::assignment_parameter({0x5FC5, 0}) == 6'276'352); // OBJECT_REQ, L3287
  CHECK(cx::assignment_parameter({0x5FC6, 0}) == 6'276'608); // OBJECT_RSP, L3309 (CX-26)
  CHECK(cx::assignment_parameter({0x607A, 0}) == 6'322'688); // LAGE_ZIEL
  CHECK(cx::assignment_parameter({0x5FF7, 0}) == 6'289'152); // OUTPUT_WORD
  CHECK(cx::assignment_parameter({0x6064, 0}) == 6'317'056); // LAGE_IST
  CHECK(cx::assignment_parameter({0x5FF8, 0}) == 6'289'408); // INPUT_WORD
  CHECK(cx::assignment_parameter({0x5FEC, 0}) == 6'286'336); // SPEED
  CHECK(cx::assignment_parameter({0x5FFA, 0}) == 6'289'920); // S3
  CHECK(cx::assignment_parameter({0x5FFC, 0}) == 6'290'432); // S4
  CHECK(cx::assignment_from_parameter(6'322'688).value() == cx::pd_assignment{0x607A, 0});
  CHECK(cx::assignment_from_parameter(16'777'216).error() == errc::out_of_range);

  // PE_SELECT example (2.12.2): INPUT_WORD, S3, S4 on PED 3/5/7 of an 8-byte channel.
  cx::pd_select pe{};
  pe.length = 6;
  pe.slots[0] = {0x5FF8, 0};
  pe.slots[2] = {0x5FFA, 0};
  pe.slots[4] = {0x5FFC, 0};
  const auto rec = cx::encode_pd_select(pe);
  CHECK(rec[0] == 6);
  CHECK(rec[1] == 0x5F);
  CHECK(rec[2] == 0xF8);
  CHECK(rec[7] == 0x5F);
  CHECK(rec[8] == 0xFA);
  CHECK(rec[13] == 0x5F);
  CHECK(rec[14] == 0xFC);
  CHECK(cx::decode_pd_select(rec).value() == pe);
  CHECK(cx::decode_pd_select(std::span<const std::uint8_t>{rec}.first(18)).error() ==
        errc::truncated);
  CHECK(cx::pd_select_subindex_size(0).value() == 19);
  CHECK(cx::pd_select_subindex_size(1).value() == 1);
  CHECK(cx::pd_select_subindex_size(13).value() == 1);
  CHECK(cx::pd_select_subindex_size(14).error() == errc::unknown_object);
}

TEST_CASE("PCP request: index and sub-index of any integer type, checked") {
  CHECK(cx::pcp_read(0x5FE8, 300).error() == errc::out_of_range); // not sub-index 44
  CHECK(cx::pcp_read(0x15FE8, 1).error() == errc::out_of_range);  // not index 0x5FE8
  CHECK(cx::pcp_read(-1, 1).error() == errc::out_of_range);
  CHECK(cx::pcp_read(std::uint64_t{0x5FE8}, 23L).value().sub == 23);
  const std::array<std::uint8_t, 1> one{0x01};
  CHECK(cx::pcp_write(0x5FE9, 256, one).error() == errc::out_of_range);
  CHECK(cx::pcp_write(0x5FE9U, std::int8_t{0}, one).value().index == 0x5FE9);
}

TEST_CASE("PCP request bad input") {
  CHECK(cx::pcp_write(0x5FE6, 0, std::span<const std::uint8_t>{}).error() == errc::bad_length);
  const std::array<std::uint8_t, 33> big{};
  CHECK(cx::pcp_write(0x5FE6, 0, big).error() == errc::bad_length);
  auto r = cx::pcp_read(0x5FE8, 1).value();
  r.service = static_cast<cx::pcp_service>(0x8083);
  CHECK(cx::check_pcp_request(r).error() == errc::unknown_command);
  r = cx::pcp_read(0x5FE8, 1).value();
  r.length = 2;
  CHECK(cx::check_pcp_request(r).error() == errc::bad_length);
  std::array<std::uint8_t, 4> small{};
  CHECK(cx::encode_pcp_request(cx::pcp_read(0x5FE8, 1).value(), small).error() ==
        errc::buffer_too_small);
  // wire: read request is 10 bytes; one byte less is truncated, one more is left over
  std::array<std::uint8_t, 11> wire{};
  REQUIRE(cx::encode_pcp_request(cx::pcp_read(0x5FE8, 23).value(), wire).value() == 10);
  CHECK(wire[0] == 0x80);
  CHECK(wire[1] == 0x81);
  CHECK(wire[3] == 3);
  CHECK(wire[6] == 0x5F);
  CHECK(wire[7] == 0xE8);
  CHECK(wire[8] == 23);
  CHECK(cx::decode_pcp_request(std::span<const std::uint8_t>{wire}.first(9)).error() ==
        errc::truncated);
  CHECK(cx::decode_pcp_request(wire).error() == errc::bad_length);
}

// Issue 12: the pad byte after odd-length data must be 0x00, like every other padding of the
// module that a decoder checks.
TEST_CASE("PCP request: non-zero pad byte after odd-length data") {
  const std::array<std::uint8_t, 1> one{0x01};
  auto r = cx::pcp_write(0x5FE9, 0, one);
  REQUIRE(r.has_value());
  std::array<std::uint8_t, 12> wire{};
  REQUIRE(cx::encode_pcp_request(r.value(), wire).value() == 12);
  CHECK(wire[10] == 0x01);
  CHECK(wire[11] == 0x00);
  CHECK(cx::decode_pcp_request(wire).value() == r.value());
  wire[11] = 0x20;
  CHECK(cx::decode_pcp_request(wire).error() == errc::unexpected_frame);
}
