# Generates the Fortran named constants of module creepwork from the C header,
# so that the two cannot drift (CONTRIBUTING.md, house rules):
#   - every X(CW_NAME, value, "message") of CW_STATUS_LIST becomes
#     integer(c_int), parameter :: CW_NAME = value, plus the arrays
#     CW_STATUS_CODES and CW_STATUS_MESSAGES (same order as the list);
#   - every object-like #define CW_NAME <number or constant expression of
#     other CW_ macros> becomes an integer(c_int) or real(c_double) parameter.
# Function-like macros and macros without a value are skipped.
#
# Usage: cmake -DHEADER=creepwork.h -DOUTPUT=creepwork_constants.inc -P generate_constants.cmake

if(NOT HEADER OR NOT OUTPUT)
  message(FATAL_ERROR "usage: cmake -DHEADER=<creepwork.h> -DOUTPUT=<file.inc> -P ${CMAKE_CURRENT_LIST_FILE}")
endif()

include("${CMAKE_CURRENT_LIST_DIR}/../cmake/read_public_header.cmake")
creepwork_read_public_header("${HEADER}" text)
# Join continued lines so that each macro is on one line.
string(REGEX REPLACE "\\\\\r?\n" " " text "${text}")

get_filename_component(header_name "${HEADER}" NAME)
set(out "! Generated from ${header_name} by generate_constants.cmake: do not edit.\n")
string(APPEND out "! Included in the specification part of module creepwork.\n\n")

# --- status codes: X(name, value, "message") entries of CW_STATUS_LIST
string(REGEX MATCH "#define CW_STATUS_LIST\\(X\\)[^\n]*" status_list "${text}")
if(NOT status_list)
  message(FATAL_ERROR "CW_STATUS_LIST not found in ${HEADER}")
endif()
string(REGEX MATCHALL "X\\(CW_[A-Z0-9_]+, *-?[0-9]+, *\"[^\"]*\"\\)" entries "${status_list}")
list(LENGTH entries n_status)
if(n_status EQUAL 0)
  message(FATAL_ERROR "no X(name, value, message) entries in CW_STATUS_LIST")
endif()
set(codes "")
set(messages "")
set(max_len 1)
foreach(entry IN LISTS entries)
  string(REGEX REPLACE "X\\((CW_[A-Z0-9_]+), *(-?[0-9]+), *\"([^\"]*)\"\\)" "\\1;\\2;\\3" parts "${entry}")
  list(GET parts 0 name)
  list(GET parts 1 value)
  list(GET parts 2 msg)
  string(APPEND out "integer(c_int), parameter, public :: ${name} = ${value}_c_int\n")
  list(APPEND codes "${value}_c_int")
  string(REPLACE "'" "''" msg_f "${msg}")
  list(APPEND messages "'${msg_f}'")
  string(LENGTH "${msg}" len)
  if(len GREATER max_len)
    set(max_len ${len})
  endif()
endforeach()
string(APPEND out "\n! Every status code of CW_STATUS_LIST and its message, in list order.\n")
string(APPEND out "integer, parameter, public :: CW_STATUS_COUNT = ${n_status}\n")
list(JOIN codes ", &\n    " codes_f)
string(APPEND out "integer(c_int), parameter, public :: CW_STATUS_CODES(${n_status}) = [ &\n    ${codes_f}]\n")
list(JOIN messages ", &\n    " messages_f)
string(APPEND out "character(len=${max_len}), parameter, public :: CW_STATUS_MESSAGES(${n_status}) = &\n")
string(APPEND out "  [character(len=${max_len}) :: &\n    ${messages_f}]\n\n")

# --- object-like #defines with a numeric value
string(REGEX MATCHALL "#define[ \t]+CW_[A-Z0-9_]+[ \t]+[^\n]+" defines "${text}")
foreach(def IN LISTS defines)
  string(REGEX REPLACE "#define[ \t]+(CW_[A-Z0-9_]+)[ \t]+(.*)" "\\1;\\2" parts "${def}")
  list(GET parts 0 name)
  list(GET parts 1 value)
  # Drop a trailing C comment and surrounding blanks.
  string(REGEX REPLACE "/\\*.*$" "" value "${value}")
  string(REGEX REPLACE "//.*$" "" value "${value}")
  string(STRIP "${value}" value)
  if(name MATCHES "_$" OR value STREQUAL "")
    continue()
  endif()
  if(value MATCHES "^-?[0-9]+$")
    string(APPEND out "integer(c_int), parameter, public :: ${name} = ${value}_c_int\n")
  elseif(value MATCHES "^-?[0-9]*\\.?[0-9]+([eE][-+]?[0-9]+)?$" OR value MATCHES "^-?[0-9]+\\.[0-9]*$")
    string(APPEND out "real(c_double), parameter, public :: ${name} = ${value}_c_double\n")
  elseif(value MATCHES "^[-+*/() 0-9A-Z_]+$" AND value MATCHES "CW_")
    # A constant expression of integer macros, e.g. CW_VERSION_NUMBER: valid Fortran as written.
    string(APPEND out "integer(c_int), parameter, public :: ${name} = ${value}\n")
  endif()
endforeach()

file(WRITE "${OUTPUT}" "${out}")
