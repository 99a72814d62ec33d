// Issue 12 regressions of the generator: what real EDS/DCF files do that the reader and writer
// got wrong (string capacity, REAL bit patterns, $NODEID limits, PDO orphans, inline comments,
// diagnostics, DCF sections lost in the export). The CLI side is in cli.cmake.
#include "eds_text.hpp"
#include "text.hpp"

#include <doctest/doctest.h>

#include <bit>
#include <sstream>
#include <string>

namespace gen = fieldcodec::gen;
namespace od = fieldcodec::od;
using gen::test::eds_file;
using gen::test::find_entry;
using gen::test::line_of;
using gen::test::read_csv_text;
using gen::test::read_eds_text;

namespace {

std::string var(const char *index, const char *type, const std::string &more) {
  return std::string("[") + index + "]\nParameterName=Object " + index +
         "\nObjectType=0x7\nDataType=" + type + "\nAccessType=rw\nPDOMapping=0\n" + more + "\n";
}

} // namespace

// ---- 1: the capacity of strings and DOMAINs --------------------------------------------------

TEST_CASE("issue 12.1: a string's capacity is its Size=, else its default's length") {
  const std::string text = eds_file(var("2000", "0x0009", "DefaultValue=Servo X\n") +
                                    var("2001", "0x0009", "Size=30\n") +
                                    var("2002", "0x0009", "DefaultValue=no error\nSize=100\n"));
  auto r = read_eds_text(text);
  REQUIRE(r.dict);
  CHECK(r.diags.empty());
  // before the fix every string entry had size 0: a fixed-slot store could not serve it
  CHECK(find_entry(*r.dict, 0x2000, 0)->size == 7);
  CHECK_FALSE(find_entry(*r.dict, 0x2000, 0)->size_declared);
  CHECK(find_entry(*r.dict, 0x2001, 0)->size == 30);
  CHECK(find_entry(*r.dict, 0x2001, 0)->size_declared);
  CHECK(find_entry(*r.dict, 0x2002, 0)->size == 100);
  CHECK(find_entry(*r.dict, 0x2002, 0)->default_text == "no error");
}

TEST_CASE("issue 12.1: OCTET_STRING / DOMAIN values are hex digit pairs, UNICODE_STRING UTF-16LE") {
  const std::string text = eds_file(var("2000", "0x000A", "DefaultValue=C83DBB\n") +
                                    var("2001", "0x000F", "DefaultValue=01 02 03 04\n") +
                                    var("2002", "0x000B", "DefaultValue=A\xC3\xA9\n") + // "Aé"
                                    var("2003", "0x000F", "DefaultValue=0\n"));
  auto r = read_eds_text(text);
  REQUIRE(r.dict);
  const auto &d = *r.dict;
  CHECK(find_entry(d, 0x2000, 0)->default_text == std::string("\xC8\x3D\xBB", 3));
  CHECK(find_entry(d, 0x2000, 0)->size == 3);
  CHECK(find_entry(d, 0x2001, 0)->default_text == std::string("\x01\x02\x03\x04", 4));
  CHECK(find_entry(d, 0x2002, 0)->default_text == std::string("A\0\xE9\0", 4));
  CHECK(find_entry(d, 0x2002, 0)->size == 4);
  // CANopenNode writes DOMAIN defaults as "0": not a byte, ignored with a warning
  CHECK(find_entry(d, 0x2003, 0)->default_text.empty());
  CHECK(find_entry(d, 0x2003, 0)->size == 0);
  REQUIRE(r.diags.size() == 1);
  CHECK(r.diags[0] == "t.eds:" + std::to_string(line_of(text, "DefaultValue=0\n")) +
                          ":14: warning: DefaultValue '0' of [2003] ignored: DOMAIN values are "
                          "written as hex digits, two per byte");
  // the writer writes them back as it read them
  const std::string w = gen::write_eds(d);
  CHECK(w.find("DefaultValue=C83DBB\nPDOMapping=0\nSize=3\n") != std::string::npos);
  CHECK(w.find("DefaultValue=01020304\n") != std::string::npos);
  CHECK(w.find("DefaultValue=A\xC3\xA9\n") != std::string::npos);
  const auto again = gen::test::reread(d);
  CHECK(find_entry(again, 0x2002, 0)->default_text == find_entry(d, 0x2002, 0)->default_text);
}

