// Fuzz harness for the COMPAX codecs (compax/): BCD positions and speeds, identification
// numbers and dates, booleans / integers / visible strings, DSP numbers, Nx program records
// (bytes and program text), OBJECT_REQ / OBJECT_RSP and their handshake, PCP requests and
// confirmations, the process-data configuration records, the speed step profiles, FKT_GRUPPE,
// CAM_MEM, S23_S26 and the LAGE_ZIEL set-point handshake. Byte 0 selects the codec (modulo 16,
// so the seeds of the first eleven keep their meaning); the rest is its input.
//
// Property: what decodes re-encodes to the same bytes, or to this canonical form:
// * BCD position: "minus zero" (sign FF, all digits 0) becomes 00 00 00 00 00 00.
// * Visible string: the text without its padding (spaces, or NULs after the text), padded
//   again with spaces: the same bytes with every NUL replaced by a space.
// * Nx record: length byte, content, then zero padding to 20 bytes (padding is ignored when
//   read, and a record may be given shorter than 20 bytes).
// * Nx program text: bytes → command → text → command is exact; a command holding a raw DSP
//   value off the 0.001 grid has no text (format_command: not_representable, nothing rounded);
//   text → command → text → command is exact, and the text of that command is a fixed point.
// * POLARITAET: bit 7 only. OVERRIDE: byte → percent at 2 places → the same byte.
// * OBJECT_REQ / OBJECT_RSP, PCP requests and confirmations (a non-zero pad byte is refused),
//   DSP numbers, identification, FKT_GRUPPE, CAM_MEM (signed and unsigned), S23_S26 words,
//   POSRXSPEEDY / PRXSDYALZ, process-data records, integers, booleans, CONTROL commands and
//   selection codes: the same bytes.
// * Nx numbers from the input (any integer): a POSA/ACCEL built from one encodes exactly when it
//   fits its field, and decodes to the same command.
// * LAGE_ZIEL handshake fed arbitrary status words: "new set point" is 1 only while announced,
//   poll() reports the acknowledgement once per set point, the target bytes decode to it.
// * Objects by dictionary entry (objects.hpp): bytes → engineering value (6 places) → the same
//   bytes, unless the value lies outside the entry's limits (encode says out_of_range).
// And what encodes decodes to the same value (numbers given as thousandths, DSP conversions,
// OBJECT_REQ/RSP answered through object_channel).
#include "check.hpp"

#include <fieldcodec/compax/cam.hpp>
#include <fieldcodec/compax/control.hpp>
#include <fieldcodec/compax/diagnosis.hpp>
#include <fieldcodec/compax/dsp_number.hpp>
#include <fieldcodec/compax/identification.hpp>
#include <fieldcodec/compax/nx.hpp>
#include <fieldcodec/compax/nx_text.hpp>
#include <fieldcodec/compax/object_channel.hpp>
#include <fieldcodec/compax/objects.hpp>
#include <fieldcodec/compax/pcp.hpp>
#include <fieldcodec/compax/position.hpp>
#include <fieldcodec/compax/process_data.hpp>
#include <fieldcodec/compax/set_point.hpp>
#include <fieldcodec/compax/speed_profile.hpp>
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
    // canonical form: NUL padding is written back as spaces
    std::vector<std::uint8_t> canon(in.begin(), in.end());
    std::replace(canon.begin(), canon.end(), std::uint8_t{0}, std::uint8_t{0x20});
    FUZZ_CHECK(out == canon);
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
  if (!len) {
    // only a raw DSP value off the 0.001 grid has no program text
    const auto raw = [](const nx::arg &a) {
      return nx::normalized(a).kind == nx::arg_kind::dsp_raw;
    };
    const auto &v = c.value();
    FUZZ_CHECK(len.is(errc::not_representable) &&
               (raw(v.argument) || raw(v.second_argument) || raw(v.third_argument) || v.left.raw ||
                v.right.raw));
    return;
  }
  const std::string_view t1(text.data(), len.value());
  auto p = nx::parse_command(t1);
  FUZZ_CHECK(p.has_value() && p.value() == c.value()); // text is exact for what it prints
  std::array<char, nx::text_max> text2{};
  auto len2 = nx::format_command(p.value(), text2);
  FUZZ_CHECK(len2.has_value() && std::string_view(text2.data(), len2.value()) == t1);
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
  FUZZ_CHECK(std::equal(in.begin(), in.end(), out.begin())); // a non-zero pad byte is refused
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

