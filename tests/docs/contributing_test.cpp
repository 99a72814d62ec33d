// The C++ block of docs/contributing.md ("Propagation"), as written there, inside a function
// that uses both macros; the test checks that each returns the error and otherwise goes on.
// tests/docs_check/run.cmake fails when the page's block and this copy differ.
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include <doctest/doctest.h>

namespace doc_contributing {
using namespace fieldcodec;

// Parses `text`, then writes `code` and the number's places: the block's two lines.
constexpr result<decimal> parse_and_tag(std::string_view text, std::uint8_t code, byte_writer &w) {
  // clang-format off
  FIELDCODEC_TRY(const decimal d, parse_decimal(text)); // returns the error, or declares d
  FIELDCODEC_TRY_STATUS(w.write_u8(code));              // returns the error, or goes on
  // clang-format on
  FIELDCODEC_TRY_STATUS(w.write_u8(d.places));
  return d;
}

constexpr bool parses_and_writes() {
  std::array<std::uint8_t, 2> buf{};
  byte_writer w(buf);
  const auto r = parse_and_tag("12.50", 0x2A, w);
  return r && r.value().mantissa == 1250 && r.value().places == 2 && buf[0] == 0x2A && buf[1] == 2;
}
static_assert(parses_and_writes());

} // namespace doc_contributing

TEST_CASE("docs/contributing: FIELDCODEC_TRY returns the first error and writes nothing after it") {
  using namespace fieldcodec;
  std::array<std::uint8_t, 2> buf{};
  byte_writer w(buf);
  CHECK(doc_contributing::parse_and_tag("1x", 1, w).is(errc::bad_digit));
  CHECK(w.size() == 0); // the parse failed: nothing written
  std::array<std::uint8_t, 1> one{};
  byte_writer small(one);
  CHECK(doc_contributing::parse_and_tag("3", 1, small).is(errc::buffer_too_small));
  CHECK(small.size() == 1); // the code went in, the places did not fit
}
