// Fuzz harness for PDO mappings and bit packing (canopen/pdo.hpp) against the generated XENAX
// CANopen dictionary.
//
// Input: byte 0 = number of entries (low 4 bits) and direction (bit 4: TPDO); then 4 bytes per
// entry: a selector byte (bit 7 clear: the entry is the dictionary's entry number `rest` with
// its natural length; set: the 3 following bytes are index/sub/bits verbatim) and 3 bytes; then
// a 4-byte PDO COB-ID parameter; then the PDO bytes (the rest).
//
// Properties:
// * check_mapping accepts a mapping only if every entry is a dummy or a dictionary entry that
//   is mappable and accessible in the direction, its length fits the type, and the total is at
//   most 64 bits; validate() agrees with check_mapping.
// * unpack_all → pack_all gives back the PDO bytes, canonical form: the bits beyond the
//   mapping's total length cleared (pack_all leaves them as the buffer had them: zero). A PDO
//   shorter than the mapping is truncated.
// * pack_all of the fuzzed raw values (also sign-extended negatives) → unpack_all gives each
//   value's low `bits` bits; unpack_signed → pack_signed round-trips every entry.
// * unpack of a single entry at any offset / length agrees with a bit-by-bit reference model
//   (CiA 301: little-endian bit order), and pack changes exactly that entry's bits.
// * decode_cob_id → encode_cob_id gives back the same 32-bit value (there is nothing to
//   canonicalise: decode refuses every bit it would drop), and to_frame carries the bytes.
#include "check.hpp"

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/od/data_type.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace fc = fieldcodec;
namespace co = fieldcodec::canopen;
namespace pdo = fieldcodec::canopen::pdo;
namespace od = fieldcodec::od;
using fc::errc;

namespace {

constexpr auto dict = fieldcodec::dictionaries::xenax_canopen::dictionary;

std::uint8_t natural_bits(const od::entry &e) {
  if (e.type == od::data_type::boolean) return 1;
  if (od::is_byte_string(e.type))
    return static_cast<std::uint8_t>(std::min<std::size_t>(8U * e.width(), 64U));
  return static_cast<std::uint8_t>(8U * od::fixed_size(e.type));
}

bool entry_ok(pdo::mapping_entry m, pdo::direction d) {
  if (m.bits == 0U) return false;
  if (m.is_dummy()) return m.sub == 0U; // the length is checked by the module, type by type
  const od::entry *e = dict.find(m.index, m.sub);
  if (e == nullptr) return false;
  if (d == pdo::direction::rpdo) return od::mappable_rx(e->pdo) && od::writable(e->access_type);
  return od::mappable_tx(e->pdo) && od::readable(e->access_type);
}

/// Reference model: CiA 301 packs PDO data little-endian, bit k of the PDO is bit k % 8 of byte
/// k / 8; an entry of n bits at offset o holds bits o .. o + n - 1, least significant first.
std::uint64_t reference_unpack(std::span<const std::uint8_t> pdo, std::size_t offset,
                               std::size_t length) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < length; ++i) {
    const std::size_t k = offset + i;
    if (((static_cast<unsigned>(pdo[k / 8U]) >> (k % 8U)) & 1U) != 0U) v |= std::uint64_t{1} << i;
  }
  return v;
}

