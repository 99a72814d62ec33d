// fieldcodec-gen — XDD / XDC writer: the model as an ISO 15745 profile container for CANopen
// (CiA 311) or POWERLINK (EPSG DS 311). It writes what the XDD reader keeps (xdd_reader.cpp), so
// XDD → model → XDD loses nothing; what an XDD cannot hold is reported (docs/generator.md,
// "Writing XDD").
#include "options.hpp"
#include "readers.hpp"
#include "text.hpp"
#include "xdd_tables.hpp"
#include "xml.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace fieldcodec::gen {

namespace {

using xdd::bit_rates;
using xdd::file_keys;
using xdd::general_feature_keys;
using xdd::identity_keys;
using xdd::mapped_key;
using xdd::master_feature_keys;

// "11-16-2016" (CiA 306) → "2016-11-16" (xs:date); anything else as it is.
std::string xdd_date(const std::string &d) {
  if (d.size() == 10 && d[2] == '-' && d[5] == '-') {
    return d.substr(6, 4) + "-" + d.substr(0, 2) + "-" + d.substr(3, 2);
  }
  return d;
}

// Whether XML 1.0 can hold the text (valid UTF-8, no C0 control but TAB, LF, CR).
bool xml_text(std::string_view s) {
  if (!valid_utf8(s)) return false;
  return std::none_of(s.begin(), s.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20U && c != '\t' && c != '\n' && c != '\r';
  });
}

class xdd_writer {
public:
  xdd_writer(const dictionary &d, bus_profile profile, const std::string &file, diagnostics &diag)
      : d_(d), powerlink_(profile == bus_profile::powerlink), file_(file), diag_(diag) {}

  std::string write() {
    // the profile only: whether the file is an XDC is what it holds (actualValue, denotation,
    // deviceCommissioning), which a POWERLINK file of a DCF may not (fuzz F32)
    w_.comment("Written by fieldcodec-gen from " + d_.source_name + " (" +
               (powerlink_ ? "EPSG DS 311 POWERLINK" : "CiA 311 CANopen") + ")");
    w_.open("ISO15745ProfileContainer");
    w_.attribute("xmlns", powerlink_ ? "http://www.ethernet-powerlink.org"
                                     : "http://www.canopen.org/xml/1.1");
    w_.attribute("xmlns:xsi", "http://www.w3.org/2001/XMLSchema-instance");
    plan_parameters();
    device_profile();
    network_profile();
    w_.close();
    not_written();
    return w_.str();
  }

private:
  // ---- what is where in the model -------------------------------------------------------------
  const std::string *key(const key_list &list, std::string_view k) const {
    for (const auto &[name, value] : list) {
      if (name == k) return &value;
    }
    return nullptr;
  }
  const other_section *section(std::string_view name) const {
    for (const auto &s : d_.other_sections) {
      if (s.name == name) return &s;
    }
    return nullptr;
  }
  void lost(int line, const std::string &what) { diag_.warning(file_, line, 0, what); }

  // ---- profile headers and bodies ---------------------------------------------------------------
  void header(bool device) {
    w_.open("ProfileHeader");
    w_.leaf("ProfileIdentification",
            powerlink_
                ? (device ? "Powerlink_Device_Profile" : "Powerlink_Communication_Profile")
                : (device ? "CANopen device profile" : "CANopen communication network profile"));
    w_.leaf("ProfileRevision", "1");
    const std::string *product = key(d_.device_info, "ProductName");
    w_.leaf("ProfileName", product != nullptr ? *product : d_.stem);
    w_.leaf("ProfileSource", "");
    w_.leaf("ProfileClassID", device ? "Device" : "CommunicationNetwork");
    w_.open("ISO15745Reference");
    w_.leaf("ISO15745Part", powerlink_ ? "4" : "1");
    w_.leaf("ISO15745Edition", "1");
    w_.leaf("ProfileTechnology", powerlink_ ? "Powerlink" : "CANopen");
    w_.close();
    w_.close();
  }

