# The grading run (tests/grading/, its manual README.md): `cmake/workbook grade` (the instructor's
# batch run over a class), `cmake/workbook check` (the student's own check), the Gradescope and
# cluster deployments, and the two gates that prove the graders can fail (the stub gate and the
# mutation gate). One room:
#   engine/    the library workbook_grading and its programs (workbook_grade, workbook_hints), the two
#              processes of a graded test (remote/: the judge and the student's side), the class report
#   tests/     the grading run's own tests and their fixtures (cases/, similarity/, private/)
#   mutants/   the gates: the mutation gate (workbook_mutants, the likely-mistakes catalogue) and the
#              stub gate (stub_gate)
#   deploy/    Gradescope (gradescope/) and the cluster recipes (cluster/)
# The engine includes the API headers (exercises/), the graders' checks.hpp and reference (tests/) and
# the support library, never a scene (chapters/) or the book's tools; no scene or grader includes
# the engine (cmake/checks/include_check.cmake).
#
# Included by the top-level CMakeLists.txt after every topic, provided library and grader is
# declared (workbook_topic()); workbook_grading() is called once, after the chapters.
include_guard(GLOBAL)
set(WORKBOOK_GRADING_DIR "${CMAKE_CURRENT_LIST_DIR}")

# Private tests: graders an instructor adds that students never see (README.md, "Private tests").
#
#   cmake -DWORKBOOK_PRIVATE_TESTS=<folder> ...   (cmake/workbook grade|gradescope --private-tests <folder>)
#
# <folder>/<topic>_test.cpp is written like tests/<topic>_test.cpp (the same includes and
# checks, test cases named "<function>: ..."). Per topic that has one:
#   private_<topic>_objects   its compiled tests, linked into judge_<topic> (the trusted process)
#                             and never into anything a student's file is linked with;
#   grade_<topic>_private     those tests on the reference solution: the manifest lists their
#                             names from it, and the build stops when one fails on the reference.
# cmake/workbook check configures with the variable empty, so a student's check never builds them.
set(WORKBOOK_PRIVATE_TESTS "" CACHE PATH "A folder of private graders, <topic>_test.cpp (empty: none)")

# workbook_private_grader(<topic> <out-var>): the object target of the topic's private tests, or
# "" when the folder has none for it.
function(workbook_private_grader topic out)
  set(${out} "" PARENT_SCOPE)
  if(WORKBOOK_PRIVATE_TESTS STREQUAL "")
    return()
  endif()
  get_filename_component(dir "${WORKBOOK_PRIVATE_TESTS}" ABSOLUTE)
  if(NOT IS_DIRECTORY "${dir}")
    message(FATAL_ERROR "WORKBOOK_PRIVATE_TESTS: '${dir}' is not a folder")
  endif()
  if(dir MATCHES "[,*?]")
    message(FATAL_ERROR "WORKBOOK_PRIVATE_TESTS: '${dir}' holds a comma or a wildcard, which doctest's file filter cannot name")
  endif()
  set(file "${dir}/${topic}_test.cpp")
  if(NOT EXISTS "${file}")
    return()
  endif()
  add_library(private_${topic}_objects OBJECT "${file}")
  target_include_directories(private_${topic}_objects PRIVATE "${WORKBOOK_ROOT}/tests"
                             $<TARGET_PROPERTY:rigid_${topic},INTERFACE_INCLUDE_DIRECTORIES>)
  target_link_libraries(private_${topic}_objects PRIVATE doctest::doctest Eigen3::Eigen workbook_reference)
  workbook_warnings(private_${topic}_objects)
  add_executable(grade_${topic}_private $<TARGET_OBJECTS:private_${topic}_objects>)
  target_link_libraries(grade_${topic}_private PRIVATE workbook_doctest_main rigid_${topic}_solutions doctest::doctest)
  set_target_properties(grade_${topic}_private PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/grading/private")
  workbook_warnings(grade_${topic}_private)
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_PRIVATE_LIST "${topic}|${file}")
  set(${out} private_${topic}_objects PARENT_SCOPE)
endfunction()


