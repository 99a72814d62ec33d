// One message for each device family, built and checked with fieldcodec alone:
//   DPQ      SDO write of Inj. P Limit 1 = 4.0 bar to node 5 (CANopen)
//   COMPAX   the Nx program record of "IF E5=1 GOTO 12" and back to program text (Interbus)
//   PA-CONTROL  "move axis 2 to 5552.0" as an RS232 request, and the device's answer decoded
//               one byte at a time, as a serial interrupt would
#include <fieldcodec/compax/nx.hpp>
#include <fieldcodec/compax/nx_text.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/sdo.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>

#include <array>
#include <cstdio>
#include <string_view>

namespace fc = fieldcodec;
namespace nx = fieldcodec::compax::nx;
namespace serial = fieldcodec::pacontrol::serial;

namespace {
void print_bytes(const char *label, std::span<const std::uint8_t> bytes) {
  std::printf("%-28s", label);
  for (auto b : bytes) std::printf(" %02X", b);
  std::printf("\n");
}
} // namespace

int main() {
  int failures = 0;

  // DPQ (manual 004, ch. 3): 4.0 bar at scale 327.67 is raw 1311 = 0x051F.
  auto sdo = fc::dpq::write_request(5, fc::dictionaries::dpq_parameters::inj_p_limit_1, 4.0);
  if (!sdo) return 1;
  std::printf("DPQ  0x%03X:", sdo.value().id);
  print_bytes("", sdo.value().payload());
  failures += sdo.value().data[4] == 0x1F && sdo.value().data[5] == 0x05 ? 0 : 1;

  // COMPAX Nx record and program text.
  auto cmd = nx::parse_command("IF E5=1 GOTO 12");
  if (!cmd) return 1;
  auto rec = nx::encode_record(cmd.value());
  if (!rec) return 1;
  print_bytes("COMPAX IF E5=1 GOTO 12 ->", rec.value());
  std::array<char, 64> text{};
  auto back = nx::decode_record(rec.value()).and_then([&](const nx::command &c) {
    return nx::format_command(c, text);
  });
  if (!back) return 1;
  const std::string_view round_trip(text.data(), back.value());
  std::printf("COMPAX record -> text       %.*s\n", static_cast<int>(round_trip.size()),
              round_trip.data());
  failures += round_trip == "IF E5=1 GOTO 12" ? 0 : 1;

  // PA-CONTROL RS232 request, then an acknowledgement decoded byte by byte.
  std::array<std::uint8_t, serial::max_frame_size> frame{};
  auto date = fc::pacontrol::value::of_float(5552.0F);
  if (!date) return 1;
  auto n = serial::encode_request({0x0A87, 2, date.value()}, frame);
  if (!n) return 1;
  print_bytes("PA-CONTROL request", std::span(frame).first(n.value()));

  serial::acknowledgement ack{};
  ack.end_of_processing = true;
  ack.operating_status = 10;
  ack.date = date.value();
  auto m = serial::encode_acknowledgement(ack, frame);
  if (!m) return 1;
  serial::decoder rx({{}, serial::accept::acknowledgements});
  bool got = false;
  for (std::size_t i = 0; i < m.value(); ++i) {
    auto r = rx.push(frame[i]);
    if (r && r.value() == serial::frame_kind::acknowledgement) got = rx.acknowledgement() == ack;
  }
  std::printf("PA-CONTROL acknowledgement  %s\n", got ? "decoded, same fields" : "NOT decoded");
  failures += got ? 0 : 1;

  return failures;
}
