// The C++ header emitter as it was before issue 18's second round (codegen/src/emit_header.cpp
// at 81837bf), verbatim but for the namespace and `inline`: the reference of
// emit_speed_test.cpp, which compares the emitter that writes through a pointer with it. Issue 27
// changed what an entry row holds (the lean od::entry: flags and its columns packed by od::pack
// as a string literal) and added the `kinds` line: emit_core, append_flags, the includes and
// emit_kinds below write that, in the same plain std::string style.
#pragma once

#include "readers.hpp"
#include "text.hpp"

#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/value_kinds.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <limits>
#include <map>
#include <string>
#include <unordered_set>
#include <vector>

namespace emit_reference {

using namespace fieldcodec;
using gen::dictionary;
using gen::entry;
using gen::hex;
using gen::is_cpp_keyword;
using gen::make_identifier;
using gen::object_info;
using gen::to_lower;

// append_cpp_string and append_cpp_value_text before the emitter's pointer writers, verbatim but
// for the names (make_identifier, is_cpp_keyword and hex are compared with their own references
// in reader_speed_test.cpp and kept from fieldcodec-gen).
inline void append_cpp_string(std::string &out, std::string_view s) {
  out.reserve(out.size() + s.size() + 2U);
  out += '"';
  std::size_t run = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20U && c != 0x7FU && c != '"' && c != '\\' && c != '?') continue;
    out.append(s.data() + run, i - run);
    run = i + 1U;
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '?') {
      if (i + 1U < s.size() && s[i + 1U] == '?') {
        out += "?\\"; // never a trigraph
      } else {
        out += '?';
      }
    } else {
      constexpr char digits[] = "01234567";
      out += '\\';
      out += digits[(c >> 6U) & 7U];
      out += digits[(c >> 3U) & 7U];
      out += digits[c & 7U];
    }
  }
  out.append(s.data() + run, s.size() - run);
  out += '"';
}
inline std::string cpp_string(std::string_view s) {
  std::string out;
  append_cpp_string(out, s);
  return out;
}
inline void append_cpp_value_text(std::string &out, od::data_type type, std::string_view bytes) {
  if (type == od::data_type::visible_string) {
    append_cpp_string(out, bytes);
    return;
  }
  out += "std::string_view{\"";
  for (const char ch : bytes) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20U && c < 0x7FU && c != '"' && c != '\\' && c != '?') {
      out += static_cast<char>(c);
    } else {
      constexpr char digits[] = "01234567";
      out += '\\';
      out += digits[(c >> 6U) & 7U];
      out += digits[(c >> 3U) & 7U];
      out += digits[c & 7U];
    }
  }
  out += "\", " + std::to_string(bytes.size()) + "}";
}

// Appenders that write straight into the header (no temporary strings: the emitter runs once
// per entry and table).
template <class Int>
inline void append_int(std::string &o, Int v) {
  std::array<char, 24> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  o.append(buf.data(), r.ptr);
}
/// Upper-case hex with at least `digits` digits.
inline void append_hex(std::string &o, std::uint64_t v, int digits) {
  std::array<char, 16> buf{};
  int n = 0;
  while (v != 0U || n < digits) {
    buf[static_cast<std::size_t>(15 - n)] = "0123456789ABCDEF"[v & 0xFU];
    v >>= 4U;
    ++n;
  }
  o.append(buf.data() + 16 - n, static_cast<std::size_t>(n));
}

inline void append_number(std::string &o, const od::number &n) {
  switch (n.kind) {
  case od::number_kind::none: o += "{}"; return;
  case od::number_kind::signed_: {
    const auto v = static_cast<std::int64_t>(n.bits);
    if (v == std::numeric_limits<std::int64_t>::min()) {
      o += "od::signed_number(-9223372036854775807 - 1)";
      return;
    }
    o += "od::signed_number(";
    append_int(o, v);
    o += ')';
    return;
  }
  case od::number_kind::unsigned_:
    o += "od::unsigned_number(";
    append_int(o, n.bits);
    o += "U)";
    return;
  case od::number_kind::real: {
    std::array<char, 64> buf{};
    const double d = n.to_double();
    auto [p, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), d);
    std::string_view t(buf.data(), static_cast<std::size_t>(p - buf.data()));
    o += "od::real_number(";
    o += t;
    if (t.find_first_of(".e") == std::string_view::npos) o += ".0";
    o += ')';
    return;
  }
  case od::number_kind::decimal_:
    o += "od::decimal_number(";
    append_int(o, static_cast<std::int64_t>(n.bits));
    o += ", ";
    append_int(o, n.places);
    o += ')';
    return;
  }
  o += "{}";
}
inline std::string number_literal(const od::number &n) {
  std::string o;
  append_number(o, n);
  return o;
}

