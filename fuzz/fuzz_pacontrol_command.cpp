// Fuzz harness for the typed PA-CONTROL commands (pacontrol/command.hpp) over the generated
// command table: requests built for a command, and the replies read for it, on the RS232 and
// the Profibus/Interbus CMD interface.
//
// Input: bytes 0-1 pick the command, bytes 2-3 the parameter, bytes 4-7 a 32-bit date (a
// Profibus acknowledgement date, an int32 and a float bit pattern), byte 8 the float style.
//
// Properties:
// * A Profibus reply date decodes (reply_value) to a value that cmd_date encodes back to the
//   same 32 bits. Canonical form: a float −0.0 reads as 0.0 (a decimal has no sign of zero).
//   reply_value fails only for NaN / ±∞ and (F9, documented) for finite
//   floats below 1e-8 or from about 9.2e17 on.
// * A request built for a command (make_request with an int32 / float / its own value) passes
//   the command's checks, encodes, and the RS232 frame decodes to the same request; the
//   Profibus command date of a float command is the float's bit pattern.
#include "check.hpp"

#include <fieldcodec/core/ieee754.hpp>
#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/pacontrol/command.hpp>
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
  FUZZ_CHECK(back.value().req == req);
}

void check_reply(const od::command &cmd, std::uint32_t date) {
  pb::cmd_reply reply{};
  reply.date = date;
  auto v = pac::reply_value(cmd, reply);
  const bool is_float = cmd.reply_type == od::command_value::floating;
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
  FUZZ_CHECK(v.value().type == (is_float ? pac::data_type::real : pac::data_type::integer));
  // back to the 32 bits (through a command that takes such a date)
  od::command echo = cmd;
  echo.date_type = is_float ? od::command_value::floating : od::command_value::integer;
  auto d = pac::cmd_date(echo, v.value());
  FUZZ_CHECK(d.has_value());
  const bool minus_zero = is_float && date == 0x8000'0000U;
  FUZZ_CHECK(d.value() == (minus_zero ? 0U : date));
}

void check_request(const od::command &cmd, std::uint16_t parameter, std::uint32_t date,
                   std::uint8_t style_byte) {
  const bool param_ok = cmd.check_parameter(parameter).has_value();
  if (cmd.date_type == od::command_value::none) {
    auto r = pac::make_request(cmd, parameter);
    FUZZ_CHECK(r.has_value() == param_ok);
    if (r) round_trip_request(r.value());
    return;
  }
  if (cmd.date_type == od::command_value::floating) {
    const float f = fc::ieee754::from_bits(date);
    const auto style =
        (style_byte & 1U) != 0U ? pac::float_style::device : pac::float_style::master;
    auto r = pac::make_request(cmd, parameter, f, style);
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
  auto r = pac::make_request(cmd, parameter, static_cast<std::int32_t>(date));
  FUZZ_CHECK(r.has_value() == param_ok);
  if (r) {
    round_trip_request(r.value());
    auto d = pac::cmd_date(cmd, r.value().date);
    FUZZ_CHECK(d.has_value() && d.value() == date);
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size < 9) return 0;
  constexpr auto &commands = fieldcodec::dictionaries::pacontrol_commands::commands;
  const od::command &cmd = commands[(std::size_t{data[0]} << 8U | data[1]) % commands.size()];
  const auto parameter = static_cast<std::uint16_t>(data[2] << 8U | data[3]);
  const auto date = static_cast<std::uint32_t>(data[4]) << 24U |
                    static_cast<std::uint32_t>(data[5]) << 16U |
                    static_cast<std::uint32_t>(data[6]) << 8U | data[7];
  check_reply(cmd, date);
  check_request(cmd, parameter, date, data[8]);
  return 0;
}
