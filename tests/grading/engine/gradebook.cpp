// The class's scores in the CSV layouts two learning management systems import as they are:
// canvas.csv (Canvas: Grades, Import) and moodle.csv (Moodle: Grades, Import, CSV file). One
// row per submission, its folder name as the student's login, and the total score in one
// column named after the assignment. class.csv keeps every exercise; these keep what the LMS
// needs and nothing else.
#include <algorithm>

#include "grading.hpp"

namespace grading {

namespace {

std::string field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    return "\"" + replace_all(s, "\"", "\"\"") + "\"";
}

double points_possible(const std::vector<SubmissionResult>& results) {
    double most = 0;
    for (const auto& r : results) most = std::max(most, r.max_score);
    return most;
}

}  // namespace

// Canvas's own gradebook export, cut down: the five student columns in the order Canvas
// writes them (Student, ID, SIS User ID, SIS Login ID, Section), a "Points Possible" row,
// then the assignment. Canvas finds each student by the SIS Login ID (the folder name here)
// and makes a new assignment of a column it does not know.
std::string canvas_csv(const std::vector<SubmissionResult>& results, const std::string& assignment) {
    std::string out = "Student,ID,SIS User ID,SIS Login ID,Section," + field(assignment) + "\n";
    out += "Points Possible,,,,," + format_number(points_possible(results)) + "\n";
    for (const auto& r : results)
        out += field(r.student) + ",,," + field(r.student) + ",," + format_number(r.score) + "\n";
    return out;
}

// Moodle maps the columns when it imports: "Username" to the user field username, and the
// assignment's column to a grade item (or a new one).
std::string moodle_csv(const std::vector<SubmissionResult>& results, const std::string& assignment) {
    std::string out = "Username," + field(assignment) + "\n";
    for (const auto& r : results) out += field(r.student) + "," + format_number(r.score) + "\n";
    return out;
}

}  // namespace grading
