// Every C++ block of docs/pacontrol.md, as written there (the includes of all blocks first;
// each block's body in a namespace of its own), and the results its comments state. Keep
// this file and the page in step: a block changed there is changed here.
#if __has_include(<fieldcodec/dictionaries/pacontrol_commands.hpp>)

// The includes of the four blocks.
#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/pacontrol/axis_motion.hpp>
#include <fieldcodec/pacontrol/axis_parameter.hpp>
#include <fieldcodec/pacontrol/command.hpp>
#include <fieldcodec/pacontrol/elements.hpp>
#include <fieldcodec/pacontrol/profibus_cmd.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

#include "pac_test_util.hpp"

#include <doctest/doctest.h>

#include <array>

// clang-format off
namespace doc_rs232 { // "## RS232"
namespace serial = fieldcodec::pacontrol::serial;
using fieldcodec::pacontrol::value;

// 0A87 "move axis 2 to 5552.0" (manual 3.4.3) into `tx`; returns the frame's length, 0 when
// `tx` is too small (tx should hold serial::max_frame_size bytes).
std::size_t write_move(std::span<std::uint8_t> tx) {
  auto n = serial::encode_request({0x0A87, 2, value::of_float(5552.0F).value()}, tx);
  return n.value_or(0); // 01 02 "0A87;2;1;5552.0" 03 "95" 04: 21 bytes
}

serial::decoder rx({{}, serial::accept::acknowledgements}); // a master
serial::acknowledgement last_ack{};

void on_byte(std::uint8_t b) { // from the UART interrupt
  auto r = rx.push(b);
  if (!r) return; // r.error(): frame dropped, the decoder already hunts for the next SOH
  if (r.value() == serial::frame_kind::acknowledgement) last_ack = rx.acknowledgement();
}
} // namespace doc_rs232

namespace doc_handshake { // "### CMD interface and handshake"
namespace pac = fieldcodec::pacontrol;
namespace profibus = fieldcodec::pacontrol::profibus;
namespace cmds = fieldcodec::dictionaries::pacontrol_commands;

// Once, after a restart of the master: take over the device's RECEIVE flag, start nothing.
void resynchronize(profibus::cmd_handshake &hs, std::span<const std::uint8_t, 8> in) {
  if (auto reply = profibus::decode_cmd_reply(in)) hs.synchronize(reply.value());
}

// "Read N2" (1906) into the 8 output bytes; toggles SF. False when refused.
bool start_read_n2(profibus::cmd_handshake &hs, std::span<std::uint8_t, 8> out) {
  auto req = pac::start_command(hs, cmds::cmd_get_int_reg, 2);
  if (!req) return false; // req.error(): bad_state while the last toggle is unseen, …
  auto bytes = profibus::encode_cmd_request(req.value());
  if (!bytes) return false;
  std::copy(bytes.value().begin(), bytes.value().end(), out.begin());
  return true; // 00 00 00 00 | 00 02 | 99 06 on a fresh handshake (SF 1, code 1906)
}

// Every cycle: how far the command is.
profibus::cmd_progress progress(profibus::cmd_handshake &hs,
                                std::span<const std::uint8_t, 8> in) {
  auto reply = profibus::decode_cmd_reply(in);
  if (!reply) return profibus::cmd_progress::waiting;
  // waiting: SF != RF, not seen yet; running: seen, end of processing 0; done: the result is
  // in reply.date; failed: reply.command_error_number says why
  return hs.update(reply.value());
}
} // namespace doc_handshake

namespace doc_command_table { // "## Command table"
namespace pac = fieldcodec::pacontrol;
namespace cmds = fieldcodec::dictionaries::pacontrol_commands;
using fieldcodec::errc;

// N5 := 12345 (3.4.1) with an unsigned date: any integer type, checked against the table.
constexpr auto write_n5 = pac::make_request(cmds::cmd_put_int_reg, 5, 12345U);
static_assert(write_n5.value().parameter == 5);
static_assert(write_n5.value().date.as_int().value() == 12345);

// Axis 3 acceleration := 200.0 (5.2.3): PAR_1 is 0306 hex = 774.
constexpr auto set_acceleration =
    pac::make_request(cmds::cmd_set_axis_parameter, pac::axis_parameter{3, 6}, 200.0F);
static_assert(set_acceleration.value().parameter == 774);

// Refused before a frame is built:
static_assert(pac::make_request(cmds::cmd_get_single_input, 65537).error() ==
              errc::out_of_range); // not input 1
static_assert(pac::make_request(cmds::cmd_put_single_output, 13, 2).error() ==
              errc::out_of_range); // an output is set with 0 or 1
static_assert(pac::make_request(cmds::cmd_get_axis_parameter, 0x0133).error() ==
              errc::out_of_range); // axis 1 has no parameter 51
static_assert(pac::make_request(cmds::cmd_pos_axis_absolut, 2, 5552).error() ==
              errc::type_mismatch); // a position is a real number: 5552.0F
} // namespace doc_command_table

