// The C++ blocks of docs/compax.md, word for word, each in a namespace of its own: compiled by
// the test build (the README's flags: -Wall -Wextra -Wpedantic -Werror -Wconversion
// -Wsign-conversion -Wshadow) with their static_asserts, and checked again at run time below.
// The first test case reads the page and fails when a block there is not held here unchanged,
// so the page cannot drift from code that compiles (issue 13, "Docs that cannot lie").
// The headers the blocks include are included here first; the blocks' own #include lines then
// change nothing.
#include <fieldcodec/compax/nx_text.hpp>
#include <fieldcodec/compax/objects.hpp>
#include <fieldcodec/compax/pcp.hpp>
#include <fieldcodec/compax/speed_profile.hpp>
#include <fieldcodec/dictionaries/compax_objects.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

// clang-format off
namespace doc_snippet_1 {
#include <fieldcodec/compax/nx_text.hpp>

namespace nx = fieldcodec::compax::nx;

// Program text -> record: byte 1 is the content length (IF E5=1 GOTO 12 has 7 bytes).
constexpr auto rec = nx::encode_record(nx::parse_command("IF E5=1 GOTO 12").value());
static_assert(rec.value()[0] == 7 && rec.value()[1] == 0x49 && rec.value()[7] == 0x0C);

// Numbers carry the command's unit: POSA 250 is 250 mm (DSP bytes 00 00 00 FA 00 00).
constexpr auto posa = nx::make(nx::op::posa, nx::integer(250));
static_assert(posa == nx::parse_command("POSA 250").value());
static_assert(nx::encode_record(posa).value()[5] == 0xFA);
// A raw DSP value is spelled out: 250 raw units are 250 / 2^24 mm.
static_assert(nx::make(nx::op::posa, nx::dsp_raw(250)) != posa);
} // namespace doc_snippet_1

namespace doc_snippet_2 {
#include <fieldcodec/compax/objects.hpp>
#include <fieldcodec/dictionaries/compax_objects.hpp>

#include <array>
#include <cstdint>

namespace cx = fieldcodec::compax;
namespace d = fieldcodec::dictionaries::compax_objects;
using fieldcodec::decimal;
using bytes4 = std::array<std::uint8_t, 4>;
using bytes6 = std::array<std::uint8_t, 6>;

// POSA 7350.15 mm: signed BCD, 2.7.1 example.
constexpr bytes6 posa_bytes() {
  bytes6 buf{};
  if (!cx::encode_object(d::posa, decimal{735015, 2}, buf)) return {};
  return buf;
}
static_assert(posa_bytes() == bytes6{0x00, 0x00, 0x07, 0x35, 0x01, 0x50});

// GRENZEN is an array: the element is part of the call (2.7.9 example, erratum CX-20).
constexpr bytes4 negative_limit() {
  bytes4 buf{};
  if (!cx::encode_object(d::grenzen, 1, decimal{-1650, 0}, buf)) return {};
  return buf;
}
static_assert(negative_limit() == bytes4{0xFF, 0xE6, 0xD2, 0xB0});

// Px with the resolution of its row: P11 = 5000 (2.4.13 example).
constexpr bytes4 p11_bytes() {
  bytes4 buf{};
  if (!cx::encode_px(d::dictionary, 11, decimal{5000, 0}, buf)) return {};
  return buf;
}
static_assert(p11_bytes() == bytes4{0x00, 0x4C, 0x4B, 0x40});

// CONTROL takes command numbers 1..21 (2.4.10): 22 is refused before a byte is written.
constexpr bool control_22_refused() {
  std::array<std::uint8_t, 1> buf{};
  return cx::encode_object(d::control, decimal{22, 0}, buf).is(fieldcodec::errc::out_of_range);
}
static_assert(control_22_refused());
} // namespace doc_snippet_2

