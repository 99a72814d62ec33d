// Issue 14 (generator side): one table of data types and one of access types, read by both
// readers and the writer; the ObjFlags of a container is read once and its errors reported;
// the object lists as an enum.
#include "eds_text.hpp"
#include "text.hpp"

#include <doctest/doctest.h>
#include <fieldcodec/od/data_type.hpp>

#include <string>

namespace gen = fieldcodec::gen;
namespace od = fieldcodec::od;
using gen::test::eds_file;
using gen::test::find_entry;
using gen::test::line_of;
using gen::test::read_csv_text;
using gen::test::read_eds_text;

// The table answers for every type (the predicates are read from it).
static_assert(od::data_types.size() == 25);
static_assert(od::info(od::data_type::integer24).size == 3);
static_assert(od::info(od::data_type::unsigned56).kind == od::type_class::unsigned_integer);
static_assert(od::fixed_size(od::data_type::time_of_day) == 6 &&
              od::is_time(od::data_type::time_difference));
static_assert(od::is_byte_string(od::data_type::domain) &&
              od::fixed_size(od::data_type::domain) == 0);
static_assert(od::find_data_type(std::uint16_t{0x000E}) == nullptr);
static_assert(od::find_data_type(std::uint16_t{0x001C}) == nullptr);
static_assert(od::find_data_type(std::uint16_t{0x0011})->type == od::data_type::real64);
static_assert(od::find_data_type(std::string_view("REAL64"))->identifier == "real64");
static_assert(od::find_data_type(std::string_view("real64")) == nullptr); // exact spelling
// a value of the enumeration that is no type has an empty row, not an out-of-bounds read
static_assert(od::info(static_cast<od::data_type>(0x0017)).kind == od::type_class::unassigned);
static_assert(od::name(static_cast<od::data_type>(0x0040)).empty());
static_assert(od::find_access("const")->value == od::access::constant);
static_assert(od::info(od::access::constant).identifier == "constant");
static_assert(od::find_access("RO") == nullptr);
static_assert(od::readable(od::access::rww) && od::writable(od::access::rwr));
static_assert(!od::writable(od::access::ro) && !od::readable(od::access::wo));
static_assert(od::find_object_code(std::uint32_t{0x9})->name == "RECORD");
static_assert(od::find_object_code(std::uint32_t{0x3}) == nullptr);
static_assert(od::find_object_code(std::string_view("DEFSTRUCT"))->code ==
              od::object_code::defstruct);
static_assert(od::name(od::pdo_mapping::tx) == "tx");

TEST_CASE("data types: every row of the table reads from EDS and CSV and writes back") {
  for (const auto &row : od::data_types) {
    INFO(row.name);
    const bool bytes = row.kind == od::type_class::byte_string;
    // CSV: the CiA name
    auto c = read_csv_text(std::string("index,name,data_type,bytes\n0x2000,x,") +
                           std::string(row.name) + "," + (bytes ? "4" : "") + "\n");
    REQUIRE(c.dict);
    CHECK(find_entry(*c.dict, 0x2000, 0)->type == row.type);
    // EDS: the code
    auto e = read_eds_text(eds_file("[2000]\nParameterName=x\nObjectType=0x7\nDataType=0x" +
                                    gen::hex(static_cast<std::uint16_t>(row.type), 4) +
                                    "\nAccessType=rw\nPDOMapping=0\n"));
    REQUIRE(e.dict);
    CHECK(find_entry(*e.dict, 0x2000, 0)->type == row.type);
    // the writer: the code again
    CHECK(gen::write_eds(*c.dict).find("DataType=0x" +
                                       gen::hex(static_cast<std::uint16_t>(row.type), 4) + "\n") !=
          std::string::npos);
  }
}

TEST_CASE("access types: every row reads from EDS (any case) and CSV and writes back") {
  for (const auto &row : od::access_types) {
    INFO(row.name);
    auto c = read_csv_text("index,name,data_type,access\n0x2000,x,UNSIGNED8," +
                           std::string(row.name) + "\n");
    REQUIRE(c.dict);
    CHECK(find_entry(*c.dict, 0x2000, 0)->access == row.value);
    auto e = read_eds_text(eds_file("[2000]\nParameterName=x\nObjectType=0x7\nDataType=0x0005\n"
                                    "AccessType=" +
                                    gen::to_upper(row.name) + "\nPDOMapping=0\n"));
    REQUIRE(e.dict);
    CHECK(find_entry(*e.dict, 0x2000, 0)->access == row.value);
    CHECK(gen::write_eds(*c.dict).find("AccessType=" + std::string(row.name) + "\n") !=
          std::string::npos);
  }
  auto bad = read_csv_text("index,name,data_type,access\n0x2000,x,UNSIGNED8,RO\n");
  CHECK(bad.diags == std::vector<std::string>{"t.csv:2:20: error: expected ro, wo, rw, rwr, rww "
                                              "or const, got 'RO' in column 'access'"});
}

