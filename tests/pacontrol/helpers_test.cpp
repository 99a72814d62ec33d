// The helpers a PA-CONTROL master needs besides frames, each checked against the manual's own
// tables and worked examples (manual 001; every printed example below was recomputed by hand):
// axis parameter addresses (5.2.3), element numbers ↔ words and bits (5.2.4, 6.3), the axis
// states of 1910 / 1911 / 1921 (5.2.4.22, 5.2.4.23, 5.2.4.28), 0AA3's packed date (5.2.6.23),
// value equality by number, and the "either check rule" option for acknowledgements (3.4.3).
#include <fieldcodec/pacontrol/axis_motion.hpp>
#include <fieldcodec/pacontrol/axis_parameter.hpp>
#include <fieldcodec/pacontrol/command.hpp>
#include <fieldcodec/pacontrol/elements.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>
#include <fieldcodec/pacontrol/value.hpp>

#include "pac_test_util.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <limits>

namespace fc = fieldcodec;
namespace pac = fc::pacontrol;
using fc::decimal;
using fc::errc;
using pac::axis_motion;
using pac::element_type;

namespace {

// --- Axis parameters (5.2.3). The four examples of 5.2.3 - 5.2.3.3:
//   0800 acceleration of axis 3:           0306 hex = 774 dec
//   1800 shaft encoder inverted on axis 2: 021F hex = 543 dec (parameter 31 = 1F hex)
//   1801 max. traverse speed of axis 3:    0301 hex = 769 dec
//   1802 min. acceleration of axis 4:      0406 hex = 1030 dec
static_assert(pac::encode_axis_parameter({3, 6}).value() == 0x0306);
static_assert(pac::encode_axis_parameter({3, 6}).value() == 774);
static_assert(pac::encode_axis_parameter({2, 31}).value() == 543);
static_assert(pac::encode_axis_parameter({3, 1}).value() == 769);
static_assert(pac::encode_axis_parameter({4, 6}).value() == 1030);
static_assert(pac::decode_axis_parameter(774).value() == pac::axis_parameter{3, 6});
static_assert(pac::decode_axis_parameter(0x021F).value() == pac::axis_parameter{2, 31});
static_assert(pac::decode_axis_parameter(769U).value() == pac::axis_parameter{3, 1});
static_assert(pac::decode_axis_parameter(std::int64_t{1030}).value() == pac::axis_parameter{4, 6});
// Limits: axis 1-16 (10 hex = axis 16), parameter 1-50 (32 hex = enable mode).
static_assert(pac::encode_axis_parameter({16, 50}).value() == 0x1032);
static_assert(pac::encode_axis_parameter({1, 1}).value() == 0x0101);
static_assert(pac::encode_axis_parameter({0, 1}).error() == errc::out_of_range);
static_assert(pac::encode_axis_parameter({17, 1}).error() == errc::out_of_range);
static_assert(pac::encode_axis_parameter({1, 0}).error() == errc::out_of_range);
static_assert(pac::encode_axis_parameter({1, 51}).error() == errc::out_of_range);
static_assert(pac::decode_axis_parameter(0x10FF).error() == errc::out_of_range); // printed max
static_assert(pac::decode_axis_parameter(0x0133).error() == errc::out_of_range);
static_assert(pac::decode_axis_parameter(65536).error() == errc::overflow);
static_assert(pac::decode_axis_parameter(-1).error() == errc::overflow);
static_assert(pac::make_axis_parameter(3, 6).value() == pac::axis_parameter{3, 6});
static_assert(pac::make_axis_parameter(3L, 256).error() == errc::out_of_range); // no wrap to 0
static_assert(pac::make_axis_parameter(259, 6).error() == errc::out_of_range);  // no wrap to 3

// --- Elements and words (6.3 flag word table; the same numbering for input and output words,
// 5.2.4.2, 5.2.4.5). Word k holds elements 16k-15 … 16k, bit 0 the lowest.
static_assert(pac::locate_element(1).value() == pac::element_bit{1, 0});     // FW1 bit 0 = M1
static_assert(pac::locate_element(16).value() == pac::element_bit{1, 15});   // FW1 bit 15 = M16
static_assert(pac::locate_element(17).value() == pac::element_bit{2, 0});    // FW2 bit 0 = M17
static_assert(pac::locate_element(128).value() == pac::element_bit{8, 15});  // FW8 bit 15
static_assert(pac::locate_element(129).value() == pac::element_bit{9, 0});   // part 2, FW9
static_assert(pac::locate_element(256).value() == pac::element_bit{16, 15}); // FW16 bit 15
static_assert(pac::locate_element(337).value() == pac::element_bit{22, 0});  // FW22 bit 0
// FW22 bits 15 and 14 are printed M252 / M251; they are M352 / M351 (errata "Other examples
// and tables").
static_assert(pac::locate_element(352).value() == pac::element_bit{22, 15});
static_assert(pac::locate_element(351).value() == pac::element_bit{22, 14});
static_assert(pac::element_number(22, 15).value() == 352);
static_assert(pac::locate_element(252).value() == pac::element_bit{16, 11}); // not in FW22
static_assert(pac::locate_element(385).value() == pac::element_bit{25, 0});  // part 4, FW25
static_assert(pac::locate_element(497).value() == pac::element_bit{32, 0});  // FW32 bit 0
static_assert(pac::locate_element(512).value() == pac::element_bit{32, 15}); // FW32 bit 15
static_assert(pac::locate_element(1024).value() == pac::element_bit{64, 15});
static_assert(pac::locate_element(0).error() == errc::out_of_range);
static_assert(pac::locate_element(1025).error() == errc::out_of_range);
static_assert(pac::locate_element(-1).error() == errc::out_of_range);
static_assert(pac::element_number(1, 0).value() == 1);
static_assert(pac::element_number(9, 0).value() == 129);
static_assert(pac::element_number(64, 15).value() == 1024);
static_assert(pac::element_number(0, 0).error() == errc::out_of_range);
static_assert(pac::element_number(65, 0).error() == errc::out_of_range);
static_assert(pac::element_number(1, 16).error() == errc::out_of_range);

/// The word a 5.2.4 example writes: the listed elements set, all others clear.
template <std::size_t N>
constexpr std::uint16_t word_of(int addressed_by, const int (&elements)[N]) {
  auto w = pac::element_word::containing(addressed_by).value();
  for (const int e : elements) {
    if (!w.set(e)) return 0xDEAD;
  }
  return w.bits;
}

// 0903 (5.2.4.5): outputs 17, 21 and 26 to 30 set, output 25 selects word 2 → 3E11 hex = 15889.
constexpr int outputs_0903[] = {17, 21, 26, 27, 28, 29, 30};
static_assert(word_of(25, outputs_0903) == 0x3E11);
static_assert(word_of(25, outputs_0903) == 15889);
static_assert(pac::element_word::containing(25).value().word == 2);
static_assert(pac::element_word::containing(25).value().first() == 17);
// 0905 (5.2.4.9): flags 18, 21-25, 27 and 31 of flag word 2, addressed by M17 → 45F2 = 17906.
constexpr int flags_0905[] = {18, 21, 22, 23, 24, 25, 27, 31};
static_assert(word_of(17, flags_0905) == 0x45F2);
static_assert(word_of(17, flags_0905) == 17906);
// An element of another word is refused, not folded into this one.
constexpr int wrong_word[] = {17, 33};
static_assert(word_of(17, wrong_word) == 0xDEAD);

/// True when exactly `set` of the word's 16 elements are 1.
template <std::size_t N>
constexpr bool only(const pac::element_word &w, const int (&set)[N]) {
  for (int e = w.first(); e < w.first() + 16; ++e) {
    bool want = false;
    for (const int s : set) want = want || s == e;
    if (w.test(e).value() != want) return false;
  }
  return true;
}

// 1901 (5.2.4.2): input word 1 (addressed by I10) reads 8D03 hex = 36099: inputs 1, 2, 9, 11,
// 12 and 16 are 1. The reply is an int32 date.
constexpr int inputs_1901[] = {1, 2, 9, 11, 12, 16};
static_assert(only(pac::element_word::containing(10, std::int32_t{36099}).value(), inputs_1901));
static_assert(0x8D03 == 36099);
// 1903 (5.2.4.6): output word 3 (addressed by O33) reads 5555 hex = 21845: outputs 33, 35, …,
// 47. (The result text says "input word 3"; the command reads outputs.)
constexpr int outputs_1903[] = {33, 35, 37, 39, 41, 43, 45, 47};
static_assert(only(pac::element_word::containing(33, 21845).value(), outputs_1903));
// 1905 (5.2.4.10): flag word 3 (addressed by M33) reads 0F0F hex = 3855: flags 33-36 and 41-44.
constexpr int flags_1905[] = {33, 34, 35, 36, 41, 42, 43, 44};
static_assert(only(pac::element_word::containing(33, 3855).value(), flags_1905));
static_assert(pac::element_word::containing(33, 3855).value().test(32).error() ==
              errc::out_of_range);
static_assert(pac::element_word::containing(33, 65536).error() == errc::overflow);
static_assert(pac::element_word::containing(33, -1).error() == errc::overflow);
static_assert(pac::element_word::containing(1025).error() == errc::out_of_range);

// --- 1910 axis status (5.2.4.22): 0 in position, 1 moving, 2 stopped, 4 stopped with fault,
// 8 measuring mode. Its example reads 0002 for axis 4: stopped.
static_assert(pac::decode_axis_motion(2).value() == axis_motion::stopped);
static_assert(pac::decode_axis_motion(0).value() == axis_motion::in_position);
static_assert(pac::decode_axis_motion(1).value() == axis_motion::moving);
static_assert(pac::decode_axis_motion(4).value() == axis_motion::stopped_with_fault);
static_assert(pac::decode_axis_motion(8U).value() == axis_motion::measuring_mode);
static_assert(pac::decode_axis_motion(3).error() == errc::unknown_object);
static_assert(pac::decode_axis_motion(16).error() == errc::unknown_object);
static_assert(pac::decode_axis_motion(-1).error() == errc::unknown_object);
static_assert(pac::decode_axis_motion(256 + 2).error() == errc::unknown_object); // no wrap
static_assert(pac::name(axis_motion::stopped) == "stopped");

// --- 1911 (5.2.4.23): 0000 00D0 hex = 208: axes 5, 7 and 8 running, 1-4 and 6 in position.
static_assert(pac::axis_moving(208, 5).value() && pac::axis_moving(208, 7).value() &&
              pac::axis_moving(208, 8).value());
static_assert(!pac::axis_moving(208, 1).value() && !pac::axis_moving(208, 2).value() &&
              !pac::axis_moving(208, 3).value() && !pac::axis_moving(208, 4).value() &&
              !pac::axis_moving(208, 6).value());
static_assert(pac::axis_moving(0x8000, 16).value());
static_assert(pac::axis_moving(208, 0).error() == errc::out_of_range);
static_assert(pac::axis_moving(208, 17).error() == errc::out_of_range);
static_assert(pac::axis_moving(65536, 1).error() == errc::overflow);

// --- 1921 (5.2.4.28): axis 8 reads 0100 0104 hex = 16777476: power pack ready, positive limit
// switch reached (byte 1 = 0: actuated), negative not, axis still with malfunction.
constexpr pac::extended_axis_status axis8{true, true, false, axis_motion::stopped_with_fault};
static_assert(0x01000104 == 16777476);
static_assert(pac::decode_extended_axis_status(16777476).value() == axis8);
static_assert(pac::encode_extended_axis_status(axis8) == 0x01000104U);
static_assert(pac::decode_extended_axis_status(0x00010100).value() ==
              pac::extended_axis_status{false, false, false, axis_motion::in_position});
static_assert(pac::decode_extended_axis_status(0x01000008).value() ==
              pac::extended_axis_status{true, true, true, axis_motion::measuring_mode});
static_assert(pac::decode_extended_axis_status(0x02000104).error() == errc::out_of_range);
static_assert(pac::decode_extended_axis_status(0x01020104).error() == errc::out_of_range);
static_assert(pac::decode_extended_axis_status(0x01000204).error() == errc::out_of_range);
static_assert(pac::decode_extended_axis_status(0x01000103).error() == errc::unknown_object);
static_assert(pac::decode_extended_axis_status(-1).error() == errc::overflow);
static_assert(pac::decode_extended_axis_status(std::int64_t{1} << 32).error() == errc::overflow);

// --- 0AA3 (5.2.6.23): state in bits 31-24, element type (1 input, 2 output, 3 flag) in bits
// 23-16, element number in bits 15-0. The manual gives no example; these follow its layout.
static_assert(pac::encode_element_condition({true, element_type::flag, 11}).value() == 0x0103000BU);
static_assert(pac::encode_element_condition({false, element_type::input, 1024}).value() ==
              0x00010400U);
static_assert(pac::encode_element_condition({true, element_type::output, 243}).value() ==
              0x010200F3U);
static_assert(pac::decode_element_condition(0x0103000B).value() ==
              pac::element_condition{true, element_type::flag, 11});
static_assert(pac::decode_element_condition(0x00010400).value() ==
              pac::element_condition{false, element_type::input, 1024});
static_assert(pac::encode_element_condition({true, element_type::flag, 0}).error() ==
              errc::out_of_range);
static_assert(pac::encode_element_condition({true, element_type::flag, 1025}).error() ==
              errc::out_of_range);
static_assert(pac::encode_element_condition({true, static_cast<element_type>(4), 1}).error() ==
              errc::invalid_argument);
static_assert(pac::decode_element_condition(0x0203000B).error() == errc::out_of_range); // state
static_assert(pac::decode_element_condition(0x0104000B).error() == errc::out_of_range); // type 4
static_assert(pac::decode_element_condition(0x0100000B).error() == errc::out_of_range); // type 0
static_assert(pac::decode_element_condition(0x01030000).error() == errc::out_of_range); // no. 0
static_assert(pac::decode_element_condition(0x01030401).error() == errc::out_of_range); // 1025
static_assert(pac::decode_element_condition(-1).error() == errc::overflow);

// --- value == compares numbers; same_text compares the digits a frame carries (3.4.3: the
// master sends 5552.0, the PA-CONTROL answers 5552.000).
constexpr auto sent = pac::value::of_real(decimal{55520, 1}).value();
constexpr auto answered = pac::value::of_real(decimal{5552000, 3}).value();
static_assert(sent == answered);
static_assert(!sent.same_text(answered));
static_assert(sent.same_text(pac::value::of_float(5552.0F).value()));
static_assert(answered.same_text(pac::value::of_float(5552.0F, pac::float_style::device).value()));
static_assert(sent != pac::value::of_real(decimal{55521, 1}).value());
static_assert(pac::value::of_int(5552).value() != sent); // TYP differs: a different date
static_assert(pac::value::of_int(std::int64_t{1} << 31).error() == errc::overflow);
static_assert(pac::value::of_int(-2147483648LL).value().as_int().value() == -2147483648LL);

} // namespace

