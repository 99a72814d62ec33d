// fieldcodec-gen --config-list: the configuration list of a DCF (docs/master.md).
#include "config_list.hpp"
#include "eds_text.hpp"
#include "readers.hpp"

#include "skip.hpp"
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace gen = fieldcodec::gen;
namespace master = fieldcodec::master;
using fieldcodec::od::address;

namespace {

std::string slurp(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<address> addresses(const gen::config_list &l) {
  std::vector<address> r;
  for (const auto &i : l.items) r.push_back(i.address);
  return r;
}

const char *const objects = R"(
[1000]
ParameterName=Device type
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00020192

[1017]
ParameterName=Producer heartbeat time
ObjectType=0x7
DataType=0x0006
AccessType=rw
DefaultValue=0
ParameterValue=100

[1018]
ParameterName=Identity
ObjectType=0x9
SubNumber=2

[1018sub0]
ParameterName=Number
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=1

[1018sub1]
ParameterName=Vendor-ID
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x1234
ParameterValue=0x4321

[1400]
ParameterName=RPDO 1 communication
ObjectType=0x9
SubNumber=3

[1400sub0]
ParameterName=Highest sub-index
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=2

[1400sub1]
ParameterName=COB-ID
ObjectType=0x7
DataType=0x0007
AccessType=rw
DefaultValue=$NODEID+0x200

[1400sub2]
ParameterName=Transmission type
ObjectType=0x7
DataType=0x0005
AccessType=rw
DefaultValue=255

[1600]
ParameterName=RPDO 1 mapping
ObjectType=0x9
SubNumber=3

[1600sub0]
ParameterName=Count
ObjectType=0x7
DataType=0x0005
AccessType=rw
DefaultValue=1
ParameterValue=2

[1600sub1]
ParameterName=Entry 1
ObjectType=0x7
DataType=0x0007
AccessType=rw
DefaultValue=0x60400010

[1600sub2]
ParameterName=Entry 2
ObjectType=0x7
DataType=0x0007
AccessType=rw
DefaultValue=0
ParameterValue=0x607A0020

[1801]
ParameterName=TPDO 2 communication
ObjectType=0x9
SubNumber=3

[1801sub0]
ParameterName=Highest sub-index
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=2

[1801sub1]
ParameterName=COB-ID
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=$NODEID+0x280

[1801sub2]
ParameterName=Transmission type
ObjectType=0x7
DataType=0x0005
AccessType=rw
DefaultValue=255
ParameterValue=1

[2000]
ParameterName=Gain
ObjectType=0x7
DataType=0x0008
AccessType=rw
DefaultValue=1.5
ParameterValue=0.25

[2001]
ParameterName=Offset
ObjectType=0x7
DataType=0x0003
AccessType=wo
DefaultValue=0
ParameterValue=-2

[2002]
ParameterName=Label
ObjectType=0x7
DataType=0x0009
AccessType=rw
DefaultValue=axis
ParameterValue=x1

[2003]
ParameterName=Unchanged
ObjectType=0x7
DataType=0x0007
AccessType=rw
DefaultValue=7
ParameterValue=7

[2004]
ParameterName=Read only
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=7
ParameterValue=8
)";

gen::config_list build(const std::string &text, gen::config_values v, gen::diagnostics &diag,
                       int node = 3) {
  std::string dcf = gen::test::eds_file(objects + text);
  dcf += "\n[DeviceComissioning]\nNodeID=" + std::to_string(node) + "\n";
  auto d = gen::read_eds(dcf, "t.dcf", diag);
  REQUIRE(d);
  return gen::build_config_list(*d, v, "t.dcf", diag);
}

} // namespace