inline std::string lower_hex(std::uint64_t v, int digits) { return to_lower(hex(v, digits)); }

// The enumerators' C++ names come from od/data_type.hpp's tables (od::info(…).identifier: one
// table per idea, shared by the readers, the EDS writer and this emitter).

/// Assigns unique identifiers in a deterministic order.
class symbols {
public:
  symbols() {
    for (const char *r : {"entries", "infos", "scales", "dictionary", "kinds", "commands", "table",
                          "od", "std", "fieldcodec", "scaling", "node_id", "source_file", "detail",
                          "dpq", "compax", "dpq_columns", "compax_columns"}) {
      used_.insert(r);
    }
  }
  // (a hash set: one look-up per generated name, the order of names plays no part)
  /// `wanted` if free, else wanted_<suffix>, else wanted_<suffix>_2, _3, ...
  std::string take(std::string wanted, const std::string &suffix) {
    if (wanted.empty()) wanted = "object_" + suffix;
    if (is_cpp_keyword(wanted)) wanted += '_';
    if (used_.insert(wanted).second) return wanted;
    std::string s = join(wanted, suffix);
    for (int n = 2; !used_.insert(s).second; ++n)
      s = join(wanted, suffix) + "_" + std::to_string(n);
    return s;
  }
  /// name + '_' + part, one '_' only after a name that ends in '_' (fix of F19 in
  /// fuzz/FINDINGS.md, applied to this reference too: a name with "__" is reserved).
  static std::string join(const std::string &name, const std::string &part) {
    return !name.empty() && name.back() == '_' ? name + part : name + "_" + part;
  }

private:
  std::unordered_set<std::string> used_;
};

/// A std::string_view literal, `"text"sv`: its length is known without the compiler counting
/// the characters in constant evaluation, and there is no constructor overload to resolve (both
/// are a measurable part of compiling a big dictionary). Embedded NULs are kept.
inline void append_view(std::string &o, const std::string &v) {
  append_cpp_string(o, v);
  o += "sv";
}

/// An od::text column, `{"text", N}`: od::text's (pointer, length) constructor, the length
/// written out (no counting in constant evaluation). A VISIBLE_STRING (and every descriptive
/// column) as its text, other bytes (OCTET_STRING, UNICODE_STRING, DOMAIN) with every byte
/// escaped. Embedded NULs are kept.
inline void append_text(std::string &o, od::data_type type, const std::string &bytes) {
  if (type == od::data_type::visible_string) {
    o += '{';
    append_cpp_string(o, bytes);
    o += ", ";
    append_int(o, bytes.size());
    o += '}';
    return;
  }
  // append_cpp_value_text writes `std::string_view{"…", n}`: keep the braces
  const std::size_t at = o.size();
  append_cpp_value_text(o, type, bytes);
  constexpr std::string_view prefix = "std::string_view";
  if (o.compare(at, prefix.size(), prefix) == 0) o.erase(at, prefix.size());
}
inline void append_text(std::string &o, const std::string &v) {
  append_text(o, od::data_type::visible_string, v);
}

/// The entry as od::pack takes it.
inline od::entry_spec spec_of(const entry &e) {
  od::entry_spec s;
  s.index = e.index;
  s.sub = e.sub;
  s.object = e.object;
  s.type = e.type;
  s.access_type = e.access;
  s.pdo = e.pdo;
  std::uint16_t f = e.flags;
  if (e.scaled) f |= od::flag::scaled;
  if (e.default_nodeid) f |= od::flag::default_nodeid;
  if (e.low_nodeid) f |= od::flag::low_nodeid;
  if (e.high_nodeid) f |= od::flag::high_nodeid;
  if (e.parameter_nodeid) f |= od::flag::parameter_nodeid;
  s.flags = f;
  s.size = e.size;
  s.low = e.low;
  s.high = e.high;
  s.default_value = e.default_value;
  s.default_text = std::string_view(e.default_text);
  return s;
}

