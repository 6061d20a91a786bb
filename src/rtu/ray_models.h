#pragma once
// What every triangle kind's job set-up of a world-space ray record shares (issue 28): the
// record's model address names a model header (rtu/model_header.h) whose word 15 is the word
// address of the kind's image, its 16-word header first (rtu/image_sections.h). The first ray
// against a model reads both headers, 16 words each at one word a cycle (2 x headerFetchCycles,
// in which no record is accepted), and the set-up keeps what it made of them for the rest of the
// run; every ray then takes `rayStages` more than a t-value record (the move into the model's
// space, rtu/model_transform.h, and the kind's conversion of the ray).

#include <array>
#include <cstdint>
#include <map>
#include <string>

#include "rtu/core_kind.h"
#include "rtu/image_sections.h"
#include "rtu/job_manager_timing.h"
#include "rtu/model_header.h"
#include "rtu/ray_record.h"
#include "rtu/word_memory.h"

namespace rtu {

// A model header and the image header its word 15 names.
struct ImageEntry {
  ModelHeader model;
  std::array<uint32_t, kImageHeaderWords> header{};
  std::string where;  // "model header at word A: <kind> image at R", for a kind's own errors
};

// Reads the model header at `address` (readModelHeader) and the image's header. Throws
// std::runtime_error naming the address for an image not on a multiple of `alignWords` words,
// running past the end of the memory, or whose words 0 and 1 are not `magic` and `kind`.
ImageEntry readImageEntry(const WordMemory& memory, uint32_t address, uint32_t alignWords,
                          uint32_t magic, uint32_t kind, const std::string& kindName);

// The models a set-up has read, by model address, each made once by the kind's `readModel`.
template <class Model>
class RayModels {
 public:
  explicit RayModels(const JobManagerTiming& timing) : timing_(timing) {}

  // `set`'s id word (the record's id, bit 31 set for an any-hit ray, as the SVO kind's job word:
  // rtu/ray_span.h) and latency for `record`, and its model: the first against a model address
  // reads it (`readModel(address)`) and waits for both headers.
  template <class Job, class ReadModel>
  const Model& find(const RayRecord& record, JobSetUp<Job>& set, ReadModel&& readModel) {
    set.idWord = record.id | (record.span == RaySpan::AnyHit ? kAnyHitBit : 0u);
    set.latency = static_cast<uint64_t>(timing_.stages + timing_.rayStages);
    auto model = models_.find(record.modelAddress);
    if (model == models_.end()) {
      model = models_.emplace(record.modelAddress, readModel(record.modelAddress)).first;
      set.headerFetch = 2 * static_cast<uint64_t>(timing_.headerFetchCycles);
      set.latency += set.headerFetch;
    }
    return model->second;
  }

 private:
  JobManagerTiming timing_;
  std::map<uint32_t, Model> models_;
};

}  // namespace rtu
