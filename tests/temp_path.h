#pragma once
// A file path in the temporary directory, unique to this test process, removed when the test ends.

#include <unistd.h>

#include <filesystem>
#include <string>

namespace rtu {

class TempPath {
 public:
  explicit TempPath(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("rtusim-test-" + std::to_string(getpid()) + "-" + name)) {}
  ~TempPath() { std::filesystem::remove(path_); }
  TempPath(const TempPath&) = delete;
  TempPath& operator=(const TempPath&) = delete;
  std::string str() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace rtu
