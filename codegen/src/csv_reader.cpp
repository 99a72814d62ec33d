// fieldcodec-gen — CSV object and command tables (docs/dictionary-formats.md).
#include "readers.hpp"
#include "text.hpp"

#include <fieldcodec/core/ascii.hpp>

#include <algorithm>
#include <map>
#include <set>

namespace fieldcodec::gen {

namespace {

struct field {
  std::string text;
  int line = 0;
  int col = 0;
};
using row = std::vector<field>;

// RFC 4180 with CRLF or LF. Reports unterminated quotes and text after a closing quote.
bool split_csv(std::string_view text, const std::string &file, diagnostics &diag,
               std::vector<row> &rows) {
  std::size_t i = 0;
  int line = 1;
  int col = 1;
  row current;
  field f;
  f.line = line;
  f.col = col;
  bool row_has_content = false;
  auto end_field = [&] {
    current.push_back(std::move(f));
    f = field{};
  };
  while (i <= text.size()) {
    if (i == text.size()) {
      if (row_has_content || !f.text.empty() || !current.empty()) {
        end_field();
        rows.push_back(std::move(current));
      }
      break;
    }
    const char c = text[i];
    if (f.text.empty() && c == '"' && f.col == col) {
      // quoted field
      const int qline = line;
      const int qcol = col;
      ++i;
      ++col;
      bool closed = false;
      while (i < text.size()) {
        const char q = text[i];
        if (q == '"') {
          if (i + 1U < text.size() && text[i + 1U] == '"') {
            f.text += '"';
            i += 2;
            col += 2;
            continue;
          }
          ++i;
          ++col;
          closed = true;
          break;
        }
        if (q == '\n') {
          ++line;
          col = 1;
        } else if (q != '\r') {
          ++col;
        }
        if (q != '\r') f.text += q;
        ++i;
      }
      if (!closed) {
        diag.error(file, qline, qcol, "expected '\"' to close the quoted field opened here");
        return false;
      }
      row_has_content = true;
      if (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r') {
        diag.error(file, line, col, "expected ',' or end of line after the closing '\"'");
        return false;
      }
      continue;
    }
    if (c == ',') {
      row_has_content = true;
      end_field();
      ++i;
      ++col;
      f.line = line;
      f.col = col;
      continue;
    }
    if (c == '\r' || c == '\n') {
      if (c == '\r' && i + 1U < text.size() && text[i + 1U] == '\n') ++i;
      ++i;
      if (row_has_content || !f.text.empty() || !current.empty()) {
        end_field();
        rows.push_back(std::move(current));
        current.clear();
      }
      row_has_content = false;
      ++line;
      col = 1;
      f.line = line;
      f.col = col;
      continue;
    }
    if (static_cast<unsigned char>(c) < 0x20U && c != '\t') {
      diag.error(file, line, col,
                 "unexpected control character 0x" + hex(static_cast<unsigned char>(c), 2));
      return false;
    }
    f.text += c;
    ++i;
    ++col;
  }
  return true;
}

class csv_reader {
public:
  csv_reader(const std::string &file, diagnostics &diag) : file_(file), diag_(diag) {}

