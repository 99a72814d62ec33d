# fieldcodec_generate_dictionary(<target> INPUT <file>
#                                [NAME <namespace>] [OUTPUT_DIR <dir>] [STRICT] [PDO_HEADER]
#                                [OPTIONS <generator option>...])
#
# Generates <OUTPUT_DIR>/fieldcodec/dictionaries/<NAME>.hpp from an EDS, DCF, CSV, XDD/XDC or
# ESI file at build time (re-generated when the file or the generator changes) and makes
# <target> depend on it and see it: `#include <fieldcodec/dictionaries/<NAME>.hpp>`, namespace
# fieldcodec::dictionaries::<NAME>.
#
#   PDO_HEADER  also <NAME>_pdos.hpp, the compile-time PDO layouts (--pdo-header), namespace
#               fieldcodec::dictionaries::<NAME>::pdos
#
#   NAME        default: the file name without extension, lower case, every character other
#               than a letter or digit replaced by '_' (runs collapsed), "n_" before a digit
#   OUTPUT_DIR  default: ${CMAKE_CURRENT_BINARY_DIR}/fieldcodec_generated
#   STRICT      warnings about the input are errors
#   OPTIONS     further fieldcodec-gen options, e.g. --string-capacity 0x2122=1024, or
#               --device 0x1234:0x20000 for an ESI of several devices
#
# The generator is the fieldcodec-gen target when it exists (fieldcodec built as a
# subproject), else the program named by FIELDCODEC_GEN_EXECUTABLE or found on the PATH.
function(fieldcodec_generate_dictionary target)
  cmake_parse_arguments(ARG "STRICT;PDO_HEADER" "INPUT;NAME;OUTPUT_DIR" "OPTIONS" ${ARGN})
  if(NOT ARG_INPUT)
    message(FATAL_ERROR "fieldcodec_generate_dictionary: INPUT is required")
  endif()
  get_filename_component(input "${ARG_INPUT}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT ARG_NAME)
    get_filename_component(stem "${input}" NAME_WE)
    string(TOLOWER "${stem}" stem)
    string(REGEX REPLACE "[^a-z0-9]+" "_" stem "${stem}")
    string(REGEX REPLACE "^_+|_+$" "" stem "${stem}")
    if(stem MATCHES "^[0-9]")
      set(stem "n_${stem}")
    endif()
    set(ARG_NAME "${stem}")
  endif()
  if(NOT ARG_OUTPUT_DIR)
    set(ARG_OUTPUT_DIR "${CMAKE_CURRENT_BINARY_DIR}/fieldcodec_generated")
  endif()
  if(TARGET fieldcodec-gen)
    set(gen "$<TARGET_FILE:fieldcodec-gen>")
    set(gen_dep fieldcodec-gen)
  else()
    if(NOT FIELDCODEC_GEN_EXECUTABLE)
      find_program(FIELDCODEC_GEN_EXECUTABLE fieldcodec-gen REQUIRED)
    endif()
    set(gen "${FIELDCODEC_GEN_EXECUTABLE}")
    set(gen_dep "${FIELDCODEC_GEN_EXECUTABLE}")
  endif()
  set(strict)
  if(ARG_STRICT)
    set(strict --strict)
  endif()
  set(out "${ARG_OUTPUT_DIR}/fieldcodec/dictionaries/${ARG_NAME}.hpp")
  set(outputs "${out}")
  set(pdo_option)
  if(ARG_PDO_HEADER)
    set(pdo_out "${ARG_OUTPUT_DIR}/fieldcodec/dictionaries/${ARG_NAME}_pdos.hpp")
    list(APPEND outputs "${pdo_out}")
    set(pdo_option --pdo-header "${pdo_out}")
  endif()
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ${CMAKE_COMMAND} -E make_directory "${ARG_OUTPUT_DIR}/fieldcodec/dictionaries"
    COMMAND ${gen} ${strict} ${ARG_OPTIONS} --quiet --name ${ARG_NAME} -o "${out}" ${pdo_option}
            "${input}"
    DEPENDS "${input}" ${gen_dep}
    COMMENT "fieldcodec-gen: ${ARG_NAME}.hpp from ${ARG_INPUT}"
    VERBATIM)
  target_sources(${target} PRIVATE ${outputs})
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    target_include_directories(${target} INTERFACE "${ARG_OUTPUT_DIR}")
  else()
    target_include_directories(${target} PUBLIC "${ARG_OUTPUT_DIR}")
  endif()
endfunction()
