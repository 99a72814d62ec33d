// fieldcodec — UTF-8 sequences, strictly (RFC 3629: shortest form, no surrogates, at most
// U+10FFFF), constexpr and without allocation: the one UTF-8 reader of the library (od's
// UNICODE_STRING text, the CLI's JSON lines).
#pragma once

#include <fieldcodec/core/result.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace fieldcodec::utf8 {

/// The code point of the sequence at s[i]; advances `i` past it. Errors: bad_character (not the
/// start of a valid sequence, a sequence cut off, an overlong form, a surrogate, beyond
/// U+10FFFF); `i` is then unchanged.
[[nodiscard]] constexpr result<std::uint32_t> next(std::string_view s, std::size_t &i) noexcept {
  if (i >= s.size()) return errc::bad_character;
  const auto c = static_cast<unsigned char>(s[i]);
  if (c < 0x80U) {
    ++i;
    return c;
  }
  std::size_t n = 0;
  std::uint32_t cp = 0;
  if (c >= 0xC2U && c <= 0xDFU) {
    n = 1;
    cp = c & 0x1FU;
  } else if (c >= 0xE0U && c <= 0xEFU) {
    n = 2;
    cp = c & 0x0FU;
  } else if (c >= 0xF0U && c <= 0xF4U) {
    n = 3;
    cp = c & 0x07U;
  } else {
    return errc::bad_character;
  }
  for (std::size_t k = 1; k <= n; ++k) {
    if (i + k >= s.size()) return errc::bad_character;
    const auto b = static_cast<unsigned char>(s[i + k]);
    if ((b & 0xC0U) != 0x80U) return errc::bad_character;
    cp = (cp << 6U) | (b & 0x3FU);
  }
  const std::uint32_t min = n == 1 ? 0x80U : n == 2 ? 0x800U : 0x10000U;
  if (cp < min || cp > 0x10FFFFU || (cp >= 0xD800U && cp <= 0xDFFFU)) return errc::bad_character;
  i += n + 1U;
  return cp;
}

/// The length of the valid sequence at s[i], 0 when there is none.
[[nodiscard]] constexpr std::size_t sequence_length(std::string_view s, std::size_t i) noexcept {
  std::size_t j = i;
  return next(s, j) ? j - i : 0U;
}

/// Whether all of `s` is valid UTF-8.
[[nodiscard]] constexpr bool valid(std::string_view s) noexcept {
  std::size_t i = 0;
  while (i < s.size()) {
    if (!next(s, i)) return false;
  }
  return true;
}

} // namespace fieldcodec::utf8
