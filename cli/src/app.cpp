// fieldcodec CLI — the subcommands.
#include "app.hpp"

#include "can_decoder.hpp"
#include "dictionary.hpp"
#include "pacontrol_decoder.hpp"
#include "readers.hpp"
#include "util.hpp"
#include "values.hpp"

#include <fieldcodec/canopen/lss.hpp>
#include <fieldcodec/canopen/lss_master.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/network.hpp>
#include <fieldcodec/host/pacontrol_link.hpp>
#include <fieldcodec/host/parameter_file.hpp>
#include <fieldcodec/host/sdo.hpp>
#include <fieldcodec/host/slcan.hpp>
#include <fieldcodec/host/socketcan_bus.hpp>
#include <fieldcodec/od/value.hpp>
#include <fieldcodec/pacontrol/codes.hpp>
#include <fieldcodec/pacontrol/command.hpp>

#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <iostream>
#include <istream>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>

namespace fieldcodec::cli {

namespace {

// ---------------------------------------------------------------------------------------------
// help texts

constexpr const char *main_help = R"(usage: fieldcodec COMMAND [ARGS] [OPTIONS]

Decode CANopen and PA-CONTROL traffic, read and write CANopen objects.

commands:
  decode          a candump log (or a PA-CONTROL capture) to one readable line per frame
  monitor         decode the live traffic of a CAN interface
  sdo read        read an object of a node (SDO upload)
  sdo write       write an object of a node (SDO download)
  nmt             send an NMT command
  lss             layer setting services (CiA 305): find a node, set its node-ID and bit rate
  dump            read every readable object of a node into a DCF
  serve           simulate a node from an EDS/DCF (values set from standard input)
  pacontrol send  send a command to a PA-CONTROL over RS232 and show the answer

'fieldcodec help COMMAND' (or 'fieldcodec COMMAND --help') describes a command.
Exit status: 0 success, 1 the device refused or did not answer, 2 usage error, 3 a
file, interface or port failed, 4 decode input that could not be decoded, 5 a
dictionary could not be read.
)";

constexpr const char *transport_help = R"(
transport (one of):
  --can IFACE         a SocketCAN interface (can0, vcan0)
  --slcan PORT        an slcan (LAWICEL) adapter on a serial port (/dev/ttyACM0)
  --bitrate BPS       slcan bit rate: 10000 20000 50000 100000 125000 250000
                      500000 (default) 800000 1000000
  --slcan-no-answers  do not wait for the adapter's answers to C/Sn/O (a peer that
                      does not answer commands, e.g. another slcan host)
)";

constexpr const char *decode_help = R"(usage: fieldcodec decode [FILE] [OPTIONS]

Reads what candump writes (FILE, or standard input when FILE is '-' or missing)
and writes one line per frame: NMT, SYNC, TIME, EMCY, PDO, heartbeat, node
guarding, LSS, and one line per SDO transfer (expedited, segmented and block
transfers are reassembled; aborts are spelled out). With a dictionary, objects
are named and values shown in engineering units; PDOs are unpacked by the mapping
the dictionary or the log's own SDO writes define.

Input lines, as candump prints them:
  (1700000000.123456) can0 605#2B00180564000000     candump -l / -L (log)
    can0  605   [8]  2B 00 18 05 64 00 00 00          candump can0 (also -ta -tA
                                                      -td -tz, -x, -a, -e)
  605#2B00180564000000, 705#R                         the compact notation
Blank lines and lines starting with '#' are skipped.

options:
  --dict [NODE=]FILE  object dictionary (.eds, .dcf, .csv) of node NODE (1..127),
                      or of every node without its own when NODE= is left out
  --device NODE=KIND  device family of a node: generic, ds402, xenax, dpq
                      (default: from the dictionary)
  --iface NAME        only frames of interface NAME (repeatable)
  --json              one JSON object per line instead of text
  --sdo-frames        also one line per SDO frame
  --pacontrol         the input is a PA-CONTROL RS232 capture instead
  --hex / --raw       the capture is hex text / raw bytes (default: detected)
  --check-rule R      PA-CONTROL: which check rule a frame must follow:
                      manual (default: requests body, acknowledgements body+ETX),
                      either (both rules pass, the other one noted)

exit status: 0, or 4 when some input could not be decoded, 3 unreadable file,
5 unreadable dictionary.
)";

constexpr const char *monitor_help =
    R"(usage: fieldcodec monitor (--can IFACE | --slcan PORT) [OPTIONS]

Decodes the live traffic of an interface, as 'decode' does for a log, until
interrupted (Ctrl-C), or after --count frames or --duration seconds.

options:
  --dict [NODE=]FILE, --device NODE=KIND, --json, --sdo-frames   as for decode
  --count N           stop after N frames
  --duration S        stop after S seconds
  --log FILE          also write the frames to FILE as a candump log
)";

constexpr const char *sdo_read_help =
    R"(usage: fieldcodec sdo read NODE INDEX[:SUB] (--can IFACE | --slcan PORT) [OPTIONS]

Reads one object of node NODE (1..127) with an SDO upload and prints it:
  1018h:01 Identity Object: Vendor Id = 0x0000012E
INDEX and SUB are hex (1018:1, 0x1018:01, 1018h:01). A scaled value is shown in
engineering units with its raw number: 6073h:00 Limit I_Force = 1500 mA (raw 150).
'sdo write' takes back what this prints, in the same unit.

options:
  --dict FILE         dictionary of the node: names, types, units, scales
  --type T            type without a dictionary: u8 u16 u32 u64 i8 i16 i32 i64
                      f32 f64 bool str hex (default: raw bytes)
  --raw               the raw number of a scaled value, not engineering units
  --timeout MS        SDO timeout, 1..3600000 (default 1000)
  --block             use block transfer
  --switch-threshold N  with --block: let the node answer with a normal upload for
                      objects of at most N bytes (0..127, default 0: never)
  --json              print a JSON object
)";

constexpr const char *sdo_write_help =
    R"(usage: fieldcodec sdo write NODE INDEX[:SUB] VALUE (--can IFACE | --slcan PORT) [OPTIONS]

Writes VALUE to one object of node NODE with an SDO download and prints what it
sent, as 'sdo read' prints it. VALUE is what 'sdo read' prints, in the same unit:
numbers in engineering units when the dictionary scales the object (1500 or
1500 mA; rounded half away from zero to a raw step), integers also as 0x hex when
the object is not scaled, reals, text or "quoted text" for strings, hex bytes
for OCTET_STRING and DOMAIN. A value outside the object's limits (those of node
NODE), too long for its capacity or not of its type is refused before anything
is sent (exit status 2).

options:
  --dict FILE         dictionary of the node (types, limits, scales, units)
  --type T            type without a dictionary: u8 u16 u32 u64 i8 i16 i32 i64
                      f32 f64 bool str hex
  --raw               VALUE is the raw number (decimal or 0x hex), not engineering units
  --timeout MS        SDO timeout, 1..3600000 (default 1000)
  --block             use block transfer
  --json              print a JSON object
)";

constexpr const char *nmt_help = R"(usage: fieldcodec nmt COMMAND NODE (--can IFACE | --slcan PORT)

Sends an NMT command to NODE (1..127) or to all nodes (NODE = all or 0).
COMMAND: start, stop, pre-operational, reset-node, reset-communication.
)";

constexpr const char *lss_help =
    R"(usage: fieldcodec lss SERVICE [ARGS] (--can IFACE | --slcan PORT) [OPTIONS]

Layer setting services (CiA 305) of an LSS master towards the nodes on the bus.
SERVICE:
  scan              fastscan: the LSS address of a node without node-ID, printed as
                    'address VENDOR,PRODUCT,REVISION,SERIAL' (what --address takes); that
                    node is then in LSS configuration
  set-node NODE     configure node-ID NODE (1..127, or 255: none) of the node in LSS
                    configuration; it takes effect at its next NMT reset, or, for a node
                    without node-ID, at 'lss waiting'
  set-bitrate KBIT  configure the bit timing (CiA 305's table: 1000, 800, 500, 250, 125, 50,
                    20, 10) of the node in LSS configuration
  activate MS       activate the configured bit timing after MS ms (all nodes in LSS
                    configuration switch; no answer)
  store             store the configured node-ID and bit timing in the node
  inquire           the LSS address and the node-ID of the node in LSS configuration
  configuration     switch state global: every node to LSS configuration
  waiting           switch state global: every node back to LSS waiting

