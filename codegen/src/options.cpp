// fieldcodec-gen — generator options applied after reading (options.hpp).
#include "options.hpp"
#include "text.hpp"

#include <algorithm>
#include <map>

namespace fieldcodec::gen {

namespace {

// An index as the options write it: 0x and 1..4 hex digits.
std::string parse_index(std::string_view t, std::uint16_t &out) {
  t = trim(t);
  if (t.size() < 3U || t[0] != '0' || (t[1] != 'x' && t[1] != 'X')) {
    return "expected an index such as 0x1000, got '" + std::string(t) + "'";
  }
  const int_parse p = parse_int(t);
  auto v = p.value.to_uint64();
  if (!p.ok || p.suffix || !v)
    return p.ok ? "expected an index such as 0x1000, got '" + std::string(t) + "'" : p.error;
  if (v.value() > 0xFFFFU) {
    return "index '" + std::string(t) + "' is beyond 0xFFFF";
  }
  out = static_cast<std::uint16_t>(v.value());
  return "";
}

// A count in decimal or 0x hex (no octal), min..max.
std::string parse_count(std::string_view t, std::uint64_t min, std::uint64_t max, const char *what,
                        std::uint64_t &out) {
  t = trim(t);
  const bool hex_prefix = t.size() > 2U && t[0] == '0' && (t[1] == 'x' || t[1] == 'X');
  if (t.empty() || (!hex_prefix && t.size() > 1U && t[0] == '0') ||
      !std::all_of(t.begin() + (hex_prefix ? 2 : 0), t.end(), [&](char c) {
        return (c >= '0' && c <= '9') ||
               (hex_prefix && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')));
      })) {
    return "expected " + std::string(what) + " (decimal or 0x hex), got '" + std::string(t) + "'";
  }
  const int_parse p = parse_int(t);
  auto v = p.value.to_uint64();
  if (!p.ok || !v || v.value() < min || v.value() > max) {
    return "expected " + std::string(what) + " " + std::to_string(min) + ".." +
           std::to_string(max) + ", got '" + std::string(t) + "'";
  }
  out = v.value();
  return "";
}

bool alike(const entry &a, const entry &b) {
  auto same_decimal = [](decimal x, decimal y) {
    return x.mantissa == y.mantissa && x.places == y.places;
  };
  return a.index == b.index && a.object == b.object && a.type_code == b.type_code &&
         a.type == b.type && a.access == b.access && a.pdo == b.pdo && a.flags == b.flags &&
         a.size == b.size && a.size_declared == b.size_declared && a.symbol.empty() &&
         b.symbol.empty() && a.low == b.low && a.high == b.high &&
         a.default_value == b.default_value && a.parameter_value == b.parameter_value &&
         a.low_nodeid == b.low_nodeid && a.high_nodeid == b.high_nodeid &&
         a.default_nodeid == b.default_nodeid && a.parameter_nodeid == b.parameter_nodeid &&
         a.default_text == b.default_text && a.parameter_text == b.parameter_text &&
         a.denotation == b.denotation && a.scaled == b.scaled && same_decimal(a.scale, b.scale) &&
         same_decimal(a.offset, b.offset) && a.unit == b.unit && a.alt_name == b.alt_name &&
         a.acceptance == b.acceptance && a.section == b.section && a.remark == b.remark &&
         a.pointer == b.pointer && a.bus == b.bus && a.obj_flags == b.obj_flags &&
         a.has_obj_flags == b.has_obj_flags && a.other_keys == b.other_keys;
}

// The name of sub-index `sub` without its decimal number at the end; nothing when the name does
// not end in it.
std::optional<std::string> run_base(const entry &e) {
  const std::string n = std::to_string(e.sub);
  if (e.count != 1U || e.sub == 0U || !e.name.ends_with(n)) return std::nullopt;
  return e.name.substr(0, e.name.size() - n.size());
}

void only(dictionary &d, const generator_options &o, const std::string &file, diagnostics &diag) {
  if (o.only.empty()) return;
  auto kept = [&](std::uint16_t index) {
    return std::any_of(o.only.begin(), o.only.end(),
                       [&](const index_range &r) { return index >= r.first && index <= r.last; });
  };
  for (const auto &r : o.only) {
    const bool any = std::any_of(d.objects.begin(), d.objects.end(), [&](const auto &obj) {
      return obj.first >= r.first && obj.first <= r.last;
    });
    if (!any) {
      diag.warning(file, 0, 0,
                   "--only: no object in 0x" + hex(r.first, 4) + "-0x" + hex(r.last, 4));
    }
  }
  std::erase_if(d.entries, [&](const entry &e) { return !kept(e.index); });
  std::erase_if(d.objects, [&](const auto &obj) { return !kept(obj.first); });
}

std::string type_list() { return "VISIBLE_STRING, OCTET_STRING, UNICODE_STRING or DOMAIN"; }

bool capacities(dictionary &d, const generator_options &o, const std::string &file,
                diagnostics &diag) {
  bool ok = true;
  for (const auto &c : o.capacities) {
    bool matched = false;
    for (auto &e : d.entries) {
      if (e.index != c.index || (c.sub && e.sub != *c.sub) || !od::is_byte_string(e.type)) {
        continue;
      }
      matched = true;
      const std::size_t longest = std::max(e.default_text.size(), e.parameter_text.size());
      if (longest > c.bytes) {
        diag.error(file, e.line, 0,
                   "--string-capacity " + c.text + ": the " +
                       (e.default_text.size() == longest ? "default" : "DCF value") + " of 0x" +
                       hex(e.index, 4) + " sub-index " + std::to_string(e.sub) + " is " +
                       std::to_string(longest) + " bytes");
        ok = false;
        continue;
      }
      e.size = c.bytes;
      e.size_declared = true;
    }
    if (!matched) {
      diag.error(file, 0, 0,
                 "--string-capacity " + c.text + ": " +
                     (d.objects.count(c.index) == 0U
                          ? "no object 0x" + hex(c.index, 4)
                          : "object 0x" + hex(c.index, 4) + " has no " + type_list() + " entry" +
                                (c.sub ? " at sub-index " + std::to_string(*c.sub) : "")));
      ok = false;
    }
  }
  // one warning per object: DOMAIN arrays have up to 254 sub-objects
  std::map<std::uint16_t, std::vector<const entry *>> without;
  for (auto &e : d.entries) {
    if (!od::is_byte_string(e.type)) continue;
    if (o.string_capacity && !e.size_declared) e.size = std::max(e.size, *o.string_capacity);
    if (e.size == 0U) without[e.index].push_back(&e);
  }
  for (const auto &[index, list] : without) {
    const entry &e = *list.front();
    auto obj = d.objects.find(index);
    const std::string what =
        list.size() == 1U
            ? std::string(od::name(e.type)) + " 0x" + hex(index, 4) +
                  (e.sub != 0U ? " sub-index " + std::to_string(e.sub) : std::string()) + " '" +
                  e.name + "' has"
            : std::to_string(list.size()) + " string or DOMAIN sub-objects of 0x" + hex(index, 4) +
                  (obj != d.objects.end() ? " '" + obj->second.name + "'" : std::string()) +
                  " have";
    diag.warning(file, e.line, 0,
                 what +
                     " no capacity (no declared size, no default): a fixed-slot store cannot "
                     "hold " +
                     (list.size() == 1U ? "it" : "them") +
                     "; declare a size (EDS Size=, CSV bytes) or use "
                     "--string-capacity");
  }
  return ok;
}

} // namespace

std::string parse_index_ranges(std::string_view text, std::vector<index_range> &out) {
  if (trim(text).empty()) return "expected index ranges such as 0x1000-0x1FFF,0x6000-0x67FF";
  std::size_t pos = 0;
  while (true) {
    const auto comma = text.find(',', pos);
    const std::string_view item = trim(
        text.substr(pos, comma == std::string_view::npos ? std::string_view::npos : comma - pos));
    if (item.empty()) return "expected an index range between the commas, got nothing";
    index_range r;
    const auto dash = item.find('-');
    if (dash == std::string_view::npos) {
      if (auto e = parse_index(item, r.first); !e.empty()) return e;
      r.last = r.first;
    } else {
      if (auto e = parse_index(item.substr(0, dash), r.first); !e.empty()) return e;
      if (auto e = parse_index(item.substr(dash + 1U), r.last); !e.empty()) return e;
      if (r.first > r.last) {
        return "range '" + std::string(item) + "' ends before it begins";
      }
    }
    out.push_back(r);
    if (comma == std::string_view::npos) break;
    pos = comma + 1U;
  }
  return "";
}

std::string parse_string_capacity(std::string_view text, generator_options &o) {
  const std::string_view t = trim(text);
  const auto eq = t.find('=');
  std::uint64_t bytes = 0;
  if (eq == std::string_view::npos) {
    if (o.string_capacity) return "--string-capacity BYTES is given twice";
    if (auto e = parse_count(t, 1, 0xFFFF'FFFFU, "a capacity in bytes", bytes); !e.empty()) {
      return e;
    }
    o.string_capacity = static_cast<std::uint32_t>(bytes);
    return "";
  }
  capacity_override c;
  c.text = std::string(t);
  const std::string_view target = trim(t.substr(0, eq));
  const auto colon = target.find(':');
  if (auto e = parse_index(target.substr(0, colon), c.index); !e.empty()) return e;
  if (colon != std::string_view::npos) {
    std::uint64_t sub = 0;
    if (auto e = parse_count(target.substr(colon + 1U), 0, 255, "a sub-index", sub); !e.empty()) {
      return e;
    }
    c.sub = static_cast<std::uint8_t>(sub);
  }
  if (auto e = parse_count(t.substr(eq + 1U), 1, 0xFFFF'FFFFU, "a capacity in bytes", bytes);
      !e.empty()) {
    return e;
  }
  c.bytes = static_cast<std::uint32_t>(bytes);
  for (const auto &x : o.capacities) {
    if (x.index == c.index && x.sub == c.sub)
      return "capacity of '" + std::string(target) + "' is given twice";
  }
  o.capacities.push_back(std::move(c));
  return "";
}

void compact_arrays(dictionary &d) {
  std::vector<entry> out;
  out.reserve(d.entries.size());
  for (std::size_t i = 0; i < d.entries.size();) {
    const entry &first = d.entries[i];
    auto obj = d.objects.find(first.index);
    const auto base = run_base(first);
    std::size_t n = 1;
    if (base && obj != d.objects.end() && obj->second.code == od::object_code::array) {
      while (i + n < d.entries.size()) {
        const entry &next = d.entries[i + n];
        if (next.sub != first.sub + n || !alike(first, next) || run_base(next) != base) break;
        ++n;
      }
    }
    out.push_back(first);
    if (n > 1U) {
      out.back().count = static_cast<std::uint16_t>(n);
      out.back().name = *base;
    }
    i += n;
  }
  d.entries = std::move(out);
}

void expand_runs(dictionary &d) {
  std::vector<entry> out;
  out.reserve(d.entries.size());
  for (const auto &e : d.entries) {
    if (e.count <= 1U) {
      out.push_back(e);
      continue;
    }
    for (std::uint16_t k = 0; k < e.count; ++k) {
      entry x = e;
      x.count = 1;
      x.sub = static_cast<std::uint8_t>(e.sub + k);
      x.name = e.name + std::to_string(x.sub);
      out.push_back(std::move(x));
    }
  }
  d.entries = std::move(out);
}

bool apply_options(dictionary &d, const generator_options &o, const std::string &file,
                   diagnostics &diag) {
  only(d, o, file, diag);
  const bool ok = capacities(d, o, file, diag);
  if (o.compact_arrays) compact_arrays(d);
  d.sub_descriptors = o.sub_descriptors;
  return ok && !diag.has_errors();
}

} // namespace fieldcodec::gen
