# Where a grading run's results come from: grading/provenance.txt, written at every build of the
# target `grading` (tests/grading/CMakeLists.txt runs this script; the file is rewritten only when a
# line changes). The grading run copies it into every results/<student>.json and run.json
# (provenance.cpp), with the hashes of the graders and of the limits it computes itself.
#
#   cmake -DROOT=<workbook> -DOUT=<provenance.txt> -DCOMPILER_ID=GNU -DCOMPILER_VERSION=12.2.0
#         -DCOMPILER=/usr/bin/c++ -P provenance.cmake
#
# The compiler is CMake's, as the build uses it (CMAKE_CXX_COMPILER_ID and _VERSION). The package
# versions are Debian's, asked of dpkg-query when the build runs ("unknown" where there is no dpkg
# or no such package, e.g. a library built by hand). The commit is `git rev-parse HEAD` of the
# workbook when the build runs ("unknown" outside git), and "modified" says whether tracked files
# differ from it (then the commit alone does not say what graded).
set(lines "# Generated at build time by tests/grading/provenance.cmake. Do not edit.\n")
string(APPEND lines "compiler\t${COMPILER_ID} ${COMPILER_VERSION}\n")
string(APPEND lines "compiler_path\t${COMPILER}\n")

set(commit "unknown")
set(modified "unknown")
find_program(GIT git)
if(GIT)
  execute_process(COMMAND "${GIT}" -C "${ROOT}" rev-parse HEAD OUTPUT_VARIABLE out RESULT_VARIABLE status
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
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
