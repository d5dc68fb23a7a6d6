# The book's live scenes (cmake/live/, cmake/book/live.js): a scene's own C++ compiled with
# Debian's emscripten into one single-file module, which the book's page runs when the reader
# moves a control. Declared in a chapter's CMakeLists.txt, after the scene:
#
#   workbook_live_scene(<scene>)
#
# The scene must not need GSL (Debian builds none for WebAssembly).
#
# The module is built from the scene's source and the sources of every library it links (its
# topics from WORKBOOK_IMPL, the provided code), never from a second copy. Its page spec,
# cmake/live/<scene>.json (the controls, the numbers shown, the plot), is merged at build time
# with the scene's own `--list-options` into <build>/live/<scene>.live.json, which the book's
# render puts into the page (<!-- live: <scene> --> in the prose).
# Without emscripten (em++ and its CMake toolchain file) nothing of this is built: the book then
# renders without live scenes and says so on each page that has one. Scenes and graders never
# need emscripten.

set(WORKBOOK_EMSCRIPTEN_TOOLCHAIN "/usr/share/emscripten/cmake/Modules/Platform/Emscripten.cmake"
    CACHE FILEPATH "emscripten's CMake toolchain file (Debian: emscripten)")
find_program(WORKBOOK_EMXX em++)
set(WORKBOOK_LIVE_GSL "" CACHE PATH
    "prefix of a GSL built with emscripten (include/gsl, lib/libgsl.a, lib/libgslcblas.a) for live scenes that need GSL")

# Every library a target links, itself included, that holds workbook sources: the topics
# (rigid_*) and a chapter's own code shared by its scenes (chNN_*, e.g. Chapter 7's ch07_bench).
function(_workbook_live_sources target out)
  set(seen "")
  set(stack ${target})
  set(sources "")
  while(stack)
    list(POP_FRONT stack t)
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
endfunction()

function(workbook_live_scene name)
  set(spec "${WORKBOOK_ROOT}/cmake/live/${name}.json")
  if(NOT EXISTS "${spec}")
    message(FATAL_ERROR "workbook_live_scene(${name}): its page spec ${spec} is missing")
  endif()
  _workbook_live_sources(${name} sources)
  string(REPLACE ";" "," sources "${sources}")
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_LIVE_LIST
               "${name}|${CMAKE_CURRENT_SOURCE_DIR}/${name}.cpp|${sources}")
  set_property(GLOBAL APPEND PROPERTY WORKBOOK_LIVE_SCENES ${name})
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
  include(ExternalProject)
  ExternalProject_Add(live_modules
    SOURCE_DIR "${WORKBOOK_ROOT}/cmake/live"
    BINARY_DIR "${CMAKE_BINARY_DIR}/live-build"
    CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${WORKBOOK_EMSCRIPTEN_TOOLCHAIN} -DCMAKE_BUILD_TYPE=Release
               -DWORKBOOK_ROOT=${WORKBOOK_ROOT} -DLIVE_LIST=${out}/scenes.txt -DLIVE_OUT=${out}
               -DWORKBOOK_LIVE_GSL=${WORKBOOK_LIVE_GSL}
    # emscripten's JavaScript optimizer needs acorn: Debian's node finds it, another node is told
    # where Debian keeps it.
    BUILD_COMMAND ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs ${CMAKE_COMMAND} --build <BINARY_DIR>
    BUILD_ALWAYS ON
    INSTALL_COMMAND ""
    USES_TERMINAL_BUILD ON)
  set(specs "")
  foreach(s IN LISTS scenes)
    add_custom_command(OUTPUT "${out}/${s}.live.json"
      COMMAND ${CMAKE_COMMAND} -DSCENE=$<TARGET_FILE:${s}> -DSPEC=${WORKBOOK_ROOT}/cmake/live/${s}.json
              -DOUT=${out}/${s}.live.json -P "${WORKBOOK_ROOT}/cmake/live/spec.cmake"
      DEPENDS ${s} "${WORKBOOK_ROOT}/cmake/live/${s}.json" "${WORKBOOK_ROOT}/cmake/live/spec.cmake"
      COMMENT "Live scene ${s}: its controls from its --list-options")
    list(APPEND specs "${out}/${s}.live.json")
  endforeach()
  add_custom_target(live ALL DEPENDS ${specs} live_modules)
  # The books render after the modules are built: the run's book and `book`.
  add_dependencies(workbook live)
  add_dependencies(book live)
  _workbook_live_tests()
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
           COMMAND python3 "${WORKBOOK_ROOT}/cmake/book/browser_live.py" "${book}" "${CMAKE_BINARY_DIR}"
                   "${CMAKE_BINARY_DIR}/test/live" --expect ${marked})
  add_test(NAME "${self}"
           COMMAND python3 "${WORKBOOK_ROOT}/cmake/book/browser_live.py" --selftest "${book}" "${CMAKE_BINARY_DIR}"
                   "${CMAKE_BINARY_DIR}/test/live-selftest")
  set_tests_properties("${check}" "${self}" PROPERTIES LABELS "book;browser" TIMEOUT 600 SKIP_RETURN_CODE 77
                       FIXTURES_REQUIRED book_html RESOURCE_LOCK browser)
endfunction()