TEST_CASE("pacontrol helpers: axis parameter requests (5.2.3 examples)") {
  namespace serial = pac::serial;
  const fc::od::command set_axis_parameter{.code = 0x0800,
                                           .parameter_min = fc::od::signed_number(0x0101),
                                           .parameter_max = fc::od::signed_number(0x1032),
                                           .parameter_packing = fc::od::packing::byte_byte,
                                           .date_type = fc::od::command_value::real,
                                           .reply_type = fc::od::command_value::real};
  // RS232: "0800;774;1;200.0" (the manual writes the date as 200.00; the master's shortest
  // float text is 200.0, both the same float 4348 0000).
  auto r = pac::make_request(set_axis_parameter, pac::axis_parameter{3, 6}, 200.0F);
  REQUIRE(r);
  CHECK(r->parameter == 774);
  std::array<std::uint8_t, serial::max_frame_size> buf{};
  auto n = serial::encode_request(r.value(), buf);
  REQUIRE(n);
  CHECK(pactest::frame("0800;774;1;200.0", "26") == std::span<const std::uint8_t>(buf).first(*n));
  CHECK(pac::cmd_date(r->date).value() == 0x43480000U);
  CHECK(pac::decode_axis_parameter(r->parameter).value() == pac::axis_parameter{3, 6});
}

