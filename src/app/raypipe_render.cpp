#include "app/raypipe_render.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <future>
#include <optional>
#include <ostream>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "app/frame_images.h"
#include "app/raypipe_trace.h"
#include "app/results_csv.h"
#include "base/output_file.h"
#include "config/run_json.h"
#include "explore/raypipe_frame.h"
#include "raypipe/raypipe_golden.h"
#include "raypipe/raypipe_statistics.h"
#include "raypipe/simple_shader.h"
#include "run/statistics_output.h"
#include "sim/raypipe/raypipe_timed.h"

namespace rtu {
namespace {

// Each component in its shortest exact form.
std::string registerText(const std::array<float, 3>& value) {
  std::string text;
  for (float component : value) {
    char digits[32];
    char* end = std::to_chars(digits, digits + sizeof digits, component).ptr;
    text += (text.empty() ? "" : ",") + std::string(digits, static_cast<size_t>(end - digits));
  }
  return text;
}

// A setting's value as the configuration writes it.
std::string settingText(const std::string& key, const RunConfig& settings) {
  return findSetting(key).get(settings);
}

std::string perRay(uint64_t count, uint64_t rays) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", rays ? static_cast<double>(count) / rays : 0.0);
  return text;
}

void report(const RaypipeScene& scene, const RunConfig& settings, const RaypipeCamera& registers,
            const RaypipeGoldenFrame& frame, double seconds, std::ostream& out) {
  const PrgFrameSize size = raypipeFrameSize(settings);
  const RaypipeConfig& pipe = settings.raypipe;  // its short stack
  const RaypipeFrameTotals& t = frame.totals;
  const std::string level = settings.raypipeView.level >= 0
                                ? " (level " + std::to_string(settings.raypipeView.level) + ")"
                                : "";
  out << "scene       " << scene.name << ": " << scene.description << "\n"
      << "model       "
      << (settings.model == ModelKind::CycleAccurate
              ? "ca (the timed model, cycle for cycle the per-cycle reference)"
              : "golden")
      << ", ray pipe (seed 001): short stack " << pipe.shortStackDepth << ", divider "
      << settingText("raypipe.division", settings) << ", t_max "
      << settingText("raypipe.tmax_clamp", settings) << "\n"
      << "frame       " << size.width << "x" << size.height << level << "\n"
      << "camera      E " << registerText(registers.eye) << "  U " << registerText(registers.u)
      << "  V " << registerText(registers.v) << "  W " << registerText(registers.w) << "\n"
      << "rays        " << t.rays << ": " << t.boxMisses << " box misses, " << t.hits << " hits, "
      << t.rays - t.hits - t.boxMisses << " misses\n"
      << "traversal   " << perRay(t.nodes, t.rays) << " nodes/ray, "
      << perRay(t.triangleTests, t.rays) << " triangle tests/ray, " << t.pushes << " pushes, "
      << t.restarts << " restarts, " << t.dropped << " stack entries dropped\n";
  char host[96];
  std::snprintf(host, sizeof host, "host        %.3f s, %.2f M rays/s (golden model)\n", seconds,
                t.rays / seconds / 1e6);
  out << host;
  for (const std::string& warning : scene.warnings) out << "warning     " << warning << "\n";
}

// The frame on the timed model (sim/raypipe), from the PRG's rays in issue order, checked: its
// results must be the golden frame's, pixel by pixel; anything else is a model defect, never a
// number.
RaypipeCycleRun checkedTimedFrame(RaypipeCycleRun run, const RaypipeGoldenFrame& golden) {
  for (size_t i = 0; i < run.results.size(); ++i) {
    const RaypipeCycleResult& timed = run.results[i];
    const RaypipePixel& expected = golden.pixels[i];
    if (timed.hit != expected.hit || timed.boxMiss != expected.boxMiss ||
        timed.primitive != expected.primitive || !(timed.t == expected.t))
      throw std::logic_error(
          "the ray pipe's timed model and its golden traversal differ at pixel " +
          std::to_string(expected.pixel.pixelId) + " (a model defect)");
  }
  return run;
}

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100.0 * share);
  return text;
}

double shareOf(int64_t part, int64_t whole) {
  return whole ? static_cast<double>(part) / static_cast<double>(whole) : 0.0;
}

// With the set-associative caches: each one's hits, misses and refused cycles, and the DRAM's
// reads.
void reportCaches(const RaypipeCycleRun& run, std::ostream& out) {
  if (run.caches.empty()) return;
  out << "caches     ";
  for (const RaypipeCacheCounts& c : run.caches)
    out << " " << c.cache << " " << percent(shareOf(c.hits, c.hits + c.misses)) << " hits of "
        << c.hits + c.misses << ", " << c.stalls << " cycles refused;";
  out << "\ndram        " << run.dram.reads << " lines, " << run.dram.bytes << " bytes, bus busy "
      << percent(shareOf(run.dram.busyCycles, run.frameCycles)) << "\n";
}