/// The od::flag bits of an entry, as a C++ expression ("" when none).
inline void append_flags(std::string &o, std::uint16_t f) {
  const std::pair<std::uint16_t, const char *> bits[] = {
      {od::flag::range_exceeds_field, "range_exceeds_field"},
      {od::flag::index_anomaly, "index_anomaly"},
      {od::flag::signedness_guess, "signedness_guess"},
      {od::flag::scaled, "scaled"},
      {od::flag::default_nodeid, "default_nodeid"},
      {od::flag::low_nodeid, "low_nodeid"},
      {od::flag::high_nodeid, "high_nodeid"},
      {od::flag::parameter_nodeid, "parameter_nodeid"},
      {od::flag::has_size, "has_size"},
      {od::flag::has_default, "has_default"},
      {od::flag::default_number, "default_number"},
      {od::flag::has_low, "has_low"},
      {od::flag::has_high, "has_high"},
      {od::flag::limits_number, "limits_number"},
      {od::flag::has_text, "has_text"},
  };
  bool first = true;
  for (const auto &[bit, name] : bits) {
    if ((f & bit) == 0U) continue;
    o += first ? ", .flags = od::flag::" : " | od::flag::";
    o += name;
    first = false;
  }
}

/// `{...}` initialising the od::entry part.
inline void emit_core(std::string &o, const entry &e) {
  const od::entry_spec spec = emit_reference::spec_of(e);
  o += "{.index = 0x";
  append_hex(o, e.index, 4);
  if (e.sub != 0U) {
    o += ", .sub = ";
    append_int(o, e.sub);
  }
  if (e.object != od::object_code::var) {
    o += ", .object = od::object_code::";
    o += od::info(e.object).identifier;
  }
  o += ", .type = od::data_type::";
  o += od::info(e.type).identifier;
  if (e.access != od::access::rw) {
    o += ", .access_type = od::access::";
    o += od::info(e.access).identifier;
  }
  if (e.pdo != od::pdo_mapping::no) {
    o += ", .pdo = od::pdo_mapping::";
    o += od::name(e.pdo);
  }
  append_flags(o, od::make_entry(spec, nullptr).flags);
  std::string bytes(od::packed_size(spec), '\0');
  if (!bytes.empty()) {
    (void)od::pack(spec, std::span<char>(bytes.data(), bytes.size()));
    o += ", .extra = ";
    const std::size_t at = o.size();
    append_cpp_value_text(o, od::data_type::octet_string, bytes); // std::string_view{"…", n}
    o.erase(at, std::string_view("std::string_view{").size());
    o.erase(o.rfind(','));
  }
  o += '}';
}

/// The `kinds` line: what od::kinds_of finds in the entries.
inline void emit_kinds(std::string &o, const dictionary &d) {
  std::vector<od::entry> lean;
  for (const entry &e : d.entries)
    lean.push_back(od::make_entry(emit_reference::spec_of(e), nullptr));
  const od::value_kinds k = od::kinds_of(lean);
  auto b = [](bool v) { return v ? "true" : "false"; };
  o += "\n// The kinds of values in the entries (od/value_kinds.hpp).\n"
       "inline constexpr od::value_kinds kinds{.strings = ";
  o += b(k.strings);
  o += ", .real = ";
  o += b(k.real);
  o += ", .time = ";
  o += b(k.time);
  o += ", .wide = ";
  o += b(k.wide);
  o += ", .limits = ";
  o += b(k.limits);
  o += ", .node_limits = ";
  o += b(k.node_limits);
  o += ", .scaled = ";
  o += b(k.scaled);
  o += ", .numbers = ";
  o += b(k.numbers);
  o += "};\n";
}

/// `{...}` initialising the od::entry_info part ("{}" when the entry has no descriptive column).
inline void emit_info(std::string &o, const entry &e) {
  o += "{";
  bool first = true;
  auto field = [&](const char *name) {
    o += first ? "." : ", .";
    o += name;
    o += " = ";
    first = false;
  };
  auto text = [&](const char *name, const std::string &v) {
    if (v.empty()) return;
    field(name);
    append_text(o, v);
  };
  text("name", e.name);
  text("unit", e.unit);
  text("alt_name", e.alt_name);
  text("section", e.section);
  text("remark", e.remark);
  text("denotation", e.denotation);
  if (e.has_obj_flags && e.obj_flags != 0U) {
    field("obj_flags");
    o += "0x";
    append_hex(o, e.obj_flags, 1);
  }
  if (e.parameter_value) {
    field("parameter_value");
    append_number(o, e.parameter_value);
  }
  if (!e.parameter_text.empty()) {
    field("parameter_text");
    append_text(o, e.type, e.parameter_text);
  }
  o += "}";
}

