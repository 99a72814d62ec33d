// Regression tests for inputs found by the CLI's fuzz harnesses (fuzz/fuzz_cli_*.cpp; see
// fuzz/FINDINGS.md).
#include "can_decoder.hpp"
#include "dictionary.hpp"
#include "util.hpp"

#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace cli = fieldcodec::cli;

// F22 (fuzz_cli_decode): a log line with bytes that are not UTF-8 ("605#\xFF") was reported as
// MALFORMED with those bytes copied into the text and into the JSON string: `decode --json`
// printed invalid JSON (JSON text is UTF-8) and the terminal got stray bytes.
TEST_CASE("fuzz F22: JSON strings and text lines are UTF-8 whatever the input") {
  // each byte that is not part of valid UTF-8 as \u00XX (its Latin-1 reading)
  CHECK(cli::json_string("a\xFF"
                         "b") == "\"a\\u00FFb\"");
  CHECK(cli::json_string("\xC3") == "\"\\u00C3\"");            // cut
  CHECK(cli::json_string("\xC0\x80") == "\"\\u00C0\\u0080\""); // overlong: 2 bytes
  CHECK(cli::json_string("\xC3\xA9\xE2\x82\xAC") == "\"\xC3\xA9\xE2\x82\xAC\""); // kept
  CHECK(cli::json_string("\"\\\n\x01") == "\"\\\"\\\\\\n\\u0001\"");
  cli::can_decoder dec({}, {}, {});
  std::vector<cli::decoded_line> lines;
  dec.malformed("605#\xFF", fieldcodec::errc::bad_digit, 3, lines);
  REQUIRE(lines.size() == 1U);
  // the text quotes the input as the JSON does, each such byte as \u00XX
  CHECK(cli::render_json(lines[0]) ==
        "{\"line\":3,\"function\":\"MALFORMED\",\"error\":\"bad digit\",\"reason\":\"bad "
        "digit\",\"column\":1,\"input\":\"605#\\u00FF\",\"text\":\"line 3: bad digit at column "
        "1: \\\"605#\\\\u00FF\\\"\"}");
  CHECK(cli::render_text(lines[0]) ==
        "-   MALFORMED line 3: bad digit at column 1: \"605#\\u00FF\"");
}

// F24 (fuzz_cli_dictionary): a node-ID relative default near the end of the 64-bit range
// ("$NODEID+0x7FFFFFFFFFFFFFFF") was added to the node-ID in int64 (undefined behaviour), and an
// UNSIGNED64 default above 2^63 - 1 was wrapped to a negative number.
TEST_CASE("fuzz F24: configured values of a --dict file are never wrapped") {
  const auto path = std::filesystem::temp_directory_path() / "fieldcodec_fuzz_f24.eds";
  std::ofstream(path) << "[2000]\nParameterName=Big\nObjectType=0x7\nDataType=0x1B\n"
                         "AccessType=rw\nDefaultValue=$NODEID+0x7FFFFFFFFFFFFFFF\n"
                         "[2001]\nParameterName=Huge\nObjectType=0x7\nDataType=0x1B\n"
                         "AccessType=rw\nDefaultValue=0xFFFFFFFFFFFFFFFF\n"
                         "[2002]\nParameterName=Fits\nObjectType=0x7\nDataType=0x7\n"
                         "AccessType=rw\nDefaultValue=$NODEID+0x180\n";
  std::string error;
  const auto loaded = cli::node_dictionary::load(path.string(), error);
  std::filesystem::remove(path);
  REQUIRE_MESSAGE(loaded, error);
  const std::optional<cli::node_dictionary> d = loaded->for_node(5);
  REQUIRE(d->find({0x2000, 0}) != nullptr);
  CHECK_FALSE(d->find({0x2000, 0})->configured.has_value());
  CHECK_FALSE(d->find({0x2001, 0})->configured.has_value());
  CHECK(d->find({0x2002, 0})->configured == 0x185);
  CHECK(d->for_node(127).find({0x2002, 0})->configured == 0x1FF);
  CHECK(d->for_node(0).find({0x2000, 0})->configured == 0x7FFFFFFFFFFFFFFF);
}
