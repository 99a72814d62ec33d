// `fieldcodec decode`: golden tests over candump logs the tests make with the library (SDO
// client and server machines, the frame codecs), for every service and device family, with
// aborts, toggle errors, malformed frames and a truncated log. The logs and the outputs are
// kept in tests/cli/golden/; docs/cli.md quotes them (checked by docs_test.cpp).
#include "cli_support.hpp"

#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/sync.hpp>
#include <fieldcodec/canopen/time_stamp.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/dpq/emergency.hpp>
#include <fieldcodec/pacontrol/command.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>

#include <doctest/doctest.h>

#include <array>
#include <string>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
namespace t = fieldcodec::test;
using fieldcodec::byte_order;
using fieldcodec::to_bytes;

namespace {

constexpr auto xenax_layout =
    co::make_layout<fieldcodec::dictionaries::xenax_canopen::entries.size()>(
        fieldcodec::dictionaries::xenax_canopen::dictionary);
constexpr auto dpq_layout =
    co::make_layout<fieldcodec::dictionaries::dpq_parameters::entries.size()>(
        fieldcodec::dictionaries::dpq_parameters::dictionary);

template <class T>
std::vector<std::uint8_t> le(T v) {
  const auto a = to_bytes<T>(v, byte_order::little);
  return {a.begin(), a.end()};
}

/// A XENAX node 5 behind an SDO server, and a client talking to it; every frame logged.
struct xenax_bus {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(
      co::dictionary_store<>::storage_size(fieldcodec::dictionaries::xenax_canopen::dictionary));
  std::vector<std::uint8_t> staging = std::vector<std::uint8_t>(1024);
  co::dictionary_store<> store{fieldcodec::dictionaries::xenax_canopen::dictionary, xenax_layout,
                               storage, staging};
  std::array<std::uint8_t, 256> buffer{};
  sdo::server<co::dictionary_store<>> server{5, store, buffer};
  sdo::client client{5};
  std::array<std::uint8_t, 256> rx{};
  t::log_maker log;

  xenax_bus() {
    (void)store.init_defaults(5);
    const auto vendor = le<std::uint32_t>(0x0000012E);
    (void)store.set({0x1018, 1}, vendor);
  }
  void read(od::address a) { t::exchange(log, client, server, client.upload(a, rx, 0)); }
  void block_read(od::address a) {
    t::exchange(log, client, server, client.block_upload(a, rx, 0));
  }
  void write(od::address a, const std::vector<std::uint8_t> &v) {
    t::exchange(log, client, server, client.download(a, v, 0));
  }
  void block_write(od::address a, const std::vector<std::uint8_t> &v) {
    t::exchange(log, client, server, client.block_download(a, v, 0));
  }
};

std::string decode_golden(const std::string &name, const std::string &log,
                          std::vector<std::string> args, int expected_code = 0) {
  t::check_golden(name + ".log", log);
  args.insert(args.begin(), "decode");
  const auto r = t::run_cli(args, log);
  CHECK(r.err == "");
  CHECK(r.code == expected_code);
  t::check_golden(name + ".txt", r.out);
  return r.out;
}

} // namespace

