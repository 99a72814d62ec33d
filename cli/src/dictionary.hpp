// fieldcodec CLI — object dictionaries loaded at run time (EDS, DCF, CSV through the
// generator's readers) as od tables (codegen's od_tables): the descriptors od's one value path
// converts with (od/value_text.hpp), display names, the configured PDO communication and
// mapping values, and the device family.
#pragma once

#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/descriptor.hpp>

#include "model.hpp"
#include "od_tables.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::cli {

/// What the decoder knows about a device beyond its dictionary.
enum class device_family : std::uint8_t {
  generic, ///< CiA 301 only
  ds402,   ///< a CiA 402 drive (6040h/6041h shown as command/state)
  xenax,   ///< Jenny Science XENAX: CiA 402 and the units of xenax::canopen_units
  dpq,     ///< Rexroth DPQ: scaled parameters (from its table), its EMCY codes
};
[[nodiscard]] std::string_view to_string(device_family f);
/// Case-insensitive ("XENAX", "xenax").
[[nodiscard]] bool parse_family(std::string_view s, device_family &out);

/// One sub-object as the CLI uses it.
struct object_desc {
  od::descriptor d{}; ///< entry, info (name, unit) and scale; vendor units applied
  std::string name;   ///< "Identity Object: Vendor Id" for a sub-object of a record
  /// DCF ParameterValue, else the default (node resolved); empty when it is no integer of 64
  /// signed bits
  std::optional<std::int64_t> configured;
};

class node_dictionary {
public:
  /// Load `path` (.eds, .dcf, .csv). On failure returns nothing and sets `error` to one line
  /// per problem. The result describes no node yet: see for_node.
  static std::optional<node_dictionary> load(const std::string &path, std::string &error);

  /// The dictionary for node `node` (1..127, node-ID-relative values resolved; 0: none) of
  /// family `f` (its vendor units applied).
  [[nodiscard]] node_dictionary for_node(std::uint8_t node, device_family f) const;
  [[nodiscard]] node_dictionary for_node(std::uint8_t node) const {
    return for_node(node, family_);
  }

  [[nodiscard]] const object_desc *find(od::address a) const;
  [[nodiscard]] const std::vector<object_desc> &objects() const { return objects_; }
  /// The family the dictionary names (VendorName, file name, 6041h), or the one given.
  [[nodiscard]] device_family family() const { return family_; }
  [[nodiscard]] const std::string &path() const { return path_; }
  [[nodiscard]] std::uint8_t node() const { return node_; }
  /// The tables a simulated device of this dictionary serves (`fieldcodec serve`): values as
  /// they travel (no vendor units: the store holds raw numbers) and byte strings with room for
  /// their declared size or, without one, their default text.
  [[nodiscard]] std::shared_ptr<const gen::od_tables> device_tables() const;
  /// The generator's model (for writing a DCF).
  [[nodiscard]] const gen::dictionary &model() const { return *model_; }

private:
  void build();
  std::string path_;
  std::shared_ptr<const gen::dictionary> model_;
  std::shared_ptr<const gen::od_tables> tables_;
  std::vector<object_desc> objects_; ///< sorted by address
  device_family family_ = device_family::generic;
  std::uint8_t node_ = 0;
};

} // namespace fieldcodec::cli
