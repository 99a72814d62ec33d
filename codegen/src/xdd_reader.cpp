// fieldcodec-gen — XDD / XDC / XPD reader: ISO 15745 profile containers of CANopen (CiA 311)
// and POWERLINK (EPSG DS 311) devices into the model the EDS reader fills
// (docs/generator.md, "XDD and XDC").
#include "readers.hpp"
#include "text.hpp"
#include "xdd_tables.hpp"
#include "xml.hpp"
#include "xml_values.hpp"

#include <fieldcodec/core/ascii.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace fieldcodec::gen {

namespace {

constexpr std::string_view xsi_ns = "http://www.w3.org/2001/XMLSchema-instance";

using xdd::bit_rates;
using xdd::file_keys;
using xdd::identity_keys;
using xdd::iec_type;
using xdd::iec_types;
using xdd::mapped_key;

bool is_hex(std::string_view s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](char c) { return ascii::hex_value(c) >= 0; });
}

/// The value of at most 8 hex digits (is_hex(s) holds).
std::uint32_t hex_value(std::string_view s) {
  return static_cast<std::uint32_t>(ascii::parse_hex(s).value_or(0));
}

// "2016-11-16" (xs:date) → "11-16-2016" (CiA 306); anything else as it is.
std::string eds_date(std::string_view d) {
  if (d.size() == 10 && d[4] == '-' && d[7] == '-') {
    return std::string(d.substr(5, 2)) + "-" + std::string(d.substr(8, 2)) + "-" +
           std::string(d.substr(0, 4));
  }
  return std::string(d);
}

class xdd_reader {
public:
  xdd_reader(const std::string &file, diagnostics &diag) : file_(file), diag_(diag) {}

  std::optional<dictionary> read(const xml::document &doc) {
    const xml::element &root = doc.root;
    if (root.local != "ISO15745ProfileContainer") {
      error(root.at, "expected the root element <ISO15745ProfileContainer> of an XDD/XDC, got <" +
                         std::string(root.name) + ">");
      return std::nullopt;
    }
    const xml::element *network = nullptr;
    for (const auto &profile : root.children) {
      if (profile.local != "ISO15745Profile") {
        not_kept(profile);
        continue;
      }
      const xml::element *body = profile.find_child("ProfileBody");
      if (body == nullptr) {
        warning(profile.at, "<ISO15745Profile> without <ProfileBody> ignored");
        continue;
      }
      for (const auto &c : profile.children) {
        if (c.local != "ProfileBody" && c.local != "ProfileHeader") not_kept(c);
      }
      const std::string type = body_type(*body);
      if (type.empty()) continue;
      if (type.find("Modular") != std::string::npos) {
        error(body->at, "modular device descriptions (xsi:type \"" + type +
                            "\") are not supported: generate from the description of one module "
                            "configuration");
        continue;
      }
      bus_profile bus = bus_profile::unspecified;
      if (type.ends_with("_CANopen")) bus = bus_profile::canopen;
      if (type.ends_with("_Powerlink")) bus = bus_profile::powerlink;
      const bool device = type.starts_with("ProfileBody_Device_");
      const bool comm = type.starts_with("ProfileBody_CommunicationNetwork_");
      if (bus == bus_profile::unspecified || (!device && !comm)) {
        error(body->at, "unknown profile body type \"" + type +
                            "\" (ProfileBody_Device_CANopen, ProfileBody_Device_Powerlink, "
                            "ProfileBody_CommunicationNetwork_CANopen or _Powerlink expected)");
        continue;
      }
      if (dict_.profile != bus_profile::unspecified && dict_.profile != bus) {
        error(body->at, "profile body \"" + type + "\" is for another bus than the first one");
        continue;
      }
      dict_.profile = bus;
      file_attributes(*body);
      if (device) {
        device_body(*body);
      } else if (network != nullptr) {
        error(body->at, "a second communication network profile (the first at line " +
                            std::to_string(network->at.line) + ")");
      } else {
        network = body;
      }
    }
    if (diag_.has_errors()) return std::nullopt;
    if (network == nullptr) {
      error(root.at, "no communication network profile (<ProfileBody "
                     "xsi:type=\"ProfileBody_CommunicationNetwork_…\">): the file has no object "
                     "list");
      return std::nullopt;
    }
    network_body(*network);
    report_summaries();
    if (diag_.has_errors()) return std::nullopt;
    check_pdo_pairs(dict_, file_, diag_);
    if (diag_.has_errors()) return std::nullopt;
    const auto by_address = [](const entry &a, const entry &b) {
      return a.index != b.index ? a.index < b.index : a.sub < b.sub;
    };
    std::stable_sort(dict_.entries.begin(), dict_.entries.end(), by_address);
    return std::move(dict_);
  }

private:
  // ---- diagnostics --------------------------------------------------------------------------
  void error(xml::position at, const std::string &msg) {
    diag_.error(file_, at.line, at.column, msg);
  }
  void warning(xml::position at, const std::string &msg) {
    diag_.warning(file_, at.line, at.column, msg);
  }
  // An element the reader does not keep: one warning per element name.
  void not_kept(const xml::element &e, const char *why = nullptr) {
    auto &n = dropped_[std::string(e.local)];
    if (n.count++ == 0) {
      n.at = e.at;
      n.why = why != nullptr ? why : "";
    }
  }
  void report_summaries() {
    for (const auto &[name, d] : dropped_) {
      warning(d.at, "<" + name + "> is not kept" + (d.why.empty() ? "" : " (" + d.why + ")") +
                        (d.count > 1 ? " (" + std::to_string(d.count) + " elements)" : ""));
    }
    for (const auto &[code, u] : extended_use_) {
      warning(u.at, "data type 0x" + hex(code, 4) + (u.name.empty() ? "" : " (" + u.name + ")") +
                        " of " + std::to_string(u.count) + (u.count == 1 ? " entry" : " entries") +
                        " is not a CiA 301 basic type; its value is kept as DOMAIN");
    }
    if (bitstring_.count != 0U) {
      warning(bitstring_.at, "IEC type BITSTRING of " + std::to_string(bitstring_.count) +
                                 (bitstring_.count == 1 ? " entry" : " entries") +
                                 " read as OCTET_STRING (CiA 311 writes OCTET_STRING and DOMAIN "
                                 "alike; a dataType attribute tells them apart)");
    }
    if (struct_domain_.count != 0U) {
      warning(struct_domain_.at, std::to_string(struct_domain_.count) +
                                     (struct_domain_.count == 1 ? " object" : " objects") +
                                     " typed by a structure of the dataTypeList read as DOMAIN "
                                     "(the structure's members are not kept)");
    }
    if (pdo_default_.count != 0U) {
      warning(pdo_default_.at, "PDOmapping=\"default\" of " + std::to_string(pdo_default_.count) +
                                   (pdo_default_.count == 1 ? " entry" : " entries") +
                                   " read as mappable (the model, like an EDS, does not tell a "
                                   "default mapping from an optional one)");
    }
    if (!languages_.empty()) {
      std::string list;
      for (const auto &l : languages_) list += (list.empty() ? "" : ", ") + l;
      warning(languages_at_, "labels in " + list +
                                 " are not kept (names are the objects' name "
                                 "attributes)");
    }
  }

