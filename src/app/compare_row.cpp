#include "app/compare_row.h"

#include <chrono>

#include <glm/geometric.hpp>

#include "app/frame_outputs.h"
#include "app/raypipe_render.h"
#include "config/config_schema.h"
#include "explore/architecture_resources.h"
#include "explore/exploration_run.h"
#include "explore/frame_agreement.h"
#include "explore/frame_scene.h"
#include "explore/raypipe_frame.h"
#include "explore/reference_frame.h"
#include "kinds/kd/trayracer_scene.h"
#include "run/analytic_run.h"

namespace rtu {
namespace {

using Json = nlohmann::ordered_json;

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<FrameHit> frameHits(const RenderedFrame& frame) {
  std::vector<FrameHit> hits;
  hits.reserve(frame.pixels.size());
  for (const FramePixel& pixel : frame.pixels) hits.push_back({pixel.hit, pixel.t, pixel.triangle});
  return hits;
}

// What an architecture's frame is measured with: its pixels from the golden model, whose results
// the timed models equal (the equivalence tests over every kind, the pipe's fidelity tests), and
// the reference of its rays.
struct MeasuredFrame {
  std::vector<FrameHit> hits;
  std::vector<std::optional<OracleHit>> reference;
};

// The ray pipe's rays are its PRG's (through a corner of each pixel, in binary32, in hardware
// space where its scene lies), so its reference traces them, moved into the world.
std::vector<std::optional<OracleHit>> raypipeReference(const std::vector<PrimaryRay>& rays,
                                                       const ModelPlacement& placement,
                                                       const ReferenceTracer& tracer) {
  std::vector<std::optional<OracleHit>> reference(rays.size());
  for (const PrimaryRay& primary : rays) {
    const auto world = [](const std::array<float, 3>& v) {
      return toHardwareSpace(glm::dvec3(v[0], v[1], v[2]));  // its own inverse
    };
    Ray ray;
    ray.origin =
        placement.translation + placement.rotation * (placement.scale * world(primary.ray.origin));
    ray.direction =
        glm::normalize(placement.rotation * (placement.scale * world(primary.ray.direction)));
    reference.at(primary.pixel.pixelId) = tracer.trace(ray);
  }
  return reference;
}

MeasuredFrame measuredFrame(const CompareTarget& target, const FrameScene& scene,
                            const CompareReference& shared) {
  const RunConfig& settings = target.configuration.values();
  if (settings.architecture == Architecture::Raypipe) {
    const PrgFrameSize size = raypipeFrameSize(settings);
    const RaypipeCamera registers = settings.raypipeView.camera.resolve(settings.camera);
    const std::vector<PrimaryRay> rays = primaryRays(registers, size);
    RenderedFrame frame = raypipeRenderedFrame(runGoldenFrame(scene.words, rays, settings.raypipe),
                                               rays, {}, registers, size);
    for (FramePixel& pixel : frame.pixels) pixel.t *= target.raypipePlacement.scale.x;
    return {frameHits(frame), raypipeReference(rays, target.raypipePlacement, shared.tracer)};
  }
  const std::vector<CoreKindResult> results =
      traceGolden(scene.memory(), frameRecords(scene, settings), settings.rtu);
  return {frameHits(framePixels(settings, scene, results)), shared.frame};
}

ObjectRule objectRule(const RunConfig& settings) {
  const bool voxels = settings.architecture == Architecture::Rtu && settings.rtu.core == "svo";
  return ObjectRule{voxels, settings.scene.depth};
}

Json agreementJson(const ImageAgreement& a) {
  return {{"pixels", a.pixels},
          {"both_hit", a.bothHit},
          {"both_miss", a.bothMiss},
          {"hit_miss_differ", a.hitMissDiffer()},
          {"false_hits", a.falseHits},
          {"missed_hits", a.missedHits},
          {"other_object", a.otherObject},
          {"mean_depth_error", a.meanDepthError},
          {"max_depth_error", a.maxDepthError}};
}

// The statistic at `key` ("memory/l1/hit_rate") as a number, or null.
Json statistic(const Json& statistics, const std::string& key) {
  const Json::json_pointer pointer("/" + key);
  return statistics.contains(pointer) ? statistics[pointer] : Json();
}

Json perRay(const Json& value, double rays) {
  return value.is_number() && rays > 0 ? Json(value.get<double>() / rays) : Json();
}

// The kind's own counter of `what` (nodes_visited, triangle_tests, bytes_fetched), or the ray
// pipe's traversal count; null for the SVO core, which counts none of them.
Json kindCount(const Json& row, const std::string& what) {
  const Json& statistics = row["statistics"];
  if (row["config"]["architecture"] == "raypipe") {
    if (what == "bytes_fetched") return Json();
    return statistic(statistics, "traversal/" + (what == "nodes_visited" ? "nodes" : what));
  }
  return statistic(statistics, row["config"]["core"].get<std::string>() + "_" + what);
}

// Bytes per ray the core fetches: the kind's counter, or for the SVO its L1 accesses of one word.
Json coreBytes(const Json& row) {
  const Json counted = kindCount(row, "bytes_fetched");
  if (!counted.is_null() || row["config"]["architecture"] == "raypipe") return counted;
  const Json accesses = statistic(row["statistics"], "memory/l1/accesses");
  return accesses.is_number() ? Json(4 * accesses.get<double>()) : Json();
}

// Bytes the L2 serves: a line of the L1 for each L2 access.
Json l2Bytes(const Json& row) {
  const Json accesses = statistic(row["statistics"], "memory/l2/accesses");
  const Json& line = row["config"]["memory.l1.line"];
  if (!accesses.is_number() || !line.is_string()) return Json();
  return accesses.get<double>() *
         static_cast<double>(parseBytes(line.get<std::string>(), "memory.l1.line"));
}

}  // namespace

Json compareFigures(const Json& row) {
  const Json& s = row["statistics"];
  const double rays = s["rays"].get<double>();
  const bool raypipe = row["config"]["architecture"] == "raypipe";
  const Json resources = row.contains("resources") ? row["resources"] : Json::object();
  return {{"total_cycles", s["total_cycles"]},
          {"fps", s["fps"]},
          {"frame_ms", s["frame_ms"]},
          {"cycles_per_ray", s["cycles_per_ray"]},
          {"core_bytes_per_ray", perRay(coreBytes(row), rays)},
          {"l2_bytes_per_ray", perRay(l2Bytes(row), rays)},
          {"dram_bytes_per_ray", perRay(statistic(s, "memory/dram/bytes"), rays)},
          {"l1_hit_rate", statistic(s, "memory/l1/hit_rate")},
          {"l2_hit_rate", statistic(s, "memory/l2/hit_rate")},
          {"nodes_per_ray", perRay(kindCount(row, "nodes_visited"), rays)},
          {"tests_per_ray", perRay(kindCount(row, "triangle_tests"), rays)},
          {"utilisation", raypipe ? s["limit_utilisation"] : statistic(s, "utilisation/cores")},
          {"limit", s["limit"]},
          {"limit_utilisation", s["limit_utilisation"]},
          {"memory_bits", resources["memory_bits"]},
          {"bram18k", resources["bram18k"]},
          {"dsp48e", resources["dsp48e"]},
          {"multipliers", resources["multipliers"]},
          {"fps_per_bram18k", perResource(s["fps"], resources["bram18k"])},
          {"fps_per_dsp48e", perResource(s["fps"], resources["dsp48e"])}};
}

Json compareRow(const CompareTarget& target, const CompareReference& reference) {
  Json out = {{"architecture", target.name}, {"preset", target.preset}};
  try {
    const auto start = std::chrono::steady_clock::now();
    const FrameScene scene = loadFrameScene(target.configuration.values());
    const double buildSeconds = secondsSince(start);
    const Json row = runFrameRow(target.configuration, scene, RowModel::RecurrenceWhereExact);
    const MeasuredFrame measured = measuredFrame(target, scene, reference);
    const ObjectRule rule = objectRule(target.configuration.values());
    const Camera& camera = target.configuration.values().camera;
    if (!target.differenceImage.empty())
      writePrecisionImage(camera, pixelVerdicts(camera, measured.hits, measured.reference, rule),
                          target.differenceImage);
    out.update(Json{{"status", "ok"},
                    {"error", ""},
                    {"scene", scene.name},
                    {"structure", scene.description},
                    {"image_bytes", scene.words.size() * sizeof(uint32_t)},
                    {"build_seconds", buildSeconds},
                    {"figures", compareFigures(row)},
                    {"agreement", agreementJson(imageAgreement(camera, measured.hits,
                                                               measured.reference, rule))},
                    {"difference_image", target.differenceImage},
                    {"row", row}});
  } catch (const std::exception& error) {
    out.update(Json{{"status", "failed"}, {"error", error.what()}});
  }
  return out;
}

const std::vector<std::string>& compareColumns() {
  static const std::vector<std::string> columns = {"architecture",
                                                   "preset",
                                                   "image_bytes",
                                                   "build_seconds",
                                                   "total_cycles",
                                                   "fps",
                                                   "frame_ms",
                                                   "cycles_per_ray",
                                                   "core_bytes_per_ray",
                                                   "l2_bytes_per_ray",
                                                   "dram_bytes_per_ray",
                                                   "l1_hit_rate",
                                                   "l2_hit_rate",
                                                   "nodes_per_ray",
                                                   "tests_per_ray",
                                                   "utilisation",
                                                   "limit",
                                                   "limit_utilisation",
                                                   "memory_bits",
                                                   "bram18k",
                                                   "dsp48e",
                                                   "multipliers",
                                                   "fps_per_bram18k",
                                                   "fps_per_dsp48e",
                                                   "pixels",
                                                   "hit_miss_differ",
                                                   "false_hits",
                                                   "missed_hits",
                                                   "other_object",
                                                   "mean_depth_error",
                                                   "max_depth_error",
                                                   "error"};
  return columns;
}

std::vector<std::string> compareFields(const Json& row) {
  std::vector<std::string> fields;
  for (const std::string& column : compareColumns()) {
    const Json* value = nullptr;
    for (const Json* object : {&row, row.contains("figures") ? &row["figures"] : nullptr,
                               row.contains("agreement") ? &row["agreement"] : nullptr})
      if (object && object->contains(column)) value = &(*object)[column];
    fields.push_back(!value || value->is_null() ? std::string() : csvValue(*value));
  }
  return fields;
}

}  // namespace rtu
