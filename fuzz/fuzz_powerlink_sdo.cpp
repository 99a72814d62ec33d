// Fuzz harness for the POWERLINK SDO codecs (canopen/powerlink/sdo.hpp): the input is read as an
// Ethernet frame, as an ASnd frame and as a command layer frame. Properties: decoding never
// reads outside the input; what decodes re-encodes into a frame that decodes to the same fields
// and bytes; the by-index, request, transfer size and abort readers run on every decoded
// command.
#include "check.hpp"

#include <fieldcodec/canopen/powerlink/sdo.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pl = fieldcodec::canopen::powerlink;

namespace {
bool same(const pl::command &a, const pl::command &b) {
  return a.transaction_id == b.transaction_id && a.response == b.response && a.abort == b.abort &&
         a.seg == b.seg && a.id == b.id && a.data_size == b.data_size &&
         std::equal(a.segment.begin(), a.segment.end(), b.segment.begin(), b.segment.end());
}
void check_command(const pl::command &c) {
  (void)pl::decode_by_index(c.segment);
  (void)pl::decode_abort(c);
  if (const auto r = pl::decode_index_request(c)) {
    FUZZ_CHECK(r.value().value_size >= r.value().data.size());
    FUZZ_CHECK(r.value().id == pl::command_id::write_by_index ||
               r.value().id == pl::command_id::read_by_index);
  }
  if (const auto t = pl::transfer_size(c)) FUZZ_CHECK(t.value() >= c.segment.size());
  std::vector<std::uint8_t> out(pl::command_size(c));
  const auto n = pl::encode_command(out, c);
  FUZZ_CHECK(n.has_value() && n.value() == out.size());
  const auto again = pl::decode_command(out);
  FUZZ_CHECK(again.has_value() && same(again.value(), c));
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  const std::span<const std::uint8_t> in(data, size);
  if (const auto c = pl::decode_command(in)) check_command(c.value());
  for (const auto &f : {pl::decode_asnd(in), pl::decode_ethernet(in)}) {
    if (!f) continue;
    std::vector<std::uint8_t> out(in.size() + 16);
    const auto n = pl::encode_asnd(out, f.value());
    FUZZ_CHECK(n.has_value());
    const auto again = pl::decode_asnd(std::span(out).first(n.value()));
    FUZZ_CHECK(again.has_value());
    FUZZ_CHECK(again.value().sequence == f.value().sequence);
    FUZZ_CHECK(again.value().destination == f.value().destination);
    FUZZ_CHECK(again.value().source == f.value().source);
    const auto &seq = f.value().sequence;
    FUZZ_CHECK(pl::is_next_frame(seq.receive_sequence, seq.send_sequence).has_value() ||
               pl::is_next_frame(seq.receive_sequence, seq.send_sequence).error() ==
                   fieldcodec::errc::unexpected_frame);
    FUZZ_CHECK(again.value().cmd.has_value() == f.value().cmd.has_value());
    if (f.value().cmd) {
      FUZZ_CHECK(same(*again.value().cmd, *f.value().cmd));
      check_command(*f.value().cmd);
    }
  }
  return 0;
}
