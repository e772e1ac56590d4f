// read_file hands the parser the whole file or fails loudly: a file cut
// short by a refused allocation would parse into a wrong error ("found the
// end of the file") or, worse, into a different task.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>
#include <vector>

#include "pddl_parser/parser.h"
#include "planner/address_space.h"

namespace {

std::string temporary_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()))).string();
}

void write_file(const std::string& path, const std::string& contents) {
  std::ofstream out(path, std::ios::binary);
  out << contents;
}

}  // namespace

TEST_CASE("read_file returns every byte of a file larger than its read chunk") {
  std::string contents;
  for (int i = 0; contents.size() < 200'001; ++i) contents += "(at r" + std::to_string(i) + " room)\n";
  contents += '\0';  // bytes the parser will refuse must still arrive
  const std::string path = temporary_path("alplan-read-file");
  write_file(path, contents);
  std::string read;
  std::vector<alplan::pddl::Diagnostic> diagnostics;
  CHECK(alplan::pddl::read_file(path, read, diagnostics));
  CHECK(diagnostics.empty());
  CHECK(read == contents);
  std::filesystem::remove(path);
}

TEST_CASE("read_file names a file it cannot open") {
  std::string read = "untouched";
  std::vector<alplan::pddl::Diagnostic> diagnostics;
  CHECK_FALSE(alplan::pddl::read_file("/nonexistent/alplan/domain.pddl", read, diagnostics));
  REQUIRE(diagnostics.size() == 1);
  CHECK(diagnostics[0].file == "/nonexistent/alplan/domain.pddl");
  CHECK(diagnostics[0].message == "cannot open the file: No such file or directory");
  // No place in the file: no "0:0" for a reader to look for.
  CHECK(diagnostics[0].to_string() ==
        "/nonexistent/alplan/domain.pddl: error: cannot open the file: No such file or directory");
  CHECK(read == "untouched");
}

TEST_CASE("read_file says a directory is one") {
  std::string read;
  std::vector<alplan::pddl::Diagnostic> diagnostics;
  CHECK_FALSE(alplan::pddl::read_file(std::filesystem::temp_directory_path().string(), read, diagnostics));
  REQUIRE(diagnostics.size() == 1);
  CHECK(diagnostics[0].message == "cannot open the file: it is a directory");
}

// Copying through `out << in.rdbuf()` swallowed the bad_alloc and returned a
// truncated file as if it were whole; `alplan plan --memory-limit` then
// reported a syntax error instead of exit 11 (a CI run caught it).
TEST_CASE("read_file under an exhausted address space throws, it does not truncate") {
#if defined(__SANITIZE_ADDRESS__)
  WARN("RLIMIT_AS cannot be used under AddressSanitizer");
  return;
#endif
  const std::string path = temporary_path("alplan-read-file-large");
  write_file(path, std::string(std::size_t{64} << 20, 'x'));
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    const std::size_t limit = alplan::address_space_bytes() + (std::size_t{16} << 20);
    const rlimit bound{limit, limit};
    if (::setrlimit(RLIMIT_AS, &bound) != 0) ::_exit(4);
    std::string read;
    std::vector<alplan::pddl::Diagnostic> diagnostics;
    try {
      const bool ok = alplan::pddl::read_file(path, read, diagnostics);
      ::_exit(ok ? 1 : 2);
    } catch (const std::bad_alloc&) {
      ::_exit(0);
    }
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  std::filesystem::remove(path);
  REQUIRE(WIFEXITED(status));
  // 1: a partial file came back as a success; 2: reported as unreadable.
  CHECK(WEXITSTATUS(status) == 0);
}
