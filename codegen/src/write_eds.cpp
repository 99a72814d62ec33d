// fieldcodec-gen — CiA 306 EDS/DCF writer (normalised form: hex indices, explicit sub-object
// sections instead of CompactSubObj, LF line endings, objects in index order). It writes
// everything the EDS reader keeps: keys and sections it does not interpret are written back as
// they were read.
#include "options.hpp"
#include "readers.hpp"
#include "text.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <fieldcodec/core/scaling.hpp>

namespace fieldcodec::gen {

namespace {

std::string eds_number(const od::number &n, bool nodeid) {
  std::string s;
  switch (n.kind) {
  case od::number_kind::none: return nodeid ? "$NODEID" : "";
  case od::number_kind::signed_: s = std::to_string(static_cast<std::int64_t>(n.bits)); break;
  case od::number_kind::unsigned_: s = "0x" + hex(n.bits, 1); break;
  case od::number_kind::real: {
    std::array<char, 64> buf{};
    auto [p, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), n.to_double());
    s.assign(buf.data(), p);
    break;
  }
  case od::number_kind::decimal_: {
    std::array<char, 48> buf{};
    auto r = format_decimal(decimal{static_cast<std::int64_t>(n.bits), n.places}, buf);
    s.assign(buf.data(), r ? r.value() : 0U);
    break;
  }
  }
  return nodeid ? "$NODEID+" + s : s;
}

// Text as an EDS value: readers trim the spaces around a value, so they are not written
// (a CSV name printed with a trailing space, DPQ "BackP: Pres 4Ds ", would otherwise change
// on every EDS pass — fuzz F13).
std::string eds_text(const std::string &s) { return std::string(trim(s)); }

// A byte string's value as text: OCTET_STRING / DOMAIN as hex digits, UNICODE_STRING as UTF-8.
// Text the reader would change (surrounding blanks, which it trims; surrounding double quotes,
// which it removes) is written in double quotes.
std::string eds_string(const entry &e, const std::string &bytes) {
  std::string t = byte_string_text(e.type, bytes);
  if (e.type != od::data_type::visible_string && e.type != od::data_type::unicode_string) return t;
  const bool blank =
      !t.empty() && (t.front() == ' ' || t.front() == '\t' || t.back() == ' ' || t.back() == '\t');
  const bool quoted = t.size() >= 2U && t.front() == '"' && t.back() == '"';
  return blank || quoted ? '"' + t + '"' : t;
}

void other_keys(std::string &o, const key_list &keys) {
  for (const auto &[k, v] : keys) o += k + "=" + v + "\n";
}

void var_keys(std::string &o, const entry &e, bool dcf) {
  o += "ParameterName=" + eds_text(e.name) + "\n";
  o += "ObjectType=0x" +
       hex(static_cast<std::uint8_t>(e.sub == 0 && (e.object == od::object_code::var ||
                                                    e.object == od::object_code::domain ||
                                                    e.object == od::object_code::deftype)
                                         ? e.object
                                         : od::object_code::var),
           1) +
       "\n";
  const std::uint16_t type = e.type_code != 0U ? e.type_code : static_cast<std::uint16_t>(e.type);
  o += "DataType=0x" + hex(type, 4) + "\n";
  o += "AccessType=" + std::string(od::name(e.access)) + "\n";
  if (od::is_byte_string(e.type)) {
    if (!e.default_text.empty()) o += "DefaultValue=" + eds_string(e, e.default_text) + "\n";
  } else if (e.default_value || e.default_nodeid) {
    o += "DefaultValue=" + entry_number(e, e.default_value, e.default_nodeid) + "\n";
  }
  if (!od::is_byte_string(e.type)) { // limits of a string are not expressible in an EDS
    if (e.low || e.low_nodeid) o += "LowLimit=" + limit_number(e, e.low, e.low_nodeid) + "\n";
    if (e.high || e.high_nodeid) o += "HighLimit=" + limit_number(e, e.high, e.high_nodeid) + "\n";
  }
  o += std::string("PDOMapping=") + (e.pdo == od::pdo_mapping::no ? "0" : "1") + "\n";
  if (od::is_byte_string(e.type) && e.size != 0U) o += "Size=" + std::to_string(e.size) + "\n";
  if (e.has_obj_flags) o += "ObjFlags=0x" + hex(e.obj_flags, 1) + "\n";
  if (dcf) {
    if (od::is_byte_string(e.type)) {
      if (!e.parameter_text.empty()) {
        o += "ParameterValue=" + eds_string(e, e.parameter_text) + "\n";
      }
    } else if (e.parameter_value || e.parameter_nodeid) {
      o += "ParameterValue=" + entry_number(e, e.parameter_value, e.parameter_nodeid) + "\n";
    }
    if (!e.denotation.empty()) o += "Denotation=" + eds_text(e.denotation) + "\n";
  }
  other_keys(o, e.other_keys);
}

} // namespace