TEST_CASE("decode: NMT, SYNC, TIME, EMCY, heartbeat, guarding, errors, malformed, truncated") {
  t::log_maker log;
  log.line("# made by tests/cli/decode_test.cpp");
  log.add(co::nmt::encode(co::nmt::command::reset_communication, 0));
  log.add(co::nmt::encode_boot_up(5));
  log.add(co::nmt::encode(co::nmt::command::start, 5));
  log.add(co::sync::encode());
  log.add(co::sync::encode(3));
  log.add(co::time_stamp::encode({12 * 3600000U + 34 * 60000U + 56789U, 14610}));
  log.add(co::nmt::encode_heartbeat(5, co::nmt::state::operational));
  log.add(co::emcy::encode(5, {co::emcy::code::life_guard_error, 0x11, {}}));
  log.add(co::emcy::encode(5, {0x0000, 0x00, {}}));
  log.add(co::emcy::encode(5, {0xFF01, 0x81, {1, 2, 3, 0, 0}}));
  // node guarding: request, two responses, a third with the same toggle
  log.add(co::nmt::encode_guard_request(6));
  log.add(co::nmt::encode_guard_response(6, co::nmt::state::pre_operational, false));
  log.add(co::nmt::encode_guard_request(6));
  log.add(co::nmt::encode_guard_response(6, co::nmt::state::pre_operational, true));
  log.add(co::nmt::encode_guard_request(6));
  log.add(co::nmt::encode_guard_response(6, co::nmt::state::pre_operational, true));
  // without a dictionary: PDO bytes as they are
  log.add(co::make_frame(0x185, {0x37, 0x06}));
  log.add(co::make_remote_frame(0x285, 0));
  // not CANopen: an extended frame, a controller error frame, an unassigned identifier
  log.frame("12345678#DEADBEEF");
  log.frame("20000240#0000000000008000");
  log.frame("20000004#0020000000000000");
  log.add(co::make_frame(0x7FF, {0x01}));
  // malformed frames: a heartbeat with 2 bytes, an NMT with an unknown command, an EMCY of 4
  log.add(co::make_frame(0x705, {0x05, 0x00}));
  log.add(co::make_frame(0x000, {0x07, 0x05}));
  log.add(co::make_frame(0x085, {0x00, 0x10, 0x01, 0x00}));
  log.add(co::make_frame(0x705, {0x03}));
  // lines that are no frames, and a log cut off in the middle of a line
  log.frame("605#2B0018056400000000");
  log.frame("6O5#00");
  log.line("garbage");
  log.frame("605#2B00");
  log.frame("605#2B0");
  log.text.pop_back(); // the last line has no end
  decode_golden("services", log.text, {}, 4);

  const auto json = t::run_cli({"decode", "--json"}, log.text);
  CHECK(json.code == 4);
  t::check_golden("services.jsonl", json.out);
  t::check_json_lines(json.out);
}

TEST_CASE("decode: SDO transfers of a XENAX drive with its EDS, PDOs, CiA 402") {
  xenax_bus bus;
  bus.log.line("# XENAX node 5, SDO client and server of fieldcodec");
  bus.read({0x1018, 1});                             // expedited upload
  bus.read({0x1008, 0});                             // segmented upload
  bus.block_read({0x1008, 0});                       // block upload
  bus.write({0x6060, 0}, {0x01});                    // modes of operation: profile position
  bus.write({0x6040, 0}, le<std::uint16_t>(0x0006)); // shutdown
  bus.write({0x6040, 0}, le<std::uint16_t>(0x0007)); // switch on
  bus.write({0x6040, 0}, le<std::uint16_t>(0x000F)); // enable operation
  (void)bus.store.set({0x6041, 0}, le<std::uint16_t>(0x0637));
  bus.read({0x6041, 0});                            // operation enabled
  bus.write({0x6073, 0}, le<std::uint16_t>(150));   // 1.5 A in 10 mA steps
  bus.write({0x607A, 0}, le<std::int32_t>(-20000)); // target position, increments
  bus.block_write({0x607A, 0}, le<std::int32_t>(20000));
  bus.read({0x1234, 0});                        // no such object: abort
  bus.write({0x1018, 1}, le<std::uint32_t>(1)); // read-only: abort
  bus.write({0x6081, 0}, le<std::uint32_t>(1)); // below the low limit (10): abort
  // TPDO2 mapped by the log's own SDO writes: statusword + position actual value
  bus.write({0x1A01, 0}, {0x00});
  bus.write({0x1A01, 1}, le<std::uint32_t>(0x60410010));
  bus.write({0x1A01, 2}, le<std::uint32_t>(0x60640020));
  bus.write({0x1A01, 0}, {0x02});
  bus.log.add(co::make_frame(0x285, {0x37, 0x06, 0x20, 0x4E, 0x00, 0x00}));
  // RPDO1 and TPDO1 by the EDS defaults: controlword, statusword
  bus.log.add(co::make_frame(0x205, {0x0F, 0x00}));
  bus.log.add(co::make_frame(0x185, {0x08, 0x02}));
  bus.log.add(co::make_frame(0x205, {0x80, 0x00}));
  bus.log.add(co::make_frame(0x185, {0x37})); // too short for its mapping
  // a segmented upload whose server repeats a toggle: the client aborts (05030000h)
  {
    std::array<std::uint8_t, 64> rx{};
    sdo::client c(5);
    auto s = c.upload({0x1008, 0}, rx, 0).value();
    bus.log.add(s.send[0]);
    const auto ch = sdo::channel::default_for(5).value();
    auto answer = [&](const sdo::payload &p) {
      const auto f = ch.response(p);
      bus.log.add(f);
      for (const auto &g : c.on_frame(f, 0).send) bus.log.add(g);
    };
    answer(sdo::upload_response({0x1008, 0}, 14));
    const std::uint8_t part[] = {'X', 'E', 'N', 'A', 'X', ' ', 'X'};
    answer(sdo::upload_segment(false, part, false).value());
    answer(sdo::upload_segment(false, part, false).value()); // toggle 0 again
  }
  const std::string eds = "../dictionaries/xenax_canopen.eds";
  decode_golden("xenax", bus.log.text, {"--dict", "5=" + eds});
  // the same log read from its file
  const auto from_file = t::run_cli({"decode", "cli/golden/xenax.log", "--dict", "5=" + eds});
  CHECK(from_file.code == 0);
  CHECK(from_file.out == t::read_text("cli/golden/xenax.txt"));
  // the same log without the dictionary: objects by address, values raw
  const auto bare = t::run_cli({"decode"}, bus.log.text);
  CHECK(bare.code == 0);
  t::check_golden("xenax-no-dictionary.txt", bare.out);
  const auto json = t::run_cli({"decode", "--json", "--dict", eds}, bus.log.text);
  CHECK(json.code == 0);
  t::check_golden("xenax.jsonl", json.out);
  t::check_json_lines(json.out);
  // every SDO frame on its own line as well
  const auto frames = t::run_cli({"decode", "--sdo-frames", "--dict", eds}, bus.log.text);
  CHECK(frames.code == 0);
  t::check_golden("xenax-sdo-frames.txt", frames.out);
}

