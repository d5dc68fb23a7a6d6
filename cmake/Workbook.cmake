# CMake helpers for the Grioli workbook: dependencies, the API topics (one function written
# once, in two implementations), the graders, the scenes, the runs and the chapters. The other
# rooms have CMake files of their own, included here: the support library (support/support.cmake),
# the book (book/book.cmake) and the quality gates (checks/checks.cmake); the grading run's is
# tests/grading/grading.cmake, included by the top-level CMakeLists.txt.
include_guard(GLOBAL)

get_filename_component(WORKBOOK_ROOT "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
include(contents)  # workbook_read_contents(): the table of contents, read once
include("${CMAKE_CURRENT_LIST_DIR}/support/support.cmake")  # workbook_support(), workbook_embed_gnuplot()
include("${CMAKE_CURRENT_LIST_DIR}/book/book.cmake")  # workbook_book(), workbook_live_scene(), workbook_live()
include("${CMAKE_CURRENT_LIST_DIR}/checks/checks.cmake")  # workbook_function_size(), ..., workbook_door_tests()

include("${CMAKE_CURRENT_LIST_DIR}/pristine_stubs.cmake")  # WORKBOOK_PRISTINE_DIR: the stubs as committed

# compile_commands.json: the grading run compiles a student's file with exactly these flags.
set(CMAKE_EXPORT_COMPILE_COMMANDS ON)

# ------------------------------------------------------------------------------------------
# Every test's TIMEOUT is a hang catch, never a measurement: the value written beside a test is
# generous for an idle 2-core machine, and at the end of each folder's CMake code every test
# there gets WORKBOOK_HANG_FACTOR times it, so that a test that is only slow on a loaded machine
# (a course lab, a CI box with neighbours) is never failed for it. Tests listed when CTest runs
# (doctest's, the corners) take the factor where they are declared.
set(WORKBOOK_HANG_FACTOR 4 CACHE STRING "Each test's TIMEOUT is this many times the value beside it (a hang catch)")
if(NOT WORKBOOK_HANG_FACTOR MATCHES "^[1-9][0-9]*$")
  message(FATAL_ERROR "WORKBOOK_HANG_FACTOR is '${WORKBOOK_HANG_FACTOR}': it must be a whole number, 1 or more")
endif()
function(_workbook_scale_timeouts)
  get_directory_property(tests TESTS)
  foreach(test IN LISTS tests)
    get_test_property("${test}" TIMEOUT seconds)
    if(seconds)
      math(EXPR seconds "${seconds} * ${WORKBOOK_HANG_FACTOR}")
      set_tests_properties("${test}" PROPERTIES TIMEOUT ${seconds})
    endif()
  endforeach()
endfunction()
# Schedules the scaling for the end of the current folder, once.
macro(workbook_hang_catch)
  get_directory_property(_workbook_hang_scheduled WORKBOOK_HANG_SCHEDULED)
  if(NOT _workbook_hang_scheduled)
    set_directory_properties(PROPERTIES WORKBOOK_HANG_SCHEDULED ON)
    cmake_language(DEFER CALL _workbook_scale_timeouts)
  endif()
endmacro()
# The hang catch of a test that doctest lists when CTest runs (each is one test case).
math(EXPR WORKBOOK_CASE_TIMEOUT "120 * ${WORKBOOK_HANG_FACTOR}")

# ------------------------------------------------------------------------------------------
# Dependencies: each missing piece stops the configure step with the Debian package to install.
macro(workbook_missing what package)
  message(FATAL_ERROR
    "\n${what} was not found.\n"
    "Install it with:  sudo apt-get install ${package}\n"
    "(or run cmake/workbook, which installs every missing package itself).\n")
endmacro()

macro(workbook_find_dependencies)
  find_package(Eigen3 3.3 QUIET NO_MODULE)
  if(NOT Eigen3_FOUND)
    workbook_missing("Eigen 3 (linear algebra)" libeigen3-dev)
  endif()
  find_package(GSL QUIET)
  if(NOT GSL_FOUND)
    workbook_missing("GSL, the GNU Scientific Library" libgsl-dev)
  endif()
  find_package(doctest QUIET)
  if(NOT doctest_FOUND)
    workbook_missing("doctest (the graders' test framework)" doctest-dev)
  endif()
  include(doctest)  # doctest_discover_tests(), shipped with doctest-dev
  find_package(nlohmann_json 3 QUIET)
  if(NOT nlohmann_json_FOUND)
    workbook_missing("nlohmann-json (every JSON the tools and the grading run read or write)" nlohmann-json3-dev)
  endif()
  find_package(CLI11 2 QUIET)
  if(NOT CLI11_FOUND)
    workbook_missing("CLI11 (the command lines of the scenes, the book's tools and the grading run's programs)"
                     libcli11-dev)
  endif()
  find_package(Boost 1.65 QUIET COMPONENTS iostreams filesystem)
  if(NOT Boost_FOUND)
    workbook_missing("Boost.Iostreams and Boost.Filesystem (used by gnuplot-iostream)"
                     "libboost-iostreams-dev libboost-filesystem-dev")
  endif()
  find_path(GNUPLOT_IOSTREAM_INCLUDE_DIR gnuplot-iostream.h)
  if(NOT GNUPLOT_IOSTREAM_INCLUDE_DIR)
    workbook_missing("gnuplot-iostream.h" libgnuplot-iostream-dev)
  endif()
  find_program(GNUPLOT_EXECUTABLE gnuplot)
  if(NOT GNUPLOT_EXECUTABLE)
    workbook_missing("The gnuplot program (draws every figure)" gnuplot-nox)
  endif()
  # pandoc renders the book; without it everything else still builds and runs.
  find_program(PANDOC_EXECUTABLE pandoc)
  if(NOT PANDOC_EXECUTABLE)
    message(WARNING "pandoc was not found, so the book cannot be rendered. Install it with "
                    "sudo apt-get install pandoc (cmake/workbook does this itself).")
    set(PANDOC_EXECUTABLE pandoc)
  endif()
endmacro()

# ------------------------------------------------------------------------------------------
# Warnings: -Wall -Wextra -Wpedantic everywhere; errors when WORKBOOK_WERROR is on (CI).
function(workbook_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic
                         $<$<BOOL:${WORKBOOK_WERROR}>:-Werror>)
endfunction()


# Where a topic's implementation comes from: "solutions", "exercises", or a folder.
function(workbook_resolve_impl)
  if(WORKBOOK_IMPL STREQUAL "solutions")
    set(dir "${WORKBOOK_ROOT}/solutions")
  elseif(WORKBOOK_IMPL STREQUAL "exercises")
    set(dir "${WORKBOOK_ROOT}/exercises")
  else()
    get_filename_component(dir "${WORKBOOK_IMPL}" ABSOLUTE BASE_DIR "${CMAKE_BINARY_DIR}")
    if(NOT IS_DIRECTORY "${dir}")
      message(FATAL_ERROR "WORKBOOK_IMPL='${WORKBOOK_IMPL}': no such folder. "
        "Use solutions, exercises, or a folder holding your exercises/*.cpp files.")
    endif()
  endif()
  set(WORKBOOK_IMPL_DIR "${dir}" PARENT_SCOPE)
endfunction()

# ------------------------------------------------------------------------------------------
# Where the headers are, each folder one role, each included as "rigid/<name>.hpp":
#   exercises/rigid/           the student's API: one header per topic, what they implement
#   exercises/provided/rigid/  the code given to them: vocabulary types, input checks, todo(),
#                              the GSL wrapper, the stepping driver, the Taylor and exact references
# and, for the graders and the scenes only, tests/include/reference/ ("reference/<name>.hpp"): the
# independent computations both check the exercises against, the graders' yardstick, beside them
# and outside what a student's compile sees (the grading run gives it exercises/ only). Its
# include root, tests/include/, holds the reference and nothing else, so that a scene reaches no
# other file of tests/ (the graders' checks.hpp, the grading run): the include check
# (workbook_include_check, cmake/checks/include_check.cmake) holds it.
set(WORKBOOK_API_INCLUDES "${WORKBOOK_ROOT}/exercises" "${WORKBOOK_ROOT}/exercises/provided")
add_library(workbook_reference INTERFACE)
target_include_directories(workbook_reference INTERFACE "${WORKBOOK_ROOT}/tests/include")

# ------------------------------------------------------------------------------------------
# One API topic: exercises/rigid/<name>.hpp, with solutions/<name>.cpp, exercises/<name>.cpp and
# its graders tests/<name>_test.cpp; declared here once, with the chapter (label chNN of the
# contents) that teaches it.
#
#   workbook_topic(<name> CHAPTER <chNN> [DEPENDS <topic>...] [LIBS <target>...])
#
# Makes rigid_<name> from the chosen implementation (WORKBOOK_IMPL; only the topics listed in
# WORKBOOK_TOPICS when that is set), and for the stub gate rigid_<name>_solutions and
# rigid_<name>_stubs. A stub library links the reference versions of its dependencies, so
# each topic's graders see only that topic's stubs.
function(_workbook_topic_library target source deps libs)
  add_library(${target} STATIC "${source}")
  target_include_directories(${target} PUBLIC ${WORKBOOK_API_INCLUDES})
  target_link_libraries(${target} PUBLIC Eigen3::Eigen ${deps} ${libs})
  workbook_warnings(${target})
  get_filename_component(dir "${source}" DIRECTORY)
  if(NOT dir STREQUAL "${WORKBOOK_ROOT}/solutions")
    # Stubs name parameters they do not use yet: that is not worth a warning.
    target_compile_options(${target} PRIVATE -Wno-unused-parameter)
  endif()
endfunction()

# The topics named in <variable> (WORKBOOK_TOPICS, WORKBOOK_GRADING_TOPICS) as a user may write
# them: "rotation;precession" (a CMake list, what workbook_topics writes), "rotation precession" or
# "rotation,precession". CHECKED, once every topic is declared: each must be one, or the configure
# stops naming it (a misspelt topic would silently be built from solutions/, or not graded).
#
#   workbook_topic_names(<out> <variable> [CHECKED])
function(workbook_topic_names out variable)
  string(REGEX REPLACE "[ ,;]+" ";" names "${${variable}}")
  list(REMOVE_ITEM names "")
  if(ARGN STREQUAL "CHECKED")
    get_property(topics GLOBAL PROPERTY WORKBOOK_TOPIC_LIST)
    foreach(t IN LISTS names)
      if(NOT t IN_LIST topics)
        string(REPLACE ";" " " topics "${topics}")
        message(FATAL_ERROR "${variable}: '${t}' is not a topic with graders (they are: ${topics})")
      endif()
    endforeach()
  endif()
  set(${out} "${names}" PARENT_SCOPE)
endfunction()

function(workbook_topic name)
  cmake_parse_arguments(T "" "CHAPTER" "DEPENDS;LIBS" ${ARGN})
  set(impl_dir "${WORKBOOK_IMPL_DIR}")
  workbook_topic_names(own WORKBOOK_TOPICS)
  if(own AND NOT name IN_LIST own)
    set(impl_dir "${WORKBOOK_ROOT}/solutions")
  endif()
  set(source "${impl_dir}/${name}.cpp")
  if(NOT EXISTS "${source}")
    message(FATAL_ERROR "WORKBOOK_IMPL='${WORKBOOK_IMPL}': the file ${name}.cpp is missing from ${impl_dir}.")
  endif()
  set(deps "")
  set(ref_deps "")
  foreach(d IN LISTS T_DEPENDS)
    list(APPEND deps rigid_${d})
    list(APPEND ref_deps rigid_${d}_solutions)
  endforeach()
  _workbook_topic_library(rigid_${name} "${source}" "${deps}" "${T_LIBS}")
  if(WORKBOOK_IMPL STREQUAL "solutions")
    add_library(rigid_${name}_solutions ALIAS rigid_${name})
  else()
    _workbook_topic_library(rigid_${name}_solutions "${WORKBOOK_ROOT}/solutions/${name}.cpp" "${ref_deps}" "${T_LIBS}")
  endif()
  if(WORKBOOK_STUB_GATE)
    _workbook_topic_library(rigid_${name}_stubs "${WORKBOOK_PRISTINE_DIR}/${name}.cpp" "${ref_deps}" "${T_LIBS}")
    # The same stubs refusing every input (tests/grading/mutants/refuse.hpp): no test may pass on them.
    _workbook_topic_library(rigid_${name}_refusing "${WORKBOOK_PRISTINE_DIR}/${name}.cpp" "${ref_deps}" "${T_LIBS}")
    target_compile_options(rigid_${name}_refusing PRIVATE -include "${WORKBOOK_ROOT}/tests/grading/mutants/refuse.hpp")
  endif()
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_TOPIC_LIST ${name})
  # Its graders, tests/<name>_test.cpp, labelled with its chapter of the contents.
  get_property(labels GLOBAL PROPERTY WORKBOOK_CHAPTER_LABELS)
  if(NOT T_CHAPTER IN_LIST labels)
    string(REPLACE ";" " " labels "${labels}")
    message(FATAL_ERROR "workbook_topic(${name}): CHAPTER '${T_CHAPTER}' is not a chapter of chapters/README.md (they are: ${labels})")
  endif()
  workbook_grader(${name} CHAPTER ${T_CHAPTER})
