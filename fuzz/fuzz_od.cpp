// Fuzz harness for typed object-dictionary values (od/value.hpp) and the SDO frames built on
// them (canopen/sdo_object.hpp), over every entry of the generated dictionaries.
//
// Input: byte 0 = dictionary (low 3 bits: XENAX CANopen, EtherCAT, POWERLINK, DPQ, COMPAX) and
// byte order (bit 3: big-endian); bytes 1-2 = entry number; the rest = the value's bytes.
//
// Properties:
// * od::decode (limits checked) → od::encode gives back the same bytes (nothing to
//   canonicalise: every bit of a fixed-size value is significant; BOOLEAN accepts only 0/1,
//   REAL refuses NaN/∞). A value that decodes only with limits::ignore is refused by encode
//   with out_of_range, exactly as decode with limits::check refuses it.
// * Byte strings: decode_bytes → encode_bytes gives the same bytes; canonical form of a
//   VISIBLE_STRING: trailing NULs cut.
// * An expedited SDO upload response carrying the bytes decodes (upload_value) to the value
//   od::decode gives; sdo::download of that value for a writable entry carries the same bytes.
// * The dictionary finds every entry under its own index/sub-index.
#include "check.hpp"

#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_object.hpp>
#include <fieldcodec/dictionaries/compax_objects.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/dictionaries/xenax_ethercat.hpp>
#include <fieldcodec/dictionaries/xenax_powerlink.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/value.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fc = fieldcodec;
namespace od = fieldcodec::od;
namespace sdo = fieldcodec::canopen::sdo;
namespace dict = fieldcodec::dictionaries;
using fc::errc;

namespace {

constexpr std::array<od::dictionary, 5> dictionaries{
    dict::xenax_canopen::dictionary, dict::xenax_ethercat::dictionary,
    dict::xenax_powerlink::dictionary, dict::dpq_parameters::dictionary,
    dict::compax_objects::dictionary};

/// The node-ID the SDO frames are for; node-ID-relative limits are checked for it.
constexpr std::uint8_t node = 5;

void check_fixed(const od::descriptor &e, std::span<const std::uint8_t> all, fc::byte_order order) {
  const std::size_t w = od::fixed_size(e.type);
  const auto in = all.first(std::min(all.size(), w));
  auto checked = od::decode(e, in, order, od::limits::check, node);
  auto any = od::decode(e, in, order, od::limits::ignore, node);
  if (in.size() < w) {
    FUZZ_CHECK(checked.is(errc::truncated) && any.is(errc::truncated));
    return;
  }
  if (!any) {
    FUZZ_CHECK(checked.has_value() == false && checked.error() == any.error());
    FUZZ_CHECK(any.error() == errc::out_of_range || any.error() == errc::not_representable);
    return;
  }
  std::array<std::uint8_t, 8> out{};
  auto n = od::encode(e, any.value(), out, order, node);
  if (checked) {
    FUZZ_CHECK(checked.value() == any.value());
    FUZZ_CHECK(n.has_value() && n.value() == w);
    FUZZ_CHECK(std::equal(in.begin(), in.end(), out.begin()));
  } else {
    FUZZ_CHECK(checked.is(errc::out_of_range));
    FUZZ_CHECK(n.is(errc::out_of_range));
  }

  // SDO: expedited upload response with the bytes (little-endian on CANopen) → the value.
  if (order != fc::byte_order::little || w > 4U) return;
  auto f = sdo::channel::default_for(node).value().response(
      sdo::expedited_upload_response({e.index, e.sub}, in));
  FUZZ_CHECK(f.has_value());
  auto v = sdo::upload_value(e, f.value());
  FUZZ_CHECK(v.has_value() && v.value() == any.value());
  if (checked && od::writable(e.access_type)) {
    auto d = sdo::download(node, e, any.value().to_double()); // typed path through a double
    if (od::is_integer(e.type) || e.type == od::data_type::boolean) {
      // integers above 2^53 do not survive the double; compare only exact ones
      const auto i = any.value().to_int64();
      if (i && i.value() > -(std::int64_t{1} << 53) && i.value() < (std::int64_t{1} << 53)) {
        FUZZ_CHECK(d.has_value());
        auto m = sdo::decode(d.value(), sdo::direction::to_server);
        FUZZ_CHECK(m.has_value() && m.value().expedited && m.value().size == w);
        const auto sent = m.value().value_bytes();
        FUZZ_CHECK(std::equal(in.begin(), in.end(), sent.begin()));
      }
    }
  }
}

void check_bytes(const od::entry &e, std::span<const std::uint8_t> in) {
  auto v = od::decode_bytes(e, in);
  if (!v) {
    FUZZ_CHECK(v.error() == errc::too_long || v.error() == errc::bad_length ||
               v.error() == errc::bad_character);
    return;
  }
  std::size_t n = in.size();
  if (e.type == od::data_type::visible_string) {
    while (n > 0U && in[n - 1U] == 0U) --n;
  }
  FUZZ_CHECK(v.value().size() == n);
  std::array<std::uint8_t, 512> out{};
  if (v.value().size() > out.size()) return;
  auto w = od::encode_bytes(e, v.value(), out);
  FUZZ_CHECK(w.has_value() && w.value() == n);
  FUZZ_CHECK(std::equal(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(n), out.begin()));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size < 3) return 0;
  const od::dictionary &d = dictionaries[(data[0] & 7U) % dictionaries.size()];
  const auto order = (data[0] & 8U) != 0U ? fc::byte_order::big : fc::byte_order::little;
  const std::size_t k = (std::size_t{data[1]} << 8U | data[2]) % d.size();
  const od::descriptor e = d.describe(d.entries()[k]).value(); // with its scale
  const std::span<const std::uint8_t> in(data + 3, size - 3);

  const od::entry *found = d.find(e.index, e.sub);
  FUZZ_CHECK(found != nullptr && found->index == e.index && found->sub == e.sub);

  if (od::is_byte_string(e.type)) {
    check_bytes(e, in);
    FUZZ_CHECK(od::decode(e, in, order).is(errc::type_mismatch));
  } else if (od::fixed_size(e.type) != 0U) {
    check_fixed(e, in, order);
  }
  return 0;
}
