// Serial port and the PA-CONTROL RS232 link over a pseudo-terminal with a scripted PA-CONTROL
// on the other side (host/serial_port.hpp, host/pacontrol_link.hpp).
#include "peers.hpp"

#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/host/pacontrol_link.hpp>
#include <fieldcodec/pacontrol/command.hpp>

#include <doctest/doctest.h>

#include <string>

namespace host = fieldcodec::host;
namespace pa = fieldcodec::pacontrol;
namespace cmds = fieldcodec::dictionaries::pacontrol_commands;
using fieldcodec::errc;
using namespace std::chrono_literals;

namespace {
/// Register N12 holds 4711; everything else is answered with command error 1.
std::string register_script(const pa::serial::decoded_frame &f) {
  pa::serial::acknowledgement a;
  a.operating_status = 31; // online (manual 001, status codes)
  a.end_of_processing = true;
  if (f.kind == pa::serial::frame_kind::poll) return fieldcodec::test::pacontrol_peer::ack(a);
  if (f.req.code == 0x1906 && f.req.parameter == 12) {
    a.date = pa::value::of_int(4711).value();
  } else {
    a.command_error_number = 1;
  }
  return fieldcodec::test::pacontrol_peer::ack(a);
}
} // namespace

TEST_CASE("serial port: line settings") {
  // manual 001, 3.1: 9600 baud, 7 data bits, 1 stop bit, no parity
  CHECK(host::pacontrol_line.baud == 9600);
  CHECK(host::pacontrol_line.data_bits == 7);
  CHECK(host::pacontrol_line.par == host::parity::none);
  CHECK(host::pacontrol_line.stop_bits == 1);
  CHECK(host::check(host::pacontrol_line));
  CHECK(host::check({.baud = 12345}) == errc::invalid_argument);
  CHECK(host::check({.data_bits = 9}) == errc::invalid_argument);
  CHECK(host::check({.stop_bits = 3}) == errc::invalid_argument);
  // the switch settings of manual 001, 3.2.1 (S2 3: 7E1, S3 7: 19200)
  CHECK(host::check({.baud = 19200, .data_bits = 7, .par = host::parity::even}));

  // what open() asks of the driver
  termios want{};
  host::apply(
      {.baud = 19200, .data_bits = 7, .par = host::parity::odd, .stop_bits = 2, .rts_cts = true},
      want);
  CHECK((want.c_cflag & CSIZE) == CS7);
  CHECK((want.c_cflag & PARENB) != 0U);
  CHECK((want.c_cflag & PARODD) != 0U);
  CHECK((want.c_cflag & CSTOPB) != 0U);
  CHECK((want.c_cflag & CRTSCTS) != 0U);
  CHECK((want.c_iflag & INPCK) != 0U);
  CHECK(::cfgetospeed(&want) == B19200);
  CHECK((want.c_lflag & (ECHO | ICANON)) == 0U);
  host::apply(host::pacontrol_line, want);
  CHECK((want.c_cflag & CSIZE) == CS7);
  CHECK((want.c_cflag & (PARENB | CSTOPB | CRTSCTS)) == 0U);
  CHECK(::cfgetospeed(&want) == B9600);
  host::apply({.data_bits = 8, .par = host::parity::even}, want);
  CHECK((want.c_cflag & CSIZE) == CS8);
  CHECK((want.c_cflag & (PARENB | PARODD)) == PARENB);

  // a pseudo-terminal takes the speed, the stop bits and raw mode (it has 8 data bits without
  // parity, whatever is asked); it can be opened again
  fieldcodec::test::pty_pair pty;
  REQUIRE(pty.ok());
  host::serial_port p;
  REQUIRE(p.open(
      pty.path(),
      {.baud = 19200, .data_bits = 7, .par = host::parity::odd, .stop_bits = 2, .rts_cts = true}));
  termios t{};
  REQUIRE(::tcgetattr(p.native_handle(), &t) == 0);
  CHECK((t.c_cflag & CSTOPB) != 0U);
  CHECK(::cfgetospeed(&t) == B19200);
  CHECK((t.c_lflag & ECHO) == 0U);
  CHECK((t.c_cflag & CSIZE) == CS8);
  p.close();
  REQUIRE(p.open(pty.path(), host::pacontrol_line));
  REQUIRE(p.open(pty.path(), host::pacontrol_line));

  // bytes both ways; a read times out when nothing comes
  REQUIRE(p.write(std::string_view("hello")));
  CHECK(pty.read_master(500) == "hello");
  pty.write_master("abc");
  std::array<std::uint8_t, 16> buf{};
  auto n = p.read(buf, 500ms);
  REQUIRE(n);
  CHECK(std::string(reinterpret_cast<const char *>(buf.data()), n.value()) == "abc");
  CHECK(p.read(buf, 20ms) == errc::timeout);
  CHECK(p.last_error().what == pty.path() + ": no answer in time");
  CHECK(p.read(std::span<std::uint8_t>(), 20ms) == errc::buffer_too_small);
  p.close();
  CHECK(p.write(std::string_view("x")) == errc::bad_state);
  CHECK(p.open("/nonexistent/tty", host::pacontrol_line) == errc::invalid_argument);
  CHECK(p.open(pty.path(), {.baud = 1}) == errc::invalid_argument);
}

