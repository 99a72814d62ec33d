# Runs fieldcodec-gen over every XDD/XDC/XPD in CORPUS/xdd and every ESI in CORPUS/esi (the
# first device of a file that describes several) and compiles all emitted headers — the
# dictionaries and their PDO layouts (--pdo-header) — in one translation unit with the
# project's warning flags. A file the generator refuses must be refused with a diagnostic that
# names a place (file:line:column: error: ...); which refusals are right is checked by
# xml_corpus.py (CTest codegen_xml_corpus), which also reads every device of every ESI.
file(GLOB files "${CORPUS}/xdd/*.xdd" "${CORPUS}/xdd/*.xdc" "${CORPUS}/xdd/*.xpd"
  "${CORPUS}/esi/*.xml")
list(SORT files)
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/fieldcodec/dictionaries")
set(includes "")
set(read 0)
set(refused 0)
foreach(f IN LISTS files)
  get_filename_component(stem "${f}" NAME_WE)
  string(TOLOWER "${stem}" stem)
  string(REGEX REPLACE "[^a-z0-9]+" "_" stem "${stem}")
  string(REGEX REPLACE "^_+|_+$" "" stem "${stem}")
  string(REGEX REPLACE "^([0-9])" "n_\\1" stem "${stem}")
  set(out "${WORK_DIR}/fieldcodec/dictionaries/${stem}")
  set(device "")
  execute_process(COMMAND "${GEN}" --quiet --name "${stem}" -o "${out}.hpp"
      --pdo-header "${out}_pdos.hpp" "${f}"
    RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(rc EQUAL 1 AND err MATCHES "choose one with --device[^\n]*\n  '[^']*' \\(product code ([^,]+), revision ([^,]+),")
    set(device "${CMAKE_MATCH_1}:${CMAKE_MATCH_2}")
    execute_process(COMMAND "${GEN}" --quiet --name "${stem}" --device "${device}"
        -o "${out}.hpp" --pdo-header "${out}_pdos.hpp" "${f}"
      RESULT_VARIABLE rc ERROR_VARIABLE err)
  endif()
  if(rc EQUAL 0)
    math(EXPR read "${read} + 1")
    string(APPEND includes "#include <fieldcodec/dictionaries/${stem}.hpp>\n"
      "#include <fieldcodec/dictionaries/${stem}_pdos.hpp>\n")
  elseif(rc EQUAL 1 AND err MATCHES "[^\n]+:[0-9]+:[0-9]+: error: ")
    math(EXPR refused "${refused} + 1")
  else()
    message(FATAL_ERROR "${f}: exit ${rc} without a placed diagnostic:\n${err}")
  endif()
endforeach()
list(LENGTH files n)
message("xml corpus: ${n} XDD/XDC and ESI files, ${read} read, ${refused} refused")
file(WRITE "${WORK_DIR}/all.cpp" "${includes}int main() { return 0; }\n")
execute_process(COMMAND "${CXX}" -std=c++20 -Wall -Wextra -Wpedantic -Werror -Wconversion
    -Wsign-conversion -Wshadow -I${INCLUDE_DIR} -I${WORK_DIR} -c "${WORK_DIR}/all.cpp"
    -o "${WORK_DIR}/all.o"
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "emitted headers do not compile:\n${err}")
endif()
