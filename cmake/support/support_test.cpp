// The support library's own tests: files, text, programs started without a shell, and gnuplot
// scripts filled (each way of filling one wrong planted, so that a script never reaches gnuplot
// half filled).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "support/file.hpp"
#include "support/process.hpp"
#include "support/script.hpp"
#include "support/text.hpp"

namespace {

support::RunOptions merged_options(const std::string& file = "") {
    support::RunOptions o;
    o.stdout_file = file;
    o.stderr_to_stdout = true;
    return o;
}

support::RunOptions within(double seconds) {
    support::RunOptions o;
    o.timeout = seconds;
    return o;
}

std::string scratch(const std::string& name) {
    return "/tmp/workbook_support_test_" + std::to_string(getpid()) + "_" + name;
}

}  // namespace

TEST_CASE("a file written is read back whole and a missing one reads as empty and not ok") {
    const std::string path = scratch("file");
    const std::string text = std::string("two\nlines\0and a zero byte", 26);
    REQUIRE(support::write_file(path, text));
    bool ok = false;
    CHECK(support::read_file(path, &ok) == text);
    CHECK(ok);
    std::remove(path.c_str());
    CHECK(support::read_file(path, &ok).empty());
    CHECK_FALSE(ok);
    CHECK_FALSE(support::write_file("/nonexistent-folder/x", "y"));
}

TEST_CASE("trim takes the blanks off both ends only and split keeps the empty pieces") {
    CHECK(support::trim(" \t a b \r\n") == "a b");
    CHECK(support::trim(" \n\t").empty());
    CHECK(support::split("a,,b", ',') == std::vector<std::string>{"a", "", "b"});
    CHECK(support::split("", ',') == std::vector<std::string>{""});
    CHECK(support::split("a\n", '\n') == std::vector<std::string>{"a", ""});
}

TEST_CASE("a program gets its arguments as they are: no shell reads them") {
    const std::string tricky = "a b; echo injected $HOME `id` 'q' \"d\" > /tmp/x";
    const support::Result r = support::run({"printf", "%s", tricky});
    CHECK(r.status == 0);
    CHECK(r.out == tricky);
    CHECK(r.err.empty());
}

TEST_CASE("stdout and stderr are captured apart and the exit status and a signal are reported") {
    const support::Result r = support::run({"sh", "-c", "echo out; echo err >&2; exit 3"});
    CHECK(r.status == 3);
    CHECK(r.out == "out\n");
    CHECK(r.err == "err\n");
    CHECK_FALSE(r.timed_out);
    const support::Result merged = support::run({"sh", "-c", "echo out; echo err >&2"}, merged_options());
    CHECK(merged.out == "out\nerr\n");
    CHECK(support::run({"sh", "-c", "kill -TERM $$"}).status == 128 + 15);
    CHECK(support::run({"cat"}).out.empty());  // stdin is /dev/null: it ends at once
}

TEST_CASE("a program that does not exist is reported and not run") {
    const support::Result r = support::run({"/nonexistent/program", "x"});
    CHECK(r.status == -1);
    CHECK(r.error.find("/nonexistent/program") != std::string::npos);
    std::string error;
    CHECK(support::spawn({"/nonexistent/program"}, {}, &error) == -1);
    CHECK_FALSE(error.empty());
}

TEST_CASE("a program past its timeout is killed even when it closed its streams") {
    const support::Result r = support::run({"sleep", "5"}, within(0.2));
    CHECK(r.timed_out);
    CHECK(r.status == 128 + 9);
    const support::Result quiet = support::run({"sh", "-c", "exec >&- 2>&-; sleep 5"}, within(0.2));
    CHECK(quiet.timed_out);
    const support::Result quick = support::run({"true"}, within(5));
    CHECK_FALSE(quick.timed_out);
    CHECK(quick.status == 0);
}