TEST_CASE(
    "issue 12.1: a Size= that does not hold the value, or disagrees with a type, is an error") {
  const std::string text = eds_file(
      var("2000", "0x0009", "DefaultValue=too long\nSize=3\n") + var("2001", "0x0006", "Size=4\n") +
      var("2002", "0x0006", "Size=2\n") + var("2003", "0x0009", "Size=0\n"));
  auto r = read_eds_text(text);
  CHECK_FALSE(r.dict);
  const int l2000 = line_of(text, "DefaultValue=too long");
  const int l2001 = line_of(text, "Size=4");
  const int l2003 = line_of(text, "Size=0");
  CHECK(r.diags ==
        std::vector<std::string>{
            "t.eds:" + std::to_string(l2000) +
                ":14: error: DefaultValue of [2000] is 8 bytes, more than its Size=3",
            "t.eds:" + std::to_string(l2001) +
                ":6: error: size 4 disagrees with UNSIGNED16 (2 bytes) in Size of [2001]",
            "t.eds:" + std::to_string(l2003) +
                ":6: error: expected a size 1..4294967295 bytes, got '0' in Size of "
                "[2003]"});
}

TEST_CASE("issue 12.1: a DCF ParameterValue longer than the default sets the capacity") {
  auto r =
      read_eds_text(eds_file(var("2000", "0x0009", "DefaultValue=ab\nParameterValue=abcdef\n")));
  REQUIRE(r.dict);
  CHECK(find_entry(*r.dict, 0x2000, 0)->size == 6);
}

TEST_CASE("issue 12.1: CompactSubObj sub-objects inherit Size=") {
  auto r = read_eds_text(eds_file("[2000]\nParameterName=Names\nObjectType=0x8\nDataType=0x0009\n"
                                  "AccessType=rw\nCompactSubObj=3\nPDOMapping=0\nSize=16\n"));
  REQUIRE(r.dict);
  for (std::uint8_t s = 1; s <= 3; ++s) CHECK(find_entry(*r.dict, 0x2000, s)->size == 16);
}

TEST_CASE("issue 12.1: the capacity options and the warning when nothing gives one") {
  const std::string text =
      eds_file(var("2000", "0x0009", "DefaultValue=abc\n") + var("2001", "0x0009", "") +
               var("2002", "0x0009", "Size=8\n") +
               "[2003]\nParameterName=Domains\nObjectType=0x8\nDataType=0x000F\n"
               "AccessType=rw\nCompactSubObj=4\nPDOMapping=0\n");
  SUBCASE("no option: a warning per object") {
    auto r = read_eds_text(text);
    REQUIRE(r.dict);
    gen::diagnostics diag;
    CHECK(gen::apply_options(*r.dict, {}, "t.eds", diag));
    REQUIRE(diag.all().size() == 2);
    CHECK(gen::diagnostics::format(diag.all()[0]) ==
          "t.eds:" + std::to_string(line_of(text, "[2001]")) +
              ": warning: VISIBLE_STRING 0x2001 'Object 2001' has no capacity (no declared size, "
              "no default): a fixed-slot store cannot hold it; declare a size (EDS Size=, CSV "
              "bytes) or use --string-capacity");
    CHECK(gen::diagnostics::format(diag.all()[1]) ==
          "t.eds:" + std::to_string(line_of(text, "[2003]")) +
              ": warning: 4 string or DOMAIN sub-objects of 0x2003 'Domains' have no capacity (no "
              "declared size, no default): a fixed-slot store cannot hold them; declare a size "
              "(EDS Size=, CSV bytes) or use --string-capacity");
  }
  SUBCASE("--string-capacity 64: at least 64 where nothing is declared") {
    auto r = read_eds_text(text);
    REQUIRE(r.dict);
    gen::generator_options o;
    REQUIRE(gen::parse_string_capacity("64", o).empty());
    gen::diagnostics diag;
    CHECK(gen::apply_options(*r.dict, o, "t.eds", diag));
    CHECK(diag.all().empty());
    CHECK(find_entry(*r.dict, 0x2000, 0)->size == 64);
    CHECK(find_entry(*r.dict, 0x2001, 0)->size == 64);
    CHECK(find_entry(*r.dict, 0x2002, 0)->size == 8); // declared: kept
    CHECK(find_entry(*r.dict, 0x2003, 4)->size == 64);
  }
  SUBCASE("overrides per object and per sub-index win over the file") {
    auto r = read_eds_text(text);
    REQUIRE(r.dict);
    gen::generator_options o;
    REQUIRE(gen::parse_string_capacity("0x2002=30", o).empty());
    REQUIRE(gen::parse_string_capacity("0x2003:2=512", o).empty());
    REQUIRE(gen::parse_string_capacity("16", o).empty());
    gen::diagnostics diag;
    CHECK(gen::apply_options(*r.dict, o, "t.eds", diag));
    CHECK(find_entry(*r.dict, 0x2002, 0)->size == 30);
    CHECK(find_entry(*r.dict, 0x2003, 2)->size == 512);
    CHECK(find_entry(*r.dict, 0x2003, 2)->size_declared);
    CHECK(find_entry(*r.dict, 0x2003, 1)->size == 16);
  }
  SUBCASE("an override smaller than the default, or naming no string, is an error") {
    auto r = read_eds_text(text);
    REQUIRE(r.dict);
    gen::generator_options o;
    REQUIRE(gen::parse_string_capacity("0x2000=2", o).empty());
    REQUIRE(gen::parse_string_capacity("0x2004=2", o).empty());
    REQUIRE(gen::parse_string_capacity("0x2003:9=2", o).empty());
    gen::diagnostics diag;
    CHECK_FALSE(gen::apply_options(*r.dict, o, "t.eds", diag));
    REQUIRE(diag.all().size() == 5); // the errors, then the warnings about 0x2001 and 0x2003
    CHECK(gen::diagnostics::format(diag.all()[0]) ==
          "t.eds:" + std::to_string(line_of(text, "[2000]")) +
              ": error: --string-capacity 0x2000=2: the default of 0x2000 sub-index 0 is 3 bytes");
    CHECK(gen::diagnostics::format(diag.all()[1]) ==
          "t.eds: error: --string-capacity 0x2004=2: no object 0x2004");
    CHECK(gen::diagnostics::format(diag.all()[2]) ==
          "t.eds: error: --string-capacity 0x2003:9=2: object 0x2003 has no VISIBLE_STRING, "
          "OCTET_STRING, UNICODE_STRING or DOMAIN entry at sub-index 9");
  }
}

