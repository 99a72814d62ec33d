// fieldcodec — typed PA-CONTROL requests from a command table entry (od::command, e.g. from
// the generated <fieldcodec/dictionaries/pacontrol_commands.hpp>).
//
// The builder checks the date against the command's date type (a float where an integer
// belongs, or the reverse, is errc::type_mismatch) and the parameter against its range, and
// picks TYP_PAR_2: the date's type for commands with a date, otherwise the type of the reply
// (the manual's "read R1" request 1907 is sent with TYP 1, its "read N2" with TYP 0).
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/command.hpp>
#include <fieldcodec/pacontrol/profibus_cmd.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>
#include <fieldcodec/pacontrol/value.hpp>

#include <cstdint>
#include <limits>

namespace fieldcodec::pacontrol {

/// The value type a command table type stands for (none → integer).
[[nodiscard]] constexpr data_type to_data_type(od::command_value v) noexcept {
  return v == od::command_value::floating ? data_type::real : data_type::integer;
}

/// TYP_PAR_2 of a request for `cmd`.
[[nodiscard]] constexpr data_type request_type(const od::command &cmd) noexcept {
  return to_data_type(cmd.date_type != od::command_value::none ? cmd.date_type : cmd.reply_type);
}

/// Checks a date against the command. Errors: type_mismatch (no date expected, or the wrong
/// type), those of validate(value).
[[nodiscard]] constexpr status check_date(const od::command &cmd, const value &date) noexcept {
  FIELDCODEC_TRY_STATUS(validate(date));
  if (cmd.date_type == od::command_value::none) return errc::type_mismatch;
  if (date.type != to_data_type(cmd.date_type)) return errc::type_mismatch;
  return {};
}

namespace detail {
constexpr result<serial::request> build(const od::command &cmd, std::uint16_t parameter,
                                        const value &date) noexcept {
  FIELDCODEC_TRY_STATUS(cmd.check_parameter(parameter));
  return serial::request{cmd.code, parameter, date};
}
} // namespace detail

/// A request for a command without a date ("0" is sent, typed as the reply).
/// Errors: type_mismatch (the command needs a date), out_of_range (parameter).
[[nodiscard]] constexpr result<serial::request> make_request(const od::command &cmd,
                                                             std::uint16_t parameter = 0) noexcept {
  if (cmd.date_type != od::command_value::none) return errc::type_mismatch;
  return detail::build(cmd, parameter, value{request_type(cmd), decimal{0, 0}});
}

/// A request with a typed date. Errors: type_mismatch, out_of_range, those of validate().
[[nodiscard]] constexpr result<serial::request>
make_request(const od::command &cmd, std::uint16_t parameter, const value &date) noexcept {
  FIELDCODEC_TRY_STATUS(check_date(cmd, date));
  return detail::build(cmd, parameter, date);
}

/// A request with an integer date. Errors: type_mismatch (a float command), out_of_range.
[[nodiscard]] constexpr result<serial::request>
make_request(const od::command &cmd, std::uint16_t parameter, std::int32_t date) noexcept {
  return make_request(cmd, parameter, value::of_int(date));
}

/// A request with a float date, written in `style` (masters send the shortest form).
/// Errors: type_mismatch (an integer command), not_representable (NaN, ±∞), out_of_range.
[[nodiscard]] constexpr result<serial::request>
make_request(const od::command &cmd, std::uint16_t parameter, float date,
             float_style style = float_style::master) noexcept {
  if (cmd.date_type != od::command_value::floating) return errc::type_mismatch;
  auto v = value::of_float(date, style);
  if (!v) return v.error();
  return make_request(cmd, parameter, v.value());
}

/// A double date is sent as the float the PA-CONTROL computes with.
/// Errors: as the float overload; not_representable also beyond float range.
[[nodiscard]] constexpr result<serial::request>
make_request(const od::command &cmd, std::uint16_t parameter, double date,
             float_style style = float_style::master) noexcept {
  if (cmd.date_type != od::command_value::floating) return errc::type_mismatch;
  if (!(date <= static_cast<double>(std::numeric_limits<float>::max()) &&
        date >= static_cast<double>(std::numeric_limits<float>::lowest()))) {
    return errc::not_representable; // also NaN
  }
  return make_request(cmd, parameter, static_cast<float>(date), style);
}

/// A request with an exact decimal date, written as given ("5552.0").
/// Errors: type_mismatch (an integer command), out_of_range, invalid_argument.
[[nodiscard]] constexpr result<serial::request>
make_request(const od::command &cmd, std::uint16_t parameter, decimal date) noexcept {
  if (cmd.date_type != od::command_value::floating) return errc::type_mismatch;
  auto v = value::of_real(date);
  if (!v) return v.error();
  return make_request(cmd, parameter, v.value());
}

/// The result of an acknowledgement, checked against the command's reply type.
/// Errors: type_mismatch (TYP_QUIT differs from the reply type; not checked for commands
/// without a reply).
[[nodiscard]] constexpr result<value> reply_value(const od::command &cmd,
                                                  const serial::acknowledgement &ack) noexcept {
  if (cmd.reply_type != od::command_value::none && ack.date.type != to_data_type(cmd.reply_type)) {
    return errc::type_mismatch;
  }
  return ack.date;
}

// ---------------------------------------------------------------------------------------------
// Profibus / Interbus CMD interface.

/// The 32-bit command date for `cmd` (IEEE-754 for float commands, int32 otherwise; 0 for
/// commands without a date). Errors: type_mismatch, not_representable.
[[nodiscard]] constexpr result<std::uint32_t> cmd_date(const od::command &cmd,
                                                       const value &date) noexcept {
  FIELDCODEC_TRY_STATUS(check_date(cmd, date));
  if (date.type == data_type::integer) return profibus::date_from_int(date.as_int().value());
  return profibus::date_from_float(date.as_float());
}

/// Starts `cmd` through a handshake (toggles the SEND flag).
/// Errors: those of cmd_date, out_of_range (parameter), bad_state, overflow (code).
[[nodiscard]] constexpr result<profibus::cmd_request> start_command(profibus::cmd_handshake &hs,
                                                                    const od::command &cmd,
                                                                    std::uint16_t parameter,
                                                                    const value &date) noexcept {
  FIELDCODEC_TRY_STATUS(cmd.check_parameter(parameter));
  auto d = cmd_date(cmd, date);
  if (!d) return d.error();
  return hs.start(cmd.code, parameter, d.value());
}

/// The same for a command without a date.
[[nodiscard]] constexpr result<profibus::cmd_request>
start_command(profibus::cmd_handshake &hs, const od::command &cmd,
              std::uint16_t parameter = 0) noexcept {
  if (cmd.date_type != od::command_value::none) return errc::type_mismatch;
  FIELDCODEC_TRY_STATUS(cmd.check_parameter(parameter));
  return hs.start(cmd.code, parameter, 0);
}

/// The acknowledgement date of a Profibus reply, typed by the command (a float reply is
/// given in the shortest decimal form, as the RS232 text would carry it: no exponent).
/// Errors: not_representable (NaN/∞, or a finite float too small for a decimal of at most 18
/// places, |v| below about 1e-10 including every denormal), overflow (|v| from about 9.2e17
/// on, where the decimal's int64 mantissa ends). Such values cannot travel as PA-CONTROL text
/// either; the raw bits are still in the reply (fuzz F9).
[[nodiscard]] constexpr result<value> reply_value(const od::command &cmd,
                                                  const profibus::cmd_reply &reply) noexcept {
  if (cmd.reply_type == od::command_value::floating) {
    auto f = profibus::date_as_float(reply.date);
    if (!f) return f.error();
    return value::of_float(f.value(), float_style::master);
  }
  return value::of_int(profibus::date_as_int(reply.date));
}

} // namespace fieldcodec::pacontrol
