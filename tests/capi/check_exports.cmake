# cmake -DLIBRARY=<libcreepwork.so> -DHEADER=<creepwork.h> -DNM=<nm> -P check_exports.cmake
# Fails unless the dynamic symbols the library defines are exactly the
# functions the header declares with CW_API: nothing outside the cw_ prefix
# leaks (no C++ core, no Eigen, no STL), and nothing declared is missing.
cmake_minimum_required(VERSION 3.25)
foreach(var LIBRARY HEADER NM)
  if(NOT ${var})
    message(FATAL_ERROR "check_exports: -D${var}=... is required")
  endif()
endforeach()

execute_process(COMMAND ${NM} -D --defined-only ${LIBRARY}
  OUTPUT_VARIABLE nm_out ERROR_VARIABLE nm_err RESULT_VARIABLE nm_rc)
if(NOT nm_rc EQUAL 0)
  message(FATAL_ERROR "nm failed (${nm_rc}): ${nm_err}")
endif()

# "<address> <type> <name>[@version]" per line.
set(exported "")
set(foreign "")
string(REPLACE "\n" ";" lines "${nm_out}")
foreach(line IN LISTS lines)
  if(line MATCHES "^[0-9a-fA-F]* *[A-Za-z] ([^@ ]+)")
    set(name "${CMAKE_MATCH_1}")
    list(APPEND exported "${name}")
    if(NOT name MATCHES "^cw_")
      list(APPEND foreign "${name}")
    endif()
  endif()
endforeach()

include("${CMAKE_CURRENT_LIST_DIR}/../../cmake/read_public_header.cmake")
creepwork_read_public_header("${HEADER}" header)
string(REGEX MATCHALL "CW_API[^(;]*[ *](cw_[a-z0-9_]+)\\(" decls "${header}")
set(declared "")
foreach(decl IN LISTS decls)
  string(REGEX REPLACE ".*[ *](cw_[a-z0-9_]+)\\($" "\\1" fn "${decl}")
  list(APPEND declared "${fn}")
endforeach()
list(LENGTH declared n_declared)
list(LENGTH exported n_exported)
if(n_declared LESS 10)
  message(FATAL_ERROR "found only ${n_declared} CW_API declarations in ${HEADER}: parser broken?")
endif()

set(missing "")
foreach(fn IN LISTS declared)
  if(NOT fn IN_LIST exported)
    list(APPEND missing "${fn}")
  endif()
endforeach()
set(undeclared "")
foreach(sym IN LISTS exported)
  if(sym MATCHES "^cw_" AND NOT sym IN_LIST declared)
    list(APPEND undeclared "${sym}")
  endif()
endforeach()

if(foreign OR missing OR undeclared)
  message(FATAL_ERROR "libcreepwork exports: not cw_: [${foreign}]; declared but not exported: "
                      "[${missing}]; exported but not declared: [${undeclared}]")
endif()
message(STATUS "${n_exported} exported symbols, all cw_, all ${n_declared} declared functions present")
