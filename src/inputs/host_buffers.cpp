#include "inputs/host_buffers.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "base/binary_file.h"
#include "base/prefault.h"
#include "kinds/svo/ray_setup.h"

namespace rtu {

namespace {

std::runtime_error recordError(size_t record, const std::string& problem) {
  return std::runtime_error("record " + std::to_string(record) + ": " + problem);
}

// A record whose values are impossible (NaN, infinite, out of range, t0 > t1): readers that skip
// records skip these. Other errors (id bits: a file of another kind) stop every reader.
struct ImpossibleValue : std::runtime_error {
  using std::runtime_error::runtime_error;
};

ImpossibleValue valueError(size_t record, const std::string& problem) {
  return ImpossibleValue(recordError(record, problem).what());
}

uint32_t toWord32(int64_t value, const char* field) {
  if (value < std::numeric_limits<int32_t>::min() || value > std::numeric_limits<int32_t>::max())
    throw std::invalid_argument(std::string(field) +
                                " does not fit the 32-bit result record; host buffers hold "
                                "formats of at most 32 bits");
  return static_cast<uint32_t>(value);
}

int64_t signExtend32(uint32_t word) { return static_cast<int32_t>(word); }

// A 64-bit two's complement value as two words, low word first.
void putWord64(int64_t value, uint32_t* words) {
  words[0] = static_cast<uint32_t>(static_cast<uint64_t>(value));
  words[1] = static_cast<uint32_t>(static_cast<uint64_t>(value) >> 32);
}
int64_t getWord64(const uint32_t* words) {
  return static_cast<int64_t>(uint64_t{words[1]} << 32 | words[0]);
}

// One codec per record kind: decode(words of record i, i) checks and returns the record, encode
// writes its 8 words. The vector and file functions below share them.
struct JobCodec {
  using Record = TValueRecord;
  static constexpr size_t kWords = kRecordWords;
  static constexpr const char* kWhat = "job buffer";

  static TValueRecord decode(const uint32_t* record, size_t i) {
    static const char* axes = "xyz";
    if (record[0] >> 31)
      throw recordError(i, "bit 31 of the job word is set (ids have 28 bits, a has 3)");
    TValueRecord job;
    job.id = record[0] & TValueRecord::kMaxId;
    job.a = static_cast<uint8_t>(record[0] >> 28 & 7);
    for (int k = 0; k < 3; ++k) {
      job.t0Bits[k] = record[1 + k];
      job.t1Bits[k] = record[4 + k];
      const float t0 = bitsToFloat(job.t0Bits[k]);
      const float t1 = bitsToFloat(job.t1Bits[k]);
      if (std::isnan(t0) || std::isnan(t1))
        throw valueError(i, std::string("t-value on axis ") + axes[k] + " is NaN");
      if (t0 > t1)
        throw valueError(i, std::string("t0") + axes[k] + " > t1" + axes[k] +
                                ": after mirroring every direction is positive, so t0 <= t1");
    }
    job.root = record[7];
    return job;
  }

  static void encode(const TValueRecord& job, size_t, uint32_t* words) {
    if (job.id > TValueRecord::kMaxId || job.a > 7)
      throw std::invalid_argument("job id " + std::to_string(job.id) +
                                  " or a does not fit the job word");
    if (job.span != RaySpan::Line)
      throw std::invalid_argument("job " + std::to_string(job.id) +
                                  ": a t-value record has no span bits; write ray records");
    words[0] = job.idWord();
    for (int k = 0; k < 3; ++k) {
      words[1 + k] = job.t0Bits[k];
      words[4 + k] = job.t1Bits[k];
    }
    words[7] = job.root;
  }
};

// The fields both result layouts share: checked, then filled in beside t and the normal.
TraversalResult decodeResult(uint32_t idWord, uint32_t hitWord, int64_t tHit,
                             const std::array<int64_t, 3>& normal, uint32_t cost, uint32_t flags,
                             size_t i) {
  if (hitWord > 1) throw recordError(i, "hit word is " + std::to_string(hitWord) + ", not 0 or 1");
  if (flags & ~(kResultFlagStackOverflow | kResultFlagTOverflow | kResultFlagBelowResolution))
    throw recordError(i, "unknown flag bits in the flags word");
  TraversalResult result;
  result.idWord = idWord;
  result.hit = hitWord == 1;
  result.tHit = tHit;
  result.normal = normal;
  if (!result.hit && (normal[0] || normal[1] || normal[2]))
    throw recordError(i, "a miss with a non-zero normal");
  result.cost = cost;
  result.stackOverflow = (flags & kResultFlagStackOverflow) != 0;
  result.tOverflow = (flags & kResultFlagTOverflow) != 0;
  result.belowResolution = (flags & kResultFlagBelowResolution) != 0;
  return result;
}

uint32_t flagsWord(const TraversalResult& result) {
  return (result.stackOverflow ? kResultFlagStackOverflow : 0u) |
         (result.tOverflow ? kResultFlagTOverflow : 0u) |
         (result.belowResolution ? kResultFlagBelowResolution : 0u);
}

// Formats of at most 32 bits: t and the normal in one word each.
struct ResultCodec {
  using Record = TraversalResult;
  static constexpr const char* kWhat = "result buffer";
  static constexpr size_t kWords = kRecordWords;

