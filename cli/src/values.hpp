// fieldcodec CLI — a value as a person reads it: typed by the dictionary, in engineering units
// (DPQ scale/offset, XENAX unit factors), CiA 402 controlword/statusword as command/state.
#pragma once

#include "dictionary.hpp"
#include "util.hpp"

#include <fieldcodec/od/address.hpp>

#include <cstdint>
#include <span>
#include <string>

namespace fieldcodec::cli {

/// A formatted value: the text and the JSON fields ("value", "unit", "raw", "state", ...).
struct formatted_value {
  std::string text;
  json_object json;
};

/// What the decoder remembers between values of one node (the controlword's fault-reset edge).
struct value_context {
  std::uint16_t previous_controlword = 0;
};

/// Format the bytes of `a` (`d` may be null: no dictionary entry).
[[nodiscard]] formatted_value format_value(const object_desc *d, od::address a,
                                           std::span<const std::uint8_t> bytes,
                                           device_family family, value_context &ctx);

/// The same for a value parsed from text for a download (sdo write): `text` → bytes of the
/// entry's type (integers in EU when scaled), or the error text. Without an entry the type
/// comes from `type_hint` ("u8", "i16", "u32", "f32", "str", "hex"...).
struct parsed_value {
  bool ok = false;
  std::vector<std::uint8_t> bytes;
  std::string error;
};
[[nodiscard]] parsed_value parse_value(const object_desc *d, std::string_view type_hint,
                                       std::string_view text);

} // namespace fieldcodec::cli