  void body(bool device) {
    w_.open("ProfileBody");
    w_.attribute("xsi:type",
                 std::string(device ? "ProfileBody_Device_" : "ProfileBody_CommunicationNetwork_") +
                     (powerlink_ ? "Powerlink" : "CANopen"));
    for (const auto &k : file_keys) {
      const std::string *v = key(d_.file_info, k.eds_key);
      if (v == nullptr) continue;
      w_.attribute(k.xdd_name, k.eds_key.ends_with("Date") ? xdd_date(*v) : *v);
    }
    if (const other_section *s = section("XDD.ProfileBody")) {
      for (const auto &[k, v] : s->keys) w_.attribute(k, v);
    }
  }

  void device_profile() {
    w_.open("ISO15745Profile");
    header(true);
    body(true);
    w_.open("DeviceIdentity");
    for (const auto &k : identity_keys) {
      const std::string *v = key(d_.device_info, k.eds_key);
      if (v != nullptr) w_.leaf(k.xdd_name, *v);
    }
    if (const other_section *s = section("XDD.DeviceIdentity")) {
      for (const auto &[k, v] : s->keys) {
        if (k.starts_with("version.")) {
          w_.open("version");
          w_.attribute("versionType", k.substr(8));
          w_.text(v);
          w_.close();
        } else if (k == "vendorText" || k == "productText" || k == "deviceFamily" ||
                   k == "productFamily") {
          w_.open(k);
          w_.open("label");
          w_.attribute("lang", "en");
          w_.text(v);
          w_.close();
          w_.close();
        } else {
          w_.leaf(k, v);
        }
      }
    }
    w_.close();
    if (!parameters_.empty()) application_process();
    w_.close(); // ProfileBody
    w_.close(); // ISO15745Profile
  }

  // ---- ApplicationProcess: the capacities of byte strings (CO_stringLengthMin)
  // --------------------
  static std::string unique_id(const entry &e) {
    return "UID_" + hex(e.index, 4) + "_" + hex(e.sub, 2);
  }
  void plan_parameters() {
    for (const auto &e : d_.entries) {
      // every capacity, as the EDS writer writes Size= for every one
      if (od::is_byte_string(e.type) && e.size != 0U && e.count == 1U && e.type_code < 0x0401U) {
        parameters_.push_back(&e);
        with_parameter_.insert({e.index, e.sub});
      }
    }
  }
  void application_process() {
    w_.open("ApplicationProcess");
    w_.open("parameterList");
    for (const entry *e : parameters_) {
      w_.open("parameter");
      w_.attribute("uniqueID", unique_id(*e));
      w_.attribute("access", [&] {
        switch (e->access) {
        case od::access::constant: return "const";
        case od::access::ro: return "read";
        case od::access::wo: return "write";
        case od::access::rw: return "readWrite";
        case od::access::rwr: return "readWriteInput";
        case od::access::rww: return "readWriteOutput";
        }
        return "read";
      }());
      w_.open("label");
      w_.attribute("lang", "en");
      w_.text(e->name);
      w_.close();
      w_.open(xdd::iec_name(e->type_code));
      w_.close();
      w_.open("property");
      w_.attribute("name", "CO_stringLengthMin");
      w_.attribute("value", std::to_string(e->size));
      w_.close();
      w_.close();
    }
    w_.close();
    w_.close();
  }

  void network_profile() {
    w_.open("ISO15745Profile");
    header(false);
    body(false);
    w_.open("ApplicationLayers");
    if (const other_section *s = section("XDD.identity")) {
      w_.open("identity");
      for (const auto &[k, v] : s->keys) {
        if (k.starts_with("version.")) {
          w_.open("version");
          w_.attribute("versionType", k.substr(8));
          w_.text(v);
          w_.close();
        } else {
          w_.leaf(k, v);
        }
      }
      w_.close();
    }
    if (powerlink_) data_type_list();
    object_list();
    if (!d_.dummy_usage.empty()) {
      w_.open("dummyUsage");
      for (const auto &[k, v] : d_.dummy_usage) {
        w_.open("dummy");
        w_.attribute("entry", k + "=" + v);
        w_.close();
      }
      w_.close();
    }
    dynamic_channels();
    w_.close(); // ApplicationLayers
    transport_layers();
    network_management();
    w_.close(); // ProfileBody
    w_.close(); // ISO15745Profile
  }

