# The book's checks must be able to fail. Builds a one-chapter workbook that is broken on
# purpose, in every way the checks know, runs each check on it and requires that it fails and
# names the damage.
#   -DSNIPPETS=<exe> -DBOOK=<exe> -DPANDOC=<exe> -DWORK=<scratch folder>
get_filename_component(ROOT "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
set(tree "${WORK}/tree")
file(REMOVE_RECURSE "${WORK}")
file(COPY "${ROOT}/cmake/book/web/page.html" "${ROOT}/cmake/book/web/book.css" DESTINATION "${tree}/cmake/book/web")

file(WRITE "${tree}/README.md" "# A workbook broken on purpose\n")
# Every chapter is checked as a lesson; 5 and 6 are in an older layout that is not one (no
# Learning objectives, Errata instead of Checking [P]); there is no notation page, and the
# contents do not link one.
file(WRITE "${tree}/chapters/README.md" "| 1 | [Mini](01_mini/README.md) |\n| 2 | [Lesson](02_lesson/README.md) |\n"
     "| 5 | [Bare](05_bare/README.md) |\n| 6 | [Old](06_old/README.md) |\n")
file(WRITE "${tree}/chapters/05_bare/README.md"
     "# Chapter 5. Bare\n\n**Before you start.** Chapter 1.\n\n## Errata\n\nNone.\n\n## 2.1 After the errata\n")
file(WRITE "${tree}/chapters/06_old/README.md"
     "# Chapter 6. Old\n\nNo word on what to know first.\n\n## Exercises\n\nDo it somewhere.\n")
# A lesson with every heading, but Checking [P] before the exercises, seven objectives and no
# time, two predictions (one without a command) and no scene in Check your work.
file(WRITE "${tree}/chapters/02_lesson/README.md" [=[
# Chapter 2. Lesson

## Before you start

Chapter 1.

## Learning objectives

* one
* two
* three
* four
* five
* six
* seven

## Worked example

<details>
<summary>Predict: what does the scene show?</summary>

Run `build/solutions/scenes/mini_scene --alpha 1`. It shows a circle.
</details>

<details>
<summary>Predict: and now?</summary>

Nothing to run.
</details>

## Checking [P]

Fine.

## Exercises

In `exercises/mini.cpp`: `mini` (derivation).

## Check your work

Run the graders.

## Going further

More.
]=])
file(WRITE "${tree}/exercises/rigid/mini.hpp" [=[
// snippet: quoted
int mini(int x);
// end snippet
// snippet: never_quoted
int other(int x);
// end snippet
]=])
file(WRITE "${tree}/chapters/errata.md" [=[
| Chapter | Where in [P] | Printed | Corrected or qualified | Evidence |
|---|---|---|---|---|
| 9 | (1.1) | a | b | off by 1e-3 |
| 1 | (1.2) | a | b | it looked wrong |
| 1 | (1.3) | a | b |
]=])
file(WRITE "${tree}/tests/mini_test.cpp" "TEST_CASE(\"mini: doubles\") {}\n")
file(WRITE "${tree}/chapters/01_mini/mini_scene.cpp"
     "opts.real(\"alpha\", 1.0, \"a frequency\");\nfig << \"set xlabel '{/Symbol W}_1'\";\n"
     "fig << \"set ylabel '{/Symbol a}'\";\n")
# The runs CMake declares, the committed reports of two of them, and the test suite's report.
file(WRITE "${tree}/runs.txt" "mini_scene|01_mini|default\nmini_scene|01_mini|long|--long|yes\n")
file(WRITE "${tree}/figures/01_mini/mini_scene.json" [=[
{"run": {"name": "default", "args": []}, "scene": "mini_scene", "error": 1.5e-3, "run_time_s": 2e-6,
 "not_measured": -1, "not_finite": null, "fastest": "none", "gone": 3,
 "by_case": {"columns": ["order", "error"], "rows": [[1, 0.5], [2, 0.25]]}}
]=])
file(WRITE "${tree}/figures/01_mini/long/mini_scene.json" [=[
{"run": {"name": "long", "args": ["--long", "no"]}, "scene": "mini_scene", "error": 1e-9, "run_time_s": 2}
]=])
file(WRITE "${tree}/smoke/mini_scene.json" [=[
{"scene": "mini_scene", "error": 1e-2, "run_time_s": 1e-6, "not_measured": -1, "not_finite": null, "fastest": "rk4",
 "by_case": {"columns": ["order", "error"], "rows": [[1, 0.5], [2, 0.25]]}}
]=])
# A figure that writes a Greek letter with gnuplot's Symbol-font escape, and one in a font that
# has no such letter (or is not installed at all).
file(WRITE "${tree}/figures/01_mini/escape.svg"
     "<svg><g font-family=\"DejaVu Sans\"><text><tspan>{/Symbol W}_1</tspan></text></g></svg>\n")
file(WRITE "${tree}/figures/01_mini/symbol.svg"
     "<svg><g font-family=\"DejaVu Sans\"><text><tspan font-family=\"Symbol\">W</tspan>_1</text></g></svg>\n")
file(WRITE "${tree}/figures/01_mini/font.svg"
     "<svg><g font-family=\"No Such Font At All\"><text><tspan>Ω(t)</tspan></text></g></svg>\n")
file(WRITE "${tree}/chapters/01_mini/README.md" [=[
# Chapter 1. Mini

A chapter that does not say what to know first.

## 1.1 Code

<!-- snippet: quoted -->
```cpp
int mini(double x);
```
<!-- end snippet -->

<!-- snippet: vanished -->
```cpp
int vanished();
```
<!-- end snippet -->

It calls `renamed_function` from `exercises/rigid/gone.hpp`, graded by `nosuchtest:`.

```sh
build/solutions/scenes/mini_scene --alpha 1 --beta 2
build/solutions/scenes/lost_scene
```

The error is <!-- value: mini_scene.no_such_key run=default fmt=%.2g -->1e-3<!-- end value -->, the table
gives <!-- value: mini_scene.by_case[order=3].error run=default -->0.1<!-- end value -->, and a bad
format <!-- value: mini_scene.error run=default fmt=%q -->x<!-- end value -->; a good
one <!-- value: mini_scene.by_case[order=2].error run=default fmt=%.2f -->0.25<!-- end value -->.
A value of no run <!-- value: mini_scene.error fmt=%.1g -->0.002<!-- end value -->, of a run never
declared <!-- value: mini_scene.error run=quick -->0.002<!-- end value -->, of a run whose report was made with other
options <!-- value: mini_scene.error run=long fmt=%.0e -->1e-09<!-- end value -->, not
measured <!-- value: mini_scene.not_measured run=default -->-1<!-- end value -->, not
finite <!-- value: mini_scene.not_finite run=default -->nan<!-- end value -->, a word that says it is
missing <!-- value: mini_scene.fastest run=default -->none<!-- end value -->, stale
text <!-- value: mini_scene.error run=default fmt=%.2g -->0.002<!-- end value -->, and a key the scene no longer
reports <!-- value: mini_scene.gone run=default fmt=%d -->3<!-- end value -->.
A line that starts with a tag (GitHub shows it as raw HTML):
<!--exact-->2.5 is half of 5.

Math that pandoc cannot read: $\unknowncmd{x}$.

Numbers: an untagged 3.4e-15, a tagged <!--P-->0.2122 and an exact <!--exact-->$\sqrt{2}/2 = 0.7071$; a
hand value within its tolerance <!-- value: mini_scene.error run=default tol=0.01 -->1.5e-3<!-- end value -->
and one that drifted <!-- value: mini_scene.by_case[order=1].error run=default tol=1e-5 -->0.4999<!-- end value -->;
a tag of a kind that does not exist <!--guess-->1.234, a measurement by hand <!--once-->12.34 in a chapter, and
a tag <!--input:2-->that covers 2.5e-3 and then nothing.

As section 1.2 showed, and [section 1.2](#13-the-end) too.

* A list item, tagged <!--const-->2.2e-16,
* and the next item, not: 8.8888.

| Case | Error |
|---|---|
| one | 3.3333 |

![A figure that was never drawn.](../../figures/01_mini/none.svg)

See [the next chapter](../02_missing/README.md) and [section 9](#9-nowhere).

## 1.2 The end, without exercises

## Exercises

Do something, somewhere, and check it somehow.
]=])

# Its table of contents, read as the build reads the workbook's (cmake/contents.cmake).
include("${ROOT}/cmake/contents.cmake")
workbook_read_contents("${tree}" "${tree}/contents.json" _)

set(failures "")
# check(<name> <regex>... COMMAND <command...>): the command must fail and print every regex.
function(check name)
  cmake_parse_arguments(C "" "" "EXPECT;COMMAND" ${ARGN})
  execute_process(COMMAND ${C_COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(all "${out}${err}")
  if(rc EQUAL 0)
    set(failures "${failures}\n${name}: passed on the broken chapter:\n${all}" PARENT_SCOPE)
    return()
  endif()
  foreach(re IN LISTS C_EXPECT)
    if(NOT all MATCHES "${re}")
      set(failures "${failures}\n${name}: did not report /${re}/:\n${all}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(STATUS "${name}: fails as it should (exit ${rc})")
endfunction()

check("snippets --check"
  EXPECT "snippet 'quoted' differs" "no source defines snippet 'vanished'"
         "snippet 'never_quoted' is not quoted anywhere" "value 'mini_scene.error': fmt=%q"
         "value 'mini_scene.error': states no run"
  COMMAND "${SNIPPETS}" --check "${tree}")
check("snippets --check-names"
  EXPECT "`renamed_function` does not occur" "`exercises/rigid/gone.hpp` does not exist"
         "no grader's test name starts with 'nosuchtest:'" "mini_scene has no option --beta"
         "runs the scene 'lost_scene'"
  COMMAND "${SNIPPETS}" --check-names "${tree}")
check("snippets --check-numbers"
  EXPECT "01_mini/README.md:[0-9]+: 3.4e-15 looks measured" "'<!--guess-->' is no kind of number"
         "1.234 looks measured" "<!--once--> \\(measured once, by hand\\) belongs in the manuals"
         "the tag <!--input--> has 1 number\\(s\\) left" "'section 1.2' is not a link"
         "names section 1.2 but does not lead to its heading"
         "01_mini/README.md:[0-9]+: 8.8888 looks measured" "01_mini/README.md:[0-9]+: 3.3333 looks measured"
         "01_mini/README.md:[0-9]+: starts with a value marker or a number tag"
  COMMAND "${SNIPPETS}" --check-numbers "${tree}")
check("snippets --check-values"
  EXPECT "the hand value 0.4999 is 0.0001 from the run's 0.5 "
         "has no key 'no_such_key'" "has no row with order = 3" "has no run 'quick' \\(declared: default, long\\)"
         "comes from the run 'long' with --long no, but the run 'long' of mini_scene is declared with --long yes"
         "'mini_scene.not_measured' is -1 in the run 'default'" "'mini_scene.not_finite' is null"
         "'mini_scene.fastest' is \"none\"" "the text says '0.002', its committed report [^ ]+ says '0.0015'"
         "value 'mini_scene.gone': the scene as built no longer reports it"
  COMMAND "${SNIPPETS}" --check-values "${tree}" "${tree}/runs.txt" "${tree}/smoke")
check("book --check-structure"
  EXPECT "06_old/README.md: its first section is not '## Before you start'" "06_old/README.md: has no '## Check your work' section"
         "06_old/README.md: its Exercises do not say where to work" "06_old/README.md: has 0 <details> blocks"
         "05_bare/README.md: has no '## Exercises' section"
         "must name a chapter of the contents \\(1, 2, 5, 6\\), not '9'" "this one has none" "has 4 cells"
         "chapters/notation.md: missing" "chapters/README.md: does not link the notation page"
         "01_mini/README.md: does not link the notation page"
         "01_mini/README.md: has no '## Learning objectives' section" "01_mini/README.md: has 0 <details> blocks"
         "01_mini/README.md: its Exercises list no exercise marked '\\(derivation\\)'"
         "01_mini/README.md: its Exercises do not say where to work"
         "01_mini/README.md: its first section is not '## Before you start'"
         "02_lesson/README.md: '## Checking \\[P\\]' comes too early" "02_lesson/README.md: its Learning objectives have 7 bullets"
         "02_lesson/README.md: its Learning objectives have no line starting '\\*\\*Time:\\*\\*'"
         "02_lesson/README.md: has 2 <details> blocks" "02_lesson/README.md: 1 of its Predict: blocks name no command"
         "02_lesson/README.md: its Check your work does not use 'cmake/workbook check'"
         "02_lesson/README.md: its Check your work names no scene command"
         "02_lesson/README.md: has no '## Key points' section" "02_lesson/README.md: its Key points have 0 bullets"
         "02_lesson/README.md: '## Going further' comes after '## Checking \\[P\\]'"
         "02_lesson/README.md: its Checking \\[P\\] does not link checking.md"
         "02_lesson/README.md: the chapter has no checking.md"
  COMMAND "${BOOK}" --check-structure "${tree}" --contents "${tree}/contents.json")
check("book --render"
  EXPECT "has no key 'no_such_key'" "the figure figures/01_mini/none.svg does not exist"
         "broken link: ../02_missing/README.md" "names #9-nowhere" "Could not convert TeX math"
         "'mini_scene.not_measured' is -1 in the run 'default'" "has no run 'quick'"
         "comes from the run 'long' with --long no" "the hand value 0.4999 is 0.0001 from the run's 0.5"
         "01_mini/README.md:[0-9]+: starts with a value marker or a number tag"
  COMMAND "${BOOK}" --render "${tree}" --runs "${tree}/runs.txt" --out "${WORK}/book" --pandoc "${PANDOC}" --strict
          --contents "${tree}/contents.json")
check("book --check-figures"
  EXPECT "chapters/01_mini/mini_scene.cpp:2: gnuplot's [{]/Symbol [.][.][.][}] escape"
         "chapters/01_mini/mini_scene.cpp:3: gnuplot's" "escape.svg: its text has gnuplot's"
         "font.svg: its text uses U.3a9 and is in the font 'No Such Font At All', which is not installed"
         "symbol.svg: text in the font 'Symbol'"
  COMMAND "${BOOK}" --check-figures "${tree}" "${tree}/figures")

# And the one good value of the broken chapter is rendered as the report has it.
if(EXISTS "${WORK}/book/01_mini.html")
  file(READ "${WORK}/book/01_mini.html" html)
  if(NOT html MATCHES "from the committed report\">0\\.25</span>")
    set(failures "${failures}\nbook --render: the value by_case[order=2].error was not shown as 0.25")
  endif()
else()
  set(failures "${failures}\nbook --render: rendered no page for the broken chapter")
endif()

if(failures)
  message(FATAL_ERROR "The book's checks missed damage done on purpose:${failures}")
endif()
