// fieldcodec-gen — C++ header emitter. Output is deterministic: the same dictionary gives the
// same bytes (sorted entries, symbols assigned in index order, no dates, no paths).
#include "readers.hpp"
#include "text.hpp"

#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/value_kinds.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace fieldcodec::gen {

namespace {

/// The header under construction: one string reserved for the whole header and written through
/// a pointer (a literal is a copy of a length known at compile time, a number is formatted in
/// place, a name or text is escaped straight into the header), no temporary strings. The
/// string's size runs at most one chunk ahead of what is written (`grow` zero-fills that chunk
/// only): the pages of the reservation are touched once, in order. With a `sink`, the string is
/// a buffer of `capacity` bytes handed to the sink whenever it is full (and at the end).
class writer {
public:
  explicit writer(std::size_t capacity, const header_sink *sink = nullptr) : sink_(sink) {
    if (sink_ != nullptr) {
      s_.resize(capacity); // a buffer used again and again: its size at once
    } else {
      s_.reserve(capacity);
    }
    p_ = s_.data();
    end_ = p_ + s_.size();
  }
  /// Room for `n` more bytes at the returned position; write there, then `advance` to the end.
  [[nodiscard]] char *room(std::size_t n) {
    if (static_cast<std::size_t>(end_ - p_) < n) {
      if (sink_ != nullptr) flush();
      if (static_cast<std::size_t>(end_ - p_) < n) grow(n);
    }
    return p_;
  }
  void advance(char *end) noexcept { p_ = end; }

  template <std::size_t N>
  void lit(const char (&t)[N]) {
    char *const q = room(N - 1U);
    std::memcpy(q, t, N - 1U);
    p_ = q + (N - 1U);
  }
  void put(std::string_view t) {
    char *const q = room(t.size());
    if (!t.empty()) std::memcpy(q, t.data(), t.size());
    p_ = q + t.size();
  }
  void put(char c) {
    *room(1) = c;
    ++p_;
  }
  /// Decimal, as std::to_chars writes it.
  void uint(std::uint64_t v) {
    char tmp[20];
    std::size_t n = 0;
    do {
      tmp[n++] = static_cast<char>('0' + v % 10U);
      v /= 10U;
    } while (v != 0U);
    char *q = room(n);
    while (n > 0U) *q++ = tmp[--n];
    p_ = q;
  }
  void sint(std::int64_t v) {
    if (v < 0) {
      put('-');
      uint(0U - static_cast<std::uint64_t>(v)); // INT64_MIN's magnitude too
    } else {
      uint(static_cast<std::uint64_t>(v));
    }
  }
  /// Upper-case hex with at least `digits` digits.
  void hex(std::uint64_t v, int digits) {
    char tmp[16];
    int n = 0;
    while (v != 0U || n < digits) {
      tmp[15 - n] = "0123456789ABCDEF"[v & 0xFU];
      v >>= 4U;
      ++n;
    }
    put(std::string_view(tmp + 16 - n, static_cast<std::size_t>(n)));
  }
  /// `"text"` (append_cpp_string's literal).
  void cpp_string(std::string_view t) {
    advance(write_cpp_string(room(cpp_string_capacity(t.size())), t));
  }
  /// `"bytes"`, every byte outside printable ASCII escaped (write_cpp_bytes's literal).
  void cpp_bytes(std::string_view t) {
    advance(write_cpp_bytes(room(cpp_string_capacity(t.size())), t));
  }

