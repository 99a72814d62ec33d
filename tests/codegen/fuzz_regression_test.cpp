// Regression tests for inputs found by fuzz/fuzz_codegen.cpp and fuzz/fuzz_codegen_emit.cpp
// (see fuzz/FINDINGS.md).
// A test marked may_fail reproduces an OPEN finding: it reports the failure without failing the
// suite. Whoever fixes the finding removes the decorator (and the finding's status says fixed).
#include "readers.hpp"
#include "text.hpp"

#include <fieldcodec/core/utf8.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>

namespace gen = fieldcodec::gen;

namespace {

std::optional<gen::dictionary> read(std::string_view text, bool csv, gen::diagnostics &diag) {
  const std::string file = csv ? "fuzz.csv" : "fuzz.eds";
  auto d = csv ? gen::read_csv(text, file, diag) : gen::read_eds(text, file, diag);
  if (d) {
    d->source_name = file; // as read_file() does
    d->stem = "fuzz";
  }
  return d;
}

} // namespace

// F5 (2026-11-21, fuzz_codegen, CSV): the writer's normalised EDS is not a fixed point for CSV
// input. The CSV reader keeps the limits 0 and 10 of an UNSIGNED16 as signed numbers, which
// write_eds prints in decimal ("LowLimit=0"); the EDS reader reads them back as unsigned, which
// write_eds prints in hex ("LowLimit=0x0"). CSV → EDS → EDS changes the file.
TEST_CASE("fuzz F5: CSV -> EDS -> EDS is a fixed point") {
  gen::diagnostics diag;
  auto d = read("index,subindex,name,data_type,access,low,high\n"
                "0x2000,0,Speed,UNSIGNED16,rw,0,10\n",
                true, diag);
  REQUIRE(d.has_value());
  const std::string w1 = gen::write_eds(*d);
  gen::diagnostics diag2;
  auto d2 = gen::read_eds(w1, "w1.eds", diag2);
  REQUIRE(d2.has_value());
  CHECK(gen::write_eds(*d2) == w1);
}

// F6 (2026-11-21, fuzz_codegen, EDS): DataType=0x0 is accepted with a warning ("not a basic
// type … kept as DOMAIN"), although the reader's own error text says "expected a data type
// 0x0001..0xFFFF"; the writer then writes DataType=0x000F, so read → write → read changes the
// object's data type code. Either refusing 0 or keeping the code fixes it.
TEST_CASE("fuzz F6: DataType=0x0 is refused or kept") {
  gen::diagnostics diag;
  auto d = read("[FileInfo]\nFileName=x.eds\n\n[DeviceInfo]\nVendorName=x\n\n"
                "[OptionalObjects]\nSupportedObjects=1\n1=0x2000\n\n"
                "[2000]\nParameterName=Zero type\nObjectType=0x7\nDataType=0x0\n"
                "AccessType=rw\nPDOMapping=0\n",
                false, diag);
  if (!d) return; // refused: fixed
  const auto find = [](const gen::dictionary &x) {
    return std::find_if(x.entries.begin(), x.entries.end(),
                        [](const gen::entry &e) { return e.index == 0x2000; });
  };
  REQUIRE(find(*d) != d->entries.end());
  gen::diagnostics diag2;
  auto d2 = gen::read_eds(gen::write_eds(*d), "w1.eds", diag2);
  REQUIRE(d2.has_value());
  REQUIRE(find(*d2) != d2->entries.end());
  CHECK(find(*d2)->type_code == find(*d)->type_code);
}

// F11 (2026-11-21, fuzz_codegen, EDS): `ObjectType=0` (NULL) is accepted — only a warning that
// SubNumber=2 has no sub-object sections — although the reader refuses 0x1, 0x3, 0x4 with
// "expected object type 0x2, 0x5, 0x6, 0x7, 0x8 or 0x9"; write_eds then writes the object as
// `ObjectType=0x0` without DataType, and reading that back fails with "missing DataType in
// [2000]": the generator writes an EDS it cannot read.
TEST_CASE("fuzz F11: what the reader accepts, the writer writes readably") {
  gen::diagnostics diag;
  auto d = read("[FileInfo]\nFileName=x.eds\n\n[DeviceInfo]\nVendorName=x\n\n"
                "[OptionalObjects]\nSupportedObjects=1\n1=0x2000\n\n"
                "[2000]\nSubNumber=2\nParameterName=Rec\nObjectType=0\n",
                false, diag);
  if (!d) return; // refused: fixed
  gen::diagnostics diag2;
  auto d2 = gen::read_eds(gen::write_eds(*d), "w1.eds", diag2);
  CHECK(d2.has_value());
}

