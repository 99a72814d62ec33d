// fieldcodec — COMPAX process-data configuration (manual 000, sections 1.4, 2.12, 4):
// PE_SELECT / PA_SELECT records, PED_INI / PAD_INI / IN_SELECT / OUT_SELECT assignments,
// the parameters P135..P142 (index · 256 + sub-index) and the P196 channel layouts.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::compax {

/// The object (index, sub-index) placed on a process-data byte; {0, 0} is the null object
/// that removes an assignment.
struct pd_assignment {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;

  [[nodiscard]] constexpr bool is_null() const noexcept { return index == 0U && sub == 0U; }
  friend constexpr bool operator==(const pd_assignment &, const pd_assignment &) = default;
};

/// Value of P135..P142: index · 256 + sub-index (e.g. LAGE_ZIEL 0x607A → 6322688).
[[nodiscard]] constexpr std::uint32_t assignment_parameter(pd_assignment a) noexcept {
  return (std::uint32_t{a.index} << 8U) | a.sub;
}
/// P135..P142 value → assignment. Errors: out_of_range (above 16 777 215).
[[nodiscard]] constexpr result<pd_assignment> assignment_from_parameter(std::uint32_t v) noexcept {
  if (v > 0xFFFFFFU) return errc::out_of_range;
  return pd_assignment{static_cast<std::uint16_t>(v >> 8U), static_cast<std::uint8_t>(v & 0xFFU)};
}

inline constexpr std::size_t assignment_size = 3;

/// PED_INI / PAD_INI sub-index data and IN_SELECT / OUT_SELECT (sub-index 0, whole record):
/// index high byte, index low byte, sub-index.
[[nodiscard]] constexpr std::array<std::uint8_t, assignment_size>
encode_assignment(pd_assignment a) noexcept {
  const auto index = to_bytes<std::uint16_t>(a.index, byte_order::big);
  return {index[0], index[1], a.sub};
}
/// Errors: truncated, bad_length.
[[nodiscard]] constexpr result<pd_assignment>
decode_assignment(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < assignment_size) return errc::truncated;
  if (in.size() > assignment_size) return errc::bad_length;
  return pd_assignment{load<std::uint16_t>(in, byte_order::big).value(), in[2]};
}

/// PE_SELECT / PA_SELECT (record of 19 bytes): sub-index 1 = channel length (bytes), then for
/// each of the 6 configurable process-data bytes an index (sub-index 2, 4, …, 12, Unsigned16)
/// and a sub-index (3, 5, …, 13, Unsigned8).
inline constexpr std::size_t pd_select_slots = 6;
inline constexpr std::size_t pd_select_size = 1U + pd_select_slots * assignment_size;

struct pd_select {
  std::uint8_t length = 0; ///< sub-index 1, "not variable"
  std::array<pd_assignment, pd_select_slots> slots{};
  friend constexpr bool operator==(const pd_select &, const pd_select &) = default;
};

/// Size of one PE_SELECT / PA_SELECT sub-index (0 = whole record). Errors: unknown_object.
[[nodiscard]] constexpr result<std::size_t> pd_select_subindex_size(std::uint8_t sub) noexcept {
  if (sub == 0U) return pd_select_size;
  if (sub == 1U) return std::size_t{1};
  if (sub > 13U) return errc::unknown_object;
  return (sub % 2U == 0U) ? std::size_t{2} : std::size_t{1};
}

[[nodiscard]] constexpr std::array<std::uint8_t, pd_select_size>
encode_pd_select(const pd_select &s) noexcept {
  std::array<std::uint8_t, pd_select_size> out{};
  out[0] = s.length;
  for (std::size_t i = 0; i < pd_select_slots; ++i) {
    const auto a = encode_assignment(s.slots[i]);
    for (std::size_t k = 0; k < assignment_size; ++k) out[1U + i * assignment_size + k] = a[k];
  }
  return out;
}
/// Errors: truncated, bad_length.
[[nodiscard]] constexpr result<pd_select>
decode_pd_select(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < pd_select_size) return errc::truncated;
  if (in.size() > pd_select_size) return errc::bad_length;
  pd_select s{};
  s.length = in[0];
  for (std::size_t i = 0; i < pd_select_slots; ++i) {
    s.slots[i] = decode_assignment(in.subspan(1U + i * assignment_size, assignment_size)).value();
  }
  return s;
}

/// P196 "process data length & protocol" (section 4).
struct p196 {
  std::uint8_t pd_mode = 0;          ///< bits 0..2: 0/1 = 1 word, 2 = 2, 3 = 3, 4 = 4 words w/o PCP
  bool variables_milli = false;      ///< bit 4: V1..V40 all with resolution 0.001
  bool temporary_object_req = false; ///< bit 5: OBJECT_REQ/RSP may be assigned temporarily
  bool object_rsp_explicit = false;  ///< bit 6: OBJECT_RSP is not assigned automatically
  bool cpx_words = false; ///< bit 7: PD1/2 = CPX_STW/CPX_ZSW (else STEUERWORT/STATUSWORT)

  [[nodiscard]] constexpr std::uint8_t raw() const noexcept {
    return static_cast<std::uint8_t>((pd_mode & 0x07U) | (variables_milli ? 0x10U : 0U) |
                                     (temporary_object_req ? 0x20U : 0U) |
                                     (object_rsp_explicit ? 0x40U : 0U) | (cpx_words ? 0x80U : 0U));
  }
  /// Errors: out_of_range (bits 0..2 above 4, or bit 3 set: not defined).
  [[nodiscard]] static constexpr result<p196> decode(std::uint8_t v) noexcept {
    if ((v & 0x07U) > 4U || (v & 0x08U) != 0U) return errc::out_of_range;
    return p196{static_cast<std::uint8_t>(v & 0x07U), (v & 0x10U) != 0U, (v & 0x20U) != 0U,
                (v & 0x40U) != 0U, (v & 0x80U) != 0U};
  }
  /// The acyclic PCP channel exists (not in the 8-byte mode).
  [[nodiscard]] constexpr bool has_pcp() const noexcept { return pd_mode != 4U; }
  /// Bytes of the cyclic process-data channel.
  [[nodiscard]] constexpr std::size_t pd_bytes() const noexcept {
    return pd_mode <= 1U ? 2U : std::size_t{2U} * pd_mode;
  }
  /// Number (1-based) of the first process-data byte the configuration objects address: 3 in
  /// the 8-byte mode (PD1/PD2 carry the control/status word), 1 otherwise.
  [[nodiscard]] constexpr std::size_t first_free_pd_byte() const noexcept {
    return pd_mode == 4U ? 3U : 1U;
  }
  /// Interbus ID code (section 1.3): 227 with PCP, 3 without.
  [[nodiscard]] constexpr std::uint8_t id_code() const noexcept { return has_pcp() ? 227U : 3U; }
  friend constexpr bool operator==(const p196 &, const p196 &) = default;
};

} // namespace fieldcodec::compax
