// fieldcodec-gen readers and writers: quirks, exact diagnostics, round trips.
// Fixtures are hand-written (tests/codegen/fixtures); the tests run with tests/ as working
// directory, so diagnostics name "codegen/fixtures/...".
#include "readers.hpp"
#include "text.hpp"

#include <doctest/doctest.h>
#include <fieldcodec/dpq/columns.hpp>
#include <fieldcodec/od/value.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gen = fieldcodec::gen;
namespace od = fieldcodec::od;

namespace {

struct outcome {
  std::optional<gen::dictionary> dict;
  std::vector<std::string> diags;
};

outcome read(const std::string &path, bool strict = false) {
  gen::diagnostics d;
  d.strict = strict;
  outcome o;
  o.dict = gen::read_file(path, d);
  for (const auto &x : d.all()) o.diags.push_back(gen::diagnostics::format(x));
  if (d.has_errors()) o.dict.reset();
  return o;
}

outcome read_text(const std::string &text, const std::string &name, bool eds = true) {
  gen::diagnostics d;
  outcome o;
  o.dict = eds ? gen::read_eds(text, name, d) : gen::read_csv(text, name, d);
  for (const auto &x : d.all()) o.diags.push_back(gen::diagnostics::format(x));
  return o;
}

const gen::entry *find(const gen::dictionary &d, std::uint16_t index, std::uint8_t sub) {
  for (const auto &e : d.entries) {
    if (e.index == index && e.sub == sub) return &e;
  }
  return nullptr;
}

// The fields an EDS can carry.
void same_eds_content(const gen::dictionary &a, const gen::dictionary &b, bool limits = true) {
  REQUIRE(a.entries.size() == b.entries.size());
  for (std::size_t i = 0; i < a.entries.size(); ++i) {
    const gen::entry &x = a.entries[i];
    const gen::entry &y = b.entries[i];
    INFO("entry 0x" << gen::hex(x.index, 4) << " sub " << int{x.sub});
    CHECK(x.index == y.index);
    CHECK(x.sub == y.sub);
    CHECK(x.object == y.object);
    CHECK(x.type == y.type);
    CHECK(x.access == y.access);
    CHECK((x.pdo == od::pdo_mapping::no) == (y.pdo == od::pdo_mapping::no));
    CHECK(x.name == y.name);
    CHECK(x.default_value == y.default_value);
    CHECK(x.default_nodeid == y.default_nodeid);
    CHECK(x.default_text == y.default_text);
    CHECK(x.parameter_value == y.parameter_value);
    CHECK(x.parameter_nodeid == y.parameter_nodeid);
    CHECK(x.parameter_text == y.parameter_text);
    CHECK(x.denotation == y.denotation);
    CHECK(x.obj_flags == y.obj_flags);
    if (limits) {
      CHECK(x.low == y.low);
      CHECK(x.high == y.high);
    }
  }
  REQUIRE(a.objects.size() == b.objects.size());
  for (const auto &[index, info] : a.objects) {
    auto it = b.objects.find(index);
    REQUIRE(it != b.objects.end());
    CHECK(info.name == it->second.name);
    CHECK(info.code == it->second.code);
  }
}

void round_trip(const gen::dictionary &m1, bool limits = true) {
  const std::string eds = gen::write_eds(m1);
  gen::diagnostics d;
  auto m2 = gen::read_eds(eds, "written.eds", d);
  for (const auto &x : d.all()) INFO(gen::diagnostics::format(x));
  REQUIRE(m2.has_value());
  CHECK_FALSE(d.has_errors());
  same_eds_content(m1, *m2, limits);
  m2->source_name = m1.source_name;
  m2->stem = m1.stem;
  m2->is_dcf = m1.is_dcf;
  CHECK(gen::write_eds(*m2) == eds); // normalisation is idempotent
}

} // namespace