endfunction()

# A provided library: code in exercises/provided/rigid/ that the workbook gives the student (not
# an exercise), the same in every implementation. Topics may DEPENDS on it like on a topic.
#
#   workbook_provided(<name> SOURCES <file>... [LIBS <target>...])
function(workbook_provided name)
  cmake_parse_arguments(P "" "" "SOURCES;LIBS" ${ARGN})
  list(TRANSFORM P_SOURCES PREPEND "${WORKBOOK_ROOT}/")
  add_library(rigid_${name} STATIC ${P_SOURCES})
  target_include_directories(rigid_${name} PUBLIC ${WORKBOOK_API_INCLUDES})
  target_link_libraries(rigid_${name} PUBLIC Eigen3::Eigen ${P_LIBS})
  workbook_warnings(rigid_${name})
  add_library(rigid_${name}_solutions ALIAS rigid_${name})
endfunction()

# Tests of a provided library (tests/<name>_test.cpp): ordinary tests, outside the stub gate.
function(workbook_unit_test name)
  add_executable(test_${name} "${WORKBOOK_ROOT}/tests/${name}_test.cpp")  # checks.hpp: beside it
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_UNIT_TESTS test_${name})
  target_link_libraries(test_${name} PRIVATE workbook_doctest_main rigid_${name} doctest::doctest)
  set_target_properties(test_${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/graders")
  workbook_warnings(test_${name})
  doctest_discover_tests(test_${name} TEST_PREFIX "provided: " PROPERTIES LABELS "provided"
                                                                       TIMEOUT ${WORKBOOK_CASE_TIMEOUT})
endfunction()

# ------------------------------------------------------------------------------------------
# The graders of one topic: tests/<topic>_test.cpp, one doctest binary per implementation.
#
#   workbook_grader(<topic> CHAPTER <label>)
#
# grade_<topic> grades the chosen implementation; every test case becomes one CTest test
# (its own process), labelled with the chapter. For the stub gate, grade_<topic>_solutions,
# grade_<topic>_stubs and grade_<topic>_refusing grade the reference, the pristine stubs and the
# stubs refusing every input.
function(workbook_grader topic)
  cmake_parse_arguments(G "" "CHAPTER" "" ${ARGN})
  # The test file is compiled once; every flavour, and the grading run, links these objects.
  add_library(grade_${topic}_objects OBJECT "${WORKBOOK_ROOT}/tests/${topic}_test.cpp")
  # checks.hpp is beside it; tests/ is not on its path, so that it reaches nothing of the grading run.
  target_include_directories(grade_${topic}_objects PRIVATE $<TARGET_PROPERTY:rigid_${topic},INTERFACE_INCLUDE_DIRECTORIES>)
  target_link_libraries(grade_${topic}_objects PRIVATE doctest::doctest Eigen3::Eigen workbook_reference)
  workbook_warnings(grade_${topic}_objects)
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_GRADER_LIST "${topic}|${G_CHAPTER}")
  foreach(flavour IN ITEMS "" _solutions _stubs _refusing)
    if(flavour STREQUAL "_solutions" AND WORKBOOK_IMPL STREQUAL "solutions")
      continue()  # grade_<topic> already is the reference
    endif()
    if(flavour MATCHES "^_(stubs|refusing)$" AND NOT WORKBOOK_STUB_GATE)
      continue()
    endif()
    set(exe grade_${topic}${flavour})
    add_executable(${exe} $<TARGET_OBJECTS:grade_${topic}_objects>)
    target_link_libraries(${exe} PRIVATE workbook_doctest_main rigid_${topic}${flavour} doctest::doctest)
    set_target_properties(${exe} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/graders")
    workbook_warnings(${exe})
  endforeach()
  # One label: doctest's script splits a list of labels into words, and "LABELS grader ch01 TIMEOUT
  # n" then set a property named ch01 and no TIMEOUT at all (the chapter is in the name).
  doctest_discover_tests(grade_${topic} TEST_PREFIX "${G_CHAPTER}: "
                         PROPERTIES LABELS grader TIMEOUT ${WORKBOOK_CASE_TIMEOUT})
  if(WORKBOOK_STUB_GATE)
    if(TARGET grade_${topic}_solutions)
      set(ref grade_${topic}_solutions)
    else()
      set(ref grade_${topic})
    endif()
    set_property(GLOBAL APPEND PROPERTY WORKBOOK_GATE_ARGS
                 "${topic}" "$<TARGET_FILE:${ref}>" "$<TARGET_FILE:grade_${topic}_stubs>")
    set_property(GLOBAL APPEND PROPERTY WORKBOOK_GATE_TARGETS ${ref} grade_${topic}_stubs grade_${topic}_refusing)
    set_property(GLOBAL APPEND PROPERTY WORKBOOK_REFUSING_GATE_ARGS
                 "${topic}" "$<TARGET_FILE:${ref}>" "$<TARGET_FILE:grade_${topic}_refusing>")
  endif()
endfunction()

# ------------------------------------------------------------------------------------------
# A scene: a small driver in chapters/NN_slug/ that draws a figure or prints a table.
#
#   workbook_scene(<name> TOPICS <topic>... [FIGURES] [LIBS <target>...] [ARGS <arg>...]
#                  [SMOKE_ARGS <arg>...] [CORNER_ARGS <arg>...])
#
# Links only what it names: the topics it uses, the kit, and the figure helper only with
# FIGURES; its gnuplot scripts (<name>.gp, <name>.<figure>.gp) are embedded in it
# (workbook_embed_gnuplot, below). ARGS are the options of its run `default`, the one
# `cmake/workbook run` makes and the book quotes (value markers with run=default). Registers a
# smoke test (scene.<name>) that runs it with --json and checks its report and figures;
# SMOKE_ARGS are added for that test only (a lighter run of a long scene, which the book never
# quotes). The corner sweep (below) starts from CORNER_ARGS when given, else from SMOKE_ARGS.
function(workbook_scene name)
  workbook_hang_catch()
  cmake_parse_arguments(S "FIGURES" "" "TOPICS;LIBS;ARGS;SMOKE_ARGS;CORNER_ARGS" ${ARGN})
  get_filename_component(chapter "${CMAKE_CURRENT_SOURCE_DIR}" NAME)
  add_executable(${name} ${name}.cpp)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/scenes")
  target_link_libraries(${name} PRIVATE workbook_kit ${S_LIBS})
  foreach(t IN LISTS S_TOPICS)
    target_link_libraries(${name} PRIVATE rigid_${t})
  endforeach()
  if(S_FIGURES)
    target_link_libraries(${name} PRIVATE workbook_kit_figure)
  endif()
  # Its gnuplot scripts, <name>.gp and <name>.<figure>.gp beside it: kit::gp::... in <name>.gp.hpp.
  file(GLOB scripts CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/${name}.gp" "${CMAKE_CURRENT_SOURCE_DIR}/${name}.*.gp")
  if(scripts)
    workbook_embed_gnuplot(${name} "${name}.gp.hpp" ${scripts})
  endif()
  workbook_warnings(${name})
  set(smoke "${CMAKE_BINARY_DIR}/smoke/${name}")
  set(args "")
  foreach(a IN LISTS S_ARGS)
    string(APPEND args "|${a}")
  endforeach()
  set(smoke_args "${args}")
  foreach(a IN LISTS S_SMOKE_ARGS)
    string(APPEND smoke_args "|${a}")
  endforeach()
  add_test(NAME "scene: ${name}"
           COMMAND ${CMAKE_COMMAND} -DEXPECT=0 -DOUT=${smoke} -DFIGURES=${S_FIGURES}
                   -DJSON=${CMAKE_BINARY_DIR}/smoke/reports/${name}.json
                   "-DCOMMAND=$<TARGET_FILE:${name}>|--json|--out|${smoke}${smoke_args}"
                   -P "${WORKBOOK_ROOT}/cmake/scene_check.cmake")
  # Its JSON report gives the book's tests the numbers the prose quotes.
  set_tests_properties("scene: ${name}" PROPERTIES LABELS "scene;${chapter}" TIMEOUT 300
                       FIXTURES_SETUP scene_reports)
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_SCENE_LIST "${chapter}|${name}|$<TARGET_FILE:${name}>${args}")
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_SCENE_TARGETS ${name})
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_RUN_LIST "${name}|${chapter}|default${args}")
  if(S_CORNER_ARGS)
    set(corner_args "${args}")
    foreach(a IN LISTS S_CORNER_ARGS)
      string(APPEND corner_args "|${a}")
    endforeach()
  else()
    set(corner_args "${smoke_args}")
  endif()
  _workbook_scene_corners(${name} ${chapter} "${corner_args}")