  void data_type_list() {
    std::set<std::uint16_t> codes;
    for (const auto &e : d_.entries) {
      codes.insert(e.type_code != 0U ? e.type_code : static_cast<std::uint16_t>(e.type));
    }
    w_.open("DataTypeList");
    for (const std::uint16_t c : codes) {
      const auto *t = std::find_if(std::begin(xdd::powerlink_types), std::end(xdd::powerlink_types),
                                   [&](const xdd::type_name &n) { return n.code == c; });
      if (t == std::end(xdd::powerlink_types)) continue; // the reader needs no entry for it
      w_.open("defType");
      w_.attribute("dataType", hex(c, 4));
      w_.open(t->name);
      w_.close();
      w_.close();
    }
    w_.close();
  }

  // ---- objects ----------------------------------------------------------------------------------
  std::string value_text(const entry &e, const od::number &n, bool nodeid, const rare_text &text,
                         bool limit) {
    if (od::is_byte_string(e.type)) {
      if (limit) return {};
      const std::string &bytes = text;
      if (e.type_code == xdd::mac_address || e.type_code == xdd::ip_address) {
        const bool mac = e.type_code == xdd::mac_address;
        std::string s;
        for (std::size_t i = 0; i < bytes.size(); ++i) {
          if (i != 0U) s += mac ? ':' : '.';
          const auto b = static_cast<unsigned char>(bytes[i]);
          s += mac ? hex(b, 2) : std::to_string(b);
        }
        return s;
      }
      return byte_string_text(e.type, bytes);
    }
    if (!n.has_value() && !nodeid) return {};
    // BOOLEAN as 0/1 like every integer (the reader reads true/false too): the number keeps its
    // kind through a round trip
    return limit ? limit_number(e, n, nodeid) : entry_number(e, n, nodeid);
  }

  void value_attribute(const entry &e, std::string_view name, const std::string &v) {
    if (v.empty()) return;
    if (!xml_text(v)) {
      lost(e.line, std::string(name) + " of 0x" + hex(e.index, 4) + " sub " +
                       std::to_string(e.sub) +
                       " is not written to the XDD: it holds characters XML 1.0 cannot carry");
      return;
    }
    w_.attribute(name, v);
  }

  void entry_attributes(const entry &e, bool sub) {
    if (sub) w_.attribute("subIndex", hex(e.sub, 2));
    w_.attribute("name", e.name);
    w_.attribute("objectType", sub ? "7" : std::to_string(static_cast<unsigned>(e.object)));
    const std::uint16_t code = e.type_code != 0U ? e.type_code : static_cast<std::uint16_t>(e.type);
    w_.attribute("dataType", hex(code, 4));
    value_attribute(e, "lowLimit", value_text(e, e.low, e.low_nodeid, {}, true));
    value_attribute(e, "highLimit", value_text(e, e.high, e.high_nodeid, {}, true));
    w_.attribute("accessType", od::name(e.access));
    value_attribute(e, "defaultValue",
                    value_text(e, e.default_value, e.default_nodeid, e.default_text, false));
    if (d_.is_dcf) {
      value_attribute(
          e, "actualValue",
          value_text(e, e.parameter_value, e.parameter_nodeid, e.parameter_text, false));
      if (!e.denotation.empty()) w_.attribute("denotation", e.denotation);
    }
    w_.attribute("PDOmapping", [&] {
      switch (e.pdo) {
      case od::pdo_mapping::no: return "no";
      case od::pdo_mapping::yes: return "optional";
      case od::pdo_mapping::rx: return "RPDO";
      case od::pdo_mapping::tx: return "TPDO";
      }
      return "no";
    }());
    if (e.has_obj_flags) w_.attribute("objFlags", hex(e.obj_flags, 4));
    if (with_parameter_.count({e.index, e.sub}) != 0U) {
      w_.attribute("uniqueIDRef", unique_id(e));
    }
    if (od::is_byte_string(e.type) && (e.low || e.high)) {
      lost(e.line, "the limits of 0x" + hex(e.index, 4) + " sub " + std::to_string(e.sub) +
                       " are not written to the XDD (it has no limits for " +
                       std::string(od::name(e.type)) + ")");
    }
    if (e.scaled) {
      lost(e.line, "the scale, unit and other table columns of 0x" + hex(e.index, 4) + " sub " +
                       std::to_string(e.sub) +
                       " are not written to the XDD (it has no place for them)");
    }
    for (const auto &[k, v] : e.other_keys) {
      lost(e.line, "key " + k + "=" + v + " of 0x" + hex(e.index, 4) + " sub " +
                       std::to_string(e.sub) + " is not written to the XDD (no XDD attribute)");
    }
  }