  std::optional<dictionary> read(std::string_view text) {
    if (text.size() >= 3U && text.substr(0, 3) == "\xEF\xBB\xBF") {
      diag_.warning(file_, 1, 1, "byte-order mark ignored (the dialect is UTF-8 without BOM)");
      text.remove_prefix(3);
    }
    bool converted = false;
    const std::string utf8 = to_utf8(text, converted);
    if (converted) diag_.warning(file_, 1, 1, "file is not UTF-8; read as Windows-1252");
    std::vector<row> all;
    if (!split_csv(utf8, file_, diag_, all)) return std::nullopt;
    std::vector<row> rows;
    for (auto &r : all) {
      if (!r.empty() && !r[0].text.empty() && r[0].text.front() == '#') continue;
      if (std::all_of(r.begin(), r.end(), [](const field &f) { return f.text.empty(); })) continue;
      rows.push_back(std::move(r));
    }
    if (rows.empty()) {
      diag_.error(file_, 1, 1, "expected a header row, got an empty table");
      return std::nullopt;
    }
    const row &header = rows.front();
    if (!header_row(header)) return std::nullopt;
    for (std::size_t i = 1; i < rows.size(); ++i) {
      const row &r = rows[i];
      if (r.size() != header.size()) {
        diag_.error(file_, r.front().line, r.back().col,
                    "expected " + std::to_string(header.size()) +
                        " fields as in the header row, got " + std::to_string(r.size()));
      } else if (dict_.is_command_table) {
        command_row(r);
      } else {
        object_row(r);
      }
      if (diag_.too_many()) break;
    }
    if (diag_.has_errors()) return std::nullopt;
    if (dict_.is_command_table) {
      finish_commands();
    } else {
      finish_objects();
    }
    if (diag_.has_errors()) return std::nullopt;
    return std::move(dict_);
  }

private:
  // The header row: the kind of table, known and required columns.
  bool header_row(const row &header) {
    for (std::size_t c = 0; c < header.size(); ++c) {
      const std::string &n = header[c].text;
      if (columns_.count(n) != 0U) {
        diag_.error(file_, header[c].line, header[c].col, "duplicate column '" + n + "'");
        return false;
      }
      columns_[n] = c;
    }
    const bool has_index = columns_.count("index") != 0U;
    const bool has_code = columns_.count("code") != 0U;
    if (has_index == has_code) {
      diag_.error(file_, header[0].line, header[0].col,
                  has_index ? "expected either an 'index' column (object table) or a 'code' column "
                              "(command table), got both"
                            : "expected an 'index' column (object table) or a 'code' column "
                              "(command table) in the header row");
      return false;
    }
    static const std::set<std::string> object_columns{
        "index",       "subindex", "name",   "alt_name",    "symbol",  "object_code",
        "data_type",   "bytes",    "access", "pdo_mapping", "low",     "high",
        "default",     "scale",    "offset", "unit",        "pointer", "acceptance",
        "bus_manager", "section",  "flags",  "remark"};
    static const std::set<std::string> command_columns{
        "code",      "name",          "symbol",        "section",           "title",
        "parameter", "parameter_min", "parameter_max", "parameter_packing", "date_type",
        "date",      "date_min",      "date_max",      "date_packing",      "reply_type",
        "reply",     "modes",         "remark"};
    const auto &known = has_index ? object_columns : command_columns;
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (known.count(header[c].text) == 0U) {
        diag_.warning(file_, header[c].line, header[c].col,
                      "unknown column '" + header[c].text + "' for " +
                          (has_index ? "an object table" : "a command table") + " ignored");
      }
    }
    const std::vector<std::string> required =
        has_index ? std::vector<std::string>{"index", "name", "data_type"}
                  : std::vector<std::string>{"code", "name", "date_type", "reply_type"};
    for (const auto &r : required) {
      if (columns_.count(r) == 0U) {
        diag_.error(file_, header[0].line, header[0].col, "missing required column '" + r + "'");
        return false;
      }
    }
    dict_.is_command_table = has_code;
    return true;
  }

