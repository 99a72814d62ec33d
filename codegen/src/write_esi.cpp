// fieldcodec-gen — ESI writer (--esi): the model as an ETG.2000 EtherCATInfo file with one
// device: its dictionary (DataTypes and Objects), its PDOs and, where the model has them from an
// ESI, sync managers, FMMUs, mailbox and EEPROM data (docs/generator.md, "Writing ESI").
#include "esi_tables.hpp"
#include "options.hpp"
#include "readers.hpp"
#include "text.hpp"
#include "xml.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fieldcodec::gen {

namespace {

std::string esi_hex(std::uint64_t v, int digits) { return "#x" + hex(v, digits); }

class esi_writer {
public:
  esi_writer(const dictionary &d, const std::string &file, diagnostics &diag)
      : d_(d), file_(file), diag_(diag) {}

  std::string write() {
    const bool runs = std::any_of(d_.entries.begin(), d_.entries.end(),
                                  [](const entry &e) { return e.count > 1U; });
    if (runs) {
      expanded_ = d_;
      expand_runs(expanded_);
    }
    const dictionary &d = runs ? expanded_ : d_;
    identity(d);
    w_.comment("Written by fieldcodec-gen from " + d.source_name +
               " (ETG.2000 EtherCAT Slave Information)");
    w_.open("EtherCATInfo");
    w_.attribute("xmlns:xsi", "http://www.w3.org/2001/XMLSchema-instance");
    w_.attribute("Version", "1.6");
    w_.open("Vendor");
    w_.leaf("Id", esi_hex(dev_.vendor_id, 8));
    w_.leaf("Name", dev_.vendor_name);
    w_.close();
    w_.open("Descriptions");
    w_.open("Groups");
    w_.open("Group");
    w_.leaf("Type", dev_.group);
    w_.leaf("Name", dev_.group_name.empty() ? dev_.group : dev_.group_name);
    w_.close();
    w_.close();
    w_.open("Devices");
    w_.open("Device");
    w_.attribute("Physics", dev_.physics.empty() ? "YY" : dev_.physics);
    w_.open("Type");
    w_.attribute("ProductCode", esi_hex(dev_.product_code, 8));
    w_.attribute("RevisionNo", esi_hex(dev_.revision, 8));
    w_.text(dev_.type);
    w_.close();
    w_.open("Name");
    w_.attribute("LcId", "1033");
    w_.text(dev_.name);
    w_.close();
    w_.leaf("GroupType", dev_.group);
    w_.open("Profile");
    if (dev_.profile_no != 0U) w_.leaf("ProfileNo", std::to_string(dev_.profile_no));
    if (!dev_.add_info.empty()) w_.leaf("AddInfo", dev_.add_info);
    w_.open("Dictionary");
    data_types(d);
    objects(d);
    w_.close(); // Dictionary
    w_.close(); // Profile
    for (const auto &f : dev_.fmmu) w_.leaf("Fmmu", f);
    for (const auto &sm : dev_.sync_managers) {
      w_.open("Sm");
      w_.attribute("ControlByte", esi_hex(sm.control, 2));
      if (sm.has_default_size) w_.attribute("DefaultSize", std::to_string(sm.default_size));
      w_.attribute("Enable", sm.enable ? "1" : "0");
      w_.attribute("StartAddress", esi_hex(sm.start, 4));
      w_.text(sm.type);
      w_.close();
    }
    pdos(d);
    mailbox();
    if (dev_.eeprom_bytes != 0U || !dev_.config_data.empty() || !dev_.bootstrap.empty()) {
      w_.open("Eeprom");
      if (dev_.eeprom_bytes != 0U) w_.leaf("ByteSize", std::to_string(dev_.eeprom_bytes));
      if (!dev_.config_data.empty()) w_.leaf("ConfigData", dev_.config_data);
      if (!dev_.bootstrap.empty()) w_.leaf("BootStrap", dev_.bootstrap);
      w_.close();
    }
    w_.close(); // Device
    w_.close(); // Devices
    w_.close(); // Descriptions
    w_.close(); // EtherCATInfo
    summaries();
    return w_.str();
  }

private:
  void lost(int line, const std::string &what) { diag_.warning(file_, line, 0, what); }