TEST_CASE("PA-CONTROL link: request, acknowledgement, poll") {
  fieldcodec::test::pacontrol_peer peer(register_script);
  REQUIRE(peer.ok());
  host::pacontrol_link link;
  REQUIRE(link.open(peer.path()));

  const auto req = pa::make_request(cmds::cmd_get_int_reg, 12).value();
  auto ack = link.transact(req, 1000ms);
  REQUIRE(ack);
  CHECK(ack.value().command_error_number == 0);
  CHECK(ack.value().end_of_processing);
  CHECK(ack.value().operating_status == 31);
  CHECK(pa::reply_value(cmds::cmd_get_int_reg, ack.value()).value().number.mantissa == 4711);
  // the request went out as the manual's frame: SOH STX 1906;12;0;0 ETX check EOT
  const std::string sent(link.sent().begin(), link.sent().end());
  CHECK(sent.substr(0, 2) == "\x01\x02");
  CHECK(sent.substr(2, 11) == "1906;12;0;0");
  CHECK(peer.received().find("1906;12;0;0") != std::string::npos);

  ack = link.transact(pa::make_request(cmds::cmd_get_int_reg, 13).value(), 1000ms);
  REQUIRE(ack);
  CHECK(ack.value().command_error_number == 1);

  ack = link.poll(1000ms);
  REQUIRE(ack);
  CHECK(ack.value().operating_status == 31);
}

TEST_CASE("PA-CONTROL link: broken and missing answers are precise errors") {
  std::atomic<int> mode{0};
  fieldcodec::test::pacontrol_peer peer([&mode](const pa::serial::decoded_frame &) -> std::string {
    switch (mode) {
    case 0: return {}; // silence
    case 1:
      return "\x01\x02"
             "0;1;31;0;0;0\x03"
             "99\x04"; // wrong check
    case 2:
      return "\x01\x02"
             "0;1;31;0"; // cut short
    default:
      return "\x01\x02"
             "1906;12;0;0\x03"
             "0\x04"; // a request, not an answer
    }
  });
  REQUIRE(peer.ok());
  host::pacontrol_link link;
  REQUIRE(link.open(peer.path()));
  const auto req = pa::make_request(cmds::cmd_get_int_reg, 12).value();

  CHECK(link.transact(req, 100ms) == errc::timeout);
  CHECK(link.last_error().what == peer.path() + ": no acknowledgement in time");
  mode = 1;
  CHECK(link.transact(req, 1000ms) == errc::bad_checksum);
  CHECK(link.last_error().what == peer.path() + ": bad acknowledgement (bad checksum): "
                                                "<SOH><STX>0;1;31;0;0;0<ETX>99<EOT>");
  mode = 2;
  CHECK(link.transact(req, 200ms) == errc::timeout);
  CHECK(link.last_error().what == peer.path() + ": acknowledgement incomplete: <SOH><STX>0;1;31;0");
  mode = 3;
  CHECK(link.transact(req, 1000ms) == errc::unexpected_frame);
  // a date the command does not take cannot be sent
  pa::serial::request bad = req;
  bad.date.type = fieldcodec::od::command_value::none;
  CHECK(link.transact(bad, 100ms) == errc::invalid_argument);
}
