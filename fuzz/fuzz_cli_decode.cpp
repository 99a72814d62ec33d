// Fuzz harness for the CLI's CANopen traffic decoder (cli/src/can_decoder.cpp, behind
// `fieldcodec decode` and `monitor`), fed arbitrary candump text the way `decode` reads a log:
// line by line, blank lines and comments skipped, each line through the candump reader, then
// the decoder (a frame) or its malformed-line report; at the end the transfers still running.
//
// Byte 0: bits 0-1 the dictionaries (none; the XENAX EDS for every node; the XENAX EDS for node
// 5, the DPQ CSV for node 0x22 and the I/O node EDS for every other node; no dictionary but
// node 5 declared a CiA 402 drive), bit 2 --sdo-frames. The rest is the log text.
//
// Properties, for every line the decoder gives (text as `decode` prints it, and JSON as
// `decode --json` prints it):
// * the JSON is one valid JSON object (RFC 8259, UTF-8) with a "function" and a "text" string;
// * the text line is valid UTF-8 without control characters (one terminal line);
// * every malformed input line gives exactly one MALFORMED line, which is a problem;
// * bounded output: everything printed is at most 256 bytes per input byte + 4 kB.
#include "check.hpp"
#include "cli_check.hpp"

#include "can_decoder.hpp"
#include "dictionary.hpp"

#include <fieldcodec/host/candump.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cli = fieldcodec::cli;
namespace candump = fieldcodec::host::candump;

namespace {

const cli::node_dictionary &load(const char *relative) {
  static std::map<std::string, cli::node_dictionary> loaded;
  auto it = loaded.find(relative);
  if (it == loaded.end()) {
    std::string error;
    auto d = cli::node_dictionary::load(std::string(FIELDCODEC_SOURCE_DIR) + "/" + relative, error);
    if (!d) {
      std::fprintf(stderr, "%s\n", error.c_str());
      std::abort();
    }
    it = loaded.emplace(relative, std::move(*d)).first;
  }
  return it->second;
}

cli::can_decoder make_decoder(std::uint8_t mode) {
  // the dictionaries of each mode, loaded once (the decoder takes copies)
  static std::map<int, std::map<std::uint8_t, cli::node_dictionary>> prepared;
  const int set = mode & 3U;
  auto it = prepared.find(set);
  if (it == prepared.end()) {
    std::map<std::uint8_t, cli::node_dictionary> dicts;
    switch (set) {
    case 1: dicts.emplace(0, load("dictionaries/xenax_canopen.eds")); break;
    case 2:
      dicts.emplace(5, load("dictionaries/xenax_canopen.eds").for_node(5));
      dicts.emplace(0x22, load("dictionaries/dpq_parameters.csv").for_node(0x22));
      dicts.emplace(0, load("examples/firmware/io_node.eds"));
      break;
    default: break;
    }
    it = prepared.emplace(set, std::move(dicts)).first;
  }
  std::map<std::uint8_t, cli::device_family> families;
  if (set == 3) families.emplace(5, cli::device_family::ds402);
  return cli::can_decoder(it->second, std::move(families), {(mode & 4U) != 0U});
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  cli::can_decoder dec = make_decoder(data[0]);
  std::string_view text(reinterpret_cast<const char *>(data + 1), size - 1);
  std::vector<cli::decoded_line> lines;
  std::size_t printed = 0;
  std::size_t n = 0;
  while (!text.empty()) {
    const std::size_t lf = text.find('\n');
    std::string line(text.substr(0, lf));
    text = lf == std::string_view::npos ? std::string_view{} : text.substr(lf + 1U);
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (candump::is_blank_or_comment(line)) continue;
    const auto r = candump::parse_line(line);
    if (!r) {
      dec.malformed(line, r.error(), n, lines);
      FUZZ_CHECK(lines.size() == 1U && lines[0].function == "MALFORMED" && lines[0].problem);
    } else {
      dec.feed(r.value(), n, lines);
    }
    printed += fuzz_cli::check_lines(lines);
    lines.clear();
  }
  dec.finish(lines);
  printed += fuzz_cli::check_lines(lines);
  FUZZ_CHECK(printed <= 256U * size + 4096U);
  return 0;
}
