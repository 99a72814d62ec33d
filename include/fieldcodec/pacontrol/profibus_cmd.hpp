// fieldcodec — PA-CONTROL CMD interface on Profibus-DP and Interbus-S (8 bytes, big-endian).
//
//   master → PA-CONTROL   bytes 0-3 command date (32 bit; a 16-bit date sits in bytes 2-3)
//                         bytes 4-5 command parameter
//                         bytes 6-7 bit 15 SEND flag, bits 14-0 command code
//   PA-CONTROL → master   bytes 0-3 acknowledgement date
//                         bytes 4-5 bit 15 PA-CONTROL error flag, bits 7-0 operating status
//                         bytes 6-7 bit 15 RECEIVE flag, bit 14 command error, bit 13 end of
//                                   processing, bits 12-0 command error number
//
// A change of the SEND flag starts a command. The reply counts only once the RECEIVE flag
// equals the SEND flag; cmd_handshake does this bookkeeping without blocking.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/ieee754.hpp>
#include <fieldcodec/core/integer.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <concepts>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

namespace fieldcodec::pacontrol::profibus {

inline constexpr std::size_t cmd_size = 8;

/// Highest command code (15 bits) and command error number (13 bits).
inline constexpr std::uint16_t max_command_code = 0x7FFF;
inline constexpr std::uint16_t max_command_error = 0x1FFF;

/// The command date of an integer command (int32, two's complement), from any integer type.
/// Errors: overflow (outside int32).
template <integer_argument T>
[[nodiscard]] constexpr result<std::uint32_t> date_from_int(T v) noexcept {
  auto i = checked_narrow<std::int32_t>(v);
  if (!i) return i.error();
  return static_cast<std::uint32_t>(i.value());
}
/// The command date of a float command (IEEE-754 single); a double or long double is sent as
/// its nearest float. Errors: not_representable (NaN, ±∞, beyond float range).
template <std::floating_point F>
[[nodiscard]] constexpr result<std::uint32_t> date_from_float(F v) noexcept {
  if constexpr (!std::is_same_v<F, float>) {
    if (!(v <= static_cast<F>(std::numeric_limits<float>::max()) &&
          v >= static_cast<F>(std::numeric_limits<float>::lowest()))) {
      return errc::not_representable; // also NaN
    }
  }
  const std::uint32_t bits = ieee754::to_bits(static_cast<float>(v));
  if (ieee754::is_nonfinite_bits(bits)) return errc::not_representable;
  return bits;
}

/// A raw 32-bit date from any integer type: an int32 (two's complement) or a uint32.
/// Errors: overflow (outside −2^31 … 2^32 − 1).
template <integer_argument T>
[[nodiscard]] constexpr result<std::uint32_t> raw_date(T v) noexcept {
  if (auto u = checked_narrow<std::uint32_t>(v)) return u;
  return date_from_int(v);
}
/// A date read as a signed integer.
[[nodiscard]] constexpr std::int32_t date_as_int(std::uint32_t date) noexcept {
  return static_cast<std::int32_t>(date);
}
/// A date read as an IEEE-754 float. Errors: not_representable (NaN, ±∞).
[[nodiscard]] constexpr result<float> date_as_float(std::uint32_t date) noexcept {
  if (ieee754::is_nonfinite_bits(date)) return errc::not_representable;
  return ieee754::from_bits(date);
}

/// Master → PA-CONTROL.
struct cmd_request {
  std::uint32_t date = 0;      ///< command date (date_from_int / date_from_float)
  std::uint16_t parameter = 0; ///< axis, register, input number …
  std::uint16_t code = 0;      ///< command code, 0 … 0x7FFF (e.g. 0x1906)
  bool send_flag = false;      ///< SF, word 3 bit 15

