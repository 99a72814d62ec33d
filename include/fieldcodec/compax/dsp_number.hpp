// fieldcodec — the "DSP number format" of COMPAX Nx program records (manual 000, 2.11.2: key
// to the set-memory command code table, bytes NL NM NH VL VM VH).
//
// The manual names the six bytes but gives no example. Assumption (docs/compax.md, "DSP number
// format"), kept in this one place so that a correction is one edit:
// * NL NM NH = low, mid, high byte of the fractional part, VL VM VH = low, mid, high byte of the
//   integral part, in that order in the record: the 48-bit value is sent least significant
//   byte first (DESIGN.md: "6-byte DSP values are least significant first").
// * Together they are one 48-bit two's complement fixed-point number with 24 fractional bits
//   ("24.24"): value = raw / 2^24. A 24-bit signed integral part holds ±8 388 607, which covers
//   the drive's travel range of ±4 000 000 — the only cross-check the text offers.
// * All six bytes 0xFF are the special forms POSA HOME / POSR CAM / SPEED SYNC (the table
//   prints them so); as a number they would be −2^-24, which no 0.001-resolution value becomes.
// Values the user writes (positions in mm, speeds in %) have 3 decimals; they convert to the
// nearest raw value and back exactly (2^-24 is far finer than 0.001).
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace fieldcodec::compax {

struct dsp_format {
  static constexpr std::size_t size = 6;                  ///< bytes in a record
  static constexpr unsigned fraction_bits = 24;           ///< NL NM NH
  static constexpr byte_order order = byte_order::little; ///< NL first, VH last
  static constexpr std::int64_t one = std::int64_t{1} << fraction_bits;
  static constexpr std::int64_t raw_min = -(std::int64_t{1} << 47U);
  static constexpr std::int64_t raw_max = (std::int64_t{1} << 47U) - 1;
};

/// A DSP fixed-point number: value = raw / 2^24, raw a 48-bit two's complement integer.
struct dsp_number {
  std::int64_t raw = 0;

  /// Range of from_thousandths(): [−2^23, 2^23) in units of 0.001.
  static constexpr std::int64_t min_thousandths = -(std::int64_t{1} << 23U) * 1000;
  static constexpr std::int64_t max_thousandths = (std::int64_t{1} << 23U) * 1000 - 1;

  /// From units of 0.001 (thousandths), rounded half away from zero.
  /// Errors: overflow (outside [min_thousandths, max_thousandths]).
  [[nodiscard]] static constexpr result<dsp_number> from_thousandths(std::int64_t t) noexcept {
    if (t > max_thousandths || t < min_thousandths) return errc::overflow;
    const bool neg = t < 0;
    const std::int64_t mag = neg ? -t : t;
    const std::int64_t r = (mag * dsp_format::one + 500) / 1000;
    return dsp_number{neg ? -r : r};
  }
  /// To units of 0.001, rounded half away from zero and limited to [min_thousandths,
  /// max_thousandths] (the top 2^-24 steps below 2^23 would round up to 2^23), so that the
  /// result always converts back.
  [[nodiscard]] constexpr std::int64_t to_thousandths() const noexcept {
    const bool neg = raw < 0;
    const std::int64_t mag = neg ? -raw : raw;
    const std::int64_t t = (mag * 1000 + dsp_format::one / 2) / dsp_format::one;
    const std::int64_t v = neg ? -t : t;
    return v > max_thousandths ? max_thousandths : v;
  }
  /// The value in units of 0.001 when `raw` lies exactly on the 0.001 grid, i.e. is what
  /// from_thousandths() gives for it (every value written in program text or as a decimal with
  /// at most 3 places is). Errors: not_representable (between two thousandths), overflow
  /// (outside 48 bits).
  [[nodiscard]] constexpr result<std::int64_t> exact_thousandths() const noexcept {
    if (raw < dsp_format::raw_min || raw > dsp_format::raw_max) return errc::overflow;
    const std::int64_t t = to_thousandths();
    auto back = from_thousandths(t);
    if (!back || back.value().raw != raw) return errc::not_representable;
    return t;
  }
  friend constexpr bool operator==(const dsp_number &, const dsp_number &) = default;
};

/// Write the 6 bytes NL NM NH VL VM VH to the front of `out`.
/// Errors: overflow (raw outside 48 bits), buffer_too_small.
[[nodiscard]] constexpr status encode_dsp(dsp_number n, std::span<std::uint8_t> out) noexcept {
  if (n.raw < dsp_format::raw_min || n.raw > dsp_format::raw_max) return errc::overflow;
  return store_signed(out, dsp_format::size, n.raw, dsp_format::order);
}

/// Read 6 bytes NL … VH from the front of `in`. Errors: truncated.
[[nodiscard]] constexpr result<dsp_number> decode_dsp(std::span<const std::uint8_t> in) noexcept {
  auto v = load_signed(in, dsp_format::size, dsp_format::order);
  if (!v) return v.error();
  return dsp_number{v.value()};
}

} // namespace fieldcodec::compax