TEST_CASE("eds: every quirk of quirks.eds (CRLF, Latin-1, case, CompactSubObj, $NODEID, ...)") {
  auto o = read("codegen/fixtures/quirks.eds");
  CHECK(o.diags == std::vector<std::string>{
                       "codegen/fixtures/quirks.eds:72:2: warning: unknown section "
                       "[Vendor_Private_Stuff] not interpreted (kept in the EDS export)",
                       "codegen/fixtures/quirks.eds:408:10: warning: data type 0x0040 of [3000] is "
                       "not a basic type (0x0001..0x001B); its value is kept as DOMAIN",
                       "codegen/fixtures/quirks.eds:179: warning: TPDO 1 has a mapping parameter "
                       "0x1A00 but no communication parameter 0x1800 (CiA 301: a PDO has both; "
                       "masters that configure the PDO fail on it)"});
  REQUIRE(o.dict);
  const auto &d = *o.dict;
  CHECK(d.entries.size() == 42);
  CHECK(d.comments ==
        std::vector<std::string>{"first comment line", "second comment line, lower-case key"});
  CHECK(d.dummy_usage.size() == 2);
  // lower-case keys with spaces around '=', decimal type codes, "RO"
  const auto *err = find(d, 0x1001, 0);
  REQUIRE(err);
  CHECK(err->type == od::data_type::unsigned8);
  CHECK(err->access == od::access::ro);
  // $NODEID in either operand order and any case
  CHECK(find(d, 0x1014, 0)->default_value == od::unsigned_number(0x80));
  CHECK(find(d, 0x1014, 0)->default_nodeid);
  CHECK(find(d, 0x1014, 0)->obj_flags == 1U);
  CHECK(find(d, 0x1400, 1)->default_value == od::unsigned_number(0x200));
  CHECK(find(d, 0x1400, 1)->default_nodeid);
  CHECK(find(d, 0x2006, 0)->default_value == od::unsigned_number(384));
  // sub-index gaps (SubNumber counts sub-objects), [1018Sub4], hex sub-index [1600subA]
  CHECK(find(d, 0x1018, 4) != nullptr);
  CHECK(find(d, 0x1018, 2) == nullptr);
  CHECK(find(d, 0x1600, 10)->default_value == od::unsigned_number(0x60400010));
  // CompactSubObj with a partial [1A00Name]
  CHECK(find(d, 0x1A00, 0)->default_value == od::unsigned_number(3));
  CHECK(find(d, 0x1A00, 1)->name == "First mapped");
  CHECK(find(d, 0x1A00, 2)->name == "TPDO 1 mapping2");
  CHECK(find(d, 0x1A00, 3)->name == "Third mapped");
  // numbers: octal, negative hex, two's complement bit patterns of signed types
  CHECK(find(d, 0x2002, 0)->default_value == od::signed_number(8));
  CHECK(find(d, 0x2001, 0)->low == od::signed_number(-16));
  CHECK(find(d, 0x2003, 0)->low == od::signed_number(-2147483647 - 1));
  CHECK(find(d, 0x2003, 0)->default_value == od::signed_number(-1));
  CHECK(find(d, 0x2014, 0)->default_value == od::signed_number(INT64_MIN));
  CHECK(find(d, 0x201A, 0)->default_value == od::unsigned_number(UINT64_MAX));
  CHECK(find(d, 0x2007, 0)->low == od::real_number(-1000.0));
  CHECK(find(d, 0x2008, 0)->default_text == "Quirk; not a comment");
  CHECK(find(d, 0x200C, 0)->default_value == od::to_number({.ms = 1000, .days = 1}));
  CHECK(find(d, 0x200D, 0)->object == od::object_code::domain);
  CHECK(find(d, 0x0002, 0)->object == od::object_code::deftype);
  // Latin-1 converted to UTF-8
  CHECK(find(d, 0x201B, 0)->name == "Gr\xC3\xB6\xC3\x9F"
                                    "e \xC3\xA4u\xC3\x9F"
                                    "erst");
  CHECK(find(d, 0x3000, 0)->type_code == 0x40);
  // every basic data type is present once
  for (std::uint16_t t = 1; t <= 0x1B; ++t) {
    if (!od::is_data_type(t)) continue;
    bool seen = false;
    for (const auto &e : d.entries) seen = seen || e.type_code == t;
    CHECK_MESSAGE(seen, "data type " << t);
  }
}