/// POSRXSPEEDY / PRXSDYALZ: bytes → step → bytes, and step (from input numbers) → bytes → step.
void check_speed_profile(bytes in) {
  const auto eight = in.first(std::min(in.size(), cx::posrxspeedy_size));
  if (auto s = cx::decode_posrxspeedy(eight)) {
    auto e = cx::encode_posrxspeedy(s.value());
    FUZZ_CHECK(e.has_value() && same(e.value(), eight));
  }
  const auto ten = in.first(std::min(in.size(), cx::prxsdyalz_size));
  if (auto s = cx::decode_prxsdyalz(ten)) {
    FUZZ_CHECK(s.value().ramp_ms >= 0 && s.value().ramp_ms <= cx::speed_step_ramp_max);
    auto e = cx::encode_prxsdyalz(s.value());
    FUZZ_CHECK(e.has_value() && same(e.value(), ten));
  }
  if (in.size() < 17) return;
  const auto pos = fc::load<std::int64_t>(in, fc::byte_order::little).value();
  const auto speed = fc::load<std::int64_t>(in.subspan(8), fc::byte_order::little).value();
  const auto places = static_cast<std::uint8_t>(in[16] % 5U);
  const cx::speed_step step{fc::decimal{pos, places}, fc::decimal{speed, places}};
  auto e = cx::encode_posrxspeedy(step);
  if (!e) {
    FUZZ_CHECK(e.is(errc::out_of_range) || e.is(errc::not_representable) || e.is(errc::overflow));
    return;
  }
  auto d = cx::decode_posrxspeedy(e.value());
  FUZZ_CHECK(d.has_value() && fc::equal(d.value().position, step.position) &&
             fc::equal(d.value().speed, step.speed));
}

/// FKT_GRUPPE, CAM_MEM, S23_S26: the same bytes back; CAM_MEM signed and unsigned agree.
void check_small_objects(bytes in) {
  const auto four = in.first(std::min(in.size(), cx::function_group_size));
  if (auto f = cx::decode_function_group(four)) {
    FUZZ_CHECK(same(cx::encode_function_group(f.value()), four));
    FUZZ_CHECK((f.value().profile_number >> 12U) == static_cast<unsigned>(f.value().profile()));
  }
  const auto three = in.first(std::min(in.size(), cx::cam_mem_size));
  auto u = cx::decode_cam_mem_unsigned(three);
  auto sg = cx::decode_cam_mem_signed(three);
  FUZZ_CHECK(u.has_value() == sg.has_value());
  if (u) {
    FUZZ_CHECK(same(cx::encode_cam_mem_unsigned(u.value()).value(), three));
    FUZZ_CHECK(same(cx::encode_cam_mem_signed(sg.value()).value(), three));
    FUZZ_CHECK((static_cast<std::uint32_t>(sg.value()) & 0xFFFFFFU) == u.value());
  }
  const auto two = in.first(std::min<std::size_t>(in.size(), 2));
  if (auto w = cx::diagnosis_word::decode(two)) FUZZ_CHECK(same(w.value().bytes(), two));
  if (auto p = cx::decode_cam_mem_pointer(two)) {
    FUZZ_CHECK(same(cx::encode_cam_mem_pointer(p.value()).value(), two));
  }
}