TEST_CASE("issue 12.1: bad --string-capacity arguments") {
  gen::generator_options o;
  CHECK(gen::parse_string_capacity("0", o) ==
        "expected a capacity in bytes 1..4294967295, got '0'");
  CHECK(gen::parse_string_capacity("12x", o) ==
        "expected a capacity in bytes (decimal or 0x hex), got '12x'");
  CHECK(gen::parse_string_capacity("2000=4", o) == "expected an index such as 0x1000, got '2000'");
  CHECK(gen::parse_string_capacity("0x2000:256=4", o) == "expected a sub-index 0..255, got '256'");
  CHECK(gen::parse_string_capacity("0x12345=4", o) == "index '0x12345' is beyond 0xFFFF");
  CHECK(gen::parse_string_capacity("0x2000=", o) ==
        "expected a capacity in bytes (decimal or 0x hex), got ''");
  CHECK(gen::parse_string_capacity("8", o).empty());
  CHECK(gen::parse_string_capacity("9", o) == "--string-capacity BYTES is given twice");
  CHECK(gen::parse_string_capacity("0x2000=4", o).empty());
  CHECK(gen::parse_string_capacity("0x2000=5", o) == "capacity of '0x2000' is given twice");
}

TEST_CASE("issue 12.1: CSV OCTET_STRING defaults are hex digit pairs too") {
  auto r = read_csv_text("index,name,data_type,bytes,default\n"
                         "0x2000,Mask,OCTET_STRING,2,00FF\n"
                         "0x2001,Bad,OCTET_STRING,2,0\n"
                         "0x2002,Long,VISIBLE_STRING,2,abc\n");
  CHECK_FALSE(r.dict);
  CHECK(r.diags == std::vector<std::string>{
                       "t.csv:3:27: warning: default '0' ignored: OCTET_STRING values are "
                       "written as hex digits, two per byte",
                       "t.csv:4:30: error: the default is 3 bytes, more than the 2 of "
                       "column 'bytes' in column 'default'"});
  auto ok = read_csv_text("index,name,data_type,bytes,default\n0x2000,Mask,OCTET_STRING,2,00FF\n");
  REQUIRE(ok.dict);
  CHECK(find_entry(*ok.dict, 0x2000, 0)->default_text == std::string("\x00\xFF", 2));
  CHECK(find_entry(*ok.dict, 0x2000, 0)->size_declared);
}

