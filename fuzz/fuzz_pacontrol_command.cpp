// Fuzz harness for the typed PA-CONTROL commands (pacontrol/command.hpp) over the generated
// command table: requests built for a command, and the replies read for it, on the RS232 and
// the Profibus/Interbus CMD interface.
//
// Input: bytes 0-1 pick the command, bytes 2-3 the parameter, bytes 4-7 a 32-bit date (a
// Profibus acknowledgement date, an int32 and a float bit pattern), byte 8 the float style,
// byte 9 (optional, signed) the parameter's bits above 16 (parameters below 0 and above
// 65535 must be refused).
//
// Properties:
// * A Profibus reply date decodes (reply_value) to a value that cmd_date encodes back to the
//   same 32 bits. Canonical form: a float −0.0 reads as 0.0 (a decimal has no sign of zero).
//   reply_value fails only for NaN / ±∞ and (F9, documented) for finite
//   floats below 1e-8 or from about 9.2e17 on.
// * A request built for a command (make_request with an int64 parameter and an int32 / float
//   date) is built exactly when the parameter passes the table's checks and fits PAR_1 and
//   an integer date passes the table's range and packing; it carries the parameter and date
//   unchanged (nothing wraps), encodes, and the RS232 frame decodes to the same request; the
//   Profibus command date of a float command is the float's bit pattern. An integer date
//   widened beyond int32 is refused.
// * A 32-bit date that decode_extended_axis_status accepts encodes back to itself, and it is
//   refused exactly when an upper byte is not 0/1 or the motion byte is not 0, 1, 2, 4, 8;
//   element_word::containing(parameter, date) accepts exactly elements 1-1024 and 16-bit words
//   and reads every bit of the date.
// * The table's packed bounds agree with the helpers: a parameter of 0800/1800/1801/1802 passes
//   the table exactly when decode_axis_parameter accepts it, a date of 0AA3 exactly when
//   decode_element_condition accepts it, and both re-encode to the same number.
#include "check.hpp"

#include <fieldcodec/core/ieee754.hpp>
#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/pacontrol/axis_motion.hpp>
#include <fieldcodec/pacontrol/command.hpp>
#include <fieldcodec/pacontrol/elements.hpp>
#include <fieldcodec/pacontrol/profibus_cmd.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fc = fieldcodec;
namespace pac = fieldcodec::pacontrol;
namespace od = fieldcodec::od;
namespace serial = fieldcodec::pacontrol::serial;
namespace pb = fieldcodec::pacontrol::profibus;
using fc::errc;