// A number of an entry in the form the EDS reader reads back unchanged: values of unsigned
// types are written in hex whatever kind the source gave them (a CSV "0" is read as signed, an
// EDS "0x0" as unsigned), so CSV -> EDS -> EDS is a fixed point (fuzz F5).
std::string entry_number(const entry &e, const od::number &n, bool nodeid) {
  if (n.kind == od::number_kind::signed_ && od::is_unsigned_integer(e.type) &&
      static_cast<std::int64_t>(n.bits) >= 0) {
    return eds_number(od::unsigned_number(n.bits), nodeid);
  }
  return eds_number(n, nodeid);
}

// A limit as a raw value: CSV limits of scaled entries are engineering units.
std::string limit_number(const entry &e, const od::number &n, bool nodeid) {
  if (!n && !nodeid) return "";
  if (e.scaled && !nodeid && od::is_integer(e.type)) {
    auto d = n.to_decimal();
    if (d) {
      auto raw = scaling::scale_to_raw(d.value(), scaling::linear{e.scale, e.offset});
      if (raw) {
        // An EDS limit must be a value of the object's type: a printed range wider than the
        // field (flag range_exceeds_field) is cut to what the field can hold.
        std::int64_t v = raw.value();
        const auto width = od::fixed_size(e.type);
        const scaling::field f{static_cast<std::uint8_t>(width), od::is_signed_integer(e.type)};
        if (width >= 1U && width <= 8U) {
          if (v < f.min()) v = f.min();
          if (v > f.max()) v = f.max();
        }
        return v < 0 || od::is_signed_integer(e.type)
                   ? std::to_string(v)
                   : eds_number(od::unsigned_number(static_cast<std::uint64_t>(v)), false);
      }
    }
  }
  return entry_number(e, n, nodeid);
}

void add_mandatory_objects(dictionary &d) {
  auto add = [&](std::uint16_t index, od::object_code code, std::string name,
                 std::vector<entry> subs) {
    if (d.objects.count(index) != 0U) return;
    object_info info;
    info.index = index;
    info.code = code;
    info.name = name;
    info.list = object_list::mandatory;
    info.sub_number = code == od::object_code::var ? 0 : static_cast<std::uint8_t>(subs.size());
    d.objects[index] = info;
    for (auto &e : subs) {
      e.index = index;
      d.entries.push_back(std::move(e));
    }
  };
  auto var = [](std::uint8_t sub, std::string name, od::data_type t, od::number def) {
    entry e;
    e.sub = sub;
    e.name = std::move(name);
    e.type = t;
    e.type_code = static_cast<std::uint16_t>(t);
    e.access = od::access::ro;
    e.default_value = def;
    return e;
  };
  add(0x1000, od::object_code::var, "Device type",
      {var(0, "Device type", od::data_type::unsigned32, od::unsigned_number(0))});
  add(0x1001, od::object_code::var, "Error register",
      {var(0, "Error register", od::data_type::unsigned8, od::unsigned_number(0))});
  add(0x1018, od::object_code::record, "Identity object",
      {var(0, "Highest sub-index supported", od::data_type::unsigned8, od::unsigned_number(1)),
       var(1, "Vendor-ID", od::data_type::unsigned32, od::unsigned_number(0))});
  for (auto &e : d.entries) {
    if (e.index == 0x1018U) e.object = od::object_code::var;
  }
  std::stable_sort(d.entries.begin(), d.entries.end(), [](const entry &a, const entry &b) {
    return a.index != b.index ? a.index < b.index : a.sub < b.sub;
  });
}