  // ---- profile bodies -----------------------------------------------------------------------
  std::string body_type(const xml::element &body) {
    for (const auto &a : body.attributes) {
      if (a.local == "type" && a.ns == xsi_ns) {
        const auto colon = a.value.find(':');
        return colon == std::string::npos ? a.value : a.value.substr(colon + 1U);
      }
    }
    error(body.at, "<ProfileBody> without xsi:type (which profile it is)");
    return {};
  }

  void set_key(key_list &list, std::string_view key, std::string value) {
    for (auto &[k, v] : list) {
      if (k == key) {
        v = std::move(value);
        return;
      }
    }
    list.emplace_back(std::string(key), std::move(value));
  }

  other_section &section(const std::string &name) {
    for (auto &s : dict_.other_sections) {
      if (s.name == name) return s;
    }
    dict_.other_sections.push_back({name, {}});
    return dict_.other_sections.back();
  }

  // File attributes of the first profile body: CiA 306 [FileInfo] keys; the others in
  // [XDD.ProfileBody].
  void file_attributes(const xml::element &body) {
    if (files_done_) return;
    files_done_ = true;
    for (const auto &k : file_keys) { // in the order the writer writes them
      if (const xml::attribute *a = body.find_attribute(k.xdd_name)) {
        set_key(dict_.file_info, k.eds_key,
                k.xdd_name.ends_with("Date") ? eds_date(a->value) : a->value);
      }
    }
    for (const auto &a : body.attributes) {
      if (!a.ns.empty()) continue; // xsi:type, xsi:schemaLocation
      if (std::none_of(std::begin(file_keys), std::end(file_keys),
                       [&](const mapped_key &k) { return k.xdd_name == a.local; })) {
        set_key(section("XDD.ProfileBody").keys, a.local, a.value);
      }
    }
  }

  std::string label_text(const xml::element &e) {
    const xml::element *l = pick_label(e, "en", "label", "lang", other_languages_);
    note_languages(e);
    return l != nullptr ? l->text : e.text;
  }
  void note_languages(const xml::element &e) {
    for (const auto &l : other_languages_) {
      if (std::find(languages_.begin(), languages_.end(), l) == languages_.end()) {
        if (languages_.empty()) languages_at_ = e.at;
        languages_.push_back(l);
      }
    }
    other_languages_.clear();
  }

  void device_body(const xml::element &body) {
    for (const auto &c : body.children) {
      if (c.local == "DeviceIdentity") {
        device_identity(c);
      } else if (c.local == "ApplicationProcess") {
        application_process(c);
      } else if (c.local == "DeviceFunction") {
        not_kept(c, "descriptive: characteristics, pictures, connectors");
      } else if (c.local == "DeviceManager") {
        not_kept(c, "LEDs and indicators");
      } else {
        not_kept(c);
      }
    }
  }

  void device_identity(const xml::element &id) {
    key_list xs_keys;
    struct {
      key_list &keys;
    } xs{xs_keys};
    for (const auto &c : id.children) {
      const auto it = std::find_if(std::begin(identity_keys), std::end(identity_keys),
                                   [&](const mapped_key &k) { return k.xdd_name == c.local; });
      if (it != std::end(identity_keys)) {
        set_key(dict_.device_info, it->eds_key, std::string(trim(c.text)));
      } else if (c.local == "version") {
        const xml::attribute *t = c.find_attribute("versionType");
        set_key(xs.keys, "version." + (t != nullptr ? t->value : std::string("?")),
                std::string(trim(c.text)));
      } else if (c.find_child("label") != nullptr) {
        set_key(xs.keys, c.local, label_text(c));
      } else if (c.children.empty()) {
        set_key(xs.keys, c.local, std::string(trim(c.text)));
      } else {
        not_kept(c);
      }
    }
    if (!xs_keys.empty()) section("XDD.DeviceIdentity").keys = std::move(xs_keys);
  }

  void application_process(const xml::element &ap) {
    for (const auto &c : ap.children) {
      if (c.local == "parameterList") {
        for (const auto &p : c.children) {
          if (p.local != "parameter") {
            not_kept(p);
            continue;
          }
          const xml::attribute *id = p.find_attribute("uniqueID");
          if (id == nullptr) {
            error(p.at, "<parameter> without uniqueID");
            continue;
          }
          auto [it, fresh] = parameters_.emplace(id->value, &p);
          if (!fresh) {
            error(p.at, "duplicate parameter uniqueID \"" + id->value + "\" (first at line " +
                            std::to_string(it->second->at.line) + ")");
          }
        }
      } else if (c.local != "dataTypeList") {
        // dataTypeList describes the ARRAY/RECORD types whose sub-objects have parameters of
        // their own; everything else of the application process is about functions, not objects
        not_kept(c);
      }
    }
  }

