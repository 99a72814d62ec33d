// fieldcodec — PA-CONTROL elements: inputs I1…, outputs O1… and flags M1… (manual 001, 5.2.4,
// 5.2.6.23, 6.3).
//
// Elements are numbered from 1 (the element commands take 1-1024). Sixteen consecutive
// elements form a word: word k holds elements 16k-15 … 16k, bit 0 the lowest (input word 1 =
// I1…I16, flag word FW22 = M337…M352). The word commands (1901, 0903, 1903, 0905, 1905) take
// any element of the word as their parameter and carry the word's 16 states as their date.
//
//   locate_element(352)              → {22, 15}       (6.3: FW22 bit 15)
//   element_word w = element_word::containing(17).value();
//   w.set(17), w.set(21), … w.set(30) → w.bits == 0x3E11 (5.2.4.5 example)
//
// Command 0AA3 moves an axis only while an element has a given state; its 32-bit date packs
// the state (bits 31-24), the element type (23-16) and the element number (15-0):
//
//   encode_element_condition({true, element_type::flag, 11}) → 0x0103000B
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/integer.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace fieldcodec::pacontrol {

/// Highest element number the element commands take (5.2.4: 0001-0400 hex).
inline constexpr std::uint16_t max_element_number = 1024;
/// Elements in one input, output or flag word.
inline constexpr std::uint16_t elements_per_word = 16;
/// Words that hold elements 1-1024.
inline constexpr std::uint16_t max_element_word = max_element_number / elements_per_word;

/// Where an element sits: word 1-64 and bit 0-15.
struct element_bit {
  std::uint16_t word = 1;
  std::uint8_t bit = 0;

  friend constexpr bool operator==(const element_bit &, const element_bit &) noexcept = default;
};

/// The word and bit of element `number` (I, O or M). Errors: out_of_range (not 1-1024).
template <integer_argument T>
[[nodiscard]] constexpr result<element_bit> locate_element(T number) noexcept {
  if (!in_closed_range(number, 1, max_element_number)) return errc::out_of_range;
  const auto index = static_cast<std::uint16_t>(static_cast<std::uint16_t>(number) - 1U);
  return element_bit{static_cast<std::uint16_t>(index / elements_per_word + 1U),
                     static_cast<std::uint8_t>(index % elements_per_word)};
}

/// The element number at a word and bit. Errors: out_of_range (word not 1-64, bit not 0-15).
template <integer_argument W, integer_argument B>
[[nodiscard]] constexpr result<std::uint16_t> element_number(W word, B bit) noexcept {
  if (!in_closed_range(word, 1, max_element_word) ||
      !in_closed_range(bit, 0, elements_per_word - 1U)) {
    return errc::out_of_range;
  }
  return static_cast<std::uint16_t>((static_cast<unsigned>(word) - 1U) * elements_per_word +
                                    static_cast<unsigned>(bit) + 1U);
}

/// The 16 states of one input, output or flag word.
struct element_word {
  std::uint16_t word = 1; ///< 1-64
  std::uint16_t bits = 0; ///< bit 0 = the word's first element

  /// The word holding element `number`, with the given states (a word date as read, e.g.
  /// the int32 date of 1901). Errors: out_of_range (number not 1-1024), overflow (bits
  /// negative or beyond 16 bits).
  template <integer_argument N, integer_argument B = std::uint16_t>
  [[nodiscard]] static constexpr result<element_word> containing(N number, B bits = 0) noexcept {
    auto at = locate_element(number);
    if (!at) return at.error();
    auto b = checked_narrow<std::uint16_t>(bits);
    if (!b) return b.error();
    return element_word{at.value().word, b.value()};
  }

  /// Number of the word's first element (16·word − 15).
  [[nodiscard]] constexpr std::uint16_t first() const noexcept {
    return static_cast<std::uint16_t>((word - 1U) * elements_per_word + 1U);
  }
  /// The state of element `number`. Errors: out_of_range (not in this word).
  template <integer_argument T>
  [[nodiscard]] constexpr result<bool> test(T number) const noexcept {
    auto b = bit_of(number);
    if (!b) return b.error();
    return (bits & (1U << b.value())) != 0U;
  }
  /// Sets the state of element `number`. Errors: out_of_range (not in this word).
  template <integer_argument T>
  [[nodiscard]] constexpr status set(T number, bool state = true) noexcept {
    auto b = bit_of(number);
    if (!b) return b.error();
    const auto mask = static_cast<std::uint16_t>(1U << b.value());
    bits = static_cast<std::uint16_t>(state ? (bits | mask) : (bits & ~mask));
    return {};
  }

  friend constexpr bool operator==(const element_word &, const element_word &) noexcept = default;

private:
  template <integer_argument T>
  [[nodiscard]] constexpr result<unsigned> bit_of(T number) const noexcept {
    auto at = locate_element(number);
    if (!at || at.value().word != word) return errc::out_of_range;
    return unsigned{at.value().bit};
  }
};

/// Element types of 0AA3's condition (5.2.6.23).
enum class element_type : std::uint8_t { input = 1, output = 2, flag = 3 };

/// 0AA3: move the axis only while element `number` of `type` has `state`.
struct element_condition {
  bool state = true; ///< move while the element is 1 (true) or 0 (false)
  element_type type = element_type::input;
  std::uint16_t number = 1; ///< 1-1024

  friend constexpr bool operator==(const element_condition &,
                                   const element_condition &) noexcept = default;
};

/// The 32-bit date of 0AA3: state (bits 31-24), type (23-16), number (15-0).
/// Errors: out_of_range (number not 1-1024), invalid_argument (type not 1-3).
[[nodiscard]] constexpr result<std::uint32_t>
encode_element_condition(const element_condition &c) noexcept {
  if (c.type != element_type::input && c.type != element_type::output &&
      c.type != element_type::flag) {
    return errc::invalid_argument;
  }
  if (!in_closed_range(c.number, 1, max_element_number)) return errc::out_of_range;
  std::array<std::uint8_t, 4> b{};
  b[0] = c.state ? 1U : 0U;
  b[1] = static_cast<std::uint8_t>(c.type);
  FIELDCODEC_TRY_STATUS(
      store<std::uint16_t>(std::span<std::uint8_t>(b).subspan(2), c.number, byte_order::big));
  return from_bytes<std::uint32_t>(b, byte_order::big);
}

/// A 0AA3 date read back. Errors: overflow (negative or beyond 32 bits), out_of_range (state
/// not 0/1, type not 1-3, number not 1-1024).
template <integer_argument T>
[[nodiscard]] constexpr result<element_condition> decode_element_condition(T date) noexcept {
  auto d = checked_narrow<std::uint32_t>(date);
  if (!d) return d.error();
  const auto b = to_bytes<std::uint32_t>(d.value(), byte_order::big);
  const auto number =
      load<std::uint16_t>(std::span<const std::uint8_t>(b).subspan(2), byte_order::big).value();
  if (b[0] > 1U || b[1] < 1U || b[1] > 3U || !in_closed_range(number, 1, max_element_number)) {
    return errc::out_of_range;
  }
  return element_condition{b[0] == 1U, static_cast<element_type>(b[1]), number};
}

} // namespace fieldcodec::pacontrol
