// The C++ blocks of docs/cookbook.md, as written there, and the results their comments state
// (static_asserts in the blocks; doctest cases below for what runs). tests/docs_check/run.cmake
// fails when a block of the page and its copy here differ. Each block sits in a namespace of
// its own (the page's blocks are complete programs; here they share one translation unit).
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_object.hpp>
#include <fieldcodec/compax/control.hpp>
#include <fieldcodec/compax/drivecom.hpp>
#include <fieldcodec/compax/faults.hpp>
#include <fieldcodec/compax/nx.hpp>
#include <fieldcodec/compax/nx_text.hpp>
#include <fieldcodec/compax/object_channel.hpp>
#include <fieldcodec/compax/objects.hpp>
#include <fieldcodec/compax/pcp.hpp>
#include <fieldcodec/compax/position.hpp>
#include <fieldcodec/compax/set_point.hpp>
#include <fieldcodec/dictionaries/compax_objects.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/dpq/emergency.hpp>
#include <fieldcodec/dpq/parameter.hpp>
#include <fieldcodec/dpq/sdo.hpp>
#include <fieldcodec/dpq/sdo_abort.hpp>
#include <fieldcodec/ds402/modes.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/ds402/statusword.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/pacontrol/axis_parameter.hpp>
#include <fieldcodec/pacontrol/codes.hpp>
#include <fieldcodec/pacontrol/command.hpp>
#include <fieldcodec/pacontrol/elements.hpp>
#include <fieldcodec/pacontrol/position.hpp>
#include <fieldcodec/pacontrol/profibus_cmd.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>
#include <fieldcodec/xenax/bus.hpp>
#include <fieldcodec/xenax/error_code.hpp>
#include <fieldcodec/xenax/homing.hpp>
#include <fieldcodec/xenax/modes.hpp>
#include <fieldcodec/xenax/units.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <doctest/doctest.h>

// clang-format off
namespace cb_dpq_1 { // "Read the identity (1018h) over SDO"
namespace co = fieldcodec::canopen;
namespace od = fieldcodec::od;

constexpr od::entry vendor_id{.index = 0x1018,
                              .sub = 1,
                              .object = od::object_code::record,
                              .type = od::data_type::unsigned32,
                              .access_type = od::access::ro};

// the request: 605: 40 18 10 01 00 00 00 00
constexpr co::can_frame request = co::sdo::upload(5, vendor_id).value();
static_assert(request == co::can_frame{0x605, false, 8, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0}});

// the answer 585: 43 18 10 01 2D 01 00 00 is from node 5 and says vendor-ID 0x0000012D
constexpr co::can_frame answer{0x585, false, 8, {0x43, 0x18, 0x10, 0x01, 0x2D, 0x01, 0, 0}};
static_assert(co::sdo::channel::default_for(5).value().is_response(answer));
static_assert(co::sdo::upload_value(vendor_id, answer).value().to_uint64().value() == 0x12D);
} // namespace cb_dpq_1

namespace cb_dpq_2 { // "Write a pressure in bar and read it back"
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;
using fieldcodec::canopen::can_frame;

// Inj. P Limit 1 := 4.0 bar (scale 327.67 → raw 1311): 605: 23 23 20 00 1F 05 00 00
constexpr auto write = dpq::write_request(5, p::inj_p_limit_1, 4.0);
static_assert(write.value() ==
              can_frame{0x605, false, 8, {0x23, 0x23, 0x20, 0x00, 0x1F, 0x05, 0, 0}});
// the card confirms: 585: 60 23 20 00 00 00 00 00
static_assert(dpq::write_response(5, p::inj_p_limit_1,
                                  can_frame{0x585, false, 8, {0x60, 0x23, 0x20, 0x00, 0, 0, 0, 0}})
                  .has_value());

// read it back: 605: 40 23 20 00 …, answer 585: 43 23 20 00 1F 05 00 00 → 4.001 bar
static_assert(dpq::read_request(5, p::inj_p_limit_1).value().data[0] == 0x40);
constexpr auto bar = dpq::read_response(
    5, p::inj_p_limit_1, can_frame{0x585, false, 8, {0x43, 0x23, 0x20, 0x00, 0x1F, 0x05, 0, 0}});
static_assert(bar.value().mantissa == 4001 && bar.value().places == 3);
} // namespace cb_dpq_2

namespace cb_dpq_3 { // "Write a velocity in mm/s from a PLC REAL"
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;
using fieldcodec::errc;

// Analog Vel Max (mm/s, 0…5000, scale 327.67): 90.73 mm/s → raw 29729 = 0x7421
static_assert(p::analog_vel_max.to_raw(90.73F).value() == 29729);
constexpr auto frame = dpq::write_request(5, p::analog_vel_max, 90.73F).value();
static_assert(frame.data[0] == 0x23 && frame.data[4] == 0x21 && frame.data[5] == 0x74);

// 5000.5 mm/s is above the printed maximum; −1 mm/s below the minimum
static_assert(dpq::write_request(5, p::analog_vel_max, 5000.5).is(errc::out_of_range));
static_assert(dpq::write_request(5, p::analog_vel_max, -1).is(errc::out_of_range));
} // namespace cb_dpq_3

namespace cb_dpq_4 { // "Read an actual value (signed, in mm)"
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;
using fieldcodec::canopen::can_frame;
using fieldcodec::errc;

// Position Error : (2F09h, INTEGER32, 327.67 per mm) answered 585: 43 09 2F 00 FF FF FF FF
constexpr can_frame answer{0x585, false, 8, {0x43, 0x09, 0x2F, 0x00, 0xFF, 0xFF, 0xFF, 0xFF}};
static_assert(dpq::read_raw_response(5, p::position_error, answer).value() == -1);
constexpr auto mm = dpq::read_response(5, p::position_error, answer).value(); // exact: −0.003
static_assert(mm.mantissa == -3 && mm.places == 3);
static_assert(p::position_error.to_eu(-1) < -0.00305 && p::position_error.to_eu(-1) > -0.00306);

// it is an actual value: writing it is refused before a frame is built
static_assert(dpq::write_request(5, p::position_error, 0.0).is(errc::access_denied));
} // namespace cb_dpq_4

namespace cb_dpq_5 { // "Decode an emergency and print its text"
namespace co = fieldcodec::canopen;
namespace dpq = fieldcodec::dpq;

// 085: 02 83 01 00 00 00 00 00 → "node 5: 8302 pressure monitor tripped [generic error]"
std::string emcy_text(const co::can_frame &f) {
  auto e = co::emcy::decode(f);
  if (!e) return std::string(fieldcodec::to_string(e.error())); // not an EMCY, or DLC ≠ 8
  const co::emcy::message &m = e.value().m;
  char head[24];
  std::snprintf(head, sizeof head, "node %u: %04X ", unsigned{e.value().node},
                unsigned{m.error_code});
  std::string text = head;
  const std::string_view what = dpq::describe_emcy(m.error_code);
  text += what.empty() ? std::string_view{"not listed by the DPQ manual"} : what;
  std::array<std::string_view, 8> bits{};
  const std::size_t n = dpq::error_register::describe(m.error_register, bits);
  for (std::size_t i = 0; i < n; ++i) (text += i == 0 ? " [" : ", ") += bits[i];
  if (n > 0) text += ']';
  return text;
}
} // namespace cb_dpq_5

