// Fuzz harness for the generator's readers (codegen/: CiA 306 EDS/DCF reader and CSV table
// reader of fieldcodec-gen). The generator is a host tool whose reader is a library target
// (fieldcodec_codegen) that the fuzz build does not configure (FIELDCODEC_BUILD_CODEGEN=OFF),
// so the harness compiles the reader and writer sources into itself (a unity build of
// text.cpp, checks.cpp, eds_reader.cpp, csv_reader.cpp, options.cpp and write_eds.cpp;
// read_file.cpp, emit_header.cpp and main.cpp are not needed).
//
// Byte 0 bit 0 selects the reader (0 EDS/DCF, 1 CSV); the rest is the file's text.
//
// Properties:
// * The reader returns a dictionary exactly when it reported no error, and every diagnostic
//   names the file and a line within the text (1..lines+1, or 0 for the whole file).
// * What reads re-writes to the writer's normalised EDS (hex indices, explicit sub-object
//   sections, LF line endings, objects in index order — the canonical form), and that reads
//   back without errors to the same objects (index, sub-index, data type, access, PDO mapping,
//   limits and default with their node-ID flags, the bytes of a string's default and DCF
//   value, a string's capacity, denotation, kept keys) and re-writes to exactly the same text
//   (the normalised form is a fixed point). CSV object tables go through the same EDS round
//   trip; command tables only through the reader.
// * --compact-arrays changes nothing the EDS export says.
#include "check.hpp"

#include "../codegen/src/text.cpp"

#include "../codegen/src/checks.cpp"
#include "../codegen/src/csv_reader.cpp"
#include "../codegen/src/eds_reader.cpp"
#include "../codegen/src/options.cpp"
#include "../codegen/src/write_eds.cpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace gen = fieldcodec::gen;

namespace {

void check_diagnostics(const gen::diagnostics &diag, const std::optional<gen::dictionary> &d,
                       std::string_view text, const std::string &file) {
  FUZZ_CHECK(d.has_value() == !diag.has_errors());
  // Line breaks as the readers count them: LF, CR LF, or a lone CR.
  int lines = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) {
      ++lines;
    }
  }
  for (const auto &x : diag.all()) {
    FUZZ_CHECK(x.file == file);
    FUZZ_CHECK(x.line >= 0 && x.line <= lines + 1);
    FUZZ_CHECK(x.column >= 0);
    FUZZ_CHECK(!x.message.empty());
  }
}

/// Same number, whatever its kind (the writer prints non-negative integers in hex, which read
/// back as unsigned; reals shortest-round-trip).
bool same_number(const fieldcodec::od::number &a, const fieldcodec::od::number &b) {
  if (a.has_value() != b.has_value()) return false;
  if (!a) return true;
  auto x = a.to_decimal();
  auto y = b.to_decimal();
  if (x && y) return fieldcodec::compare(x.value(), y.value()) == 0;
  return a == b;
}

/// Same object as far as an EDS can say: PDO mapping only as mappable or not (EDS PDOMapping is
/// 0/1; the CSV's rx/tx become 1), limits of scaled CSV entries are written as raw values, a
/// byte string has no limits in an EDS (F18: a CSV may give them; the CLI warns on export).
/// (F6, fixed: DataType=0x0 is refused, so type codes survive unchanged.)
bool same_entry(const gen::entry &a, const gen::entry &b) {
  return a.index == b.index && a.sub == b.sub && a.type_code == b.type_code &&
         a.access == b.access &&
         (a.pdo == fieldcodec::od::pdo_mapping::no) == (b.pdo == fieldcodec::od::pdo_mapping::no) &&
         (a.scaled || fieldcodec::od::is_byte_string(a.type) ||
          (same_number(a.low, b.low) && same_number(a.high, b.high) &&
           a.low_nodeid == b.low_nodeid && a.high_nodeid == b.high_nodeid)) &&
         same_number(a.default_value, b.default_value) && a.default_nodeid == b.default_nodeid &&
         a.default_text == b.default_text && a.size == b.size && a.other_keys == b.other_keys;
}

/// DCF data survives when the source was a DCF (the writer writes it only then).
bool same_dcf(const gen::entry &a, const gen::entry &b) {
  return same_number(a.parameter_value, b.parameter_value) &&
         a.parameter_nodeid == b.parameter_nodeid && a.parameter_text == b.parameter_text &&
         a.denotation == b.denotation;
}

void round_trip(const gen::dictionary &d, bool from_csv) {
  if (d.is_command_table) return;
  const std::string w1 = gen::write_eds(d);
  gen::diagnostics diag2;
  auto d2 = gen::read_eds(w1, "w1.eds", diag2);
  check_diagnostics(diag2, d2, w1, "w1.eds");
  // (F11, fixed: ObjectType=0 is refused by the reader, so whatever it accepts the writer
  // writes readably.)
  FUZZ_CHECK(d2.has_value());
  FUZZ_CHECK(d2->entries.size() >= d.entries.size());
  for (const auto &e : d.entries) {
    const auto it = std::find_if(d2->entries.begin(), d2->entries.end(), [&](const auto &x) {
      return x.index == e.index && x.sub == e.sub;
    });
    FUZZ_CHECK(it != d2->entries.end());
    FUZZ_CHECK(same_entry(e, *it));
    if (d.is_dcf) FUZZ_CHECK(same_dcf(e, *it));
  }
  // The normalised EDS is a fixed point, also for CSV input (F5, fixed: values of unsigned
  // types are written in hex whatever kind the CSV gave them).
  (void)from_csv;
  FUZZ_CHECK(gen::write_eds(*d2) == w1);
  // runs of alike ARRAY sub-objects are written as every sub-object again
  gen::dictionary compact = d;
  gen::compact_arrays(compact);
  FUZZ_CHECK(gen::write_eds(compact) == w1);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char *>(data + 1), size - 1);
  gen::diagnostics diag;
  const bool csv = (data[0] & 1U) != 0U;
  const std::string file = csv ? "fuzz.csv" : "fuzz.eds";
  auto d = csv ? gen::read_csv(text, file, diag) : gen::read_eds(text, file, diag);
  check_diagnostics(diag, d, text, file);
  if (!d) return 0;
  d->source_name = file; // as read_file() does
  d->stem = "fuzz";
  round_trip(*d, csv);
  return 0;
}
