// Fuzz harness for the generator's XDD/XDC reader and writer (codegen/src/xdd_reader.cpp,
// write_xdd.cpp), compiled into the harness with the XML reader and the EDS reader and writer
// (the fuzz build does not configure the generator library; see fuzz_codegen.cpp).
//
// Byte 0 bit 0 selects the XDD profile the writer writes (CANopen or POWERLINK); the rest is
// the file. Properties:
// * read_xdd returns a dictionary exactly when it reported no error; every diagnostic names the
//   file, a line >= 0 and a column >= 0.
// * What reads is written as an XDD, which reads back without errors to the same entries
//   (address, object code, data type, access, PDO mapping, name, capacity, limits, values with
//   their node-ID flags, the bytes of byte strings, denotation, ObjFlags) and objects, and whose
//   second writing is the same text (the written XDD is a fixed point).
// * The EDS export of what reads reads back.
#include "check.hpp"

#include "../codegen/src/text.cpp"

#include "../codegen/src/checks.cpp"
#include "../codegen/src/eds_reader.cpp"
#include "../codegen/src/options.cpp"
#include "../codegen/src/write_eds.cpp"
#include "../codegen/src/write_xdd.cpp"
#include "../codegen/src/xdd_reader.cpp"
#include "../codegen/src/xml.cpp"
#include "../codegen/src/xml_values.cpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace gen = fieldcodec::gen;

namespace {

void check_diagnostics(const gen::diagnostics &diag, bool read) {
  FUZZ_CHECK(read == !diag.has_errors());
  for (const auto &d : diag.all()) {
    FUZZ_CHECK(d.line >= 0 && d.column >= 0);
    FUZZ_CHECK(!d.message.empty());
  }
}

bool same_entry(const gen::entry &a, const gen::entry &b) {
  return a.index == b.index && a.sub == b.sub && a.object == b.object &&
         a.type_code == b.type_code && a.type == b.type && a.access == b.access && a.pdo == b.pdo &&
         a.name == b.name && a.size == b.size && a.low == b.low && a.high == b.high &&
         a.default_value == b.default_value && a.parameter_value == b.parameter_value &&
         a.low_nodeid == b.low_nodeid && a.high_nodeid == b.high_nodeid &&
         a.default_nodeid == b.default_nodeid && a.parameter_nodeid == b.parameter_nodeid &&
         a.default_text == b.default_text && a.parameter_text == b.parameter_text &&
         a.denotation == b.denotation && a.has_obj_flags == b.has_obj_flags &&
         a.obj_flags == b.obj_flags;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  const auto profile =
      (data[0] & 1U) != 0U ? gen::bus_profile::powerlink : gen::bus_profile::canopen;
  const std::string_view text(reinterpret_cast<const char *>(data + 1), size - 1);
  gen::diagnostics diag;
  auto d = gen::read_xdd(text, "fuzz.xdd", diag);
  check_diagnostics(diag, d.has_value());
  if (!d) return 0;
  d->source_name = "fuzz.xdd";
  gen::diagnostics lost;
  const std::string x1 = gen::write_xdd(*d, profile, "fuzz.xdd", lost);
  gen::diagnostics diag2;
  auto back = gen::read_xdd(x1, "w1.xdd", diag2);
  check_diagnostics(diag2, back.has_value());
  FUZZ_CHECK(back.has_value());
  FUZZ_CHECK(back->entries.size() == d->entries.size());
  for (std::size_t i = 0; i < d->entries.size(); ++i) {
    FUZZ_CHECK(same_entry(d->entries[i], back->entries[i]));
  }
  FUZZ_CHECK(back->objects.size() == d->objects.size());
  for (const auto &[index, info] : d->objects) {
    const auto it = back->objects.find(index);
    FUZZ_CHECK(it != back->objects.end());
    FUZZ_CHECK(it->second.code == info.code && it->second.name == info.name);
  }
  back->source_name = "fuzz.xdd";
  gen::diagnostics lost2;
  FUZZ_CHECK(gen::write_xdd(*back, profile, "fuzz.xdd", lost2) == x1);
  gen::diagnostics diag3;
  const auto eds = gen::read_eds(gen::write_eds(*d), "w.eds", diag3);
  FUZZ_CHECK(eds.has_value());
  return 0;
}