  void object_list() {
    const bool runs = std::any_of(d_.entries.begin(), d_.entries.end(),
                                  [](const entry &e) { return e.count > 1U; });
    if (runs) {
      expanded_ = d_;
      expand_runs(expanded_);
    }
    const dictionary &d = runs ? expanded_ : d_;
    w_.open(powerlink_ ? "ObjectList" : "CANopenObjectList");
    std::size_t i = 0;
    for (const auto &[index, info] : d.objects) {
      while (i < d.entries.size() && d.entries[i].index < index) ++i;
      std::size_t n = 0;
      while (i + n < d.entries.size() && d.entries[i + n].index == index) ++n;
      object(d, info, i, n);
      i += n;
    }
    w_.close();
  }

  void object(const dictionary &d, const object_info &info, std::size_t first, std::size_t n) {
    const bool single = info.code == od::object_code::var || info.code == od::object_code::domain ||
                        info.code == od::object_code::deftype;
    if (info.list != default_list(info.index)) {
      lost(info.line, "object 0x" + hex(info.index, 4) +
                          " is written without its object list (an XDD lists objects by index "
                          "range: mandatory 1000h/1001h/1018h, manufacturer 2000h-5FFFh)");
    }
    if (!info.object_links.empty()) {
      lost(info.line, "the object links of 0x" + hex(info.index, 4) +
                          " are not written to the XDD (it has no object links)");
    }
    w_.open(powerlink_ ? "Object" : "CANopenObject");
    w_.attribute("index", hex(info.index, 4));
    if (single && n == 1U && d.entries[first].sub == 0U) {
      entry_attributes(d.entries[first], false);
      w_.close();
      return;
    }
    w_.attribute("name", info.name);
    const auto code = single ? od::object_code::record : info.code;
    w_.attribute("objectType", std::to_string(static_cast<unsigned>(code)));
    const std::pair<std::string_view, std::string_view> attrs[] = {
        {"DataType", "dataType"},          {"AccessType", "accessType"},
        {"DefaultValue", "defaultValue"},  {"LowLimit", "lowLimit"},
        {"HighLimit", "highLimit"},        {"PDOMapping", "PDOmapping"},
        {"ParameterValue", "actualValue"}, {"Denotation", "denotation"}};
    for (const auto &kv : info.other_keys) {
      const std::string &k = kv.first; // (clang 14 captures no structured binding)
      const std::string &v = kv.second;
      const auto *a = std::find_if(std::begin(attrs), std::end(attrs),
                                   [&](const auto &x) { return iequals(x.first, k); });
      if (a == std::end(attrs)) {
        lost(info.line, "key " + k + "=" + v + " of object 0x" + hex(info.index, 4) +
                            " is not written to the XDD (no XDD attribute)");
        continue;
      }
      std::string value = v;
      if (a->second == "dataType") {
        const int_parse p = parse_int(v);
        const auto c = p.value.to_uint64();
        if (!p.ok || !c || c.value() > 0xFFFFU) {
          lost(info.line, "DataType=" + v + " of object 0x" + hex(info.index, 4) +
                              " is not written to the XDD (not a data type code)");
          continue;
        }
        value = hex(c.value(), 4);
      }
      w_.attribute(a->second, value);
    }
    if (!powerlink_) w_.attribute("subNumber", std::to_string(n));
    if (info.has_obj_flags) w_.attribute("objFlags", hex(info.obj_flags, 4));
    for (std::size_t k = first; k < first + n; ++k) {
      w_.open(powerlink_ ? "SubObject" : "CANopenSubObject");
      entry_attributes(d.entries[k], true);
      w_.close();
    }
    w_.close();
  }