// The timed frame's lines: frame cycles and rate at the pipe's clock, the busiest units, where
// rays waited, and the FIFOs that filled.
void reportTiming(const RaypipeCycleRun& run, const RaypipeConfig& config, std::ostream& out) {
  const double ms = run.frameCycles / (config.clockMHz * 1e3);
  char line[160];
  std::snprintf(line, sizeof line,
                "timing      %lld cycles at %g MHz: frame %.3f ms, %.2f frames/s, %.3f "
                "rays/cycle\n",
                static_cast<long long>(run.frameCycles), config.clockMHz, ms, 1e3 / ms,
                static_cast<double>(run.results.size()) / run.frameCycles);
  out << line;
  // Busiest by utilisation: a unit's share of its full rate (the PRG's and SINT's one ray in 3
  // cycles), per copy when there are two traversal units.
  const RaypipeStatistics statistics = RaypipeStatistics::of(run, config);
  std::vector<RaypipeUnitStatistics> busiest = statistics.units;
  std::stable_sort(busiest.begin(), busiest.end(), [&](const auto& a, const auto& b) {
    return statistics.utilisation(a) > statistics.utilisation(b);
  });
  out << "busiest    ";
  for (size_t i = 0; i < busiest.size() && i < 4; ++i)
    out << " " << busiest[i].unit << " " << percent(statistics.utilisation(busiest[i])) << ";";
  std::vector<RaypipeUnitActivity> units = run.units;
  std::sort(units.begin(), units.end(),
            [](const auto& a, const auto& b) { return a.stall > b.stall; });
  out << "\nstalled    ";
  for (size_t i = 0; i < units.size() && i < 3 && units[i].stall > 0; ++i)
    out << " " << units[i].unit << " " << units[i].stall << " cycles;";
  out << "\nfifos      ";
  int full = 0;
  for (const RaypipeFifoPeak& fifo : run.fifos)
    if (fifo.peak >= fifo.depth) out << (full++ ? ", " : " full at some point: ") << fifo.fifo;
  if (full == 0) out << " none filled";
  out << "; " << run.maxRaysInFlight << " of " << config.raysInFlight
      << " ray ids in flight at most\n";
  out << "writer      "
      << (config.vgaWindow
              ? std::to_string(run.writerWaits) +
                    " cycles a pixel waited for the VGA reader (phase " +
                    std::to_string(config.vgaPhase) + ")"
              : std::string("the SRAM writer takes a pixel every cycle (no VGA window)"))
      << "\n";
  reportCaches(run, out);
  std::snprintf(line, sizeof line, "host        %.3f s timed model, %.2f M rays/s\n",
                run.hostSeconds, run.results.size() / run.hostSeconds / 1e6);
  out << line;
}

// The timed frame's statistics (raypipe/raypipe_statistics.h) as a run's JSON, as a row has them.
void writeStats(const RaypipeCycleRun& run, const Configuration& configuration,
                const std::string& path) {
  const RaypipeStatistics statistics = RaypipeStatistics::of(run, configuration.values().raypipe);
  writeTextFile(path, runJson(statisticsJson(statistics), configuration).dump(2) + "\n");
}

std::vector<std::string> extraColumns(bool timed) {
  std::vector<std::string> columns = {"x",      "y",       "box_miss", "nodes", "triangle_tests",
                                      "pushes", "restarts"};
  if (timed) columns.insert(columns.end(), {"issue_cycle", "exit_cycle"});
  return columns;
}

std::vector<ResultRow> resultRows(const RaypipeGoldenFrame& frame, const RaypipeCycleRun* timed) {
  std::vector<ResultRow> rows;
  rows.reserve(frame.pixels.size());
  for (size_t i = 0; i < frame.pixels.size(); ++i) {
    const RaypipePixel& p = frame.pixels[i];
    ResultRow row{p.pixel.pixelId, p.hit, p.t, p.primitive, p.u, p.v, {}};
    row.extra = {static_cast<uint64_t>(p.pixel.x),
                 static_cast<uint64_t>(p.pixel.y),
                 p.boxMiss,
                 p.counts.nodes,
                 p.counts.triangleTests,
                 p.counts.pushes,
                 p.counts.restarts};
    if (timed)
      row.extra.insert(row.extra.end(), {static_cast<uint64_t>(timed->results[i].issueCycle),
                                         static_cast<uint64_t>(timed->results[i].exitCycle)});
    rows.push_back(std::move(row));
  }
  return rows;
}

void writePaletteImage(const RaypipeGoldenFrame& frame, PrgFrameSize size,
                       const std::string& path) {
  std::vector<float> rgb(static_cast<size_t>(size.width) * size.height * 3);
  for (const RaypipePixel& p : frame.pixels) {
    const std::array<uint8_t, 3> colour = rgb888(simpleShade(p.boxMiss, p.hit, p.primitive));
    for (int c = 0; c < 3; ++c) rgb[p.pixel.pixelId * 3 + c] = colour[c] / 255.0f;
  }
  writeRgbImage(path, size.width, size.height, rgb);
}

}  // namespace