namespace cb_dpq_6 { // "Read the error history (1003h)"
namespace co = fieldcodec::canopen;
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;
using fieldcodec::errc;

// 605: 40 03 10 00 → 585: 4F 03 10 00 02 …: two errors recorded
constexpr auto count_request = dpq::read_request(5, p::error_history_sub0).value();
static_assert(count_request.data[0] == 0x40 && count_request.data[1] == 0x03);
constexpr co::can_frame count_answer{0x585, false, 8, {0x4F, 0x03, 0x10, 0x00, 0x02}};
static_assert(dpq::read_raw_response(5, p::error_history_sub0, count_answer).value() == 2);

// 605: 40 03 10 01 → 585: 43 03 10 01 00 34 00 00: the newest error, code 3400h
constexpr co::can_frame newest_answer{0x585, false, 8, {0x43, 0x03, 0x10, 0x01, 0x00, 0x34}};
constexpr auto newest = dpq::decode_error_field(
    static_cast<std::uint32_t>(dpq::read_raw_response(5, p::error_code_1, newest_answer).value()));
static_assert(newest.code == 0x3400 && newest.info == 0); // no manufacturer-specific part
static_assert(newest.text() == "current input: cable break");

// writing 0 to sub 0 clears the history: 605: 2F 03 10 00 00 00 00 00
static_assert(dpq::write_request(5, p::error_history_sub0, 0).value().data[0] == 0x2F);
static_assert(dpq::write_request(5, p::error_history_sub0, 5).is(errc::out_of_range));
static_assert(dpq::write_request(5, p::error_code_1, 0).is(errc::access_denied));
} // namespace cb_dpq_6

namespace cb_dpq_7 { // "Understand an SDO abort from the card"
namespace co = fieldcodec::canopen;
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;
using fieldcodec::errc;

// the card refused the write of Inj. P Limit 1: 585: 80 23 20 00 31 00 09 06
constexpr co::can_frame refused{0x585, false, 8, {0x80, 0x23, 0x20, 0x00, 0x31, 0x00, 0x09, 0x06}};
static_assert(dpq::write_response(5, p::inj_p_limit_1, refused).is(errc::aborted));

constexpr auto why = dpq::write_response(5, p::inj_p_limit_1, refused).error();
static_assert(why.abort == co::sdo::abort_code::value_too_high); // 0609 0031h, kept
static_assert(why.address == fieldcodec::od::address{0x2023, 0x00});
static_assert(why.text() == "value too high (download only)"); // CiA 301, canopen/sdo.hpp
static_assert(why.cause() == errc::out_of_range);
static_assert(dpq::describe_sdo_abort(why.abort) == "value too large"); // the DPQ's wording
} // namespace cb_dpq_7

namespace cb_dpq_8 { // "Configure the TPDO1 event timer and start the card"
namespace co = fieldcodec::canopen;
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;
using fieldcodec::errc;

// 605: 2B 00 18 05 64 00 00 00, confirmed by 585: 60 00 18 05 …
constexpr auto timer = dpq::write_request(5, p::tx_pdo1_event_timer, 100);
static_assert(timer.value() ==
              co::can_frame{0x605, false, 8, {0x2B, 0x00, 0x18, 0x05, 0x64, 0, 0, 0}});
constexpr co::can_frame confirmed{0x585, false, 8, {0x60, 0x00, 0x18, 0x05}};
static_assert(dpq::write_response(5, p::tx_pdo1_event_timer, confirmed).has_value());
// 0…65535 ms: 70 000 ms is refused before a frame exists
static_assert(dpq::write_request(5, p::tx_pdo1_event_timer, 70000).is(errc::out_of_range));

// then start node 5: 000: 01 05
static_assert(co::nmt::encode(co::nmt::command::start, 5).value() ==
              co::can_frame{0x000, false, 2, {0x01, 0x05}});
} // namespace cb_dpq_8

namespace cb_dpq_9 { // "Read the actual values in a TPDO"
namespace co = fieldcodec::canopen;
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;

constexpr auto tpdo1 = co::pdo::make_static_mapping(
    p::dictionary, co::pdo::direction::tpdo, {{0x2F07, 0, 32}, {0x2F11, 0, 32}});

// 185: FF 7F 00 00 FE FF 00 00 → position 100.000 mm, pressure 200.000 bar
constexpr co::can_frame f{0x185, false, 8, {0xFF, 0x7F, 0x00, 0x00, 0xFE, 0xFF, 0x00, 0x00}};
constexpr auto mm = dpq::to_eu_decimal(p::position_fb, tpdo1.get_signed(f.payload(), 0).value());
constexpr auto bar = dpq::to_eu_decimal(p::pressure_fb, tpdo1.get_signed(f.payload(), 1).value());
static_assert(mm.value().mantissa == 100000 && mm.value().places == 3);
static_assert(bar.value().mantissa == 200000 && bar.value().places == 3);
} // namespace cb_dpq_9

namespace cb_pac_1 { // "Send a command over RS232 (with its XOR check)"
namespace pac = fieldcodec::pacontrol;
namespace serial = fieldcodec::pacontrol::serial;
namespace cmds = fieldcodec::dictionaries::pacontrol_commands;

// "read N2" (1906): 01 02 "1906;2;0;0" 03 "7" 04
constexpr auto read_n2 = pac::make_request(cmds::cmd_get_int_reg, 2).value();
constexpr bool sent_as(std::string_view wire) {
  std::array<std::uint8_t, serial::max_frame_size> tx{};
  auto n = serial::encode_request(read_n2, tx);
  return n && std::ranges::equal(std::span(tx).first(n.value()), wire);
}
static_assert(sent_as("\x01\x02" "1906;2;0;0" "\x03" "7" "\x04"));

// the check by hand: '1'^'9'^'0'^'6'^';'^'2'^';'^'0'^';'^'0' = 7
static_assert(serial::compute_check(std::string_view("1906;2;0;0"), serial::check_rule::body) == 7);
} // namespace cb_pac_1