namespace {

void round_trip_request(const serial::request &req) {
  std::array<std::uint8_t, serial::max_frame_size> out{};
  auto n = serial::encode_request(req, out);
  FUZZ_CHECK(n.has_value());
  auto back = serial::decode_frame(std::span<const std::uint8_t>(out).first(n.value()));
  FUZZ_CHECK(back.has_value() && back.value().kind == serial::frame_kind::request);
  FUZZ_CHECK(back.value().req == req && back.value().req.date.same_text(req.date));
}

void check_reply(const od::command &cmd, std::uint32_t date) {
  pb::cmd_reply reply{};
  reply.date = date;
  auto v = pac::reply_value(cmd, reply);
  const bool is_float = cmd.reply_type == od::command_value::real;
  if (!v) {
    FUZZ_CHECK(is_float);
    if (fc::ieee754::is_nonfinite_bits(date)) { // the documented failure
      FUZZ_CHECK(v.is(errc::not_representable));
      return;
    }
    // F9 (decided and documented in reply_value): finite floats below 1e-8 or from 9e18 on have
    // no exact decimal of at most 18 places / 9 digits (not_representable), and from about
    // 9.2e17 on the master style's one fractional digit overflows the int64 mantissa
    // (overflow).
    const float f = fc::ieee754::from_bits(date);
    const float a = f < 0.0F ? -f : f;
    FUZZ_CHECK((v.is(errc::not_representable) && (a < 1e-8F || a >= 9e18F)) ||
               (v.is(errc::overflow) && a >= 9.2e17F));
    return;
  }
  FUZZ_CHECK(v.value().type == (is_float ? od::command_value::real : od::command_value::integer));
  // back to the 32 bits
  auto d = pac::cmd_date(v.value());
  FUZZ_CHECK(d.has_value());
  const bool minus_zero = is_float && date == 0x8000'0000U;
  FUZZ_CHECK(d.value() == (minus_zero ? 0U : date));
}

void check_request(const od::command &cmd, std::int64_t parameter, std::uint32_t date,
                   std::uint8_t style_byte) {
  // A parameter is accepted exactly when the table accepts it and it fits PAR_1; it is sent
  // as it is (never wrapped).
  const bool param_ok =
      cmd.check_parameter(parameter).has_value() && parameter >= 0 && parameter <= 0xFFFF;
  if (cmd.parameter_packing == od::packing::byte_byte) {
    // the table's packed bounds and the axis_parameter helper agree
    FUZZ_CHECK(param_ok == pac::decode_axis_parameter(parameter).has_value());
    if (param_ok) {
      auto ap = pac::decode_axis_parameter(parameter).value();
      FUZZ_CHECK(pac::encode_axis_parameter(ap).value() == parameter);
      FUZZ_CHECK(pac::command_parameter(cmd, ap).value() == parameter);
    }
  }
  auto sent_as = [&](const fc::result<serial::request> &r) {
    if (r) FUZZ_CHECK(r.value().code == cmd.code && r.value().parameter == parameter);
  };
  if (cmd.date_type == od::command_value::none) {
    auto r = pac::make_request(cmd, parameter);
    FUZZ_CHECK(r.has_value() == param_ok);
    sent_as(r);
    if (r) round_trip_request(r.value());
    return;
  }
  if (cmd.date_type == od::command_value::real) {
    const float f = fc::ieee754::from_bits(date);
    const auto style =
        (style_byte & 1U) != 0U ? pac::float_style::device : pac::float_style::master;
    auto r = pac::make_request(cmd, parameter, f, style);
    sent_as(r);
    if (r) {
      FUZZ_CHECK(param_ok);
      round_trip_request(r.value());
      // the date text reads back as the same float (shortest / 7-digit forms)
      if (style == pac::float_style::master) FUZZ_CHECK(r.value().date.as_float() == f || f != f);
      auto d = pac::cmd_date(cmd, r.value().date);
      FUZZ_CHECK(d.has_value());
    } else {
      FUZZ_CHECK(!param_ok || r.is(errc::not_representable) || r.is(errc::overflow));
    }
    FUZZ_CHECK(
        pac::make_request(cmd, parameter, static_cast<std::int32_t>(date)).is(errc::type_mismatch));
    return;
  }
  const auto idate = static_cast<std::int32_t>(date);
  const bool date_ok = cmd.check_date(idate).has_value();
  auto r = pac::make_request(cmd, parameter, idate);
  FUZZ_CHECK(r.has_value() == (param_ok && date_ok));
  sent_as(r);
  if (r) {
    round_trip_request(r.value());
    auto d = pac::cmd_date(cmd, r.value().date);
    FUZZ_CHECK(d.has_value() && d.value() == date);
  }
  // the same date widened beyond int32 is refused, never wrapped
  const std::int64_t wide =
      std::int64_t{idate} + (idate < 0 ? -(std::int64_t{1} << 32) : (std::int64_t{1} << 32));
  FUZZ_CHECK(!pac::make_request(cmd, parameter, wide).has_value());
  if (cmd.date_packing == od::packing::byte_byte_word) {
    // the table's packed bounds and the element_condition helper agree
    auto c = pac::decode_element_condition(idate);
    FUZZ_CHECK(c.has_value() == date_ok);
    if (c) {
      FUZZ_CHECK(pac::encode_element_condition(c.value()).value() == date);
      auto rc = pac::make_request(cmd, parameter, c.value());
      FUZZ_CHECK(rc.has_value() == param_ok);
      if (rc && r) FUZZ_CHECK(rc.value() == r.value());
    }
  }
}

/// The decoders of numbers inside acknowledgement dates: what decodes encodes back.
void check_reply_numbers(std::uint32_t date, std::int64_t element) {
  if (auto st = pac::decode_extended_axis_status(date)) {
    FUZZ_CHECK(pac::encode_extended_axis_status(st.value()) == date);
  } else {
    const std::uint32_t hi = date >> 8U;
    FUZZ_CHECK((hi & 0xFEFEFEU) != 0U || !pac::decode_axis_motion(date & 0xFFU));
  }
  if (auto m = pac::decode_axis_motion(date)) {
    FUZZ_CHECK(static_cast<std::uint32_t>(m.value()) == date);
  }
  auto w = pac::element_word::containing(element, date);
  FUZZ_CHECK(w.has_value() == (element >= 1 && element <= 1024 && date <= 0xFFFFU));
  if (w) {
    FUZZ_CHECK(w.value().first() <= element && element < w.value().first() + 16);
    for (std::int64_t e = w.value().first(); e < w.value().first() + 16; ++e) {
      const auto bit = static_cast<unsigned>(e - w.value().first());
      FUZZ_CHECK(w.value().test(e).value() == (((date >> bit) & 1U) != 0U));
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size < 9) return 0;
  constexpr auto &commands = fieldcodec::dictionaries::pacontrol_commands::commands;
  const od::command &cmd = commands[(std::size_t{data[0]} << 8U | data[1]) % commands.size()];
  // PAR_1 candidates beyond 16 bits and below 0 come from byte 9 (the high part, signed)
  const std::int64_t high = size > 9 ? static_cast<std::int8_t>(data[9]) : 0;
  const std::int64_t parameter = high * 0x10000 + (data[2] << 8U | data[3]);
  const auto date = static_cast<std::uint32_t>(data[4]) << 24U |
                    static_cast<std::uint32_t>(data[5]) << 16U |
                    static_cast<std::uint32_t>(data[6]) << 8U | data[7];
  check_reply(cmd, date);
  check_request(cmd, parameter, date, data[8]);
  check_reply_numbers(date, parameter);
  return 0;
}
