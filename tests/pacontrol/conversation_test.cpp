// A master and a simulated PA-CONTROL talking through fieldcodec only: the command sequence of
// manual 001, 3.4.3 (start ONLINE, move axis 2 to 5552.0, poll until done) over RS232 with
// line noise, and the same over the Profibus CMD interface.
#if __has_include(<fieldcodec/dictionaries/pacontrol_commands.hpp>)

#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/pacontrol/codes.hpp>
#include <fieldcodec/pacontrol/command.hpp>
#include <fieldcodec/pacontrol/profibus_cmd.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace fc = fieldcodec;
namespace pac = fc::pacontrol;
namespace serial = pac::serial;
namespace pb = pac::profibus;
namespace cmds = fc::dictionaries::pacontrol_commands;

namespace {

/// A tiny device: answers 0603 with status 31 and 0A87 with the start position, then moves
/// 1255 → 1516.95 → 2634.75 → 5552 on each poll.
struct device {
  serial::decoder rx{{{}, serial::accept::requests}};
  std::uint16_t status = pac::operating_status::home_position;
  int step = -1;
  static constexpr std::array<float, 4> path{1255.0F, 1516.95F, 2634.75F, 5552.0F};

  serial::acknowledgement answer(const serial::request &r) {
    if (r.code == cmds::cmd_start_online.code) {
      status = pac::operating_status::online;
      return {0, true, status, 0, pac::value::of_int(0).value()};
    }
    if (r.code == cmds::cmd_pos_axis_absolut.code) {
      step = 0;
      return {0, false, status, 0, pac::value::of_float(path[0], pac::float_style::device).value()};
    }
    return {pac::command_error::unknown_command, true, status, 0, pac::value::of_int(0).value()};
  }
  serial::acknowledgement poll() {
    if (step < 3) ++step;
    return {0, step == 3, status, 0,
            pac::value::of_float(path[static_cast<std::size_t>(step)], pac::float_style::device)
                .value()};
  }
  /// Feeds the line to the device; returns the bytes it sends back.
  std::vector<std::uint8_t> receive(const std::vector<std::uint8_t> &line) {
    std::vector<std::uint8_t> out;
    for (auto b : line) {
      auto r = rx.push(b);
      serial::acknowledgement a{};
      if (!r) {
        a = {pac::command_error_for(r.error()), true, status, 0, pac::value::of_int(0).value()};
        if (r.error() != fc::errc::bad_syntax) append(out, a); // noise is ignored
        continue;
      }
      if (r.value() == serial::frame_kind::request) append(out, answer(rx.request()));
      if (r.value() == serial::frame_kind::poll) append(out, poll());
    }
    return out;
  }
  static void append(std::vector<std::uint8_t> &out, const serial::acknowledgement &a) {
    std::array<std::uint8_t, serial::max_frame_size> buf{};
    auto n = serial::encode_acknowledgement(a, buf);
    REQUIRE(n);
    out.insert(out.end(), buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(n.value()));
  }
};

std::vector<std::uint8_t> bytes_of(const fc::result<serial::request> &r) {
  REQUIRE(r);
  std::array<std::uint8_t, serial::max_frame_size> buf{};
  auto n = serial::encode_request(r.value(), buf);
  REQUIRE(n);
  return {buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(n.value())};
}

/// The master's side: feeds what came back and returns the acknowledgements.
std::vector<serial::acknowledgement> master_receive(serial::decoder &rx,
                                                    const std::vector<std::uint8_t> &line) {
  std::vector<serial::acknowledgement> acks;
  for (auto b : line) {
    auto r = rx.push(b);
    if (r && r.value() == serial::frame_kind::acknowledgement) acks.push_back(rx.acknowledgement());
  }
  return acks;
}

} // namespace