TEST_CASE("config list: ParameterValue that differs, in the CiA 301 PDO order") {
  gen::diagnostics diag;
  const auto l = build("", gen::config_values::parameter, diag);
  const std::vector<address> expect{{0x1017, 0}, // heartbeat
                                    {0x1400, 1}, {0x1600, 0}, {0x1600, 1},
                                    {0x1600, 2}, {0x1600, 0}, {0x1400, 1}, // RPDO 1
                                    {0x1801, 2}, // TPDO 2: COB-ID read-only
                                    {0x2000, 0}, {0x2001, 0}, {0x2002, 0}};
  CHECK(addresses(l) == expect);
  CHECK(l.node_id == 3U);
  // identity: 1000h default, 1018h sub 1 from its ParameterValue; never written
  CHECK(l.expected.device_type == 0x00020192U);
  CHECK(l.expected.vendor_id == 0x4321U);
  CHECK(l.expected.product_code == 0U);
  // RPDO 1: COB-ID disabled (bit 31) node-relative, mapping 0, entries, count, COB-ID enabled
  CHECK(l.items[1].value == std::vector<std::uint8_t>{0x00, 0x02, 0x00, 0x80});
  CHECK(l.items[1].flags == master::config_flag::node_relative);
  CHECK(l.items[2].value == std::vector<std::uint8_t>{0});
  CHECK(l.items[3].value == std::vector<std::uint8_t>{0x10, 0x00, 0x40, 0x60}); // default kept
  CHECK(l.items[4].value == std::vector<std::uint8_t>{0x20, 0x00, 0x7A, 0x60});
  CHECK(l.items[5].value == std::vector<std::uint8_t>{2});
  CHECK(l.items[6].value == std::vector<std::uint8_t>{0x00, 0x02, 0x00, 0x00});
  CHECK(l.items[6].name == "RPDO 1 communication: COB-ID");
  // REAL32 0.25, INTEGER16 -2 (write-only: not verified), a string
  CHECK(l.items[8].value == std::vector<std::uint8_t>{0x00, 0x00, 0x80, 0x3E});
  CHECK(l.items[9].value == std::vector<std::uint8_t>{0xFE, 0xFF});
  CHECK(l.items[9].flags == master::config_flag::no_verify);
  CHECK(l.items[10].value == std::vector<std::uint8_t>{'x', '1'});
  CHECK(l.items[10].name == "Label");
  // TPDO 2 has a read-only COB-ID: said, and its parameters written without disabling
  REQUIRE(diag.warning_count() >= 1U);
  CHECK(diag.all().back().message ==
        "TPDO 2: no writable COB-ID value (sub 1): its parameters are written without disabling "
        "the PDO first");
}

TEST_CASE("config list: a mapping entry is named by what it maps, not by its EDS name") {
  // 1601h sub 1 is named after its default content (Controlword) while the DCF maps 607Ah there
  const char *const remapped = R"(
[1401]
ParameterName=RPDO 2 communication
ObjectType=0x9
SubNumber=2

[1401sub0]
ParameterName=Highest sub-index
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=1

[1401sub1]
ParameterName=COB-ID
ObjectType=0x7
DataType=0x0007
AccessType=rw
DefaultValue=$NODEID+0x300

[1601]
ParameterName=RPDO 2 mapping
ObjectType=0x9
SubNumber=4

[1601sub0]
ParameterName=Count
ObjectType=0x7
DataType=0x0005
AccessType=rw
DefaultValue=1
ParameterValue=3

[1601sub1]
ParameterName=Controlword
ObjectType=0x7
DataType=0x0007
AccessType=rw
DefaultValue=0x60400010
ParameterValue=0x607A0020

[1601sub2]
ParameterName=Modes of operation
ObjectType=0x7
DataType=0x0007
AccessType=rw
DefaultValue=0x60600008
ParameterValue=0x20050108

[1601sub3]
ParameterName=Target velocity
ObjectType=0x7
DataType=0x0007
AccessType=rw
DefaultValue=0x60FF0020
ParameterValue=0

[2005]
ParameterName=Outputs
ObjectType=0x8
SubNumber=2

[2005sub0]
ParameterName=Highest sub-index
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=1

[2005sub1]
ParameterName=Output 1
ObjectType=0x7
DataType=0x0005
AccessType=rw
PDOMapping=1
DefaultValue=0

[607A]
ParameterName=Target position
ObjectType=0x7
DataType=0x0004
AccessType=rw
PDOMapping=1
DefaultValue=0
)";
  gen::diagnostics diag;
  const auto l = build(remapped, gen::config_values::parameter, diag);
  std::vector<std::string> names;
  for (const auto &i : l.items) {
    if (i.address.index == 0x1601U || i.address.index == 0x1600U) names.push_back(i.name);
  }
  const std::vector<std::string> expect{
      "RPDO 1 mapping: Count",
      "RPDO 1 mapping: entry 1 = 6040h sub 0, 16 bits", // not in this dictionary
      "RPDO 1 mapping: entry 2 = Target position (607Ah sub 0, 32 bits)",
      "RPDO 1 mapping: Count",
      "RPDO 2 mapping: Count",
      "RPDO 2 mapping: entry 1 = Target position (607Ah sub 0, 32 bits)",
      "RPDO 2 mapping: entry 2 = Outputs: Output 1 (2005h sub 1, 8 bits)",
      "RPDO 2 mapping: entry 3 = empty",
      "RPDO 2 mapping: Count"};
  CHECK(names == expect);
}

