// PDO speed-ups of issue 18 change no result: the sign extension without a test of the sign bit
// (unpack_signed, and field_value behind every get of a mapping) and pack_all's 64-bit-word fast
// path are each compared with the code they replaced, kept here as the reference: every
// offset/length combination, every signedness and value type, values at and past each field's
// limits, bad lengths, short buffers, and the bytes left in the buffer on success and on error.
#include <fieldcodec/canopen/pdo.hpp>

#include <doctest/doctest.h>

#include "xorshift.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

namespace fc = fieldcodec;
namespace pdo = fieldcodec::canopen::pdo;
using fc::errc;
using pdo::mapping_entry;
using pdo::signedness;

namespace {

// ----- the code before issue 18, verbatim but for the names -----------------------------------

fc::result<std::int64_t> reference_unpack_signed(std::span<const std::uint8_t> p,
                                                 std::size_t offset, std::size_t length) {
  FIELDCODEC_TRY(std::uint64_t v, pdo::unpack(p, offset, length));
  if (length < 64U && ((v >> (length - 1U)) & 1U) != 0U) v |= ~std::uint64_t{0} << length;
  return static_cast<std::int64_t>(v);
}

template <class T>
fc::result<T> reference_field_value(std::uint64_t raw, std::size_t length, signedness s) {
  if (s == signedness::signed_ && length < 64U && ((raw >> (length - 1U)) & 1U) != 0U) {
    raw |= ~std::uint64_t{0} << length; // sign-extend
  }
  if (s == signedness::signed_ && (raw >> 63U) != 0U) { // negative
    const auto x = static_cast<std::int64_t>(raw);
    if constexpr (std::is_signed_v<T>) {
      if (x < static_cast<std::int64_t>(std::numeric_limits<T>::min())) return errc::overflow;
      return static_cast<T>(x);
    } else {
      return errc::overflow;
    }
  }
  if (raw > static_cast<std::uint64_t>(std::numeric_limits<T>::max())) return errc::overflow;
  return static_cast<T>(raw);
}

template <class T>
fc::result<std::size_t> reference_pack_all(std::span<const mapping_entry> entries,
                                           std::span<const T> values, std::span<std::uint8_t> p) {
  if (values.size() != entries.size()) return errc::bad_length;
  std::size_t offset = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    FIELDCODEC_TRY_STATUS(
        pdo::detail::pack_value(p, offset, entries[i].bits, signedness::unknown, values[i]));
    offset += entries[i].bits;
  }
  return (offset + 7U) / 8U;
}

// ----- inputs
// -------------------------------------------------------------------------------------

struct rng : fieldcodec::test::xorshift {
  using xorshift::xorshift;
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
};

/// Values at and around the limits of a `bits`-bit field (as unsigned and as two's complement),
/// and of 64 bits.
std::vector<std::uint64_t> edges(std::size_t bits) {
  std::vector<std::uint64_t> v{0U, 1U, ~std::uint64_t{0}, std::uint64_t{1} << 63U,
                               (std::uint64_t{1} << 63U) - 1U};
  if (bits >= 1U && bits <= 64U) {
    const std::uint64_t mask = bits == 64U ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1U;
    const std::uint64_t half = std::uint64_t{1} << (bits - 1U);
    for (const std::uint64_t x : {mask, mask + 1U, mask - 1U, half, half - 1U, half + 1U,
                                  ~half + 1U, ~half, ~half + 2U, ~mask, ~mask + 1U}) {
      v.push_back(x);
    }
  }
  return v;
}

template <class T>
bool same(const fc::result<T> &a, const fc::result<T> &b) {
  if (a.has_value() != b.has_value()) return false;
  return a.has_value() ? a.value() == b.value() : a.error() == b.error();
}

