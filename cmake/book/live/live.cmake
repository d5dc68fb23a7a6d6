# The book's live scenes (cmake/book/live/, cmake/book/web/live.js): a scene's own C++ compiled with
# Debian's emscripten into one single-file module, which the book's page runs when the reader
# moves a control. Declared in a chapter's CMakeLists.txt, after the scene:
#
#   workbook_live_scene(<scene>)
#
# A scene that links GSL gets it too: Debian builds no GSL for WebAssembly, so the build makes one
# from Debian's own source package, once, in <build>/live-gsl/ (cmake/book/live/gsl.cmake, the target
# live_gsl: apt-get source, dpkg-source, emconfigure and emmake), unless WORKBOOK_LIVE_GSL names
# one already built. Where that cannot be done (offline, no apt-get), the live scenes that need
# GSL are left out with one message, each of their pages says why, and the others stay live.
#
# The module is built from the scene's source and the sources of every library it links (its
# topics from WORKBOOK_IMPL, the provided code), never from a second copy. Its page spec,
# cmake/book/live/<scene>.json (the controls, the numbers shown, the plot), is merged at build time
# with the scene's own `--list-options` into <build>/live/<scene>.live.json, which the book's
# render puts into the page (<!-- live: <scene> --> in the prose).
# Without emscripten (em++ and its CMake toolchain file) nothing of this is built: the book then
# renders without live scenes and says so on each page that has one. Scenes and graders never
# need emscripten.

set(WORKBOOK_EMSCRIPTEN_TOOLCHAIN "/usr/share/emscripten/cmake/Modules/Platform/Emscripten.cmake"
    CACHE FILEPATH "emscripten's CMake toolchain file (Debian: emscripten)")
find_program(WORKBOOK_EMXX em++)
set(WORKBOOK_LIVE_GSL "" CACHE PATH
    "prefix of a GSL built with emscripten (include/gsl, lib/libgsl.a, lib/libgslcblas.a) for live scenes that need GSL; empty: the build makes one from Debian's source package in <build>/live-gsl")

# Every library a target links, itself included, that holds workbook sources: the topics
# (rigid_*) and a chapter's own code shared by its scenes (chNN_*, e.g. Chapter 7's ch07_bench);
# in `gsl`, whether GSL is among what it links.
function(_workbook_live_sources target out gsl)
  set(needs_gsl "")
  set(seen "")
  set(stack ${target})
  set(sources "")
  while(stack)
    list(POP_FRONT stack t)
    if(t MATCHES "^GSL::")
      set(needs_gsl gsl)
    endif()
    if(NOT TARGET ${t} OR t IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${t})
    get_target_property(aliased ${t} ALIASED_TARGET)
    if(aliased)
      list(APPEND stack ${aliased})
      continue()
    endif()
    get_target_property(type ${t} TYPE)
    if(NOT type STREQUAL "INTERFACE_LIBRARY" AND t MATCHES "^(rigid_|ch[0-9][0-9]_)")
      get_target_property(srcs ${t} SOURCES)
      get_target_property(dir ${t} SOURCE_DIR)  # where its relative sources are
      foreach(s IN LISTS srcs)
        get_filename_component(s "${s}" ABSOLUTE BASE_DIR "${dir}")
        list(APPEND sources "${s}")
      endforeach()
    endif()
    get_target_property(libs ${t} LINK_LIBRARIES)
    if(libs)
      list(APPEND stack ${libs})
    endif()
  endwhile()
  set(${out} "${sources}" PARENT_SCOPE)
  set(${gsl} "${needs_gsl}" PARENT_SCOPE)
endfunction()

function(workbook_live_scene name)
  set(spec "${WORKBOOK_ROOT}/cmake/book/live/${name}.json")
  if(NOT EXISTS "${spec}")
    message(FATAL_ERROR "workbook_live_scene(${name}): its page spec ${spec} is missing")
  endif()
  _workbook_live_sources(${name} sources gsl)
  string(REPLACE ";" "," sources "${sources}")
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_LIVE_LIST
               "${name}|${CMAKE_CURRENT_SOURCE_DIR}/${name}.cpp|${sources}|${gsl}")
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_LIVE_SCENES ${name})
endfunction()

