#include "readers.hpp"
#include "text.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <system_error>

#if __has_include(<sys/mman.h>) && __has_include(<sys/stat.h>) && __has_include(<fcntl.h>) && \
    __has_include(<unistd.h>)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#define FIELDCODEC_GEN_MMAP 1
#endif

namespace fieldcodec::gen {

const char *read_bytes(const std::string &path, std::string &out) {
  // One buffer filled block by block: a stream copied through a stringstream cost two more
  // copies of the file.
  const std::unique_ptr<std::FILE, int (*)(std::FILE *)> in(std::fopen(path.c_str(), "rb"),
                                                            &std::fclose);
  if (!in) return "cannot open file";
  // The first block holds a regular file whole (its size + 1, to see the end at once).
  // (Only a regular file's size is a size: ftell of a directory is LONG_MAX on Linux.)
  std::size_t first = std::size_t{1} << 16U;
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) {
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size < (std::uintmax_t{1} << 32U)) {
      first = std::max(first, static_cast<std::size_t>(size) + 1U);
    }
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

file_bytes::~file_bytes() {
#ifdef FIELDCODEC_GEN_MMAP
  if (map_ != nullptr) ::munmap(map_, map_size_);
#endif
}

const char *file_bytes::load(const std::string &path) {
#ifdef FIELDCODEC_GEN_MMAP
  // Mapped, a file costs a few page faults (the kernel maps cached pages around each one)
  // instead of a buffer's worth of fresh pages and a copy: a measurable part of a generator run.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return "cannot open file";
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    const auto size = static_cast<std::size_t>(st.st_size);
    void *const m = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    if (m != MAP_FAILED) {
      ::close(fd);
      map_ = m;
      map_size_ = size;
      view_ = {static_cast<const char *>(m), size};
      return nullptr;
    }
  }
  ::close(fd);
#endif
  if (const char *failed = read_bytes(path, buffer_)) return failed;
  view_ = buffer_;
  return nullptr;
}

std::optional<dictionary> read_file(const std::string &path, diagnostics &diag,
                                    const read_options &options) {
  file_bytes file;
  if (const char *failed = file.load(path)) {
    diag.error(path, 0, 0, failed);
    return std::nullopt;
  }
  const std::string_view bytes = file.view();
  const auto slash = path.find_last_of("/\\");
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1U);
  const auto dot = base.find_last_of('.');
  const std::string ext = to_lower(dot == std::string::npos ? "" : base.substr(dot + 1U));
  std::optional<dictionary> d;
  if (ext == "csv") {
    d = read_csv(bytes, path, diag);
  } else if (ext == "eds" || ext == "dcf") {
    d = read_eds(bytes, path, diag);
  } else if (ext == "xdd" || ext == "xdc" || ext == "xpd") {
    d = read_xdd(bytes, path, diag);
  } else if (ext == "xml") {
    d = read_esi(bytes, path, diag, options.device);
  } else {
    diag.error(path, 0, 0, "expected a file ending in .eds, .dcf, .csv, .xdd, .xdc, .xpd or .xml");
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
