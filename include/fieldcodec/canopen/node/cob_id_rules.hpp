// fieldcodec — the CiA 301 rules for COB-ID values written to communication objects (PDO
// 1400h–1BFFh, SDO 1200h–12FFh, EMCY 1014h, SYNC 1005h), which the node services check.
#pragma once

#include <fieldcodec/canopen/abort_code.hpp>

#include <cstdint>
#include <optional>

namespace fieldcodec::canopen::node {

using sdo::abort_code;

/// The COB-ID bits of CiA 301 communication parameters.
namespace cob_bits {
inline constexpr std::uint32_t invalid = 0x8000'0000U; ///< bit 31: not valid / does not exist
inline constexpr std::uint32_t bit30 = 0x4000'0000U;   ///< PDO: no RTR; SYNC: generate
inline constexpr std::uint32_t frame = 0x2000'0000U;   ///< bit 29: 29-bit identifier
inline constexpr std::uint32_t id = 0x0000'07FFU;      ///< 11-bit CAN-ID
} // namespace cob_bits

/// CiA 301 7.3.5 "restricted CAN-IDs": identifiers no PDO, SDO or EMCY may use (NMT, the
/// default SDO channels, NMT error control and the reserved ranges).
[[nodiscard]] constexpr bool is_restricted_can_id(std::uint16_t id) noexcept {
  return id <= 0x07FU || (id >= 0x101U && id <= 0x180U) || (id >= 0x581U && id <= 0x5FFU) ||
         (id >= 0x601U && id <= 0x67FU) || (id >= 0x6E0U && id <= 0x6FFU) || id >= 0x701U;
}

/// The common rule for a COB-ID written to a communication parameter whose current value is
/// `current`: a 29-bit identifier (bit 29) or any of bits 11..28 set is refused; while the
/// object is valid (bit 31 clear) and stays valid, bits 0..30 may not change (CiA 301: "it is
/// not allowed to change bits 0 to 29 while the PDO exists"; bit 30 is kept with them); a
/// valid COB-ID must not be a restricted CAN-ID (when `check_restricted`). Every refusal is
/// 0x06090030 (invalid value). `current` nullopt: nothing to compare with.
[[nodiscard]] constexpr abort_code check_cob_id(std::uint32_t value,
                                                std::optional<std::uint32_t> current,
                                                bool check_restricted) noexcept {
  if ((value & cob_bits::frame) != 0U || (value & 0x1FFF'F800U) != 0U) {
    return abort_code::invalid_value;
  }
  const bool valid = (value & cob_bits::invalid) == 0U;
  if (valid && current && (*current & cob_bits::invalid) == 0U &&
      (*current & ~cob_bits::invalid) != (value & ~cob_bits::invalid)) {
    return abort_code::invalid_value;
  }
  if (valid && check_restricted &&
      is_restricted_can_id(static_cast<std::uint16_t>(value & cob_bits::id))) {
    return abort_code::invalid_value;
  }
  return abort_code::none;
}

} // namespace fieldcodec::canopen::node
