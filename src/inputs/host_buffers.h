#pragma once
// The DMA buffers of the thesis driver (appendix F), so job streams can come from and go to other
// tools. Every record is 8 little-endian 32-bit words:
//   input:  [job_id | a << 28, t0x, t0y, t0z, t1x, t1y, t1z (float32 bits), root address]
//   output: [job_id | a << 28, hit, t_hit, nx, ny, nz (fixed point), cost, flags]
//   wide output, for formats over 32 bits, 12 words: [job_id | a << 28, hit, t_hit, nx, ny, nz,
//           cost, flags] with t_hit, nx, ny, nz as 64-bit two's complement, low word first
// The output's job word is returned as received, as the RTL does. `flags` is 0 on the RTL; rtusim
// sets bit 0 when the traversal ran out of stack frames, bit 1 when t-values were beyond the
// fixed-point range (a t sum wrapped or the conversion saturated), bit 2 when the ray descended
// into nodes narrower than a step of the format.
// The second input kind, for a job manager that moves rays into animated models (ray_transform.h):
//   rays:   [job_id (bits 31:28 zero), ox, oy, oz, dx, dy, dz (float32 bits, world), model address]

#include <string>
#include <vector>

#include "kinds/registry.h"
#include "kinds/svo/fixed_point.h"
#include "kinds/svo/ray_transform.h"
#include "kinds/svo/thesis_records.h"
#include "rtu/host_link.h"

namespace rtu {

constexpr size_t kRecordWords = 8;
constexpr size_t kRecordBytes = kRecordWords * 4;
constexpr size_t kWideResultWords = kWideResultRecordBytes / 4;
constexpr uint32_t kResultFlagStackOverflow = 1;
constexpr uint32_t kResultFlagTOverflow = 2;
constexpr uint32_t kResultFlagBelowResolution = 4;

// Throws std::runtime_error naming the record and field for impossible contents: bit 31 of the
// job word set, a NaN t-value, or t0 > t1 on an axis (after mirroring every direction is
// positive, so t0 <= t1).
std::vector<TValueRecord> decodeJobRecords(const std::vector<uint32_t>& words);
std::vector<uint32_t> encodeJobRecords(const std::vector<TValueRecord>& jobs);

// Result records of `recordWords` words: kRecordWords, or kWideResultWords for formats over 32
// bits (resultRecordWords). Decoding throws std::runtime_error for hit words other than 0/1,
// unknown flag bits, or a normal that is not zero on a miss.
std::vector<TraversalResult> decodeResultRecords(const std::vector<uint32_t>& words,
                                                 size_t recordWords = kRecordWords);
// Throws std::invalid_argument when t_hit or the normal do not fit 32 bits in 8-word records.
std::vector<uint32_t> encodeResultRecords(const std::vector<TraversalResult>& results,
                                          size_t recordWords = kRecordWords);

// Throws std::runtime_error naming the record for anything RayRecord::validate() rejects.
std::vector<RayRecord> decodeRayRecords(const std::vector<uint32_t>& words);
// Throws std::invalid_argument naming the record for the same.
std::vector<uint32_t> encodeRayRecords(const std::vector<RayRecord>& records);

// A record left out of a buffer: its number and what is impossible about it.
struct SkippedRecord {
  size_t record = 0;
  std::string problem;  // "record 3: t-value on axis y is NaN"
};

std::vector<TValueRecord> readJobBuffer(const std::string& path);
// As readJobBuffer and readRayBuffer, but a record with impossible values (NaN or infinite fields,
// components beyond 2^64, a zero direction, t0 > t1) is left out and noted in `skipped`, so the
// rest can still be traced. Id bits (a file of another kind) and a file that is not whole records
// still throw.
std::vector<TValueRecord> readJobBufferSkipping(const std::string& path,
                                                std::vector<SkippedRecord>& skipped);
// readJobBufferSkipping straight into the records a run reads, without a job vector in between.
std::vector<HostRecord> readJobRecordsSkipping(const std::string& path,
                                               std::vector<SkippedRecord>& skipped);
std::vector<RayRecord> readRayBufferSkipping(const std::string& path,
                                             std::vector<SkippedRecord>& skipped);
void writeJobBuffer(const std::string& path, const std::vector<TValueRecord>& jobs);
std::vector<TraversalResult> readResultBuffer(const std::string& path,
                                              size_t recordWords = kRecordWords);
// Before a run: the result record words for `format` (8 up to 32 bits, 12 above), so every t and
// normal it can produce is representable; throws std::invalid_argument naming the format when it
// is not a valid one.
size_t resultRecordWords(const FixedFormat& format);
void writeResultBuffer(const std::string& path, const std::vector<TraversalResult>& results,
                       size_t recordWords = kRecordWords);
std::vector<RayRecord> readRayBuffer(const std::string& path);
void writeRayBuffer(const std::string& path, const std::vector<RayRecord>& records);

}  // namespace rtu
