// Issue 33: an output file is in place only when complete; a failure names the file and its
// cause and never removes a path the program did not create.

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <stdexcept>
#include <string>

#include "base/binary_file.h"
#include "base/output_file.h"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

// A folder of its own, removed with everything in it when the test ends.
struct Folder {
  fs::path path;
  Folder() {
    std::string name = (fs::temp_directory_path() / "rtusim-output-XXXXXX").string();
    path = ::mkdtemp(name.data());
  }
  ~Folder() { fs::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
  size_t entries() const {
    return static_cast<size_t>(std::distance(fs::directory_iterator(path), {}));
  }
};

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeOld(const std::string& path) { std::ofstream(path) << "old"; }

}  // namespace

TEST_CASE("An output file appears only when committed", "[output_file]") {
  Folder folder;
  const std::string path = folder.file("out.csv");
  writeOld(path);
  {
    rtu::OutputFile file(path);
    file.stream() << "new";
    CHECK(contents(path) == "old");  // written beside it meanwhile
    CHECK(folder.entries() == 2);
    file.commit();
  }
  CHECK(contents(path) == "new");
  CHECK(folder.entries() == 1);
}

TEST_CASE("An output file not committed leaves the path as it was", "[output_file]") {
  Folder folder;
  const std::string path = folder.file("out.bin");
  writeOld(path);
  {
    rtu::OutputFile file(path);
    file.stream() << "partial";
  }
  CHECK(contents(path) == "old");
  CHECK(folder.entries() == 1);
  // A writer that throws before close (as an encoding error) leaves no file either.
  const std::string fresh = folder.file("fresh.bin");
  { rtu::WordFileWriter writer(fresh); }
  CHECK_FALSE(fs::exists(fresh));
  CHECK(folder.entries() == 1);
}

TEST_CASE("An output file replaces the file a link names and keeps its mode", "[output_file]") {
  Folder folder;
  const std::string target = folder.file("target.json"), link = folder.file("link.json");
  writeOld(target);
  ::chmod(target.c_str(), 0640);
  fs::create_symlink(target, link);
  rtu::writeTextFile(link, "new");
  CHECK(fs::is_symlink(link));
  CHECK(contents(target) == "new");
  CHECK((fs::status(target).permissions() & fs::perms::all) ==
        (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
}

TEST_CASE("An output through a link to a missing file creates that file", "[output_file]") {
  Folder folder;
  const std::string target = folder.file("made.txt"), link = folder.file("link.txt");
  fs::create_symlink("made.txt", link);  // relative to the link's folder
  rtu::writeTextFile(link, "new");
  CHECK(fs::is_symlink(link));
  CHECK(contents(target) == "new");
  CHECK(folder.entries() == 2);
}

TEST_CASE("A write error names the file and its cause and removes nothing", "[output_file]") {
  if (!fs::exists("/dev/full")) {
    WARN("no /dev/full: skipped");
    return;
  }
  Folder folder;
  const std::string link = folder.file("full.csv");
  fs::create_symlink("/dev/full", link);
  {
    rtu::OutputFile file(link);
    file.stream() << std::string(100000, 'x');
    CHECK_THROWS_WITH(file.commit(), Contains("cannot write '" + link + "'") &&
                                         Contains("No space left on device"));
  }
  CHECK(fs::is_symlink(link));
  CHECK(fs::is_character_file("/dev/full"));
  // A short write fails as well (at close, not while buffered).
  CHECK_THROWS_WITH(rtu::writeTextFile("/dev/full", "x"), Contains("No space left"));
  CHECK(fs::is_character_file("/dev/full"));
  CHECK_THROWS_WITH(rtu::writeWordFile(link, {1, 2, 3}), Contains(link));
  CHECK(fs::is_symlink(link));
}

TEST_CASE("An output file that cannot be created names the file and the cause", "[output_file]") {
  Folder folder;
  const std::string path = folder.file("missing/out.png");
  CHECK_THROWS_WITH(rtu::OutputFile(path), Contains("cannot create '" + path + "'") &&
                                               Contains("No such file or directory"));
}

namespace {

// A pid that no process has: a child's, once it has ended and been waited for.
pid_t endedPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

std::string hostOfThisMachine() {
  char name[256] = {};
  ::gethostname(name, sizeof name - 1);
  std::string host(name);
  for (char& c : host)
    if (c == '/' || c == '-') c = '_';
  return host;
}

}  // namespace

TEST_CASE("An output's temporary file names this host and process", "[output_file]") {
  Folder folder;
  rtu::OutputFile file(folder.file("frame.png"));
  const std::string name = fs::path(file.writePath()).filename().string();
  const std::string prefix =
      ".frame.part-" + hostOfThisMachine() + "-" + std::to_string(::getpid()) + "-";
  CHECK(name.rfind(prefix, 0) == 0);
  CHECK(name.size() == prefix.size() + 6 + 4);  // six random characters, ".png"
}

TEST_CASE("A temporary file left by an ended process is removed by the next output to its path\\, "
          "others stay",
          "[output_file]") {
  Folder folder;
  const std::string host = hostOfThisMachine();
  const std::string stale =
      folder.file(".out.part-" + host + "-" + std::to_string(endedPid()) + "-a1b2c3.csv");
  const std::string running =
      folder.file(".out.part-" + host + "-" + std::to_string(::getppid()) + "-d4e5f6.csv");
  const std::string otherHost =
      folder.file(".out.part-elsewhere-" + std::to_string(endedPid()) + "-g7h8i9.csv");
  const std::string otherOutput =
      folder.file(".other.part-" + host + "-" + std::to_string(endedPid()) + "-j1k2l3.csv");
  const std::string notOurs = folder.file(".out.part-notes.csv");
  for (const std::string& path : {stale, running, otherHost, otherOutput, notOurs}) writeOld(path);
  rtu::writeTextFile(folder.file("out.csv"), "new");
  CHECK_FALSE(fs::exists(stale));
  for (const std::string& path : {running, otherHost, otherOutput, notOurs})
    CHECK(contents(path) == "old");
}