  // Sorts the rows, refuses duplicates, and derives the object-level information from the first
  // row of each index.
  void finish_objects() {
    std::sort(dict_.entries.begin(), dict_.entries.end(), [](const entry &a, const entry &b) {
      return a.index != b.index ? a.index < b.index : a.sub < b.sub;
    });
    for (std::size_t i = 1; i < dict_.entries.size(); ++i) {
      const entry &a = dict_.entries[i - 1U];
      const entry &b = dict_.entries[i];
      if (a.index == b.index && a.sub == b.sub) {
        diag_.error(file_, std::max(a.line, b.line), 1,
                    "duplicate object 0x" + hex(b.index, 4) + " sub-index " +
                        std::to_string(b.sub) + " (also at line " +
                        std::to_string(std::min(a.line, b.line)) + ")");
      }
    }
    for (const auto &e : dict_.entries) {
      auto [it, fresh] = dict_.objects.try_emplace(e.index);
      if (!fresh) {
        if (it->second.code != e.object) {
          diag_.error(file_, e.line, col("object_code"),
                      "object 0x" + hex(e.index, 4) + " has object_code " +
                          std::string(od::name(it->second.code)) + " in an earlier row");
        }
        continue;
      }
      it->second.index = e.index;
      it->second.code = e.object;
      it->second.name = e.name;
      it->second.symbol = e.symbol;
      it->second.line = e.line;
      it->second.list = default_list(e.index);
    }
    for (auto &[index, info] : dict_.objects) {
      std::uint8_t n = 0;
      bool var = true;
      for (const auto &e : dict_.entries) {
        if (e.index == index) {
          ++n;
          if (e.sub != 0U) var = false;
        }
      }
      if (info.code == od::object_code::var && !var) {
        diag_.error(file_, info.line, col("subindex"),
                    "object 0x" + hex(index, 4) + " is a VAR but has sub-index rows other than 0");
      }
      info.sub_number = var ? 0 : n;
    }
    if (!diag_.has_errors()) check_pdo_pairs(dict_, file_, diag_);
  }

  void finish_commands() {
    std::sort(dict_.commands.begin(), dict_.commands.end(),
              [](const command &a, const command &b) { return a.code < b.code; });
    for (std::size_t i = 1; i < dict_.commands.size(); ++i) {
      if (dict_.commands[i - 1U].code == dict_.commands[i].code) {
        diag_.error(file_, std::max(dict_.commands[i].line, dict_.commands[i - 1U].line), 1,
                    "duplicate command code " + hex(dict_.commands[i].code, 4));
      }
    }
  }

  [[nodiscard]] int col(const std::string &name) const {
    auto it = columns_.find(name);
    return it == columns_.end() ? 1 : static_cast<int>(it->second) + 1;
  }
  const field *get(const row &r, const std::string &name) const {
    auto it = columns_.find(name);
    if (it == columns_.end()) return nullptr;
    return &r[it->second];
  }
  std::string text(const row &r, const std::string &name) const {
    const field *f = get(r, name);
    return f == nullptr ? std::string() : f->text;
  }
  // The field of `name` when it is given (a column that is present and not empty).
  const field *given(const row &r, const std::string &name) const {
    const field *f = get(r, name);
    return f == nullptr || f->text.empty() ? nullptr : f;
  }
  void bad(const field &f, const std::string &column, const std::string &what,
           std::size_t pos = 0) {
    diag_.error(file_, f.line, f.col + static_cast<int>(pos), what + " in column '" + column + "'");
  }

  // An integer (decimal or 0x hex; leading zeros are decimal, there is no octal in the dialect).
  bool csv_int(const row &r, const std::string &column, od::number &out, bool &present) {
    present = false;
    const field *f = given(r, column);
    if (f == nullptr) return true;
    if (!int_text(*f, column, f->text, 0, out)) return false;
    present = true;
    return true;
  }
  // `t` is part of the field `f` starting at `offset`.
  bool int_text(const field &f, const std::string &column, std::string_view t, std::size_t offset,
                od::number &out) {
    const bool neg = !t.empty() && t.front() == '-';
    std::string_view digits = neg ? t.substr(1) : t;
    std::size_t skipped = 0;
    if (digits.size() > 1U && digits.front() == '0' && digits[1] != 'x' && digits[1] != 'X') {
      // leading zeros are decimal here: strip them so parse_int does not read octal
      while (digits.size() > 1U && digits.front() == '0') {
        digits.remove_prefix(1);
        ++skipped;
      }
    }
    const std::string s = (neg ? "-" : "") + std::string(digits);
    const int_parse p = parse_int(s);
    if (!p.ok || p.suffix) {
      std::string what = "expected a number, got '" + std::string(t) + "'";
      if (!p.ok) { // quote the text as written, with the leading zeros parse_int did not see
        what = p.error;
        const std::string parsed = "'" + s + "'";
        if (const auto at = what.find(parsed); at != std::string::npos) {
          what.replace(at, parsed.size(), "'" + std::string(t) + "'");
        }
      }
      bad(f, column, what, offset + (p.ok ? 0U : p.error_pos + skipped));
      return false;
    }
    out = p.value;
    return true;
  }
  // A decimal or hex number: exact decimal when it has a '.', integer otherwise.
  bool csv_number(const field &f, const std::string &column, od::number &out) {
    if (f.text.find('.') != std::string::npos) {
      auto d = parse_decimal(f.text);
      if (!d) {
        bad(f, column, "expected a decimal number such as 327.67, got '" + f.text + "'");
        return false;
      }
      out = od::decimal_number(normalize(d.value()));
      return true;
    }
    return int_text(f, column, f.text, 0, out);
  }