namespace cb_pac_2 { // "Decode the answer byte by byte"
namespace pac = fieldcodec::pacontrol;
namespace serial = fieldcodec::pacontrol::serial;
namespace cmds = fieldcodec::dictionaries::pacontrol_commands;
using fieldcodec::errc;

constexpr fieldcodec::result<serial::acknowledgement> answer(std::string_view line,
                                                             serial::check_options check = {}) {
  serial::decoder rx({check, serial::accept::acknowledgements}); // a master hears answers only
  errc dropped = errc::truncated;
  for (const char c : line) {
    auto r = rx.push(static_cast<std::uint8_t>(c));
    if (!r) {
      dropped = r.error(); // bad_checksum, bad_syntax, …: the decoder waits for the next SOH
    } else if (r.value() == serial::frame_kind::acknowledgement) {
      return rx.acknowledgement();
    }
  }
  return dropped;
}

// 01 02 "0;1;1;0;0;222" 03 "58" 04: QUIT 0 (no error), BE 1 (done), STATUS 1, ERROR 0, N2 = 222
constexpr auto ack = answer("\x01\x02" "0;1;1;0;0;222" "\x03" "58" "\x04").value();
static_assert(ack.command_error_number == 0 && ack.end_of_processing);
static_assert(pac::reply_value(cmds::cmd_get_int_reg, ack).value().as_int().value() == 222);

// one bit flipped on the line: the check finds it
static_assert(answer("\x01\x02" "0;1;1;0;0;223" "\x03" "58" "\x04").error() == errc::bad_checksum);
// a device that checks its answers like requests (XOR without ETX: 57): accept either rule
constexpr serial::check_options lenient{.acknowledgement_either_rule = true};
static_assert(answer("\x01\x02" "0;1;1;0;0;222" "\x03" "57" "\x04").error() == errc::bad_checksum);
static_assert(answer("\x01\x02" "0;1;1;0;0;222" "\x03" "57" "\x04", lenient).has_value());
} // namespace cb_pac_2

namespace cb_pac_3 { // "Move an axis and poll until it arrives"
namespace pac = fieldcodec::pacontrol;
namespace serial = fieldcodec::pacontrol::serial;
namespace cmds = fieldcodec::dictionaries::pacontrol_commands;
using fieldcodec::errc;

// axis 2 to 5552.0: 01 02 "0A87;2;1;5552.0" 03 "95" 04 (21 bytes)
constexpr auto move = pac::make_request(cmds::cmd_pos_axis_absolut, 2, 5552.0F);
static_assert(move.value().code == 0x0A87 && move.value().parameter == 2);
static_assert(pac::make_request(cmds::cmd_pos_axis_absolut, 2, 5552).is(errc::type_mismatch));

constexpr std::size_t frame_length() {
  std::array<std::uint8_t, serial::max_frame_size> tx{};
  return serial::encode_request(move.value(), tx).value_or(0);
}
static_assert(frame_length() == 21);

// the poll is one byte, EOT (04)
constexpr std::uint8_t poll = [] {
  std::array<std::uint8_t, 1> tx{};
  return serial::encode_poll(tx) ? tx[0] : std::uint8_t{0};
}();
static_assert(poll == serial::eot);

// done when BE is 1 and QUIT 0; the position in the date compares as a number (5552.000)
constexpr bool arrived(const serial::acknowledgement &a) {
  return a.end_of_processing && a.command_error_number == 0;
}
constexpr serial::acknowledgement last{0, true, 31, 0, pac::value::of_real({5552000, 3}).value()};
static_assert(arrived(last) && last.date == pac::value::of_float(5552.0F).value());
} // namespace cb_pac_3

namespace cb_pac_4 { // "Say what an error number means"
namespace pac = fieldcodec::pacontrol;
using fieldcodec::errc;

static_assert(pac::describe_command_error(41).value() == "value out of range");
static_assert(pac::describe_command_error(43).value() == "axis not referenced");
static_assert(pac::describe_operating_status(31).value() == "ONLINE");
static_assert(pac::describe_controller_error(529).value() ==
              "positive limit switch reached or cable broken");
static_assert(pac::classify_controller_error(530) == pac::controller_error_class::operation);
static_assert(pac::describe_command_error(42000).is(errc::unknown_object)); // not in the table
} // namespace cb_pac_4

namespace cb_pac_5 { // "Set and read an axis parameter"
namespace pac = fieldcodec::pacontrol;
namespace cmds = fieldcodec::dictionaries::pacontrol_commands;
using fieldcodec::errc;

// axis 3, parameter 6 (acceleration) := 200.0: 0800 with PAR_1 0306h = 774
constexpr auto set =
    pac::make_request(cmds::cmd_set_axis_parameter, pac::axis_parameter{3, 6}, 200.0F);
static_assert(set.value().code == 0x0800 && set.value().parameter == 774);
// read it back with 1800 on the same PAR_1
constexpr auto get = pac::make_request(cmds::cmd_get_axis_parameter, pac::axis_parameter{3, 6});
static_assert(get.value().code == 0x1800 && get.value().parameter == 774);
// and the other way round
static_assert(pac::decode_axis_parameter(774).value() == pac::axis_parameter{3, 6});

// axis 17 or parameter 51 do not exist (the device would answer QUIT 32 / 33)
static_assert(pac::make_axis_parameter(17, 6).is(errc::out_of_range));
static_assert(pac::make_request(cmds::cmd_get_axis_parameter, pac::axis_parameter{1, 51})
                  .is(errc::out_of_range));
} // namespace cb_pac_5

namespace cb_pac_6 { // "Read one input out of an input word"
namespace pac = fieldcodec::pacontrol;

// I10 is bit 9 of input word 1
static_assert(pac::locate_element(10).value() == pac::element_bit{1, 9});
// 1901 answered 36099 (8D03h) for word 1: I9 is set, I10 is not
constexpr auto word1 = pac::element_word::containing(10, 36099).value();
static_assert(word1.test(9).value() && !word1.test(10).value());
} // namespace cb_pac_6

namespace cb_pac_7 { // "Run a command through the Profibus CMD handshake"
namespace pac = fieldcodec::pacontrol;
namespace profibus = fieldcodec::pacontrol::profibus;
namespace cmds = fieldcodec::dictionaries::pacontrol_commands;

constexpr bool read_n2_over_profibus() {
  profibus::cmd_handshake hs;
  // "read N2": output bytes 00 00 00 00 | 00 02 | 99 06 (SF set, code 1906)
  auto req = pac::start_command(hs, cmds::cmd_get_int_reg, 2);
  if (!req) return false;
  const std::array<std::uint8_t, 8> out = profibus::encode_cmd_request(req.value()).value();
  if (out != std::array<std::uint8_t, 8>{0, 0, 0, 0, 0x00, 0x02, 0x99, 0x06}) return false;

  // a cycle later: 00 00 00 00 | 00 1F | 00 00 — RECEIVE not yet toggled
  const std::array<std::uint8_t, 8> seen_not{0, 0, 0, 0, 0x00, 0x1F, 0x00, 0x00};
  if (hs.update(profibus::decode_cmd_reply(seen_not).value()) != profibus::cmd_progress::waiting) {
    return false;
  }
  // then: 00 00 00 DE | 00 1F | A0 00 — RECEIVE = SEND, end of processing, date 222
  const std::array<std::uint8_t, 8> done{0, 0, 0, 0xDE, 0x00, 0x1F, 0xA0, 0x00};
  const auto reply = profibus::decode_cmd_reply(done).value();
  if (hs.update(reply) != profibus::cmd_progress::done) return false;
  return pac::reply_value(cmds::cmd_get_int_reg, reply).value().as_int().value() == 222;
}
static_assert(read_n2_over_profibus());
} // namespace cb_pac_7

