// fieldcodec — a word of named bits, the building block of the COMPAX control and status
// objects (control.hpp). Bit n of the word is bit n of the value: for a 2-byte object data
// byte 1 (sent first) holds bits 15..8 and data byte 2 bits 7..0.
#pragma once

#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <type_traits>

namespace fieldcodec::compax {

/// `Bit` is an enum whose values are bit numbers; `Word` is std::uint8_t or std::uint16_t.
template <class Bit, class Word>
struct bit_word {
  static_assert(std::is_enum_v<Bit>);
  static_assert(std::is_same_v<Word, std::uint8_t> || std::is_same_v<Word, std::uint16_t>);
  using bit_type = Bit;
  using word_type = Word;
  static constexpr std::size_t size = sizeof(Word);

  Word raw = 0;

  [[nodiscard]] static constexpr Word mask(Bit b) noexcept {
    return static_cast<Word>(1U << static_cast<unsigned>(b));
  }
  [[nodiscard]] constexpr bool test(Bit b) const noexcept { return (raw & mask(b)) != 0U; }
  [[nodiscard]] constexpr bool operator[](Bit b) const noexcept { return test(b); }
  /// Set or clear one bit; returns *this so calls chain.
  constexpr bit_word &set(Bit b, bool on = true) noexcept {
    raw = on ? static_cast<Word>(raw | mask(b)) : static_cast<Word>(raw & ~mask(b));
    return *this;
  }
  /// A copy with one bit set or cleared.
  [[nodiscard]] constexpr bit_word with(Bit b, bool on = true) const noexcept {
    bit_word w = *this;
    w.set(b, on);
    return w;
  }
  /// The object's data bytes (big-endian).
  [[nodiscard]] constexpr std::array<std::uint8_t, size> bytes() const noexcept {
    return to_bytes<Word>(raw, bus_order);
  }
  /// From exactly `size` data bytes. Errors: truncated, bad_length.
  [[nodiscard]] static constexpr result<bit_word>
  decode(std::span<const std::uint8_t> in) noexcept {
    auto v = decode_integer<Word>(in);
    if (!v) return v.error();
    return bit_word{v.value()};
  }

  friend constexpr bool operator==(const bit_word &, const bit_word &) = default;
};

} // namespace fieldcodec::compax
