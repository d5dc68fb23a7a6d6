# Formatting: every C++ source of the workbook is laid out as the repository's .clang-format says
# (Debian's clang-format 14, which cmake/workbook test installs). A student's working files,
# exercises/*.cpp, are not checked: how a student lays out an answer is theirs.
#
#   cmake -DFORMAT=<clang-format> -DROOT=<workbook> -P cmake/checks/format_check.cmake
#       checks the sources; names each file clang-format would change, with the command that fixes it;
#   cmake -DFORMAT=<clang-format> -DROOT=<workbook> -DSELFTEST=<scratch folder> -P cmake/checks/format_check.cmake
#       the check must be able to fail: it must flag a badly laid out file and pass a well laid out one.
if(NOT FORMAT OR NOT EXISTS "${FORMAT}")
  if("$ENV{CI}" STREQUAL "true")
    message(FATAL_ERROR "clang-format was not found: sudo apt-get install clang-format (cmake/workbook test installs it)")
  endif()
  message(FATAL_ERROR "SKIPPED: clang-format was not found (sudo apt-get install clang-format; cmake/workbook test installs it)")
endif()

# The files among `ARGN` that clang-format would change, in `out`.
function(unformatted out)
  set(found "")
  foreach(file IN LISTS ARGN)
    execute_process(COMMAND "${FORMAT}" --dry-run --Werror "--style=file:${ROOT}/.clang-format" "${file}"
                    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      list(APPEND found "${file}")
    endif()
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

if(SELFTEST)
  file(REMOVE_RECURSE "${SELFTEST}")
  file(WRITE "${SELFTEST}/good.cpp" "int f(int x) { return x + 1; }\n")
  file(WRITE "${SELFTEST}/bad.cpp" "int  f( int x ){return x+1;}\n")
  unformatted(good "${SELFTEST}/good.cpp")
  unformatted(bad "${SELFTEST}/bad.cpp")
  if(good OR NOT bad)
    message(FATAL_ERROR "the format check is broken: a well laid out file gave '${good}', a badly laid out one "
                        "gave '${bad}' (it must be flagged)")
  endif()
  message(STATUS "flags a badly laid out file, passes a well laid out one")
  return()
endif()

set(files "")
foreach(dir IN ITEMS chapters exercises/rigid exercises/provided solutions tests cmake)
  file(GLOB_RECURSE found "${ROOT}/${dir}/*.cpp" "${ROOT}/${dir}/*.hpp")
  list(APPEND files ${found})
endforeach()
unformatted(bad ${files})
list(LENGTH files n)
if(bad)
  list(TRANSFORM bad REPLACE "^${ROOT}/" "")
  list(JOIN bad " " names)
  list(JOIN bad "\n  " lines)
  message(FATAL_ERROR "not laid out as .clang-format says:\n  ${lines}\nFix them with: clang-format -i ${names}")
endif()
message(STATUS "${n} C++ sources laid out as .clang-format says")