options:
  --address V,P,R,S switch state selective first: the node with this LSS address (1018h
                    sub 1..4; decimal or 0x hex) goes to LSS configuration
  --timeout MS      how long to wait for an answer, 1..60000 (default 1000)
  --probe MS        how long a fastscan step waits, 1..60000 (default 100)
)";

constexpr const char *dump_help =
    R"(usage: fieldcodec dump NODE --dict FILE (--can IFACE | --slcan PORT) [OPTIONS]

Reads every readable object of the dictionary from node NODE and writes a DCF:
the dictionary with the values found as ParameterValue. Objects the node refuses
are listed on standard error and left without a value. A progress line goes to
standard error while it runs.

options:
  -o, --output FILE   the DCF (default: standard output)
  --timeout MS        SDO timeout per object (default 1000)
  --block             use block transfer
  --progress          show the progress line also when standard error is no terminal
  --quiet             no progress line
)";

constexpr const char *serve_help =
    R"(usage: fieldcodec serve NODE --dict FILE (--can IFACE | --slcan PORT) [OPTIONS]

Simulates node NODE (1..127) with the objects of FILE (EDS or DCF): boot-up,
NMT, heartbeat (1017h), node guarding, SDO (expedited, segmented, block), PDOs,
SYNC and EMCY as a CiA 301 device does, until interrupted (Ctrl-C) or after
--duration seconds. The objects start with their DCF values or EDS defaults.

Standard input sets values, one per line: INDEX[:SUB] VALUE, VALUE as 'sdo read'
prints it (1500 mA, 0x000F, "text"; checked against the object's limits and
capacity), or --raw numbers with 'raw INDEX[:SUB] VALUE'. 'INDEX[:SUB]' alone
prints the value. Empty lines and lines starting with # are skipped.

Standard output: one line per value set or asked for (as 'sdo read' prints it),
'written: ' and that line for every value the network writes (SDO, RPDO), and
'NMT: STATE' for every NMT state the node enters.

options:
  --duration S        stop after S seconds
  --storage FILE      1010h "save" / 1011h "load" keep the node's parameters in
                      FILE; its values are set at start and after every reset
exit status: 0, 2 usage error or a refused input line (the node keeps
running), 3 the interface or port failed or FILE of --storage is malformed,
5 the dictionary could not be read.
)";

constexpr const char *pacontrol_send_help =
    R"(usage: fieldcodec pacontrol send PORT COMMAND [PARAMETER [DATE]] [OPTIONS]

Sends one command to a PA-CONTROL over its RS232 command interface and prints
the acknowledgement. COMMAND is a name of the command table (cmd_get_int_reg) or
its code in hex (1906); 'poll' sends the poll (EOT).

options:
  --baud N            (default 9600; the manual's line settings are 9600 7N1)
  --data-bits 7|8     (default 7)
  --parity none|even|odd   (default none)
  --stop-bits 1|2     (default 1)
  --rts-cts           hardware flow control (switch settings 5-8)
  --timeout MS        (default 1000)
  --json              print a JSON object

exit status: 0, 1 when the control answers with a command error (QUIT) or not
at all, 3 when the port cannot be used.
)";

// ---------------------------------------------------------------------------------------------
// command line

struct options {
  std::vector<std::string> positional;
  std::multimap<std::string, std::string> values;
  std::set<std::string> flags;

  [[nodiscard]] bool has(const std::string &f) const { return flags.count(f) != 0U; }
  [[nodiscard]] std::string get(const std::string &k, std::string fallback = {}) const {
    auto it = values.find(k);
    return it == values.end() ? fallback : it->second;
  }
  [[nodiscard]] bool given(const std::string &k) const { return values.count(k) != 0U; }
};

/// Parses `args` from `first` on. `with_value`: options that take a value.
bool parse_options(const std::vector<std::string> &args, std::size_t first,
                   const std::set<std::string> &with_value, const std::set<std::string> &flags,
                   options &out, std::string &error) {
  for (std::size_t i = first; i < args.size(); ++i) {
    const std::string &a = args[i];
    if (a == "-" || a.empty() || a[0] != '-' || (a.size() > 1U && a[1] >= '0' && a[1] <= '9')) {
      out.positional.push_back(a);
      continue;
    }
    std::string name = a;
    std::string value;
    bool inline_value = false;
    if (const auto eq = a.find('='); eq != std::string::npos && a.rfind("--", 0) == 0) {
      name = a.substr(0, eq);
      value = a.substr(eq + 1U);
      inline_value = true;
    }
    if (name == "-o") name = "--output";
    if (name == "-h") name = "--help";
    if (with_value.count(name) != 0U) {
      if (!inline_value) {
        if (i + 1U >= args.size()) {
          error = name + " needs a value";
          return false;
        }
        value = args[++i];
      }
      out.values.emplace(name, value);
    } else if (flags.count(name) != 0U || name == "--help") {
      if (inline_value) {
        error = name + " takes no value";
        return false;
      }
      out.flags.insert(name);
    } else {
      error = "unknown option " + name;
      return false;
    }
  }
  return true;
}

const std::set<std::string> transport_values = {"--can", "--slcan", "--bitrate"};
const std::set<std::string> transport_flags = {"--slcan-no-answers"};

std::set<std::string> join(std::set<std::string> a, const std::set<std::string> &b) {
  a.insert(b.begin(), b.end());
  return a;
}

struct context {
  std::istream &in;
  std::ostream &out;
  std::ostream &err;
  std::string command; ///< "sdo read", for error lines
  bool err_terminal = false;
  int fail(int code, const std::string &what) const {
    err << "fieldcodec: " << command << ": " << what << "\n";
    return code;
  }
  int usage(const std::string &what) const {
    err << "fieldcodec: " << command << ": " << what << " (try 'fieldcodec " << command
        << " --help')\n";
    return exit_usage;
  }
};

bool parse_node(const std::string &s, bool allow_all, std::uint8_t &node) {
  if (allow_all && (s == "all" || s == "0")) {
    node = 0;
    return true;
  }
  std::uint64_t v = 0;
  if (!parse_uint(s, 127, v) || v == 0U) return false;
  node = static_cast<std::uint8_t>(v);
  return true;
}

/// Opens the bus the options name. Returns null (and prints the error) on failure.
std::unique_ptr<host::can_bus> open_bus(const options &o, const context &c, int &code) {
  code = exit_ok;
  const bool can = o.given("--can");
  const bool slcan = o.given("--slcan");
  if (can == slcan) {
    code = c.usage("give one of --can IFACE or --slcan PORT");
    return nullptr;
  }
  if (can) {
#ifdef FIELDCODEC_HAS_SOCKETCAN
    auto bus = std::make_unique<host::socketcan_bus>();
    if (!bus->open(o.get("--can"))) {
      code = c.fail(exit_io, bus->last_error().what);
      return nullptr;
    }
    return bus;
#else
    code = c.fail(exit_io, "SocketCAN is not available on this system");
    return nullptr;
#endif
  }
  std::uint64_t bitrate = 500000;
  if (o.given("--bitrate") && !parse_uint(o.get("--bitrate"), 1000000, bitrate)) {
    code = c.usage("bad --bitrate " + o.get("--bitrate"));
    return nullptr;
  }
  auto bus = std::make_unique<host::slcan_bus>();
  host::slcan_options so;
  so.check_answers = !o.has("--slcan-no-answers");
  if (!bus->open(o.get("--slcan"), static_cast<std::uint32_t>(bitrate), so)) {
    code = c.fail(bus->last_error().code == errc::invalid_argument &&
                          bus->last_error().what.find("bit rate") != std::string::npos
                      ? exit_usage
                      : exit_io,
                  bus->last_error().what);
    return nullptr;
  }
  return bus;
}

