// slcan: the line codec, and the bus over a pseudo-terminal with a fieldcodec CANopen node on
// the other side; the blocking SDO layer (host/sdo.hpp) over it.
#include "peers.hpp"

#include <fieldcodec/host/sdo.hpp>
#include <fieldcodec/host/slcan.hpp>

#include <doctest/doctest.h>

#include <string>
#include <vector>

namespace co = fieldcodec::canopen;
namespace host = fieldcodec::host;
namespace slcan = fieldcodec::host::slcan;
using fieldcodec::errc;
using namespace std::chrono_literals;

TEST_CASE("slcan: frames as lines") {
  const auto f = co::make_frame(0x605, {0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}).value();
  CHECK(slcan::encode(f).value().view() == "t60582B00180564000000\r");
  CHECK(slcan::encode(co::make_remote_frame(0x705, 1).value()).value().view() == "r7051\r");
  CHECK(slcan::encode(co::make_frame(0x080, {}).value()).value().view() == "t0800\r");
  co::can_frame bad = f;
  bad.id = 0x800;
  CHECK(slcan::encode(bad) == errc::invalid_argument);
  bad = f;
  bad.dlc = 9;
  CHECK(slcan::encode(bad) == errc::bad_length);

  auto l = slcan::decode("t60582B00180564000000").value();
  CHECK(l.kind == slcan::line_kind::frame);
  CHECK(host::to_canopen(l.record).value() == f);
  // with the adapter's millisecond timestamp (Z1)
  l = slcan::decode("t60582B00180564000000EA60").value();
  CHECK(host::to_canopen(l.record).value() == f);
  l = slcan::decode("r7051").value();
  CHECK(l.record.rtr);
  CHECK(l.record.dlc == 1);
  l = slcan::decode("T0000FF052AABB").value();
  CHECK(l.record.extended);
  CHECK(l.record.id == 0xFF05U);
  CHECK(l.record.dlc == 2);
  CHECK(slcan::decode("").value().kind == slcan::line_kind::ok);
  CHECK(slcan::decode("z").value().kind == slcan::line_kind::transmitted);
  CHECK(slcan::decode("Z").value().kind == slcan::line_kind::transmitted);
  l = slcan::decode("F20").value();
  CHECK(l.kind == slcan::line_kind::status);
  CHECK(l.status == slcan::status_flags::error_passive);
  CHECK(slcan::decode("V1013").value().kind == slcan::line_kind::other);
  CHECK(slcan::decode("O").value().kind == slcan::line_kind::other);

  CHECK(slcan::decode("t60") == errc::truncated);
  CHECK(slcan::decode("t6058") == errc::truncated);
  CHECK(slcan::decode("t60582B0018056400000") == errc::truncated);
  CHECK(slcan::decode("t6059") == errc::bad_length);
  CHECK(slcan::decode("t605X") == errc::bad_digit);
  CHECK(slcan::decode("tG0500") == errc::bad_digit);
  CHECK(slcan::decode("t8050") == errc::invalid_argument);
  CHECK(slcan::decode("T300000000") == errc::invalid_argument);
  CHECK(slcan::decode("t6051001") == errc::bad_length); // one stray digit after the data
  CHECK(slcan::decode("t605100GGGG") == errc::bad_digit);
  CHECK(slcan::decode("FXX") == errc::bad_digit);

  CHECK(slcan::bitrate_code(500000).value() == '6');
  CHECK(slcan::bitrate_code(10000).value() == '0');
  CHECK(slcan::bitrate_code(1000000).value() == '8');
  CHECK(slcan::bitrate_code(800000).value() == '7');
  CHECK(slcan::bitrate_code(750000) == errc::invalid_argument);
}

