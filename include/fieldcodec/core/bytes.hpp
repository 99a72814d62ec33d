// fieldcodec — byte order: load/store of integers of 1..8 bytes in either byte order, and
// bounded reader/writer cursors, and copies of short runs of bytes.
//
// Everything works on values, never on the host's memory layout, so results are the same on
// little- and big-endian hosts. Widths 3, 5, 6 and 7 (CANopen INTEGER24/40/48/56) are supported.
#pragma once

#include <fieldcodec/core/result.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

namespace fieldcodec {

using byte_order = std::endian; // std::endian::little or std::endian::big

namespace detail {
[[nodiscard]] constexpr std::uint64_t width_mask(std::size_t width) noexcept {
  return width >= 8U ? ~std::uint64_t{0} : (std::uint64_t{1} << (8U * width)) - 1U;
}
} // namespace detail

/// Smallest and largest signed value of a `width`-byte two's complement field (1..8).
[[nodiscard]] constexpr std::int64_t signed_min(std::size_t width) noexcept {
  return width >= 8U ? std::numeric_limits<std::int64_t>::min()
                     : -static_cast<std::int64_t>(std::uint64_t{1} << (8U * width - 1U));
}
[[nodiscard]] constexpr std::int64_t signed_max(std::size_t width) noexcept {
  return width >= 8U ? std::numeric_limits<std::int64_t>::max()
                     : static_cast<std::int64_t>((std::uint64_t{1} << (8U * width - 1U)) - 1U);
}
/// Largest unsigned value of a `width`-byte field (1..8).
[[nodiscard]] constexpr std::uint64_t unsigned_max(std::size_t width) noexcept {
  return detail::width_mask(width);
}

/// The `n` bytes (0..8) at `p` as a little-endian unsigned integer, without checks: for
/// callers that know their bytes are there (a slot of a known width, a dictionary's packed
/// columns). `Byte` is std::uint8_t or char (a string literal's bytes).
template <class Byte>
requires(sizeof(Byte) == 1) [[nodiscard]] constexpr std::uint64_t
    load_le(const Byte *p, std::size_t n) noexcept {
  std::uint64_t v = 0;
  for (std::size_t i = n; i > 0U; --i) v = (v << 8U) | static_cast<std::uint8_t>(p[i - 1U]);
  return v;
}
/// The low `n` bytes (0..8) of `v` to `p`, little-endian, without checks (as load_le).
template <class Byte>
requires(sizeof(Byte) == 1) constexpr void store_le(Byte *p, std::uint64_t v,
                                                    std::size_t n) noexcept {
  for (std::size_t i = 0; i < n; ++i)
    p[i] = static_cast<Byte>(static_cast<std::uint8_t>(v >> (8U * i)));
}

// GCC 12 at -O2/-O3 reports -Warray-bounds / -Wstringop-overflow inside the loops below
// for paths its jump threading invents after inlining (a constant width larger than a constant
// span whose size check has already returned). Every access is preceded by an explicit size
// check, so the false positives are silenced here, and only here.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wstringop-overflow"
#endif

namespace detail {
// Fixed-width bodies, written as the plain shift-or loops a person would write: with a constant
// width, compilers unroll them early and merge them into one (byte-swapped) load or store.
// Built with -Os, load_unsigned takes them only for a width that is constant after inlining
// (__builtin_constant_p) and reads a run-time width with one compact loop (≈ 350 bytes less on
// Cortex-M); otherwise a run-time width jumps to its unrolled body, which is faster (an SDO
// expedited value: 79 instead of 114 instructions). store_unsigned always switches: with a loop
// present, GCC no longer keeps a caller's small output buffer in registers.
template <std::size_t W>
[[nodiscard]] constexpr std::uint64_t load_fixed(std::span<const std::uint8_t> in,
                                                 byte_order order) noexcept {
  std::uint64_t v = 0;
  if (order == byte_order::big) {
    for (std::size_t i = 0; i < W; ++i) v = (v << 8U) | in[i];
  } else {
    for (std::size_t i = W; i-- > 0U;) v = (v << 8U) | in[i];
  }
  return v;
}
template <std::size_t W>
constexpr void store_fixed(std::span<std::uint8_t> out, std::uint64_t value,
                           byte_order order) noexcept {
  for (std::size_t i = 0; i < W; ++i) {
    out[order == byte_order::little ? i : W - 1U - i] =
        static_cast<std::uint8_t>(value >> (8U * i));
  }
}
} // namespace detail

/// Copy N bytes (a length known at compile time) from `from` to `to`, which must not overlap.
/// At run time one copy of constant length, which compilers turn into a few moves (a loop of
/// 7 byte moves cost 14 instructions, and GCC merged a `std::copy_n` of 7 next to a copy of
/// run-time length into a call of memcpy); in constant evaluation a byte loop.
template <std::size_t N>
constexpr void copy_bytes(const std::uint8_t *from, std::uint8_t *to) noexcept {
#if defined(__GNUC__)
  if (!std::is_constant_evaluated()) {
    __builtin_memcpy(to, from, N);
    return;
  }
#endif
  for (std::size_t i = 0; i < N; ++i) to[i] = from[i];
}

/// Copy n bytes from `from` to `to` (not overlapping): the widths of numbers (1, 2, 4, 8) as
/// copies of constant length, other lengths (strings, SDO parts) as one `std::copy_n`.
constexpr void copy_bytes(const std::uint8_t *from, std::uint8_t *to, std::size_t n) noexcept {
  switch (n) {
  case 1: to[0] = from[0]; return;
  case 2: copy_bytes<2>(from, to); return;
  case 4: copy_bytes<4>(from, to); return;
  case 8: copy_bytes<8>(from, to); return;
  default: std::copy_n(from, n, to); return;
  }
}

/// Read an unsigned integer of `width` bytes (1..8) from the front of `in`.
/// Errors: bad_length (width not 1..8), truncated (fewer than `width` bytes).
[[nodiscard]] constexpr result<std::uint64_t>
load_unsigned(std::span<const std::uint8_t> in, std::size_t width, byte_order order) noexcept {
  if (width < 1U || width > 8U) return errc::bad_length;
  if (in.size() < width) return errc::truncated;
#if defined(__OPTIMIZE_SIZE__)
  if (!__builtin_constant_p(width)) { // -Os and a run-time width: one compact loop
    std::uint64_t v = 0;
    if (order == byte_order::big) {
      for (std::size_t i = 0; i < width; ++i) v = (v << 8U) | in[i];
    } else {
      for (std::size_t i = width; i-- > 0U;) v = (v << 8U) | in[i];
    }
    return v;
  }
#endif
  switch (width) { // a constant width (after inlining) selects one unrolled body
  case 1: return detail::load_fixed<1>(in, order);
  case 2: return detail::load_fixed<2>(in, order);
  case 3: return detail::load_fixed<3>(in, order);
  case 4: return detail::load_fixed<4>(in, order);
  case 5: return detail::load_fixed<5>(in, order);
  case 6: return detail::load_fixed<6>(in, order);
  case 7: return detail::load_fixed<7>(in, order);
  default: return detail::load_fixed<8>(in, order);
  }
}

/// Read a two's complement signed integer of `width` bytes (1..8), sign-extended.
[[nodiscard]] constexpr result<std::int64_t>
load_signed(std::span<const std::uint8_t> in, std::size_t width, byte_order order) noexcept {
  FIELDCODEC_TRY(std::uint64_t v, load_unsigned(in, width, order));
  if (width < 8U) { // sign extension without a branch: (v ^ s) − s, s the sign bit
    const std::uint64_t sign = std::uint64_t{1} << (8U * width - 1U);
    v = (v ^ sign) - sign;
  }
  return static_cast<std::int64_t>(v); // modular conversion, well defined since C++20
}

/// Write the low `width` bytes (1..8) of `value` to the front of `out`.
/// Errors: bad_length, buffer_too_small, overflow (value needs more than `width` bytes).
[[nodiscard]] constexpr status store_unsigned(std::span<std::uint8_t> out, std::size_t width,
                                              std::uint64_t value, byte_order order) noexcept {
  if (width < 1U || width > 8U) return errc::bad_length;
  if (value > unsigned_max(width)) return errc::overflow;
  if (out.size() < width) return errc::buffer_too_small;
#if defined(__OPTIMIZE_SIZE__)
  if (!__builtin_constant_p(width)) { // -Os and a run-time width: one compact loop
    for (std::size_t i = 0; i < width; ++i) {
      out[order == byte_order::big ? width - 1U - i : i] = static_cast<std::uint8_t>(value);
      value >>= 8U;
    }
    return {};
  }
#endif
  switch (width) { // a constant width (after inlining) selects one unrolled body
  case 1: detail::store_fixed<1>(out, value, order); break;
  case 2: detail::store_fixed<2>(out, value, order); break;
  case 3: detail::store_fixed<3>(out, value, order); break;
  case 4: detail::store_fixed<4>(out, value, order); break;
  case 5: detail::store_fixed<5>(out, value, order); break;
  case 6: detail::store_fixed<6>(out, value, order); break;
  case 7: detail::store_fixed<7>(out, value, order); break;
  default: detail::store_fixed<8>(out, value, order); break;
  }
  return {};
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

/// Write `value` as a `width`-byte two's complement integer.
/// Errors: bad_length, buffer_too_small, overflow (outside signed_min..signed_max of width).
[[nodiscard]] constexpr status store_signed(std::span<std::uint8_t> out, std::size_t width,
                                            std::int64_t value, byte_order order) noexcept {
  if (width < 1U || width > 8U) return errc::bad_length;
  if (value < signed_min(width) || value > signed_max(width)) return errc::overflow;
  return store_unsigned(out, width, static_cast<std::uint64_t>(value) & detail::width_mask(width),
                        order);
}

/// Integer types of 1..8 bytes (not bool).
template <class T>
concept wire_integer =
    std::integral<T> && !std::same_as<std::remove_cv_t<T>, bool> && sizeof(T) <= 8U;

/// Read a T from the front of `in`. Errors: truncated.
template <wire_integer T>
[[nodiscard]] constexpr result<T> load(std::span<const std::uint8_t> in,
                                       byte_order order) noexcept {
  if constexpr (std::is_signed_v<T>) {
    FIELDCODEC_TRY(const std::int64_t v, load_signed(in, sizeof(T), order));
    return static_cast<T>(v);
  } else {
    FIELDCODEC_TRY(const std::uint64_t v, load_unsigned(in, sizeof(T), order));
    return static_cast<T>(v);
  }
}

/// Write a T to the front of `out`. Errors: buffer_too_small.
template <wire_integer T>
[[nodiscard]] constexpr status store(std::span<std::uint8_t> out, T value,
                                     byte_order order) noexcept {
  if constexpr (std::is_signed_v<T>) {
    return store_signed(out, sizeof(T), static_cast<std::int64_t>(value), order);
  } else {
    return store_unsigned(out, sizeof(T), static_cast<std::uint64_t>(value), order);
  }
}

/// The bytes of a T in the given order (cannot fail).
template <wire_integer T>
[[nodiscard]] constexpr std::array<std::uint8_t, sizeof(T)> to_bytes(T value,
                                                                     byte_order order) noexcept {
  std::array<std::uint8_t, sizeof(T)> out{};
  using U = std::make_unsigned_t<T>;
  const auto u = static_cast<U>(value);
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    const std::size_t k = order == byte_order::little ? i : sizeof(T) - 1U - i;
    out[k] = static_cast<std::uint8_t>(static_cast<std::uint64_t>(u) >> (8U * i));
  }
  return out;
}

/// A T from exactly sizeof(T) bytes (cannot fail).
template <wire_integer T>
[[nodiscard]] constexpr T from_bytes(const std::array<std::uint8_t, sizeof(T)> &in,
                                     byte_order order) noexcept {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    const std::size_t k = order == byte_order::big ? i : sizeof(T) - 1U - i;
    v = (v << 8U) | in[k];
  }
  return static_cast<T>(static_cast<std::make_unsigned_t<T>>(v));
}

