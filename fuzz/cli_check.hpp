// What every line the CLI's decoders give must be, for the fuzz harnesses of the CLI: its text
// (as `fieldcodec decode` prints it) valid UTF-8 without control characters — one terminal
// line — and its JSON (`decode --json`) one valid JSON object with "function" and "text".
#pragma once

#include "check.hpp"
#include "text_check.hpp"

#include "can_decoder.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fuzz_cli {

/// Valid UTF-8 without control characters.
inline bool printable_utf8(std::string_view s) {
  if (!fuzz_text::valid_utf8(s)) return false;
  for (const char c : s) {
    if (static_cast<unsigned char>(c) < 0x20U || c == 0x7F) return false;
  }
  return true;
}

/// Checks every line; returns how many bytes printing them (text and JSON) takes.
inline std::size_t check_lines(const std::vector<fieldcodec::cli::decoded_line> &lines) {
  std::size_t printed = 0;
  for (const fieldcodec::cli::decoded_line &l : lines) {
    const std::string text = fieldcodec::cli::render_text(l);
    const std::string json = fieldcodec::cli::render_json(l);
    printed += text.size() + json.size() + 2U;
    FUZZ_CHECK(printable_utf8(text));
    FUZZ_CHECK(fuzz_text::valid_json_object(json));
    FUZZ_CHECK(json.find("\"function\":\"") != std::string::npos);
    FUZZ_CHECK(json.find(",\"text\":\"") != std::string::npos);
  }
  return printed;
}

} // namespace fuzz_cli