endfunction()

# Another run of a scene that the book quotes (value markers with run=<run>): a long one that
# `cmake/workbook run` does not make, e.g. a benchmark's full sweep. Call it in the scene's
# chapter folder, after workbook_scene(). The target run-<run> makes it; its figures and report
# go to <build>/figures/<chapter>/<run>/, and update-figures commits them like the others.
#
#   workbook_scene_run(<scene> <run> ARGS <arg>...)
function(workbook_scene_run scene run)
  cmake_parse_arguments(R "" "" "ARGS" ${ARGN})
  get_filename_component(chapter "${CMAKE_CURRENT_SOURCE_DIR}" NAME)
  if(run STREQUAL "default" OR NOT run MATCHES "^[a-z][a-z0-9_]*$")
    message(FATAL_ERROR "workbook_scene_run(${scene} ${run}): a run's name is lower case, digits and _, not 'default'")
  endif()
  set(args "")
  foreach(a IN LISTS R_ARGS)
    string(APPEND args "|${a}")
  endforeach()
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_RUN_LIST "${scene}|${chapter}|${run}${args}")
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_EXTRA_RUNS "${run}")
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_EXTRA_RUN_${run} "${chapter}|${scene}|$<TARGET_FILE:${scene}>${args}")
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_EXTRA_RUN_TARGETS_${run} ${scene})
endfunction()