TEST_CASE("a spawned program writes its output to a file and is waited for") {
    const std::string out = scratch("spawn_out");
    const pid_t pid = support::spawn({"sh", "-c", "sleep 0.3; echo done; echo oops >&2"}, merged_options(out));
    REQUIRE(pid > 0);
    CHECK(support::wait(pid, 0) == -1);  // still running
    CHECK(support::wait(pid, 10) == 0);
    CHECK(support::read_file(out) == "done\noops\n");
    std::remove(out.c_str());
}

TEST_CASE("gnuplot scripts: a placeholder is replaced by its value, gnuplot's own braces and brackets stay") {
    const support::Script s{"t.gp", "set title '@title@'\nset xrange [0:*]\nset ylabel '{/:Bold a}'\nplot @plot@\n"};
    CHECK(support::filled(s, {{"plot", "'-' with lines"}, {"title", "n = 3"}}) ==
          "set title 'n = 3'\nset xrange [0:*]\nset ylabel '{/:Bold a}'\nplot '-' with lines\n");
}

TEST_CASE("gnuplot scripts: a value is inserted as it is, never scanned for placeholders again") {
    const support::Script s{"t.gp", "@a@ @b@"};
    CHECK(support::filled(s, {{"a", "@b@"}, {"b", "x"}}) == "@b@ x");
}

TEST_CASE("gnuplot scripts: an '@' that opens no placeholder (a gnuplot macro, an address) stays") {
    const support::Script s{"t.gp", "@macro plot\nmail a@b.c\n@1@ @@\n"};
    CHECK(support::filled(s) == "@macro plot\nmail a@b.c\n@1@ @@\n");
}

TEST_CASE("gnuplot scripts: a comment line may name a placeholder: it stays as it is, and needs no value") {
    const support::Script s{"t.gp", "# @curves@: one per method\n  # @x@\nplot @curves@\n#"};
    CHECK(support::filled(s, {{"curves", "'-'"}}) == "# @curves@: one per method\n  # @x@\nplot '-'\n#");
}

TEST_CASE("gnuplot scripts: a placeholder left without a value throws, naming the script and the placeholder") {
    const support::Script s{"planted.gp", "set title '@title@'\nset xlabel '@xlabel@'\n"};
    CHECK_THROWS_WITH_AS(support::filled(s, {{"title", "x"}}), doctest::Contains("planted.gp"), std::logic_error);
    CHECK_THROWS_WITH_AS(support::filled(s, {{"title", "x"}}), doctest::Contains("@xlabel@"), std::logic_error);
}

TEST_CASE("gnuplot scripts: a value for a placeholder the script does not have throws (a misspelt name)") {
    const support::Script s{"planted.gp", "set title '@title@'\n"};
    CHECK_THROWS_WITH_AS(support::filled(s, {{"title", "x"}, {"titel", "y"}}), doctest::Contains("@titel@"),
                         std::logic_error);
}

TEST_CASE("gnuplot scripts: a string literal doubles its quotes") {
    CHECK(support::gnuplot_quoted("it's") == "'it''s'");
    CHECK(support::gnuplot_quoted("") == "''");
}

TEST_CASE("gnuplot scripts: a clause is filled once per item and joined on one line, its comments dropped") {
    const support::Script clause{"curve.gp", "# one curve per method\n'-' with lines ls @ls@ title '@title@'\n"};
    CHECK(support::joined(clause, {{{"ls", "1"}, {"title", "a"}}, {{"ls", "2"}, {"title", "b"}}}) ==
          "'-' with lines ls 1 title 'a', '-' with lines ls 2 title 'b'");
    CHECK(support::joined(clause, {{{"ls", "1"}, {"title", "a"}}}, " | ") == "'-' with lines ls 1 title 'a'");
    CHECK(support::joined(clause, {}).empty());
    CHECK_THROWS_WITH_AS(support::joined(clause, {{{"ls", "1"}}}), doctest::Contains("@title@"), std::logic_error);
    const support::Script two{"planted.gp", "'-' with lines\n'-' with points\n"};
    CHECK_THROWS_WITH_AS(support::joined(two, {{}}), doctest::Contains("one line"), std::logic_error);
}
