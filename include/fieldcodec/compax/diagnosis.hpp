// fieldcodec — COMPAX diagnosis values S23_S26 (object 0x5FD8, manual 000, section 2.5.7).
//
// An array of four 2-byte status words: sub-index 1 = S23 status of the drive, 2 = S24 status
// of the switch, 3 = S25 status of the limits, 4 = S26 status of the final stage (output stage).
// Data byte 1 holds status bits 15..8, data byte 2 bits 7..0, like every 2-byte word on this
// bus. What each bit means is defined only in the COMPAX-M/S product manual, which the
// interface manual refers to; the library therefore names the words, not their bits.
#pragma once

#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::compax {

/// Sub-indices of S23_S26.
enum class diagnosis_item : std::uint8_t {
  drive = 1,       ///< S23 status of the drive
  switch_ = 2,     ///< S24 status of the switch
  limits = 3,      ///< S25 status of the limits
  final_stage = 4, ///< S26 status of the final stage (printed "final step")
};

/// The status number (23 … 26) of an item. Errors: unknown_object (not a sub-index 1 … 4).
[[nodiscard]] constexpr result<std::uint8_t> status_number(diagnosis_item i) noexcept {
  const auto sub = static_cast<std::uint8_t>(i);
  if (sub < 1U || sub > 4U) return errc::unknown_object;
  return static_cast<std::uint8_t>(22U + sub);
}

/// The item of a sub-index. Any integer type. Errors: unknown_object (not 1 … 4).
template <integer_argument T>
[[nodiscard]] constexpr result<diagnosis_item> diagnosis_item_of(T sub) noexcept {
  if (!in_closed_range(sub, 1, 4)) return errc::unknown_object;
  return static_cast<diagnosis_item>(sub);
}

[[nodiscard]] constexpr std::string_view to_string(diagnosis_item i) noexcept {
  switch (i) {
  case diagnosis_item::drive: return "S23 status drive";
  case diagnosis_item::switch_: return "S24 status switch";
  case diagnosis_item::limits: return "S25 status limits";
  case diagnosis_item::final_stage: return "S26 status final stage";
  }
  return "";
}

/// One S23 … S26 status word.
struct diagnosis_word {
  std::uint16_t raw = 0;

  /// Status bit n (0 … 15). Any integer type. Errors: out_of_range.
  template <integer_argument T>
  [[nodiscard]] constexpr result<bool> bit(T n) const noexcept {
    if (!in_closed_range(n, 0, 15)) return errc::out_of_range;
    return ((raw >> static_cast<unsigned>(n)) & 1U) != 0U;
  }
  [[nodiscard]] constexpr std::array<std::uint8_t, 2> bytes() const noexcept {
    return to_bytes<std::uint16_t>(raw, bus_order);
  }
  /// From exactly 2 data bytes. Errors: truncated, bad_length.
  [[nodiscard]] static constexpr result<diagnosis_word>
  decode(std::span<const std::uint8_t> in) noexcept {
    auto v = decode_integer<std::uint16_t>(in);
    if (!v) return v.error();
    return diagnosis_word{v.value()};
  }
  friend constexpr bool operator==(const diagnosis_word &, const diagnosis_word &) = default;
};

} // namespace fieldcodec::compax
