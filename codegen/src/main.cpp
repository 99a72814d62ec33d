// fieldcodec-gen — turns EDS/DCF files and CSV tables into constexpr C++ headers, and writes
// EDS. Exit status: 0 success, 1 input errors (or --check found a difference), 2 usage errors.
#include "config_list.hpp"
#include "options.hpp"
#include "readers.hpp"
#include "text.hpp"

#include <cstdlib>
#if defined(__GLIBC__) || __has_include(<malloc.h>)
#include <malloc.h>
#endif
#include <cstdio>
#include <string>
#include <string_view>

namespace {

// Standard output and error and the output files are written with <cstdio>, not iostreams: a
// static binary that uses std::cout initialises the stream objects and the locale at start-up
// (≈ 16 page faults and 0.06 ms of every run; docs/performance.md).
void put(std::FILE *f, std::string_view s) { std::fwrite(s.data(), 1, s.size(), f); }

// Writes `content` to the file at `path` (created or truncated). False when that fails.
bool write_file(const std::string &path, std::string_view content) {
  std::FILE *f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return false;
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  return std::fclose(f) == 0 && written;
}

constexpr const char *usage_text =
    R"(usage: fieldcodec-gen [options] INPUT

Reads INPUT (.eds or .dcf: CiA 306; .csv: object or command table, see
docs/dictionary-formats.md; .xdd, .xdc or .xpd: CiA 311 CANopen or EPSG DS 311
POWERLINK; .xml: EtherCAT ESI, ETG.2000) and writes a constexpr C++ header, an
EDS, an XDD, an ESI, PDO layouts and/or an SII EEPROM image. INPUT .bin is an
SII EEPROM image (ETG.2010): its report is written to -o FILE (default:
standard output).

options:
  -o, --output FILE   write the C++ header to FILE ("-" for standard output)
      --eds FILE      write the dictionary as a CiA 306 EDS/DCF to FILE ("-" for
                      standard output); for CSV object tables and EDS/DCF input
      --xdd FILE      write the dictionary as an XDD (an XDC when it has DCF values)
                      to FILE ("-" for standard output); what an XDD cannot hold is
                      reported as warnings
      --xdd-profile canopen|powerlink
                      the XDD's profile: CiA 311 CANopen or EPSG DS 311 POWERLINK
                      (default: the profile of an XDD/XDC input, else canopen)
      --esi FILE      write the dictionary as an EtherCAT ESI (ETG.2000) to FILE ("-"
                      for standard output); what an ESI cannot hold is reported
      --sii FILE      write the SII EEPROM image (ETG.2010) of an ESI device to FILE
      --pdo-header FILE
                      write the PDO layouts to FILE: one compile-time layout per PDO,
                      checked against the header of -o (included as
                      <fieldcodec/dictionaries/NAME.hpp>)
      --device DEVICE the device of an ESI that describes several: its name,
                      PRODUCTCODE or PRODUCTCODE:REVISION (0x.../#x... or decimal)
      --name NAME     namespace name below fieldcodec::dictionaries (default: from
                      the input's file name, e.g. dpq_parameters)
      --check         do not write; exit 1 when an output file differs from what
                      would be written (drift check)
      --only RANGES   keep only the objects in RANGES, e.g. 0x1000-0x1FFF,0x6000-0x67FF
                      (indices in hex with 0x; a single index such as 0x1018 is a range)
      --string-capacity BYTES
                      capacity of every string / DOMAIN entry without a declared size:
                      at least BYTES (the default's length when it is longer)
      --string-capacity INDEX[:SUB]=BYTES
                      capacity of the string / DOMAIN entries of one object (or one
                      sub-index), e.g. 0x5011=30 or 0x2121:2=64; overrides the file
      --compact-arrays
                      keep runs of alike ARRAY sub-objects (CompactSubObj) as one
                      entry each instead of one entry per sub-index
      --no-sub-descriptors
                      no standalone descriptor per named sub-object of an ARRAY or
                      RECORD (name it as view[sub]): the header compiles faster
      --config-list FILE
                      write the configuration list of a DCF to FILE: the SDO
                      downloads from the EDS defaults to the DCF's values, in
                      order (PDOs disabled, written, enabled), the identity to
                      check and the concise DCF (docs/master.md)
      --config-values parameter|default
                      the values the list writes: ParameterValue where it differs
                      from DefaultValue (parameter, the default), or DefaultValue
                      of every writable entry (default)
      --nmt-slaves FILE
                      write the slaves of a CiA 302 master DCF to FILE: per node
                      with a 1F81h value, its assignment, expected identity
                      (1F84h..1F88h), concise DCF (1F22h, its UploadFile or
                      value), consumer time (1016h), 1F55h, 1F26h, 1F27h, 1F8Ah
                      (docs/master.md)
      --strict        treat warnings as errors
  -q, --quiet         do not print warnings
  -h, --help          show this text
      --version       show the version

Without -o, --eds, --xdd, --esi or --pdo-header the input is only checked. Diagnostics are printed as
file:line:column: error|warning: message, in line order, followed by a count
("2 errors, 1 warning"). Exit status: 0 success, 1 errors in the input (or a
difference under --check), 2 usage errors.
)";

int usage_error(const std::string &msg) {
  put(stderr,
      "fieldcodec-gen: error: " + msg + "\nusage: fieldcodec-gen [options] INPUT (try --help)\n");
  return 2;
}

// Whether the file at `path` exists (can be read) and whether it holds `content`. The old file
// is released before the caller writes it.
struct existing {
  bool exists = false;
  bool same = false;
};
existing compare_file(const std::string &path, const std::string &content) {
  fieldcodec::gen::file_bytes old;
  if (old.load(path) != nullptr) return {};
  return {true, old.view() == content};
}

// 0 ok, 1 failure (reported)
int output(const std::string &path, const std::string &content, bool check) {
  if (path == "-") {
    if (!check) put(stdout, content);
    return 0;
  }
  const auto [exists, same] = compare_file(path, content);
  if (check) {
    if (!exists || !same) {
      put(stderr, path + ": error: " + (exists ? "differs from" : "missing, expected") +
                      " the generated output\n");
      return 1;
    }
    return 0;
  }
  if (exists && same) return 0; // unchanged: keep the time stamp
  if (!write_file(path, content)) {
    put(stderr, path + ": error: cannot write file\n");
    return 1;
  }
  return 0;
}

// The header: emitted in pieces and compared with the existing file as they come, so that an
// unchanged header (the usual case of a build or of --check) is never held whole; it is collected
// (the bytes equal so far taken from the existing file) only when it is to be written.
int output_header(const std::string &path, const fieldcodec::gen::dictionary &d, bool check) {
  if (path == "-") {
    if (!check) {
      fieldcodec::gen::emit_header(d, [](std::string_view piece) { put(stdout, piece); });
    }
    return 0;
  }
  bool exists = false;
  bool differs = false;
  std::string text; // the header, once it differs (not under --check)
  const auto start_text = [&](std::string_view equal) {
    text.reserve(d.entries.size() * 400U + d.commands.size() * 400U + 4096U); // as emit_header
    text.assign(equal);
  };
  {
    fieldcodec::gen::file_bytes old; // released before the file is written
    exists = old.load(path) == nullptr;
    const std::string_view before = exists ? old.view() : std::string_view{};
    std::size_t same = 0; // leading bytes equal to the existing file
    differs = !exists;
    if (differs && !check) start_text({});
    fieldcodec::gen::emit_header(d, [&](std::string_view piece) {
      if (!differs) {
        if (before.substr(same, piece.size()) == piece) {
          same += piece.size();
          return;
        }
        differs = true;
        if (!check) start_text(before.substr(0, same));
      }
      if (!check) text.append(piece);
    });
    if (!differs && same != before.size()) { // the existing file is longer
      differs = true;
      if (!check) start_text(before.substr(0, same));
    }
  }
  if (check) {
    if (differs) {
      put(stderr, path + ": error: " + (exists ? "differs from" : "missing, expected") +
                      " the generated output\n");
      return 1;
    }
    return 0;
  }
  if (!differs) return 0; // unchanged: keep the time stamp
  if (!write_file(path, text)) {
    put(stderr, path + ": error: cannot write file\n");
    return 1;
  }
  return 0;
}

// What the command line asks for.
struct command_line {
  std::string input;
  std::string header_out;
  std::string eds_out;
  std::string xdd_out;
  std::string pdo_out;
  std::string esi_out;
  std::string sii_out;
  fieldcodec::gen::bus_profile xdd_profile = fieldcodec::gen::bus_profile::unspecified;
  std::string config_out;
  std::string slaves_out;
  fieldcodec::gen::config_values config_values = fieldcodec::gen::config_values::parameter;
  std::string name;
  fieldcodec::gen::read_options read;
  bool check = false;
  bool strict = false;
  bool quiet = false;
  fieldcodec::gen::generator_options opts;
};

// Parses argv into `cl`. Returns -1 to go on, otherwise the exit status (0 after --help or
// --version, 2 after a usage error, which it printed).
int parse_command_line(int argc, char **argv, command_line &cl) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string &dst) -> bool {
      if (i + 1 >= argc) return false;
      dst = argv[++i];
      return true;
    };
    if (a == "-h" || a == "--help") {
      put(stdout, usage_text);
      return 0;
    }
    if (a == "--version") {
      put(stdout, "fieldcodec-gen 0.1.0\n");
      return 0;
    }
    if (a == "-o" || a == "--output") {
      if (!value(cl.header_out)) return usage_error("option " + a + " needs a file name");
    } else if (a == "--eds") {
      if (!value(cl.eds_out)) return usage_error("option --eds needs a file name");
    } else if (a == "--xdd") {
      if (!value(cl.xdd_out)) return usage_error("option --xdd needs a file name");
    } else if (a == "--sii") {
      if (!value(cl.sii_out)) return usage_error("option --sii needs a file name");
    } else if (a == "--esi") {
      if (!value(cl.esi_out)) return usage_error("option --esi needs a file name");
    } else if (a == "--pdo-header") {
      if (!value(cl.pdo_out)) return usage_error("option --pdo-header needs a file name");
    } else if (a == "--xdd-profile") {
      std::string v;
      if (!value(v)) return usage_error("option --xdd-profile needs canopen or powerlink");
      if (v == "canopen") {
        cl.xdd_profile = fieldcodec::gen::bus_profile::canopen;
      } else if (v == "powerlink") {
        cl.xdd_profile = fieldcodec::gen::bus_profile::powerlink;
      } else {
        return usage_error("--xdd-profile '" + v + "': expected canopen or powerlink");
      }
    } else if (a == "--config-list") {
      if (!value(cl.config_out)) return usage_error("option --config-list needs a file name");
    } else if (a == "--nmt-slaves") {
      if (!value(cl.slaves_out)) return usage_error("option --nmt-slaves needs a file name");
    } else if (a == "--config-values") {
      std::string v;
      if (!value(v)) return usage_error("option --config-values needs parameter or default");
      if (v == "parameter") {
        cl.config_values = fieldcodec::gen::config_values::parameter;
      } else if (v == "default") {
        cl.config_values = fieldcodec::gen::config_values::default_;
      } else {
        return usage_error("--config-values '" + v + "': expected parameter or default");
      }
    } else if (a == "--device") {
      if (!value(cl.read.device) || cl.read.device.empty()) {
        return usage_error("option --device needs a device name or product code");
      }
    } else if (a == "--name") {
      if (!value(cl.name)) return usage_error("option --name needs a name");
      if (!fieldcodec::gen::is_identifier(cl.name) || cl.name == "od" || cl.name == "std" ||
          cl.name == "detail") {
        return usage_error("--name '" + cl.name + "' is not a C++ identifier");
      }
    } else if (a == "--only") {
      std::string ranges;
      if (!value(ranges)) return usage_error("option --only needs index ranges");
      if (!cl.opts.only_text.empty()) return usage_error("option --only is given twice");
      if (auto e = fieldcodec::gen::parse_index_ranges(ranges, cl.opts.only); !e.empty()) {
        return usage_error("--only '" + ranges + "': " + e);
      }
      cl.opts.only_text = ranges;
    } else if (a == "--string-capacity") {
      std::string cap;
      if (!value(cap)) return usage_error("option --string-capacity needs a capacity");
      if (auto e = fieldcodec::gen::parse_string_capacity(cap, cl.opts); !e.empty()) {
        return usage_error("--string-capacity '" + cap + "': " + e);
      }
    } else if (a == "--compact-arrays") {
      cl.opts.compact_arrays = true;
    } else if (a == "--no-sub-descriptors") {
      cl.opts.sub_descriptors = false;
    } else if (a == "--check") {
      cl.check = true;
    } else if (a == "--strict") {
      cl.strict = true;
    } else if (a == "-q" || a == "--quiet") {
      cl.quiet = true;
    } else if (a.size() > 1 && a[0] == '-') {
      return usage_error("unknown option '" + a + "'");
    } else if (cl.input.empty()) {
      cl.input = a;
    } else {
      return usage_error("more than one input file ('" + cl.input + "', '" + a + "')");
    }
  }
  if (cl.input.empty()) return usage_error("no input file");
  return -1;
}