  // ---- the columns of an object row --------------------------------------------------------
  void object_row(const row &r) {
    entry e;
    e.line = r.front().line;
    const bool ok = address_columns(r, e) && name_columns(r, e) && object_code_column(r, e) &&
                    data_type_column(r, e) && bytes_column(r, e) && access_column(r, e) &&
                    pdo_mapping_column(r, e) && scale_columns(r, e) && value_columns(r, e) &&
                    pointer_column(r, e) && acceptance_column(r, e) && bus_manager_column(r, e) &&
                    flags_column(r, e);
    if (!ok) return;
    e.unit = text(r, "unit");
    e.section = text(r, "section");
    e.remark = text(r, "remark");
    dict_.entries.push_back(std::move(e));
  }

  bool address_columns(const row &r, entry &e) {
    od::number n;
    bool present = false;
    if (!csv_int(r, "index", n, present)) return false;
    const field &fi = *get(r, "index");
    auto idx = n.to_uint64();
    if (!present || !idx || idx.value() > 0xFFFFU) {
      bad(fi, "index",
          present ? "expected an index 0x0000..0xFFFF, got '" + fi.text + "'"
                  : "expected an index, got nothing");
      return false;
    }
    e.index = static_cast<std::uint16_t>(idx.value());
    if (!csv_int(r, "subindex", n, present)) return false;
    if (present) {
      auto s = n.to_uint64();
      if (!s || s.value() > 255U) {
        bad(*get(r, "subindex"), "subindex",
            "expected a sub-index 0..255, got '" + text(r, "subindex") + "'");
        return false;
      }
      e.sub = static_cast<std::uint8_t>(s.value());
    }
    return true;
  }

  // A field that an EDS export writes as a value: one line (an EDS value cannot hold a line
  // break, so the export could not be read back).
  bool one_line(const field &f, const std::string &column) {
    if (f.text.find_first_of("\r\n") == std::string::npos) return true;
    bad(f, column, "expected one line, got a line break");
    return false;
  }

  bool name_columns(const row &r, entry &e) {
    e.name = text(r, "name");
    if (e.name.empty()) {
      bad(*get(r, "name"), "name", "expected a name, got nothing");
      return false;
    }
    if (!one_line(*get(r, "name"), "name")) return false;
    e.alt_name = text(r, "alt_name");
    e.symbol = text(r, "symbol");
    if (!e.symbol.empty() && !is_identifier(e.symbol)) {
      bad(*get(r, "symbol"), "symbol", "expected a C++ identifier, got '" + e.symbol.str() + "'");
      return false;
    }
    return true;
  }

  bool object_code_column(const row &r, entry &e) {
    const field *f = given(r, "object_code");
    if (f == nullptr) {
      e.object = od::object_code::var;
      return true;
    }
    const od::object_code_info *c = od::find_object_code(std::string_view(f->text));
    if (c == nullptr || c->code == od::object_code::null) {
      bad(*f, "object_code",
          "expected VAR, ARRAY, RECORD, DOMAIN, DEFTYPE or DEFSTRUCT, got '" + f->text + "'");
      return false;
    }
    e.object = c->code;
    return true;
  }

