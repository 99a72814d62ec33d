// Fuzz harness for the CLI's run-time dictionaries (cli/src/dictionary.cpp: `--dict FILE` of
// `decode`, `monitor`, `sdo`, `dump`): an EDS, DCF or CSV file of any content loaded through
// the generator's readers into what the decoder uses, then used to decode traffic.
//
// Byte 0: bits 0-1 the file's name (node.eds, node.dcf, node.csv, dpq_node.csv: the extension
// picks the reader, a "dpq" stem the DPQ family), bits 2-7 and byte 1 the node (0..127). The
// rest is the file's content.
//
// Properties:
// * load gives a dictionary, or an error text that is not empty, names the file and is valid
//   UTF-8 (it is printed);
// * a dictionary's objects are sorted by address without duplicates, find() finds each of
//   them and nothing else; names and units are valid UTF-8 without control characters;
// * for_node(n) has the same objects for every node 1..127; a configured value (DCF value or
//   default) that is node-ID relative moves with the node, the others do not (UBSan: never by
//   an overflowing sum);
// * traffic decoded with it (an SDO upload response with the configured value or zeros for
//   each object, the PDOs of the first four TPDOs, an SDO write of each PDO parameter) gives
//   lines whose JSON is valid and whose text is valid UTF-8 without control characters.
#include "check.hpp"
#include "cli_check.hpp"
#include "text_check.hpp"

#include "can_decoder.hpp"
#include "dictionary.hpp"

#include <fieldcodec/host/frame_record.hpp>

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cli = fieldcodec::cli;
namespace host = fieldcodec::host;
namespace od = fieldcodec::od;

namespace {

std::string scratch_file(std::string_view name) {
  static const std::string dir = [] {
    const char *tmp = std::getenv("TMPDIR");
    std::string pattern =
        std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/fuzz_cli_dictionary.XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) std::abort();
    return pattern;
  }();
  return dir + "/" + std::string(name);
}

host::frame_record frame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  host::frame_record r;
  r.id = id;
  for (const std::uint8_t b : bytes) r.data[r.dlc++] = b;
  return r;
}

void decode_with(const cli::node_dictionary &d, std::uint8_t node) {
  std::map<std::uint8_t, cli::node_dictionary> dicts;
  dicts.emplace(node, d);
  cli::can_decoder dec(std::move(dicts), {}, {});
  std::vector<cli::decoded_line> lines;
  std::size_t n = 0;
  const auto feed = [&](const host::frame_record &r) {
    dec.feed(r, ++n, lines);
    (void)fuzz_cli::check_lines(lines);
    lines.clear();
  };
  std::size_t objects = 0;
  for (const cli::object_desc &o : d.objects()) {
    if (++objects > 64U) break;
    const auto lo = static_cast<std::uint8_t>(o.d.index & 0xFFU);
    const auto hi = static_cast<std::uint8_t>(o.d.index >> 8U);
    const auto v = static_cast<std::uint64_t>(o.configured.value_or(0));
    feed(frame(0x600U + node, {0x40, lo, hi, o.d.sub, 0, 0, 0, 0}));
    feed(frame(0x580U + node,
               {0x43, lo, hi, o.d.sub, static_cast<std::uint8_t>(v),
                static_cast<std::uint8_t>(v >> 8U), static_cast<std::uint8_t>(v >> 16U),
                static_cast<std::uint8_t>(v >> 24U)}));
  }
  for (std::uint32_t k = 0; k < 4U; ++k) {
    feed(frame(0x180U + 0x100U * k + node, {1, 2, 3, 4, 5, 6, 7, 8}));
    feed(frame(0x180U + 0x100U * k + node, {0xFF}));
  }
  dec.finish(lines);
  (void)fuzz_cli::check_lines(lines);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size < 2) return 0;
  static constexpr std::string_view names[] = {"node.eds", "node.dcf", "node.csv", "dpq_node.csv"};
  const std::string path = scratch_file(names[data[0] & 3U]);
  const auto node = static_cast<std::uint8_t>(((data[0] >> 2U) ^ data[1]) % 128U);
  {
    std::FILE *f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) std::abort();
    if (std::fwrite(data + 2, 1, size - 2, f) != size - 2) std::abort();
    std::fclose(f);
  }
  std::string error;
  const auto loaded = cli::node_dictionary::load(path, error);
  if (!loaded) {
    FUZZ_CHECK(!error.empty());
    FUZZ_CHECK(error.find(path) != std::string::npos);
    FUZZ_CHECK(fuzz_text::valid_utf8(error));
    return 0;
  }
  const std::optional<cli::node_dictionary> d = loaded->for_node(node);
  const auto &objects = d->objects();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const od::address a{objects[i].d.index, objects[i].d.sub};
    if (i > 0U) {
      FUZZ_CHECK((od::address{objects[i - 1U].d.index, objects[i - 1U].d.sub} < a));
    }
    FUZZ_CHECK(d->find(a) == &objects[i]);
    FUZZ_CHECK(fuzz_cli::printable_utf8(objects[i].name));
    FUZZ_CHECK(fuzz_cli::printable_utf8(std::string_view(objects[i].d.info.unit)));
  }
  FUZZ_CHECK(d->find({0x0000, 0}) == nullptr || objects.front().d.index == 0U);
  // the same dictionary for other nodes
  for (const std::uint8_t other : {std::uint8_t{1}, std::uint8_t{127}}) {
    const cli::node_dictionary o = d->for_node(other);
    FUZZ_CHECK(o.objects().size() == objects.size());
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const cli::object_desc &a = objects[i];
      const cli::object_desc &b = o.objects()[i];
      FUZZ_CHECK(a.d.index == b.d.index && a.d.sub == b.d.sub);
      FUZZ_CHECK(a.name == b.name);
      // (a node-ID relative value near the end of the 64-bit range may fit for one node only)
      if (a.configured && b.configured) {
        // in modular arithmetic: the values may lie at the ends of the 64-bit range
        const std::uint64_t moved =
            static_cast<std::uint64_t>(*b.configured) - static_cast<std::uint64_t>(*a.configured);
        FUZZ_CHECK(moved == 0U ||
                   moved == static_cast<std::uint64_t>(other) - static_cast<std::uint64_t>(node));
      }
    }
  }
  decode_with(*d, node == 0U ? std::uint8_t{1} : node);
  return 0;
}