/// A cursor over input bytes that reports `truncated` instead of reading past the end.
/// A failed read does not move the cursor.
class byte_reader {
public:
  constexpr explicit byte_reader(std::span<const std::uint8_t> in) noexcept : in_(in) {}

  [[nodiscard]] constexpr std::size_t position() const noexcept { return pos_; }
  [[nodiscard]] constexpr std::size_t remaining() const noexcept { return in_.size() - pos_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return pos_ == in_.size(); }
  /// The bytes not read yet.
  [[nodiscard]] constexpr std::span<const std::uint8_t> rest() const noexcept {
    return in_.subspan(pos_);
  }

  [[nodiscard]] constexpr result<std::uint8_t> read_u8() noexcept {
    if (remaining() < 1U) return errc::truncated;
    return in_[pos_++];
  }
  template <wire_integer T>
  [[nodiscard]] constexpr result<T> read(byte_order order) noexcept {
    auto v = load<T>(rest(), order);
    if (v) pos_ += sizeof(T);
    return v;
  }
  [[nodiscard]] constexpr result<std::uint64_t> read_unsigned(std::size_t width,
                                                              byte_order order) noexcept {
    auto v = load_unsigned(rest(), width, order);
    if (v) pos_ += width;
    return v;
  }
  [[nodiscard]] constexpr result<std::int64_t> read_signed(std::size_t width,
                                                           byte_order order) noexcept {
    auto v = load_signed(rest(), width, order);
    if (v) pos_ += width;
    return v;
  }
  /// The next `n` bytes as a view into the input.
  [[nodiscard]] constexpr result<std::span<const std::uint8_t>> read_bytes(std::size_t n) noexcept {
    if (remaining() < n) return errc::truncated;
    auto s = in_.subspan(pos_, n);
    pos_ += n;
    return s;
  }
  [[nodiscard]] constexpr status skip(std::size_t n) noexcept {
    if (remaining() < n) return errc::truncated;
    pos_ += n;
    return {};
  }

private:
  std::span<const std::uint8_t> in_;
  std::size_t pos_ = 0;
};

