// fieldcodec-gen — CiA 306 EDS/DCF reader, lenient about what real files do.
#include "readers.hpp"
#include "text.hpp"

#include <fieldcodec/od/value.hpp>

#include <algorithm>
#include <deque>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fieldcodec::gen {

namespace {

// Message building with views into the file text.
std::string operator+(std::string a, std::string_view b) { return a.append(b); }
std::string operator+(const char *a, std::string_view b) { return std::string(a).append(b); }

struct ini_key {
  std::string_view name;  // as written (trimmed), points into the reader's text
  std::string upper;      // upper case, for lookup
  std::string_view value; // trimmed
  int line = 0;
  int value_col = 0;
};

struct ini_section {
  std::string name;
  std::string upper;
  int line = 0;
  std::vector<ini_key> keys;

  [[nodiscard]] const ini_key *find(std::string_view upper_key) const {
    for (auto it = keys.rbegin(); it != keys.rend(); ++it) {
      if (it->upper == upper_key) return &*it;
    }
    return nullptr;
  }
};

enum class section_kind { other, object, sub, names, values };

struct classified {
  section_kind kind = section_kind::other;
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
};

bool hex_digits(std::string_view s, std::size_t max, std::uint32_t &v) {
  if (s.empty() || s.size() > max) return false;
  v = 0;
  for (const char c : s) {
    unsigned d = 0;
    if (c >= '0' && c <= '9') {
      d = static_cast<unsigned>(c - '0');
    } else if (c >= 'A' && c <= 'F') {
      d = static_cast<unsigned>(c - 'A' + 10);
    } else {
      return false;
    }
    v = v * 16U + d;
  }
  return true;
}

classified classify(const std::string &upper) {
  classified c;
  std::uint32_t v = 0;
  if (hex_digits(upper, 4, v)) {
    c.kind = section_kind::object;
    c.index = static_cast<std::uint16_t>(v);
    return c;
  }
  const auto sub = upper.find("SUB");
  if (sub != std::string::npos && sub > 0U) {
    std::uint32_t s = 0;
    if (hex_digits(upper.substr(0, sub), 4, v) && hex_digits(upper.substr(sub + 3U), 2, s)) {
      c.kind = section_kind::sub;
      c.index = static_cast<std::uint16_t>(v);
      c.sub = static_cast<std::uint8_t>(s);
      return c;
    }
  }
  for (auto [suffix, kind] : {std::pair{std::string_view("NAME"), section_kind::names},
                              std::pair{std::string_view("VALUE"), section_kind::values}}) {
    if (upper.size() > suffix.size() && upper.ends_with(suffix) &&
        hex_digits(upper.substr(0, upper.size() - suffix.size()), 4, v)) {
      c.kind = kind;
      c.index = static_cast<std::uint16_t>(v);
      return c;
    }
  }
  return c;
}

bool known_ignored_section(const std::string &u) {
  static const std::set<std::string> names{
      "TOOLS",          "TOOLINFOS", "DYNAMICCHANNELS", "SUPPORTEDMODULES", "CONNECTEDMODULES",
      "TYPEDEFINITIONS"};
  if (names.count(u) != 0U) return true;
  if (u.starts_with("TOOL") && u.size() > 4U &&
      std::all_of(u.begin() + 4, u.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return true;
  }
  // modular devices: [M1ModuleInfo], [M1FixedObjects], [M1SubExtends], [M1Comments], ...
  if (u.size() > 1U && u[0] == 'M' && u[1] >= '0' && u[1] <= '9') return true;
  return false;
}

class eds_reader {
public:
  eds_reader(const std::string &file, diagnostics &diag) : file_(file), diag_(diag) {}

  std::optional<dictionary> read(std::string_view bytes) {
    bool converted = false;
    text_ = to_utf8(bytes, converted);
    if (!split(text_)) return std::nullopt;
    if (sections_.empty()) {
      diag_.error(file_, 1, 1, "expected a section such as '[FileInfo]', got an empty file");
      return std::nullopt;
    }
    index_sections();
    dict_.entries.reserve(sections_.size());
    header_sections();
    objects();
    object_lists();
    if (diag_.has_errors()) return std::nullopt;
    std::sort(dict_.entries.begin(), dict_.entries.end(), [](const entry &a, const entry &b) {
      return a.index != b.index ? a.index < b.index : a.sub < b.sub;
    });
    return std::move(dict_);
  }

private:
  // ---- lexing ----------------------------------------------------------------------------
  bool split(const std::string &text) {
    int line_no = 0;
    std::size_t pos = 0;
    ini_section *current = nullptr;
    while (pos < text.size()) {
      std::size_t end = pos;
      while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
      std::string_view line(text.data() + pos, end - pos);
      ++line_no;
      if (end < text.size() && text[end] == '\r' && end + 1U < text.size() &&
          text[end + 1U] == '\n') {
        pos = end + 2U;
      } else {
        pos = end + 1U;
      }
      // binary garbage: stop at the first NUL, report other control characters
      bool bad = false;
      for (std::size_t i = 0; i < line.size(); ++i) {
        const auto c = static_cast<unsigned char>(line[i]);
        if (c < 0x20U && c != '\t') {
          diag_.error(file_, line_no, static_cast<int>(i) + 1,
                      "unexpected control character 0x" + hex(c, 2) +
                          (c == 0U ? " (binary data, not a text file); reading stopped" : ""));
          if (c == 0U) return false;
          bad = true;
          break;
        }
      }
      if (bad) {
        if (diag_.too_many()) return false;
        continue;
      }
      std::size_t lead = 0;
      while (lead < line.size() && (line[lead] == ' ' || line[lead] == '\t')) ++lead;
      const std::string_view t = trim(line);
      if (t.empty() || t.front() == ';' || t.front() == '#') continue;
      if (t.front() == '[') {
        const auto close = t.find(']');
        if (close == std::string_view::npos) {
          diag_.error(file_, line_no, static_cast<int>(lead + t.size()) + 1,
                      "expected ']' to end section name '" + std::string(t.substr(1)) + "'");
          current = nullptr;
          continue;
        }
        const std::string_view rest = trim(t.substr(close + 1U));
        if (!rest.empty() && rest.front() != ';') {
          diag_.warning(file_, line_no, static_cast<int>(lead + close) + 2,
                        "text after ']' ignored");
        }
        const std::string name(trim(t.substr(1, close - 1U)));
        if (name.empty()) {
          diag_.error(file_, line_no, static_cast<int>(lead) + 2, "expected a section name");
          current = nullptr;
          continue;
        }
        sections_.push_back({name, to_upper(name), line_no, {}});
        current = &sections_.back();
        current->keys.reserve(8);
        continue;
      }
      const auto eq = line.find('=');
      if (eq == std::string_view::npos) {
        diag_.error(file_, line_no, static_cast<int>(lead) + 1,
                    "expected 'key=value', got '" + std::string(t) + "'");
        if (diag_.too_many()) return false;
        continue;
      }
      if (current == nullptr) {
        if (sections_.empty()) {
          diag_.error(file_, line_no, static_cast<int>(lead) + 1,
                      "expected a section header such as '[FileInfo]' before the first key");
        }
        // keys of a section whose header was bad: already reported
        if (diag_.too_many()) return false;
        continue;
      }
      const std::string_view key = trim(line.substr(0, eq));
      std::size_t vstart = eq + 1U;
      while (vstart < line.size() && (line[vstart] == ' ' || line[vstart] == '\t')) ++vstart;
      if (key.empty()) {
        diag_.error(file_, line_no, static_cast<int>(lead) + 1, "expected a key before '='");
        continue;
      }
      current->keys.push_back(
          {key, to_upper(key), trim(line.substr(eq + 1U)), line_no, static_cast<int>(vstart) + 1});
    }
    return true;
  }

  void index_sections() {
    for (auto &s : sections_) {
      const classified c = classify(s.upper);
      switch (c.kind) {
      case section_kind::object: {
        auto [it, fresh] = objects_.emplace(c.index, &s);
        if (!fresh) {
          diag_.error(file_, s.line, 2,
                      "duplicate object 0x" + hex(c.index, 4) + " (first defined at line " +
                          std::to_string(it->second->line) + ")");
        }
        break;
      }
      case section_kind::sub: {
        auto [it, fresh] = subs_[c.index].emplace(c.sub, &s);
        if (!fresh) {
          diag_.error(file_, s.line, 2,
                      "duplicate sub-object 0x" + hex(c.index, 4) + " sub-index 0x" +
                          hex(c.sub, 2) + " (first defined at line " +
                          std::to_string(it->second->line) + ")");
        }
        break;
      }
      case section_kind::names: names_[c.index] = &s; break;
      case section_kind::values: values_[c.index] = &s; break;
      case section_kind::other: {
        auto [it, fresh] = others_.emplace(s.upper, &s);
        if (!fresh) {
          // DeviceComissioning spelled both ways is handled later; duplicates of the same name:
          diag_.warning(file_, s.line, 2,
                        "section [" + s.name + "] appears again (first at line " +
                            std::to_string(it->second->line) + "); keys are merged");
          for (auto &k : s.keys) it->second->keys.push_back(k);
        }
        break;
      }
      }
    }
  }

  const ini_section *other(std::string_view upper) const {
    auto it = others_.find(std::string(upper));
    return it == others_.end() ? nullptr : it->second;
  }

  void header_sections() {
    auto copy = [](const ini_section *s, std::vector<std::pair<std::string, std::string>> &out) {
      if (s == nullptr) return;
      for (const auto &k : s->keys) out.emplace_back(k.name, k.value);
    };
    const ini_section *fi = other("FILEINFO");
    const ini_section *di = other("DEVICEINFO");
    if (fi == nullptr) diag_.warning(file_, 1, 1, "missing section [FileInfo]");
    if (di == nullptr) diag_.warning(file_, 1, 1, "missing section [DeviceInfo]");
    copy(fi, dict_.file_info);
    copy(di, dict_.device_info);
    copy(other("DUMMYUSAGE"), dict_.dummy_usage);
    if (const ini_section *c = other("COMMENTS")) {
      for (const auto &k : c->keys) {
        if (k.upper.starts_with("LINE") && k.upper != "LINES") dict_.comments.emplace_back(k.value);
      }
    }
    const ini_section *dc = other("DEVICECOMISSIONING");
    if (dc == nullptr) dc = other("DEVICECOMMISSIONING");
    if (dc != nullptr) {
      dict_.is_dcf = true;
      if (const ini_key *k = dc->find("NODEID"); k != nullptr && !k->value.empty()) {
        const int_parse p = parse_int(k->value);
        auto v = p.value.to_int64();
        if (!p.ok || !v || v.value() < 1 || v.value() > 127) {
          diag_.warning(file_, k->line, k->value_col,
                        "expected a node-ID 1..127, got '" + k->value + "'; ignored");
        } else {
          dict_.node_id = static_cast<int>(v.value());
        }
      }
      if (const ini_key *k = dc->find("NODENAME")) dict_.node_name = k->value;
    }
    for (const auto &[name, s] : others_) {
      static const std::set<std::string> known{
          "FILEINFO",           "DEVICEINFO",      "DUMMYUSAGE",          "COMMENTS",
          "MANDATORYOBJECTS",   "OPTIONALOBJECTS", "MANUFACTUREROBJECTS", "DEVICECOMISSIONING",
          "DEVICECOMMISSIONING"};
      if (known.count(name) == 0U && !known_ignored_section(name)) {
        diag_.warning(file_, s->line, 2, "unknown section [" + s->name + "] ignored");
      }
    }
  }

  // ---- values ----------------------------------------------------------------------------
  void bad_value(const ini_section &s, const ini_key &k, const std::string &what, std::size_t pos) {
    diag_.error(file_, k.line, k.value_col + static_cast<int>(pos),
                what + " in " + k.name + " of [" + s.name + "]");
  }

  // Parses a $NODEID expression or a plain number. Returns false after reporting.
  bool parse_number_value(const ini_section &s, const ini_key &k, od::data_type type,
                          od::number &out, bool &nodeid) {
    const std::string v(k.value);
    nodeid = false;
    const std::string up = to_upper(v);
    const auto at = up.find("$NODEID");
    if (at != std::string::npos) {
      nodeid = true;
      std::string rest = up.substr(0, at) + up.substr(at + 7U);
      std::string compact;
      for (const char c : rest) {
        if (c != ' ' && c != '\t') compact += c;
      }
      std::string operand;
      if (compact.empty()) {
        operand = "0";
      } else if (compact.front() == '+') {
        operand = compact.substr(1);
      } else if (compact.back() == '+') {
        operand = compact.substr(0, compact.size() - 1U);
      } else {
        bad_value(s, k, "expected '$NODEID+<number>' or '<number>+$NODEID', got '" + v + "'", 0);
        return false;
      }
      const int_parse p = parse_int(operand);
      if (!p.ok) {
        bad_value(s, k, p.error, 0);
        return false;
      }
      out = p.value;
      if (od::is_unsigned_integer(type) && out.kind == od::number_kind::signed_ &&
          static_cast<std::int64_t>(out.bits) >= 0) {
        out = od::num::u(out.bits);
      }
      return true;
    }
    if (od::is_time(type) && trim(v).find(' ') != std::string_view::npos) {
      // "<days> <milliseconds>" as lely writes TIME_OF_DAY / TIME_DIFFERENCE
      const std::string_view t = trim(v);
      const auto sp = t.find(' ');
      const int_parse days = parse_int(t.substr(0, sp));
      const int_parse ms = parse_int(t.substr(sp + 1U));
      auto dv = days.value.to_uint64();
      auto mv = ms.value.to_uint64();
      if (!days.ok || !ms.ok || !dv || !mv || dv.value() > 0xFFFFU ||
          mv.value() > od::time_ms_max) {
        bad_value(s, k, "expected '<days 0..65535> <milliseconds 0..268435455>', got '" + v + "'",
                  0);
        return false;
      }
      out = od::to_number(od::time_value{static_cast<std::uint32_t>(mv.value()),
                                         static_cast<std::uint16_t>(dv.value())});
      return true;
    }
    if (od::is_real(type)) {
      if (auto d = parse_real(v)) {
        out = od::num::f(*d);
        return true;
      }
      const int_parse p = parse_int(v);
      if (p.ok) {
        out = od::num::f(p.value.to_double());
        return true;
      }
      bad_value(s, k, "expected a real number, got '" + v + "'", 0);
      return false;
    }
    int_parse p = parse_int(v);
    if (!p.ok) {
      // a decimal fraction for an integer type ("0.0"): keep it exactly, warn
      if (auto d = parse_decimal(trim(v)); d && v.find('.') != std::string::npos) {
        diag_.warning(file_, k.line, k.value_col,
                      "expected an integer, got '" + v + "' in " + k.name + " of [" + s.name + "]");
        out = od::num::d(d.value());
        return true;
      }
      bad_value(s, k, p.error, p.error_pos);
      return false;
    }
    if (p.suffix) {
      diag_.warning(file_, k.line, k.value_col,
                    "C integer suffix in '" + v + "' ignored (" + k.name + " of [" + s.name + "])");
    }
    // a signed type written as its two's complement bit pattern (LowLimit=0x80000000)
    if (od::is_signed_integer(type) && p.value.kind == od::number_kind::unsigned_) {
      const unsigned w = od::fixed_size(type);
      if (p.value.bits <= unsigned_max(w) &&
          p.value.bits > static_cast<std::uint64_t>(signed_max(w))) {
        std::uint64_t b = p.value.bits;
        if (w < 8U) b |= ~detail::width_mask(w);
        p.value = od::num::i(static_cast<std::int64_t>(b));
      } else if (p.value.bits <= static_cast<std::uint64_t>(signed_max(w))) {
        p.value = od::num::i(static_cast<std::int64_t>(p.value.bits));
      }
    }
    if (od::is_integer(type) || type == od::data_type::boolean) {
      if (p.value.kind == od::number_kind::signed_ &&
          static_cast<std::int64_t>(p.value.bits) >= 0 && od::is_unsigned_integer(type)) {
        p.value = od::num::u(p.value.bits);
      }
      if (!fits(type, p.value)) {
        diag_.warning(file_, k.line, k.value_col,
                      "value '" + v + "' does not fit " + std::string(od::name(type)) + " (" +
                          k.name + " of [" + s.name + "])");
      }
    }
    out = p.value;
    return true;
  }

  static bool fits(od::data_type t, od::number n) {
    if (t == od::data_type::boolean) {
      auto u = n.to_uint64();
      return u && u.value() <= 1U;
    }
    const unsigned w = od::fixed_size(t);
    if (od::is_signed_integer(t)) {
      auto i = n.to_int64();
      return i && i.value() >= signed_min(w) && i.value() <= signed_max(w);
    }
    auto u = n.to_uint64();
    return u && u.value() <= unsigned_max(w);
  }

  static std::string unquote(std::string_view v) {
    if (v.size() >= 2U && v.front() == '"' && v.back() == '"')
      return std::string(v.substr(1, v.size() - 2U));
    return std::string(v);
  }

  // Fills `e` from the keys of a VAR-like section. `base` supplies inherited values
  // (CompactSubObj). Returns false when an error was reported.
  bool var_keys(const ini_section &s, entry &e, bool need_type) {
    bool ok = true;
    static const std::set<std::string> known{
        "PARAMETERNAME", "OBJECTTYPE",       "DATATYPE",
        "ACCESSTYPE",    "DEFAULTVALUE",     "PDOMAPPING",
        "LOWLIMIT",      "HIGHLIMIT",        "SUBNUMBER",
        "COMPACTSUBOBJ", "OBJFLAGS",         "PARAMETERVALUE",
        "DENOTATION",    "UPLOADFILE",       "DOWNLOADFILE",
        "COUNT",         "SRDOMAPPING",      "INVERTEDSRAD",
        "PARAMREFD",     "REFUSEREADONSCAN", "REFUSEWRITEONDOWNLOAD"};
    for (const auto &k : s.keys) {
      if (known.count(k.upper) == 0U) {
        diag_.warning(file_, k.line, 1, "unknown key '" + k.name + "' in [" + s.name + "] ignored");
      }
    }
    if (const ini_key *k = s.find("PARAMETERNAME")) {
      e.name = k->value;
    } else {
      diag_.warning(file_, s.line, 2, "missing ParameterName in [" + s.name + "]");
      e.name = s.name;
    }
    if (const ini_key *k = s.find("DATATYPE"); k != nullptr && !k->value.empty()) {
      const int_parse p = parse_int(k->value);
      auto v = p.value.to_uint64();
      if (!p.ok || !v || v.value() == 0U || v.value() > 0xFFFFU) { // 0 is no type (fuzz F6)
        bad_value(s, *k, p.ok ? "expected a data type 0x0001..0xFFFF" : p.error, p.error_pos);
        ok = false;
      } else {
        e.type_code = static_cast<std::uint16_t>(v.value());
        if (od::is_data_type(e.type_code)) {
          e.type = static_cast<od::data_type>(e.type_code);
        } else {
          e.type = od::data_type::domain;
          diag_.warning(file_, k->line, k->value_col,
                        "data type 0x" + hex(e.type_code, 4) + " of [" + s.name +
                            "] is not a basic type (0x0001..0x001B); its value is kept as DOMAIN");
        }
      }
    } else if (need_type) {
      diag_.error(file_, s.line, 2, "missing DataType in [" + s.name + "]");
      ok = false;
    }
    if (const ini_key *k = s.find("ACCESSTYPE"); k != nullptr && !k->value.empty()) {
      const std::string a = to_lower(k->value);
      if (a == "ro") {
        e.access = od::access::ro;
      } else if (a == "wo") {
        e.access = od::access::wo;
      } else if (a == "rw") {
        e.access = od::access::rw;
      } else if (a == "rwr") {
        e.access = od::access::rwr;
      } else if (a == "rww") {
        e.access = od::access::rww;
      } else if (a == "const") {
        e.access = od::access::constant;
      } else {
        bad_value(s, *k, "expected ro, wo, rw, rwr, rww or const, got '" + k->value + "'", 0);
        ok = false;
      }
    } else if (need_type) {
      diag_.warning(file_, s.line, 2, "missing AccessType in [" + s.name + "]; taken as ro");
    }
    if (const ini_key *k = s.find("PDOMAPPING"); k != nullptr && !k->value.empty()) {
      const int_parse p = parse_int(k->value);
      auto v = p.value.to_uint64();
      if (p.ok && v && v.value() <= 1U) {
        e.pdo = v.value() == 1U ? od::pdo_mapping::yes : od::pdo_mapping::no;
      } else {
        bad_value(s, *k, "expected 0 or 1, got '" + k->value + "'", 0);
        ok = false;
      }
    }
    if (const ini_key *k = s.find("OBJFLAGS"); k != nullptr && !k->value.empty()) {
      const int_parse p = parse_int(k->value);
      auto v = p.value.to_uint64();
      if (p.ok && v && v.value() <= 0xFFFFFFFFU) {
        e.obj_flags = static_cast<std::uint32_t>(v.value());
        e.has_obj_flags = true;
      } else {
        bad_value(s, *k, p.ok ? "expected a 32-bit number" : p.error, p.error_pos);
        ok = false;
      }
    }
    const bool numeric = !od::is_byte_string(e.type);
    auto value_key = [&](const char *key, od::number &num, bool &nodeid, std::string &text) {
      const ini_key *k = s.find(key);
      if (k == nullptr || k->value.empty()) return;
      if (numeric) {
        if (!parse_number_value(s, *k, e.type, num, nodeid)) ok = false;
      } else {
        text = e.type == od::data_type::visible_string ? unquote(k->value) : std::string(k->value);
      }
    };
    bool dummy = false;
    std::string dummy_text;
    value_key("DEFAULTVALUE", e.default_value, e.default_nodeid, e.default_text);
    value_key("PARAMETERVALUE", e.parameter_value, e.parameter_nodeid, e.parameter_text);
    value_key("LOWLIMIT", e.low, dummy, dummy_text);
    value_key("HIGHLIMIT", e.high, dummy, dummy_text);
    if (const ini_key *k = s.find("DENOTATION")) e.denotation = k->value;
    if (!e.parameter_text.empty() || e.parameter_value.has_value() || !e.denotation.empty()) dict_.is_dcf = true;
    return ok;
  }

  bool count_key(const ini_section &s, const char *key, std::uint32_t max, std::uint32_t &out,
                 bool &present) {
    present = false;
    const ini_key *k = s.find(key);
    if (k == nullptr || k->value.empty()) return true;
    const int_parse p = parse_int(k->value);
    auto v = p.value.to_uint64();
    if (!p.ok || !v || v.value() > max) {
      bad_value(s, *k,
                p.ok ? "expected a number 0.." + std::to_string(max) + ", got '" + k->value + "'"
                     : p.error,
                p.error_pos);
      return false;
    }
    out = static_cast<std::uint32_t>(v.value());
    present = true;
    return true;
  }

  void objects() {
    for (const auto &[index, subs] : subs_) {
      if (objects_.count(index) == 0U) {
        const ini_section *first = subs.begin()->second;
        diag_.error(file_, first->line, 2,
                    "sub-object section [" + first->name + "] without object section [" +
                        hex(index, 4) + "]");
      }
    }
    for (const auto &[index, s] : objects_) object(index, *s);
  }

  void object(std::uint16_t index, const ini_section &s) {
    object_info info;
    info.index = index;
    info.line = s.line;
    std::uint32_t code = 7;
    bool has_code = false;
    if (!count_key(s, "OBJECTTYPE", 0xFF, code, has_code)) return;
    switch (code) {
    // 0x0 (NULL) is refused like the other undefined codes: it has no data type, so the writer
    // could not write it back readably (fuzz F11).
    case 0x2:
    case 0x5:
    case 0x6:
    case 0x7:
    case 0x8:
    case 0x9: info.code = static_cast<od::object_code>(code); break;
    default: {
      const ini_key *k = s.find("OBJECTTYPE");
      bad_value(s, *k,
                "expected object type 0x2, 0x5, 0x6, 0x7, 0x8 or 0x9, got '" + k->value + "'", 0);
      return;
    }
    }
    if (const ini_key *k = s.find("PARAMETERNAME")) {
      info.name = k->value;
    } else {
      diag_.warning(file_, s.line, 2, "missing ParameterName in [" + s.name + "]");
      info.name = s.name;
    }
    std::uint32_t sub_number = 0;
    std::uint32_t compact = 0;
    bool has_sub_number = false;
    bool has_compact = false;
    if (!count_key(s, "SUBNUMBER", 0xFF, sub_number, has_sub_number)) return;
    if (!count_key(s, "COMPACTSUBOBJ", 0xFE, compact, has_compact)) return;
    if (const ini_key *k = s.find("OBJFLAGS"); k != nullptr && !k->value.empty()) {
      const int_parse p = parse_int(k->value);
      auto v = p.value.to_uint64();
      if (p.ok && v && v.value() <= 0xFFFFFFFFU) {
        info.obj_flags = static_cast<std::uint32_t>(v.value());
        info.has_obj_flags = true;
      }
    }
    const bool composite = info.code == od::object_code::array ||
                           info.code == od::object_code::record ||
                           info.code == od::object_code::defstruct ||
                           (has_sub_number && sub_number > 0U) || (has_compact && compact > 0U);
    auto sub_it = subs_.find(index);
    if (!composite) {
      if (sub_it != subs_.end()) {
        diag_.warning(file_, sub_it->second.begin()->second->line, 2,
                      "sub-object sections of [" + s.name + "] (object type " +
                          std::string(od::name(info.code)) + ", no SubNumber) ignored");
      }
      entry e;
      e.index = index;
      e.object = info.code;
      e.line = s.line;
      if (!var_keys(s, e, true)) return;
      dict_.objects[index] = info;
      dict_.entries.push_back(std::move(e));
      return;
    }
    if (has_compact && compact > 0U) {
      compact_object(index, s, info, compact, sub_it != subs_.end());
      return;
    }
    if (!has_sub_number && sub_it == subs_.end()) {
      // an ARRAY/RECORD written like a VAR (no SubNumber, no sub-sections): keep its one value
      diag_.warning(file_, s.line, 2,
                    "[" + s.name + "] (object type " + std::string(od::name(info.code)) +
                        ") has no SubNumber, CompactSubObj or sub-object sections; read as one "
                        "entry at sub-index 0");
      entry e;
      e.index = index;
      e.object = info.code;
      e.line = s.line;
      if (!var_keys(s, e, true)) return;
      dict_.objects[index] = info;
      dict_.entries.push_back(std::move(e));
      return;
    }
    std::size_t count = 0;
    if (sub_it != subs_.end()) {
      for (const auto &[sub, ss] : sub_it->second) {
        ++count;
        if (has_sub_number && count == sub_number + 1U) {
          diag_.warning(file_, ss->line, 2,
                        "sub-index 0x" + hex(sub, 2) + " of [" + ss->name +
                            "] is sub-object number " + std::to_string(count) + " but [" + s.name +
                            "] has SubNumber=" + std::to_string(sub_number) +
                            " (SubNumber counts sub-objects); all " +
                            std::to_string(sub_it->second.size()) + " are kept");
        }
        entry e;
        e.index = index;
        e.sub = sub;
        e.object = info.code;
        e.line = ss->line;
        if (!var_keys(*ss, e, true)) continue;
        dict_.entries.push_back(std::move(e));
      }
    }
    if (!has_sub_number) {
      diag_.warning(file_, s.line, 2,
                    "missing SubNumber in [" + s.name + "]; " + std::to_string(count) +
                        " sub-object sections found");
    } else if (count < sub_number) {
      const ini_key *k = s.find("SUBNUMBER");
      diag_.warning(file_, k->line, k->value_col,
                    "[" + s.name + "] has SubNumber=" + std::to_string(sub_number) + " but " +
                        std::to_string(count) + " sub-object section" + (count == 1U ? "" : "s"));
    }
    info.sub_number = static_cast<std::uint8_t>(count);
    dict_.objects[index] = info;
  }

  void compact_object(std::uint16_t index, const ini_section &s, object_info info,
                      std::uint32_t compact, bool has_subs) {
    if (has_subs) {
      diag_.warning(file_, subs_[index].begin()->second->line, 2,
                    "[" + s.name + "] has CompactSubObj; its sub-object sections are ignored");
    }
    info.compact_sub = static_cast<std::uint8_t>(compact);
    info.sub_number = static_cast<std::uint8_t>(compact + 1U);
    entry proto;
    proto.index = index;
    proto.object = info.code;
    proto.line = s.line;
    if (!var_keys(s, proto, true)) return;
    entry sub0;
    sub0.index = index;
    sub0.object = info.code;
    sub0.line = s.line;
    sub0.name = "NrOfObjects";
    sub0.type_code = 0x0005;
    sub0.type = od::data_type::unsigned8;
    sub0.access = od::access::ro;
    sub0.default_value = od::num::u(compact);
    std::map<std::uint32_t, std::string> names;
    std::map<std::uint32_t, const ini_key *> values;
    if (auto it = names_.find(index); it != names_.end()) {
      for (const auto &k : it->second->keys) {
        if (k.upper == "NROFENTRIES") continue;
        const int_parse p = parse_int(k.name);
        auto v = p.value.to_uint64();
        if (!p.ok || !v || v.value() < 1U || v.value() > compact) {
          diag_.warning(file_, k.line, 1,
                        "key '" + k.name + "' in [" + it->second->name +
                            "] is not a sub-index 1.." + std::to_string(compact) + "; ignored");
          continue;
        }
        names[static_cast<std::uint32_t>(v.value())] = k.value;
      }
    }
    if (auto it = values_.find(index); it != values_.end()) {
      dict_.is_dcf = true;
      for (const auto &k : it->second->keys) {
        if (k.upper == "NROFENTRIES") continue;
        const int_parse p = parse_int(k.name);
        auto v = p.value.to_uint64();
        if (!p.ok || !v || v.value() < 1U || v.value() > compact) {
          diag_.warning(file_, k.line, 1,
                        "key '" + k.name + "' in [" + it->second->name +
                            "] is not a sub-index 1.." + std::to_string(compact) + "; ignored");
          continue;
        }
        values[static_cast<std::uint32_t>(v.value())] = &k;
      }
    }
    dict_.entries.push_back(sub0);
    for (std::uint32_t i = 1; i <= compact; ++i) {
      entry e = proto;
      e.sub = static_cast<std::uint8_t>(i);
      e.parameter_value = {};
      e.parameter_nodeid = false;
      e.parameter_text.clear();
      e.denotation.clear();
      auto n = names.find(i);
      e.name = n != names.end() ? n->second : proto.name + std::to_string(i);
      if (auto v = values.find(i); v != values.end()) {
        const ini_section &vs = *values_.find(index)->second;
        if (od::is_byte_string(e.type)) {
          e.parameter_text = v->second->value;
        } else if (!v->second->value.empty()) {
          parse_number_value(vs, *v->second, e.type, e.parameter_value, e.parameter_nodeid);
        }
      }
      dict_.entries.push_back(std::move(e));
    }
    dict_.objects[index] = info;
  }

  void object_lists() {
    const std::pair<const char *, object_list> lists[] = {
        {"MANDATORYOBJECTS", object_list::mandatory},
        {"OPTIONALOBJECTS", object_list::optional},
        {"MANUFACTUREROBJECTS", object_list::manufacturer}};
    std::set<std::uint16_t> listed;
    bool any_list = false;
    for (const auto &[name, which] : lists) {
      const ini_section *s = other(name);
      if (s == nullptr) continue;
      any_list = true;
      for (const auto &k : s->keys) {
        if (k.upper == "SUPPORTEDOBJECTS") continue;
        const int_parse p = parse_int(k.value);
        auto v = p.value.to_uint64();
        if (!p.ok || !v || v.value() > 0xFFFFU) {
          bad_value(*s, k, p.ok ? "expected an object index 0x0000..0xFFFF" : p.error, p.error_pos);
          continue;
        }
        const auto index = static_cast<std::uint16_t>(v.value());
        listed.insert(index);
        auto obj = objects_.find(index);
        if (obj == objects_.end()) {
          diag_.warning(file_, k.line, k.value_col,
                        "object 0x" + hex(index, 4) + " listed in [" + s->name +
                            "] has no section [" + hex(index, 4) + "]");
          continue;
        }
        if (auto it = dict_.objects.find(index); it != dict_.objects.end()) it->second.list = which;
      }
    }
    if (!any_list) {
      diag_.warning(file_, 1, 1, "missing section [MandatoryObjects]");
      return;
    }
    for (const auto &[index, s] : objects_) {
      if (listed.count(index) == 0U && index >= 0x1000U) {
        diag_.warning(file_, s->line, 2,
                      "object [" + s->name +
                          "] is not listed in [MandatoryObjects], "
                          "[OptionalObjects] or [ManufacturerObjects]");
        if (auto it = dict_.objects.find(index); it != dict_.objects.end()) {
          it->second.list = default_list(index);
        }
      }
    }
  }

  const std::string &file_;
  diagnostics &diag_;
  std::string text_;                 // the file as UTF-8; keys and values are views into it
  std::deque<ini_section> sections_; // deque: pointers stay valid
  std::map<std::uint16_t, const ini_section *> objects_;
  std::map<std::uint16_t, std::map<std::uint8_t, const ini_section *>> subs_;
  std::map<std::uint16_t, const ini_section *> names_, values_;
  std::map<std::string, ini_section *> others_;
  dictionary dict_;
};

} // namespace

std::optional<dictionary> read_eds(std::string_view text, const std::string &file,
                                   diagnostics &diag) {
  eds_reader r(file, diag);
  return r.read(text);
}

} // namespace fieldcodec::gen
