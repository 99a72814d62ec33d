// fieldcodec CLI — PA-CONTROL RS232 captures (raw bytes or hex text) → requests,
// acknowledgements and polls with command names, values and the check result, through the
// library's byte-at-a-time decoder.
#pragma once

#include "can_decoder.hpp"

#include <fieldcodec/pacontrol/serial_decoder.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::cli {

/// Bytes of a hex capture ("01 02 31 39 30 36 …", "0x01,0x02", "# comments"). Returns false and
/// sets `error` on a character that is not hex (or an odd digit count in one token).
[[nodiscard]] bool parse_hex_capture(std::string_view text, std::vector<std::uint8_t> &out,
                                     std::string &error);
/// True when `bytes` look like a hex capture (only hex digits, blanks, commas, "0x", comments).
[[nodiscard]] bool looks_like_hex(std::string_view bytes);

/// --check-rule: "manual" (requests: body, acknowledgements: body+ETX, as the manual's examples;
/// nothing else passes), "either" (the manual's rule per direction, the other one accepted and
/// noted — the manual mixes them: 3.4.3), "body", "body+etx" (that rule both ways). Nothing for
/// another word.
[[nodiscard]] std::optional<pacontrol::serial::check_options> parse_check_rule(std::string_view s);
/// The check rules decode uses without --check-rule: "either".
[[nodiscard]] pacontrol::serial::check_options default_decode_checks();

/// Decode a whole capture into lines ("REQUEST", "ACK", "POLL", "NOISE", "MALFORMED").
[[nodiscard]] std::vector<decoded_line>
decode_pacontrol(std::span<const std::uint8_t> capture,
                 const pacontrol::serial::check_options &checks = default_decode_checks());

} // namespace fieldcodec::cli
