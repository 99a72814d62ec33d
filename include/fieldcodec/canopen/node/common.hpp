// fieldcodec — what the node services (canopen/node/) share: bounded lists of the frames and
// events one call produces, times in the caller's millisecond counter, the CiA 301 rules for
// COB-ID values written to communication objects, and the store a node works on.
//
// Every node service is a plain object the caller owns (no heap, no I/O, no clock): frames go in
// through on_frame(frame, now), time through poll(now), and every call returns the common
// canopen::step (frames to send, state, next deadline; see canopen/step.hpp).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/dictionary.hpp>

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fieldcodec::canopen::node {

using sdo::abort_code;

// ---------------------------------------------------------------------------------------------
// Bounded lists

/// The frames one call produces, held by the machine (valid until its next call). A list is
/// sized so that one call cannot overflow it; push() still refuses rather than overwrite, and
/// counts what it refused (lost(), which the tests check is always 0).
template <std::size_t N>
class frame_list {
public:
  constexpr void clear() noexcept { n_ = 0; }
  constexpr bool push(const can_frame &f) noexcept {
    if (n_ == N) {
      ++lost_;
      return false;
    }
    f_[n_++] = f;
    return true;
  }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return n_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return n_ == 0U; }
  [[nodiscard]] constexpr std::span<const can_frame> span() const noexcept {
    return std::span<const can_frame>(f_.data(), n_);
  }
  [[nodiscard]] constexpr frames view() const noexcept {
    if (n_ == 0U) return {};
    if (n_ == 1U) return frames(f_[0]);
    return frames(span());
  }
  /// Frames refused because the list was full (a sizing error; never expected).
  [[nodiscard]] constexpr std::size_t lost() const noexcept { return lost_; }

private:
  std::array<can_frame, N> f_{};
  std::size_t n_ = 0;
  std::size_t lost_ = 0;
};

/// The events one call produces (valid until the next call), sized like frame_list.
template <class Event, std::size_t N>
class event_list {
public:
  constexpr void clear() noexcept { n_ = 0; }
  constexpr bool push(const Event &e) noexcept {
    if (n_ == N) {
      ++lost_;
      return false;
    }
    e_[n_++] = e;
    return true;
  }
  [[nodiscard]] constexpr std::span<const Event> span() const noexcept {
    return std::span<const Event>(e_.data(), n_);
  }
  [[nodiscard]] constexpr std::size_t lost() const noexcept { return lost_; }

private:
  std::array<Event, N> e_{};
  std::size_t n_ = 0;
  std::size_t lost_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Time

/// The earlier of two optional deadlines (wrap-around safe, relative to `now`).
[[nodiscard]] constexpr std::optional<std::uint32_t> earliest(std::optional<std::uint32_t> a,
                                                              std::optional<std::uint32_t> b,
                                                              std::uint32_t now) noexcept {
  if (!a) return b;
  if (!b) return a;
  // compare distances from now; a deadline already passed (distance ≥ 2^31) counts as now
  const std::uint32_t da = reached(*a, now) ? 0U : *a - now;
  const std::uint32_t db = reached(*b, now) ? 0U : *b - now;
  return da <= db ? a : b;
}

/// A time in units of 100 µs (inhibit times) as whole milliseconds of the caller's counter,
/// rounded up: an inhibit time is a minimum, so 1 (100 µs) waits 1 ms.
[[nodiscard]] constexpr std::uint32_t ms_from_100us(std::uint32_t t) noexcept {
  return t / 10U + (t % 10U != 0U ? 1U : 0U);
}
/// Microseconds (1006h, 1007h) as milliseconds, rounded up.
[[nodiscard]] constexpr std::uint32_t ms_from_us(std::uint32_t t) noexcept {
  return t / 1000U + (t % 1000U != 0U ? 1U : 0U);
}

// ---------------------------------------------------------------------------------------------
// Values of communication objects

/// A value of 1..4 bytes (little-endian) as an unsigned 32-bit number; nullopt for any other
/// length (the store then refuses the write with its own length abort code).
[[nodiscard]] constexpr std::optional<std::uint32_t>
u32_of(std::span<const std::uint8_t> v) noexcept {
  if (v.empty() || v.size() > 4U) return std::nullopt;
  return static_cast<std::uint32_t>(load_unsigned(v, v.size(), byte_order::little).value_or(0));
}

/// The COB-ID bits of CiA 301 communication parameters (PDO 1400h–1BFFh, SDO 1200h–12FFh,
/// EMCY 1014h, SYNC 1005h).
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

// ---------------------------------------------------------------------------------------------
// The store of a node

/// What the node (node::device) needs of a store: the canopen::object_store parts interface, plus
/// the application's own write (`set`: no access check, no write hook), the current value, the
/// dictionary, and restoring the power-on values of a range of objects (NMT resets).
/// canopen::dictionary_store is one.
template <class S>
concept node_store = canopen::object_store<S> &&
    requires(S &s, const S &cs, od::address a, std::span<const std::uint8_t> v, std::uint16_t i) {
  { s.set(a, v) } -> std::same_as<abort_code>;
  { cs.value(a) } -> std::same_as<result<std::span<const std::uint8_t>>>;
  { cs.dictionary() } -> std::same_as<od::dictionary>;
  { s.restore_defaults(i, i) } -> std::same_as<status>;
};

/// Read a value of at most 4 bytes through a store's parts interface (nullopt when the object
/// is missing, unreadable or longer).
template <canopen::object_store Store>
[[nodiscard]] constexpr std::optional<std::uint32_t> read_u32(const Store &s,
                                                              od::address a) noexcept {
  std::array<std::uint8_t, 4> b{};
  std::size_t total = 0;
  if (s.read(a, 0, b, total) != abort_code::none || total == 0U || total > 4U) {
    return std::nullopt;
  }
  return u32_of(std::span<const std::uint8_t>(b).first(total));
}

/// Little-endian bytes of `v` in the width of `a`'s entry (1..4), for the node's own writes.
struct le_value {
  std::array<std::uint8_t, 4> bytes{};
  std::size_t size = 0;
  [[nodiscard]] constexpr std::span<const std::uint8_t> span() const noexcept {
    return std::span<const std::uint8_t>(bytes).first(size);
  }
};
[[nodiscard]] constexpr le_value encode_le(std::uint32_t v, std::size_t width) noexcept {
  le_value out;
  out.size = width > 4U ? 4U : width;
  for (std::size_t i = 0; i < out.size; ++i) {
    out.bytes[i] = static_cast<std::uint8_t>((v >> (8U * i)) & 0xFFU);
  }
  return out;
}

} // namespace fieldcodec::canopen::node
