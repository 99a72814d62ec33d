// fieldcodec-gen — the configuration list of a DCF (docs/master.md, "Configuration list").
#include "config_list.hpp"

#include "readers.hpp"
#include "text.hpp"

#include <algorithm>
#include <bit>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace fieldcodec::gen {

namespace {

/// A chosen value of one entry: bytes and whether they are node-relative.
struct chosen {
  std::vector<std::uint8_t> bytes;
  bool node_relative = false;
  friend bool operator==(const chosen &, const chosen &) = default;
};

/// The bytes of `n` for type `t`; nothing for a type without a plain byte form.
std::optional<std::vector<std::uint8_t>> number_bytes(od::data_type t, const od::number &n) {
  std::uint64_t bits = 0;
  std::size_t size = od::fixed_size(t);
  if (t == od::data_type::real32) {
    bits = std::bit_cast<std::uint32_t>(static_cast<float>(n.to_double()));
  } else if (t == od::data_type::real64) {
    bits = std::bit_cast<std::uint64_t>(n.to_double());
  } else if (od::is_integer(t) || t == od::data_type::boolean) {
    if (n.kind == od::number_kind::signed_ || n.kind == od::number_kind::unsigned_) {
      bits = n.bits;
    } else {
      auto i = n.to_int64();
      if (!i) return std::nullopt;
      bits = static_cast<std::uint64_t>(i.value());
    }
  } else {
    return std::nullopt;
  }
  if (size == 0U || size > 8U) return std::nullopt;
  std::vector<std::uint8_t> out(size);
  for (std::size_t i = 0; i < size; ++i) out[i] = static_cast<std::uint8_t>(bits >> (8U * i));
  return out;
}

std::optional<chosen> value_of(const entry &e, bool parameter) {
  const od::number &n = parameter ? e.parameter_value : e.default_value;
  const std::string &text = parameter ? e.parameter_text : e.default_text;
  if (od::is_byte_string(e.type)) {
    if (text.empty()) return std::nullopt;
    return chosen{std::vector<std::uint8_t>(text.begin(), text.end()), false};
  }
  if (!n.has_value()) return std::nullopt;
  auto b = number_bytes(e.type, n);
  if (!b) return std::nullopt;
  return chosen{*b, parameter ? e.parameter_nodeid : e.default_nodeid};
}

/// The value the device should end up with: ParameterValue when given, else DefaultValue.
std::optional<chosen> final_value(const entry &e) {
  if (auto p = value_of(e, true)) return p;
  return value_of(e, false);
}

/// The entry (index, sub) of `d`, or nullptr.
const entry *find_entry(const dictionary &d, std::uint16_t index, std::uint8_t sub) {
  const auto it = std::lower_bound(d.entries.begin(), d.entries.end(), od::address{index, sub},
                                   [](const entry &e, const od::address &a) {
                                     return od::address{e.index, e.sub} < a;
                                   });
  if (it == d.entries.end() || it->index != index || it->sub != sub) return nullptr;
  return &*it;
}

std::string item_name(const dictionary &d, const entry &e) {
  const auto o = d.objects.find(e.index);
  if (e.object == od::object_code::var || o == d.objects.end() || o->second.name.empty()) {
    return e.name;
  }
  return o->second.name + ": " + e.name;
}

bool is_pdo_comm(std::uint16_t i) {
  return (i >= 0x1400U && i <= 0x15FFU) || (i >= 0x1800U && i <= 0x19FFU);
}
bool is_pdo_map(std::uint16_t i) {
  return (i >= 0x1600U && i <= 0x17FFU) || (i >= 0x1A00U && i <= 0x1BFFU);
}

class builder {
public:
  builder(const dictionary &d, config_values v, const std::string &file, diagnostics &diag)
      : d_(d), values_(v), file_(file), diag_(diag) {}