// ---- 3: REAL32/REAL64 written in hex are bit patterns ------------------------------------

TEST_CASE("issue 12.3: REAL values in hex are IEEE 754 bit patterns, decimals stay decimals") {
  const std::string text = eds_file(var("2000", "0x0008",
                                        "DefaultValue=0x40490FDB\nLowLimit=0xC2C80000\n"
                                        "HighLimit=100.5\n") +
                                    var("2001", "0x0011", "DefaultValue=0x400921FB54442D18\n") +
                                    var("2002", "0x0008", "DefaultValue=3.14\n") +
                                    var("2003", "0x0008", "DefaultValue=10\n"));
  auto r = read_eds_text(text);
  REQUIRE(r.dict);
  CHECK(r.diags.empty());
  const auto &d = *r.dict;
  // before the fix: 1078530011.0 and 4.6e18
  CHECK(find_entry(d, 0x2000, 0)->default_value ==
        od::real_number(static_cast<double>(std::bit_cast<float>(0x40490FDBU))));
  CHECK(find_entry(d, 0x2000, 0)->default_value.to_double() == doctest::Approx(3.14159274));
  CHECK(find_entry(d, 0x2000, 0)->low == od::real_number(-100.0));
  CHECK(find_entry(d, 0x2000, 0)->high == od::real_number(100.5));
  CHECK(find_entry(d, 0x2001, 0)->default_value ==
        od::real_number(std::bit_cast<double>(0x400921FB54442D18ULL)));
  CHECK(find_entry(d, 0x2002, 0)->default_value == od::real_number(3.14));
  CHECK(find_entry(d, 0x2003, 0)->default_value == od::real_number(10.0));
  // the export writes the value, which reads back to the same bits
  const auto again = gen::test::reread(d);
  CHECK(find_entry(again, 0x2000, 0)->default_value == find_entry(d, 0x2000, 0)->default_value);
  CHECK(find_entry(again, 0x2001, 0)->default_value == find_entry(d, 0x2001, 0)->default_value);
}

TEST_CASE("issue 12.3: REAL bit patterns that are no finite value of the type are errors") {
  const std::string text = eds_file(var("2000", "0x0008", "DefaultValue=0x1FFFFFFFF\n") +
                                    var("2001", "0x0008", "DefaultValue=0x7FC00000\n") +
                                    var("2002", "0x0011", "HighLimit=0x7FF0000000000000\n") +
                                    var("2003", "0x0008", "LowLimit=-0x3F800000\n"));
  auto r = read_eds_text(text);
  CHECK_FALSE(r.dict);
  auto at = [&](const char *needle, int col) {
    return "t.eds:" + std::to_string(line_of(text, needle)) + ":" + std::to_string(col);
  };
  CHECK(r.diags ==
        std::vector<std::string>{
            at("0x1FFFFFFFF", 14) +
                ": error: expected a REAL32 bit pattern of at most 8 "
                "hexadecimal digits, got '0x1FFFFFFFF' in DefaultValue of [2000]",
            at("0x7FC00000", 14) +
                ": error: expected a finite REAL32, got '0x7FC00000' (NaN) in DefaultValue of "
                "[2001]",
            at("0x7FF0", 11) + ": error: expected a finite REAL64, got '0x7FF0000000000000' "
                               "(infinity) in HighLimit of [2002]",
            at("-0x3F8", 10) + ": error: expected a REAL32 bit pattern without a sign, got "
                               "'-0x3F800000' in LowLimit of [2003]"});
}

TEST_CASE("issue 12.3: CSV REAL values in hex are bit patterns") {
  auto r = read_csv_text("index,name,data_type,default,low\n"
                         "0x2000,Pi,REAL32,0x40490FDB,-1.5\n");
  REQUIRE(r.dict);
  CHECK(find_entry(*r.dict, 0x2000, 0)->default_value ==
        od::real_number(static_cast<double>(std::bit_cast<float>(0x40490FDBU))));
  CHECK(find_entry(*r.dict, 0x2000, 0)->low == od::real_number(-1.5));
}

// ---- 4: $NODEID in LowLimit / HighLimit ----------------------------------------------------