TEST_CASE("dcf: ParameterValue, Denotation, [DeviceCommissioning], [xxxxValue]") {
  auto o = read("codegen/fixtures/quirks.dcf");
  CHECK(o.diags.empty());
  REQUIRE(o.dict);
  const auto &d = *o.dict;
  CHECK(d.is_dcf);
  CHECK(d.node_id == 5);
  CHECK(find(d, 0x2100, 1)->parameter_value == od::signed_number(-1000));
  CHECK(find(d, 0x2100, 2)->parameter_value == od::signed_number(1000));
  CHECK(find(d, 0x2100, 2)->parameter_nodeid);
  CHECK(find(d, 0x2101, 0)->parameter_text == "X axis, left");
  CHECK(find(d, 0x2101, 0)->denotation == "Left X axis \xE2\x80\x94 5");
}

TEST_CASE("eds/csv: malformed files get exact diagnostics") {
  const std::string m = "codegen/fixtures/malformed/";
  struct expect {
    std::string file;
    bool ok;
    std::vector<std::string> diags;
  };
  const std::vector<expect> cases{
      {"bad_access.eds",
       false,
       {m + "bad_access.eds:16:12: error: expected ro, wo, rw, rwr, rww or const, got "
            "'readonly' in AccessType of [1000]"}},
      {"bad_code.csv",
       false,
       {m + "bad_code.csv:2:1: error: expected 4 upper-case hex digits such as 0A87, got '0a87' "
            "in column 'code'"}},
      {"bad_nodeid.eds",
       false,
       {m + "bad_nodeid.eds:17:14: error: expected '$NODEID+<number>' or '<number>+$NODEID', got "
            "'$NODEID*2' in DefaultValue of [1000]"}},
      {"bad_number.eds",
       false,
       {m + "bad_number.eds:17:18: error: expected a hexadecimal digit, got 'G' in '0x12G4' in "
            "DefaultValue of [1000]"}},
      {"bad_octal.eds",
       false,
       {m + "bad_octal.eds:17:16: error: expected an octal digit, got '8' in '0189' in "
            "DefaultValue of [1000]"}},
      {"bad_object_type.eds",
       false,
       {m + "bad_object_type.eds:14:12: error: expected object type 0x2, 0x5, 0x6, 0x7, 0x8 or "
            "0x9, got '0x4' in ObjectType of [1000]"}},
      {"bad_type.csv",
       false,
       {m + "bad_type.csv:2:16: error: expected a CiA 301 data type name such as UNSIGNED16, got "
            "'UNSIGNED17' in column 'data_type'"}},
      {"binary_garbage.eds",
       false,
       {m + "binary_garbage.eds:3:5: error: unexpected control character 0x00 (binary data, not "
            "a text file); reading stopped"}},
      {"both_kinds.csv",
       false,
       {m + "both_kinds.csv:1:1: error: expected either an 'index' column (object table) or a "
            "'code' column (command table), got both"}},
      {"duplicate_object.eds",
       false,
       {m +
        "duplicate_object.eds:20:2: error: duplicate object 0x1000 (first defined at line 12)"}},
      {"duplicate_row.csv",
       false,
       {m + "duplicate_row.csv:3:1: error: duplicate object 0x2000 sub-index 0 (also at line 2)"}},
      {"empty.eds",
       false,
       {m + "empty.eds:1:1: error: expected a section such as '[FileInfo]', got an empty file"}},
      {"field_count.csv",
       false,
       {m + "field_count.csv:2:39: error: expected 8 fields as in the header row, got 9"}},
      {"missing_datatype.eds",
       false,
       {m + "missing_datatype.eds:12:2: error: missing DataType in [1000]"}},
      {"missing_sections.eds",
       true,
       {m + "missing_sections.eds:1:1: warning: missing section [FileInfo]",
        m + "missing_sections.eds:1:1: warning: missing section [DeviceInfo]",
        m + "missing_sections.eds:4:3: warning: object '0x1001' listed in [MandatoryObjects] has "
            "no section [1001]"}},
      {"no_key_value.eds",
       false,
       {m + "no_key_value.eds:19:1: error: expected 'key=value', got 'this line has no equals "
            "sign'"}},
      {"orphan_sub.eds",
       false,
       {m + "orphan_sub.eds:20:2: error: sub-object section [2000sub1] without object section "
            "[2000]"}},
      {"sub_beyond_subnumber.eds",
       true,
       {m + "sub_beyond_subnumber.eds:40:2: warning: sub-index 0x02 of [1018sub2] is sub-object "
            "number 3 but [1018] has SubNumber=2 (SubNumber counts sub-objects); all 3 are kept",
        m + "sub_beyond_subnumber.eds:20:2: warning: object [1018] is not listed in "
            "[MandatoryObjects], [OptionalObjects] or [ManufacturerObjects]"}},
      {"unterminated_quote.csv",
       false,
       {m + "unterminated_quote.csv:2:10: error: expected '\"' to close the quoted field opened "
            "here"}},
      {"unterminated_section.eds",
       false,
       {m + "unterminated_section.eds:20:6: error: expected ']' to end section name '2000' (the "
            "section header is not closed)"}},
      // the only error: not "an empty file", no "section header before the first key" (issue 26)
      {"unterminated_first_section.eds",
       false,
       {m + "unterminated_first_section.eds:2:6: error: expected ']' to end section name '1000' "
            "(the section header is not closed)"}},
  };
  std::size_t files = 0;
  for (const auto &f : std::filesystem::directory_iterator(m)) {
    (void)f;
    ++files;
  }
  CHECK(files == cases.size()); // every fixture has its expectation
  for (const auto &c : cases) {
    INFO(c.file);
    auto o = read(m + c.file);
    CHECK(o.dict.has_value() == c.ok);
    CHECK(o.diags == c.diags);
  }
}

