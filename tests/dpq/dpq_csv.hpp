// Test helper: reads dictionaries/dpq_parameters.csv (the source of truth) at run time, so the
// conversion tests cover all 221 parameters independently of the generator. Tests run in
// tests/, so the file is ../dictionaries/dpq_parameters.csv.
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/number.hpp>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace dpq_test {

struct row {
  std::string section, index, name, data_type, unit, access, flags;
  int bytes = 0;
  fieldcodec::decimal low, high, scale, offset;
  std::string low_text, high_text, scale_text, offset_text;

  [[nodiscard]] bool has_flag(const std::string &f) const {
    return (";" + flags + ";").find(";" + f + ";") != std::string::npos;
  }
  [[nodiscard]] bool is_signed() const { return data_type.rfind("INTEGER", 0) == 0; }
  /// The row as a descriptor built here from the CSV (independent of the generator): type
  /// from bytes and signedness, scale and offset, printed range.
  [[nodiscard]] fieldcodec::od::descriptor descriptor() const {
    namespace od = fieldcodec::od;
    od::descriptor d;
    d.type = bytes == 2 ? (is_signed() ? od::data_type::integer16 : od::data_type::unsigned16)
                        : (is_signed() ? od::data_type::integer32 : od::data_type::unsigned32);
    d.flags = od::flag::scaled;
    d.low = od::decimal_number(low);
    d.high = od::decimal_number(high);
    d.scale = {scale, offset};
    return d;
  }
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

inline fieldcodec::decimal parse(const std::string &s, bool &ok) {
  auto d = fieldcodec::parse_decimal(s);
  if (!d) {
    ok = false;
    return {};
  }
  return d.value();
}

// Empty on any error (the tests then fail on the row count).
inline std::vector<row> load(const char *path = "../dictionaries/dpq_parameters.csv") {
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
                    c_scale = col("scale"), c_offset = col("offset"), c_flags = col("flags");
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto f = split_csv(line);
    if (f.size() != header.size()) return {};
    row r;
    bool ok = true;
    r.section = f[c_section];
    r.index = f[c_index];
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
    r.low = parse(f[c_low], ok);
    r.high = parse(f[c_high], ok);
    r.scale = parse(f[c_scale], ok);
    r.offset = parse(f[c_offset], ok);
    if (!ok) return {};
    rows.push_back(r);
  }
  return rows;
}

} // namespace dpq_test
