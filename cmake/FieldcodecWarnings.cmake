# Warning flags of the project's own targets (tests, generator, CLI, examples, fuzzers, bench;
# never exported to users, whose own flags apply to the headers they include).
#
# FIELDCODEC_WERROR makes those warnings errors. Default: on with the compilers CI proves
# warning-free in Debug and optimised builds (g++ 12, clang++ 14: Debian bookworm's), off with
# any other compiler or version, whose new diagnostics nobody has seen yet — a user who builds
# the tree with g++ 14 gets the warnings printed and a working build. CI and the presets turn it
# on explicitly (.ci/test passes -DFIELDCODEC_WERROR=ON). docs/contributing.md, "Warnings".
if((CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 12
    AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
   OR (CMAKE_CXX_COMPILER_ID STREQUAL "Clang" AND CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 14
       AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 15))
  set(fieldcodec_werror_default ON)
else()
  set(fieldcodec_werror_default OFF)
endif()
option(FIELDCODEC_WERROR "Warnings of the project's own targets are errors" ${fieldcodec_werror_default})
if(FIELDCODEC_TOP_LEVEL AND NOT FIELDCODEC_WERROR)
  message(STATUS "fieldcodec: warnings are not errors (FIELDCODEC_WERROR=OFF; CI checks g++ 12 "
    "and clang++ 14 with it on, -DFIELDCODEC_WERROR=ON to do the same)")
endif()

add_library(fieldcodec_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(fieldcodec_warnings INTERFACE
    -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Wshadow)
  if(FIELDCODEC_WERROR)
    target_compile_options(fieldcodec_warnings INTERFACE -Werror)
  endif()
endif()
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  # GCC 12's flow-based -Warray-bounds / -Wstringop-* checks run only when optimising and report
  # accesses on paths that jump threading invents after inlining, behind size checks that have
  # already returned (GCC bugs 104165, 105651 and relatives). They cannot be told apart from
  # real findings in optimised builds, so they are off; bounds are proven instead by the
  # explicit checks in the code, AddressSanitizer/UBSan runs and the fuzzers.
  target_compile_options(fieldcodec_warnings INTERFACE
    -Wno-array-bounds -Wno-stringop-overflow -Wno-stringop-overread)
  # GCC 12 reports -Wrestrict inside libstdc++'s basic_string when `"text" + std::string` is
  # inlined at -O2 and above (GCC bug 105329, fixed in GCC 13): host code (tests, CLI,
  # generator) builds strings so. The public headers build no std::string; the users' build
  # step of CI (.ci/steps/users_build.sh) compiles them with -Wrestrict on.
  if(CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(fieldcodec_warnings INTERFACE -Wno-restrict)
  endif()
endif()