namespace doc_numbers { // "## Numbers inside commands"
namespace pac = fieldcodec::pacontrol;

// M352 is bit 15 of flag word 22 (6.3 prints it as M252).
static_assert(pac::locate_element(352).value() == pac::element_bit{22, 15});

// 1901 answered 36099 (8D03 hex) for the input word that holds I10: I9 is set, I10 is not.
constexpr auto input_word_1 = pac::element_word::containing(10, 36099).value();
static_assert(input_word_1.test(9).value() && !input_word_1.test(10).value());

// 1921 answered 16777476 (0100 0104 hex) for axis 8 (5.2.4.28).
constexpr auto axis8 = pac::decode_extended_axis_status(16777476).value();
static_assert(axis8.power_pack_ready && axis8.positive_limit_actuated);
static_assert(axis8.motion == pac::axis_motion::stopped_with_fault);

// 0AA3: move only while flag M11 is 1.
static_assert(pac::encode_element_condition({true, pac::element_type::flag, 11}).value() ==
              0x0103000BU);
} // namespace doc_numbers
// clang-format on

namespace pac = fieldcodec::pacontrol;

TEST_CASE("docs/pacontrol.md, RS232: the frame written and an acknowledgement read") {
  std::array<std::uint8_t, pac::serial::max_frame_size> tx{};
  const std::size_t n = doc_rs232::write_move(tx);
  CHECK(n == 21);
  CHECK(pactest::frame("0A87;2;1;5552.0", "95") == std::span<const std::uint8_t>(tx).first(n));
  std::array<std::uint8_t, 4> small{};
  CHECK(doc_rs232::write_move(small) == 0);
  // The device's answer of 3.4.3 (done at 5552.000), with noise before it.
  doc_rs232::on_byte(0x55);
  const auto answer = pactest::frame("0;1;31;0;1;5552.000", "35");
  for (const auto b : answer.span()) doc_rs232::on_byte(b);
  CHECK(doc_rs232::last_ack.end_of_processing);
  CHECK(doc_rs232::last_ack.operating_status == 31);
  CHECK(doc_rs232::last_ack.date == pac::value::of_float(5552.0F).value());
}

TEST_CASE("docs/pacontrol.md, CMD handshake: start, bytes, progress") {
  pac::profibus::cmd_handshake hs;
  // The device kept RF = 1 while the master restarted.
  const auto idle = pactest::hex("00 00 00 00 00 01 80 00");
  doc_handshake::resynchronize(hs, std::span<const std::uint8_t, 8>(idle.data.data(), 8));
  CHECK(hs.send_flag());
  std::array<std::uint8_t, 8> out{};
  REQUIRE(doc_handshake::start_read_n2(hs, out));
  CHECK(pactest::hex("00 00 00 00 00 02 19 06") == std::span<const std::uint8_t>(out));
  // not toggled back yet: a second start is refused
  CHECK_FALSE(doc_handshake::start_read_n2(hs, out));
  const auto unseen = pactest::hex("00 00 00 00 00 01 80 00");
  CHECK(doc_handshake::progress(hs, std::span<const std::uint8_t, 8>(unseen.data.data(), 8)) ==
        pac::profibus::cmd_progress::waiting);
  // RF = SF = 0, BF: done, N2 = 222 (3.4.2).
  const auto done = pactest::hex("00 00 00 DE 00 01 20 00");
  CHECK(doc_handshake::progress(hs, std::span<const std::uint8_t, 8>(done.data.data(), 8)) ==
        pac::profibus::cmd_progress::done);
  // From a fresh handshake (SF 0) the start sets SF: 99 06, as the comment says.
  pac::profibus::cmd_handshake fresh;
  REQUIRE(doc_handshake::start_read_n2(fresh, out));
  CHECK(pactest::hex("00 00 00 00 00 02 99 06") == std::span<const std::uint8_t>(out));
}

TEST_CASE("docs/pacontrol.md, command table and numbers: run-time copies of the asserts") {
  CHECK(doc_command_table::write_n5.value().parameter == 5);
  CHECK(doc_command_table::set_acceleration.value().parameter == 774);
  CHECK(doc_numbers::axis8.motion == pac::axis_motion::stopped_with_fault);
  CHECK(doc_numbers::input_word_1.word == 1);
}

#endif