TEST_CASE("config list: --config-values default writes every writable default") {
  gen::diagnostics diag;
  const auto l = build("", gen::config_values::default_, diag);
  const std::vector<address> expect{{0x1017, 0}, {0x1400, 1}, {0x1400, 2}, {0x1600, 0}, {0x1600, 1},
                                    {0x1600, 2}, {0x1600, 0}, {0x1400, 1}, {0x1801, 2}, {0x2000, 0},
                                    {0x2001, 0}, {0x2002, 0}, {0x2003, 0}};
  CHECK(addresses(l) == expect);
  CHECK(l.items[0].value == std::vector<std::uint8_t>{0, 0});
  CHECK(l.items[9].value == std::vector<std::uint8_t>{0x00, 0x00, 0xC0, 0x3F}); // 1.5f
  // the mapping entries keep the final values (ParameterValue where given)
  CHECK(l.items[5].value == std::vector<std::uint8_t>{0x20, 0x00, 0x7A, 0x60});
}

TEST_CASE("config list: the emitted header, the concise DCF, no node-ID") {
  gen::diagnostics diag;
  std::string dcf = gen::test::eds_file(objects);
  auto d = gen::read_eds(dcf, "t.dcf", diag);
  REQUIRE(d);
  d->stem = "t";
  const auto l = gen::build_config_list(*d, gen::config_values::parameter, "t.dcf", diag);
  CHECK(l.node_id == 0U);
  const std::string h = gen::emit_config_list(*d, l);
  CHECK(h.find("namespace fieldcodec::dictionaries::t::config {") != std::string::npos);
  CHECK(h.find("inline constexpr std::uint8_t node_id = 0;") != std::string::npos);
  CHECK(h.find("// No concise DCF") != std::string::npos); // node-relative, no node-ID
  CHECK(h.find("master::config_flag::no_verify, \"Offset\"") != std::string::npos);
}

TEST_CASE("config list: the fixture of the master tests matches its checked-in header") {
  gen::diagnostics diag;
  diag.strict = true;
  auto d = gen::read_file("master/fixtures/xenax_axis.dcf", diag);
  REQUIRE(d);
  const auto l = gen::build_config_list(*d, gen::config_values::parameter, "xenax_axis.dcf", diag);
  CHECK_FALSE(diag.has_errors());
  // regenerate with: fieldcodec-gen --config-list tests/master/generated/xenax_axis_config.hpp
  //                  tests/master/fixtures/xenax_axis.dcf
  CHECK(gen::emit_config_list(*d, l) == slurp("master/generated/xenax_axis_config.hpp"));
}

