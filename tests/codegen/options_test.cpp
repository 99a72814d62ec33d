// Issue 18 generator options: --only index filters and --compact-arrays (options.hpp).
#include "eds_text.hpp"
#include "text.hpp"

#include <doctest/doctest.h>

#include <string>

namespace gen = fieldcodec::gen;
namespace od = fieldcodec::od;
using gen::test::eds_file;
using gen::test::find_entry;
using gen::test::read_eds_text;

namespace {

std::string var(const char *index) {
  return std::string("[") + index + "]\nParameterName=Object " + index +
         "\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nPDOMapping=0\n\n";
}

std::string compact_array(const char *index, int n, const std::string &extra = "") {
  return std::string("[") + index + "]\nParameterName=Map\nObjectType=0x8\nDataType=0x0007\n" +
         "AccessType=rw\nDefaultValue=0\nPDOMapping=0\nCompactSubObj=" + std::to_string(n) +
         "\n\n" + extra;
}

} // namespace

TEST_CASE("--only: index ranges and their errors") {
  std::vector<gen::index_range> r;
  CHECK(gen::parse_index_ranges("0x1000-0x1FFF,0x6000-0x67FF, 0x1018", r).empty());
  REQUIRE(r.size() == 3);
  CHECK(r[0].first == 0x1000);
  CHECK(r[0].last == 0x1FFF);
  CHECK(r[1].first == 0x6000);
  CHECK(r[2].first == 0x1018);
  CHECK(r[2].last == 0x1018);
  std::vector<gen::index_range> x;
  CHECK(gen::parse_index_ranges("", x) ==
        "expected index ranges such as 0x1000-0x1FFF,0x6000-0x67FF");
  CHECK(gen::parse_index_ranges("0x2000-0x1000", x) ==
        "range '0x2000-0x1000' ends before it begins");
  CHECK(gen::parse_index_ranges("0x1000-", x) == "expected an index such as 0x1000, got ''");
  CHECK(gen::parse_index_ranges("1000-1FFF", x) == "expected an index such as 0x1000, got '1000'");
  CHECK(gen::parse_index_ranges("0x1000-0x10000", x) == "index '0x10000' is beyond 0xFFFF");
  CHECK(gen::parse_index_ranges("0x1000,,0x2000", x) ==
        "expected an index range between the commas, got nothing");
  CHECK(gen::parse_index_ranges("0x1000,", x) ==
        "expected an index range between the commas, got nothing");
  CHECK(gen::parse_index_ranges("0x1G00", x) ==
        "expected a hexadecimal digit, got 'G' in '0x1G00'");
}

TEST_CASE("--only keeps the objects in the ranges, in the header model and the export") {
  auto r =
      read_eds_text(eds_file(var("1000") + var("1018") + var("2000") + var("6040") + var("6800")));
  REQUIRE(r.dict);
  gen::generator_options o;
  REQUIRE(gen::parse_index_ranges("0x1000-0x1FFF,0x6000-0x67FF", o.only).empty());
  gen::diagnostics diag;
  CHECK(gen::apply_options(*r.dict, o, "t.eds", diag));
  CHECK(diag.all().empty());
  std::vector<std::uint16_t> kept;
  for (const auto &[index, info] : r.dict->objects) kept.push_back(index);
  CHECK(kept == std::vector<std::uint16_t>{0x1000, 0x1018, 0x6040});
  CHECK(r.dict->entries.size() == 3);
  const std::string w = gen::write_eds(*r.dict);
  CHECK(w.find("[2000]") == std::string::npos);
  CHECK(w.find("[6800]") == std::string::npos);

  gen::generator_options none;
  REQUIRE(gen::parse_index_ranges("0x3000-0x3FFF", none.only).empty());
  gen::diagnostics d2;
  CHECK(gen::apply_options(*r.dict, none, "t.eds", d2));
  REQUIRE(d2.all().size() == 1);
  CHECK(gen::diagnostics::format(d2.all()[0]) ==
        "t.eds: warning: --only: no object in 0x3000-0x3FFF");
}