  // ---- dynamic channels, transport layers, network management -----------------------------------
  void dynamic_channels() {
    const other_section *s = section("DynamicChannels");
    if (s == nullptr) return;
    std::map<std::string, std::string> keys(s->keys.begin(), s->keys.end());
    const std::string *n = key(s->keys, "NrOfSeg");
    const int_parse p = parse_int(n != nullptr ? *n : "0");
    const auto count = p.value.to_uint64();
    w_.open("dynamicChannels");
    for (std::uint64_t i = 1; p.ok && count && i <= count.value() && i <= 0xFFU; ++i) {
      const std::string k = std::to_string(i);
      w_.open("dynamicChannel");
      if (const std::string *t = key(s->keys, "Type" + k)) {
        const int_parse tp = parse_int(*t);
        const auto c = tp.value.to_uint64();
        if (tp.ok && c && c.value() <= 0xFFFFU) w_.attribute("dataType", hex(c.value(), 4));
      }
      if (const std::string *dir = key(s->keys, "Dir" + k)) {
        w_.attribute("accessType", *dir == "rww"   ? "readWriteOutput"
                                   : *dir == "rwr" ? "readWriteInput"
                                                   : *dir);
      }
      if (const std::string *r = key(s->keys, "Range" + k)) {
        const auto dash = r->find('-');
        const int_parse a = parse_int(r->substr(0, dash));
        const int_parse b = parse_int(dash == std::string::npos ? "" : r->substr(dash + 1U));
        const auto av = a.value.to_uint64();
        const auto bv = b.value.to_uint64();
        if (a.ok && b.ok && av && bv) {
          w_.attribute("startIndex", hex(av.value(), 4));
          w_.attribute("endIndex", hex(bv.value(), 4));
        }
      }
      if (const std::string *o = key(s->keys, "PPOffset" + k)) w_.attribute("addressOffset", *o);
      for (const auto &[kk, v] : s->keys) {
        if (kk.starts_with("XDD.") && kk.ends_with(k) && kk.size() > 4U + k.size() &&
            !(kk[kk.size() - k.size() - 1U] >= '0' && kk[kk.size() - k.size() - 1U] <= '9')) {
          w_.attribute(kk.substr(4, kk.size() - 4U - k.size()), v);
        }
      }
      w_.close();
    }
    w_.close();
  }

  void transport_layers() {
    w_.open("TransportLayers");
    if (!powerlink_) {
      std::vector<std::uint32_t> rates;
      for (const std::uint32_t r : bit_rates) {
        const std::string *v = key(d_.device_info, "BaudRate_" + std::to_string(r));
        if (v != nullptr && trim(*v) == "1") rates.push_back(r);
      }
      const other_section *br = section("XDD.baudRate");
      if (!rates.empty() || br != nullptr) {
        w_.open("PhysicalLayer");
        w_.open("baudRate");
        if (br != nullptr) {
          for (const auto &[k, v] : br->keys) w_.attribute(k, v);
        }
        for (const std::uint32_t r : rates) {
          w_.open("supportedBaudRate");
          w_.attribute("value", std::to_string(r) + " Kbps");
          w_.close();
        }
        w_.close();
        w_.close();
      }
    }
    w_.close();
  }

  void features(std::string_view element, std::span<const mapped_key> keys) {
    const other_section *s = section("XDD." + std::string(element));
    std::vector<std::pair<std::string, std::string>> attrs;
    for (const auto &k : keys) {
      const std::string *v = key(d_.device_info, k.eds_key);
      if (v == nullptr) continue;
      if (k.flag) {
        const std::string_view t = trim(*v);
        if (t != "0" && t != "1") {
          lost(0, "[DeviceInfo] " + std::string(k.eds_key) + "=" + *v +
                      " is not written to the XDD (expected 0 or 1)");
          continue;
        }
        attrs.emplace_back(k.xdd_name, t == "1" ? "true" : "false");
      } else {
        attrs.emplace_back(k.xdd_name, std::string(trim(*v)));
      }
    }
    if (s == nullptr && attrs.empty()) return;
    w_.open(element);
    for (const auto &[k, v] : attrs) w_.attribute(k, v);
    if (s != nullptr) {
      for (const auto &[k, v] : s->keys) w_.attribute(k, v);
    }
    w_.close();
  }

  void network_management() {
    w_.open("NetworkManagement");
    if (powerlink_) {
      if (section("XDD.GeneralFeatures") == nullptr) {
        lost(0, "the XDD has no POWERLINK <GeneralFeatures> (the source has none); EPSG DS 311 "
                "tools expect NMTCycleTimeMin, NMTCycleTimeMax, NMTBootTimeNotActive and "
                "NMTErrorEntries there");
      }
      for (const auto &s : d_.other_sections) { // in the order they were read
        if (s.name == "XDD.GeneralFeatures" || s.name == "XDD.CNFeatures" ||
            s.name == "XDD.MNFeatures" || s.name == "XDD.Diagnostic") {
          features(std::string_view(s.name).substr(4), {});
        }
      }
    } else {
      features("CANopenGeneralFeatures", general_feature_keys);
      features("CANopenMasterFeatures", master_feature_keys);
      if (d_.is_dcf && (!d_.commissioning.empty() || d_.node_id > 0)) commissioning();
    }
    w_.close();
  }

