# Where a grading run's results come from: grading/provenance.txt, written at every build of the
# target `grading` (tests/grading/grading.cmake runs this script; the file is rewritten only when a
# line changes). The grading run copies it into every results/<student>.json and run.json
# (provenance.cpp), with the hashes of the graders and of the limits it computes itself.
#
#   cmake -DROOT=<workbook> -DOUT=<provenance.txt> -DCOMPILER_ID=GNU -DCOMPILER_VERSION=12.2.0
#         -DCOMPILER=/usr/bin/c++ -P provenance.cmake
#
# The compiler is CMake's, as the build uses it (CMAKE_CXX_COMPILER_ID and _VERSION). The package
# versions are Debian's, asked of dpkg-query when the build runs ("unknown" where there is no dpkg
# or no such package, e.g. a library built by hand). The commit is `git rev-parse HEAD` of the
# workbook when the build runs (outside git, the packed_from.txt that `cmake/workbook gradescope`
# writes into its zip; else "unknown"), and "modified" says whether tracked files
# differ from it (then the commit alone does not say what graded).
set(lines "# Generated at build time by tests/grading/engine/provenance.cmake. Do not edit.\n")
string(APPEND lines "compiler\t${COMPILER_ID} ${COMPILER_VERSION}\n")
string(APPEND lines "compiler_path\t${COMPILER}\n")

set(commit "unknown")
set(modified "unknown")
find_program(GIT git)
if(GIT)
  # Only a checkout whose top is the workbook: a copy inside another checkout (an unpacked
  # Gradescope zip under build/) must not take that checkout's commit.
  execute_process(COMMAND "${GIT}" -C "${ROOT}" rev-parse --show-toplevel OUTPUT_VARIABLE top RESULT_VARIABLE status
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  file(REAL_PATH "${ROOT}" real_root)
  if(status EQUAL 0)
    file(REAL_PATH "${top}" top)
  endif()
  set(out "")
  if(status EQUAL 0 AND top STREQUAL real_root)
    execute_process(COMMAND "${GIT}" -C "${ROOT}" rev-parse HEAD OUTPUT_VARIABLE out RESULT_VARIABLE status
                    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  endif()
  if(status EQUAL 0 AND out MATCHES "^[0-9a-f]+$")
    set(commit "${out}")
    execute_process(COMMAND "${GIT}" -C "${ROOT}" status --porcelain --untracked-files=no
                    OUTPUT_VARIABLE out RESULT_VARIABLE status ERROR_QUIET)
    if(status EQUAL 0)
      if(out STREQUAL "")
        set(modified "no")
      else()
        set(modified "yes")
      endif()
    endif()
  endif()
endif()
# A copy packed by `cmake/workbook gradescope` has no .git; the commit it was packed from is in its
# packed_from.txt (lines "commit<TAB>..." and "modified<TAB>...").
if(commit STREQUAL "unknown" AND EXISTS "${ROOT}/packed_from.txt")
  file(STRINGS "${ROOT}/packed_from.txt" packed)
  foreach(line IN LISTS packed)
    if(line MATCHES "^commit\t([0-9a-f]+)$")
      set(commit "${CMAKE_MATCH_1}")
    elseif(line MATCHES "^modified\t(yes|no)$")
      set(modified "${CMAKE_MATCH_1}")
    endif()
  endforeach()
  if(NOT commit STREQUAL "unknown")
    string(APPEND lines "commit_from\tpacked_from.txt, written by cmake/workbook gradescope\n")
  endif()
endif()
string(APPEND lines "commit\t${commit}\nmodified\t${modified}\n")

find_program(DPKG_QUERY dpkg-query)
foreach(pair "eigen;libeigen3-dev" "gsl;libgsl-dev" "doctest;doctest-dev")
  list(GET pair 0 key)
  list(GET pair 1 package)
  set(version "unknown")
  if(DPKG_QUERY)
    execute_process(COMMAND "${DPKG_QUERY}" -W "-f=\${Version}" "${package}" OUTPUT_VARIABLE out
                    RESULT_VARIABLE status ERROR_QUIET)
    if(status EQUAL 0 AND NOT out STREQUAL "")
      set(version "${out}")
    endif()
  endif()
  string(APPEND lines "${key}\t${package} ${version}\n")
endforeach()
string(APPEND lines "packages_from\tdpkg-query at build time\n")

file(WRITE "${OUT}.new" "${lines}")
file(COPY_FILE "${OUT}.new" "${OUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUT}.new")
