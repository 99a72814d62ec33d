// A doctest case that cannot run on this machine (the python canopen peer, the EDS corpus in
// ../shared, a vcan interface) says why with a "SKIPPED (kind): why" line and returns
// (tests/skip_report.py lists these lines after a run). Under CI=true it fails with the same
// message instead, unless $FIELDCODEC_CI_MAY_SKIP lists its kind (.ci/run keeps that list and
// the reasons): CI must not pass by skipping. The same rule for the tests CTest runs through a
// script: tests/run_test.sh.
#pragma once

#include <doctest/doctest.h>

#include <cstdlib>
#include <string_view>

namespace fieldcodec::test {

/// True when a test of `kind` may skip here: always outside CI, under CI=true only when
/// $FIELDCODEC_CI_MAY_SKIP names the kind (words separated by spaces or commas).
inline bool may_skip(std::string_view kind) {
  const char *ci = std::getenv("CI");
  if (ci == nullptr || std::string_view(ci) != "true") return true;
  const char *env = std::getenv("FIELDCODEC_CI_MAY_SKIP");
  std::string_view list = env != nullptr ? env : "";
  while (!list.empty()) {
    const auto end = list.find_first_of(" ,");
    if (list.substr(0, end) == kind) return true;
    if (end == std::string_view::npos) break;
    list.remove_prefix(end + 1);
  }
  return false;
}

/// Where the test material beside the repository is (../shared, or FIELDCODEC_SHARED_DIR given
/// to CMake): the python canopen peer, the EDS corpus.
inline constexpr std::string_view shared_dir = FIELDCODEC_SHARED_DIR;

} // namespace fieldcodec::test

/// Skips the rest of the test case (outside CI) or fails it (under CI=true), saying why.
#define FIELDCODEC_SKIP_TEST(kind, why)                                                            \
  do {                                                                                             \
    if (::fieldcodec::test::may_skip(kind)) {                                                      \
      MESSAGE("SKIPPED (" << kind << "): " << why);                                                \
      return;                                                                                      \
    }                                                                                              \
    FAIL("SKIPPED (" << kind << "): " << why << " -- and CI=true: a test that needs '" << kind     \
                     << "' may not skip (FIELDCODEC_CI_MAY_SKIP does not list it)");               \
  } while (false)
