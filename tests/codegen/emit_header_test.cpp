// The C++ emitter's shape (issue 14): the lean entry table, the parallel info and scale tables,
// standalone descriptors for named sub-objects, object views, node-ID-relative limits as flags,
// text columns as {"…", n} (od::text: pointer and length, nothing counted by the compiler),
// view names as "…"sv literals.
#include "readers.hpp"

#include <doctest/doctest.h>

#include <string>

namespace gen = fieldcodec::gen;

namespace {

std::string emit_eds(const std::string &eds, bool sub_descriptors = true) {
  gen::diagnostics d;
  auto dict = gen::read_eds(eds, "t.eds", d);
  REQUIRE(dict.has_value());
  dict->stem = "t";
  dict->source_name = "t.eds";
  dict->sub_descriptors = sub_descriptors;
  return gen::emit_header(*dict);
}

bool has(const std::string &h, const std::string &s) { return h.find(s) != std::string::npos; }

const std::string eds = "[FileInfo]\nFileName=t.eds\n[DeviceInfo]\nVendorName=v\n"
                        "[MandatoryObjects]\nSupportedObjects=2\n1=0x1000\n2=0x1200\n"
                        "[1000]\nParameterName=Device type\nObjectType=0x7\nDataType=0x0007\n"
                        "AccessType=ro\nDefaultValue=0x00020192\nPDOMapping=0\n"
                        "[1200]\nParameterName=Server SDO parameter\nObjectType=0x9\n"
                        "SubNumber=2\n"
                        "[1200sub0]\nParameterName=Highest sub-index\nObjectType=0x7\n"
                        "DataType=0x0005\nAccessType=ro\nDefaultValue=1\nPDOMapping=0\n"
                        "[1200sub1]\nParameterName=COB-ID client to server\nObjectType=0x7\n"
                        "DataType=0x0007\nAccessType=ro\nLowLimit=$NODEID+0x600\n"
                        "HighLimit=$NODEID+0x600\nDefaultValue=$NODEID+0x600\nPDOMapping=0\n";

} // namespace

TEST_CASE("emit_header: tables, descriptors, views, flags, strings") {
  const std::string h = emit_eds(eds);
  CHECK(has(h, "using namespace std::string_view_literals;"));
  // the tables are C arrays in namespace detail, published as static-extent spans
  CHECK(has(h, "namespace detail {\ninline constexpr od::entry entries[3]{\n    {.index = 0x1000"));
  CHECK(has(h, "inline constexpr od::entry_info infos[3]{\n"));
  CHECK(has(h, "} // namespace detail\n\ninline constexpr std::span<const od::entry, 3> "
               "entries{detail::entries};\ninline constexpr std::span<const od::entry_info, 3> "
               "infos{detail::infos};\n"));
  CHECK(has(h, "#include <span>\n"));
  CHECK_FALSE(has(h, "std::array"));
  CHECK_FALSE(has(h, "scales")); // no scaled entry: no scale table
  CHECK(has(h, "inline constexpr od::dictionary dictionary{entries, infos};"));
  CHECK(has(h, "{.name = {\"Device type\", 11}}"));
  // a VAR object and a named RECORD sub-object: standalone descriptors (copies of table rows)
  CHECK(has(h, "inline constexpr od::descriptor device_type{detail::entries[0], detail::infos[0]}; "
               "// 0x1000"));
  CHECK(has(h, "inline constexpr od::object server_sdo_parameter{0x1200, "
               "od::object_code::record, \"Server SDO parameter\"sv, "
               "dictionary.entries().subspan(1, 2), dictionary.infos().subspan(1, 2)};"));
  CHECK(has(h, "inline constexpr od::descriptor server_sdo_parameter_cob_id_client_to_server{"
               "detail::entries[2], detail::infos[2]}; // 0x1200 sub 1"));
  // $NODEID+0x600 in LowLimit, HighLimit and DefaultValue: the number plus a flag each, the
  // numbers packed in the entry's own width (UNSIGNED32: 4 bytes each, little-endian)
  CHECK(has(h, ".flags = od::flag::default_nodeid | od::flag::low_nodeid | "
               "od::flag::high_nodeid | od::flag::has_default | od::flag::has_low | "
               "od::flag::has_high, .extra = \"\\000\\006\\000\\000\\000\\006\\000\\000\\000\\006"
               "\\000\\000\""));
  // the kinds of its values: integers only, with limits relative to the node-ID
  CHECK(has(h, "inline constexpr od::value_kinds kinds{.strings = false, .real = false, .time = "
               "false, .wide = false, .limits = true, .node_limits = true, .scaled = false, "
               ".numbers = false};\n"));
}