TEST_CASE("decode: DPQ parameters in engineering units, DPQ EMCY codes") {
  std::vector<std::uint8_t> storage(
      co::dictionary_store<>::storage_size(fieldcodec::dictionaries::dpq_parameters::dictionary));
  co::dictionary_store<> store{fieldcodec::dictionaries::dpq_parameters::dictionary, dpq_layout,
                               storage};
  (void)store.init_defaults(3);
  std::array<std::uint8_t, 64> buffer{};
  sdo::server<co::dictionary_store<>> server{3, store, buffer};
  sdo::client client{3};
  std::array<std::uint8_t, 64> rx{};
  t::log_maker log;
  log.line("# DPQ node 3: Inj P Limit 1 (2023h) in bar, scale 327.67 raw per bar");
  // 4.0 bar → raw 1311 (manual 004; dpq::inj_p_limit_1.to_raw(4.0))
  const auto raw = le<std::uint32_t>(1311);
  t::exchange(log, client, server, client.download({0x2023, 0}, raw, 0));
  t::exchange(log, client, server, client.upload({0x2023, 0}, rx, 0));
  t::exchange(log, client, server, client.upload({0x2C69, 0}, rx, 0));
  log.add(co::emcy::encode(
      3, {static_cast<std::uint16_t>(fieldcodec::dpq::emcy_code::pressure_monitor), 0x81, {}}));
  log.add(co::emcy::encode(
      3, {static_cast<std::uint16_t>(fieldcodec::dpq::emcy_code::no_error), 0x00, {}}));
  // Analog Vel Max in mm/s: raw 16383 at 327.67 raw per mm/s
  const auto vmax = le<std::uint32_t>(16383);
  t::exchange(log, client, server, client.download({0x2C69, 0}, vmax, 0));
  decode_golden("dpq", log.text, {"--dict", "3=../dictionaries/dpq_parameters.csv"});
}

TEST_CASE("decode: a log that ends inside an SDO transfer") {
  xenax_bus bus;
  bus.read({0x1008, 0});
  // keep only the first three frames of the segmented upload
  const auto lines = fieldcodec::cli::split_lines(bus.log.text);
  std::string cut;
  for (std::size_t i = 0; i < 3; ++i) cut += std::string(lines[i]) + "\n";
  decode_golden("truncated-transfer", cut, {"--dict", "../dictionaries/xenax_canopen.eds"}, 4);
}