namespace cb_pac_8 { // "Send a position as IEEE-754 or ×1000"
namespace pac = fieldcodec::pacontrol;
using fieldcodec::errc;
using bytes = std::array<std::uint8_t, 4>;

static_assert(pac::encode_position(5552.0F, pac::position_format::ieee_float).value() ==
              bytes{0x45, 0xAD, 0x80, 0x00});
static_assert(pac::encode_position(5552.0F, pac::position_format::milli_integer).value() ==
              bytes{0x00, 0x54, 0xB7, 0x80}); // 5 552 000
static_assert(pac::decode_position_decimal(bytes{0x00, 0x54, 0xB7, 0x81},
                                           pac::position_format::milli_integer)
                  .value()
                  .mantissa == 5552001); // 5552.001
// beyond ±2147483.647 does not fit the int32: refused, never wrapped
static_assert(
    pac::encode_position(2147484.0, pac::position_format::milli_integer).is(errc::overflow));
} // namespace cb_pac_8

namespace cb_xenax_1 { // "Read the identity (1018h)"
namespace co = fieldcodec::canopen;
namespace x = fieldcodec::dictionaries::xenax_canopen;

// 601: 40 18 10 02 … asks for the product code;
// 581: 43 18 10 02 08 75 00 00 answers 7508h (Xvi75V8)
static_assert(co::sdo::upload(1, x::identity_object_product_code).value().data[3] == 0x02);
constexpr co::can_frame answer{0x581, false, 8, {0x43, 0x18, 0x10, 0x02, 0x08, 0x75, 0, 0}};
static_assert(co::sdo::upload_value(x::identity_object_product_code, answer)
                  .value()
                  .to_uint64()
                  .value() == 0x7508);
} // namespace cb_xenax_1

namespace cb_xenax_2 { // "Enable the drive (CiA 402 power state machine)"
namespace co = fieldcodec::canopen;
namespace ds402 = fieldcodec::ds402;
namespace x = fieldcodec::dictionaries::xenax_canopen;
using ds402::state;

// switch on disabled (statusword 0250h) → 06 (shutdown)
static_assert(ds402::next_controlword(0x0250, state::operation_enabled, 0x0000).value() == 0x06);
// ready to switch on (0231h) → 0F (switch on + enable operation at once)
static_assert(ds402::next_controlword(0x0231, state::operation_enabled, 0x0006).value() == 0x0F);
// operation enabled (0237h) → 0F: stay
static_assert(ds402::next_controlword(0x0237, state::operation_enabled, 0x000F).value() == 0x0F);
static_assert(ds402::decode_state(0x0237).value() == state::operation_enabled);

// the controlword by SDO: 601: 2B 40 60 00 06 00 00 00
static_assert(co::sdo::download(1, x::controlword, 0x06).value() ==
              co::can_frame{0x601, false, 8, {0x2B, 0x40, 0x60, 0x00, 0x06, 0, 0, 0}});

// the whole walk against a drive that follows CiA 402: two cycles from switch on disabled
constexpr int cycles_to_enable(state drive) {
  std::uint16_t previous = 0;
  for (int cycle = 1; cycle <= 8; ++cycle) {
    auto cw = ds402::next_controlword(ds402::state_bits(drive), state::operation_enabled, previous);
    if (!cw) return -1;
    drive = ds402::apply(drive, cw.value(), previous).to;
    previous = cw.value();
    if (drive == state::operation_enabled) return cycle;
  }
  return -1;
}
static_assert(cycles_to_enable(state::switch_on_disabled) == 2);
static_assert(cycles_to_enable(state::fault) == 3); // fault reset (80), then 06, then 0F
} // namespace cb_xenax_2

namespace cb_xenax_3 { // "Switch the mode of operation"
namespace co = fieldcodec::canopen;
namespace ds402 = fieldcodec::ds402;
namespace x = fieldcodec::dictionaries::xenax_canopen;
namespace xenax = fieldcodec::xenax;

// profile position: 601: 2F 60 60 00 01 00 00 00
constexpr auto pp =
    co::sdo::download(1, x::modes_of_operation_requested, ds402::mode::profile_position);
static_assert(pp.value() ==
              co::can_frame{0x601, false, 8, {0x2F, 0x60, 0x60, 0x00, 0x01, 0, 0, 0}});
// XENAX jog: 601: 2F 60 60 00 FF 00 00 00
static_assert(co::sdo::download(1, x::modes_of_operation_requested, xenax::mode::jog)
                  .value()
                  .data[4] == 0xFF);

// 6061h answered 581: 4F 61 60 00 FF …: the drive is in jog mode
constexpr co::can_frame shown{0x581, false, 8, {0x4F, 0x61, 0x60, 0x00, 0xFF}};
constexpr auto raw = co::sdo::upload_value(x::modes_of_operation_display, shown).value();
static_assert(xenax::decode_mode(static_cast<std::int8_t>(raw.to_int64().value())).value() ==
              xenax::mode::jog);
// the XENAX supports pp, homing, CSP and jog (6502h)
static_assert(xenax::is_supported(xenax::supported_modes, xenax::mode::cyclic_sync_position));
} // namespace cb_xenax_3

namespace cb_xenax_4 { // "Move to a position (profile position set-point)"
namespace co = fieldcodec::canopen;
namespace x = fieldcodec::dictionaries::xenax_canopen;
namespace xenax = fieldcodec::xenax;
using fieldcodec::errc;

// target 100 000 increments: 601: 23 7A 60 00 A0 86 01 00
static_assert(co::sdo::download(1, x::target_position, 100000).value() ==
              co::can_frame{0x601, false, 8, {0x23, 0x7A, 0x60, 0x00, 0xA0, 0x86, 0x01, 0x00}});
// speed and acceleration are checked against the dictionary's limits (6081h: 10…100 000 000)
static_assert(co::sdo::download(1, x::speed, 50000).has_value());
static_assert(co::sdo::download(1, x::speed, 5).is(errc::out_of_range));
static_assert(co::sdo::download(1, x::acceleration, 1000000).has_value());

// start: 1F absolute (5F relative); halt: 10F
static_assert(xenax::pp_start(xenax::positioning::absolute) == 0x1F);
static_assert(xenax::pp_start(xenax::positioning::relative) == 0x5F);
// 1237h: set-point acknowledged (bit 12) → send 0F again; 0637h: target reached (bit 10)
constexpr auto ack = xenax::decode_status(0x1237, xenax::mode::profile_position).value();
static_assert(ack.set_point_acknowledge && !ack.target_reached);
constexpr auto there = xenax::decode_status(0x0637, xenax::mode::profile_position).value();
static_assert(there.target_reached && !there.following_error);
} // namespace cb_xenax_4