  [[nodiscard]] std::string finish() {
    s_.resize(static_cast<std::size_t>(p_ - s_.data()));
    return std::move(s_);
  }
  /// Hands what was written since the last flush to the sink.
  void flush() {
    if (p_ != s_.data())
      (*sink_)(std::string_view(s_.data(), static_cast<std::size_t>(p_ - s_.data())));
    p_ = s_.data();
  }

private:
  void grow(std::size_t n) {
    const auto used = static_cast<std::size_t>(p_ - s_.data());
    s_.resize(used + std::max<std::size_t>(n, 16384U));
    p_ = s_.data() + used;
    end_ = s_.data() + s_.size();
  }
  const header_sink *sink_;
  std::string s_;
  char *p_;
  char *end_;
};

void append_number(writer &o, const od::number &n) {
  switch (n.kind) {
  case od::number_kind::none: o.lit("{}"); return;
  case od::number_kind::signed_: {
    const auto v = static_cast<std::int64_t>(n.bits);
    if (v == std::numeric_limits<std::int64_t>::min()) {
      o.lit("od::signed_number(-9223372036854775807 - 1)");
      return;
    }
    o.lit("od::signed_number(");
    o.sint(v);
    o.put(')');
    return;
  }
  case od::number_kind::unsigned_:
    o.lit("od::unsigned_number(");
    o.uint(n.bits);
    o.lit("U)");
    return;
  case od::number_kind::real: {
    std::array<char, 64> buf{};
    const double d = n.to_double();
    auto [p, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), d);
    std::string_view t(buf.data(), static_cast<std::size_t>(p - buf.data()));
    o.lit("od::real_number(");
    o.put(t);
    if (t.find_first_of(".e") == std::string_view::npos) o.lit(".0");
    o.put(')');
    return;
  }
  case od::number_kind::decimal_:
    o.lit("od::decimal_number(");
    o.sint(static_cast<std::int64_t>(n.bits));
    o.lit(", ");
    o.uint(n.places);
    o.put(')');
    return;
  }
  o.lit("{}");
}

// The enumerators' C++ names come from od/data_type.hpp's tables (od::info(…).identifier: one
// table per idea, shared by the readers, the EDS writer and this emitter).

/// Appends '_' and `part` to the identifier `name`, one '_' only when `name` ends in one (a
/// keyword's trailing '_', a symbol such as `speed_`): an identifier with "__" is reserved to the
/// implementation in every scope (F19 in fuzz/FINDINGS.md).
void append_part(std::string &name, std::string_view part) {
  if (name.empty() || name.back() != '_') name += '_';
  name += part;
}

/// Assigns unique identifiers in a deterministic order. The names live in blocks that never
/// move; the set is open addressing over views of them (one look-up per generated name, the
/// order of names plays no part).
class symbols {
public:
  explicit symbols(std::size_t expected) {
    std::size_t cap = 64;
    while (cap < 2U * (expected + 16U)) cap *= 2U;
    slots_.resize(cap);
    for (const char *r : {"entries", "infos", "scales", "dictionary", "kinds", "commands", "table",
                          "od", "std", "fieldcodec", "scaling", "node_id", "source_file", "detail",
                          "dpq", "compax", "dpq_columns", "compax_columns"}) {
      (void)insert(r);
    }
  }
  /// `wanted` if free, else wanted_<suffix>, else wanted_<suffix>_2, _3, ...
  std::string_view take(std::string_view wanted, std::string_view suffix) {
    std::string &w = want_;
    w.assign(wanted);
    if (w.empty()) {
      w = "object_";
      w += suffix;
    }
    if (is_cpp_keyword(w)) w += '_';
    if (const std::string_view s = insert(w); !s.empty()) return s;
    std::string &t = try_;
    t.assign(w);
    append_part(t, suffix);
    for (unsigned n = 2;; ++n) {
      if (const std::string_view s = insert(t); !s.empty()) return s;
      t.assign(w);
      append_part(t, suffix);
      t += '_';
      t += std::to_string(n);
    }
  }

private:
  /// Eight bytes at a time, each word mixed in by a multiplication (names are 10..60 bytes).
  static std::size_t hash(std::string_view s) noexcept {
    constexpr std::uint64_t k = 0x9E3779B97F4A7C15U;
    std::uint64_t h = s.size() * k;
    std::size_t i = 0;
    for (; i + 8U <= s.size(); i += 8U) {
      std::uint64_t w = 0;
      std::memcpy(&w, s.data() + i, 8);
      h = (h ^ w) * k;
      h ^= h >> 32U;
    }
    if (i < s.size()) {
      std::uint64_t w = 0;
      std::memcpy(&w, s.data() + i, s.size() - i);
      h = (h ^ w) * k;
      h ^= h >> 32U;
    }
    return static_cast<std::size_t>(h ^ (h >> 29U));
  }
  /// The stored name, or empty when `s` is taken already.
  std::string_view insert(std::string_view s) {
    if (2U * (used_ + 1U) > slots_.size()) rehash();
    const std::size_t mask = slots_.size() - 1U;
    for (std::size_t i = hash(s) & mask;; i = (i + 1U) & mask) {
      if (slots_[i].empty()) {
        slots_[i] = store(s);
        ++used_;
        return slots_[i];
      }
      if (slots_[i] == s) return {};
    }
  }
  void rehash() {
    std::vector<std::string_view> old(slots_.size() * 2U);
    old.swap(slots_);
    const std::size_t mask = slots_.size() - 1U;
    for (const std::string_view s : old) {
      if (s.empty()) continue;
      std::size_t i = hash(s) & mask;
      while (!slots_[i].empty()) i = (i + 1U) & mask;
      slots_[i] = s;
    }
  }
  std::string_view store(std::string_view s) {
    if (left_ < s.size()) {
      const std::size_t size = std::max<std::size_t>(s.size(), 32768U);
      blocks_.push_back(std::make_unique<char[]>(size));
      free_ = blocks_.back().get();
      left_ = size;
    }
    std::memcpy(free_, s.data(), s.size());
    const std::string_view stored(free_, s.size());
    free_ += s.size();
    left_ -= s.size();
    return stored;
  }
  std::vector<std::string_view> slots_; ///< empty: free (a name is never empty)
  std::size_t used_ = 0;
  std::vector<std::unique_ptr<char[]>> blocks_;
  char *free_ = nullptr;
  std::size_t left_ = 0;
  std::string want_, try_;
};

