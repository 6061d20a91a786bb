#include "explore/animation_workers.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "explore/sweep_workers.h"
#include "run/statistics_output.h"

namespace rtu {
namespace {

// A frame's statistics on one line from worker to parent (doubles survive the JSON exactly).
std::string statisticsLine(const FrameStatistics& statistics) {
  return statisticsJson(statistics).dump() + "\n";
}

std::string rangeText(const FrameRange& range) {
  return "frames " + std::to_string(range.first) + " to " + std::to_string(range.end - 1);
}

// In the worker: one line per frame, or an error line.
void renderRange(const SceneDescription& scene, const std::vector<SceneModel>& models,
                 const AnimationOptions& options, const FrameRange& range,
                 const std::function<void(const SceneFrame&)>& writeFrame, const WorkerSay& say) {
  try {
    AnimationRenderer renderer(scene, models, options);
    if (range.first > 0 && options.hitBuffer) renderer.prime(range.first - 1);
    for (int frame = range.first; frame < range.end; ++frame) {
      const SceneFrame rendered = renderer.render(frame);
      writeFrame(rendered);
      say(statisticsLine(rendered.statistics));
    }
  } catch (const std::exception& error) {
    say(nlohmann::json{{"error", error.what()}}.dump() + "\n");
  }
}

// The parent's side: statistics in frame order, the first failure kept for the end.
class FrameCollector {
 public:
  FrameCollector(int frames, const std::function<void(const FrameStatistics&)>& frameDone)
      : progress_("animate", static_cast<size_t>(frames), "frames"), frameDone_(frameDone) {}

  void heard(const FrameRange& range, const std::string& text) {
    try {
      const nlohmann::ordered_json line = nlohmann::ordered_json::parse(text);
      if (line.contains("error")) return fail(range, line["error"].get<std::string>());
      FrameStatistics statistics;
      readStatistics(statistics, line);
      waiting_.emplace(statistics.frame, statistics);
    } catch (const nlohmann::json::exception& error) {
      return fail(range, std::string("unreadable worker answer: ") + error.what());
    }
    progress_.update(++received_, 0);
    for (auto next = waiting_.find(handed_); next != waiting_.end();
         next = waiting_.find(handed_)) {
      frameDone_(next->second);
      waiting_.erase(next);
      ++handed_;
    }
  }

  void done(const FrameRange& range, const WorkerOutcome& outcome) {
    if (!outcome.answered) fail(range, outcome.failure);
  }

  // Throws the first failure, or when a frame is missing.
  void finish(int frames) {
    progress_.finish();
    if (!failure_.empty()) throw std::runtime_error(failure_);
    if (handed_ != frames)
      throw std::runtime_error("animate: frame " + std::to_string(handed_) + " was not rendered");
  }

 private:
  void fail(const FrameRange& range, const std::string& why) {
    if (failure_.empty()) failure_ = "animate: " + rangeText(range) + ": " + why;
  }

  Progress progress_;
  std::function<void(const FrameStatistics&)> frameDone_;
  std::map<int, FrameStatistics> waiting_;
  size_t received_ = 0;
  int handed_ = 0;
  std::string failure_;
};

}  // namespace

std::vector<FrameRange> splitFrames(int frames, int ranges) {
  const int count = std::max(1, std::min(ranges, frames));
  std::vector<FrameRange> split;
  for (int i = 0, first = 0; i < count; ++i) {
    const int length = frames / count + (i < frames % count ? 1 : 0);
    split.push_back({first, first + length});
    first += length;
  }
  return split;
}

void renderFramesInWorkers(const SceneDescription& scene, const std::vector<SceneModel>& models,
                           const AnimationOptions& options, int workers,
                           const std::function<void(const SceneFrame&)>& writeFrame,
                           const std::function<void(const FrameStatistics&)>& frameDone) {
  const std::vector<FrameRange> ranges =
      splitFrames(scene.frames, workers == 1 ? 1 : workers * kFrameRangesPerWorker);
  std::vector<size_t> rows;
  for (size_t i = 0; i < ranges.size(); ++i) rows.push_back(i);
  FrameCollector collector(scene.frames, frameDone);
  runInWorkers(
      rows, workers,
      [&](size_t row, const WorkerSay& say) {
        renderRange(scene, models, options, ranges[row], writeFrame, say);
      },
      [&](size_t row, const std::string& line) { collector.heard(ranges[row], line); },
      [&](size_t row, const WorkerOutcome& outcome) { collector.done(ranges[row], outcome); });
  collector.finish(scene.frames);
}

}  // namespace rtu
