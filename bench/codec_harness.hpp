// fieldcodec benchmarks — a tiny harness with no dependency beyond the standard library.
//
// Every operation is measured twice in the same run: the fieldcodec call and a straightforward
// hand-written implementation of the same operation (the limit fieldcodec should reach). Both
// run in the same loop over the same inputs, and both results pass through a compiler barrier,
// so neither can be optimised away or hoisted out of the loop. Before timing, every operation is
// checked: the two implementations must return the same result for every input.
//
// Usage of every bench executable (codec_core, codec_ds402, ...):
//   codec_x                         time every operation, print a table (median of repetitions)
//   codec_x --quick                 short run (CI smoke test; timings meaningless)
//   codec_x --filter TEXT           only operations whose name contains TEXT
//   codec_x --reps N                repetitions per measurement (default 9, median reported)
//   codec_x --list                  operation names, one per line
//   codec_x --check                 only compare fieldcodec against the baseline on all inputs
//   codec_x --run NAME --impl fieldcodec|baseline|empty --iterations N
//                                   exactly N iterations of one operation, nothing else (for
//                                   valgrind --tool=callgrind: instructions(2N) − instructions(N)
//                                   divided by N is instructions per operation, see callgrind.sh;
//                                   "empty" is the loop alone over the same inputs)
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace bench {

/// Compiler barrier: `v` must be computed and stored, as if the asm statement read it (a CAN
/// controller's transmit buffer, a register). No "memory" clobber: that would also force every
/// temporary whose address was ever taken to be stored, which real code does not pay for.
template <class T>
inline void keep(const T &v) noexcept {
  asm volatile("" : : "m"(v));
}

/// Number of inputs each operation cycles through (a power of two).
inline constexpr std::size_t input_count = 256;

template <class T>
using inputs = std::array<T, input_count>;

/// A deterministic pseudo-random generator for inputs (xorshift64*).
class rng {
public:
  explicit rng(std::uint64_t seed) noexcept : s_(seed | 1U) {}
  std::uint64_t next() noexcept {
    s_ ^= s_ >> 12U;
    s_ ^= s_ << 25U;
    s_ ^= s_ >> 27U;
    return s_ * 0x2545F4914F6CDD1DULL;
  }
  /// Uniform in [0, n).
  std::uint64_t below(std::uint64_t n) noexcept { return next() % n; }
  /// Uniform in [lo, hi].
  std::int64_t between(std::int64_t lo, std::int64_t hi) noexcept {
    return lo + static_cast<std::int64_t>(
                    below(static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo) + 1U));
  }

private:
  std::uint64_t s_;
};

using run_fn = void (*)(std::size_t iterations);
using check_fn = bool (*)();

struct op {
  std::string name;
  run_fn fieldcodec;
  run_fn baseline;
  check_fn check;
  run_fn empty; ///< the same loop over the same inputs, doing nothing with them
};

using registry = std::vector<op>;

template <auto &In, class F>
[[gnu::noinline]] void run(std::size_t iterations) {
  constexpr std::size_t mask = In.size() - 1U;
  static_assert((In.size() & mask) == 0U, "input count must be a power of two");
  for (std::size_t i = 0; i < iterations; ++i) {
    const auto r = F{}(In[i & mask]);
    keep(r);
  }
}

template <auto &In>
[[gnu::noinline]] void run_empty(std::size_t iterations) {
  constexpr std::size_t mask = In.size() - 1U;
  for (std::size_t i = 0; i < iterations; ++i) keep(In[i & mask]);
}

template <auto &In, class Fc, class Base>
bool check() {
  std::size_t bad = 0;
  for (const auto &x : In) {
    if (!(Fc{}(x) == Base{}(x))) ++bad;
  }
  return bad == 0U;
}

/// Register an operation over the inputs `In` (a global bench::inputs<T>): `fc` is the
/// fieldcodec call, `base` the hand-written one; both take `const T &` and return comparable
/// values.
template <auto &In, class Fc, class Base>
void add(registry &r, std::string name, Fc, Base) {
  static_assert(std::is_empty_v<Fc> && std::is_empty_v<Base>,
                "pass captureless lambdas (they are default-constructed in the loop)");
  r.push_back(
      op{std::move(name), &run<In, Fc>, &run<In, Base>, &check<In, Fc, Base>, &run_empty<In>});
}

/// Register the harness itself: an operation that only moves its input to the barrier.
template <auto &In>
void add_harness(registry &r) {
  auto id = [](const auto &x) { return x; };
  add<In>(r, "harness/empty loop", id, id);
}