TEST_CASE("ObjFlags of a container is read once and a bad value is an error") {
  const std::string text = eds_file("[2000]\nParameterName=Rec\nObjectType=0x9\nSubNumber=1\n"
                                    "ObjFlags=0x1Z\n\n[2000sub0]\nParameterName=n\nObjectType=0x7\n"
                                    "DataType=0x0005\nAccessType=ro\nPDOMapping=0\n");
  auto r = read_eds_text(text);
  // before the fix the object section's ObjFlags was parsed a second time and its error dropped
  CHECK_FALSE(r.dict);
  CHECK(r.diags == std::vector<std::string>{
                       "t.eds:" + std::to_string(line_of(text, "ObjFlags=0x1Z")) +
                       ":13: error: expected a hexadecimal digit, got 'Z' in '0x1Z' in ObjFlags "
                       "of [2000]"});
  auto ok = read_eds_text(eds_file("[2000]\nParameterName=Rec\nObjectType=0x9\nSubNumber=1\n"
                                   "ObjFlags=0x3\n\n[2000sub0]\nParameterName=n\nObjectType=0x7\n"
                                   "DataType=0x0005\nAccessType=ro\nPDOMapping=0\n"));
  REQUIRE(ok.dict);
  CHECK(ok.dict->objects.at(0x2000).obj_flags == 3U);
  CHECK(ok.dict->objects.at(0x2000).has_obj_flags);
  CHECK(gen::write_eds(*ok.dict).find("ObjectType=0x9\nObjFlags=0x3\n") != std::string::npos);
}

TEST_CASE("object lists: read into the enum, written back in the same lists") {
  const std::string text =
      "[FileInfo]\nFileName=t.eds\n\n[DeviceInfo]\nVendorName=T\n\n"
      "[MandatoryObjects]\nSupportedObjects=1\n1=0x1000\n\n"
      "[ManufacturerObjects]\nSupportedObjects=1\n1=0x2000\n\n"
      "[1000]\nParameterName=a\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nPDOMapping=0\n\n"
      "[2000]\nParameterName=b\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nPDOMapping=0\n\n"
      "[6000]\nParameterName=c\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nPDOMapping=0\n";
  auto r = read_eds_text(text);
  REQUIRE(r.dict);
  CHECK(r.dict->objects.at(0x1000).list == gen::object_list::mandatory);
  CHECK(r.dict->objects.at(0x2000).list == gen::object_list::manufacturer);
  CHECK(r.dict->objects.at(0x6000).list == gen::object_list::optional); // not listed: warned
  const std::string w = gen::write_eds(*r.dict);
  CHECK(w.find("[MandatoryObjects]\nSupportedObjects=1\n1=0x1000\n") != std::string::npos);
  CHECK(w.find("[OptionalObjects]\nSupportedObjects=1\n1=0x6000\n") != std::string::npos);
  CHECK(w.find("[ManufacturerObjects]\nSupportedObjects=1\n1=0x2000\n") != std::string::npos);
}

// A CSV table has no object lists: 1000h, 1001h and 1018h go to MandatoryObjects (CiA 306), the
// rest by range. The DPQ table has 1001h and no 1000h/1018h (write_eds adds those two).
TEST_CASE("object lists of a CSV table: 1001h is mandatory") {
  auto r = read_csv_text("index,subindex,object_code,name,data_type,access\n"
                         "0x1001,0,VAR,Error Register,UNSIGNED8,ro\n"
                         "0x1017,0,VAR,Producer Heartbeat,UNSIGNED16,rw\n"
                         "0x2000,0,VAR,x,UNSIGNED8,rw\n");
  REQUIRE(r.dict);
  CHECK(r.dict->objects.at(0x1001).list == gen::object_list::mandatory);
  CHECK(r.dict->objects.at(0x1017).list == gen::object_list::optional);
  CHECK(r.dict->objects.at(0x2000).list == gen::object_list::manufacturer);
  gen::add_mandatory_objects(*r.dict); // as fieldcodec-gen --eds does for a CSV table
  CHECK(r.dict->objects.at(0x1001).name == "Error Register"); // the table's, not doubled
  const std::string w = gen::write_eds(*r.dict);
  CHECK(w.find("[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018\n") !=
        std::string::npos);
  CHECK(w.find("[OptionalObjects]\nSupportedObjects=1\n1=0x1017\n") != std::string::npos);
}

TEST_CASE("a missing DataType is one error, not followed by errors about the values") {
  const std::string text =
      eds_file("[2000]\nParameterName=x\nObjectType=0x7\nAccessType=ro\nDefaultValue=7\nSize=3\n");
  auto r = read_eds_text(text);
  CHECK(r.diags == std::vector<std::string>{"t.eds:" + std::to_string(line_of(text, "[2000]")) +
                                            ":2: error: missing DataType in [2000]"});
}