  config_list build() {
    config_list l;
    l.node_id = d_.node_id >= 1 && d_.node_id <= 127 ? static_cast<std::uint8_t>(d_.node_id) : 0;
    l.expected = identity();
    std::map<std::uint16_t, bool> pdo_changed; // communication index -> changed
    for (const entry &e : d_.entries) {
      if (wanted(e) && (is_pdo_comm(e.index) || is_pdo_map(e.index))) {
        pdo_changed[is_pdo_map(e.index) ? static_cast<std::uint16_t>(e.index - 0x200U) : e.index] =
            true;
      }
    }
    bool pdos_done = false;
    for (const entry &e : d_.entries) {
      if (e.index >= 0x1400U && e.index <= 0x1BFFU) {
        if (!pdos_done) {
          // RPDOs (1400h..) then TPDOs (1800h..), each in the CiA 301 sequence
          for (const auto &[comm, changed] : pdo_changed) {
            if (changed) pdo(l, comm);
          }
          pdos_done = true;
        }
        continue;
      }
      if (e.index == 0x1018U) continue; // the identity is checked, not written
      if (wanted(e)) add(l, e, *value(e));
    }
    if (!pdos_done) {
      for (const auto &[comm, changed] : pdo_changed) {
        if (changed) pdo(l, comm);
      }
    }
    return l;
  }

private:
  [[nodiscard]] const entry *find(std::uint16_t index, std::uint8_t sub) const {
    return find_entry(d_, index, sub);
  }

  /// The value the list writes for `e` in this mode.
  [[nodiscard]] std::optional<chosen> value(const entry &e) const {
    return values_ == config_values::parameter ? value_of(e, true) : value_of(e, false);
  }

  /// An entry the list writes: writable, a value, and (ParameterValue mode) a change.
  [[nodiscard]] bool wanted(const entry &e) const {
    if (e.index < 0x1000U || !od::writable(e.access)) return false;
    const auto v = value(e);
    if (!v) return false;
    if (values_ == config_values::default_) return true;
    const auto def = value_of(e, false);
    return !def || !(*def == *v);
  }

  void add(config_list &l, const entry &e, const chosen &v) const {
    config_list_item i;
    i.address = {e.index, e.sub};
    i.value = v.bytes;
    i.flags =
        static_cast<std::uint8_t>((v.node_relative ? master::config_flag::node_relative : 0U) |
                                  (od::readable(e.access) ? 0U : master::config_flag::no_verify));
    i.name = is_pdo_map(e.index) && e.sub != 0U ? mapping_name(e, v) : item_name(d_, e);
    l.items.push_back(std::move(i));
  }

  /// A PDO mapping entry is named by what it maps, not by its sub-object's name: an EDS often
  /// names 1601h sub 1 after its default content ("Controlword") while the DCF maps another
  /// object there. "RPDO 2 mapping: entry 1 = Target Position (607Ah sub 0, 32 bits)"; the object
  /// part is the address alone when the dictionary does not have it; "entry 3 = empty" for 0; a
  /// value that is no mapping (not 4 plain bytes) keeps the sub-object's name.
  [[nodiscard]] std::string mapping_name(const entry &e, const chosen &v) const {
    const auto o = d_.objects.find(e.index);
    std::string name =
        o != d_.objects.end() && !o->second.name.empty() ? o->second.name : hex(e.index, 4) + "h";
    if (v.node_relative || v.bytes.size() != 4U) return item_name(d_, e); // not a mapping value
    name += ": entry " + std::to_string(e.sub) + " = ";
    std::uint32_t m = 0;
    for (std::size_t i = 0; i < 4U; ++i) m |= std::uint32_t{v.bytes[i]} << (8U * i);
    if (m == 0U) return name + "empty";
    const auto index = static_cast<std::uint16_t>(m >> 16U);
    const auto sub = static_cast<std::uint8_t>(m >> 8U);
    const std::string where =
        hex(index, 4) + "h sub " + std::to_string(sub) + ", " + std::to_string(m & 0xFFU) + " bits";
    const entry *mapped = find(index, sub);
    if (mapped == nullptr) return name + where;
    return name + item_name(d_, *mapped) + " (" + where + ")";
  }

