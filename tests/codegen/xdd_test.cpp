// fieldcodec-gen's XDD/XDC reader and writer (codegen/src/xdd_reader.cpp, write_xdd.cpp): the
// hand-written fixtures (tests/codegen/fixtures/xdd/), exact diagnostics for bad input, the
// round trips XDD → XDD, XDD → EDS → XDD, EDS → XDD → EDS, and the XENAX dictionaries written
// as XDD and read back equal.
#include "config_list.hpp"
#include "readers.hpp"
#include "text.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

namespace gen = fieldcodec::gen;
namespace od = fieldcodec::od;

namespace {

struct outcome {
  std::optional<gen::dictionary> dict;
  std::vector<std::string> diags;
};

outcome read(const std::string &path) {
  gen::diagnostics d;
  outcome o;
  o.dict = gen::read_file(path, d);
  for (const auto &x : d.sorted()) o.diags.push_back(gen::diagnostics::format(x));
  if (d.has_errors()) o.dict.reset();
  return o;
}

outcome read_xdd_text(const std::string &text, const std::string &name) {
  gen::diagnostics d;
  outcome o;
  o.dict = gen::read_xdd(text, name, d);
  for (const auto &x : d.sorted()) o.diags.push_back(gen::diagnostics::format(x));
  return o;
}

const gen::entry &at(const gen::dictionary &d, std::uint16_t index, std::uint8_t sub) {
  for (const auto &e : d.entries) {
    if (e.index == index && e.sub == sub) return e;
  }
  FAIL("no entry ", index, " sub ", int{sub});
  static const gen::entry none;
  return none;
}

std::string text(const gen::rare_text &t) { return t.str(); }

// The same objects and entries as far as the model says (the source line aside).
void check_same(const gen::dictionary &a, const gen::dictionary &b) {
  REQUIRE(a.entries.size() == b.entries.size());
  for (std::size_t i = 0; i < a.entries.size(); ++i) {
    const gen::entry &x = a.entries[i];
    const gen::entry &y = b.entries[i];
    CAPTURE(x.index);
    CAPTURE(int{x.sub});
    CHECK(x.index == y.index);
    CHECK(x.sub == y.sub);
    CHECK(x.object == y.object);
    CHECK(x.type_code == y.type_code);
    CHECK(x.type == y.type);
    CHECK(x.access == y.access);
    CHECK(x.pdo == y.pdo);
    CHECK(x.name == y.name);
    CHECK(x.size == y.size);
    CHECK(x.low == y.low);
    CHECK(x.high == y.high);
    CHECK(x.default_value == y.default_value);
    CHECK(x.parameter_value == y.parameter_value);
    CHECK(x.low_nodeid == y.low_nodeid);
    CHECK(x.high_nodeid == y.high_nodeid);
    CHECK(x.default_nodeid == y.default_nodeid);
    CHECK(x.parameter_nodeid == y.parameter_nodeid);
    CHECK(text(x.default_text) == text(y.default_text));
    CHECK(text(x.parameter_text) == text(y.parameter_text));
    CHECK(x.denotation == y.denotation);
    CHECK(x.has_obj_flags == y.has_obj_flags);
    CHECK(x.obj_flags == y.obj_flags);
  }
  REQUIRE(a.objects.size() == b.objects.size());
  for (const auto &object : a.objects) {
    const auto index = object.first; // CAPTURE's lambda cannot name a structured binding (clang 14)
    const auto &info = object.second;
    CAPTURE(index);
    const auto it = b.objects.find(index);
    REQUIRE(it != b.objects.end());
    CHECK(info.code == it->second.code);
    CHECK(info.name == it->second.name);
  }
  CHECK(a.node_id == b.node_id);
  CHECK(a.is_dcf == b.is_dcf);
}

gen::dictionary xdd_round_trip(const gen::dictionary &d, gen::bus_profile profile,
                               std::vector<std::string> *lost = nullptr) {
  gen::diagnostics w;
  const std::string x = gen::write_xdd(d, profile, "src", w);
  if (lost != nullptr) {
    for (const auto &l : w.all()) lost->push_back(gen::diagnostics::format(l));
  }
  gen::diagnostics r;
  auto back = gen::read_xdd(x, "back.xdd", r);
  INFO(r.text());
  REQUIRE(back.has_value());
  CHECK(r.error_count() == 0U);
  return std::move(*back);
}

} // namespace