namespace detail {

inline double ns_per_op(run_fn f, std::size_t iterations) {
  const auto t0 = std::chrono::steady_clock::now();
  f(iterations);
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::nano>(t1 - t0).count() /
         static_cast<double>(iterations);
}

/// Iterations so that one repetition takes about `target_ns`.
inline std::size_t calibrate(run_fn f, double target_ns) {
  std::size_t n = 64;
  for (;;) {
    const double per = ns_per_op(f, n);
    const double total = per * static_cast<double>(n);
    if (total >= target_ns / 8.0 || n >= (std::size_t{1} << 30U)) {
      const double want = target_ns / (per > 0.01 ? per : 0.01);
      return std::max<std::size_t>(64, static_cast<std::size_t>(want));
    }
    n *= 8U;
  }
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2U;
  return v.size() % 2U != 0U ? v[m] : (v[m - 1U] + v[m]) / 2.0;
}

inline int usage(const char *self) {
  std::fprintf(stderr,
               "usage: %s [--quick] [--reps N] [--filter TEXT] [--list] [--check]\n"
               "       %s --run NAME --impl fieldcodec|baseline|empty --iterations N\n",
               self, self);
  return 2;
}

} // namespace detail

/// The command line of every bench executable (see the comment at the top).
inline int main(int argc, char **argv, const registry &ops) {
  bool quick = false;
  bool list = false;
  bool check_only = false;
  std::size_t reps = 9;
  std::string filter;
  std::string run_name;
  std::string impl;
  std::size_t iterations = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    const bool has_next = i + 1 < argc;
    if (a == "--quick") {
      quick = true;
    } else if (a == "--list") {
      list = true;
    } else if (a == "--check") {
      check_only = true;
    } else if (a == "--reps" && has_next) {
      reps = static_cast<std::size_t>(std::strtoull(argv[++i], nullptr, 10));
    } else if (a == "--filter" && has_next) {
      filter = argv[++i];
    } else if (a == "--run" && has_next) {
      run_name = argv[++i];
    } else if (a == "--impl" && has_next) {
      impl = argv[++i];
    } else if (a == "--iterations" && has_next) {
      iterations = static_cast<std::size_t>(std::strtoull(argv[++i], nullptr, 10));
    } else {
      return detail::usage(argv[0]);
    }
  }

  if (!run_name.empty()) {
    for (const op &o : ops) {
      if (o.name != run_name) continue;
      if (impl == "fieldcodec") {
        o.fieldcodec(iterations);
      } else if (impl == "baseline") {
        o.baseline(iterations);
      } else if (impl == "empty") {
        o.empty(iterations);
      } else {
        return detail::usage(argv[0]);
      }
      return 0;
    }
    std::fprintf(stderr, "no operation named '%s' (see --list)\n", run_name.c_str());
    return 2;
  }

  if (list) {
    for (const op &o : ops) std::printf("%s\n", o.name.c_str());
    return 0;
  }

  int failures = 0;
  for (const op &o : ops) {
    if (!filter.empty() && o.name.find(filter) == std::string::npos) continue;
    if (!o.check()) {
      std::fprintf(stderr, "MISMATCH: fieldcodec and baseline disagree on %s\n", o.name.c_str());
      ++failures;
    }
  }
  if (check_only || failures != 0) return failures == 0 ? 0 : 1;

  if (quick) reps = 3;
  if (reps == 0U) reps = 1;
  const double target_ns = quick ? 2e5 : 5e6; // per repetition
  std::printf("%-40s %12s %12s %7s\n", "operation", "fieldcodec", "baseline", "ratio");
  std::printf("%-40s %12s %12s %7s\n", "", "ns/op", "ns/op", "");
  for (const op &o : ops) {
    if (!filter.empty() && o.name.find(filter) == std::string::npos) continue;
    const std::size_t n = std::max(detail::calibrate(o.fieldcodec, target_ns),
                                   detail::calibrate(o.baseline, target_ns));
    std::vector<double> fc;
    std::vector<double> base;
    for (std::size_t r = 0; r < reps; ++r) { // interleaved, so drifting load hits both alike
      fc.push_back(detail::ns_per_op(o.fieldcodec, n));
      base.push_back(detail::ns_per_op(o.baseline, n));
    }
    const double f = detail::median(fc);
    const double b = detail::median(base);
    std::printf("%-40s %12.2f %12.2f %7.2f\n", o.name.c_str(), f, b, b > 0.0 ? f / b : 0.0);
    std::fflush(stdout);
  }
  return 0;
}

} // namespace bench
