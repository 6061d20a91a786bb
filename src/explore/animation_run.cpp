#include "explore/animation_run.h"

#include <chrono>
#include <thread>

#include "explore/animation_frame_columns.h"
#include "kinds/core_result.h"
#include "rtu/job_manager_timing.h"
#include "rtu/rtu_recurrence.h"
#include "run/lt_simulation.h"
#include "run/rtu_simulation.h"

namespace rtu {

namespace {

std::vector<size_t> instanceModels(const SceneDescription& scene) {
  std::vector<size_t> models;
  for (const InstanceDescription& instance : scene.instances) models.push_back(instance.model);
  return models;
}

bool sameCamera(const Camera& a, const Camera& b) {
  return a.position == b.position && a.lookAt == b.lookAt && a.up == b.up &&
         a.verticalFovDegrees == b.verticalFovDegrees && a.width == b.width && a.height == b.height;
}

void count(FrameStatistics& statistics, const SceneHit& hit) {
  ++statistics.raysTraced;
  statistics.jobs += hit.jobs;
  statistics.culled += hit.culled;
  statistics.skipped += hit.skipped;
  statistics.earlyTerminations += hit.skipped > 0;
  statistics.traversalCycles += resultCost(hit.result);
}

}  // namespace

const StatisticGroup<FrameStatistics>& FrameStatistics::declaration() {
  using F = FrameStatistics;
  static const StatisticGroup<F> group = withFrameTime(
      animationFrameColumns<F>("a frame of an animation: the columns of animate's CSV")
          .count(Statistic("pixels", "pixels", "the frame's pixels"), &F::pixels)
          .count(Statistic("rays_traced", "rays", "pixels the scene manager traced"),
                 &F::raysTraced)
          .count(Statistic("rays_saved", "rays", "pixels the hit buffer answered"), &F::raysSaved)
          .count(Statistic("hits", "rays", "pixels whose ray hit an instance"), &F::hits)
          .count(Statistic("jobs", "jobs",
                           "jobs issued: one per instance a ray was traced against"),
                 &F::jobs)
          .derived(Statistic("jobs_per_ray", "jobs", "jobs per traced ray"), &F::jobsPerRay)
          .count(Statistic("culled", "instances", "instance tests that missed the bounding sphere"),
                 &F::culled)
          .count(Statistic("early_terminations", "rays", "rays ended with instances left untraced"),
                 &F::earlyTerminations)
          .count(Statistic("skipped", "instances", "instances left untraced by those rays"),
                 &F::skipped)
          .count(Statistic("traversal_cycles", "cycles", "the traced jobs' golden costs summed"),
                 &F::traversalCycles));
  return group;
}

// One frame's shared state; each thread writes only its own rows and its own statistics.
struct AnimationRenderer::Work {
  Camera camera;
  std::vector<SceneInstance> instances;
  std::vector<SceneHit> pixels;
  std::vector<std::vector<IssuedJob>> issuedPerRow;
  std::vector<FrameStatistics> perThread;
  std::vector<uint8_t> traced;  // per pixel: traced, not answered by the hit buffer
};

AnimationRenderer::AnimationRenderer(const SceneDescription& scene,
                                     const std::vector<SceneModel>& models,
                                     AnimationOptions options)
    : scene_(scene),
      options_(options),
      memory_(models, instanceModels(scene)),
      hitBuffer_(static_cast<size_t>(scene.width) * static_cast<size_t>(scene.height)) {
  if (options_.threads < 1) options_.threads = 1;
}

void AnimationRenderer::traceRows(Work& work, int firstRow, int rowStep) {
  SceneManager manager(memory_.memory(), options_.golden, work.instances, options_.manager);
  FrameStatistics& statistics = work.perThread[static_cast<size_t>(firstRow)];
  const int width = work.camera.width;
  for (int y = firstRow; y < work.camera.height; y += rowStep) {
    for (int x = 0; x < width; ++x) {
      const uint32_t id = static_cast<uint32_t>(x + y * width);
      const RayRecord ray = makeRayRecord(id, work.camera.primaryRay(x, y), 0);
      const SceneHit* reused = options_.hitBuffer ? hitBuffer_.reusable(id, ray, work.instances)
                                                  : nullptr;
      if (reused) {
        work.pixels[id] = *reused;
        ++statistics.raysSaved;
      } else {
        work.pixels[id] = manager.trace(ray, &work.issuedPerRow[static_cast<size_t>(y)]);
        work.traced[id] = 1;
        count(statistics, work.pixels[id]);
      }
      statistics.hits += work.pixels[id].instance >= 0;
    }
  }
}

// The issued jobs in pixel order through the recurrence; the first job against each instance
// waits for its header, as the job manager fetches it once per frame.
uint64_t AnimationRenderer::frameCycles(
    const std::vector<std::vector<IssuedJob>>& issuedPerRow) const {
  const JobManagerTiming jobManager;
  std::vector<JobTiming> jobs;
  std::vector<uint8_t> headerFetched(memory_.instanceCount(), 0);
  for (const std::vector<IssuedJob>& row : issuedPerRow)
    for (const IssuedJob& issued : row) {
      JobTiming job{issued.cost, static_cast<uint64_t>(jobManager.stages + jobManager.rayStages),
                    0};
      if (!headerFetched[issued.instance]) {
        headerFetched[issued.instance] = 1;
        job.headerFetch = static_cast<uint64_t>(jobManager.headerFetchCycles);
        job.pipelineCycles += job.headerFetch;
      }
      jobs.push_back(job);
    }
  if (jobs.empty()) return 0;
  RecurrenceConfig config;
  config.cores = options_.cores;
  return runRecurrence(jobs, config).totalCycles;
}

// The issued jobs in pixel order as ray records against their instances' headers, through the
// loosely-timed RTU: its job manager fetches each header once, as the cycle-accurate one does.
uint64_t AnimationRenderer::looselyTimedCycles(const Work& work) const {
  std::vector<HostRecord> records;
  const int width = work.camera.width;
  for (const std::vector<IssuedJob>& row : work.issuedPerRow)
    for (const IssuedJob& issued : row) {
      const Ray ray = work.camera.primaryRay(static_cast<int>(issued.ray % width),
                                             static_cast<int>(issued.ray / width));
      records.push_back(makeRayRecord(issued.ray, ray, memory_.headerAddress(issued.instance)));
    }
  if (records.empty()) return 0;
  return runLooselyTimed(memory_.memory(), records, *options_.rtu).totalCycles;
}

uint64_t AnimationRenderer::simulateFrame(Work& work, const std::vector<uint32_t>& traced) const {
  std::vector<RayRecord> rays;
  for (uint32_t id : traced)
    rays.push_back(makeRayRecord(id,
                                 work.camera.primaryRay(static_cast<int>(id % work.camera.width),
                                                        static_cast<int>(id / work.camera.width)),
                                 0));
  RtuConfig config = *options_.rtu;
  config.sceneManager.options = options_.manager;
  const RtuRun run = simulateScene(memory_.memory(), rays, work.instances, config);
  for (size_t i = 0; i < run.results.size(); ++i) {
    SceneHit& pixel = work.pixels[traced[run.jobIndices[i]]];
    pixel.result = run.results[i];
    pixel.instance = run.instances[i];
  }
  return run.totalCycles;
}

SceneFrame AnimationRenderer::render(int frame) {
  const auto start = std::chrono::steady_clock::now();
  SceneFrame result;
  Work work = trace(frame, result);
  FrameStatistics& statistics = result.statistics;
  for (const FrameStatistics& part : work.perThread) addStatisticsOf(statistics, part);
  if (options_.model == ModelKind::LooselyTimed) {
    statistics.cycles = looselyTimedCycles(work);
  } else if (options_.model == ModelKind::CycleAccurate) {
    std::vector<uint32_t> traced;
    for (uint32_t pixel = 0; pixel < work.traced.size(); ++pixel)
      if (work.traced[pixel]) traced.push_back(pixel);
    statistics.cycles = traced.empty() ? 0 : simulateFrame(work, traced);
  } else {
    statistics.cycles = frameCycles(work.issuedPerRow);
  }
  remember(result, work);
  statistics.frame = frame;
  statistics.time = scene_.timeOf(frame);
  statistics.clockMhz = options_.clockMhz;
  statistics.pixels = work.pixels.size();
  result.pixels = std::move(work.pixels);
  statistics.hostSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void AnimationRenderer::prime(int frame) {
  SceneFrame result;
  Work work = trace(frame, result);
  remember(result, work);
}

// The frame's camera and instances, and every pixel through the hit buffer or the golden scene
// manager, in parallel threads.
AnimationRenderer::Work AnimationRenderer::trace(int frame, SceneFrame& result) {
  const double time = scene_.timeOf(frame);
  result.camera = scene_.camera.at(time, scene_.width, scene_.height);
  for (const InstanceDescription& instance : scene_.instances)
    result.placements.push_back(instance.placement.at(time));

  Work work;
  work.camera = result.camera;
  work.instances = memory_.place(result.placements);
  work.pixels.resize(result.camera.pixelCount());
  work.issuedPerRow.resize(static_cast<size_t>(result.camera.height));
  work.traced.resize(result.camera.pixelCount());
  const int threads = std::min(options_.threads, result.camera.height);
  work.perThread.resize(static_cast<size_t>(threads));

  std::vector<uint8_t> moved(memory_.instanceCount(), 1);
  for (size_t i = 0; i < moved.size() && !lastHeaders_.empty(); ++i)
    moved[i] = memory_.headerWords(i) != lastHeaders_[i];
  hitBuffer_.beginFrame(!lastCamera_ || !sameCamera(*lastCamera_, result.camera), moved);

  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back([&work, t, threads, this] { traceRows(work, t, threads); });
  traceRows(work, 0, threads);
  for (std::thread& thread : pool) thread.join();
  return work;
}

// What the next frame's hit buffer compares with.
void AnimationRenderer::remember(const SceneFrame& frame, const Work& work) {
  for (size_t pixel = 0; pixel < work.pixels.size(); ++pixel)
    hitBuffer_.store(pixel, work.pixels[pixel]);
  lastCamera_ = frame.camera;
  lastHeaders_.clear();
  for (size_t i = 0; i < memory_.instanceCount(); ++i)
    lastHeaders_.push_back(memory_.headerWords(i));
}

}  // namespace rtu
