# Installs the build tree into a fresh prefix and builds programs outside the
# tree against it, the ways a user would:
#   1. libcreepwork.so exports cw_* symbols only;
#   2. the .mod file and the legacy include files are under
#      include/creepwork/fortran, both .pc files and bin/creepwork installed;
#   3. C via find_package(creepwork)            (consumers/c_find_package)
#   4. C via pkg-config                          (cc consumer.c $(pkg-config ...))
#   5. Fortran via the plain line of doc/fortran.md:
#        gfortran my_code.f90 -I<prefix>/include/creepwork/fortran -L<prefix>/lib
#                 -lcreepwork_fortran -lcreepwork
#   6. FORTRAN 77 legacy caller, no module:  gfortran legacy.f -L<prefix>/lib ...
#   7. Fortran via find_package(creepwork)       (consumers/fortran_find_package)
# Every program is run and must succeed.
# Usage: cmake -DBUILD_DIR=... -DWORK_DIR=... -DSOURCE_DIR=<tests/install>
#              -DC_COMPILER=... -DFortran_COMPILER=... [-DCONFIG=Release] -P run_install_test.cmake

cmake_minimum_required(VERSION 3.25)
foreach(var BUILD_DIR WORK_DIR SOURCE_DIR C_COMPILER Fortran_COMPILER)
  if(NOT ${var})
    message(FATAL_ERROR "${var} is not set")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()

set(prefix ${WORK_DIR}/prefix)
set(consumers ${SOURCE_DIR}/consumers)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# run(<what> COMMAND ...): runs a command, fails the test with its output.
function(run what)
  cmake_parse_arguments(R "" "" "COMMAND" ${ARGN})
  execute_process(COMMAND ${R_COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  WORKING_DIRECTORY ${WORK_DIR})
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " line "${R_COMMAND}")
    set(hint "")
    if("${out}${err}" MATCHES "Could NOT find OpenMP")
      string(CONCAT hint "\nHINT: creepworkConfig.cmake calls find_dependency(OpenMP COMPONENTS CXX), "
               "which fails in projects without C++ (C- or Fortran-only consumers); it should "
               "look for OpenMP only when CXX is enabled (cmake/creepworkConfig.cmake.in).")
    endif()
    message(FATAL_ERROR "${what} failed (${rc}):\n${line}\n${out}\n${err}${hint}")
  endif()
  message(STATUS "${what}: ok ${out}")
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

run("install" COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --config ${CONFIG})
set(libdir ${prefix}/lib)

# 1. Only cw_ symbols leave libcreepwork.so (CONTRIBUTING.md, C ABI).
find_program(NM nm REQUIRED)
run("exported symbols" COMMAND ${NM} -D --defined-only ${libdir}/libcreepwork.so)
string(REGEX MATCHALL "[0-9a-fA-F]+ [A-Za-z] [^\n]+" symbols "${run_output}")
set(foreign "")
set(count 0)
foreach(line IN LISTS symbols)
  string(REGEX REPLACE "^[0-9a-fA-F]+ [A-Za-z] " "" name "${line}")
  if(NOT name MATCHES "^cw_")
    list(APPEND foreign ${name})
  endif()
  math(EXPR count "${count} + 1")
endforeach()
if(foreign OR count EQUAL 0)
  message(FATAL_ERROR "libcreepwork.so exports symbols other than cw_*: ${foreign}")
endif()
message(STATUS "libcreepwork.so exports ${count} symbols, all cw_*")

# 2. The compiler-specific module file, the legacy layer's include files,
# both pkg-config files and the program (which finds its library in ../lib).
foreach(file include/creepwork/fortran/creepwork.mod include/creepwork/fortran/creepwork_legacy.inc
             include/creepwork/fortran/creepwork_legacy.fi lib/pkgconfig/creepwork.pc
             lib/pkgconfig/creepwork-fortran.pc bin/creepwork)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "${file} was not installed")
  endif()
endforeach()
run("installed program" COMMAND ${prefix}/bin/creepwork --version)

# 3. C, find_package.
run("C find_package configure" COMMAND ${CMAKE_COMMAND} -S ${consumers}/c_find_package
    -B ${WORK_DIR}/c_find_package -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${CONFIG}
    -DCMAKE_C_COMPILER=${C_COMPILER})
run("C find_package build" COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/c_find_package)
run("C find_package run" COMMAND ${WORK_DIR}/c_find_package/consumer)

# 4. C, pkg-config. The .pc file locates its prefix relative to itself, so
# this relocated install (not the build's configured prefix) works as is.
find_program(PKG_CONFIG pkg-config REQUIRED)
run("pkg-config" COMMAND ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${libdir}/pkgconfig
    ${PKG_CONFIG} --cflags --libs creepwork)
string(STRIP "${run_output}" pc_flags)
separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")
run("C pkg-config build" COMMAND ${C_COMPILER} ${consumers}/consumer.c ${pc_flags} -lm
    -Wl,-rpath,${libdir} -o ${WORK_DIR}/c_pkg_config)
run("C pkg-config run" COMMAND ${WORK_DIR}/c_pkg_config)

# 5. Fortran, the plain command line of doc/fortran.md.
run("Fortran plain build" COMMAND ${Fortran_COMPILER} ${consumers}/my_code.f90
    -I${prefix}/include/creepwork/fortran -L${libdir} -lcreepwork_fortran -lcreepwork
    -o ${WORK_DIR}/my_code)
run("Fortran plain run" COMMAND ${CMAKE_COMMAND} -E env LD_LIBRARY_PATH=${libdir}
    ${WORK_DIR}/my_code)

# 6. FORTRAN 77 legacy caller: no module, no -I.
run("F77 legacy build" COMMAND ${Fortran_COMPILER} ${consumers}/legacy.f -L${libdir}
    -lcreepwork_fortran -lcreepwork -o ${WORK_DIR}/legacy)
run("F77 legacy run" COMMAND ${CMAKE_COMMAND} -E env LD_LIBRARY_PATH=${libdir} ${WORK_DIR}/legacy)

# 7. Fortran, find_package.
run("Fortran find_package configure" COMMAND ${CMAKE_COMMAND}
    -S ${consumers}/fortran_find_package -B ${WORK_DIR}/fortran_find_package
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${CONFIG}
    -DCMAKE_Fortran_COMPILER=${Fortran_COMPILER})
run("Fortran find_package build" COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/fortran_find_package)
run("Fortran find_package run" COMMAND ${WORK_DIR}/fortran_find_package/my_code)