# The GSL the live scenes link: WORKBOOK_LIVE_GSL when the user names one (the target live_gsl
# then does nothing), else Debian's, built once in <build>/live-gsl/ by cmake/book/live/gsl.cmake (quick
# once it is there; it never fails the build, and says why when it cannot build). Its prefix and
# status file (empty for the user's own) go to the live project.
function(_workbook_live_gsl prefix status)
  if(WORKBOOK_LIVE_GSL)
    add_custom_target(live_gsl)
    set(${prefix} "${WORKBOOK_LIVE_GSL}" PARENT_SCOPE)
    set(${status} "" PARENT_SCOPE)
    return()
  endif()
  set(dir "${CMAKE_BINARY_DIR}/live-gsl")
  cmake_host_system_information(RESULT cores QUERY NUMBER_OF_LOGICAL_CORES)
  add_custom_target(live_gsl
    COMMAND ${CMAKE_COMMAND} -DDIR=${dir} -DJOBS=${cores} -P "${WORKBOOK_ROOT}/cmake/book/live/gsl.cmake"
    COMMENT "GSL for the live scenes: Debian's source package built with emscripten (once)"
    USES_TERMINAL)
  set(${prefix} "${dir}/prefix" PARENT_SCOPE)
  set(${status} "${dir}/status.txt" PARENT_SCOPE)
endfunction()

# After every scene: the target `live` (the modules and their page specs, in <build>/live/),
# which the book's targets depend on; and the browser test of the live scenes.
function(workbook_live)
  get_property(scenes GLOBAL PROPERTY WORKBOOK_LIVE_SCENES)
  get_property(lines GLOBAL PROPERTY WORKBOOK_LIVE_LIST)
  set(out "${CMAKE_BINARY_DIR}/live")
  if(NOT WORKBOOK_EMXX OR NOT EXISTS "${WORKBOOK_EMSCRIPTEN_TOOLCHAIN}")
    message(STATUS "emscripten not found: the book renders without its live scenes "
                   "(sudo apt-get install emscripten; cmake/workbook run installs it)")
    add_custom_target(live COMMAND ${CMAKE_COMMAND} -E rm -rf "${out}"
                      COMMENT "No emscripten: the book's live scenes are not built")
    add_dependencies(workbook live)
    add_dependencies(book live)
    return()
  endif()
  string(REPLACE ";" "\n" text "${lines}")
  file(GENERATE OUTPUT "${out}/scenes.txt" CONTENT "${text}\n")
  _workbook_live_gsl(gsl_prefix gsl_status)
  include(ExternalProject)
  cmake_host_system_information(RESULT cores QUERY NUMBER_OF_LOGICAL_CORES)
  ExternalProject_Add(live_modules
    DEPENDS live_gsl
    SOURCE_DIR "${WORKBOOK_ROOT}/cmake/book/live"
    BINARY_DIR "${CMAKE_BINARY_DIR}/live-build"
    CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${WORKBOOK_EMSCRIPTEN_TOOLCHAIN} -DCMAKE_BUILD_TYPE=Release
               -DWORKBOOK_ROOT=${WORKBOOK_ROOT} -DLIVE_LIST=${out}/scenes.txt -DLIVE_OUT=${out}
               -DWORKBOOK_LIVE_GSL=${gsl_prefix} -DWORKBOOK_LIVE_GSL_STATUS=${gsl_status}
    # emscripten's JavaScript optimizer needs acorn: Debian's node finds it, another node is told
    # where Debian keeps it.
    # The outer make's jobserver does not reach through `cmake -E env` (the inner build ran at
    # -j1, minutes for the kit): the inner build is given the machine's cores itself.
    BUILD_COMMAND ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs ${CMAKE_COMMAND} --build <BINARY_DIR>
                  --parallel ${cores}
    BUILD_ALWAYS ON
    INSTALL_COMMAND ""
    USES_TERMINAL_BUILD ON)
  set(specs "")
  foreach(s IN LISTS scenes)
    add_custom_command(OUTPUT "${out}/${s}.live.json"
      COMMAND ${CMAKE_COMMAND} -DSCENE=$<TARGET_FILE:${s}> -DSPEC=${WORKBOOK_ROOT}/cmake/book/live/${s}.json
              -DOUT=${out}/${s}.live.json -P "${WORKBOOK_ROOT}/cmake/book/live/spec.cmake"
      DEPENDS ${s} "${WORKBOOK_ROOT}/cmake/book/live/${s}.json" "${WORKBOOK_ROOT}/cmake/book/live/spec.cmake"
      COMMENT "Live scene ${s}: its controls from its --list-options")
    list(APPEND specs "${out}/${s}.live.json")
  endforeach()
  add_custom_target(live ALL DEPENDS ${specs} live_modules)
  # The books render after the modules are built: the run's book and `book`.
  add_dependencies(workbook live)
  add_dependencies(book live)
  _workbook_live_tests()
  _workbook_live_gsl_tests("${gsl_prefix}")
