// fieldcodec-gen — ESI reader: EtherCAT Slave Information (ETG.2000 EtherCATInfo) into the
// model the EDS reader fills, plus the device's PDOs, sync managers and mailbox
// (docs/generator.md, "ESI").
#include "esi_tables.hpp"
#include "readers.hpp"
#include "text.hpp"
#include "xml.hpp"
#include "xml_values.hpp"

#include <fieldcodec/core/ascii.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fieldcodec::gen {

namespace {

// One sub-object of an object, flattened from its data type.
struct flat_sub {
  std::uint8_t sub = 0;
  std::string name;
  std::string type;                   // the type's name
  const xml::element *item = nullptr; // the DataType SubItem (access, PDO mapping)
  bool element_of_array = false;
};

struct data_type_def {
  const xml::element *el = nullptr;
  std::string base;       // BaseType
  std::uint32_t bits = 0; // BitSize
  bool array = false;
  std::uint32_t lbound = 0;
  std::uint32_t elements = 0;
  std::vector<const xml::element *> items; // SubItem
};

class esi_reader {
public:
  esi_reader(const std::string &file, diagnostics &diag, const std::string &selector)
      : file_(file), diag_(diag), selector_(selector) {}

  std::optional<dictionary> read(std::string_view bytes) {
    auto doc = xml::parse(bytes, file_, diag_);
    if (!doc) return std::nullopt;
    const xml::element &root = doc->root;
    if (root.local == "ISO15745ProfileContainer") return read_xdd_document(*doc, file_, diag_);
    if (root.local != "EtherCATInfo") {
      error(root.at, "expected the root element <EtherCATInfo> of an ESI, got <" +
                         std::string(root.name) + ">");
      return std::nullopt;
    }
    esi_device dev;
    if (const xml::element *v = root.find_child("Vendor")) {
      if (const xml::element *id = v->find_child("Id")) {
        dev.vendor_id = number32(*id, "vendor Id");
      } else {
        warning(v->at, "<Vendor> without <Id>; vendor ID 0");
      }
      if (const xml::element *n = name_of(*v)) dev.vendor_name = trimmed(n->text);
    } else {
      warning(root.at, "no <Vendor>; vendor ID 0");
    }
    const xml::element *descriptions = root.find_child("Descriptions");
    const xml::element *devices =
        descriptions != nullptr ? descriptions->find_child("Devices") : nullptr;
    std::vector<const xml::element *> list;
    if (devices != nullptr) list = devices->children_named("Device");
    if (list.empty()) {
      error(root.at, "no <Descriptions><Devices><Device> in the ESI");
      return std::nullopt;
    }
    const xml::element *d = choose(list);
    if (d == nullptr) return std::nullopt;
    if (descriptions != nullptr) groups_ = descriptions->find_child("Groups");
    device(*d, dev);
    if (diag_.has_errors()) return std::nullopt;
    complete_from_pdos(dev);
    report_summaries();
    if (diag_.has_errors()) return std::nullopt;
    dict_.profile = bus_profile::ethercat;
    dict_.ethercat = std::move(dev);
    check_pdo_pairs(dict_, file_, diag_);
    const auto by_address = [](const entry &a, const entry &b) {
      return a.index != b.index ? a.index < b.index : a.sub < b.sub;
    };
    std::stable_sort(dict_.entries.begin(), dict_.entries.end(), by_address);
    if (diag_.has_errors()) return std::nullopt;
    return std::move(dict_);
  }

private:
  // ---- diagnostics ----------------------------------------------------------------------------
  void error(xml::position at, const std::string &msg) {
    diag_.error(file_, at.line, at.column, msg);
  }
  void warning(xml::position at, const std::string &msg) {
    diag_.warning(file_, at.line, at.column, msg);
  }
  void not_kept(const xml::element &e, const char *why = nullptr) {
    auto &n = dropped_[std::string(e.local)];
    if (n.count++ == 0) {
      n.at = e.at;
      n.why = why != nullptr ? why : "";
    }
  }
  void count(std::map<std::string, std::pair<std::size_t, xml::position>> &m,
             const std::string &what, xml::position at) {
    auto &[n, where] = m[what];
    if (n++ == 0) where = at;
  }
  void report_summaries() {
    for (const auto &[name, d] : dropped_) {
      warning(d.at, "<" + name + "> is not kept" + (d.why.empty() ? "" : " (" + d.why + ")") +
                        (d.count > 1 ? " (" + std::to_string(d.count) + " elements)" : ""));
    }
    for (const auto &[name, u] : nonstandard_) {
      warning(u.second, "data type " + name + " (" + std::to_string(u.first) +
                            (u.first == 1 ? " use" : " uses") +
                            ") is no ETG.2000 name; read as the integer of its width");
    }
    for (const auto &[name, u] : sm_attributes_) {
      warning(u.second, "attribute " + name + " of <Sm> is not kept (" + std::to_string(u.first) +
                            (u.first == 1 ? " use)" : " uses)"));
    }
    for (const auto &[name, u] : bit_fields_) {
      warning(u.second, "data type " + name + " of " + std::to_string(u.first) +
                            (u.first == 1 ? " entry" : " entries") +
                            " has no CiA 301 type; kept as DOMAIN with its ETG.1000.6 code");
    }
    if (!languages_.empty()) {
      std::string list;
      for (const auto &l : languages_) list += (list.empty() ? "" : ", ") + l;
      warning(languages_at_, "names in the languages " + list +
                                 " are not kept (the names are those of LcId 1033, English)");
    }
  }

  // ---- small readers --------------------------------------------------------------------------
  static std::string trimmed(std::string_view s) {
    std::size_t b = 0;
    std::size_t e = s.size();
    while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\n' || s[b] == '\r')) ++b;
    while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\n' || s[e - 1] == '\r')) {
      --e;
    }
    return std::string(s.substr(b, e - b));
  }