  void network_body(const xml::element &body) {
    for (const auto &c : body.children) {
      if (c.local == "ApplicationLayers") {
        application_layers(c);
      } else if (c.local == "TransportLayers") {
        transport_layers(c);
      } else if (c.local == "NetworkManagement") {
        network_management(c);
      } else {
        not_kept(c);
      }
    }
  }

  void application_layers(const xml::element &al) {
    // the data types first: objects refer to them
    for (const auto &c : al.children) {
      if (c.local == "DataTypeList") data_type_list(c);
    }
    const xml::element *list = nullptr;
    for (const auto &c : al.children) {
      if (c.local == "DataTypeList") continue;
      if (c.local == "ObjectList" || c.local == "CANopenObjectList") {
        if (list != nullptr) {
          error(c.at,
                "a second object list (the first at line " + std::to_string(list->at.line) + ")");
          continue;
        }
        list = &c;
        object_list(c);
      } else if (c.local == "identity") {
        other_section &s = section("XDD.identity");
        for (const auto &x : c.children) {
          if (x.local == "version") {
            const xml::attribute *t = x.find_attribute("versionType");
            set_key(s.keys, "version." + (t != nullptr ? t->value : std::string("?")),
                    std::string(trim(x.text)));
          } else if (x.children.empty()) {
            set_key(s.keys, x.local, std::string(trim(x.text)));
          } else {
            not_kept(x);
          }
        }
      } else if (c.local == "dummyUsage") {
        for (const auto &d : c.children) {
          const xml::attribute *e = d.find_attribute("entry");
          const auto eq = e != nullptr ? e->value.find('=') : std::string::npos;
          if (d.local != "dummy" || eq == std::string::npos) {
            error(d.at, "expected <dummy entry=\"DummyNNNN=0|1\"/> in <dummyUsage>");
            continue;
          }
          dict_.dummy_usage.emplace_back(e->value.substr(0, eq), e->value.substr(eq + 1U));
        }
      } else if (c.local == "dynamicChannels") {
        dynamic_channels(c);
      } else {
        not_kept(c);
      }
    }
    if (list == nullptr) error(al.at, "<ApplicationLayers> without an object list");
  }

  // <dynamicChannels><dynamicChannel dataType="0007" accessType="readWriteOutput"
  // startIndex="A080" endIndex="A0BF" maxNumber="64" addressOffset="0" bitAlignment="8"/>
  // → CiA 306 [DynamicChannels] (NrOfSeg, TypeN, DirN, RangeN, PPOffsetN).
  void dynamic_channels(const xml::element &dc) {
    other_section &s = section("DynamicChannels");
    std::size_t n = 0;
    for (const auto &ch : dc.children) {
      if (ch.local != "dynamicChannel") {
        not_kept(ch);
        continue;
      }
      ++n;
      const std::string k = std::to_string(n);
      // in the order the writer writes them
      if (const xml::attribute *a = ch.find_attribute("dataType")) {
        set_key(s.keys, "Type" + k, "0x" + a->value);
      }
      if (const xml::attribute *a = ch.find_attribute("accessType")) {
        set_key(s.keys, "Dir" + k,
                a->value == "readWriteOutput"  ? "rww"
                : a->value == "readWriteInput" ? "rwr"
                                               : a->value);
      }
      const xml::attribute *from = ch.find_attribute("startIndex");
      const xml::attribute *to = ch.find_attribute("endIndex");
      if (from != nullptr && to != nullptr) {
        set_key(s.keys, "Range" + k, "0x" + from->value + "-0x" + to->value);
      }
      if (const xml::attribute *a = ch.find_attribute("addressOffset")) {
        set_key(s.keys, "PPOffset" + k, a->value);
      }
      for (const auto &a : ch.attributes) {
        if (a.local != "dataType" && a.local != "accessType" && a.local != "startIndex" &&
            a.local != "endIndex" && a.local != "addressOffset") {
          set_key(s.keys, "XDD." + std::string(a.local) + k, a.value);
        }
      }
    }
    s.keys.insert(s.keys.begin(), {"NrOfSeg", std::to_string(n)});
  }

  void transport_layers(const xml::element &tl) {
    for (const auto &c : tl.children) {
      const xml::element *br = c.local == "PhysicalLayer" ? c.find_child("baudRate") : nullptr;
      if (br == nullptr) {
        not_kept(c);
        continue;
      }
      std::set<std::uint32_t> rates;
      for (const auto &s : br->children) {
        const xml::attribute *v =
            s.local == "supportedBaudRate" ? s.find_attribute("value") : nullptr;
        std::uint32_t kbit = 0;
        if (v != nullptr) {
          const std::string_view t = v->value;
          const auto sp = t.find(' ');
          const int_parse p = parse_int(t.substr(0, sp), int_syntax::xml);
          const auto u = p.value.to_uint64();
          if (p.ok && u && sp != std::string_view::npos && iequals(trim(t.substr(sp)), "Kbps")) {
            kbit = static_cast<std::uint32_t>(std::min<std::uint64_t>(u.value(), 0xFFFFFFFFU));
          }
        }
        if (std::find(std::begin(bit_rates), std::end(bit_rates), kbit) == std::end(bit_rates)) {
          error(v != nullptr ? v->value_at : s.at,
                "expected a CiA 301 bit rate such as \"500 Kbps\" (10, 20, 50, 125, 250, 500, "
                "800, 1000), got \"" +
                    (v != nullptr ? v->value : std::string()) + "\"");
          continue;
        }
        rates.insert(kbit);
      }
      for (const std::uint32_t r : bit_rates) {
        set_key(dict_.device_info, "BaudRate_" + std::to_string(r),
                rates.count(r) != 0U ? "1" : "0");
      }
      if (const xml::attribute *d = br->find_attribute("defaultValue")) {
        set_key(section("XDD.baudRate").keys, "defaultValue", d->value);
      }
    }
  }

