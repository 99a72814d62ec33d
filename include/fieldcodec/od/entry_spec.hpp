// fieldcodec — od::entry_spec, an entry as a person writes it (every column a plain member), and
// od::pack / od::table, which turn specs into lean od::entries with their packed columns
// (od/entry.hpp). The generator packs the same way and writes the result into generated headers;
// hand-written dictionaries (tests, small firmware, run-time tables) use these.
//
//   static constexpr std::array<od::entry_spec, 2> specs{{
//       {.index = 0x2000, .type = od::data_type::unsigned8, .low = od::unsigned_number(1),
//        .high = od::unsigned_number(100), .default_value = od::unsigned_number(5)},
//       {.index = 0x2001, .type = od::data_type::visible_string, .size = 16,
//        .default_text = "pump"},
//   }};
//   constexpr auto entries = od::entries_of<specs>;   // std::span<const od::entry, 2>, packed once
//   constexpr od::dictionary dict{entries};
//   constexpr od::descriptor pump{od::entry_of<one_spec>, {.name = "Pump"}};   // one entry
//
// od::table (what entries_of and entry_of keep, one per spec array) holds its entries and the
// bytes they point to, so it is neither copied nor moved: make one where it stays (a
// `static constexpr`, a global; a local at run time is fine as long as its entries are not used
// after it). pack() / packed_size() serve tables whose bytes live elsewhere (the CLI keeps them
// next to its run-time dictionary).
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/text.hpp>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

