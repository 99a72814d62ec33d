// Fuzz harness for the SII EEPROM codecs (include/fieldcodec/ethercat/sii.hpp) and the
// generator's SII report (codegen/src/sii.cpp, compiled into the harness: the fuzz build does
// not configure the generator library; see fuzz_codegen.cpp).
//
// The input is the image. Properties:
// * The fixed area decodes exactly when the image has 128 bytes; encoded again it gives the
//   same 128 bytes except the reserved words and a checksum that is then the right one, and
//   check_config_area accepts it.
// * The category reader walks forward only, every category's data lies inside the image, and
//   it stops (end, the end of the image or truncated) within image size / 4 + 1 steps.
// * Every decoder of a category's contents stays inside it: strings, general (decoded,
//   encoded, decoded to the same), sync managers, PDOs and their entries, DC modes (round trip).
// * The report is written without a crash; it reports an error when the fixed area is missing,
//   the checksum is wrong or a category runs past the image.
#include "check.hpp"

#include "../codegen/src/text.cpp"

#include "../codegen/src/sii.cpp"

#include <fieldcodec/ethercat/sii.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace sii = fieldcodec::ethercat::sii;
namespace gen = fieldcodec::gen;

namespace {

void contents(const sii::category &c) {
  const auto d = c.data;
  switch (c.type) {
  case sii::category_type::strings: {
    const auto n = sii::string_count(d);
    if (!n) break;
    for (unsigned i = 0; i <= n.value() + 1U && i <= 255U; ++i) {
      const auto s = sii::string_at(d, static_cast<std::uint8_t>(i));
      if (s) {
        const auto *p = reinterpret_cast<const std::uint8_t *>(s.value().data());
        FUZZ_CHECK(p > d.data() && p + s.value().size() <= d.data() + d.size());
      } else {
        FUZZ_CHECK(i == 0U || i > n.value() || s.error() == fieldcodec::errc::truncated);
      }
    }
    break;
  }
  case sii::category_type::general: {
    const auto g = sii::decode_general(d);
    FUZZ_CHECK(g.has_value() == (d.size() >= 16U));
    if (!g) break;
    std::array<std::uint8_t, sii::general_bytes> b{};
    FUZZ_CHECK(sii::encode_general(g.value(), b).has_value());
    const auto again = sii::decode_general(b).value();
    FUZZ_CHECK(again == g.value());
    break;
  }
  case sii::category_type::sync_manager:
    for (std::size_t i = 0;; ++i) {
      const auto m = sii::decode_sync_manager(d, i);
      if (!m) {
        FUZZ_CHECK(i == d.size() / sii::sync_manager_bytes);
        break;
      }
      std::array<std::uint8_t, sii::sync_manager_bytes> b{};
      FUZZ_CHECK(sii::encode_sync_manager(m.value(), b).has_value());
      FUZZ_CHECK(std::equal(b.begin(), b.end(), d.begin() + static_cast<std::ptrdiff_t>(8U * i)));
    }
    break;
  case sii::category_type::txpdo:
  case sii::category_type::rxpdo: {
    std::size_t at = 0;
    while (at < d.size()) {
      const auto p = sii::decode_pdo(d, at);
      if (!p) break;
      FUZZ_CHECK(p.value().next > at && p.value().next <= d.size());
      for (std::size_t i = 0; i <= p.value().header.entries; ++i) {
        const auto e = sii::decode_pdo_entry(d, p.value(), i);
        FUZZ_CHECK(e.has_value() == (i < p.value().header.entries));
      }
      at = p.value().next;
    }
    break;
  }
  case sii::category_type::dc:
    for (std::size_t i = 0;; ++i) {
      const auto m = sii::decode_dc_mode(d, i);
      if (!m) {
        FUZZ_CHECK(i == d.size() / sii::dc_mode_bytes);
        break;
      }
      std::array<std::uint8_t, sii::dc_mode_bytes> b{};
      FUZZ_CHECK(sii::encode_dc_mode(m.value(), b).has_value());
      FUZZ_CHECK(sii::decode_dc_mode(b, 0).value() == m.value());
    }
    break;
  default: break;
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  const std::span<const std::uint8_t> image(data, size);
  const auto fixed = sii::decode_fixed_area(image);
  FUZZ_CHECK(fixed.has_value() == (size >= sii::fixed_area_bytes));
  bool checksum_ok = false;
  if (fixed) {
    std::array<std::uint8_t, sii::fixed_area_bytes> b{};
    FUZZ_CHECK(sii::encode_fixed_area(fixed.value(), b).has_value());
    // words 0..6, 8..0x12, 0x14..0x1C and 0x3E..0x3F again; the checksum recomputed
    FUZZ_CHECK(std::equal(b.begin(), b.begin() + 14, image.begin()));
    FUZZ_CHECK(std::equal(b.begin() + 16, b.begin() + 0x26, image.begin() + 16));
    FUZZ_CHECK(std::equal(b.begin() + 0x28, b.begin() + 0x3A, image.begin() + 0x28));
    FUZZ_CHECK(std::equal(b.begin() + 0x7C, b.end(), image.begin() + 0x7C));
    FUZZ_CHECK(sii::check_config_area(b).has_value());
    const auto again = sii::decode_fixed_area(b).value();
    FUZZ_CHECK(again.vendor_id == fixed.value().vendor_id && again.serial == fixed.value().serial);
    checksum_ok = sii::check_config_area(image).has_value();
    FUZZ_CHECK(checksum_ok == (fixed.value().config.checksum == sii::checksum_disabled ||
                               fixed.value().config.checksum == sii::checksum_of(image).value()));
  }
  sii::category_reader r(image);
  bool truncated = false;
  std::size_t steps = 0;
  std::size_t last = 0;
  for (;;) {
    FUZZ_CHECK(++steps <= size / 4U + 2U);
    const auto c = r.next();
    if (!c) {
      truncated = true;
      FUZZ_CHECK(!r.next().has_value() || !r.next().value()); // stays stopped
      break;
    }
    if (!c.value()) break;
    const sii::category &cat = *c.value();
    FUZZ_CHECK(cat.offset >= sii::fixed_area_bytes && cat.offset >= last);
    FUZZ_CHECK(cat.data.data() >= data && cat.data.data() + cat.data.size() <= data + size);
    last = cat.offset + 4U;
    contents(cat);
  }
  gen::diagnostics diag;
  (void)gen::sii_report(image, "fuzz.bin", diag);
  for (const auto &x : diag.all()) FUZZ_CHECK(x.line == 0 && x.column == 0);
  if (!fixed || !checksum_ok || truncated) FUZZ_CHECK(diag.has_errors());
  return 0;
}
