# The table of contents, chapters/README.md, read once: each row that links NN_slug/README.md is
# a chapter, in reading order. CMake reads it here when it configures (the chapters it builds,
# the chapter each topic belongs to) and writes what it read to <build>/contents.json, which the
# book tool (--contents) and the grading run (grading/topics.txt) read instead of the Markdown:
#
#   {"chapters": [{"number": 1, "folder": "01_pure_rotations", "label": "ch01",
#                  "title": "Pure rotations"}, ...]}
#
# In a CMake project:  include(contents); workbook_read_contents(<root> <json file> <var>)
#   (<var>: the list of chapter folders). As a script (the book's self-test):
#   cmake -DROOT=<root> -DOUT=<json file> -P cmake/contents.cmake
include_guard(GLOBAL)

function(workbook_read_contents root json_file folders_var)
  set(toc "${root}/chapters/README.md")
  file(STRINGS "${toc}" lines REGEX "\\]\\([0-9][0-9]_[a-z0-9_]+/README\\.md\\)")
  set(json "{\"chapters\": []}")
  set(folders "")
  set(i 0)
  foreach(line IN LISTS lines)
    string(REGEX MATCH "\\[([^]]*)\\]\\(([0-9][0-9])_([a-z0-9_]+)/README\\.md\\)" _ "${line}")
    set(title "${CMAKE_MATCH_1}")
    set(nn "${CMAKE_MATCH_2}")
    set(folder "${nn}_${CMAKE_MATCH_3}")
    if(NOT IS_DIRECTORY "${root}/chapters/${folder}")
      message(FATAL_ERROR "chapters/README.md lists ${folder}, but chapters/${folder}/ does not exist")
    endif()
    math(EXPR number "${nn}")  # "07" -> 7
    # A JSON string: the title with its backslashes and quotes escaped (one line: no control
    # characters); string(JSON) checks the result.
    string(REPLACE "\\" "\\\\" title "${title}")
    string(REPLACE "\"" "\\\"" title "${title}")
    string(JSON json SET "${json}" chapters ${i}
           "{\"number\": ${number}, \"folder\": \"${folder}\", \"label\": \"ch${nn}\", \"title\": \"${title}\"}")
    list(APPEND folders "${folder}")
    math(EXPR i "${i} + 1")
  endforeach()
  file(WRITE "${json_file}.new" "${json}\n")
  file(COPY_FILE "${json_file}.new" "${json_file}" ONLY_IF_DIFFERENT)
  file(REMOVE "${json_file}.new")
  set(${folders_var} "${folders}" PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  if(NOT ROOT OR NOT OUT)
    message(FATAL_ERROR "usage: cmake -DROOT=<workbook root> -DOUT=<contents.json> -P cmake/contents.cmake")
  endif()
  workbook_read_contents("${ROOT}" "${OUT}" _)
endif()