  const entry *find(const dictionary &d, std::uint16_t index, std::uint8_t sub) const {
    for (const auto &e : d.entries) {
      if (e.index == index && e.sub == sub) return &e;
    }
    return nullptr;
  }
  const std::string *device_info(std::string_view k) const {
    for (const auto &[name, value] : d_.device_info) {
      if (name == k) return &value;
    }
    return nullptr;
  }
  std::uint32_t identity_number(const dictionary &d, std::uint8_t sub, std::string_view key,
                                const char *what) {
    if (const entry *e = find(d, 0x1018, sub)) {
      if (const auto v = e->default_value.to_uint64(); v && v.value() <= 0xFFFF'FFFFU) {
        return static_cast<std::uint32_t>(v.value());
      }
    }
    if (const std::string *v = device_info(key)) {
      const int_parse p = parse_int(*v);
      if (const auto n = p.value.to_uint64(); p.ok && n && n.value() <= 0xFFFF'FFFFU) {
        return static_cast<std::uint32_t>(n.value());
      }
    }
    lost(0, std::string("no ") + what + " (1018h sub " + std::to_string(sub) +
                " has no default, [DeviceInfo] no " + std::string(key) +
                "): written as #x00000000");
    return 0;
  }

  // The device: from the ESI read, or from the dictionary (1018h, 1000h, [DeviceInfo]).
  void identity(const dictionary &d) {
    if (d.ethercat) {
      dev_ = *d.ethercat;
      if (dev_.group.empty()) dev_.group = dev_.type;
      return;
    }
    dev_.vendor_id = identity_number(d, 1, "VendorNumber", "vendor ID");
    dev_.product_code = identity_number(d, 2, "ProductNumber", "product code");
    dev_.revision = identity_number(d, 3, "RevisionNumber", "revision number");
    if (const std::string *v = device_info("VendorName")) dev_.vendor_name = *v;
    if (const std::string *v = device_info("ProductName")) dev_.name = *v;
    const std::string *order = device_info("OrderCode");
    dev_.type = order != nullptr && !order->empty() ? *order : dev_.name;
    if (dev_.type.empty()) dev_.type = d.stem;
    if (dev_.name.empty()) dev_.name = dev_.type;
    dev_.group = d.stem;
    dev_.group_name = dev_.vendor_name.empty() ? d.stem : dev_.vendor_name;
    if (const entry *t = find(d, 0x1000, 0)) {
      if (const auto v = t->default_value.to_uint64(); v && v.value() <= 0xFFFF'FFFFU) {
        dev_.profile_no = static_cast<std::uint32_t>(v.value() & 0xFFFFU);
        if ((v.value() >> 16U) != 0U) dev_.add_info = std::to_string(v.value() >> 16U);
      }
    }
    lost(0, "the dictionary has no EtherCAT device description (it is not from an ESI): the ESI "
            "has no <Sm>, <Fmmu> or <Eeprom> (a master reads them from the slave's SII), and "
            "its <Mailbox> names CoE only");
    dev_.mailbox = true;
    dev_.protocols = {"CoE"};
    const auto writable = [&](std::uint16_t lo, std::uint16_t hi) {
      bool any = false;
      for (const auto &e : d.entries) {
        if (e.index >= lo && e.index <= hi && od::writable(e.access)) any = true;
      }
      return any;
    };
    dev_.coe.emplace_back("PdoAssign", writable(0x1C10, 0x1C2F) ? "true" : "false");
    dev_.coe.emplace_back("PdoConfig",
                          writable(0x1600, 0x17FF) || writable(0x1A00, 0x1BFF) ? "true" : "false");
  }