TEST_CASE("issue 12.4: node-ID relative limits stay node-relative in the model and the export") {
  const std::string text = eds_file(
      var("1200", "0x0007",
          "DefaultValue=$NODEID+0x600\nLowLimit=$NODEID+0x600\nHighLimit=0x67F + $NODEID\n"));
  auto r = read_eds_text(text);
  REQUIRE(r.dict);
  CHECK(r.diags.empty());
  const gen::entry *e = find_entry(*r.dict, 0x1200, 0);
  // before the fix: low 0x600 without a flag, so node 1's own 0x601 was out of range
  CHECK(e->low == od::unsigned_number(0x600));
  CHECK(e->low_nodeid);
  CHECK(e->high == od::unsigned_number(0x67F));
  CHECK(e->high_nodeid);
  CHECK(e->default_nodeid);
  const std::string w = gen::write_eds(*r.dict);
  CHECK(w.find("LowLimit=$NODEID+0x600\nHighLimit=$NODEID+0x67F\n") != std::string::npos);
  const auto again = gen::test::reread(*r.dict);
  CHECK(find_entry(again, 0x1200, 0)->low_nodeid);
  CHECK(find_entry(again, 0x1200, 0)->high_nodeid);
}

TEST_CASE("issue 12.4: diagnostics quote a node-ID relative value as written") {
  const std::string text = eds_file(var("1200", "0x0006", "LowLimit=$NODEID+0xFFF0\n") +
                                    var("1201", "0x0007", "DefaultValue=$NodeId+0x12G\n"));
  auto r = read_eds_text(text);
  CHECK_FALSE(r.dict);
  CHECK(r.diags ==
        std::vector<std::string>{
            "t.eds:" + std::to_string(line_of(text, "LowLimit=$NODEID+0xFFF0")) +
                ":10: warning: value '$NODEID+0xFFF0' does not fit UNSIGNED16 for node-ID 127 "
                "(LowLimit of [1200])",
            // the operand as written (before the fix: upper case, '0X12G', column of the value)
            "t.eds:" + std::to_string(line_of(text, "$NodeId+0x12G")) +
                ":26: error: expected a hexadecimal digit, got 'G' in '0x12G' in DefaultValue of "
                "[1201]"});
}

TEST_CASE("issue 12.4: CSV limits may be node-relative") {
  auto r = read_csv_text("index,name,data_type,low,high,default\n"
                         "0x1200,COB-ID,UNSIGNED32,$NODEID+0x600,$NODEID+0x67F,$NODEID+0x600\n");
  REQUIRE(r.dict);
  const gen::entry *e = find_entry(*r.dict, 0x1200, 0);
  CHECK(e->low_nodeid);
  CHECK(e->high_nodeid);
  CHECK(e->low == od::unsigned_number(0x600));
  CHECK(gen::write_eds(*r.dict).find("LowLimit=$NODEID+0x600\n") != std::string::npos);
}

// ---- 6: PDO communication objects without mapping objects --------------------------------

TEST_CASE("issue 12.6: PDO parameters without their partner are reported, in EDS and CSV") {
  const std::string pdo_comm = "[1415]\nParameterName=RPDO 22\nObjectType=0x9\nSubNumber=1\n\n"
                               "[1415sub0]\nParameterName=n\nObjectType=0x7\nDataType=0x0005\n"
                               "AccessType=ro\nDefaultValue=1\nPDOMapping=0\n\n";
  const std::string tpdo_map =
      "[1A02]\nParameterName=TPDO 3 mapping\nObjectType=0x9\nSubNumber=1\n\n"
      "[1A02sub0]\nParameterName=n\nObjectType=0x7\nDataType=0x0005\n"
      "AccessType=rw\nDefaultValue=0\nPDOMapping=0\n\n";
  const std::string text = eds_file(pdo_comm + tpdo_map);
  auto r = read_eds_text(text);
  REQUIRE(r.dict);
  CHECK(r.diags ==
        std::vector<std::string>{
            "t.eds:" + std::to_string(line_of(text, "[1415]")) +
                ": warning: RPDO 22 has a communication parameter 0x1415 but no mapping parameter "
                "0x1615 (CiA 301: a PDO has both; masters that configure the PDO fail on it)",
            "t.eds:" + std::to_string(line_of(text, "[1A02]")) +
                ": warning: TPDO 3 has a mapping parameter 0x1A02 but no communication parameter "
                "0x1802 (CiA 301: a PDO has both; masters that configure the PDO fail on it)"});
  CHECK_FALSE(read_eds_text(text, true).dict); // --strict

  auto c = read_csv_text("index,subindex,name,object_code,data_type\n"
                         "0x1800,0,n,RECORD,UNSIGNED8\n0x1A00,0,n,RECORD,UNSIGNED8\n"
                         "0x1401,0,n,RECORD,UNSIGNED8\n");
  REQUIRE(c.dict);
  CHECK(c.diags == std::vector<std::string>{
                       "t.csv:4: warning: RPDO 2 has a communication parameter 0x1401 but no "
                       "mapping parameter 0x1601 (CiA 301: a PDO has both; masters that "
                       "configure the PDO fail on it)"});
}

