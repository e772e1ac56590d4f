#include "perception/service/private_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <sstream>

namespace alplan::perception::service {
namespace {

constexpr mode_t kPrivate = S_IRUSR | S_IWUSR;
constexpr mode_t kOthers = S_IRWXG | S_IRWXO;

std::string octal(mode_t mode) {
  std::ostringstream out;
  out << '0' << std::oct << (mode & 07777);
  return out.str();
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw PrivateFileError(path.string() + ": error: " + what + ": " + std::strerror(errno));
}

}  // namespace

void make_private_file(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, kPrivate);
  if (fd >= 0) {
    ::close(fd);
    return;
  }
  if (errno != EEXIST) fail(path, "cannot create the file");
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) fail(path, "cannot read the file's permissions");
  if ((info.st_mode & kOthers) != 0 && ::chmod(path.c_str(), info.st_mode & ~kOthers & 07777) != 0) {
    fail(path, "cannot take the permissions of others away (chmod 600)");
  }
}

int create_private_file(const std::filesystem::path& path, bool overwrite) {
  const int flags = O_WRONLY | O_CREAT | O_CLOEXEC | (overwrite ? O_TRUNC : O_EXCL);
  const int fd = ::open(path.c_str(), flags, kPrivate);
  if (fd < 0 && errno == EEXIST) {
    throw PrivateFileError(path.string() + ": error: the file exists; remove it or give --force to overwrite it");
  }
  if (fd < 0) fail(path, "cannot create the file");
  // An existing file keeps its mode through O_TRUNC: set it.
  if (::fchmod(fd, kPrivate) != 0) {
    ::close(fd);
    fail(path, "cannot make the file private (chmod 600)");
  }
  return fd;
}

void write_and_close(int fd, const std::string& text, const std::filesystem::path& path) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      ::close(fd);
      fail(path, "cannot write the file");
    }
    written += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) fail(path, "cannot write the file");
}

std::string private_file_problem(const std::filesystem::path& path, const std::string& what) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return {};
  if ((info.st_mode & kOthers) == 0) return {};
  const bool readable = (info.st_mode & (S_IRGRP | S_IROTH)) != 0;
  return path.string() + ": error: the " + what + " is " + (readable ? "readable" : "writable") +
         " by others (mode " + octal(info.st_mode) + "); run: chmod 600 " + path.string();
}

}  // namespace alplan::perception::service