namespace cb_xenax_5 { // "Run the reference (homing)"
namespace co = fieldcodec::canopen;
namespace x = fieldcodec::dictionaries::xenax_canopen;
namespace xenax = fieldcodec::xenax;

// method 2 (linear, start negative): 601: 2F 98 60 00 02 …; mode 6: 601: 2F 60 60 00 06 …
static_assert(co::sdo::download(1, x::reference_methods, xenax::reference_method::linear_negative)
                  .value()
                  .data[4] == 0x02);
static_assert(co::sdo::download(1, x::modes_of_operation_requested, xenax::mode::reference)
                  .value()
                  .data[4] == 0x06);
static_assert(xenax::reference_start == 0x1F);

// 1637h: reference performed (bit 10) and achieved (bit 12), no error (bit 13)
constexpr auto done = xenax::decode_status(0x1637, xenax::mode::reference).value();
static_assert(done.reference_performed && done.reference_achieved && !done.reference_error);
// jog is refused after a gantry reference (methods 3…6)
static_assert(!xenax::allows_jog(xenax::reference_method::gantry_same_positive));
} // namespace cb_xenax_5

namespace cb_xenax_6 { // "Read the error code (603Fh) and its text"
namespace co = fieldcodec::canopen;
namespace x = fieldcodec::dictionaries::xenax_canopen;
namespace xenax = fieldcodec::xenax;
using fieldcodec::errc;

// 601: 40 3F 60 00 → 581: 4B 3F 60 00 32 FF 00 00: FF32h, XENAX error 50
constexpr co::can_frame answer{0x581, false, 8, {0x4B, 0x3F, 0x60, 0x00, 0x32, 0xFF}};
constexpr auto code = static_cast<std::uint16_t>(
    co::sdo::upload_value(x::error_code, answer).value().to_uint64().value());
static_assert(code == 0xFF32);
constexpr std::uint8_t number = xenax::decode_error_code(code).value();
static_assert(number == 50);
static_assert(xenax::error_text(number) == "following error (position error window exceeded)");
// after error 50 the drive continues without a new reference (power continue, 5000h = 2010h)
static_assert(!xenax::needs_reference_after(number));
// a code that is not a XENAX error number
static_assert(xenax::decode_error_code(0x8611).is(errc::out_of_range));
} // namespace cb_xenax_6

namespace cb_xenax_7 { // "Reset a fault"
namespace ds402 = fieldcodec::ds402;
using ds402::state;

constexpr bool reset_and_enable() {
  ds402::power_sequencer seq; // remembers the controlword it sent last
  // fault (0218h) → 80 (fault reset); still in fault → 80 held
  if (seq.next(0x0218, state::operation_enabled).value() != 0x80) return false;
  if (seq.next(0x0218, state::operation_enabled).value() != 0x80) return false;
  // switch on disabled (0250h) → 06, ready to switch on (0231h) → 0F
  if (seq.next(0x0250, state::operation_enabled).value() != 0x06) return false;
  return seq.next(0x0231, state::operation_enabled).value() == 0x0F;
}
static_assert(reset_and_enable());
} // namespace cb_xenax_7

namespace cb_xenax_8 { // "Send a set-point in RPDO2"
namespace co = fieldcodec::canopen;
namespace x = fieldcodec::dictionaries::xenax_canopen;

constexpr auto rpdo2 = co::pdo::make_static_mapping(
    x::dictionary, co::pdo::direction::rpdo, {{0x6040, 0, 16}, {0x607A, 0, 32}});
// the mapping entries are 1601h's defaults: 60400010h, 607A0020h
static_assert(rpdo2.values() == std::array<std::uint32_t, 2>{0x60400010, 0x607A0020});
static_assert(x::receive_pdo_mapping_param_2[2].default_value().to_uint64().value() == 0x607A0020);

// controlword 1F, target 100 000: 301: 1F 00 A0 86 01 00
constexpr co::can_frame rpdo2_frame = [] {
  std::array<std::uint8_t, 6> b{};
  if (!rpdo2.set(b, 0, 0x1F) || !rpdo2.set(b, 1, 100000)) return co::can_frame{};
  return co::pdo::to_frame({.id = 0x301}, b).value();
}();
static_assert(rpdo2_frame ==
              co::can_frame{0x301, false, 6, {0x1F, 0x00, 0xA0, 0x86, 0x01, 0x00}});
} // namespace cb_xenax_8

namespace cb_xenax_9 { // "Read the device name (1008h) with the SDO client"
namespace co = fieldcodec::canopen;
namespace x = fieldcodec::dictionaries::xenax_canopen;

class device_name {
public:
  // sends 601: 40 08 10 00 …; false while a transfer is running
  template <class Send> bool start(std::uint32_t now, Send send) {
    auto s = client_.upload({x::manufacturer_device_name.index, 0}, buffer_, now);
    if (!s) return false;
    for (const co::can_frame &f : s.value().send) send(f);
    return true;
  }
  // every frame received from the bus (frames of other COB-IDs are ignored)
  template <class Send> void on_frame(const co::can_frame &f, std::uint32_t now, Send send) {
    for (const co::can_frame &out : client_.on_frame(f, now).send) send(out);
  }
  // at the deadline: a drive that does not answer ends the transfer with an abort (timeout)
  template <class Send> void poll(std::uint32_t now, Send send) {
    for (const co::can_frame &out : client_.poll(now).send) send(out);
  }
  // the name once the upload is done ("Servocontroller XENAX Xvi 75V8"); empty before and
  // after a failure (client_.error() says why)
  std::string_view name() const {
    if (client_.state() != co::sdo::transfer_state::done) return {};
    const auto b = client_.received();
    return {reinterpret_cast<const char *>(b.data()), b.size()};
  }

private:
  co::sdo::client client_{1, 500}; // node 1, 500 ms for each answer
  std::array<std::uint8_t, x::manufacturer_device_name.capacity()> buffer_{};
};
} // namespace cb_xenax_9

namespace cb_xenax_10 { // "Read a TPDO with the drive's default mapping"
namespace co = fieldcodec::canopen;
namespace x = fieldcodec::dictionaries::xenax_canopen;

constexpr auto entries = co::pdo::default_mapping(x::dictionary, 0x1A01).value();
static_assert(entries.size() == 2 && entries[0].to_u32() == 0x60410010 &&
              entries[1].to_u32() == 0x60640020);
constexpr auto tpdo2 =
    co::pdo::make_mapping(x::dictionary, co::pdo::direction::tpdo, entries.entries()).value();

// 281: 37 02 F6 FF FF FF → statusword 0237h (operation enabled), position −10 increments
constexpr co::can_frame f{0x281, false, 6, {0x37, 0x02, 0xF6, 0xFF, 0xFF, 0xFF}};
static_assert(tpdo2.get<std::uint16_t>(f.payload(), 0).value() == 0x0237);
static_assert(tpdo2.get<std::int32_t>(f.payload(), 1).value() == -10);
} // namespace cb_xenax_10

