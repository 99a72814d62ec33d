// powerlink: the SDO codecs of a POWERLINK controlled node (canopen/powerlink/sdo.hpp) — an ASnd
// frame read from its layers, the sequence number rule, a WriteByIndex / ReadByIndex request
// read, and the answer written: a response with data or an abort. No transfer machine and no
// dictionary: what the codecs cost on their own. Frames come from and go to volatile registers,
// so every path stays reachable.
#include "io.hpp"

#include <fieldcodec/canopen/powerlink/sdo.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace pl = fieldcodec::canopen::powerlink;
namespace sdo = fieldcodec::canopen::sdo;

namespace {
std::uint8_t last_received = 0;

void answer(const pl::asnd_sdo &in) {
  std::array<std::uint8_t, 64> out{};
  std::array<std::uint8_t, 4> data{};
  pl::asnd_sdo reply{in.source, in.destination, in.sequence, std::nullopt};
  const auto fresh = pl::is_next_frame(last_received, in.sequence.send_sequence);
  if (!fresh) {
    reply.sequence.rcon = pl::receive_con::error_response;
  } else if (fresh.value() && in.cmd) {
    last_received = in.sequence.send_sequence;
    reply.sequence.receive_sequence = last_received;
    const auto req = pl::decode_index_request(*in.cmd);
    if (!req) {
      // the ASnd and sequence layer headers, then the abort's command layer after them
      const auto head = pl::encode_asnd(out, reply);
      if (!head) return;
      const auto n = pl::encode_abort(std::span(out).subspan(head.value()), in.cmd->transaction_id,
                                      in.cmd->id, sdo::abort_code::unknown_command);
      if (n) fw::transmit(out);
      return;
    }
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = fw::rx_register[i + 40U];
    reply.cmd =
        pl::command{in.cmd->transaction_id, true,         false, pl::segmentation::expedited,
                    req.value().id,         std::nullopt, data};
  }
  if (const auto n = pl::encode_asnd(out, reply)) fw::transmit(out);
}
} // namespace

int main() {
  const auto frame = fw::receive<60>();
  if (const auto f = pl::decode_ethernet(frame)) answer(f.value());
  return 0;
}