template <class T>
void check_field_value_type(std::uint64_t raw, std::size_t length) {
  for (const signedness s : {signedness::unknown, signedness::unsigned_, signedness::signed_}) {
    const auto got = pdo::detail::field_value<T>(raw, length, s);
    const auto want = reference_field_value<T>(raw, length, s);
    if (!same(got, want)) {
      FAIL_CHECK("field_value differs: raw " << raw << " length " << length << " sign "
                                             << static_cast<int>(s));
    }
  }
}

void check_field_value(std::uint64_t raw, std::size_t length) {
  check_field_value_type<std::int8_t>(raw, length);
  check_field_value_type<std::uint8_t>(raw, length);
  check_field_value_type<std::int16_t>(raw, length);
  check_field_value_type<std::uint16_t>(raw, length);
  check_field_value_type<std::int32_t>(raw, length);
  check_field_value_type<std::uint32_t>(raw, length);
  check_field_value_type<std::int64_t>(raw, length);
  check_field_value_type<std::uint64_t>(raw, length);
}

/// pack_all and the reference on the same entries, values and buffer contents: the same result
/// and the same bytes afterwards (also on error: what the reference wrote before failing).
template <class T>
void check_pack_all(std::span<const mapping_entry> entries, std::span<const T> values,
                    std::size_t buffer, std::uint64_t fill, int &differences) {
  std::array<std::uint8_t, 12> a{};
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = static_cast<std::uint8_t>(fill >> (5U * i));
  auto b = a;
  const auto got = pdo::pack_all(entries, values, std::span<std::uint8_t>(a).first(buffer));
  const auto want = reference_pack_all(entries, values, std::span<std::uint8_t>(b).first(buffer));
  if (!same(got, want) || a != b) ++differences;
}

} // namespace

