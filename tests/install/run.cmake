# Proves the packaging with the recipes of README.md and docs/generator.md, run as printed: each
# recipe is the fenced block after a `<!-- recipe: NAME -->` line. Only the install prefix
# (/opt/fieldcodec), the folders, the compiler and install-sh's optimisation level (-O0, below)
# are substituted.
#   install-sh                 configure, build and install to a fresh prefix
#   find-package-cmake         a consumer that finds the installed package
#   generate-installed-cmake   the installed generator turns an EDS into a header at build time
#   subproject-cmake           add_subdirectory(): tests, generator, examples, fuzzers stay off
#   generate-subproject-cmake  add_subdirectory() with the generator switched on
#   plain-sh                   a plain include path
# The recipes' `cmake --build` lines use every core (the generator they build is this test's
# longest part; CTest runs the other tests beside it).
cmake_host_system_information(RESULT cores QUERY NUMBER_OF_LOGICAL_CORES)
set(ENV{CMAKE_BUILD_PARALLEL_LEVEL} ${cores})
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}")
  endif()
endfunction()

# recipe(<var> <file> <name>): the lines of the fenced block after `<!-- recipe: name -->`.
function(recipe var file name)
  # Split into lines without letting CMake's list syntax see the file's ';' and '\'.
  file(READ ${file} text)
  string(REPLACE "\\" "@FC_BACKSLASH@" text "${text}")
  string(REPLACE ";" "@FC_SEMICOLON@" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(state 0)
  set(body "")
  foreach(line IN LISTS lines)
    if(state EQUAL 0 AND line STREQUAL "<!-- recipe: ${name} -->")
      set(state 1)
    elseif(state EQUAL 1 AND line MATCHES "^```")
      set(state 2)
    elseif(state EQUAL 2 AND line MATCHES "^```")
      set(state 3)
      break()
    elseif(state EQUAL 2)
      string(APPEND body "${line}\n")
    endif()
  endforeach()
  if(NOT state EQUAL 3)
    message(FATAL_ERROR "${file}: no recipe '${name}'")
  endif()
  string(REPLACE "@FC_SEMICOLON@" ";" body "${body}")
  string(REPLACE "@FC_BACKSLASH@" "\\" body "${body}")
  set(${var} "${body}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(readme ${SOURCE_DIR}/README.md)
set(generator_doc ${SOURCE_DIR}/docs/generator.md)

# --- install-sh: run in the source folder, into a build folder of the work dir --------------
recipe(install ${readme} install-sh)
string(REPLACE "/opt/fieldcodec" "${prefix}" install "${install}")
string(REPLACE "build-install" "${WORK_DIR}/build-install" install "${install}")
string(REPLACE "cmake -S" "cmake -DCMAKE_CXX_COMPILER=${CXX} -S" install "${install}")
# The recipe's Release build, without the optimiser: this test proves the packaging (what is
# installed and how a consumer finds it); the generator and the CLI are compiled optimised by the
# build that runs this test. At -O3 the two programs took two of this test's three minutes.
string(REPLACE "-DCMAKE_BUILD_TYPE=Release" "-DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O0"
  install "${install}")
string(REPLACE "cmake " "${CMAKE_COMMAND} " install "${install}")
run(sh -ec "cd '${SOURCE_DIR}'\n${install}")
foreach(f include/fieldcodec/core/result.hpp bin/fieldcodec-gen
    share/cmake/fieldcodec/fieldcodecConfig.cmake share/cmake/fieldcodec/FieldcodecGenerate.cmake)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "install-sh did not install ${f}")
  endif()
endforeach()
# The command-line tool is installed beside the generator (Linux: host adapters available).
if(CMAKE_HOST_SYSTEM_NAME STREQUAL "Linux")
  if(NOT EXISTS ${prefix}/bin/fieldcodec)
    message(FATAL_ERROR "install-sh did not install bin/fieldcodec")
  endif()
  execute_process(COMMAND ${prefix}/bin/fieldcodec decode --help RESULT_VARIABLE rc
    OUTPUT_VARIABLE help ERROR_VARIABLE help)
  if(NOT rc EQUAL 0 OR NOT help MATCHES "usage: fieldcodec decode")
    message(FATAL_ERROR "the installed fieldcodec does not run (${rc}): ${help}")
  endif()
endif()

# A consumer project: the recipe's CMake block after `add_executable(<target> <main>)`.
function(consumer dir target main block)
  file(MAKE_DIRECTORY ${dir})
  file(WRITE ${dir}/CMakeLists.txt
    "cmake_minimum_required(VERSION 3.20)\nproject(consumer LANGUAGES CXX)\n"
    "set(CMAKE_CXX_STANDARD 20)\nset(CMAKE_CXX_STANDARD_REQUIRED ON)\n"
    "add_executable(${target} ${main})\n${block}")
endfunction()

# --- find-package-cmake + the generator of the installed package -------------------------
recipe(find_block ${readme} find-package-cmake)
# The package also exports the host adapters' target (FIELDCODEC_HOST, on for a Linux build).
consumer(${WORK_DIR}/find_package app ${SOURCE_DIR}/tests/install/main.cpp "${find_block}
if(NOT TARGET fieldcodec::host)
  message(FATAL_ERROR \"the installed package does not export fieldcodec::host\")
endif()
")
run(${CMAKE_COMMAND} -S ${WORK_DIR}/find_package -B ${WORK_DIR}/find_package/build
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/find_package/build)
run(${WORK_DIR}/find_package/build/app)

recipe(gen_installed ${generator_doc} generate-installed-cmake)
set(dir ${WORK_DIR}/generate_installed)
file(MAKE_DIRECTORY ${dir}/devices)
configure_file(${SOURCE_DIR}/tests/install/drive.eds ${dir}/devices/drive.eds COPYONLY)
consumer(${dir} my_app ${SOURCE_DIR}/tests/install/generated.cpp "${gen_installed}")
run(${CMAKE_COMMAND} -S ${dir} -B ${dir}/build -DCMAKE_CXX_COMPILER=${CXX}
    -DCMAKE_PREFIX_PATH=${prefix})
run(${CMAKE_COMMAND} --build ${dir}/build)
run(${dir}/build/my_app)

# --- subproject-cmake: fieldcodec as third_party/fieldcodec --------------------------------
recipe(sub_block ${readme} subproject-cmake)
set(dir ${WORK_DIR}/subproject)
file(MAKE_DIRECTORY ${dir}/third_party)
file(CREATE_LINK ${SOURCE_DIR} ${dir}/third_party/fieldcodec SYMBOLIC)
consumer(${dir} app ${SOURCE_DIR}/tests/install/main.cpp "${sub_block}
foreach(opt TESTS CODEGEN EXAMPLES FUZZERS BENCH INSTALL HOST)
  if(FIELDCODEC_BUILD_\${opt} OR FIELDCODEC_\${opt})
    message(FATAL_ERROR \"FIELDCODEC_BUILD_\${opt} is on in a subproject\")
  endif()
endforeach()
if(TARGET fieldcodec_test_main OR TARGET fieldcodec-gen OR TARGET fieldcodec::host)
  message(FATAL_ERROR \"tests or the generator were configured in a subproject\")
endif()
")
run(${CMAKE_COMMAND} -S ${dir} -B ${dir}/build -DCMAKE_CXX_COMPILER=${CXX})
run(${CMAKE_COMMAND} --build ${dir}/build)
run(${dir}/build/app)

recipe(gen_sub ${generator_doc} generate-subproject-cmake)
set(dir ${WORK_DIR}/generate_subproject)
file(MAKE_DIRECTORY ${dir}/third_party ${dir}/devices)
file(CREATE_LINK ${SOURCE_DIR} ${dir}/third_party/fieldcodec SYMBOLIC)
configure_file(${SOURCE_DIR}/tests/install/drive.eds ${dir}/devices/drive.eds COPYONLY)
consumer(${dir} my_app ${SOURCE_DIR}/tests/install/generated.cpp "${gen_sub}")
run(${CMAKE_COMMAND} -S ${dir} -B ${dir}/build -DCMAKE_CXX_COMPILER=${CXX})
run(${CMAKE_COMMAND} --build ${dir}/build --target my_app)
run(${dir}/build/my_app)

# --- plain-sh: g++ -I fieldcodec/include app.cpp ---------------------------------------------
recipe(plain ${readme} plain-sh)
set(dir ${WORK_DIR}/plain)
file(MAKE_DIRECTORY ${dir})
file(CREATE_LINK ${SOURCE_DIR} ${dir}/fieldcodec SYMBOLIC)
configure_file(${SOURCE_DIR}/tests/install/main.cpp ${dir}/app.cpp COPYONLY)
string(REGEX REPLACE "^g\\+\\+" "${CXX}" plain "${plain}")
run(sh -ec "cd '${dir}'\n${plain}")
run(${dir}/a.out)

message(STATUS "README and docs/generator.md recipes: installed, consumed, generated, included")