// Writes the header and the EDS the command line asks for. Returns the exit status.
int write_outputs(const command_line &cl, fieldcodec::gen::dictionary &dict) {
  int rc = 0;
  if (!cl.config_out.empty()) {
    if (dict.is_command_table) {
      put(stderr, cl.input + ": error: a command table has no configuration list\n");
      return 1;
    }
    fieldcodec::gen::diagnostics diag;
    diag.strict = cl.strict;
    auto list = fieldcodec::gen::build_config_list(dict, cl.config_values, cl.input, diag);
    put(stderr, diag.text(!cl.quiet));
    if (diag.has_errors()) return 1;
    rc |= output(cl.config_out, fieldcodec::gen::emit_config_list(dict, list), cl.check);
  }
  if (!cl.slaves_out.empty()) {
    if (dict.is_command_table) {
      put(stderr, cl.input + ": error: a command table has no NMT slaves\n");
      return 1;
    }
    fieldcodec::gen::diagnostics diag;
    diag.strict = cl.strict;
    auto rows = fieldcodec::gen::build_nmt_slaves(dict, cl.input, diag);
    put(stderr, diag.text(!cl.quiet));
    if (diag.has_errors()) return 1;
    rc |= output(cl.slaves_out, fieldcodec::gen::emit_nmt_slaves(dict, rows), cl.check);
  }
  if (!cl.header_out.empty()) {
    // The emitter writes one od::entry per sub-index: the runs of --compact-arrays are expanded
    // for it until od::entry can describe a run (docs/generator.md, "--compact-arrays").
    fieldcodec::gen::dictionary for_header;
    if (cl.opts.compact_arrays) {
      for_header = dict;
      fieldcodec::gen::expand_runs(for_header);
    }
    rc |= output_header(cl.header_out, cl.opts.compact_arrays ? for_header : dict, cl.check);
  }
  if (!cl.eds_out.empty()) {
    if (dict.is_command_table) {
      put(stderr, cl.input + ": error: a command table cannot be written as EDS\n");
      return 1;
    }
    // A CSV table holds only the device's own parameters: the export adds the mandatory
    // communication objects so that CANopen tools load it.
    const std::string &in = cl.input;
    if (in.size() >= 4 &&
        (in.substr(in.size() - 4) == ".csv" || in.substr(in.size() - 4) == ".CSV")) {
      fieldcodec::gen::add_mandatory_objects(dict);
    }
    // CiA 306 gives a byte string no LowLimit/HighLimit: the limits a CSV may give one (the
    // range of the value a COMPAX BCD field encodes) are not written, and the user is told.
    fieldcodec::gen::diagnostics lost;
    lost.strict = cl.strict;
    for (const auto &e : dict.entries) {
      if (fieldcodec::od::is_byte_string(e.type) &&
          (e.low || e.high || e.low_nodeid || e.high_nodeid)) {
        lost.warning(cl.input, e.line, 0,
                     "the limits of 0x" + fieldcodec::gen::hex(e.index, 4) + " sub " +
                         std::to_string(e.sub) +
                         " are not written to the EDS (CiA 306 has no limits for " +
                         std::string(fieldcodec::od::name(e.type)) + ")");
      }
    }
    // CiA 306 PDOMapping is 0 or 1: a direction (CSV rx/tx, XDD RPDO/TPDO, ESI R/T) is not kept
    std::size_t directed = 0;
    int first_line = 0;
    for (const auto &e : dict.entries) {
      if (e.pdo == fieldcodec::od::pdo_mapping::rx || e.pdo == fieldcodec::od::pdo_mapping::tx) {
        if (directed++ == 0) first_line = e.line;
      }
    }
    if (directed != 0U) {
      lost.warning(cl.input, first_line, 0,
                   std::to_string(directed) + (directed == 1U ? " entry" : " entries") +
                       " mappable into RPDOs or TPDOs only written as PDOMapping=1 (CiA 306 "
                       "has no PDO direction)");
    }
    put(stderr, lost.text(!cl.quiet));
    if (lost.has_errors()) return 1;
    rc |= output(cl.eds_out, fieldcodec::gen::write_eds(dict), cl.check);
  }
  if (!cl.sii_out.empty()) {
    fieldcodec::gen::diagnostics diag;
    diag.strict = cl.strict;
    const auto image = fieldcodec::gen::write_sii(dict, cl.input, diag);
    put(stderr, diag.text(!cl.quiet));
    if (!image || diag.has_errors()) return 1;
    rc |= output(cl.sii_out, std::string(image->begin(), image->end()), cl.check);
  }
  if (!cl.esi_out.empty()) {
    if (dict.is_command_table) {
      put(stderr, cl.input + ": error: a command table cannot be written as ESI\n");
      return 1;
    }
    fieldcodec::gen::diagnostics lost;
    lost.strict = cl.strict;
    const std::string text = fieldcodec::gen::write_esi(dict, cl.input, lost);
    put(stderr, lost.text(!cl.quiet));
    if (lost.has_errors()) return 1;
    rc |= output(cl.esi_out, text, cl.check);
  }
  if (!cl.pdo_out.empty()) {
    if (dict.is_command_table) {
      put(stderr, cl.input + ": error: a command table has no PDOs\n");
      return 1;
    }
    fieldcodec::gen::diagnostics checks;
    checks.strict = cl.strict;
    const std::string text = fieldcodec::gen::emit_pdo_layouts(dict, cl.input, checks);
    put(stderr, checks.text(!cl.quiet));
    if (checks.has_errors()) return 1;
    rc |= output(cl.pdo_out, text, cl.check);
  }
  if (!cl.xdd_out.empty()) {
    if (dict.is_command_table) {
      put(stderr, cl.input + ": error: a command table cannot be written as XDD\n");
      return 1;
    }
    auto profile = cl.xdd_profile;
    if (profile == fieldcodec::gen::bus_profile::unspecified) {
      profile = dict.profile == fieldcodec::gen::bus_profile::powerlink
                    ? fieldcodec::gen::bus_profile::powerlink
                    : fieldcodec::gen::bus_profile::canopen;
    }
    fieldcodec::gen::diagnostics lost;
    lost.strict = cl.strict;
    const std::string text = fieldcodec::gen::write_xdd(dict, profile, cl.input, lost);
    put(stderr, lost.text(!cl.quiet));
    if (lost.has_errors()) return 1;
    rc |= output(cl.xdd_out, text, cl.check);
  }
  return rc;
}

