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
