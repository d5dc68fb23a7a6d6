# The quality gates (cmake/checks/, README.md there): checks of the workbook's own sources and pages
# that no compiler makes. Each comes with a self-test that plants the fault it hunts:
#   function_size.cmake  no function over WORKBOOK_FUNCTION_LINES lines (function_size.cpp, universal-ctags)
#   format_check.cmake   every C++ source laid out as .clang-format says
#   include_check.cmake  what a scene, a grader and the grading engine may include
#   readme/              the front doors: every command the pages tell a user to type, run as written
#   load/                the same answers on a busy machine: doors run idle and beside CPU hogs
#   margins.sh           (a maintainer's tool, no test) the graders' margins on the reference solutions
# Included by cmake/Workbook.cmake; each workbook_*() below is called once, after every target.
include_guard(GLOBAL)

# Short functions in chapters/, exercises/provided/, cmake/ and tests/grading/: none over
# WORKBOOK_FUNCTION_LINES lines, as clang-tidy's readability-function-size counts them, measured in
# a second by the tool function_size (universal-ctags and a lexer: cmake/checks/function_size.cmake, which
# cmake/workbook test installs). A second test proves the check can fail and that it counts as
# Debian's clang-tidy does on functions of every shape.
set(WORKBOOK_FUNCTION_LINES 60 CACHE STRING "The longest function allowed in chapters, exercises/provided, cmake and tests/grading")
function(workbook_function_size)
  add_executable(function_size "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/function_size.cpp")
  target_link_libraries(function_size PRIVATE nlohmann_json::nlohmann_json CLI11::CLI11 workbook_support)
  workbook_warnings(function_size)
  target_compile_options(function_size PRIVATE -O1)
  set_target_properties(function_size PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/tools")
  find_program(CLANG_TIDY_EXECUTABLE NAMES clang-tidy clang-tidy-14)
  set(tidy "${CLANG_TIDY_EXECUTABLE}")
  if(NOT tidy)
    set(tidy "")
  endif()
  set(script "${WORKBOOK_ROOT}/cmake/checks/function_size.cmake")
  set(check "code: no function in chapters, exercises/provided, cmake or tests/grading is over ${WORKBOOK_FUNCTION_LINES} lines")
  set(selftest "code: the function-size check flags a function one line too long and counts as clang-tidy does")
  add_test(NAME "${check}"
           COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:function_size> -DROOT=${WORKBOOK_ROOT}
                   -DLINES=${WORKBOOK_FUNCTION_LINES} -P "${script}")
  add_test(NAME "${selftest}"
           COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:function_size> -DTIDY=${tidy} -DROOT=${WORKBOOK_ROOT}
                   -DSELFTEST=${CMAKE_BINARY_DIR}/test/function-size -DLINES=${WORKBOOK_FUNCTION_LINES} -P "${script}")
  set_tests_properties("${check}" "${selftest}" PROPERTIES LABELS code TIMEOUT 300
                       SKIP_REGULAR_EXPRESSION "SKIPPED: (clang-tidy|universal-ctags) was not found")
endfunction()

# ------------------------------------------------------------------------------------------
# What each kind of source may include (include_check.cmake): a scene the reference and nothing else
# of tests/, no scene or grader the grading engine or the book's tools, the grading engine no scene;
# checked with every target's own include path and on every quoted #include of their sources. The
# self-test plants one fault of each kind and must see each flagged.
function(workbook_include_check)
  set(text "")
  get_property(scenes GLOBAL PROPERTY WORKBOOK_SCENE_LIST)
  foreach(entry IN LISTS scenes)
    string(REPLACE "|" ";" parts "${entry}")
    list(GET parts 1 name)
    list(APPEND roles "scene|${name}")
  endforeach()
  get_property(graders GLOBAL PROPERTY WORKBOOK_GRADER_LIST)
  foreach(entry IN LISTS graders)
    string(REPLACE "|" ";" parts "${entry}")
    list(GET parts 0 topic)
    list(APPEND roles "grader|grade_${topic}_objects")
  endforeach()
  get_property(units GLOBAL PROPERTY WORKBOOK_UNIT_TESTS)
  foreach(name IN LISTS units)
    list(APPEND roles "grader|${name}")
  endforeach()
  foreach(name IN ITEMS workbook_grading workbook_catalog workbook_api_objects workbook_api workbook_grade workbook_hints
                        workbook_topics workbook_judge workbook_serve workbook_mutants)
    list(APPEND roles "engine|${name}")
  endforeach()
  foreach(entry IN LISTS roles)
    string(REPLACE "|" ";" parts "${entry}")
    list(GET parts 1 name)
    string(APPEND text "${entry}|$<JOIN:$<TARGET_PROPERTY:${name},INCLUDE_DIRECTORIES>,|>\n")
  endforeach()
  set(list "${CMAKE_BINARY_DIR}/test/include_check_targets.txt")
  file(GENERATE OUTPUT "${list}" CONTENT "${text}")
  set(script "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/include_check.cmake")
  set(check "code: a scene reaches the reference and nothing else of tests/, no scene or grader the grading engine or the book's tools, the grading engine no scene")
  set(selftest "code: the include check flags a planted include path and a planted #include of each kind")
  set(args -DCXX=${CMAKE_CXX_COMPILER} -DROOT=${WORKBOOK_ROOT} -DTARGETS=${list})
  add_test(NAME "${check}" COMMAND ${CMAKE_COMMAND} ${args} -DWORK=${CMAKE_BINARY_DIR}/test/include-check
                                   -P "${script}")
  add_test(NAME "${selftest}" COMMAND ${CMAKE_COMMAND} ${args} -DWORK=${CMAKE_BINARY_DIR}/test/include-check-selftest
                                      -DPLANT=ON -P "${script}")
  set_tests_properties("${check}" "${selftest}" PROPERTIES LABELS code TIMEOUT 300)
endfunction()

# ------------------------------------------------------------------------------------------
# The layout of the C++ sources: as .clang-format says (cmake/checks/format_check.cmake; Debian's
# clang-format, which cmake/workbook test installs). A second test proves the check can fail.
function(workbook_format_check)
  find_program(CLANG_FORMAT_EXECUTABLE NAMES clang-format clang-format-14)
  set(format "${CLANG_FORMAT_EXECUTABLE}")
  if(NOT format)
    set(format "")
  endif()
  set(script "${WORKBOOK_ROOT}/cmake/checks/format_check.cmake")
  set(check "code: every C++ source is laid out as .clang-format says")
  set(selftest "code: the format check flags a badly laid out file")
  add_test(NAME "${check}" COMMAND ${CMAKE_COMMAND} -DFORMAT=${format} -DROOT=${WORKBOOK_ROOT} -P "${script}")
  add_test(NAME "${selftest}"
           COMMAND ${CMAKE_COMMAND} -DFORMAT=${format} -DROOT=${WORKBOOK_ROOT}
                   -DSELFTEST=${CMAKE_BINARY_DIR}/test/format-check -P "${script}")
  set_tests_properties("${check}" "${selftest}" PROPERTIES LABELS code
                       SKIP_REGULAR_EXPRESSION "SKIPPED: clang-format was not found")
endfunction()

# ------------------------------------------------------------------------------------------
# The front doors (readme/): every command of the front page, the instructor's manual, the
# contributors' page and the chapters' "Check your work", run as written in a scratch clone.
function(workbook_door_tests)
  add_subdirectory("${CMAKE_CURRENT_FUNCTION_LIST_DIR}/readme" "${CMAKE_BINARY_DIR}/checks/readme")
endfunction()

# ------------------------------------------------------------------------------------------
# The same answers on a busy machine (load/): a small class graded, a student's check of the
# chapter with the heaviest grader and the default run of the sweep scenes, once as the machine
# is and once beside four CPU hogs that the test starts and kills itself; everything but run
# times must be the same. Its self-test plants a sweep that stops on seconds, and must fail.
function(workbook_load_test)
  find_package(Python3 REQUIRED COMPONENTS Interpreter)
  set(script "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/load/load.py")
  set(check "load: a class graded, a check and the sweep scenes give the same answers beside four CPU hogs")
  set(selftest "load: the load test flags a sweep that stops on seconds")
  add_test(NAME "${check}" COMMAND ${Python3_EXECUTABLE} "${script}" --build "${CMAKE_BINARY_DIR}"
                                   --root "${WORKBOOK_ROOT}" --work "${CMAKE_BINARY_DIR}/test/load")
  add_test(NAME "${selftest}" COMMAND ${Python3_EXECUTABLE} "${script}" --build "${CMAKE_BINARY_DIR}"
                                      --root "${WORKBOOK_ROOT}" --work "${CMAKE_BINARY_DIR}/test/load-planted"
                                      --plant --only-planted)
  set_tests_properties("${selftest}" PROPERTIES PASS_REGULAR_EXPRESSION
                       "FAILED: the load changed more than run times:.*planted wall-clock sweep: 1 differences")
  set_tests_properties("${check}" "${selftest}" PROPERTIES LABELS "load;grading" TIMEOUT 1200 PROCESSORS 2)
endfunction()

# ------------------------------------------------------------------------------------------
# Contracts state every rule the graders check (contracts.py): each CHECK_THROWS of an exercise
# names what it rejects in its arguments (NaN or infinity, an empty list or state, a zero vector,
# the exception), and the exercise's comment in exercises/rigid/ must say so. Its self-test plants
# a header without its empty-state rule, one without "finite" and a grader expecting an exception
# no contract names; each must be flagged.
function(workbook_contract_check)
  find_package(Python3 REQUIRED COMPONENTS Interpreter)
  set(script "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/contracts.py")
  set(check "code: every rejection a grader tests is stated in the exercise's contract")
  set(selftest "code: the contract check flags a rule missing from a contract and an exception no contract names")
  add_test(NAME "${check}" COMMAND ${Python3_EXECUTABLE} "${script}" check --root "${WORKBOOK_ROOT}")
  add_test(NAME "${selftest}" COMMAND ${Python3_EXECUTABLE} "${script}" selftest --root "${WORKBOOK_ROOT}"
                                      --work "${CMAKE_BINARY_DIR}/test/contracts")
  set_tests_properties("${check}" "${selftest}" PROPERTIES LABELS code TIMEOUT 120)
endfunction()

# ------------------------------------------------------------------------------------------
# Every failing check shows what it was given (messages.py): each grader's failure messages, on the
# pristine stubs and at every check of the reference (the workbook reporter with --success), must
# name the check's inputs (tests/inputs.hpp, INPUTS), not only loop indices or bare numbers; the
# tests messages_baseline.txt lists are known offenders, and one that no longer offends must be taken
# out of it. A second reads the same on one planted wrong answer per exercise, as the grading run
# shows it (tests/grading/grading.cmake). The self-test plants messages without inputs.
function(workbook_message_check)
  if(NOT WORKBOOK_STUB_GATE)
    return()  # the stubs' graders are not built
  endif()
  find_package(Python3 REQUIRED COMPONENTS Interpreter)
  set(script "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/messages.py")
  set(check "code: every failing check of a grader shows its inputs, on the stubs and at every check")
  set(selftest "code: the message check flags a failing check that shows only loop indices or a bare number")
  add_test(NAME "${check}" COMMAND ${Python3_EXECUTABLE} "${script}" check --build "${CMAKE_BINARY_DIR}"
                                   --root "${WORKBOOK_ROOT}")
  add_test(NAME "${selftest}" COMMAND ${Python3_EXECUTABLE} "${script}" selftest
                                      --work "${CMAKE_BINARY_DIR}/test/messages-selftest")
  set_tests_properties("${check}" "${selftest}" PROPERTIES LABELS code TIMEOUT 120)
  set_tests_properties("${selftest}" PROPERTIES PASS_REGULAR_EXPRESSION
                       "the planted messages without inputs were flagged, and the one with them was not")
endfunction()