# The corner sweep: every numeric option of a scene at the smallest and the largest value it
# accepts, one at a time (the others at their defaults, plus the scene's SMOKE_ARGS), with
# --no-figure and a small budget (WORKBOOK_CORNER_BUDGET seconds). The scene lists its own
# options and ranges (--list-options) when it is built; each corner is a CTest test of its own
# (label "corner"), checked by cmake/corner_check.cmake: exit 0 within the budget, or exit 2
# naming an option, or exit 1 with a message; never a crash or a hang.
set(WORKBOOK_CORNER_BUDGET 3 CACHE STRING "The --budget (seconds) of the corner sweep's scene runs")
function(_workbook_scene_corners name chapter base)
  set(dir "${CMAKE_BINARY_DIR}/corners")
  set(list_file "${dir}/${name}.cmake")
  math(EXPR timeout "(10 * ${WORKBOOK_CORNER_BUDGET} + 90) * ${WORKBOOK_HANG_FACTOR}")
  add_custom_command(TARGET ${name} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -DSCENE=$<TARGET_FILE:${name}> -DNAME=${name} -DCHAPTER=${chapter} "-DBASE=${base}"
            -DBUDGET=${WORKBOOK_CORNER_BUDGET} -DTIMEOUT=${timeout} -DHANG=${WORKBOOK_HANG_FACTOR} -DOUT=${list_file} -DWORK=${dir}/runs
            -DCHECK=${WORKBOOK_ROOT}/cmake/corner_check.cmake -P ${WORKBOOK_ROOT}/cmake/corner_list.cmake
    VERBATIM)
  # CTest reads the list when it runs; before the scene is built there is none, and one test says so.
  set(include_file "${dir}/${name}.include.cmake")
  file(WRITE "${include_file}"
    "if(EXISTS \"${list_file}\")\n  include(\"${list_file}\")\nelse()\n"
    "  add_test(\"corner: ${name} (not built yet)\" \"${CMAKE_COMMAND}\" -E false)\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${include_file}")
