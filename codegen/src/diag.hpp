// fieldcodec-gen — compiler-style diagnostics: file:line:column: error|warning: message
#pragma once

#include <algorithm>
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

/// Collects diagnostics. Under `strict`, warnings are reported as errors. After `max_errors`
/// errors further errors are dropped; `stopped_at()` names the error that reached the limit,
/// and the readers stop reading there.
class diagnostics {
public:
  bool strict = false;
  std::size_t max_errors = 50;

  void error(const std::string &file, int line, int column, std::string msg) {
    add(severity::error, file, line, column, std::move(msg));
  }
  void warning(const std::string &file, int line, int column, std::string msg) {
    add(strict ? severity::error : severity::warning, file, line, column, std::move(msg));
  }
  [[nodiscard]] std::size_t error_count() const noexcept { return errors_; }
  [[nodiscard]] std::size_t warning_count() const noexcept { return list_.size() - errors_; }
  [[nodiscard]] bool has_errors() const noexcept { return errors_ != 0; }
  [[nodiscard]] bool too_many() const noexcept { return errors_ >= max_errors; }
  /// The error that reached `max_errors` (only meaningful when too_many()).
  [[nodiscard]] const diagnostic &stopped_at() const noexcept { return stop_; }
  /// In the order they were reported.
  [[nodiscard]] const std::vector<diagnostic> &all() const noexcept { return list_; }

  /// In line order: by file, then line, then column (reports about the whole file, line 0,
  /// first); the order of reporting among equals.
  [[nodiscard]] std::vector<diagnostic> sorted() const {
    std::vector<diagnostic> v = list_;
    std::stable_sort(v.begin(), v.end(), [](const diagnostic &a, const diagnostic &b) {
      if (a.file != b.file) return a.file < b.file;
      if (a.line != b.line) return a.line < b.line;
      return a.column < b.column;
    });
    return v;
  }

  /// "file:line:column: error: message" (line/column left out when 0).
  [[nodiscard]] static std::string format(const diagnostic &d) {
    std::string s = location(d);
    s += d.sev == severity::error ? ": error: " : ": warning: ";
    s += d.message;
    return s;
  }
  /// "file:line:column" (line/column left out when 0).
  [[nodiscard]] static std::string location(const diagnostic &d) {
    std::string s = d.file;
    if (d.line > 0) {
      s += ':' + std::to_string(d.line);
      if (d.column > 0) s += ':' + std::to_string(d.column);
    }
    return s;
  }
  /// "3 errors, 1 warning".
  [[nodiscard]] std::string summary() const {
    const std::size_t w = warning_count();
    return std::to_string(errors_) + (errors_ == 1U ? " error, " : " errors, ") +
           std::to_string(w) + (w == 1U ? " warning" : " warnings");
  }
  /// Every diagnostic in line order, then (when the limit was reached) where reading stopped.
  void print(std::ostream &os, bool warnings = true) const { os << text(warnings); }
  /// What print() prints (fieldcodec-gen writes it without iostreams, whose start-up it saves).
  [[nodiscard]] std::string text(bool warnings = true) const {
    std::string out;
    for (const auto &d : sorted()) {
      if (warnings || d.sev == severity::error) out += format(d) + '\n';
    }
    if (too_many()) out += stop_message() + '\n';
    return out;
  }
  /// "file:line:col: error: too many errors (50); reading stopped here, later problems are not
  /// reported".
  [[nodiscard]] std::string stop_message() const {
    return location(stop_) + ": error: too many errors (" + std::to_string(max_errors) +
           "); reading stopped here, later problems are not reported";
  }

private:
  void add(severity s, const std::string &file, int line, int column, std::string msg) {
    if (s == severity::error) {
      if (errors_ >= max_errors) return;
      ++errors_;
      if (errors_ == max_errors) stop_ = {s, file, line, column, msg};
    }
    list_.push_back({s, file, line, column, std::move(msg)});
  }
  std::vector<diagnostic> list_;
  std::size_t errors_ = 0;
  diagnostic stop_;
};

} // namespace fieldcodec::gen
