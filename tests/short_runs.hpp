#pragma once
// How often a randomised or sweeping test repeats its check. The big-endian build runs the suite
// under qemu-user (.ci/steps/big_endian.sh), where these loops take minutes; it defines
// FIELDCODEC_TEST_SHORT_RUNS and each such test runs a tenth of its count (and expects a tenth of
// its coverage counts): every input takes the same byte paths, so a byte-order mistake shows in a
// tenth as surely as in all of them. The native builds run the full counts.
namespace fieldcodec_test {
template <class T>
constexpr T runs(T full) noexcept {
#if defined(FIELDCODEC_TEST_SHORT_RUNS)
  return full / 10 > 0 ? full / 10 : 1;
#else
  return full;
#endif
}
} // namespace fieldcodec_test
