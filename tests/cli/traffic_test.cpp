// `fieldcodec decode` on the devices' own traffic (issue 26, section 2): each case a defect of the
// decoder as it was, with the input that showed it. Frames are written by hand as the devices
// send them (the DPQ manual's SDO forms, a XENAX with a longer name than its EDS default, two
// interfaces in one `candump -l any` log, candump's display formats, bad input of every kind).
#include "cli_support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <string>

namespace t = fieldcodec::test;

namespace {
const std::string xenax_eds = "../dictionaries/xenax_canopen.eds";
const std::string dpq_csv = "../dictionaries/dpq_parameters.csv";

/// The description of each output line: what follows TIME IFACE ID FUNCTION (and "node N: ").
std::vector<std::string> texts(const std::string &out) {
  std::vector<std::string> v;
  for (const auto l : fieldcodec::cli::split_lines(out)) {
    std::string_view rest = l;
    for (int field = 0; field < 4; ++field) { // time, interface, identifier, function
      rest.remove_prefix(std::min(rest.find(' '), rest.size()));
      while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    }
    if (rest.rfind("node ", 0) == 0) rest.remove_prefix(rest.find(": ") + 2U);
    v.emplace_back(rest);
  }
  return v;
}
} // namespace

TEST_CASE("expedited SDO without the size: the object's type decides (0x22, 0x42)") {
  t::log_maker log;
  // DPQ manual, 3.2 "Client → Server Download Request": command 0x22, 4 data bytes
  log.frame("603#229C2100E9030000"); // 219Ch BackP: Decomp Rate 2, UNSIGNED16, scale 10.5
  log.frame("583#609C210000000000");
  // an upload answer 0x42 with a stray byte beyond the UNSIGNED16
  log.frame("603#409C210000000000");
  log.frame("583#429C2100E9030100");
  // XENAX 1017h (UNSIGNED16, ms) and 6040h without a dictionary
  log.frame("605#22171000E8030000");
  log.frame("585#6017100000000000");
  log.frame("606#2240600006000000");
  log.frame("586#6040600000000000");
  const auto r =
      t::run_cli({"decode", "--dict", "3=" + dpq_csv, "--dict", "5=" + xenax_eds}, log.text);
  CHECK(r.err == "");
  CHECK(r.code == 0); // decoded, with a note (exit 4 is for input that could not be decoded)
  const auto v = texts(r.out);
  REQUIRE(v.size() == 4);
  // was: 0x000003E9 (1001) (4 bytes, UNSIGNED16 has 2), unscaled
  CHECK(v[0] == "write 219Ch:00 BackP: Decomp Rate 2 = 95.33 (raw 1001)");
  CHECK(v[1] == "read 219Ch:00 BackP: Decomp Rate 2 = 95.33 (raw 1001) (size not indicated; the "
                "bytes beyond the 2 of UNSIGNED16 are not zero: 01 00)");
  CHECK(v[2] == "write 1017h:00 Producer Heartbeat Time = 1000");
  CHECK(v[3] == "write 6040h:00 = 0x0006 (shutdown)");
  const auto j = t::run_cli({"decode", "--json", "--dict", "3=" + dpq_csv}, log.text);
  t::check_json_lines(j.out);
  CHECK(j.out.find("\"value\":95.33,\"raw\":1001,\"transfer\":\"expedited\",\"size\":2,"
                   "\"size_indicated\":false}") != std::string::npos);
}

