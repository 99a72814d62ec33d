// fieldcodec-gen — CSV object and command tables (docs/dictionary-formats.md).
#include "readers.hpp"
#include "text.hpp"

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
    for (std::size_t c = 0; c < header.size(); ++c) {
      const std::string &n = header[c].text;
      if (columns_.count(n) != 0U) {
        diag_.error(file_, header[c].line, header[c].col, "duplicate column '" + n + "'");
        return std::nullopt;
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
      return std::nullopt;
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
        return std::nullopt;
      }
    }
    dict_.is_command_table = has_code;
    for (std::size_t i = 1; i < rows.size(); ++i) {
      const row &r = rows[i];
      if (r.size() != header.size()) {
        diag_.error(file_, r.front().line, r.back().col,
                    "expected " + std::to_string(header.size()) +
                        " fields as in the header row, got " + std::to_string(r.size()));
        continue;
      }
      if (has_index) {
        object_row(r);
      } else {
        command_row(r);
      }
      if (diag_.too_many()) break;
    }
    if (diag_.has_errors()) return std::nullopt;
    if (has_index) {
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
      // object-level info from the first row of each index
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
        it->second.list = e.index >= 0x2000U && e.index < 0x6000U ? 2 : 1;
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
                      "object 0x" + hex(index, 4) +
                          " is a VAR but has sub-index rows other than 0");
        }
        info.sub_number = var ? 0 : n;
      }
    } else {
      std::sort(dict_.commands.begin(), dict_.commands.end(),
                [](const command &a, const command &b) { return a.code < b.code; });
      for (std::size_t i = 1; i < dict_.commands.size(); ++i) {
        if (dict_.commands[i - 1U].code == dict_.commands[i].code) {
          diag_.error(file_, std::max(dict_.commands[i].line, dict_.commands[i - 1U].line), 1,
                      "duplicate command code " + hex(dict_.commands[i].code, 4));
        }
      }
    }
    if (diag_.has_errors()) return std::nullopt;
    return std::move(dict_);
  }

