# Included at the end of the top-level CMakeLists.txt (cmake_language DEFER in
# codegen/CMakeLists.txt), when tests/ has defined its targets.
if(TARGET test_codegen)
  target_link_libraries(test_codegen PRIVATE fieldcodec_codegen)
endif()

# The CLI: exit codes 0 / 1 / 2, --help, --check.
add_test(NAME codegen_cli
  COMMAND ${CMAKE_COMMAND}
    -DGEN=$<TARGET_FILE:fieldcodec-gen>
    -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/codegen_cli
    -P ${PROJECT_SOURCE_DIR}/tests/codegen/cli.cmake)

# The checked-in generated headers are what the generator writes today.
add_test(NAME codegen_drift
  COMMAND ${PROJECT_SOURCE_DIR}/codegen/regenerate.sh --check --gen $<TARGET_FILE:fieldcodec-gen>)

# Every real EDS/DCF of the shared corpus is read and its header compiles. Without the corpus
# folder the test says so and is skipped (a failure under CI=true, tests/run_test.sh).
# FIELDCODEC_EDS_CORPUS names another folder; empty (the default) follows FIELDCODEC_SHARED_DIR,
# also when that changes after the first configure.
set(FIELDCODEC_EDS_CORPUS "" CACHE PATH
  "Folder of real EDS/DCF files for the corpus test (empty: FIELDCODEC_SHARED_DIR/eds-corpus)")
set(fieldcodec_eds_corpus "${FIELDCODEC_EDS_CORPUS}")
if(NOT fieldcodec_eds_corpus)
  set(fieldcodec_eds_corpus "${FIELDCODEC_SHARED_DIR}/eds-corpus")
endif()
if(EXISTS "${fieldcodec_eds_corpus}")
  add_test(NAME codegen_corpus
    COMMAND ${CMAKE_COMMAND}
      -DGEN=$<TARGET_FILE:fieldcodec-gen>
      -DCORPUS=${fieldcodec_eds_corpus}
      -DCXX=${CMAKE_CXX_COMPILER}
      -DINCLUDE_DIR=${PROJECT_SOURCE_DIR}/include
      -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/codegen_corpus
      -P ${PROJECT_SOURCE_DIR}/tests/codegen/corpus.cmake)
else()
  add_test(NAME codegen_corpus
    COMMAND sh ${PROJECT_SOURCE_DIR}/tests/run_test.sh corpus skip
      "EDS corpus not found at ${fieldcodec_eds_corpus}")
  set_tests_properties(codegen_corpus PROPERTIES SKIP_RETURN_CODE 77)
endif()

# Every XDD/XDC (and ESI) of the shared XML corpus is read or refused with a placed diagnostic,
# and the headers of all it reads compile in one translation unit; xml_corpus.py checks each
# file's objects, defaults and PDO entries against its own reading with python's xml.etree (and
# that each refusal names a defect it finds itself). Without the corpus folder
# (FIELDCODEC_XML_CORPUS; empty: FIELDCODEC_SHARED_DIR/xml-corpus) both say so and are skipped,
# and python3 missing skips the second; under CI=true either fails (tests/run_test.sh).
set(FIELDCODEC_XML_CORPUS "" CACHE PATH
  "Folder of XDD/XDC and ESI files for the XML corpus tests (empty: SHARED_DIR/xml-corpus)")
set(fieldcodec_xml_corpus "${FIELDCODEC_XML_CORPUS}")
if(NOT fieldcodec_xml_corpus)
  set(fieldcodec_xml_corpus "${FIELDCODEC_SHARED_DIR}/xml-corpus")
endif()
if(EXISTS "${fieldcodec_xml_corpus}")
  add_test(NAME codegen_xml_corpus_headers
    COMMAND ${CMAKE_COMMAND}
      -DGEN=$<TARGET_FILE:fieldcodec-gen>
      -DCORPUS=${fieldcodec_xml_corpus}
      -DCXX=${CMAKE_CXX_COMPILER}
      -DINCLUDE_DIR=${PROJECT_SOURCE_DIR}/include
      -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/codegen_xml_corpus_headers
      -P ${PROJECT_SOURCE_DIR}/tests/codegen/xml_corpus.cmake)
  add_test(NAME codegen_xml_corpus
    COMMAND sh ${PROJECT_SOURCE_DIR}/tests/run_test.sh python python3
      ${PROJECT_SOURCE_DIR}/tests/codegen/xml_corpus.py $<TARGET_FILE:fieldcodec-gen>
      ${fieldcodec_xml_corpus} ${CMAKE_CURRENT_BINARY_DIR}/codegen_xml_corpus)
  set_tests_properties(codegen_xml_corpus PROPERTIES SKIP_RETURN_CODE 77)
else()
  foreach(name codegen_xml_corpus_headers codegen_xml_corpus)
    add_test(NAME ${name}
      COMMAND sh ${PROJECT_SOURCE_DIR}/tests/run_test.sh corpus skip
        "XML corpus not found at ${fieldcodec_xml_corpus}")
    set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 77)
  endforeach()
endif()

# fieldcodec_generate_dictionary() in a user project (fieldcodec added as a subproject). The
# project is configured afresh: a cache left by another compiler is reset by CMake, which drops
# the -D options and fails the configuration.
add_test(NAME codegen_cmake_function_clean
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${CMAKE_CURRENT_BINARY_DIR}/codegen_cmake_function)
set_tests_properties(codegen_cmake_function_clean PROPERTIES FIXTURES_SETUP codegen_cmake_function)
add_test(NAME codegen_cmake_function
  COMMAND ${CMAKE_CTEST_COMMAND} --build-and-test
    ${PROJECT_SOURCE_DIR}/tests/codegen/cmake_function
    ${CMAKE_CURRENT_BINARY_DIR}/codegen_cmake_function
    --build-generator ${CMAKE_GENERATOR}
    --build-options -DFIELDCODEC_SOURCE_DIR=${PROJECT_SOURCE_DIR}
      -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
    --test-command user)
set_tests_properties(codegen_cmake_function PROPERTIES FIXTURES_REQUIRED codegen_cmake_function)

# The DPQ EDS export (dictionaries/export/) is a clean CiA 306 file: read back with --strict.
add_test(NAME codegen_export_strict
  COMMAND fieldcodec-gen --strict ${PROJECT_SOURCE_DIR}/dictionaries/export/dpq_parameters.eds)
