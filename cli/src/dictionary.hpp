// fieldcodec CLI — object dictionaries loaded at run time (EDS, DCF, CSV through the
// generator's readers) and what the decoder needs of them: names, types, units, scales, the
// configured PDO communication and mapping values, and the device family.
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/entry.hpp>

#include "model.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fieldcodec::cli {

/// What the decoder knows about a device beyond its dictionary.
enum class device_family : std::uint8_t {
  generic, ///< CiA 301 only
  ds402,   ///< a CiA 402 drive (6040h/6041h shown as command/state)
  xenax,   ///< Jenny Science XENAX: CiA 402 and the units of docs/xenax.md
  dpq,     ///< Rexroth DPQ: scaled parameters, its EMCY codes
};
[[nodiscard]] std::string_view to_string(device_family f);
[[nodiscard]] bool parse_family(std::string_view s, device_family &out);

/// One sub-object as the decoder uses it.
struct object_desc {
  od::entry core{}; ///< index, sub, object code, type, access, PDO mapping, capacity
  /// The packed columns `core` points to (od::pack; shared, so that a copy's `core` stays valid).
  std::shared_ptr<const char[]> packed;
  std::string name; ///< "Identity Object: Vendor Id" for a sub-object of a record
  std::string unit; ///< engineering unit ("bar", "mA", "inc"), empty when none
  std::optional<scaling::linear> scale; ///< EU = raw / scale + offset (DPQ)
  /// A unit factor the device manual gives (XENAX 6073h: 10 mA per raw step): EU = raw × factor
  std::optional<decimal> factor;
  std::optional<std::int64_t> configured; ///< DCF ParameterValue, else the default (node resolved)
};

class node_dictionary {
public:
  /// Load `path` (.eds, .dcf, .csv) for node `node` (1..127; 0 when it serves every node).
  /// On failure returns nothing and sets `error` to one line per problem.
  static std::optional<node_dictionary> load(const std::string &path, std::uint8_t node,
                                             std::string &error);

  [[nodiscard]] const object_desc *find(od::address a) const;
  [[nodiscard]] const std::vector<object_desc> &objects() const { return objects_; }
  [[nodiscard]] device_family family() const { return family_; }
  void set_family(device_family f) { family_ = f; }
  [[nodiscard]] const std::string &path() const { return path_; }
  /// The generator's model (for writing a DCF).
  [[nodiscard]] const gen::dictionary &model() const { return *model_; }
  /// The same dictionary for another node (node-ID-relative defaults resolved again).
  [[nodiscard]] node_dictionary for_node(std::uint8_t node) const;

private:
  void build(std::uint8_t node);
  std::string path_;
  std::shared_ptr<const gen::dictionary> model_;
  std::vector<object_desc> objects_; ///< sorted by address
  device_family family_ = device_family::generic;
};

/// The units the XENAX manual gives for objects whose EDS cannot say (CiA 306 has no unit
/// keyword; docs/xenax.md, "Units are not in the EDS").
struct unit_rule {
  std::uint16_t index;
  int sub; ///< -1: every sub-index
  std::string_view unit;
  decimal factor; ///< EU per raw step
};
[[nodiscard]] std::span<const unit_rule> xenax_units();

} // namespace fieldcodec::cli
