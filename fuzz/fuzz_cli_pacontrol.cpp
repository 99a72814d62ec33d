// Fuzz harness for the CLI's PA-CONTROL capture decoder (cli/src/pacontrol_decoder.cpp, behind
// `fieldcodec decode --pacontrol`): a capture as raw bytes or as hex text, decoded into
// requests, acknowledgements, polls, noise and malformed frames.
//
// Byte 0: bit 0 set: the rest is taken as `decode --pacontrol` takes a file (hex text when it
// looks like hex, raw bytes otherwise); clear: the rest is the raw capture.
//
// Properties:
// * Every line the decoder gives is printable: its text (as `decode` prints it) valid UTF-8
//   without control characters, its JSON (`decode --json`) one valid JSON object.
// * A capture written as hex text ("01 02 ..." with comments, "0x" prefixes and commas) looks
//   like hex, reads back to the same bytes and decodes to the same lines.
// * Hex text that reads gives at most one byte per two characters; text that does not read
//   says why.
// * Bounded output: everything printed is at most 256 bytes per input byte + 4 kB (a one-byte poll
// is a line of its own).
#include "check.hpp"
#include "cli_check.hpp"

#include "can_decoder.hpp"
#include "pacontrol_decoder.hpp"

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cli = fieldcodec::cli;

namespace {

bool same_lines(const std::vector<cli::decoded_line> &a, const std::vector<cli::decoded_line> &b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (cli::render_json(a[i]) != cli::render_json(b[i])) return false;
  }
  return true;
}

/// The capture as hex text, in one of the spellings a capture file uses.
std::string as_hex_text(std::span<const std::uint8_t> bytes, std::uint8_t style) {
  static constexpr char digits[] = "0123456789ABCDEF";
  std::string out = (style & 1U) != 0U ? "# a capture\n" : "";
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (i != 0U) out += (style & 2U) != 0U ? "," : (i % 16U == 0U ? "\n" : " ");
    if ((style & 4U) != 0U) out += "0x";
    out += digits[bytes[i] >> 4U];
    const char low = digits[bytes[i] & 0xFU];
    out +=
        (style & 8U) != 0U ? static_cast<char>(std::tolower(static_cast<unsigned char>(low))) : low;
  }
  return out + "\n";
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  const std::span<const std::uint8_t> rest(data + 1, size - 1);
  std::vector<std::uint8_t> capture(rest.begin(), rest.end());
  if ((data[0] & 1U) != 0U) {
    const std::string_view text(reinterpret_cast<const char *>(rest.data()), rest.size());
    if (cli::looks_like_hex(text)) {
      std::string error;
      std::vector<std::uint8_t> bytes;
      if (!cli::parse_hex_capture(text, bytes, error)) {
        FUZZ_CHECK(!error.empty());
        return 0;
      }
      FUZZ_CHECK(bytes.size() <= text.size() / 2U);
      capture = std::move(bytes);
    }
  }
  const auto lines = cli::decode_pacontrol(capture);
  const std::size_t printed = fuzz_cli::check_lines(lines);
  FUZZ_CHECK(printed <= 256U * size + 4096U);

  // the same capture as hex text
  if (capture.empty()) return 0;
  const std::string hex = as_hex_text(capture, data[0] >> 1U);
  FUZZ_CHECK(cli::looks_like_hex(hex));
  std::string error;
  std::vector<std::uint8_t> back;
  FUZZ_CHECK(cli::parse_hex_capture(hex, back, error));
  FUZZ_CHECK(back == capture);
  FUZZ_CHECK(same_lines(cli::decode_pacontrol(back), lines));
  return 0;
}
