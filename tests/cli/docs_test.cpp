// docs/cli.md quotes the CLI's output: every fenced block after a `<!-- golden: NAME -->` line
// must be a run of consecutive lines of tests/cli/golden/NAME (the outputs the other tests of
// this folder check), so the documentation cannot drift from what the tool prints. A golden
// line starting with "<time> " (monitor: the host's clock) matches any time.
#include "cli_support.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

namespace t = fieldcodec::test;

namespace {

std::vector<std::string> lines_of(const std::string &text) {
  std::vector<std::string> out;
  for (const auto l : fieldcodec::cli::split_lines(text)) out.emplace_back(l);
  return out;
}

bool same_line(const std::string &doc, const std::string &golden) {
  if (doc == golden) return true;
  const std::string placeholder = "<time> ";
  if (golden.rfind(placeholder, 0) != 0) return false;
  const auto sp = doc.find(' ');
  if (sp == std::string::npos) return false;
  for (std::size_t i = 0; i < sp; ++i) {
    if ((doc[i] < '0' || doc[i] > '9') && doc[i] != '.') return false;
  }
  return doc.substr(sp + 1U) == golden.substr(placeholder.size());
}

bool contains_run(const std::vector<std::string> &golden, const std::vector<std::string> &block) {
  if (block.empty()) return false;
  for (std::size_t start = 0; start + block.size() <= golden.size(); ++start) {
    bool all = true;
    for (std::size_t i = 0; i < block.size() && all; ++i) {
      all = same_line(block[i], golden[start + i]);
    }
    if (all) return true;
  }
  return false;
}

} // namespace

TEST_CASE("docs/cli.md: every example is the tool's output") {
  const std::string doc = t::read_text("../docs/cli.md");
  REQUIRE_FALSE(doc.empty());
  const auto lines = lines_of(doc);
  const std::string marker = "<!-- golden: ";
  std::size_t checked = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind(marker, 0) != 0) continue;
    const std::string name = lines[i].substr(marker.size(), lines[i].size() - marker.size() - 4U);
    REQUIRE(i + 1U < lines.size());
    REQUIRE(lines[i + 1U].rfind("```", 0) == 0);
    std::vector<std::string> block;
    std::size_t j = i + 2U;
    for (; j < lines.size() && lines[j].rfind("```", 0) != 0; ++j) block.push_back(lines[j]);
    const auto golden = lines_of(t::read_text("cli/golden/" + name));
    CAPTURE(name);
    CAPTURE(i + 1U);
    CHECK_MESSAGE(contains_run(golden, block),
                  "docs/cli.md line " << i + 1U << ": the example is not in golden/" << name);
    ++checked;
    i = j;
  }
  CHECK(checked >= 15);
}

TEST_CASE("README shows the CLI") {
  const std::string readme = t::read_text("../README.md");
  CHECK(readme.find("fieldcodec decode") != std::string::npos);
  CHECK(readme.find("fieldcodec sdo read 5 1018:1") != std::string::npos);
}