/// Loads the --dict options: "NODE=FILE" or "FILE" (every node, stored at 0).
bool load_dictionaries(const options &o, const context &c,
                       std::map<std::uint8_t, node_dictionary> &dicts,
                       std::map<std::uint8_t, device_family> &families, int &code) {
  code = exit_ok;
  for (auto [it, end] = o.values.equal_range("--dict"); it != end; ++it) {
    std::string spec = it->second;
    std::uint8_t node = 0;
    const auto eq = spec.find('=');
    if (eq != std::string::npos) {
      if (!parse_node(spec.substr(0, eq), false, node)) {
        code = c.usage("bad node in --dict " + spec);
        return false;
      }
      spec = spec.substr(eq + 1U);
    }
    if (dicts.count(node) != 0U) {
      code = c.usage(node == 0U ? std::string("--dict FILE (for every node) given twice")
                                : "--dict " + std::to_string(node) + "= given twice");
      return false;
    }
    std::string error;
    auto d = node_dictionary::load(spec, error);
    if (!d) {
      code = c.fail(exit_dictionary, error);
      return false;
    }
    dicts.emplace(node, std::move(*d));
  }
  for (auto [it, end] = o.values.equal_range("--device"); it != end; ++it) {
    const std::string &spec = it->second;
    const auto eq = spec.find('=');
    std::uint8_t node = 0;
    device_family f{};
    if (eq == std::string::npos || !parse_node(spec.substr(0, eq), false, node) ||
        !parse_family(spec.substr(eq + 1U), f)) {
      code = c.usage("bad --device " + spec + " (NODE=generic|ds402|xenax|dpq)");
      return false;
    }
    families[node] = f;
  }
  return true;
}

bool read_stream(std::istream &in, std::string &out) {
  std::ostringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return !in.bad();
}

void print_lines(const std::vector<decoded_line> &lines, bool json, std::ostream &out) {
  for (const auto &l : lines) out << (json ? render_json(l) : render_text(l)) << "\n";
}

// ---------------------------------------------------------------------------------------------
// decode

std::string check_rule_error(const std::string &r) {
  return "bad --check-rule " + r + " (manual, either, body, body+etx)";
}

/// --iface NAME (repeatable): only frames of these interfaces.
struct interface_filter {
  std::set<std::string> names;
  explicit interface_filter(const options &o) {
    for (auto [it, end] = o.values.equal_range("--iface"); it != end; ++it) {
      names.insert(it->second);
    }
  }
  [[nodiscard]] bool passes(const host::frame_record &r) const {
    return names.empty() || names.count(std::string(r.iface.view())) != 0U;
  }
};

int cmd_decode(const std::vector<std::string> &args, context c) {
  options o;
  std::string error;
  if (!parse_options(args, 1, {"--dict", "--device", "--iface", "--check-rule"},
                     {"--json", "--sdo-frames", "--pacontrol", "--hex", "--raw"}, o, error)) {
    return c.usage(error);
  }
  if (o.has("--help")) {
    c.out << decode_help;
    return exit_ok;
  }
  if (o.positional.size() > 1U) return c.usage("one input file at most");
  const std::string file = o.positional.empty() ? "-" : o.positional[0];
  std::ifstream in_file;
  if (file != "-") {
    in_file.open(file, std::ios::binary);
    if (!in_file) return c.fail(exit_io, file + ": cannot open");
  }
  std::istream &in = file == "-" ? c.in : in_file;
  const bool json = o.has("--json");
  bool problems = false;
  if (o.has("--pacontrol")) {
    std::string input;
    if (!read_stream(in, input)) return c.fail(exit_io, file + ": cannot read");
    std::vector<std::uint8_t> bytes;
    const bool hex = o.has("--hex") || (!o.has("--raw") && looks_like_hex(input));
    if (hex) {
      if (!parse_hex_capture(input, bytes, error)) return c.fail(exit_input, file + ": " + error);
    } else {
      bytes.assign(input.begin(), input.end());
    }
    auto checks = default_decode_checks();
    if (o.given("--check-rule")) {
      const auto r = parse_check_rule(o.get("--check-rule"));
      if (!r) return c.usage(check_rule_error(o.get("--check-rule")));
      checks = *r;
    }
    const auto lines = decode_pacontrol(bytes, checks);
    print_lines(lines, json, c.out);
    for (const auto &l : lines) {
      problems = problems || l.function == "MALFORMED" || l.function == "NOISE" ||
                 l.function == "TRUNCATED" ||
                 (l.problem && l.json.text().find("bad checksum") != std::string::npos);
    }
    return problems ? exit_input : exit_ok;
  }
  if (o.has("--hex") || o.has("--raw") || o.given("--check-rule")) {
    return c.usage("--hex, --raw and --check-rule go with --pacontrol");
  }
  std::map<std::uint8_t, node_dictionary> dicts;
  std::map<std::uint8_t, device_family> families;
  int code = exit_ok;
  if (!load_dictionaries(o, c, dicts, families, code)) return code;
  can_decoder dec(std::move(dicts), std::move(families), {o.has("--sdo-frames")});
  std::vector<decoded_line> lines;
  std::size_t n = 0;
  const interface_filter only(o);
  // line by line, so that `candump can0 | fieldcodec decode` shows frames as they come
  std::string line;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::string_view raw = line;
    if (n == 1U && raw.substr(0, 3) == "\xEF\xBB\xBF") raw.remove_prefix(3); // UTF-8 BOM
    if (host::candump::is_blank_or_comment(raw)) continue;
    if (raw.substr(0, 9) == "DROPCOUNT") { // candump -d: frames the kernel dropped
      dec.note(raw, n, lines);
    } else if (auto r = host::candump::parse_line(raw); !r) {
      dec.malformed(raw, r.error(), n, lines);
      problems = true;
    } else if (only.passes(r.value())) {
      dec.feed(r.value(), n, lines);
    }
    print_lines(lines, json, c.out);
    if (file == "-") c.out.flush();
    lines.clear();
  }
  if (in.bad()) return c.fail(exit_io, file + ": cannot read");
  dec.finish(lines);
  problems = problems || !lines.empty();
  print_lines(lines, json, c.out);
  return problems ? exit_input : exit_ok;
}

// ---------------------------------------------------------------------------------------------
// monitor

volatile std::sig_atomic_t interrupted = 0;
extern "C" void on_interrupt(int) { interrupted = 1; }

int cmd_monitor(const std::vector<std::string> &args, context c) {
  options o;
  std::string error;
  if (!parse_options(
          args, 1, join({"--dict", "--device", "--count", "--duration", "--log"}, transport_values),
          join({"--json", "--sdo-frames"}, transport_flags), o, error)) {
    return c.usage(error);
  }
  if (o.has("--help")) {
    c.out << monitor_help << transport_help;
    return exit_ok;
  }
  if (!o.positional.empty()) return c.usage("unexpected argument " + o.positional[0]);
  std::uint64_t count = 0;
  std::uint64_t duration = 0;
  if (o.given("--count") && !parse_uint(o.get("--count"), ~std::uint64_t{0}, count)) {
    return c.usage("bad --count");
  }
  if (o.given("--duration") && !parse_uint(o.get("--duration"), 1U << 30U, duration)) {
    return c.usage("bad --duration");
  }
  std::map<std::uint8_t, node_dictionary> dicts;
  std::map<std::uint8_t, device_family> families;
  int code = exit_ok;
  if (!load_dictionaries(o, c, dicts, families, code)) return code;
  std::ofstream log;
  if (o.given("--log")) {
    log.open(o.get("--log"));
    if (!log) return c.fail(exit_io, o.get("--log") + ": cannot write");
  }
  auto bus = open_bus(o, c, code);
  if (!bus) return code;
  can_decoder dec(std::move(dicts), std::move(families), {o.has("--sdo-frames")});
  const bool json = o.has("--json");
  interrupted = 0;
  auto old = std::signal(SIGINT, on_interrupt);
  const auto start = std::chrono::steady_clock::now();
  std::uint64_t frames = 0;
  std::vector<decoded_line> lines;
  int result = exit_ok;
  while (interrupted == 0 && (count == 0U || frames < count)) {
    if (duration != 0U &&
        std::chrono::steady_clock::now() - start >= std::chrono::seconds(duration)) {
      break;
    }
    auto r = bus->receive_record(std::chrono::milliseconds(100));
    if (!r) {
      if (r.error() == errc::timeout) continue;
      result = c.fail(exit_io, bus->last_error().what);
      break;
    }
    ++frames;
    if (log) log << host::candump::format_line(r.value()) << "\n" << std::flush;
    dec.feed(r.value(), 0, lines);
    print_lines(lines, json, c.out);
    c.out.flush();
    lines.clear();
  }
  std::signal(SIGINT, old);
  dec.finish(lines);
  print_lines(lines, json, c.out);
  return result;
}

// ---------------------------------------------------------------------------------------------
// sdo read / write

struct sdo_target {
  std::uint8_t node = 0;
  od::address a{};
  std::optional<node_dictionary> dict;
  std::optional<object_desc> typed; ///< the entry --type makes
  const object_desc *desc = nullptr;
  std::string label; ///< "node 5, 6073h:00 Limit I_Force"
};

