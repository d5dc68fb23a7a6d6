# Short functions: no function in chapters/ (the scenes and the kit), exercises/provided/ (the code
# given to students), cmake/ (the book's tools and live build, the support library, the checks) or
# tests/grading/ (the grading run, its judge and student side, the mutation gate) is longer than
# LINES lines, as clang-tidy's readability-function-size counts them (its LineThreshold: the lines
# after the opening brace's line). A scene reads as named steps (parse, compute, report, draw),
# each a function of its own. The graders' test suites (tests/*_test.cpp) are not held to it.
#
# The lengths come from cmake/checks/function_size.cpp (universal-ctags finds the functions, a small
# lexer their bodies), which reads every source in about a second without compiling it; clang-tidy,
# which compiles each one, took over half an hour for the same sources on a loaded 2-core machine.
#
#   cmake -DTOOL=<function_size> -DROOT=<workbook> -DLINES=<n> -P cmake/checks/function_size.cmake
#       checks the sources;
#   cmake -DTOOL=<function_size> -DTIDY=<clang-tidy> -DROOT=<workbook> -DSELFTEST=<scratch folder>
#         -DLINES=<n> -P cmake/checks/function_size.cmake
#       the check must be able to fail and must count as clang-tidy does: it must flag a function
#       of LINES + 1 lines and pass one of LINES, and give every function of
#       cmake/checks/function_size_shapes.cpp (a wrapped signature, members, braces in strings and raw
#       strings, a lambda inside, ...) the length clang-tidy gives it.
if(NOT TOOL OR NOT EXISTS "${TOOL}")
  message(FATAL_ERROR "the function-size tool was not built (target function_size): '${TOOL}'")
endif()
find_program(CTAGS NAMES ctags universal-ctags)
if(NOT CTAGS)
  # Outside CI the test reports itself skipped (SKIP_REGULAR_EXPRESSION), like the browser tests.
  if("$ENV{CI}" STREQUAL "true")
    message(FATAL_ERROR "universal-ctags was not found: sudo apt-get install universal-ctags (cmake/workbook test installs it)")
  endif()
  message(FATAL_ERROR "SKIPPED: universal-ctags was not found (sudo apt-get install universal-ctags; cmake/workbook test installs it)")
endif()

# The tool's rows for the files over `limit` lines: "path:line: function 'name' has N lines".
function(tool_rows out limit)
  execute_process(COMMAND "${TOOL}" --lines ${limit} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE text ERROR_VARIABLE err)
  if(rc GREATER 1 OR err)
    message(FATAL_ERROR "the function-size tool failed (${rc}):\n${err}")
  endif()
  string(REGEX MATCHALL "[^\n]+" rows "${text}")
  set(${out} "${rows}" PARENT_SCOPE)
endfunction()

# The functions of `files` over `limit` lines, one "path:line: N" a line (the name left out:
# clang-tidy writes 'operator==' where ctags writes 'operator =='), from the tool.
function(measured_by_tool out limit)
  tool_rows(rows ${limit} ${ARGN})
  list(TRANSFORM rows REPLACE "^([^:]+:[0-9]+): function '.*' has ([0-9]+) lines$" "\\1: \\2")
  set(${out} "${rows}" PARENT_SCOPE)
endfunction()

# The same by clang-tidy, which compiles the file (a self-contained one: -std=c++20 only).
function(measured_by_tidy out limit file)
  set(config "{CheckOptions: [{key: readability-function-size.LineThreshold, value: ${limit}}]}")
  execute_process(COMMAND "${TIDY}" --quiet "--checks=-*,readability-function-size" "--config=${config}"
                          "${file}" -- -std=c++20
                  RESULT_VARIABLE rc OUTPUT_VARIABLE text ERROR_VARIABLE err)
  string(REGEX MATCHALL "[^\n]*:[0-9]+:[0-9]+: note: [0-9]+ lines including" rows "${text}")
  list(TRANSFORM rows REPLACE "^(.*):([0-9]+):[0-9]+: note: ([0-9]+) lines including" "\\1:\\2: \\3")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "clang-tidy failed on ${file} (${rc}): ${text}${err}")
  endif()
  set(${out} "${rows}" PARENT_SCOPE)
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
  measured_by_tool(at_limit ${LINES} "${SELFTEST}/f${LINES}.cpp")
  measured_by_tool(over_limit ${LINES} "${SELFTEST}/f${over}.cpp")
  if(at_limit OR NOT over_limit STREQUAL "${SELFTEST}/f${over}.cpp:1: ${over}")
    message(FATAL_ERROR "the function-size check is broken: a function of ${LINES} lines gave '${at_limit}', "
                        "one of ${over} lines gave '${over_limit}' (it must be flagged, with ${over} lines)")
  endif()
  message(STATUS "flags a function of ${over} lines (${over_limit}), passes one of ${LINES}")
  if(NOT TIDY OR NOT EXISTS "${TIDY}")
    if("$ENV{CI}" STREQUAL "true")
      message(FATAL_ERROR "clang-tidy was not found: sudo apt-get install clang-tidy (cmake/workbook test installs it)")
    endif()
    message(FATAL_ERROR "SKIPPED: clang-tidy was not found, to compare the counts with (sudo apt-get install clang-tidy)")
  endif()
  set(shapes "${ROOT}/cmake/checks/function_size_shapes.cpp")
  measured_by_tool(by_tool 0 "${shapes}")
  measured_by_tidy(by_tidy 0 "${shapes}")
  list(SORT by_tool)
  list(SORT by_tidy)
  list(LENGTH by_tidy n)
  if(NOT by_tool STREQUAL by_tidy OR n LESS 10)
    list(JOIN by_tool "\n  " a)
    list(JOIN by_tidy "\n  " b)
    message(FATAL_ERROR "the function-size tool and clang-tidy disagree on ${shapes}:\n"
                        "the tool:\n  ${a}\nclang-tidy:\n  ${b}")
  endif()
  message(STATUS "measures the ${n} functions of cmake/checks/function_size_shapes.cpp as clang-tidy does")
  return()
endif()

set(files "")
foreach(folder IN ITEMS chapters exercises/provided cmake tests/grading)
  file(GLOB_RECURSE found "${ROOT}/${folder}/*.cpp" "${ROOT}/${folder}/*.hpp")
  list(APPEND files ${found})
endforeach()
list(REMOVE_ITEM files "${ROOT}/cmake/checks/function_size_shapes.cpp")  # the self-test's shapes, long on purpose
list(LENGTH files n)
tool_rows(found ${LINES} ${files})
list(TRANSFORM found REPLACE "^${ROOT}/([^:]+):[0-9]+: (function '.*') has ([0-9]+) lines$" "\\1: \\2 (\\3 lines)")
if(found)
  list(JOIN found "\n  " lines)
  message(FATAL_ERROR "functions over ${LINES} lines (split them into named steps):\n  ${lines}")
endif()
message(STATUS "${n} sources of chapters/, exercises/provided/, cmake/ and tests/grading/: no function over "
               "${LINES} lines")