TEST_CASE("decode: PA-CONTROL captures, raw and hex") {
  namespace pa = fieldcodec::pacontrol;
  namespace cmds = fieldcodec::dictionaries::pacontrol_commands;
  std::string capture;
  auto put = [&capture](const fieldcodec::result<std::size_t> &n,
                        const std::array<std::uint8_t, pa::serial::max_frame_size> &b) {
    capture.append(reinterpret_cast<const char *>(b.data()), n.value());
  };
  std::array<std::uint8_t, pa::serial::max_frame_size> b{};
  // read register N12 → 4711
  put(pa::serial::encode_request(pa::make_request(cmds::cmd_get_int_reg, 12).value(), b), b);
  pa::serial::acknowledgement a{0, true, 31, 0, pa::value::of_int(4711).value()};
  put(pa::serial::encode_acknowledgement(a, b), b);
  // write axis parameter 1/5 = 200.0 (a real date)
  put(pa::serial::encode_request(pa::make_request(cmds::cmd_set_axis_parameter, 0x0105,
                                                  pa::value::of_real({2000, 1}).value())
                                     .value(),
                                 b),
      b);
  a = {0, true, 1, 0, pa::value::of_real({2000, 1}).value()};
  put(pa::serial::encode_acknowledgement(a, b), b);
  // the poll and the answer with a command error and a PA-CONTROL error
  capture += '\x04';
  a = {19, true, 1, 205, pa::value::of_int(0).value()};
  put(pa::serial::encode_acknowledgement(a, b), b);
  // "0" instead of the check
  put(pa::serial::encode_request(pa::make_request(cmds::cmd_get_state).value(), b,
                                 pa::serial::check_rule::body, pa::serial::check_mode::unchecked),
      b);
  // a wrong check, noise, a frame cut short by the next, and a capture that ends in a frame
  capture += std::string("\x01\x02"
                         "1906;12;0;0\x03"
                         "99\x04",
                         17);
  capture += "xyz";
  capture += std::string("\x01\x02"
                         "1906;1",
                         8);
  put(pa::serial::encode_request(pa::make_request(cmds::cmd_get_int_reg, 1).value(), b), b);
  capture += std::string("\x01\x02"
                         "0;1;31",
                         8);
  t::check_golden("pacontrol.bin", capture);
  auto r = t::run_cli({"decode", "--pacontrol"}, capture);
  CHECK(r.code == 4);
  CHECK(r.err == "");
  t::check_golden("pacontrol.txt", r.out);
  // the same as hex text
  std::string hex;
  for (std::size_t i = 0; i < capture.size(); ++i) {
    hex += fieldcodec::cli::hex_bytes(
        std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t *>(&capture[i]), 1));
    hex += (i % 16U == 15U) ? "\n" : " ";
  }
  const auto h = t::run_cli({"decode", "--pacontrol"}, hex);
  CHECK(h.code == 4);
  CHECK(h.out == r.out);
  const auto j = t::run_cli({"decode", "--pacontrol", "--json"}, capture);
  t::check_golden("pacontrol.jsonl", j.out);
  // bad hex
  const auto bad = t::run_cli({"decode", "--pacontrol", "--hex"}, "01 02 3G\n");
  CHECK(bad.code == 4);
  CHECK(bad.err == "fieldcodec: decode: -: line 1: not hex: '3G'\n");
}

TEST_CASE("decode: command line errors") {
  auto r = t::run_cli({"decode", "--dict", "nosuch.eds"});
  CHECK(r.code == 5);
  CHECK(r.err == "fieldcodec: decode: nosuch.eds: error: cannot open file\n");
  r = t::run_cli({"decode", "--dict", "200=x.eds"});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: decode: bad node in --dict 200=x.eds (try 'fieldcodec decode "
                 "--help')\n");
  r = t::run_cli({"decode", "nosuch.log"});
  CHECK(r.code == 3);
  CHECK(r.err == "fieldcodec: decode: nosuch.log: cannot open\n");
  r = t::run_cli({"decode", "--device", "5=robot"});
  CHECK(r.code == 2);
  r = t::run_cli({"decode", "--frobnicate"});
  CHECK(r.code == 2);
  CHECK(r.err == "fieldcodec: decode: unknown option --frobnicate (try 'fieldcodec decode "
                 "--help')\n");
  r = t::run_cli({"decode", "--hex"});
  CHECK(r.code == 2);
  r = t::run_cli({"decode", "--dict", "../dictionaries/pacontrol_commands.csv"});
  CHECK(r.code == 5);
  CHECK(r.err.find("a command table, not an object dictionary") != std::string::npos);
}
