#include "base/binary_file.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "base/input_file.h"
#include "base/work_phase.h"

namespace rtu {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "file formats assume a little-endian host");

namespace {
constexpr size_t kReadChunkBytes = size_t{1} << 20;
}

RecordFileReader::RecordFileReader(const std::string& path, size_t recordBytes,
                                   const std::string& what)
    : path_(path), what_(what) {
  uint64_t size = 0;
  in_ = openInputFile(path, what, size);
  if (size % recordBytes != 0)
    throw std::runtime_error(what + " '" + path + "' has " + std::to_string(size) +
                             " bytes, not a multiple of its " + std::to_string(recordBytes) +
                             "-byte records");
  recordWords_ = recordBytes / sizeof(uint32_t);
  records_ = recordsLeft_ = static_cast<size_t>(size) / recordBytes;
  chunk_.resize(std::max<size_t>(1, kReadChunkBytes / recordBytes) * recordWords_);
}

const uint32_t* RecordFileReader::next(size_t& count) {
  count = std::min(recordsLeft_, chunk_.size() / recordWords_);
  if (count == 0) return nullptr;
  const auto bytes = static_cast<std::streamsize>(count * recordWords_ * sizeof(uint32_t));
  if (!in_.read(reinterpret_cast<char*>(chunk_.data()), bytes))
    throw std::runtime_error("cannot read " + what_ + " '" + path_ + "'");
  recordsLeft_ -= count;
  return chunk_.data();
}

WordFileWriter::WordFileWriter(const std::string& path) : out_(path), chunk_(kChunkWords) {}

uint32_t* WordFileWriter::append(size_t words) {
  if (used_ + words > chunk_.size()) flush();
  uint32_t* space = chunk_.data() + used_;
  used_ += words;
  return space;
}

void WordFileWriter::flush() {
  out_.stream().write(reinterpret_cast<const char*>(chunk_.data()),
                      static_cast<std::streamsize>(used_ * sizeof(uint32_t)));
  used_ = 0;
}

void WordFileWriter::close() {
  flush();
  out_.commit();
}

std::vector<uint32_t> readWordFile(const std::string& path, size_t recordBytes,
                                   const std::string& what) {
  RecordFileReader reader(path, recordBytes, what);
  // Images are addressed by 32-bit word addresses: a larger file is no image.
  if (reader.records() * recordBytes / sizeof(uint32_t) > kMaxImageWords)
    throw std::runtime_error(what + " '" + path + "' has " +
                             std::to_string(reader.records() * recordBytes) +
                             " bytes, more than the 2^32 words a 32-bit word address reaches");
  const WorkPhase phase("reading " + what + " '" + path + "' (" +
                        std::to_string(reader.records() * recordBytes) + " bytes)");
  std::vector<uint32_t> words;
  words.reserve(reader.records() * recordBytes / sizeof(uint32_t));
  size_t count = 0;
  while (const uint32_t* chunk = reader.next(count))
    words.insert(words.end(), chunk, chunk + count * recordBytes / sizeof(uint32_t));
  return words;
}

void writeWordFile(const std::string& path, const std::vector<uint32_t>& words) {
  WordFileWriter writer(path);
  for (size_t done = 0; done < words.size(); done += WordFileWriter::kChunkWords) {
    const size_t n = std::min(WordFileWriter::kChunkWords, words.size() - done);
    std::memcpy(writer.append(n), words.data() + done, n * sizeof(uint32_t));
  }
  writer.close();
}

}  // namespace rtu
