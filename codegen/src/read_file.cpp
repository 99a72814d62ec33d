#include "readers.hpp"
#include "text.hpp"

#include <fstream>
#include <iterator>
#include <sstream>

namespace fieldcodec::gen {

std::optional<dictionary> read_file(const std::string &path, diagnostics &diag) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diag.error(path, 0, 0, "cannot open file");
    return std::nullopt;
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string bytes = ss.str();
  const auto slash = path.find_last_of("/\\");
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1U);
  const auto dot = base.find_last_of('.');
  const std::string ext = to_lower(dot == std::string::npos ? "" : base.substr(dot + 1U));
  std::optional<dictionary> d;
  if (ext == "csv") {
    d = read_csv(bytes, path, diag);
  } else if (ext == "eds" || ext == "dcf") {
    d = read_eds(bytes, path, diag);
  } else {
    diag.error(path, 0, 0, "expected a file ending in .eds, .dcf or .csv");
    return std::nullopt;
  }
  if (d) {
    d->source_name = base;
    d->stem = stem_identifier(dot == std::string::npos ? base : base.substr(0, dot));
    if (ext == "dcf") d->is_dcf = true;
  }
  return d;
}

} // namespace fieldcodec::gen