  [[nodiscard]] std::uint32_t identity_value(std::uint16_t index, std::uint8_t sub) const {
    const entry *e = find(index, sub);
    if (e == nullptr) return 0;
    const auto v = final_value(*e);
    if (!v || v->node_relative || v->bytes.size() != 4U) return 0;
    std::uint32_t r = 0;
    for (std::size_t i = 0; i < 4U; ++i) r |= std::uint32_t{v->bytes[i]} << (8U * i);
    return r;
  }
  [[nodiscard]] master::identity identity() const {
    return {identity_value(0x1000, 0), identity_value(0x1018, 1), identity_value(0x1018, 2),
            identity_value(0x1018, 3), identity_value(0x1018, 4)};
  }

  /// The CiA 301 sequence for the PDO with communication parameter `comm`.
  void pdo(config_list &l, std::uint16_t comm) {
    const auto map = static_cast<std::uint16_t>(comm + 0x200U);
    const char *kind = comm < 0x1800U ? "RPDO" : "TPDO";
    const int number = (comm & 0x1FFU) + 1;
    const entry *cob = find(comm, 1);
    // a plain value and a flag, not an optional: GCC 12 -O2 warns (maybe-uninitialized) about
    // copying the vector out of an optional here
    chosen cob_value;
    bool has_cob = false;
    if (cob != nullptr && od::writable(cob->access)) {
      if (auto v = final_value(*cob); v && v->bytes.size() == 4U) {
        cob_value.bytes = v->bytes;
        cob_value.node_relative = v->node_relative;
        has_cob = true;
      }
    }
    if (!has_cob) {
      diag_.warning(file_, cob != nullptr ? cob->line : 0, 1,
                    std::string(kind) + " " + std::to_string(number) +
                        ": no writable COB-ID value (sub 1): its parameters are written without "
                        "disabling the PDO first");
    }
    // 1. disable: the COB-ID with bit 31 (valid) set
    if (has_cob) {
      chosen off = cob_value;
      off.bytes[3] = static_cast<std::uint8_t>(off.bytes[3] | 0x80U);
      add(l, *cob, off);
    }
    // 2. the other communication parameters that change
    for (const entry &e : d_.entries) {
      if (e.index == comm && e.sub != 1U && e.sub != 0U && wanted(e)) add(l, e, *value(e));
    }
    // 3. the mapping: count 0, the entries, the count
    bool map_changed = false;
    for (const entry &e : d_.entries) {
      if (e.index == map && wanted(e)) map_changed = true;
    }
    if (map_changed) {
      const entry *count = find(map, 0);
      const auto count_value = count != nullptr ? final_value(*count) : std::nullopt;
      if (count == nullptr || !od::writable(count->access) || !count_value ||
          count_value->bytes.size() != 1U) {
        diag_.warning(file_, count != nullptr ? count->line : 0, 1,
                      std::string(kind) + " " + std::to_string(number) +
                          ": the mapping count (sub 0) is not writable or has no value: the "
                          "mapping is left out of the configuration list");
      } else {
        add(l, *count, chosen{{0}, false});
        const std::uint8_t n = count_value->bytes[0];
        for (std::uint8_t s = 1; s <= n && s != 0U; ++s) {
          const entry *m = find(map, s);
          const auto v = m != nullptr ? final_value(*m) : std::nullopt;
          if (m == nullptr || !v || !od::writable(m->access)) {
            diag_.warning(file_, m != nullptr ? m->line : count->line, 1,
                          std::string(kind) + " " + std::to_string(number) + ": mapping entry " +
                              std::to_string(s) + " has no writable value");
            continue;
          }
          add(l, *m, *v);
        }
        if (n != 0U) add(l, *count, *count_value); // a mapping left empty stays at 0
      }
    }
    // 4. enable (when the final COB-ID has bit 31 clear; otherwise step 1 left it disabled)
    if (has_cob && (cob_value.bytes[3] & 0x80U) == 0U) add(l, *cob, cob_value);
  }

