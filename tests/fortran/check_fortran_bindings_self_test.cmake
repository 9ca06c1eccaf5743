# check_fortran_bindings.cmake must fail when the header gains a function the
# module does not wrap: a copy of the header with one more prototype goes
# through the generator and the check, which must name the new function.
# Usage: cmake -DHEADER=creepwork.h -DSOURCES="a.f90;b.f90" -DWORK_DIR=<dir>
#              -DGENERATOR=generate_interfaces.cmake -DCHECK=check_fortran_bindings.cmake
#              -P check_fortran_bindings_self_test.cmake

cmake_minimum_required(VERSION 3.25)

file(MAKE_DIRECTORY "${WORK_DIR}")
# The header with its parts inlined: the copy stands alone.
include("${CMAKE_CURRENT_LIST_DIR}/../../cmake/read_public_header.cmake")
creepwork_read_public_header("${HEADER}" header)
set(extra "CW_API int cw_solver_new_feature(cw_solver* solver, const double* x, size_t x_len);\n")
string(REPLACE "#ifdef __cplusplus\n} /* extern \"C\" */" "${extra}#ifdef __cplusplus\n} /* extern \"C\" */"
       grown "${header}")
if(grown STREQUAL header)
  message(FATAL_ERROR "could not add a prototype to the copy of ${HEADER}")
endif()
file(WRITE "${WORK_DIR}/creepwork.h" "${grown}")

# The real header passes; the grown one is bound (the generator accepts it)
# but fails the check, naming the function.
foreach(case real grown)
  if(case STREQUAL "real")
    set(h "${HEADER}")
  else()
    set(h "${WORK_DIR}/creepwork.h")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -DHEADER=${h} -DTYPES=${WORK_DIR}/types_${case}.inc
                          -DBINDINGS=${WORK_DIR}/bindings_${case}.inc -P ${GENERATOR}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "generator failed on the ${case} header: ${err}")
  endif()
  file(READ "${WORK_DIR}/bindings_${case}.inc" bound)
  execute_process(COMMAND ${CMAKE_COMMAND} -DHEADER=${h} -DBINDINGS=${WORK_DIR}/bindings_${case}.inc
                          "-DSOURCES=${SOURCES}" -P ${CHECK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(check_${case}_rc ${rc})
  set(check_${case}_err "${err}")
endforeach()

if(NOT check_real_rc EQUAL 0)
  message(FATAL_ERROR "the check fails on the real header:\n${check_real_err}")
endif()
if(NOT bound MATCHES "function capi_solver_new_feature\\(solver, x, x_len\\)")
  message(FATAL_ERROR "the generator did not bind the added function:\n${bound}")
endif()
if(check_grown_rc EQUAL 0 OR NOT check_grown_err MATCHES "cw_solver_new_feature: its interface")
  message(FATAL_ERROR "the check did not catch the unwrapped function (rc ${check_grown_rc}):\n"
                      "${check_grown_err}")
endif()
message(STATUS "an unwrapped function added to the header fails check_fortran_bindings")