namespace fieldcodec::od {

/// Every column of an entry as a plain member (the shape od::entry had before its columns were
/// packed). flags: the od::flag bits the source gives (scaled, node-ID-relative, the table marks);
/// the packing bits (flag::packed) are od::pack's and are ignored here.
struct entry_spec {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  object_code object = object_code::var;
  data_type type = data_type::unsigned8;
  access access_type = access::rw;
  pdo_mapping pdo = pdo_mapping::no;
  std::uint16_t flags = 0;
  /// Capacity in bytes of a VISIBLE_STRING / OCTET_STRING / UNICODE_STRING / DOMAIN value
  /// (0: not given); ignored for every other type.
  std::uint32_t size = 0;
  number low{};           ///< lowest allowed value: engineering units when scaled, raw otherwise
  number high{};          ///< highest allowed value, same units as `low`
  number default_value{}; ///< raw default; add the node-ID when flag::default_nodeid
  text default_text{};    ///< default of a string / domain entry, as its bytes
};

namespace detail {

/// Whether `v` travels exactly in the entry's own width (and comes back as what it is, its
/// kind aside for integers: an integer entry's integers come back of the kind of its
/// signedness).
[[nodiscard]] constexpr bool fits_width(data_type t, const number &v) noexcept {
  const std::size_t w = fixed_size(t);
  if (w == 0U || !v) return false;
  if (t == data_type::real64) return v.kind == number_kind::real;
  if (t == data_type::real32) {
    if (v.kind != number_kind::real) return false;
    const double d = std::bit_cast<double>(v.bits);
    if (d != d) return false; // NaN: keep its exact bits
    const auto f = static_cast<float>(d);
    return std::bit_cast<std::uint64_t>(static_cast<double>(f)) == v.bits;
  }
  if (v.kind != number_kind::signed_ && v.kind != number_kind::unsigned_) return false;
  const bool negative = v.kind == number_kind::signed_ && static_cast<std::int64_t>(v.bits) < 0;
  if (is_signed_integer(t)) {
    const auto i = static_cast<std::int64_t>(v.bits);
    if (v.kind == number_kind::unsigned_)
      return v.bits <= static_cast<std::uint64_t>(signed_max(w));
    return i >= signed_min(w) && i <= signed_max(w);
  }
  // unsigned, BOOLEAN (one byte), TIME (6 bytes)
  return !negative && v.bits <= unsigned_max(w);
}

/// The packing bits (flag::packed) of `s`.
[[nodiscard]] constexpr std::uint16_t packed_flags(const entry_spec &s) noexcept {
  std::uint16_t f = 0;
  if (is_byte_string(s.type) && s.size != 0U) f |= flag::has_size;
  if (s.default_value) {
    f |= flag::has_default;
    if (!fits_width(s.type, s.default_value)) f |= flag::default_number;
  }
  if (s.low) f |= flag::has_low;
  if (s.high) f |= flag::has_high;
  if ((s.low && !fits_width(s.type, s.low)) || (s.high && !fits_width(s.type, s.high))) {
    f |= flag::limits_number;
  }
  if (!s.default_text.empty()) f |= flag::has_text;
  return f;
}

/// The bytes of `v` in width form (fits_width) or as a packed number; returns the bytes written.
constexpr std::size_t put_value(char *p, data_type t, const number &v, bool as_number) noexcept {
  if (as_number) {
    p[0] = static_cast<char>(static_cast<std::uint8_t>(v.kind));
    p[1] = static_cast<char>(v.places);
    store_le(p + 2, v.bits, 8);
    return packed_number_size;
  }
  const std::size_t w = fixed_size(t);
  std::uint64_t bits = v.bits;
  if (t == data_type::real32) {
    bits = std::bit_cast<std::uint32_t>(static_cast<float>(std::bit_cast<double>(v.bits)));
  }
  store_le(p, bits, w);
  return w;
}

} // namespace detail

/// The entry `s` describes, with `extra` as its packed columns (which pack(s, …) wrote).
[[nodiscard]] constexpr entry make_entry(const entry_spec &s, const char *extra) noexcept {
  entry e;
  e.index = s.index;
  e.sub = s.sub;
  e.object = s.object;
  e.type = s.type;
  e.access_type = s.access_type;
  e.pdo = s.pdo;
  e.flags = static_cast<std::uint16_t>((s.flags & ~flag::packed) | detail::packed_flags(s));
  e.extra = extra;
  return e;
}

/// Bytes of the packed columns of `s` (0: the entry needs none).
[[nodiscard]] constexpr std::size_t packed_size(const entry_spec &s) noexcept {
  const std::uint16_t f = detail::packed_flags(s);
  const std::size_t w = fixed_size(s.type);
  std::size_t n = 0;
  if ((f & flag::has_size) != 0U) n += 4U;
  if ((f & flag::has_default) != 0U) {
    n += (f & flag::default_number) != 0U ? packed_number_size : w;
  }
  const std::size_t limit = (f & flag::limits_number) != 0U ? packed_number_size : w;
  if ((f & flag::has_low) != 0U) n += limit;
  if ((f & flag::has_high) != 0U) n += limit;
  if ((f & flag::has_text) != 0U) n += 4U + s.default_text.size();
  return n;
}

/// Bytes of the packed columns of every spec.
[[nodiscard]] constexpr std::size_t packed_size(std::span<const entry_spec> specs) noexcept {
  std::size_t n = 0;
  for (const entry_spec &s : specs) n += packed_size(s);
  return n;
}

/// Writes the packed columns of `s` to the front of `out`; returns the bytes written
/// (packed_size(s)). Errors: buffer_too_small.
[[nodiscard]] constexpr result<std::size_t> pack(const entry_spec &s,
                                                 std::span<char> out) noexcept {
  const std::size_t n = packed_size(s);
  if (out.size() < n) return errc::buffer_too_small;
  const std::uint16_t f = detail::packed_flags(s);
  char *p = out.data();
  if ((f & flag::has_size) != 0U) {
    store_le(p, s.size, 4);
    p += 4;
  }
  if ((f & flag::has_default) != 0U) {
    p += detail::put_value(p, s.type, s.default_value, (f & flag::default_number) != 0U);
  }
  if ((f & flag::has_low) != 0U) {
    p += detail::put_value(p, s.type, s.low, (f & flag::limits_number) != 0U);
  }
  if ((f & flag::has_high) != 0U) {
    p += detail::put_value(p, s.type, s.high, (f & flag::limits_number) != 0U);
  }
  if ((f & flag::has_text) != 0U) {
    store_le(p, s.default_text.size(), 4);
    p += 4;
    for (std::size_t i = 0; i < s.default_text.size(); ++i) p[i] = s.default_text[i];
  }
  return n;
}

/// The spec of an entry (its columns unpacked): pack(spec_of(e)) gives e's bytes again.
[[nodiscard]] constexpr entry_spec spec_of(const entry &e) noexcept {
  entry_spec s;
  s.index = e.index;
  s.sub = e.sub;
  s.object = e.object;
  s.type = e.type;
  s.access_type = e.access_type;
  s.pdo = e.pdo;
  s.flags = static_cast<std::uint16_t>(e.flags & ~flag::packed);
  s.size = e.capacity();
  s.low = e.low();
  s.high = e.high();
  s.default_value = e.default_value();
  s.default_text = e.default_text();
  return s;
}

/// N entries and the `Bytes` bytes of their packed columns, made from N specs (in dictionary
/// order: sorted by index, then sub-index). Not copyable: the entries point into the table.
/// ok() is false when the bytes do not fit (never for table_of, whose size is computed).
template <std::size_t N, std::size_t Bytes>
class table {
public:
  constexpr explicit table(const std::array<entry_spec, N> &specs) noexcept {
    build(std::span<const entry_spec, N>(specs));
  }
  constexpr explicit table(const entry_spec (&specs)[N]) noexcept {
    build(std::span<const entry_spec, N>(specs));
  }
  /// A table of one entry.
  constexpr explicit table(const entry_spec &spec) noexcept requires(N == 1) {
    build(std::span<const entry_spec, 1>(&spec, 1));
  }
  table(const table &) = delete;
  table &operator=(const table &) = delete;

