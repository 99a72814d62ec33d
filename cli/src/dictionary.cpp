// fieldcodec CLI — object dictionaries loaded at run time.
#include "dictionary.hpp"

#include "readers.hpp"

#include <fieldcodec/od/entry_spec.hpp>

#include <algorithm>

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
  for (auto f :
       {device_family::generic, device_family::ds402, device_family::xenax, device_family::dpq}) {
    if (s == to_string(f)) {
      out = f;
      return true;
    }
  }
  return false;
}

namespace {
// docs/xenax.md, decision 15: 6073h and 5003h subs 0Ch (IS) / 13h (IR) in 10 mA; 2005h and 6078h
// in mA; 2009h and 200Ah in mN; 2007h in µs; 6068h in ms; positions in encoder increments,
// speeds in inc/s, accelerations in inc/s².
constexpr unit_rule xenax_rules[] = {
    {0x6073, -1, "mA", {10, 0}},    {0x5003, 0x0C, "mA", {10, 0}},  {0x5003, 0x13, "mA", {10, 0}},
    {0x2005, -1, "mA", {1, 0}},     {0x6078, -1, "mA", {1, 0}},     {0x2009, -1, "mN", {1, 0}},
    {0x200A, -1, "mN", {1, 0}},     {0x2007, -1, "µs", {1, 0}},     {0x6068, -1, "ms", {1, 0}},
    {0x6062, -1, "inc", {1, 0}},    {0x6063, -1, "inc", {1, 0}},    {0x6064, -1, "inc", {1, 0}},
    {0x6065, -1, "inc", {1, 0}},    {0x6067, -1, "inc", {1, 0}},    {0x607A, -1, "inc", {1, 0}},
    {0x607C, -1, "inc", {1, 0}},    {0x607D, -1, "inc", {1, 0}},    {0x60F4, -1, "inc", {1, 0}},
    {0x606C, -1, "inc/s", {1, 0}},  {0x6081, -1, "inc/s", {1, 0}},  {0x60FF, -1, "inc/s", {1, 0}},
    {0x60B1, -1, "inc/s", {1, 0}},  {0x6099, -1, "inc/s", {1, 0}},  {0x6083, -1, "inc/s²", {1, 0}},
    {0x6084, -1, "inc/s²", {1, 0}}, {0x6085, -1, "inc/s²", {1, 0}}, {0x609A, -1, "inc/s²", {1, 0}},
};

bool has_key_value(const gen::key_list &keys, std::string_view key, std::string_view needle) {
  for (const auto &[k, v] : keys) {
    if (k == key && v.find(needle) != std::string::npos) return true;
  }
  return false;
}

/// The integer a number holds (integers only).
std::optional<std::int64_t> integer_of(const od::number &n) {
  auto i = n.to_int64();
  if (i) return i.value();
  auto u = n.to_uint64();
  if (u) return static_cast<std::int64_t>(u.value());
  return std::nullopt;
}
} // namespace

std::span<const unit_rule> xenax_units() { return xenax_rules; }

std::optional<node_dictionary> node_dictionary::load(const std::string &path, std::uint8_t node,
                                                     std::string &error) {
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
  } else {
    for (const auto &e : m.entries) {
      if (e.index == 0x6041) {
        out.family_ = device_family::ds402;
        break;
      }
    }
  }
  out.build(node);
  return out;
}

node_dictionary node_dictionary::for_node(std::uint8_t node) const {
  node_dictionary out;
  out.path_ = path_;
  out.model_ = model_;
  out.family_ = family_;
  out.build(node);
  return out;
}

void node_dictionary::build(std::uint8_t node) {
  objects_.clear();
  const gen::dictionary &m = *model_;
  for (const gen::entry &e : m.entries) {
    for (std::uint16_t k = 0; k < e.count; ++k) {
      object_desc d;
      od::entry_spec spec;
      spec.index = e.index;
      spec.sub = static_cast<std::uint8_t>(e.sub + k);
      spec.object = e.object;
      spec.type = e.type;
      spec.access_type = e.access;
      spec.pdo = e.pdo;
      spec.size = e.size;
      if (const std::size_t n = od::packed_size(spec); n != 0U) {
        auto bytes = std::make_shared<char[]>(n);
        (void)od::pack(spec, std::span<char>(bytes.get(), n));
        d.packed = std::move(bytes);
      }
      d.core = od::make_entry(spec, d.packed.get());
      std::string sub_name = e.name;
      if (e.count > 1U) sub_name += std::to_string(d.core.sub);
      const auto obj = m.objects.find(e.index);
      if (e.object == od::object_code::var || obj == m.objects.end() || obj->second.name.empty() ||
          obj->second.name == sub_name) {
        d.name = sub_name;
      } else {
        d.name = obj->second.name + ": " + sub_name;
      }
      d.unit = e.unit;
      if (e.scaled) d.scale = scaling::linear{e.scale, e.offset};
      const od::number &v = e.parameter_value ? e.parameter_value : e.default_value;
      const bool relative = e.parameter_value ? e.parameter_nodeid : e.default_nodeid;
      if (auto i = integer_of(v)) {
        d.configured = *i + (relative ? node : 0);
      }
      objects_.push_back(std::move(d));
    }
  }
  if (family_ == device_family::xenax) {
    for (object_desc &d : objects_) {
      for (const unit_rule &r : xenax_rules) {
        if (r.index != d.core.index || (r.sub >= 0 && r.sub != d.core.sub)) continue;
        if (d.core.object != od::object_code::var && r.sub < 0 && d.core.sub == 0) continue;
        if (!d.unit.empty()) continue;
        d.unit = r.unit;
        if (r.factor.mantissa != 1 || r.factor.places != 0) d.factor = r.factor;
      }
    }
  }
  std::sort(objects_.begin(), objects_.end(), [](const object_desc &a, const object_desc &b) {
    return od::address{a.core.index, a.core.sub} < od::address{b.core.index, b.core.sub};
  });
}

const object_desc *node_dictionary::find(od::address a) const {
  auto it = std::lower_bound(objects_.begin(), objects_.end(), a,
                             [](const object_desc &d, od::address x) {
                               return od::address{d.core.index, d.core.sub} < x;
                             });
  if (it == objects_.end() || it->core.index != a.index || it->core.sub != a.sub) return nullptr;
  return &*it;
}

} // namespace fieldcodec::cli