endfunction()

# A bad-input check: the scene must exit with status 2, say MESSAGE (a regex) on stderr,
# and leave no file behind.
#
#   workbook_scene_rejects(<scene> <label> MESSAGE <regex> ARGS <arg>...)
function(workbook_scene_rejects scene label)
  workbook_hang_catch()
  cmake_parse_arguments(R "" "MESSAGE" "ARGS" ${ARGN})
  set(out "${CMAKE_BINARY_DIR}/smoke/${scene}-rejects-${label}")
  set(args "")
  foreach(a IN LISTS R_ARGS)
    string(APPEND args "|${a}")
  endforeach()
  add_test(NAME "bad input: ${scene} ${label}"
           COMMAND ${CMAKE_COMMAND} -DEXPECT=2 -DOUT=${out} "-DMESSAGE=${R_MESSAGE}"
                   "-DCOMMAND=$<TARGET_FILE:${scene}>|--out|${out}${args}"
                   -P "${WORKBOOK_ROOT}/cmake/scene_check.cmake")
  set_tests_properties("bad input: ${scene} ${label}" PROPERTIES LABELS "scene;bad-input" TIMEOUT 60)
endfunction()

# A case a scene must serve: input inside its documented ranges (often where it once failed its
# own check), run with --json --no-figure. It must exit 0, and each EXPECT key of its JSON report
# (a.b for a nested one; a boolean reads ON or OFF) must match its regex (key=regex; no '|' in
# it), or be at most or at least a number (key<=number, key>=number: a range of numbers that a
# regex would need '|' for). A corner test, named "corner: <scene> <label>", like the corner
# sweep's; KIND names another kind of case ("stability: <scene> <label>", chapters/kit/stability.cmake),
# labelled LABELS instead of "corner;<chapter>".
#
#   workbook_scene_case(<scene> <label> [KIND <kind> LABELS <label>...] ARGS <arg>...
#                       [EXPECT <key>=<regex>|<key><=<number>|<key>>=<number>...])
function(workbook_scene_case scene label)
  workbook_hang_catch()
  cmake_parse_arguments(C "" "KIND" "ARGS;EXPECT;LABELS" ${ARGN})
  get_filename_component(chapter "${CMAKE_CURRENT_SOURCE_DIR}" NAME)
  set(kind corner)
  set(labels corner ${chapter})
  set(out "${CMAKE_BINARY_DIR}/smoke/${scene}-case-${label}")
  if(C_KIND)
    set(kind "${C_KIND}")
    set(labels ${C_LABELS})
    set(out "${CMAKE_BINARY_DIR}/smoke/${kind}/${scene}-${label}")
  endif()
  foreach(e IN LISTS C_EXPECT)
    if(e MATCHES "[|]")
      message(FATAL_ERROR "workbook_scene_case(${scene} ${label}): '${e}' holds a '|', which separates the "
                          "keys: bound the number with key<=number and key>=number instead")
    endif()
  endforeach()
  string(JOIN "|" args ${C_ARGS})
  string(JOIN "|" keys ${C_EXPECT})
  add_test(NAME "${kind}: ${scene} ${label}"
           COMMAND ${CMAKE_COMMAND} -DEXPECT=0 -DOUT=${out} "-DKEYS=${keys}"
                   "-DCOMMAND=$<TARGET_FILE:${scene}>|--json|--no-figure|--out|${out}|${args}"
                   -P "${WORKBOOK_ROOT}/cmake/scene_check.cmake")
  set_tests_properties("${kind}: ${scene} ${label}" PROPERTIES LABELS "${labels}" TIMEOUT 300)