// INPUT .bin: the report of an SII EEPROM image, to -o FILE or standard output. Exit 1 after an
// error in the image (a wrong checksum, a category past its end).
int sii_report(const command_line &cl) {
  if (!cl.eds_out.empty() || !cl.xdd_out.empty() || !cl.esi_out.empty() || !cl.sii_out.empty() ||
      !cl.pdo_out.empty() || !cl.config_out.empty()) {
    return usage_error("an SII image (.bin) gives a report only (-o FILE)");
  }
  fieldcodec::gen::file_bytes file;
  if (const char *failed = file.load(cl.input)) {
    put(stderr, cl.input + ": error: " + failed + "\n");
    return 1;
  }
  const std::string_view bytes = file.view();
  const std::span<const std::uint8_t> image(reinterpret_cast<const std::uint8_t *>(bytes.data()),
                                            bytes.size());
  fieldcodec::gen::diagnostics diag;
  diag.strict = cl.strict;
  const std::string report = fieldcodec::gen::sii_report(image, cl.input, diag);
  put(stderr, diag.text(!cl.quiet));
  int rc = diag.has_errors() ? 1 : 0;
  if (!report.empty()) {
    rc |= output(cl.header_out.empty() ? std::string("-") : cl.header_out, report, cl.check);
  }
  return rc;
}

} // namespace