TEST_CASE("xdd: a POWERLINK device description") {
  const outcome o = read("codegen/fixtures/xdd/powerlink.xdd");
  REQUIRE(o.dict);
  const gen::dictionary &d = *o.dict;
  CHECK(d.profile == gen::bus_profile::powerlink);
  CHECK(o.diags == std::vector<std::string>{
                       "codegen/fixtures/xdd/powerlink.xdd:26:7: warning: <DeviceFunction> is not "
                       "kept (descriptive: characteristics, pictures, connectors)",
                       "codegen/fixtures/xdd/powerlink.xdd:66:91: warning: data type 0x0401 "
                       "(MAC_ADDRESS) of 1 entry is not a CiA 301 basic type; its value is kept "
                       "as DOMAIN",
                       "codegen/fixtures/xdd/powerlink.xdd:67:80: warning: data type 0x0402 "
                       "(IP_ADDRESS) of 1 entry is not a CiA 301 basic type; its value is kept as "
                       "DOMAIN",
                       "codegen/fixtures/xdd/powerlink.xdd:70: warning: RPDO 1 has a mapping "
                       "parameter 0x1600 but no communication parameter 0x1400 (CiA 301: a PDO "
                       "has both; masters that configure the PDO fail on it)"});
  CHECK(d.objects.size() == 10U);
  CHECK(d.entries.size() == 18U);
  CHECK(at(d, 0x1000, 0).default_value == od::unsigned_number(0x000F0191));
  CHECK(at(d, 0x1000, 0).access == od::access::constant);
  const gen::entry &cycle = at(d, 0x1006, 0);
  CHECK(cycle.low == od::unsigned_number(400));
  CHECK(cycle.high == od::unsigned_number(100000));
  CHECK(text(at(d, 0x1008, 0).default_text) == "Fixture <CN>");
  CHECK(at(d, 0x1008, 0).size == 12U);
  CHECK(at(d, 0x1018, 2).default_value == od::unsigned_number(0x1234));
  CHECK(d.objects.at(0x1018).code == od::object_code::record);
  // the RECORD's own dataType describes no entry: kept as an EDS key
  CHECK(d.objects.at(0x1018).other_keys == gen::key_list{{"DataType", "0x0023"}});
  const gen::entry &mac = at(d, 0x1030, 1);
  CHECK(mac.type_code == 0x0401);
  CHECK(mac.type == od::data_type::domain);
  CHECK(text(mac.default_text) == std::string("\x00\x60\x65\x0A\x0B\xFF", 6));
  CHECK(mac.size == 6U);
  CHECK(text(at(d, 0x1030, 2).default_text) == "\xC0\xA8\x64\x01");
  CHECK(at(d, 0x1030, 3).default_value == od::signed_number(1)); // BOOLEAN "true"
  CHECK(at(d, 0x1600, 1).default_value == od::unsigned_number(0x0008000000016200U));
  CHECK(at(d, 0x1F93, 1).default_nodeid);
  CHECK(at(d, 0x2000, 0).default_value.to_double() == doctest::Approx(3.14159274));
  const gen::entry &offset = at(d, 0x2001, 0);
  CHECK(offset.default_value == od::signed_number(-1)); // INTEGER16 0xFFFF: the bit pattern
  CHECK(offset.low == od::signed_number(-100));
  CHECK(offset.high == od::signed_number(100));
  CHECK(offset.pdo == od::pdo_mapping::yes);
  CHECK(at(d, 0x6200, 1).pdo == od::pdo_mapping::rx);
  // identity, file information and the POWERLINK features
  const auto key = [](const gen::key_list &l, const std::string &k) {
    for (const auto &[n, v] : l) {
      if (n == k) return v;
    }
    return std::string("<none>");
  };
  CHECK(key(d.device_info, "VendorName") == "Fixture & Co.");
  CHECK(key(d.device_info, "VendorNumber") == "0x0000ABCD");
  CHECK(key(d.device_info, "ProductNumber") == "0x00001234");
  CHECK(key(d.file_info, "CreationDate") == "01-27-2025");
  CHECK(key(d.file_info, "CreationTime") == "10:00:00+01:00");
  REQUIRE(d.other_sections.size() == 6U);
  CHECK(d.other_sections[0].name == "XDD.ProfileBody");
  CHECK(d.other_sections[0].keys == gen::key_list{{"supportedLanguages", "en"}});
  CHECK(d.other_sections[1].name == "XDD.DeviceIdentity");
  CHECK(d.other_sections[1].keys ==
        gen::key_list{{"version.HW", "1.00"}, {"version.FW", "FW 2.7"}});
  CHECK(d.other_sections[2].name == "XDD.identity");
  CHECK(d.other_sections[3].name == "XDD.GeneralFeatures");
  CHECK(d.other_sections[3].keys.size() == 5U);
  CHECK(d.other_sections[4].name == "XDD.CNFeatures");
  CHECK(d.other_sections[5].name == "XDD.Diagnostic");
}