endfunction()

# ------------------------------------------------------------------------------------------
# The chapters, in the order of chapters/README.md: the one list that drives book and build.
# workbook_contents() reads it (cmake/contents.cmake) into <build>/contents.json, the one copy the
# tools read; call it before the topics (each names its chapter). workbook_chapters() then adds
# the chapters' folders.
function(workbook_contents)
  set(json "${CMAKE_BINARY_DIR}/contents.json")
  workbook_read_contents("${WORKBOOK_ROOT}" "${json}" chapters)
  set_property(DIRECTORY "${CMAKE_SOURCE_DIR}" APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${WORKBOOK_ROOT}/chapters/README.md")
  set(labels "")
  foreach(ch IN LISTS chapters)
    list(APPEND labels "ch${ch}")
  endforeach()
  list(TRANSFORM labels REPLACE "^(ch[0-9][0-9]).*" "\\1")
  set_property(GLOBAL PROPERTY WORKBOOK_CHAPTER_LIST ${chapters})
  set_property(GLOBAL PROPERTY WORKBOOK_CHAPTER_LABELS ${labels})
  set_property(GLOBAL PROPERTY WORKBOOK_CONTENTS "${json}")
endfunction()

function(workbook_chapters)
  workbook_topic_names(own WORKBOOK_TOPICS CHECKED)  # every topic is declared by now
  get_property(chapters GLOBAL PROPERTY WORKBOOK_CHAPTER_LIST)
  foreach(ch IN LISTS chapters)
    if(EXISTS "${WORKBOOK_ROOT}/chapters/${ch}/CMakeLists.txt")
      add_subdirectory("${WORKBOOK_ROOT}/chapters/${ch}" "${CMAKE_BINARY_DIR}/chapters/${ch}")
    endif()
  endforeach()
endfunction()

# ------------------------------------------------------------------------------------------
# The main job (target `workbook`): run every scene (its run `default`), write every figure and
# the report of each scene's error against its run time, then render the book from that run.
# Everything goes to the build folder: <build>/figures/<chapter>/ (figures and each scene's JSON
# report), <build>/report/ (report.md, scenes.json), <build>/book/. The committed figures/
# change only through the target update-figures (reference solutions only), which a maintainer
# runs after a run worth keeping. Targets run-<run> make the runs of workbook_scene_run().
# Call once, after every scene is declared.
function(workbook_main_job)
  get_property(scenes GLOBAL PROPERTY WORKBOOK_SCENE_LIST)
  get_property(scene_targets GLOBAL PROPERTY WORKBOOK_SCENE_TARGETS)
  get_property(runs GLOBAL PROPERTY WORKBOOK_RUN_LIST)
  string(REPLACE ";" "\n" scene_lines "${scenes}")
  file(GENERATE OUTPUT "${CMAKE_BINARY_DIR}/report/scenes.txt" CONTENT "${scene_lines}\n")
  # Every run the book may quote: scene|chapter|run|arg|... (read by cmake/tools/).
  string(REPLACE ";" "\n" run_lines "${runs}")
  file(GENERATE OUTPUT "${CMAKE_BINARY_DIR}/runs.txt" CONTENT "${run_lines}\n")
  set(figures "${CMAKE_BINARY_DIR}/figures")
  set_property(GLOBAL PROPERTY WORKBOOK_FIGURES_DIR "${figures}")
  # After the scenes, the book: rendered with the numbers and figures of this very run.
  get_property(contents GLOBAL PROPERTY WORKBOOK_CONTENTS)
  set(book "$<TARGET_FILE:book_tool>|--render|${WORKBOOK_ROOT}|--runs|${CMAKE_BINARY_DIR}/runs.txt|--contents|${contents}"
           "--figures|${figures}|--out|${CMAKE_BINARY_DIR}/book|--pandoc|${PANDOC_EXECUTABLE}"
           "--label|scenes run by cmake/workbook run on the ${WORKBOOK_IMPL} implementation")
  string(REPLACE ";" "|" book "${book}")
  add_custom_target(workbook
    COMMAND ${CMAKE_COMMAND} -DSCENES=${CMAKE_BINARY_DIR}/report/scenes.txt -DRUN=default
            -DFIGURES=${figures} -DREPORT=${CMAKE_BINARY_DIR}/report
            -DIMPL=${WORKBOOK_IMPL} "-DBOOK=${book}" -P "${WORKBOOK_ROOT}/cmake/run_scenes.cmake"
    DEPENDS ${scene_targets} book_tool
    USES_TERMINAL VERBATIM
    COMMENT "Running every scene: figures and reports in ${figures}, the error/run-time report in ${CMAKE_BINARY_DIR}/report")

  # One target per chapter, scenes-NN: that chapter's scenes alone, run as `workbook` runs them
  # (no book): what `cmake/workbook scenes NN` builds and runs on a student's own code.
  get_property(chapters GLOBAL PROPERTY WORKBOOK_CHAPTER_LIST)
  foreach(ch IN LISTS chapters)
    set(lines "")
    set(targets "")
    foreach(line IN LISTS scenes)
      if(line MATCHES "^${ch}\\|([^|]+)\\|")
        list(APPEND lines "${line}")
        list(APPEND targets "${CMAKE_MATCH_1}")
      endif()
    endforeach()
    if(NOT targets)
      continue()
    endif()
    string(SUBSTRING "${ch}" 0 2 nn)
    string(REPLACE ";" "\n" lines "${lines}")
    file(GENERATE OUTPUT "${CMAKE_BINARY_DIR}/report/${ch}/scenes.txt" CONTENT "${lines}\n")
    # build-scenes-NN builds them; scenes-NN builds and runs them (cmake/workbook scenes NN: the first
    # shows a compile error as such, the second the runs).
    add_custom_target(build-scenes-${nn})
    add_dependencies(build-scenes-${nn} ${targets})
    add_custom_target(scenes-${nn}
      COMMAND ${CMAKE_COMMAND} -DSCENES=${CMAKE_BINARY_DIR}/report/${ch}/scenes.txt -DRUN=default
              -DFIGURES=${figures} -DREPORT=${CMAKE_BINARY_DIR}/report/${ch} -DIMPL=${WORKBOOK_IMPL}
              -P "${WORKBOOK_ROOT}/cmake/run_scenes.cmake"
      DEPENDS ${targets}
      USES_TERMINAL VERBATIM
      COMMENT "Running the scenes of ${ch}: figures and reports in ${figures}/${ch}")
  endforeach()

  get_property(extra GLOBAL PROPERTY WORKBOOK_EXTRA_RUNS)
  list(REMOVE_DUPLICATES extra)
  foreach(run IN LISTS extra)
    get_property(lines GLOBAL PROPERTY WORKBOOK_EXTRA_RUN_${run})
    get_property(targets GLOBAL PROPERTY WORKBOOK_EXTRA_RUN_TARGETS_${run})
    string(REPLACE ";" "\n" lines "${lines}")
    file(GENERATE OUTPUT "${CMAKE_BINARY_DIR}/report/${run}/scenes.txt" CONTENT "${lines}\n")
    add_custom_target(run-${run}
      COMMAND ${CMAKE_COMMAND} -DSCENES=${CMAKE_BINARY_DIR}/report/${run}/scenes.txt -DRUN=${run}
              -DFIGURES=${figures} -DREPORT=${CMAKE_BINARY_DIR}/report/${run} -DIMPL=${WORKBOOK_IMPL}
              -P "${WORKBOOK_ROOT}/cmake/run_scenes.cmake"
      DEPENDS ${targets}
      USES_TERMINAL VERBATIM
      COMMENT "The run '${run}': figures and reports in ${figures}/<chapter>/${run}")
  endforeach()

  # The maintainer's target: the last run's figures and reports become the committed ones
  # (figures/), and the numbers in the prose follow them. Only from the reference solutions.
  if(WORKBOOK_IMPL STREQUAL "solutions" AND NOT WORKBOOK_TOPICS)
    add_custom_target(update-figures
      COMMAND ${CMAKE_COMMAND} -DFROM=${figures} -DTO=${WORKBOOK_ROOT}/figures -DREPORT=${CMAKE_BINARY_DIR}/report
              -DSNIPPETS=$<TARGET_FILE:snippets> -DROOT=${WORKBOOK_ROOT} -DRUNS=${CMAKE_BINARY_DIR}/runs.txt
              -P "${WORKBOOK_ROOT}/cmake/update_figures.cmake"
      DEPENDS snippets
      USES_TERMINAL VERBATIM
      COMMENT "Committing the last run's figures and reports to figures/, and their numbers to the prose")
  else()
    add_custom_target(update-figures
      COMMAND ${CMAKE_COMMAND} -E echo "update-figures: the committed figures come from the reference solutions only (this build: WORKBOOK_IMPL=${WORKBOOK_IMPL} ${WORKBOOK_TOPICS})"
      COMMAND ${CMAKE_COMMAND} -E false)
  endif()
endfunction()

