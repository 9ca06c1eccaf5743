# The Fortran objects of libcreepwork_fortran hold no mutable static data:
# no SAVEd or module variable, and none of the static result lengths that
# gfortran 12 makes where a function returning a deferred-length character
# is called (slen.N) -- each would be shared by every thread, and the
# library promises that distinct objects (and the legacy routines) may be
# used from several threads at once. Only gfortran's type tables (__vtab_,
# __vtype_, __def_init_, written once at load) and AddressSanitizer's
# one-definition markers (__odr_asan.) may be there.
# Usage: cmake -DLIBRARY=libcreepwork_fortran.a -DNM=nm -P check_fortran_static_data.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var LIBRARY NM)
  if(NOT ${var})
    message(FATAL_ERROR "check_fortran_static_data: -D${var}=... is required")
  endif()
endforeach()
execute_process(COMMAND ${NM} -A ${LIBRARY} OUTPUT_VARIABLE out ERROR_VARIABLE err
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nm failed (${rc}): ${err}")
endif()
string(REPLACE "\n" ";" lines "${out}")
set(found "")
set(seen "")
set(objects 0)
foreach(line IN LISTS lines)
  # "<library>:<member>: <address> <type> <name>"
  if(NOT line MATCHES ":([^:]+\\.f90\\.o): *[0-9a-fA-F]* ([A-Za-z]) (.+)$")
    continue()
  endif()
  set(member ${CMAKE_MATCH_1})
  set(type ${CMAKE_MATCH_2})
  set(name ${CMAKE_MATCH_3})
  if(NOT member IN_LIST seen)
    list(APPEND seen ${member})
    math(EXPR objects "${objects} + 1")
  endif()
  if(type MATCHES "^[bBdD]$" AND NOT name MATCHES "__(vtab|vtype|def_init)_|^__odr_asan\\.")
    list(APPEND found "${member}: ${name}")
  endif()
endforeach()
if(objects LESS 5)
  message(FATAL_ERROR "found only ${objects} Fortran objects in ${LIBRARY}: nm output not understood")
endif()
if(found)
  list(JOIN found "\n  " found)
  message(FATAL_ERROR "static data in the Fortran library (shared by all threads):\n  ${found}")
endif()
message(STATUS "${objects} Fortran objects, no mutable static data")
