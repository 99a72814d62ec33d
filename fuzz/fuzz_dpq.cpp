// Fuzz harness for the DPQ parameter conversions (dpq/conversion.hpp, dpq/parameter.hpp) over
// the generated DPQ dictionary and over arbitrary scale / offset / field / range conversions.
//
// Byte 0 bit 0 selects the mode: 0 = an entry of the generated DPQ dictionary (bytes 1-2 pick
// it), 1 = a fuzzed dpq::conversion (scale, offset, field, range from the input). The rest
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
// * SDO answers: a read response decodes to a raw value inside the field; its canonical form
//   (expedited upload response with size indication and the field's bytes) decodes to the same
//   raw value, and writing the EU read back sends those bytes.
#include "check.hpp"

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/conversion.hpp>
#include <fieldcodec/dpq/parameter.hpp>
#include <fieldcodec/dpq/sdo.hpp>
#include <fieldcodec/dpq/sdo_abort.hpp>

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

bool in_range(decimal eu, const fc::scaling::range &r) {
  return fc::compare(eu, r.low) >= 0 && fc::compare(eu, r.high) <= 0;
}

void check_conversion(const dpq::conversion &c, decimal eu, double eu_d,
                      std::span<const std::uint8_t> bytes) {
  const bool field_ok = c.field.bytes >= 1U && c.field.bytes <= 8U;
  for (const auto raw : {c.to_raw(eu), c.to_raw(eu_d)}) {
    if (!raw) {
      FUZZ_CHECK(allowed_error(raw.error()));
      continue;
    }
    FUZZ_CHECK(field_ok);
    FUZZ_CHECK(fc::scaling::check_field(raw.value(), c.field).has_value());
    FUZZ_CHECK(raw.value() >= c.field.min() && raw.value() <= c.field.max());
    auto p = c.encode_raw(raw.value());
    FUZZ_CHECK(p.has_value() && p.value().size == c.field.bytes);
    FUZZ_CHECK(c.decode_raw(p.value().span()).value() == raw.value());
    // F3/F8 (fixed): round_trip_places refuses offsets beyond 18 places (invalid_argument) and
    // scales above 10^18 (not_representable) instead of overflowing or breaking the promise.
    auto back = c.to_eu_decimal(raw.value());
    if (!back) {
      FUZZ_CHECK(allowed_error(back.error()));
    } else {
      auto again = fc::scaling::to_raw(back.value(), c.scale, c.field);
      FUZZ_CHECK(again.has_value() && again.value() == raw.value());
    }
  }
  if (c.has_range) {
    if (auto raw = c.to_raw(eu)) FUZZ_CHECK(in_range(eu, c.range));
  }

  // bytes → raw → EU → raw → bytes
  if (!field_ok) {
    FUZZ_CHECK(c.decode_raw(bytes).is(errc::invalid_argument));
    return;
  }
  const auto in = bytes.first(std::min<std::size_t>(bytes.size(), c.field.bytes));
  auto raw = c.decode_raw(in);
  if (in.size() < c.field.bytes) {
    FUZZ_CHECK(raw.is(errc::truncated));
    return;
  }
  if (!raw) {
    FUZZ_CHECK(raw.is(errc::overflow) && !c.field.is_signed && c.field.bytes == 8U);
    return;
  }
  auto p = c.encode_raw(raw.value());
  FUZZ_CHECK(p.has_value() && std::equal(in.begin(), in.end(), p.value().span().begin()));
  auto e = c.decode(in);
  if (!e) return; // scaling::to_eu_decimal overflow (huge scale/offset)
  auto back = c.to_raw(e.value());
  if (back) {
    FUZZ_CHECK(back.value() == raw.value());
    FUZZ_CHECK(c.encode(e.value()).value() == p.value());
  } else {
    FUZZ_CHECK(back.is(errc::out_of_range) && c.has_range && !in_range(e.value(), c.range));
  }
}

void check_entry(const od::entry &e, decimal eu, double eu_d, std::span<const std::uint8_t> bytes) {
  auto f = e.raw_field();
  if (!f) {
    FUZZ_CHECK(dpq::to_raw(e, eu).is(errc::type_mismatch));
    return;
  }
  for (const auto raw : {dpq::to_raw(e, eu), dpq::to_raw(e, eu_d)}) {
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
    auto again = dpq::to_raw(e, back.value());
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
  auto again = dpq::to_raw(e, eu_back.value());
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
void check_sdo(const od::entry &e, reader &r) {
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
      auto canon = fieldcodec::canopen::sdo::expedited_upload_response(5, e.index, e.subindex,
                                                                       p.value().span());
      FUZZ_CHECK(canon.has_value());
      FUZZ_CHECK(dpq::read_raw_response(5, e, canon.value()).value() == raw.value());
    } else {
      FUZZ_CHECK(p.is(errc::out_of_range)); // a value outside the printed range
    }
    if (auto eu = dpq::read_response(5, e, f)) {
      auto w = dpq::write_request(5, e, eu.value());
      if (w) {
        auto m = fieldcodec::canopen::sdo::decode_request(w.value());
        FUZZ_CHECK(m.has_value() && p.has_value());
        FUZZ_CHECK(std::equal(m.value().bytes().begin(), m.value().bytes().end(),
                              p.value().span().begin(), p.value().span().end()));
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
    const od::entry &e = dict.entries()[r.take(2) % dict.size()];
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
                 row.abort_code);
      FUZZ_CHECK(dpq::find_sdo_abort(row.abort_code) != nullptr);
    }
    return 0;
  }
  dpq::conversion c;
  c.scale.scale = decimal_of(r);
  c.scale.offset = decimal_of(r);
  const auto fb = r.take(1);
  c.field = {static_cast<std::uint8_t>(fb % 10U), (fb & 0x10U) != 0U}; // 0, 9: invalid widths
  c.has_range = (fb & 0x20U) != 0U;
  c.range.low = decimal_of(r);
  c.range.high = decimal_of(r);
  const decimal eu = decimal_of(r);
  double eu_d = 0;
  const auto bits = r.take(8);
  std::memcpy(&eu_d, &bits, sizeof eu_d);
  check_conversion(c, eu, eu_d, r.in);
  return 0;
}
