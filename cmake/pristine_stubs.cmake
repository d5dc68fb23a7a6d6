# The pristine stubs: exercises/*.cpp as committed (git HEAD), copied at configure time into
# <build>/pristine/exercises/. The stub gate and the grading run's own tests (the harness's
# cases, the class of 30, the similarity report's baseline) build from this copy, never from the
# student's edited files: a student's progress must not look like a grader that passes on its
# stub. Without git (a zip of the workbook, Gradescope) or for a file git does not know, the
# copy is the file as it is, and the configure step says so. Included by cmake/Workbook.cmake.
set(WORKBOOK_PRISTINE_DIR "${CMAKE_BINARY_DIR}/pristine/exercises")
file(MAKE_DIRECTORY "${WORKBOOK_PRISTINE_DIR}")
file(GLOB _workbook_stubs RELATIVE "${WORKBOOK_ROOT}/exercises" "${WORKBOOK_ROOT}/exercises/*.cpp")
find_package(Git QUIET)
set(_workbook_git_dir "")
if(GIT_EXECUTABLE)
  execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${WORKBOOK_ROOT}" rev-parse --absolute-git-dir
                  OUTPUT_VARIABLE _workbook_git_dir OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE _workbook_git_status ERROR_QUIET)
  if(NOT _workbook_git_status EQUAL 0)
    set(_workbook_git_dir "")
  endif()
endif()
set(WORKBOOK_PRISTINE_FROM_TREE "")
foreach(_stub IN LISTS _workbook_stubs)
  set(_copied OFF)
  if(_workbook_git_dir)
    execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${WORKBOOK_ROOT}" show "HEAD:./exercises/${_stub}"
                    OUTPUT_FILE "${WORKBOOK_PRISTINE_DIR}/${_stub}.new" RESULT_VARIABLE _status ERROR_QUIET)
    if(_status EQUAL 0)
      # Only when it changed: an unchanged stub is not compiled again.
      file(COPY_FILE "${WORKBOOK_PRISTINE_DIR}/${_stub}.new" "${WORKBOOK_PRISTINE_DIR}/${_stub}" ONLY_IF_DIFFERENT)
      set(_copied ON)
    endif()
    file(REMOVE "${WORKBOOK_PRISTINE_DIR}/${_stub}.new")
  endif()
  if(NOT _copied)
    file(COPY_FILE "${WORKBOOK_ROOT}/exercises/${_stub}" "${WORKBOOK_PRISTINE_DIR}/${_stub}" ONLY_IF_DIFFERENT)
    list(APPEND WORKBOOK_PRISTINE_FROM_TREE "${_stub}")
  endif()
endforeach()
if(WORKBOOK_PRISTINE_FROM_TREE)
  string(REPLACE ";" ", " _list "${WORKBOOK_PRISTINE_FROM_TREE}")
  message(STATUS "Pristine stubs: not in git, taken from the tree as they are: ${_list}")
endif()
# A commit or a checkout changes HEAD's log: configure again, so the copy follows the commit.
if(_workbook_git_dir AND EXISTS "${_workbook_git_dir}/logs/HEAD")
  set_property(DIRECTORY "${CMAKE_SOURCE_DIR}" APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${_workbook_git_dir}/logs/HEAD")
endif()
