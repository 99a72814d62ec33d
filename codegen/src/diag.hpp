// fieldcodec-gen — compiler-style diagnostics: file:line:column: error|warning: message
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace fieldcodec::gen {

enum class severity { warning, error };

struct diagnostic {
  severity sev = severity::error;
  std::string file;
  int line = 0;   ///< 1-based, 0 when not about a line
  int column = 0; ///< 1-based, 0 when not about a column
  std::string message;
};

/// Collects diagnostics. Under `strict`, warnings are reported as errors.
class diagnostics {
public:
  bool strict = false;
  std::size_t max_errors = 50; ///< after this many errors, further ones are dropped

  void error(const std::string &file, int line, int column, std::string msg) {
    add(severity::error, file, line, column, std::move(msg));
  }
  void warning(const std::string &file, int line, int column, std::string msg) {
    add(strict ? severity::error : severity::warning, file, line, column, std::move(msg));
  }
  [[nodiscard]] std::size_t error_count() const noexcept { return errors_; }
  [[nodiscard]] bool has_errors() const noexcept { return errors_ != 0; }
  [[nodiscard]] bool too_many() const noexcept { return errors_ >= max_errors; }
  [[nodiscard]] const std::vector<diagnostic> &all() const noexcept { return list_; }

  /// "file:line:column: error: message" (line/column left out when 0).
  [[nodiscard]] static std::string format(const diagnostic &d) {
    std::string s = d.file;
    if (d.line > 0) {
      s += ':' + std::to_string(d.line);
      if (d.column > 0) s += ':' + std::to_string(d.column);
    }
    s += d.sev == severity::error ? ": error: " : ": warning: ";
    s += d.message;
    return s;
  }
  void print(std::ostream &os) const {
    for (const auto &d : list_) os << format(d) << '\n';
  }

private:
  void add(severity s, const std::string &file, int line, int column, std::string msg) {
    if (s == severity::error) {
      if (errors_ >= max_errors) return;
      ++errors_;
    }
    list_.push_back({s, file, line, column, std::move(msg)});
  }
  std::vector<diagnostic> list_;
  std::size_t errors_ = 0;
};

} // namespace fieldcodec::gen