TEST_CASE("pdo: unpack_signed reads what the reference read, every offset and length") {
  rng r{0x5EED'0001U};
  int differences = 0;
  for (std::size_t size = 0; size <= 10U; ++size) {
    std::array<std::uint8_t, 10> buf{};
    for (int k = 0; k < 8; ++k) {
      for (auto &b : buf) b = static_cast<std::uint8_t>(r.next());
      if (k == 0) buf.fill(0xFF); // every sign bit set
      if (k == 1) buf.fill(0x00);
      if (k == 2) buf.fill(0x80);
      const std::span<const std::uint8_t> p = std::span<const std::uint8_t>(buf).first(size);
      for (std::size_t offset = 0; offset <= 8U * size + 1U; ++offset) {
        for (std::size_t length = 0; length <= 66U; ++length) { // 0, 65, 66: bad_length
          if (!same(pdo::unpack_signed(p, offset, length),
                    reference_unpack_signed(p, offset, length))) {
            ++differences;
          }
        }
      }
    }
  }
  CHECK(differences == 0);
}

TEST_CASE("pdo: field_value gives the reference's value or error for every type, sign, length") {
  rng r{0x5EED'0002U};
  for (std::size_t length = 1; length <= 64U; ++length) {
    const std::uint64_t mask =
        length == 64U ? ~std::uint64_t{0} : (std::uint64_t{1} << length) - 1U;
    for (const std::uint64_t e : edges(length)) check_field_value(e & mask, length);
    for (int k = 0; k < 200; ++k) check_field_value(r.next() & mask, length);
  }
}

TEST_CASE("pdo: a static mapping's get and get_signed read what the reference read") {
  // every sign bit set and clear, through mappings built with and without signedness
  constexpr mapping_entry e[] = {
      {0x2000, 1, 3}, {0x2000, 2, 16}, {0x2000, 3, 13}, {0x2000, 4, 8}, {0x2000, 5, 24}};
  constexpr auto raw = pdo::make_static_mapping(e);
  auto typed = raw;
  typed.signs = {signedness::signed_, signedness::unsigned_, signedness::signed_,
                 signedness::signed_, signedness::unknown};
  rng r{0x5EED'0003U};
  int differences = 0;
  for (int k = 0; k < 4000; ++k) {
    std::array<std::uint8_t, 8> p{};
    for (auto &b : p) b = static_cast<std::uint8_t>(r.next());
    for (std::size_t i = 0; i < 5U; ++i) {
      const auto bits = e[i].bits;
      const auto at = raw.offsets[i];
      if (!same(raw.get_signed(p, i), reference_unpack_signed(p, at, bits))) ++differences;
      const auto u = pdo::unpack(p, at, bits).value();
      if (!same(typed.get<std::int8_t>(p, i),
                reference_field_value<std::int8_t>(u, bits, typed.signs[i])) ||
          !same(typed.get<std::uint16_t>(p, i),
                reference_field_value<std::uint16_t>(u, bits, typed.signs[i])) ||
          !same(typed.get(p, i), reference_field_value<std::int64_t>(u, bits, typed.signs[i])) ||
          !same(raw.get(p, i), reference_field_value<std::int64_t>(u, bits, signedness::unknown))) {
        ++differences;
      }
    }
  }
  CHECK(differences == 0);
}

TEST_CASE("pdo: pack_all gives the reference's result and bytes, good values and bad") {
  rng r{0x5EED'0004U};
  int differences = 0;
  // the benchmark's RPDO and single entries of every length 0..66 at every offset a 12-byte
  // buffer allows (through a dummy entry before it), each value at the field's limits
  for (std::size_t lead = 0; lead <= 64U; lead += 1U) {
    for (std::size_t bits = 0; bits <= 66U; ++bits) {
      std::vector<mapping_entry> entries;
      std::size_t l = lead;
      while (l > 0U) { // dummy entries (UNSIGNED8/16/32-sized lengths do not matter here)
        const std::size_t n = l > 32U ? 32U : l;
        entries.push_back({0x0007, 0, static_cast<std::uint8_t>(n)});
        l -= n;
      }
      entries.push_back({0x2000, 1, static_cast<std::uint8_t>(bits)});
      for (const std::uint64_t e : edges(bits)) {
        std::vector<std::uint64_t> u(entries.size(), 0U);
        std::vector<std::int64_t> s(entries.size(), 0);
        u.back() = e;
        s.back() = static_cast<std::int64_t>(e);
        for (const std::size_t buffer :
             {std::size_t{0}, std::size_t{1}, std::size_t{4}, std::size_t{7}, std::size_t{8},
              std::size_t{9}, std::size_t{12}}) {
          const std::uint64_t fill = r.next();
          check_pack_all<std::uint64_t>(entries, u, buffer, fill, differences);
          check_pack_all<std::int64_t>(entries, s, buffer, fill, differences);
        }
      }
    }
  }
  // random mappings: 0..10 entries of random lengths (sometimes 0 or over 64), random values
  // (sometimes too wide, sometimes negative), value counts that sometimes differ
  for (int k = 0; k < 60000; ++k) {
    const std::size_t count = r.below(11);
    std::vector<mapping_entry> entries(count);
    for (auto &e : entries) {
      const std::size_t pick = r.below(20);
      e.index = 0x2000;
      e.bits = static_cast<std::uint8_t>(pick == 0U   ? 0U
                                         : pick == 1U ? 65U + r.below(191)
                                         : pick < 8U  ? 8U * (1U + r.below(8))
                                                      : 1U + r.below(64));
      if (count > 2U && e.bits > 24U && r.below(4) != 0U)
        e.bits = static_cast<std::uint8_t>(1U + r.below(24));
    }
    const std::size_t nvalues = r.below(30) == 0U ? r.below(11) : count;
    std::vector<std::uint64_t> u(nvalues);
    std::vector<std::int64_t> s(nvalues);
    for (std::size_t i = 0; i < nvalues; ++i) {
      const std::size_t bits =
          i < count && entries[i].bits >= 1U && entries[i].bits <= 64U ? entries[i].bits : 64U;
      const std::uint64_t mask = bits == 64U ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1U;
      const std::size_t how = r.below(10);
      std::uint64_t v = r.next();
      if (how < 5U) v &= mask >> r.below(2);   // fits (as unsigned, or as signed)
      if (how == 5U) v = ~(v & (mask >> 1U));  // negative, fits as two's complement
      if (how == 6U) v = ~(mask >> 1U);        // the most negative value of the field
      if (how == 7U) v = mask + 1U + (v & 3U); // one past the field
      u[i] = v;
      s[i] = static_cast<std::int64_t>(v);
    }
    const std::size_t buffer = r.below(13);
    const std::uint64_t fill = r.next();
    check_pack_all<std::uint64_t>(entries, u, buffer, fill, differences);
    check_pack_all<std::int64_t>(entries, s, buffer, fill, differences);
  }
  CHECK(differences == 0);
}

TEST_CASE("pdo: pack_all's fast path keeps the bits past the mapping and refuses what it did") {
  // 12 bits into a buffer of 0xFF: the upper nibble of byte 1 and the bytes after it stay
  constexpr mapping_entry e[] = {{0x2000, 1, 4}, {0x2000, 2, 8}};
  std::array<std::uint8_t, 9> p{};
  p.fill(0xFF);
  const std::array<std::uint64_t, 2> v{0x5, 0xA3};
  const auto n = pdo::pack_all(e, v, p);
  REQUIRE(n.has_value());
  CHECK(n.value() == 2U);
  CHECK(p == std::array<std::uint8_t, 9>{0x35, 0xFA, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF});
  // a value one past its field: overflow, the entry before it written (as the general loop does)
  p.fill(0x00);
  const std::array<std::int64_t, 2> bad{0x5, 0x100};
  CHECK(pdo::pack_all(e, bad, p).error() == errc::overflow);
  CHECK(p[0] == 0x05);
  CHECK(p[1] == 0x00);
  // -8 fits 4 bits as two's complement, -9 does not; a uint64 is never negative
  const std::array<std::int64_t, 2> neg{-8, -128};
  REQUIRE(pdo::pack_all(e, neg, p).has_value());
  CHECK(p[0] == 0x08);
  CHECK(p[1] == 0x08);
  const std::array<std::int64_t, 2> neg9{-9, 0};
  CHECK(pdo::pack_all(e, neg9, p).error() == errc::overflow);
  const std::array<std::uint64_t, 2> huge{~std::uint64_t{0} - 4U, 0};
  CHECK(pdo::pack_all(e, huge, p).error() == errc::overflow);
  // too short a buffer, a zero length, more than 64 bits
  std::array<std::uint8_t, 1> one{};
  CHECK(pdo::pack_all(e, v, one).error() == errc::buffer_too_small);
  constexpr mapping_entry zero[] = {{0x2000, 1, 0}};
  const std::array<std::uint64_t, 1> z{0};
  CHECK(pdo::pack_all(zero, z, p).error() == errc::bad_length);
  constexpr mapping_entry wide[] = {{0x2000, 1, 64}, {0x2000, 2, 8}};
  const std::array<std::uint64_t, 2> w{~std::uint64_t{0}, 0x42};
  REQUIRE(pdo::pack_all(wide, w, p).has_value());
  CHECK(p == std::array<std::uint8_t, 9>{0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x42});
}

static_assert([] { // the fast path at compile time
  constexpr mapping_entry e[] = {{0x6040, 0, 16}, {0x607A, 0, 32}, {0x6060, 0, 8}};
  std::array<std::uint8_t, 8> p{};
  const std::array<std::int64_t, 3> v{0x000F, -2, 1};
  const auto n = pdo::pack_all(e, v, p);
  return n.has_value() && n.value() == 7U &&
         p == std::array<std::uint8_t, 8>{0x0F, 0x00, 0xFE, 0xFF, 0xFF, 0xFF, 0x01, 0x00};
}());
static_assert(pdo::unpack_signed(std::array<std::uint8_t, 2>{0xF0, 0x0F}, 4, 8).value() == -1);
static_assert(pdo::unpack_signed(std::array<std::uint8_t, 2>{0xF0, 0x07}, 4, 8).value() == 127);