TEST_CASE("a VISIBLE_STRING longer than the EDS default is text, in JSON too") {
  // XENAX 1008h: the EDS default has 30 characters, this drive's name 36
  const std::string name = "Servocontroller XENAX Xvi 75V8 CAN-1";
  t::log_maker log;
  log.frame("605#4008100000000000");
  log.frame("585#4108100024000000"); // segmented, 36 bytes
  bool toggle = false;
  for (std::size_t at = 0; at < name.size(); at += 7U) {
    const std::string part = name.substr(at, 7);
    const bool last = at + 7U >= name.size();
    log.frame(std::string("605#") + (toggle ? "70" : "60") + "00000000000000");
    std::uint8_t cs = static_cast<std::uint8_t>((toggle ? 0x10U : 0U) | ((7U - part.size()) << 1U) |
                                                (last ? 1U : 0U));
    std::string data = fieldcodec::cli::hex_bytes(
        std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t *>(part.data()),
                                      part.size()),
        "");
    data.append(2U * (7U - part.size()), '0');
    log.frame("585#" + fieldcodec::cli::hex_bytes(std::span<const std::uint8_t>(&cs, 1), "") +
              data);
    toggle = !toggle;
  }
  auto r = t::run_cli({"decode", "--dict", "5=" + xenax_eds}, log.text);
  CHECK(r.code == 0);
  CHECK(texts(r.out).at(0) ==
        "read 1008h:00 Manufacturer Device Name = \"" + name + "\" [segmented, 36 bytes]");
  r = t::run_cli({"decode", "--json", "--dict", "5=" + xenax_eds}, log.text);
  t::check_json_lines(r.out);
  CHECK(r.out.find("\"value\":\"" + name + "\"") != std::string::npos);
}

TEST_CASE("candump -l any: the same node on two interfaces keeps two transfers") {
  t::log_maker log;
  // node 5 on can0 starts a segmented upload of 1008h; node 5 on can1 reads 1018h:01 between
  log.line("(1700000000.000100) can0 605#4008100000000000");
  log.line("(1700000000.000200) can0 585#410810000A000000");
  log.line("(1700000000.000300) can1 605#4018100100000000");
  log.line("(1700000000.000400) can0 605#6000000000000000");
  log.line("(1700000000.000500) can1 585#431810012E010000");
  log.line("(1700000000.000600) can0 585#0058454E41582058");
  log.line("(1700000000.000700) can0 605#7000000000000000");
  log.line("(1700000000.000800) can0 585#1976693100000000");
  const auto r = t::run_cli({"decode", "--dict", "5=" + xenax_eds}, log.text);
  CHECK(r.err == "");
  CHECK(r.code == 0); // was: "transfer interrupted by a new request", exit 4
  CHECK(r.out ==
        "1700000000.000500 can1 585 SDO       node 5: read 1018h:01 Identity Object: Vendor "
        "Id = 0x0000012E\n"
        "1700000000.000800 can0 585 SDO       node 5: read 1008h:00 Manufacturer Device "
        "Name = \"XENAX Xvi1\" [segmented, 10 bytes]\n");
  // --iface keeps one interface
  const auto only = t::run_cli({"decode", "--iface", "can1", "--dict", "5=" + xenax_eds}, log.text);
  CHECK(only.out == "1700000000.000500 can1 585 SDO       node 5: read 1018h:01 Identity Object: "
                    "Vendor Id = 0x0000012E\n");
}

TEST_CASE("candump's display formats decode like its log (candump can0 | fieldcodec decode)") {
  const std::string plain = "  can0  705   [1]  05\n"
                            "  can0  185   [2]  37 06\n";
  const std::string ta = " (1700000000.000250)  can0  705   [1]  05\n"
                         " (1700000000.000500)  can0  185   [2]  37 06\n";
  const std::string tA = " (2023-11-14 22:13:20.000250)  can0  705   [1]  05\n";
  const std::string tz = " (000.000000)  can0  705   [1]  05\n"
                         " (000.000250)  can0  185   [2]  37 06\n";
  const std::string x = " (1700000000.000250)  can0  RX - -  705   [1]  05\n";
  auto r = t::run_cli({"decode", "--dict", "5=" + xenax_eds}, plain);
  CHECK(r.code == 0);
  CHECK(r.out == "can0 705 HEARTBEAT node 5: operational\n"
                 "can0 185 TPDO1     node 5: Statusword = 0x0637 (operation enabled, target "
                 "reached)\n");
  r = t::run_cli({"decode", "--dict", "5=" + xenax_eds}, ta);
  CHECK(r.out == "1700000000.000250 can0 705 HEARTBEAT node 5: operational\n"
                 "1700000000.000500 can0 185 TPDO1     node 5: Statusword = 0x0637 (operation "
                 "enabled, target reached)\n");
  t::check_golden("candump-display.txt", r.out);
  r = t::run_cli({"decode"}, tA);
  CHECK(r.out == "2023-11-14 22:13:20.000250 can0 705 HEARTBEAT node 5: operational\n");
  r = t::run_cli({"decode"}, tz);
  CHECK(r.out.rfind("0.000000 can0 705 HEARTBEAT", 0) == 0);
  r = t::run_cli({"decode"}, x);
  CHECK(r.out == "1700000000.000250 can0 705 HEARTBEAT node 5: operational\n");
  // candump -e's explanation lines after an error frame are skipped
  r = t::run_cli({"decode"}, "  can0  20000004   [8]  00 10 00 00 00 00 00 00   ERRORFRAME\n"
                             "\tcontroller-problem{rx-error-passive}\n");
  CHECK(r.out == "can0 20000004 CAN-ERROR error passive (rx)\n");
}

