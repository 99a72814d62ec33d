// fieldcodec-gen — the PDO layouts header (--pdo-header): one compile-time layout per PDO of the
// dictionary, made by canopen::pdo::make_static_mapping and so checked by the compiler against
// the generated dictionary (docs/generator.md, "PDO layouts").
#include "options.hpp"
#include "readers.hpp"
#include "text.hpp"

#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace fieldcodec::gen {

namespace {

namespace pdo = canopen::pdo;

struct layout {
  bool tx = false;
  std::uint16_t index = 0;
  std::string name;
  std::string note; ///< Sm, fixed, mandatory (ESI)
  std::vector<pdo::mapping_entry> entries;
  std::size_t max_bits = 0;
  int line = 0;
};

// The dictionary as od::entry values, for pdo::check_mapping (the library's own rules). The
// entries point into `packed` (their packed columns: a byte string's capacity), which is sized
// once, before the first entry is made, and never grows.
struct od_table {
  std::vector<char> packed;
  std::vector<od::entry> entries;
};
od_table od_entries(const dictionary &d) {
  std::vector<od::entry_spec> specs;
  specs.reserve(d.entries.size());
  for (const auto &e : d.entries) {
    for (std::uint16_t k = 0; k < e.count; ++k) {
      od::entry_spec o;
      o.index = e.index;
      o.sub = static_cast<std::uint8_t>(e.sub + k);
      o.object = e.object;
      o.type = e.type;
      o.access_type = e.access;
      o.pdo = e.pdo;
      o.size = e.size;
      specs.push_back(o);
    }
  }
  od_table t;
  t.packed.resize(od::packed_size(std::span<const od::entry_spec>(specs)));
  t.entries.reserve(specs.size());
  std::size_t at = 0;
  for (const od::entry_spec &s : specs) {
    const auto n = od::pack(s, std::span<char>(t.packed).subspan(at));
    t.entries.push_back(od::make_entry(s, t.packed.data() + at));
    if (n) at += n.value(); // never fails: `packed` holds every spec's bytes
  }
  return t;
}

const entry *find(const dictionary &d, std::uint16_t index, std::uint8_t sub) {
  const auto it =
      std::lower_bound(d.entries.begin(), d.entries.end(), std::pair{index, sub},
                       [](const entry &e, const std::pair<std::uint16_t, std::uint8_t> &k) {
                         return e.index != k.first ? e.index < k.first : e.sub < k.second;
                       });
  return it != d.entries.end() && it->index == index && it->sub == sub ? &*it : nullptr;
}

// The PDOs of the dictionary: an ESI's PDO descriptions, else the default values of the
// mapping objects (1600h-17FFh, 1A00h-1BFFh) with 32-bit entries.
std::vector<layout> layouts(const dictionary &d, std::vector<std::string> &skipped) {
  std::vector<layout> out;
  const bool coe = d.profile == bus_profile::ethercat || d.objects.count(0x1C12) != 0U ||
                   d.objects.count(0x1C13) != 0U;
  if (d.ethercat) {
    for (const esi_pdo &p : d.ethercat->pdos) {
      layout l;
      l.tx = p.tx;
      l.index = p.index;
      l.name = p.name;
      l.line = p.line;
      if (p.sm >= 0) l.note += "Sm " + std::to_string(p.sm);
      if (p.fixed) l.note += std::string(l.note.empty() ? "" : ", ") + "fixed";
      if (p.mandatory) l.note += std::string(l.note.empty() ? "" : ", ") + "mandatory";
      for (const auto &e : p.entries) l.entries.push_back({e.index, e.sub, e.bits});
      std::size_t bits = 0;
      for (const auto &e : l.entries) bits += e.bits;
      l.max_bits = (bits + 7U) / 8U * 8U;
      if (p.sm >= 0 && static_cast<std::size_t>(p.sm) < d.ethercat->sync_managers.size()) {
        const esi_sync_manager &sm = d.ethercat->sync_managers[static_cast<std::size_t>(p.sm)];
        if (sm.has_default_size && sm.default_size != 0U) l.max_bits = 8U * sm.default_size;
      }
      out.push_back(std::move(l));
    }
    return out;
  }
  for (const auto &[index, info] : d.objects) {
    const bool rx = index >= 0x1600U && index <= 0x17FFU;
    const bool tx = index >= 0x1A00U && index <= 0x1BFFU;
    if (!rx && !tx) continue;
    const entry *n = find(d, index, 0);
    const auto count =
        n != nullptr ? n->default_value.to_uint64() : result<std::uint64_t>(errc::unknown_object);
    if (n == nullptr || !count) {
      skipped.push_back("0x" + hex(index, 4) + ": no default for sub-index 0");
      continue;
    }
    layout l;
    l.tx = tx;
    l.index = index;
    l.name = info.name;
    l.line = info.line;
    l.max_bits = coe ? 8U * 1024U : pdo::can_max_bits;
    bool ok = true;
    for (std::uint64_t s = 1; s <= count.value() && s <= 0xFFU; ++s) {
      const entry *m = find(d, index, static_cast<std::uint8_t>(s));
      const auto v =
          m != nullptr ? m->default_value.to_uint64() : result<std::uint64_t>(errc::unknown_object);
      if (m == nullptr || !v || m->type != od::data_type::unsigned32) {
        skipped.push_back("0x" + hex(index, 4) + ": sub-index " + std::to_string(s) +
                          (m == nullptr ? " missing"
                           : m->type != od::data_type::unsigned32
                               ? " is not an UNSIGNED32 mapping entry (POWERLINK maps with 64 bits)"
                               : " has no default"));
        ok = false;
        break;
      }
      l.entries.push_back(pdo::mapping_entry::from_u32(static_cast<std::uint32_t>(v.value())));
    }
    if (ok) out.push_back(std::move(l));
  }
  return out;
}

} // namespace

