// fieldcodec CLI — object dictionaries loaded at run time.
#include "dictionary.hpp"

#include "readers.hpp"

#include <fieldcodec/xenax/canopen_units.hpp>

#include <algorithm>
#include <cctype>

namespace fieldcodec::cli {

std::string_view to_string(device_family f) {
  switch (f) {
  case device_family::generic: return "generic";
  case device_family::ds402: return "ds402";
  case device_family::xenax: return "xenax";
  case device_family::dpq: return "dpq";
  }
  return "?";
}

bool parse_family(std::string_view s, device_family &out) {
  std::string lower(s);
  for (char &c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (auto f :
       {device_family::generic, device_family::ds402, device_family::xenax, device_family::dpq}) {
    if (lower == to_string(f)) {
      out = f;
      return true;
    }
  }
  return false;
}

namespace {
bool has_key_value(const gen::key_list &keys, std::string_view key, std::string_view needle) {
  for (const auto &[k, v] : keys) {
    if (k == key && v.find(needle) != std::string::npos) return true;
  }
  return false;
}

/// The units a family's vendor supplies for objects its dictionary file cannot describe.
std::span<const od::unit_rule> vendor_units(device_family f) {
  if (f == device_family::xenax) return xenax::canopen_units;
  return {};
}
} // namespace

std::optional<node_dictionary> node_dictionary::load(const std::string &path, std::string &error) {
  gen::diagnostics diag;
  auto d = gen::read_file(path, diag);
  if (!d || diag.has_errors()) {
    error.clear();
    for (const auto &x : diag.sorted()) {
      if (x.sev != gen::severity::error) continue;
      if (!error.empty()) error += "\n";
      error += gen::diagnostics::format(x);
    }
    if (error.empty()) error = path + ": cannot be read";
    return std::nullopt;
  }
  if (d->is_command_table) {
    error = path + ": a command table, not an object dictionary";
    return std::nullopt;
  }
  node_dictionary out;
  out.path_ = path;
  out.model_ = std::make_shared<const gen::dictionary>(std::move(*d));
  const gen::dictionary &m = *out.model_;
  if (has_key_value(m.device_info, "VendorName", "Jenny Science")) {
    out.family_ = device_family::xenax;
  } else if (m.stem.rfind("dpq", 0) == 0) {
    out.family_ = device_family::dpq;
  } else if (std::any_of(m.entries.begin(), m.entries.end(),
                         [](const gen::entry &e) { return e.index == 0x6041; })) {
    out.family_ = device_family::ds402;
  }
  out.build();
  return out;
}

node_dictionary node_dictionary::for_node(std::uint8_t node, device_family f) const {
  node_dictionary out;
  out.path_ = path_;
  out.model_ = model_;
  out.family_ = f;
  out.node_ = node;
  out.build();
  return out;
}

void node_dictionary::build() {
  objects_.clear();
  tables_ = std::make_shared<const gen::od_tables>(
      *model_, gen::od_table_options{false, vendor_units(family_)});
  const od::dictionary view = tables_->view();
  objects_.reserve(view.size());
  for (const od::entry &e : view) {
    object_desc o;
    o.d = view.describe(e).value();
    o.name = std::string(tables_->display_name({e.index, e.sub}));
    const bool dcf = o.d.info.parameter_value.has_value();
    const auto v = dcf ? o.d.parameter_for(node_) : o.d.default_for(node_);
    if (v) {
      // an UNSIGNED64 above 2^63 - 1 is no int64: none, never wrapped (fuzz/FINDINGS.md F24)
      if (auto i = v.value().to_int64()) o.configured = i.value();
    }
    objects_.push_back(std::move(o));
  }
}

std::shared_ptr<const gen::od_tables> node_dictionary::device_tables() const {
  return std::make_shared<const gen::od_tables>(*model_, gen::od_table_options{true, {}});
}

const object_desc *node_dictionary::find(od::address a) const {
  auto it = std::lower_bound(objects_.begin(), objects_.end(), a,
                             [](const object_desc &o, od::address x) {
                               return od::address{o.d.index, o.d.sub} < x;
                             });
  if (it == objects_.end() || it->d.index != a.index || it->d.sub != a.sub) return nullptr;
  return &*it;
}

} // namespace fieldcodec::cli