TEST_CASE("issue 12.6: EtherCAT (CoE) mapping objects need no communication objects") {
  auto record = [](const char *index, const char *name) {
    return std::string("[") + index + "]\nParameterName=" + name +
           "\nObjectType=0x9\nSubNumber=1\n\n[" + index +
           "sub0]\nParameterName=n\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
           "DefaultValue=0\nPDOMapping=0\n\n";
  };
  // 1C13h (TxPDO assignment) makes it a CoE dictionary: 1A00h alone is fine, 1400h alone is not
  const std::string text = eds_file(record("1400", "RPDO 1") + record("1A00", "TPDO 1 mapping") +
                                    record("1C13", "TxPDO assign"));
  auto r = read_eds_text(text);
  REQUIRE(r.dict);
  CHECK(r.diags == std::vector<std::string>{
                       "t.eds:" + std::to_string(line_of(text, "[1400]")) +
                       ": warning: RPDO 1 has a communication parameter 0x1400 but no mapping "
                       "parameter 0x1600 (CiA 301: a PDO has both; masters that configure the "
                       "PDO fail on it)"});
}

// ---- 7: comments after a value -------------------------------------------------------------

TEST_CASE("issue 12.7: a comment after a value is ignored with a warning (an error if strict)") {
  const std::string text =
      eds_file(var("2000", "0x0006", "DefaultValue=0x3ED ; prevent homing\n") +
               var("2003", "0x0007", "DefaultValue=$NODEID+0x80000300 ; disabled\n") +
               var("2001", "0x0009", "DefaultValue=Quirk; not a comment\n") +
               var("2002", "0x0005", "LowLimit=1;min\n"));
  auto r = read_eds_text(text);
  REQUIRE(r.dict); // before the fix: hard errors
  CHECK(find_entry(*r.dict, 0x2000, 0)->default_value == od::unsigned_number(0x3ED));
  CHECK(find_entry(*r.dict, 0x2003, 0)->default_value == od::unsigned_number(0x80000300));
  CHECK(find_entry(*r.dict, 0x2003, 0)->default_nodeid);
  CHECK(find_entry(*r.dict, 0x2001, 0)->default_text == "Quirk; not a comment"); // text keeps ';'
  CHECK(find_entry(*r.dict, 0x2002, 0)->low == od::unsigned_number(1));
  const std::string l2000 = std::to_string(line_of(text, "0x3ED"));
  const std::string l2003 = std::to_string(line_of(text, "0x80000300"));
  const std::string l2002 = std::to_string(line_of(text, "1;min"));
  CHECK(r.diags ==
        std::vector<std::string>{
            "t.eds:" + l2000 +
                ":20: warning: comment after the value of DefaultValue in [2000] ignored: '; "
                "prevent homing'",
            "t.eds:" + l2002 +
                ":11: warning: comment after the value of LowLimit in [2002] "
                "ignored: ';min'",
            "t.eds:" + l2003 +
                ":33: warning: comment after the value of DefaultValue in [2003] "
                "ignored: '; disabled'"});
  auto strict = read_eds_text(text, true);
  CHECK_FALSE(strict.dict);
  CHECK(strict.diags[0].find(": error: comment after the value") != std::string::npos);
}

// ---- 8: diagnostics ------------------------------------------------------------------------

