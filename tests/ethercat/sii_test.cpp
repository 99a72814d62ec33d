// EtherCAT SII (ethercat/sii.hpp): an image assembled by hand from the ETG.1000.6 / ETG.2010
// layout, decoded field by field, at compile time and at run time; every codec's bad input.
#include <fieldcodec/ethercat/sii.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace sii = fieldcodec::ethercat::sii;
using fieldcodec::errc;

namespace {

// Words 0..0x3F, then a strings, a general, an FMMU, a sync manager, a TxPDO and a DC category
// and the end marker. Every byte is written out (little-endian).
constexpr std::array<std::uint8_t, 128 + 24 + 36 + 8 + 20 + 28 + 28 + 2> image = [] {
  std::array<std::uint8_t, 128 + 24 + 36 + 8 + 20 + 28 + 28 + 2> i{};
  // configuration area: PDI control 0x0E08, PDI configuration 0xCC00, SYNC pulse 0x1388
  // (50 us in 10 ns), alias 0x1235; checksum CRC-8 of these 14 bytes = 0x29 (computed with the
  // bitwise definition)
  const std::uint8_t config[16] = {0x08, 0x0E, 0x00, 0xCC, 0x88, 0x13, 0x00, 0x00,
                                   0x35, 0x12, 0x00, 0x00, 0x00, 0x00, 0x29, 0x00};
  for (std::size_t k = 0; k < 16; ++k) i[k] = config[k];
  // vendor 0x00000ABC, product 0x00001234, revision 0x00020000, serial 7
  const std::uint8_t id[16] = {0xBC, 0x0A, 0, 0, 0x34, 0x12, 0, 0, 0, 0, 0x02, 0, 7, 0, 0, 0};
  for (std::size_t k = 0; k < 16; ++k) i[16 + k] = id[k];
  // mailboxes (word 0x14): bootstrap 0x1000/128, 0x1080/128; standard 0x1000/128, 0x1080/128
  const std::uint8_t mbx[16] = {0x00, 0x10, 0x80, 0, 0x80, 0x10, 0x80, 0,
                                0x00, 0x10, 0x80, 0, 0x80, 0x10, 0x80, 0};
  for (std::size_t k = 0; k < 16; ++k) i[0x28 + k] = mbx[k];
  i[0x38] = 0x0C; // word 0x1C: CoE + FoE
  i[0x7C] = 0x0F; // word 0x3E: 16 kbit - 1
  i[0x7E] = 0x01; // word 0x3F: version 1
  std::size_t at = 128;
  const auto put = [&](std::initializer_list<std::uint8_t> bytes) {
    for (const auto b : bytes) i[at++] = b;
  };
  // strings (10), 10 words: 3 strings "Grp", "FX-100", "Outputs" (1 + 4 + 7 + 8 = 20 bytes)
  put({10, 0, 10, 0});
  put({3, 3, 'G', 'r', 'p', 6, 'F', 'X', '-', '1', '0', '0', 7, 'O', 'u', 't', 'p', 'u', 't', 's'});
  // general (30), 16 words: group 1, order 2, name 2, CoE 0x0F, FoE 1, flags 0x04, E-Bus
  // current -50 mA, group index (compatibility) 1, ports 0x0011
  put({30, 0, 16, 0});
  put({1, 0, 2, 2, 0, 0x0F, 0x01, 0x00, 0, 0, 0, 0x04, 0xCE, 0xFF, 1, 0});
  put({0x11, 0x00, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  // FMMU (40), 2 words: outputs, inputs, mailbox state, unused
  put({40, 0, 2, 0, 0x01, 0x02, 0x03, 0xFF});
  // sync manager (41), 8 words: SM2 outputs 0x1100 length 6 control 0x64 enable 1 type 3, SM3
  put({41, 0, 8, 0});
  put({0x00, 0x11, 6, 0, 0x64, 0, 0x01, 3});
  put({0x80, 0x11, 2, 0, 0x20, 0, 0x01, 4});
  // TxPDO (50), 12 words: 0x1A00, 2 entries, SM 3, name 3, flags mandatory | fixed
  put({50, 0, 12, 0});
  put({0x00, 0x1A, 2, 3, 0, 3, 0x11, 0x00});
  put({0x00, 0x60, 1, 0, 0x01, 1, 0, 0}); // 0x6000:01 BOOL 1 bit
  put({0x00, 0x00, 0, 0, 0x00, 7, 0, 0}); // a 7-bit gap
  // DC (60), 12 words: cycle 1 ms, shift 0, shift 0, SYNC1 factor 0, AssignActivate 0x0300,
  // SYNC0 factor 0, name 2
  put({60, 0, 12, 0});
  put({0x40, 0x42, 0x0F, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  put({0, 0, 0x00, 0x03, 0, 0, 2, 0, 0, 0, 0, 0});
  put({0xFF, 0xFF});
  return i;
}();

constexpr auto span = std::span<const std::uint8_t>(image);

} // namespace

// The checksum in the hand-made image is the CRC-8 of its first 14 bytes (ETG.1000.6 5.4).
static_assert(sii::checksum_of(span).value() == 0x29);
static_assert(sii::check_config_area(span).has_value());
static_assert(sii::decode_fixed_area(span).value().vendor_id == 0xABC);
static_assert(sii::decode_fixed_area(span).value().config.station_alias == 0x1235);
static_assert(sii::decode_fixed_area(span).value().eeprom_bytes() == 2048);

TEST_CASE("sii: the fixed area, decoded and encoded back to the same bytes") {
  const auto a = sii::decode_fixed_area(span).value();
  CHECK(a.config.pdi_control == 0x0E08);
  CHECK(a.config.pdi_configuration == 0xCC00);
  CHECK(a.config.sync_impulse == 0x1388);
  CHECK(a.config.checksum == 0x0029);
  CHECK(a.product_code == 0x1234U);
  CHECK(a.revision == 0x00020000U);
  CHECK(a.serial == 7U);
  CHECK(a.bootstrap_send == sii::mailbox{0x1080, 128});
  CHECK(a.standard_receive == sii::mailbox{0x1000, 128});
  CHECK(a.protocols == (sii::protocol::coe | sii::protocol::foe));
  CHECK(a.version == 1U);
  std::array<std::uint8_t, 128> out{};
  REQUIRE(sii::encode_fixed_area(a, out).has_value());
  CHECK(std::equal(out.begin(), out.end(), image.begin()));
  // bad input
  CHECK(sii::decode_fixed_area(span.first(127)) == errc::truncated);
  CHECK(sii::encode_fixed_area(a, std::span(out).first(127)) == errc::buffer_too_small);
  std::array<std::uint8_t, 16> bad{};
  std::copy(image.begin(), image.begin() + 16, bad.begin());
  bad[2] = 0x01; // a changed configuration byte
  CHECK(sii::check_config_area(bad) == errc::bad_checksum);
  bad[14] = 0xA4; // 0x88A4: the check switched off (debugging only)
  bad[15] = 0x88;
  CHECK(sii::check_config_area(bad).has_value());
  CHECK(sii::check_config_area(std::span(bad).first(15)) == errc::truncated);
  bad[15] = 0x01; // the high byte of the checksum word must be 0
  CHECK(sii::check_config_area(bad) == errc::bad_checksum);
}

TEST_CASE("sii: categories one by one, and their contents") {
  sii::category_reader r(span);
  std::vector<std::uint16_t> types;
  std::vector<sii::category> cats;
  for (;;) {
    auto c = r.next();
    REQUIRE(c.has_value());
    if (!c.value()) break;
    types.push_back(c.value()->type);
    cats.push_back(*c.value());
  }
  CHECK(r.end_found());
  CHECK(types == std::vector<std::uint16_t>{10, 30, 40, 41, 50, 60});
  // strings
  const auto strings = cats[0].data;
  CHECK(sii::string_count(strings).value() == 3);
  CHECK(sii::string_at(strings, 2).value() == "FX-100");
  CHECK(sii::string_at(strings, 3).value() == "Outputs");
  CHECK(sii::string_at(strings, 0) == errc::out_of_range);
  CHECK(sii::string_at(strings, 4) == errc::out_of_range);
  CHECK(sii::string_at(strings.first(8), 2) == errc::truncated);
  // general
  const auto g = sii::decode_general(cats[1].data).value();
  CHECK(g.group_index == 1);
  CHECK(g.name_index == 2);
  CHECK(g.coe == (sii::coe_details::sdo | sii::coe_details::sdo_info |
                  sii::coe_details::pdo_assign | sii::coe_details::pdo_config));
  CHECK(g.foe == 1);
  CHECK(g.flags == sii::general_flags::mailbox_data_link_layer);
  CHECK(g.ebus_current == -50);
  CHECK(g.physical_ports == 0x0011);
  std::array<std::uint8_t, 32> gb{};
  REQUIRE(sii::encode_general(g, gb).has_value());
  CHECK(std::equal(gb.begin(), gb.end(), cats[1].data.begin()));
  CHECK(sii::decode_general(cats[1].data.first(15)) == errc::bad_length);
  // FMMU
  CHECK(cats[2].data[2] == sii::fmmu_usage::mailbox_state);
  // sync managers
  const auto sm = sii::decode_sync_manager(cats[3].data, 1).value();
  CHECK(sm == sii::sync_manager{0x1180, 2, 0x20, 0, 1, sii::sync_manager_type::inputs});
  CHECK(sii::decode_sync_manager(cats[3].data, 2) == errc::out_of_range);
  // TxPDO
  const auto p = sii::decode_pdo(cats[4].data, 0).value();
  CHECK(p.header == sii::pdo_header{0x1A00, 2, 3, 0, 3,
                                    sii::pdo_flags::mandatory | sii::pdo_flags::fixed_content});
  CHECK(p.next == cats[4].data.size());
  CHECK(sii::decode_pdo_entry(cats[4].data, p, 0).value() ==
        sii::pdo_entry{0x6000, 1, 0, 0x01, 1, 0});
  CHECK(sii::decode_pdo_entry(cats[4].data, p, 1).value().bits == 7);
  CHECK(sii::decode_pdo_entry(cats[4].data, p, 2) == errc::out_of_range);
  CHECK(sii::decode_pdo(cats[4].data.first(20), 0) == errc::truncated); // entries cut
  CHECK(sii::decode_pdo(cats[4].data, 24) == errc::truncated);
  // DC
  const auto dc = sii::decode_dc_mode(cats[5].data, 0).value();
  CHECK(dc.cycle_time_sync0 == 1'000'000U);
  CHECK(dc.assign_activate == 0x0300);
  CHECK(dc.name_index == 2);
  std::array<std::uint8_t, 24> db{};
  REQUIRE(sii::encode_dc_mode(dc, db).has_value());
  CHECK(std::equal(db.begin(), db.end(), cats[5].data.begin()));
}

TEST_CASE("sii: an image that ends inside a category") {
  // the TxPDO category claims 12 words; cut the image in the middle of it
  const auto cut = span.first(128 + 24 + 36 + 8 + 20 + 10);
  sii::category_reader r(cut);
  std::size_t read = 0;
  for (;;) {
    auto c = r.next();
    if (!c.has_value()) {
      CHECK(c.error() == errc::truncated);
      break;
    }
    if (!c.value()) {
      FAIL("the truncation was not found");
      break;
    }
    ++read;
  }
  CHECK(read == 4);
  CHECK(!r.end_found());
  // no end marker, but the image ends after a whole category: the end, without the marker
  sii::category_reader q(span.first(128 + 24));
  CHECK(q.next().value().has_value());
  CHECK(!q.next().value().has_value());
  CHECK(!q.end_found());
  // a header cut in two
  sii::category_reader h(span.first(130));
  CHECK(h.next() == errc::truncated);
}