TEST_CASE("csv: the manufacturers' columns (acceptance, bus_manager, pointer)") {
  namespace dpq = fieldcodec::dpq;
  const std::string head = "index,name,data_type,acceptance,bus_manager,pointer\n";
  auto o = read_text(head + "0x2000,A,UNSIGNED8,also with active enabling,available,7\n"
                            "0x2001,B,UNSIGNED8,only with deactivated enabling,not available,\n"
                            "0x2002,C,UNSIGNED8,,,\n",
                     "m.csv", false);
  REQUIRE(o.dict.has_value());
  CHECK(o.diags.empty());
  const gen::entry *a = find(*o.dict, 0x2000, 0);
  const gen::entry *b = find(*o.dict, 0x2001, 0);
  const gen::entry *c = find(*o.dict, 0x2002, 0);
  REQUIRE((a != nullptr && b != nullptr && c != nullptr));
  CHECK(a->acceptance == dpq::acceptance::also_when_enabled);
  CHECK(a->bus == dpq::bus_manager::available);
  CHECK(a->pointer == std::optional<std::uint8_t>(7));
  CHECK(b->acceptance == dpq::acceptance::only_when_disabled);
  CHECK(b->bus == dpq::bus_manager::not_available);
  CHECK(!b->pointer.has_value());
  CHECK(c->acceptance == dpq::acceptance::unknown);
  CHECK(c->bus == dpq::bus_manager::unspecified);
  CHECK(!c->pointer.has_value());
  // a text the manual does not print (here: another case) is an error, not "unknown"
  auto bad = read_text(head + "0x2000,A,UNSIGNED8,Also with active enabling,,\n", "m.csv", false);
  REQUIRE(bad.diags.size() == 1U);
  CHECK(bad.diags[0] == "m.csv:2:20: error: expected 'only with deactivated enabling' or 'also "
                        "with active enabling', got 'Also with active enabling' in column "
                        "'acceptance'");
  auto bad_bus = read_text(head + "0x2000,A,UNSIGNED8,,yes,\n", "m.csv", false);
  REQUIRE(bad_bus.diags.size() == 1U);
  CHECK(bad_bus.diags[0] ==
        "m.csv:2:21: error: expected 'available' or 'not available', got 'yes' in column "
        "'bus_manager'");
  auto bad_pointer = read_text(head + "0x2000,A,UNSIGNED8,,,128\n", "m.csv", false);
  REQUIRE(bad_pointer.diags.size() == 1U);
  CHECK(bad_pointer.diags[0] ==
        "m.csv:2:22: error: expected an index pointer 0..127, got '128' in column 'pointer'");
}

TEST_CASE("eds: --strict turns warnings into errors") {
  auto o = read("codegen/fixtures/malformed/sub_beyond_subnumber.eds", true);
  CHECK_FALSE(o.dict);
  REQUIRE(!o.diags.empty());
  CHECK(o.diags[0].find(": error: sub-index 0x02 of [1018sub2]") != std::string::npos);
}