TEST_CASE("slcan bus over a pseudo-terminal: open, SDO read and write, NMT") {
  fieldcodec::test::slcan_node node;
  REQUIRE(node.ok());
  const std::uint8_t vendor[] = {0x78, 0x56, 0x34, 0x12};
  node.set({0x1018, 1}, vendor);

  host::slcan_bus bus;
  REQUIRE(bus.open(node.path(), 500000));
  CHECK(bus.name() == node.path());

  // expedited upload
  host::sdo_session s(bus, 5, {.timeout = 2000ms});
  auto v = s.read({0x1018, 1});
  REQUIRE(v);
  CHECK(std::vector<std::uint8_t>(v.value().begin(), v.value().end()) ==
        std::vector<std::uint8_t>{0x78, 0x56, 0x34, 0x12});
  // segmented upload of a string
  v = s.read({0x1008, 0});
  REQUIRE(v);
  CHECK(std::string(v.value().begin(), v.value().end()) == "Servocontroller XENAX Xvi xxVx");
  // expedited download, read back
  const std::uint8_t hb[] = {0xE8, 0x03};
  REQUIRE_MESSAGE(s.write({0x6040, 0}, hb), s.last_error().what);
  CHECK(node.value({0x6040, 0}) == std::vector<std::uint8_t>{0xE8, 0x03});
  // block upload
  host::sdo_session b(bus, 5, {.timeout = 2000ms, .block = true});
  v = b.read({0x1008, 0});
  REQUIRE(v);
  CHECK(std::string(v.value().begin(), v.value().end()) == "Servocontroller XENAX Xvi xxVx");
  REQUIRE(b.write({0x6040, 0}, hb));

  // the one-shot forms
  auto bytes = host::sdo_read(bus, 5, {0x1018, 1}, 2000ms);
  REQUIRE(bytes);
  CHECK(bytes.value() == std::vector<std::uint8_t>{0x78, 0x56, 0x34, 0x12});
  CHECK(host::sdo_write(bus, 5, {0x6040, 0}, hb, 2000ms));

  // aborts name node, object, code and text
  auto why = host::sdo_read(bus, 5, {0x1234, 0}, 2000ms);
  REQUIRE_FALSE(why);
  CHECK(why == errc::aborted);
  CHECK(why.error().code == errc::aborted);
  CHECK(why.error().abort == co::sdo::abort_code::no_object);
  CHECK(why.error().address == fieldcodec::od::address{0x1234, 0});
  CHECK_FALSE(why.error().bus_failed);
  CHECK(why.error().what ==
        "node 5, 1234h:00: SDO abort 06020000h: object not in the object dictionary");
  auto w = host::sdo_write(bus, 5, {0x1018, 1}, hb, 2000ms);
  CHECK(w == errc::aborted);
  CHECK(w.error().what == "node 5, 1018h:01: SDO abort 06010002h: write to a read-only object");
  // a buffer too small: the client aborts the upload
  host::sdo_session small(bus, 5, {.timeout = 2000ms, .max_size = 4});
  CHECK(small.read({0x1008, 0}) == errc::buffer_too_small);
  CHECK(small.last_error().what == "node 5, 1008h:00: output buffer too small (sent SDO abort "
                                   "05040005h: out of memory)");
  // nobody answers node 6: timeout
  why = host::sdo_read(bus, 6, {0x1018, 1}, 100ms);
  CHECK(why == errc::timeout);
  CHECK(why.error().what ==
        "node 6, 1018h:01: timeout (sent SDO abort 05040000h: SDO protocol timed out)");
  // node-ID 0 cannot start
  CHECK(host::sdo_read(bus, 0, {0x1018, 1}, 100ms) == errc::invalid_argument);

  // NMT goes out as a frame
  REQUIRE(bus.send(co::nmt::encode(co::nmt::command::start, 5).value()));
  for (int i = 0; i < 100 && !node.last_nmt(); ++i) std::this_thread::sleep_for(5ms);
  CHECK(node.last_nmt() == co::nmt::command::start);

  // frames from the bus arrive with a time; extended frames are skipped by receive()
  node.inject_text("T123456781AB\r");
  node.inject(co::make_frame(0x705, {0x05}).value());
  auto r = bus.receive(2000ms);
  REQUIRE(r);
  CHECK(r.value().frame == co::make_frame(0x705, {0x05}).value());
  CHECK(r.value().time.known());
  // a bad line from the adapter is an error with the line quoted
  node.inject_text("t70\r");
  CHECK(bus.receive(2000ms) == errc::truncated);
  CHECK(bus.last_error().what == node.path() + ": bad line from the adapter: t70");
  // BEL from the adapter
  node.inject_text("\a");
  CHECK(bus.receive(2000ms) == errc::bad_state);
  CHECK(bus.receive(50ms) == errc::timeout);

  const auto commands = node.commands();
  REQUIRE(commands.size() >= 3);
  CHECK(commands[commands.size() - 3] == "C");
  CHECK(commands[commands.size() - 2] == "S6");
  CHECK(commands[commands.size() - 1] == "O");
}

TEST_CASE("slcan bus: open failures name the port and the command") {
  host::slcan_bus bus;
  CHECK(bus.open("/nonexistent/ttyX", 500000) == errc::invalid_argument);
  CHECK(bus.last_error().what == "/nonexistent/ttyX: open: No such file or directory");
  CHECK(bus.open("/dev/null", 500000) == errc::bad_state);
  CHECK(bus.last_error().what.find("/dev/null: not a serial port") == 0);
  CHECK(bus.open("/dev/null", 123) == errc::invalid_argument);
  CHECK(bus.last_error().what == "/dev/null: no slcan bit rate 123");
  CHECK(bus.send(co::make_frame(0x80, {}).value()) == errc::bad_state);

  {
    fieldcodec::test::slcan_node refusing({.refuse_bitrate = true});
    CHECK(bus.open(refusing.path(), 500000) == errc::bad_state);
    CHECK(bus.last_error().what == refusing.path() + ": the adapter refused 'S6'");
  }
  {
    fieldcodec::test::slcan_node silent({.answer_commands = false});
    CHECK(bus.open(silent.path(), 500000, {.answer_timeout = 100ms}) == errc::timeout);
    CHECK(bus.last_error().what == silent.path() + ": no answer to 'S6' (is it an slcan adapter?)");
    // a peer that does not answer commands: open without checking answers
    REQUIRE(bus.open(silent.path(), 500000, {.check_answers = false}));
    CHECK(host::sdo_read(bus, 5, {0x1000, 0}, 2000ms).value().size() == 4);
  }
}