  void features(const xml::element &f, std::span<const mapped_key> keys) {
    const std::string name = "XDD." + std::string(f.local);
    if (f.attributes.empty()) section(name); // kept present
    for (const auto &a : f.attributes) {
      const auto it = std::find_if(keys.begin(), keys.end(),
                                   [&](const mapped_key &k) { return k.xdd_name == a.local; });
      if (it == keys.end()) {
        set_key(section(name).keys, a.local, a.value);
      } else if (it->flag) {
        if (a.value != "true" && a.value != "false" && a.value != "1" && a.value != "0") {
          error(a.value_at,
                "expected true or false, got \"" + a.value + "\" in " + std::string(a.local));
          continue;
        }
        set_key(dict_.device_info, it->eds_key, a.value == "true" || a.value == "1" ? "1" : "0");
      } else {
        set_key(dict_.device_info, it->eds_key, a.value);
      }
    }
    if (!f.children.empty()) not_kept(f.children.front());
  }

  void network_management(const xml::element &nm) {
    for (const auto &c : nm.children) {
      if (c.local == "CANopenGeneralFeatures") {
        features(c, xdd::general_feature_keys);
      } else if (c.local == "CANopenMasterFeatures") {
        features(c, xdd::master_feature_keys);
      } else if (c.local == "GeneralFeatures" || c.local == "CNFeatures" ||
                 c.local == "MNFeatures") {
        features(c, {});
      } else if (c.local == "deviceCommissioning") {
        commissioning(c);
      } else if (c.local == "Diagnostic" && c.children.empty() && c.attributes.empty()) {
        section("XDD.Diagnostic");
      } else {
        not_kept(c);
      }
    }
  }

  // XDC <deviceCommissioning nodeID="5" nodeName="…" actualBaudRate="500 Kbps" …/> → CiA 306
  // [DeviceComissioning].
  void commissioning(const xml::element &c) {
    dict_.is_dcf = true;
    for (const auto &a : c.attributes) {
      if (a.local == "nodeID") {
        const int_parse p = parse_int(a.value, int_syntax::xml);
        const auto id = p.value.to_int64();
        if (!p.ok || !id || id.value() < 1 || id.value() > 127) {
          warning(a.value_at, "expected a node-ID 1..127, got \"" + a.value + "\"; ignored");
        } else {
          dict_.node_id = static_cast<int>(id.value());
        }
        set_key(dict_.commissioning, "NodeID", a.value);
      } else if (a.local == "nodeName") {
        dict_.node_name = a.value;
        set_key(dict_.commissioning, "NodeName", a.value);
      } else if (a.local == "actualBaudRate") {
        const auto sp = a.value.find(' ');
        set_key(dict_.commissioning, "Baudrate", a.value.substr(0, sp));
      } else if (a.local == "networkNumber") {
        set_key(dict_.commissioning, "NetNumber", a.value);
      } else if (a.local == "networkName") {
        set_key(dict_.commissioning, "NetworkName", a.value);
      } else if (a.local == "CANopenManager") {
        set_key(dict_.commissioning, "CANopenManager",
                a.value == "true" || a.value == "1" ? "1" : "0");
      } else {
        set_key(dict_.commissioning, "XDD." + std::string(a.local), a.value);
      }
    }
  }

  // POWERLINK <DataTypeList><defType dataType="0401"><MAC_ADDRESS/></defType>…
  void data_type_list(const xml::element &l) {
    for (const auto &d : l.children) {
      const xml::attribute *code = d.find_attribute("dataType");
      if (code == nullptr || !is_hex(code->value) || code->value.size() != 4) {
        error(code != nullptr ? code->value_at : d.at,
              "expected dataType as four hexadecimal digits in <" + std::string(d.local) + ">");
        continue;
      }
      const auto c = static_cast<std::uint16_t>(hex_value(code->value));
      std::string name;
      if (d.local == "defType" && !d.children.empty()) {
        name = d.children.front().local;
      } else if (const xml::attribute *n = d.find_attribute("name")) {
        name = n->value;
      }
      defined_types_[c] = name;
    }
  }

  // ---- objects ------------------------------------------------------------------------------
  struct object_attrs {
    const xml::attribute *index = nullptr, *sub_index = nullptr, *name = nullptr,
                         *object_type = nullptr, *data_type = nullptr, *low = nullptr,
                         *high = nullptr, *access = nullptr, *default_value = nullptr,
                         *actual_value = nullptr, *denotation = nullptr, *pdo = nullptr,
                         *obj_flags = nullptr, *unique_id_ref = nullptr, *sub_number = nullptr;
  };

  object_attrs attributes_of(const xml::element &e) {
    object_attrs o;
    const std::pair<std::string_view, const xml::attribute * object_attrs::*> names[] = {
        {"index", &object_attrs::index},
        {"subIndex", &object_attrs::sub_index},
        {"name", &object_attrs::name},
        {"objectType", &object_attrs::object_type},
        {"dataType", &object_attrs::data_type},
        {"lowLimit", &object_attrs::low},
        {"highLimit", &object_attrs::high},
        {"accessType", &object_attrs::access},
        {"defaultValue", &object_attrs::default_value},
        {"actualValue", &object_attrs::actual_value},
        {"denotation", &object_attrs::denotation},
        {"PDOmapping", &object_attrs::pdo},
        {"objFlags", &object_attrs::obj_flags},
        {"uniqueIDRef", &object_attrs::unique_id_ref},
        {"subNumber", &object_attrs::sub_number},
    };
    for (const auto &a : e.attributes) {
      const auto it = std::find_if(std::begin(names), std::end(names),
                                   [&](const auto &n) { return n.first == a.local; });
      if (it == std::end(names) || !a.ns.empty()) {
        warning(a.at, "attribute " + std::string(a.name) + " of <" + std::string(e.name) +
                          "> is not kept");
        continue;
      }
      o.*(it->second) = &a;
    }
    return o;
  }