  const dictionary &d_;
  config_values values_;
  const std::string &file_;
  diagnostics &diag_;
};

void append_hex_byte(std::string &o, std::uint8_t b) {
  o += "0x";
  o += hex(b, 2);
}

void append_bytes(std::string &o, const std::vector<std::uint8_t> &v, std::size_t per_line) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i != 0U) o += (i % per_line == 0U) ? ",\n    " : ", ";
    append_hex_byte(o, v[i]);
  }
}

/// The final value of (index, sub) as an unsigned number of `size` bytes; 0 when the entry is
/// absent or has no such value.
std::uint32_t unsigned_value(const dictionary &d, std::uint16_t index, std::uint8_t sub,
                             std::size_t size) {
  const entry *e = find_entry(d, index, sub);
  if (e == nullptr) return 0;
  const auto v = final_value(*e);
  if (!v || v->node_relative || v->bytes.size() != size) return 0;
  std::uint32_t r = 0;
  for (std::size_t i = 0; i < size; ++i) r |= std::uint32_t{v->bytes[i]} << (8U * i);
  return r;
}

/// The value of a DOMAIN sub-object as the master holds it: its UploadFile (the file a read of
/// it returns, relative to the DCF), else its ParameterValue / DefaultValue.
bool domain_value(const entry &e, const std::string &file, nmt_slave_row &row, diagnostics &diag) {
  for (const auto &[key, value] : e.other_keys) {
    if (key != "UploadFile") continue;
    const std::filesystem::path path =
        std::filesystem::path(file).parent_path() / std::filesystem::path(value);
    std::string bytes;
    if (const char *why = read_bytes(path.string(), bytes); why != nullptr) {
      diag.error(file, e.line, 1,
                 "1F22h sub " + std::to_string(e.sub) + ": UploadFile '" + value + "': " + why);
      return false;
    }
    row.concise_dcf.assign(bytes.begin(), bytes.end());
    row.dcf_source = value;
    return true;
  }
  const std::string &text =
      !e.parameter_text.str().empty() ? e.parameter_text.str() : e.default_text.str();
  row.concise_dcf.assign(text.begin(), text.end());
  if (!text.empty())
    row.dcf_source = e.parameter_text.str().empty() ? "DefaultValue" : "ParameterValue";
  return true;
}

/// The top of a generated master header, up to and inside namespace
/// fieldcodec::dictionaries::<stem>::<inner>.
std::string preamble(const dictionary &d, const std::string &what, const std::string &inner) {
  std::string o = "// Generated by fieldcodec-gen from " + d.source_name + ": " + what +
                  " (docs/master.md).\n// Do not edit.\n// clang-format off\n#pragma once\n\n";
  o += "#include <fieldcodec/master/config.hpp>\n\n#include <cstdint>\n#include <span>\n\n";
  o += "namespace fieldcodec::dictionaries::" + stem_identifier(d.stem) + "::" + inner + " {\n\n";
  // the library's master/, also when a dictionary is itself named "master"
  o += "namespace master = ::fieldcodec::master;\n\n";
  return o;
}

} // namespace