TEST_CASE("--compact-arrays: a CompactSubObj array stays one run, the export expands it") {
  auto r = read_eds_text(eds_file(compact_array("1A00", 254)));
  REQUIRE(r.dict);
  const gen::dictionary expanded = *r.dict;
  REQUIRE(expanded.entries.size() == 255);
  gen::generator_options o;
  o.compact_arrays = true;
  gen::diagnostics diag;
  CHECK(gen::apply_options(*r.dict, o, "t.eds", diag));
  REQUIRE(r.dict->entries.size() == 2);
  const gen::entry &sub0 = r.dict->entries[0];
  CHECK(sub0.sub == 0);
  CHECK(sub0.count == 1);
  CHECK(sub0.default_value == od::unsigned_number(254));
  const gen::entry &run = r.dict->entries[1];
  CHECK(run.sub == 1);
  CHECK(run.count == 254);
  CHECK(run.name == "Map"); // sub-index i is named "Map<i>"
  CHECK(run.default_value == od::unsigned_number(0));
  // the EDS export is the same as without the option
  CHECK(gen::write_eds(*r.dict) == gen::write_eds(expanded));
  gen::dictionary back = *r.dict;
  gen::expand_runs(back);
  REQUIRE(back.entries.size() == 255);
  CHECK(back.entries[254].sub == 254);
  CHECK(back.entries[254].name == "Map254");
}

TEST_CASE("--compact-arrays: sub-objects with their own name or value stay apart") {
  auto r = read_eds_text(eds_file(compact_array("1A00", 6,
                                                "[1A00Name]\nNrOfEntries=1\n3=Status word\n\n"
                                                "[1A00Value]\nNrOfEntries=1\n5=0x60410010\n\n")));
  REQUIRE(r.dict);
  gen::dictionary expanded = *r.dict;
  gen::compact_arrays(*r.dict);
  std::vector<std::pair<int, int>> runs; // (sub, count)
  for (const auto &e : r.dict->entries) runs.emplace_back(e.sub, e.count);
  CHECK(runs == std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {3, 1}, {4, 1}, {5, 1}, {6, 1}});
  CHECK(find_entry(*r.dict, 0x1A00, 3)->name == "Status word");
  CHECK(find_entry(*r.dict, 0x1A00, 5)->parameter_value == od::unsigned_number(0x60410010));
  gen::expand_runs(*r.dict);
  CHECK(gen::write_eds(*r.dict) == gen::write_eds(expanded));
}

TEST_CASE("--compact-arrays: only ARRAYs; RECORDs and explicit unlike sub-objects stay") {
  const std::string rec =
      "[2000]\nParameterName=Rec\nObjectType=0x9\nSubNumber=3\n\n"
      "[2000sub0]\nParameterName=n\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
      "DefaultValue=2\nPDOMapping=0\n\n"
      "[2000sub1]\nParameterName=Value1\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
      "PDOMapping=0\n\n"
      "[2000sub2]\nParameterName=Value2\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
      "PDOMapping=0\n\n";
  std::string arr = rec;
  arr.replace(arr.find("ObjectType=0x9"), 14, "ObjectType=0x8");
  for (const std::string &text : {rec, arr}) {
    auto r = read_eds_text(eds_file(text));
    REQUIRE(r.dict);
    gen::compact_arrays(*r.dict);
    const bool array = r.dict->objects.at(0x2000).code == od::object_code::array;
    CHECK(r.dict->entries.size() == (array ? 2U : 3U));
  }
  // an ARRAY whose sub-objects differ in access stays expanded
  std::string unlike = arr;
  unlike.replace(unlike.rfind("AccessType=rw"), 13, "AccessType=ro");
  auto u = read_eds_text(eds_file(unlike));
  REQUIRE(u.dict);
  gen::compact_arrays(*u.dict);
  CHECK(u.dict->entries.size() == 3);
}