  // ---- data types -------------------------------------------------------------------------------
  // The ESI name of an entry's type.
  std::string type_of(const entry &e) {
    if (e.type == od::data_type::visible_string) return "STRING(" + std::to_string(e.size) + ")";
    if (e.type == od::data_type::octet_string || e.type == od::data_type::domain) {
      if (e.type_code >= 0x0031U && e.type_code <= 0x0037U) {
        return "BIT" + std::to_string(e.type_code - 0x0030U + 1U);
      }
      if (e.type == od::data_type::domain) count(domains_, e);
      return "ARRAY [0.." + std::to_string(e.size == 0U ? 0U : e.size - 1U) + "] OF BYTE";
    }
    if (e.type == od::data_type::unicode_string) {
      count(unicode_, e);
      return "ARRAY [0.." + std::to_string(e.size == 0U ? 0U : e.size - 1U) + "] OF BYTE";
    }
    const std::string &n = e.type_name;
    if (!n.empty()) {
      if (const esi::base_type *b = esi::find_base_type(n);
          b != nullptr && b->code == e.type_code) {
        return n;
      }
    }
    const std::string_view std_name =
        esi::name_of(e.type_code != 0U ? e.type_code : static_cast<std::uint16_t>(e.type));
    if (std_name.empty()) {
      count(no_type_, e);
      return "ARRAY [0.." + std::to_string(e.size == 0U ? 0U : e.size - 1U) + "] OF BYTE";
    }
    return std::string(std_name);
  }
  static std::uint32_t bits_of(const entry &e) {
    if (e.type_code >= 0x0031U && e.type_code <= 0x0037U) return e.type_code - 0x0030U + 1U;
    if (e.type == od::data_type::boolean) return 1U;
    const std::uint32_t f = od::fixed_size(e.type);
    return 8U * (f != 0U ? f : e.size);
  }
  void count(std::pair<std::size_t, int> &c, const entry &e) {
    if (c.first++ == 0) c.second = e.line;
  }

  void base_type(const std::string &name, std::uint32_t bits) {
    if (!written_types_.insert(name).second) return;
    w_.open("DataType");
    w_.leaf("Name", name);
    if (name.starts_with("ARRAY [0..")) {
      w_.leaf("BaseType", "BYTE");
      w_.leaf("BitSize", std::to_string(bits));
      w_.open("ArrayInfo");
      w_.leaf("LBound", "0");
      w_.leaf("Elements", std::to_string(bits / 8U));
      w_.close();
    } else {
      w_.leaf("BitSize", std::to_string(bits));
    }
    w_.close();
  }

  // An ARRAY written as ETG writes arrays (sub-index 0 and one "Elements" sub-item of an array
  // type): sub-indices k..k+n-1 without gaps (k >= 1 is the array type's LBound), all of one
  // type and access.
  static bool array_form(const std::vector<const entry *> &subs) {
    if (subs.empty() || subs[0]->sub != 0U || subs[0]->object != od::object_code::array) {
      return false;
    }
    for (std::size_t i = 1; i < subs.size(); ++i) {
      const entry &e = *subs[i];
      if (e.sub != subs[1]->sub + (i - 1U) || e.type_code != subs[1]->type_code ||
          e.type != subs[1]->type || e.size != subs[1]->size || e.access != subs[1]->access ||
          e.pdo != subs[1]->pdo || e.other_keys != subs[1]->other_keys ||
          e.type_name.str() != subs[1]->type_name.str()) {
        return false;
      }
    }
    return true;
  }

