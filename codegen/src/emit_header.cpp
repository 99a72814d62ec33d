// fieldcodec-gen — C++ header emitter. Output is deterministic: the same dictionary gives the
// same bytes (sorted entries, symbols assigned in index order, no dates, no paths).
#include "readers.hpp"
#include "text.hpp"

#include <array>
#include <charconv>
#include <limits>
#include <map>
#include <set>

namespace fieldcodec::gen {

namespace {

std::string number_literal(const od::number &n) {
  switch (n.kind) {
  case od::number_kind::none: return "{}";
  case od::number_kind::signed_: {
    const auto v = static_cast<std::int64_t>(n.bits);
    if (v == std::numeric_limits<std::int64_t>::min())
      return "od::num::i(-9223372036854775807 - 1)";
    return "od::num::i(" + std::to_string(v) + ")";
  }
  case od::number_kind::unsigned_: return "od::num::u(" + std::to_string(n.bits) + "U)";
  case od::number_kind::real: {
    std::array<char, 64> buf{};
    const double d = n.to_double();
    auto [p, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), d);
    std::string s(buf.data(), p);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return "od::num::f(" + s + ")";
  }
  case od::number_kind::decimal_:
    return "od::num::d(" + std::to_string(static_cast<std::int64_t>(n.bits)) + ", " +
           std::to_string(n.places) + ")";
  }
  return "{}";
}

std::string lower_hex(std::uint64_t v, int digits) { return to_lower(hex(v, digits)); }

const char *data_type_enum(od::data_type t) {
  switch (t) {
  case od::data_type::boolean: return "boolean";
  case od::data_type::integer8: return "integer8";
  case od::data_type::integer16: return "integer16";
  case od::data_type::integer24: return "integer24";
  case od::data_type::integer32: return "integer32";
  case od::data_type::integer40: return "integer40";
  case od::data_type::integer48: return "integer48";
  case od::data_type::integer56: return "integer56";
  case od::data_type::integer64: return "integer64";
  case od::data_type::unsigned8: return "unsigned8";
  case od::data_type::unsigned16: return "unsigned16";
  case od::data_type::unsigned24: return "unsigned24";
  case od::data_type::unsigned32: return "unsigned32";
  case od::data_type::unsigned40: return "unsigned40";
  case od::data_type::unsigned48: return "unsigned48";
  case od::data_type::unsigned56: return "unsigned56";
  case od::data_type::unsigned64: return "unsigned64";
  case od::data_type::real32: return "real32";
  case od::data_type::real64: return "real64";
  case od::data_type::visible_string: return "visible_string";
  case od::data_type::octet_string: return "octet_string";
  case od::data_type::unicode_string: return "unicode_string";
  case od::data_type::time_of_day: return "time_of_day";
  case od::data_type::time_difference: return "time_difference";
  case od::data_type::domain: return "domain";
  }
  return "domain";
}

const char *object_enum(od::object_code c) {
  switch (c) {
  case od::object_code::null: return "null";
  case od::object_code::domain: return "domain";
  case od::object_code::deftype: return "deftype";
  case od::object_code::defstruct: return "defstruct";
  case od::object_code::var: return "var";
  case od::object_code::array: return "array";
  case od::object_code::record: return "record";
  }
  return "var";
}

const char *access_enum(od::access a) {
  switch (a) {
  case od::access::ro: return "ro";
  case od::access::wo: return "wo";
  case od::access::rw: return "rw";
  case od::access::rwr: return "rwr";
  case od::access::rww: return "rww";
  case od::access::constant: return "constant";
  }
  return "rw";
}

/// Assigns unique identifiers in a deterministic order.
class symbols {
public:
  symbols() {
    for (const char *r : {"entries", "dictionary", "commands", "table", "od", "std", "fieldcodec",
                          "node_id", "source_file", "detail"}) {
      used_.insert(r);
    }
  }
  /// `wanted` if free, else wanted_<suffix>, else wanted_<suffix>_2, _3, ...
  std::string take(std::string wanted, const std::string &suffix) {
    if (wanted.empty()) wanted = "object_" + suffix;
    if (is_cpp_keyword(wanted)) wanted += '_';
    if (used_.insert(wanted).second) return wanted;
    std::string s = wanted + "_" + suffix;
    for (int n = 2; !used_.insert(s).second; ++n)
      s = wanted + "_" + suffix + "_" + std::to_string(n);
    return s;
  }

private:
  std::set<std::string> used_;
};

void emit_entry(std::string &o, const entry &e) {
  o += "    {.index = 0x" + hex(e.index, 4);
  if (e.sub != 0U) o += ", .sub = " + std::to_string(e.sub);
  if (e.object != od::object_code::var)
    o += std::string(", .object = od::object_code::") + object_enum(e.object);
  o += std::string(", .type = od::data_type::") + data_type_enum(e.type);
  if (e.access != od::access::rw)
    o += std::string(", .access_type = od::access::") + access_enum(e.access);
  if (e.pdo != od::pdo_mapping::no)
    o += ", .pdo = od::pdo_mapping::" + std::string(od::name(e.pdo));
  if (e.flags != 0U) o += ", .flags = 0x" + hex(e.flags, 2);
  if (e.size != 0U) o += ", .size = " + std::to_string(e.size);
  o += ", .name = ";
  append_cpp_string(o, e.name);
  if (e.low) {
    o += ", .low = ";
    o += number_literal(e.low);
  }
  if (e.high) {
    o += ", .high = ";
    o += number_literal(e.high);
  }
  if (e.default_value) {
    o += ", .default_value = ";
    o += number_literal(e.default_value);
  }
  if (e.default_nodeid) o += ", .default_nodeid = true";
  if (!e.default_text.empty()) {
    o += ", .default_text = ";
    append_cpp_value_text(o, e.type, e.default_text);
  }
  if (e.scaled || e.offset.mantissa != 0) {
    o += ", .scale = {{" + std::to_string(e.scale.mantissa) + ", " +
         std::to_string(e.scale.places) + "}, {" + std::to_string(e.offset.mantissa) + ", " +
         std::to_string(e.offset.places) + "}}";
  }
  if (e.scaled) o += ", .scaled = true";
  if (!e.unit.empty()) {
    o += ", .unit = ";
    append_cpp_string(o, e.unit);
  }
  if (!e.alt_name.empty()) {
    o += ", .alt_name = ";
    append_cpp_string(o, e.alt_name);
  }
  if (e.pointer != od::no_pointer) o += ", .pointer = " + std::to_string(e.pointer);
  if (e.bus == od::bus_manager::available) o += ", .bus = od::bus_manager::available";
  if (e.bus == od::bus_manager::not_available) o += ", .bus = od::bus_manager::not_available";
  if (!e.acceptance.empty()) {
    o += ", .acceptance = ";
    append_cpp_string(o, e.acceptance);
  }
  if (!e.section.empty()) {
    o += ", .section = ";
    append_cpp_string(o, e.section);
  }
  if (!e.remark.empty()) {
    o += ", .remark = ";
    append_cpp_string(o, e.remark);
  }
  if (e.has_obj_flags && e.obj_flags != 0U) o += ", .obj_flags = 0x" + hex(e.obj_flags, 1);
  if (e.parameter_value) {
    o += ", .parameter_value = ";
    o += number_literal(e.parameter_value);
  }
  if (e.parameter_nodeid) o += ", .parameter_nodeid = true";
  if (!e.parameter_text.empty()) {
    o += ", .parameter_text = ";
    append_cpp_value_text(o, e.type, e.parameter_text);
  }
  if (!e.denotation.empty()) {
    o += ", .denotation = ";
    append_cpp_string(o, e.denotation);
  }
  o += "},\n";
}

std::string command_value_enum(od::command_value v) {
  switch (v) {
  case od::command_value::none: return "none";
  case od::command_value::integer: return "integer";
  case od::command_value::real: return "real";
  }
  return "none";
}

void emit_commands(std::string &o, const dictionary &d) {
  o += "inline constexpr std::array<od::command, " + std::to_string(d.commands.size()) +
       "> commands{{\n";
  for (const auto &c : d.commands) {
    o += "    {.code = 0x" + hex(c.code, 4) + ", .name = " + cpp_string(c.name);
    if (!c.section.empty()) {
      o += ", .section = ";
      append_cpp_string(o, c.section);
    }
    if (!c.title.empty()) {
      o += ", .title = ";
      append_cpp_string(o, c.title);
    }
    if (!c.parameter.empty()) {
      o += ", .parameter = ";
      append_cpp_string(o, c.parameter);
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
      append_cpp_string(o, c.date);
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
      append_cpp_string(o, c.reply);
    }
    if (!c.modes.empty()) {
      o += ", .modes = ";
      append_cpp_string(o, c.modes);
    }
    if (!c.remark.empty()) {
      o += ", .remark = ";
      append_cpp_string(o, c.remark);
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

} // namespace

std::string stem_identifier(std::string_view stem) {
  std::string s = make_identifier(stem);
  if (s.empty()) s = "dictionary_";
  if (s == "od" || s == "std" || s == "detail") s += '_';
  return s;
}

std::string emit_header(const dictionary &d) {
  std::string o;
  o.reserve(d.entries.size() * 160U + 4096U);
  o += "// Generated from " + d.source_name + " by fieldcodec-gen \xE2\x80\x94 do not edit.\n";
  o += "// Regenerate with codegen/regenerate.sh (or the fieldcodec_generate_dictionary CMake "
       "function).\n";
  o += "// clang-format off\n#pragma once\n\n";
  if (d.is_command_table) {
    o += "#include <fieldcodec/od/command.hpp>\n#include <fieldcodec/od/number.hpp>\n\n#include "
         "<array>\n\n";
  } else {
    o += "#include <fieldcodec/od/data_type.hpp>\n#include <fieldcodec/od/dictionary.hpp>\n"
         "#include <fieldcodec/od/entry.hpp>\n#include <fieldcodec/od/number.hpp>\n"
         "#include <fieldcodec/od/object.hpp>\n\n#include <array>\n#include <cstdint>\n\n";
  }
  o += "namespace fieldcodec::dictionaries::" + d.stem + " {\n\n";
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
  o += "inline constexpr std::array<od::entry, " + std::to_string(d.entries.size()) +
       "> entries{{\n";
  for (const auto &e : d.entries) emit_entry(o, e);
  o += "}};\n\ninline constexpr od::dictionary dictionary{entries};\n"
       "static_assert(dictionary.is_valid());\n\n";
  // descriptors, one per object, in index order
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
      o += "inline constexpr const od::entry &" + s + " = entries[" + std::to_string(i) +
           "]; // 0x" + hex(index, 4) + "\n";
    } else {
      o += "inline constexpr od::object " + s + "{0x" + hex(index, 4) +
           ", od::object_code::" + object_enum(info.code) + ", " + cpp_string(info.name) +
           ", {entries.data() + " + std::to_string(i) + ", " + std::to_string(n) + "}};\n";
      // named sub-entries: every sub-object of a RECORD/DEFSTRUCT, explicit symbols of arrays
      for (std::size_t k = i; k < i + n; ++k) {
        const entry &e = d.entries[k];
        const bool named = info.code != od::object_code::array || !e.symbol.empty();
        if (!named) continue;
        std::string sub = !e.symbol.empty() ? e.symbol : s + "_" + make_identifier(e.name);
        if (e.symbol.empty() && make_identifier(e.name).empty()) {
          sub = s + "_sub" + std::to_string(e.sub);
        }
        const std::string ss = sym.take(sub, "sub" + std::to_string(e.sub));
        o += "inline constexpr const od::entry &" + ss + " = entries[" + std::to_string(k) + "];\n";
      }
    }
    i += n;
  }
  o += "\n} // namespace fieldcodec::dictionaries::" + d.stem + "\n// clang-format on\n";
  return o;
}

} // namespace fieldcodec::gen