namespace cb_xenax_11 { // "Limit the force in newtons (6073h)"
namespace co = fieldcodec::canopen;
namespace x = fieldcodec::dictionaries::xenax_canopen;
namespace xenax = fieldcodec::xenax;
using fieldcodec::errc;

// ELAX Ex F20 limited to 4 N: 48 steps (480 mA); 601: 2B 73 60 00 30 00 00 00
constexpr auto steps = xenax::current_limit_for(xenax::newtons{{4, 0}}, xenax::motor::elax_ex_f20);
static_assert(steps.value() == 48);
static_assert(co::sdo::download(1, x::limit_i_force, steps.value()).value().data[4] == 0x30);

// 2005h I_Force actual read 300 mA: 2.5 N
constexpr auto force = xenax::to_newtons(300, xenax::motor::elax_ex_f20).value();
static_assert(force.value.mantissa == 2500 && force.value.places == 3);

// a ROTAX takes a torque, not a force; above 20 A is refused
static_assert(xenax::current_limit_for(xenax::newtons{{1, 0}}, xenax::motor::rotax_rxvp_t0_04)
                  .is(errc::invalid_argument));
static_assert(xenax::current_limit_for(xenax::newtons{{200, 0}}, xenax::motor::elax_ex_f20)
                  .is(errc::out_of_range));
} // namespace cb_xenax_11

namespace cb_xenax_12 { // "Send a direct command (5000h)"
namespace co = fieldcodec::canopen;
namespace x = fieldcodec::dictionaries::xenax_canopen;
namespace xenax = fieldcodec::xenax;

// power continue (PWC, 2010h): 601: 23 00 50 00 10 20 00 00
static_assert(co::sdo::download(1, x::direct_commands, xenax::direct_command::power_continue)
                  .value() ==
              co::can_frame{0x601, false, 8, {0x23, 0x00, 0x50, 0x00, 0x10, 0x20, 0x00, 0x00}});
static_assert(xenax::mnemonic(xenax::direct_command::power_continue) == "PWC");
static_assert(xenax::to_string(xenax::direct_command::power_continue) ==
              "power continue at the actual position");
} // namespace cb_xenax_12

namespace cb_xenax_13 { // "Mind what differs per bus"
namespace xenax = fieldcodec::xenax;
using fieldcodec::errc;

static_assert(xenax::node_id(99).value() == 99);
static_assert(xenax::node_id(100).is(errc::out_of_range)); // a CiA 301 ID the XENAX cannot take
static_assert(xenax::node_id(0).is(errc::out_of_range));   // CI not set

// 1 000 000 inc/s²: 60B2h = 20 on EtherCAT; on CANopen it does not fit the INTEGER16
static_assert(xenax::torque_offset_from_acceleration(1000000, xenax::bus::ethercat).value() == 20);
static_assert(xenax::torque_offset_from_acceleration(1000000, xenax::bus::canopen)
                  .is(errc::overflow));
static_assert(xenax::acceleration_from_torque_offset(20, xenax::bus::ethercat) == 1000000);
} // namespace cb_xenax_13
namespace cb_compax_1 { // "Encode a position in BCD"
namespace cx = fieldcodec::compax;
using fieldcodec::decimal;
using fieldcodec::errc;
using bcd6 = std::array<std::uint8_t, 6>;

// 7350.15 mm → 00 00 07 35 01 50; −1650 mm → FF 00 01 65 00 00
static_assert(cx::encode_bcd_position(decimal{735015, 2}).value() ==
              bcd6{0x00, 0x00, 0x07, 0x35, 0x01, 0x50});
static_assert(cx::encode_bcd_position(decimal{-1650, 0}).value() ==
              bcd6{0xFF, 0x00, 0x01, 0x65, 0x00, 0x00});
// back to 0.001 mm
static_assert(cx::decode_bcd_position(bcd6{0x00, 0x00, 0x07, 0x35, 0x01, 0x50}).value() ==
              7350150);

// finer than 0.001 mm, beyond the travel range, or a bad digit: refused
static_assert(cx::encode_bcd_position(decimal{12345, 4}).is(errc::not_representable));
static_assert(cx::encode_bcd_position(decimal{4000001, 0}).is(errc::out_of_range));
constexpr bcd6 bad{0x00, 0x00, 0x07, 0x3A, 0x01, 0x50};
static_assert(cx::decode_bcd_position(bad).is(errc::bad_digit));
} // namespace cb_compax_1

namespace cb_compax_2 { // "Write and read a Px parameter"
namespace cx = fieldcodec::compax;
namespace d = fieldcodec::dictionaries::compax_objects;
using fieldcodec::decimal;
using bytes4 = std::array<std::uint8_t, 4>;

// P11 := 5000 → 00 4C 4B 40 (resolution 0.001: raw 5 000 000)
constexpr bytes4 p11() {
  bytes4 out{};
  if (!cx::encode_px(d::dictionary, 11, decimal{5000, 0}, out)) return {};
  return out;
}
static_assert(p11() == bytes4{0x00, 0x4C, 0x4B, 0x40});
// and back
static_assert(cx::decode_px(d::dictionary, 11, bytes4{0x00, 0x4C, 0x4B, 0x40}).value().mantissa ==
              5000);
} // namespace cb_compax_2

namespace cb_compax_3 { // "Write an object with a PCP request and check the confirmation"
namespace cx = fieldcodec::compax;

// P11 := 00 4C 4B 40: write request 8082h to 5FD4h sub 11, 4 data bytes, counter 3 + 2 = 5
constexpr std::array<std::uint8_t, 4> value{0x00, 0x4C, 0x4B, 0x40};
constexpr auto request = cx::pcp_write(0x5FD4, 11, value);
static_assert(request.value().param_counter == 5 && request.value().length == 4);

// the drive's positive confirmation: 80 82 00 02 00 00 00 00
constexpr std::array<std::uint8_t, 8> reply{0x80, 0x82, 0x00, 0x02, 0x00, 0x00, 0x00, 0x00};
constexpr auto confirmation = cx::decode_pcp_response(reply).value();
static_assert(!confirmation.is_error && cx::answers(request.value(), confirmation));
} // namespace cb_compax_3

namespace cb_compax_4 { // "Read an object through OBJECT_REQ / OBJECT_RSP"
namespace cx = fieldcodec::compax;
namespace d = fieldcodec::dictionaries::compax_objects;

// read SPEED (index pointer 38): OBJECT_REQ A6 00 00 00 00 00
constexpr auto request =
    cx::object_read(cx::index_pointer(d::compax_columns, d::speed).value()).value();
static_assert(cx::encode_object_request(request).value() ==
              cx::object_frame{0xA6, 0x00, 0x00, 0x00, 0x00, 0x00});

// OBJECT_RSP A6 00 00 00 00 32 answers it: SPEED = 50
constexpr auto response =
    cx::decode_object_response(cx::object_frame{0xA6, 0x00, 0x00, 0x00, 0x00, 0x32}).value();
static_assert(cx::answers(request, response));
// an error reply FF 00 52 00 00 00 is error 82, "wrong index pointer"
constexpr auto refused =
    cx::decode_object_response(cx::object_frame{0xFF, 0x00, 0x52, 0x00, 0x00, 0x00}).value();
static_assert(refused.is_error &&
              cx::to_string(static_cast<cx::object_error>(refused.error_number)) ==
                  "wrong index pointer");
} // namespace cb_compax_4