  // An unsigned number ("#x1A00", "1234") in an element's text or an attribute; `ok` false
  // after an error.
  std::uint64_t number(std::string_view text, xml::position at, const std::string &what,
                       std::uint64_t max, bool &ok) {
    const std::string t = trimmed(text);
    const int_parse p = parse_int(t, int_syntax::xml);
    const auto v = p.value.to_uint64();
    if (!p.ok || !v || v.value() > max) {
      error(at, "expected " + what + " (a number 0.." + std::to_string(max) +
                    ", decimal or #x hex), got \"" + t + "\"");
      ok = false;
      return 0;
    }
    return v.value();
  }
  std::uint32_t number32(const xml::element &e, const std::string &what) {
    bool ok = true;
    return static_cast<std::uint32_t>(
        number(e.text, e.text_at.line != 0 ? e.text_at : e.at, what, 0xFFFF'FFFFU, ok));
  }
  std::uint32_t attribute32(const xml::attribute &a, const std::string &what) {
    bool ok = true;
    return static_cast<std::uint32_t>(number(a.value, a.value_at, what, 0xFFFF'FFFFU, ok));
  }

  // <Name LcId="1033">…</Name>: the English one, else the first.
  const xml::element *name_of(const xml::element &parent) {
    std::vector<std::string> others;
    const xml::element *n = pick_label(parent, "1033", "Name", "LcId", others);
    for (const auto &l : others) {
      if (std::find(languages_.begin(), languages_.end(), l) == languages_.end()) {
        if (languages_.empty()) languages_at_ = parent.at;
        languages_.push_back(l);
      }
    }
    return n;
  }

  static bool true_attribute(const xml::element &e, std::string_view name) {
    const xml::attribute *a = e.find_attribute(name);
    return a != nullptr && (a->value == "true" || a->value == "1");
  }

  // ---- the device -----------------------------------------------------------------------------
  // Its description for the list of devices: name, product code, revision, line.
  std::string describe(const xml::element &d) {
    std::string s;
    const xml::element *type = d.find_child("Type");
    std::string name = type != nullptr ? trimmed(type->text) : std::string("?");
    s += "'" + name + "'";
    if (type != nullptr) {
      const xml::attribute *pc = type->find_attribute("ProductCode");
      const xml::attribute *rev = type->find_attribute("RevisionNo");
      s += " (product code " + (pc != nullptr ? pc->value : std::string("-")) + ", revision " +
           (rev != nullptr ? rev->value : std::string("-")) + ", line " +
           std::to_string(d.at.line) + ")";
    }
    return s;
  }

  // The device the selector names (--device): its Type text or Name, or "<product code>" or
  // "<product code>:<revision>" (decimal, 0x… or #x…).
  const xml::element *choose(const std::vector<const xml::element *> &list) {
    if (selector_.empty()) {
      if (list.size() == 1U) return list.front();
      std::string names;
      for (const xml::element *d : list) names += "\n  " + describe(*d);
      error(list.front()->at, "the ESI describes " + std::to_string(list.size()) +
                                  " devices; choose one with --device NAME, --device "
                                  "PRODUCTCODE or --device PRODUCTCODE:REVISION:" +
                                  names);
      return nullptr;
    }
    const auto colon = selector_.find(':');
    const int_parse code = parse_int(selector_.substr(0, colon), int_syntax::xml);
    const int_parse rev = colon == std::string::npos
                              ? int_parse{}
                              : parse_int(selector_.substr(colon + 1U), int_syntax::xml);
    std::vector<const xml::element *> hits;
    for (const xml::element *d : list) {
      const xml::element *type = d->find_child("Type");
      if (type == nullptr) continue;
      bool by_number = false;
      if (code.ok && (colon == std::string::npos || rev.ok)) {
        const xml::attribute *pc = type->find_attribute("ProductCode");
        const xml::attribute *rn = type->find_attribute("RevisionNo");
        const int_parse p = pc != nullptr ? parse_int(pc->value, int_syntax::xml) : int_parse{};
        const int_parse r = rn != nullptr ? parse_int(rn->value, int_syntax::xml) : int_parse{};
        by_number =
            p.ok && p.value.to_uint64() == code.value.to_uint64() &&
            (colon == std::string::npos || (r.ok && r.value.to_uint64() == rev.value.to_uint64()));
      }
      bool by_name = trimmed(type->text) == selector_;
      for (const xml::element *n : d->children_named("Name")) {
        if (trimmed(n->text) == selector_) by_name = true;
      }
      if (by_number || by_name) hits.push_back(d);
    }
    if (hits.size() == 1U) return hits.front();
    std::string names;
    for (const xml::element *d : hits.empty() ? list : hits) names += "\n  " + describe(*d);
    error(list.front()->at,
          hits.empty() ? "no device of the ESI is '" + selector_ + "'; it describes:" + names
                       : std::to_string(hits.size()) + " devices of the ESI are '" + selector_ +
                             "' (add the revision: --device PRODUCTCODE:REVISION):" + names);
    return nullptr;
  }

  void device(const xml::element &d, esi_device &dev) {
    dev.line = d.at.line;
    if (const xml::attribute *p = d.find_attribute("Physics")) dev.physics = p->value;
    for (const auto &c : d.children) {
      if (c.local == "Type") {
        dev.type = trimmed(c.text);
        if (const xml::attribute *a = c.find_attribute("ProductCode")) {
          dev.product_code = attribute32(*a, "ProductCode");
        }
        if (const xml::attribute *a = c.find_attribute("RevisionNo")) {
          dev.revision = attribute32(*a, "RevisionNo");
        }
      } else if (c.local == "Name") {
        continue; // below, by language
      } else if (c.local == "GroupType") {
        dev.group = trimmed(c.text);
      } else if (c.local == "Profile") {
        if (dev.profile_no != 0U || dictionary_ != nullptr) {
          not_kept(c, "a device's second profile");
          continue;
        }
        profile(c, dev);
      } else if (c.local == "Fmmu") {
        dev.fmmu.push_back(trimmed(c.text));
      } else if (c.local == "Sm") {
        sync_manager(c, dev);
      } else if (c.local == "RxPdo" || c.local == "TxPdo") {
        pdo(c, dev);
      } else if (c.local == "Mailbox") {
        mailbox(c, dev);
      } else if (c.local == "Eeprom") {
        eeprom(c, dev);
      } else if (c.local == "Slots" || c.local == "Modules") {
        not_kept(c, "modular devices: the modules' PDOs and objects are not read");
      } else {
        not_kept(c);
      }
    }
    if (const xml::element *n = name_of(d)) dev.name = trimmed(n->text);
    if (groups_ != nullptr && !dev.group.empty()) {
      for (const xml::element *g : groups_->children_named("Group")) {
        const xml::element *t = g->find_child("Type");
        if (t != nullptr && trimmed(t->text) == dev.group) {
          if (const xml::element *n = name_of(*g)) dev.group_name = trimmed(n->text);
        }
      }
    }
    // the CiA 306 [DeviceInfo] keys of what the ESI says
    dict_.device_info.emplace_back("VendorName", dev.vendor_name);
    dict_.device_info.emplace_back("VendorNumber", "0x" + hex(dev.vendor_id, 8));
    dict_.device_info.emplace_back("ProductName", dev.name);
    dict_.device_info.emplace_back("ProductNumber", "0x" + hex(dev.product_code, 8));
    dict_.device_info.emplace_back("RevisionNumber", "0x" + hex(dev.revision, 8));
    dict_.device_info.emplace_back("OrderCode", dev.type);
    if (dictionary_ != nullptr) read_dictionary(*dictionary_);
  }

  void profile(const xml::element &p, esi_device &dev) {
    for (const auto &c : p.children) {
      if (c.local == "ProfileNo") {
        dev.profile_no = number32(c, "ProfileNo");
      } else if (c.local == "AddInfo") {
        dev.add_info = trimmed(c.text);
      } else if (c.local == "Dictionary") {
        dictionary_ = &c;
      } else if (c.local == "DictionaryFile") {
        error(c.at, "<DictionaryFile> (a dictionary in another file) is not supported: "
                    "merge it into the ESI");
      } else {
        not_kept(c);
      }
    }
  }

  void sync_manager(const xml::element &c, esi_device &dev) {
    esi_sync_manager sm;
    sm.type = trimmed(c.text);
    sm.line = c.at.line;
    for (const auto &a : c.attributes) {
      if (a.local == "StartAddress") {
        sm.start = static_cast<std::uint16_t>(
            std::min<std::uint32_t>(attribute32(a, "StartAddress"), 0xFFFF));
      } else if (a.local == "DefaultSize") {
        sm.default_size = static_cast<std::uint16_t>(
            std::min<std::uint32_t>(attribute32(a, "DefaultSize"), 0xFFFF));
        sm.has_default_size = true;
      } else if (a.local == "ControlByte") {
        sm.control = static_cast<std::uint8_t>(attribute32(a, "ControlByte") & 0xFFU);
      } else if (a.local == "Enable") {
        sm.enable = a.value == "1" || a.value == "true";
      } else {
        count(sm_attributes_, std::string(a.local), a.at);
      }
    }
    dev.sync_managers.push_back(std::move(sm));
  }

  void pdo(const xml::element &c, esi_device &dev) {
    esi_pdo p;
    p.tx = c.local == "TxPdo";
    p.line = c.at.line;
    p.fixed = true_attribute(c, "Fixed");
    p.mandatory = true_attribute(c, "Mandatory");
    for (const auto &a : c.attributes) {
      if (a.local == "Sm") {
        p.sm = static_cast<int>(std::min<std::uint32_t>(attribute32(a, "Sm"), 255));
      } else if (a.local != "Fixed" && a.local != "Mandatory") {
        p.other_attributes.emplace_back(std::string(a.local), a.value);
      }
    }
    bool have_index = false;
    for (const auto &x : c.children) {
      if (x.local == "Index") {
        p.index =
            static_cast<std::uint16_t>(std::min<std::uint32_t>(number32(x, "PDO Index"), 0xFFFF));
        have_index = true;
      } else if (x.local == "Name") {
        continue;
      } else if (x.local == "Exclude") {
        p.excludes.push_back(static_cast<std::uint16_t>(number32(x, "Exclude") & 0xFFFFU));
      } else if (x.local == "Entry") {
        esi_pdo_entry e;
        e.line = x.at.line;
        bool ok = true;
        for (const auto &f : x.children) {
          if (f.local == "Index") {
            e.index =
                static_cast<std::uint16_t>(number(f.text, f.text_at, "Entry Index", 0xFFFF, ok));
          } else if (f.local == "SubIndex") {
            e.sub =
                static_cast<std::uint8_t>(number(f.text, f.text_at, "Entry SubIndex", 0xFF, ok));
          } else if (f.local == "BitLen") {
            e.bits = static_cast<std::uint8_t>(number(f.text, f.text_at, "Entry BitLen", 0xFF, ok));
          } else if (f.local == "Name") {
            e.name = trimmed(f.text);
          } else if (f.local == "DataType") {
            e.data_type = trimmed(f.text);
          } else {
            not_kept(f);
          }
        }
        if (e.bits == 0U && ok) {
          error(x.at, "PDO entry without BitLen (or BitLen 0) in " + std::string(c.local) + " 0x" +
                          hex(p.index, 4));
        }
        p.entries.push_back(std::move(e));
      } else {
        not_kept(x);
      }
    }
    if (const xml::element *n = name_of(c)) p.name = trimmed(n->text);
    if (!have_index) {
      error(c.at, "<" + std::string(c.local) + "> without <Index>");
      return;
    }
    const bool rx_range = p.index >= 0x1600U && p.index <= 0x17FFU;
    const bool tx_range = p.index >= 0x1A00U && p.index <= 0x1BFFU;
    if ((p.tx && !tx_range) || (!p.tx && !rx_range)) {
      warning(c.at,
              std::string(c.local) + " 0x" + hex(p.index, 4) + " is outside the " +
                  (p.tx ? "TxPDO mapping range 1A00h-1BFFh" : "RxPDO mapping range 1600h-17FFh"));
    }
    for (const auto &other : dev.pdos) {
      if (other.index == p.index) {
        error(c.at, "duplicate PDO 0x" + hex(p.index, 4) + " (first at line " +
                        std::to_string(other.line) + ")");
        return;
      }
    }
    dev.pdos.push_back(std::move(p));
  }

  void mailbox(const xml::element &m, esi_device &dev) {
    dev.mailbox = true;
    dev.data_link_layer = true_attribute(m, "DataLinkLayer");
    for (const auto &c : m.children) {
      dev.protocols.emplace_back(c.local);
      if (c.local == "CoE") {
        for (const auto &a : c.attributes) dev.coe.emplace_back(std::string(a.local), a.value);
        for (const auto &x : c.children) not_kept(x);
      }
    }
  }

  void eeprom(const xml::element &e, esi_device &dev) {
    dev.eeprom_line = e.at.line;
    for (const auto &c : e.children) {
      if (c.local == "ByteSize") {
        dev.eeprom_bytes = number32(c, "Eeprom ByteSize");
      } else if (c.local == "ConfigData") {
        dev.config_data = trimmed(c.text);
      } else if (c.local == "BootStrap") {
        dev.bootstrap = trimmed(c.text);
      } else {
        not_kept(c);
      }
    }
  }

  // ---- the dictionary -------------------------------------------------------------------------
  void read_dictionary(const xml::element &dict) {
    if (const xml::element *types = dict.find_child("DataTypes")) {
      for (const xml::element *t : types->children_named("DataType")) data_type(*t);
    }
    const xml::element *objects = dict.find_child("Objects");
    if (objects == nullptr) {
      warning(dict.at, "<Dictionary> without <Objects>");
      return;
    }
    for (const auto &o : objects->children) {
      if (o.local != "Object") {
        not_kept(o);
        continue;
      }
      if (diag_.too_many()) return;
      object(o);
    }
  }

  void data_type(const xml::element &t) {
    data_type_def d;
    d.el = &t;
    std::string name;
    for (const auto &c : t.children) {
      if (c.local == "Name") {
        name = trimmed(c.text);
      } else if (c.local == "BaseType") {
        d.base = trimmed(c.text);
      } else if (c.local == "BitSize") {
        d.bits = number32(c, "BitSize");
      } else if (c.local == "ArrayInfo") {
        d.array = true;
        for (const auto &a : c.children) {
          if (a.local == "LBound") d.lbound = number32(a, "LBound");
          if (a.local == "Elements") d.elements = number32(a, "Elements");
        }
      } else if (c.local == "SubItem") {
        d.items.push_back(&c);
      } else if (c.local == "EnumInfo") {
        not_kept(c, "enumerations: their values are read as integers");
      } else {
        not_kept(c);
      }
    }
    if (name.empty()) {
      error(t.at, "<DataType> without <Name>");
      return;
    }
    auto [it, fresh] = types_.emplace(name, d);
    if (!fresh && it->second.el->at.line != t.at.line) {
      // the same name defined twice: identical definitions are harmless (SOES writes them)
      warning(t.at, "data type " + name + " defined again (first at line " +
                        std::to_string(it->second.el->at.line) + "); the first is used");
    }
  }

  // The CiA 301 type of a type name (STRING(n), a base type, a BIT field, or a DataType of the
  // file that is an array of bytes or a renamed base type). False after an error.
  struct resolved {
    std::uint16_t code = 0;
    od::data_type type = od::data_type::domain;
    std::uint32_t bytes = 0; // byte strings: capacity
    std::string name;        // as written
  };
  bool resolve(const std::string &name, xml::position at, resolved &r, int depth = 0) {
    r.name = name;
    if (name.starts_with("STRING(") && name.ends_with(")")) {
      const int_parse p = parse_int(name.substr(7, name.size() - 8U), int_syntax::xml);
      const auto n = p.value.to_uint64();
      if (!p.ok || !n || n.value() > 0xFFFFU) {
        error(at, "expected STRING(<length>), got " + name);
        return false;
      }
      r.code = 0x0009;
      r.type = od::data_type::visible_string;
      r.bytes = static_cast<std::uint32_t>(n.value());
      return true;
    }
    if (const esi::base_type *b = esi::find_base_type(name)) {
      if (!b->standard) count(nonstandard_, name, at);
      r.code = b->code;
      r.type = static_cast<od::data_type>(b->code);
      return true;
    }
    if (name.size() == 4 && name.starts_with("BIT") && name[3] >= '2' && name[3] <= '8') {
      count(bit_fields_, name, at);
      r.code = esi::bit_field_code(static_cast<unsigned>(name[3] - '0'));
      r.type = od::data_type::domain;
      r.bytes = 1;
      return true;
    }
    const auto it = types_.find(name);
    if (it != types_.end() && depth < 8) {
      const data_type_def &d = it->second;
      if (d.array && d.items.empty() && (d.base == "BYTE" || d.base == "USINT")) {
        r.code = 0x000A; // ARRAY [0..n] OF BYTE: an OCTET_STRING
        r.type = od::data_type::octet_string;
        r.bytes = d.elements;
        return true;
      }
      if (!d.array && d.items.empty() && !d.base.empty()) {
        const std::string keep = name;
        if (!resolve(d.base, at, r, depth + 1)) return false;
        r.name = keep;
        return true;
      }
      if (!d.array && d.items.empty() && name.starts_with("STRING")) {
        r.code = 0x0009;
        r.type = od::data_type::visible_string;
        r.bytes = d.bits / 8U;
        return true;
      }
    }
    if (name.starts_with("ARRAY [0..") && name.ends_with("] OF BYTE")) {
      const int_parse p = parse_int(name.substr(10, name.size() - 19U), int_syntax::xml);
      const auto n = p.value.to_uint64();
      if (p.ok && n && n.value() < 0xFFFFU) {
        r.code = 0x000A;
        r.type = od::data_type::octet_string;
        r.bytes = static_cast<std::uint32_t>(n.value() + 1U);
        return true;
      }
    }
    error(at, "unknown data type " + name +
                  ": not an ETG.2000 base type, not STRING(n) and not a <DataType> of the file "
                  "with a base type or as an array of bytes");
    return false;
  }

  // The sub-objects of an object of data type `d`: explicit SubIdx, or in order; a SubItem
  // whose type is an array stands for its elements (sub-indices LBound..LBound+Elements-1).
  bool flatten(const data_type_def &d, std::vector<flat_sub> &out, bool &array_object) {
    int next = 0;
    bool arrays = false;
    bool others = false;
    for (const xml::element *item : d.items) {
      flat_sub f;
      f.item = item;
      bool has_sub = false;
      for (const auto &c : item->children) {
        if (c.local == "SubIdx") {
          bool ok = true;
          f.sub = static_cast<std::uint8_t>(number(c.text, c.text_at, "SubIdx", 0xFF, ok));
          if (!ok) return false;
          has_sub = true;
        } else if (c.local == "Name") {
          f.name = trimmed(c.text);
        } else if (c.local == "Type") {
          f.type = trimmed(c.text);
        }
      }
      const auto it = types_.find(f.type);
      // a SubItem without SubIdx whose type is an array: the array's elements
      if (!has_sub && it != types_.end() && it->second.array && it->second.items.empty()) {
        arrays = true;
        const data_type_def &a = it->second;
        for (std::uint32_t k = 0; k < a.elements; ++k) {
          flat_sub e;
          e.item = item;
          e.sub = static_cast<std::uint8_t>(a.lbound + k);
          e.type = a.base;
          e.element_of_array = true;
          out.push_back(e);
        }
        next = static_cast<int>(a.lbound + a.elements);
        continue;
      }
      if (!has_sub) f.sub = static_cast<std::uint8_t>(next);
      next = f.sub + 1;
      if (f.sub != 0U) others = true;
      out.push_back(std::move(f));
    }
    array_object = arrays && !others;
    return true;
  }

  void object(const xml::element &o) {
    const xml::element *index_el = o.find_child("Index");
    const xml::element *type_el = o.find_child("Type");
    if (index_el == nullptr || type_el == nullptr) {
      error(o.at, "<Object> without <Index> or <Type>");
      return;
    }
    bool ok = true;
    const auto index = static_cast<std::uint16_t>(
        number(index_el->text, index_el->text_at, "an object Index", 0xFFFF, ok));
    if (!ok) return;
    if (auto [it, fresh] = seen_.emplace(index, o.at.line); !fresh) {
      error(index_el->text_at, "duplicate object 0x" + hex(index, 4) + " (first at line " +
                                   std::to_string(it->second) + ")");
      return;
    }
    const std::string what = "object 0x" + hex(index, 4);
    object_info info;
    info.index = index;
    info.line = o.at.line;
    info.list = default_list(index);
    if (const xml::element *n = name_of(o)) info.name = trimmed(n->text);
    const xml::element *info_el = o.find_child("Info");
    const xml::element *flags = o.find_child("Flags");
    const std::string type = trimmed(type_el->text);
    if (flags != nullptr) category(*flags, info);
    const auto dt = types_.find(type);
    if (dt == types_.end() || dt->second.items.empty()) {
      // a VAR
      entry &e = dict_.entries.emplace_back();
      e.index = index;
      e.line = o.at.line;
      e.name = info.name;
      if (!entry_type(type, type_el->text_at, e) || !entry_flags(flags, nullptr, e, what) ||
          !entry_values(info_el, e, what)) {
        dict_.entries.pop_back();
        return;
      }
      info.code = od::object_code::var;
      dict_.objects[index] = std::move(info);
      return;
    }
    std::vector<flat_sub> subs;
    bool array_object = false;
    if (!flatten(dt->second, subs, array_object)) return;
    info.code = array_object ? od::object_code::array : od::object_code::record;
    // Info/SubItem by name; the rest in order to the elements of an array
    std::vector<const xml::element *> infos;
    if (info_el != nullptr) infos = info_el->children_named("SubItem");
    std::vector<bool> used(infos.size(), false);
    std::vector<const xml::element *> info_of(subs.size(), nullptr);
    for (std::size_t k = 0; k < subs.size(); ++k) {
      if (subs[k].element_of_array) continue;
      for (std::size_t i = 0; i < infos.size(); ++i) {
        const xml::element *n = infos[i]->find_child("Name");
        if (!used[i] && n != nullptr && trimmed(n->text) == subs[k].name) {
          used[i] = true;
          info_of[k] = infos[i];
          break;
        }
      }
    }
    std::size_t next_info = 0;
    for (std::size_t k = 0; k < subs.size(); ++k) {
      if (!subs[k].element_of_array) continue;
      while (next_info < infos.size() && used[next_info]) ++next_info;
      if (next_info < infos.size()) {
        used[next_info] = true;
        info_of[k] = infos[next_info];
        if (const xml::element *n = infos[next_info]->find_child("Name")) {
          subs[k].name = trimmed(n->text);
        }
      }
    }
    for (std::size_t i = 0; i < infos.size(); ++i) {
      if (!used[i]) {
        const xml::element *n = infos[i]->find_child("Name");
        warning(infos[i]->at, "<SubItem> '" + (n != nullptr ? trimmed(n->text) : std::string()) +
                                  "' of " + what + "'s Info names no sub-item of type " + type +
                                  "; not kept");
      }
    }
    std::set<std::uint8_t> taken;
    bool all_ok = true;
    for (std::size_t k = 0; k < subs.size(); ++k) {
      const flat_sub &f = subs[k];
      const std::string sub_what = what + " sub " + std::to_string(f.sub);
      if (!taken.insert(f.sub).second) {
        error(f.item->at, "duplicate sub-index " + std::to_string(f.sub) + " in data type " + type +
                              " of " + what);
        all_ok = false;
        continue;
      }
      entry &e = dict_.entries.emplace_back();
      e.index = index;
      e.sub = f.sub;
      e.object = info.code;
      e.line = f.item->at.line;
      e.name = f.name.empty() ? info.name + " " + std::to_string(f.sub) : f.name;
      const xml::element *item_flags = f.item->find_child("Flags");
      const xml::element *vinfo = info_of[k] != nullptr ? info_of[k]->find_child("Info") : nullptr;
      if (!entry_type(f.type, f.item->at, e) || !entry_flags(flags, item_flags, e, sub_what) ||
          !entry_values(vinfo, e, sub_what)) {
        dict_.entries.pop_back();
        all_ok = false;
      }
    }
    info.sub_number = static_cast<std::uint8_t>(std::min<std::size_t>(taken.size(), 0xFF));
    if (all_ok) dict_.objects[index] = std::move(info);
  }

  void category(const xml::element &flags, object_info &info) {
    const xml::element *c = flags.find_child("Category");
    if (c == nullptr) return;
    const std::string v = trimmed(c->text);
    if (v == "m") {
      info.list = object_list::mandatory;
    } else if (v != "o" && v != "c" && !v.empty()) { // optional, conditional: by the index
      warning(c->at, "expected Category m, o or c, got \"" + v + "\"; ignored");
    }
  }

  bool entry_type(const std::string &name, xml::position at, entry &e) {
    resolved r;
    if (!resolve(name, at, r)) return false;
    e.type_code = r.code;
    e.type = r.type;
    if (od::is_byte_string(e.type)) {
      e.size = r.bytes;
      e.size_declared = r.bytes != 0U;
    }
    if (esi::name_of(r.code) != name && !(name.starts_with("STRING(") && r.code == 0x0009)) {
      e.type_name = name;
    }
    return true;
  }

  // Access (with ETG's per-state restrictions, kept as keys) and PDO mapping: the sub-item's
  // flags, else the object's.
  bool entry_flags(const xml::element *object_flags, const xml::element *item_flags, entry &e,
                   const std::string &what) {
    const xml::element *access = nullptr;
    const xml::element *mapping = nullptr;
    for (const xml::element *f : {item_flags, object_flags}) {
      if (f == nullptr) continue;
      if (access == nullptr) access = f->find_child("Access");
      if (mapping == nullptr) mapping = f->find_child("PdoMapping");
    }
    e.access = od::access::ro;
    if (access != nullptr) {
      const std::string v = trimmed(access->text);
      if (v == "ro") {
        e.access = od::access::ro;
      } else if (v == "rw") {
        e.access = od::access::rw;
      } else if (v == "wo") {
        e.access = od::access::wo;
      } else {
        error(access->text_at.line != 0 ? access->text_at : access->at,
              "expected Access ro, rw or wo, got \"" + v + "\" (" + what + ")");
        return false;
      }
      for (const auto &a : access->attributes) {
        e.other_keys.emplace_back(std::string(a.local), a.value);
      }
    }
    if (mapping != nullptr) {
      std::string v = to_upper(trimmed(mapping->text));
      if (v == "R") {
        e.pdo = od::pdo_mapping::rx;
      } else if (v == "T") {
        e.pdo = od::pdo_mapping::tx;
      } else if (v == "RT" || v == "TR") {
        e.pdo = od::pdo_mapping::yes;
      } else if (!v.empty()) {
        error(mapping->at, "expected PdoMapping R, T or RT, got \"" + trimmed(mapping->text) +
                               "\" (" + what + ")");
        return false;
      }
    }
    return true;
  }

  // DefaultValue / DefaultData / DefaultString, MinValue / MinData, MaxValue / MaxData.
  bool entry_values(const xml::element *info, entry &e, const std::string &what) {
    if (info == nullptr) return true;
    bool ok = true;
    for (const auto &c : info->children) {
      value_role role{};
      bool data = false;
      if (c.local == "DefaultValue" || c.local == "DefaultString") {
        role = value_role::default_value;
      } else if (c.local == "DefaultData") {
        role = value_role::default_value;
        data = true;
      } else if (c.local == "MinValue") {
        role = value_role::low_limit;
      } else if (c.local == "MinData") {
        role = value_role::low_limit;
        data = true;
      } else if (c.local == "MaxValue") {
        role = value_role::high_limit;
      } else if (c.local == "MaxData") {
        role = value_role::high_limit;
        data = true;
      } else if (c.local == "SubItem") {
        continue; // an object's sub-items: matched in object()
      } else {
        not_kept(c, c.local == "Unit" || c.local == "DisplayName" ? "descriptive texts" : nullptr);
        continue;
      }
      const xml::position at = c.text_at.line != 0 ? c.text_at : c.at;
      const xml_place place{file_, diag_, at, std::string(c.local) + " of " + what};
      if (!data) {
        const std::string text = c.local == "DefaultString" ? c.text : trimmed(c.text);
        if (od::is_byte_string(e.type) && e.type != od::data_type::visible_string &&
            c.local == "DefaultValue") {
          // a number for a byte string (#x… as its bytes, big-endian as written)
          ok = hex_value_bytes(place, text, e, role) && ok;
          continue;
        }
        ok = read_xml_value(place, text, e, role) && ok;
        continue;
      }
      ok = data_value(place, trimmed(c.text), e, role) && ok;
    }
    if (ok) ok = check_value_range({file_, diag_, info->at, what}, e);
    if (od::is_byte_string(e.type) && e.default_text.size() > e.size) {
      if (e.size_declared && e.type == od::data_type::visible_string && e.size == 0U) {
        e.size = static_cast<std::uint32_t>(e.default_text.size()); // STRING(0): no length given
      } else if (e.size_declared) {
        error(info->at, "the default of " + what + " is " + std::to_string(e.default_text.size()) +
                            " bytes, more than its type's " + std::to_string(e.size));
        return false;
      } else {
        e.size = static_cast<std::uint32_t>(e.default_text.size());
      }
    }
    return ok;
  }

  static bool hex_bytes(std::string_view t, std::string &out) {
    if (t.size() % 2U != 0U) return false;
    for (std::size_t i = 0; i < t.size(); i += 2U) {
      const int byte = ascii::hex_byte(t[i], t[i + 1U]);
      if (byte < 0) return false;
      out += static_cast<char>(byte);
    }
    return true;
  }

  bool hex_value_bytes(const xml_place &place, const std::string &text, entry &e, value_role role) {
    std::string t = text;
    if (t.size() >= 2 && t[0] == '#' && (t[1] == 'x' || t[1] == 'X')) t = t.substr(2);
    std::string bytes;
    if (role != value_role::default_value || !hex_bytes(t, bytes)) {
      return read_xml_value(place, text, e, role); // the reader's warning for byte strings
    }
    e.default_text = bytes;
    return true;
  }

  // DefaultData / MinData / MaxData: the value's bytes as hex, little-endian (ETG.2000).
  bool data_value(const xml_place &place, const std::string &text, entry &e, value_role role) {
    std::string bytes;
    if (!hex_bytes(text, bytes)) {
      place.diag.error(place.file, place.at.line, place.at.column,
                       "expected hex digit pairs (the value's bytes, little-endian), got \"" +
                           text + "\" in " + place.what);
      return false;
    }
    if (od::is_byte_string(e.type)) {
      if (role != value_role::default_value) {
        return read_xml_value(place, text, e, role); // warning: no limits
      }
      e.default_text = bytes;
      return true;
    }
    const unsigned width = e.type == od::data_type::boolean ? 1U : od::fixed_size(e.type);
    if (width == 0U || bytes.size() > width || bytes.empty()) {
      place.diag.error(place.file, place.at.line, place.at.column,
                       std::to_string(bytes.size()) + " bytes of data for a " +
                           std::string(od::name(e.type)) + " (" + std::to_string(width) +
                           (width == 1U ? " byte" : " bytes") + ") in " + place.what);
      return false;
    }
    if (bytes.size() < width) {
      // shorter than the type (real files do that): the missing high bytes are zero
      place.diag.warning(place.file, place.at.line, place.at.column,
                         std::to_string(bytes.size()) + (bytes.size() == 1U ? " byte" : " bytes") +
                             " of data for a " + std::string(od::name(e.type)) + " (" +
                             std::to_string(width) + " bytes) in " + place.what +
                             ": the missing high bytes are taken as zero");
      bytes.resize(width, '\0');
    }
    // little-endian bytes → the bit pattern in hex, which the value reader reads as the
    // reader of an XDD or EDS would (signed types as two's complement, REALs as IEEE 754)
    std::string pattern = "0x";
    for (std::size_t i = bytes.size(); i-- > 0;)
      pattern += hex(static_cast<unsigned char>(bytes[i]), 2);
    return read_xml_value(place, pattern, e, role);
  }

  // ---- what the PDOs say and the dictionary lacks ---------------------------------------------
  // PDO mapping objects, the objects they map and the sync manager assignments (1C10h + n)
  // that the ESI describes only as PDOs (devices without CoE, or without a <Dictionary>) are
  // added, so the header holds the process data and its layouts are checked against it.
  void complete_from_pdos(const esi_device &dev) {
    std::size_t mapping_objects = 0;
    std::size_t data_objects = 0;
    int first_line = 0;
    std::map<std::uint16_t, std::map<std::uint8_t, const esi_pdo_entry *>> data;
    std::map<std::uint16_t, bool> data_tx;
    std::map<std::uint16_t, std::string> data_pdo;
    for (const esi_pdo &p : dev.pdos) {
      const auto it = dict_.objects.find(p.index);
      if (it == dict_.objects.end()) {
        add_mapping_object(p);
        if (mapping_objects++ == 0 && first_line == 0) first_line = p.line;
      } else {
        compare_mapping(p);
      }
      for (const esi_pdo_entry &e : p.entries) {
        if (e.index == 0U) continue; // a gap
        if (dict_.objects.count(e.index) != 0U) {
          check_mapped(p, e);
          continue;
        }
        data[e.index].emplace(e.sub, &e);
        data_tx[e.index] = p.tx;
        data_pdo.emplace(e.index, p.name);
      }
    }
    for (const auto &[index, subs] : data) {
      if (!add_data_object(index, subs, data_tx[index], data_pdo[index])) continue;
      if (data_objects++ == 0 && first_line == 0) first_line = dev.pdos.front().line;
    }
    // sync manager PDO assignment
    std::map<int, std::vector<std::uint16_t>> assigned;
    for (const esi_pdo &p : dev.pdos) {
      if (p.sm >= 0 && p.sm < 32) assigned[p.sm].push_back(p.index);
    }
    std::size_t assignments = 0;
    for (const auto &[sm, list] : assigned) {
      const auto index = static_cast<std::uint16_t>(0x1C10 + sm);
      if (dict_.objects.count(index) != 0U) continue;
      add_assignment(index, sm, list);
      ++assignments;
    }
    if (mapping_objects + data_objects + assignments != 0U) {
      diag_.warning(
          file_, first_line, 0,
          "the ESI's dictionary lacks what its PDOs describe: " + std::to_string(mapping_objects) +
              " PDO mapping objects, " + std::to_string(data_objects) + " mapped objects and " +
              std::to_string(assignments) +
              " sync manager assignments (1C10h+n) are added from the PDOs");
    }
  }

  entry make_entry(std::uint16_t index, std::uint8_t sub, od::object_code code,
                   const std::string &name, od::data_type t, int line) {
    entry e;
    e.index = index;
    e.sub = sub;
    e.object = code;
    e.name = name;
    e.type = t;
    e.type_code = static_cast<std::uint16_t>(t);
    e.line = line;
    return e;
  }

  void add_mapping_object(const esi_pdo &p) {
    object_info info;
    info.index = p.index;
    info.code = od::object_code::record;
    info.name = p.name;
    info.line = p.line;
    info.list = default_list(p.index);
    info.sub_number = static_cast<std::uint8_t>(std::min<std::size_t>(p.entries.size() + 1U, 0xFF));
    entry n =
        make_entry(p.index, 0, info.code, "Number of entries", od::data_type::unsigned8, p.line);
    n.access = p.fixed ? od::access::ro : od::access::rw;
    n.default_value = od::unsigned_number(p.entries.size());
    dict_.entries.push_back(std::move(n));
    std::uint8_t sub = 1;
    for (const esi_pdo_entry &e : p.entries) {
      entry m = make_entry(p.index, sub, info.code,
                           e.name.empty() ? "Entry " + std::to_string(sub) : e.name,
                           od::data_type::unsigned32, p.line);
      m.access = p.fixed ? od::access::ro : od::access::rw;
      m.default_value = od::unsigned_number((std::uint32_t{e.index} << 16U) |
                                            (std::uint32_t{e.sub} << 8U) | e.bits);
      dict_.entries.push_back(std::move(m));
      if (sub++ == 0xFF) break;
    }
    dict_.objects[p.index] = std::move(info);
  }

  // A PDO whose mapping object is in the dictionary: its default mapping should be the PDO's.
  void compare_mapping(const esi_pdo &p) {
    std::vector<std::uint32_t> have;
    for (const auto &e : dict_.entries) {
      if (e.index != p.index || e.sub == 0U) continue;
      const auto v = e.default_value.to_uint64();
      if (v) have.push_back(static_cast<std::uint32_t>(v.value()));
    }
    std::vector<std::uint32_t> want;
    for (const auto &e : p.entries) {
      want.push_back((std::uint32_t{e.index} << 16U) | (std::uint32_t{e.sub} << 8U) | e.bits);
    }
    if (have.size() >= want.size() && std::equal(want.begin(), want.end(), have.begin())) return;
    diag_.warning(file_, p.line, 0,
                  std::string(p.tx ? "TxPdo" : "RxPdo") + " 0x" + hex(p.index, 4) +
                      " maps other entries than the defaults of object 0x" + hex(p.index, 4) +
                      " in the dictionary; the dictionary's defaults are kept");
  }

  // A PDO entry whose object is in the dictionary: its sub-index and length should fit.
  void check_mapped(const esi_pdo &p, const esi_pdo_entry &m) {
    for (const auto &e : dict_.entries) {
      if (e.index != m.index || e.sub != m.sub) continue;
      const unsigned bits = e.type == od::data_type::boolean ? 1U : 8U * od::fixed_size(e.type);
      if (!od::is_byte_string(e.type) && e.type != od::data_type::domain && bits != m.bits &&
          !(e.type == od::data_type::boolean && m.bits == 8U)) {
        diag_.warning(file_, p.line, 0,
                      std::string(p.tx ? "TxPdo" : "RxPdo") + " 0x" + hex(p.index, 4) + " maps 0x" +
                          hex(m.index, 4) + ":" + hex(m.sub, 2) + " with " +
                          std::to_string(m.bits) + " bits, but it is " +
                          std::string(od::name(e.type)) + " (" + std::to_string(bits) + " bits)");
      }
      return;
    }
    diag_.warning(file_, p.line, 0,
                  std::string(p.tx ? "TxPdo" : "RxPdo") + " 0x" + hex(p.index, 4) + " maps 0x" +
                      hex(m.index, 4) + ":" + hex(m.sub, 2) +
                      ", which the dictionary's object has no sub-index for");
  }

  bool add_data_object(std::uint16_t index,
                       const std::map<std::uint8_t, const esi_pdo_entry *> &subs, bool tx,
                       const std::string &pdo_name) {
    object_info info;
    info.index = index;
    info.line = 0;
    info.list = default_list(index);
    const bool var = subs.size() == 1U && subs.begin()->first == 0U;
    info.code = var ? od::object_code::var : od::object_code::record;
    info.name = var ? subs.begin()->second->name : pdo_name;
    if (info.name.empty()) info.name = "Object " + hex(index, 4);
    if (!var) {
      entry n = make_entry(index, 0, info.code, "Number of entries", od::data_type::unsigned8, 0);
      n.default_value = od::unsigned_number(subs.rbegin()->first);
      dict_.entries.push_back(std::move(n));
    }
    for (const auto &[sub, m] : subs) {
      if (!var && sub == 0U) continue;
      entry e = make_entry(index, sub, info.code,
                           !m->name.empty() ? m->name
                           : var            ? info.name
                                            : "Entry " + std::to_string(sub),
                           od::data_type::domain, 0);
      resolved r;
      const std::string &type = m->data_type;
      if (type.empty()) {
        error({m->line, 0},
              "PDO entry 0x" + hex(index, 4) + ":" + hex(sub, 2) + " \"" + m->name +
                  "\" names no object of the dictionary and has no DataType to make one of");
        return false;
      }
      if (!resolve(type, {m->line, 0}, r)) return false;
      e.type_code = r.code;
      e.type = r.type;
      if (od::is_byte_string(e.type)) {
        e.size = r.bytes != 0U ? r.bytes : m->bits / 8U;
        e.size_declared = true;
      }
      if (esi::name_of(r.code) != type) e.type_name = type;
      e.access = tx ? od::access::ro : od::access::rw;
      e.pdo = tx ? od::pdo_mapping::tx : od::pdo_mapping::rx;
      dict_.entries.push_back(std::move(e));
    }
    info.sub_number =
        static_cast<std::uint8_t>(std::min<std::size_t>(subs.size() + (var ? 0U : 1U), 0xFF));
    dict_.objects[index] = std::move(info);
    return true;
  }

  void add_assignment(std::uint16_t index, int sm, const std::vector<std::uint16_t> &list) {
    object_info info;
    info.index = index;
    info.code = od::object_code::array;
    info.name = "Sync manager " + std::to_string(sm) + " PDO assignment";
    info.list = default_list(index);
    entry n =
        make_entry(index, 0, info.code, "Number of assigned PDOs", od::data_type::unsigned8, 0);
    n.default_value = od::unsigned_number(list.size());
    dict_.entries.push_back(std::move(n));
    std::uint8_t sub = 1;
    for (const std::uint16_t pdo : list) {
      entry e = make_entry(index, sub, info.code, "PDO " + std::to_string(sub),
                           od::data_type::unsigned16, 0);
      e.default_value = od::unsigned_number(pdo);
      dict_.entries.push_back(std::move(e));
      if (sub++ == 0xFF) break;
    }
    info.sub_number = static_cast<std::uint8_t>(std::min<std::size_t>(list.size() + 1U, 0xFF));
    dict_.objects[index] = std::move(info);
  }

  struct dropped {
    std::size_t count = 0;
    xml::position at;
    std::string why;
  };

  const std::string &file_;
  diagnostics &diag_;
  const std::string &selector_;
  dictionary dict_;
  const xml::element *dictionary_ = nullptr;
  const xml::element *groups_ = nullptr;
  std::map<std::string, data_type_def> types_;
  std::map<std::uint16_t, int> seen_;
  std::map<std::string, dropped> dropped_;
  std::map<std::string, std::pair<std::size_t, xml::position>> nonstandard_, bit_fields_,
      sm_attributes_;
  std::vector<std::string> languages_;
  xml::position languages_at_;
};

} // namespace

std::optional<dictionary> read_esi(std::string_view bytes, const std::string &file,
                                   diagnostics &diag, const std::string &device) {
  esi_reader r(file, diag, device);
  return r.read(bytes);
}

} // namespace fieldcodec::gen