  bool data_type_column(const row &r, entry &e) {
    const std::string dt = text(r, "data_type");
    if (const od::data_type_info *t = od::find_data_type(std::string_view(dt))) {
      e.type = t->type;
      e.type_code = static_cast<std::uint16_t>(t->type);
      return true;
    }
    bad(*get(r, "data_type"), "data_type",
        dt.empty() ? "expected a CiA 301 data type name, got nothing"
                   : "expected a CiA 301 data type name such as UNSIGNED16, got '" + dt + "'");
    return false;
  }

  bool bytes_column(const row &r, entry &e) {
    od::number n;
    bool present = false;
    if (!csv_int(r, "bytes", n, present)) return false;
    if (!present) {
      if (!od::is_byte_string(e.type)) return true;
      bad(*get(r, "data_type"), "bytes",
          "expected a size for " + std::string(od::name(e.type)) + ", got nothing");
      return false;
    }
    auto b = n.to_uint64();
    const std::uint8_t fixed = od::fixed_size(e.type);
    if (!b || b.value() == 0U || b.value() > 0xFFFFFFFFU) {
      bad(*get(r, "bytes"), "bytes", "expected a size in bytes, got '" + text(r, "bytes") + "'");
      return false;
    }
    if (fixed != 0U && b.value() != fixed) {
      bad(*get(r, "bytes"), "bytes",
          "size " + text(r, "bytes") + " disagrees with " + std::string(od::name(e.type)) + " (" +
              std::to_string(fixed) + " bytes)");
      return false;
    }
    if (fixed == 0U) {
      e.size = static_cast<std::uint32_t>(b.value());
      e.size_declared = true;
    }
    return true;
  }

  bool access_column(const row &r, entry &e) {
    const field *f = given(r, "access");
    if (f == nullptr) {
      e.access = od::access::rw;
      return true;
    }
    if (const od::access_info *a = od::find_access(std::string_view(f->text))) {
      e.access = a->value;
      return true;
    }
    bad(*f, "access", "expected ro, wo, rw, rwr, rww or const, got '" + f->text + "'");
    return false;
  }

  bool pdo_mapping_column(const row &r, entry &e) {
    const field *f = given(r, "pdo_mapping");
    if (f == nullptr || od::find_pdo_mapping(f->text, e.pdo)) return true;
    bad(*f, "pdo_mapping", "expected no, yes, rx or tx, got '" + f->text + "'");
    return false;
  }

  bool scale_columns(const row &r, entry &e) {
    if (const field *f = given(r, "scale")) {
      auto d = parse_decimal(f->text);
      if (!d || d.value().mantissa == 0) {
        bad(*f, "scale", "expected a non-zero decimal such as 327.67, got '" + f->text + "'");
        return false;
      }
      e.scale = normalize(d.value());
      e.scaled = true;
    }
    if (const field *f = given(r, "offset")) {
      auto d = parse_decimal(f->text);
      if (!d) {
        bad(*f, "offset", "expected a decimal such as -12.5, got '" + f->text + "'");
        return false;
      }
      e.offset = normalize(d.value());
    }
    return true;
  }

  // low, high, default: numbers of the entry's type ($NODEID expressions, REAL bit patterns in
  // hex), or the bytes of a string / domain default.
  bool value_columns(const row &r, entry &e) {
    if (!number_column(r, "low", e, e.low, e.low_nodeid) ||
        !number_column(r, "high", e, e.high, e.high_nodeid)) {
      return false;
    }
    const field *f = given(r, "default");
    if (f == nullptr) return true;
    if (!od::is_byte_string(e.type)) {
      return number_column(r, "default", e, e.default_value, e.default_nodeid);
    }
    if (!one_line(*f, "default")) return false;
    if (auto bytes = byte_string_value(e.type, f->text)) {
      e.default_text = std::move(*bytes);
    } else {
      diag_.warning(file_, f->line, f->col,
                    "default '" + f->text + "' ignored: " + std::string(od::name(e.type)) +
                        " values are written as hex digits, two per byte");
    }
    if (e.default_text.size() > e.size) {
      bad(*f, "default",
          "the default is " + std::to_string(e.default_text.size()) + " bytes, more than the " +
              std::to_string(e.size) + " of column 'bytes'");
      return false;
    }
    return true;
  }