/// A std::string_view literal, `"text"sv`: its length is known without the compiler counting
/// the characters in constant evaluation, and there is no constructor overload to resolve (both
/// are a measurable part of compiling a big dictionary). Embedded NULs are kept.
void append_view(writer &o, const std::string &v) {
  o.cpp_string(v);
  o.lit("sv");
}

/// An od::text column, `{"text", N}`: od::text's (pointer, length) constructor, the length
/// written out (no counting in constant evaluation). A VISIBLE_STRING (and every descriptive
/// column) as its text, other bytes (OCTET_STRING, UNICODE_STRING, DOMAIN) with every byte
/// escaped (append_cpp_value_text's literal). Embedded NULs are kept.
void append_text(writer &o, od::data_type type, const std::string &bytes) {
  char *q = o.room(cpp_string_capacity(bytes.size()) + 1U);
  *q++ = '{';
  q = type == od::data_type::visible_string ? write_cpp_string(q, bytes)
                                            : write_cpp_bytes(q, bytes);
  o.advance(q);
  o.lit(", ");
  o.uint(bytes.size());
  o.put('}');
}
void append_text(writer &o, const std::string &v) {
  append_text(o, od::data_type::visible_string, v);
}

/// The od::flag bits `f`, as a C++ expression after ", .flags = " (nothing when none).
void append_flags(writer &o, std::uint16_t f) {
  static constexpr std::pair<std::uint16_t, std::string_view> bits[] = {
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
    if (first) {
      o.lit(", .flags = od::flag::");
    } else {
      o.lit(" | od::flag::");
    }
    o.put(name);
    first = false;
  }
}

/// `{...}` initialising the od::entry part: the lean columns, and the packed ones (od::pack's
/// bytes) as a string literal. `scratch` is reused for the bytes.
void emit_core(writer &o, const entry &e, std::string &scratch) {
  const od::entry_spec spec = spec_of(e);
  const od::entry packed = od::make_entry(spec, nullptr);
  o.lit("{.index = 0x");
  o.hex(e.index, 4);
  if (e.sub != 0U) {
    o.lit(", .sub = ");
    o.uint(e.sub);
  }
  if (e.object != od::object_code::var) {
    o.lit(", .object = od::object_code::");
    o.put(od::info(e.object).identifier);
  }
  o.lit(", .type = od::data_type::");
  o.put(od::info(e.type).identifier);
  if (e.access != od::access::rw) {
    o.lit(", .access_type = od::access::");
    o.put(od::info(e.access).identifier);
  }
  if (e.pdo != od::pdo_mapping::no) {
    o.lit(", .pdo = od::pdo_mapping::");
    o.put(od::name(e.pdo));
  }
  append_flags(o, packed.flags);
  if (const std::size_t n = od::packed_size(spec); n != 0U) {
    scratch.resize(n);
    (void)od::pack(spec, std::span<char>(scratch.data(), n));
    o.lit(", .extra = ");
    o.cpp_bytes(scratch);
  }
  o.put('}');
}