// F12 (2026-11-21, fuzz_codegen, 10-minute campaign): an object with ObjectType=5 (DEFTYPE) and
// SubNumber=2 but no sub-object sections is read (with a warning); write_eds wrote it as
// `ObjectType=0x5` with `SubNumber=0` and no DataType, which the reader refuses ("missing
// DataType in [2000]"). Objects written as containers are now written as RECORD.
TEST_CASE("fuzz F12: a DEFTYPE object with a SubNumber is written readably") {
  for (const char *type : {"5", "2", "7"}) {
    gen::diagnostics diag;
    const std::string text =
        std::string("[FileInfo]\nFileName=x.eds\n\n[DeviceInfo]\nVendorName=x\n\n"
                    "[OptionalObjects]\nSupportedObjects=1\n1=0x2000\n\n"
                    "[2000]\nSubNumber=2\nParameterName=Rec\nObjectType=") +
        type + "\n";
    auto d = read(text, false, diag);
    if (!d) continue; // refused on reading: consistent too
    const std::string w1 = gen::write_eds(*d);
    gen::diagnostics diag2;
    auto d2 = gen::read_eds(w1, "w1.eds", diag2);
    REQUIRE(d2.has_value());
    CHECK(gen::write_eds(*d2) == w1);
  }
}

// F13 (2026-11-21, fuzz_codegen, 10-minute campaign): a CSV name with a trailing space (the DPQ
// table has "BackP: Pres 4Ds " as printed) was written to the EDS with the space, which the EDS
// reader trims: CSV -> EDS -> EDS was not a fixed point. The writer trims text values.
TEST_CASE("fuzz F13: text values with surrounding spaces are written trimmed") {
  gen::diagnostics diag;
  auto d =
      read("index,subindex,name,data_type,access\n0x2000,0,Pres 4Ds ,UNSIGNED16,rw\n", true, diag);
  REQUIRE(d.has_value());
  const std::string w1 = gen::write_eds(*d);
  CHECK(w1.find("ParameterName=Pres 4Ds\n") != std::string::npos);
  gen::diagnostics diag2;
  auto d2 = gen::read_eds(w1, "w1.eds", diag2);
  REQUIRE(d2.has_value());
  CHECK(gen::write_eds(*d2) == w1);
}

// F15 (2026-11-24, found in review; the harness's round-trip property covers it): a quoted CSV
// name or VISIBLE_STRING default with a line break was written into the EDS export, which then
// did not read back ("expected 'key=value'"). CSV names and string defaults are one line.
TEST_CASE("fuzz F15: a CSV value with a line break is refused, not written into an EDS") {
  gen::diagnostics diag;
  auto d = read("index,name,data_type,bytes,default\n0x2000,\"a\nb\",UNSIGNED8,,\n"
                "0x2001,c,VISIBLE_STRING,8,\"x\ny\"\n",
                true, diag);
  if (d) { // accepted: then the export must read back
    gen::diagnostics diag2;
    CHECK(gen::read_eds(gen::write_eds(*d), "w1.eds", diag2).has_value());
  } else {
    CHECK(diag.error_count() == 2);
  }
}

// F19 (2026-11-25, fuzz_codegen_emit, EDS; the seeds written for the emitter harness): a name
// that is a C++ keyword gets a trailing '_' ("Switch" -> switch_), and the emitter then joined
// a sub-object's name or a collision suffix with a second '_': switch__mode, int__2101. An
// identifier with "__" is reserved to the implementation in every scope. One '_' joins them now.
TEST_CASE("fuzz F19: names after a keyword's trailing '_' have no double underscore") {
  gen::diagnostics diag;
  auto d = read("[2100]\nParameterName=Switch\nObjectType=0x9\nSubNumber=3\n\n"
                "[2100sub0]\nParameterName=Count\nObjectType=0x7\nDataType=0x0005\n"
                "AccessType=ro\n\n"
                "[2100sub1]\nParameterName=Mode\nObjectType=0x7\nDataType=0x0005\n"
                "AccessType=rw\n\n"
                "[2100sub2]\nParameterName=\nObjectType=0x7\nDataType=0x0005\nAccessType=rw\n\n"
                "[2101]\nParameterName=int\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n\n"
                "[2102]\nParameterName=int\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n\n"
                "[2103]\nParameterName=int\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n",
                false, diag);
  REQUIRE(d.has_value());
  const std::string h = gen::emit_header(*d);
  CHECK(h.find("__") == std::string::npos);
  CHECK(h.find(" switch_{0x2100,") != std::string::npos);
  CHECK(h.find(" switch_count{detail::entries[0]") != std::string::npos);
  CHECK(h.find(" switch_mode{detail::entries[1]") != std::string::npos);
  CHECK(h.find(" switch_sub2{detail::entries[2]") != std::string::npos);
  CHECK(h.find(" int_{detail::entries[3]") != std::string::npos);
  CHECK(h.find(" int_2102{detail::entries[4]") != std::string::npos);
  CHECK(h.find(" int_2103{detail::entries[5]") != std::string::npos);
}

