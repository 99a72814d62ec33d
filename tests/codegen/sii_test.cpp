// fieldcodec-gen's SII EEPROM writer and report (codegen/src/sii.cpp): the image of the ESI
// fixture tests/codegen/fixtures/esi/drive.xml byte for byte, its report, and exact diagnostics
// for bad input on both sides.
#include "readers.hpp"
#include "text.hpp"

#include <fieldcodec/ethercat/sii.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace gen = fieldcodec::gen;
namespace sii = fieldcodec::ethercat::sii;

namespace {

const std::string fixture = "codegen/fixtures/esi/drive.xml";

gen::dictionary drive() {
  gen::diagnostics d;
  gen::read_options opts;
  opts.device = "#x1234:#x20000";
  auto dict = gen::read_file(fixture, d, opts);
  REQUIRE(dict);
  REQUIRE(!d.has_errors());
  return *dict;
}

struct written {
  std::optional<std::vector<std::uint8_t>> image;
  std::vector<std::string> diags;
};

written write(const gen::dictionary &dict) {
  gen::diagnostics d;
  written w;
  w.image = gen::write_sii(dict, fixture, d);
  for (const auto &x : d.sorted()) w.diags.push_back(gen::diagnostics::format(x));
  return w;
}

struct reported {
  std::string text;
  std::vector<std::string> diags;
  bool errors = false;
};

reported report(const std::vector<std::uint8_t> &image) {
  gen::diagnostics d;
  reported r;
  r.text = gen::sii_report(image, "e.bin", d);
  for (const auto &x : d.sorted()) r.diags.push_back(gen::diagnostics::format(x));
  r.errors = d.has_errors();
  return r;
}

bool contains(const std::string &text, const std::string &part) {
  return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("sii writer: the fixture's device, word by word") {
  const auto w = write(drive());
  REQUIRE(w.image);
  CHECK(w.diags.empty());
  const std::vector<std::uint8_t> &img = *w.image;
  REQUIRE(img.size() == 2048); // Eeprom/ByteSize
  // words 0..7: ConfigData 080E00CC88130000, zeros, the CRC-8 of bytes 0..13 in word 7
  const std::array<std::uint8_t, 16> config{0x08, 0x0E, 0x00, 0xCC, 0x88, 0x13, 0,    0,
                                            0,    0,    0,    0,    0,    0,    0xF7, 0};
  CHECK(std::equal(config.begin(), config.end(), img.begin()));
  // words 8..0x0F: vendor, product code, revision, serial 0
  const std::array<std::uint8_t, 16> identity{0xBC, 0x0A, 0, 0, 0x34, 0x12, 0, 0,
                                              0,    0,    2, 0, 0,    0,    0, 0};
  CHECK(std::equal(identity.begin(), identity.end(), img.begin() + 16));
  // words 0x14..0x1C: bootstrap mailboxes from Eeprom/BootStrap, standard ones from the Sm
  // MBoxOut/MBoxIn, protocols CoE + FoE
  const std::array<std::uint8_t, 18> mailboxes{0x00, 0x10, 0x80, 0,    0x80, 0x10, 0x80, 0,    0x00,
                                               0x10, 0x80, 0,    0x80, 0x10, 0x80, 0,    0x0C, 0};
  CHECK(std::equal(mailboxes.begin(), mailboxes.end(), img.begin() + 0x28));
  CHECK(img[0x7C] == 15); // 16 kbit - 1
  CHECK(img[0x7E] == 1);  // version
  CHECK(std::all_of(img.begin() + 0x3A, img.begin() + 0x7C, [](auto b) { return b == 0; }));

  // the categories, through the library's decoders
  sii::category_reader r(img);
  std::vector<sii::category> cats;
  for (;;) {
    const auto c = r.next();
    REQUIRE(c.has_value());
    if (!c.value()) break;
    cats.push_back(*c.value());
  }
  CHECK(r.end_found());
  REQUIRE(cats.size() == 6);
  CHECK(cats[0].type == sii::category_type::strings);
  CHECK(cats[1].type == sii::category_type::general);
  CHECK(cats[2].type == sii::category_type::fmmu);
  CHECK(cats[3].type == sii::category_type::sync_manager);
  CHECK(cats[4].type == sii::category_type::txpdo);
  CHECK(cats[5].type == sii::category_type::rxpdo);
  // after the end marker the EEPROM is erased (0xFF)
  CHECK(std::all_of(img.begin() + static_cast<std::ptrdiff_t>(r.offset()), img.end(),
                    [](auto b) { return b == 0xFF; }));
  const auto strings = cats[0].data;
  CHECK(sii::string_count(strings).value() == 10);
  CHECK(sii::string_at(strings, 1).value() == "Drives");
  CHECK(sii::string_at(strings, 2).value() == "FX-100");
  CHECK(sii::string_at(strings, 3).value() == "FX-100 drive");
  const auto g = sii::decode_general(cats[1].data).value();
  CHECK(g.group_index == 1);
  CHECK(g.order_index == 2);
  CHECK(g.name_index == 3);
  CHECK(g.coe == (sii::coe_details::sdo | sii::coe_details::sdo_info |
                  sii::coe_details::pdo_assign | sii::coe_details::complete_access));
  CHECK(g.foe == 1);
  CHECK(g.eoe == 0);
  CHECK(g.flags == sii::general_flags::mailbox_data_link_layer);
  CHECK(g.physical_ports == 0x0011); // Physics="YY"
  CHECK(std::vector<std::uint8_t>(cats[2].data.begin(), cats[2].data.end()) ==
        std::vector<std::uint8_t>{1, 2, 3, 0});
  CHECK(sii::decode_sync_manager(cats[3].data, 0).value() ==
        sii::sync_manager{0x1000, 128, 0x26, 0, 1, sii::sync_manager_type::mailbox_out});
  CHECK(sii::decode_sync_manager(cats[3].data, 3).value() ==
        sii::sync_manager{0x1180, 2, 0x20, 0, 1, sii::sync_manager_type::inputs});
  const auto tx = sii::decode_pdo(cats[4].data, 0).value();
  CHECK(tx.header.index == 0x1A00);
  CHECK(tx.header.entries == 4);
  CHECK(tx.header.sync_manager == 3);
  CHECK(tx.header.flags == (sii::pdo_flags::default_ | sii::pdo_flags::fixed_content));
  CHECK(sii::decode_pdo_entry(cats[4].data, tx, 1).value().data_type == 0x31); // BIT2
  CHECK(sii::decode_pdo_entry(cats[4].data, tx, 2).value() == sii::pdo_entry{0, 0, 0, 0, 5, 0});
  CHECK(sii::decode_pdo_entry(cats[4].data, tx, 3).value().data_type == 0x1E); // BYTE
  const auto rx = sii::decode_pdo(cats[5].data, 0).value();
  CHECK(rx.header.index == 0x1600);
  CHECK(rx.header.flags ==
        (sii::pdo_flags::mandatory | sii::pdo_flags::default_ | sii::pdo_flags::fixed_content));
  const auto e = sii::decode_pdo_entry(cats[5].data, rx, 1).value();
  CHECK(e.index == 0x607A);
  CHECK(e.data_type == 0x04); // DINT: INTEGER32
  CHECK(e.bits == 32);
  CHECK(sii::string_at(strings, e.name_index).value() == "Target position");
}

TEST_CASE("sii report: the fixture's image") {
  const auto w = write(drive());
  REQUIRE(w.image);
  const auto r = report(*w.image);
  CHECK(r.diags.empty());
  CHECK(contains(r.text, "SII EEPROM image, 2048 bytes; word 0x3E: 2048-byte EEPROM (16 kbit); "
                         "version 1\n"));
  CHECK(contains(r.text, "  checksum              0x00F7, CRC-8 of bytes 0..13 0xF7: ok\n"));
  CHECK(contains(r.text, "  product code          0x00001234\n"));
  CHECK(contains(r.text, "  protocols             CoE, FoE (0x000C)\n"));
  CHECK(contains(r.text, "    CoE: SDO, SDO info, PDO assign, complete access; FoE yes; EoE no\n"));
  CHECK(contains(r.text, "    SM2: 0x1100, 6 bytes, control 0x64, enable 0x01, outputs\n"));
  CHECK(contains(r.text, "    PDO 0x1600 \"Outputs\", 2 entries, SM 2, mandatory, default, fixed "
                         "(flags 0x0013)\n"));
  CHECK(contains(r.text, "      0x6000:02 \"Mode\"                   type 0x31, 2 bits\n"));
  CHECK(contains(r.text, "  END at word 0x00BD\n"));
}

TEST_CASE("sii writer: what it refuses and what it warns about") {
  SUBCASE("a dictionary without an ESI device") {
    gen::diagnostics d;
    auto eds = gen::read_file("codegen/fixtures/interop.eds", d);
    REQUIRE(eds);
    const auto w = write(*eds);
    CHECK(!w.image);
    REQUIRE(w.diags.size() == 1);
    CHECK(w.diags[0] == fixture + ": error: an SII image is written from an ESI device (.xml "
                                  "input); this dictionary has no EtherCAT device description");
  }
  auto dict = drive();
  SUBCASE("ConfigData that is no hex") {
    dict.ethercat->config_data = "080E00CC8813000G";
    const auto w = write(dict);
    CHECK(!w.image);
    REQUIRE(w.diags.size() == 1);
    CHECK(w.diags[0] == fixture + ":119: error: Eeprom/ConfigData \"080E00CC8813000G\" is not up "
                                  "to 14 bytes of hex digit pairs (words 0..6)");
  }
  SUBCASE("BootStrap of 6 bytes") {
    dict.ethercat->bootstrap = "001080008010";
    const auto w = write(dict);
    CHECK(!w.image);
    REQUIRE(w.diags.size() == 1);
    CHECK(contains(w.diags[0], ":119: error: Eeprom/BootStrap \"001080008010\" is not 8 bytes"));
  }
  SUBCASE("ByteSize no whole number of kbit") {
    dict.ethercat->eeprom_bytes = 1000;
    const auto w = write(dict);
    CHECK(!w.image);
    REQUIRE(w.diags.size() == 1);
    CHECK(w.diags[0] == fixture + ":119: error: Eeprom/ByteSize 1000 is no whole number of kbit "
                                  "(128 bytes): word 0x3E cannot say it");
  }
  SUBCASE("ByteSize too small for the PDOs: written without them") {
    dict.ethercat->eeprom_bytes = 256;
    const auto w = write(dict);
    REQUIRE(w.image);
    CHECK(w.image->size() == 256);
    REQUIRE(w.diags.size() == 1);
    CHECK(w.diags[0] == fixture + ":119: warning: the SII image with every PDO (380 bytes) does "
                                  "not fit the EEPROM of 256 bytes (Eeprom/ByteSize): written "
                                  "without the PDO categories; a master reads the PDOs over CoE");
    sii::category_reader r(*w.image);
    std::vector<std::uint16_t> types;
    for (auto c = r.next(); c && c.value(); c = r.next()) types.push_back(c.value()->type);
    CHECK(types == std::vector<std::uint16_t>{10, 30, 40, 41});
    CHECK(r.end_found());
  }
  SUBCASE("ByteSize too small even without the PDOs") {
    dict.ethercat->eeprom_bytes = 128;
    const auto w = write(dict);
    CHECK(!w.image);
    REQUIRE(w.diags.size() == 1);
    CHECK(w.diags[0] == fixture + ":119: error: the SII image of 242 bytes does not fit the EEPROM "
                                  "of 128 bytes (Eeprom/ByteSize)");
  }
  SUBCASE("the PDOs not assigned by default left out, then the entries' names") {
    dict.ethercat->eeprom_bytes = 256;
    dict.ethercat->pdos[0].sm = -1; // RxPDO 0x1600
    auto &tx = dict.ethercat->pdos[1];
    tx.entries.resize(1);
    tx.name.clear();
    dict.ethercat->name = "FX";
    auto w = write(dict);
    REQUIRE(w.image);
    REQUIRE(w.diags.size() == 1);
    CHECK(w.diags[0] == fixture + ":119: warning: the SII image with every PDO (322 bytes) does "
                                  "not fit the EEPROM of 256 bytes (Eeprom/ByteSize): written "
                                  "with the 1 PDO assigned by default only (1 left out) and "
                                  "without the names of their entries; a master reads the PDOs "
                                  "over CoE");
    tx.entries[0].name.clear();
    w = write(dict);
    REQUIRE(w.image);
    REQUIRE(w.diags.size() == 1);
    CHECK(w.diags[0] == fixture + ":119: warning: the SII image with every PDO (316 bytes) does "
                                  "not fit the EEPROM of 256 bytes (Eeprom/ByteSize): written "
                                  "with the 1 PDO assigned by default only (1 left out); a "
                                  "master reads the PDOs over CoE");
  }
  SUBCASE("no ByteSize, no ConfigData") {
    dict.ethercat->eeprom_bytes = 0;
    dict.ethercat->config_data.clear();
    const auto w = write(dict);
    REQUIRE(w.image);
    CHECK(w.image->size() == 512);
    CHECK((*w.image)[0x7C] == 3);
    CHECK((*w.image)[14] == 0x30); // CRC-8 of 14 zero bytes (from 0xFF)
    REQUIRE(w.diags.size() == 2);
    CHECK(w.diags[0] == fixture + ":18: warning: the ESI has no Eeprom/ByteSize: word 0x3E says "
                                  "512 bytes, the smallest EEPROM that holds the 380-byte image");
    CHECK(w.diags[1] == fixture + ":119: warning: the ESI has no Eeprom/ConfigData: the "
                                  "configuration area (PDI, SYNC) is written as zeros");
  }
  SUBCASE("unknown sync manager type and Physics letter") {
    dict.ethercat->sync_managers[2].type = "Outputz";
    dict.ethercat->physics = "YQ";
    const auto w = write(dict);
    REQUIRE(w.image);
    REQUIRE(w.diags.size() == 2);
    CHECK(w.diags[0] == fixture + ":18: warning: Physics letter 'Q' of port 1 unknown: written "
                                  "as unused");
    CHECK(w.diags[1] == fixture + ":99: warning: sync manager type \"Outputz\" unknown: written "
                                  "as unused");
  }
}

TEST_CASE("sii report: bad images") {
  const auto good = *write(drive()).image;
  SUBCASE("shorter than the fixed area") {
    const auto r = report(std::vector<std::uint8_t>(good.begin(), good.begin() + 100));
    CHECK(r.errors);
    REQUIRE(r.diags.size() == 1);
    CHECK(r.diags[0] == "e.bin: error: an SII image has at least 128 bytes (words 0x00..0x3F); "
                        "this file has 100");
  }
  SUBCASE("a changed configuration byte") {
    auto img = good;
    img[4] = 0x89;
    const auto r = report(img);
    CHECK(r.errors);
    REQUIRE(r.diags.size() == 1);
    CHECK(r.diags[0] == "e.bin: error: checksum 0x00F7 of the configuration area is not its CRC-8 "
                        "0x" +
                            gen::hex(sii::checksum_of(img).value(), 2) +
                            ": the ESC refuses the configuration");
    CHECK(contains(r.text, ": WRONG\n"));
  }
  SUBCASE("the check switched off") {
    auto img = good;
    img[14] = 0xA4;
    img[15] = 0x88;
    const auto r = report(img);
    CHECK(!r.errors);
    REQUIRE(r.diags.size() == 1);
    CHECK(contains(r.diags[0], "warning: the configuration area's checksum is 0x88A4"));
  }
  SUBCASE("cut inside a category, and without the end marker") {
    const auto r = report(std::vector<std::uint8_t>(good.begin(), good.begin() + 0x140));
    CHECK(r.errors);
    REQUIRE(r.diags.size() == 1);
    CHECK(r.diags[0] == "e.bin: error: category at word 0x0099 runs past the end of the image");
    const auto q = report(std::vector<std::uint8_t>(good.begin(), good.begin() + 0x132));
    CHECK(!q.errors);
    REQUIRE(q.diags.size() == 1);
    CHECK(q.diags[0] == "e.bin: warning: no end category (0xFFFF) before the end of the image");
  }
  SUBCASE("a PDO that claims more entries than its category holds, a string that is not there") {
    auto img = good;
    img[0x136 + 5] = 40; // TxPDO 0x1A00's name: string 40 of 10
    img[0x162 + 2] = 3;  // RxPDO 0x1600: 3 entries in a category of 2
    const auto r = report(img);
    CHECK(r.errors);
    REQUIRE(r.diags.size() == 2);
    CHECK(r.diags[0] == "e.bin: warning: string index 40 names no string of the STRINGS category");
    CHECK(r.diags[1] == "e.bin: error: PDO at word 0x00B1 runs past its category (at word 0x00AF)");
    CHECK(contains(r.text, "    PDO 0x1A00 #40 (missing), 4 entries"));
  }
}
