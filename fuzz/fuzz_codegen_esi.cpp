// Fuzz harness for the generator's ESI reader and writer and the PDO layouts emitter
// (codegen/src/esi_reader.cpp, write_esi.cpp, emit_pdo.cpp), compiled into the harness with
// the XML reader, the XDD reader (an ESI reader reads an XDD given as .xml) and the EDS writer
// (the fuzz build does not configure the generator library; see fuzz_codegen.cpp).
//
// The input is the file. Properties:
// * read_esi returns a dictionary exactly when it reported no error; every diagnostic has a
//   line >= 0 and a column >= 0.
// * What reads is written as an ESI, which reads back without errors to the same entries
//   (address, object code (an ARRAY the writer reports as written as a record comes back as a
//   RECORD), data type, access, PDO mapping, name, capacity, limits, default, the
//   bytes of a byte string's default) and objects, and whose second writing is the same text.
// * The PDO layouts header of what reads is written (no crash, no diagnostic error).
// * When an SII image is written from what reads, its report has no error.
#include "check.hpp"

#include "../codegen/src/text.cpp"

#include "../codegen/src/checks.cpp"
#include "../codegen/src/emit_pdo.cpp"
#include "../codegen/src/esi_reader.cpp"
#include "../codegen/src/options.cpp"
#include "../codegen/src/sii.cpp"
#include "../codegen/src/write_eds.cpp"
#include "../codegen/src/write_esi.cpp"
#include "../codegen/src/xdd_reader.cpp"
#include "../codegen/src/xml.cpp"
#include "../codegen/src/xml_values.cpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace gen = fieldcodec::gen;

namespace {

// `b` is `a` written and read back; an ARRAY that ETG's array form cannot hold comes back as a
// RECORD, which the writer reports (`records_reported`).
bool same_entry(const gen::entry &a, const gen::entry &b, bool records_reported) {
  const bool same_object =
      a.object == b.object || (records_reported && a.object == fieldcodec::od::object_code::array &&
                               b.object == fieldcodec::od::object_code::record);
  return a.index == b.index && a.sub == b.sub && same_object && a.type_code == b.type_code &&
         a.type == b.type && a.access == b.access && a.pdo == b.pdo && a.name == b.name &&
         a.size == b.size && a.low == b.low && a.high == b.high &&
         a.default_value == b.default_value && a.default_text == b.default_text;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char *>(data), size);
  gen::diagnostics diag;
  auto d = gen::read_esi(text, "fuzz.xml", diag);
  FUZZ_CHECK(d.has_value() == !diag.has_errors());
  for (const auto &x : diag.all()) FUZZ_CHECK(x.line >= 0 && x.column >= 0);
  if (!d || d->profile != gen::bus_profile::ethercat) return 0;
  d->source_name = "fuzz.xml";
  d->stem = "fuzz";
  gen::diagnostics lost;
  const std::string x1 = gen::write_esi(*d, "fuzz.xml", lost);
  gen::diagnostics diag2;
  auto back = gen::read_esi(x1, "w1.xml", diag2);
  FUZZ_CHECK(back.has_value());
  FUZZ_CHECK(back->entries.size() == d->entries.size());
  bool records_reported = false;
  for (const auto &x : lost.all()) {
    records_reported =
        records_reported || x.message.find("written as records") != std::string::npos;
  }
  for (std::size_t i = 0; i < d->entries.size(); ++i) {
    FUZZ_CHECK(same_entry(d->entries[i], back->entries[i], records_reported));
  }
  FUZZ_CHECK(back->objects.size() == d->objects.size());
  back->source_name = "fuzz.xml";
  gen::diagnostics lost2;
  FUZZ_CHECK(gen::write_esi(*back, "fuzz.xml", lost2) == x1);
  gen::diagnostics layouts;
  (void)gen::emit_pdo_layouts(*d, "fuzz.xml", layouts);
  FUZZ_CHECK(!layouts.has_errors());
  gen::diagnostics sii_diag;
  if (const auto image = gen::write_sii(*d, "fuzz.xml", sii_diag)) {
    FUZZ_CHECK(!sii_diag.has_errors());
    gen::diagnostics report;
    (void)gen::sii_report(*image, "fuzz.bin", report);
    FUZZ_CHECK(!report.has_errors());
  }
  return 0;
}