/// A cursor over an output buffer that reports `buffer_too_small` instead of writing past the
/// end. A failed write does not move the cursor.
class byte_writer {
public:
  constexpr explicit byte_writer(std::span<std::uint8_t> out) noexcept : out_(out) {}

  [[nodiscard]] constexpr std::size_t size() const noexcept { return pos_; }
  [[nodiscard]] constexpr std::size_t remaining() const noexcept { return out_.size() - pos_; }
  /// The bytes written so far.
  [[nodiscard]] constexpr std::span<std::uint8_t> written() const noexcept {
    return out_.first(pos_);
  }

  [[nodiscard]] constexpr status write_u8(std::uint8_t b) noexcept {
    if (remaining() < 1U) return errc::buffer_too_small;
    out_[pos_++] = b;
    return {};
  }
  template <wire_integer T>
  [[nodiscard]] constexpr status write(T value, byte_order order) noexcept {
    auto s = store<T>(out_.subspan(pos_), value, order);
    if (s) pos_ += sizeof(T);
    return s;
  }
  [[nodiscard]] constexpr status write_unsigned(std::size_t width, std::uint64_t value,
                                                byte_order order) noexcept {
    auto s = store_unsigned(out_.subspan(pos_), width, value, order);
    if (s) pos_ += width;
    return s;
  }
  [[nodiscard]] constexpr status write_signed(std::size_t width, std::int64_t value,
                                              byte_order order) noexcept {
    auto s = store_signed(out_.subspan(pos_), width, value, order);
    if (s) pos_ += width;
    return s;
  }
  [[nodiscard]] constexpr status write_bytes(std::span<const std::uint8_t> bytes) noexcept {
    if (remaining() < bytes.size()) return errc::buffer_too_small;
    for (auto b : bytes) out_[pos_++] = b;
    return {};
  }
  /// Write `n` copies of `fill`.
  [[nodiscard]] constexpr status pad(std::size_t n, std::uint8_t fill = 0) noexcept {
    if (remaining() < n) return errc::buffer_too_small;
    for (std::size_t i = 0; i < n; ++i) out_[pos_++] = fill;
    return {};
  }

private:
  std::span<std::uint8_t> out_;
  std::size_t pos_ = 0;
};

} // namespace fieldcodec
