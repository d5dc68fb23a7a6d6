# The book (cmake/book/, README.md there): the chapters rendered to HTML with their equations,
# code, figures and a run's numbers, and the checks that keep the prose true to the code and the
# numbers. One room:
#   tools/   the C++ tools: book_tool (render, the structure and figure checks) and snippets (the
#            code and the numbers quoted in the prose, the names it mentions)
#   web/     what a rendered page loads: its template, style, the motion viewer and the live driver
#   tests/   the browser tests and the checks' self-test
#   live/    the live scenes: a scene's own C++ compiled to WebAssembly for its page (live.cmake)
# Included by cmake/Workbook.cmake; workbook_book() and workbook_live() are called once, after every
# scene is declared and after workbook_main_job().
#
#   target book             render it again from the last run's reports (cmake/workbook run)
#   target update-snippets  rewrite the code and the numbers quoted in the prose's sources
include_guard(GLOBAL)
include("${CMAKE_CURRENT_LIST_DIR}/live/live.cmake")  # workbook_live_scene(), workbook_live()

function(workbook_book)
  get_property(figures GLOBAL PROPERTY WORKBOOK_FIGURES_DIR)
  set(root "${WORKBOOK_ROOT}")
  set(runs "${CMAKE_BINARY_DIR}/runs.txt")

  set(tools "${root}/cmake/book/tools")
  add_executable(snippets "${tools}/snippets.cpp" "${tools}/snippet_values.cpp" "${tools}/numbers.cpp"
                          "${tools}/names.cpp" "${tools}/markdown.cpp")
  # One program, a translation unit per job: render, check the structure, check the figures.
  add_executable(book_tool "${tools}/book.cpp" "${tools}/common.cpp" "${tools}/markdown.cpp"
                           "${tools}/render.cpp" "${tools}/live.cpp" "${tools}/structure.cpp"
                           "${tools}/figures.cpp")
  get_property(contents GLOBAL PROPERTY WORKBOOK_CONTENTS)
  foreach(t snippets book_tool)
    target_link_libraries(${t} PRIVATE nlohmann_json::nlohmann_json CLI11::CLI11 workbook_support)
    workbook_warnings(${t})
    target_compile_options(${t} PRIVATE -O1)  # tools: quick to build, fast enough to run
    set_target_properties(${t} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/tools")
  endforeach()

  # The test suite's book shows the committed reports and figures (what the repository says),
  # in its own folder: never the numbers of its light smoke runs, never over the run's book.
  set(test_book "${CMAKE_BINARY_DIR}/test/book")
  add_test(NAME "book: every code snippet in the prose matches its source"
           COMMAND snippets --check "${root}")
  add_test(NAME "book: the code the prose names exists"
           COMMAND snippets --check-names "${root}")
  add_test(NAME "book: every number that looks measured is a value marker or says what it is, every section named by number is a link"
           COMMAND snippets --check-numbers "${root}")
  add_test(NAME "book: every chapter is a lesson in the order the book teaches and every erratum gives numbers"
           COMMAND book_tool --check-structure "${root}" --contents "${contents}")
  add_test(NAME "book: every number in the prose is its run's committed value, and the scenes still report it"
           COMMAND snippets --check-values "${root}" "${runs}" "${CMAKE_BINARY_DIR}/smoke/reports")
  add_test(NAME "book: renders to HTML with MathML, its figures and no broken link"
           COMMAND book_tool --render "${root}" --runs "${runs}" --out "${test_book}" --pandoc "${PANDOC_EXECUTABLE}"
                   --strict --label "the committed reports (figures/)" --contents "${contents}")
  add_test(NAME "book: in a browser every image loads, the math is MathML, no link is broken, nothing is wider than the column"
           COMMAND bash "${root}/cmake/book/tests/browser_test.sh" "${test_book}" "${CMAKE_BINARY_DIR}/test/browser" "${root}/chapters")
  add_test(NAME "book: the browser checks fail on a book broken on purpose"
           COMMAND bash "${root}/cmake/book/tests/browser_selftest.sh" "${CMAKE_BINARY_DIR}/test/browser-selftest")
  add_test(NAME "book: the motion checks fail on a viewer broken on purpose"
           COMMAND python3 "${root}/cmake/book/tests/browser_motion.py" --selftest "${CMAKE_BINARY_DIR}/test/motion-selftest")
  add_test(NAME "book: the checks fail on a chapter broken on purpose"
           COMMAND ${CMAKE_COMMAND} -DSNIPPETS=$<TARGET_FILE:snippets> -DBOOK=$<TARGET_FILE:book_tool>
                   -DPANDOC=${PANDOC_EXECUTABLE} -DWORK=${CMAKE_BINARY_DIR}/test/book-selftest
                   -P "${root}/cmake/book/tests/selftest.cmake")
  # The committed figures, and those the scenes as built draw now (in the smoke runs).
  add_test(NAME "figures: Greek letters in UTF-8, in a font that has them"
           COMMAND book_tool --check-figures "${root}" "${root}/figures" "${CMAKE_BINARY_DIR}/smoke")
  set_tests_properties(
    "book: every code snippet in the prose matches its source"
    "book: the code the prose names exists"
    "book: every number that looks measured is a value marker or says what it is, every section named by number is a link"
    "book: every chapter is a lesson in the order the book teaches and every erratum gives numbers"
    "book: every number in the prose is its run's committed value, and the scenes still report it"
    "book: renders to HTML with MathML, its figures and no broken link"
    "book: in a browser every image loads, the math is MathML, no link is broken, nothing is wider than the column"
    "book: the browser checks fail on a book broken on purpose"
    "book: the motion checks fail on a viewer broken on purpose"
    "book: the checks fail on a chapter broken on purpose"
    "figures: Greek letters in UTF-8, in a font that has them"
    PROPERTIES LABELS book TIMEOUT 300)
  set_tests_properties("book: every number in the prose is its run's committed value, and the scenes still report it"
                       "figures: Greek letters in UTF-8, in a font that has them"
                       PROPERTIES FIXTURES_REQUIRED scene_reports)
  set_tests_properties("book: renders to HTML with MathML, its figures and no broken link"
                       PROPERTIES FIXTURES_SETUP book_html)
  # 73 pages, their screenshots and the motion viewers: 249 s beside the grading suite at a load of
  # 7, past 300 s at a higher one. The limit only stops a browser that hangs.
  set_tests_properties("book: in a browser every image loads, the math is MathML, no link is broken, nothing is wider than the column"
                       PROPERTIES FIXTURES_REQUIRED book_html SKIP_RETURN_CODE 77 TIMEOUT 900)
  set_tests_properties("book: the browser checks fail on a book broken on purpose"
                       "book: the motion checks fail on a viewer broken on purpose" PROPERTIES SKIP_RETURN_CODE 77)
  # Two browsers at once on two cores time out: one browser test at a time.
  set_tests_properties("book: in a browser every image loads, the math is MathML, no link is broken, nothing is wider than the column"
                       "book: the browser checks fail on a book broken on purpose"
                       "book: the motion checks fail on a viewer broken on purpose" PROPERTIES RESOURCE_LOCK browser)

  add_custom_target(update-snippets
    COMMAND snippets --update "${root}" "${runs}"
    COMMENT "Refreshing the code and the numbers quoted in the chapters (numbers: from the committed reports in figures/)")
  add_custom_target(book
    COMMAND book_tool --render "${root}" --runs "${runs}" --figures "${figures}"
            --out "${CMAKE_BINARY_DIR}/book" --pandoc "${PANDOC_EXECUTABLE}" --contents "${contents}"
            --label "the last cmake/workbook run on the ${WORKBOOK_IMPL} implementation"
    COMMENT "Rendering the book from the last run's reports into ${CMAKE_BINARY_DIR}/book")
endfunction()
