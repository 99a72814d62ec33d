// candump log lines: read, write, round trip, bad input (host/candump.hpp).
#include <fieldcodec/host/candump.hpp>

#include <doctest/doctest.h>

#include <string>

namespace host = fieldcodec::host;
namespace candump = fieldcodec::host::candump;
using fieldcodec::errc;

TEST_CASE("candump: a log line keeps time, interface and frame") {
  // The DPQ manual's event-timer write (004, CANopen chapter) as candump logs it.
  const auto r = candump::parse_line("(1700000000.123456) can0 605#2B00180564000000").value();
  CHECK(r.time.seconds == 1700000000);
  CHECK(r.time.fraction == 123456U);
  CHECK(r.time.digits == 6);
  CHECK(r.time.microseconds() == 1700000000123456);
  CHECK(r.iface.view() == "can0");
  CHECK(r.id == 0x605U);
  CHECK_FALSE(r.extended);
  CHECK_FALSE(r.rtr);
  CHECK(r.dlc == 8);
  CHECK(r.data[0] == 0x2B);
  CHECK(r.data[4] == 0x64);
  CHECK(candump::format_line(r) == "(1700000000.123456) can0 605#2B00180564000000");
  const auto f = host::to_canopen(r).value();
  CHECK(f.id == 0x605);
  CHECK(f.dlc == 8);

  // other fraction lengths are written back as read
  for (const char *line : {"(1.5) vcan0 000#0105", "(1700000000.000000001) can1 080#",
                           "(0.000100) x 7FF#0102030405060708"}) {
    CAPTURE(line);
    CHECK(candump::format_line(candump::parse_line(line).value()) == line);
  }
}

TEST_CASE("candump: compact notation, remote, extended and error frames") {
  auto r = candump::parse_frame("605#2B.00.18.05.64.00.00.00").value();
  CHECK(r.dlc == 8);
  CHECK(candump::format_frame(r) == "605#2B00180564000000");
  CHECK_FALSE(r.time.known());
  CHECK(candump::format_line(r) == "605#2B00180564000000");

  r = candump::parse_line("705#R").value();
  CHECK(r.rtr);
  CHECK(r.dlc == 0);
  CHECK(candump::format_frame(r) == "705#R");
  r = candump::parse_line("705#R1").value();
  CHECK(r.rtr);
  CHECK(r.dlc == 1);
  CHECK(candump::format_frame(r) == "705#R1");
  CHECK(host::to_canopen(r).value().rtr);

  r = candump::parse_line("0000FF05#11").value();
  CHECK(r.extended);
  CHECK(r.id == 0xFF05U);
  CHECK(candump::format_frame(r) == "0000FF05#11");
  CHECK(host::to_canopen(r) == errc::unexpected_frame);

  // bus-off with counters, as candump logs a SocketCAN error frame
  r = candump::parse_line("(1700000001.000000) can0 20000240#0000000000008000").value();
  CHECK(r.error);
  const auto e = host::decode_error(r).value();
  CHECK(e.is_bus_off());
  CHECK_FALSE(e.is_error_passive());
  CHECK(host::describe(e) == "bus-off, tx errors 128, rx errors 0");
  CHECK(candump::format_frame(r) == "20000240#0000000000008000");
  CHECK(host::to_canopen(r) == errc::unexpected_frame);
  r = candump::parse_line("20000004#0020000000000000").value();
  CHECK(host::decode_error(r).value().is_error_passive());
  CHECK(host::describe(host::decode_error(r).value()) == "error passive (tx)");
  CHECK(host::decode_error(candump::parse_line("605#").value()) == errc::unexpected_frame);
  CHECK(candump::parse_line("605#").value().dlc == 0);
}

TEST_CASE("candump: bad lines, each with its error") {
  CHECK(candump::parse_line("605") == errc::bad_syntax);
  CHECK(candump::parse_line("60#00") == errc::bad_syntax);   // 2 digits
  CHECK(candump::parse_line("6050#00") == errc::bad_syntax); // 4 digits
  CHECK(candump::parse_line("G05#00") == errc::bad_digit);
  CHECK(candump::parse_line("805#00") == errc::invalid_argument); // above 7FF
  CHECK(candump::parse_line("40000000#00") == errc::invalid_argument);
  CHECK(candump::parse_line("605#001") == errc::truncated);
  CHECK(candump::parse_line("605#001122334455667788") == errc::too_long);
  CHECK(candump::parse_line("605#0") == errc::truncated);
  CHECK(candump::parse_line("605#0G") == errc::bad_digit);
  CHECK(candump::parse_line("605#.00") == errc::bad_syntax);
  CHECK(candump::parse_line("605##100") == errc::unexpected_frame); // CAN FD
  CHECK(candump::parse_line("705#R9") == errc::bad_length);
  CHECK(candump::parse_line("705#RX") == errc::bad_digit);
  CHECK(candump::parse_line("705#R12") == errc::bad_syntax);
  CHECK(candump::parse_line("20000004#R") == errc::bad_syntax);
  CHECK(candump::parse_line("(1700000000.123456) can0") == errc::bad_syntax);
  CHECK(candump::parse_line("(1700000000.123456)") == errc::bad_syntax);
  CHECK(candump::parse_line("(1700000000.123456 can0 605#00") == errc::bad_syntax);
  CHECK(candump::parse_line("(17000x0000.1) can0 605#00") == errc::bad_digit);
  CHECK(candump::parse_line("(1.1234567890) can0 605#00") == errc::too_long);
  CHECK(candump::parse_line("(99999999999999999999.1) can0 605#00") == errc::overflow);
  CHECK(candump::parse_line("(.1) can0 605#00") == errc::bad_syntax);
  CHECK(candump::parse_line("(1.) can0 605#00") == errc::bad_syntax);
  CHECK(candump::parse_line("(1.1) averyveryverylongname 605#00") == errc::too_long);
  CHECK(candump::is_blank_or_comment(""));
  CHECK(candump::is_blank_or_comment("  \r"));
  CHECK(candump::is_blank_or_comment("# a comment"));
  CHECK_FALSE(candump::is_blank_or_comment("605#00"));
}

