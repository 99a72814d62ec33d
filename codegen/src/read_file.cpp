#include "readers.hpp"
#include "text.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>

namespace fieldcodec::gen {

const char *read_bytes(const std::string &path, std::string &out) {
  // One buffer filled block by block: a stream copied through a stringstream cost two more
  // copies of the file.
  const std::unique_ptr<std::FILE, int (*)(std::FILE *)> in(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!in) return "cannot open file";
  // The first block holds a regular file whole (its size + 1, to see the end at once).
  std::size_t first = std::size_t{1} << 16U;
  if (std::fseek(in.get(), 0, SEEK_END) == 0) {
    const long size = std::ftell(in.get());
    if (size > 0) first = std::max(first, static_cast<std::size_t>(size) + 1U);
    std::rewind(in.get());
  }
  out.clear();
  std::size_t used = 0;
  for (std::size_t block = first;; block *= 2U) {
    out.resize(used + block);
    const std::size_t got = std::fread(out.data() + used, 1, block, in.get());
    used += got;
    if (got < block) break;
  }
  out.resize(used);
  if (std::ferror(in.get()) != 0) return "cannot read file";
  return nullptr;
}

std::optional<dictionary> read_file(const std::string &path, diagnostics &diag) {
  std::string bytes;
  if (const char *failed = read_bytes(path, bytes)) {
    diag.error(path, 0, 0, failed);
    return std::nullopt;
  }
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