TEST_CASE("xdd: a CANopen device description with ApplicationProcess parameters") {
  const outcome o = read("codegen/fixtures/xdd/canopen.xdd");
  REQUIRE(o.dict);
  const gen::dictionary &d = *o.dict;
  CHECK(d.profile == gen::bus_profile::canopen);
  CHECK(o.diags ==
        std::vector<std::string>{
            "codegen/fixtures/xdd/canopen.xdd:26:11: warning: labels in de are not kept (names "
            "are the objects' name attributes)",
            "codegen/fixtures/xdd/canopen.xdd:29:13: warning: the list of 3 allowed values of "
            "object 0x2000 is kept as its range (the model has limits, not lists)",
            "codegen/fixtures/xdd/canopen.xdd:31:49: warning: <description> is not kept "
            "(documentation texts)",
            "codegen/fixtures/xdd/canopen.xdd:31:102: warning: IEC type BITSTRING of 1 entry read "
            "as OCTET_STRING (CiA 311 writes OCTET_STRING and DOMAIN alike; a dataType attribute "
            "tells them apart)",
            "codegen/fixtures/xdd/canopen.xdd:69:85: warning: PDOmapping=\"default\" of 1 entry "
            "read as mappable (the model, like an EDS, does not tell a default mapping from an "
            "optional one)"});
  // types, access and values from the parameters the uniqueIDRefs name
  const gen::entry &hb = at(d, 0x1017, 0);
  CHECK(hb.type == od::data_type::unsigned16);
  CHECK(hb.access == od::access::rw);
  CHECK(hb.default_value == od::unsigned_number(1000));
  CHECK(hb.high == od::unsigned_number(60000));
  CHECK(at(d, 0x1000, 0).access == od::access::ro); // no access attribute: ISO 15745's "read"
  const gen::entry &mode = at(d, 0x2000, 0);
  CHECK(mode.type == od::data_type::integer8);
  CHECK(mode.low == od::signed_number(-1));
  CHECK(mode.high == od::signed_number(3));
  const gen::entry &serial = at(d, 0x2001, 0);
  CHECK(text(serial.default_text) == "abc");
  CHECK(serial.size == 16U); // CO_stringLengthMin
  CHECK(serial.size_declared);
  CHECK(text(at(d, 0x2002, 0).default_text) == "\xC8\x3D\xBB");
  CHECK(at(d, 0x2002, 0).type == od::data_type::octet_string);
  CHECK(at(d, 0x1400, 1).default_nodeid);
  CHECK(at(d, 0x1400, 1).default_value == od::unsigned_number(0x200));
  CHECK(at(d, 0x6200, 1).access == od::access::rww);
  CHECK(at(d, 0x6200, 1).pdo == od::pdo_mapping::rx);
  CHECK(at(d, 0x6200, 2).default_value == od::unsigned_number(0x0F));
  // CiA 306 [DeviceInfo] keys from the features and bit rates
  const gen::key_list want{{"VendorName", "Fixture"},
                           {"VendorNumber", "0x00000099"},
                           {"ProductName", "Fixture IO"},
                           {"BaudRate_10", "0"},
                           {"BaudRate_20", "0"},
                           {"BaudRate_50", "0"},
                           {"BaudRate_125", "0"},
                           {"BaudRate_250", "1"},
                           {"BaudRate_500", "1"},
                           {"BaudRate_800", "0"},
                           {"BaudRate_1000", "0"},
                           {"Granularity", "8"},
                           {"NrOfRXPDO", "1"},
                           {"NrOfTXPDO", "0"},
                           {"SimpleBootUpSlave", "1"},
                           {"LSS_Supported", "0"}};
  CHECK(d.device_info == want);
  CHECK(d.dummy_usage == gen::key_list{{"Dummy0005", "1"}, {"Dummy0007", "0"}});
}