  void flags(const entry &e, bool with_category, const object_info *info) {
    w_.open("Flags");
    w_.open("Access");
    for (const auto &[k, v] : e.other_keys) {
      if (k == "ReadRestrictions" || k == "WriteRestrictions") w_.attribute(k, v);
    }
    std::string access = "ro";
    switch (e.access) {
    case od::access::ro: access = "ro"; break;
    case od::access::constant:
      access = "ro";
      count(const_, e);
      break;
    case od::access::wo: access = "wo"; break;
    case od::access::rw: access = "rw"; break;
    case od::access::rwr:
    case od::access::rww:
      access = "rw";
      count(rwr_, e);
      break;
    }
    w_.text(access);
    w_.close();
    if (with_category && info != nullptr) {
      w_.leaf("Category", info->list == object_list::mandatory ? "m" : "o");
    }
    switch (e.pdo) {
    case od::pdo_mapping::no: break;
    case od::pdo_mapping::yes: w_.leaf("PdoMapping", "RT"); break;
    case od::pdo_mapping::rx: w_.leaf("PdoMapping", "R"); break;
    case od::pdo_mapping::tx: w_.leaf("PdoMapping", "T"); break;
    }
    w_.close();
    for (const auto &[k, v] : e.other_keys) {
      if (k != "ReadRestrictions" && k != "WriteRestrictions") {
        lost(e.line, "key " + k + "=" + v + " of 0x" + hex(e.index, 4) + " sub " +
                         std::to_string(e.sub) + " is not written to the ESI (no ESI element)");
      }
    }
  }

  void data_types(const dictionary &d) {
    w_.open("DataTypes");
    // base types first, in code order, then one per ARRAY/RECORD
    std::map<std::string, std::uint32_t> bases;
    for (const auto &e : d.entries) bases.emplace(type_of(e), bits_of(e));
    for (const auto &[name, bits] : bases) base_type(name, bits);
    std::size_t i = 0;
    for (const auto &[index, info] : d.objects) {
      std::vector<const entry *> subs;
      while (i < d.entries.size() && d.entries[i].index < index) ++i;
      for (std::size_t k = i; k < d.entries.size() && d.entries[k].index == index; ++k) {
        subs.push_back(&d.entries[k]);
      }
      if (single(info, subs)) continue;
      const std::string dt = "DT" + hex(index, 4);
      std::uint32_t offset = 0;
      if (array_form(subs)) {
        // an ARRAY of no element (only sub-index 0) is written as one of 0 USINT elements
        const entry &el = subs.size() > 1U ? *subs[1] : *subs[0];
        const std::uint32_t bits = subs.size() > 1U ? bits_of(el) : 8U;
        w_.open("DataType");
        w_.leaf("Name", dt + "ARR");
        w_.leaf("BaseType", subs.size() > 1U ? type_of(el) : std::string("USINT"));
        w_.leaf("BitSize", std::to_string(bits * (subs.size() - 1U)));
        w_.open("ArrayInfo");
        w_.leaf("LBound", std::to_string(subs.size() > 1U ? subs[1]->sub : 1U));
        w_.leaf("Elements", std::to_string(subs.size() - 1U));
        w_.close();
        w_.close();
        w_.open("DataType");
        w_.leaf("Name", dt);
        w_.leaf("BitSize", std::to_string(16U + bits * (subs.size() - 1U)));
        sub_item(*subs[0], "0", type_of(*subs[0]), bits_of(*subs[0]), 0);
        sub_item(el, "", dt + "ARR", bits * static_cast<std::uint32_t>(subs.size() - 1U), 16,
                 "Elements");
        w_.close();
        continue;
      }
      if (info.code == od::object_code::array) count(arrays_as_records_, *subs.front());
      w_.open("DataType");
      w_.leaf("Name", dt);
      std::string items;
      for (const entry *e : subs) {
        const std::uint32_t bits = bits_of(*e);
        if (bits % 8U == 0U) offset = (offset + 7U) / 8U * 8U;
        if (e->sub == 1U && offset < 16U) offset = 16U; // sub-index 0 takes a word (ETG)
        offset += bits;
      }
      w_.leaf("BitSize", std::to_string((offset + 7U) / 8U * 8U));
      offset = 0;
      for (const entry *e : subs) {
        const std::uint32_t bits = bits_of(*e);
        if (bits % 8U == 0U) offset = (offset + 7U) / 8U * 8U;
        if (e->sub == 1U && offset < 16U) offset = 16U;
        sub_item(*e, std::to_string(e->sub), type_of(*e), bits, offset);
        offset += bits;
      }
      w_.close();
    }
    w_.close();
  }

