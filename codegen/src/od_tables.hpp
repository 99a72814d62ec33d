// fieldcodec-gen — a dictionary read at run time as od tables: the entries, infos and scales a
// generated header would hold, built in memory from the generator's model, so that a host
// program (the fieldcodec CLI, a remote node loaded from an EDS) looks objects up with
// od::dictionary and converts their values with od's one value path (od/engineering.hpp,
// od/value_text.hpp) — exactly as code using a generated header does.
#pragma once

#include "model.hpp"

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/engineering.hpp>
#include <fieldcodec/od/entry.hpp>

#include <deque>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::gen {

struct od_table_options {
  /// A byte string's capacity: only a size the file declares (Size=, the CSV bytes column)
  /// when false — a device's string may be longer than the EDS default, and a tool talking to
  /// a real device must not refuse it —, also the capacity derived from the default's length
  /// (what a generated header gives a firmware store) when true.
  bool capacity_from_default = false;
  /// Units and scales a vendor supplies for objects the file cannot describe
  /// (xenax::canopen_units), applied with od::with_unit.
  std::span<const od::unit_rule> units{};
};

/// The tables of one dictionary. Not copyable (the infos point into its own text storage);
/// movable.
class od_tables {
public:
  explicit od_tables(const dictionary &d, od_table_options o = {});
  od_tables(const od_tables &) = delete;
  od_tables &operator=(const od_tables &) = delete;
  od_tables(od_tables &&) noexcept = default;
  od_tables &operator=(od_tables &&) noexcept = default;
  ~od_tables() = default;

  /// The view od's lookups work on.
  [[nodiscard]] od::dictionary view() const noexcept {
    return od::dictionary(entries_, infos_, scales_);
  }
  /// The descriptor at `a`. Errors: unknown_object.
  [[nodiscard]] result<od::descriptor> at(od::address a) const noexcept { return view().at(a); }
  /// The name a person reads: the sub-object's own name for a VAR or where the object has
  /// none, else "Object: Sub-object" ("Identity Object: Vendor Id"); empty when absent.
  [[nodiscard]] std::string_view display_name(od::address a) const noexcept;
  /// The address of a sub-object by the names the file gives: the object's name and, for an
  /// ARRAY/RECORD, the sub-object's (`address_of("Identity Object", "Vendor Id")`); a VAR by its
  /// name alone. Exact, case-sensitive. Errors: unknown_object (no such name, or a RECORD
  /// without the sub-object's name).
  [[nodiscard]] result<od::address> address_of(std::string_view object,
                                               std::string_view sub = {}) const noexcept;
  /// The entries that could not take their vendor unit (od::with_unit failed), by address.
  [[nodiscard]] const std::vector<od::address> &unit_failures() const noexcept {
    return unit_failures_;
  }

private:
  od::text keep(std::string_view s);

  std::vector<od::entry> entries_;
  std::vector<od::entry_info> infos_;
  std::vector<scaling::linear> scales_;
  std::vector<std::string_view> display_names_; ///< parallel to entries_
  std::vector<std::string_view> object_names_;  ///< parallel: the object's name ("" for a VAR)
  std::deque<std::string> texts_;               ///< stable storage for every od::text
  std::vector<od::address> unit_failures_;
};

} // namespace fieldcodec::gen