/// `{...}` initialising the od::entry_info part ("{}" when the entry has no descriptive column).
void emit_info(writer &o, const entry &e) {
  o.put('{');
  bool first = true;
  auto field = [&](std::string_view name) {
    if (first) {
      o.put('.');
    } else {
      o.lit(", .");
    }
    o.put(name);
    o.lit(" = ");
    first = false;
  };
  auto text = [&](std::string_view name, const std::string &v) {
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
    o.lit("0x");
    o.hex(e.obj_flags, 1);
  }
  if (e.parameter_value) {
    field("parameter_value");
    append_number(o, e.parameter_value);
  }
  if (!e.parameter_text.empty()) {
    field("parameter_text");
    append_text(o, e.type, e.parameter_text);
  }
  o.put('}');
}

bool has_scale(const entry &e) {
  return e.scaled || e.offset.mantissa != 0 || e.scale.mantissa != 1 || e.scale.places != 0;
}

/// `{{scale}, {offset}}`, or "{}" for the identity.
void emit_scale(writer &o, const entry &e) {
  if (!has_scale(e)) {
    o.lit("{}");
    return;
  }
  o.lit("{{");
  o.sint(e.scale.mantissa);
  o.lit(", ");
  o.uint(e.scale.places);
  o.lit("}, {");
  o.sint(e.offset.mantissa);
  o.lit(", ");
  o.uint(e.offset.places);
  o.lit("}}");
}

std::string_view command_value_enum(od::command_value v) {
  switch (v) {
  case od::command_value::none: return "none";
  case od::command_value::integer: return "integer";
  case od::command_value::real: return "real";
  }
  return "none";
}

/// Four lower-case hex digits (the suffix of a colliding name).
std::array<char, 4> lower_hex4(std::uint16_t v) {
  std::array<char, 4> h{};
  for (std::size_t k = 0; k < 4U; ++k)
    h[3U - k] = "0123456789abcdef"[(static_cast<unsigned>(v) >> (4U * k)) & 0xFU];
  return h;
}

void emit_commands(writer &o, const dictionary &d) {
  o.lit("inline constexpr std::array<od::command, ");
  o.uint(d.commands.size());
  o.lit("> commands{{\n");
  for (const auto &c : d.commands) {
    o.lit("    {.code = 0x");
    o.hex(c.code, 4);
    o.lit(", .name = ");
    append_view(o, c.name);
    if (!c.section.empty()) {
      o.lit(", .section = ");
      append_view(o, c.section);
    }
    if (!c.title.empty()) {
      o.lit(", .title = ");
      append_view(o, c.title);
    }
    if (!c.parameter.empty()) {
      o.lit(", .parameter = ");
      append_view(o, c.parameter);
    }
    if (c.parameter_min) {
      o.lit(", .parameter_min = ");
      append_number(o, c.parameter_min);
    }
    if (c.parameter_max) {
      o.lit(", .parameter_max = ");
      append_number(o, c.parameter_max);
    }
    if (c.parameter_packing != od::packing::whole) {
      o.lit(", .parameter_packing = od::packing::");
      o.put(od::name(c.parameter_packing));
    }
    if (c.date_type != od::command_value::none) {
      o.lit(", .date_type = od::command_value::");
      o.put(command_value_enum(c.date_type));
    }
    if (!c.date.empty()) {
      o.lit(", .date = ");
      append_view(o, c.date);
    }
    if (c.date_min) {
      o.lit(", .date_min = ");
      append_number(o, c.date_min);
    }
    if (c.date_max) {
      o.lit(", .date_max = ");
      append_number(o, c.date_max);
    }
    if (c.date_packing != od::packing::whole) {
      o.lit(", .date_packing = od::packing::");
      o.put(od::name(c.date_packing));
    }
    if (c.reply_type != od::command_value::none) {
      o.lit(", .reply_type = od::command_value::");
      o.put(command_value_enum(c.reply_type));
    }
    if (!c.reply.empty()) {
      o.lit(", .reply = ");
      append_view(o, c.reply);
    }
    if (!c.modes.empty()) {
      o.lit(", .modes = ");
      append_view(o, c.modes);
    }
    if (!c.remark.empty()) {
      o.lit(", .remark = ");
      append_view(o, c.remark);
    }
    o.lit("},\n");
  }
  o.lit("}};\n\ninline constexpr od::command_table "
        "table{commands};\nstatic_assert(table.is_valid());\n\n");
  symbols sym(d.commands.size());
  for (std::size_t i = 0; i < d.commands.size(); ++i) {
    const auto &c = d.commands[i];
    const auto suffix = lower_hex4(c.code);
    const std::string_view s = sym.take(c.symbol.empty() ? make_identifier(c.name) : c.symbol,
                                        std::string_view(suffix.data(), suffix.size()));
    o.lit("inline constexpr const od::command &");
    o.put(s);
    o.lit(" = commands[");
    o.uint(i);
    o.lit("];\n");
  }
}

} // namespace

