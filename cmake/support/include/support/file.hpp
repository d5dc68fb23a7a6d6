// Files for the workbook's own programs (the grading run, the stub gate, the mutation gate, the
// scene kit): one way to read a whole file and one way to write one.
#pragma once

#include <string>

namespace support {

// The file's bytes; empty when it cannot be read (*ok, when given, tells which).
std::string read_file(const std::string& path, bool* ok = nullptr);

// Writes through a temporary file beside it and a rename, so that a reader never sees half of
// it (several processes may share a folder). False when it could not.
bool write_file(const std::string& path, const std::string& text);

}  // namespace support
