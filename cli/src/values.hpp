// fieldcodec CLI — a value as a person reads and types it. The value itself goes through od's
// one value path (od/value_text.hpp: engineering units, limits, scale, capacity); this file
// only chooses how it is shown (hex for identifiers and CiA 402 words) and adds what the
// decoder knows beside it: the CiA 402 controlword command, statusword state and bits, the
// mode of 6060h/6061h, what a PDO mapping entry maps, the raw number of a scaled value.
#pragma once

#include "dictionary.hpp"
#include "util.hpp"

#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/engineering.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::cli {

/// A formatted value: the text and the JSON fields ("value", "unit", "raw", "state", ...).
struct formatted_value {
  std::string text;
  json_object json;
  bool problem = false; ///< the bytes do not make a value of the type
};

/// What the decoder remembers between values of one node: the controlword's fault-reset edge,
/// the mode the drive reports (for the statusword's mode bits).
struct value_context {
  std::uint16_t previous_controlword = 0;
  std::optional<std::int8_t> mode; ///< 6061h (or 6060h) as last seen
};

/// How `d` is shown and read by the CLI for node `node`: hex for identifiers and bit fields of
/// the communication area and the CiA 402 control/statusword, raw numbers with `raw`.
[[nodiscard]] od::value_options display_options(const od::descriptor &d, std::uint8_t node,
                                                bool raw);

/// Format the bytes of `a` (`d` may be null: no dictionary entry; raw: --raw).
[[nodiscard]] formatted_value format_value(const object_desc *d, od::address a,
                                           std::span<const std::uint8_t> bytes,
                                           device_family family, value_context &ctx,
                                           bool raw = false);

/// The text a user typed for `d`, through od's value path, for node `node`.
struct parsed_value {
  bool ok = false;
  std::vector<std::uint8_t> bytes;
  std::string error; ///< why it was refused (names the limit, the capacity, ...)
};
[[nodiscard]] parsed_value parse_value(const object_desc &d, std::string_view text,
                                       std::uint8_t node, bool raw);

/// An entry of type `hint` ("u8" … "u64", "i8" … "i64", "f32", "f64", "bool", "str", "hex")
/// at `a`, for --type without a dictionary; nothing for an unknown hint.
[[nodiscard]] std::optional<object_desc> type_entry(std::string_view hint, od::address a);
/// The --type names, for messages.
inline constexpr std::string_view type_names = "u8 u16 u32 u64 i8 i16 i32 i64 f32 f64 bool str hex";

} // namespace fieldcodec::cli
