// fieldcodec — typed PA-CONTROL requests from a command table entry (od::command, e.g. from
// the generated <fieldcodec/dictionaries/pacontrol_commands.hpp>).
//
// make_request(cmd, parameter[, date]) checks everything the table says before a frame is
// built, in this order:
//   1. the date's type: a date for a command without one, none for a command that needs one,
//      a float where an integer belongs or the reverse → errc::type_mismatch;
//   2. the parameter (any integer type, or an axis_parameter for 0800/1800/1801/1802): the
//      table's range and, for packed parameters, each byte → out_of_range; beyond PAR_1's
//      16 bits → overflow;
//   3. the date (any integer type, float, double, decimal, value, or an element_condition for
//      0AA3): the table's range and packing → out_of_range; beyond int32 → overflow;
//      NaN/∞ → not_representable.
// Nothing is narrowed: make_request(cmd, 65537) is refused, never sent as PAR_1 = 1.
// TYP_PAR_2 is the date's type for commands with a date, otherwise the type of the reply (the
// manual's "read R1" request 1907 is sent with TYP 1, its "read N2" with TYP 0).
//
// start_command(handshake, cmd, parameter[, date]) takes the same arguments and starts the
// command on the Profibus/Interbus CMD interface.
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/integer.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/command.hpp>
#include <fieldcodec/pacontrol/axis_parameter.hpp>
#include <fieldcodec/pacontrol/elements.hpp>
#include <fieldcodec/pacontrol/profibus_cmd.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>
#include <fieldcodec/pacontrol/value.hpp>

#include <concepts>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

