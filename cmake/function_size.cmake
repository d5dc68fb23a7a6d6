# Short functions in the workbook's own tools: no function in cmake/tools/ or tests/grading/ (the
# book tool, the snippet checker, the grading run and its judge and student side) is longer than LINES
# lines, by clang-tidy's readability-function-size (its LineThreshold counts the lines of the body);
# and no scene's main (chapters/*/*.cpp) is either: a scene reads as named steps (parse, compute,
# report, draw), each a function of its own.
#
#   cmake -DTIDY=<clang-tidy> -DROOT=<workbook> -DBUILD=<build folder> -DLINES=<n> -P cmake/function_size.cmake
#       checks the sources as the build compiles them (BUILD/compile_commands.json);
#   cmake -DTIDY=<clang-tidy> -DSELFTEST=<scratch folder> -DLINES=<n> -P cmake/function_size.cmake
#       the check must be able to fail: it must flag a function of LINES + 1 lines and pass one of LINES
#       (a function's lines, as clang-tidy counts them: those after its opening brace's line).
if(NOT TIDY OR NOT EXISTS "${TIDY}")
  # Outside CI the test reports itself skipped (SKIP_REGULAR_EXPRESSION), like the browser tests.
  if("$ENV{CI}" STREQUAL "true")
    message(FATAL_ERROR "clang-tidy was not found: sudo apt-get install clang-tidy (cmake/workbook test installs it)")
  endif()
  message(FATAL_ERROR "SKIPPED: clang-tidy was not found (sudo apt-get install clang-tidy; cmake/workbook test installs it)")
endif()
set(config "{CheckOptions: [{key: readability-function-size.LineThreshold, value: ${LINES}}]}")
set(tidy_args --quiet "--checks=-*,readability-function-size" "--config=${config}" "--warnings-as-errors=*"
              --extra-arg=-Wno-unknown-warning-option)

# The functions over the limit in `files`, one "path: function 'name'" a line.
function(long_functions out)
  set(found "")
  foreach(file IN LISTS ARGN)
    execute_process(COMMAND "${TIDY}" ${tidy_args} ${TIDY_EXTRA} "${file}" ${TIDY_TAIL}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE text ERROR_VARIABLE err)
    string(REGEX MATCHALL "[^\n]*: (warning|error): function '[^']+' exceeds recommended size/complexity" hits "${text}")
    foreach(hit IN LISTS hits)
      string(REGEX REPLACE ":[0-9]+:[0-9]+: (warning|error): (function '[^']+').*" ": \\2" hit "${hit}")
      list(APPEND found "${hit}")
    endforeach()
    if(NOT rc EQUAL 0 AND NOT hits)
      list(APPEND found "${file}: clang-tidy failed (${rc}): ${text}${err}")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES found)  # a header's function, seen from every source that includes it
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

if(SELFTEST)
  file(REMOVE_RECURSE "${SELFTEST}")
  math(EXPR over "${LINES} + 1")
  foreach(n IN ITEMS ${LINES} ${over})
    # n lines as clang-tidy counts them (those after the opening brace's): n - 2 statements,
    # the return and the closing brace.
    math(EXPR last "${n} - 2")
    set(body "")
    foreach(i RANGE 1 ${last})
      string(APPEND body "    x += ${i};\n")
    endforeach()
    file(WRITE "${SELFTEST}/f${n}.cpp" "int f(int x) {\n${body}    return x;\n}\n")
  endforeach()
  set(TIDY_TAIL -- -std=c++20)
  long_functions(at_limit "${SELFTEST}/f${LINES}.cpp")
  long_functions(over_limit "${SELFTEST}/f${over}.cpp")
  if(at_limit OR NOT over_limit)
    message(FATAL_ERROR "the function-size check is broken: a function of ${LINES} lines gave '${at_limit}', "
                        "one of ${over} lines gave '${over_limit}' (it must be flagged)")
  endif()
  message(STATUS "flags a function of ${over} lines (${over_limit}), passes one of ${LINES}")
  return()
endif()

# Still over the limit, each with the reason; the list may only shrink (a function listed here
# that is short now fails the test until it is taken off). Empty: every function is short.
set(known_long)

file(GLOB files "${ROOT}/cmake/tools/*.cpp" "${ROOT}/tests/grading/*.cpp" "${ROOT}/tests/grading/remote/*.cpp")
set(TIDY_EXTRA -p "${BUILD}" "--header-filter=.*/(cmake/tools|tests/grading)/.*")
long_functions(found ${files})
list(TRANSFORM found REPLACE "^${ROOT}/" "")
set(new_long "${found}")
if(known_long)
  list(REMOVE_ITEM new_long ${known_long})
endif()
set(now_short "${known_long}")
if(found)
  list(REMOVE_ITEM now_short ${found})
endif()
list(LENGTH files n)
list(JOIN known_long "\n  " listed)
# The scenes: only main is held to the limit (a scene's steps are its other functions).
file(GLOB scenes "${ROOT}/chapters/*/*.cpp")
set(TIDY_EXTRA -p "${BUILD}" "--header-filter=^$")
long_functions(scene_long ${scenes})
list(FILTER scene_long INCLUDE REGEX ": (function 'main'|clang-tidy failed)")
list(TRANSFORM scene_long REPLACE "^${ROOT}/" "")
list(APPEND new_long ${scene_long})
list(LENGTH scenes n_scenes)

if(new_long OR now_short)
  list(JOIN new_long "\n  " lines)
  list(JOIN now_short "\n  " short)
  message(FATAL_ERROR "functions over ${LINES} lines (split them into named steps):\n  ${lines}\n"
                      "listed as long in cmake/function_size.cmake but no longer over ${LINES} lines "
                      "(take them off the list):\n  ${short}")
endif()
if(known_long)
  message(STATUS "${n} sources of cmake/tools and tests/grading: no function over ${LINES} lines but the "
                 "ones listed in cmake/function_size.cmake:\n  ${listed}\n"
                 "${n_scenes} sources of chapters/: no main over ${LINES} lines")
else()
  message(STATUS "${n} sources of cmake/tools and tests/grading: no function over ${LINES} lines; "
                 "${n_scenes} sources of chapters/: no main over ${LINES} lines")
endif()
