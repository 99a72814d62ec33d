// Serial bytes as diagnostic text (host/quoted_bytes.hpp), used by pacontrol_link's errors and
// the CLI's PA-CONTROL capture decoder.
#include <fieldcodec/host/quoted_bytes.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>

using fieldcodec::host::quoted_bytes;

TEST_CASE("quoted_bytes: frame control characters are named, text kept") {
  // Shaped like a PA-CONTROL frame: SOH STX body ETX check EOT, then other bytes.
  const std::array<std::uint8_t, 14> ack{0x01, 0x02, '0', ';',  '1',  ';', '1',
                                         '5',  0x03, '2', 0x04, 0x00, ' ', '~'};
  CHECK(quoted_bytes(ack) == "<SOH><STX>0;1;15<ETX>2<EOT><NUL> ~");
}

TEST_CASE("quoted_bytes: every other byte is two hex digits in brackets") {
  const std::array<std::uint8_t, 6> odd{0x05, 0x0D, 0x1F, 0x7F, 0x80, 0xFF};
  CHECK(quoted_bytes(odd) == "<05><0D><1F><7F><80><FF>");
  CHECK(quoted_bytes(std::span<const std::uint8_t>{}).empty());
}

TEST_CASE("quoted_bytes: all 256 bytes, one piece each") {
  for (unsigned b = 0; b < 256U; ++b) {
    const std::uint8_t byte = static_cast<std::uint8_t>(b);
    const auto s = quoted_bytes(std::span<const std::uint8_t>(&byte, 1));
    if (b >= 0x20U && b < 0x7FU) {
      CHECK(s.size() == 1U);
    } else if (b < 5U) {
      CHECK(s.size() == 5U);
    } else {
      REQUIRE(s.size() == 4U);
      CHECK(s.front() == '<');
      CHECK(s.back() == '>');
    }
  }
}
