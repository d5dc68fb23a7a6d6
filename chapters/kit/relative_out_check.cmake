# A scene's figures with a relative --out (kit/figure.cpp, kit/motion.cpp): the SVG, the
# motion JSON and its GIF all land in the folder --out names, relative to where the scene
# runs, and nowhere else (the GIF once went to <out>/<out>/).
#
#   cmake -DSCENE=<pure_rotation> -DDIR=<empty work folder> -P relative_out_check.cmake
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
execute_process(COMMAND "${SCENE}" --out rel --motion m.motion.json
                WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SCENE} --out rel exited with ${rc}: ${err}")
endif()
file(GLOB_RECURSE files RELATIVE "${DIR}" "${DIR}/*")
list(SORT files)
set(expected "rel/m.motion.gif;rel/m.motion.json;rel/pure_rotation.svg")
if(NOT files STREQUAL expected)
  message(FATAL_ERROR "with --out rel the files are\n  ${files}\nnot\n  ${expected}")
endif()
file(REMOVE_RECURSE "${DIR}")
