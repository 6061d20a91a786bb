#pragma once
// A frame's rays as streams (kinds/host_stream.h, docs/robustness.md "Memory"): the records made
// from the camera one at a time as the run asks for them, and the results taken as they leave it,
// summed into the kind's report lines (its KindOutputs<Kind>::Tally, app/kind_outputs.h)
// and, when pixels are wanted, placed: into the frame when secondary passes read it, else into
// the images as they are written (app/frame_image_writer.h). What it holds per ray is then only
// the pixels asked for; it counts the rays held at once (made and not yet taken), which the RTU's
// buffers bound, not the frame.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/frame_images.h"
#include "config/run_config.h"
#include "explore/frame_scene.h"
#include "kinds/host_stream.h"

namespace rtu {

// What a frame's render still holds per ray, estimated before it starts: the pixels, when kept
// for secondary passes (a FramePixel each; their shaded image is written a row at a time), with
// the passes' hits (a SurfaceHit a pixel) and rays (a RayRecord and a bit each: passRays); the
// images' samples held to the end (`imageBytes` a pixel: FrameImageWriter::bytesPerPixel, the
// same whether the pixels are kept or streamed); a traced frame's records and its dry runs'
// results. `what` names them.
struct FrameMemory {
  double bytes = 0;
  std::string what;
};
FrameMemory estimateFrameMemory(const RunConfig& settings, bool keepPixels, size_t imageBytes,
                                bool traced);
// Throws std::runtime_error naming the estimate and the limit (this machine's memory) when it is
// over it.
void checkFrameFits(const RunConfig& settings, bool keepPixels, size_t imageBytes, bool traced);

class FrameStream {
 public:
  // The kind's report and pixels of results (frame_stream.cpp).
  class Tally;

  // The frame of `settings`' camera on `scene` (or its recorded workload, held as a vector); both
  // must outlive the stream, and `images` (where the pixels go when not kept; may be null) too.
  // Throws as frameRecords does (another core's scene, too few stack frames) before any ray is
  // made.
  FrameStream(const RunConfig& settings, const FrameScene& scene, bool keepPixels,
              PixelSink* images = nullptr);
  ~FrameStream();

  // The frame's records; each counts as held from when the run makes it.
  RecordSource records();
  // Takes a result: counted, its pixel placed when pixels are kept or images written.
  ResultTaker taker();
  // The records as one vector (a traced run's dry runs read them more than once).
  std::vector<HostRecord> heldRecords();

  const RaysHeld& held() const { return held_; }
  // The report lines of the results taken.
  std::string describe() const;
  // The pixels placed, when kept.
  std::optional<RenderedFrame> takeFrame();

 private:
  HostRecord make(uint64_t index);
  void take(const CoreKindResult& result);

  const RunConfig& settings_;
  const FrameScene& scene_;
  FrameRecordMaker makeRecord_;  // the kind's record of a primary ray (KindScene<Kind>::record)
  std::unique_ptr<Tally> tally_;
  std::optional<std::vector<HostRecord>> recorded_;  // a recorded workload's
  HostRecord sample_;                                // record 0 of the frame, made beforehand
  std::optional<RenderedFrame> frame_;
  PixelSink* images_;
  RaysHeld held_;
};

}  // namespace rtu