std::string emit_pdo_layouts(const dictionary &d, const std::string &file, diagnostics &diag) {
  std::vector<std::string> skipped;
  const std::vector<layout> list = layouts(d, skipped);
  const od_table table = od_entries(d);
  const od::dictionary dict{std::span<const od::entry>(table.entries)};
  std::string o;
  o += "// Generated from ";
  o += valid_utf8(d.source_name) ? d.source_name : cpp_string(d.source_name);
  o += " by fieldcodec-gen --pdo-header — do not edit.\n";
  o += "// The PDO layouts of the dictionary fieldcodec::dictionaries::" + d.stem +
       ", each made by\n// canopen::pdo::make_static_mapping: with the dictionary, checked by the "
       "compiler against\n// it (objects, PDO mapping, access, lengths) and read with each "
       "object's signedness; a\n// layout that fails those checks is checked for lengths only "
       "(the comment says why).\n";
  // Like the dictionary header: the generator's layout, not clang-format's (a long name in a
  // title or a long entry list stays on its line), so a committed header passes the project's
  // formatting check as written.
  o += "// clang-format off\n#pragma once\n\n#include <fieldcodec/canopen/pdo.hpp>\n#include "
       "<fieldcodec/dictionaries/" +
       d.stem + ".hpp>\n\nnamespace fieldcodec::dictionaries::" + d.stem + "::pdos {\n\n";
  for (const auto &s : skipped) o += "// not a layout: " + s + "\n";
  if (!skipped.empty()) o += "\n";
  for (const layout &l : list) {
    const std::string id = std::string(l.tx ? "txpdo_" : "rxpdo_") + to_lower(hex(l.index, 4));
    std::size_t bits = 0;
    for (const auto &e : l.entries) bits += e.bits;
    std::string title = "// " + std::string(l.tx ? "TxPDO" : "RxPDO") + " 0x" + hex(l.index, 4);
    if (!l.name.empty()) title += " \"" + l.name + "\"";
    if (!l.note.empty()) title += " (" + l.note + ")";
    title += ": " + std::to_string(l.entries.size()) +
             (l.entries.size() == 1U ? " entry, " : " entries, ") + std::to_string(bits) + " bits";
    for (auto &c : title) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    o += title + "\n";
    if (l.entries.empty()) {
      o += "// (maps nothing: no layout)\n\n";
      continue;
    }
    if (l.entries.size() > pdo::max_entries) {
      diag.warning(file, l.line, 0,
                   std::string(l.tx ? "TxPDO" : "RxPDO") + " 0x" + hex(l.index, 4) + " has " +
                       std::to_string(l.entries.size()) + " entries; a compile-time layout holds " +
                       std::to_string(pdo::max_entries) + " (CiA 301's limit): none is written");
      o += "// (more than " + std::to_string(pdo::max_entries) +
           " entries: no compile-time layout)\n\n";
      continue;
    }
    o += "inline constexpr canopen::pdo::mapping_entry " + id + "_entries[]{";
    for (std::size_t i = 0; i < l.entries.size(); ++i) {
      const auto &e = l.entries[i];
      o += (i == 0U ? "" : ", ");
      o += "{0x" + hex(e.index, 4) + ", " + std::to_string(e.sub) + ", " + std::to_string(e.bits) +
           "}";
    }
    o += "};\n";
    const auto r = pdo::check_mapping(dict, l.tx ? pdo::direction::tpdo : pdo::direction::rpdo,
                                      std::span<const pdo::mapping_entry>(l.entries), l.max_bits);
    const std::string max = std::to_string(l.max_bits);
    if (r.ok()) {
      o += "inline constexpr auto " + id +
           " = canopen::pdo::make_static_mapping(\n    dictionary, " +
           "canopen::pdo::direction::" + (l.tx ? "tpdo" : "rpdo") + ", " + id + "_entries, " + max +
           ");\n\n";
      continue;
    }
    const auto &bad = l.entries[std::min(r.entry, l.entries.size() - 1U)];
    const std::string why = "entry " + std::to_string(r.entry + 1U) + " (0x" + hex(bad.index, 4) +
                            ":" + hex(bad.sub, 2) + ", " + std::to_string(bad.bits) +
                            " bits): " + std::string(pdo::to_string(r.problem));
    diag.warning(file, l.line, 0,
                 std::string(l.tx ? "TxPDO" : "RxPDO") + " 0x" + hex(l.index, 4) +
                     " fails the dictionary's checks, " + why +
                     "; its layout is checked for lengths only");
    o += "// not checked against the dictionary: " + why + "\n";
    o += "inline constexpr auto " + id + " = canopen::pdo::make_static_mapping(" + id +
         "_entries, " + max + ");\n\n";
  }
  o += "} // namespace fieldcodec::dictionaries::" + d.stem + "::pdos\n// clang-format on\n";
  return o;
}

} // namespace fieldcodec::gen