  [[nodiscard]] constexpr bool ok() const noexcept { return ok_; }
  /// The entries (those past a spec whose bytes did not fit are empty: see ok()).
  [[nodiscard]] constexpr std::span<const entry, N> entries() const noexcept { return entries_; }
  [[nodiscard]] constexpr const entry &operator[](std::size_t i) const noexcept {
    return entries_[i];
  }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return N; }
  /// The dictionary of the entries (no infos, no scales); empty when !ok().
  [[nodiscard]] constexpr od::dictionary dictionary() const noexcept {
    return ok_ ? od::dictionary{entries()} : od::dictionary{};
  }

private:
  constexpr void build(std::span<const entry_spec, N> specs) noexcept {
    std::size_t at = 0;
    for (std::size_t i = 0; i < N; ++i) {
      auto n = pack(specs[i], std::span<char>(bytes_).subspan(at));
      if (!n) return;
      entries_[i] = make_entry(specs[i], bytes_.data() + at);
      at += n.value();
    }
    ok_ = true;
  }

  std::array<entry, N> entries_{};
  std::array<char, Bytes == 0U ? 1U : Bytes> bytes_{};
  bool ok_ = false;
};

namespace detail {
template <std::size_t N>
[[nodiscard]] constexpr std::size_t spec_count(const std::array<entry_spec, N> &) noexcept {
  return N;
}
[[nodiscard]] constexpr std::size_t spec_count(const entry_spec &) noexcept { return 1; }
template <std::size_t N>
[[nodiscard]] constexpr std::size_t spec_count(const entry_spec (&)[N]) noexcept {
  return N;
}
template <std::size_t N>
[[nodiscard]] constexpr std::size_t spec_bytes(const std::array<entry_spec, N> &s) noexcept {
  return packed_size(std::span<const entry_spec>(s));
}
[[nodiscard]] constexpr std::size_t spec_bytes(const entry_spec &s) noexcept {
  return packed_size(s);
}
template <std::size_t N>
[[nodiscard]] constexpr std::size_t spec_bytes(const entry_spec (&s)[N]) noexcept {
  return packed_size(std::span<const entry_spec>(s));
}
} // namespace detail

/// The table of a constexpr array of specs (std::array or C array), or of one spec (a reference
/// to an object with static storage): `static constexpr od::table_of<specs> t{specs};`.
template <const auto &Specs>
using table_of = table<detail::spec_count(Specs), detail::spec_bytes(Specs)>;

namespace detail {
template <const auto &Specs>
inline constexpr table_of<Specs> table_for{Specs};
} // namespace detail

/// The entries of a constexpr array of specs with static storage, packed once (one table per
/// array): `constexpr auto entries = od::entries_of<specs>;` (a std::span<const entry, N>).
template <const auto &Specs>
inline constexpr auto entries_of = detail::table_for<Specs>.entries();

/// The entry of one constexpr spec with static storage, packed once:
/// `constexpr od::descriptor d{od::entry_of<spec>, {.name = "Speed"}, scale};`.
template <const entry_spec &Spec>
inline constexpr const entry &entry_of = detail::table_for<Spec>[0];

} // namespace fieldcodec::od
