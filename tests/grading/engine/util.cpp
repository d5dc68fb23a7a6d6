// Text and file helpers for the grading run.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "grading.hpp"

namespace grading {

namespace fs = std::filesystem;

bool starts_with(const std::string& s, const std::string& prefix) {
    return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

bool ends_with(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
    if (from.empty()) return s;
    for (std::size_t p = 0; (p = s.find(from, p)) != std::string::npos; p += to.size()) s.replace(p, from.size(), to);
    return s;
}

std::string json_text(const nlohmann::ordered_json& j) {
    // Invalid UTF-8 in a student's output becomes U+FFFD rather than an exception.
    return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

double json_number(double x) { return std::round(x * 1e4) / 1e4; }

std::string format_number(double x) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.4f", std::round(x * 1e4) / 1e4);
    std::string s = buffer;
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    if (s == "-0") s = "0";
    return s;
}

std::string first_lines(const std::string& s, std::size_t max_chars) {
    if (s.size() <= max_chars) return s;
    std::size_t cut = max_chars;
    while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
    return s.substr(0, cut) + "\n[... " + std::to_string(s.size() - cut) + " more bytes not shown]";
}

std::uint64_t hash(const std::string& data, std::uint64_t seed) {
    std::uint64_t h = seed;
    for (const char c : data) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ULL;
    }
    // Fold in the length too, so that concatenations of different pieces do not collide.
    for (std::size_t n = data.size(), k = 0; k < 8; ++k, n >>= 8) {
        h ^= n & 0xFF;
        h *= 0x100000001b3ULL;
    }
    return h;
}

std::string hex(std::uint64_t x) {
    char buffer[20];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(x));
    return buffer;
}

// The folder helpers: std::filesystem with error codes (the grading run reports a failure, it
// does not throw), never following a symbolic link (a submission may plant one).
bool make_dirs(const std::string& path) {
    if (path.empty()) return false;
    std::error_code ec;
    fs::create_directories(path, ec);
    return is_directory(path);
}

void remove_tree(const std::string& path) {
    std::error_code ec;
    fs::remove_all(path, ec);  // removes a link, not what it points to
}

bool is_directory(const std::string& path) {
    std::error_code ec;
    return fs::is_directory(fs::symlink_status(path, ec));
}

std::vector<std::string> list_dir(const std::string& path) {
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec))
        names.push_back(it->path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Splits a command line the way a POSIX shell would (quotes and backslashes; no expansion).
std::vector<std::string> shell_split(const std::string& command) {
    std::vector<std::string> words;
    std::string word;
    bool in_word = false;
    for (std::size_t i = 0; i < command.size(); ++i) {
        const char c = command[i];
        if (c == ' ' || c == '\t' || c == '\n') {
            if (in_word) words.push_back(word), word.clear(), in_word = false;
        } else if (c == '\\' && i + 1 < command.size()) {
            word += command[++i], in_word = true;
        } else if (c == '\'') {
            in_word = true;
            for (++i; i < command.size() && command[i] != '\''; ++i) word += command[i];
        } else if (c == '"') {
            in_word = true;
            for (++i; i < command.size() && command[i] != '"'; ++i) {
                if (command[i] == '\\' && i + 1 < command.size() &&
                    std::string("\"\\$`").find(command[i + 1]) != std::string::npos)
                    ++i;
                word += command[i];
            }
        } else {
            word += c, in_word = true;
        }
    }
    if (in_word) words.push_back(word);
    return words;
}

}  // namespace grading