  bool number_column(const row &r, const std::string &column, const entry &e, od::number &out,
                     bool &nodeid) {
    const field *f = given(r, column);
    if (f == nullptr) return true;
    // limits of a byte string are those of the value it encodes (COMPAX BCD positions)
    if (od::is_byte_string(e.type)) return csv_number(*f, column, out);
    const nodeid_expr x = split_nodeid(f->text);
    if (x.present) {
      if (!x.ok) {
        bad(*f, column, "expected '$NODEID+<number>' or '<number>+$NODEID', got '" + f->text + "'");
        return false;
      }
      if (e.scaled && column != "default") {
        bad(*f, column,
            "a node-ID relative limit of a scaled row (engineering units) is not defined, got '" +
                f->text + "'");
        return false;
      }
      nodeid = true;
      if (x.operand.empty()) {
        out = od::unsigned_number(0);
        return true;
      }
      return int_text(*f, column, x.operand, x.operand_pos, out);
    }
    if (od::is_real(e.type)) {
      const real_parse p = parse_real_value(f->text, e.type);
      if (!p.ok) {
        bad(*f, column, p.error, p.error_pos);
        return false;
      }
      out = od::real_number(p.value);
      return true;
    }
    return csv_number(*f, column, out);
  }

  bool pointer_column(const row &r, entry &e) {
    od::number n;
    bool present = false;
    if (!csv_int(r, "pointer", n, present)) return false;
    if (!present) return true;
    auto p = n.to_uint64();
    if (!p || p.value() > 127U) {
      bad(*get(r, "pointer"), "pointer",
          "expected an index pointer 0..127, got '" + text(r, "pointer") + "'");
      return false;
    }
    e.pointer = static_cast<std::uint8_t>(p.value());
    return true;
  }

  // DPQ "Value acceptance": one of the two texts chapter 4 prints (dpq/columns.hpp).
  bool acceptance_column(const row &r, entry &e) {
    const field *f = given(r, "acceptance");
    if (f == nullptr) return true;
    e.acceptance = dpq::parse_acceptance(f->text);
    if (e.acceptance == dpq::acceptance::unknown) {
      bad(*f, "acceptance",
          "expected 'only with deactivated enabling' or 'also with active enabling', got '" +
              f->text + "'");
      return false;
    }
    return true;
  }

  bool bus_manager_column(const row &r, entry &e) {
    const field *f = given(r, "bus_manager");
    if (f == nullptr) return true;
    e.bus = dpq::parse_bus_manager(f->text);
    if (e.bus == dpq::bus_manager::unspecified) {
      bad(*f, "bus_manager", "expected 'available' or 'not available', got '" + f->text + "'");
      return false;
    }
    return true;
  }

  bool flags_column(const row &r, entry &e) {
    const field *f = given(r, "flags");
    if (f == nullptr) return true;
    std::string_view rest = f->text;
    while (true) {
      const auto semi = rest.find(';');
      const std::string_view word = trim(rest.substr(0, semi));
      if (word == "range_exceeds_field") {
        e.flags |= od::flag::range_exceeds_field;
      } else if (word == "index_anomaly") {
        e.flags |= od::flag::index_anomaly;
      } else if (word == "signedness_guess") {
        e.flags |= od::flag::signedness_guess;
      } else {
        bad(*f, "flags",
            "expected range_exceeds_field, index_anomaly or signedness_guess, got '" +
                std::string(word) + "'");
        return false;
      }
      if (semi == std::string_view::npos) break;
      rest.remove_prefix(semi + 1U);
    }
    return true;
  }

