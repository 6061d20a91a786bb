#include "host_buffers.h"

#include <cmath>
#include <cstdio>
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

// One codec per record kind: decode(words of record i, i) checks and returns the record, encode
// writes its 8 words. The vector and file functions below share them.
struct JobCodec {
  using Record = TraversalJob;
  static constexpr const char* kWhat = "job buffer";

  static TraversalJob decode(const uint32_t* record, size_t i) {
    static const char* axes = "xyz";
    if (record[0] >> 31)
      throw recordError(i, "bit 31 of the job word is set (ids have 28 bits, a has 3)");
    TraversalJob job;
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
    return job;
  }

  static void encode(const TraversalJob& job, size_t, uint32_t* words) {
    if (job.id > TraversalJob::kMaxId || job.a > 7)
      throw std::invalid_argument("job id " + std::to_string(job.id) +
                                  " or a does not fit the job word");
    words[0] = job.idWord();
    for (int k = 0; k < 3; ++k) {
      words[1 + k] = job.t0Bits[k];
      words[4 + k] = job.t1Bits[k];
    }
    words[7] = job.root;
  }
};

struct ResultCodec {
  using Record = TraversalResult;
  static constexpr const char* kWhat = "result buffer";

  static TraversalResult decode(const uint32_t* record, size_t i) {
    if (record[1] > 1) throw recordError(i, "hit word is " + std::to_string(record[1]) + ", not 0 or 1");
    if (record[7] & ~(kResultFlagStackOverflow | kResultFlagTOverflow | kResultFlagBelowResolution))
      throw recordError(i, "unknown flag bits in word 7");
    TraversalResult result;
    result.idWord = record[0];
    result.hit = record[1] == 1;
    result.tHit = signExtend32(record[2]);
    for (int k = 0; k < 3; ++k) result.normal[k] = signExtend32(record[3 + k]);
    if (!result.hit && (result.normal[0] || result.normal[1] || result.normal[2]))
      throw recordError(i, "a miss with a non-zero normal");
    result.cost = record[6];
    result.stackOverflow = (record[7] & kResultFlagStackOverflow) != 0;
    result.tOverflow = (record[7] & kResultFlagTOverflow) != 0;
    result.belowResolution = (record[7] & kResultFlagBelowResolution) != 0;
    return result;
  }

  static void encode(const TraversalResult& result, size_t, uint32_t* words) {
    words[0] = result.idWord;
    words[1] = result.hit ? 1u : 0u;
    words[2] = toWord32(result.tHit, "t_hit");
    for (int k = 0; k < 3; ++k) words[3 + k] = toWord32(result.normal[k], "normal");
    words[6] = result.cost;
    words[7] = (result.stackOverflow ? kResultFlagStackOverflow : 0u) |
               (result.tOverflow ? kResultFlagTOverflow : 0u) |
               (result.belowResolution ? kResultFlagBelowResolution : 0u);
  }
};

struct RayCodec {
  using Record = RayRecord;
  static constexpr const char* kWhat = "ray buffer";

  static RayRecord decode(const uint32_t* word, size_t i) {
    RayRecord record;
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
    return record;
  }

  static void encode(const RayRecord& record, size_t i, uint32_t* words) {
    try {
      record.validate();
    } catch (const std::runtime_error& error) {
      throw std::invalid_argument("ray record " + std::to_string(i) + ": " + error.what());
    }
    words[0] = record.id;
    for (int k = 0; k < 3; ++k) {
      words[1 + k] = floatBits(record.origin[k]);
      words[4 + k] = floatBits(record.direction[k]);
    }
    words[7] = record.modelAddress;
  }
};

template <class Codec>
std::vector<typename Codec::Record> decodeAll(const std::vector<uint32_t>& words) {
  if (words.size() % kRecordWords != 0)
    throw std::runtime_error(std::string(Codec::kWhat) + " holds " + std::to_string(words.size()) +
                             " words, not a multiple of 8");
  std::vector<typename Codec::Record> records;
  records.reserve(words.size() / kRecordWords);
  for (size_t i = 0; i < words.size() / kRecordWords; ++i)
    records.push_back(Codec::decode(&words[i * kRecordWords], i));
  return records;
}

template <class Codec>
std::vector<uint32_t> encodeAll(const std::vector<typename Codec::Record>& records) {
  std::vector<uint32_t> words(records.size() * kRecordWords);
  for (size_t i = 0; i < records.size(); ++i) Codec::encode(records[i], i, &words[i * kRecordWords]);
  return words;
}

// Decoding errors are prefixed with the file.
template <class Codec>
std::vector<typename Codec::Record> readAll(const std::string& path) {
  const std::string what = Codec::kWhat;
  RecordFileReader reader(path, kRecordBytes, what);
  std::vector<typename Codec::Record> records;
  records.reserve(reader.records());
  size_t count = 0;
  try {
    while (const uint32_t* chunk = reader.next(count))
      for (size_t r = 0; r < count; ++r)
        records.push_back(Codec::decode(chunk + r * kRecordWords, records.size()));
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(what + " '" + path + "': " + error.what());
  }
  return records;
}

// A record that cannot be encoded leaves no file behind.
template <class Codec>
void writeAll(const std::string& path, const std::vector<typename Codec::Record>& records) {
  WordFileWriter writer(path);
  try {
    for (size_t i = 0; i < records.size(); ++i)
      Codec::encode(records[i], i, writer.append(kRecordWords));
    writer.close();
  } catch (...) {
    std::remove(path.c_str());
    throw;
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
  return decodeAll<JobCodec>(words);
}
std::vector<uint32_t> encodeJobRecords(const std::vector<TraversalJob>& jobs) {
  return encodeAll<JobCodec>(jobs);
}
std::vector<TraversalResult> decodeResultRecords(const std::vector<uint32_t>& words) {
  return decodeAll<ResultCodec>(words);
}
std::vector<uint32_t> encodeResultRecords(const std::vector<TraversalResult>& results) {
  return encodeAll<ResultCodec>(results);
}
std::vector<RayRecord> decodeRayRecords(const std::vector<uint32_t>& words) {
  return decodeAll<RayCodec>(words);
}
std::vector<uint32_t> encodeRayRecords(const std::vector<RayRecord>& records) {
  return encodeAll<RayCodec>(records);
}

std::vector<TraversalJob> readJobBuffer(const std::string& path) { return readAll<JobCodec>(path); }
void writeJobBuffer(const std::string& path, const std::vector<TraversalJob>& jobs) {
  writeAll<JobCodec>(path, jobs);
}
std::vector<TraversalResult> readResultBuffer(const std::string& path) {
  return readAll<ResultCodec>(path);
}
void writeResultBuffer(const std::string& path, const std::vector<TraversalResult>& results) {
  writeAll<ResultCodec>(path, results);
}
std::vector<RayRecord> readRayBuffer(const std::string& path) { return readAll<RayCodec>(path); }
void writeRayBuffer(const std::string& path, const std::vector<RayRecord>& records) {
  writeAll<RayCodec>(path, records);
}

}  // namespace rtu