// F20 (2026-11-25, fuzz_codegen_emit, file names; found by a hand-written input while writing
// the harness): the file name was written into the "Generated from" comment as it is, and a line
// break in it (a file system allows any byte but '/' and NUL) ended the comment: the rest of the
// name was read as code. A byte that is not UTF-8 went raw into the comment and into
// `source_file`, and the header was no UTF-8 text. Such a name is written as a literal with
// every byte outside printable ASCII escaped, in the comment and in source_file.
TEST_CASE("fuzz F20: a file name with a line break or a non-UTF-8 byte keeps the header sound") {
  gen::diagnostics diag;
  auto d = read("[2000]\nParameterName=x\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n", false,
                diag);
  REQUIRE(d.has_value());
  d->source_name = "a\nb.eds";
  std::string h = gen::emit_header(*d);
  CHECK(h.starts_with("// Generated from \"a\\012b.eds\" by fieldcodec-gen \xE2\x80\x94 do not "
                      "edit.\n// Regenerate"));
  CHECK(h.find("source_file = \"a\\012b.eds\";") != std::string::npos);
  d->source_name = "caf\xE9.eds"; // Latin-1, as an old file system may hold it
  h = gen::emit_header(*d);
  CHECK(h.starts_with("// Generated from \"caf\\351.eds\" by"));
  CHECK(h.find("source_file = \"caf\\351.eds\";") != std::string::npos);
  CHECK(gen::valid_utf8(h));
  // UTF-8 names stay as they are
  d->source_name = "caf\xC3\xA9 \"1\".eds";
  h = gen::emit_header(*d);
  CHECK(h.starts_with("// Generated from caf\xC3\xA9 \"1\".eds by"));
  CHECK(h.find("source_file = \"caf\xC3\xA9 \\\"1\\\".eds\";") != std::string::npos);
}

// F23 (fuzz_cli_dictionary, `--dict` of the CLI): a number with a non-ASCII character among its
// digits ("DataType=0xÀ0005", a Latin-1 file converted to UTF-8) was reported as "got '\xC3'":
// the first byte of the character alone, so the diagnostic the CLI prints was not UTF-8.
TEST_CASE("fuzz F23: a diagnostic quotes a whole character") {
  gen::diagnostics diag;
  (void)read("[1000]\nParameterName=Device type\nObjectType=0x7\nDataType=0x\xC3\x80"
             "0007\nAccessType=ro\n",
             false, diag);
  REQUIRE(diag.has_errors());
  bool found = false;
  for (const auto &x : diag.all()) {
    CHECK(gen::valid_utf8(x.message));
    found = found || x.message.find("got '\xC3\x80'") != std::string::npos;
  }
  CHECK(found);
  // the one primitive (core/utf8): the length of the character at a position, 0 where none starts
  CHECK(fieldcodec::utf8::sequence_length("a\xC3\x80\xE2\x82\xAC\xF0\x9F\x98\x80", 1) == 2U);
  CHECK(fieldcodec::utf8::sequence_length("a\xC3\x80\xE2\x82\xAC\xF0\x9F\x98\x80", 3) == 3U);
  CHECK(fieldcodec::utf8::sequence_length("a\xC3\x80\xE2\x82\xAC\xF0\x9F\x98\x80", 6) == 4U);
  CHECK(fieldcodec::utf8::sequence_length("a\xC3\x80", 2) == 0U);        // a continuation byte
  CHECK(fieldcodec::utf8::sequence_length("\xC3", 0) == 0U);             // cut
  CHECK(fieldcodec::utf8::sequence_length("\xC0\x80", 0) == 0U);         // overlong
  CHECK(fieldcodec::utf8::sequence_length("\xED\xA0\x80", 0) == 0U);     // a surrogate
  CHECK(fieldcodec::utf8::sequence_length("\xF4\x90\x80\x80", 0) == 0U); // beyond U+10FFFF
  CHECK(fieldcodec::utf8::sequence_length("ab", 2) == 0U);               // past the end
}
