// Fuzz harness for od's value text (od/value_text.hpp over od/engineering.hpp), over every entry
// of the generated dictionaries, the XENAX ones also with their vendor units (xenax/
// canopen_units.hpp), and over entries of every data type without limits.
//
// Input: byte 0 = dictionary (low 3 bits: XENAX CANopen, EtherCAT, POWERLINK, DPQ, COMPAX, a
// synthetic entry of type byte 1), bit 3: the XENAX units, bit 4: raw units, bit 5: hex
// integers, bit 6: the rest is text (else: the value's bytes); bytes 1-2 = entry number; byte 3 =
// node-ID; the rest = text or bytes.
//
// Properties:
// * parse_value never reads out of bounds or crashes; what it accepts, format_value prints and
//   parse_value takes back as the same bytes (the text of a value is a fixed point).
// * format_value of bytes, parsed back, gives the same bytes (a VISIBLE_STRING without its
//   trailing NULs) — or the value is refused for a reason the bytes have: outside the limits of
//   the node (out_of_range), too long for the capacity, a character a VISIBLE_STRING cannot
//   hold, NaN/infinity, an UNSIGNED64 above INT64_MAX of a scaled entry.
#include "check.hpp"

#include <fieldcodec/dictionaries/compax_objects.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/dictionaries/xenax_ethercat.hpp>
#include <fieldcodec/dictionaries/xenax_powerlink.hpp>
#include <fieldcodec/od/value_text.hpp>
#include <fieldcodec/xenax/canopen_units.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fc = fieldcodec;
namespace od = fieldcodec::od;
namespace dict = fieldcodec::dictionaries;
using fc::errc;

namespace {

constexpr std::array<od::dictionary, 5> dictionaries{
    dict::xenax_canopen::dictionary, dict::xenax_ethercat::dictionary,
    dict::xenax_powerlink::dictionary, dict::dpq_parameters::dictionary,
    dict::compax_objects::dictionary};

/// The bytes of a value as the entry holds them (a VISIBLE_STRING's trailing NULs are padding).
std::span<const std::uint8_t> value_of(const od::descriptor &d, std::span<const std::uint8_t> b) {
  if (d.type == od::data_type::visible_string) {
    while (!b.empty() && b.back() == 0U) b = b.first(b.size() - 1U);
  }
  return b;
}

bool same(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] != b[i]) return false;
  }
  return true;
}

/// format → parse of `bytes` for `d`: the same bytes, or a refusal the bytes explain.
void round_trip(const od::descriptor &d, std::span<const std::uint8_t> bytes,
                const od::value_options &o) {
  std::array<char, 8100> text{};
  auto n = od::format_value(d, bytes, text, o);
  if (!n) {
    // not a value of the type: wrong length, NaN/∞, an odd UNICODE_STRING, no EU for a raw
    // value beyond int64
    FUZZ_CHECK(n.error() != errc::buffer_too_small);
    return;
  }
  std::array<std::uint8_t, 2100> out{};
  auto back = od::parse_value(d, std::string_view(text.data(), n.value()), out, o);
  if (back) {
    FUZZ_CHECK(same(std::span<const std::uint8_t>(out.data(), back.value()), value_of(d, bytes)));
    return;
  }
  const od::value_error e = back.error();
  FUZZ_CHECK(e.code == errc::out_of_range || e.code == errc::too_long ||
             e.code == errc::bad_character || e.code == errc::not_representable ||
             e.code == errc::overflow);
  if (e.code == errc::out_of_range) {
    FUZZ_CHECK(e.issue == od::value_issue::low_limit || e.issue == od::value_issue::high_limit ||
               od::is_time(d.type) || d.type == od::data_type::boolean);
  }
}

/// parse → format → parse of `text`: a text that is accepted reads back as the same bytes.
void fixed_point(const od::descriptor &d, std::string_view text, const od::value_options &o) {
  std::array<std::uint8_t, 2100> out{};
  auto n = od::parse_value(d, text, out, o);
  if (!n) return;
  const auto bytes = std::span<const std::uint8_t>(out.data(), n.value());
  std::array<char, 8500> printed{};
  auto t = od::format_value(d, bytes, printed, o);
  FUZZ_CHECK(t.has_value());
  std::array<std::uint8_t, 2100> again{};
  auto m = od::parse_value(d, std::string_view(printed.data(), t.value()), again, o);
  FUZZ_CHECK(m.has_value());
  FUZZ_CHECK(same(std::span<const std::uint8_t>(again.data(), m.value()), bytes));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size < 4U) return 0;
  const std::uint8_t which = data[0] & 0x07U;
  od::value_options o;
  o.unit = (data[0] & 0x10U) != 0U ? od::value_unit::raw : od::value_unit::engineering;
  o.integers = (data[0] & 0x20U) != 0U ? od::radix::hex : od::radix::decimal;
  o.node = static_cast<std::uint8_t>(data[3] & 0x7FU); // 0: any node
  const bool text = (data[0] & 0x40U) != 0U;
  od::unit_descriptor d{};
  std::array<char, 4> capacity{}; // the packed capacity of a byte string built here
  if (which >= dictionaries.size()) {
    // every data type code, without limits (and UNICODE_STRING / OCTET_STRING capacities)
    if (!od::is_data_type(data[1])) return 0;
    od::entry_spec s{};
    s.type = static_cast<od::data_type>(data[1]);
    s.size = od::is_byte_string(s.type) ? data[2] : 0U;
    FUZZ_CHECK(od::pack(s, capacity).has_value());
    static_cast<od::entry &>(d) = od::make_entry(s, capacity.data());
  } else {
    const od::dictionary &dict = dictionaries[which];
    const std::size_t k = (std::size_t{data[1]} << 8U | data[2]) % dict.size();
    d = od::unit_descriptor(dict.describe(dict.entries()[k]).value());
    if ((data[0] & 0x08U) != 0U && which < 3U) {
      auto u = od::with_unit(d, fc::xenax::canopen_units);
      FUZZ_CHECK(u.has_value()); // every XENAX entry takes its unit
      d = u.value();
    }
  }
  const auto rest = std::span<const std::uint8_t>(data + 4, size - 4U);
  if (text) {
    fixed_point(d, std::string_view(reinterpret_cast<const char *>(rest.data()), rest.size()), o);
  } else if (rest.size() <= 2000U) {
    round_trip(d, rest, o);
  }
  return 0;
}
