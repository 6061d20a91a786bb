#pragma once
// Every output file is written through an OutputFile: into a temporary file beside it, every
// write checked, and renamed into place only by commit(), so a file at the output's path is
// always complete. A failure names the file and its cause, and never removes a path the program
// did not create: a symbolic link is followed (the file it names is replaced, the link kept), and
// a path that is not a regular file (a device such as /dev/full, a pipe, /dev/stdout) is written
// in place. The temporary file's name and its removal after a signal or a kill are
// temporary_files.h's.

#include <iosfwd>
#include <memory>
#include <string>

namespace rtu {

class TemporaryRegistration;

class OutputFile {
 public:
  // Throws std::runtime_error naming `path` when the file cannot be created.
  explicit OutputFile(const std::string& path);
  // Without commit(): removes the temporary file (the output's path is left as it was).
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  const std::string& path() const { return path_; }
  // What is written: buffered, its errors kept for commit().
  std::ostream& stream();
  // The file a library that opens files by name writes instead (OpenImageIO, the FST writer),
  // which must have closed it before commit(); the stream is not used then.
  const std::string& writePath() const { return writePath_; }
  // Flushes and closes, then renames the temporary file to path(). Throws std::runtime_error
  // "cannot write 'path': cause" for the first failed write, flush, close or rename.
  void commit();
  // Throws commit()'s error for a write that failed so far, when there was one (a library's
  // failure may come from it); else returns.
  void throwIfFailed();
  // Throws that error with `cause` (a library's own status); the file is never renamed.
  [[noreturn]] void fail(const std::string& cause) const;

 private:
  class Buffer;

  std::string path_, target_, writePath_;  // target_: path_ with links followed
  bool inPlace_ = false, committed_ = false;
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<std::ostream> stream_;
  std::unique_ptr<TemporaryRegistration> registration_;  // removed on SIGINT, SIGTERM, SIGHUP
};

// Writes `text` to `path` through an OutputFile.
void writeTextFile(const std::string& path, const std::string& text);

// Flushes standard output; throws std::runtime_error when any write to it failed (as `rtusim
// config --dump > /dev/full`), with the cause when the last flush tells it (stdio keeps only
// that a write failed).
void checkStandardOutput();

}  // namespace rtu