inline bool has_scale(const entry &e) {
  return e.scaled || e.offset.mantissa != 0 || e.scale.mantissa != 1 || e.scale.places != 0;
}

/// `{{scale}, {offset}}`, or "{}" for the identity.
inline void emit_scale(std::string &o, const entry &e) {
  if (!has_scale(e)) {
    o += "{}";
    return;
  }
  o += "{{";
  append_int(o, e.scale.mantissa);
  o += ", ";
  append_int(o, e.scale.places);
  o += "}, {";
  append_int(o, e.offset.mantissa);
  o += ", ";
  append_int(o, e.offset.places);
  o += "}}";
}

inline std::string command_value_enum(od::command_value v) {
  switch (v) {
  case od::command_value::none: return "none";
  case od::command_value::integer: return "integer";
  case od::command_value::real: return "real";
  }
  return "none";
}

inline void emit_commands(std::string &o, const dictionary &d) {
  o += "inline constexpr std::array<od::command, " + std::to_string(d.commands.size()) +
       "> commands{{\n";
  for (const auto &c : d.commands) {
    o += "    {.code = 0x" + hex(c.code, 4) + ", .name = ";
    append_view(o, c.name);
    if (!c.section.empty()) {
      o += ", .section = ";
      append_view(o, c.section);
    }
    if (!c.title.empty()) {
      o += ", .title = ";
      append_view(o, c.title);
    }
    if (!c.parameter.empty()) {
      o += ", .parameter = ";
      append_view(o, c.parameter);
    }
    if (c.parameter_min) {
      o += ", .parameter_min = ";
      o += number_literal(c.parameter_min);
    }
    if (c.parameter_max) {
      o += ", .parameter_max = ";
      o += number_literal(c.parameter_max);
    }
    if (c.parameter_packing != od::packing::whole)
      o += ", .parameter_packing = od::packing::" + std::string(od::name(c.parameter_packing));
    if (c.date_type != od::command_value::none)
      o += ", .date_type = od::command_value::" + command_value_enum(c.date_type);
    if (!c.date.empty()) {
      o += ", .date = ";
      append_view(o, c.date);
    }
    if (c.date_min) {
      o += ", .date_min = ";
      o += number_literal(c.date_min);
    }
    if (c.date_max) {
      o += ", .date_max = ";
      o += number_literal(c.date_max);
    }
    if (c.date_packing != od::packing::whole)
      o += ", .date_packing = od::packing::" + std::string(od::name(c.date_packing));
    if (c.reply_type != od::command_value::none)
      o += ", .reply_type = od::command_value::" + command_value_enum(c.reply_type);
    if (!c.reply.empty()) {
      o += ", .reply = ";
      append_view(o, c.reply);
    }
    if (!c.modes.empty()) {
      o += ", .modes = ";
      append_view(o, c.modes);
    }
    if (!c.remark.empty()) {
      o += ", .remark = ";
      append_view(o, c.remark);
    }
    o += "},\n";
  }
  o += "}};\n\ninline constexpr od::command_table "
       "table{commands};\nstatic_assert(table.is_valid());\n\n";
  symbols sym;
  for (std::size_t i = 0; i < d.commands.size(); ++i) {
    const auto &c = d.commands[i];
    const std::string s =
        sym.take(c.symbol.empty() ? make_identifier(c.name) : c.symbol, lower_hex(c.code, 4));
    o += "inline constexpr const od::command &" + s + " = commands[" + std::to_string(i) + "];\n";
  }
}

inline bool has_dpq_columns(const entry &e) {
  return e.acceptance != dpq::acceptance::unknown || e.bus != dpq::bus_manager::unspecified;
}