namespace {

// [FileInfo], [DeviceInfo] (as read; CSV tables get a minimal set naming the source),
// [DummyUsage], [Comments], [DeviceComissioning].
void header_sections(std::string &o, const dictionary &d) {
  auto copy_or = [&](const key_list &kv, const key_list &fallback) {
    for (const auto &[k, v] : kv.empty() ? fallback : kv) o += k + "=" + v + "\n";
  };
  o += "[FileInfo]\n";
  copy_or(d.file_info, {{"FileName", d.stem + (d.is_dcf ? ".dcf" : ".eds")},
                        {"FileVersion", "1"},
                        {"FileRevision", "0"},
                        {"EDSVersion", "4.0"},
                        {"Description", "Written by fieldcodec-gen from " + d.source_name},
                        {"CreatedBy", "fieldcodec-gen"}});
  o += "\n[DeviceInfo]\n";
  copy_or(d.device_info, {{"VendorName", ""},
                          {"ProductName", d.stem},
                          {"BaudRate_10", "0"},
                          {"BaudRate_20", "0"},
                          {"BaudRate_50", "0"},
                          {"BaudRate_125", "1"},
                          {"BaudRate_250", "1"},
                          {"BaudRate_500", "1"},
                          {"BaudRate_800", "0"},
                          {"BaudRate_1000", "1"},
                          {"SimpleBootUpMaster", "0"},
                          {"SimpleBootUpSlave", "1"},
                          {"Granularity", "8"},
                          {"DynamicChannelsSupported", "0"},
                          {"GroupMessaging", "0"},
                          {"NrOfRXPDO", "0"},
                          {"NrOfTXPDO", "0"},
                          {"LSS_Supported", "0"}});
  if (!d.dummy_usage.empty()) {
    o += "\n[DummyUsage]\n";
    copy_or(d.dummy_usage, {});
  }
  if (!d.comments.empty()) {
    o += "\n[Comments]\nLines=" + std::to_string(d.comments.size()) + "\n";
    for (std::size_t i = 0; i < d.comments.size(); ++i) {
      o += "Line" + std::to_string(i + 1U) + "=" + d.comments[i] + "\n";
    }
  }
  if (d.is_dcf && !d.commissioning.empty()) {
    o += "\n[DeviceComissioning]\n";
    other_keys(o, d.commissioning);
  } else if (d.is_dcf && d.node_id > 0) {
    o += "\n[DeviceComissioning]\nNodeID=" + std::to_string(d.node_id) + "\n";
    if (!d.node_name.empty()) o += "NodeName=" + d.node_name + "\n";
  }
}

void object_lists(std::string &o, const dictionary &d) {
  const std::pair<const char *, object_list> lists[] = {
      {"MandatoryObjects", object_list::mandatory},
      {"OptionalObjects", object_list::optional},
      {"ManufacturerObjects", object_list::manufacturer}};
  for (const auto &[list_name, list] : lists) {
    std::vector<std::uint16_t> idx;
    for (const auto &[index, info] : d.objects) {
      if (index >= 0x1000U && info.list == list) idx.push_back(index);
    }
    o +=
        std::string("\n[") + list_name + "]\nSupportedObjects=" + std::to_string(idx.size()) + "\n";
    for (std::size_t i = 0; i < idx.size(); ++i) {
      o += std::to_string(i + 1U) + "=0x" + hex(idx[i], 4) + "\n";
    }
  }
}

// One object: its section, its sub-object sections (entries[first, first + n)), its links.
void object_sections(std::string &o, const dictionary &d, std::uint16_t index,
                     const object_info &info, std::size_t first, std::size_t n) {
  const bool single_code = info.code == od::object_code::var ||
                           info.code == od::object_code::domain ||
                           info.code == od::object_code::deftype;
  o += "\n[" + hex(index, 4) + "]\n";
  if (single_code && n == 1U && d.entries[first].sub == 0U) {
    var_keys(o, d.entries[first], d.is_dcf);
  } else {
    o += "ParameterName=" + eds_text(info.name) + "\n";
    // Written with sub-object sections: VAR, DOMAIN and DEFTYPE objects (which the reader
    // accepts with a SubNumber, leniently) become RECORD, the code its reader expects for a
    // container; DEFTYPE with SubNumber was written back unreadable (fuzz F12).
    const auto code = single_code ? od::object_code::record : info.code;
    o += "ObjectType=0x" + hex(static_cast<std::uint8_t>(code), 1) + "\n";
    if (info.has_obj_flags) o += "ObjFlags=0x" + hex(info.obj_flags, 1) + "\n";
    o += "SubNumber=" + std::to_string(n) + "\n";
    other_keys(o, info.other_keys);
    for (std::size_t k = first; k < first + n; ++k) {
      o += "\n[" + hex(index, 4) + "sub" + hex(d.entries[k].sub, 1) + "]\n";
      var_keys(o, d.entries[k], d.is_dcf);
    }
  }
  if (!info.object_links.empty()) {
    o += "\n[" + hex(index, 4) +
         "ObjectLinks]\nObjectLinks=" + std::to_string(info.object_links.size()) + "\n";
    for (std::size_t k = 0; k < info.object_links.size(); ++k) {
      o += std::to_string(k + 1U) + "=0x" + hex(info.object_links[k], 4) + "\n";
    }
  }
}

} // namespace

std::string write_eds(const dictionary &dict) {
  // runs of alike sub-objects (--compact-arrays) are written one section per sub-object
  const bool runs = std::any_of(dict.entries.begin(), dict.entries.end(),
                                [](const entry &e) { return e.count > 1U; });
  dictionary expanded;
  if (runs) {
    expanded = dict;
    expand_runs(expanded);
  }
  const dictionary &d = runs ? expanded : dict;
  std::string o;
  o.reserve(d.entries.size() * 120U + 2048U);
  header_sections(o, d);
  object_lists(o, d);
  std::size_t i = 0;
  for (const auto &[index, info] : d.objects) {
    while (i < d.entries.size() && d.entries[i].index < index) ++i;
    std::size_t n = 0;
    while (i + n < d.entries.size() && d.entries[i + n].index == index) ++n;
    object_sections(o, d, index, info, i, n);
    i += n;
  }
  for (const auto &s : d.other_sections) {
    o += "\n[" + s.name + "]\n";
    other_keys(o, s.keys);
  }
  return o;
}

} // namespace fieldcodec::gen
