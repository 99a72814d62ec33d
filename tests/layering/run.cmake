# Generic layers know no vendor (DESIGN.md, "Layout"; docs/contributing.md): checks the headers
# under include/fieldcodec/.
#  * No header of a generic layer (core, od, canopen, ds402, master, ethercat) includes a
#    vendor's folder (compax, dpq, pacontrol, xenax) or a generated dictionary (dictionaries/,
#    written from a vendor's files): a vendor's rules come in as a parameter or a table its
#    folder supplies.
#  * No header under the folders of `name_free` mentions a vendor or its device at all, not even
#    in a comment: master/ commands any CiA 301/402 device alike, od/ describes any dictionary,
#    and so on. (host/ is not a generic layer: it holds device adapters such as
#    host/pacontrol_link.hpp.)
# Fails naming the file, the line and what it found.
#   cmake -DSOURCE_DIR=<project root> -P tests/layering/run.cmake
cmake_minimum_required(VERSION 3.20)
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=<project root> -P run.cmake")
endif()

set(generic core od canopen ds402 master ethercat)
set(name_free core od canopen ds402 master ethercat)
set(vendor_folders "compax|dpq|pacontrol|xenax|dictionaries")
# vendor, device and maker names, matched without regard to case
set(vendor_names "xenax|dpq|compax|pa-?control|jenny|rexroth|parker|hauser|ief werner")

set(problems "")
set(checked 0)
foreach(layer IN LISTS generic)
  file(GLOB_RECURSE headers ${SOURCE_DIR}/include/fieldcodec/${layer}/*.hpp)
  list(FIND name_free ${layer} strict)
  foreach(h IN LISTS headers)
    math(EXPR checked "${checked} + 1")
    file(RELATIVE_PATH rel ${SOURCE_DIR} ${h})
    # one list element per line: ';' and '[' ']' masked so that lines stay whole
    file(READ ${h} text)
    string(REPLACE ";" "@SEMI@" text "${text}")
    string(REPLACE "[" "@LB@" text "${text}")
    string(REPLACE "]" "@RB@" text "${text}")
    string(REPLACE "\n" ";" lines "${text}")
    set(n 0)
    foreach(masked IN LISTS lines)
      math(EXPR n "${n} + 1")
      string(REPLACE "@SEMI@" ";" line "${masked}")
      string(REPLACE "@LB@" "[" line "${line}")
      string(REPLACE "@RB@" "]" line "${line}")
      if(line MATCHES "#[ \t]*include[ \t]*[<\"]fieldcodec/(${vendor_folders})/")
        string(APPEND problems "${rel}:${n}: includes a vendor's folder: ${line}\n")
      endif()
      if(NOT strict EQUAL -1)
        string(TOLOWER "${line}" lower)
        if(lower MATCHES "(${vendor_names})")
          string(APPEND problems "${rel}:${n}: names a vendor (${CMAKE_MATCH_1}): ${line}\n")
        endif()
      endif()
    endforeach()
  endforeach()
endforeach()

if(checked EQUAL 0)
  message(FATAL_ERROR "no headers found under ${SOURCE_DIR}/include/fieldcodec")
endif()
if(problems)
  message(FATAL_ERROR "generic layers that know a vendor:\n${problems}")
endif()
message(STATUS "${checked} headers of ${generic}: no vendor includes; ${name_free}: no vendor names")
