#include "host_buffers.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "binary_file.h"
#include "ray_setup.h"

namespace rtu {

namespace {

std::runtime_error recordError(size_t record, const std::string& problem) {
  return std::runtime_error("record " + std::to_string(record) + ": " + problem);
}

uint32_t toWord32(int64_t value, const char* field) {
  if (value < std::numeric_limits<int32_t>::min() || value > std::numeric_limits<int32_t>::max())
    throw std::invalid_argument(std::string(field) +
                                " does not fit the 32-bit result record; host buffers hold "
                                "formats of at most 32 bits");
  return static_cast<uint32_t>(value);
}

int64_t signExtend32(uint32_t word) { return static_cast<int32_t>(word); }

// Reads a buffer file and decodes it; decoding errors are prefixed with the file.
template <class Decode>
auto readBuffer(const std::string& path, const std::string& what, Decode decode) {
  const std::vector<uint32_t> words = readWordFile(path, kRecordBytes, what);
  try {
    return decode(words);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(what + " '" + path + "': " + error.what());
  }
}

}  // namespace

void checkFitsResultRecords(const FixedFormat& format) {
  if (format.totalBits > 32)
    throw std::invalid_argument("--total-bits " + std::to_string(format.totalBits) +
                                ": the host result records (--out) hold formats of at most 32 "
                                "bits");
}

std::vector<TraversalJob> decodeJobRecords(const std::vector<uint32_t>& words) {
  if (words.size() % kRecordWords != 0)
    throw std::runtime_error("job buffer holds " + std::to_string(words.size()) +
                             " words, not a multiple of 8");
  const char* axes = "xyz";
  std::vector<TraversalJob> jobs(words.size() / kRecordWords);
  for (size_t i = 0; i < jobs.size(); ++i) {
    const uint32_t* record = &words[i * kRecordWords];
    if (record[0] >> 31)
      throw recordError(i, "bit 31 of the job word is set (ids have 28 bits, a has 3)");
    TraversalJob& job = jobs[i];
    job.id = record[0] & TraversalJob::kMaxId;
    job.a = static_cast<uint8_t>(record[0] >> 28 & 7);
    for (int k = 0; k < 3; ++k) {
      job.t0Bits[k] = record[1 + k];
      job.t1Bits[k] = record[4 + k];
      const float t0 = bitsToFloat(job.t0Bits[k]);
      const float t1 = bitsToFloat(job.t1Bits[k]);
      if (std::isnan(t0) || std::isnan(t1))
        throw recordError(i, std::string("t-value on axis ") + axes[k] + " is NaN");
      if (t0 > t1)
        throw recordError(i, std::string("t0") + axes[k] + " > t1" + axes[k] +
                                 ": after mirroring every direction is positive, so t0 <= t1");
    }
    job.root = record[7];
  }
  return jobs;
}

std::vector<uint32_t> encodeJobRecords(const std::vector<TraversalJob>& jobs) {
  std::vector<uint32_t> words;
  words.reserve(jobs.size() * kRecordWords);
  for (const TraversalJob& job : jobs) {
    if (job.id > TraversalJob::kMaxId || job.a > 7)
      throw std::invalid_argument("job id " + std::to_string(job.id) +
                                  " or a does not fit the job word");
    words.push_back(job.idWord());
    words.insert(words.end(), job.t0Bits.begin(), job.t0Bits.end());
    words.insert(words.end(), job.t1Bits.begin(), job.t1Bits.end());
    words.push_back(job.root);
  }
  return words;
}

std::vector<TraversalResult> decodeResultRecords(const std::vector<uint32_t>& words) {
  if (words.size() % kRecordWords != 0)
    throw std::runtime_error("result buffer holds " + std::to_string(words.size()) +
                             " words, not a multiple of 8");
  std::vector<TraversalResult> results(words.size() / kRecordWords);
  for (size_t i = 0; i < results.size(); ++i) {
    const uint32_t* record = &words[i * kRecordWords];
    if (record[1] > 1) throw recordError(i, "hit word is " + std::to_string(record[1]) + ", not 0 or 1");
    if (record[7] & ~kResultFlagStackOverflow)
      throw recordError(i, "unknown flag bits in word 7");
    TraversalResult& result = results[i];
    result.idWord = record[0];
    result.hit = record[1] == 1;
    result.tHit = signExtend32(record[2]);
    for (int k = 0; k < 3; ++k) result.normal[k] = signExtend32(record[3 + k]);
    if (!result.hit && (result.normal[0] || result.normal[1] || result.normal[2]))
      throw recordError(i, "a miss with a non-zero normal");
    result.cost = record[6];
    result.stackOverflow = (record[7] & kResultFlagStackOverflow) != 0;
  }
  return results;
}

std::vector<uint32_t> encodeResultRecords(const std::vector<TraversalResult>& results) {
  std::vector<uint32_t> words;
  words.reserve(results.size() * kRecordWords);
  for (const TraversalResult& result : results) {
    words.push_back(result.idWord);
    words.push_back(result.hit ? 1u : 0u);
    words.push_back(toWord32(result.tHit, "t_hit"));
    for (int k = 0; k < 3; ++k) words.push_back(toWord32(result.normal[k], "normal"));
    words.push_back(result.cost);
    words.push_back(result.stackOverflow ? kResultFlagStackOverflow : 0u);
  }
  return words;
}

std::vector<RayRecord> decodeRayRecords(const std::vector<uint32_t>& words) {
  if (words.size() % kRecordWords != 0)
    throw std::runtime_error("ray buffer holds " + std::to_string(words.size()) +
                             " words, not a multiple of 8");
  std::vector<RayRecord> records(words.size() / kRecordWords);
  for (size_t i = 0; i < records.size(); ++i) {
    const uint32_t* word = &words[i * kRecordWords];
    RayRecord& record = records[i];
    record.id = word[0];
    for (int k = 0; k < 3; ++k) {
      record.origin[k] = bitsToFloat(word[1 + k]);
      record.direction[k] = bitsToFloat(word[4 + k]);
    }
    record.modelAddress = word[7];
    try {
      record.validate();
    } catch (const std::runtime_error& error) {
      throw recordError(i, error.what());
    }
  }
  return records;
}

std::vector<uint32_t> encodeRayRecords(const std::vector<RayRecord>& records) {
  std::vector<uint32_t> words;
  words.reserve(records.size() * kRecordWords);
  for (size_t i = 0; i < records.size(); ++i) {
    const RayRecord& record = records[i];
    try {
      record.validate();
    } catch (const std::runtime_error& error) {
      throw std::invalid_argument("ray record " + std::to_string(i) + ": " + error.what());
    }
    words.push_back(record.id);
    for (float component : record.origin) words.push_back(floatBits(component));
    for (float component : record.direction) words.push_back(floatBits(component));
    words.push_back(record.modelAddress);
  }
  return words;
}

std::vector<TraversalJob> readJobBuffer(const std::string& path) {
  return readBuffer(path, "job buffer", decodeJobRecords);
}

void writeJobBuffer(const std::string& path, const std::vector<TraversalJob>& jobs) {
  writeWordFile(path, encodeJobRecords(jobs));
}

std::vector<TraversalResult> readResultBuffer(const std::string& path) {
  return readBuffer(path, "result buffer", decodeResultRecords);
}

void writeResultBuffer(const std::string& path, const std::vector<TraversalResult>& results) {
  writeWordFile(path, encodeResultRecords(results));
}

std::vector<RayRecord> readRayBuffer(const std::string& path) {
  return readBuffer(path, "ray buffer", decodeRayRecords);
}

void writeRayBuffer(const std::string& path, const std::vector<RayRecord>& records) {
  writeWordFile(path, encodeRayRecords(records));
}

}  // namespace rtu
