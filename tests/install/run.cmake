# Proves the packaging: install fieldcodec to a fresh prefix, then build and run a consumer
# that uses find_package(fieldcodec CONFIG REQUIRED), and one that uses add_subdirectory().
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}")
  endif()
endfunction()

set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/lib -DCMAKE_CXX_COMPILER=${CXX}
    -DFIELDCODEC_BUILD_TESTS=OFF -DFIELDCODEC_BUILD_CODEGEN=ON
    -DFIELDCODEC_BUILD_EXAMPLES=OFF -DFIELDCODEC_BUILD_FUZZERS=OFF
    -DCMAKE_INSTALL_PREFIX=${prefix})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/lib --target fieldcodec-gen)
run(${CMAKE_COMMAND} --install ${WORK_DIR}/lib)
if(NOT EXISTS ${prefix}/include/fieldcodec/core/result.hpp)
  message(FATAL_ERROR "headers were not installed")
endif()
if(NOT EXISTS ${prefix}/bin/fieldcodec-gen)
  message(FATAL_ERROR "the generator was not installed")
endif()

run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/consumer
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run(${WORK_DIR}/consumer/consumer)

run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/subproject -B ${WORK_DIR}/subproject
    -DCMAKE_CXX_COMPILER=${CXX} -DFIELDCODEC_SOURCE_DIR=${SOURCE_DIR})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/subproject)
run(${WORK_DIR}/subproject/subproject)
message(STATUS "install + find_package and add_subdirectory consumers built and ran")