  static TraversalResult decode(const uint32_t* record, size_t i) {
    return decodeResult(record[0], record[1], signExtend32(record[2]),
                        {signExtend32(record[3]), signExtend32(record[4]), signExtend32(record[5])},
                        record[6], record[7], i);
  }

  static void encode(const TraversalResult& result, size_t, uint32_t* words) {
    words[0] = result.idWord;
    words[1] = result.hit ? 1u : 0u;
    words[2] = toWord32(result.tHit, "t_hit");
    for (int k = 0; k < 3; ++k) words[3 + k] = toWord32(result.normal[k], "normal");
    words[6] = result.cost;
    words[7] = flagsWord(result);
  }
};

// Formats over 32 bits: t and the normal in two words each (docs/user-guide.md).
struct WideResultCodec {
  using Record = TraversalResult;
  static constexpr const char* kWhat = "wide result buffer";
  static constexpr size_t kWords = kWideResultWords;

  static TraversalResult decode(const uint32_t* record, size_t i) {
    return decodeResult(record[0], record[1], getWord64(record + 2),
                        {getWord64(record + 4), getWord64(record + 6), getWord64(record + 8)},
                        record[10], record[11], i);
  }

  static void encode(const TraversalResult& result, size_t, uint32_t* words) {
    words[0] = result.idWord;
    words[1] = result.hit ? 1u : 0u;
    putWord64(result.tHit, words + 2);
    for (int k = 0; k < 3; ++k) putWord64(result.normal[k], words + 4 + 2 * k);
    words[10] = result.cost;
    words[11] = flagsWord(result);
  }
};

struct RayCodec {
  using Record = RayRecord;
  static constexpr size_t kWords = kRecordWords;
  static constexpr const char* kWhat = "ray buffer";

  static RayRecord decode(const uint32_t* word, size_t i) {
    RayRecord record;
    try {
      record = recordOfWord0(word[0]);
    } catch (const std::runtime_error& error) {
      throw recordError(i, error.what());
    }
    for (int k = 0; k < 3; ++k) {
      record.origin[k] = bitsToFloat(word[1 + k]);
      record.direction[k] = bitsToFloat(word[4 + k]);
    }
    record.modelAddress = word[7];
    try {
      record.validate();
    } catch (const std::runtime_error& error) {
      if (record.id > TValueRecord::kMaxId) throw recordError(i, error.what());
      throw valueError(i, error.what());
    }
    return record;
  }

