#pragma once
// The temporary files output files are written to (output_file.h), named so that they are
// recognisably this program's and whose: ".frame.part-HOST-PID-XXXXXX.png" beside "frame.png".
// A process ended by SIGINT, SIGTERM or SIGHUP removes its own before it ends; one killed by a
// signal that cannot be caught (SIGKILL, a crash) leaves them, and the next output to the same
// path removes those of processes of this host that are no longer running.

#include <filesystem>
#include <string>

namespace rtu {

// The pattern of a temporary file beside `target`, for mkostemps: its last six characters before
// the extension are the X's.
std::string temporaryPattern(const std::filesystem::path& target);

// Removes the temporary files beside `target` of processes of this host that no longer run.
void removeStaleTemporaries(const std::filesystem::path& target);

// While registered, `path` is removed should the process be ended by SIGINT, SIGTERM or SIGHUP
// (the handler is installed on first use, for signals whose action is still the default; it
// removes the files, then ends the process by the signal's default action). At most
// kMaxTemporaries at once; more are not registered (left to the next run's clean-up).
class TemporaryRegistration {
 public:
  static constexpr int kMaxTemporaries = 64;

  explicit TemporaryRegistration(const std::string& path);
  ~TemporaryRegistration();
  TemporaryRegistration(const TemporaryRegistration&) = delete;
  TemporaryRegistration& operator=(const TemporaryRegistration&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace rtu
