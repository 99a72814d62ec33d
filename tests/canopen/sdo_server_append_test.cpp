// sdo::detail::append_parts (the SDO server's download buffer) against the byte-at-a-time loop
// it replaced for issue 18's services benchmark: the same bytes in the buffer, the same parts
// passed on at the same moments, the same errors, for every buffer size, fill and length.
#include <fieldcodec/canopen/sdo_server.hpp>

#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace sdo = fieldcodec::canopen::sdo;
using sdo::abort_code;

namespace {

/// What happened: the parts passed on (their bytes), the buffer and the result.
struct trace {
  std::vector<std::vector<std::uint8_t>> parts;
  std::vector<std::uint8_t> buffer;
  std::size_t used = 0;
  abort_code result = abort_code::none;
  bool operator==(const trace &) const = default;
};

/// The previous server::append, with the store's write as `flush`: one byte and one check at a
/// time.
template <class Flush>
abort_code reference_append(std::span<std::uint8_t> buf, std::size_t &used,
                            std::span<const std::uint8_t> bytes, Flush flush) {
  for (const std::uint8_t b : bytes) {
    if (used == buf.size()) {
      if (buf.empty()) return abort_code::out_of_memory;
      const auto c = flush();
      if (c != abort_code::none) return c;
      used = 0;
    }
    buf[used++] = b;
  }
  return abort_code::none;
}

/// Run one of the two with a flush that fails at its `fail_at`-th call (0: never).
template <bool Reference>
trace run(std::size_t capacity, std::size_t used, std::size_t length, std::size_t fail_at) {
  trace t;
  t.buffer.assign(capacity, 0xEE);
  for (std::size_t i = 0; i < used; ++i) t.buffer[i] = static_cast<std::uint8_t>(0x80U + i);
  t.used = used;
  std::vector<std::uint8_t> bytes(length);
  for (std::size_t i = 0; i < length; ++i) bytes[i] = static_cast<std::uint8_t>(i * 7U + 1U);
  std::size_t calls = 0;
  auto flush = [&]() noexcept {
    ++calls;
    if (calls == fail_at) return abort_code::general_error;
    t.parts.emplace_back(t.buffer.begin(), t.buffer.end());
    return abort_code::none;
  };
  const std::span<std::uint8_t> buf(t.buffer);
  if constexpr (Reference) {
    t.result = reference_append(buf, t.used, bytes, flush);
  } else {
    t.result = sdo::detail::append_parts(buf, t.used, bytes, flush);
  }
  return t;
}

} // namespace

TEST_CASE("append_parts equals the byte-at-a-time append") {
  std::size_t cases = 0;
  std::size_t mismatches = 0;
  for (std::size_t capacity = 0; capacity <= 20U; ++capacity) {
    for (std::size_t used = 0; used <= capacity; ++used) {
      for (std::size_t length = 0; length <= 45U; ++length) {
        for (std::size_t fail_at = 0; fail_at <= 3U; ++fail_at) {
          const trace a = run<false>(capacity, used, length, fail_at);
          const trace b = run<true>(capacity, used, length, fail_at);
          if (!(a == b)) ++mismatches;
          ++cases;
        }
      }
    }
  }
  CHECK(cases > 40000U);
  CHECK(mismatches == 0U);
  // a few outcomes spelled out: a full buffer with bytes left is passed on, an empty one cannot
  // take anything, a failing flush stops the append with its code
  const trace full = run<false>(4, 4, 5, 0);
  CHECK(full.parts.size() == 2U);
  CHECK(full.used == 1U);
  CHECK(run<false>(0, 0, 1, 0).result == abort_code::out_of_memory);
  CHECK(run<false>(0, 0, 0, 0).result == abort_code::none);
  CHECK(run<false>(3, 3, 1, 1).result == abort_code::general_error);
}
