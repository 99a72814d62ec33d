// fieldcodec-gen — generator options applied to a dictionary after reading (docs/generator.md):
// --only (index filter), --string-capacity (capacities of byte strings), --compact-arrays.
#pragma once

#include "diag.hpp"
#include "model.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::gen {

/// Objects first..last (inclusive).
struct index_range {
  std::uint16_t first = 0;
  std::uint16_t last = 0;
};

/// `--string-capacity INDEX[:SUB]=BYTES`: the capacity of the byte-string entries of one object
/// (or of one of its sub-indices).
struct capacity_override {
  std::uint16_t index = 0;
  std::optional<std::uint8_t> sub; ///< nothing: every sub-index
  std::uint32_t bytes = 0;
  std::string text; ///< as given on the command line (diagnostics)
};

struct generator_options {
  std::vector<index_range> only;                ///< empty: every object
  std::string only_text;                        ///< --only as given (diagnostics)
  std::optional<std::uint32_t> string_capacity; ///< --string-capacity BYTES
  std::vector<capacity_override> capacities;    ///< --string-capacity INDEX[:SUB]=BYTES
  bool compact_arrays = false;                  ///< --compact-arrays
  bool sub_descriptors = true;                  ///< false: --no-sub-descriptors
};

/// Parses the argument of --only ("0x1000-0x1FFF,0x6000-0x67FF", "0x1018"; indices in hex with
/// 0x). Returns an error text ("" when it is valid) and appends the ranges to `out`.
[[nodiscard]] std::string parse_index_ranges(std::string_view text, std::vector<index_range> &out);

/// Parses the argument of --string-capacity ("64", "0x5011=30", "0x2121:2=64") into `o`.
/// Returns an error text ("" when it is valid).
[[nodiscard]] std::string parse_string_capacity(std::string_view text, generator_options &o);

/// Applies the options to a dictionary read from `file`, in this order: --only, the capacities
/// of byte strings (overrides, then --string-capacity BYTES; every VISIBLE_STRING /
/// OCTET_STRING / UNICODE_STRING / DOMAIN entry still without a capacity gets a warning), then
/// --compact-arrays; --no-sub-descriptors sets dictionary::sub_descriptors. Returns false when an
/// error was reported.
bool apply_options(dictionary &d, const generator_options &o, const std::string &file,
                   diagnostics &diag);

/// --compact-arrays: every run of two or more consecutive sub-objects of an ARRAY that are alike
/// in everything but their sub-index and a name that ends in the sub-index in decimal
/// ("TPDO 1 mapping1", "TPDO 1 mapping2", ...) becomes one entry with `count` > 1 (its name the
/// common part).
void compact_arrays(dictionary &d);

/// The inverse: every entry with `count` > 1 becomes `count` entries (what the EDS writer does).
void expand_runs(dictionary &d);

} // namespace fieldcodec::gen