TEST_CASE("bad input: precise messages, a BOM, bytes that are no UTF-8, long lines") {
  auto r = t::run_cli({"decode"}, "800#00\n");
  CHECK(r.code == 4);
  CHECK(r.out == "-   MALFORMED line 1: 11-bit identifier above 7FF at column 1: \"800#00\"\n");
  // a UTF-8 BOM before the first line (an editor saved the log)
  r = t::run_cli({"decode"}, "\xEF\xBB\xBF(1700000000.000250) can0 705#05\n");
  CHECK(r.code == 0);
  CHECK(r.out == "1700000000.000250 can0 705 HEARTBEAT node 5: operational\n");
  // bytes that are no UTF-8 never go raw into JSON
  r = t::run_cli({"decode", "--json"}, "6\xFF\xFE#00\n");
  CHECK(r.code == 4);
  t::check_json_lines(r.out);
  CHECK(r.out.find("\"input\":\"6\\u00FF\\u00FE#00\"") != std::string::npos);
  // a 1 MB line is echoed in part
  const std::string huge(1U << 20U, 'x');
  r = t::run_cli({"decode"}, huge + "\n");
  CHECK(r.code == 4);
  CHECK(r.out.size() < 400U);
  CHECK(r.out.find("… (1048576 characters)") != std::string::npos);
  r = t::run_cli({"decode", "--json"}, huge + "\n");
  t::check_json_lines(r.out);
  CHECK(r.out.size() < 800U);
  // DROPCOUNT lines of candump -d are shown as a note, not as a broken line
  r = t::run_cli({"decode"}, "DROPCOUNT: dropped 3 CAN frames on 'can0' socket (total drops 3)\n");
  CHECK(r.code == 0);
  CHECK(r.out == "-   NOTE      candump: DROPCOUNT: dropped 3 CAN frames on 'can0' socket (total "
                 "drops 3)\n");
  // an EDS whose first section is not closed says so (it said "got an empty file")
  t::write_text("cli_unterminated.eds", "[1000\nParameterName=Device Type\n");
  r = t::run_cli({"decode", "--dict", "cli_unterminated.eds"}, "");
  std::remove("cli_unterminated.eds");
  CHECK(r.code == 5);
  CHECK(r.err == "fieldcodec: decode: cli_unterminated.eds:1:6: error: expected ']' to end "
                 "section name '1000' (the section header is not closed)\n");
}