TEST_CASE("xdd: an XDC's actual values are the DCF's parameter values") {
  const outcome o = read("codegen/fixtures/xdd/node5.xdc");
  REQUIRE(o.dict);
  const gen::dictionary &d = *o.dict;
  CHECK(o.diags.empty());
  CHECK(d.is_dcf);
  CHECK(d.node_id == 5);
  CHECK(d.node_name == "drive 5");
  CHECK(d.commissioning == gen::key_list{{"NodeID", "5"},
                                         {"NodeName", "drive 5"},
                                         {"Baudrate", "500"},
                                         {"NetNumber", "1"},
                                         {"CANopenManager", "0"}});
  CHECK(at(d, 0x1017, 0).parameter_value == od::unsigned_number(250));
  CHECK(at(d, 0x1017, 0).denotation == "heartbeat");
  // the concise DCF and configuration list work on it as on a DCF
  gen::diagnostics diag;
  const gen::config_list l =
      gen::build_config_list(d, gen::config_values::parameter, "node5.xdc", diag);
  REQUIRE(l.items.size() >= 2U);
  CHECK(l.node_id == 5U);
  bool heartbeat = false;
  for (const auto &i : l.items) {
    if (i.address == fieldcodec::od::address{0x1017, 0}) {
      heartbeat = true;
      CHECK(i.value == std::vector<std::uint8_t>{250, 0});
    }
  }
  CHECK(heartbeat);
  // written back as an XDC: the same
  const gen::dictionary back = xdd_round_trip(d, gen::bus_profile::canopen);
  check_same(d, back);
  CHECK(back.commissioning == d.commissioning);
}

