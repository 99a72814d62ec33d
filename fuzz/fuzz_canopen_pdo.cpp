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
// * make_mapping succeeds exactly when check_mapping does; its slots lie end to end with each
//   object's signedness; every value it unpacks is the entry's bits read with that signedness
//   (or overflow for an UNSIGNED64 beyond INT64_MAX), and packing the values gives the bytes
//   back. set() of an arbitrary int64 succeeds exactly when the value fits the field as the
//   object's type says, and get() then returns it.
// * POWERLINK entries: from_u64 refuses exactly the values with reserved bits; to_u64 gives the
//   value back. check_mapping against the XENAX POWERLINK dictionary accepts only entries that
//   are in range and do not overlap; an accepted mapping packs and unpacks at its offsets.
#include "check.hpp"

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/dictionaries/xenax_powerlink.hpp>
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
constexpr auto powerlink_dict = fieldcodec::dictionaries::xenax_powerlink::dictionary;

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
    const bool want = inside ? ((value >> (k - offset)) & 1U) != 0U
                             : ((unsigned{bytes[k / 8U]} >> (k % 8U)) & 1U) != 0U;
    FUZZ_CHECK((((unsigned{buf[k / 8U]} >> (k % 8U)) & 1U) != 0U) == want);
  }
  if (length < 64U && (value >> length) != 0U) {
    FUZZ_CHECK(pdo::pack(buf, offset, length, value).is(errc::overflow));
  }
}

/// The range a field of `bits` bits holds for a signedness, as [lo, hi] in a 65-bit sense:
/// fits(v) for an int64 value.
bool fits(std::int64_t v, std::size_t bits, pdo::signedness s) {
  if (bits >= 64U) return s != pdo::signedness::unsigned_ || v >= 0;
  const std::int64_t top = std::int64_t{1} << bits;
  const std::int64_t half = std::int64_t{1} << (bits - 1U);
  switch (s) {
  case pdo::signedness::signed_: return v >= -half && v < half;
  case pdo::signedness::unsigned_: return v >= 0 && v < top;
  case pdo::signedness::unknown: return v >= -half && v < top;
  }
  return false;
}

/// make_mapping against the dictionary: signedness, values and the checked set/get.
void check_typed(const std::vector<pdo::mapping_entry> &entries, pdo::direction dir, bool ok,
                 std::span<const std::uint8_t> bytes, std::int64_t probe) {
  auto m = pdo::make_mapping(dict, dir, entries);
  FUZZ_CHECK(m.has_value() == ok);
  if (!m) return;
  const auto &map = m.value();
  FUZZ_CHECK(map.size() == entries.size());
  std::size_t offset = 0;
  for (std::size_t i = 0; i < map.size(); ++i) {
    const pdo::slot &sl = map[i];
    FUZZ_CHECK(sl.index == entries[i].index && sl.sub == entries[i].sub &&
               sl.bits == entries[i].bits && sl.offset == offset);
    const od::data_type type = entries[i].is_dummy() ? static_cast<od::data_type>(entries[i].index)
                                                     : dict.find(sl.index, sl.sub)->type;
    FUZZ_CHECK(sl.sign == pdo::signedness_of(type));
    offset += sl.bits;
  }
  FUZZ_CHECK(map.total_bits() == offset);
  std::vector<std::int64_t> values(map.size());
  auto u = map.unpack_all(bytes, values);
  if (bytes.size() * 8U < offset) {
    FUZZ_CHECK(u.is(errc::truncated));
    return;
  }
  if (!u) {
    // only an UNSIGNED64 beyond INT64_MAX has no int64 form
    FUZZ_CHECK(u.is(errc::overflow));
    return;
  }
  for (std::size_t i = 0; i < map.size(); ++i) {
    const pdo::slot &sl = map[i];
    if (sl.sign == pdo::signedness::signed_) {
      FUZZ_CHECK(values[i] == pdo::unpack_signed(bytes, sl.offset, sl.bits).value());
    } else {
      FUZZ_CHECK(static_cast<std::uint64_t>(values[i]) ==
                 pdo::unpack(bytes, sl.offset, sl.bits).value());
    }
  }
  std::vector<std::uint8_t> out(map.bytes(), 0);
  FUZZ_CHECK(map.pack_all(values, out).value() == map.bytes());
  for (std::size_t bit = 0; bit < offset; ++bit) {
    FUZZ_CHECK(((unsigned{out[bit / 8U]} >> (bit % 8U)) & 1U) ==
               ((unsigned{bytes[bit / 8U]} >> (bit % 8U)) & 1U));
  }
  // set an arbitrary value: accepted exactly when it fits the object's type
  for (std::size_t i = 0; i < map.size(); ++i) {
    const pdo::slot &sl = map[i];
    auto st = map.set(out, i, probe);
    FUZZ_CHECK(st.has_value() == fits(probe, sl.bits, sl.sign));
    if (st) {
      FUZZ_CHECK(map.get(out, i).value() == probe);
    } else {
      FUZZ_CHECK(st.is(errc::overflow));
    }
  }
}

