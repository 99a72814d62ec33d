// fieldcodec — host helper: bytes of a serial capture as readable text, for diagnostics.
//
//   host::quoted_bytes(frame)   // "<SOH><STX>0;1;15;0;0;0<ETX>2<EOT>"
//
// The control characters of ASCII serial framing (NUL, SOH, STX, ETX, EOT) are named, printable
// ASCII (20h..7Eh) is kept, every other byte is written as two upper-case hex digits in angle
// brackets ("<0D>", "<FF>"). Host only: it returns a std::string.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace fieldcodec::host {

inline std::string quoted_bytes(std::span<const std::uint8_t> bytes) {
  static constexpr std::string_view names[] = {"<NUL>", "<SOH>", "<STX>", "<ETX>", "<EOT>"};
  static constexpr char digits[] = "0123456789ABCDEF";
  std::string out;
  out.reserve(bytes.size());
  for (const std::uint8_t b : bytes) {
    if (b < 5U) {
      out += names[b];
    } else if (b >= 0x20U && b < 0x7FU) {
      out += static_cast<char>(b);
    } else {
      out += '<';
      out += digits[b >> 4U];
      out += digits[b & 0xFU];
      out += '>';
    }
  }
  return out;
}

} // namespace fieldcodec::host