  static bool single(const object_info &info, const std::vector<const entry *> &subs) {
    return (info.code == od::object_code::var || info.code == od::object_code::domain ||
            info.code == od::object_code::deftype) &&
           subs.size() == 1U && subs[0]->sub == 0U;
  }

  void sub_item(const entry &e, const std::string &sub, const std::string &type, std::uint32_t bits,
                std::uint32_t offset, const std::string &name = {}) {
    w_.open("SubItem");
    if (!sub.empty()) w_.leaf("SubIdx", sub);
    w_.leaf("Name", name.empty() ? e.name : name);
    w_.leaf("Type", type);
    w_.leaf("BitSize", std::to_string(bits));
    w_.leaf("BitOffs", std::to_string(offset));
    flags(e, false, nullptr);
    w_.close();
  }

  // ---- objects ----------------------------------------------------------------------------------
  void values(const entry &e) {
    std::vector<std::pair<std::string, std::string>> out;
    if (od::is_byte_string(e.type)) {
      if (!e.default_text.empty()) {
        const std::string &t = e.default_text;
        const bool text =
            valid_utf8(t) && std::none_of(t.begin(), t.end(), [](char c) {
              return static_cast<unsigned char>(c) < 0x20U; // XML carries no C0 controls; the
            });                                             // reader trims blanks: data then
        const bool trims = !t.empty() && (t.front() == ' ' || t.back() == ' ');
        if (e.type == od::data_type::visible_string && text && !trims) {
          out.emplace_back("DefaultString", e.default_text.str());
        } else {
          out.emplace_back("DefaultData",
                           byte_string_text(od::data_type::octet_string, e.default_text));
        }
      }
    } else {
      const auto number = [&](const od::number &n, bool nodeid, const char *what, bool limit) {
        if (!n && !nodeid) return;
        if (nodeid) {
          count(nodeid_, e);
          return;
        }
        std::string t = limit ? limit_number(e, n, false) : entry_number(e, n, false);
        if (t.starts_with("0x")) t = "#x" + t.substr(2);
        out.emplace_back(what, t);
      };
      number(e.default_value, e.default_nodeid, "DefaultValue", false);
      number(e.low, e.low_nodeid, "MinValue", true);
      number(e.high, e.high_nodeid, "MaxValue", true);
    }
    if (e.parameter_value || e.parameter_nodeid || !e.parameter_text.empty()) count(dcf_, e);
    if (out.empty()) return;
    w_.open("Info");
    for (const auto &[k, v] : out) w_.leaf(k, v);
    w_.close();
  }

  void objects(const dictionary &d) {
    w_.open("Objects");
    std::size_t i = 0;
    for (const auto &[index, info] : d.objects) {
      std::vector<const entry *> subs;
      while (i < d.entries.size() && d.entries[i].index < index) ++i;
      for (std::size_t k = i; k < d.entries.size() && d.entries[k].index == index; ++k) {
        subs.push_back(&d.entries[k]);
      }
      if (subs.empty()) continue;
      if (!info.object_links.empty()) {
        lost(info.line, "the object links of 0x" + hex(index, 4) + " are not written to the ESI");
      }
      w_.open("Object");
      w_.leaf("Index", esi_hex(index, 4));
      if (single(info, subs)) {
        const entry &e = *subs[0];
        w_.leaf("Name", e.name);
        w_.leaf("Type", type_of(e));
        w_.leaf("BitSize", std::to_string(bits_of(e)));
        values(e);
        flags(e, true, &info);
        w_.close();
        continue;
      }
      w_.leaf("Name", info.name);
      w_.leaf("Type", "DT" + hex(index, 4));
      std::uint32_t size = 0;
      for (const entry *e : subs) size += bits_of(*e);
      w_.leaf("BitSize", std::to_string(size));
      w_.open("Info");
      for (const entry *e : subs) {
        w_.open("SubItem");
        w_.leaf("Name", e->name);
        values(*e);
        w_.close();
      }
      w_.close();
      w_.open("Flags");
      w_.leaf("Access", "ro");
      w_.leaf("Category", info.list == object_list::mandatory ? "m" : "o");
      w_.close();
      w_.close();
    }
    w_.close();
  }

