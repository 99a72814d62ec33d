// Benchmarks of od::dictionary lookup (binary search) against a hand-written binary search over
// the same entries, for dictionaries of 16 to 8192 entries (the cost must grow as log n).
#include "codec_harness.hpp"

#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace {

namespace od = fieldcodec::od;

struct key {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  bool operator==(const key &) const = default;
};

template <std::size_t N>
struct dict {
  static inline std::array<od::entry, N> entries{};
  static inline bench::inputs<key> keys{};
};

/// A dictionary shaped like a generated one: objects from 0x1000 up, 1..4 sub-entries each.
/// 90 % of the keys exist, 10 % do not.
template <std::size_t N>
void fill(bench::rng &r) {
  auto &e = dict<N>::entries;
  std::uint16_t index = 0x1000;
  std::size_t i = 0;
  while (i < N) {
    const auto subs = static_cast<std::size_t>(r.between(1, 4));
    for (std::size_t s = 0; s < subs && i < N; ++s, ++i) {
      e[i].index = index;
      e[i].sub = static_cast<std::uint8_t>(s);
    }
    index = static_cast<std::uint16_t>(index + r.between(1, 3));
  }
  for (auto &k : dict<N>::keys) {
    const od::entry &x = e[r.below(N)];
    k = {x.index, x.sub};
    if (r.below(10) == 0U) k.sub = 0xFE; // a miss
  }
}

template <std::size_t N>
void add_lookup(bench::registry &r) {
  bench::add<dict<N>::keys>(
      r, "od/dictionary::find n=" + std::to_string(N),
      [](const key &k) {
        const od::dictionary d{dict<N>::entries};
        return d.find(k.index, k.sub);
      },
      [](const key &k) -> const od::entry * {
        // hand-written: binary search on the combined 24-bit key
        const od::entry *e = dict<N>::entries.data();
        const std::uint32_t want = (std::uint32_t{k.index} << 8U) | k.sub;
        std::size_t lo = 0;
        std::size_t hi = N;
        while (lo < hi) {
          const std::size_t mid = (lo + hi) / 2U;
          const std::uint32_t have = (std::uint32_t{e[mid].index} << 8U) | e[mid].sub;
          if (have < want) {
            lo = mid + 1U;
          } else {
            hi = mid;
          }
        }
        if (lo < N && e[lo].index == k.index && e[lo].sub == k.sub) return &e[lo];
        return nullptr;
      });
}

bench::registry make_registry() {
  bench::rng rng(1000);
  fill<16>(rng);
  fill<128>(rng);
  fill<1000>(rng);
  fill<8192>(rng);
  bench::registry r;
  bench::add_harness<dict<16>::keys>(r);
  add_lookup<16>(r);
  add_lookup<128>(r);
  add_lookup<1000>(r);
  add_lookup<8192>(r);
  return r;
}

} // namespace

int main(int argc, char **argv) { return bench::main(argc, argv, make_registry()); }
