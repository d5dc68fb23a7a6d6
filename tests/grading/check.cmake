# The student's check (included from tests/grading/CMakeLists.txt). The hint ladders (hints.cpp):
# `cmake/workbook check` prints Hint 1 of the first exercise that fails (report.cpp), and
# `cmake/workbook check <exercise> --hint N` runs workbook_hints, which builds in seconds,
# without the graders. pristine.cpp: where the stubs as committed are (cmake/pristine_stubs.cmake).
target_sources(workbook_grading PRIVATE "${CMAKE_CURRENT_LIST_DIR}/hints.cpp" "${CMAKE_CURRENT_LIST_DIR}/pristine.cpp")

add_executable(workbook_hints "${CMAKE_CURRENT_LIST_DIR}/workbook_hints.cpp" "${CMAKE_CURRENT_LIST_DIR}/hints.cpp")
set_target_properties(workbook_hints PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/grading")
target_link_libraries(workbook_hints PRIVATE workbook_support CLI11::CLI11)
workbook_warnings(workbook_hints)

add_executable(test_hints "${CMAKE_CURRENT_LIST_DIR}/hints_test.cpp" "${CMAKE_CURRENT_LIST_DIR}/hints.cpp")
target_include_directories(test_hints PRIVATE "${CMAKE_CURRENT_LIST_DIR}")
target_link_libraries(test_hints PRIVATE doctest::doctest workbook_support)
workbook_warnings(test_hints)

set(hints_file "${WORKBOOK_ROOT}/exercises/hints.md")
add_test(NAME "hints: the reader, the terminal printer and the code rule catch planted bad hints and malformed files"
         COMMAND test_hints)
add_test(NAME "hints: every graded exercise has a ladder of 2-3 levels, no TeX left in the terminal, no code in any rung"
         COMMAND workbook_hints lint "${hints_file}" --manifest "${CMAKE_BINARY_DIR}/grading/manifest.txt")
# `cmake/workbook check <exercise> --hint N` ends in this command: each level, and a clear refusal.
add_test(NAME "hints: --hint N shows level N of the ladder and refuses a level the ladder does not have"
         COMMAND bash -c [=[set -e
           for n in 1 2 3; do "$1" show "$2" rotation_about $n | grep -q "^Hint $n of 3 for rotation_about"; done
           "$1" show "$2" rotation_about 1 | grep -q -- "--hint 2"
           if out=$("$1" show "$2" rotation_about 4 2>&1); then exit 1; fi
           grep -q "from 1 to 3" <<<"$out"
           if out=$("$1" show "$2" no_such_exercise 1 2>&1); then exit 1; fi
           grep -q "no hints for 'no_such_exercise'" <<<"$out"]=]
                 hints-show $<TARGET_FILE:workbook_hints> "${hints_file}")
set_tests_properties("hints: the reader, the terminal printer and the code rule catch planted bad hints and malformed files"
                     "hints: every graded exercise has a ladder of 2-3 levels, no TeX left in the terminal, no code in any rung"
                     "hints: --hint N shows level N of the ladder and refuses a level the ladder does not have"
                     PROPERTIES LABELS hints TIMEOUT 60)

# An exercise the student has not started (the pristine stub) gets no hint, only how to ask.
add_test(NAME "check: an exercise not started gets no hint, only the command that asks for one"
         COMMAND bash -c [=[out=$("$1" check --setup "$2" --folder "$3" --out "$4" hat 2>&1)
           printf '%s\n' "$out"
           grep -q "not started" <<<"$out" && grep -q -- "cmake/workbook check hat --hint 1" <<<"$out" &&
             ! grep -q "^Hint 1 of" <<<"$out"]=]
                 check-not-started $<TARGET_FILE:workbook_grade> "${CMAKE_BINARY_DIR}/grading" "${WORKBOOK_PRISTINE_DIR}"
                 "${CMAKE_BINARY_DIR}/check-not-started")
set_tests_properties("check: an exercise not started gets no hint, only the command that asks for one"
                     PROPERTIES LABELS "hints;grading" TIMEOUT 300)
