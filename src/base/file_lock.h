#pragma once
// An exclusive lock (flock) on a lock file, held until destroyed, for files that one process at a
// time may write (a sweep's rows). The lock file holds the holder's pid and host, so a refusal
// says who holds it; flock works across hosts on NFS (Linux emulates it with POSIX locks), where
// a Slurm array's sweeps share their files. The file is left in place: removing it would let a
// second process lock a new file while a third holds the old one.

#include <string>

namespace rtu {

class FileLock {
 public:
  // Takes the lock on `path` (created if missing) without waiting. Throws std::runtime_error
  // "`what` is in use by process PID on host HOST (lock file 'path')" when another holds it.
  FileLock(const std::string& path, const std::string& what);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace rtu