TEST_CASE("eds: garbage never crashes") {
  std::string s = "[1000]\nParameterName=x\nDataType=0x7\nAccessType=ro\n";
  for (int i = 0; i < 2000; ++i) {
    std::string t = s;
    t[static_cast<std::size_t>(i * 7) % t.size()] = static_cast<char>(i * 31);
    if (i % 3 == 0) t.resize(static_cast<std::size_t>(i) % t.size());
    auto o = read_text(t, "fuzz.eds");
    (void)o;
    auto c = read_text(t, "fuzz.csv", false);
    (void)c;
  }
  CHECK(true);
}

TEST_CASE("eds: round trip of the fixtures and of every dictionary") {
  for (const char *f : {"codegen/fixtures/quirks.eds", "codegen/fixtures/quirks.dcf"}) {
    INFO(f);
    auto o = read(f);
    REQUIRE(o.dict);
    round_trip(*o.dict);
  }
  for (const auto &f : std::filesystem::directory_iterator("../dictionaries")) {
    const std::string p = f.path().string();
    const std::string ext = f.path().extension().string();
    if (ext != ".eds" && ext != ".dcf" && ext != ".csv") continue;
    INFO(p);
    auto o = read(p);
    if (!o.dict) {
      WARN_MESSAGE(false, p << " does not read: " << (o.diags.empty() ? "" : o.diags[0]));
      continue;
    }
    if (o.dict->is_command_table) continue;
    round_trip(*o.dict, ext != ".csv"); // CSV limits of scaled rows become raw EDS limits
  }
}

TEST_CASE("csv: DPQ table exported as EDS has raw limits") {
  auto o = read("../dictionaries/dpq_parameters.csv");
  REQUIRE(o.dict);
  const std::string eds = gen::write_eds(*o.dict);
  // Inj. P Limit 1: 0..5000 bar × 327.67 → 0..1638350
  const auto at = eds.find("[2023]");
  REQUIRE(at != std::string::npos);
  CHECK(eds.find("HighLimit=0x18FFCE", at) < eds.find("[", at + 1));
}

TEST_CASE("identifiers") {
  CHECK(gen::make_identifier("Inj. P Limit 1") == "inj_p_limit_1");
  CHECK(gen::make_identifier("1st value") == "n_1st_value");
  CHECK(gen::make_identifier("delete") == "delete_");
  CHECK(gen::make_identifier("Valve % open") == "valve_open");
  // Signs are spelled out where they tell parameters apart (DPQ "Limit-" / "Limit+").
  CHECK(gen::make_identifier("Decompres.: Limit-") == "decompres_limit_minus");
  CHECK(gen::make_identifier("Decompres.: Limit+") == "decompres_limit_plus");
  CHECK(gen::make_identifier("Limit- :") == "limit_minus");
  CHECK(gen::make_identifier("Jog -1") == "jog_minus_1");
  CHECK(gen::make_identifier("Pos-FB 2") == "pos_fb_2"); // a hyphen between words separates
  CHECK(gen::make_identifier("\xC3\x9C"
                             "berlast") == "ueberlast");
  CHECK(gen::make_identifier("---") == "");
  CHECK(gen::stem_identifier("XENAX-CANopen") == "xenax_canopen");
  CHECK(gen::stem_identifier("od") == "od_");
}

// The line splitter scans eight bytes at a time (issue 18): control characters anywhere in a
// line, on either side of an eight-byte boundary, are still found and reported at their column;
// TAB and bytes of UTF-8 text are not control characters.
TEST_CASE("eds: control characters at every column of a long line") {
  const std::string head = "[1000]\nParameterName=Device type\nDataType=0x0007\nAccessType=ro\n";
  for (std::size_t col = 0; col < 24; ++col) {
    std::string line = "DefaultValue=0x00020192 ; \xC3\xA4 comment text";
    line.insert(col, 1, '\x0B');
    auto o = read_text(head + line + "\nPDOMapping=0\n", "ctrl.eds");
    INFO("column " << col + 1);
    REQUIRE(!o.diags.empty());
    CHECK(o.diags.front() ==
          "ctrl.eds:5:" + std::to_string(col + 1) + ": error: unexpected control character 0x0B");
  }
  auto t = read_text(head + "DefaultValue=\t0x00020192\t\nPDOMapping=0\n", "tab.eds");
  for (const auto &d : t.diags) CHECK(d.find("control character") == std::string::npos);
  REQUIRE(t.dict);
  CHECK(t.dict->entries.at(0).default_value.has_value());
}
