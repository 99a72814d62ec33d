// Fuzz harness for the COMPAX codecs (compax/): BCD positions and speeds, identification
// numbers and dates, booleans / integers / visible strings, DSP numbers, Nx program records
// (bytes and program text), OBJECT_REQ / OBJECT_RSP and their handshake, PCP requests and the
// process-data configuration records. Byte 0 selects the codec; the rest is its input.
//
// Property: what decodes re-encodes to the same bytes, or to this canonical form:
// * BCD position: "minus zero" (sign FF, all digits 0) becomes 00 00 00 00 00 00.
// * Visible string: the text without trailing spaces, padded again with spaces: same bytes.
// * Nx record: length byte, content, then zero padding to 20 bytes (padding is ignored when
//   read, and a record may be given shorter than 20 bytes).
// * Nx program text: DSP values print with at most 3 decimals, so bytes → text → command
//   rounds a DSP raw value to the nearest thousandth (documented in nx_text.hpp); text → command
//   → text → command is exact, and the text of that command is a fixed point.
// * PCP request: the pad byte after an odd data length becomes 0.
// * POLARITAET: bit 7 only. OVERRIDE: byte → percent at 2 places → the same byte.
// * OBJECT_REQ / OBJECT_RSP, DSP numbers, identification, process-data records, integers,
//   booleans, CONTROL commands and selection codes: the same bytes.
// * Objects by dictionary entry (objects.hpp): bytes → engineering value (6 places) → the same
//   bytes, unless the value lies outside the entry's limits (encode says out_of_range).
// And what encodes decodes to the same value (numbers given as thousandths, DSP conversions,
// OBJECT_REQ/RSP answered through object_channel).
#include "check.hpp"

#include <fieldcodec/compax/control.hpp>
#include <fieldcodec/compax/dsp_number.hpp>
#include <fieldcodec/compax/identification.hpp>
#include <fieldcodec/compax/nx.hpp>
#include <fieldcodec/compax/nx_text.hpp>
#include <fieldcodec/compax/object_channel.hpp>
#include <fieldcodec/compax/objects.hpp>
#include <fieldcodec/compax/pcp.hpp>
#include <fieldcodec/compax/position.hpp>
#include <fieldcodec/compax/process_data.hpp>
#include <fieldcodec/compax/values.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/dictionaries/compax_objects.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

namespace fc = fieldcodec;
namespace cx = fieldcodec::compax;
namespace nx = fieldcodec::compax::nx;
using fc::errc;

