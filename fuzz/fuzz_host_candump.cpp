// Fuzz harness for the candump reader and writer (host/candump.hpp): log lines
// "(time) iface ID#DATA", compact frames, remote frames "ID#R" / "ID#Rn", extended and error
// frames, data with '.' separators, blanks and CRs around them.
//
// Byte 0 selects the mode:
//   even  the rest is log text, split at LF into lines, each read as `fieldcodec decode` reads
//         it (is_blank_or_comment, then parse_line);
//   odd   the rest builds frame records (every kind the writer writes), each written with
//         format_line / format_frame and read back.
//
// Properties:
// * A line the reader accepts is a record of the documented domain: an identifier of 11 bits
//   (29 for extended and error frames), DLC 0..8, no data bytes past the DLC (none for a remote
//   frame), a time of 1..9 fraction digits with a fraction below 10^digits, or none.
// * What the writer writes the reader reads back identical (every field, time and interface
//   included; a record with a time but no interface is written with "-", which reads back as
//   none), and writing that again gives the same text: the log is a fixed point. A line the
//   reader accepted and the writer wrote reads back to the same record.
// * A blank line or a comment is never a frame; the reader never reads past the line.
// * Bounded output: a written line is at most 80 characters.
#include "check.hpp"
#include "input.hpp"

#include <fieldcodec/host/candump.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace host = fieldcodec::host;
namespace candump = fieldcodec::host::candump;

namespace {

using fuzz_input::reader;

constexpr std::size_t max_line = 80; // "(" 19 "." 9 ") " 15 " " 8 "#" 16

void check_domain(const host::frame_record &r) {
  FUZZ_CHECK(!(r.extended && r.error));
  FUZZ_CHECK(r.id <= (r.extended || r.error ? 0x1FFFFFFFU : 0x7FFU));
  FUZZ_CHECK(r.dlc <= 8U);
  FUZZ_CHECK(!(r.rtr && r.error));
  for (std::size_t i = r.rtr ? 0U : r.dlc; i < 8U; ++i) FUZZ_CHECK(r.data[i] == 0U);
  FUZZ_CHECK(r.time.digits <= 9U);
  if (r.time.known()) {
    std::uint64_t limit = 1;
    for (unsigned i = 0; i < r.time.digits; ++i) limit *= 10U;
    FUZZ_CHECK(r.time.fraction < limit);
    FUZZ_CHECK(r.time.seconds >= 0);
  } else {
    FUZZ_CHECK(r.time.seconds == 0 && r.time.fraction == 0U);
  }
}

/// Written, read back identical; written again, the same text.
void check_round_trip(const host::frame_record &r) {
  const std::string line = candump::format_line(r);
  FUZZ_CHECK(line.size() <= max_line);
  const auto back = candump::parse_line(line);
  FUZZ_CHECK(back.has_value());
  FUZZ_CHECK(back.value() == r);
  FUZZ_CHECK(candump::format_line(back.value()) == line);
  FUZZ_CHECK(!candump::is_blank_or_comment(line));
  // the compact frame alone: the same frame without time and interface
  const std::string compact = candump::format_frame(r);
  const auto frame = candump::parse_frame(compact);
  FUZZ_CHECK(frame.has_value());
  host::frame_record bare = r;
  bare.time = {};
  bare.iface = {};
  FUZZ_CHECK(frame.value() == bare);
}

void text_mode(std::string_view text) {
  while (!text.empty()) {
    const std::size_t lf = text.find('\n');
    std::string_view line = text.substr(0, lf);
    text = lf == std::string_view::npos ? std::string_view{} : text.substr(lf + 1U);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    // read from a copy that ends where the line ends: nothing past it may be touched
    const std::string copy(line);
    const auto r = candump::parse_line(copy);
    if (candump::is_blank_or_comment(copy)) {
      FUZZ_CHECK(!r.has_value());
      continue;
    }
    if (!r) continue;
    check_domain(r.value());
    check_round_trip(r.value());
  }
}

host::frame_record make_record(reader &in) {
  host::frame_record r;
  const std::uint8_t kind = in.byte();
  const std::uint32_t id = in.u32();
  switch (kind % 3U) {
  case 0: r.id = id & 0x7FFU; break;
  case 1:
    r.extended = true;
    r.id = id & 0x1FFFFFFFU;
    break;
  default:
    r.error = true;
    r.id = id & 0x1FFFFFFFU;
    break;
  }
  r.rtr = !r.error && (kind & 0x10U) != 0U;
  r.dlc = static_cast<std::uint8_t>(in.byte() % 9U);
  if (!r.rtr) {
    for (std::size_t i = 0; i < r.dlc; ++i) r.data[i] = in.byte();
  }
  if ((kind & 0x20U) != 0U) {
    r.time.digits = static_cast<std::uint8_t>(1U + in.byte() % 9U);
    std::uint32_t limit = 1;
    for (unsigned i = 0; i < r.time.digits; ++i) limit *= 10U;
    r.time.fraction = in.u32() % limit;
    r.time.seconds =
        static_cast<std::int64_t>((static_cast<std::uint64_t>(in.u32()) << 31U) ^ in.u32()) &
        0x7FFFFFFFFFFFFFFF;
    // none (the writer writes "-"), or 1..15 characters a Linux interface name may have
    if ((kind & 0x40U) != 0U) return r;
    char name[16];
    const std::size_t n = 1U + in.byte() % 15U;
    for (std::size_t i = 0; i < n; ++i) {
      static constexpr std::string_view chars =
          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._-@:+";
      name[i] = chars[in.byte() % chars.size()];
    }
    // "-" alone is how the writer says "no interface": not a name a record can carry
    if (n == 1U && name[0] == '-') name[0] = 'x';
    auto iface = host::interface_name::make(std::string_view(name, n));
    FUZZ_CHECK(iface.has_value());
    r.iface = iface.value();
  }
  return r;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  reader in{std::span<const std::uint8_t>(data + 1, size - 1)};
  if ((data[0] & 1U) == 0U) {
    text_mode(std::string_view(reinterpret_cast<const char *>(data + 1), size - 1));
    return 0;
  }
  for (int n = 0; n < 64 && !in.empty(); ++n) {
    const host::frame_record r = make_record(in);
    check_domain(r);
    check_round_trip(r);
  }
  return 0;
}