TEST_CASE("pacontrol conversation over RS232 (3.4.3)") {
  device dev;
  serial::decoder rx({{}, serial::accept::acknowledgements});

  // Start ONLINE.
  auto acks = master_receive(rx, dev.receive(bytes_of(pac::make_request(cmds::cmd_start_online))));
  REQUIRE(acks.size() == 1);
  CHECK(acks[0].operating_status == 31);
  CHECK(pac::describe_operating_status(acks[0].operating_status).value() == "ONLINE");

  // Move axis 2 to 5552.0, with noise before the request.
  auto line = std::vector<std::uint8_t>{0x7E, 0x00, 0x55};
  auto req = bytes_of(pac::make_request(cmds::cmd_pos_axis_absolut, 2, 5552.0F));
  line.insert(line.end(), req.begin(), req.end());
  acks = master_receive(rx, dev.receive(line));
  REQUIRE(acks.size() == 1);
  CHECK_FALSE(acks[0].end_of_processing);
  CHECK(pac::reply_value(cmds::cmd_pos_axis_absolut, acks[0])->as_float() == 1255.0F);

  // Poll until the end of processing; the device prints positions as 1516.950 etc.
  std::vector<float> seen;
  for (int i = 0; i < 10; ++i) {
    std::array<std::uint8_t, 1> poll{};
    REQUIRE(serial::encode_poll(poll));
    acks = master_receive(rx, dev.receive({poll[0]}));
    REQUIRE(acks.size() == 1);
    seen.push_back(acks[0].date.as_float());
    if (acks[0].end_of_processing) break;
  }
  CHECK(seen == std::vector<float>{1516.95F, 2634.75F, 5552.0F});

  // A corrupted request: the device answers QUIT 16 (check sum), the master sees it.
  req = bytes_of(pac::make_request(cmds::cmd_get_int_reg, 2));
  req[req.size() - 2] = '9';
  acks = master_receive(rx, dev.receive(req));
  REQUIRE(acks.size() == 1);
  CHECK(acks[0].command_error_number == 16);
  CHECK(pac::describe_command_error(acks[0].command_error_number).value() ==
        "RS232 check sum wrong");
}

TEST_CASE("pacontrol conversation over Profibus CMD (2.4)") {
  // Device side: RF follows SF one cycle later, the traverse takes three cycles.
  pb::cmd_reply dev{};
  bool last_sf = false;
  int moving = 0;
  auto device_cycle = [&](const std::array<std::uint8_t, pb::cmd_size> &out) {
    auto r = pb::decode_cmd_request(out).value();
    if (r.send_flag != last_sf) {
      last_sf = r.send_flag;
      dev.receive_flag = r.send_flag;
      dev.command_error = false;
      if (r.code == cmds::cmd_pos_axis_absolut.code) {
        moving = 3;
        dev.end_of_processing = false;
        dev.date = pb::date_from_float(1255.0F).value();
      } else {
        dev.end_of_processing = true;
        dev.date = 0;
      }
    } else if (moving > 0 && --moving == 0) {
      dev.end_of_processing = true;
      dev.date = pb::date_from_float(5552.0F).value();
    }
    return pb::encode_cmd_reply(dev).value();
  };

  pb::cmd_handshake hs;
  auto out = pb::encode_cmd_request(pb::cmd_request{}).value();
  auto in = device_cycle(out);
  hs.synchronize(pb::decode_cmd_reply(in).value());
  auto req =
      pac::start_command(hs, cmds::cmd_pos_axis_absolut, 2, pac::value::of_float(5552.0F).value());
  REQUIRE(req);
  out = pb::encode_cmd_request(req.value()).value();
  std::vector<pb::cmd_progress> trace;
  for (int cycle = 0; cycle < 6; ++cycle) {
    trace.push_back(hs.update(pb::decode_cmd_reply(in).value()));
    in = device_cycle(out);
  }
  using P = pb::cmd_progress;
  CHECK(trace == std::vector<P>{P::waiting, P::running, P::running, P::running, P::done, P::done});
  auto v = pac::reply_value(cmds::cmd_pos_axis_absolut, pb::decode_cmd_reply(in).value());
  REQUIRE(v);
  CHECK(v->as_float() == 5552.0F);
}

#endif
