# The command-line tool's library sources (all but main.cpp), listed once: cli/CMakeLists.txt
# builds fieldcodec_cli from them, and the libFuzzer build (fuzz/CMakeLists.txt) compiles the
# same list with the harnesses' instrumentation.
set(fieldcodec_cli_sources
  ${CMAKE_CURRENT_LIST_DIR}/src/app.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/can_decoder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/dictionary.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/pacontrol_decoder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/util.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/values.cpp)