  // ---- PDOs -------------------------------------------------------------------------------------
  std::string entry_type_name(const dictionary &d, std::uint16_t index, std::uint8_t sub) {
    if (const entry *e = find(d, index, sub)) return type_of(*e);
    return {};
  }

  void pdos(const dictionary &d) {
    std::vector<esi_pdo> list;
    if (d_.ethercat) {
      list = d_.ethercat->pdos;
    } else {
      std::map<std::uint16_t, int> sm; // PDO → sync manager, from 1C10h+n
      for (const auto &e : d.entries) {
        if (e.index < 0x1C10U || e.index > 0x1C2FU || e.sub == 0U) continue;
        if (const auto v = e.default_value.to_uint64(); v && v.value() <= 0xFFFFU) {
          sm.emplace(static_cast<std::uint16_t>(v.value()), e.index - 0x1C10);
        }
      }
      for (const auto &[index, info] : d.objects) {
        const bool rx = index >= 0x1600U && index <= 0x17FFU;
        const bool tx = index >= 0x1A00U && index <= 0x1BFFU;
        if (!rx && !tx) continue;
        esi_pdo p;
        p.tx = tx;
        p.index = index;
        p.name = info.name;
        p.line = info.line;
        const entry *n = find(d, index, 0);
        const auto count = n != nullptr ? n->default_value.to_uint64()
                                        : result<std::uint64_t>(errc::unknown_object);
        if (!count) continue;
        bool fixed = n != nullptr && !od::writable(n->access);
        bool ok = true;
        for (std::uint64_t s = 1; s <= count.value() && s <= 0xFFU; ++s) {
          const entry *m = find(d, index, static_cast<std::uint8_t>(s));
          const auto v = m != nullptr ? m->default_value.to_uint64()
                                      : result<std::uint64_t>(errc::unknown_object);
          if (m == nullptr || !v || m->type != od::data_type::unsigned32) {
            lost(info.line,
                 "mapping object 0x" + hex(index, 4) +
                     " has no complete 32-bit default mapping: no PDO is written for it");
            ok = false;
            break;
          }
          if (od::writable(m->access)) fixed = false;
          const auto me = canopen_entry(static_cast<std::uint32_t>(v.value()));
          if (me.bits == 0U || (me.index != 0U && find(d, me.index, me.sub) == nullptr)) {
            lost(m->line, "mapping object 0x" + hex(index, 4) + " sub " + std::to_string(s) +
                              " maps " +
                              (me.bits == 0U ? std::string("an entry of length 0")
                                             : "0x" + hex(me.index, 4) + ":" + hex(me.sub, 2) +
                                                   ", which is not in the dictionary") +
                              ": no PDO is written for it");
            ok = false;
            break;
          }
          esi_pdo_entry pe;
          pe.index = me.index;
          pe.sub = me.sub;
          pe.bits = me.bits;
          if (const entry *o = find(d, me.index, me.sub)) pe.name = o->name;
          pe.data_type = me.index == 0U ? std::string() : entry_type_name(d, me.index, me.sub);
          p.entries.push_back(std::move(pe));
        }
        if (!ok) continue;
        p.fixed = fixed;
        if (const auto it = sm.find(index); it != sm.end()) p.sm = it->second;
        list.push_back(std::move(p));
      }
    }
    for (const esi_pdo &p : list) {
      w_.open(p.tx ? "TxPdo" : "RxPdo");
      if (p.fixed) w_.attribute("Fixed", "true");
      if (p.mandatory) w_.attribute("Mandatory", "true");
      if (p.sm >= 0) w_.attribute("Sm", std::to_string(p.sm));
      for (const auto &[k, v] : p.other_attributes) w_.attribute(k, v);
      w_.leaf("Index", esi_hex(p.index, 4));
      w_.leaf("Name", p.name);
      for (const std::uint16_t x : p.excludes) w_.leaf("Exclude", esi_hex(x, 4));
      for (const auto &e : p.entries) {
        w_.open("Entry");
        w_.leaf("Index", esi_hex(e.index, 4));
        w_.leaf("SubIndex", esi_hex(e.sub, 2));
        w_.leaf("BitLen", std::to_string(e.bits));
        if (!e.name.empty()) w_.leaf("Name", e.name);
        if (!e.data_type.empty()) w_.leaf("DataType", e.data_type);
        w_.close();
      }
      w_.close();
    }
  }

