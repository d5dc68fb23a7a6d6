// The replay's state: the record (read from the file WORKBOOK_RECORD names, at the start of the
// test case), the position in it, and the first problem found (see replay.hpp).
#include "replay.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <new>
#include <sstream>

#include "listener.hpp"
#include "rigid/todo.hpp"

namespace workbook_replay::replay {

namespace {

constexpr std::size_t max_record = std::size_t(256) << 20;

struct State {
    std::string data;
    std::size_t at = 0;
    std::uint32_t calls = 0;
    bool loaded = false;
    std::string problem;
};

State& state() {
    static State s;
    return s;
}

void load() {
    State& s = state();
    s = State{};
    s.loaded = true;
    const char* path = std::getenv("WORKBOOK_RECORD");
    if (!path) {
        s.problem = "no record to replay (WORKBOOK_RECORD is not set)";
        return;
    }
    std::ifstream in(path, std::ios::binary);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    s.data = buffer.str();
    const std::string m = magic;
    if (s.data.size() > max_record)
        s.problem = "the record is larger than " + std::to_string(max_record >> 20) + " MiB";
    else if (s.data.compare(0, m.size(), m) != 0)
        s.problem = "the submission's process left no record (it ended before the test began, or wrote over it)";
    s.at = m.size();
}

// Loads the record when the test case starts: exactly one test case runs per replay process.
struct Loader : checks::Listener {
    explicit Loader(const doctest::ContextOptions&) {}
    void test_case_start(const doctest::TestCaseData&) override { load(); }
};

REGISTER_LISTENER("workbook_replay", 0, Loader);

// An exception of a kind the replay does not know: not a std::exception, as recorded.
struct unknown_exception {};
struct replayed_exception : std::exception {
    explicit replayed_exception(std::string w) : what_(std::move(w)) {}
    const char* what() const noexcept override { return what_.c_str(); }
    std::string what_;
};

}  // namespace

void fail(const std::string& why) {
    State& s = state();
    if (s.problem.empty()) s.problem = why;
    throw abort_replay{};
}

bool failed() {
    State& s = state();
    if (!s.loaded) load();
    return !s.problem.empty();
}

Cursor cursor() { return {&state().data, &state().at}; }

int next_tag() {
    State& s = state();
    if (s.at >= s.data.size()) return -1;
    return static_cast<unsigned char>(s.data[s.at++]);
}

std::uint32_t call_number() { return state().calls + 1; }

void expect_head(Tag tag, std::uint32_t id, std::uint64_t hash, const std::string& what) {
    State& s = state();
    ++s.calls;
    const int got = next_tag();
    if (got < 0)
        fail(what +
             ": the record ends before this call (the submission's process ended there: exit, a crash or "
             "the time limit)");
    if (got != tag) fail(what + ": the record has another event here; the grader and the record disagree");
    std::uint32_t recorded_id = 0;
    std::uint64_t recorded_hash = 0;
    try {
        auto r = reader();
        recorded_id = r.u32();
        recorded_hash = r.u64();
    } catch (const bad_record& e) {
        fail(what + ": " + e.what());
    }
    if (recorded_id != id) {
        std::string other = tag == tag_call && recorded_id < api_count ? api_names[recorded_id] : "another function";
        fail(what + ": the record has a call of " + other + " here");
    }
    if (recorded_hash != hash) fail(what + ": the grader's inputs differ from the recorded ones");
}

void throw_recorded() {
    Kind kind;
    std::string what, extra;
    try {
        auto r = reader();
        unsigned char k = 0;
        r.raw(&k, 1);
        kind = static_cast<Kind>(k);
        what = r.string();
        extra = r.string();
    } catch (const bad_record& e) {
        fail(std::string("a recorded exception is malformed: ") + e.what());
    }
    switch (kind) {
        case k_not_implemented:
            throw rigid::not_implemented(extra);
        case k_invalid_argument:
            throw std::invalid_argument(what);
        case k_domain_error:
            throw std::domain_error(what);
        case k_length_error:
            throw std::length_error(what);
        case k_out_of_range:
            throw std::out_of_range(what);
        case k_logic_error:
            throw std::logic_error(what);
        case k_range_error:
            throw std::range_error(what);
        case k_overflow_error:
            throw std::overflow_error(what);
        case k_underflow_error:
            throw std::underflow_error(what);
        case k_runtime_error:
            throw std::runtime_error(what);
        case k_bad_alloc:
            throw std::bad_alloc();
        case k_exception:
            throw replayed_exception(what);
        case k_unknown:
            throw unknown_exception{};
    }
    fail("a recorded exception is of an unknown kind");
}

}  // namespace workbook_replay::replay

// Asked by the verdict reporter (tests/main.cpp) when the test case ends: empty when the record
// was replayed to its end, else why the test cannot pass.
extern "C" const char* workbook_replay_verdict() {
    using namespace workbook_replay;
    using namespace workbook_replay::replay;
    static std::string answer;
    State& s = state();
    if (!s.loaded) load();
    if (s.problem.empty()) {
        const int tag = next_tag();
        if (tag < 0)
            s.problem =
                "the record ends before the test case did (the submission's process ended early: exit, a "
                "crash or the time limit)";
        else if (tag != tag_end)
            s.problem = "the record holds calls the grader did not make (after call " + std::to_string(s.calls) + ")";
        else if (s.at != s.data.size())
            s.problem = "the record goes on after the end of the test case";
    }
    answer = s.problem;
    return answer.c_str();
}