/// --timeout MS: 1 ms .. 1 hour (0 would time out before any answer could come).
bool parse_timeout(const options &o, const context &c, std::uint64_t &ms, int &code) {
  code = exit_ok;
  if (!o.given("--timeout")) return true;
  if (!parse_uint(o.get("--timeout"), 3600000, ms) || ms == 0U) {
    code = c.usage("bad --timeout " + o.get("--timeout") + " (1..3600000 ms)");
    return false;
  }
  return true;
}

int sdo_common(const std::vector<std::string> &args, context &c, bool write, options &o,
               sdo_target &t, host::sdo_options &so) {
  std::string error;
  if (!parse_options(
          args, 2, join({"--dict", "--type", "--timeout", "--switch-threshold"}, transport_values),
          join({"--block", "--json", "--raw"}, transport_flags), o, error)) {
    return c.usage(error);
  }
  if (o.has("--help")) {
    c.out << (write ? sdo_write_help : sdo_read_help) << transport_help;
    return -1;
  }
  const std::size_t want = write ? 3U : 2U;
  if (o.positional.size() != want) {
    return c.usage(write ? "expected NODE INDEX[:SUB] VALUE" : "expected NODE INDEX[:SUB]");
  }
  if (!parse_node(o.positional[0], false, t.node)) {
    return c.usage("bad node '" + o.positional[0] + "' (1..127)");
  }
  if (!parse_address(o.positional[1], t.a)) {
    return c.usage("bad object '" + o.positional[1] + "' (INDEX[:SUB] in hex, e.g. 1018:1)");
  }
  if (o.given("--dict") && o.given("--type")) {
    return c.usage("--dict and --type both give the object's type: give one");
  }
  if (o.values.count("--dict") > 1U || o.values.count("--type") > 1U) {
    return c.usage(o.values.count("--dict") > 1U ? "--dict given twice" : "--type given twice");
  }
  std::uint64_t timeout = 1000;
  int code = exit_ok;
  if (!parse_timeout(o, c, timeout, code)) return code;
  so.timeout = std::chrono::milliseconds(timeout);
  so.block = o.has("--block");
  if (o.given("--switch-threshold")) {
    std::uint64_t pst = 0;
    if (!parse_uint(o.get("--switch-threshold"), 127, pst))
      return c.usage("bad --switch-threshold");
    so.block_options.switch_threshold = static_cast<std::uint8_t>(pst);
  }
  t.label = "node " + std::to_string(t.node) + ", " + address_text(t.a);
  if (o.given("--type")) {
    t.typed = type_entry(o.get("--type"), t.a);
    if (!t.typed) {
      return c.usage("unknown type '" + o.get("--type") + "' (" + std::string(type_names) + ")");
    }
    t.desc = &*t.typed;
  }
  if (o.given("--dict")) {
    auto loaded = node_dictionary::load(o.get("--dict"), error);
    if (!loaded) return c.fail(exit_dictionary, error);
    t.dict = loaded->for_node(t.node);
    t.desc = t.dict->find(t.a);
    if (t.desc == nullptr) {
      return c.fail(exit_failed, t.label + ": not in " + o.get("--dict"));
    }
    t.label += " " + t.desc->name;
  }
  return exit_ok;
}

/// The line `sdo read` prints for a value (and `sdo write` for what it sent): with --json also
/// the bytes ("bytes" that came, "sent" that went).
std::string value_line(const sdo_target &t, const formatted_value &f, bool json,
                       std::span<const std::uint8_t> bytes, bool sent) {
  if (json) {
    json_object j;
    j.num("node", t.node).unum("index", t.a.index).unum("sub", t.a.sub);
    if (t.dict && t.desc != nullptr) j.str("name", t.desc->name);
    std::string s = j.text();
    if (!f.json.empty()) {
      s.pop_back();
      s += "," + f.json.text().substr(1);
    }
    s.pop_back();
    s += std::string(sent ? ",\"sent\":" : ",\"bytes\":") + json_string(hex_bytes(bytes, "")) + "}";
    return s;
  }
  const std::string name = t.dict && t.desc != nullptr ? " " + t.desc->name : std::string();
  return address_text(t.a) + name + " = " + f.text;
}

/// The SDO failure as a line, with a hint when block transfer was the likely cause.
int sdo_failure(const context &c, const host::sdo_session &s, bool block) {
  const host::sdo_error &e = s.last_error();
  std::string what = e.what;
  const bool protocol =
      e.code == errc::unexpected_frame || e.abort == canopen::sdo::abort_code::unknown_command;
  if (block && protocol) {
    what += " (with --block: the node may not support block transfer, or answers a block upload "
            "with a normal upload; try without --block, or allow the switch with "
            "--switch-threshold 127)";
  }
  return c.fail(e.bus_failed ? exit_io : exit_failed, what);
}

int cmd_sdo_read(const std::vector<std::string> &args, context c) {
  options o;
  sdo_target t;
  host::sdo_options so;
  if (const int r = sdo_common(args, c, false, o, t, so); r != exit_ok) {
    return r < 0 ? exit_ok : r;
  }
  int code = exit_ok;
  auto bus = open_bus(o, c, code);
  if (!bus) return code;
  host::sdo_session s(*bus, t.node, so);
  auto v = s.read(t.a);
  if (!v) return sdo_failure(c, s, so.block);
  const std::vector<std::uint8_t> bytes(v.value().begin(), v.value().end());
  value_context ctx;
  const device_family fam = t.dict ? t.dict->family() : device_family::generic;
  const auto f = format_value(t.desc, t.a, bytes, fam, ctx, o.has("--raw"));
  c.out << value_line(t, f, o.has("--json"), bytes, false) << "\n";
  return exit_ok;
}

int cmd_sdo_write(const std::vector<std::string> &args, context c) {
  options o;
  sdo_target t;
  host::sdo_options so;
  if (const int r = sdo_common(args, c, true, o, t, so); r != exit_ok) {
    return r < 0 ? exit_ok : r;
  }
  if (t.desc == nullptr) {
    return c.usage("no dictionary entry: give the type with --type (" + std::string(type_names) +
                   ") or the dictionary with --dict");
  }
  const bool raw = o.has("--raw");
  const auto v = parse_value(*t.desc, o.positional[2], t.node, raw);
  if (!v.ok) return c.fail(exit_usage, t.label + ": " + v.error + " (nothing sent)");
  int code = exit_ok;
  auto bus = open_bus(o, c, code);
  if (!bus) return code;
  host::sdo_session s(*bus, t.node, so);
  if (!s.write(t.a, v.bytes)) return sdo_failure(c, s, so.block);
  // what was sent, shown as `sdo read` shows it
  value_context ctx;
  const device_family fam = t.dict ? t.dict->family() : device_family::generic;
  const auto f = format_value(t.desc, t.a, v.bytes, fam, ctx, raw);
  c.out << value_line(t, f, o.has("--json"), v.bytes, true) << "\n";
  return exit_ok;
}

// ---------------------------------------------------------------------------------------------
// nmt

int cmd_nmt(const std::vector<std::string> &args, context c) {
  options o;
  std::string error;
  if (!parse_options(args, 1, transport_values, transport_flags, o, error)) return c.usage(error);
  if (o.has("--help")) {
    c.out << nmt_help << transport_help;
    return exit_ok;
  }
  if (o.positional.size() != 2U) return c.usage("expected COMMAND NODE");
  static const std::map<std::string, canopen::nmt::command> commands = {
      {"start", canopen::nmt::command::start},
      {"stop", canopen::nmt::command::stop},
      {"pre-operational", canopen::nmt::command::enter_pre_operational},
      {"reset-node", canopen::nmt::command::reset_node},
      {"reset-communication", canopen::nmt::command::reset_communication}};
  const auto cmd = commands.find(o.positional[0]);
  if (cmd == commands.end()) {
    return c.usage("unknown NMT command '" + o.positional[0] +
                   "' (start, stop, pre-operational, reset-node, reset-communication)");
  }
  std::uint8_t node = 0;
  if (!parse_node(o.positional[1], true, node))
    return c.usage("bad node '" + o.positional[1] + "'");
  int code = exit_ok;
  auto bus = open_bus(o, c, code);
  if (!bus) return code;
  if (!bus->send(canopen::nmt::encode(cmd->second, node).value())) {
    return c.fail(exit_io, bus->last_error().what);
  }
  return exit_ok;
}

