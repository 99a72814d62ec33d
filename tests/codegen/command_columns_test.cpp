// Command tables: the columns that say what a command's parameter and date may be
// (parameter_packing, date_min, date_max, date_packing; docs/dictionary-formats.md), read into
// the model, written into the header, and their diagnostics.
#include "readers.hpp"

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

outcome read_csv(const std::string &text) {
  gen::diagnostics d;
  outcome o;
  o.dict = gen::read_csv(text, "t.csv", d);
  for (const auto &x : d.all()) o.diags.push_back(gen::diagnostics::format(x));
  if (d.has_errors()) o.dict.reset();
  return o;
}

const std::string header = "code,name,parameter_min,parameter_max,parameter_packing,date_type,"
                           "date_min,date_max,date_packing,reply_type\n";

} // namespace

TEST_CASE("command table: ranges and packings are read and emitted") {
  const auto o = read_csv(header + "0800,cmd_a,0x0101,0x1032,byte_byte,float,,,,real\n"
                                   "0902,cmd_b,1,1024,,integer,0,1,,integer\n"
                                   "0AA3,cmd_c,0,16,whole,integer,0x00010001,0x01030400,"
                                   "byte_byte_word,none\n");
  CHECK(o.diags.empty());
  REQUIRE(o.dict);
  const auto &c = o.dict->commands;
  REQUIRE(c.size() == 3);
  CHECK(c[0].parameter_packing == od::packing::byte_byte);
  CHECK(c[0].date_type == od::command_value::real);
  CHECK(c[0].reply_type == od::command_value::real); // "real" is read like "float"
  CHECK(!c[0].date_min);
  CHECK(c[1].date_min == od::signed_number(0));
  CHECK(c[1].date_max == od::signed_number(1));
  CHECK(c[1].date_packing == od::packing::whole);
  CHECK(c[2].date_packing == od::packing::byte_byte_word);
  CHECK(c[2].date_max.to_uint64().value() == 0x01030400U);
  const std::string h = gen::emit_header(*o.dict);
  CHECK(h.find(".parameter_packing = od::packing::byte_byte,") != std::string::npos);
  CHECK(h.find(".date_type = od::command_value::real") != std::string::npos);
  CHECK(h.find(".date_min = od::signed_number(0), .date_max = od::signed_number(1)") !=
        std::string::npos);
  CHECK(h.find(".date_packing = od::packing::byte_byte_word") != std::string::npos);
  CHECK(h.find("od::packing::whole") == std::string::npos); // the default is not written
}

TEST_CASE("command table: bad packings and packed bounds get exact diagnostics") {
  auto o = read_csv(header + "0902,cmd_b,1,1024,,integer,0,1,bytes,integer\n");
  CHECK_FALSE(o.dict);
  REQUIRE(o.diags.size() == 1);
  CHECK(o.diags[0] == "t.csv:2:32: error: expected whole, byte_byte or byte_byte_word, got "
                      "'bytes' in column 'date_packing'");
  o = read_csv(header + "0800,cmd_a,0x0101,0x11032,byte_byte,float,,,,float\n");
  CHECK_FALSE(o.dict);
  REQUIRE(o.diags.size() == 1);
  CHECK(o.diags[0] == "t.csv:2:19: error: expected a value of byte_byte packing (0 to 65535) in "
                      "column 'parameter_max'");
  o = read_csv(header + "0AA3,cmd_c,0,16,,integer,-1,0x01030400,byte_byte_word,none\n");
  CHECK_FALSE(o.dict);
  REQUIRE(o.diags.size() == 1);
  CHECK(o.diags[0] == "t.csv:2:26: error: expected a value of byte_byte_word packing (0 to "
                      "4294967295) in column 'date_min'");
  o = read_csv(header + "0902,cmd_b,1,1024,,integer,zero,1,,integer\n");
  CHECK_FALSE(o.dict);
  REQUIRE(o.diags.size() == 1);
  CHECK(o.diags[0].find("in column 'date_min'") != std::string::npos);
}
