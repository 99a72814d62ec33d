# The generator library's sources, listed once: codegen/CMakeLists.txt builds fieldcodec_codegen
# from them, and the libFuzzer build (fuzz/CMakeLists.txt), which configures no generator,
# compiles the same list with the harnesses' instrumentation.
set(fieldcodec_codegen_sources
  ${CMAKE_CURRENT_LIST_DIR}/src/checks.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/config_list.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/csv_reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/eds_reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/emit_header.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/emit_pdo.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/esi_reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/od_tables.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/options.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/read_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/sii.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/text.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/write_eds.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/write_esi.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/write_xdd.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/xdd_reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/xml.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/xml_values.cpp)