TEST_CASE("xdd: refusals and warnings name the construct and its place") {
  const std::string m = "codegen/fixtures/xdd/malformed/";
  const auto diags = [&](const std::string &f) { return read(m + f).diags; };
  CHECK(diags("unclosed.xdd") ==
        std::vector<std::string>{m + "unclosed.xdd:8:9: error: end tag '</ObjectList>' does not "
                                     "match '<Object>' (line 7, column 11)"});
  CHECK(diags("latin1_undeclared.xdd") ==
        std::vector<std::string>{m + "latin1_undeclared.xdd:7:41: error: byte 0xE4 is not UTF-8 "
                                     "(the declaration names encoding 'UTF-8')"});
  CHECK(diags("unknown_type.xdd") ==
        std::vector<std::string>{
            m + "unknown_type.xdd:7:66: error: unknown data type 0x7777 of object 0x1000: not a "
                "CiA 301 basic type, not in a data type area (0x0020-0x025F, 0x0401-0x04FF) and "
                "not defined in the file's <DataTypeList>"});
  CHECK(diags("duplicate_index.xdd") ==
        std::vector<std::string>{m + "duplicate_index.xdd:8:26: error: duplicate object 0x1000 "
                                     "(first at line 7)"});
  CHECK(diags("bad_value.xdd") ==
        std::vector<std::string>{m + "bad_value.xdd:7:106: error: expected a hexadecimal digit, "
                                     "got 'G' in '0x12G4' in defaultValue of object 0x1000"});
  CHECK(diags("bad_index.xdd") ==
        std::vector<std::string>{m + "bad_index.xdd:7:26: error: expected index as four "
                                     "hexadecimal digits, got \"100\""});
  CHECK(diags("modular.xdd") ==
        std::vector<std::string>{
            m + "modular.xdd:4:5: error: modular device descriptions (xsi:type "
                "\"ProfileBody_Device_Powerlink_Modular_Head\") are not supported: generate from "
                "the description of one module configuration"});
  CHECK(diags("not_xdd.xdd") ==
        std::vector<std::string>{m + "not_xdd.xdd:2:1: error: expected the root element "
                                     "<ISO15745ProfileContainer> of an XDD/XDC, got "
                                     "<EtherCATInfo>"});
  const outcome limits = read(m + "limits.xdd");
  CHECK(limits.dict); // limits that contradict each other are warnings, as in an EDS
  CHECK(limits.diags ==
        std::vector<std::string>{
            m + "limits.xdd:7:11: warning: low limit 10 is above the high limit -10: every value "
                "is out of range (object 0x2000)",
            m + "limits.xdd:8:11: warning: default value 20 is outside the limits 0..10 (object "
                "0x2001)",
            m + "limits.xdd:9:99: warning: value '300' does not fit INTEGER8 (highLimit of "
                "object 0x2002)"});
  const outcome u16 = read(m + "utf16.xdd"); // not malformed: UTF-16 with a byte-order mark
  REQUIRE(u16.dict);
  CHECK(u16.dict->entries.front().name == "\xC3\x84");
}