std::vector<nmt_slave_row> build_nmt_slaves(const dictionary &d, const std::string &file,
                                            diagnostics &diag) {
  std::vector<nmt_slave_row> rows;
  for (unsigned n = 1; n <= 127U; ++n) {
    const auto node = static_cast<std::uint8_t>(n);
    nmt_slave_row row;
    row.node = node;
    auto &o = row.objects;
    o.assignment = unsigned_value(d, 0x1F81, node, 4);
    if (o.assignment == 0U) continue;
    o.expected = {unsigned_value(d, 0x1F84, node, 4), unsigned_value(d, 0x1F85, node, 4),
                  unsigned_value(d, 0x1F86, node, 4), unsigned_value(d, 0x1F87, node, 4),
                  unsigned_value(d, 0x1F88, node, 4)};
    o.software_version = unsigned_value(d, 0x1F55, node, 4);
    o.configuration_date = unsigned_value(d, 0x1F26, node, 4);
    o.configuration_time = unsigned_value(d, 0x1F27, node, 4);
    o.restore_sub = static_cast<std::uint8_t>(unsigned_value(d, 0x1F8A, node, 1));
    // the consumer time: the master's 1016h entry that names this node
    for (const entry &e : d.entries) {
      if (e.index != 0x1016U || e.sub == 0U) continue;
      const std::uint32_t v = unsigned_value(d, 0x1016, e.sub, 4);
      if (((v >> 16U) & 0x7FU) == n && (v & 0xFFFFU) != 0U) {
        o.consumer_time_ms = static_cast<std::uint16_t>(v);
      }
    }
    if (const entry *e = find_entry(d, 0x1F22, node); e != nullptr) {
      if (!domain_value(*e, file, row, diag)) continue;
      if (!row.concise_dcf.empty()) {
        if (const auto c = master::check_concise_dcf(row.concise_dcf); !c) {
          diag.error(file, e->line, 1,
                     "1F22h sub " + std::to_string(n) + " (" + row.dcf_source +
                         "): not a concise DCF: " + std::string(to_string(c.error())));
          continue;
        }
      }
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string emit_nmt_slaves(const dictionary &d, const std::vector<nmt_slave_row> &rows) {
  std::string o = preamble(d, "the NMT slaves of a CiA 302 master", "slaves");
  o += "/// Per slave in node order: 1F81h, 1F84h..1F88h, 1F22h, the 1016h consumer time, 1F55h,\n"
       "/// 1F26h, 1F27h, 1F8Ah (0 or empty: not set).\n";
  if (rows.empty()) {
    o += "inline constexpr std::span<const master::nmt_slave> slaves{};\n";
  } else {
    o += "namespace detail {\n";
    for (const auto &r : rows) {
      if (r.concise_dcf.empty()) continue;
      o += "/// 1F22h sub " + std::to_string(r.node) + " (" + r.dcf_source + ")\n";
      o += "inline constexpr std::uint8_t dcf" + std::to_string(r.node) + "[] = {\n    ";
      append_bytes(o, r.concise_dcf, 12);
      o += "};\n";
    }
    o += "inline constexpr master::nmt_slave slaves[] = {\n";
    for (const auto &r : rows) {
      const auto &s = r.objects;
      o += "    {" + std::to_string(r.node) + ", {0x" + hex(s.assignment, 8) + "U, {0x" +
           hex(s.expected.device_type, 8) + "U, 0x" + hex(s.expected.vendor_id, 8) + "U, 0x" +
           hex(s.expected.product_code, 8) + "U, 0x" + hex(s.expected.revision, 8) + "U, 0x" +
           hex(s.expected.serial, 8) + "U}, ";
      if (r.concise_dcf.empty()) {
        o += "{}";
      } else {
        o += "detail::dcf";
        o += std::to_string(r.node);
      }
      o += ", " + std::to_string(s.consumer_time_ms) + ", 0x" + hex(s.software_version, 8) +
           "U, 0x" + hex(s.configuration_date, 8) + "U, 0x" + hex(s.configuration_time, 8) + "U, " +
           std::to_string(s.restore_sub) + "}},\n";
    }
    o += "};\n} // namespace detail\n\n";
    o += "inline constexpr std::span<const master::nmt_slave> slaves{detail::slaves};\n";
  }
  o += "\n} // namespace fieldcodec::dictionaries::" + stem_identifier(d.stem) +
       "::slaves\n// clang-format on\n";
  return o;
}

config_list build_config_list(const dictionary &d, config_values values, const std::string &file,
                              diagnostics &diag) {
  return builder(d, values, file, diag).build();
}

std::string emit_config_list(const dictionary &d, const config_list &l) {
  const std::string ns = stem_identifier(d.stem);
  std::string o = preamble(d, "the configuration list", "config");
  o += "/// The DCF's node-ID ([DeviceComissioning] NodeID; 0: none).\n";
  o += "inline constexpr std::uint8_t node_id = " + std::to_string(l.node_id) + ";\n\n";
  o += "/// 1000h and 1018h sub 1..4 to compare at boot (0: not checked).\n";
  o += "inline constexpr master::identity identity{0x" + hex(l.expected.device_type, 8) + "U, 0x" +
       hex(l.expected.vendor_id, 8) + "U, 0x" + hex(l.expected.product_code, 8) +
       "U,\n                                            0x" + hex(l.expected.revision, 8) +
       "U, 0x" + hex(l.expected.serial, 8) + "U};\n\n";
  if (l.items.empty()) {
    o += "/// Nothing to write: the DCF's values are the EDS defaults.\n";
    o += "inline constexpr std::span<const master::config_item> items{};\n\n";
  } else {
    o += "namespace detail {\n";
    for (std::size_t i = 0; i < l.items.size(); ++i) {
      if (l.items[i].value.empty()) continue;
      o += "inline constexpr std::uint8_t v" + std::to_string(i) + "[] = {";
      append_bytes(o, l.items[i].value, 12);
      o += "};\n";
    }
    o += "inline constexpr master::config_item items[] = {\n";
    for (std::size_t i = 0; i < l.items.size(); ++i) {
      const auto &it = l.items[i];
      o += "    {{0x" + hex(it.address.index, 4) + ", 0x" + hex(it.address.sub, 2) + "}, ";
      // appended piece by piece: GCC 12 -O2 warns (restrict) about "v" + std::to_string(i) here
      if (it.value.empty()) {
        o += "{}";
      } else {
        o += 'v';
        o += std::to_string(i);
      }
      o += ", ";
      std::string flags;
      if ((it.flags & master::config_flag::node_relative) != 0U) {
        flags = "master::config_flag::node_relative";
      }
      if ((it.flags & master::config_flag::no_verify) != 0U) {
        flags += std::string(flags.empty() ? "" : " | ") + "master::config_flag::no_verify";
      }
      o += flags.empty() ? "0" : flags;
      o += ", " + cpp_string(it.name) + "},\n";
    }
    o += "};\n} // namespace detail\n\n";
    o += "/// The SDO downloads in order.\n";
    o += "inline constexpr std::span<const master::config_item> items{detail::items};\n\n";
  }
  o += "inline constexpr master::configuration configuration{items, identity, node_id};\n";
  // the concise DCF for the DCF's node-ID
  std::vector<master::config_item> view;
  for (const auto &it : l.items) {
    view.push_back({it.address, std::span<const std::uint8_t>(it.value), it.flags, it.name});
  }
  const master::configuration c{view, l.expected, l.node_id};
  std::vector<std::uint8_t> concise(master::concise_dcf_size(c));
  const auto n = master::write_concise_dcf(c, l.node_id, concise);
  o += "\n";
  if (n) {
    o += "/// The concise DCF (object 1F22h format) for node " + std::to_string(l.node_id) +
         ": count, then index, sub, size, data.\n";
    o += "inline constexpr std::uint8_t concise_dcf[] = {\n    ";
    append_bytes(o, concise, 12);
    o += "};\n";
  } else {
    o += "// No concise DCF: node-relative values and the DCF names no node-ID; build one at run\n"
         "// time with master::write_concise_dcf(configuration, node, buffer).\n";
  }
  o += "\n} // namespace fieldcodec::dictionaries::" + ns + "::config\n// clang-format on\n";
  return o;
}

} // namespace fieldcodec::gen