TEST_CASE("candump: every CANopen frame survives a write and a read") {
  for (unsigned dlc = 0; dlc <= 8; ++dlc) {
    fieldcodec::canopen::can_frame f;
    f.id = static_cast<std::uint16_t>(0x100 + dlc);
    f.dlc = static_cast<std::uint8_t>(dlc);
    for (unsigned i = 0; i < dlc; ++i) f.data[i] = static_cast<std::uint8_t>(0xA0 + i);
    const auto rec = host::to_record(f, host::timestamp::from_microseconds(1700000000000001),
                                     host::interface_name::make("can0").value());
    const std::string line = candump::format_line(rec);
    CAPTURE(line);
    const auto back = candump::parse_line(line).value();
    CHECK(back == rec);
    CHECK(host::to_canopen(back).value() == f);
  }
  CHECK(host::interface_name::make("can 0") == errc::bad_character);
  CHECK(host::interface_name::make("a/b") == errc::bad_character);
}

TEST_CASE("candump: the display format, with every time stamp option (issue 26)") {
  // `candump can0` without options
  auto r = candump::parse_line("  can0  605   [8]  2B 00 18 05 64 00 00 00").value();
  CHECK(r.iface.view() == "can0");
  CHECK(r.id == 0x605U);
  CHECK(r.dlc == 8U);
  CHECK(r.data[4] == 0x64U);
  CHECK_FALSE(r.time.known());
  // -ta: absolute
  r = candump::parse_line(" (1700000000.123456)  can0  705   [1]  05").value();
  CHECK(r.time.seconds == 1700000000);
  CHECK(r.time.fraction == 123456U);
  CHECK(candump::format_time(r.time) == "1700000000.123456");
  // -td / -tz: relative, as printed
  r = candump::parse_line(" (000.000250)  can0  705   [1]  05").value();
  CHECK(candump::format_time(r.time) == "0.000250");
  // -tA: a local date, written back as one
  r = candump::parse_line(" (2024-05-01 12:34:56.123456)  can0  705   [1]  05").value();
  CHECK(r.time.date);
  CHECK(candump::format_time(r.time) == "2024-05-01 12:34:56.123456");
  CHECK(candump::format_line(r) == "(2024-05-01 12:34:56.123456) can0 705#05");
  CHECK(candump::parse_line(candump::format_line(r)).value() == r);
  // 29-bit frames (SFF indented), remote requests, -x, -a, error frames with -e
  r = candump::parse_line("  can0  12345678   [2]  DE AD").value();
  CHECK(r.extended);
  CHECK(r.id == 0x12345678U);
  r = candump::parse_line("  can0       705   [1]  remote request").value();
  CHECK(r.rtr);
  CHECK(r.dlc == 1U);
  r = candump::parse_line(" (1700000000.000001)  can0  RX - -  185   [2]  37 06").value();
  CHECK(r.id == 0x185U);
  r = candump::parse_line("  can0  185   [2]  41 42                     'AB'").value();
  CHECK(r.data[1] == 0x42U);
  r = candump::parse_line("  can0  20000004   [8]  00 04 00 00 00 00 00 00   ERRORFRAME").value();
  CHECK(r.error);
  CHECK(candump::is_blank_or_comment("\tcontroller-problem{rx-error-passive}"));
  // the log format with candump -x's direction after the frame
  CHECK(candump::parse_line("(1700000000.000001) can0 185#3706 R").value().dlc == 2U);
}

TEST_CASE("candump: every bad line says what is wrong and where") {
  auto e = candump::parse_line("800#00").error();
  CHECK(e.code == errc::invalid_argument);
  CHECK(std::string_view(e.reason) == "11-bit identifier above 7FF");
  CHECK(e.column == 0U);
  e = candump::parse_line("(1.000000) can0 800#00").error();
  CHECK(std::string_view(e.reason) == "11-bit identifier above 7FF");
  CHECK(e.column == 16U);
  e = candump::parse_line("  can0  800   [1]  00").error();
  CHECK(std::string_view(e.reason) == "11-bit identifier above 7FF");
  CHECK(e.column == 8U);
  e = candump::parse_line("  can0  605   [12]  00 11 22 33 44 55 66 77 88 99 AA BB").error();
  CHECK(e.code == errc::unexpected_frame);
  e = candump::parse_line("  can0  605   [3]  00 11").error();
  CHECK(e.code == errc::truncated);
  CHECK(std::string_view(e.reason) == "fewer data bytes than the length says");
  e = candump::parse_line("  can0  605   [2]  00 1G").error();
  CHECK(e.code == errc::bad_digit);
  CHECK(e.column == 22U); // the byte "1G"
  e = candump::parse_line("  can0  605   [9]  00").error();
  CHECK(e.code == errc::bad_length);
  e = candump::parse_line("  can0  605   [1]  00 junk").error();
  CHECK(std::string_view(e.reason) == "unexpected text after the data");
  e = candump::parse_line("605#0011 junk").error();
  CHECK(std::string_view(e.reason) == "unexpected text after the frame");
  e = candump::parse_line("garbage").error();
  CHECK(e.code == errc::bad_syntax);
  CHECK(std::string_view(e.reason) == "no frame: ID#DATA expected");
  e = candump::parse_line("(2024-13-01 00:00:00.000000) can0 605#00").error();
  CHECK(e.code == errc::out_of_range);
}
