# Module creepwork cannot drift from the C header:
#   1. the generated bind(C) interfaces (BINDINGS, from generate_interfaces.cmake)
#      are exactly the CW_API functions of HEADER, each once, with the same
#      number of arguments (a check on the generator);
#   2. every generated interface capi_x is used by a hand-written source of
#      the module (SOURCES), i.e. wrapped by a public procedure, or is listed
#      below as deliberately not wrapped, with the reason.
# A function added to the header is bound automatically and fails 2 until a
# wrapper calls it (check_fortran_bindings_self_test.cmake shows that).
# Usage: cmake -DHEADER=creepwork.h -DBINDINGS=creepwork_bindings.inc
#              -DSOURCES="a.f90;b.f90" -P check_fortran_bindings.cmake

cmake_minimum_required(VERSION 3.25)

# "cw_name: reason" for each C function module creepwork does not wrap.
set(not_wrapped
  "cw_wheelrail_patch_solver: the patch's fields come through get_patch_field and its wear through add_wear, and a borrowed solver would need a handle type that is never destroyed")

foreach(var HEADER BINDINGS SOURCES)
  if(NOT ${var})
    message(FATAL_ERROR "check_fortran_bindings: -D${var}=... is required")
  endif()
endforeach()
include("${CMAKE_CURRENT_LIST_DIR}/../../cmake/read_public_header.cmake")
creepwork_read_public_header("${HEADER}" header)
file(READ "${BINDINGS}" bindings)

# Number of arguments of "(a, b, c)" text ("" and "void": 0).
function(count_args args out)
  string(STRIP "${args}" args)
  if(args STREQUAL "void" OR args STREQUAL "")
    set(${out} 0 PARENT_SCOPE)
  else()
    string(REGEX MATCHALL "," commas "${args}")
    list(LENGTH commas n)
    math(EXPR n "${n} + 1")
    set(${out} ${n} PARENT_SCOPE)
  endif()
endfunction()

# C: "CW_API <type> cw_name(<args>);" possibly over several lines.
string(REGEX REPLACE "[\r\n]+" " " header "${header}")
string(REGEX MATCHALL "CW_API[^;]*" prototypes "${header}")
set(c_names "")
foreach(proto IN LISTS prototypes)
  if(NOT proto MATCHES "(cw_[a-z0-9_]+)[ ]*\\(([^)]*)\\)")
    message(FATAL_ERROR "cannot read the prototype: ${proto}")
  endif()
  set(name ${CMAKE_MATCH_1})
  count_args("${CMAKE_MATCH_2}" count)
  list(APPEND c_names ${name})
  set(c_args_${name} ${count})
endforeach()

# Fortran: "function capi_x(<args>) bind(c, name='cw_x')", continuation lines joined.
string(REGEX REPLACE "&[ ]*\r?\n[ ]*(&)?" "" bindings "${bindings}")
string(REGEX MATCHALL "function[ ]+[a-z0-9_]+\\([^)]*\\)[ ]*bind\\(c, name='cw_[a-z0-9_]+'\\)"
       interfaces "${bindings}")
set(f_names "")
foreach(itf IN LISTS interfaces)
  string(REGEX MATCH "function[ ]+([a-z0-9_]+)\\(([^)]*)\\)[ ]*bind\\(c, name='(cw_[a-z0-9_]+)'\\)"
         _ "${itf}")
  set(iname ${CMAKE_MATCH_1})
  count_args("${CMAKE_MATCH_2}" count)
  set(name ${CMAKE_MATCH_3})
  if(name IN_LIST f_names)
    message(SEND_ERROR "${name} is bound twice in ${BINDINGS}")
  endif()
  list(APPEND f_names ${name})
  set(f_args_${name} ${count})
  set(f_interface_${name} ${iname})
endforeach()

set(failed FALSE)
list(LENGTH c_names n_c)
if(n_c EQUAL 0)
  message(SEND_ERROR "no CW_API prototypes found in ${HEADER}")
  set(failed TRUE)
endif()
foreach(name IN LISTS c_names)
  if(NOT name IN_LIST f_names)
    message(SEND_ERROR "${name} (creepwork.h) has no bind(C) interface in ${BINDINGS}")
    set(failed TRUE)
  elseif(NOT c_args_${name} EQUAL f_args_${name})
    message(SEND_ERROR "${name}: ${c_args_${name}} arguments in C, ${f_args_${name}} in Fortran")
    set(failed TRUE)
  endif()
endforeach()
foreach(name IN LISTS f_names)
  if(NOT name IN_LIST c_names)
    message(SEND_ERROR "${name} is bound in ${BINDINGS} but not declared in creepwork.h")
    set(failed TRUE)
  endif()
endforeach()

# Wrapped: the interface is called ("capi_x(...)", or passed on as
# "capi_x": a handle's destroy and last_error) in a hand-written source.
set(code "")
foreach(source IN LISTS SOURCES)
  file(READ "${source}" text)
  string(APPEND code "${text}\n")
endforeach()
string(REGEX REPLACE "![^\n]*" "" code "${code}") # comments do not wrap anything
string(TOLOWER "${code}" code)
set(excluded "")
foreach(entry IN LISTS not_wrapped)
  string(REGEX REPLACE ":.*" "" name "${entry}")
  if(NOT name IN_LIST c_names)
    message(SEND_ERROR "not_wrapped names ${name}, which creepwork.h does not declare")
    set(failed TRUE)
  endif()
  list(APPEND excluded ${name})
endforeach()
set(n_wrapped 0)
foreach(name IN LISTS f_names)
  if(name IN_LIST excluded)
    continue()
  endif()
  if(code MATCHES "[^a-z0-9_]${f_interface_${name}}[ ]*[(,)]")
    math(EXPR n_wrapped "${n_wrapped} + 1")
  else()
    message(SEND_ERROR "${name}: its interface ${f_interface_${name}} has no wrapper in module "
                       "creepwork (call it from a public procedure, or list it in not_wrapped "
                       "of ${CMAKE_CURRENT_LIST_FILE} with the reason)")
    set(failed TRUE)
  endif()
endforeach()
if(NOT failed)
  list(LENGTH excluded n_excluded)
  message(STATUS "all ${n_c} functions of creepwork.h are bound with matching argument counts; "
                 "${n_wrapped} are wrapped, ${n_excluded} deliberately not")
endif()