TEST_CASE("pacontrol helpers: 0AA3 with an element condition") {
  const fc::od::command condition_move{.code = 0x0AA3,
                                       .parameter_min = fc::od::signed_number(0),
                                       .parameter_max = fc::od::signed_number(16),
                                       .date_type = fc::od::command_value::integer,
                                       .date_min = fc::od::unsigned_number(0x00010001),
                                       .date_max = fc::od::unsigned_number(0x01030400),
                                       .date_packing = fc::od::packing::byte_byte_word};
  auto r =
      pac::make_request(condition_move, 2, pac::element_condition{true, element_type::flag, 11});
  REQUIRE(r);
  CHECK(r->date.as_int().value() == 0x0103000B);
  std::array<std::uint8_t, pac::serial::max_frame_size> buf{};
  auto n = pac::serial::encode_request(r.value(), buf);
  REQUIRE(n);
  CHECK(pactest::frame("0AA3;2;0;16973835", "62") == std::span<const std::uint8_t>(buf).first(*n));
  // The same date as a plain integer is checked field by field against the table.
  CHECK(pac::make_request(condition_move, 2, 0x0103000B).value() == r.value());
  CHECK(pac::make_request(condition_move, 2, 0x0104000B).error() == errc::out_of_range);
  CHECK(pac::make_request(condition_move, 2, 0x0203000B).error() == errc::out_of_range);
  CHECK(pac::make_request(condition_move, 2, 0x01030401).error() == errc::out_of_range);
  CHECK(pac::make_request(condition_move, 2, -1).error() == errc::overflow);
  // A condition for a command whose date is not one.
  const fc::od::command put_int_reg{.code = 0x0906, .date_type = fc::od::command_value::integer};
  CHECK(pac::make_request(put_int_reg, 1, pac::element_condition{}).error() == errc::type_mismatch);
}