  static void encode(const RayRecord& record, size_t i, uint32_t* words) {
    try {
      record.validate();
    } catch (const std::runtime_error& error) {
      throw std::invalid_argument("ray record " + std::to_string(i) + ": " + error.what());
    }
    words[0] = record.idWord();
    for (int k = 0; k < 3; ++k) {
      words[1 + k] = floatBits(record.origin[k]);
      words[4 + k] = floatBits(record.direction[k]);
    }
    words[7] = record.modelAddress;
  }
};

template <class Codec>
std::vector<typename Codec::Record> decodeAll(const std::vector<uint32_t>& words) {
  if (words.size() % Codec::kWords != 0)
    throw std::runtime_error(std::string(Codec::kWhat) + " holds " + std::to_string(words.size()) +
                             " words, not a multiple of " + std::to_string(Codec::kWords));
  std::vector<typename Codec::Record> records;
  records.reserve(words.size() / Codec::kWords);
  for (size_t i = 0; i < words.size() / Codec::kWords; ++i)
    records.push_back(Codec::decode(&words[i * Codec::kWords], i));
  return records;
}

template <class Codec>
std::vector<uint32_t> encodeAll(const std::vector<typename Codec::Record>& records) {
  std::vector<uint32_t> words(records.size() * Codec::kWords);
  for (size_t i = 0; i < records.size(); ++i)
    Codec::encode(records[i], i, &words[i * Codec::kWords]);
  return words;
}

// Decodes record `index` into `records`; with `skipped`, an impossible record is noted there
// instead of failing.
template <class Codec, class Out>
void decodeInto(const uint32_t* words, size_t index, std::vector<Out>& records,
                std::vector<SkippedRecord>* skipped) {
  if (!skipped) {
    records.push_back(Codec::decode(words, index));
    return;
  }
  try {
    records.push_back(Codec::decode(words, index));
  } catch (const ImpossibleValue& error) {
    skipped->push_back({index, error.what()});
  }
}

// Decoding errors are prefixed with the file. `Out`: what the records are kept as.
template <class Codec, class Out = typename Codec::Record>
std::vector<Out> readAll(const std::string& path, std::vector<SkippedRecord>* skipped = nullptr) {
  const std::string what = Codec::kWhat;
  RecordFileReader reader(path, Codec::kWords * 4, what);
  std::vector<Out> records;
  records.reserve(reader.records());
  prefaultCapacity(records);
  size_t count = 0, index = 0;
  try {
    while (const uint32_t* chunk = reader.next(count))
      for (size_t r = 0; r < count; ++r, ++index)
        decodeInto<Codec>(chunk + r * Codec::kWords, index, records, skipped);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(what + " '" + path + "': " + error.what());
  }
  return records;
}

// A record that cannot be encoded leaves the path as it was (the writer is never closed).
template <class Codec>
void writeAll(const std::string& path, const std::vector<typename Codec::Record>& records) {
  WordFileWriter writer(path);
  for (size_t i = 0; i < records.size(); ++i)
    Codec::encode(records[i], i, writer.append(Codec::kWords));
  writer.close();
}

}  // namespace

size_t resultRecordWords(const FixedFormat& format) {
  try {
    format.validate();
  } catch (const std::invalid_argument& invalid) {
    throw std::invalid_argument("format " + format.describe() + ": " + invalid.what() +
                                "; the host result records hold formats of 8 to 48 bits");
  }
  return resultRecordBytes(format.totalBits) / 4;
}

std::vector<TValueRecord> decodeJobRecords(const std::vector<uint32_t>& words) {
  return decodeAll<JobCodec>(words);
}
std::vector<uint32_t> encodeJobRecords(const std::vector<TValueRecord>& jobs) {
  return encodeAll<JobCodec>(jobs);
}
std::vector<TraversalResult> decodeResultRecords(const std::vector<uint32_t>& words,
                                                 size_t recordWords) {
  return recordWords == kWideResultWords ? decodeAll<WideResultCodec>(words)
                                         : decodeAll<ResultCodec>(words);
}
std::vector<uint32_t> encodeResultRecords(const std::vector<TraversalResult>& results,
                                          size_t recordWords) {
  return recordWords == kWideResultWords ? encodeAll<WideResultCodec>(results)
                                         : encodeAll<ResultCodec>(results);
}
std::vector<RayRecord> decodeRayRecords(const std::vector<uint32_t>& words) {
  return decodeAll<RayCodec>(words);
}
std::vector<uint32_t> encodeRayRecords(const std::vector<RayRecord>& records) {
  return encodeAll<RayCodec>(records);
}

std::vector<TValueRecord> readJobBuffer(const std::string& path) { return readAll<JobCodec>(path); }
std::vector<TValueRecord> readJobBufferSkipping(const std::string& path,
                                                std::vector<SkippedRecord>& skipped) {
  return readAll<JobCodec>(path, &skipped);
}
std::vector<HostRecord> readJobRecordsSkipping(const std::string& path,
                                               std::vector<SkippedRecord>& skipped) {
  return readAll<JobCodec, HostRecord>(path, &skipped);
}
void writeJobBuffer(const std::string& path, const std::vector<TValueRecord>& jobs) {
  writeAll<JobCodec>(path, jobs);
}
std::vector<TraversalResult> readResultBuffer(const std::string& path, size_t recordWords) {
  return recordWords == kWideResultWords ? readAll<WideResultCodec>(path)
                                         : readAll<ResultCodec>(path);
}
void writeResultBuffer(const std::string& path, const std::vector<TraversalResult>& results,
                       size_t recordWords) {
  if (recordWords == kWideResultWords)
    writeAll<WideResultCodec>(path, results);
  else
    writeAll<ResultCodec>(path, results);
}
std::vector<RayRecord> readRayBuffer(const std::string& path) { return readAll<RayCodec>(path); }
std::vector<RayRecord> readRayBufferSkipping(const std::string& path,
                                             std::vector<SkippedRecord>& skipped) {
  return readAll<RayCodec>(path, &skipped);
}
void writeRayBuffer(const std::string& path, const std::vector<RayRecord>& records) {
  writeAll<RayCodec>(path, records);
}

}  // namespace rtu
