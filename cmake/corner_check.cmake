# One corner of a scene's accepted ranges (see cmake/corner_list.cmake). The scene must end
# one of three ways, and say what happened:
#   exit 0 within the budget, with its JSON report. The budget is CPU time on one core, and so is
#          what is measured (the child's user + system time, from bash's `times`), never wall
#          time: a shared, loaded machine stretches wall time but not CPU time. Three times the
#          budget is allowed (the scenes' cost estimates are estimates);
#   exit 2, a message on stderr that names an option (bad input, or a request over the budget);
#   exit 1, a message on stderr (a numerical failure, or one of its own checks failed).
# A crash, a hang (the scene's watchdog, or this script's timeout) or silence fails the test.
#   -DCOMMAND=<exe>|<arg>|...  -DBUDGET=<seconds>  -DOPTION=--name  [-DHANG=<factor>]
string(REPLACE "|" ";" command "${COMMAND}")
# Only a hang guard: wall time under load may be many times the CPU time (WORKBOOK_HANG_FACTOR).
if(NOT HANG)
  set(HANG 1)
endif()
math(EXPR limit "(10 * ${BUDGET} + 60) * ${HANG}")
string(RANDOM LENGTH 12 tag)
set(cpu_file "${CMAKE_CURRENT_BINARY_DIR}/corner-cpu-${tag}.txt")
string(TIMESTAMP t0 "%s")
execute_process(COMMAND bash -c "\"$@\"; rc=$?; times > '${cpu_file}'; exit $rc" corner ${command}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT ${limit})
string(TIMESTAMP t1 "%s")
math(EXPR elapsed "${t1} - ${t0}")
set(cpu "")
if(EXISTS "${cpu_file}")
  file(STRINGS "${cpu_file}" times_lines)
  file(REMOVE "${cpu_file}")
  list(LENGTH times_lines n)
  if(n EQUAL 2)  # bash's `times`: the shell's user and system time, then its children's
    list(GET times_lines 1 children)
    if(children MATCHES "^([0-9]+)m([0-9.]+)s ([0-9]+)m([0-9.]+)s$")
      math(EXPR cpu_ms "(${CMAKE_MATCH_1} + ${CMAKE_MATCH_3}) * 60000")
      string(REPLACE "." ";" us "${CMAKE_MATCH_2};${CMAKE_MATCH_4}")  # seconds.milliseconds
      list(GET us 0 s1)
      list(GET us 1 f1)
      list(GET us 2 s2)
      list(GET us 3 f2)
      math(EXPR cpu_ms "${cpu_ms} + (${s1} + ${s2}) * 1000 + ${f1} + ${f2}")
      set(cpu "${cpu_ms}")
    endif()
  endif()
endif()
string(STRIP "${err}" err)
if(rc STREQUAL "0")
  if(cpu STREQUAL "")
    message(FATAL_ERROR "exit 0, but its CPU time could not be read (bash's times)")
  endif()
  math(EXPR allowed_ms "3 * ${BUDGET} * 1000 + 2000")
  if(cpu GREATER allowed_ms)
    message(FATAL_ERROR "exit 0, but after ${cpu} ms of CPU time: over three times the budget of ${BUDGET} s")
  endif()
  string(JSON e ERROR_VARIABLE json_error GET "${out}" error)
  if(json_error)
    message(FATAL_ERROR "exit 0 without a JSON report: ${json_error}\n${out}\n${err}")
  endif()
  message(STATUS "ran in ${cpu} ms of CPU time (${elapsed} s of wall time): error ${e}")
elseif(rc STREQUAL "2")
  if(NOT err MATCHES "--[A-Za-z]")
    message(FATAL_ERROR "exit 2 without a message naming an option:\n${err}")
  endif()
  message(STATUS "refused: ${err}")
elseif(rc STREQUAL "1")
  if(err STREQUAL "")
    message(FATAL_ERROR "exit 1 without a message")
  endif()
  message(STATUS "failed with a message: ${err}")
else()
  message(FATAL_ERROR "exit status '${rc}' after ${elapsed} s (a crash or a hang):\n${err}")
endif()