namespace doc_snippet_3 {
#include <fieldcodec/compax/pcp.hpp>
#include <fieldcodec/compax/speed_profile.hpp>

#include <array>
#include <cstdint>

namespace cx = fieldcodec::compax;
using fieldcodec::decimal;

// POSRXSPEEDY: after 580 mm continue at 33 % (2.8.4 example), as a PCP write request.
constexpr auto step = cx::encode_posrxspeedy({decimal{580, 0}, decimal{33, 0}});
static_assert(step.value() ==
              std::array<std::uint8_t, 8>{0x00, 0x08, 0xD9, 0xA0, 0x00, 0x00, 0x80, 0xE8});
constexpr auto request = cx::pcp_write(0x5FE4, 0, step.value());
static_assert(request.value().param_counter == 7);

// The drive's positive write confirmation (layout: "PCP responses" below).
constexpr std::array<std::uint8_t, 8> reply{0x80, 0x82, 0x00, 0x02, 0x00, 0x00, 0x00, 0x00};
constexpr auto confirmation = cx::decode_pcp_response(reply);
static_assert(!confirmation.value().is_error && cx::answers(request.value(), confirmation.value()));
} // namespace doc_snippet_3

// clang-format on

namespace {

std::string read_text(const std::string &path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The bodies of the ```cpp blocks of a Markdown text.
std::vector<std::string> cpp_blocks(const std::string &md) {
  std::vector<std::string> out;
  const std::string open = "```cpp\n";
  std::size_t at = 0;
  while ((at = md.find(open, at)) != std::string::npos) {
    at += open.size();
    const std::size_t end = md.find("```", at);
    if (end == std::string::npos) break;
    out.push_back(md.substr(at, end - at));
    at = end + 3;
  }
  return out;
}

} // namespace

TEST_CASE("docs/compax.md: every C++ block is compiled here, word for word") {
  // tests run with tests/ as the working directory
  const std::string page = read_text("../docs/compax.md");
  REQUIRE_MESSAGE(!page.empty(), "../docs/compax.md not readable from the working directory");
  const std::string self = read_text(__FILE__);
  REQUIRE_MESSAGE(!self.empty(), "this test's source is not readable: ", __FILE__);
  const auto blocks = cpp_blocks(page);
  CHECK(blocks.size() == 3);
  for (const auto &b : blocks) {
    CAPTURE(b);
    CHECK(self.find(b) != std::string::npos);
  }
}

TEST_CASE("docs/compax.md: the blocks' stated results, at run time") {
  namespace nx = fieldcodec::compax::nx;
  // block 1: the record of IF E5=1 GOTO 12 has 7 content bytes; POSA 250 is 250 mm
  CHECK(doc_snippet_1::rec.value()[0] == 7);
  CHECK(doc_snippet_1::rec.value()[1] == 0x49);
  CHECK(doc_snippet_1::posa == nx::parse_command("POSA 250").value());
  CHECK(nx::encode_record(doc_snippet_1::posa).value() ==
        nx::record{7, 0x41, 0x00, 0x00, 0x00, 0xFA, 0x00, 0x00});
  // block 2: objects by descriptor, by array element, Px, CONTROL's range
  CHECK(doc_snippet_2::posa_bytes() ==
        std::array<std::uint8_t, 6>{0x00, 0x00, 0x07, 0x35, 0x01, 0x50});
  CHECK(doc_snippet_2::negative_limit() == std::array<std::uint8_t, 4>{0xFF, 0xE6, 0xD2, 0xB0});
  CHECK(doc_snippet_2::p11_bytes() == std::array<std::uint8_t, 4>{0x00, 0x4C, 0x4B, 0x40});
  CHECK(doc_snippet_2::control_22_refused());
  // block 3: POSRXSPEEDY as a PCP write and its confirmation
  CHECK(doc_snippet_3::request.value().param_counter == 7);
  CHECK(doc_snippet_3::step.value()[2] == 0xD9);
  CHECK(fieldcodec::compax::answers(doc_snippet_3::request.value(),
                                    doc_snippet_3::confirmation.value()));
}