int main(int argc, char **argv) {
#if defined(M_MMAP_THRESHOLD) && defined(M_TRIM_THRESHOLD)
  // Every block from the heap, none mapped on its own, and the heap never given back: the
  // memory the reader frees (its list of keys, its sections) holds the header next, instead of
  // the header taking fresh pages (a page fault costs microseconds; docs/performance.md).
  mallopt(M_MMAP_THRESHOLD, 256 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 256 * 1024 * 1024);
#endif
  command_line cl;
  if (const int rc = parse_command_line(argc, argv, cl); rc >= 0) return rc;
  if (cl.input.size() > 4 && (cl.input.ends_with(".bin") || cl.input.ends_with(".BIN"))) {
    return sii_report(cl);
  }
  fieldcodec::gen::diagnostics diag;
  diag.strict = cl.strict;
  auto dict = fieldcodec::gen::read_file(cl.input, diag, cl.read);
  if (dict && !diag.has_errors()) {
    const auto &o = cl.opts;
    if (dict->is_command_table && (!o.only.empty() || o.compact_arrays || o.string_capacity ||
                                   !o.capacities.empty() || !o.sub_descriptors)) {
      return usage_error("--only, --string-capacity, --compact-arrays and --no-sub-descriptors "
                         "apply to object "
                         "dictionaries, not to the command table '" +
                         cl.input + "'");
    }
    (void)fieldcodec::gen::apply_options(*dict, o, cl.input, diag);
  }
  // in line order, then where reading stopped, then the count
  put(stderr, diag.text(!cl.quiet));
  if (diag.error_count() != 0U || (!cl.quiet && diag.warning_count() != 0U)) {
    put(stderr, cl.input + ": " + diag.summary() + '\n');
  }
  if (!dict || diag.has_errors()) return 1;
  if (!cl.name.empty()) dict->stem = cl.name;
  const int rc = write_outputs(cl, *dict);
  // Done: the process ends without freeing the dictionary's thousands of strings one by one
  // (a measurable part of a run on a big file). Every file is closed by now; the standard
  // streams are flushed here.
  std::fflush(stdout);
  std::fflush(stderr);
  std::_Exit(rc);
}