/// PCP confirmations: bytes → response → the same bytes; a request's confirmation answers it.
void check_pcp_response(bytes in) {
  auto r = cx::decode_pcp_response(in);
  if (r) {
    FUZZ_CHECK(cx::check_pcp_response(r.value()).has_value());
    std::array<std::uint8_t, 128> out{};
    auto n = cx::encode_pcp_response(r.value(), out);
    FUZZ_CHECK(n.has_value() && n.value() == in.size() &&
               n.value() == cx::pcp_response_size(r.value()));
    FUZZ_CHECK(std::equal(in.begin(), in.end(), out.begin()));
  }
  if (auto req = cx::decode_pcp_request(in)) {
    const auto data = in.first(std::min(in.size(), cx::pcp_data_max));
    auto c = req.value().service == cx::pcp_service::read_request
                 ? cx::pcp_confirm(req.value(), data)
                 : cx::pcp_confirm(req.value());
    FUZZ_CHECK(c.has_value() && cx::answers(req.value(), c.value()));
  }
}

/// The set-point handshake fed arbitrary status words (2 bytes per cycle).
void check_set_point(bytes in) {
  if (in.size() < 5) return;
  cx::set_point_handshake hs;
  const auto target = fc::load<std::int32_t>(in, fc::byte_order::little).value();
  const bool relative = (in[4] & 1U) != 0U;
  const cx::steuerwort base{};
  auto st = hs.submit(fc::decimal{target, 3}, relative, cx::statuswort{}, base);
  if (!st) {
    FUZZ_CHECK(st.is(errc::overflow) && target == cx::integer32_overflow);
    return;
  }
  FUZZ_CHECK(fc::equal(fc::decimal{cx::decode_integer<std::int32_t>(hs.target_bytes()).value(), 3},
                       fc::decimal{target, 3}));
  int acknowledged = 0;
  for (std::size_t at = 5; at + 2 <= in.size(); at += 2) {
    const auto cw = hs.control(base);
    FUZZ_CHECK(cw.test(cx::steuerwort_bit::new_set_point) ==
               (hs.current_phase() == cx::set_point_handshake::phase::announced));
    FUZZ_CHECK(cw.test(cx::steuerwort_bit::target_position_relative) == relative);
    const cx::statuswort s{fc::load<std::uint16_t>(in.subspan(at), fc::byte_order::big).value()};
    if (hs.poll(s, cw)) {
      ++acknowledged;
      FUZZ_CHECK(s.test(cx::statuswort_bit::set_point_acknowledge) && !cx::shows_popup(s, cw));
    }
  }
  FUZZ_CHECK(acknowledged <= 1);
}

/// Nx numbers of the input, as POSA (mm) and ACCEL (ms): encode exactly when they fit.
void check_nx_numbers(bytes in) {
  if (in.size() < 8) return;
  const auto v = fc::load<std::int64_t>(in, fc::byte_order::little).value();
  const auto posa = nx::make(nx::op::posa, nx::integer(v));
  auto e = nx::encode_record(posa);
  const bool fits = v > -8'388'608 - 1 && v < 8'388'608;
  FUZZ_CHECK(e.has_value() == fits);
  if (e) FUZZ_CHECK(nx::decode_record(e.value()).value() == posa);
  const auto accel = nx::make(nx::op::accel, nx::integer(v));
  auto a = nx::encode_record(accel);
  FUZZ_CHECK(a.has_value() == (v >= 0 && v <= 0xFFFF));
  if (a) FUZZ_CHECK(nx::decode_record(a.value()).value() == accel);
  const auto u = fc::load<std::uint64_t>(in, fc::byte_order::little).value();
  auto p = nx::encode_record(nx::make(nx::op::posa, nx::parameter(u)));
  FUZZ_CHECK(p.has_value() == (u <= 0xFFFF));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  const bytes in(data + 1, size - 1);
  switch (data[0] % 16U) {
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
  case 11: check_speed_profile(in); break;
  case 12: check_small_objects(in); break;
  case 13: check_pcp_response(in); break;
  case 14: check_set_point(in); break;
  case 15: check_nx_numbers(in); break;
  }
  return 0;
}