TEST_CASE("issue 12.8: diagnostics in line order, where reading stopped, the count") {
  // [9000] (unknown section, reported while reading the header sections) comes after [2000]
  // in the file; [2000]'s error is reported later, while reading objects
  const std::string text =
      eds_file(var("2000", "0x0006", "DefaultValue=0x1G\n")) + "\n[Vendor]\nKey=1\n";
  gen::diagnostics diag;
  (void)gen::read_eds(text, "t.eds", diag);
  REQUIRE(diag.all().size() == 2);
  CHECK(diag.all()[0].line > diag.all()[1].line); // reported out of line order
  const auto sorted = diag.sorted();
  CHECK(sorted[0].line < sorted[1].line);
  CHECK(diag.summary() == "1 error, 1 warning");

  // the error limit names the place of the last error reported, and reading stops there
  std::string bad;
  for (int i = 0; i < 6; ++i) bad += "no equals sign " + std::to_string(i) + "\n";
  gen::diagnostics limited;
  limited.max_errors = 3;
  (void)gen::read_eds("[FileInfo]\n" + bad, "t.eds", limited);
  CHECK(limited.error_count() == 3);
  CHECK(limited.stopped_at().line == 4);
  CHECK(limited.stop_message() ==
        "t.eds:4:1: error: too many errors (3); reading stopped here, later problems are not "
        "reported");
  std::ostringstream os;
  limited.print(os);
  CHECK(os.str().ends_with(limited.stop_message() + "\n"));
}

TEST_CASE("issue 12.8: CSV diagnostics quote a number as written") {
  auto r = read_csv_text("index,name,data_type,low\n0x2000,x,UNSIGNED8,0089x\n");
  CHECK(r.diags == std::vector<std::string>{"t.csv:2:24: error: expected a digit, got 'x' in "
                                            "'0089x' in column 'low'"});
}

// ---- 9: the export keeps what the reader read -----------------------------------------------

TEST_CASE("issue 12.9: DCF sections and keys the reader does not interpret survive the export") {
  const std::string text =
      "[FileInfo]\nFileName=t.dcf\n\n[DeviceInfo]\nVendorName=T\n\n"
      "[DeviceComissioning]\nNodeID=5\nNodeName=Axis\nBaudrate=500\nNetNumber=1\n\n"
      "[OptionalObjects]\nSupportedObjects=2\n1=0x1A00\n2=0x1800\n\n"
      "[1800]\nParameterName=TPDO 1\nObjectType=0x9\nSubNumber=1\n\n"
      "[1800sub0]\nParameterName=n\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
      "DefaultValue=1\nPDOMapping=0\nUploadFile=pdo.bin\n\n"
      "[1A00]\nParameterName=TPDO 1 mapping\nObjectType=0x8\nDataType=0x0007\nAccessType=rw\n"
      "PDOMapping=0\nCompactSubObj=2\n\n"
      "[1A00Value]\nNrOfEntries=1\n1=0x60410010\n\n"
      "[1A00Denotation]\nNrOfEntries=2\n1=Status word\n2=Spare\n\n"
      "[1A00ObjectLinks]\nObjectLinks=2\n1=0x6041\n2=0x6064\n\n"
      "[Tools]\nItems=1\n\n[Vendor]\nAnything=goes\n";
  auto r = read_eds_text(text);
  REQUIRE(r.dict);
  CHECK(r.diags == std::vector<std::string>{"t.eds:" + std::to_string(line_of(text, "[Vendor]")) +
                                            ":2: warning: unknown section [Vendor] not "
                                            "interpreted (kept in the EDS export)"});
  const auto &d = *r.dict;
  CHECK(find_entry(d, 0x1A00, 1)->denotation == "Status word");
  CHECK(find_entry(d, 0x1A00, 2)->denotation == "Spare");
  CHECK(find_entry(d, 0x1A00, 1)->parameter_value == od::unsigned_number(0x60410010));
  CHECK(d.objects.at(0x1A00).object_links == std::vector<std::uint16_t>{0x6041, 0x6064});
  CHECK(find_entry(d, 0x1800, 0)->other_keys == gen::key_list{{"UploadFile", "pdo.bin"}});
  const std::string w = gen::write_eds(d);
  // before the fix: [1A00Denotation] and [1A00ObjectLinks] were dropped with a warning
  CHECK(w.find("Denotation=Status word\n") != std::string::npos);
  CHECK(w.find("[1A00ObjectLinks]\nObjectLinks=2\n1=0x6041\n2=0x6064\n") != std::string::npos);
  CHECK(w.find("[DeviceComissioning]\nNodeID=5\nNodeName=Axis\nBaudrate=500\nNetNumber=1\n") !=
        std::string::npos);
  CHECK(w.find("UploadFile=pdo.bin\n") != std::string::npos);
  CHECK(w.find("[Tools]\nItems=1\n") != std::string::npos);
  CHECK(w.find("[Vendor]\nAnything=goes\n") != std::string::npos);
  // and reading the export gives the same again
  const auto again = gen::test::reread(d);
  CHECK(find_entry(again, 0x1A00, 1)->denotation == "Status word");
  CHECK(again.objects.at(0x1A00).object_links == d.objects.at(0x1A00).object_links);
  CHECK(again.commissioning == d.commissioning);
  CHECK(again.other_sections.size() == 2);
  CHECK(gen::write_eds(again) == w);
}