  friend constexpr bool operator==(const cmd_request &, const cmd_request &) noexcept = default;
};

/// PA-CONTROL → master.
struct cmd_reply {
  std::uint32_t date = 0;                 ///< acknowledgement date
  bool controller_error = false;          ///< FE: a PA-CONTROL error is pending (read it: 1909)
  std::uint8_t operating_status = 0;      ///< operating status (codes.hpp)
  bool receive_flag = false;              ///< RF: copy of the SEND flag once the command was seen
  bool command_error = false;             ///< KF: the command failed
  bool end_of_processing = false;         ///< BF
  std::uint16_t command_error_number = 0; ///< why it failed (QUIT), 0 … 0x1FFF

  friend constexpr bool operator==(const cmd_reply &, const cmd_reply &) noexcept = default;
};

/// The 8 bytes of a request. Errors: overflow (code above 0x7FFF).
[[nodiscard]] constexpr result<std::array<std::uint8_t, cmd_size>>
encode_cmd_request(const cmd_request &r) noexcept {
  if (r.code > max_command_code) return errc::overflow;
  std::array<std::uint8_t, cmd_size> out{};
  byte_writer w(out);
  FIELDCODEC_TRY_STATUS(w.write<std::uint32_t>(r.date, byte_order::big));
  FIELDCODEC_TRY_STATUS(w.write<std::uint16_t>(r.parameter, byte_order::big));
  const auto word3 = static_cast<std::uint16_t>((r.send_flag ? 0x8000U : 0U) | r.code);
  FIELDCODEC_TRY_STATUS(w.write<std::uint16_t>(word3, byte_order::big));
  return out;
}

/// A request from the first 8 bytes of `in` (the PA-CONTROL side). Errors: truncated.
[[nodiscard]] constexpr result<cmd_request>
decode_cmd_request(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < cmd_size) return errc::truncated;
  byte_reader r(in);
  const auto date = r.read<std::uint32_t>(byte_order::big).value();
  const auto par = r.read<std::uint16_t>(byte_order::big).value();
  const auto word3 = r.read<std::uint16_t>(byte_order::big).value();
  return cmd_request{date, par, static_cast<std::uint16_t>(word3 & max_command_code),
                     (word3 & 0x8000U) != 0U};
}

/// The 8 bytes of a reply (the PA-CONTROL side). Unused bits 14-8 of word 2 are written as 0.
/// Errors: overflow (error number above 0x1FFF).
[[nodiscard]] constexpr result<std::array<std::uint8_t, cmd_size>>
encode_cmd_reply(const cmd_reply &r) noexcept {
  if (r.command_error_number > max_command_error) return errc::overflow;
  std::array<std::uint8_t, cmd_size> out{};
  byte_writer w(out);
  FIELDCODEC_TRY_STATUS(w.write<std::uint32_t>(r.date, byte_order::big));
  const auto word2 =
      static_cast<std::uint16_t>((r.controller_error ? 0x8000U : 0U) | r.operating_status);
  FIELDCODEC_TRY_STATUS(w.write<std::uint16_t>(word2, byte_order::big));
  const auto word3 = static_cast<std::uint16_t>(
      (r.receive_flag ? 0x8000U : 0U) | (r.command_error ? 0x4000U : 0U) |
      (r.end_of_processing ? 0x2000U : 0U) | r.command_error_number);
  FIELDCODEC_TRY_STATUS(w.write<std::uint16_t>(word3, byte_order::big));
  return out;
}

/// A reply from the first 8 bytes of `in`. The unused bits 14-8 of word 2 are ignored.
/// Errors: truncated.
[[nodiscard]] constexpr result<cmd_reply>
decode_cmd_reply(std::span<const std::uint8_t> in) noexcept {
  if (in.size() < cmd_size) return errc::truncated;
  byte_reader r(in);
  const auto date = r.read<std::uint32_t>(byte_order::big).value();
  const auto word2 = r.read<std::uint16_t>(byte_order::big).value();
  const auto word3 = r.read<std::uint16_t>(byte_order::big).value();
  return cmd_reply{date,
                   (word2 & 0x8000U) != 0U,
                   static_cast<std::uint8_t>(word2 & 0xFFU),
                   (word3 & 0x8000U) != 0U,
                   (word3 & 0x4000U) != 0U,
                   (word3 & 0x2000U) != 0U,
                   static_cast<std::uint16_t>(word3 & max_command_error)};
}

