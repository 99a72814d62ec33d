// Test helper: the ```cpp blocks of a document, and whether a test source holds each of them.
//
// A doc_snippets test compiles a document's C++ blocks and asserts their stated results; this
// helper proves that the blocks in the document are the ones compiled, so that the document
// cannot drift from the code: every non-empty line of a block must appear, in order and on
// consecutive non-empty lines, in the test source (leading and trailing blanks ignored, so the
// test may indent the code inside a TEST_CASE).
#pragma once

#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace doc_blocks {

inline std::string read_file(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string trim(const std::string &line) {
  const auto b = line.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  const auto e = line.find_last_not_of(" \t\r");
  return line.substr(b, e - b + 1);
}

/// `relative` resolved against the directory of the source file `file` (pass __FILE__), so
/// that a test finds the documents whatever its working directory.
inline std::string beside(const std::string &file, const std::string &relative) {
  const auto slash = file.find_last_of('/');
  return (slash == std::string::npos ? std::string(".") : file.substr(0, slash)) + "/" + relative;
}

/// The non-empty, trimmed lines of `text`.
inline std::vector<std::string> lines(const std::string &text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    auto t = trim(line);
    if (!t.empty()) out.push_back(t);
  }
  return out;
}

/// The bodies of the ```cpp fenced blocks of a Markdown file (empty when it cannot be read).
inline std::vector<std::string> cpp_blocks(const std::string &markdown_path) {
  std::vector<std::string> blocks;
  std::istringstream in(read_file(markdown_path));
  std::string line;
  std::string body;
  bool inside = false;
  while (std::getline(in, line)) {
    const auto t = trim(line);
    if (!inside && t == "```cpp") {
      inside = true;
      body.clear();
    } else if (inside && t == "```") {
      inside = false;
      blocks.push_back(body);
    } else if (inside) {
      body += line + "\n";
    }
  }
  return blocks;
}

/// True when the non-empty lines of `block` appear consecutively in the non-empty lines of
/// `source`.
inline bool holds(const std::string &source, const std::string &block) {
  const auto src = lines(source);
  const auto blk = lines(block);
  if (blk.empty()) return true;
  for (std::size_t i = 0; i + blk.size() <= src.size(); ++i) {
    std::size_t k = 0;
    while (k < blk.size() && src[i + k] == blk[k]) ++k;
    if (k == blk.size()) return true;
  }
  return false;
}

} // namespace doc_blocks