TEST_CASE("emit_header: --no-sub-descriptors leaves out exactly the sub-object descriptors") {
  const std::string all = emit_eds(eds);
  const std::string views_only = emit_eds(eds, false);
  // the default header without its sub-object descriptor lines, plus one comment line: every
  // other name, table and view is the same (names are assigned as if the descriptors were there)
  std::string expected;
  std::size_t at = 0;
  std::size_t dropped = 0;
  while (at < all.size()) {
    const std::size_t end = all.find('\n', at) + 1U;
    const std::string line = all.substr(at, end - at);
    const bool sub_descriptor = line.starts_with("inline constexpr od::descriptor ") &&
                                line.find(" sub ") != std::string::npos;
    if (sub_descriptor) {
      ++dropped;
    } else {
      expected += line;
    }
    if (line == "// ARRAY and RECORD objects: views into the tables.\n") {
      expected += "// Sub-objects: view[sub] (generated with --no-sub-descriptors: no standalone "
                  "descriptors).\n";
    }
    at = end;
  }
  CHECK(dropped == 2); // 0x1200 sub 0 and sub 1
  CHECK(views_only == expected);
  CHECK(has(views_only, "inline constexpr od::object server_sdo_parameter{0x1200, "));
  CHECK(has(views_only, "inline constexpr od::descriptor device_type{"));
  CHECK_FALSE(has(views_only, "server_sdo_parameter_cob_id_client_to_server"));
}

TEST_CASE("emit_header: no entries, no C arrays (a C array of length 0 is ill-formed)") {
  gen::diagnostics d;
  auto dict = gen::read_csv("index,subindex,name,data_type,access\n", "t.csv", d);
  REQUIRE(dict.has_value());
  REQUIRE(dict->entries.empty());
  dict->stem = "t";
  const std::string h = gen::emit_header(*dict);
  CHECK_FALSE(has(h, "namespace detail"));
  CHECK(has(h, "inline constexpr std::span<const od::entry, 0> entries{};\n"
               "inline constexpr std::span<const od::entry_info, 0> infos{};\n"));
  CHECK(has(h, "inline constexpr od::dictionary dictionary{entries, infos};"));
}

TEST_CASE("emit_header: scaled CSV rows get a scale table and the scaled flag") {
  gen::diagnostics d;
  auto dict = gen::read_csv("index,subindex,name,data_type,access,low,high,scale,unit\n"
                            "0x2023,0,Inj. P Limit 1,UNSIGNED32,rw,0,5000,327.67,bar\n"
                            "0x2024,0,Raw,UNSIGNED16,rw,,,,\n",
                            "t.csv", d);
  REQUIRE(dict.has_value());
  dict->stem = "t";
  const std::string h = gen::emit_header(*dict);
  CHECK(has(h, "inline constexpr scaling::linear scales[2]{\n"));
  CHECK(has(h, "inline constexpr std::span<const scaling::linear, 2> scales{detail::scales};"));
  CHECK(has(h, "    {{32767, 2}, {0, 0}},\n    {},\n"));
  CHECK(has(h, ".flags = od::flag::scaled"));
  CHECK(has(h, "{.name = {\"Inj. P Limit 1\", 14}, .unit = {\"bar\", 3}}"));
  CHECK(has(h, "inline constexpr od::descriptor inj_p_limit_1{detail::entries[0], "
               "detail::infos[0], detail::scales[0]};"));
  CHECK(has(h, "inline constexpr od::dictionary dictionary{entries, infos, scales};"));
}

TEST_CASE("emit_header: a text's length is its bytes, not its escaped spelling") {
  // 4 bytes `Ab"c` are written with an escape (5 characters between the quotes)
  const std::string h =
      emit_eds("[FileInfo]\nFileName=t.eds\n[DeviceInfo]\nVendorName=v\n"
               "[MandatoryObjects]\nSupportedObjects=1\n1=0x1008\n"
               "[1008]\nParameterName=Say \"hi\"\nObjectType=0x7\nDataType=0x0009\n"
               "AccessType=const\nDefaultValue=Ab\"c\nPDOMapping=0\n");
  // capacity 4 and the default text's length 4, then its bytes ('"' is an octal escape)
  CHECK(has(h, ".flags = od::flag::has_size | od::flag::has_text, .extra = "
               "\"\\004\\000\\000\\000\\004\\000\\000\\000Ab\\042c\""));
  CHECK(has(h, "{.name = {\"Say \\\"hi\\\"\", 8}}"));
}