private:
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
  void bad(const field &f, const std::string &column, const std::string &what) {
    diag_.error(file_, f.line, f.col, what + " in column '" + column + "'");
  }

  // integer (decimal or 0x hex, no octal in the CSV dialect)
  bool csv_int(const row &r, const std::string &column, od::number &out, bool &present) {
    present = false;
    const field *f = get(r, column);
    if (f == nullptr || f->text.empty()) return true;
    std::string_view t = f->text;
    const bool neg = !t.empty() && t.front() == '-';
    std::string_view digits = neg ? t.substr(1) : t;
    if (digits.size() > 1U && digits.front() == '0' && digits[1] != 'x' && digits[1] != 'X') {
      // leading zeros are decimal here: strip them so parse_int does not read octal
      while (digits.size() > 1U && digits.front() == '0') digits.remove_prefix(1);
      const std::string s = (neg ? "-" : "") + std::string(digits);
      return csv_int_text(*f, column, s, out, present);
    }
    return csv_int_text(*f, column, std::string(t), out, present);
  }
  bool csv_int_text(const field &f, const std::string &column, const std::string &t,
                    od::number &out, bool &present) {
    const int_parse p = parse_int(t);
    if (!p.ok || p.suffix) {
      diag_.error(file_, f.line, f.col + static_cast<int>(p.error_pos),
                  (p.ok ? "expected a number, got '" + t + "'" : p.error) + " in column '" +
                      column + "'");
      return false;
    }
    out = p.value;
    present = true;
    return true;
  }
  // a decimal or hex number: exact decimal when it has a '.', integer otherwise
  bool csv_number(const row &r, const std::string &column, od::number &out) {
    const field *f = get(r, column);
    if (f == nullptr || f->text.empty()) return true;
    if (f->text.find('.') != std::string::npos) {
      auto d = parse_decimal(f->text);
      if (!d) {
        bad(*f, column, "expected a decimal number such as 327.67, got '" + f->text + "'");
        return false;
      }
      out = od::num::d(normalize(d.value()));
      return true;
    }
    bool present = false;
    return csv_int(r, column, out, present);
  }

  void object_row(const row &r) {
    entry e;
    e.line = r.front().line;
    od::number n;
    bool present = false;
    if (!csv_int(r, "index", n, present)) return;
    const field &fi = *get(r, "index");
    auto idx = n.to_uint64();
    if (!present || !idx || idx.value() > 0xFFFFU) {
      bad(fi, "index",
          present ? "expected an index 0x0000..0xFFFF, got '" + fi.text + "'"
                  : "expected an index, got nothing");
      return;
    }
    e.index = static_cast<std::uint16_t>(idx.value());
    if (!csv_int(r, "subindex", n, present)) return;
    if (present) {
      auto s = n.to_uint64();
      if (!s || s.value() > 255U) {
        bad(*get(r, "subindex"), "subindex",
            "expected a sub-index 0..255, got '" + text(r, "subindex") + "'");
        return;
      }
      e.sub = static_cast<std::uint8_t>(s.value());
    }
    e.name = text(r, "name");
    if (e.name.empty()) {
      bad(*get(r, "name"), "name", "expected a name, got nothing");
      return;
    }
    e.alt_name = text(r, "alt_name");
    e.symbol = text(r, "symbol");
    if (!e.symbol.empty() && !is_identifier(e.symbol)) {
      bad(*get(r, "symbol"), "symbol", "expected a C++ identifier, got '" + e.symbol + "'");
      return;
    }
    if (const std::string oc = text(r, "object_code"); !oc.empty()) {
      static const std::map<std::string, od::object_code> codes{
          {"VAR", od::object_code::var},         {"ARRAY", od::object_code::array},
          {"RECORD", od::object_code::record},   {"DOMAIN", od::object_code::domain},
          {"DEFTYPE", od::object_code::deftype}, {"DEFSTRUCT", od::object_code::defstruct}};
      auto it = codes.find(oc);
      if (it == codes.end()) {
        bad(*get(r, "object_code"), "object_code",
            "expected VAR, ARRAY, RECORD, DOMAIN, DEFTYPE or DEFSTRUCT, got '" + oc + "'");
        return;
      }
      e.object = it->second;
    } else {
      e.object = od::object_code::var;
    }
    {
      const std::string dt = text(r, "data_type");
      bool found = false;
      for (std::uint16_t c = 1; c <= 0x1BU; ++c) {
        if (od::is_data_type(c) && od::name(static_cast<od::data_type>(c)) == dt) {
          e.type = static_cast<od::data_type>(c);
          e.type_code = c;
          found = true;
        }
      }
      if (!found) {
        bad(*get(r, "data_type"), "data_type",
            dt.empty() ? "expected a CiA 301 data type name, got nothing"
                       : "expected a CiA 301 data type name such as UNSIGNED16, got '" + dt + "'");
        return;
      }
    }
    if (!csv_int(r, "bytes", n, present)) return;
    if (present) {
      auto b = n.to_uint64();
      const std::uint8_t fixed = od::fixed_size(e.type);
      if (!b || b.value() == 0U || b.value() > 0xFFFFFFFFU) {
        bad(*get(r, "bytes"), "bytes", "expected a size in bytes, got '" + text(r, "bytes") + "'");
        return;
      }
      if (fixed != 0U && b.value() != fixed) {
        bad(*get(r, "bytes"), "bytes",
            "size " + text(r, "bytes") + " disagrees with " + std::string(od::name(e.type)) + " (" +
                std::to_string(fixed) + " bytes)");
        return;
      }
      if (fixed == 0U) e.size = static_cast<std::uint32_t>(b.value());
    } else if (od::is_byte_string(e.type)) {
      bad(*get(r, "data_type"), "bytes",
          "expected a size for " + std::string(od::name(e.type)) + ", got nothing");
      return;
    }
    if (const std::string a = text(r, "access"); !a.empty()) {
      static const std::map<std::string, od::access> acc{
          {"ro", od::access::ro},   {"wo", od::access::wo},   {"rw", od::access::rw},
          {"rwr", od::access::rwr}, {"rww", od::access::rww}, {"const", od::access::constant}};
      auto it = acc.find(a);
      if (it == acc.end()) {
        bad(*get(r, "access"), "access", "expected ro, wo, rw, rwr, rww or const, got '" + a + "'");
        return;
      }
      e.access = it->second;
    } else {
      e.access = od::access::rw;
    }
    if (const std::string p = text(r, "pdo_mapping"); !p.empty()) {
      static const std::map<std::string, od::pdo_mapping> map{{"no", od::pdo_mapping::no},
                                                              {"yes", od::pdo_mapping::yes},
                                                              {"rx", od::pdo_mapping::rx},
                                                              {"tx", od::pdo_mapping::tx}};
      auto it = map.find(p);
      if (it == map.end()) {
        bad(*get(r, "pdo_mapping"), "pdo_mapping", "expected no, yes, rx or tx, got '" + p + "'");
        return;
      }
      e.pdo = it->second;
    }
    if (const field *f = get(r, "scale"); f != nullptr && !f->text.empty()) {
      auto d = parse_decimal(f->text);
      if (!d || d.value().mantissa == 0) {
        bad(*f, "scale", "expected a non-zero decimal such as 327.67, got '" + f->text + "'");
        return;
      }
      e.scale = normalize(d.value());
      e.scaled = true;
    }
    if (const field *f = get(r, "offset"); f != nullptr && !f->text.empty()) {
      auto d = parse_decimal(f->text);
      if (!d) {
        bad(*f, "offset", "expected a decimal such as -12.5, got '" + f->text + "'");
        return;
      }
      e.offset = normalize(d.value());
    }
    if (!csv_number(r, "low", e.low) || !csv_number(r, "high", e.high)) return;
    if (const field *f = get(r, "default"); f != nullptr && !f->text.empty()) {
      if (od::is_byte_string(e.type)) {
        e.def_text = f->text;
      } else {
        const std::string up = to_upper(f->text);
        if (up.starts_with("$NODEID")) {
          std::string rest = f->text.substr(7);
          std::string_view t = trim(rest);
          e.def_nodeid = true;
          if (t.empty()) {
            e.def = od::num::u(0);
          } else if (t.front() == '+') {
            const int_parse p = parse_int(t.substr(1));
            if (!p.ok) {
              bad(*f, "default", p.error);
              return;
            }
            e.def = p.value;
          } else {
            bad(*f, "default", "expected '$NODEID+<number>', got '" + f->text + "'");
            return;
          }
        } else if (od::is_real(e.type)) {
          auto d = parse_real(f->text);
          if (!d) {
            bad(*f, "default", "expected a real number, got '" + f->text + "'");
            return;
          }
          e.def = od::num::f(*d);
        } else if (!csv_number(r, "default", e.def)) {
          return;
        }
      }
    }
    e.unit = text(r, "unit");
    if (!csv_int(r, "pointer", n, present)) return;
    if (present) {
      auto p = n.to_uint64();
      if (!p || p.value() > 127U) {
        bad(*get(r, "pointer"), "pointer",
            "expected an index pointer 0..127, got '" + text(r, "pointer") + "'");
        return;
      }
      e.pointer = static_cast<std::uint8_t>(p.value());
    }
    e.acceptance = text(r, "acceptance");
    if (const std::string b = text(r, "bus_manager"); !b.empty()) {
      if (b == "available") {
        e.bus = od::bus_manager::available;
      } else if (b == "not available") {
        e.bus = od::bus_manager::not_available;
      } else {
        bad(*get(r, "bus_manager"), "bus_manager",
            "expected 'available' or 'not available', got '" + b + "'");
        return;
      }
    }
    e.section = text(r, "section");
    if (const std::string fl = text(r, "flags"); !fl.empty()) {
      std::string_view rest = fl;
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
          bad(*get(r, "flags"), "flags",
              "expected range_exceeds_field, index_anomaly or signedness_guess, got '" +
                  std::string(word) + "'");
          return;
        }
        if (semi == std::string_view::npos) break;
        rest.remove_prefix(semi + 1U);
      }
    }
    e.remark = text(r, "remark");
    dict_.entries.push_back(std::move(e));
  }

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
    std::uint32_t v = 0;
    bool ok = fc.text.size() == 4U;
    for (const char ch : fc.text) {
      if (ch >= '0' && ch <= '9') {
        v = v * 16U + static_cast<std::uint32_t>(ch - '0');
      } else if (ch >= 'A' && ch <= 'F') {
        v = v * 16U + static_cast<std::uint32_t>(ch - 'A' + 10);
      } else {
        ok = false;
      }
    }
    if (!ok) {
      bad(fc, "code", "expected 4 upper-case hex digits such as 0A87, got '" + fc.text + "'");
      return;
    }
    c.code = static_cast<std::uint16_t>(v);
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
