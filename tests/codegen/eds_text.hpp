// Test helpers: small EDS files written inline, and what the readers say about them.
#pragma once

#include "options.hpp"
#include "readers.hpp"

#include <doctest/doctest.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::gen::test {

/// A complete EDS around `objects` (sections written by the test): [FileInfo], [DeviceInfo] and
/// an [OptionalObjects] list naming every object section of `objects`, so that the reader has
/// nothing to say about the frame.
inline std::string eds_file(const std::string &objects) {
  std::vector<std::string> indices;
  std::size_t pos = 0;
  while ((pos = objects.find('[', pos)) != std::string::npos) {
    const auto close = objects.find(']', pos);
    if (close == std::string::npos) break;
    const std::string name = objects.substr(pos + 1, close - pos - 1);
    bool hex4 = name.size() == 4;
    for (const char c : name) {
      hex4 = hex4 && ((c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f'));
    }
    if (hex4) indices.push_back(name);
    pos = close;
  }
  std::string s = "[FileInfo]\nFileName=t.eds\nEDSVersion=4.0\n\n[DeviceInfo]\nVendorName=T\n\n"
                  "[OptionalObjects]\nSupportedObjects=" +
                  std::to_string(indices.size()) + "\n";
  for (std::size_t i = 0; i < indices.size(); ++i) {
    s += std::to_string(i + 1) + "=0x" + indices[i] + "\n";
  }
  return s + "\n" + objects;
}

/// The 1-based line of the first occurrence of `needle` in `text` (0 when absent).
inline int line_of(std::string_view text, std::string_view needle) {
  const auto at = text.find(needle);
  if (at == std::string_view::npos) return 0;
  int line = 1;
  for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n' ? 1 : 0;
  return line;
}

struct read_result {
  std::optional<dictionary> dict;
  std::vector<std::string> diags; ///< formatted, in reporting order
};

inline read_result read_eds_text(const std::string &text, bool strict = false,
                                 const std::string &file = "t.eds") {
  diagnostics d;
  d.strict = strict;
  read_result r;
  r.dict = read_eds(text, file, d);
  for (const auto &x : d.all()) r.diags.push_back(diagnostics::format(x));
  return r;
}

inline read_result read_csv_text(const std::string &text, bool strict = false,
                                 const std::string &file = "t.csv") {
  diagnostics d;
  d.strict = strict;
  read_result r;
  r.dict = read_csv(text, file, d);
  for (const auto &x : d.all()) r.diags.push_back(diagnostics::format(x));
  return r;
}

inline const entry *find_entry(const dictionary &d, std::uint16_t index, std::uint8_t sub) {
  for (const auto &e : d.entries) {
    if (e.index == index && e.sub == sub) return &e;
  }
  return nullptr;
}

/// What the EDS writer writes, read back (no errors expected).
inline dictionary reread(const dictionary &d) {
  diagnostics diag;
  auto again = read_eds(write_eds(d), "written.eds", diag);
  return again ? *again : dictionary{};
}

} // namespace fieldcodec::gen::test

// Failed CHECKs on lists of diagnostics show the lists.
namespace doctest {
template <>
struct StringMaker<std::vector<std::string>> {
  static String convert(const std::vector<std::string> &v) {
    std::string s = "{";
    for (const auto &x : v) s += "\n  \"" + x + "\"";
    return String((s + "}").c_str());
  }
};
} // namespace doctest
