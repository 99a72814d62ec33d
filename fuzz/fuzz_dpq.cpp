// Fuzz harness for the DPQ parameter conversions (od::descriptor's scaling methods and
// dpq/parameter.hpp) over the generated DPQ dictionary and over arbitrary scale / offset / field /
// range descriptors.
//
// Byte 0 bit 0 selects the mode: 0 = an entry of the generated DPQ dictionary (bytes 1-2 pick
// it), 1 = a fuzzed od::descriptor (scale, offset, integer type, range from the input). The rest
// gives an engineering value (decimal mantissa + places, and the same bytes as a double) and
// the field's bytes. With bit 1 set in the entry mode, the rest is instead the 8 data bytes of
// the card's SDO answer (dpq/sdo.hpp) on 0x585.
//
// Properties:
// * to_raw never returns a value outside the field (width and signedness), and never a value
//   for an EU outside the printed range; its errors are out_of_range / overflow /
//   invalid_argument / not_representable / type_mismatch only.
// * EU → raw → bytes → raw → EU → raw: the bytes decode to the same raw value, and the EU read
//   back (exact decimal at round_trip_places) converts to the same raw value again (to_eu /
//   to_raw round trip; the EU itself is canonicalised to the nearest raw step).
// * bytes → raw → EU → raw → bytes: what decodes re-encodes to the same bytes, unless the EU
//   lies outside the printed range (values read from the card may; then to_raw says
//   out_of_range and the EU really is outside [low, high]).
// * scaling::scale_to_raw and scaling::to_eu_decimal agree with a 128-bit reference model
//   wherever its intermediates fit (differential check of the core fast paths).
// * SDO answers: a read response decodes to a raw value inside the field; its canonical form
//   (expedited upload response with size indication and the field's bytes) decodes to the same
//   raw value, and writing the EU read back sends those bytes.
#include "check.hpp"

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/parameter.hpp>
#include <fieldcodec/dpq/sdo.hpp>
#include <fieldcodec/dpq/sdo_abort.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>

namespace fc = fieldcodec;
namespace dpq = fieldcodec::dpq;
namespace od = fieldcodec::od;
using fc::decimal;
using fc::errc;

