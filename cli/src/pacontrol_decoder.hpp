// fieldcodec CLI — PA-CONTROL RS232 captures (raw bytes or hex text) → requests,
// acknowledgements and polls with command names, values and the check result, through the
// library's byte-at-a-time decoder.
#pragma once

#include "can_decoder.hpp"

#include <cstdint>
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

/// Decode a whole capture into lines ("REQUEST", "ACK", "POLL", "NOISE", "MALFORMED").
[[nodiscard]] std::vector<decoded_line> decode_pacontrol(std::span<const std::uint8_t> capture);

} // namespace fieldcodec::cli