TEST_CASE("nmt slaves: the master DCF fixture matches its checked-in header") {
  gen::diagnostics diag;
  auto d = gen::read_file("master/fixtures/master.dcf", diag);
  REQUIRE(d);
  const auto rows = gen::build_nmt_slaves(*d, "master/fixtures/master.dcf", diag);
  CHECK_FALSE(diag.has_errors());
  REQUIRE(rows.size() == 2U); // node 7 has 0: not a slave
  CHECK(rows[0].node == 5U);
  CHECK(rows[0].dcf_source == "./master_axis5.bin");
  CHECK(rows[0].concise_dcf.size() == 80U);
  CHECK(rows[0].objects.consumer_time_ms == 500U);
  CHECK(rows[1].node == 6U);
  CHECK(rows[1].dcf_source == "ParameterValue");
  CHECK(rows[1].objects.consumer_time_ms == 0U); // 1016h sub 2 names node 6 with time 0
  // regenerate with: fieldcodec-gen --nmt-slaves tests/master/generated/master_slaves.hpp
  //                  tests/master/fixtures/master.dcf
  CHECK(gen::emit_nmt_slaves(*d, rows) == slurp("master/generated/master_slaves.hpp"));
}

TEST_CASE("nmt slaves: what is read from a master DCF, and what is refused") {
  const std::string dir = "nmt_slaves_test_dir";
  std::filesystem::create_directories(dir);
  {
    std::ofstream good(dir + "/good.bin", std::ios::binary);
    const char bytes[] = {1, 0, 0, 0, 0x17, 0x10, 0, 2, 0, 0, 0, 0x64, 0};
    good.write(bytes, sizeof bytes);
    std::ofstream bad(dir + "/bad.bin", std::ios::binary);
    bad.write(bytes, sizeof bytes - 1); // the data ends early
  }
  const auto master_dcf = [](const std::string &f22) {
    return gen::test::eds_file(R"(
[1016]
ParameterName=Consumer heartbeat time
ObjectType=0x8
DataType=0x0007
AccessType=rw
CompactSubObj=3

[1016Value]
NrOfEntries=2
1=0x000301F4
3=0x00090064

[1F81]
ParameterName=NMT slave assignment
ObjectType=0x8
DataType=0x0007
AccessType=rw
CompactSubObj=127

[1F81Value]
NrOfEntries=3
3=0x01F40315
9=0x00000085
10=0

[1F86]
ParameterName=Product code
ObjectType=0x8
DataType=0x0007
AccessType=rw
CompactSubObj=127

[1F86Value]
NrOfEntries=1
9=0x00001234

[1F8A]
ParameterName=Restore configuration
ObjectType=0x8
DataType=0x0005
AccessType=rw
CompactSubObj=127

[1F8AValue]
NrOfEntries=1
9=3

[1F22]
ParameterName=Concise DCF
ObjectType=0x8
SubNumber=2

[1F22sub0]
ParameterName=Highest sub-index supported
ObjectType=0x7
DataType=0x0005
AccessType=const
DefaultValue=3

[1F22sub3]
ParameterName=Node-ID 3
ObjectType=0x7
DataType=0x000F
AccessType=ro
)" + f22 + "\n");
  };
  SUBCASE("an UploadFile beside the DCF, the consumer time, the other objects") {
    gen::diagnostics diag;
    auto d = gen::read_eds(master_dcf("UploadFile=good.bin"), dir + "/m.dcf", diag);
    REQUIRE(d);
    d->stem = "m";
    const auto rows = gen::build_nmt_slaves(*d, dir + "/m.dcf", diag);
    CHECK_FALSE(diag.has_errors());
    REQUIRE(rows.size() == 2U);
    CHECK(rows[0].node == 3U);
    CHECK(rows[0].objects.assignment == 0x01F40315U);
    CHECK(rows[0].objects.consumer_time_ms == 500U);
    CHECK(rows[0].concise_dcf ==
          std::vector<std::uint8_t>{1, 0, 0, 0, 0x17, 0x10, 0, 2, 0, 0, 0, 0x64, 0});
    CHECK(rows[1].node == 9U);
    CHECK(rows[1].objects.consumer_time_ms == 100U);
    CHECK(rows[1].objects.expected.product_code == 0x1234U);
    CHECK(rows[1].objects.restore_sub == 3U);
    CHECK(rows[1].concise_dcf.empty());
    const std::string h = gen::emit_nmt_slaves(*d, rows);
    CHECK(h.find("namespace fieldcodec::dictionaries::m::slaves {") != std::string::npos);
    CHECK(h.find("{9, {0x00000085U, {0x00000000U, 0x00000000U, 0x00001234U, 0x00000000U, "
                 "0x00000000U}, {}, 100, 0x00000000U, 0x00000000U, 0x00000000U, 3}},") !=
          std::string::npos);
  }
  SUBCASE("a missing file and a malformed concise DCF are errors at the 1F22h sub-object") {
    for (const std::string f22 : {"UploadFile=missing.bin", "UploadFile=bad.bin"}) {
      gen::diagnostics diag;
      const std::string text = master_dcf(f22);
      auto d = gen::read_eds(text, dir + "/m.dcf", diag);
      REQUIRE(d);
      const auto rows = gen::build_nmt_slaves(*d, dir + "/m.dcf", diag);
      REQUIRE(diag.has_errors());
      CHECK(diag.all().back().line == gen::test::line_of(text, "[1F22sub3]"));
      CHECK(diag.all().back().message ==
            (f22 == "UploadFile=missing.bin"
                 ? "1F22h sub 3: UploadFile 'missing.bin': cannot open file"
                 : "1F22h sub 3 (bad.bin): not a concise DCF: truncated input"));
      CHECK(rows.size() == 1U); // node 9 still listed
    }
  }
  SUBCASE("no slaves") {
    gen::diagnostics diag;
    auto d = gen::read_eds(gen::test::eds_file(objects), "n.dcf", diag);
    REQUIRE(d);
    d->stem = "n";
    const auto rows = gen::build_nmt_slaves(*d, "n.dcf", diag);
    CHECK(rows.empty());
    CHECK(gen::emit_nmt_slaves(*d, rows).find("slaves{};") != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("config list: every DCF of the corpus gives a well-formed list") {
  const std::filesystem::path corpus =
      std::filesystem::path(fieldcodec::test::shared_dir) / "eds-corpus";
  if (!std::filesystem::exists(corpus)) {
    FIELDCODEC_SKIP_TEST("corpus", "EDS corpus not found at " << corpus.string());
  }
  int files = 0;
  for (const auto &f : std::filesystem::directory_iterator(corpus)) {
    if (f.path().extension() != ".dcf") continue;
    ++files;
    CAPTURE(f.path().string());
    gen::diagnostics diag;
    auto d = gen::read_file(f.path().string(), diag);
    if (!d) continue; // the reader's own tests judge the file
    const auto l = gen::build_config_list(*d, gen::config_values::parameter, "x", diag);
    std::size_t size = 4;
    for (std::size_t i = 0; i < l.items.size(); ++i) {
      const auto &it = l.items[i];
      size += 7U + it.value.size();
      CHECK(it.address.index >= 0x1000U);
      CHECK(it.address.index != 0x1018U);
      const bool map = it.address.index >= 0x1600U && it.address.index <= 0x17FFU;
      const bool tmap = it.address.index >= 0x1A00U && it.address.index <= 0x1BFFU;
      if ((map || tmap) && it.address.sub == 0U && it.value == std::vector<std::uint8_t>{0}) {
        // a mapping is rewritten: count 0, entries 1..n, count n (n > 0)
        std::size_t j = i + 1;
        std::uint8_t sub = 1;
        while (j < l.items.size() && l.items[j].address.index == it.address.index &&
               l.items[j].address.sub != 0U) {
          CHECK(l.items[j].address.sub >= sub);
          sub = static_cast<std::uint8_t>(l.items[j].address.sub + 1U);
          ++j;
        }
        if (j > i + 1U) {
          REQUIRE(j < l.items.size());
          CHECK(l.items[j].address == address{it.address.index, 0});
          CHECK(l.items[j].value ==
                std::vector<std::uint8_t>{static_cast<std::uint8_t>(j - i - 1U)});
        }
      }
    }
    std::vector<master::config_item> view;
    for (const auto &it : l.items) view.push_back({it.address, it.value, it.flags, it.name});
    CHECK(master::concise_dcf_size({view, l.expected, l.node_id}) == size);
  }
  CHECK(files > 0);
}
