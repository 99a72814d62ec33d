// Fuzz harness for the slcan line codec (host/slcan.hpp): what an adapter sends ("t…", "T…",
// "r…", "R…" frames with an optional 4-digit timestamp, "z"/"Z", "Fxx", an empty line, anything
// else) and the lines the host writes for a frame.
//
// Byte 0 selects the mode:
//   even  the rest is adapter output, split into lines at CR, LF or BEL as slcan_bus does, each
//         decoded;
//   odd   the rest builds CANopen frames (base identifiers, remote frames, DLC 0..8), each
//         encoded and decoded again.
//
// Properties:
// * A decoded frame line is a record of the documented domain: an identifier of 11 bits (29
//   for T/R), DLC 0..8, no data bytes past the DLC (none for a remote frame), no time, no
//   interface; its kind is `frame` exactly for lines starting with t, T, r or R.
// * A decoded line is what the line says: encoding the frame of a decoded base frame line
//   gives the line itself (upper-case hex, the timestamp left out); a line that decodes as a
//   frame decodes the same with lower-case hex.
// * "z"/"Z" alone are `transmitted`, "F" + 2 hex digits `status` with that byte, "" `ok`.
// * Encoding: every frame with an identifier up to 7FF and DLC up to 8 encodes (a longer one
//   is refused), into at most 22 characters ending in CR, and decodes back to the same frame.
#include "check.hpp"
#include "input.hpp"

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/host/slcan.hpp>

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace co = fieldcodec::canopen;
namespace host = fieldcodec::host;
namespace slcan = fieldcodec::host::slcan;
using fieldcodec::errc;

namespace {

using fuzz_input::reader;

std::string upper(std::string_view s) {
  std::string out(s);
  for (char &c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

void check_line(std::string_view line) {
  const std::string copy(line); // nothing past the line may be read
  const auto r = slcan::decode(copy);
  if (!r) return;
  const slcan::line &l = r.value();
  const char c = copy.empty() ? '\0' : copy.front();
  const bool frame_line = c == 't' || c == 'T' || c == 'r' || c == 'R';
  FUZZ_CHECK((l.kind == slcan::line_kind::frame) == frame_line);
  if (copy.empty()) FUZZ_CHECK(l.kind == slcan::line_kind::ok);
  if (copy == "z" || copy == "Z") FUZZ_CHECK(l.kind == slcan::line_kind::transmitted);
  if (l.kind == slcan::line_kind::status) {
    FUZZ_CHECK(copy.size() == 3U && c == 'F');
    constexpr std::string_view digits = "0123456789ABCDEF";
    const std::string hex{digits[l.status >> 4U], digits[l.status & 0xFU]};
    FUZZ_CHECK(upper(copy.substr(1)) == hex);
  }
  if (l.kind != slcan::line_kind::frame) return;
  const host::frame_record &f = l.record;
  FUZZ_CHECK(!f.error && !f.time.known() && f.iface.empty());
  FUZZ_CHECK(f.extended == (c == 'T' || c == 'R'));
  FUZZ_CHECK(f.rtr == (c == 'r' || c == 'R'));
  FUZZ_CHECK(f.id <= (f.extended ? 0x1FFFFFFFU : 0x7FFU));
  FUZZ_CHECK(f.dlc <= 8U);
  for (std::size_t i = f.rtr ? 0U : f.dlc; i < 8U; ++i) FUZZ_CHECK(f.data[i] == 0U);
  // the line's frame part, without a timestamp
  const std::size_t id_len = f.extended ? 8U : 3U;
  const std::size_t frame_len = 1U + id_len + 1U + (f.rtr ? 0U : 2U * f.dlc);
  FUZZ_CHECK(copy.size() == frame_len || copy.size() == frame_len + 4U);
  const std::string frame_text = upper(copy.substr(0, frame_len));
  if (!f.extended) {
    const auto canopen = host::to_canopen(f);
    FUZZ_CHECK(canopen.has_value());
    const auto again = slcan::encode(canopen.value());
    FUZZ_CHECK(again.has_value());
    std::string expected = frame_text;
    expected[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(expected[0])));
    FUZZ_CHECK(again.value().view() == expected + "\r");
  }
  // the same line in lower-case hex (the type letter kept) decodes the same
  std::string lower = copy;
  for (std::size_t i = 1; i < lower.size(); ++i) {
    lower[i] = static_cast<char>(std::tolower(static_cast<unsigned char>(lower[i])));
  }
  const auto l2 = slcan::decode(lower);
  FUZZ_CHECK(l2.has_value() && l2.value().kind == slcan::line_kind::frame &&
             l2.value().record == f);
}

void text_mode(std::string_view text) {
  while (!text.empty()) {
    const std::size_t end = text.find_first_of("\r\n\a");
    check_line(text.substr(0, end));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1U);
  }
}

void frame_mode(reader &in) {
  for (int n = 0; n < 64 && !in.empty(); ++n) {
    co::can_frame f;
    const std::uint8_t flags = in.byte();
    f.id = static_cast<std::uint16_t>((flags & 0x0FU) << 8U | in.byte());
    f.rtr = (flags & 0x10U) != 0U;
    f.dlc = static_cast<std::uint8_t>(in.byte() % 10U); // 9: refused
    for (std::size_t i = 0; i < 8U; ++i) f.data[i] = i < f.dlc && !f.rtr ? in.byte() : 0U;
    const auto line = slcan::encode(f);
    if (f.id > 0x7FFU) {
      FUZZ_CHECK(line.error() == errc::invalid_argument);
      continue;
    }
    if (f.dlc > 8U) {
      FUZZ_CHECK(line.error() == errc::bad_length);
      continue;
    }
    FUZZ_CHECK(line.has_value());
    const std::string_view text = line.value().view();
    FUZZ_CHECK(text.size() <= 22U && !text.empty() && text.back() == '\r');
    const auto back = slcan::decode(text.substr(0, text.size() - 1U));
    FUZZ_CHECK(back.has_value() && back.value().kind == slcan::line_kind::frame);
    const auto canopen = host::to_canopen(back.value().record);
    FUZZ_CHECK(canopen.has_value());
    FUZZ_CHECK(canopen.value() == f);
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  if ((data[0] & 1U) == 0U) {
    text_mode(std::string_view(reinterpret_cast<const char *>(data + 1), size - 1));
  } else {
    reader in{std::span<const std::uint8_t>(data + 1, size - 1)};
    frame_mode(in);
  }
  return 0;
}