namespace cb_compax_5 { // "Build an Nx program record"
namespace nx = fieldcodec::compax::nx;

constexpr auto posa = nx::make(nx::op::posa, nx::integer(250));
static_assert(posa == nx::parse_command("POSA 250").value());
// record: length 7, POSA (41h), the DSP number of 250 mm (00 00 00 FA 00 00), zero padding
constexpr auto rec = nx::encode_record(posa).value();
static_assert(rec[0] == 7 && rec[1] == 0x41 && rec[5] == 0xFA);

// and back to text
constexpr bool prints_as(std::string_view text) {
  std::array<char, nx::text_max> buf{};
  auto cmd = nx::decode_record(rec);
  if (!cmd) return false;
  auto n = nx::format_command(cmd.value(), buf);
  return n && std::string_view(buf.data(), n.value()) == text;
}
static_assert(prints_as("POSA 250"));
} // namespace cb_compax_5

namespace cb_compax_6 { // "Enable the drive (DRIVECOM profile 22)"
namespace cx = fieldcodec::compax;
namespace ds402 = fieldcodec::ds402;

// switch on disabled (0250h) → 06; ready to switch on (0231h) → 0F
static_assert(cx::next_steuerwort(cx::statuswort{0x0250}, ds402::state::operation_enabled,
                                  cx::steuerwort{0x0000})
                  .value() == cx::steuerwort{0x0006});
static_assert(cx::drivecom_state(cx::statuswort{0x0237}).value() ==
              ds402::state::operation_enabled);

// the COMPAX bits of the previous word are kept: START (bit 13) stays set
constexpr cx::steuerwort previous =
    cx::steuerwort{0x0006}.with(cx::steuerwort_bit::start);
static_assert(cx::next_steuerwort(cx::statuswort{0x0231}, ds402::state::operation_enabled,
                                  previous)
                  .value() == cx::steuerwort{0x200F});
// bit names, with the manual's own terms
static_assert(cx::steuerwort{0x200F}.test(cx::steuerwort_bit::power_on));
static_assert(cx::manual_term(cx::steuerwort_bit::rapid_stop_n) == "Rapid stop");
} // namespace cb_compax_6

namespace cb_compax_7 { // "Read the current error and its text"
namespace cx = fieldcodec::compax;

// read S30 sub 1 (5FD7h): 8081h, counter 3
constexpr auto request = cx::pcp_read(0x5FD7, 1).value();
static_assert(request.param_counter == 3);

// 80 81 00 04 00 00 00 00 00 01 05 00: one data byte, 5 (the pad byte 00 after it)
constexpr std::array<std::uint8_t, 12> reply{0x80, 0x81, 0x00, 0x04, 0x00, 0x00,
                                             0x00, 0x00, 0x00, 0x01, 0x05, 0x00};
constexpr auto answer = cx::decode_pcp_response(reply).value();
static_assert(cx::answers(request, answer) && answer.length == 1);
constexpr std::uint8_t error = answer.data[0];
static_assert(cx::error_text(error) == "machine-zero initiator not found"); // E05
static_assert(cx::fault_code_of(error).raw == 0x7300); // what STOERUNG shows for it
} // namespace cb_compax_7

namespace cb_compax_8 { // "Hand over a target with the LAGE_ZIEL handshake"
namespace cx = fieldcodec::compax;
using fieldcodec::decimal;

constexpr bool move_to_1250_5() {
  cx::set_point_handshake hs;
  cx::steuerwort control{0x000F}; // operation enabled
  cx::statuswort status{0x0237};
  if (!hs.submit(decimal{12505, 1}, false, status, control)) return false;
  // LAGE_ZIEL 00 13 14 C4 (1 250 500 µm), STEUERWORT 001F: new set point
  control = hs.control(control);
  if (hs.target_bytes() != std::array<std::uint8_t, 4>{0x00, 0x13, 0x14, 0xC4}) return false;
  if (control != cx::steuerwort{0x001F}) return false;
  // the drive acknowledges (STATUSWORT bit 12): back to 000F
  status = cx::statuswort{0x1237};
  if (!hs.poll(status, control)) return false;
  control = hs.control(control);
  if (control != cx::steuerwort{0x000F}) return false;
  // the acknowledgement falls: the handshake is idle, ready for the next target
  (void)hs.poll(cx::statuswort{0x0237}, control);
  return !hs.busy();
}
static_assert(move_to_1250_5());
} // namespace cb_compax_8
// clang-format on

TEST_CASE("cookbook, DPQ: an emergency and its text") {
  namespace co = fieldcodec::canopen;
  const co::can_frame pressure{0x085, false, 8, {0x02, 0x83, 0x01, 0, 0, 0, 0, 0}};
  CHECK(cb_dpq_5::emcy_text(pressure) == "node 5: 8302 pressure monitor tripped [generic error]");
  const co::can_frame cleared{0x085, false, 8, {0x00, 0x00, 0x00, 0, 0, 0, 0, 0}};
  CHECK(cb_dpq_5::emcy_text(cleared) == "node 5: 0000 no error (all errors cleared)");
  const co::can_frame vendor{0x0FF, false, 8, {0x01, 0xFF, 0x81, 0, 0, 0, 0, 0}};
  CHECK(cb_dpq_5::emcy_text(vendor) ==
        "node 127: FF01 not listed by the DPQ manual [generic error, manufacturer-specific]");
  const co::can_frame short_frame{0x085, false, 7, {0x02, 0x83, 0x01, 0, 0, 0, 0, 0}};
  CHECK(cb_dpq_5::emcy_text(short_frame) == fieldcodec::to_string(fieldcodec::errc::bad_length));
  const co::can_frame sdo{0x585, false, 8, {}};
  CHECK(cb_dpq_5::emcy_text(sdo) == fieldcodec::to_string(fieldcodec::errc::unexpected_frame));
}

TEST_CASE("cookbook, DPQ: the frames the recipes state, at run time") {
  namespace co = fieldcodec::canopen;
  // the identity request and answer
  CHECK(cb_dpq_1::request.id == 0x605);
  CHECK(co::sdo::upload_value(cb_dpq_1::vendor_id, cb_dpq_1::answer).value().to_uint64().value() ==
        0x12D);
  // the event timer write is 2B 00 18 05 64 00 00 00 and its confirmation matches the channel's
  const auto ch = co::sdo::channel::default_for(5).value();
  CHECK(ch.response(co::sdo::download_response({0x1800, 5})) ==
        co::can_frame{0x585, false, 8, {0x60, 0x00, 0x18, 0x05, 0, 0, 0, 0}});
  CHECK(cb_dpq_8::timer.value() ==
        ch.request(co::sdo::expedited_download({0x1800, 5}, std::array<std::uint8_t, 2>{0x64, 0}))
            .value());
  // the error history requests: sub 0 is 40 03 10 00, sub 1 is 40 03 10 01; clearing 2F … 00
  namespace dpq = fieldcodec::dpq;
  namespace p = fieldcodec::dictionaries::dpq_parameters;
  CHECK(cb_dpq_6::count_request ==
        co::can_frame{0x605, false, 8, {0x40, 0x03, 0x10, 0x00, 0, 0, 0, 0}});
  CHECK(dpq::read_request(5, p::error_code_1).value() ==
        co::can_frame{0x605, false, 8, {0x40, 0x03, 0x10, 0x01, 0, 0, 0, 0}});
  CHECK(dpq::write_request(5, p::error_history_sub0, 0).value() ==
        co::can_frame{0x605, false, 8, {0x2F, 0x03, 0x10, 0x00, 0, 0, 0, 0}});
  CHECK(cb_dpq_6::newest.text() == "current input: cable break");
  // the read-back request of the bar recipe
  CHECK(fieldcodec::dpq::read_request(5, fieldcodec::dictionaries::dpq_parameters::inj_p_limit_1)
            .value() == co::can_frame{0x605, false, 8, {0x40, 0x23, 0x20, 0x00, 0, 0, 0, 0}});
}