namespace fieldcodec::pacontrol {

/// What make_request takes as the command parameter: any integer type, or an axis_parameter.
template <class T>
concept parameter_argument = integer_argument<T> || std::same_as<T, axis_parameter>;

/// TYP_PAR_2 of a request for `cmd`: the date's type, for a command without a date the type
/// of its reply, integer when it has neither.
[[nodiscard]] constexpr od::command_value request_date_type(const od::command &cmd) noexcept {
  const auto t = cmd.date_type != od::command_value::none ? cmd.date_type : cmd.reply_type;
  return t == od::command_value::none ? od::command_value::integer : t;
}

/// PAR_1 of a request for `cmd`. Errors: out_of_range (outside the table's range, or a byte
/// of a packed parameter outside its bounds), overflow (beyond 16 bits).
template <integer_argument T>
[[nodiscard]] constexpr result<std::uint16_t> command_parameter(const od::command &cmd,
                                                                T parameter) noexcept {
  FIELDCODEC_TRY_STATUS(cmd.check_parameter(parameter));
  return checked_narrow<std::uint16_t>(parameter);
}

/// PAR_1 for an axis parameter. Errors: type_mismatch (the command does not address axis
/// parameters), out_of_range.
[[nodiscard]] constexpr result<std::uint16_t> command_parameter(const od::command &cmd,
                                                                axis_parameter parameter) noexcept {
  if (cmd.parameter_packing != od::packing::byte_byte) return errc::type_mismatch;
  auto par = encode_axis_parameter(parameter);
  if (!par) return par.error();
  return command_parameter(cmd, par.value());
}

/// Checks a date against the command: its type, the table's range and packing.
/// Errors: type_mismatch (no date expected, or the wrong type), out_of_range, overflow, those
/// of validate(value).
[[nodiscard]] constexpr status check_date(const od::command &cmd, const value &date) noexcept {
  FIELDCODEC_TRY_STATUS(validate(date));
  if (cmd.date_type == od::command_value::none) return errc::type_mismatch;
  if (date.type != cmd.date_type) return errc::type_mismatch;
  return cmd.check_date(date.number);
}

namespace detail {

/// Checks the date's type, then the parameter, then makes and checks the date.
template <class P, class MakeDate>
constexpr result<serial::request> build(const od::command &cmd, od::command_value date_type,
                                        P parameter, MakeDate &&make_date) noexcept {
  if (cmd.date_type != date_type) return errc::type_mismatch;
  auto par = command_parameter(cmd, parameter);
  if (!par) return par.error();
  result<value> date = make_date();
  if (!date) return date.error();
  if (date_type != od::command_value::none) FIELDCODEC_TRY_STATUS(check_date(cmd, date.value()));
  return serial::request{cmd.code, par.value(), date.value()};
}

} // namespace detail

/// A request for a command without a date ("0" is sent, typed as the reply).
/// Errors: type_mismatch (the command needs a date), out_of_range, overflow (parameter).
template <parameter_argument P = std::uint16_t>
[[nodiscard]] constexpr result<serial::request> make_request(const od::command &cmd,
                                                             P parameter = P{}) noexcept {
  return detail::build(cmd, od::command_value::none, parameter, [&]() -> result<value> {
    return value{request_date_type(cmd), decimal{0, 0}};
  });
}

/// A request with a typed date. Errors: type_mismatch, out_of_range, overflow, those of
/// validate() (invalid_argument for a date of type `none`).
template <parameter_argument P>
[[nodiscard]] constexpr result<serial::request> make_request(const od::command &cmd, P parameter,
                                                             const value &date) noexcept {
  if (date.type == od::command_value::none) return errc::invalid_argument;
  return detail::build(cmd, date.type, parameter, [&]() -> result<value> { return date; });
}

/// A request with an integer date of any integer type. Errors: type_mismatch (a real
/// command), out_of_range (outside the table's range or packing), overflow (beyond int32).
template <parameter_argument P, integer_argument D>
[[nodiscard]] constexpr result<serial::request> make_request(const od::command &cmd, P parameter,
                                                             D date) noexcept {
  return detail::build(cmd, od::command_value::integer, parameter, [&]() -> result<value> {
    FIELDCODEC_TRY_STATUS(cmd.check_date(date)); // on the argument itself, before narrowing
    return value::of_int(date);
  });
}

/// A request with a real date given as a binary float (float, double, long double), sent as
/// the float the PA-CONTROL computes with and written in `style` (masters send the shortest
/// form). Errors: type_mismatch (an integer command), not_representable (NaN, ±∞, beyond
/// float range), out_of_range, overflow.
template <parameter_argument P, std::floating_point F>
[[nodiscard]] constexpr result<serial::request>
make_request(const od::command &cmd, P parameter, F date,
             float_style style = float_style::master) noexcept {
  return detail::build(cmd, od::command_value::real, parameter, [&]() -> result<value> {
    if constexpr (std::is_same_v<F, float>) {
      return value::of_float(date, style);
    } else {
      if (!(date <= static_cast<F>(std::numeric_limits<float>::max()) &&
            date >= static_cast<F>(std::numeric_limits<float>::lowest()))) {
        return errc::not_representable; // also NaN
      }
      return value::of_float(static_cast<float>(date), style);
    }
  });
}

/// A request with an exact decimal date, written as given ("5552.0").
/// Errors: type_mismatch (an integer command), out_of_range, invalid_argument.
template <parameter_argument P>
[[nodiscard]] constexpr result<serial::request> make_request(const od::command &cmd, P parameter,
                                                             decimal date) noexcept {
  return detail::build(cmd, od::command_value::real, parameter,
                       [&]() -> result<value> { return value::of_real(date); });
}

/// A request with a packed element condition (0AA3). Errors: type_mismatch (the command's
/// date is not a packed condition), those of encode_element_condition, out_of_range.
template <parameter_argument P>
[[nodiscard]] constexpr result<serial::request>
make_request(const od::command &cmd, P parameter, const element_condition &date) noexcept {
  if (cmd.date_packing != od::packing::byte_byte_word) return errc::type_mismatch;
  return detail::build(cmd, od::command_value::integer, parameter, [&]() -> result<value> {
    auto packed = encode_element_condition(date);
    if (!packed) return packed.error();
    return value::of_int(packed.value());
  });
}

/// The result of an acknowledgement, checked against the command's reply type.
/// Errors: type_mismatch (TYP_QUIT differs from the reply type; not checked for commands
/// without a reply).
[[nodiscard]] constexpr result<value> reply_value(const od::command &cmd,
                                                  const serial::acknowledgement &ack) noexcept {
  if (cmd.reply_type != od::command_value::none && ack.date.type != cmd.reply_type) {
    return errc::type_mismatch;
  }
  return ack.date;
}

// ---------------------------------------------------------------------------------------------
// Profibus / Interbus CMD interface.

/// The 32-bit command date of a date (IEEE-754 for real dates, int32 otherwise).
/// Errors: those of validate(), not_representable (beyond float range).
[[nodiscard]] constexpr result<std::uint32_t> cmd_date(const value &date) noexcept {
  FIELDCODEC_TRY_STATUS(validate(date));
  if (date.type == od::command_value::integer) return profibus::date_from_int(date.number.mantissa);
  return profibus::date_from_float(date.as_float());
}

/// The 32-bit command date for `cmd` (0 for commands without a date).
/// Errors: those of check_date, not_representable.
[[nodiscard]] constexpr result<std::uint32_t> cmd_date(const od::command &cmd,
                                                       const value &date) noexcept {
  FIELDCODEC_TRY_STATUS(check_date(cmd, date));
  return cmd_date(date);
}

/// Starts a request built by make_request through a handshake (toggles the SEND flag).
/// Errors: those of cmd_date, bad_state, overflow (code).
[[nodiscard]] constexpr result<profibus::cmd_request>
start_command(profibus::cmd_handshake &hs, const serial::request &r) noexcept {
  auto d = cmd_date(r.date);
  if (!d) return d.error();
  return hs.start(r.code, r.parameter, d.value());
}

/// Starts `cmd` with the arguments make_request takes (parameter, date, …): checked exactly
/// as make_request checks them. Errors: those of make_request and of start_command.
template <class... Args>
[[nodiscard]] constexpr result<profibus::cmd_request>
start_command(profibus::cmd_handshake &hs, const od::command &cmd, Args &&...args) noexcept {
  auto r = make_request(cmd, std::forward<Args>(args)...);
  if (!r) return r.error();
  return start_command(hs, r.value());
}

/// The acknowledgement date of a Profibus reply, typed by the command (a float reply is
/// given in the shortest decimal form, as the RS232 text would carry it: no exponent).
/// Errors: not_representable (NaN/∞, or a finite float too small for a decimal of at most 18
/// places, |v| below about 1e-10 including every denormal), overflow (|v| from about 9.2e17
/// on, where the decimal's int64 mantissa ends). Such values cannot travel as PA-CONTROL text
/// either; the raw bits are still in the reply (fuzz F9).
[[nodiscard]] constexpr result<value> reply_value(const od::command &cmd,
                                                  const profibus::cmd_reply &reply) noexcept {
  if (cmd.reply_type == od::command_value::real) {
    auto f = profibus::date_as_float(reply.date);
    if (!f) return f.error();
    return value::of_float(f.value(), float_style::master);
  }
  return value::of_int(profibus::date_as_int(reply.date));
}

} // namespace fieldcodec::pacontrol
