# The test "live: the GSL built for the live scenes computes what Debian's native GSL computes":
# cmake/book/live/gsl_check.c built twice, with Debian's GSL (cc) and with the live scenes' GSL
# (emcc, run by node), and their printed numbers compared to a relative TOL. With PLANT=ON (the
# self-test) the WebAssembly build moves one number by 1e-9: it passes only when the check fails.
#   cmake -DPREFIX=<GSL built with emscripten> -DWORK=<scratch> -DTOL=<rel> [-DPLANT=ON] -P gsl_check.cmake
# Exit status 77 (CTest: skipped) when PREFIX has no libgsl.a (the build could not make one: it
# said why), unless CI=true; then it fails.
cmake_minimum_required(VERSION 3.20)
set(src "${CMAKE_CURRENT_LIST_DIR}/gsl_check.c")
if(NOT EXISTS "${PREFIX}/lib/libgsl.a")
  message("No GSL built with emscripten in '${PREFIX}' (the build says why it could not make one)")
  if("$ENV{CI}" STREQUAL "true")
    message(FATAL_ERROR "CI=true: the live scenes' GSL must be there")
  endif()
  # cmake -P exits 0 or 1; the test's SKIP_REGULAR_EXPRESSION reads this line.
  message("SKIPPED: no GSL for WebAssembly")
  return()
endif()
file(MAKE_DIRECTORY "${WORK}")
set(ENV{NODE_PATH} "/usr/share/nodejs")
set(plant "")
if(PLANT)
  set(plant -DPLANT)
endif()
find_program(CC NAMES cc gcc REQUIRED)
find_program(EMCC emcc REQUIRED)
find_program(NODE NAMES node nodejs REQUIRED)
execute_process(COMMAND ${CC} -O2 -o "${WORK}/native" "${src}" -lgsl -lgslcblas -lm COMMAND_ERROR_IS_FATAL ANY)
# One file, as the live modules are (node 20's fetch cannot read a .wasm beside it).
execute_process(COMMAND ${EMCC} -O2 ${plant} -sSINGLE_FILE=1 -sENVIRONMENT=node -I${PREFIX}/include -o "${WORK}/wasm.js" "${src}"
                        ${PREFIX}/lib/libgsl.a ${PREFIX}/lib/libgslcblas.a COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND "${WORK}/native" OUTPUT_VARIABLE native COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${NODE} "${WORK}/wasm.js" OUTPUT_VARIABLE wasm ERROR_VARIABLE why RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  string(SUBSTRING "${why}" 0 2000 why)
  message(FATAL_ERROR "the WebAssembly build of gsl_check.c failed to run (${rc}): ${why}")
endif()
message("native GSL:\n${native}GSL for the live scenes (WebAssembly):\n${wasm}")
string(REGEX MATCHALL "[-+0-9.e]+[0-9]" a "${native}")
string(REGEX MATCHALL "[-+0-9.e]+[0-9]" b "${wasm}")
list(LENGTH a n)
list(LENGTH b m)
if(NOT n EQUAL m OR n EQUAL 0)
  message(FATAL_ERROR "the two programs printed ${n} and ${m} numbers")
endif()
# CMake's math() has no floating point: node compares.
string(REPLACE ";" "," a "${a}")
string(REPLACE ";" "," b "${b}")
execute_process(COMMAND ${NODE} -e "const a=[${a}], b=[${b}]; let w=0;
  a.forEach((x, i) => { w = Math.max(w, Math.abs(x - b[i]) / Math.max(Math.abs(x), 1e-300)); });
  console.log(w); process.exit(w <= ${TOL} ? 0 : 1);"
  OUTPUT_VARIABLE worst OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE differ)
if(PLANT)
  if(NOT differ)
    message(FATAL_ERROR "the check missed a GSL result moved by 1e-9 (largest relative difference ${worst})")
  endif()
  message("The check fails on a GSL result moved by 1e-9 (largest relative difference ${worst}), as it must")
  return()
endif()
if(differ)
  message(FATAL_ERROR "the live scenes' GSL differs from Debian's: largest relative difference ${worst} > ${TOL}")
endif()
message("The live scenes' GSL agrees with Debian's: largest relative difference ${worst} <= ${TOL}")