/// The manufacturers' column tables (dpq_columns, compax_columns) after the dictionary.
inline void emit_vendor_columns(std::string &o, const dictionary &d) {
  std::string rows;
  std::size_t n = 0;
  for (const entry &e : d.entries) {
    if (!has_dpq_columns(e)) continue;
    ++n;
    rows += "    {.index = 0x";
    append_hex(rows, e.index, 4);
    if (e.sub != 0U) rows += ", .sub = " + std::to_string(e.sub);
    if (e.acceptance == dpq::acceptance::only_when_disabled) {
      rows += ", .value_acceptance = dpq::acceptance::only_when_disabled";
    } else if (e.acceptance == dpq::acceptance::also_when_enabled) {
      rows += ", .value_acceptance = dpq::acceptance::also_when_enabled";
    }
    if (e.bus == dpq::bus_manager::available) {
      rows += ", .bus = dpq::bus_manager::available";
    } else if (e.bus == dpq::bus_manager::not_available) {
      rows += ", .bus = dpq::bus_manager::not_available";
    }
    rows += "},\n";
  }
  if (n != 0U) {
    o += "\n// DPQ columns of the parameters that have them (dpq/columns.hpp).\n"
         "inline constexpr dpq::parameter_columns dpq_columns[" +
         std::to_string(n) + "]{\n" + rows + "};\n";
  }
  rows.clear();
  n = 0;
  for (const entry &e : d.entries) {
    if (!e.pointer) continue;
    ++n;
    rows += "    {.index = 0x";
    append_hex(rows, e.index, 4);
    if (e.sub != 0U) rows += ", .sub = " + std::to_string(e.sub);
    rows += ", .pointer = " + std::to_string(*e.pointer) + "},\n";
  }
  if (n != 0U) {
    o += "\n// COMPAX index pointers of the objects that have one (compax/columns.hpp).\n"
         "inline constexpr compax::object_columns compax_columns[" +
         std::to_string(n) + "]{\n" + rows + "};\n";
  }
}