  struct mapped {
    std::uint16_t index;
    std::uint8_t sub;
    std::uint8_t bits;
  };
  static mapped canopen_entry(std::uint32_t v) {
    return {static_cast<std::uint16_t>(v >> 16U), static_cast<std::uint8_t>((v >> 8U) & 0xFFU),
            static_cast<std::uint8_t>(v & 0xFFU)};
  }

  void mailbox() {
    if (!dev_.mailbox) return;
    w_.open("Mailbox");
    if (dev_.data_link_layer) w_.attribute("DataLinkLayer", "true");
    for (const auto &p : dev_.protocols) {
      w_.open(p);
      if (p == "CoE") {
        for (const auto &[k, v] : dev_.coe) w_.attribute(k, v);
      }
      w_.close();
    }
    w_.close();
  }

  // ---- what an ESI cannot hold
  // --------------------------------------------------------------------
  void summary(const std::pair<std::size_t, int> &c, const std::string &what) {
    if (c.first == 0U) return;
    lost(c.second, std::to_string(c.first) + (c.first == 1U ? " entry " : " entries ") + what);
  }
  void summaries() {
    summary(const_, "of access const written as ro (an ESI has ro, rw and wo)");
    summary(rwr_, "of access rwr/rww written as rw (their PDO direction is their PdoMapping)");
    summary(nodeid_, "with $NODEID values: those values are not written (EtherCAT has no node-ID)");
    summary(dcf_,
            "with DCF values (ParameterValue): not written (an ESI has no configured values)");
    summary(domains_, "of type DOMAIN written as ARRAY OF BYTE (an ESI has no DOMAIN; read back as "
                      "OCTET_STRING)");
    summary(unicode_,
            "of type UNICODE_STRING written as ARRAY OF BYTE (read back as OCTET_STRING)");
    summary(no_type_, "of a type without an ESI name written as ARRAY OF BYTE");
    if (arrays_as_records_.first != 0U) {
      lost(arrays_as_records_.second,
           std::to_string(arrays_as_records_.first) +
               (arrays_as_records_.first == 1U ? " ARRAY" : " ARRAYs") +
               " with gaps or sub-objects that differ in type, access or PDO mapping written as "
               "records (ETG's array form has one type and one set of flags; read back as "
               "RECORD)");
    }
    std::string keys;
    for (const auto &[k, v] : d_.file_info) keys += (keys.empty() ? "" : ", ") + k;
    if (!keys.empty()) lost(0, "[FileInfo] " + keys + " not written to the ESI");
    if (!d_.comments.empty()) lost(0, "[Comments] not written to the ESI");
    for (const auto &s : d_.other_sections)
      lost(0, "section [" + s.name + "] not written to the ESI");
  }

  const dictionary &d_;
  const std::string &file_;
  diagnostics &diag_;
  dictionary expanded_;
  esi_device dev_;
  xml::writer w_;
  std::set<std::string> written_types_;
  std::pair<std::size_t, int> const_{}, rwr_{}, nodeid_{}, dcf_{}, domains_{}, unicode_{},
      no_type_{}, arrays_as_records_{};
};

} // namespace

std::string write_esi(const dictionary &d, const std::string &file, diagnostics &diag) {
  esi_writer w(d, file, diag);
  return w.write();
}

} // namespace fieldcodec::gen