  // A hexBinary attribute of `digits` hexadecimal digits (index 4, subIndex 2, dataType 4).
  bool hex_attribute(const xml::attribute *a, const xml::element &e, std::size_t digits,
                     const char *what, std::uint32_t &out) {
    if (a == nullptr) {
      error(e.at, "<" + std::string(e.name) + "> without " + what);
      return false;
    }
    if (!is_hex(a->value) || a->value.size() != digits) {
      error(a->value_at, std::string("expected ") + what + " as " + (digits == 2 ? "two" : "four") +
                             " hexadecimal digits, got \"" + a->value + "\"");
      return false;
    }
    out = hex_value(a->value);
    return true;
  }

  void object_list(const xml::element &list) {
    std::map<std::uint16_t, const xml::element *> seen;
    for (const auto &o : list.children) {
      if (o.local != "Object" && o.local != "CANopenObject") {
        error(o.at, "unexpected <" + std::string(o.name) + "> in <" + std::string(list.name) +
                        "> (objects only)");
        continue;
      }
      if (diag_.too_many()) return;
      const object_attrs a = attributes_of(o);
      std::uint32_t index = 0;
      if (!hex_attribute(a.index, o, 4, "index", index)) continue;
      auto [it, fresh] = seen.emplace(static_cast<std::uint16_t>(index), &o);
      if (!fresh) {
        error(a.index->value_at, "duplicate object 0x" + hex(index, 4) + " (first at line " +
                                     std::to_string(it->second->at.line) + ")");
        continue;
      }
      object(o, a, static_cast<std::uint16_t>(index));
    }
  }

  bool object_code(const object_attrs &a, const xml::element &e, od::object_code &out) {
    if (a.object_type == nullptr) {
      error(e.at, "<" + std::string(e.name) + "> without objectType");
      return false;
    }
    const int_parse p = parse_int(a.object_type->value, int_syntax::xml);
    const auto v = p.value.to_uint64();
    const od::object_code_info *code =
        p.ok && v && v.value() <= 0xFFU ? od::find_object_code(static_cast<std::uint8_t>(v.value()))
                                        : nullptr;
    if (code == nullptr || code->code == od::object_code::null) {
      error(a.object_type->value_at,
            "expected objectType 2, 5, 6, 7, 8 or 9, got \"" + a.object_type->value + "\"");
      return false;
    }
    out = code->code;
    return true;
  }

  std::string required_name(const object_attrs &a, const xml::element &e) {
    if (a.name != nullptr) return a.name->value;
    error(e.at, "<" + std::string(e.name) + "> without name");
    return {};
  }

  void object(const xml::element &o, const object_attrs &a, std::uint16_t index) {
    object_info info;
    info.index = index;
    info.line = o.at.line;
    info.list = default_list(index);
    if (!object_code(a, o, info.code)) return;
    info.name = required_name(a, o);
    const bool container = info.code == od::object_code::array ||
                           info.code == od::object_code::record ||
                           info.code == od::object_code::defstruct;
    std::vector<const xml::element *> subs;
    for (const auto &c : o.children) {
      if (c.local == "SubObject" || c.local == "CANopenSubObject") {
        subs.push_back(&c);
      } else {
        error(c.at, "unexpected <" + std::string(c.name) + "> in <" + std::string(o.name) +
                        "> (sub-objects only)");
      }
    }
    if (!container) {
      if (!subs.empty()) {
        warning(subs.front()->at, "sub-objects of object 0x" + hex(index, 4) + " (objectType " +
                                      std::string(od::name(info.code)) + ") ignored");
      }
      entry &e = dict_.entries.emplace_back();
      e.index = index;
      e.object = info.code;
      e.line = o.at.line;
      if (!entry_attributes(o, a, e, "object 0x" + hex(index, 4))) {
        dict_.entries.pop_back();
        return;
      }
      dict_.objects[index] = std::move(info);
      return;
    }
    // the container's own value attributes (a RECORD's dataType 0x0420, ...) describe no entry:
    // kept under their CiA 306 keys for the EDS export, as the EDS reader keeps them
    const std::pair<const xml::attribute *, std::string_view> kept[] = {
        {a.data_type, "DataType"},
        {a.access, "AccessType"},
        {a.default_value, "DefaultValue"},
        {a.low, "LowLimit"},
        {a.high, "HighLimit"},
        {a.pdo, "PDOMapping"},
        {a.actual_value, "ParameterValue"},
        {a.denotation, "Denotation"}};
    for (const auto &[attr, key] : kept) {
      if (attr == nullptr) continue;
      info.other_keys.emplace_back(std::string(key), key == "DataType" && is_hex(attr->value)
                                                         ? "0x" + attr->value
                                                         : attr->value);
    }
    if (a.obj_flags != nullptr) {
      std::uint32_t flags = 0;
      if (!obj_flags(a.obj_flags, flags)) return;
      info.obj_flags = flags;
      info.has_obj_flags = true;
    }
    std::set<std::uint8_t> seen;
    bool ok = true;
    for (const xml::element *s : subs) {
      const object_attrs sa = attributes_of(*s);
      std::uint32_t sub = 0;
      if (!hex_attribute(sa.sub_index, *s, 2, "subIndex", sub)) {
        ok = false;
        continue;
      }
      if (!seen.insert(static_cast<std::uint8_t>(sub)).second) {
        error(sa.sub_index->value_at,
              "duplicate sub-object 0x" + hex(index, 4) + " sub-index 0x" + hex(sub, 2));
        ok = false;
        continue;
      }
      entry &e = dict_.entries.emplace_back();
      e.index = index;
      e.sub = static_cast<std::uint8_t>(sub);
      e.object = info.code;
      e.line = s->at.line;
      if (!entry_attributes(*s, sa, e, "object 0x" + hex(index, 4) + " sub 0x" + hex(sub, 2))) {
        dict_.entries.pop_back();
        ok = false;
      }
    }
    if (a.sub_number != nullptr) {
      const int_parse p = parse_int(a.sub_number->value, int_syntax::xml);
      const auto n = p.value.to_uint64();
      if (!p.ok || !n || n.value() > 0xFFU) {
        error(a.sub_number->value_at,
              "expected subNumber 0..255, got \"" + a.sub_number->value + "\"");
        ok = false;
      } else if (n.value() != subs.size()) {
        warning(a.sub_number->value_at, "object 0x" + hex(index, 4) +
                                            " has subNumber=" + a.sub_number->value + " but " +
                                            std::to_string(subs.size()) + " sub-objects");
      }
    }
    if (subs.empty()) {
      warning(o.at, "object 0x" + hex(index, 4) + " (objectType " +
                        std::string(od::name(info.code)) + ") has no sub-objects");
    }
    info.sub_number = static_cast<std::uint8_t>(std::min<std::size_t>(subs.size(), 0xFFU));
    if (ok) dict_.objects[index] = std::move(info);
  }