// ---------------------------------------------------------------------------------------------
// lss

/// "V,P,R,S" → an LSS address (each 32-bit, decimal or 0x hex).
bool parse_lss_address(const std::string &s, canopen::lss::address &a) {
  std::array<std::uint32_t, 4> v{};
  std::size_t at = 0;
  for (std::size_t i = 0; i < 4U; ++i) {
    const std::size_t comma = i < 3U ? s.find(',', at) : s.size();
    if (comma == std::string::npos) return false;
    std::uint64_t x = 0;
    if (!parse_uint(std::string_view(s).substr(at, comma - at), 0xFFFF'FFFFU, x)) return false;
    v[i] = static_cast<std::uint32_t>(x);
    at = comma + 1U;
  }
  if (s.find(',', s.rfind(',') + 1U) != std::string::npos) return false;
  a = {v[0], v[1], v[2], v[3]};
  return true;
}

std::string lss_address_text(const canopen::lss::address &a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "0x%08X,0x%08X,0x%08X,0x%08X", static_cast<unsigned>(a.vendor),
                static_cast<unsigned>(a.product), static_cast<unsigned>(a.revision),
                static_cast<unsigned>(a.serial));
  return buf;
}

/// Runs one LSS service to its end over `bus`: false (and the error printed) when the bus
/// failed or no answer came.
bool run_lss(host::can_bus &bus, canopen::lss::master &m, const host::steady_ms &clock,
             fieldcodec::result<canopen::lss::master::step> started, const context &c,
             const std::string &what, int &code) {
  if (!started) {
    code = c.fail(exit_usage, what + ": " + std::string(to_string(started.error())));
    return false;
  }
  canopen::lss::master::step s = started.value();
  for (;;) {
    for (const canopen::can_frame &f : s.send) {
      if (!bus.send(f)) {
        code = c.fail(exit_io, bus.last_error().what);
        return false;
      }
    }
    if (!m.busy()) break;
    const std::uint32_t now = clock.now();
    const std::uint32_t due = s.deadline.value_or(now);
    const auto left = static_cast<std::int32_t>(due - now);
    auto r = bus.receive(std::chrono::milliseconds(left > 0 ? left : 0));
    if (r) {
      s = m.on_frame(r.value().frame, clock.now());
    } else if (r.error() == errc::timeout) {
      s = m.poll(clock.now());
    } else {
      code = c.fail(exit_io, bus.last_error().what);
      return false;
    }
  }
  if (m.state() == canopen::lss::master_state::failed) {
    code = c.fail(exit_failed, what + ": no answer (is a node in LSS configuration?)");
    return false;
  }
  return true;
}

/// The answer's error code of configure / store as text; empty for none.
std::string lss_refusal(const canopen::lss::master &m, const std::string &meaning) {
  const std::uint8_t e = m.error_code();
  if (e == canopen::lss::error_code::none) return {};
  if (e == canopen::lss::error_code::not_supported) return meaning + " (error code 1)";
  if (e == canopen::lss::error_code::storage_access) return "storage access failed (error code 2)";
  if (e == canopen::lss::error_code::manufacturer) {
    return "manufacturer's error " + std::to_string(m.manufacturer_code()) + " (error code 255)";
  }
  return "error code " + std::to_string(e);
}

int cmd_lss(const std::vector<std::string> &args, context c) {
  options o;
  std::string error;
  if (!parse_options(args, 1, join({"--address", "--timeout", "--probe"}, transport_values),
                     transport_flags, o, error)) {
    return c.usage(error);
  }
  if (o.has("--help")) {
    c.out << lss_help << transport_help;
    return exit_ok;
  }
  if (o.positional.empty()) return c.usage("expected a SERVICE");
  const std::string service = o.positional[0];
  static const std::map<std::string, std::size_t> arity = {
      {"scan", 1},  {"set-node", 2}, {"set-bitrate", 2},   {"activate", 2},
      {"store", 1}, {"inquire", 1},  {"configuration", 1}, {"waiting", 1}};
  const auto known = arity.find(service);
  if (known == arity.end()) {
    return c.usage("unknown LSS service '" + service +
                   "' (scan, set-node, set-bitrate, activate, store, inquire, configuration, "
                   "waiting)");
  }
  if (o.positional.size() != known->second) {
    return c.usage(known->second == 1U ? "'" + service + "' takes no argument"
                                       : "'" + service + "' expects one argument");
  }
  canopen::lss::master_options mo;
  std::uint64_t v = 0;
  if (o.given("--timeout")) {
    if (!parse_uint(o.get("--timeout"), 60000, v) || v == 0U) {
      return c.usage("bad --timeout '" + o.get("--timeout") + "' (1..60000 ms)");
    }
    mo.timeout_ms = static_cast<std::uint32_t>(v);
  }
  if (o.given("--probe")) {
    if (!parse_uint(o.get("--probe"), 60000, v) || v == 0U) {
      return c.usage("bad --probe '" + o.get("--probe") + "' (1..60000 ms)");
    }
    mo.probe_ms = static_cast<std::uint32_t>(v);
  }
  std::optional<canopen::lss::address> select;
  if (o.given("--address")) {
    canopen::lss::address a;
    if (!parse_lss_address(o.get("--address"), a)) {
      return c.usage("bad --address '" + o.get("--address") +
                     "' (VENDOR,PRODUCT,REVISION,SERIAL, each decimal or 0x hex)");
    }
    select = a;
  }
  // the argument, checked before the bus is opened
  std::uint8_t node = 0;
  std::uint8_t bit_index = 0;
  std::uint16_t delay = 0;
  if (service == "set-node") {
    if (!parse_uint(o.positional[1], 255, v) || v == 0U || (v > 127U && v != 255U)) {
      return c.usage("bad node-ID '" + o.positional[1] + "' (1..127, or 255: none)");
    }
    node = static_cast<std::uint8_t>(v);
  } else if (service == "set-bitrate") {
    bool found = false;
    if (parse_uint(o.positional[1], 1000, v)) {
      for (std::uint8_t i = 0; i < 9U; ++i) {
        if (canopen::lss::standard_bit_rate(i) != 0U && canopen::lss::standard_bit_rate(i) == v) {
          bit_index = i;
          found = true;
        }
      }
    }
    if (!found) {
      return c.usage("bad bit rate '" + o.positional[1] +
                     "' kbit/s (1000, 800, 500, 250, 125, 50, 20, 10)");
    }
  } else if (service == "activate") {
    if (!parse_uint(o.positional[1], 0xFFFF, v)) {
      return c.usage("bad delay '" + o.positional[1] + "' (0..65535 ms)");
    }
    delay = static_cast<std::uint16_t>(v);
  }
  int code = exit_ok;
  auto bus = open_bus(o, c, code);
  if (!bus) return code;
  canopen::lss::master m(mo);
  host::steady_ms clock;
  const auto run_one = [&](auto started, const std::string &what) {
    return run_lss(*bus, m, clock, started, c, what, code);
  };
  if (select && !run_one(m.switch_selective(*select, clock.now()), "switch state selective")) {
    return code;
  }
  namespace lss = canopen::lss;
  if (service == "scan") {
    if (!run_one(m.fastscan(clock.now()), "fastscan")) return code;
    if (!m.found()) return c.fail(exit_failed, "no node without node-ID answered");
    c.out << "address " << lss_address_text(m.found_address()) << "\n";
  } else if (service == "set-node" || service == "set-bitrate" || service == "store") {
    const bool id = service == "set-node";
    const bool store = service == "store";
    auto started = id      ? m.configure_node_id(node, clock.now())
                   : store ? m.store(clock.now())
                           : m.configure_bit_timing(0, bit_index, clock.now());
    if (!run_one(started, service)) return code;
    const std::string refused = lss_refusal(m, id      ? "node-ID out of range"
                                               : store ? "storing not supported"
                                                       : "bit rate not supported");
    if (!refused.empty()) return c.fail(exit_failed, "the node refused: " + refused);
  } else if (service == "activate") {
    if (!run_one(m.activate_bit_timing(delay, clock.now()), service)) return code;
  } else if (service == "inquire") {
    constexpr std::array<std::pair<lss::command, const char *>, 5> asked{{
        {lss::command::inquire_vendor, "vendor-ID"},
        {lss::command::inquire_product, "product code"},
        {lss::command::inquire_revision, "revision number"},
        {lss::command::inquire_serial, "serial number"},
        {lss::command::inquire_node_id, "node-ID"},
    }};
    std::array<std::uint32_t, 5> got{};
    for (std::size_t i = 0; i < asked.size(); ++i) {
      if (!run_one(m.inquire(asked[i].first, clock.now()),
                   std::string("inquire ") + asked[i].second)) {
        return code;
      }
      got[i] = m.value();
    }
    c.out << "address " << lss_address_text({got[0], got[1], got[2], got[3]}) << "\n";
    c.out << "node-ID "
          << (got[4] == lss::unconfigured ? std::string("none (255)") : std::to_string(got[4]))
          << "\n";
  } else {
    const std::uint8_t mode = service == "configuration" ? 1U : 0U;
    if (!run_one(m.switch_global(mode, clock.now()), service)) return code;
  }
  return exit_ok;
}

// ---------------------------------------------------------------------------------------------
// serve

/// What a simulated node holds: node::device over a dictionary_store of the dictionary loaded at
/// run time. Capacity for the dictionaries devices describe (CiA 301 allows more; a dictionary
/// beyond it is served in part, with a warning).
constexpr canopen::node::capacity serve_capacity{.rpdos = 32,
                                                 .tpdos = 32,
                                                 .mapped = 64,
                                                 .heartbeat_consumers = 32,
                                                 .sdo_servers = 8,
                                                 .sdo_clients = 0,
                                                 .sdo_buffer = 889,
                                                 .sdo_crc_table = false,
                                                 .pdo_copies = true,
                                                 .active_errors = 16,
                                                 .error_history = 16,
                                                 .emcy_queue = 8,
                                                 .error_classes = 8,
                                                 .sync_producer = true,
                                                 .storage = true};

/// The network's writes the store took (its write hook), for `written:` lines.
struct write_log {
  std::vector<std::pair<od::address, std::vector<std::uint8_t>>> *out = nullptr;
  canopen::sdo::abort_code operator()(const od::entry &e, std::span<const std::uint8_t> v) const {
    out->emplace_back(od::address{e.index, e.sub}, std::vector<std::uint8_t>(v.begin(), v.end()));
    return canopen::sdo::abort_code::none;
  }
};

/// Lines of standard input without blocking: std::cin by poll() on descriptor 0; any other
/// stream (the tests' strings) is read whole, it never blocks.
class line_source {
public:
  explicit line_source(std::istream &in) : in_(in), fd_(&in == &std::cin) {}
  /// The complete lines that arrived; false once the input has ended and every line was given.
  bool take(std::vector<std::string> &lines) {
    if (ended_) return false;
    if (!fd_) {
      std::string l;
      while (std::getline(in_, l)) lines.push_back(l);
      ended_ = true;
      return true;
    }
    for (;;) {
      pollfd p{0, POLLIN, 0};
      if (::poll(&p, 1, 0) <= 0) break;
      char buf[4096];
      const ssize_t n = ::read(0, buf, sizeof buf);
      if (n <= 0) {
        ended_ = true;
        break;
      }
      pending_.append(buf, static_cast<std::size_t>(n));
    }
    for (std::size_t nl; (nl = pending_.find('\n')) != std::string::npos;) {
      lines.push_back(pending_.substr(0, nl));
      pending_.erase(0, nl + 1U);
    }
    if (ended_ && !pending_.empty()) lines.push_back(std::exchange(pending_, {}));
    return true;
  }

private:
  std::istream &in_;
  bool fd_;
  bool ended_ = false;
  std::string pending_;
};

int cmd_serve(const std::vector<std::string> &args, context c) {
  options o;
  std::string error;
  if (!parse_options(args, 1, join({"--dict", "--duration", "--storage"}, transport_values),
                     transport_flags, o, error)) {
    return c.usage(error);
  }
  if (o.has("--help")) {
    c.out << serve_help << transport_help;
    return exit_ok;
  }
  if (o.positional.size() != 1U) return c.usage("expected NODE");
  std::uint8_t node = 0;
  if (!parse_node(o.positional[0], false, node)) {
    return c.usage("bad node '" + o.positional[0] + "' (1..127)");
  }
  if (o.values.count("--dict") != 1U) {
    return c.usage(o.given("--dict") ? "--dict given twice" : "give the dictionary: --dict FILE");
  }
  std::uint64_t duration = 0;
  if (o.given("--duration") &&
      (!parse_uint(o.get("--duration"), 1U << 30U, duration) || duration == 0U)) {
    return c.usage("bad --duration " + o.get("--duration") + " (1..2^30 seconds)");
  }
  if (o.values.count("--storage") > 1U) return c.usage("--storage given twice");
  const std::string file = o.get("--dict");
  auto loaded = node_dictionary::load(file, error);
  if (!loaded) return c.fail(exit_dictionary, error);
  const node_dictionary values = loaded->for_node(node); // what stdin and stdout show
  const auto tables = values.device_tables();            // what the device stores
  const od::dictionary dict = tables->view();
  std::vector<std::uint32_t> offsets(dict.size() + 1U);
  (void)canopen::make_layout(dict, offsets);
  std::vector<std::uint8_t> storage(offsets.back());
  std::vector<std::uint8_t> staging(65536);
  std::vector<std::pair<od::address, std::vector<std::uint8_t>>> written;
  using store_t = canopen::dictionary_store<write_log>;
  store_t store{dict, std::span<const std::uint32_t>(offsets), storage, staging,
                write_log{&written}};
  if (const status s = store.init_defaults(node); !s) {
    // too_long: a default text longer than its object's size (cut; served)
    if (s.error() != errc::too_long) return c.fail(exit_dictionary, file + ": cannot be served");
    c.err << "fieldcodec: serve: " << file
          << ": a default text is longer than its object's size (cut)\n";
  }
  auto dev = std::make_unique<canopen::node::device<store_t, serve_capacity>>(store, node);
  // --storage: the saved values over the defaults, now and after every reset
  std::optional<host::parameter_file> saved;
  auto put_back = [&](std::uint8_t group) {
    auto r = saved->apply(*dev, group);
    if (!r)
      c.err << "fieldcodec: serve: saved values not set (the defaults stay):\n"
            << r.error() << "\n";
    return r;
  };
  if (o.given("--storage")) {
    saved.emplace(o.get("--storage"), dict, *dev);
    if (auto r = saved->read(); !r) return c.fail(exit_io, r.error());
    dev->set_storage(saved->hook());
    if (auto r = put_back(canopen::node::parameter_group::all)) {
      c.out << "storage: " << r.value() << " saved values set from " << saved->path() << "\n";
    }
  }
  int code = exit_ok;
  auto bus = open_bus(o, c, code);
  if (!bus) return code;
  const device_family family = values.family();
  value_context ctx;
  auto line_of = [&](od::address a, std::span<const std::uint8_t> bytes) {
    const object_desc *d = values.find(a);
    const auto f = format_value(d, a, bytes, family, ctx, false);
    return address_text(a) + (d != nullptr ? " " + d->name : std::string()) + " = " + f.text;
  };
  host::network net(*bus);
  const auto id = net.add(*dev, [&](const auto &, std::uint32_t) {
    for (const auto &[a, bytes] : written) c.out << "written: " << line_of(a, bytes) << "\n";
    written.clear();
    for (const auto &e : dev->events()) {
      if (e.what == canopen::node::event::kind::nmt_state) {
        c.out << "NMT: " << canopen::nmt::to_string(e.state) << "\n";
      }
      // after a reset the node holds the defaults of the area it reset: the saved ones again
      if (saved && e.what == canopen::node::event::kind::reset_application) {
        (void)put_back(canopen::node::parameter_group::all);
      } else if (saved && e.what == canopen::node::event::kind::reset_communication) {
        (void)put_back(canopen::node::parameter_group::communication);
      }
    }
    c.out.flush();
  });
  auto started = net.send(id, dev->start(net.now()));
  if (!started) return c.fail(exit_io, started.error().what);
  c.out << "NMT: " << canopen::nmt::to_string(started.value()) << "\n" << std::flush;
  if (!dev->configuration()) {
    c.err << "fieldcodec: serve: " << file << ": served in part ("
          << to_string(dev->configuration().error())
          << "): more PDOs, mapping entries or SDO channels than serve runs\n";
  }

  // one stdin line: set a value, or show it
  std::size_t line_no = 0;
  int result = exit_ok;
  auto refuse = [&](const std::string &what) {
    c.fail(exit_usage, "input line " + std::to_string(line_no) + ": " + what + " (not set)");
    result = exit_usage;
  };
  auto apply = [&](std::string_view l) {
    ++line_no;
    while (!l.empty() && (l.back() == '\r' || l.back() == ' ' || l.back() == '\t'))
      l.remove_suffix(1);
    while (!l.empty() && (l.front() == ' ' || l.front() == '\t')) l.remove_prefix(1);
    if (l.empty() || l.front() == '#') return;
    bool raw = false;
    if (l.rfind("raw ", 0) == 0) {
      raw = true;
      l.remove_prefix(4);
      while (!l.empty() && l.front() == ' ') l.remove_prefix(1);
    }
    const auto space = l.find_first_of(" \t");
    const std::string where(l.substr(0, space));
    std::string_view text = space == std::string_view::npos ? std::string_view{} : l.substr(space);
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    od::address a{};
    if (!parse_address(where, a)) {
      return refuse("bad object '" + capped(where) + "' (INDEX[:SUB] in hex, e.g. 1018:1)");
    }
    const object_desc *d = values.find(a);
    if (d == nullptr) return refuse(address_text(a) + ": not in " + file);
    if (text.empty()) {
      if (raw) return refuse(address_text(a) + ": 'raw' needs a VALUE");
      auto v = dev->value(a);
      if (!v) return refuse(address_text(a) + ": " + std::string(to_string(v.error())));
      c.out << line_of(a, v.value()) << "\n" << std::flush;
      return;
    }
    const auto v = parse_value(*d, text, node, raw);
    if (!v.ok) return refuse(address_text(a) + " " + d->name + ": " + v.error);
    auto s = dev->set(a, v.bytes, net.now());
    if (!s) {
      return refuse(address_text(a) + " " + d->name + ": " +
                    std::string(canopen::sdo::to_string(s.error())));
    }
    written.clear(); // set() asks no hook; nothing of the network's is pending here
    c.out << line_of(a, dev->value(a).value()) << "\n" << std::flush;
    if (auto r = net.send(id, s.value()); !r) {
      result = c.fail(exit_io, r.error().what);
    }
  };

  interrupted = 0;
  auto old_int = std::signal(SIGINT, on_interrupt);
  auto old_term = std::signal(SIGTERM, on_interrupt);
  line_source input(c.in);
  std::vector<std::string> lines;
  const auto start = std::chrono::steady_clock::now();
  while (interrupted == 0 && result != exit_io) {
    if (duration != 0U &&
        std::chrono::steady_clock::now() - start >= std::chrono::seconds(duration)) {
      break;
    }
    if (input.take(lines)) {
      for (const std::string &l : lines) apply(l);
      lines.clear();
    }
    if (auto r = net.run_once(std::chrono::milliseconds(50)); !r) {
      result = c.fail(exit_io, r.error().what);
    }
  }
  std::signal(SIGINT, old_int);
  std::signal(SIGTERM, old_term);
  return result;
}

// ---------------------------------------------------------------------------------------------
// dump

/// Consecutive SDO timeouts after which `dump` takes the node as silent and stops.
constexpr std::size_t dump_silent_after = 3;

int cmd_dump(const std::vector<std::string> &args, context c) {
  options o;
  std::string error;
  if (!parse_options(args, 1, join({"--dict", "--output", "--timeout"}, transport_values),
                     join({"--block", "--progress", "--quiet"}, transport_flags), o, error)) {
    return c.usage(error);
  }
  if (o.has("--help")) {
    c.out << dump_help << transport_help;
    return exit_ok;
  }
  if (o.positional.size() != 1U) return c.usage("expected NODE");
  std::uint8_t node = 0;
  if (!parse_node(o.positional[0], false, node))
    return c.usage("bad node '" + o.positional[0] + "'");
  if (!o.given("--dict")) return c.usage("dump needs the node's dictionary (--dict FILE)");
  if (o.values.count("--dict") > 1U) return c.usage("--dict given twice");
  std::uint64_t timeout = 1000;
  int code = exit_ok;
  if (!parse_timeout(o, c, timeout, code)) return code;
  auto loaded = node_dictionary::load(o.get("--dict"), error);
  if (!loaded) return c.fail(exit_dictionary, error);
  const node_dictionary dict = loaded->for_node(node);
  auto bus = open_bus(o, c, code);
  if (!bus) return code;
  host::sdo_options so;
  so.timeout = std::chrono::milliseconds(timeout);
  so.block = o.has("--block");
  host::sdo_session s(*bus, node, so);
  gen::dictionary model = dict.model();
  // a line kept on a terminal; elsewhere (a log) a line at every tenth of a long dump
  const bool terminal = c.err_terminal;
  const bool progress = !o.has("--quiet") && (o.has("--progress") || terminal);
  const bool milestones = !o.has("--quiet") && !progress;
  std::size_t readable = 0;
  for (const auto &e : model.entries) readable += od::readable(e.access) ? e.count : 0U;
  std::size_t done = 0;
  std::size_t failed = 0;
  std::size_t timeouts = 0; ///< in a row
  od::address first_timeout{};
  bool answered = false; ///< the node answered at least once
  std::vector<std::string> refused;
  for (gen::entry &e : model.entries) {
    if (!od::readable(e.access)) continue;
    for (std::uint16_t k = 0; k < e.count; ++k) {
      const od::address a{e.index, static_cast<std::uint8_t>(e.sub + k)};
      ++done;
      if (progress) {
        c.err << "\rreading " << done << "/" << readable << " " << address_text(a) << "   "
              << std::flush;
      } else if (milestones && readable >= 50U && done % (readable / 10U) == 0U) {
        c.err << "fieldcodec: dump: reading " << done << "/" << readable << "\n" << std::flush;
      }
      auto v = s.read(a);
      if (!v) {
        if (s.last_error().bus_failed) {
          if (progress) c.err << "\n";
          return c.fail(exit_io, s.last_error().what);
        }
        ++failed;
        if (s.last_error().code != errc::timeout) {
          timeouts = 0;
          answered = true;
        } else if (timeouts++ == 0U) {
          first_timeout = a;
        }
        if (timeouts >= dump_silent_after) {
          if (progress) c.err << "\n";
          return c.fail(exit_failed,
                        "node " + std::to_string(node) + " " +
                            (answered ? "stopped answering" : "does not answer") + ": " +
                            std::to_string(timeouts) + " SDO timeouts in a row, from " +
                            address_text(first_timeout) + " (" + std::to_string(done - failed) +
                            " of " + std::to_string(readable) + " objects read); no DCF written");
        }
        refused.push_back(s.last_error().what);
        continue;
      }
      timeouts = 0;
      answered = true;
      if (e.count != 1U) continue; // a compact run keeps no per-sub-index value
      const object_desc *d = dict.find(a);
      if (od::is_byte_string(e.type)) {
        e.parameter_text = std::string(v.value().begin(), v.value().end());
        continue;
      }
      auto n = od::decode(static_cast<const od::entry &>(d->d), v.value(), byte_order::little,
                          od::limits::ignore);
      if (!n) {
        ++failed;
        refused.push_back("node " + std::to_string(node) + ", " + address_text(a) + ": " +
                          std::to_string(v.value().size()) + " bytes do not make a " +
                          std::string(od::name(e.type)));
        continue;
      }
      e.parameter_value = n.value();
      e.parameter_nodeid = false;
    }
  }
  if (progress) c.err << "\rread " << done - failed << " of " << readable << " objects\n";
  for (const auto &r : refused) c.err << "fieldcodec: dump: " << r << "\n";
  model.is_dcf = true;
  model.node_id = node;
  for (auto &[k, v] : model.commissioning) {
    if (k == "NodeID") v = std::to_string(node);
  }
  const std::string dcf = gen::write_eds(model);
  if (o.given("--output") && o.get("--output") != "-") {
    std::ofstream f(o.get("--output"), std::ios::binary);
    if (!f || !(f << dcf)) return c.fail(exit_io, o.get("--output") + ": cannot write");
  } else {
    c.out << dcf;
  }
  return exit_ok;
}

// ---------------------------------------------------------------------------------------------
// pacontrol send

int cmd_pacontrol_send(const std::vector<std::string> &args, context c) {
  namespace cmds = dictionaries::pacontrol_commands;
  options o;
  std::string error;
  if (!parse_options(
          args, 2,
          {"--baud", "--data-bits", "--parity", "--stop-bits", "--timeout", "--check-rule"},
          {"--rts-cts", "--json"}, o, error)) {
    return c.usage(error);
  }
  if (o.has("--help")) {
    c.out << pacontrol_send_help;
    return exit_ok;
  }
  if (o.positional.size() < 2U || o.positional.size() > 4U) {
    return c.usage("expected PORT COMMAND [PARAMETER [DATE]]");
  }
  host::line_settings line = host::pacontrol_line;
  std::uint64_t v = 0;
  if (o.given("--baud")) {
    if (!parse_uint(o.get("--baud"), 4000000, v)) return c.usage("bad --baud");
    line.baud = static_cast<std::uint32_t>(v);
  }
  if (o.given("--data-bits")) {
    if (!parse_uint(o.get("--data-bits"), 8, v) || v < 5U) return c.usage("bad --data-bits");
    line.data_bits = static_cast<std::uint8_t>(v);
  }
  if (o.given("--stop-bits")) {
    if (!parse_uint(o.get("--stop-bits"), 2, v) || v < 1U) return c.usage("bad --stop-bits");
    line.stop_bits = static_cast<std::uint8_t>(v);
  }
  if (o.given("--parity")) {
    const std::string p = o.get("--parity");
    if (p == "none") {
      line.par = host::parity::none;
    } else if (p == "even") {
      line.par = host::parity::even;
    } else if (p == "odd") {
      line.par = host::parity::odd;
    } else {
      return c.usage("bad --parity " + p + " (none, even, odd)");
    }
  }
  line.rts_cts = o.has("--rts-cts");
  if (!host::check(line)) return c.usage("unsupported line settings (baud rate?)");
  std::uint64_t timeout = 1000;
  if (int bad = exit_ok; !parse_timeout(o, c, timeout, bad)) return bad;
  host::pacontrol_options link_options;
  auto checks = parse_check_rule(o.get("--check-rule", "manual"));
  if (!checks) return c.usage(check_rule_error(o.get("--check-rule")));
  link_options.check = *checks;
  link_options.request_rule = checks->request;
  const std::string &name = o.positional[1];
  const bool poll = name == "poll";
  const od::command *cmd = nullptr;
  pacontrol::serial::request req;
  if (!poll) {
    for (const auto &k : cmds::commands) {
      if (k.name == name) cmd = &k;
    }
    if (cmd == nullptr) {
      std::uint64_t code = 0;
      if (parse_uint("0x" + name, 0xFFFF, code))
        cmd = cmds::table.find(static_cast<std::uint16_t>(code));
    }
    if (cmd == nullptr) return c.usage("unknown PA-CONTROL command '" + name + "'");
    std::uint64_t par = 0;
    if (o.positional.size() > 2U && !parse_uint(o.positional[2], 0xFFFF, par)) {
      return c.usage("bad parameter '" + o.positional[2] + "'");
    }
    const auto p = static_cast<std::uint16_t>(par);
    const std::string cname(cmd->name);
    auto range = [](const od::number &lo, const od::number &hi) {
      auto text = [](const od::number &n) {
        auto d = n.to_decimal();
        return d ? decimal_text(d.value()) : std::string("?");
      };
      return text(lo) + ".." + text(hi);
    };
    if (!cmd->check_parameter(p)) {
      return c.usage(cname + ": parameter " + std::to_string(p) + " is outside " +
                     range(cmd->parameter_min, cmd->parameter_max));
    }
    const bool takes_date = cmd->date_type != od::command_value::none;
    const std::string date_kind =
        cmd->date_type == od::command_value::real ? "a real date" : "an integer date";
    if (takes_date && o.positional.size() < 4U) {
      return c.usage(cname + " takes " + date_kind + ": PARAMETER DATE" +
                     (cmd->date_min || cmd->date_max
                          ? " (" + range(cmd->date_min, cmd->date_max) + ")"
                          : std::string()));
    }
    if (!takes_date && o.positional.size() > 3U) {
      return c.usage(cname + " takes no date (PARAMETER only)");
    }
    result<pacontrol::serial::request> r = errc::invalid_argument;
    if (takes_date) {
      const std::string &date = o.positional[3];
      auto dec = parse_decimal(std::string_view(date));
      if (!dec)
        return c.usage("bad date '" + date + "' (" + std::string(to_string(dec.error())) + ")");
      if (cmd->date_type == od::command_value::real) {
        auto val = pacontrol::value::of_real(dec.value());
        if (!val)
          return c.usage("bad date '" + date + "' (" + std::string(to_string(val.error())) + ")");
        r = pacontrol::make_request(*cmd, p, val.value());
      } else {
        if (dec.value().places != 0U) return c.usage("the date of " + cname + " is an integer");
        r = pacontrol::make_request(*cmd, p, dec.value().mantissa);
      }
      if (!r && r.error() == errc::out_of_range) {
        return c.usage(cname + ": date " + date + " is outside " +
                       range(cmd->date_min, cmd->date_max));
      }
    } else {
      r = pacontrol::make_request(*cmd, p);
    }
    if (!r) return c.usage(cname + ": " + std::string(to_string(r.error())));
    req = r.value();
  }
  host::pacontrol_link link;
  if (!link.open(o.positional[0], line, link_options)) {
    return c.fail(exit_io, link.last_error().what);
  }
  auto ack = poll ? link.poll(std::chrono::milliseconds(timeout))
                  : link.transact(req, std::chrono::milliseconds(timeout));
  if (!ack) {
    return c.fail(link.last_error().code == errc::bad_state ? exit_io : exit_failed,
                  link.last_error().what);
  }
  // the exchange, decoded as 'decode --pacontrol' shows it
  std::vector<std::uint8_t> both(link.sent().begin(), link.sent().end());
  both.insert(both.end(), link.received().begin(), link.received().end());
  const auto lines = decode_pacontrol(both, link_options.check);
  print_lines(lines, o.has("--json"), c.out);
  if (ack.value().command_error_number != 0U) {
    auto t = pacontrol::describe_command_error(ack.value().command_error_number);
    return c.fail(exit_failed, o.positional[0] + ": " + name + ": command error " +
                                   std::to_string(ack.value().command_error_number) + " (" +
                                   std::string(t ? t.value() : "unknown") + ")");
  }
  return exit_ok;
}

} // namespace

