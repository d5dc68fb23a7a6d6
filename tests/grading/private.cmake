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