/// Single entries at any offset: unpack agrees with the reference, and pack writes exactly the
/// entry's bits (the others stay as they were).
void check_single(std::span<const std::uint8_t> bytes, std::size_t offset, std::size_t length,
                  std::uint64_t value) {
  auto u = pdo::unpack(bytes, offset, length);
  if (length < 1U || length > 64U) {
    FUZZ_CHECK(u.is(errc::bad_length));
    return;
  }
  if (offset + length > bytes.size() * 8U) {
    FUZZ_CHECK(u.is(errc::truncated));
    return;
  }
  FUZZ_CHECK(u.has_value() && u.value() == reference_unpack(bytes, offset, length));
  const std::uint64_t mask = length == 64U ? ~std::uint64_t{0} : (std::uint64_t{1} << length) - 1U;
  std::vector<std::uint8_t> buf(bytes.begin(), bytes.end());
  FUZZ_CHECK(pdo::pack(buf, offset, length, value & mask).has_value());
  for (std::size_t k = 0; k < bytes.size() * 8U; ++k) {
    const bool inside = k >= offset && k < offset + length;
    const bool want =
        inside ? ((value >> (k - offset)) & 1U) != 0U : ((bytes[k / 8U] >> (k % 8U)) & 1U) != 0U;
    FUZZ_CHECK((((buf[k / 8U] >> (k % 8U)) & 1U) != 0U) == want);
  }
  if (length < 64U && (value >> length) != 0U) {
    FUZZ_CHECK(pdo::pack(buf, offset, length, value).is(errc::overflow));
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t count = data[0] & 0x0FU;
  const auto dir = (data[0] & 0x10U) != 0U ? pdo::direction::tpdo : pdo::direction::rpdo;
  std::size_t at = 1;
  std::vector<pdo::mapping_entry> entries;
  for (std::size_t i = 0; i < count && at + 4 <= size; ++i, at += 4) {
    const std::uint8_t *p = data + at;
    if ((p[0] & 0x80U) == 0U) {
      const std::size_t k = (std::size_t{p[0]} << 8U | p[1]) % dict.size();
      const od::entry &e = dict.entries()[k];
      entries.push_back({e.index, e.sub, natural_bits(e)});
    } else {
      entries.push_back({static_cast<std::uint16_t>(p[1] | (p[2] << 8U)),
                         static_cast<std::uint8_t>(p[0] & 0x7FU), p[3]});
    }
    FUZZ_CHECK(pdo::mapping_entry::from_u32(entries.back().to_u32()) == entries.back());
  }
  std::uint32_t cob = 0;
  for (std::size_t i = 0; i < 4 && at < size; ++i) cob |= std::uint32_t{data[at++]} << (8U * i);
  const std::span<const std::uint8_t> bytes(data + at, size - at);

  // COB-ID parameter: exact round trip.
  if (auto c = pdo::decode_cob_id(cob)) {
    auto back = pdo::encode_cob_id(c.value());
    FUZZ_CHECK(back.has_value() && back.value() == cob);
    auto f = pdo::to_frame(c.value(), bytes.first(std::min<std::size_t>(bytes.size(), 9)));
    if (!c.value().valid) {
      FUZZ_CHECK(f.is(errc::bad_state));
    } else if (bytes.size() > 8) {
      FUZZ_CHECK(f.is(errc::too_long));
    } else {
      FUZZ_CHECK(f.has_value() && f.value().id == c.value().id);
      FUZZ_CHECK(std::equal(bytes.begin(), bytes.end(), f.value().payload().begin(),
                            f.value().payload().end()));
    }
  } else {
    FUZZ_CHECK(c.is(errc::out_of_range));
  }

  // Mapping check against the dictionary.
  const auto report = pdo::check_mapping(dict, dir, entries);
  const auto v = pdo::validate(dict, dir, entries);
  FUZZ_CHECK(v.has_value() == report.ok());
  std::size_t total = 0;
  for (const auto &e : entries) total += e.bits;
  if (report.ok()) {
    FUZZ_CHECK(v.value() == total && total <= pdo::can_max_bits);
    for (const auto &e : entries) FUZZ_CHECK(entry_ok(e, dir));
  } else {
    FUZZ_CHECK(v.error() == pdo::to_errc(report.problem));
    FUZZ_CHECK(report.entry < std::max<std::size_t>(entries.size(), 1U) ||
               report.problem == pdo::mapping_problem::too_many_entries);
  }

  // Single entries against the reference model, at offsets and lengths taken from the input.
  if (bytes.size() >= 2) {
    std::uint64_t value = 0;
    for (std::size_t b = 0; b < 8 && b < bytes.size(); ++b)
      value |= std::uint64_t{bytes[b]} << (8U * b);
    check_single(bytes, bytes[0] % (bytes.size() * 8U), bytes[1] % 66U,
                 value * 0x9E3779B97F4A7C15U);
  }

  // Packing (any entry lengths 1..64, checked or not).
  const bool lengths_ok = std::all_of(entries.begin(), entries.end(),
                                      [](const auto &e) { return e.bits >= 1U && e.bits <= 64U; });
  if (!lengths_ok || entries.empty()) return 0;
  std::vector<std::uint64_t> raws(entries.size());
  auto u = pdo::unpack_all(entries, bytes, raws);
  if (bytes.size() * 8U < total) {
    FUZZ_CHECK(u.is(errc::truncated));
  } else {
    FUZZ_CHECK(u.has_value());
    std::vector<std::uint8_t> out((total + 7U) / 8U + 1U, 0);
    auto n = pdo::pack_all(entries, raws, out);
    FUZZ_CHECK(n.has_value() && n.value() == (total + 7U) / 8U);
    for (std::size_t bit = 0; bit < out.size() * 8U; ++bit) {
      const bool want = bit < total && ((bytes[bit / 8U] >> (bit % 8U)) & 1U) != 0U;
      FUZZ_CHECK((((out[bit / 8U] >> (bit % 8U)) & 1U) != 0U) == want);
    }
    // signed view of every entry round-trips
    std::size_t offset = 0;
    for (const auto &e : entries) {
      auto s = pdo::unpack_signed(bytes, offset, e.bits);
      FUZZ_CHECK(s.has_value());
      std::vector<std::uint8_t> tmp(bytes.begin(), bytes.end());
      FUZZ_CHECK(pdo::pack_signed(tmp, offset, e.bits, s.value()).has_value());
      FUZZ_CHECK(std::equal(tmp.begin(), tmp.end(), bytes.begin()));
      offset += e.bits;
    }
  }

  // pack_all of values taken from the PDO bytes read as raw 64-bit numbers.
  std::vector<std::uint64_t> values(entries.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::uint64_t x = 0;
    for (std::size_t b = 0; b < 8 && i * 8 + b < bytes.size(); ++b) {
      x |= std::uint64_t{bytes[i * 8 + b]} << (8U * b);
    }
    values[i] = (x & 1U) != 0U ? x >> (x % 64U) : x; // mix large and small values
  }
  std::vector<std::uint8_t> buf((total + 7U) / 8U, 0);
  auto packed = pdo::pack_all(entries, values, buf);
  if (packed) {
    std::vector<std::uint64_t> back(entries.size());
    FUZZ_CHECK(pdo::unpack_all(entries, buf, back).has_value());
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const std::size_t b = entries[i].bits;
      const std::uint64_t mask = b == 64U ? ~std::uint64_t{0} : (std::uint64_t{1} << b) - 1U;
      FUZZ_CHECK(back[i] == (values[i] & mask));
    }
  } else {
    FUZZ_CHECK(packed.is(errc::overflow));
  }
  return 0;
}