TEST_CASE("cookbook, PA-CONTROL: the recipes' functions at run time") {
  using fieldcodec::errc;
  // the request frame helper tells a wrong wire text from the right one
  CHECK(cb_pac_1::sent_as("\x01\x02"
                          "1906;2;0;0"
                          "\x03"
                          "7"
                          "\x04"));
  CHECK_FALSE(cb_pac_1::sent_as("\x01\x02"
                                "1906;2;0;0"
                                "\x03"
                                "6"
                                "\x04"));
  // the decoder skips noise before the frame and stops at a cut frame
  auto ack = cb_pac_2::answer("xx\x04\x01\x02"
                              "0;1;1;0;0;222"
                              "\x03"
                              "58"
                              "\x04");
  CHECK(ack.value().date.as_int().value() == 222); // noise dropped, the frame after it taken
  CHECK(cb_pac_2::answer("\x01\x02"
                         "0;1;1;0;0;2")
            .is(errc::truncated));
  CHECK(cb_pac_2::answer("\x01\x02"
                         "0;1;1;0;0;222"
                         "\x03"
                         "58"
                         "\x04")
            .value()
            .date.as_int()
            .value() == 222);
  CHECK(cb_pac_3::frame_length() == 21);
  CHECK(cb_pac_7::read_n2_over_profibus());
  // an answer still on its way is not arrived
  const fieldcodec::pacontrol::serial::acknowledgement moving{
      0, false, 31, 0, fieldcodec::pacontrol::value::of_real({1516950, 3}).value()};
  CHECK_FALSE(cb_pac_3::arrived(moving));
}

TEST_CASE("cookbook, XENAX: the enable walk reaches operation enabled from every state") {
  namespace ds402 = fieldcodec::ds402;
  using ds402::state;
  CHECK(cb_xenax_2::cycles_to_enable(state::switch_on_disabled) == 2);
  CHECK(cb_xenax_2::cycles_to_enable(state::ready_to_switch_on) == 1);
  CHECK(cb_xenax_2::cycles_to_enable(state::switched_on) == 1);
  CHECK(cb_xenax_2::cycles_to_enable(state::operation_enabled) == 1);
  CHECK(cb_xenax_2::cycles_to_enable(state::fault) == 3);
  // a drive that cannot leave a state on its own gives up after eight cycles
  CHECK(cb_xenax_2::cycles_to_enable(state::fault_reaction_active) == -1);
  CHECK(cb_xenax_7::reset_and_enable());
  CHECK(cb_xenax_8::rpdo2_frame.dlc == 6);
}

TEST_CASE("cookbook, XENAX: the device name reader through a segmented upload") {
  namespace co = fieldcodec::canopen;
  namespace sdo = fieldcodec::canopen::sdo;
  const auto ch = sdo::channel::default_for(1).value();
  std::vector<co::can_frame> sent;
  const auto send = [&](const co::can_frame &f) { sent.push_back(f); };
  const std::string_view text = "Servocontroller XENAX Xvi 75V8";

  cb_xenax_9::device_name reader;
  REQUIRE(reader.start(0, send));
  REQUIRE(sent.size() == 1);
  CHECK(sent[0] == co::can_frame{0x601, false, 8, {0x40, 0x08, 0x10, 0x00, 0, 0, 0, 0}});
  CHECK_FALSE(reader.start(0, send)); // busy
  CHECK(reader.name().empty());

  reader.on_frame(ch.response(sdo::upload_response({0x1008, 0}, 30)), 10, send);
  bool toggle = false;
  std::size_t offset = 0;
  while (offset < text.size()) {
    REQUIRE(sent.size() >= 2);
    CHECK(sent.back() == ch.request(sdo::upload_segment_request(toggle)));
    const std::size_t n = std::min<std::size_t>(7, text.size() - offset);
    std::array<std::uint8_t, 7> part{};
    for (std::size_t i = 0; i < n; ++i) part[i] = static_cast<std::uint8_t>(text[offset + i]);
    offset += n;
    const auto segment = sdo::upload_segment(toggle, std::span<const std::uint8_t>(part).first(n),
                                             offset == text.size());
    reader.on_frame(ch.response(segment).value(), 20, send);
    toggle = !toggle;
  }
  CHECK(reader.name() == text);

  // a drive that does not answer: the poll at the deadline aborts with a timeout
  cb_xenax_9::device_name silent;
  sent.clear();
  REQUIRE(silent.start(0, send));
  silent.poll(100, send);
  CHECK(sent.size() == 1); // nothing yet
  silent.poll(600, send);
  REQUIRE(sent.size() == 2);
  CHECK(sent[1].data[0] == 0x80); // abort 0504 0000h
  CHECK(sent[1].data[4] == 0x00);
  CHECK(sent[1].data[7] == 0x05);
  CHECK(silent.name().empty());

  // a drive that refuses: the abort ends it, no name
  cb_xenax_9::device_name refused;
  REQUIRE(refused.start(0, send));
  refused.on_frame(ch.response(sdo::abort({0x1008, 0}, sdo::abort_code::no_object)), 5, send);
  CHECK(refused.name().empty());
}

TEST_CASE("cookbook, COMPAX: the recipes' functions at run time") {
  CHECK(cb_compax_2::p11() == std::array<std::uint8_t, 4>{0x00, 0x4C, 0x4B, 0x40});
  CHECK(cb_compax_5::prints_as("POSA 250"));
  CHECK_FALSE(cb_compax_5::prints_as("POSA 0"));
  CHECK(cb_compax_8::move_to_1250_5());
}

TEST_CASE("cookbook, XENAX: the default TPDO2 mapping at run time") {
  namespace co = fieldcodec::canopen;
  const co::can_frame f{0x281, false, 6, {0x18, 0x02, 0x40, 0x42, 0x0F, 0x00}};
  CHECK(cb_xenax_10::tpdo2.get<std::uint16_t>(f.payload(), 0).value() == 0x0218);
  CHECK(cb_xenax_10::tpdo2.get<std::int32_t>(f.payload(), 1).value() == 1000000);
  CHECK(cb_xenax_10::tpdo2.get<std::int32_t>(f.payload().first(5), 1)
            .is(fieldcodec::errc::truncated));
  CHECK(
      cb_xenax_10::tpdo2.get<std::int32_t>(f.payload(), 2).is(fieldcodec::errc::invalid_argument));
}