namespace {

struct reader {
  std::span<const std::uint8_t> in;
  std::uint64_t take(unsigned n) {
    std::uint64_t v = 0;
    for (unsigned i = 0; i < n; ++i) {
      std::uint64_t b = 0;
      if (!in.empty()) {
        b = in[0];
        in = in.subspan(1);
      }
      v |= b << (8U * i);
    }
    return v;
  }
};

decimal decimal_of(reader &r) {
  const auto places = static_cast<std::uint8_t>(r.take(1) % 20U); // 19: invalid
  const auto m = static_cast<std::int64_t>(r.take(8));
  const auto small = static_cast<std::int64_t>(static_cast<std::int32_t>(m));
  return decimal{(places & 1U) != 0U ? small : m, places};
}

bool allowed_error(errc e) {
  return e == errc::out_of_range || e == errc::overflow || e == errc::invalid_argument ||
         e == errc::not_representable || e == errc::type_mismatch;
}

bool in_range(decimal eu, const od::descriptor &d) {
  const auto lo = d.low().to_decimal();
  const auto hi = d.high().to_decimal();
  return (!lo || fc::compare(eu, lo.value()) >= 0) && (!hi || fc::compare(eu, hi.value()) <= 0);
}

// Reference model of core/scaling in 128-bit integers (only where every intermediate fits):
//   raw = round_half_away((eu − offset) × scale)
//   eu(places) = round_half_away((raw / scale + offset) × 10^places) / 10^places
__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;
constexpr i128 i128_max = static_cast<i128>(~static_cast<u128>(0) >> 1U);

bool mul_fits(i128 a, i128 b, i128 &out) {
  const i128 ma = a < 0 ? -a : a;
  const i128 mb = b < 0 ? -b : b;
  if (ma != 0 && mb > i128_max / ma) return false;
  out = a * b;
  return true;
}
i128 pow10_128(unsigned n) {
  i128 v = 1;
  for (unsigned i = 0; i < n; ++i) v *= 10;
  return v;
}
i128 round_div(i128 num, i128 den) { // den > 0, half away from zero
  const i128 q = num / den;
  const i128 r = num % den;
  const i128 twice = (r < 0 ? -r : r) * 2;
  if (twice >= den) return num < 0 ? q - 1 : q + 1;
  return q;
}

/// scale_to_raw against the reference (nothing when an intermediate would not fit 127 bits).
void check_scale_to_raw(decimal eu, const fc::scaling::linear &s) {
  if (eu.places > 18U || s.offset.places > 18U || s.scale.places > 18U || s.scale.mantissa == 0) {
    return;
  }
  const unsigned p = std::max<unsigned>(eu.places, s.offset.places);
  const i128 diff = static_cast<i128>(eu.mantissa) * pow10_128(p - eu.places) -
                    static_cast<i128>(s.offset.mantissa) * pow10_128(p - s.offset.places);
  i128 prod = 0;
  if (!mul_fits(diff, s.scale.mantissa, prod)) return;
  const unsigned den_places = p + s.scale.places;
  if (den_places > 37U) return;
  const i128 want = round_div(prod, pow10_128(den_places));
  auto got = fc::scaling::scale_to_raw(eu, s);
  if (want > std::numeric_limits<std::int64_t>::max() ||
      want < std::numeric_limits<std::int64_t>::min()) {
    FUZZ_CHECK(got.is(errc::overflow));
  } else {
    FUZZ_CHECK(got.has_value() && got.value() == static_cast<std::int64_t>(want));
  }
}

/// to_eu_decimal against the reference.
void check_to_eu_decimal(std::int64_t raw, const fc::scaling::linear &s, unsigned places) {
  if (places > 18U || s.offset.places > 18U || s.scale.places > 18U || s.scale.mantissa == 0) {
    return;
  }
  // eu × 10^places = (raw × 10^(sp + op) + o × m) × 10^places / (m × 10^op)
  const i128 m = s.scale.mantissa;
  i128 a = 0;
  i128 b = 0;
  i128 num = 0;
  i128 den = 0;
  if (s.scale.places + s.offset.places > 37U || places > 37U) return;
  if (!mul_fits(raw, pow10_128(s.scale.places + s.offset.places), a)) return;
  if (!mul_fits(s.offset.mantissa, m, b)) return;
  if ((b > 0 && a > i128_max - b) || (b < 0 && a < -i128_max - b)) return;
  if (!mul_fits(a + b, pow10_128(places), num)) return;
  if (!mul_fits(m, pow10_128(s.offset.places), den)) return;
  if (den < 0) {
    num = -num;
    den = -den;
  }
  const i128 want = round_div(num, den);
  auto got = fc::scaling::to_eu_decimal(raw, s, places);
  if (want > std::numeric_limits<std::int64_t>::max() ||
      want < std::numeric_limits<std::int64_t>::min()) {
    FUZZ_CHECK(got.is(errc::overflow));
  } else if (got) { // the module may refuse intermediates beyond its own 128-bit/64-bit limits
    FUZZ_CHECK(got.value().mantissa == static_cast<std::int64_t>(want) &&
               got.value().places == places);
  } else {
    FUZZ_CHECK(got.is(errc::overflow));
  }
}

/// A fuzzed descriptor (any scale, offset, integer type and range).
void check_descriptor(const od::descriptor &c, decimal eu, double eu_d,
                      std::span<const std::uint8_t> bytes) {
  check_scale_to_raw(eu, c.scale);
  const fc::scaling::field field = c.raw_field().value();
  const bool has_range = c.low().has_value();
  for (const auto raw : {c.to_raw(eu), c.to_raw(eu_d)}) {
    if (!raw) {
      FUZZ_CHECK(allowed_error(raw.error()));
      continue;
    }
    FUZZ_CHECK(fc::scaling::check_field(raw.value(), field).has_value());
    FUZZ_CHECK(raw.value() >= field.min() && raw.value() <= field.max());
    auto p = dpq::raw_to_bytes(c, raw.value());
    FUZZ_CHECK(p.has_value() && p.value().size == field.bytes);
    FUZZ_CHECK(dpq::raw_from_bytes(c, p.value().span()).value() == raw.value());
    // F3/F8 (fixed): round_trip_places refuses offsets beyond 18 places (invalid_argument) and
    // scales above 10^18 (not_representable) instead of overflowing or breaking the promise.
    auto back = dpq::to_eu_decimal(c, raw.value());
    if (!back) {
      FUZZ_CHECK(allowed_error(back.error()));
    } else {
      auto again = fc::scaling::to_raw(back.value(), c.scale, field);
      FUZZ_CHECK(again.has_value() && again.value() == raw.value());
    }
  }
  if (has_range) {
    if (auto raw = c.to_raw(eu)) FUZZ_CHECK(in_range(eu, c));
  }

  // bytes → raw → EU → raw → bytes
  const auto in = bytes.first(std::min<std::size_t>(bytes.size(), field.bytes));
  auto raw = dpq::raw_from_bytes(c, in);
  if (in.size() < field.bytes) {
    FUZZ_CHECK(raw.is(errc::truncated));
    return;
  }
  if (!raw) {
    FUZZ_CHECK(raw.is(errc::overflow) && !field.is_signed && field.bytes == 8U);
    return;
  }
  // raw_to_bytes also checks the printed range (converted to raw): a value read from the card
  // may lie outside it
  auto p = dpq::raw_to_bytes(c, raw.value());
  FUZZ_CHECK(p.has_value() || (p.is(errc::out_of_range) && has_range));
  if (p) FUZZ_CHECK(std::equal(in.begin(), in.end(), p.value().span().begin()));
  check_to_eu_decimal(raw.value(), c.scale, eu.places % 19U);
  auto e = dpq::from_bytes(c, in);
  if (!e) return; // scaling::to_eu_decimal overflow (huge scale/offset)
  auto back = c.to_raw(e.value());
  if (back) {
    FUZZ_CHECK(back.value() == raw.value());
    FUZZ_CHECK(p.has_value() && dpq::to_bytes(c, e.value()).value() == p.value());
  } else {
    FUZZ_CHECK(back.is(errc::out_of_range) && has_range && !in_range(e.value(), c));
  }
}

void check_entry(const od::descriptor &e, decimal eu, double eu_d,
                 std::span<const std::uint8_t> bytes) {
  auto f = e.raw_field();
  if (!f) {
    FUZZ_CHECK(e.to_raw(eu).is(errc::type_mismatch));
    return;
  }
  for (const auto raw : {e.to_raw(eu), e.to_raw(eu_d)}) {
    if (!raw) {
      FUZZ_CHECK(allowed_error(raw.error()));
      continue;
    }
    FUZZ_CHECK(raw.value() >= f.value().min() && raw.value() <= f.value().max());
    auto p = dpq::raw_to_bytes(e, raw.value());
    FUZZ_CHECK(p.has_value() && p.value().size == e.width());
    FUZZ_CHECK(dpq::raw_from_bytes(e, p.value().span()).value() == raw.value());
    auto back = dpq::from_bytes(e, p.value().span());
    FUZZ_CHECK(back.has_value());
    auto again = e.to_raw(back.value());
    // The EU read back may round to just outside the printed range at its ends (e.g. 4.001
    // for raw 1311); without the range it converts to the same raw value.
    if (!again) {
      FUZZ_CHECK(again.is(errc::out_of_range));
      again = fc::scaling::to_raw(back.value(), e.scale, f.value());
    }
    FUZZ_CHECK(again.has_value() && again.value() == raw.value());
  }

  const auto in = bytes.first(std::min<std::size_t>(bytes.size(), e.width()));
  auto raw = dpq::raw_from_bytes(e, in);
  if (!raw) {
    FUZZ_CHECK(in.size() < e.width() && raw.is(errc::truncated));
    return;
  }
  auto eu_back = dpq::from_bytes(e, in);
  FUZZ_CHECK(eu_back.has_value());
  auto again = e.to_raw(eu_back.value());
  if (again) {
    FUZZ_CHECK(again.value() == raw.value());
    auto p = dpq::to_bytes(e, eu_back.value());
    FUZZ_CHECK(p.has_value() && std::equal(in.begin(), in.end(), p.value().span().begin()));
  } else {
    FUZZ_CHECK(again.is(errc::out_of_range));
    FUZZ_CHECK(fc::scaling::to_raw(eu_back.value(), e.scale, f.value()).value() == raw.value());
  }
}

/// The card's answers to reads and writes of `e` (dpq/sdo.hpp), from 8 fuzzed data bytes.
void check_sdo(const od::descriptor &e, reader &r) {
  fieldcodec::canopen::can_frame f;
  f.id = 0x585;
  f.dlc = 8;
  for (auto &b : f.data) b = static_cast<std::uint8_t>(r.take(1));
  if (auto raw = dpq::read_raw_response(5, e, f)) {
    auto field = e.raw_field();
    FUZZ_CHECK(field.has_value());
    FUZZ_CHECK(raw.value() >= field.value().min() && raw.value() <= field.value().max());
    // canonical answer: expedited upload response with size indication and the field's bytes
    auto p = dpq::raw_to_bytes(e, raw.value());
    if (p) {
      auto canon = fieldcodec::canopen::sdo::channel::default_for(5).value().response(
          fieldcodec::canopen::sdo::expedited_upload_response({e.index, e.sub}, p.value().span()));
      FUZZ_CHECK(canon.has_value());
      FUZZ_CHECK(dpq::read_raw_response(5, e, canon.value()).value() == raw.value());
    } else {
      FUZZ_CHECK(p.is(errc::out_of_range)); // a value outside the printed range
    }
    if (auto eu = dpq::read_response(5, e, f)) {
      auto w = dpq::write_request(5, e, eu.value());
      if (w) {
        auto m = fieldcodec::canopen::sdo::decode(w.value(),
                                                  fieldcodec::canopen::sdo::direction::to_server);
        FUZZ_CHECK(m.has_value() && p.has_value());
        const auto b = m.value().value_bytes();
        FUZZ_CHECK(m.value().expedited &&
                   std::equal(b.begin(), b.begin() + m.value().size, p.value().span().begin(),
                              p.value().span().end()));
      } else {
        FUZZ_CHECK(w.is(errc::access_denied) || w.is(errc::out_of_range));
      }
    }
  }
  if (dpq::write_response(5, e, f)) FUZZ_CHECK((f.data[0] >> 5U) == 3U);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  reader r{std::span<const std::uint8_t>(data + 1, size - 1)};
  if ((data[0] & 1U) == 0U) {
    constexpr auto dict = fieldcodec::dictionaries::dpq_parameters::dictionary;
    const od::descriptor e = dict.describe(dict.entries()[r.take(2) % dict.size()]).value();
    if ((data[0] & 2U) != 0U) {
      check_sdo(e, r);
      return 0;
    }
    const decimal eu = decimal_of(r);
    double eu_d = 0;
    const auto bits = r.take(8);
    std::memcpy(&eu_d, &bits, sizeof eu_d);
    check_entry(e, eu, eu_d, r.in);
    // the abort table: every row's code is composed of its columns and found again
    for (const auto &row : dpq::sdo_abort_table) {
      FUZZ_CHECK(dpq::compose_abort_code(row.additional, row.error_code, row.error_class) ==
                 row.code);
      FUZZ_CHECK(dpq::find_sdo_abort(row.code) != nullptr);
    }
    return 0;
  }
  // 1..8-byte integer types, signed or unsigned
  static constexpr od::data_type types[2][8] = {
      {od::data_type::unsigned8, od::data_type::unsigned16, od::data_type::unsigned24,
       od::data_type::unsigned32, od::data_type::unsigned40, od::data_type::unsigned48,
       od::data_type::unsigned56, od::data_type::unsigned64},
      {od::data_type::integer8, od::data_type::integer16, od::data_type::integer24,
       od::data_type::integer32, od::data_type::integer40, od::data_type::integer48,
       od::data_type::integer56, od::data_type::integer64}};
  od::entry_spec spec;
  spec.flags = od::flag::scaled;
  od::descriptor c;
  c.scale.scale = decimal_of(r);
  c.scale.offset = decimal_of(r);
  const auto fb = r.take(1);
  spec.type = types[(fb & 0x10U) != 0U ? 1 : 0][fb % 8U];
  const decimal low = decimal_of(r);
  const decimal high = decimal_of(r);
  if ((fb & 0x20U) != 0U) {
    spec.low = od::decimal_number(low);
    spec.high = od::decimal_number(high);
  }
  std::array<char, 2 * od::packed_number_size> packed{}; // the limits, packed as numbers
  (void)od::pack(spec, packed);
  static_cast<od::entry &>(c) = od::make_entry(spec, packed.data());
  const decimal eu = decimal_of(r);
  double eu_d = 0;
  const auto bits = r.take(8);
  std::memcpy(&eu_d, &bits, sizeof eu_d);
  check_descriptor(c, eu, eu_d, r.in);
  return 0;
}
