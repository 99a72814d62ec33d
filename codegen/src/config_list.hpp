// fieldcodec-gen — the configuration list of a DCF (`--config-list FILE`, docs/master.md): the
// SDO downloads that bring a device from its EDS defaults to the DCF's values, in the order they
// must be written, the identity to check at boot, and the concise DCF (1F22h format).
#pragma once

#include "diag.hpp"
#include "model.hpp"

#include <fieldcodec/master/config.hpp>
#include <fieldcodec/od/address.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace fieldcodec::gen {

/// Which value of an entry the list writes.
enum class config_values : std::uint8_t {
  parameter, ///< DCF ParameterValue, where it differs from DefaultValue (default)
  default_,  ///< DefaultValue of every writable entry that has one (`--config-values default`)
};

struct config_list_item {
  od::address address{};
  std::vector<std::uint8_t> value; ///< little-endian; the offset x of "$NODEID+x" when relative
  std::uint8_t flags = 0;          ///< master::config_flag
  std::string name;                ///< "object: sub-object" (the object's name for a VAR)
};

struct config_list {
  std::vector<config_list_item> items;
  master::identity expected{};
  std::uint8_t node_id = 0; ///< the DCF's NodeID, 0 when none
};

/// Builds the list of `d` (read from `file`). Entries that cannot be written (read-only, no
/// value, a type without a byte form) are left out; PDOs whose parameters change are written in
/// the CiA 301 order (COB-ID with bit 31 set, communication parameters, mapping count 0,
/// mapping entries, mapping count, COB-ID). Warnings for what is left out on purpose.
[[nodiscard]] config_list build_config_list(const dictionary &d, config_values values,
                                            const std::string &file, diagnostics &diag);

/// The C++ header of a list: namespace fieldcodec::dictionaries::<stem>::config with
/// `node_id`, `identity`, `items`, `configuration` and `concise_dcf` (for the DCF's node-ID; left
/// out with a comment when node-relative items have no node-ID to resolve them).
[[nodiscard]] std::string emit_config_list(const dictionary &d, const config_list &l);

} // namespace fieldcodec::gen
