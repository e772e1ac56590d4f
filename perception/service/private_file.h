// Files that hold secrets or seniors' data (the tokens file, the readings
// database and its WAL) are for the service's own user only: created mode
// 0600, and a tokens file that others may read is refused, since anyone who
// reads a token can post readings in that wristband's name.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace alplan::perception::service {

class PrivateFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Creates `path` empty with mode 0600 when it does not exist; when it does,
// takes group and other permissions away (chmod 600). Throws
// PrivateFileError naming the file when it can do neither.
void make_private_file(const std::filesystem::path& path);

// Opens `path` for writing with mode 0600, refusing an existing file unless
// `overwrite` (then truncated and made 0600). Returns the descriptor; throws
// PrivateFileError naming the file and what to do.
int create_private_file(const std::filesystem::path& path, bool overwrite);

// Writes all of `text` to the descriptor and closes it; throws
// PrivateFileError naming `path` on failure.
void write_and_close(int fd, const std::string& text, const std::filesystem::path& path);

// Empty when `path` is missing (the reader reports that) or only its owner
// may read or write it; otherwise what is wrong and the fix:
// "tokens.txt: error: the tokens file is readable by others (mode 0644); run: chmod 600 tokens.txt".
std::string private_file_problem(const std::filesystem::path& path, const std::string& what);

}  // namespace alplan::perception::service
