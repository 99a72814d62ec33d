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

/// One slave of a CiA 302 master DCF: its node-ID and what the master's objects hold for it.
struct nmt_slave_row {
  std::uint8_t node = 0;
  master::slave_objects objects{}; ///< concise_dcf empty: the bytes are in `concise_dcf`
  std::vector<std::uint8_t> concise_dcf;
  std::string dcf_source; ///< where the concise DCF came from ("./x.bin"), for the header
};

/// The slaves of the master DCF `d` (read from `file`; an UploadFile of 1F22h is read relative to
/// its directory): every node 1..127 whose 1F81h sub-object has a value other than 0, with 1F84h
/// to 1F88h, 1F22h, the consumer time of the 1016h entry naming it, 1F55h, 1F26h, 1F27h and
/// 1F8Ah. Errors (in `diag`): a concise DCF that cannot be read or is malformed.
[[nodiscard]] std::vector<nmt_slave_row>
build_nmt_slaves(const dictionary &d, const std::string &file, diagnostics &diag);

/// The C++ header of a master's slaves: namespace fieldcodec::dictionaries::<stem>::slaves with
/// `slaves` (std::span<const master::nmt_slave>, node order).
[[nodiscard]] std::string emit_nmt_slaves(const dictionary &d,
                                          const std::vector<nmt_slave_row> &rows);

} // namespace fieldcodec::gen