  bool obj_flags(const xml::attribute *a, std::uint32_t &out) {
    const std::string_view v = a->value;
    const int_parse p = is_hex(v) ? parse_int("0x" + std::string(v), int_syntax::xml)
                                  : parse_int(v, int_syntax::xml);
    const auto n = p.value.to_uint64();
    if (!p.ok || !n || n.value() > 0xFFFF'FFFFU) {
      error(a->value_at, "expected objFlags as a 32-bit number, got \"" + a->value + "\"");
      return false;
    }
    out = static_cast<std::uint32_t>(n.value());
    return true;
  }

  // ---- one entry: attributes of an Object (VAR) or SubObject, with its parameter -------------
  bool entry_attributes(const xml::element &x, const object_attrs &a, entry &e,
                        const std::string &what) {
    e.name = required_name(a, x);
    if (a.name == nullptr) return false;
    if (a.object_type != nullptr && x.local != "Object" && x.local != "CANopenObject") {
      od::object_code code{};
      if (!object_code(a, x, code)) return false;
      if (code != od::object_code::var) {
        warning(a.object_type->value_at, "sub-object of objectType " + std::string(od::name(code)) +
                                             " read as a VAR (" + what + ")");
      }
    }
    const xml::element *param = nullptr;
    if (a.unique_id_ref != nullptr) {
      const auto it = parameters_.find(a.unique_id_ref->value);
      if (it == parameters_.end()) {
        error(a.unique_id_ref->value_at, "uniqueIDRef \"" + a.unique_id_ref->value +
                                             "\" names no <parameter> of the parameterList");
        return false;
      }
      param = it->second;
    }
    if (!data_type(x, a, param, e, what)) return false;
    if (!access(a, param, e)) return false;
    if (!pdo_mapping(a, e)) return false;
    if (a.obj_flags != nullptr) {
      if (!obj_flags(a.obj_flags, e.obj_flags)) return false;
      e.has_obj_flags = true;
    }
    bool ok = true;
    const std::pair<const xml::attribute *, value_role> values[] = {
        {a.default_value, value_role::default_value},
        {a.actual_value, value_role::actual_value},
        {a.low, value_role::low_limit},
        {a.high, value_role::high_limit}};
    for (const auto &[attr, role] : values) {
      if (attr == nullptr) continue;
      const xml_place place{file_, diag_, attr->value_at, std::string(attr->name) + " of " + what};
      ok = value(place, attr->value, e, role) && ok;
    }
    if (param != nullptr) ok = parameter_values(*param, e, what) && ok;
    if (a.actual_value != nullptr) dict_.is_dcf = true;
    if (a.denotation != nullptr) {
      e.denotation = a.denotation->value;
      dict_.is_dcf = true;
    }
    if (ok) {
      const xml_place place{file_, diag_, x.at, what};
      ok = check_value_range(place, e);
    }
    if (od::is_byte_string(e.type) &&
        e.size < std::max(e.default_text.size(), e.parameter_text.size())) {
      e.size = static_cast<std::uint32_t>(std::max(e.default_text.size(), e.parameter_text.size()));
    }
    return ok;
  }

  bool value(const xml_place &place, std::string_view text, entry &e, value_role role) {
    // POWERLINK MAC_ADDRESS "00:11:22:33:44:55" and IP_ADDRESS "192.168.100.1": their bytes
    if (e.type_code == xdd::mac_address || e.type_code == xdd::ip_address) {
      if (role == value_role::low_limit || role == value_role::high_limit) {
        return read_xml_value(place, text, e, role); // a warning: DOMAIN has no limits
      }
      std::string bytes;
      if (!address_bytes(text, e.type_code == xdd::mac_address, bytes)) {
        place.diag.error(place.file, place.at.line, place.at.column,
                         std::string("expected ") +
                             (e.type_code == xdd::mac_address
                                  ? "a MAC address such as 00:11:22:33:44:55"
                                  : "an IP address such as 192.168.100.1") +
                             ", got \"" + std::string(text) + "\" in " + place.what);
        return false;
      }
      (role == value_role::default_value ? e.default_text : e.parameter_text) = bytes;
      return true;
    }
    return read_xml_value(place, text, e, role);
  }

  static bool address_bytes(std::string_view t, bool mac, std::string &out) {
    const char sep = mac ? ':' : '.';
    const std::size_t parts = mac ? 6U : 4U;
    std::size_t start = 0;
    for (std::size_t i = 0; i < parts; ++i) {
      const auto end = i + 1U < parts ? t.find(sep, start) : t.size();
      if (end == std::string_view::npos) return false;
      const std::string_view part = t.substr(start, end - start);
      unsigned v = 0;
      if (part.empty() || part.size() > (mac ? 2U : 3U)) return false;
      for (const char c : part) {
        const int d = mac ? ascii::hex_value(c) : (ascii::is_digit(c) ? c - '0' : -1);
        if (d < 0) return false;
        v = v * (mac ? 16U : 10U) + static_cast<unsigned>(d);
      }
      if (v > 255U) return false;
      out += static_cast<char>(v);
      start = end + 1U;
    }
    return true;
  }

