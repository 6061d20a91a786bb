#pragma once
// Reads and writes of little-endian 32-bit words, shared by every binary format: whole files, or
// streamed in chunks of whole records so a large buffer needs no second copy in memory.

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "base/output_file.h"

namespace rtu {

// Streams a file of fixed-size records. Throws std::runtime_error naming `path` when it cannot be
// read or its size is not a multiple of `recordBytes` (what = the kind of file, for the message).
class RecordFileReader {
 public:
  RecordFileReader(const std::string& path, size_t recordBytes, const std::string& what);

  size_t records() const { return records_; }
  // The next chunk of whole records; `count` is 0 at the end of the file.
  const uint32_t* next(size_t& count);

 private:
  std::ifstream in_;
  std::string path_, what_;
  size_t recordWords_ = 0, records_ = 0, recordsLeft_ = 0;
  std::vector<uint32_t> chunk_;
};

// Writes words through a fixed buffer into an OutputFile; close() writes the rest and puts the file
// in place, or reports the error naming `path` (a writer destroyed without it, as when encoding
// throws, leaves the path as it was).
class WordFileWriter {
 public:
  explicit WordFileWriter(const std::string& path);

  // Space for `words` more words (at most kChunkWords), valid until the next call.
  uint32_t* append(size_t words);
  void close();

  static constexpr size_t kChunkWords = 1 << 18;  // 1 MiB

 private:
  void flush();

  OutputFile out_;
  std::vector<uint32_t> chunk_;
  size_t used_ = 0;
};

constexpr uint64_t kMaxImageWords = uint64_t{1} << 32;

// A whole file of 32-bit words, at most kMaxImageWords, read after the checks of RecordFileReader.
std::vector<uint32_t> readWordFile(const std::string& path, size_t recordBytes,
                                   const std::string& what);
void writeWordFile(const std::string& path, const std::vector<uint32_t>& words);

}  // namespace rtu