std::string stem_identifier(std::string_view stem) {
  std::string s = make_identifier(stem);
  if (s.empty()) s = "dictionary_";
  if (s == "od" || s == "std" || s == "detail") s += '_';
  return s;
}

namespace {

/// Whether a file name is written as it is: UTF-8 text without control bytes. A file system
/// allows any byte but '/' and NUL in a name, and a line break in the "Generated from" comment
/// would end the comment, a byte that is not UTF-8 would make the header no UTF-8 text (F20 in
/// fuzz/FINDINGS.md): such a name is shown as a literal with those bytes escaped.
bool plain_name(std::string_view s) noexcept {
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20U || u == 0x7FU) return false;
  }
  return valid_utf8(s);
}

// ---- vendor columns ---------------------------------------------------------------------------
// Columns that only one manufacturer's table has are not od::entry_info columns: each is written
// as that manufacturer's table beside the dictionary, one row per entry that has the column, in
// entry order (sorted by address, od/columns.hpp), with the row type of the manufacturer's folder.

bool has_dpq_columns(const entry &e) {
  return e.acceptance != dpq::acceptance::unknown || e.bus != dpq::bus_manager::unspecified;
}
bool has_compax_columns(const entry &e) { return e.pointer.has_value(); }

/// `inline constexpr <type> <name>[N]{ rows };` over the entries `has` picks (nothing when none).
template <class Has, class Columns>
void emit_vendor_table(writer &o, const dictionary &d, std::string_view comment,
                       std::string_view type, std::string_view name, Has has, Columns columns) {
  std::size_t n = 0;
  for (const entry &e : d.entries) n += has(e) ? 1U : 0U;
  if (n == 0U) return;
  o.lit("\n// ");
  o.put(comment);
  o.lit("\ninline constexpr ");
  o.put(type);
  o.put(' ');
  o.put(name);
  o.put('[');
  o.uint(n);
  o.lit("]{\n");
  for (const entry &e : d.entries) {
    if (!has(e)) continue;
    o.lit("    {.index = 0x");
    o.hex(e.index, 4);
    if (e.sub != 0U) {
      o.lit(", .sub = ");
      o.uint(e.sub);
    }
    columns(e);
    o.lit("},\n");
  }
  o.lit("};\n");
}

void emit_vendor_columns(writer &o, const dictionary &d) {
  emit_vendor_table(o, d, "DPQ columns of the parameters that have them (dpq/columns.hpp).",
                    "dpq::parameter_columns", "dpq_columns", has_dpq_columns, [&o](const entry &e) {
                      switch (e.acceptance) {
                      case dpq::acceptance::only_when_disabled:
                        o.lit(", .value_acceptance = dpq::acceptance::only_when_disabled");
                        break;
                      case dpq::acceptance::also_when_enabled:
                        o.lit(", .value_acceptance = dpq::acceptance::also_when_enabled");
                        break;
                      case dpq::acceptance::unknown: break;
                      }
                      switch (e.bus) {
                      case dpq::bus_manager::available:
                        o.lit(", .bus = dpq::bus_manager::available");
                        break;
                      case dpq::bus_manager::not_available:
                        o.lit(", .bus = dpq::bus_manager::not_available");
                        break;
                      case dpq::bus_manager::unspecified: break;
                      }
                    });
  emit_vendor_table(
      o, d, "COMPAX index pointers of the objects that have one (compax/columns.hpp).",
      "compax::object_columns", "compax_columns", has_compax_columns, [&o](const entry &e) {
        o.lit(", .pointer = ");
        o.uint(*e.pointer);
      });
}

