// host::parameter_file: a node's 1010h "save" and 1011h "load" kept in a file, and the saved
// values put back after power-on and resets (CiA 301 7.5.2.13/7.5.2.14), over the node tests'
// dictionary: groups, PDO mappings in CiA 301's order, 1019h beside 1006h, malformed files,
// refused values, unwritable paths.
#include "node/node_test_util.hpp"

#include <fieldcodec/host/parameter_file.hpp>

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

using namespace test_node;
namespace host = fieldcodec::host;
namespace fs = std::filesystem;

namespace {

constexpr std::uint32_t save = 0x6576'6173U; // "save"
constexpr std::uint32_t load = 0x6461'6F6CU; // "load"

/// A fresh folder for one test case's files, removed with it.
struct folder {
  fs::path path;
  folder() {
    std::string t = (fs::temp_directory_path() / "fieldcodec-parfile-XXXXXX").string();
    REQUIRE(::mkdtemp(t.data()) != nullptr);
    path = t;
  }
  ~folder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  [[nodiscard]] std::string file(const char *name) const { return (path / name).string(); }
};

std::string contents(const std::string &path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
void put(const std::string &path, const std::string &text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

/// A node in operational whose 1010h/1011h keep its parameters in `path`.
struct saving_node {
  rig<> r;
  host::parameter_file file;
  explicit saving_node(const std::string &path) : file(path, r.dict, r.dev) {
    r.dev.set_storage(file.hook());
    r.operational();
  }
};

} // namespace

TEST_CASE("parameter_file: save over SDO, then power-on puts the values back") {
  folder dir;
  const std::string path = dir.file("node5.par");
  {
    saving_node node(path);
    auto &r = node.r;
    const auto &file = node.file;
    CHECK(r.sdo_write(0x2000, 0, 77, 4) == abort_code::none);
    CHECK(r.sdo_write(0x1017, 0, 250, 2) == abort_code::none);
    CHECK(r.sdo_write(0x1019, 0, 5, 1) == abort_code::none); // while 1006h is 0
    CHECK(r.sdo_write(0x1006, 0, 10000, 4) == abort_code::none);
    // TPDO 1: 2100h alone, synchronous; the CiA 301 sequence over SDO
    CHECK(r.sdo_write(0x1800, 1, 0x8000'0185U, 4) == abort_code::none);
    CHECK(r.sdo_write(0x1A00, 0, 0, 1) == abort_code::none);
    CHECK(r.sdo_write(0x1A00, 1, 0x2100'0020U, 4) == abort_code::none);
    CHECK(r.sdo_write(0x1A00, 0, 1, 1) == abort_code::none);
    CHECK(r.sdo_write(0x1800, 2, 1, 1) == abort_code::none);
    CHECK(r.sdo_write(0x1800, 1, 0x185U, 4) == abort_code::none);
    CHECK(r.dev.set({0x2006, 0},
                    std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t *>("axis"),
                                                  4)) == abort_code::none);
    CHECK(r.sdo_write(0x1010, 1, save, 4) == abort_code::none);
    const std::string text = contents(path);
    CHECK(text.rfind("# fieldcodec parameter file", 0) == 0);
    CHECK(text.find("\n1017 00 FA00\n") != std::string::npos);
    CHECK(text.find("\n2000 00 4D000000\n") != std::string::npos);
    CHECK(text.find("\n1A00 00 01\n") != std::string::npos);
    CHECK(text.find("\n2006 00 61786973\n") != std::string::npos);
    CHECK(text.find("\n1010 ") == std::string::npos); // the commands are not parameters
    CHECK(text.find("\n2005 ") == std::string::npos); // nor is a DOMAIN
    CHECK(text.find("\n1000 ") == std::string::npos); // nor a read-only entry
    CHECK(file.last_error().empty());
  }
  // power-on: the dictionary's defaults, then what was saved
  rig<> r;
  host::parameter_file file(path, r.dict, r.dev);
  r.dev.set_storage(file.hook());
  CHECK(r.read_u(0x1017, 0) == 0);
  auto applied = file.apply(r.dev);
  REQUIRE_MESSAGE(applied.has_value(), applied.error());
  CHECK(applied.value() > 50U);
  CHECK(r.read_u(0x2000, 0) == 77U);
  CHECK(r.read_u(0x1017, 0) == 250U);
  CHECK(r.read_u(0x1019, 0) == 5U);
  CHECK(r.read_u(0x1006, 0) == 10000U);
  CHECK(r.read_u(0x1A00, 0) == 1U);
  CHECK(r.read_u(0x1800, 1) == 0x185U);
  CHECK(r.read_u(0x1800, 2) == 1U);
  CHECK(r.read_u(0x1A00, 1) == 0x2100'0020U);
  auto s = r.dev.value({0x2006, 0}).value();
  CHECK(std::string(s.begin(), s.end()) == "axis");
  // the node works with them: TPDO 1 on SYNC carries 2100h alone (4 bytes)
  r.operational();
  CHECK(r.set_u(0x2100, 0, 0x0A0B0C0DU, 4) == abort_code::none);
  const auto out = r.feed(F(0x80, {1})); // 1019h = 5: the SYNC carries its counter
  const auto tpdo = on(out, 0x185);
  REQUIRE(tpdo.size() == 1U);
  CHECK(tpdo[0].dlc == 4U);
  CHECK(tpdo[0].data[0] == 0x0DU);

  // reset node: the defaults again (TPDO 1 valid, two objects mapped), then the saved values
  // through the running node's PDO rules (mapping only while the PDO is invalid, count 0 first)
  (void)r.feed(F(0, {0x81, 5}));
  CHECK(r.read_u(0x1A00, 0) == 2U);
  CHECK(r.read_u(0x1019, 0) == 0U);
  CHECK(r.sdo_write(0x1006, 0, 5000, 4) == abort_code::none); // 1019h is not writable now
  CHECK(r.sdo_write(0x1019, 0, 3, 1) == A(0x08000022));
  applied = file.apply(r.dev);
  REQUIRE_MESSAGE(applied.has_value(), applied.error());
  CHECK(r.read_u(0x1A00, 0) == 1U);
  CHECK(r.read_u(0x1800, 1) == 0x185U);
  CHECK(r.read_u(0x1019, 0) == 5U);
  CHECK(r.read_u(0x1006, 0) == 10000U);
  (void)r.feed(F(0, {0x01, 5}));
  const auto again = on(r.feed(F(0x80, {1})), 0x185);
  REQUIRE(again.size() == 1U);
  CHECK(again[0].dlc == 4U);
}

TEST_CASE("parameter_file: groups and restore (1011h) keep the other groups") {
  folder dir;
  const std::string path = dir.file("p.par");
  saving_node node(path);
  auto &r = node.r;
  auto &file = node.file;
  CHECK(r.set_u(0x6040, 0, 0x000F, 2) == abort_code::none);
  CHECK(r.set_u(0x2001, 0, 0x1234, 2) == abort_code::none);
  CHECK(r.set_u(0x1017, 0, 100, 2) == abort_code::none);
  CHECK(r.sdo_write(0x1010, 3, save, 4) == abort_code::none); // application: 6000h–9FFFh
  std::string text = contents(path);
  CHECK(text.find("6040 00 0F00") != std::string::npos);
  CHECK(text.find("2001 ") == std::string::npos);
  CHECK(text.find("1017 ") == std::string::npos);
  CHECK(r.sdo_write(0x1010, 4, save, 4) == abort_code::none); // manufacturer: 2000h–5FFFh
  CHECK(r.sdo_write(0x1010, 2, save, 4) == abort_code::none); // communication
  text = contents(path);
  CHECK(text.find("6040 00 0F00") != std::string::npos);
  CHECK(text.find("2001 00 3412") != std::string::npos);
  CHECK(text.find("1017 00 6400") != std::string::npos);
  // "load" of group 4: its lines go, the rest stays; current values do not change
  CHECK(r.sdo_write(0x1011, 4, load, 4) == abort_code::none);
  text = contents(path);
  CHECK(text.find("2001 ") == std::string::npos);
  CHECK(text.find("6040 00 0F00") != std::string::npos);
  CHECK(r.read_u(0x2001, 0) == 0x1234U);
  // reset node: the defaults, then the application puts back what is saved
  (void)r.feed(F(0, {0x81, 5}));
  CHECK(r.read_u(0x2001, 0) == 0U);
  CHECK(r.read_u(0x6040, 0) == 0U);
  REQUIRE(file.apply(r.dev).has_value());
  CHECK(r.read_u(0x2001, 0) == 0U);
  CHECK(r.read_u(0x6040, 0) == 0x000FU);
  CHECK(r.read_u(0x1017, 0) == 100U);
  // only the communication group (after a reset communication)
  CHECK(r.set_u(0x6040, 0, 0x0006, 2) == abort_code::none);
  CHECK(r.set_u(0x1017, 0, 0, 2) == abort_code::none);
  REQUIRE(file.apply(r.dev, node::parameter_group::communication).has_value());
  CHECK(r.read_u(0x1017, 0) == 100U);
  CHECK(r.read_u(0x6040, 0) == 0x0006U);
  // "load" of all: nothing saved any more
  CHECK(r.sdo_write(0x1011, 1, load, 4) == abort_code::none);
  auto saved = file.read();
  REQUIRE(saved.has_value());
  CHECK(saved.value().empty());
  CHECK(file.apply(r.dev).value() == 0U);
  // group 5 is no group of the file
  CHECK(file.save(5).error() == "group 5 is unknown");
  CHECK(file.restore(0).error() == "group 0 is unknown");
  CHECK(host::parameter_file::in_group(1, 0xA000));
  CHECK_FALSE(host::parameter_file::in_group(3, 0x5FFF));
  CHECK(host::parameter_file::in_group(3, 0x9FFF));
  CHECK_FALSE(host::parameter_file::in_group(2, 0x2000));
}

TEST_CASE("parameter_file: the lines of docs/canopen.md") {
  folder dir;
  const std::string path = dir.file("docs.par");
  put(path, "1017 00 E803\n");
  rig<> r;
  host::parameter_file saved(path, r.dict, r.dev); // the file, the dictionary, the device
  r.dev.set_storage(saved.hook());                 // 1010h "save", 1011h "load"
  auto applied = saved.apply(r.dev);               // after power-on and after every reset
  CHECK(applied.value() == 1U);
  CHECK(r.read_u(0x1017, 0) == 1000U);
}

TEST_CASE("parameter_file: no file is nothing saved") {
  folder dir;
  rig<> r;
  host::parameter_file file(dir.file("none.par"), r.dict, r.dev);
  CHECK(file.read().value().empty());
  CHECK(file.apply(r.dev).value() == 0U);
  CHECK(file.restore(1).has_value()); // nothing to remove: the file is not made
  CHECK_FALSE(fs::exists(dir.file("none.par")));
}

TEST_CASE("parameter_file: malformed files, unknown objects and refused values are errors") {
  folder dir;
  const std::string path = dir.file("bad.par");
  saving_node node(path);
  auto &r = node.r;
  auto &file = node.file;
  struct bad {
    const char *line;
    const char *why;
  };
  for (const bad b :
       {bad{"1017 00 E8031", "odd number of hex digits in the value"},
        bad{"1017 00 E8G3", "bad hex digit in the value"},
        bad{"1017 0 E803", "expected 'INDEX SUB BYTES'"},
        bad{"101 00 E803", "expected 'INDEX SUB BYTES'"}, bad{"1017", "expected 'INDEX SUB BYTES'"},
        bad{"10x7 00 E803", "bad hex digit in the address"},
        bad{"1017-00 E803", "expected 'INDEX SUB BYTES'"},
        bad{"1017 00\tE803", "expected 'INDEX SUB BYTES'"}}) {
    CAPTURE(b.line);
    put(path, std::string("# saved\n\n2000 00 4D000000\n") + b.line + "\n");
    auto a = file.apply(r.dev);
    REQUIRE_FALSE(a.has_value());
    CHECK(a.error().rfind(path + ":4: ", 0) == 0);
    CHECK(a.error().find(b.why) != std::string::npos);
    // a save does not overwrite a file it cannot read back: the node answers 0606 0000h
    CHECK(r.sdo_write(0x1010, 1, save, 4) == A(0x06060000));
    CHECK(file.last_error().rfind(path + ":4: ", 0) == 0);
    CHECK(contents(path).find(b.line) != std::string::npos);
  }
  put(path, "2000 00 4D000000\n2000 00 4E000000\n");
  CHECK(file.apply(r.dev).error() == path + ":2: 2000 00 is saved twice");

  // an object this dictionary lacks and a value its limits refuse: named; the others are set
  put(path, "2000 00 4D000000\n2002 00 C8\n3000 00 01\n2001 00 0100\n2003 00 01000000\n");
  auto a = file.apply(r.dev);
  REQUIRE_FALSE(a.has_value());
  CHECK(a.error() == path + ": 2002 00: value too high (download only) (0x06090031)\n" + path +
                         ": 2003 00: data type mismatch: length too high (0x06070012)\n" + path +
                         ": 3000 00: not in the dictionary");
  CHECK(r.read_u(0x2000, 0) == 0x4DU);
  CHECK(r.read_u(0x2001, 0) == 1U);
  CHECK(r.read_u(0x2002, 0) == 0U);
}

TEST_CASE("parameter_file: a file that cannot be written is a hardware error on the wire") {
  rig<> r;
  host::parameter_file file("/nonexistent-folder-of-fieldcodec/p.par", r.dict, r.dev);
  r.dev.set_storage(file.hook());
  r.operational();
  CHECK(r.sdo_write(0x1010, 1, save, 4) == A(0x06060000));
  CHECK(file.last_error() == "/nonexistent-folder-of-fieldcodec/p.par.new: cannot be written");
  CHECK(r.sdo_write(0x1011, 1, load, 4) == abort_code::none); // no file: nothing to remove
}
