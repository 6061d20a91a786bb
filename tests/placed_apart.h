#pragma once
// The triangle kinds' instanced rays for the templated equivalence tests (tests/kind_fixture.h):
// one image placed three times, so the job manager's set-up reads three model headers.

#include <algorithm>
#include <cstdint>
#include <utility>
#include <variant>
#include <vector>

#include "kinds/host_record.h"
#include "rtu/model_transform.h"
#include "rtu/ray_record.h"
#include "rtu/word_memory.h"

namespace rtu {

template <class Frame>
struct PlacedApart {
  Frame frame;
  std::vector<HostRecord> records;
  WordMemory memory() const { return frame.memory(); }
};

// The frame's own model header (at the origin), then one moved and scaled and one turned, each
// appended to the frame's words by `appendHeader(frame, placement)` (a kind's model header);
// 40 rays against each of the first two, the rest against the third.
template <class Frame, class AppendHeader>
PlacedApart<Frame> placedApart(Frame frame, AppendHeader appendHeader) {
  PlacedApart<Frame> rays{std::move(frame), {}};
  ModelPlacement moved;
  moved.translation = {0.5, -0.25, 0.5};
  moved.scale = glm::dvec3(0.75);
  ModelPlacement turned;
  turned.rotation = rotationFromEulerDegrees({0, 30, 0});
  const uint32_t headers[3] = {std::get<RayRecord>(rays.frame.jobs[0]).modelAddress,
                               appendHeader(rays.frame, moved), appendHeader(rays.frame, turned)};
  for (size_t i = 0; i < rays.frame.jobs.size(); ++i) {
    RayRecord record = std::get<RayRecord>(rays.frame.jobs[i]);
    record.modelAddress = headers[std::min<size_t>(i / 40, 2)];
    rays.records.push_back(record);
  }
  return rays;
}

}  // namespace rtu