  void commissioning() {
    w_.open("deviceCommissioning");
    if (d_.commissioning.empty()) {
      w_.attribute("nodeID", std::to_string(d_.node_id));
      if (!d_.node_name.empty()) w_.attribute("nodeName", d_.node_name);
    }
    for (const auto &[k, v] : d_.commissioning) {
      if (iequals(k, "NodeID")) {
        w_.attribute("nodeID", v);
      } else if (iequals(k, "NodeName")) {
        w_.attribute("nodeName", v);
      } else if (iequals(k, "Baudrate")) {
        w_.attribute("actualBaudRate", v + " Kbps");
      } else if (iequals(k, "NetNumber")) {
        w_.attribute("networkNumber", v);
      } else if (iequals(k, "NetworkName")) {
        w_.attribute("networkName", v);
      } else if (iequals(k, "CANopenManager")) {
        w_.attribute("CANopenManager", trim(v) == "1" ? "true" : "false");
      } else if (k.starts_with("XDD.")) {
        w_.attribute(k.substr(4), v);
      } else {
        lost(0, "[DeviceComissioning] " + k + "=" + v + " is not written to the XDC");
      }
    }
    w_.close();
  }

  // ---- what has no place ------------------------------------------------------------------------
  void not_written() {
    std::string keys;
    for (const auto &kv : d_.file_info) {
      const std::string &k = kv.first;
      if (std::none_of(std::begin(file_keys), std::end(file_keys),
                       [&](const mapped_key &m) { return m.eds_key == k; })) {
        keys += (keys.empty() ? "" : ", ") + k;
      }
    }
    if (!keys.empty()) lost(0, "[FileInfo] " + keys + " not written to the XDD (no XDD attribute)");
    keys.clear();
    for (const auto &kv : d_.device_info) {
      const std::string &k = kv.first;
      const bool identity = std::any_of(std::begin(identity_keys), std::end(identity_keys),
                                        [&](const mapped_key &m) { return m.eds_key == k; });
      const bool feature =
          !powerlink_ &&
          (std::any_of(std::begin(general_feature_keys), std::end(general_feature_keys),
                       [&](const mapped_key &m) { return m.eds_key == k; }) ||
           std::any_of(std::begin(master_feature_keys), std::end(master_feature_keys),
                       [&](const mapped_key &m) { return m.eds_key == k; }) ||
           k.starts_with("BaudRate_"));
      if (!identity && !feature) keys += (keys.empty() ? "" : ", ") + k;
    }
    if (!keys.empty()) {
      lost(0, "[DeviceInfo] " + keys + " not written to the " + (powerlink_ ? "POWERLINK " : "") +
                  "XDD (no XDD attribute)");
    }
    if (!d_.comments.empty()) lost(0, "[Comments] not written to the XDD");
    if (powerlink_ && d_.is_dcf && (d_.node_id > 0 || !d_.commissioning.empty())) {
      lost(0, "[DeviceComissioning] not written to the POWERLINK XDC (no deviceCommissioning)");
    }
    for (const auto &s : d_.other_sections) {
      if (s.name == "DynamicChannels" && !powerlink_) continue;
      if (s.name.starts_with("XDD.")) continue;
      lost(0, "section [" + s.name + "] not written to the XDD");
    }
  }

  const dictionary &d_;
  bool powerlink_;
  const std::string &file_;
  diagnostics &diag_;
  xml::writer w_;
  dictionary expanded_;
  std::vector<const entry *> parameters_;
  std::set<std::pair<std::uint16_t, std::uint8_t>> with_parameter_;
};

} // namespace

std::string write_xdd(const dictionary &d, bus_profile profile, const std::string &file,
                      diagnostics &diag) {
  xdd_writer w(d, profile, file, diag);
  return w.write();
}

} // namespace fieldcodec::gen
