// Text for the workbook's own programs: the few operations every one of them needs.
#pragma once

#include <string>
#include <vector>

namespace support {

// Without the spaces, tabs, carriage returns and newlines at either end.
std::string trim(const std::string& s);

// The pieces between separators, empty ones included: split("a,,b", ',') is {"a", "", "b"},
// split("", ',') is {""}.
std::vector<std::string> split(const std::string& s, char separator);

}  // namespace support