RenderedFrame raypipeRenderedFrame(const RaypipeGoldenFrame& frame,
                                   const std::vector<PrimaryRay>& rays,
                                   const std::vector<glm::dvec3>& normals,
                                   const RaypipeCamera& registers, PrgFrameSize size) {
  RenderedFrame rendered(cameraOfRegisters(registers, size.width, size.height));
  for (size_t i = 0; i < frame.pixels.size(); ++i) {
    const RaypipePixel& p = frame.pixels[i];
    FramePixel pixel;
    pixel.hit = p.hit;
    pixel.cost = p.cost;
    if (p.hit) {
      const auto& d = rays[i].ray.direction;
      pixel.t = p.t * glm::length(glm::dvec3(d[0], d[1], d[2]));
      pixel.triangle = p.primitive;
      if (p.primitive < normals.size()) pixel.normal = normals[p.primitive];
    }
    rendered.place(p.pixel.pixelId, pixel);
  }
  return rendered;
}

void addRaypipeRenderOptions(CLI::App& command, RaypipeRenderOptions& options) {
  command.add_option("--accel-file", options.accelFile,
                     "ray pipe: the scene as a k-d image (.kd) or the seed's scene file (narrow "
                     "unless --index wide) instead of building the scene's triangles");
  command.add_option("--results-csv", options.resultsCsv,
                     "ray pipe: one row per ray in issue order (id = the seed's pixel id, x, y, "
                     "hit, box_miss, t, primitive, u, v and the ray's counts)");
  command.add_option("--shaded-image", options.shadedImage,
                     "ray pipe: Lambert-shaded image (--image is the simple shader's palette)");
}

void checkRaypipeOnly(const RaypipeRenderOptions& options) {
  std::vector<NamedPath> given = options.paths();
  given.push_back({"--accel-file", options.accelFile});
  for (const NamedPath& file : given)
    if (!file.path.empty())
      throw std::invalid_argument(file.option + " is written for --architecture raypipe");
}

void checkRaypipeModel(ModelKind model) {
  if (model == ModelKind::LooselyTimed)
    throw std::invalid_argument("--model lt: the ray pipe has no loosely-timed form; its timed "
                                "model (--model ca) is exact and costs per ray already");
}

void renderRaypipe(const Configuration& configuration, const FrameImagePaths& images,
                   const RaypipeRenderOptions& options, const RunOutputs& outputs,
                   std::ostream& out) {
  const std::string& statsPath = outputs.statsPath;
  const RunConfig& settings = configuration.values();
  settings.raypipe.validate();
  if (settings.model == ModelKind::CycleAccurate) checkRaypipeTimedTakes(settings.raypipe);
  const PrgFrameSize size = raypipeFrameSize(settings);
  const RaypipeCamera registers = settings.raypipeView.camera.resolve(settings.camera);
  const RaypipeScene scene = loadRaypipeScene(settings, options.accelFile);
  const std::vector<PrimaryRay> rays = primaryRays(registers, size);
  if (scene.normals.empty() && !options.shadedImage.empty())
    throw std::invalid_argument("--shaded-image needs the triangles' normals: a k-d image holds "
                                "none (give the mesh, or the seed's scene file)");
  // The timed frame on a thread of its own while the golden frame runs (they share nothing but
  // their inputs): the frame's wall time is the longer of the two, not their sum.
  std::future<RaypipeCycleRun> timedRun;
  if (settings.model == ModelKind::CycleAccurate)
    timedRun = std::async(std::launch::async,
                          [&] { return runRaypipeFrame(settings.raypipe, scene.image, rays); });
  const auto start = std::chrono::steady_clock::now();
  const RaypipeGoldenFrame frame = runGoldenFrame(scene.image, rays, settings.raypipe);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report(scene, settings, registers, frame, seconds, out);
  std::optional<RaypipeCycleRun> timed;
  if (settings.model == ModelKind::CycleAccurate) {
    timed = checkedTimedFrame(timedRun.get(), frame);
    reportTiming(*timed, settings.raypipe, out);
    if (!statsPath.empty()) writeStats(*timed, configuration, statsPath);
    writeRaypipeTraces(settings.raypipe, scene.image, rays, *timed, outputs, out);
  }
  if (!options.resultsCsv.empty())
    writeResultsCsv(options.resultsCsv, resultRows(frame, timed ? &*timed : nullptr),
                    extraColumns(timed.has_value()));
  if (!images.image.empty()) writePaletteImage(frame, size, images.image);
  if (!options.shadedImage.empty() || !images.depthImage.empty() || !images.costImage.empty()) {
    const RenderedFrame rendered =
        raypipeRenderedFrame(frame, rays, scene.normals, registers, size);
    if (!options.shadedImage.empty()) writeShadedImage(rendered, options.shadedImage);
    if (!images.depthImage.empty()) writeDepthImage(rendered, images.depthImage);
    if (!images.costImage.empty()) writeCostImage(rendered, images.costImage);
  }
  for (const std::string* path : {&statsPath, &options.resultsCsv, &images.image,
                                  &options.shadedImage, &images.depthImage, &images.costImage})
    if (!path->empty()) out << "wrote       " << *path << "\n";
}

}  // namespace rtu