namespace {

using bytes = std::span<const std::uint8_t>;

template <std::size_t N>
bool same(const std::array<std::uint8_t, N> &a, bytes b) {
  return b.size() == N && std::equal(a.begin(), a.end(), b.begin());
}

void check_position(bytes all) {
  const bytes in = all.first(std::min(all.size(), cx::bcd_position_size));
  auto p = cx::decode_bcd_position(in);
  if (p) {
    auto e = cx::encode_bcd_position(p.value());
    FUZZ_CHECK(e.has_value());
    const bool minus_zero = p.value() == 0 && in[0] == 0xFFU;
    if (minus_zero) {
      FUZZ_CHECK(e.value() == (cx::bcd_position_bytes{}));
    } else {
      FUZZ_CHECK(same(e.value(), in));
    }
    auto d = cx::encode_bcd_position(fc::decimal{p.value(), 3});
    FUZZ_CHECK(d.has_value() && d.value() == e.value());
  } else if (in.size() == cx::bcd_position_size) {
    FUZZ_CHECK(p.error() == errc::bad_sign || p.error() == errc::bad_digit ||
               p.error() == errc::out_of_range);
  }
  const auto sp = in.first(std::min<std::size_t>(in.size(), cx::bcd_speed_size));
  if (auto s = cx::decode_bcd_speed(sp)) {
    FUZZ_CHECK(s.value() >= cx::bcd_speed_min && s.value() <= cx::bcd_speed_max);
    auto e = cx::encode_bcd_speed(s.value());
    FUZZ_CHECK(e.has_value() && same(e.value(), sp));
  }
  // encode → decode of thousandths taken from the input
  if (all.size() >= 8) {
    const auto t = fc::load<std::int64_t>(all, fc::byte_order::little).value() %
                   (2 * cx::bcd_position_limit + 3);
    auto e = cx::encode_bcd_position(t);
    if (t > cx::bcd_position_limit || t < -cx::bcd_position_limit) {
      FUZZ_CHECK(e.is(errc::out_of_range));
    } else {
      FUZZ_CHECK(e.has_value() && cx::decode_bcd_position(e.value()).value() == t);
    }
  }
}

void check_identification(bytes all) {
  const bytes in = all.first(std::min(all.size(), cx::identification_size));
  if (auto v = cx::decode_identification(in)) {
    FUZZ_CHECK(v.value() <= cx::identification_max);
    auto e = cx::encode_identification(v.value());
    FUZZ_CHECK(e.has_value() && same(e.value(), in));
  }
  if (auto d = cx::decode_identification_date(in)) {
    auto e = cx::encode_identification_date(d.value());
    FUZZ_CHECK(e.has_value() && same(e.value(), in));
  }
}

void check_values(bytes in) {
  if (!in.empty()) {
    if (auto b = cx::decode_boolean(in[0])) FUZZ_CHECK(cx::encode_boolean(b.value()) == in[0]);
  }
  const auto ints = [&]<class T>(T) {
    const auto part = in.first(std::min(in.size(), sizeof(T)));
    auto v = cx::decode_integer<T>(part);
    if (v) {
      auto e = cx::encode_integer<T>(v.value());
      FUZZ_CHECK(e.has_value() && same(e.value(), part));
    } else if (part.size() == sizeof(T)) {
      constexpr bool is_int32 = std::is_same_v<T, std::int32_t>;
      FUZZ_CHECK(v.is(errc::overflow) && is_int32);
    }
  };
  ints(std::int8_t{});
  ints(std::uint8_t{});
  ints(std::int16_t{});
  ints(std::uint16_t{});
  ints(std::int32_t{});
  ints(std::uint32_t{});
  if (auto s = cx::decode_visible_string(in)) {
    std::vector<std::uint8_t> out(in.size());
    const std::string_view text(reinterpret_cast<const char *>(s.value().data()), s.value().size());
    FUZZ_CHECK(cx::encode_visible_string(text, out).has_value());
    FUZZ_CHECK(std::equal(out.begin(), out.end(), in.begin(), in.end()));
  }
}

void check_dsp(bytes in) {
  auto d = cx::decode_dsp(in);
  if (!d) {
    FUZZ_CHECK(in.size() < cx::dsp_format::size && d.is(errc::truncated));
    return;
  }
  std::array<std::uint8_t, 6> out{};
  FUZZ_CHECK(cx::encode_dsp(d.value(), out).has_value());
  FUZZ_CHECK(std::equal(out.begin(), out.end(), in.begin()));
  // thousandths: to → from → to is a fixed point; from(t).to() == t
  const auto t = d.value().to_thousandths();
  auto back = cx::dsp_number::from_thousandths(t);
  FUZZ_CHECK(back.has_value() && back.value().to_thousandths() == t);
}

/// bytes → command → bytes (canonical record) and → text → command.
void check_nx_record(bytes in) {
  const auto rec = in.first(std::min(in.size(), nx::record_size));
  auto c = nx::decode_record(rec);
  if (!c) return;
  auto e = nx::encode_record(c.value());
  FUZZ_CHECK(e.has_value());
  nx::record canon{};
  const std::size_t n = rec[0];
  std::copy_n(rec.begin(), 1U + n, canon.begin());
  FUZZ_CHECK(e.value() == canon);
  FUZZ_CHECK(nx::decode_record(e.value()).value() == c.value());
  auto content = nx::decode_content(rec.subspan(1, n));
  FUZZ_CHECK(content.has_value() && content.value() == c.value());

  std::array<char, nx::text_max> text{};
  auto len = nx::format_command(c.value(), text);
  FUZZ_CHECK(len.has_value());
  const std::string_view t1(text.data(), len.value());
  auto p = nx::parse_command(t1);
  FUZZ_CHECK(p.has_value());
  std::array<char, nx::text_max> text2{};
  auto len2 = nx::format_command(p.value(), text2);
  FUZZ_CHECK(len2.has_value() && std::string_view(text2.data(), len2.value()) == t1);
  // the command read from the text differs at most in DSP values (rounded to 0.001)
  FUZZ_CHECK(p.value().code == c.value().code && p.value().code2 == c.value().code2 &&
             p.value().code3 == c.value().code3);
  FUZZ_CHECK(nx::encode_record(p.value()).has_value());
}

/// text → command → text → command.
void check_nx_text(bytes in) {
  const std::string_view text(reinterpret_cast<const char *>(in.data()), in.size());
  auto c = nx::parse_command(text);
  if (!c) return;
  std::array<char, nx::text_max> out{};
  auto len = nx::format_command(c.value(), out);
  FUZZ_CHECK(len.has_value());
  auto again = nx::parse_command(std::string_view(out.data(), len.value()));
  FUZZ_CHECK(again.has_value() && again.value() == c.value());
  auto rec = nx::encode_record(c.value());
  FUZZ_CHECK(rec.has_value() && nx::decode_record(rec.value()).value() == c.value());
}

void check_object(bytes in) {
  const auto six = in.first(std::min<std::size_t>(in.size(), cx::object_req_size));
  if (auto r = cx::decode_object_request(six)) {
    auto e = cx::encode_object_request(r.value());
    FUZZ_CHECK(e.has_value() && same(e.value(), six));
  }
  if (auto r = cx::decode_object_response(six)) {
    FUZZ_CHECK(same(cx::encode_object_response(r.value()), six));
    FUZZ_CHECK(cx::decode_object_response(cx::encode_object_response(r.value())).value() ==
               r.value());
  }
  // The handshake: submit a request from the input, feed the rest as (toggle, response) cycles.
  if (in.size() < 6) return;
  auto req = cx::decode_object_request(in.first(6));
  if (!req || req.value().pointer == 0) return;
  cx::object_channel ch(false);
  FUZZ_CHECK(ch.submit(req.value(), false).has_value());
  FUZZ_CHECK(ch.submit(req.value(), false).is(errc::bad_state));
  bool toggle = false;
  for (std::size_t at = 6; at + 7 <= in.size() && ch.busy(); at += 7) {
    if ((in[at] & 1U) != 0U) toggle = !toggle;
    const bool was_clearing = ch.current_phase() == cx::object_channel::phase::clearing;
    auto r = ch.poll(toggle, in.subspan(at + 1, 6));
    if (r && r.value()) {
      FUZZ_CHECK(!was_clearing);
      FUZZ_CHECK(cx::answers(req.value(), *r.value()));
      FUZZ_CHECK(!ch.busy());
    } else if (!r) {
      FUZZ_CHECK(r.is(errc::unexpected_frame) && !ch.busy());
    }
    // what the channel puts on the bus always decodes
    const auto &pad = ch.pad();
    FUZZ_CHECK(cx::decode_object_request(pad).has_value());
  }
}

void check_pcp(bytes in) {
  auto r = cx::decode_pcp_request(in);
  if (!r) return;
  std::array<std::uint8_t, 128> out{};
  auto n = cx::encode_pcp_request(r.value(), out);
  FUZZ_CHECK(n.has_value() && n.value() == in.size() &&
             n.value() == cx::pcp_request_size(r.value()));
  std::vector<std::uint8_t> canon(in.begin(), in.end());
  if ((r.value().length & 1U) != 0U) canon.back() = 0;
  FUZZ_CHECK(std::equal(canon.begin(), canon.end(), out.begin()));
  FUZZ_CHECK(cx::decode_pcp_request(std::span(out).first(n.value())).value() == r.value());
}

void check_process_data(bytes in) {
  const auto three = in.first(std::min(in.size(), cx::assignment_size));
  if (auto a = cx::decode_assignment(three)) {
    FUZZ_CHECK(same(cx::encode_assignment(a.value()), three));
    FUZZ_CHECK(cx::assignment_from_parameter(cx::assignment_parameter(a.value())).value() ==
               a.value());
  }
  const auto rec = in.first(std::min(in.size(), cx::pd_select_size));
  if (auto s = cx::decode_pd_select(rec)) FUZZ_CHECK(same(cx::encode_pd_select(s.value()), rec));
}

/// CONTROL command, selection codes, OVERRIDE, POLARITAET.
void check_control(bytes in) {
  if (in.size() < 2) return;
  if (auto c = cx::decode_control(in[0])) {
    FUZZ_CHECK(static_cast<std::uint8_t>(c.value()) == in[0]);
    FUZZ_CHECK(!cx::to_string(c.value()).empty());
  }
  const auto two = in.first(2);
  const auto selection = [&]<class E>(E) {
    if (auto e = cx::decode_selection<E>(two))
      FUZZ_CHECK(same(cx::encode_selection(e.value()), two));
  };
  selection(cx::operating_mode{});
  selection(cx::ref_mode{});
  selection(cx::ramp_form{});
  // OVERRIDE: byte → percent (2 places) → byte
  auto pct = cx::decode_override(in[0]);
  FUZZ_CHECK(pct.has_value());
  auto b = cx::encode_override(pct.value());
  FUZZ_CHECK(b.has_value() && b.value() == in[0]);
  // POLARITAET: canonical form keeps bit 7 only
  FUZZ_CHECK(cx::encode_polarity(cx::decode_polarity(in[1])) == (in[1] & 0x80U));
}

/// Objects by dictionary entry (engineering units): bytes → EU (6 places) → bytes.
void check_objects(bytes in) {
  if (in.size() < 2) return;
  constexpr auto d = fieldcodec::dictionaries::compax_objects::dictionary;
  const fieldcodec::od::descriptor e =
      d.describe(d.entries()[(std::size_t{in[0]} << 8U | in[1]) % d.size()]).value();
  const bytes value = in.subspan(2);
  auto eu = cx::decode_object(e, value);
  if (!eu) return;
  std::array<std::uint8_t, 16> out{};
  auto n = cx::encode_object(e, eu.value(), out);
  if (n) {
    FUZZ_CHECK(n.value() == value.size());
    // Canonical form: a BCD "negative zero" (sign byte FF, all digits 0) is written back as
    // positive zero (sign byte 00); everything else re-encodes to the same bytes.
    const bool negative_zero = eu.value().mantissa == 0 && !value.empty() && value[0] == 0xFFU &&
                               out[0] == 0x00U &&
                               std::equal(value.begin() + 1, value.end(), out.begin() + 1);
    FUZZ_CHECK(negative_zero || std::equal(value.begin(), value.end(), out.begin()));
  } else {
    // values read from the drive may lie outside the entry's limits; nothing else may fail
    FUZZ_CHECK(n.is(errc::out_of_range));
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  const bytes in(data + 1, size - 1);
  switch (data[0] % 11U) {
  case 0: check_position(in); break;
  case 1: check_identification(in); break;
  case 2: check_values(in); break;
  case 3: check_dsp(in); break;
  case 4: check_nx_record(in); break;
  case 5: check_nx_text(in); break;
  case 6: check_object(in); break;
  case 7: check_pcp(in); break;
  case 8: check_process_data(in); break;
  case 9: check_control(in); break;
  case 10: check_objects(in); break;
  }
  return 0;
}