void emit(writer &o, const dictionary &d) {
  const bool plain = plain_name(d.source_name);
  o.lit("// Generated from ");
  if (plain) {
    o.put(d.source_name);
  } else {
    o.cpp_bytes(d.source_name);
  }
  o.lit(" by fieldcodec-gen \xE2\x80\x94 do not edit.\n");
  o.lit("// Regenerate with codegen/regenerate.sh (or the fieldcodec_generate_dictionary CMake "
        "function).\n");
  o.lit("// clang-format off\n#pragma once\n\n");
  if (d.is_command_table) {
    o.lit("#include <fieldcodec/od/command.hpp>\n#include <fieldcodec/od/number.hpp>\n\n#include "
          "<array>\n#include <string_view>\n\n");
  } else {
    bool dpq_table = false;
    bool compax_table = false;
    for (const entry &e : d.entries) {
      dpq_table = dpq_table || has_dpq_columns(e);
      compax_table = compax_table || has_compax_columns(e);
    }
    if (compax_table) o.lit("#include <fieldcodec/compax/columns.hpp>\n");
    o.lit("#include <fieldcodec/core/scaling.hpp>\n");
    if (dpq_table) o.lit("#include <fieldcodec/dpq/columns.hpp>\n");
    o.lit("#include <fieldcodec/od/data_type.hpp>\n"
          "#include <fieldcodec/od/descriptor.hpp>\n#include <fieldcodec/od/dictionary.hpp>\n"
          "#include <fieldcodec/od/entry.hpp>\n#include <fieldcodec/od/number.hpp>\n"
          "#include <fieldcodec/od/object.hpp>\n#include <fieldcodec/od/text.hpp>\n"
          "#include <fieldcodec/od/value_kinds.hpp>\n\n#include "
          "<cstdint>\n#include <span>\n"
          "#include <string_view>\n\n");
  }
  o.lit("namespace fieldcodec::dictionaries::");
  o.put(d.stem);
  o.lit(" {\n\n");
  o.lit("using namespace std::string_view_literals;\n\n");
  o.lit("inline constexpr const char *source_file = ");
  if (plain) {
    o.cpp_string(d.source_name);
  } else {
    o.cpp_bytes(d.source_name);
  }
  o.lit(";\n\n");
  if (d.is_command_table) {
    emit_commands(o, d);
    o.lit("\n} // namespace fieldcodec::dictionaries::");
    o.put(d.stem);
    o.lit("\n// clang-format on\n");
    return;
  }
  if (d.node_id > 0) {
    o.lit("/// [DeviceComissioning] NodeID\ninline constexpr std::uint8_t node_id = ");
    o.sint(d.node_id);
    o.lit(";\n\n");
  }
  // Names, assigned in index order (object, then its named sub-objects): a VAR object's single
  // entry and every named sub-object become standalone od::descriptor constants, ARRAY/RECORD
  // objects od::object views into the tables. A name is the file's symbol or is built from the
  // object's name (a sub-object's: the object's C++ name, '_' and its own), `sym` keeps it.
  struct view {
    std::string_view symbol;
    const object_info *info;
    std::size_t first, count;
  };
  std::vector<std::string_view> named(d.entries.size());
  std::vector<bool> is_var(d.entries.size(), false);
  std::vector<view> views;
  symbols sym(d.entries.size() + d.objects.size());
  // A name is built in `scratch` (grown, never shrunk: no clearing per name) or is the file's
  // symbol as it is; `want` holds a sub-object's "<object>_sub<N>".
  std::string scratch;
  std::string want;
  // prefix + the identifier of `name` (nothing after the prefix when the name has none)
  const auto identifier = [&scratch](std::string_view prefix, std::string_view name) {
    const std::size_t need = prefix.size() + identifier_capacity(name.size());
    if (scratch.size() < need) scratch.resize(std::max(need, 2U * scratch.size()));
    if (!prefix.empty()) std::memcpy(scratch.data(), prefix.data(), prefix.size());
    const std::size_t n = write_identifier(scratch.data() + prefix.size(), name);
    return std::string_view(scratch.data(), prefix.size() + n);
  };
  std::size_t i = 0;
  for (const auto &[index, info] : d.objects) {
    while (i < d.entries.size() && d.entries[i].index < index) ++i;
    std::size_t n = 0;
    while (i + n < d.entries.size() && d.entries[i + n].index == index) ++n;
    const std::string_view wanted =
        !info.symbol.empty() ? std::string_view(info.symbol) : identifier({}, info.name);
    const auto suffix = lower_hex4(index);
    const std::string_view s = sym.take(wanted, std::string_view(suffix.data(), suffix.size()));
    const bool single = info.code == od::object_code::var || info.code == od::object_code::domain ||
                        info.code == od::object_code::deftype || info.code == od::object_code::null;
    if (single && n == 1U) {
      named[i] = s;
      is_var[i] = true;
    } else {
      views.push_back({s, &info, i, n});
      // named sub-entries: every sub-object of a RECORD/DEFSTRUCT, explicit symbols of arrays
      std::string prefix(s);
      if (prefix.back() != '_') prefix += '_'; // as append_part: never "__"
      for (std::size_t k = i; k < i + n; ++k) {
        const entry &e = d.entries[k];
        const bool is_named = info.code != od::object_code::array || !e.symbol.empty();
        if (!is_named) continue;
        char sub_suffix[8] = {'s', 'u', 'b'};
        std::size_t digits = 0;
        {
          char tmp[3];
          unsigned v = e.sub;
          do {
            tmp[digits++] = static_cast<char>('0' + v % 10U);
            v /= 10U;
          } while (v != 0U);
          for (std::size_t j = 0; j < digits; ++j) sub_suffix[3U + j] = tmp[digits - 1U - j];
        }
        const std::string_view suffix_sub(sub_suffix, 3U + digits);
        std::string_view sub_wanted = e.symbol;
        if (e.symbol.empty()) {
          sub_wanted = identifier(prefix, e.name);
          if (sub_wanted.size() == prefix.size()) { // the name has no identifier
            want.assign(s);
            append_part(want, suffix_sub);
            sub_wanted = want;
          }
        }
        named[k] = sym.take(sub_wanted, suffix_sub);
      }
    }
    i += n;
  }
  bool scales = false;
  for (const auto &e : d.entries) scales = scales || has_scale(e);

  // The tables are C arrays in namespace detail, published as static-extent spans
  // (`entries.size()` stays a constant expression): a descriptor copies `detail::entries[k]`
  // with the built-in subscript, where std::array's operator[] was one function call per
  // descriptor to evaluate at compile time (docs/performance.md, "Compile time").
  std::string scratch_bytes;
  auto table = [&](std::string_view type, std::string_view name,
                   void (*literal)(writer &, const entry &, std::string &)) {
    o.lit("inline constexpr ");
    o.put(type);
    o.put(' ');
    o.put(name);
    o.put('[');
    o.uint(d.entries.size());
    o.lit("]{\n");
    for (const entry &e : d.entries) {
      o.lit("    ");
      literal(o, e, scratch_bytes);
      o.lit(",\n");
    }
    o.lit("};\n");
  };
  // (no entries: no C arrays, a C array of length 0 is ill-formed; empty spans)
  const bool empty = d.entries.empty();
  auto span = [&](std::string_view type, std::string_view name) {
    o.lit("inline constexpr std::span<const ");
    o.put(type);
    o.lit(", ");
    o.uint(d.entries.size());
    o.lit("> ");
    o.put(name);
    if (empty) {
      o.lit("{};\n");
      return;
    }
    o.lit("{detail::");
    o.put(name);
    o.lit("};\n");
  };
  if (!empty) {
    o.lit("namespace detail {\n");
    table("od::entry", "entries", emit_core);
    o.put('\n');
    table("od::entry_info", "infos",
          [](writer &w, const entry &e, std::string &) { emit_info(w, e); });
    if (scales) {
      o.put('\n');
      table("scaling::linear", "scales",
            [](writer &w, const entry &e, std::string &) { emit_scale(w, e); });
    }
    o.lit("} // namespace detail\n\n");
  }
  span("od::entry", "entries");
  span("od::entry_info", "infos");
  if (scales) span("scaling::linear", "scales");
  o.lit("\ninline constexpr od::dictionary dictionary{entries, infos");
  if (scales) o.lit(", scales");
  o.lit("};\nstatic_assert(dictionary.is_valid());\n");
  emit_vendor_columns(o, d);
  // the kinds of values of the entries, so that code over this dictionary compiles only theirs
  {
    od::value_kinds k{false, false, false, false, false, false, false, false};
    for (const entry &e : d.entries) {
      const od::value_kinds x = od::kinds_of(od::make_entry(spec_of(e), nullptr));
      k = {k.strings || x.strings, k.real || x.real,      k.time || x.time,
           k.wide || x.wide,       k.limits || x.limits,  k.node_limits || x.node_limits,
           k.scaled || x.scaled,   k.numbers || x.numbers};
    }
    const auto b = [&o](bool v) {
      if (v) {
        o.lit("true");
      } else {
        o.lit("false");
      }
    };
    o.lit("\n// The kinds of values in the entries (od/value_kinds.hpp).\n"
          "inline constexpr od::value_kinds kinds{.strings = ");
    b(k.strings);
    o.lit(", .real = ");
    b(k.real);
    o.lit(", .time = ");
    b(k.time);
    o.lit(", .wide = ");
    b(k.wide);
    o.lit(", .limits = ");
    b(k.limits);
    o.lit(", .node_limits = ");
    b(k.node_limits);
    o.lit(", .scaled = ");
    b(k.scaled);
    o.lit(", .numbers = ");
    b(k.numbers);
    o.lit("};\n");
  }
  // a standalone descriptor: a copy of table row k, not a reference into the tables
  auto descriptor = [&](std::size_t k) {
    o.lit("inline constexpr od::descriptor ");
    o.put(named[k]);
    o.lit("{detail::entries[");
    o.uint(k);
    o.lit("], detail::infos[");
    o.uint(k);
    o.put(']');
    if (scales) {
      o.lit(", detail::scales[");
      o.uint(k);
      o.put(']');
    }
    o.lit("}; // 0x");
    o.hex(d.entries[k].index, 4);
    if (!is_var[k]) {
      o.lit(" sub ");
      o.uint(d.entries[k].sub);
    }
    o.put('\n');
  };
  o.lit(
      "\n// VAR objects: standalone descriptors (firmware that names one keeps only that one).\n");
  for (std::size_t k = 0; k < d.entries.size(); ++k) {
    if (is_var[k]) descriptor(k);
  }
  if (!views.empty()) {
    o.lit("\n// ARRAY and RECORD objects: views into the tables.\n");
    if (!d.sub_descriptors) {
      o.lit("// Sub-objects: view[sub] (generated with --no-sub-descriptors: no standalone "
            "descriptors).\n");
    }
  }
  for (const view &v : views) {
    o.lit("inline constexpr od::object ");
    o.put(v.symbol);
    o.lit("{0x");
    o.hex(v.info->index, 4);
    o.lit(", od::object_code::");
    o.put(od::info(v.info->code).identifier);
    o.lit(", ");
    append_view(o, v.info->name);
    // subspan (one non-template member) instead of {entries.data() + k, n}, which makes the
    // compiler resolve std::span's constrained constructor templates for every view: bench700
    // 7.14 -> 6.74 G instructions of g++ -fsyntax-only (docs/performance.md)
    const auto range = [&] {
      o.lit(".subspan(");
      o.uint(v.first);
      o.lit(", ");
      o.uint(v.count);
      o.put(')');
    };
    o.lit(", dictionary.entries()");
    range();
    o.lit(", dictionary.infos()");
    range();
    if (scales) {
      o.lit(", dictionary.scales()");
      range();
    }
    o.lit("};\n");
    // named sub-objects of the view: standalone descriptors too (as `view[sub]`)
    for (std::size_t k = v.first; k < v.first + v.count && d.sub_descriptors; ++k) {
      if (!named[k].empty()) descriptor(k);
    }
  }
  o.lit("\n} // namespace fieldcodec::dictionaries::");
  o.put(d.stem);
  o.lit("\n// clang-format on\n");
}

} // namespace

std::string emit_header(const dictionary &d) {
  // about 310..370 bytes per entry (three tables + names)
  writer o(d.entries.size() * 400U + d.commands.size() * 400U + 4096U);
  emit(o, d);
  return o.finish();
}

void emit_header(const dictionary &d, const header_sink &sink) {
  writer o(std::size_t{64} * 1024U, &sink);
  emit(o, d);
  o.flush();
}

} // namespace fieldcodec::gen
