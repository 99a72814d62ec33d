# Runs fieldcodec-gen over every *.eds / *.dcf in CORPUS and compiles all emitted headers in
# one translation unit with the project's warning flags. Fails on the first file that does
# not read or a header that does not compile.
file(GLOB files "${CORPUS}/*.eds" "${CORPUS}/*.dcf" "${CORPUS}/*.EDS" "${CORPUS}/*.DCF")
list(SORT files)
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/fieldcodec/dictionaries")
set(includes "")
set(failed "")
foreach(f IN LISTS files)
  get_filename_component(stem "${f}" NAME_WE)
  string(TOLOWER "${stem}" stem)
  string(REGEX REPLACE "[^a-z0-9]+" "_" stem "${stem}")
  string(REGEX REPLACE "^_+|_+$" "" stem "${stem}")
  execute_process(COMMAND "${GEN}" --quiet --name "${stem}"
      -o "${WORK_DIR}/fieldcodec/dictionaries/${stem}.hpp" "${f}"
    RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    list(APPEND failed "${f}")
    message("FAIL ${f} (exit ${rc}):\n${err}")
  else()
    string(APPEND includes "#include <fieldcodec/dictionaries/${stem}.hpp>\n")
  endif()
endforeach()
list(LENGTH files n)
list(LENGTH failed nf)
message("corpus: ${n} files, ${nf} failed to read")
file(WRITE "${WORK_DIR}/all.cpp" "${includes}int main() { return 0; }\n")
execute_process(COMMAND "${CXX}" -std=c++20 -Wall -Wextra -Wpedantic -Werror -Wconversion
    -Wsign-conversion -Wshadow -I${INCLUDE_DIR} -I${WORK_DIR} -c "${WORK_DIR}/all.cpp"
    -o "${WORK_DIR}/all.o"
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "emitted headers do not compile:\n${err}")
endif()
if(nf GREATER 0)
  message(FATAL_ERROR "${nf} corpus files failed")
endif()