TEST_CASE("issue 12.9: per-sub-index sections of objects without CompactSubObj are reported") {
  const std::string text =
      eds_file(var("2000", "0x0005", "")) + "[2000Name]\n1=x\n\n" + "[2001Denotation]\n1=y\n";
  auto r = read_eds_text(text);
  REQUIRE(r.dict);
  CHECK(r.diags == std::vector<std::string>{
                       "t.eds:" + std::to_string(line_of(text, "[2001Denotation]")) +
                           ":2: warning: section [2001Denotation] without object section [2001] "
                           "ignored",
                       "t.eds:" + std::to_string(line_of(text, "[2000Name]")) +
                           ":2: warning: section [2000Name] ignored: [2000] has no CompactSubObj"});
}

TEST_CASE("a key given twice in a section is reported; the last value is used") {
  std::string list = "[OptionalObjects]\nSupportedObjects=1\n";
  for (int i = 1; i <= 20; ++i) list += std::to_string(i) + "=0x2000\n"; // 20 keys: the set
  list += "7=0x2000\n";
  const std::string text = "[FileInfo]\nFileName=t.eds\n\n[DeviceInfo]\nVendorName=T\n\n" + list +
                           "\n[2000]\nParameterName=x\nObjectType=0x7\nDataType=0x0005\n"
                           "AccessType=rw\nDefaultValue=1\ndefaultvalue=2\nPDOMapping=0\n";
  auto r = read_eds_text(text);
  REQUIRE(r.dict);
  CHECK(find_entry(*r.dict, 0x2000, 0)->default_value == od::unsigned_number(2));
  CHECK(r.diags ==
        std::vector<std::string>{
            "t.eds:" + std::to_string(line_of(text, "7=0x2000\n\n")) +
                ":1: warning: key '7' appears again in [OptionalObjects] (first at line " +
                std::to_string(line_of(text, "7=0x2000")) + "); the last value is used",
            "t.eds:" + std::to_string(line_of(text, "defaultvalue=2")) +
                ":1: warning: key 'defaultvalue' appears again in [2000] (first at line " +
                std::to_string(line_of(text, "DefaultValue=1")) + "); the last value is used"});
}

TEST_CASE("a per-sub-index section given twice is an error, not silently replaced") {
  const std::string text =
      eds_file("[2000]\nParameterName=Map\nObjectType=0x8\nDataType=0x0007\nAccessType=rw\n"
               "PDOMapping=0\nCompactSubObj=2\n\n[2000Name]\n1=a\n\n[2000name]\n1=b\n");
  auto r = read_eds_text(text);
  CHECK_FALSE(r.dict);
  CHECK(r.diags ==
        std::vector<std::string>{"t.eds:" + std::to_string(line_of(text, "[2000name]")) +
                                 ":2: error: duplicate section [2000name] (first defined at line " +
                                 std::to_string(line_of(text, "[2000Name]")) + ")"});
}

TEST_CASE("CSV names and string defaults are one line (an EDS value cannot hold a line break)") {
  auto r = read_csv_text("index,name,data_type,bytes,default\n"
                         "0x2000,\"a\nb\",UNSIGNED8,,\n"
                         "0x2001,c,VISIBLE_STRING,8,\"x\ny\"\n");
  CHECK_FALSE(r.dict);
  CHECK(r.diags ==
        std::vector<std::string>{
            "t.csv:2:8: error: expected one line, got a line break in column 'name'",
            "t.csv:4:27: error: expected one line, got a line break in column 'default'"});
}

TEST_CASE("issue 12.1: byte-string values are emitted as C++ that keeps every byte") {
  std::string o;
  gen::append_cpp_value_text(o, od::data_type::octet_string, std::string("\xC8=\0\"?", 5));
  CHECK(o == "std::string_view{\"\\310=\\000\\042\\077\", 5}");
  o.clear();
  gen::append_cpp_value_text(o, od::data_type::visible_string,
                             "Gr\xC3\xB6\xC3\x9F"
                             "e");
  CHECK(o == "\"Gr\xC3\xB6\xC3\x9F"
             "e\""); // UTF-8 text stays text
}