TEST_CASE("pacontrol helpers: acknowledgements under either check rule (3.4.3)") {
  namespace serial = pac::serial;
  // 3.4.3 command 1's acknowledgement is printed with CHECK 8, the request rule (errata serial
  // frame 5); every other acknowledgement uses body_and_etx (here 11).
  const auto printed = pactest::hex("01 02 30 3B 31 3B 33 31 3B 30 3B 30 3B 30 03 38 04");
  const auto by_rule = pactest::hex("01 02 30 3B 31 3B 33 31 3B 30 3B 30 3B 30 03 31 31 04");
  const auto neither = pactest::hex("01 02 30 3B 31 3B 33 31 3B 30 3B 30 3B 30 03 39 04");
  serial::decoder_options strict{};
  strict.frames = serial::accept::acknowledgements;
  serial::decoder_options lenient = strict;
  lenient.check.acknowledgement_either_rule = true;
  CHECK(serial::decode_frame(printed.span(), strict).error() == errc::bad_checksum);
  CHECK(serial::decode_frame(by_rule.span(), strict));
  auto a = serial::decode_frame(printed.span(), lenient);
  REQUIRE(a);
  CHECK(a->ack.operating_status == 31);
  CHECK(serial::decode_frame(by_rule.span(), lenient));
  CHECK(serial::decode_frame(neither.span(), lenient).error() == errc::bad_checksum);
  // Requests keep their own rule unless they too are allowed either.
  const auto request_by_ack_rule = pactest::frame("1900;5;0;0", "5"); // 6 ^ 3
  serial::decoder_options device{};
  device.frames = serial::accept::requests;
  device.check.acknowledgement_either_rule = true;
  CHECK(serial::decode_frame(request_by_ack_rule.span(), device).error() == errc::bad_checksum);
  device.check.request_either_rule = true;
  CHECK(serial::decode_frame(request_by_ack_rule.span(), device));
  CHECK(serial::other_rule(serial::check_rule::body) == serial::check_rule::body_and_etx);
  CHECK(serial::other_rule(serial::check_rule::body_and_etx) == serial::check_rule::body);
}
