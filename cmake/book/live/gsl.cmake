# The GSL of the live scenes: Debian's own source package of GSL, built with emscripten into a
# static library, once per build folder (cmake/book/live/live.cmake runs this script as the target
# live_gsl before the live modules; it is quick once the library is there).
#
#   cmake -DDIR=<build>/live-gsl -DJOBS=<n> -P cmake/book/live/gsl.cmake
#
# DIR/prefix/ gets include/gsl/, lib/libgsl.a and lib/libgslcblas.a. The source comes from the
# Debian mirror this machine's apt already uses, through apt-get with a configuration of its own
# in DIR/apt/ (the system's apt is not touched, no root needed): `apt-get source` of the GSL
# version installed here (libgsl-dev), which dpkg-source unpacks with Debian's patches. It is
# built the way Debian's autotools build it, with emconfigure and emmake (the host triple only
# makes configure cross-compile: its config.sub does not know wasm32).
#
# It never fails the build: offline, without apt-get or when a step fails, it says so once and
# why, the live scenes that need GSL are left out (their pages say so) and the next build tries
# again. DIR/status.txt holds `ok` or the reason (the live project reads it, and configures again
# when it changes); the steps' output is in DIR/*.log.
cmake_minimum_required(VERSION 3.20)
if(NOT DIR)
  message(FATAL_ERROR "usage: cmake -DDIR=<build>/live-gsl [-DJOBS=<n>] -P gsl.cmake")
endif()
if(NOT JOBS)
  set(JOBS 2)
endif()
set(prefix "${DIR}/prefix")
set(status_file "${DIR}/status.txt")

function(gsl_status text)
  set(old "")
  if(EXISTS "${status_file}")
    file(READ "${status_file}" old)
  endif()
  if(NOT old STREQUAL "${text}\n")
    file(WRITE "${status_file}" "${text}\n")
  endif()
endfunction()

# The reason a step failed: written to the status, said in one line, and the script ends (exit 0);
# the live project's warning then names the scenes left out, with the same reason.
macro(gsl_give_up why)
  gsl_status("${why}")
  message(STATUS "No GSL for the live scenes: ${why} (the live build names the scenes it leaves out)")
  return()
endmacro()

# Runs one step with its output in DIR/<log>.log; false in `ok` when it failed.
function(gsl_step log ok)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_FILE "${DIR}/${log}.log" ERROR_FILE "${DIR}/${log}.err.log"
                  ${GSL_STEP_DIR})
  if(rc EQUAL 0)
    set(${ok} TRUE PARENT_SCOPE)
  else()
    set(${ok} FALSE PARENT_SCOPE)
  endif()
endfunction()

if(EXISTS "${prefix}/lib/libgsl.a" AND EXISTS "${prefix}/lib/libgslcblas.a"
   AND EXISTS "${prefix}/include/gsl/gsl_odeiv2.h")
  gsl_status("ok")
  return()
endif()
file(MAKE_DIRECTORY "${DIR}")
foreach(tool apt-get emconfigure emmake)
  find_program(GSL_TOOL_${tool} ${tool})
  if(NOT GSL_TOOL_${tool})
    gsl_give_up("no ${tool} here to fetch and build Debian's GSL for WebAssembly")
  endif()
endforeach()

