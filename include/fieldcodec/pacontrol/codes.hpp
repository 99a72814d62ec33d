// fieldcodec — PA-CONTROL numbers with short texts: command error numbers (QUIT on RS232,
// bits 12-0 of CMD word 3 on Profibus; manual 001, 6.5), PA-CONTROL error numbers and their
// classes ("controller errors": ERROR field, command 1909) and operating status codes (STATUS
// field, CMD word 2 bits 7-0, command 190B; 2.4, 4.2, 6.4). All codes are decimal. The texts
// are fieldcodec's own. Every describe_* function takes any integer type.
#pragma once

#include <fieldcodec/core/integer.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <utility>

namespace fieldcodec::pacontrol {

/// A number and what it means.
struct code_text {
  std::uint16_t code = 0;
  std::string_view text{};
};

/// Command error numbers (QUIT), sorted. Codes 26-31 occur only while the operating system
/// is updated, 80-83 only during program transfer, 96-109 when AUTOMATIC or ONLINE starts,
/// 250-262 concern the AS-i master.
inline constexpr std::array<code_text, 74> command_errors{{
    {0, "no error"},
    {16, "RS232 check sum wrong"},
    {17, "RS232 control characters in wrong order"},
    {18, "RS232 frame does not start correctly"},
    {19, "unknown command"},
    {20, "command not allowed now"},
    {21, "command cannot be executed"},
    {26, "EPROM programming failed"},
    {27, "wrong number of data bytes"},
    {28, "data record not allowed"},
    {29, "data record check sum wrong"},
    {30, "EPROM erase failed"},
    {31, "EPROM address not allowed"},
    {32, "unknown axis"},
    {33, "unknown axis parameter"},
    {34, "unknown system parameter"},
    {35, "input number not allowed"},
    {36, "output number not allowed"},
    {37, "flag number not allowed"},
    {38, "N register number not allowed"},
    {39, "R register number not allowed"},
    {40, "task number not allowed"},
    {41, "value out of range"},
    {42, "axis is still moving"},
    {43, "axis not referenced"},
    {44, "external stop input not defined"},
    {45, "unknown A/D converter"},
    {46, "axis not ready"},
    {47, "not a servoTEC axis"},
    {48, "no connection to the servoTEC axis"},
    {49, "some axes not initialised"},
    {50, "axis initialisation failed"},
    {51, "axis parameter out of range"},
    {52, "axis not initialised"},
    {53, "command not allowed on a slave axis"},
    {54, "traverse distance too long"},
    {55, "axis not switched on"},
    {56, "axis moved too far while off"},
    {57, "Profibus address set by rotary switches"},
    {58, "drive parameter lists differ"},
    {59, "gantry slave axis cannot move"},
    {64, "limit switch reached or cable broken"},
    {65, "target outside the traverse range"},
    {80, "program exists already"},
    {81, "program syntax error"},
    {82, "program not present"},
    {83, "program name exists already"},
    {96, "traverse speed too high"},
    {97, "traverse speed too low"},
    {98, "reference speed too high"},
    {99, "reference speed too low"},
    {100, "manual speed too high"},
    {101, "manual speed too low"},
    {102, "creep speed too high"},
    {103, "creep speed too low"},
    {104, "start speed too high"},
    {105, "start speed too low"},
    {106, "acceleration too high"},
    {107, "acceleration too low"},
    {108, "measuring mode not possible on this axis"},
    {109, "traverse increments exceed 31 bits"},
    {250, "AS-i master: host task failed"},
    {251, "AS-i master: query failed"},
    {252, "AS-i: slave to re-address not found"},
    {253, "AS-i: a slave has address 0"},
    {254, "AS-i: address already taken"},
    {255, "AS-i: programming address 0 failed"},
    {256, "AS-i: new address not assigned"},
    {257, "AS-i: new address not stored"},
    {258, "AS-i: unknown address"},
    {259, "AS-i master: time-out"},
    {260, "AS-i power supply fault"},
    {261, "AS-i: a slave with address 0 is present"},
    {262, "AS-i configuration faulty"},
}};

/// Operating status codes, sorted. 6.4 lists 14 without a text; it is kept as a known code.
inline constexpr std::array<code_text, 22> operating_status_codes{{
    {0, "bus interface not initialised"},
    {1, "home position"},
    {2, "manual mode at the front panel"},
    {3, "manual mode at the front panel, axis moving"},
    {9, "home position with system error"},
    {10, "AUTOMATIC starting"},
    {11, "AUTOMATIC running"},
    {12, "AUTOMATIC, stop seen"},
    {13, "AUTOMATIC, stop program running"},
    {14, "AUTOMATIC (listed without a meaning)"},
    {15, "AUTOMATIC stopped"},
    {16, "AUTOMATIC, start-after-stop program running"},
    {17, "AUTOMATIC, fault seen"},
    {18, "AUTOMATIC, fault program running"},
    {19, "AUTOMATIC stopped after a fault"},
    {20, "manual mode over the serial link"},
    {30, "ONLINE starting"},
    {31, "ONLINE"},
    {32, "ONLINE, stop seen"},
    {35, "ONLINE stopped"},
    {37, "ONLINE, fault seen"},
    {39, "ONLINE stopped after a fault"},
}};

/// Classes of PA-CONTROL error numbers (5.2.4.15; the full E001 … E999 list is in the
/// operating manual).
enum class controller_error_class : std::uint8_t {
  none,        ///< 0
  cpu,         ///< 1-99: CPU fault, cleared only by power cycling
  system,      ///< 100-499: hardware/system fault, partly cleared in home position
  operation,   ///< 500-999: fault in AUTOMATIC or ONLINE, cleared by returning home
  out_of_list, ///< negative or above 999: not a PA-CONTROL error number
};

template <integer_argument T>
[[nodiscard]] constexpr controller_error_class classify_controller_error(T e) noexcept {
  if (!in_closed_range(e, 0, 999)) return controller_error_class::out_of_list;
  if (in_closed_range(e, 0, 0)) return controller_error_class::none;
  if (in_closed_range(e, 1, 99)) return controller_error_class::cpu;
  if (in_closed_range(e, 100, 499)) return controller_error_class::system;
  return controller_error_class::operation;
}

/// The PA-CONTROL error numbers this manual names.
inline constexpr std::array<code_text, 4> controller_errors{{
    {205, "Profibus rotary switch setting impossible"},
    {525, "axis not referenced"},
    {529, "positive limit switch reached or cable broken"},
    {560, "no encoder edge found when leaving measuring mode"},
}};

namespace detail {
/// Position of `code` in `table`, or N when the table does not name it (a position, not a
/// pointer: see od/detail/search.hpp on g++ -fsanitize=undefined and constant evaluation).
template <std::size_t N, integer_argument T>
constexpr std::size_t find_code(const std::array<code_text, N> &table, T code) noexcept {
  for (std::size_t i = 0; i < N; ++i) {
    if (in_closed_range(code, table[i].code, table[i].code)) return i;
  }
  return N;
}
} // namespace detail

/// Text of a command error number. Errors: unknown_object (not defined in the manual).
template <integer_argument T>
[[nodiscard]] constexpr result<std::string_view> describe_command_error(T code) noexcept {
  if (const auto i = detail::find_code(command_errors, code); i < command_errors.size())
    return command_errors[i].text;
  return errc::unknown_object;
}

/// Text of an operating status code. Errors: unknown_object.
template <integer_argument T>
[[nodiscard]] constexpr result<std::string_view> describe_operating_status(T code) noexcept {
  if (const auto i = detail::find_code(operating_status_codes, code);
      i < operating_status_codes.size())
    return operating_status_codes[i].text;
  return errc::unknown_object;
}

/// Text of a PA-CONTROL error number: the number's own text where the manual names it,
/// otherwise the text of its class. Errors: unknown_object (negative or above 999).
template <integer_argument T>
[[nodiscard]] constexpr result<std::string_view> describe_controller_error(T code) noexcept {
  if (const auto i = detail::find_code(controller_errors, code); i < controller_errors.size())
    return controller_errors[i].text;
  switch (classify_controller_error(code)) {
  case controller_error_class::none: return std::string_view("no error");
  case controller_error_class::cpu: return std::string_view("CPU fault (power cycle to clear)");
  case controller_error_class::system: return std::string_view("system fault");
  case controller_error_class::operation:
    return std::string_view("fault in AUTOMATIC or ONLINE mode");
  case controller_error_class::out_of_list: break;
  }
  return errc::unknown_object;
}

/// Named operating status codes used by masters.
namespace operating_status {
inline constexpr std::uint16_t home_position = 1;
inline constexpr std::uint16_t automatic = 11;
inline constexpr std::uint16_t automatic_stopped = 15;
inline constexpr std::uint16_t online = 31;
inline constexpr std::uint16_t online_stopped = 35;
} // namespace operating_status

/// Named command error numbers.
namespace command_error {
inline constexpr std::uint16_t none = 0;
inline constexpr std::uint16_t bad_check = 16;
inline constexpr std::uint16_t bad_sequence = 17;
inline constexpr std::uint16_t bad_start = 18;
inline constexpr std::uint16_t unknown_command = 19;
inline constexpr std::uint16_t not_allowed_now = 20;
inline constexpr std::uint16_t value_out_of_range = 41;
inline constexpr std::uint16_t not_referenced = 43;
} // namespace command_error

/// The command error number a PA-CONTROL-side receiver would answer for a serial decoding
/// error: 16 for a wrong check, 19 for an unknown command code, 17 for everything else that
/// breaks the frame.
[[nodiscard]] constexpr std::uint16_t command_error_for(errc e) noexcept {
  switch (e) {
  case errc::bad_checksum: return command_error::bad_check;
  case errc::unknown_command: return command_error::unknown_command;
  case errc::type_mismatch:
  case errc::out_of_range:
  case errc::overflow: return command_error::value_out_of_range;
  default: return command_error::bad_sequence;
  }
}

} // namespace fieldcodec::pacontrol
