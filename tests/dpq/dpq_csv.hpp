// Test helper: reads dictionaries/dpq_parameters.csv (the source of truth) at run time, so the
// conversion tests cover all 221 parameters independently of the generator. The path is
// absolute (FIELDCODEC_SOURCE_DIR, a compile definition of tests/CMakeLists.txt), so the test
// binary finds the file from any working directory.
//
// The table holds the 221 bus parameters of chapter 4 (section "4.n", scaled) and the 19
// communication objects of chapter 3 (section "3.n", raw values, no scale): load() gives every
// row, load_parameters() the chapter-4 rows.
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/number.hpp>

#include <cstdint>
#include <fstream>
#include <memory>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace dpq_test {

struct row {
  std::string section, index, subindex, object_code, name, data_type, unit, access, flags,
      default_text;
  int bytes = 0;
  fieldcodec::decimal low, high, scale, offset;
  std::string low_text, high_text, scale_text, offset_text;

  [[nodiscard]] bool has_flag(const std::string &f) const {
    return (";" + flags + ";").find(";" + f + ";") != std::string::npos;
  }
  [[nodiscard]] bool is_signed() const { return data_type.rfind("INTEGER", 0) == 0; }
  /// A bus parameter of chapter 4 (scaled); the others are communication objects of chapter 3.
  [[nodiscard]] bool is_parameter() const { return section.rfind("4.", 0) == 0; }
  /// The row as a descriptor built here from the CSV (independent of the generator): type
  /// from bytes and signedness, scale and offset, printed range.
  /// Its packed columns (the printed range) live in the row: valid while the row is.
  [[nodiscard]] fieldcodec::od::descriptor descriptor() const {
    namespace od = fieldcodec::od;
    od::entry_spec e;
    e.type = bytes == 2 ? (is_signed() ? od::data_type::integer16 : od::data_type::unsigned16)
                        : (is_signed() ? od::data_type::integer32 : od::data_type::unsigned32);
    e.flags = od::flag::scaled;
    e.low = od::decimal_number(low);
    e.high = od::decimal_number(high);
    packed = std::make_shared<char[]>(od::packed_size(e));
    (void)od::pack(e, std::span<char>(packed.get(), od::packed_size(e)));
    od::descriptor d{od::make_entry(e, packed.get())};
    d.scale = {scale, offset};
    return d;
  }
  mutable std::shared_ptr<char[]> packed;
};

// RFC 4180 fields of one line (the DPQ table has no line breaks inside fields).
inline std::vector<std::string> split_csv(const std::string &line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        out.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

// A decimal as printed ("327.67", "-100"), or a raw hexadecimal value ("0xFFFF", the style of
// the chapter-3 rows).
inline fieldcodec::decimal parse(const std::string &s, bool &ok) {
  if (s.size() > 2 && s[0] == '0' && s[1] == 'x') {
    std::size_t used = 0;
    const unsigned long long v = std::stoull(s.substr(2), &used, 16);
    if (used != s.size() - 2 || v > 0x7FFFFFFFFFFFFFFFULL) {
      ok = false;
      return {};
    }
    return fieldcodec::decimal{static_cast<std::int64_t>(v), 0};
  }
  auto d = fieldcodec::parse_decimal(s);
  if (!d) {
    ok = false;
    return {};
  }
  return d.value();
}

#ifndef FIELDCODEC_SOURCE_DIR
#error "FIELDCODEC_SOURCE_DIR (the repository's absolute path) comes from tests/CMakeLists.txt"
#endif
inline constexpr const char *csv_path = FIELDCODEC_SOURCE_DIR "/dictionaries/dpq_parameters.csv";

// Every row; empty on any error (the tests then fail on the row count). An empty number
// (`low`, `high`, `scale`, `offset` of a chapter-3 row) reads as 0 and keeps its empty text.
inline std::vector<row> load(const char *path = csv_path) {
  std::ifstream in(path);
  std::vector<row> rows;
  std::string line;
  if (!std::getline(in, line)) return {};
  const auto header = split_csv(line);
  auto col = [&](const char *n) {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == n) return i;
    }
    return header.size();
  };
  const std::size_t c_section = col("section"), c_index = col("index"), c_name = col("name"),
                    c_type = col("data_type"), c_bytes = col("bytes"), c_unit = col("unit"),
                    c_access = col("access"), c_low = col("low"), c_high = col("high"),
                    c_scale = col("scale"), c_offset = col("offset"), c_flags = col("flags"),
                    c_sub = col("subindex"), c_code = col("object_code"),
                    c_default = col("default");
  for (const std::size_t c : {c_section, c_index, c_name, c_type, c_bytes, c_unit, c_access, c_low,
                              c_high, c_scale, c_offset, c_flags, c_sub, c_code, c_default}) {
    if (c == header.size()) return {};
  }
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto f = split_csv(line);
    if (f.size() != header.size()) return {};
    row r;
    bool ok = true;
    r.section = f[c_section];
    r.index = f[c_index];
    r.subindex = f[c_sub];
    r.object_code = f[c_code];
    r.default_text = f[c_default];
    r.name = f[c_name];
    r.data_type = f[c_type];
    r.bytes = std::stoi(f[c_bytes]);
    r.unit = f[c_unit];
    r.access = f[c_access];
    r.flags = f[c_flags];
    r.low_text = f[c_low];
    r.high_text = f[c_high];
    r.scale_text = f[c_scale];
    r.offset_text = f[c_offset];
    auto number = [&ok](const std::string &text) {
      return text.empty() ? fieldcodec::decimal{} : parse(text, ok);
    };
    r.low = number(f[c_low]);
    r.high = number(f[c_high]);
    r.scale = number(f[c_scale]);
    r.offset = number(f[c_offset]);
    // a bus parameter has every number printed
    if (r.is_parameter() && (r.low_text.empty() || r.high_text.empty() || r.scale_text.empty() ||
                             r.offset_text.empty())) {
      return {};
    }
    if (!ok) return {};
    rows.push_back(r);
  }
  return rows;
}

// The 221 bus parameters of chapter 4, in file order.
inline std::vector<row> load_parameters(const char *path = csv_path) {
  std::vector<row> out;
  for (auto &r : load(path)) {
    if (r.is_parameter()) out.push_back(std::move(r));
  }
  return out;
}

} // namespace dpq_test