# apt's source lists: the machine's own Debian mirror and suites (deb822 or one-line), as deb-src.
set(apt "${DIR}/apt")
file(MAKE_DIRECTORY "${apt}/parts" "${apt}/lists/partial" "${apt}/archives/partial")
set(sources "")
file(GLOB deb822 /etc/apt/sources.list.d/*.sources)
foreach(f IN LISTS deb822)
  file(STRINGS "${f}" lines)
  foreach(l IN LISTS lines)
    if(l MATCHES "^Types:")
      string(APPEND sources "\nTypes: deb-src\n")
    elseif(l MATCHES "^(URIs|Suites|Components|Signed-By):")
      string(APPEND sources "${l}\n")
    endif()
  endforeach()
endforeach()
set(oneline "")
file(GLOB lists /etc/apt/sources.list /etc/apt/sources.list.d/*.list)
foreach(f IN LISTS lists)
  file(STRINGS "${f}" lines REGEX "^deb[ \t]")
  foreach(l IN LISTS lines)
    string(REGEX REPLACE "^deb" "deb-src" l "${l}")
    string(APPEND oneline "${l}\n")
  endforeach()
endforeach()
if(sources STREQUAL "" AND oneline STREQUAL "")
  gsl_give_up("this machine's apt names no Debian mirror (/etc/apt/sources.list*)")
endif()
file(WRITE "${apt}/parts/workbook.sources" "${sources}")
file(WRITE "${apt}/parts/workbook.list" "${oneline}")
set(apt_get ${GSL_TOOL_apt-get} -q -o Dir::Etc::SourceList=/dev/null -o Dir::Etc::SourceParts=${apt}/parts
    -o Dir::State::Lists=${apt}/lists -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache=
    -o Dir::Cache::archives=${apt}/archives -o Debug::NoLocking=1 -o APT::Sandbox::User=root
    -o Acquire::Retries=0 -o Acquire::http::Timeout=20)

set(src "${DIR}/src/gsl")
if(NOT EXISTS "${src}/configure")
  gsl_step(apt-update ok ${apt_get} update)
  file(GLOB got "${apt}/lists/*Sources*")  # apt-get update succeeds with warnings when it fetches nothing
  if(NOT ok OR NOT got)
    gsl_give_up("could not download Debian's source lists (offline?), see ${DIR}/apt-update.err.log")
  endif()
  # The version installed here, so that the scenes' native and live GSL are one GSL.
  execute_process(COMMAND dpkg-query -W -f=\${Version} libgsl-dev OUTPUT_VARIABLE version ERROR_QUIET
                  RESULT_VARIABLE rc)
  set(want gsl)
  if(rc EQUAL 0 AND version)
    set(want "gsl=${version}")
  endif()
  file(REMOVE_RECURSE "${DIR}/src")
  file(MAKE_DIRECTORY "${DIR}/src")
  set(GSL_STEP_DIR WORKING_DIRECTORY "${DIR}/src")
  gsl_step(apt-source ok ${apt_get} source --download-only ${want})
  if(NOT ok AND NOT want STREQUAL "gsl")
    gsl_step(apt-source ok ${apt_get} source --download-only gsl)
  endif()
  if(NOT ok)
    gsl_give_up("apt-get source gsl failed, see ${DIR}/apt-source.err.log")
  endif()
  file(GLOB dsc "${DIR}/src/gsl_*.dsc")
  find_program(GSL_TOOL_dpkg_source dpkg-source)
  if(NOT dsc OR NOT GSL_TOOL_dpkg_source)
    gsl_give_up("no dpkg-source to unpack Debian's GSL with its patches (Debian: sudo apt-get install dpkg-dev)")
  endif()
  gsl_step(unpack ok ${GSL_TOOL_dpkg_source} -x ${dsc} "${src}")
  if(NOT ok OR NOT EXISTS "${src}/configure")
    gsl_give_up("dpkg-source could not unpack ${dsc}, see ${DIR}/unpack.err.log")
  endif()
  message(STATUS "Debian's GSL for the live scenes: ${dsc} unpacked with its patches")
endif()

set(build "${DIR}/build")
# emcc's JavaScript optimizer needs acorn, which Debian keeps for its own node.
if(DEFINED ENV{NODE_PATH} AND NOT "$ENV{NODE_PATH}" STREQUAL "")
  set(ENV{NODE_PATH} "/usr/share/nodejs:$ENV{NODE_PATH}")
else()
  set(ENV{NODE_PATH} "/usr/share/nodejs")
endif()
file(MAKE_DIRECTORY "${build}")
set(GSL_STEP_DIR WORKING_DIRECTORY "${build}")
if(NOT EXISTS "${build}/config.status")
  gsl_step(configure ok ${GSL_TOOL_emconfigure} "${src}/configure" --host=i686-pc-linux-gnu --disable-shared
           --enable-static CFLAGS=-O2 "--prefix=${prefix}")
  if(NOT ok)
    file(REMOVE "${build}/config.status")
    gsl_give_up("emconfigure of GSL failed, see ${DIR}/configure.log and ${build}/config.log")
  endif()
endif()
# Every library, not its manual: Debian's +dfsg tarball leaves out the manual's sources, which
# doc/ would build (Debian builds it from its own copy). The rest of SUBDIRS is GSL's own.
file(STRINGS "${src}/Makefile.in" subdirs REGEX "^SUBDIRS = ")
string(REGEX REPLACE "^SUBDIRS = " "" subdirs "${subdirs}")
string(REGEX REPLACE " doc( |$)" "\\1" subdirs "${subdirs}")
message(STATUS "Building Debian's GSL with emscripten for the live scenes, once (${build}; several minutes)")
gsl_step(make ok ${GSL_TOOL_emmake} make -j${JOBS} -C "${build}" "SUBDIRS=${subdirs}")
if(NOT ok)
  gsl_give_up("emmake make of GSL failed, see ${DIR}/make.err.log")
endif()
gsl_step(install ok make -C "${build}" "SUBDIRS=${subdirs}" install)
if(NOT ok OR NOT EXISTS "${prefix}/lib/libgsl.a")
  gsl_give_up("make install of GSL failed, see ${DIR}/install.err.log")
endif()
gsl_status("ok")
message(STATUS "Debian's GSL for the live scenes is in ${prefix}")