TEST_CASE("xdd: more bad input") {
  const std::string head =
      "<ISO15745ProfileContainer xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">"
      "<ISO15745Profile><ProfileBody xsi:type=\"ProfileBody_CommunicationNetwork_Powerlink\">"
      "<ApplicationLayers><ObjectList>\n";
  const std::string tail = "\n</ObjectList></ApplicationLayers></ProfileBody></ISO15745Profile>"
                           "</ISO15745ProfileContainer>";
  const auto diag = [&](const std::string &objects) { // the first error
    const outcome o = read_xdd_text(head + objects + tail, "t.xdd");
    for (const auto &d : o.diags) {
      if (d.find(": error: ") != std::string::npos) return d;
    }
    return std::string();
  };
  CHECK(diag("<Object index=\"1000\" name=\"T\" objectType=\"7\" accessType=\"ro\"/>") ==
        "t.xdd:2:1: error: no data type for object 0x1000 (neither a dataType attribute nor an "
        "IEC type in its parameter)");
  CHECK(diag("<Object index=\"1000\" name=\"T\" objectType=\"3\" dataType=\"0007\"/>") ==
        "t.xdd:2:43: error: expected objectType 2, 5, 6, 7, 8 or 9, got \"3\"");
  CHECK(diag("<Object index=\"1000\" name=\"T\" objectType=\"7\" dataType=\"0007\" "
             "accessType=\"rx\"/>") ==
        "t.xdd:2:74: error: expected accessType const, ro, wo, rw, rwr or rww, got \"rx\"");
  CHECK(diag("<Object index=\"1000\" name=\"T\" objectType=\"7\" dataType=\"0007\" "
             "PDOmapping=\"maybe\"/>") ==
        "t.xdd:2:74: error: expected PDOmapping no, default, optional, TPDO or RPDO, got "
        "\"maybe\"");
  CHECK(diag("<Object index=\"1018\" name=\"I\" objectType=\"9\"><SubObject subIndex=\"1\" "
             "name=\"V\" objectType=\"7\" dataType=\"0007\"/></Object>") ==
        "t.xdd:2:67: error: expected subIndex as two hexadecimal digits, got \"1\"");
  CHECK(diag("<Object index=\"1018\" name=\"I\" objectType=\"9\"><SubObject subIndex=\"01\" "
             "name=\"V\" objectType=\"7\" dataType=\"0007\"/><SubObject subIndex=\"01\" name=\"W\" "
             "objectType=\"7\" dataType=\"0007\"/></Object>") ==
        "t.xdd:2:133: error: duplicate sub-object 0x1018 sub-index 0x01");
  CHECK(diag("<Object index=\"1000\" name=\"T\" objectType=\"7\" dataType=\"0007\" "
             "defaultValue=\"$NODEID*2\"/>") ==
        "t.xdd:2:76: error: expected '$NODEID+<number>' or '<number>+$NODEID', got '$NODEID*2' in "
        "defaultValue of object 0x1000");
  CHECK(diag("<Object index=\"1000\" name=\"T\" objectType=\"7\" dataType=\"0008\" "
             "defaultValue=\"0x7FC00000\"/>") ==
        "t.xdd:2:76: error: expected a finite REAL32, got '0x7FC00000' (NaN) in defaultValue of "
        "object 0x1000");
  CHECK(diag("<Object index=\"1030\" name=\"T\" objectType=\"7\" dataType=\"0402\" "
             "defaultValue=\"192.168.1\"/>") ==
        "t.xdd:2:76: error: expected an IP address such as 192.168.100.1, got \"192.168.1\" in "
        "defaultValue of object 0x1030");
  CHECK(diag("<Object index=\"1000\" name=\"T\" objectType=\"7\" dataType=\"0007\" "
             "uniqueIDRef=\"P1\"/>") ==
        "t.xdd:2:75: error: uniqueIDRef \"P1\" names no <parameter> of the parameterList");
  CHECK(diag("<Thing/>") == "t.xdd:2:1: error: unexpected <Thing> in <ObjectList> (objects only)");
  CHECK(
      read_xdd_text("<ISO15745ProfileContainer/>", "t.xdd").diags ==
      std::vector<std::string>{"t.xdd:1:1: error: no communication network profile (<ProfileBody "
                               "xsi:type=\"ProfileBody_CommunicationNetwork_…\">): the file has no "
                               "object list"});
}