endfunction()

# The live scenes' GSL computes what Debian's native GSL computes (cmake/book/live/gsl_check.cmake:
# an elliptic function and a rk8pd integration, to a relative 1e-13), and that check fails on a
# result moved by 1e-9. Skipped without that GSL (the build said why), unless CI=true.
function(_workbook_live_gsl_tests prefix)
  set(check "live: the GSL built for the live scenes computes what Debian's native GSL computes")
  set(self "live: the GSL check fails on a GSL result moved by 1e-9")
  add_test(NAME "${check}" COMMAND ${CMAKE_COMMAND} -DPREFIX=${prefix} -DWORK=${CMAKE_BINARY_DIR}/test/live-gsl
                                   -DTOL=1e-13 -P "${WORKBOOK_ROOT}/cmake/book/live/gsl_check.cmake")
  add_test(NAME "${self}" COMMAND ${CMAKE_COMMAND} -DPREFIX=${prefix} -DWORK=${CMAKE_BINARY_DIR}/test/live-gsl-plant
                                  -DTOL=1e-13 -DPLANT=ON -P "${WORKBOOK_ROOT}/cmake/book/live/gsl_check.cmake")
  set_tests_properties("${check}" "${self}" PROPERTIES LABELS "live" SKIP_REGULAR_EXPRESSION "SKIPPED: no GSL")
endfunction()

# The browser test of the live scenes, on the test suite's book (rendered by the test "book:
# renders ..." with this build's modules), and its self-test. Both report themselves skipped
# (exit status 77) without Chromium or without modules, and fail instead under CI=true.
function(_workbook_live_tests)
  set(marked 0)
  file(GLOB pages "${WORKBOOK_ROOT}/chapters/*/*.md")
  foreach(p IN LISTS pages)
    file(STRINGS "${p}" found REGEX "^<!-- live: [A-Za-z0-9_]+ -->")
    list(LENGTH found n)
    math(EXPR marked "${marked} + ${n}")
  endforeach()
  set(book "${CMAKE_BINARY_DIR}/test/book")
  set(check "book: the live scenes run in the browser from file://, offline, and show what their native scenes report")
  set(self "book: the live checks fail on a wrong number, a module that does not load and a fetch from the network")
  add_test(NAME "${check}"
           COMMAND python3 "${WORKBOOK_ROOT}/cmake/book/tests/browser_live.py" "${book}" "${CMAKE_BINARY_DIR}"
                   "${CMAKE_BINARY_DIR}/test/live" --expect ${marked})
  add_test(NAME "${self}"
           COMMAND python3 "${WORKBOOK_ROOT}/cmake/book/tests/browser_live.py" --selftest "${book}" "${CMAKE_BINARY_DIR}"
                   "${CMAKE_BINARY_DIR}/test/live-selftest")
  set_tests_properties("${check}" "${self}" PROPERTIES LABELS "book;browser" TIMEOUT 600 SKIP_RETURN_CODE 77
                       FIXTURES_REQUIRED book_html RESOURCE_LOCK browser)
endfunction()