  bool data_type(const xml::element &x, const object_attrs &a, const xml::element *param, entry &e,
                 const std::string &what) {
    std::uint16_t code = 0;
    xml::position at = x.at;
    if (a.data_type != nullptr) {
      std::uint32_t c = 0;
      if (!hex_attribute(a.data_type, x, 4, "dataType", c)) return false;
      code = static_cast<std::uint16_t>(c);
      at = a.data_type->value_at;
    }
    std::uint16_t param_code = 0;
    if (param != nullptr) {
      for (const auto &c : param->children) {
        const auto it = std::find_if(std::begin(iec_types), std::end(iec_types),
                                     [&](const iec_type &t) { return t.name == c.local; });
        if (it != std::end(iec_types)) {
          param_code = it->code;
          if (code == 0 && c.local == "BITSTRING" && bitstring_.count++ == 0) bitstring_.at = c.at;
          if (code == 0) at = c.at;
          break;
        }
      }
    }
    if (code == 0 && param_code == 0 && param != nullptr &&
        param->find_child("dataTypeIDRef") != nullptr && e.sub == 0 &&
        (e.object == od::object_code::var || e.object == od::object_code::domain)) {
      // EPSG DS 311: a VAR typed by a structure of the dataTypeList is a DOMAIN that holds it
      code = 0x000F;
      if (struct_domain_.count++ == 0) struct_domain_.at = x.at;
    }
    if (code == 0) code = param_code;
    if (code == 0) {
      error(x.at, "no data type for " + what +
                      " (neither a dataType attribute nor an IEC type in its parameter)");
      return false;
    }
    if (param_code != 0 && param_code != code &&
        !(param_code == 0x000A && (code == 0x000F || code == 0x000A))) {
      warning(at, "dataType 0x" + hex(code, 4) + " of " + what +
                      " differs from its parameter's 0x" + hex(param_code, 4) +
                      "; the dataType attribute is used");
    }
    e.type_code = code;
    if (const od::data_type_info *t = od::find_data_type(code)) {
      e.type = t->type;
      return true;
    }
    e.type = od::data_type::domain;
    const auto pl =
        std::find_if(std::begin(xdd::powerlink_types), std::end(xdd::powerlink_types),
                     [&](const xdd::type_name &t) { return t.code == code && t.bytes != 0U; });
    const auto defined = defined_types_.find(code);
    // complex and vendor types of CiA 301 (0x0020..0x025F) and EPSG DS 301 (0x0401..0x04FF)
    const bool type_area =
        (code >= 0x0020U && code <= 0x025FU) || (code >= 0x0401U && code <= 0x04FFU);
    if (pl == std::end(xdd::powerlink_types) && defined == defined_types_.end() && !type_area) {
      error(at, "unknown data type 0x" + hex(code, 4) + " of " + what +
                    ": not a CiA 301 basic type, not in a data type area (0x0020-0x025F, "
                    "0x0401-0x04FF) and not defined in the file's <DataTypeList>");
      return false;
    }
    auto &u = extended_use_[code];
    if (u.count++ == 0) {
      u.at = at;
      u.name = pl != std::end(xdd::powerlink_types) ? std::string(pl->name)
               : defined != defined_types_.end()    ? defined->second
                                                    : std::string();
    }
    if (pl != std::end(xdd::powerlink_types)) {
      e.size = pl->bytes;
      e.size_declared = true;
    }
    return true;
  }

  bool access(const object_attrs &a, const xml::element *param, entry &e) {
    if (a.access != nullptr) {
      const od::access_info *acc = od::find_access(to_lower(a.access->value));
      if (acc == nullptr) {
        error(a.access->value_at,
              "expected accessType const, ro, wo, rw, rwr or rww, got \"" + a.access->value + "\"");
        return false;
      }
      e.access = acc->value;
      return true;
    }
    if (param != nullptr) {
      const xml::attribute *pa = param->find_attribute("access");
      const std::string v = pa != nullptr ? pa->value : "read"; // ISO 15745's default
      const std::pair<std::string_view, od::access> map[] = {
          {"const", od::access::constant},     {"read", od::access::ro},
          {"write", od::access::wo},           {"readWrite", od::access::rw},
          {"readWriteInput", od::access::rwr}, {"readWriteOutput", od::access::rww}};
      for (const auto &[name, acc] : map) {
        if (name == v) {
          e.access = acc;
          return true;
        }
      }
      error(pa->value_at, "expected access const, read, write, readWrite, readWriteInput or "
                          "readWriteOutput, got \"" +
                              v + "\"");
      return false;
    }
    e.access = od::access::ro;
    return true;
  }

  bool pdo_mapping(const object_attrs &a, entry &e) {
    if (a.pdo == nullptr) return true;
    const std::string &v = a.pdo->value;
    if (v == "no") {
      e.pdo = od::pdo_mapping::no;
    } else if (v == "optional") {
      e.pdo = od::pdo_mapping::yes;
    } else if (v == "default") {
      e.pdo = od::pdo_mapping::yes;
      if (pdo_default_.count++ == 0) pdo_default_.at = a.pdo->value_at;
    } else if (v == "TPDO") {
      e.pdo = od::pdo_mapping::tx;
    } else if (v == "RPDO") {
      e.pdo = od::pdo_mapping::rx;
    } else {
      error(a.pdo->value_at,
            "expected PDOmapping no, default, optional, TPDO or RPDO, got \"" + v + "\"");
      return false;
    }
    return true;
  }