/// Where a command stands, judged from a reply (acknowledgement mechanism, 2.4).
enum class cmd_progress : std::uint8_t {
  idle,    ///< no command started yet
  waiting, ///< SF ≠ RF: the PA-CONTROL has not seen the command yet
  running, ///< SF = RF, no error, end of processing 0
  done,    ///< SF = RF, no error, end of processing 1: the reply date is the result
  failed,  ///< SF = RF, command error: command_error_number says why
};

/// Non-blocking bookkeeping of the SEND / RECEIVE flags for one master.
///
///   cmd_handshake hs;                      // or hs.synchronize(first reply)
///   auto req = hs.start(0x1906, 2, 0);     // write req.value() to the output image
///   …every cycle: switch (hs.update(decode_cmd_reply(input).value())) { … }
class cmd_handshake {
public:
  constexpr cmd_handshake() noexcept = default;
  /// Starts with the given SEND flag (set it to the device's RECEIVE flag after a restart of
  /// the master so that no command is started by accident).
  constexpr explicit cmd_handshake(bool send_flag) noexcept : send_flag_(send_flag) {}

  /// Takes over the device's RECEIVE flag as own SEND flag; nothing is started.
  constexpr void synchronize(const cmd_reply &reply) noexcept {
    send_flag_ = reply.receive_flag;
    started_ = false;
    seen_ = true;
  }

  /// The request that starts a command: the SEND flag toggled. Takes any integer types; the
  /// date is a raw 32-bit pattern (an int32 or a uint32: see raw_date).
  /// Errors: bad_state (the previous command has not been seen yet, so toggling again would
  /// undo that toggle; or an idle reply showed RF ≠ SF and synchronize() is needed),
  /// overflow (code outside 0 … 0x7FFF, parameter outside 16 bits, date outside 32 bits).
  template <integer_argument C, integer_argument P, integer_argument D>
  [[nodiscard]] constexpr result<cmd_request> start(C code, P parameter, D date) noexcept {
    if (!seen_) return errc::bad_state;
    auto r = stage(code, parameter, date);
    if (!r) return r.error();
    send_flag_ = !send_flag_;
    started_ = true;
    seen_ = false;
    r.value().send_flag = send_flag_;
    return r;
  }

  /// The same data with the SEND flag not toggled, for masters that write the command
  /// first and toggle in a later cycle (as the Interbus example of 4.2.4 does).
  /// Errors: overflow (as start).
  template <integer_argument C, integer_argument P, integer_argument D>
  [[nodiscard]] constexpr result<cmd_request> stage(C code, P parameter, D date) const noexcept {
    if (!in_closed_range(code, 0, max_command_code)) return errc::overflow;
    auto par = checked_narrow<std::uint16_t>(parameter);
    if (!par) return par.error();
    auto d = raw_date(date);
    if (!d) return d.error();
    return cmd_request{d.value(), par.value(), static_cast<std::uint16_t>(code), send_flag_};
  }

  /// Evaluates a reply against the current command.
  constexpr cmd_progress update(const cmd_reply &reply) noexcept {
    if (reply.receive_flag != send_flag_) {
      if (started_) return cmd_progress::waiting;
      seen_ = false; // out of step (e.g. the master restarted): start() waits for synchronize()
      return cmd_progress::idle;
    }
    seen_ = true;
    if (!started_) return cmd_progress::idle;
    if (reply.command_error) return cmd_progress::failed;
    return reply.end_of_processing ? cmd_progress::done : cmd_progress::running;
  }

  [[nodiscard]] constexpr bool send_flag() const noexcept { return send_flag_; }

private:
  bool send_flag_ = false;
  bool started_ = false;
  bool seen_ = true;
};

} // namespace fieldcodec::pacontrol::profibus