inline std::string emit_header(const dictionary &d) {
  std::string o;
  o.reserve(d.entries.size() * 400U + 4096U); // about 370 bytes per entry (three tables + names)
  o += "// Generated from " + d.source_name + " by fieldcodec-gen \xE2\x80\x94 do not edit.\n";
  o += "// Regenerate with codegen/regenerate.sh (or the fieldcodec_generate_dictionary CMake "
       "function).\n";
  o += "// clang-format off\n#pragma once\n\n";
  if (d.is_command_table) {
    o += "#include <fieldcodec/od/command.hpp>\n#include <fieldcodec/od/number.hpp>\n\n#include "
         "<array>\n#include <string_view>\n\n";
  } else {
    bool dpq_table = false;
    bool compax_table = false;
    for (const entry &e : d.entries) {
      dpq_table = dpq_table || has_dpq_columns(e);
      compax_table = compax_table || e.pointer.has_value();
    }
    if (compax_table) o += "#include <fieldcodec/compax/columns.hpp>\n";
    o += "#include <fieldcodec/core/scaling.hpp>\n";
    if (dpq_table) o += "#include <fieldcodec/dpq/columns.hpp>\n";
    o += "#include <fieldcodec/od/data_type.hpp>\n"
         "#include <fieldcodec/od/descriptor.hpp>\n#include <fieldcodec/od/dictionary.hpp>\n"
         "#include <fieldcodec/od/entry.hpp>\n#include <fieldcodec/od/number.hpp>\n"
         "#include <fieldcodec/od/object.hpp>\n#include <fieldcodec/od/text.hpp>\n"
         "#include <fieldcodec/od/value_kinds.hpp>\n\n#include "
         "<cstdint>\n#include <span>\n"
         "#include <string_view>\n\n";
  }
  o += "namespace fieldcodec::dictionaries::" + d.stem + " {\n\n";
  o += "using namespace std::string_view_literals;\n\n";
  o += "inline constexpr const char *source_file = " + cpp_string(d.source_name) + ";\n\n";
  if (d.is_command_table) {
    emit_commands(o, d);
    o += "\n} // namespace fieldcodec::dictionaries::" + d.stem + "\n// clang-format on\n";
    return o;
  }
  if (d.node_id > 0) {
    o += "/// [DeviceComissioning] NodeID\ninline constexpr std::uint8_t node_id = " +
         std::to_string(d.node_id) + ";\n\n";
  }
  // Names, assigned in index order (object, then its named sub-objects): a VAR object's single
  // entry and every named sub-object become standalone od::descriptor constants, ARRAY/RECORD
  // objects od::object views into the tables.
  struct view {
    std::string symbol;
    const object_info *info;
    std::size_t first, count;
  };
  std::vector<std::string> named(d.entries.size());
  std::vector<bool> is_var(d.entries.size(), false);
  std::vector<view> views;
  symbols sym;
  std::size_t i = 0;
  for (const auto &[index, info] : d.objects) {
    while (i < d.entries.size() && d.entries[i].index < index) ++i;
    std::size_t n = 0;
    while (i + n < d.entries.size() && d.entries[i + n].index == index) ++n;
    const std::string want = !info.symbol.empty() ? info.symbol : make_identifier(info.name);
    const std::string s = sym.take(want, lower_hex(index, 4));
    const bool single = info.code == od::object_code::var || info.code == od::object_code::domain ||
                        info.code == od::object_code::deftype || info.code == od::object_code::null;
    if (single && n == 1U) {
      named[i] = s;
      is_var[i] = true;
    } else {
      views.push_back({s, &info, i, n});
      // named sub-entries: every sub-object of a RECORD/DEFSTRUCT, explicit symbols of arrays
      for (std::size_t k = i; k < i + n; ++k) {
        const entry &e = d.entries[k];
        const bool is_named = info.code != od::object_code::array || !e.symbol.empty();
        if (!is_named) continue;
        std::string sub = !e.symbol.empty() ? e.symbol : symbols::join(s, make_identifier(e.name));
        if (e.symbol.empty() && make_identifier(e.name).empty()) {
          sub = symbols::join(s, "sub" + std::to_string(e.sub));
        }
        named[k] = sym.take(sub, "sub" + std::to_string(e.sub));
      }
    }
    i += n;
  }
  bool scales = false;
  for (const auto &e : d.entries) scales = scales || has_scale(e);

  const std::string size = std::to_string(d.entries.size());
  // round 5: C arrays in namespace detail, published as static-extent spans
  auto table = [&](const char *type, const char *name,
                   void (*literal)(std::string &, const entry &)) {
    o += std::string("inline constexpr ") + type + " " + name + "[" + size + "]{\n";
    for (const entry &e : d.entries) {
      o += "    ";
      literal(o, e);
      o += ",\n";
    }
    o += "};\n";
  };
  const bool empty = d.entries.empty(); // no C array of length 0: empty spans
  auto span = [&](const char *type, const char *name) {
    o += std::string("inline constexpr std::span<const ") + type + ", " + size + "> " + name +
         (empty ? std::string("{};\n") : "{detail::" + std::string(name) + "};\n");
  };
  if (!empty) {
    o += "namespace detail {\n";
    table("od::entry", "entries", emit_core);
    o += "\n";
    table("od::entry_info", "infos", emit_info);
    if (scales) {
      o += "\n";
      table("scaling::linear", "scales", emit_scale);
    }
    o += "} // namespace detail\n\n";
  }
  span("od::entry", "entries");
  span("od::entry_info", "infos");
  if (scales) span("scaling::linear", "scales");
  o += std::string("\ninline constexpr od::dictionary dictionary{entries, infos") +
       (scales ? ", scales" : "") + "};\nstatic_assert(dictionary.is_valid());\n";
  emit_vendor_columns(o, d);
  emit_kinds(o, d);
  // a standalone descriptor: a copy of table row k, not a reference into the tables
  auto descriptor = [&](std::size_t k) {
    const std::string at = std::to_string(k);
    o += "inline constexpr od::descriptor ";
    o += named[k];
    o += "{detail::entries[" + at + "], detail::infos[" + at + "]";
    if (scales) o += ", detail::scales[" + at + "]";
    o += "}; // 0x" + hex(d.entries[k].index, 4);
    if (!is_var[k]) o += " sub " + std::to_string(d.entries[k].sub);
    o += "\n";
  };
  o += "\n// VAR objects: standalone descriptors (firmware that names one keeps only that one).\n";
  for (std::size_t k = 0; k < d.entries.size(); ++k) {
    if (is_var[k]) descriptor(k);
  }
  if (!views.empty()) o += "\n// ARRAY and RECORD objects: views into the tables.\n";
  for (const view &v : views) {
    const std::string at = std::to_string(v.first);
    const std::string n = std::to_string(v.count);
    o += "inline constexpr od::object " + v.symbol + "{0x" + hex(v.info->index, 4) +
         ", od::object_code::" + std::string(od::info(v.info->code).identifier) + ", ";
    append_view(o, v.info->name);
    // subspan (one non-template member) instead of {entries.data() + k, n}, which makes the
    // compiler resolve std::span's constrained constructor templates for every view: bench700
    // 7.14 -> 6.74 G instructions of g++ -fsyntax-only (docs/performance.md)
    const std::string range = ".subspan(" + at + ", " + n + ")";
    o += ", dictionary.entries()" + range + ", dictionary.infos()" + range;
    if (scales) o += ", dictionary.scales()" + range;
    o += "};\n";
    // named sub-objects of the view: standalone descriptors too (as `view[sub]`)
    for (std::size_t k = v.first; k < v.first + v.count; ++k) {
      if (!named[k].empty()) descriptor(k);
    }
  }
  o += "\n} // namespace fieldcodec::dictionaries::" + d.stem + "\n// clang-format on\n";
  return o;
}

} // namespace emit_reference