  // The parameter's defaultValue, actualValue, allowedValues (a range, or a list kept as its
  // range) where the object's attributes give none; CO_stringLengthMin as a string's capacity.
  bool parameter_values(const xml::element &p, entry &e, const std::string &what) {
    bool ok = true;
    if (p.find_child("label") != nullptr) (void)label_text(p); // notes other languages
    const std::pair<std::string_view, value_role> simple[] = {
        {"defaultValue", value_role::default_value}, {"actualValue", value_role::actual_value}};
    for (const auto &c : p.children) {
      if (c.local == "label") {
        continue;
      } else if (c.local == "description") {
        not_kept(c, "documentation texts");
        continue;
      }
      if (std::any_of(std::begin(iec_types), std::end(iec_types),
                      [&](const iec_type &t) { return t.name == c.local; }) ||
          c.local == "dataTypeIDRef") {
        continue;
      }
      bool handled = false;
      for (const auto &[name, role] : simple) {
        if (c.local != name) continue;
        handled = true;
        const xml::attribute *v = c.find_attribute("value");
        if (v == nullptr) {
          error(c.at, "<" + std::string(c.name) + "> without value");
          ok = false;
          continue;
        }
        if (role == value_role::actual_value) dict_.is_dcf = true;
        if (already(e, role)) continue; // the object's attribute wins
        ok = value({file_, diag_, v->value_at, "parameter " + std::string(name) + " of " + what},
                   v->value, e, role) &&
             ok;
      }
      if (handled) continue;
      if (c.local == "allowedValues") {
        ok = allowed_values(c, e, what) && ok;
      } else if (c.local == "property") {
        const xml::attribute *n = c.find_attribute("name");
        const xml::attribute *v = c.find_attribute("value");
        if (n != nullptr && v != nullptr && n->value == "CO_stringLengthMin" &&
            od::is_byte_string(e.type)) {
          const int_parse ip = parse_int(v->value, int_syntax::xml);
          const auto len = ip.value.to_uint64();
          if (ip.ok && len && len.value() > 0U && len.value() <= 0xFFFF'FFFFU) {
            e.size = std::max(e.size, static_cast<std::uint32_t>(len.value()));
            e.size_declared = true;
            continue;
          }
        }
        not_kept(c, "tool properties");
      } else {
        not_kept(c);
      }
    }
    return ok;
  }

  static bool already(const entry &e, value_role role) {
    switch (role) {
    case value_role::default_value:
      return e.default_value.has_value() || e.default_nodeid || !e.default_text.empty();
    case value_role::actual_value:
      return e.parameter_value.has_value() || e.parameter_nodeid || !e.parameter_text.empty();
    case value_role::low_limit: return e.low.has_value() || e.low_nodeid;
    case value_role::high_limit: return e.high.has_value() || e.high_nodeid;
    }
    return false;
  }

  bool allowed_values(const xml::element &av, entry &e, const std::string &what) {
    bool ok = true;
    std::vector<const xml::attribute *> list;
    for (const auto &c : av.children) {
      if (c.local == "range") {
        for (const auto &m : c.children) {
          const xml::attribute *v = m.find_attribute("value");
          const value_role role =
              m.local == "minValue" ? value_role::low_limit : value_role::high_limit;
          if ((m.local != "minValue" && m.local != "maxValue") || v == nullptr) {
            error(m.at, "expected <minValue value=\"…\"/> or <maxValue value=\"…\"/> in <range>");
            ok = false;
            continue;
          }
          if (already(e, role)) continue;
          ok = value({file_, diag_, v->value_at, "allowed " + std::string(m.local) + " of " + what},
                     v->value, e, role) &&
               ok;
        }
      } else if (c.local == "value") {
        if (const xml::attribute *v = c.find_attribute("value")) list.push_back(v);
      } else {
        not_kept(c);
      }
    }
    if (!list.empty() && !already(e, value_role::low_limit) &&
        !already(e, value_role::high_limit)) {
      // a list of allowed values: its least and greatest as the limits, with a warning
      entry lo = e;
      entry hi = e;
      bool first = true;
      for (const xml::attribute *v : list) {
        entry t = e;
        if (!value({file_, diag_, v->value_at, "allowed value of " + what}, v->value, t,
                   value_role::low_limit)) {
          ok = false;
          continue;
        }
        const auto d = t.low.to_decimal();
        if (!d) continue;
        if (first || compare(d.value(), lo.low.to_decimal().value()) < 0) lo.low = t.low;
        if (first || compare(d.value(), hi.low.to_decimal().value()) > 0) hi.low = t.low;
        first = false;
      }
      if (!first) {
        e.low = lo.low;
        e.high = hi.low;
        warning(av.at, "the list of " + std::to_string(list.size()) + " allowed values of " + what +
                           " is kept as its range (the model has limits, not lists)");
      }
    }
    return ok;
  }

  struct usage {
    std::size_t count = 0;
    xml::position at;
    std::string name;
  };
  struct dropped {
    std::size_t count = 0;
    xml::position at;
    std::string why;
  };

  const std::string &file_;
  diagnostics &diag_;
  dictionary dict_;
  bool files_done_ = false;
  std::map<std::string, const xml::element *, std::less<>> parameters_;
  std::map<std::uint16_t, std::string> defined_types_;
  std::map<std::string, dropped> dropped_;
  std::map<std::uint16_t, usage> extended_use_;
  usage bitstring_, pdo_default_, struct_domain_;
  std::vector<std::string> other_languages_, languages_;
  xml::position languages_at_;
};

} // namespace

std::optional<dictionary> read_xdd_document(const xml::document &doc, const std::string &file,
                                            diagnostics &diag) {
  xdd_reader r(file, diag);
  return r.read(doc);
}

std::optional<dictionary> read_xdd(std::string_view bytes, const std::string &file,
                                   diagnostics &diag) {
  const auto doc = xml::parse(bytes, file, diag);
  if (!doc) return std::nullopt;
  return read_xdd_document(*doc, file, diag);
}

} // namespace fieldcodec::gen