TEST_CASE("LSS, TIME as a date, CiA 402 statusword bits and EMCY codes by name") {
  t::log_maker log;
  log.frame("7E5#0401000000000000"); // switch state global: configuration
  log.frame("7E5#1105000000000000"); // configure node-ID 5
  log.frame("7E4#1100000000000000"); // ok
  log.frame("7E5#1300020000000000"); // bit timing table 0 index 2: 500 kbit/s
  log.frame("7E4#1301000000000000"); // error 1
  log.frame("7E5#5A00000000000000"); // inquire vendor-ID
  log.frame("7E4#5A2E010000000000"); // = 0x0000012E
  log.frame("7E5#5E00000000000000");
  log.frame("7E4#5E05000000000000");
  log.frame("7E5#5112345678800000"); // fastscan reset
  log.frame("7E5#0400000000000000");
  log.frame("100#952CB3028B39"); // 2024-05-01 12:34:56.789
  // profile position: set-point acknowledge (bit 12) and following error (bit 13)
  log.frame("605#2F60600001000000");
  log.frame("585#6060600000000000");
  log.frame("605#4041600000000000");
  log.frame("585#4B41600037360000"); // 0x3637
  log.frame("085#1186110000000000"); // EMCY 8611h following error
  log.frame("085#10FF810000000000"); // EMCY FF10h: XENAX error 16
  const auto r = t::run_cli({"decode", "--dict", "5=" + xenax_eds}, log.text);
  CHECK(r.err == "");
  t::check_golden("lss-time-402.txt", r.out);
  const auto v = texts(r.out);
  REQUIRE(v.size() == 16U);
  CHECK(v[0] == "master: switch state global: configuration");
  CHECK(v[1] == "master: configure node-ID 5");
  CHECK(v[2] == "slave: configure node-ID: ok");
  CHECK(v[3] == "master: configure bit timing: table 0, index 2 (500 kbit/s)");
  CHECK(v[4] == "slave: configure bit timing: error 1");
  CHECK(v[6] == "slave: inquire vendor-ID = 0x0000012E");
  CHECK(v[8] == "slave: inquire node-ID = 5");
  CHECK(v[9] == "master: fastscan: IDNumber 0x78563412, reset, LSS sub 0, next 0");
  CHECK(v[11] == "2024-05-01T12:34:56.789 (day 14731 after 1984-01-01, 45296789 ms after "
                 "midnight)");
  CHECK(v[13] == "read 6041h:00 Statusword = 0x3637 (operation enabled, target reached, "
                 "set-point acknowledge, following error)");
  CHECK(v[14] == "8611h following error (monitoring), error register 11h (generic, "
                 "communication)");
  CHECK(v[15] == "FF10h XENAX error 16 (text in 5020h TES) (device specific), error register 81h "
                 "(generic, manufacturer)");
  const auto j = t::run_cli({"decode", "--json", "--dict", "5=" + xenax_eds}, log.text);
  t::check_json_lines(j.out);
}

TEST_CASE("PA-CONTROL: the manual's 3.4.3 acknowledgement, the check rule option") {
  // 001, 3.4.3 command 1 "start online mode": the request's check follows the body rule, the
  // acknowledgement's (8) too — not the body+ETX rule of the manual's other acknowledgements
  const std::string capture = "01 02 30 36 30 33 3B 30 3B 30 3B 30 03 31 34 04\n"
                              "01 02 30 3B 31 3B 33 31 3B 30 3B 30 3B 30 03 38 04\n";
  auto r = t::run_cli({"decode", "--pacontrol"}, capture);
  CHECK(r.code == 0); // was: check 8 WRONG, exit 4
  CHECK(r.out.find("check 8 ok (the other rule)") != std::string::npos);
  CHECK(r.out.find("check 14 ok\n") != std::string::npos); // the request, the manual's rule
  r = t::run_cli({"decode", "--pacontrol", "--check-rule", "manual"}, capture);
  CHECK(r.code == 4);
  CHECK(r.out.find("check 8 WRONG (body 8, body+ETX 11)") != std::string::npos);
  r = t::run_cli({"decode", "--pacontrol", "--check-rule", "body"}, capture);
  CHECK(r.code == 0);
  CHECK(r.out.find("check 8 ok\n") != std::string::npos);
  r = t::run_cli({"decode", "--pacontrol", "--check-rule", "sometimes"}, capture);
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: decode: bad --check-rule sometimes (manual, either, body, body+etx) "
                 "(try 'fieldcodec decode --help')\n");
}