  // ---- command rows -------------------------------------------------------------------------
  bool value_type(const row &r, const std::string &column, od::command_value &out) {
    const std::string t = text(r, column);
    if (t == "none") {
      out = od::command_value::none;
    } else if (t == "integer") {
      out = od::command_value::integer;
    } else if (t == "float" || t == "real") {
      out = od::command_value::real;
    } else {
      bad(*get(r, column), column, "expected none, integer or float, got '" + t + "'");
      return false;
    }
    return true;
  }

  bool packing(const row &r, const std::string &column, od::packing &out) {
    const std::string t = text(r, column);
    if (t.empty() || t == "whole") {
      out = od::packing::whole;
    } else if (t == "byte_byte") {
      out = od::packing::byte_byte;
    } else if (t == "byte_byte_word") {
      out = od::packing::byte_byte_word;
    } else {
      bad(*get(r, column), column, "expected whole, byte_byte or byte_byte_word, got '" + t + "'");
      return false;
    }
    return true;
  }

  // the bounds of a packed parameter or date must be packed values of the packing's width
  bool packed_bounds(const row &r, const std::string &what, od::packing p, const od::number &lo,
                     const od::number &hi) {
    if (p == od::packing::whole) return true;
    const std::uint64_t max = p == od::packing::byte_byte ? 0xFFFFU : 0xFFFF'FFFFU;
    for (const auto &[bound, column] : {std::pair{&lo, what + "_min"}, {&hi, what + "_max"}}) {
      if (!*bound) continue;
      auto v = bound->to_uint64();
      if (!v || v.value() > max) {
        bad(*get(r, column), column,
            "expected a value of " + std::string(od::name(p)) + " packing (0 to " +
                std::to_string(max) + ")");
        return false;
      }
    }
    return true;
  }

  void command_row(const row &r) {
    command c;
    c.line = r.front().line;
    const field &fc = *get(r, "code");
    const auto v = ascii::parse_hex(fc.text, ascii::hex_case::upper);
    if (fc.text.size() != 4U || !v) {
      bad(fc, "code", "expected 4 upper-case hex digits such as 0A87, got '" + fc.text + "'");
      return;
    }
    c.code = static_cast<std::uint16_t>(v.value());
    c.name = text(r, "name");
    if (c.name.empty()) {
      bad(*get(r, "name"), "name", "expected a name, got nothing");
      return;
    }
    c.symbol = text(r, "symbol");
    if (!c.symbol.empty() && !is_identifier(c.symbol)) {
      bad(*get(r, "symbol"), "symbol", "expected a C++ identifier, got '" + c.symbol + "'");
      return;
    }
    c.section = text(r, "section");
    c.title = text(r, "title");
    c.parameter = text(r, "parameter");
    bool present = false;
    if (!csv_int(r, "parameter_min", c.parameter_min, present)) return;
    if (!csv_int(r, "parameter_max", c.parameter_max, present)) return;
    if (!csv_int(r, "date_min", c.date_min, present)) return;
    if (!csv_int(r, "date_max", c.date_max, present)) return;
    if (!packing(r, "parameter_packing", c.parameter_packing) ||
        !packing(r, "date_packing", c.date_packing))
      return;
    if (!value_type(r, "date_type", c.date_type) || !value_type(r, "reply_type", c.reply_type))
      return;
    if (!packed_bounds(r, "parameter", c.parameter_packing, c.parameter_min, c.parameter_max) ||
        !packed_bounds(r, "date", c.date_packing, c.date_min, c.date_max))
      return;
    c.date = text(r, "date");
    c.reply = text(r, "reply");
    c.modes = text(r, "modes");
    c.remark = text(r, "remark");
    dict_.commands.push_back(std::move(c));
  }

  const std::string &file_;
  diagnostics &diag_;
  std::map<std::string, std::size_t> columns_;
  dictionary dict_;
};

} // namespace

std::optional<dictionary> read_csv(std::string_view text, const std::string &file,
                                   diagnostics &diag) {
  csv_reader r(file, diag);
  return r.read(text);
}

} // namespace fieldcodec::gen
