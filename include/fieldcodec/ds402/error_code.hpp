// fieldcodec — CiA 402 error codes (603Fh, and the error code of a drive's EMCY message) by
// name, from the code table of CiA 402-2: the codes are the standard's, the texts are short own
// words. Codes of CiA 301 (8100h communication, 8130h heartbeat, …) are canopen/emcy.hpp's.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>

namespace fieldcodec::ds402 {

/// One code of the table.
struct error_code_text {
  std::uint16_t code;
  std::string_view text;
};

/// The CiA 402 error codes with a meaning of their own, sorted by code.
inline constexpr std::array<error_code_text, 92> error_codes{{
    {0x2110, "short circuit or earth leakage (input)"},
    {0x2120, "earth leakage (input)"},
    {0x2121, "earth leakage phase L1"},
    {0x2122, "earth leakage phase L2"},
    {0x2123, "earth leakage phase L3"},
    {0x2130, "short circuit (input)"},
    {0x2131, "short circuit phases L1-L2"},
    {0x2132, "short circuit phases L2-L3"},
    {0x2133, "short circuit phases L3-L1"},
    {0x2211, "internal current no. 1"},
    {0x2212, "internal current no. 2"},
    {0x2213, "over current in ramp function"},
    {0x2214, "over current in the sequence"},
    {0x2220, "continuous over current (device internal)"},
    {0x2221, "continuous over current no. 1"},
    {0x2222, "continuous over current no. 2"},
    {0x2230, "short circuit or earth leakage (device internal)"},
    {0x2240, "earth leakage (device internal)"},
    {0x2250, "short circuit (device internal)"},
    {0x2310, "continuous over current"},
    {0x2311, "continuous over current no. 1"},
    {0x2312, "continuous over current no. 2"},
    {0x2320, "short circuit or earth leakage (motor side)"},
    {0x2330, "earth leakage (motor side)"},
    {0x2331, "earth leakage phase U"},
    {0x2332, "earth leakage phase V"},
    {0x2333, "earth leakage phase W"},
    {0x2340, "short circuit (motor side)"},
    {0x2341, "short circuit phases U-V"},
    {0x2342, "short circuit phases V-W"},
    {0x2343, "short circuit phases W-U"},
    {0x3110, "mains over-voltage"},
    {0x3120, "mains under-voltage"},
    {0x3130, "phase failure"},
    {0x3140, "mains frequency"},
    {0x3210, "DC link over-voltage"},
    {0x3220, "DC link under-voltage"},
    {0x3230, "load error"},
    {0x3310, "output over-voltage"},
    {0x3320, "armature circuit"},
    {0x3330, "field circuit"},
    {0x4110, "excess ambient temperature"},
    {0x4120, "too low ambient temperature"},
    {0x4130, "temperature supply air"},
    {0x4140, "temperature air outlet"},
    {0x4210, "excess temperature device"},
    {0x4220, "too low temperature device"},
    {0x4310, "excess temperature drive"},
    {0x4320, "too low temperature drive"},
    {0x4410, "excess temperature supply"},
    {0x4420, "too low temperature supply"},
    {0x5110, "supply low voltage"},
    {0x5210, "measurement circuit"},
    {0x5220, "computing circuit"},
    {0x5410, "output stages"},
    {0x5420, "chopper"},
    {0x5430, "input stages"},
    {0x5440, "contacts"},
    {0x5450, "fuses"},
    {0x5510, "RAM"},
    {0x5520, "EPROM"},
    {0x5530, "EEPROM"},
    {0x6010, "software reset (watchdog)"},
    {0x6310, "loss of parameters"},
    {0x6320, "parameter error"},
    {0x7110, "brake chopper"},
    {0x7111, "failure brake chopper"},
    {0x7112, "over current brake chopper"},
    {0x7113, "protective circuit brake chopper"},
    {0x7121, "motor blocked"},
    {0x7122, "motor error or commutation malfunction"},
    {0x7123, "motor tilted"},
    {0x7301, "tacho fault"},
    {0x7302, "tacho wrong polarity"},
    {0x7303, "resolver 1 fault"},
    {0x7304, "resolver 2 fault"},
    {0x7305, "incremental sensor 1 fault"},
    {0x7306, "incremental sensor 2 fault"},
    {0x7307, "incremental sensor 3 fault"},
    {0x7310, "speed"},
    {0x7320, "position"},
    {0x7510, "serial interface no. 1"},
    {0x7520, "serial interface no. 2"},
    {0x8311, "excess torque"},
    {0x8312, "difficult start up"},
    {0x8313, "standstill torque"},
    {0x8321, "insufficient torque"},
    {0x8331, "torque fault"},
    {0x8611, "following error"},
    {0x8612, "reference limit"},
    {0xF001, "deceleration"},
    {0xF002, "sub-synchronous run"},
}};

/// The CiA 402 name of an error code; empty when the table has none (a generic or
/// manufacturer-specific code: see canopen::emcy::classify).
[[nodiscard]] constexpr std::string_view describe_error_code(std::uint16_t code) noexcept {
  const auto *it =
      std::lower_bound(error_codes.begin(), error_codes.end(), code,
                       [](const error_code_text &e, std::uint16_t c) { return e.code < c; });
  return it != error_codes.end() && it->code == code ? it->text : std::string_view{};
}

} // namespace fieldcodec::ds402