/// POWERLINK 64-bit entries from the raw input.
void check_powerlink(std::span<const std::uint8_t> raw, pdo::direction dir) {
  std::vector<pdo::powerlink_mapping_entry> entries;
  for (std::size_t at = 0; at + 8U <= raw.size() && entries.size() < 6U; at += 8U) {
    std::uint64_t v = 0;
    for (std::size_t b = 0; b < 8U; ++b) v |= std::uint64_t{raw[at + b]} << (8U * b);
    // keep lengths and offsets small enough to hit real objects now and then
    v &= 0x007F'01FF'FFFF'FFFFU;
    auto e = pdo::powerlink_mapping_entry::from_u64(v);
    if ((v & 0xFF00'0000U) != 0U) {
      FUZZ_CHECK(e.is(errc::out_of_range));
      v &= ~std::uint64_t{0xFF00'0000U};
      e = pdo::powerlink_mapping_entry::from_u64(v);
    }
    FUZZ_CHECK(e.has_value() && e.value().to_u64() == v);
    entries.push_back(e.value());
  }
  const std::size_t max_bits = 8U * 64U;
  const auto r = pdo::check_mapping(powerlink_dict, dir, entries, max_bits);
  auto m = pdo::make_mapping(powerlink_dict, dir, entries, max_bits);
  FUZZ_CHECK(m.has_value() == r.ok());
  if (!r.ok()) {
    FUZZ_CHECK(m.error() == pdo::to_errc(r.problem));
    return;
  }
  std::size_t end = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto &a = entries[i];
    if (a.is_empty()) continue;
    FUZZ_CHECK(std::size_t{a.offset} + a.bits <= max_bits);
    end = std::max<std::size_t>(end, std::size_t{a.offset} + a.bits);
    for (std::size_t j = 0; j < i; ++j) {
      const auto &b = entries[j];
      if (b.is_empty()) continue;
      FUZZ_CHECK(a.offset >= std::size_t{b.offset} + b.bits ||
                 b.offset >= std::size_t{a.offset} + a.bits);
    }
  }
  FUZZ_CHECK(r.total_bits == end && m.value().total_bits() == end);
  // values read from the input bytes, packed at the entries' offsets, read back
  std::vector<std::uint8_t> frame(m.value().bytes(), 0);
  for (std::size_t i = 0; i < frame.size() && i < raw.size(); ++i) frame[i] = raw[i];
  std::vector<std::int64_t> values(m.value().size());
  if (!m.value().unpack_all(frame, values)) return; // an UNSIGNED64 beyond INT64_MAX
  std::vector<std::uint8_t> out(frame.size(), 0);
  FUZZ_CHECK(m.value().pack_all(values, out).has_value());
  std::vector<std::int64_t> back(values.size());
  FUZZ_CHECK(m.value().unpack_all(out, back).has_value() && back == values);
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

  // Mappings built from the dictionary: values with each object's signedness.
  {
    std::int64_t probe = 0;
    for (std::size_t b = 0; b < 8 && b < bytes.size(); ++b) {
      probe = static_cast<std::int64_t>(static_cast<std::uint64_t>(probe) |
                                        (std::uint64_t{bytes[b]} << (8U * b)));
    }
    if (!bytes.empty()) probe >>= bytes[0] % 64U; // small and large, negative and positive
    check_typed(entries, dir, report.ok(), bytes, probe);
  }
  check_powerlink(std::span<const std::uint8_t>(data, size).subspan(1), dir);

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
      const bool want = bit < total && ((unsigned{bytes[bit / 8U]} >> (bit % 8U)) & 1U) != 0U;
      FUZZ_CHECK((((unsigned{out[bit / 8U]} >> (bit % 8U)) & 1U) != 0U) == want);
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