TEST_CASE("xdd: XDD -> XDD and XDD -> EDS -> XDD keep the model") {
  for (const char *f : {"codegen/fixtures/xdd/powerlink.xdd", "codegen/fixtures/xdd/canopen.xdd",
                        "codegen/fixtures/xdd/node5.xdc"}) {
    CAPTURE(f);
    const outcome o = read(f);
    REQUIRE(o.dict);
    const gen::dictionary &d = *o.dict;
    std::vector<std::string> lost;
    gen::dictionary once = xdd_round_trip(d, d.profile, &lost);
    once.source_name = d.source_name;
    CHECK(lost.empty());
    check_same(d, once);
    CHECK(once.device_info == d.device_info);
    CHECK(once.file_info == d.file_info);
    CHECK(once.dummy_usage == d.dummy_usage);
    REQUIRE(once.other_sections.size() == d.other_sections.size());
    for (std::size_t i = 0; i < d.other_sections.size(); ++i) {
      CHECK(once.other_sections[i].name == d.other_sections[i].name);
      CHECK(once.other_sections[i].keys == d.other_sections[i].keys);
    }
    // the written XDD is a fixed point
    gen::diagnostics w1;
    gen::diagnostics w2;
    CHECK(gen::write_xdd(once, d.profile, "src", w1) == gen::write_xdd(d, d.profile, "src", w2));
    // through an EDS
    gen::diagnostics r;
    const auto via = gen::read_eds(gen::write_eds(d), "via.eds", r);
    REQUIRE(via);
    INFO(r.text());
    CHECK(r.text().find("unknown section") == std::string::npos); // XDD.* are known to it
    const gen::dictionary back = xdd_round_trip(*via, d.profile);
    // an EDS has no PDO direction (PDOMapping=0/1; the CLI's --eds says so): mappable or not
    gen::dictionary expected = d;
    for (auto &e : expected.entries) {
      if (e.pdo != od::pdo_mapping::no) e.pdo = od::pdo_mapping::yes;
    }
    check_same(expected, back);
    CHECK(back.other_sections.size() == d.other_sections.size());
  }
}

TEST_CASE("xdd: the XENAX dictionaries written as XDD read back equal (manual 2.4)") {
  const std::pair<const char *, gen::bus_profile> files[] = {
      {"../dictionaries/xenax_powerlink.eds", gen::bus_profile::powerlink},
      {"../dictionaries/xenax_canopen.eds", gen::bus_profile::canopen},
      {"../dictionaries/xenax_ethercat.eds", gen::bus_profile::canopen}};
  for (const auto &file : files) {
    const char *const f = file.first; // not a structured binding: CAPTURE's lambda names it
    const gen::bus_profile profile = file.second;
    CAPTURE(f);
    const outcome o = read(f);
    REQUIRE(o.dict);
    std::vector<std::string> lost;
    const gen::dictionary back = xdd_round_trip(*o.dict, profile, &lost);
    check_same(*o.dict, back);
    // what an XDD has no place for is named, nothing else
    for (const auto &l : lost) {
      CAPTURE(l);
      CHECK((l.find("not written to the") != std::string::npos ||
             l.find("GeneralFeatures") != std::string::npos));
    }
  }
  // POWERLINK: exactly these losses
  const outcome pl = read("../dictionaries/xenax_powerlink.eds");
  std::vector<std::string> lost;
  (void)xdd_round_trip(*pl.dict, gen::bus_profile::powerlink, &lost);
  CHECK(lost ==
        std::vector<std::string>{
            "src: warning: the XDD has no POWERLINK <GeneralFeatures> (the source has none); EPSG "
            "DS 311 tools expect NMTCycleTimeMin, NMTCycleTimeMax, NMTBootTimeNotActive and "
            "NMTErrorEntries there",
            "src: warning: [FileInfo] FileRevision, EDSVersion, Description not written to the "
            "XDD (no XDD attribute)",
            "src: warning: [DeviceInfo] RevisionNumber, BaudRate_10, BaudRate_20, BaudRate_50, "
            "BaudRate_125, BaudRate_250, BaudRate_500, BaudRate_800, BaudRate_1000, "
            "SimpleBootUpMaster, SimpleBootUpSlave, Granularity, DynamicChannelsSupported, "
            "GroupMessaging, NrOfRXPDO, NrOfTXPDO, LSS_Supported not written to the POWERLINK XDD "
            "(no XDD attribute)",
            "src: warning: [Comments] not written to the XDD"});
}

TEST_CASE("xdd: EDS -> XDD -> EDS keeps what an XDD can hold and names the rest") {
  const outcome o = read("codegen/fixtures/quirks.eds");
  REQUIRE(o.dict);
  std::vector<std::string> lost;
  const gen::dictionary back = xdd_round_trip(*o.dict, gen::bus_profile::canopen, &lost);
  check_same(*o.dict, back);
  CHECK(!lost.empty());
}