int run(const std::vector<std::string> &args, std::istream &in, std::ostream &out,
        std::ostream &err, bool err_terminal) {
  context c{in, out, err, "", err_terminal};
  if (args.size() > 1U && args[0] == "help") {
    // "help decode", "help sdo write": the command's own --help
    std::vector<std::string> asked(args.begin() + 1, args.end());
    asked.emplace_back("--help");
    return run(asked, in, out, err, err_terminal);
  }
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    (args.empty() ? err : out) << main_help;
    return args.empty() ? exit_usage : exit_ok;
  }
  if (args[0] == "--version") {
    out << "fieldcodec 0.1.0\n";
    return exit_ok;
  }
  const std::string &cmd = args[0];
  c.command = cmd;
  if (cmd == "decode") return cmd_decode(args, c);
  if (cmd == "monitor") return cmd_monitor(args, c);
  if (cmd == "nmt") return cmd_nmt(args, c);
  if (cmd == "lss") return cmd_lss(args, c);
  if (cmd == "dump") return cmd_dump(args, c);
  if (cmd == "serve") return cmd_serve(args, c);
  if (cmd == "sdo" || cmd == "pacontrol") {
    const std::string sub = args.size() > 1U ? args[1] : "";
    if (cmd == "sdo" && (sub == "read" || sub == "write")) {
      c.command = "sdo " + sub;
      return sub == "read" ? cmd_sdo_read(args, c) : cmd_sdo_write(args, c);
    }
    if (cmd == "pacontrol" && sub == "send") {
      c.command = "pacontrol send";
      return cmd_pacontrol_send(args, c);
    }
    if (sub == "--help" || sub == "-h") {
      out << (cmd == "sdo" ? std::string(sdo_read_help) + "\n" + sdo_write_help
                           : std::string(pacontrol_send_help));
      return exit_ok;
    }
    return c.usage(cmd == "sdo" ? "expected 'sdo read' or 'sdo write'"
                                : "expected 'pacontrol send'");
  }
  err << "fieldcodec: unknown command '" << cmd << "' (try 'fieldcodec --help')\n";
  return exit_usage;
}

} // namespace fieldcodec::cli
