#include "app/frame_stream.h"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <utility>
#include <variant>

#include "app/kind_outputs.h"
#include "explore/ray_passes.h"
#include "inputs/secondary_rays.h"
#include "kind_app_plugins.h"
#include "kinds/core_result.h"
#include "rtu/host_memory.h"
#include "run/model_run.h"

namespace rtu {

// The kind's tally (KindOutputs<Kind>::Tally, app/kind_outputs.h) behind one call per result.
class FrameStream::Tally {
 public:
  virtual ~Tally() = default;
  virtual void add(const CoreKindResult& result, PixelSink* frame) = 0;
  virtual std::string describe() const = 0;
};

namespace {

template <class Kind>
class KindTally final : public FrameStream::Tally {
 public:
  KindTally(const RunConfig& settings, const FrameScene& scene) : tally_(settings, scene) {}
  void add(const CoreKindResult& result, PixelSink* frame) override { tally_.add(result, frame); }
  std::string describe() const override { return tally_.describe(); }

 private:
  typename KindOutputs<Kind>::Tally tally_;
};

std::unique_ptr<FrameStream::Tally> tallyOf(const RunConfig& settings, const FrameScene& scene) {
  return withCoreKind(settings.rtu.core, [&](auto kind) -> std::unique_ptr<FrameStream::Tally> {
    return std::make_unique<KindTally<decltype(kind)>>(settings, scene);
  });
}

}  // namespace

FrameMemory estimateFrameMemory(const RunConfig& settings, bool keepPixels, size_t imageBytes,
                                bool traced) {
  const double rays = static_cast<double>(settings.camera.pixelCount());
  FrameMemory memory;
  const auto add = [&](double bytesPerRay, const std::string& what) {
    memory.bytes += rays * bytesPerRay;
    memory.what += (memory.what.empty() ? "" : ", ") + what;
  };
  if (keepPixels) {
    add(sizeof(FramePixel) + sizeof(SurfaceHit), "the pixels and hits secondary passes read");
    memory.bytes += passRays(settings, settings.camera.pixelCount()) * (sizeof(RayRecord) + 0.125);
    memory.what += ", their rays";
  }
  if (imageBytes > 0) add(static_cast<double>(imageBytes), "the images' samples held to the end");
  if (settings.model != ModelKind::Golden && traced)
    add(sizeof(HostRecord) + sizeof(CoreKindResult) + 4 * sizeof(uint64_t),
        "a traced frame's records and its dry run's results");
  return memory;
}

void checkFrameFits(const RunConfig& settings, bool keepPixels, size_t imageBytes, bool traced) {
  const FrameMemory memory = estimateFrameMemory(settings, keepPixels, imageBytes, traced);
  const uint64_t available = physicalMemoryBytes();
  if (memory.bytes <= static_cast<double>(available)) return;
  throw std::runtime_error("a " + std::to_string(settings.camera.width) + "x" +
                           std::to_string(settings.camera.height) + " frame would hold about " +
                           formatGiB(memory.bytes) + " (" + memory.what + "), more than the " +
                           formatGiB(static_cast<double>(available)) +
                           " of this machine: lower --width and --height" +
                           (keepPixels       ? " or drop the passes"
                            : imageBytes > 0 ? " or drop the images"
                                             : ""));
}

FrameStream::FrameStream(const RunConfig& settings, const FrameScene& scene, bool keepPixels,
                         PixelSink* images)
    : settings_(settings),
      scene_(scene),
      makeRecord_(frameRecordMaker(settings.rtu.core)),
      tally_(tallyOf(settings, scene)),
      images_(images) {
  if (recordedWorkload(settings)) {
    recorded_ = frameRecords(scene, settings);
  } else {
    sample_ = frameRecordSample(scene, settings);
  }
  if (keepPixels) frame_.emplace(settings.camera);
}

FrameStream::~FrameStream() = default;

RecordSource FrameStream::records() {
  if (recorded_) return RecordSource(*recorded_);
  return RecordSource(
      settings_.camera.pixelCount(), [this](uint64_t index) { return make(index); }, sample_);
}

std::vector<HostRecord> FrameStream::heldRecords() {
  if (recorded_) return *recorded_;
  return frameRecords(scene_, settings_);
}

ResultTaker FrameStream::taker() {
  return [this](uint64_t, const CoreKindResult& result) { take(result); };
}

// Row by row from the top, as frameRays makes them: index = x + y * width.
HostRecord FrameStream::make(uint64_t index) {
  held_.madeOne();
  return makeRecord_(scene_, settings_, static_cast<uint32_t>(index),
                     settings_.camera.pixelRay(index));
}

void FrameStream::take(const CoreKindResult& result) {
  held_.tookOne();
  tally_->add(result, frame_ ? &*frame_ : images_);
}

std::string FrameStream::describe() const { return tally_->describe(); }

std::optional<RenderedFrame> FrameStream::takeFrame() { return std::move(frame_); }

}  // namespace rtu
