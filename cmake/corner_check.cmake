# One corner of a scene's accepted ranges (see cmake/corner_list.cmake). The scene must end
# one of three ways, and say what happened:
#   exit 0 within the budget (three times the budget allowed: the estimates are estimates, and
#          the machine may be shared), with its JSON report;
#   exit 2, a message on stderr that names an option (bad input, or a request over the budget);
#   exit 1, a message on stderr (a numerical failure, or one of its own checks failed).
# A crash, a hang (the scene's watchdog, or this script's timeout) or silence fails the test.
#   -DCOMMAND=<exe>|<arg>|...  -DBUDGET=<seconds>  -DOPTION=--name
string(REPLACE "|" ";" command "${COMMAND}")
math(EXPR limit "3 * ${BUDGET} + 20")
string(TIMESTAMP t0 "%s")
execute_process(COMMAND ${command} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT ${limit})
string(TIMESTAMP t1 "%s")
math(EXPR elapsed "${t1} - ${t0}")
string(STRIP "${err}" err)
if(rc STREQUAL "0")
  math(EXPR allowed "3 * ${BUDGET} + 2")
  if(elapsed GREATER allowed)
    message(FATAL_ERROR "exit 0, but after ${elapsed} s: over three times the budget of ${BUDGET} s")
  endif()
  string(JSON e ERROR_VARIABLE json_error GET "${out}" error)
  if(json_error)
    message(FATAL_ERROR "exit 0 without a JSON report: ${json_error}\n${out}\n${err}")
  endif()
  message(STATUS "ran in ${elapsed} s: error ${e}")
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