# The stub gate: every grading test passes on solutions/ and fails on the pristine stubs.
function(workbook_stub_gate)
  # Its runner (mutants/stub_gate.cpp), built in every build folder (CONTRIBUTING.md runs it by hand).
  add_executable(stub_gate "${WORKBOOK_GRADING_DIR}/mutants/stub_gate.cpp")
  target_link_libraries(stub_gate PRIVATE workbook_support nlohmann_json::nlohmann_json CLI11::CLI11)
  set_target_properties(stub_gate PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/tests")
  workbook_warnings(stub_gate)
  if(NOT WORKBOOK_STUB_GATE)
    return()
  endif()
  get_property(args GLOBAL PROPERTY WORKBOOK_GATE_ARGS)
  add_test(NAME "stub gate: every grading test passes on solutions and fails on the stubs"
           COMMAND stub_gate ${args})
  set_tests_properties("stub gate: every grading test passes on solutions and fails on the stubs"
                       PROPERTIES LABELS "gate" TIMEOUT 600)
  # The gate itself must be able to fail: handed the reference as if it were the stubs,
  # it must find every test "passing on the stubs" and say so.
  list(GET args 0 topic)
  list(GET args 1 reference)
  add_test(NAME "stub gate: fails when a grader passes on its stubs"
           COMMAND stub_gate "${topic}" "${reference}" "${reference}")
  set_tests_properties("stub gate: fails when a grader passes on its stubs" PROPERTIES
                       LABELS "gate" WILL_FAIL TRUE)
  # The stubs refusing every input (mutants/refuse.hpp): a test made only of checks that a bad
  # input is refused must check one valid input too, or it gives points for refusing (issue 42).
  get_property(refusing GLOBAL PROPERTY WORKBOOK_REFUSING_GATE_ARGS)
  add_test(NAME "stub gate: every grading test fails on stubs that refuse every input"
           COMMAND stub_gate --stubs "the stubs that refuse every input" ${refusing})
  set_tests_properties("stub gate: every grading test fails on stubs that refuse every input" PROPERTIES
                       LABELS "gate" TIMEOUT 600 RESOURCE_LOCK stub_gate_reports)
  # Both write stub_gate_<topic>_*.jsonl in the build folder: never at the same time.
  set_tests_properties("stub gate: every grading test passes on solutions and fails on the stubs"
                       "stub gate: fails when a grader passes on its stubs" PROPERTIES RESOURCE_LOCK stub_gate_reports)
endfunction()

# ------------------------------------------------------------------------------------------
# The build's facts for the grading run. _grading_facts() writes grading/topics.txt, the facts the
# harness needs about every topic that has graders: its chapter, the grader's compiled test
# objects and the exact files to link a student's object with (the doctest main and the reference
# libraries of its dependencies, with their own libraries). The target `grading` builds all of it
# once, plus grading/manifest.txt (every exercise and test, listed from the reference graders).

# The files to link after a student's object, for the link interface of <items>: the closure
# of their link libraries in link order (each library before the ones it needs).
function(_workbook_link_closure out_files out_targets)
  set(files "")
  set(targets "")
  set(stack ${ARGN})
  set(steps 0)
  while(stack)
    list(POP_FRONT stack item)
    math(EXPR steps "${steps} + 1")
    if(steps GREATER 10000)
      message(FATAL_ERROR "workbook_grading: the link libraries of ${ARGN} do not terminate")
    endif()
    if(item MATCHES "^\\$<LINK_ONLY:(.+)>$")
      set(item "${CMAKE_MATCH_1}")
    endif()
    if(item STREQUAL "")
      continue()
    endif()
    if(TARGET "${item}")
      get_target_property(real "${item}" ALIASED_TARGET)
      if(real)
        set(item "${real}")
      endif()
      get_target_property(type "${item}" TYPE)
      get_target_property(imported "${item}" IMPORTED)
      if(type MATCHES "^(STATIC|SHARED|UNKNOWN)_LIBRARY$")
        list(APPEND files "$<TARGET_LINKER_FILE:${item}>")
      elseif(type STREQUAL "OBJECT_LIBRARY")
        list(APPEND files "$<TARGET_OBJECTS:${item}>")
      endif()
      if(NOT imported AND NOT type STREQUAL "INTERFACE_LIBRARY")
        list(APPEND targets "${item}")
      endif()
      get_target_property(next "${item}" INTERFACE_LINK_LIBRARIES)
      if(next)
        list(PREPEND stack ${next})
      endif()
    elseif(item MATCHES "^-" OR IS_ABSOLUTE "${item}" OR item MATCHES "^\\$<")
      list(APPEND files "${item}")
    else()
      list(APPEND files "-l${item}")
    endif()
  endwhile()
  # Keep the last occurrence of each: every library then comes after all that need it.
  list(REVERSE files)
  list(REMOVE_DUPLICATES files)
  list(REVERSE files)
  list(REMOVE_DUPLICATES targets)
  set(${out_files} "${files}" PARENT_SCOPE)
  set(${out_targets} "${targets}" PARENT_SCOPE)
endfunction()

# The topics the grading run grades: WORKBOOK_GRADING_TOPICS ("rotation;precession", or with spaces
# or commas between them; empty for every topic with graders). The Gradescope autograder (cmake/workbook gradescope) builds
# only these, so an assignment on one chapter builds and grades one chapter.
set(WORKBOOK_GRADING_TOPICS "" CACHE STRING "Grade only these topics (empty: every topic with graders)")
function(workbook_grading_graders out)
  get_property(graders GLOBAL PROPERTY WORKBOOK_GRADER_LIST)
  workbook_topic_names(wanted WORKBOOK_GRADING_TOPICS CHECKED)
  set(kept "")
  foreach(entry IN LISTS graders)
    string(REPLACE "|" ";" fields "${entry}")
    list(GET fields 0 topic)
    if(NOT wanted OR topic IN_LIST wanted)
      list(APPEND kept "${entry}")
    endif()
  endforeach()
  set(${out} "${kept}" PARENT_SCOPE)
endfunction()

# grading/catalog.json: every topic with graders, its chapter and its stub as committed, in chapter
# order, whatever WORKBOOK_GRADING_TOPICS keeps, and where the table of contents is: what
# workbook_topics and `workbook_grade check` read to know what a chapter, a topic or an exercise
# named on the command line means (engine/catalog.hpp). Written when CMake configures, from the
# workbook_topic() declarations, the one place the topics are declared.
function(_grading_catalog file)
  get_property(graders GLOBAL PROPERTY WORKBOOK_GRADER_LIST)
  get_property(contents GLOBAL PROPERTY WORKBOOK_CONTENTS)
  set(json "{}")
  string(JSON json SET "${json}" root "\"${WORKBOOK_ROOT}\"")
  string(JSON json SET "${json}" contents "\"${contents}\"")
  string(JSON json SET "${json}" topics "[]")
  set(n 0)
  foreach(entry IN LISTS graders)
    string(REPLACE "|" ";" fields "${entry}")
    list(GET fields 0 topic)
    list(GET fields 1 chapter)
    set(from_git true)
    if("${topic}.cpp" IN_LIST WORKBOOK_PRISTINE_FROM_TREE)
      set(from_git false)
    endif()
    string(JSON json SET "${json}" topics ${n}
           "{\"name\": \"${topic}\", \"chapter\": \"${chapter}\", \"stub\": \"${WORKBOOK_PRISTINE_DIR}/${topic}.cpp\", \"stub_from_git\": ${from_git}}")
    math(EXPR n "${n} + 1")
  endforeach()
  file(CONFIGURE OUTPUT "${file}" CONTENT "${json}\n" @ONLY)
endfunction()

function(_grading_facts)
  workbook_grading_graders(graders)
  set(dir "${CMAKE_BINARY_DIR}/grading")
  _grading_catalog("${dir}/catalog.json")
  string(TOUPPER "${CMAKE_BUILD_TYPE}" config)
  set(facts "# Generated by CMake (workbook_grading in tests/grading/grading.cmake): the facts the grading run needs.\n")
  string(APPEND facts "root\t${WORKBOOK_ROOT}\n")
  get_property(contents GLOBAL PROPERTY WORKBOOK_CONTENTS)
  string(APPEND facts "contents\t${contents}\n")
  string(APPEND facts "build\t${CMAKE_BINARY_DIR}\n")
  string(APPEND facts "compiler\t${CMAKE_CXX_COMPILER}\n")
  string(APPEND facts "nm\t${CMAKE_NM}\n")
  string(APPEND facts "compile_commands\t${CMAKE_BINARY_DIR}/compile_commands.json\n")
  string(APPEND facts "link_flags\t${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${config}} ${CMAKE_EXE_LINKER_FLAGS}\n")
  set(references "")
  set(needed workbook_doctest_main)
  foreach(entry IN LISTS graders)
    string(REPLACE "|" ";" entry "${entry}")
    list(GET entry 0 topic)
    list(GET entry 1 chapter)
    if(TARGET grade_${topic}_solutions)
      set(reference grade_${topic}_solutions)
    else()
      set(reference grade_${topic})
    endif()
    list(APPEND references ${reference})
    get_target_property(interface rigid_${topic}_solutions INTERFACE_LINK_LIBRARIES)
    if(NOT interface)
      set(interface "")
    endif()
    _workbook_link_closure(files targets ${interface})
    list(APPEND needed grade_${topic}_objects ${targets})
    string(APPEND facts "topic\t${topic}\t${chapter}\n")
    string(APPEND facts "reference\t$<TARGET_FILE:${reference}>\n")
    string(APPEND facts "objects\t$<JOIN:$<TARGET_OBJECTS:grade_${topic}_objects>,\t>\n")
    if(TARGET grade_${topic}_private)  # tests/grading/grading.cmake: listed, never linked for a student
      string(APPEND facts "private\t$<TARGET_FILE:grade_${topic}_private>\n")
      list(APPEND references grade_${topic}_private)
    endif()
    string(APPEND facts "link")
    foreach(f IN LISTS files)
      string(APPEND facts "\t${f}")
    endforeach()
    string(APPEND facts "\n")
  endforeach()
  file(GENERATE OUTPUT "${dir}/topics.txt" CONTENT "${facts}")
  set(points "${WORKBOOK_ROOT}/tests/grading/points.txt")
  add_custom_command(OUTPUT "${dir}/manifest.txt"
    COMMAND workbook_grade manifest --topics "${dir}/topics.txt" --points "${points}"
            --out "${dir}/manifest.txt"
    DEPENDS workbook_grade ${references} "${dir}/topics.txt" "${points}" workbook_doctest_main
            "${contents}"
    COMMENT "Listing the graders' exercises and tests in grading/manifest.txt")
  add_custom_target(grading ALL DEPENDS "${dir}/manifest.txt")
  list(REMOVE_DUPLICATES needed)
  add_dependencies(grading workbook_grade ${needed})
  if(TARGET grading_remote)
    add_dependencies(grading grading_remote)  # the judges and the student's side (_grading_remote)
  endif()
endfunction()

# ------------------------------------------------------------------------------------------
# The engine: the library and its programs, and the student's check (hint ladders, pristine stubs).
function(_grading_engine)
  set(G "${WORKBOOK_GRADING_DIR}")
  set(sources setup stage grade report similarity gradebook item_analysis class_report provenance mistakes calls
              private hints pristine)
  list(TRANSFORM sources REPLACE "(.+)" "${G}/engine/\\1.cpp")
  # catalog.cpp is compiled once, for workbook_topics (the front door builds that first) and the
  # library alike: a first `check` does not wait for it twice.
  add_library(workbook_catalog OBJECT "${G}/engine/catalog.cpp")
  target_link_libraries(workbook_catalog PUBLIC nlohmann_json::nlohmann_json workbook_support)
  workbook_warnings(workbook_catalog)
  # api.cpp, util.cpp and sandbox.cpp (api runs nm under limits) likewise, for workbook_api (the
  # build step that writes each topic's judge and student's side) and the library: with the step a program of its own, the judges compile
  # while the rest of the engine is still being built.
  add_library(workbook_api_objects OBJECT "${G}/engine/api.cpp" "${G}/engine/util.cpp" "${G}/engine/sandbox.cpp")
  target_link_libraries(workbook_api_objects PUBLIC nlohmann_json::nlohmann_json workbook_support)
  target_compile_options(workbook_api_objects PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)
  workbook_warnings(workbook_api_objects)
  add_library(workbook_grading STATIC ${sources} $<TARGET_OBJECTS:workbook_catalog> $<TARGET_OBJECTS:workbook_api_objects>)
  target_include_directories(workbook_grading PUBLIC "${G}/engine")
  target_link_libraries(workbook_grading PUBLIC nlohmann_json::nlohmann_json workbook_support)
  # The class report's gnuplot scripts (report/*.gp): grading::gp::<name> in class_report.gp.hpp.
  file(GLOB report_scripts CONFIGURE_DEPENDS "${G}/engine/report/*.gp")
  workbook_embed_gnuplot(workbook_grading class_report.gp.hpp NAMESPACE grading::gp ${report_scripts})
  workbook_warnings(workbook_grading)
  # GCC 12 warns falsely on "literal" + std::string temporaries at -O3 (GCC bug 105329).
  target_compile_options(workbook_grading PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)

  add_executable(workbook_api "${G}/engine/workbook_api.cpp" $<TARGET_OBJECTS:workbook_api_objects>)
  target_include_directories(workbook_api PRIVATE "${G}/engine")
  target_link_libraries(workbook_api PRIVATE workbook_support nlohmann_json::nlohmann_json CLI11::CLI11)
  workbook_warnings(workbook_api)

  add_executable(workbook_grade "${G}/engine/workbook_grade.cpp")
  target_link_libraries(workbook_grade PRIVATE workbook_grading CLI11::CLI11)
  set_target_properties(workbook_grade PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/grading")
  workbook_warnings(workbook_grade)

  # What a key on the command line means (engine/catalog.hpp), for the front door before it builds
  # anything: a program of two sources, built in seconds.
  add_executable(workbook_topics "${G}/engine/workbook_topics.cpp" $<TARGET_OBJECTS:workbook_catalog>)
  set_target_properties(workbook_topics PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/grading")
  target_link_libraries(workbook_topics PRIVATE workbook_support nlohmann_json::nlohmann_json CLI11::CLI11)
  workbook_warnings(workbook_topics)

  add_executable(workbook_hints "${G}/engine/workbook_hints.cpp" "${G}/engine/hints.cpp")
  set_target_properties(workbook_hints PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/grading")
  target_link_libraries(workbook_hints PRIVATE workbook_support CLI11::CLI11)
  workbook_warnings(workbook_hints)

  add_executable(test_hints "${G}/tests/hints_test.cpp" "${G}/engine/hints.cpp")
  target_include_directories(test_hints PRIVATE "${G}/engine")
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
endfunction()

# ------------------------------------------------------------------------------------------
# The judges and the student's side, per topic; the build's provenance.
function(_grading_remote)
  set(G "${WORKBOOK_GRADING_DIR}")
  # The two processes of a graded test (README, "Grading a class"; remote/). Per topic with
  # graders, generated from the grader's objects and the reference library (workbook_api):
  #   judge_<topic>    the trusted process that runs the grader's doctest cases: the grader's
  #                    objects, the judge's side of the API and the reference libraries of the
  #                    topic's dependencies; no student code;
  #   serve_<topic>.o  the table of the student's process, which the grading run links (in the
  #                    sandbox) with the student's object, the student's runtime (workbook_serve:
  #                    remote/serve.cpp, with the seccomp filter the build makes with libseccomp)
  #                    and the topic's link libraries; no grader, no doctest.
  find_path(SECCOMP_INCLUDE_DIR seccomp.h)
  find_library(SECCOMP_LIBRARY seccomp)
  if(NOT SECCOMP_INCLUDE_DIR OR NOT SECCOMP_LIBRARY)
    workbook_missing("libseccomp (the seccomp filter of a student's process in the grading run)" libseccomp-dev)
  endif()
  set(remote_dir "${G}/engine/remote")
  set(api_dir "${CMAKE_BINARY_DIR}/grading/api")
  file(MAKE_DIRECTORY "${api_dir}")
  add_executable(workbook_seccomp_filter "${remote_dir}/seccomp_filter.cpp")
  target_include_directories(workbook_seccomp_filter SYSTEM PRIVATE "${SECCOMP_INCLUDE_DIR}")
  target_link_libraries(workbook_seccomp_filter PRIVATE "${SECCOMP_LIBRARY}")
  workbook_warnings(workbook_seccomp_filter)
  add_custom_command(OUTPUT "${api_dir}/seccomp_filter.inc"
    COMMAND workbook_seccomp_filter "${api_dir}/seccomp_filter.inc"
    DEPENDS workbook_seccomp_filter
    COMMENT "Making the seccomp filter of a student's process (libseccomp)")
  add_custom_target(seccomp_filter DEPENDS "${api_dir}/seccomp_filter.inc")

  add_library(workbook_serve OBJECT "${remote_dir}/serve.cpp")
  add_dependencies(workbook_serve seccomp_filter)
  add_library(workbook_judge OBJECT "${remote_dir}/judge.cpp")
  foreach(t workbook_serve workbook_judge)
    target_include_directories(${t} PRIVATE "${remote_dir}" "${api_dir}" "${WORKBOOK_ROOT}/tests" ${WORKBOOK_API_INCLUDES})
    target_link_libraries(${t} PRIVATE Eigen3::Eigen)
    workbook_warnings(${t})
  endforeach()
  target_link_libraries(workbook_judge PRIVATE doctest::doctest)
  target_include_directories(workbook_judge PRIVATE "${G}/engine")  # listener.hpp

  workbook_grading_graders(graders)  # WORKBOOK_GRADING_TOPICS, or every topic with graders
  set(facts "# Generated by CMake (tests/grading/grading.cmake): the judge and the student's side, per topic.\n")
  set(remote_targets workbook_serve workbook_judge)
  foreach(entry IN LISTS graders)
    string(REPLACE "|" ";" entry "${entry}")
    list(GET entry 0 topic)
    workbook_private_grader(${topic} private)  # "" or private_<topic>_objects
    set(private_objects "")
    if(private)
      set(private_objects $<TARGET_OBJECTS:${private}>)
    endif()
    set(outputs "${api_dir}/judge_${topic}.cpp" "${api_dir}/serve_${topic}.cpp")
    # The real target behind the alias rigid_<topic>_solutions: DEPENDS takes no alias, and without
    # the dependency a fresh parallel build could read the library before it is written.
    set(library rigid_${topic}_solutions)
    get_target_property(aliased ${library} ALIASED_TARGET)
    if(aliased)
      set(library ${aliased})
    endif()
    add_custom_command(OUTPUT ${outputs}
      COMMAND workbook_api --topic ${topic} --nm "${CMAKE_NM}" --library $<TARGET_FILE:${library}>
              --out "${api_dir}" --objects $<TARGET_OBJECTS:grade_${topic}_objects> ${private_objects}
      DEPENDS workbook_api ${library} grade_${topic}_objects $<TARGET_OBJECTS:grade_${topic}_objects> ${private}
              ${private_objects}
      COMMAND_EXPAND_LISTS VERBATIM  # VERBATIM: a private test's object path may hold spaces, quotes, parentheses
      COMMENT "Generating the judge and the student's side of ${topic}'s API")
    # One target makes the generated files; the two that compile them wait for it. (Both listing
    # the outputs alone would run the command twice at once in a parallel build, racing.)
    add_custom_target(api_${topic} DEPENDS ${outputs})
    add_library(serve_${topic} OBJECT "${api_dir}/serve_${topic}.cpp")
    add_executable(judge_${topic} "${api_dir}/judge_${topic}.cpp" $<TARGET_OBJECTS:grade_${topic}_objects> ${private_objects})
    add_dependencies(serve_${topic} api_${topic})
    add_dependencies(judge_${topic} api_${topic})
    foreach(t serve_${topic} judge_${topic})
      target_include_directories(${t} PRIVATE "${remote_dir}"
                                 $<TARGET_PROPERTY:rigid_${topic}_solutions,INTERFACE_INCLUDE_DIRECTORIES>)
      workbook_warnings(${t})
    endforeach()
    target_link_libraries(serve_${topic} PRIVATE Eigen3::Eigen)
    get_target_property(interface rigid_${topic}_solutions INTERFACE_LINK_LIBRARIES)
    if(NOT interface)
      set(interface "")
    endif()
    target_link_libraries(judge_${topic} PRIVATE workbook_judge workbook_doctest_main ${interface} doctest::doctest)
    set_target_properties(judge_${topic} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/grading/judge")
    list(APPEND remote_targets serve_${topic} judge_${topic})
    string(APPEND facts "topic\t${topic}\njudge\t$<TARGET_FILE:judge_${topic}>\n"
                        "serve\t$<JOIN:$<TARGET_OBJECTS:serve_${topic}>;$<TARGET_OBJECTS:workbook_serve>,\t>\n")
  endforeach()
  file(GENERATE OUTPUT "${CMAKE_BINARY_DIR}/grading/remote.txt" CONTENT "${facts}")
  add_custom_target(grading_remote DEPENDS ${remote_targets})

  # grading/provenance.txt: the compiler, the Debian versions of Eigen, GSL and doctest, and the
  # workbook's commit, asked at every build (provenance.cmake; rewritten only when it changes). The
  # grading run copies it into every result (provenance.cpp).
  add_custom_target(grading_provenance
    COMMAND "${CMAKE_COMMAND}" "-DROOT=${WORKBOOK_ROOT}" "-DOUT=${CMAKE_BINARY_DIR}/grading/provenance.txt"
            "-DCOMPILER_ID=${CMAKE_CXX_COMPILER_ID}" "-DCOMPILER_VERSION=${CMAKE_CXX_COMPILER_VERSION}"
            "-DCOMPILER=${CMAKE_CXX_COMPILER}" -P "${G}/engine/provenance.cmake"
    BYPRODUCTS "${CMAKE_BINARY_DIR}/grading/provenance.txt"
    COMMENT "Recording the compiler, packages and commit the graders are built with (grading/provenance.txt)")
  add_dependencies(grading_remote grading_provenance)
endfunction()

# ------------------------------------------------------------------------------------------
# The grading run's own tests (tests/), the mutation gate's sample and the deployments' tests.
function(_grading_tests)
  set(G "${WORKBOOK_GRADING_DIR}")
  # The harness's own test: a class of deliberately bad submissions (tests/grading/tests/cases/), each
  # graded with the expected verdict, in one parallel run; then resumed and repeated runs agree.
  add_executable(grading_suite "${G}/tests/suite.cpp")
  target_link_libraries(grading_suite PRIVATE workbook_grading CLI11::CLI11)
  workbook_warnings(grading_suite)
  add_test(NAME "grading: bad submissions get the expected verdicts"
           COMMAND grading_suite --setup "${CMAKE_BINARY_DIR}/grading" --harness $<TARGET_FILE:workbook_grade>
                   --cases "${G}/tests/cases" --work "${CMAKE_BINARY_DIR}/grading-suite" --jobs 2)
  set_tests_properties("grading: bad submissions get the expected verdicts" PROPERTIES LABELS grading TIMEOUT 900)

  # The class of 30 (tests/grading/tests/class.cpp): copies of the reference, a copy between students,
  # three honest solutions written from the contracts (similarity/), and the usual bad ones.
  add_executable(grading_class "${G}/tests/class.cpp")
  target_link_libraries(grading_class PRIVATE workbook_grading CLI11::CLI11)
  workbook_warnings(grading_class)

  # The similarity report on that class: the planted copies and the copy between two students are
  # listed, the honest solutions and everything else are not (grading_class check).
  add_test(NAME "grading: the similarity report lists the copies in a class and not the honest solutions"
           COMMAND bash -c [=[set -e; "$1" make --setup "$2" --out "$3/submissions" --expect "$3/expected.tsv"
                    "$4" similarity --setup "$2" "$3/submissions" "$3/report"
                    "$1" check --setup "$2" --class "$3/submissions" --expect "$3/expected.tsv" --grades "$3/report"]=]
                   grading-similarity $<TARGET_FILE:grading_class> "${CMAKE_BINARY_DIR}/grading"
                   "${CMAKE_BINARY_DIR}/grading-similarity" $<TARGET_FILE:workbook_grade>)

  # The README's cluster recipes, run for real on that class (cluster/test.sh): a single-node
  # Slurm started and stopped by the test, and GNU parallel. They run the recipes' own build step
  # in this build folder, so never at the same time as each other.
  foreach(engine slurm parallel)
    set(name "grading: the README's Slurm recipe grades the class of 30 as a job array and writes the class files")
    if(engine STREQUAL "parallel")
      set(name "grading: the README's GNU parallel recipe grades 10 of the class and writes the class files")
    endif()
    add_test(NAME "${name}"
             COMMAND bash "${G}/deploy/cluster/test.sh" ${engine} "${WORKBOOK_ROOT}" "${CMAKE_BINARY_DIR}"
                     "${CMAKE_BINARY_DIR}/grading-${engine}" $<TARGET_FILE:grading_class>)
    set_tests_properties("${name}" PROPERTIES LABELS grading TIMEOUT 1800 SKIP_RETURN_CODE 77
                         RESOURCE_LOCK workbook_build_folder)
  endforeach()

  # The Gradescope autograder (gradescope/test.sh): cmake/workbook gradescope, setup.sh in a
  # folder laid out like /autograder, and run_autograder on a correct, a stub, a broken and an
  # empty submission, and with no graders built.
  add_test(NAME "grading: the Gradescope autograder builds from its zip and writes a results.json for every submission"
           COMMAND bash "${G}/deploy/gradescope/test.sh" "${WORKBOOK_ROOT}"
                   "${CMAKE_BINARY_DIR}/grading-gradescope" $<TARGET_FILE:grading_class>)
  # Private tests (private/test.sh; README.md, "Private tests"): packed for Gradescope and graded
  # there and by `grade`, by name and as totals; no byte of their source or expected values in any
  # student-visible file (a planted leak is caught); a student's check never runs them. It writes
  # build/gradescope/autograder.zip, as the test above does: never at the same time.
  add_test(NAME "grading: private tests are graded, and nothing of their source or expected values reaches a student"
           COMMAND bash "${G}/tests/private/test.sh" "${WORKBOOK_ROOT}"
                   "${CMAKE_BINARY_DIR}/grading-private" $<TARGET_FILE:grading_class>)
  set_tests_properties("grading: private tests are graded, and nothing of their source or expected values reaches a student"
                       "grading: the Gradescope autograder builds from its zip and writes a results.json for every submission"
                       PROPERTIES LABELS grading TIMEOUT 1800 RESOURCE_LOCK workbook_gradescope_zip)
  set_tests_properties("grading: the similarity report lists the copies in a class and not the honest solutions"
                       "grading: the Gradescope autograder builds from its zip and writes a results.json for every submission"
                       PROPERTIES LABELS grading TIMEOUT 1800)

  # The JSON written and read keeps every character (surrogate pairs, invalid UTF-8 replaced).
  add_executable(grading_json_test "${G}/tests/json_test.cpp")
  target_include_directories(grading_json_test PRIVATE "${WORKBOOK_ROOT}/cmake/book/tools")  # prose.hpp: the book's JSON, read back
  target_link_libraries(grading_json_test PRIVATE workbook_grading workbook_doctest_main doctest::doctest)
  workbook_warnings(grading_json_test)
  doctest_discover_tests(grading_json_test TEST_PREFIX "grading: " PROPERTIES LABELS grading TIMEOUT ${WORKBOOK_CASE_TIMEOUT})

  # A test that fails by an exception names the other exercises it uses (ALSO_USES), as a failed
  # check does: the reporter's self-test plants one.
  add_executable(grading_reporter_selftest "${G}/tests/reporter_selftest.cpp")
  target_link_libraries(grading_reporter_selftest PRIVATE workbook_doctest_main doctest::doctest Eigen3::Eigen)
  target_include_directories(grading_reporter_selftest PRIVATE ${WORKBOOK_API_INCLUDES} "${WORKBOOK_ROOT}/tests")
  workbook_warnings(grading_reporter_selftest)
  add_test(NAME "grading: a test that throws names the other exercises it uses"
           COMMAND grading_reporter_selftest --reporters=workbook --no-version)
  set_tests_properties("grading: a test that throws names the other exercises it uses" PROPERTIES LABELS grading
                       PASS_REGULAR_EXPRESSION "\"event\":\"exception\",\"info\":\\[\"this test also uses your planted_exercise")

  # Blame through the call chain (grading.hpp, blame()): a failure another exercise of the student's
  # may cause names it, in check and in the results .json; two students whose failures are their
  # own are the self-test (tests/blame.sh).
  add_test(NAME "grading: a failure that an exercise it calls may cause names that exercise, in check and in results"
           COMMAND bash "${G}/tests/blame.sh" $<TARGET_FILE:workbook_grade> "${CMAKE_BINARY_DIR}/grading"
                   "${WORKBOOK_ROOT}/solutions" "${CMAKE_BINARY_DIR}/test/blame")
  set_tests_properties("grading: a failure that an exercise it calls may cause names that exercise, in check and in results"
                       PROPERTIES LABELS grading TIMEOUT ${WORKBOOK_CASE_TIMEOUT})

  # The mutation gate (mutants/mutants.cpp; README.md, "The mutation gate"): plausible wrong
  # versions of solutions/<topic>.cpp graded by the grading run; every one must be caught unless
  # mutants/allowed.txt lists it as equivalent, with the reason. `cmake/workbook mutants` runs them
  # all.
  add_executable(workbook_mutants "${G}/mutants/mutants.cpp" "${G}/mutants/catalogue.cpp")
  target_link_libraries(workbook_mutants PRIVATE nlohmann_json::nlohmann_json workbook_support workbook_grading CLI11::CLI11)
  target_include_directories(workbook_mutants PRIVATE "${G}/engine")  # verdict.hpp
  set_target_properties(workbook_mutants PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/grading")
  workbook_warnings(workbook_mutants)
  # The CTest sample: 3 mutants per topic chosen by a fixed seed, the same every run (about 2
  # minutes on 2 cores); it fails when one survives that the allowlist does not call equivalent.
  add_test(NAME "grading: the mutation gate's fixed sample of 3 mutants per topic (seed 1) is killed by the graders"
           COMMAND workbook_mutants run --setup "${CMAKE_BINARY_DIR}/grading" --solutions "${WORKBOOK_ROOT}/solutions"
                   --out "${CMAKE_BINARY_DIR}/mutants-sample" --sample 3 --seed 1 -j 2
                   --allow "${G}/mutants/allowed.txt")
  set_tests_properties("grading: the mutation gate's fixed sample of 3 mutants per topic (seed 1) is killed by the graders"
                       PROPERTIES LABELS grading TIMEOUT 1200 PROCESSORS 2)

  # Every failing check shows its inputs, on one planted wrong answer per exercise as the grading run
  # shows it to the student (cmake/checks/messages.py planted: a mutant of each exercise from the gate
  # above, graded; the first failure of each failing test read as the message check reads the
  # graders' own; the baseline is the same, cmake/checks/messages_baseline.txt).
  find_package(Python3 REQUIRED COMPONENTS Interpreter)
  add_test(NAME "grading: every failing check on a planted wrong answer per exercise shows its inputs"
           COMMAND ${Python3_EXECUTABLE} "${WORKBOOK_ROOT}/cmake/checks/messages.py" planted --build "${CMAKE_BINARY_DIR}"
                   --root "${WORKBOOK_ROOT}" --work "${CMAKE_BINARY_DIR}/test/messages-planted" --jobs 2)
  set_tests_properties("grading: every failing check on a planted wrong answer per exercise shows its inputs"
                       PROPERTIES LABELS grading TIMEOUT 1200 PROCESSORS 2)

  # The harness's own programs spend their time waiting for compilers and tests, not computing:
  # built at -O1 (the build's -O3 is overridden, the last -O wins), they compile in about 60% of
  # the time (grade.cpp: 12.8 s against 22.1 s, measured), which a student's first `check` waits
  # for. The judges, the student's side and the graders keep the build's optimisation.
  foreach(t workbook_grading workbook_catalog workbook_api_objects workbook_api workbook_grade workbook_hints workbook_topics
            grading_suite grading_class grading_json_test
            workbook_mutants workbook_seccomp_filter test_hints)
    target_compile_options(${t} PRIVATE -O1)
  endforeach()

  # The item analysis (item_analysis.hpp): planted classes whose discrimination, counts, failing
  # checks and "started" are known.
  add_executable(grading_item_analysis_test "${G}/tests/item_analysis_test.cpp")
  target_link_libraries(grading_item_analysis_test PRIVATE workbook_grading workbook_doctest_main doctest::doctest)
  workbook_warnings(grading_item_analysis_test)
  target_compile_options(grading_item_analysis_test PRIVATE -O1)
  doctest_discover_tests(grading_item_analysis_test TEST_PREFIX "grading: " PROPERTIES LABELS grading TIMEOUT ${WORKBOOK_CASE_TIMEOUT})

  # A class run writes the item analysis of every test of every graded topic, with the numbers an
  # independent count from the results files gives (item_check.py), the same provenance in every
  # result and run.json; a verdict flipped and a provenance dropped on purpose are caught. Then the class report in Chromium:
  # every plot loads, from the out folder alone (report_browser.sh).
  add_test(NAME "grading: a class run writes the item analysis and the class report, as the results files count them"
           COMMAND bash -c [=[set -e; rm -rf "$3"; "$1" make --setup "$2" --out "$3/submissions" --expect "$3/expected.tsv"
                    "$4" grade --setup "$2" -j 2 "$3/submissions" "$3/grades" >"$3/grade.log"
                    set -- "$5" --out "$3/grades" --manifest "$2/manifest.txt" --submissions "$3/submissions" --stubs "$6"
                    python3 "$@"; python3 "$@" --plant-fault; python3 "$@" --plant-missing-provenance
                    python3 "$@" --plant-mistake]=]
                   grading-items $<TARGET_FILE:grading_class> "${CMAKE_BINARY_DIR}/grading"
                   "${CMAKE_BINARY_DIR}/grading-items" $<TARGET_FILE:workbook_grade>
                   "${G}/tests/item_check.py" "${CMAKE_BINARY_DIR}/pristine/exercises")
  add_test(NAME "grading: the class report opens offline in Chromium and every plot loads"
           COMMAND bash "${G}/tests/report_browser.sh" "${CMAKE_BINARY_DIR}/grading-items/grades"
                   "${CMAKE_BINARY_DIR}/grading-items/browser")
  set_tests_properties("grading: a class run writes the item analysis and the class report, as the results files count them"
                       PROPERTIES LABELS grading TIMEOUT 1800 FIXTURES_SETUP grading_items PROCESSORS 2)
  set_tests_properties("grading: the class report opens offline in Chromium and every plot loads"
                       PROPERTIES LABELS grading TIMEOUT 300 FIXTURES_REQUIRED grading_items SKIP_RETURN_CODE 77
                       RESOURCE_LOCK browser)
  # Likely mistakes, named (mistakes.cpp, mutants/catalogue.cpp; README.md, "Likely mistakes,
  # named"). The catalogue is committed with a hash of the graders, solution and mutants it came
  # from: it must match this tree (the planted fault: a copy of rotation's sources with its grader
  # changed by one line must be reported stale). And no correct submission and no unrelated failure
  # is ever given a likely mistake (mutants/no_false_naming.sh, with its own planted fault).
  add_test(NAME "grading: the catalogue of likely mistakes has the hash of the graders and solutions it came from"
           COMMAND bash -c [=[set -e; "$1" stale --setup "$2" --solutions "$3/solutions" --catalogue "$3/tests/grading/mutants/catalogue"
                    rm -rf "$4" && mkdir -p "$4/solutions" "$4/tests" "$4/exercises/rigid"
                    cp "$3/solutions/rotation.cpp" "$4/solutions/" && cp "$3/exercises/rigid/rotation.hpp" "$4/exercises/rigid/"
                    cp "$3/tests/rotation_test.cpp" "$3/tests/checks.hpp" "$4/tests/"
                    "$1" stale --setup "$2" --solutions "$4/solutions" --topic rotation --catalogue "$3/tests/grading/mutants/catalogue"
                    echo "// a grader changed" >> "$4/tests/rotation_test.cpp"
                    if "$1" stale --setup "$2" --solutions "$4/solutions" --topic rotation --catalogue "$3/tests/grading/mutants/catalogue"; then
                      echo "FAILED: a changed grader left the catalogue fresh"; exit 1; fi
                    echo "the planted change was reported stale"]=]
                   catalogue-stale $<TARGET_FILE:workbook_mutants> "${CMAKE_BINARY_DIR}/grading" "${WORKBOOK_ROOT}"
                   "${CMAKE_BINARY_DIR}/mistakes-stale")
  add_test(NAME "grading: no correct submission and no unrelated failure is given a likely mistake"
           COMMAND bash "${G}/mutants/no_false_naming.sh" "${WORKBOOK_ROOT}" "${CMAKE_BINARY_DIR}"
                   "${CMAKE_BINARY_DIR}/mistakes-audit")
  set_tests_properties("grading: the catalogue of likely mistakes has the hash of the graders and solutions it came from"
                       "grading: no correct submission and no unrelated failure is given a likely mistake"
                       PROPERTIES LABELS grading TIMEOUT 900)
  # The keys of check name exactly the exercises the graders grade (tests/keys_manifest.sh): every
  # topic in the solutions build; the self-test plants an exercise only a stub names.
  add_test(NAME "grading: the exercises a key of check names are the exercises the graders grade"
           COMMAND bash "${G}/tests/keys_manifest.sh" $<TARGET_FILE:workbook_topics> "${CMAKE_BINARY_DIR}/grading"
                   "${CMAKE_BINARY_DIR}/test/keys-manifest")
  add_test(NAME "grading: the check of the keys fails on an exercise that only a stub names"
           COMMAND bash "${G}/tests/keys_manifest.sh" $<TARGET_FILE:workbook_topics> "${CMAKE_BINARY_DIR}/grading"
                   "${CMAKE_BINARY_DIR}/test/keys-manifest-planted" --plant)
  set_tests_properties("grading: the check of the keys fails on an exercise that only a stub names" PROPERTIES
                       PASS_REGULAR_EXPRESSION "< rotation.planted_exercise")
  set_tests_properties("grading: the exercises a key of check names are the exercises the graders grade"
                       "grading: the check of the keys fails on an exercise that only a stub names"
                       PROPERTIES LABELS grading TIMEOUT 60)
  add_executable(grading_mistakes_test "${G}/tests/mistakes_test.cpp")
  target_link_libraries(grading_mistakes_test PRIVATE workbook_grading workbook_doctest_main doctest::doctest)
  target_compile_options(grading_mistakes_test PRIVATE -O1)
  workbook_warnings(grading_mistakes_test)
  doctest_discover_tests(grading_mistakes_test TEST_PREFIX "grading: " WORKING_DIRECTORY "${CMAKE_BINARY_DIR}"
                         PROPERTIES LABELS grading TIMEOUT ${WORKBOOK_CASE_TIMEOUT})
endfunction()

# ------------------------------------------------------------------------------------------
# The grading run, built and tested: the engine, the judges and the student's side per topic, the
# build's facts and the target `grading`, the stub gate, and the grading run's own tests.
function(workbook_grading)
  _grading_engine()
  _grading_remote()
  _grading_facts()
  workbook_stub_gate()
  _grading_tests()
  # The grading run's test programs, where they always were: <build>/tests/grading/.
  set_target_properties(test_hints workbook_seccomp_filter grading_suite grading_class grading_json_test
                        grading_reporter_selftest grading_item_analysis_test grading_mistakes_test
                        PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/tests/grading")
endfunction()
