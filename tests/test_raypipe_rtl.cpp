// The ray pipe's models against the cycles recorded from the seed's own RTL (issue 29 §3;
// tests/data/raypipe_rtl/README.md): R1's DEMOS/t5.sv under Verilator, frame and per-pixel exit
// cycles, colours and sources for R1's scenes t4s3_color_aabb and bunny_color_aabb. The PRG's rays
// of a level run through the per-cycle reference (runRaypipeCycles) and the timed model
// (runRaypipeTimed); every pixel's exit cycle, one less than the RTL's frame cycle (the README's
// numbering: rtusim's cycle 0 is the RTL's cycle 1), its colour and source, and the frame's last
// exit are compared. The 4-triangle scene is rebuilt here from its corners (facts) with the pbrt
// builder, so its runs need no R1 file; the bunny's read R1's file from RTUSIM_TRAYRACER_DIR and
// warn without it. docs/raypipe.md, "Against the RTL", gives the figures.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "kinds/kd/kd_image.h"
#include "kinds/kd/pbrt_kd_builder.h"
#include "kinds/kd/trayracer_scene.h"
#include "raypipe/primary_rays.h"
#include "raypipe/simple_shader.h"
#include "reference/raypipe_cycles.h"
#include "sim/raypipe/raypipe_timed.h"
#include "trayracer_r1.h"

namespace rtu {
namespace {

// R1's SCENES/t4s3_color_aabb.scene: four triangles in the box (0,0,0)-(2,2,2), world space (the
// file's UTTMs inverted, the float24 noise rounded off; the byte-for-byte test below confirms
// them), three corners each in the file's order; every triangle's vertex-0 normal is (0, 1, 0) in
// world space, its ambient colour (1, 1, 1) and its specular 0.5.
std::vector<glm::dvec3> t4s3Corners() {
  return {{2, 0, 0}, {0, 0, 1},   {0, 0.8, 2},  // triangle 0
          {2, 2, 1}, {2, 1.4, 0}, {1.5, 2, 0},  // triangle 1
          {0, 2, 0}, {0, 1.1, 0}, {0, 2, 2},    // triangle 2
          {0, 2, 2}, {0, 1, 2},   {2, 2, 2}};   // triangle 3
}

TrayRacerScene buildT4s3() {
  const std::vector<glm::dvec3> corners = t4s3Corners();
  const KdBuild build = buildPbrtKd(pbrtTriangleBoxes(corners), PbrtKdParameters{});
  const std::vector<glm::dvec3> normals(corners.size() / 3, glm::dvec3(0, 1, 0));
  return makeTrayRacerScene(build, corners, normals, {{1.0, 1.0, 1.0}, 0.5});
}

// t4s3 as the hardware loads it: the file written, then read back (the 28-bit splits).
KdImage t4s3Image() {
  return layOutKd(readTrayRacerScene(writeTrayRacerScene(buildT4s3(), TrayRacerFormat::Narrow),
                                     TrayRacerFormat::Narrow));
}

struct RtlPixel {
  uint32_t pixelId = 0;
  int64_t exitCycle = 0;  // rtusim's numbering: the CSV's minus 1
  uint16_t color = 0;
  std::string source;
};

std::vector<RtlPixel> readRtlCsv(const std::string& run) {
  const std::string path = std::string(RTUSIM_TEST_DATA) + "/raypipe_rtl/" + run + ".csv";
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot open " + path);
  std::string line;
  std::getline(file, line);  // pixel_id,exit_cycle,color565,source
  std::vector<RtlPixel> pixels;
  while (std::getline(file, line)) {
    std::istringstream row(line);
    std::string field;
    RtlPixel p;
    std::getline(row, field, ',');
    p.pixelId = static_cast<uint32_t>(std::stoul(field));
    std::getline(row, field, ',');
    p.exitCycle = std::stoll(field) - 1;
    std::getline(row, field, ',');
    p.color = static_cast<uint16_t>(std::stoul(field));
    std::getline(row, p.source, ',');
    pixels.push_back(p);
  }
  return pixels;
}

const char* sourceOf(const RaypipeCycleResult& r) {
  return r.boxMiss ? "box_miss" : (r.hit ? "hit" : "miss");
}

struct RtlComparison {
  size_t pixels = 0, exitEqual = 0, colourEqual = 0, sourceEqual = 0;
  int64_t modelLast = -1, rtlLast = -1;
  std::string firstDifferences;  // up to a few pixels that differ, for the report
};

RtlComparison compareWithRtl(const RaypipeCycleRun& run, const std::vector<RtlPixel>& rtl) {
  RtlComparison c;
  std::vector<const RaypipeCycleResult*> byId(run.results.size(), nullptr);
  for (const RaypipeCycleResult& r : run.results)
    if (r.pixelId < byId.size()) byId[r.pixelId] = &r;
  int shown = 0;
  for (const RtlPixel& p : rtl) {
    ++c.pixels;
    c.rtlLast = std::max(c.rtlLast, p.exitCycle);
    const RaypipeCycleResult* r = p.pixelId < byId.size() ? byId[p.pixelId] : nullptr;
    if (!r) continue;
    const bool exit = r->exitCycle == p.exitCycle;
    const bool colour = simpleShade(r->boxMiss, r->hit, r->primitive) == p.color;
    const bool source = p.source == sourceOf(*r);
    c.exitEqual += exit;
    c.colourEqual += colour;
    c.sourceEqual += source;
    if ((!exit || !colour || !source) && shown++ < 4) {
      std::ostringstream s;
      s << " [pixel " << p.pixelId << ": rtl " << p.exitCycle << " " << p.source << " " << p.color
        << ", model " << r->exitCycle << " " << sourceOf(*r) << " "
        << simpleShade(r->boxMiss, r->hit, r->primitive) << "]";
      c.firstDifferences += s.str();
    }
  }
  c.modelLast = run.lastExitCycle;
  return c;
}

std::vector<RaypipeCycleRay> rtlRays(const RaypipeCamera& camera, int level) {
  std::vector<RaypipeCycleRay> rays;
  for (const PrimaryRay& p : primaryRays(camera, prgLevelSize(level)))
    rays.push_back(RaypipeCycleRay{p.ray, p.pixel.pixelId});
  return rays;
}

// The close camera of the `_close` runs: E = (1.27, 0.88, 0), U, V, W the axes.
RaypipeCamera closeCamera() {
  RaypipeCamera camera;
  camera.eye = {1.27f, 0.88f, 0.0f};
  return camera;
}

// A recorded run: the README's table. The VGA reader's phase is the absolute cycle of rtusim's
// cycle 0: the RTL's frame cycle 0 ("start (abs)", counted in cycles after reset's release) + 1.
struct RtlRun {
  std::string name;  // the CSV's name
  int level = 0;
  bool close = false;
  int64_t renderingDone = 0;  // the RTL's rendering_done, its frame cycle
  int64_t start = 0;          // "start (abs)"
  int64_t lastAccept = 0;     // the PRG's last accept (x_y_valid), its frame cycle
};

std::vector<RtlRun> t4s3Runs() {
  return {{"t4s3_color_aabb_l0", 0, false, 1178, 5207, 898},
          {"t4s3_color_aabb_l1", 1, false, 3799, 5207, 3598},
          {"t4s3_color_aabb_l2", 2, false, 15723, 5207, 15607},
          {"t4s3_color_aabb_l3", 3, false, 65064, 5207, 64993}};
}

std::vector<RtlRun> bunnyRuns() {
  return {{"bunny_color_aabb_l0", 0, false, 3570, 153161, 898},
          {"bunny_color_aabb_l1", 1, false, 6066, 153161, 3598},
          {"bunny_color_aabb_l2", 2, false, 15788, 153161, 14398},
          {"bunny_color_aabb_l3", 3, false, 60096, 153161, 60025},
          {"bunny_color_aabb_l0_close", 0, true, 6284, 153161, 898},
          {"bunny_color_aabb_l1_close", 1, true, 18039, 153161, 7867},
          {"bunny_color_aabb_l2_close", 2, true, 68408, 153161, 58102},
          {"bunny_color_aabb_l3_close", 3, true, 274766, 153161, 269200}};
}

std::string describe(const char* model, const RtlComparison& c) {
  std::ostringstream s;
  s << model << ": exit " << c.exitEqual << "/" << c.pixels << ", colour " << c.colourEqual << "/"
    << c.pixels << ", source " << c.sourceEqual << "/" << c.pixels << ", last exit " << c.modelLast
    << " (rtl " << c.rtlLast << ")" << c.firstDifferences;
  return s.str();
}

// Both models on a run, with the VGA reader's window at the run's phase (t5.sv as simulated) or
// without it (the writer free every cycle); `expectExact`: every figure must equal the RTL's, else
// they are reported. `division`: the divider the models take (raypipe.division).
void checkAgainstRtl(const KdImage& image, const RtlRun& run, bool vgaWindow, bool expectExact,
                     Division division = Division::Ieee) {
  INFO(run.name << (vgaWindow ? " with the VGA window" : " without the VGA window")
                << (division == Division::Altfp ? ", altfp_div" : ""));
  const std::vector<RtlPixel> rtl = readRtlCsv(run.name);
  const std::vector<RaypipeCycleRay> rays =
      rtlRays(run.close ? closeCamera() : RaypipeCamera{}, run.level);
  REQUIRE(rtl.size() == rays.size());
  RaypipeConfig config;
  config.division = division;
  RaypipeCycleOptions options;
  options.writer.vgaReadWindow = vgaWindow;
  options.writer.vgaPhase = run.start + 1;
  const RaypipeCycleRun refRun = runRaypipeCycles(config, image, rays, options);
  const RaypipeCycleRun timedRun = runRaypipeTimed(config, image, rays, options);
  const RtlComparison ref = compareWithRtl(refRun, rtl);
  const RtlComparison timed = compareWithRtl(timedRun, rtl);
  INFO(describe("reference", ref));
  INFO(describe("timed", timed));
  if (!expectExact) {
    WARN(run.name << (vgaWindow ? "" : " (no VGA window)") << ": " << describe("reference", ref)
                  << ", last write " << refRun.lastWriteCycle << "; " << describe("timed", timed)
                  << ", last write " << timedRun.lastWriteCycle << " (rtl rendering_done "
                  << run.renderingDone - 1 << ")");
    return;
  }
  CHECK(ref.exitEqual == ref.pixels);
  CHECK(ref.colourEqual == ref.pixels);
  CHECK(ref.sourceEqual == ref.pixels);
  CHECK(ref.modelLast == ref.rtlLast);
  CHECK(timed.exitEqual == timed.pixels);
  CHECK(timed.colourEqual == timed.pixels);
  CHECK(timed.sourceEqual == timed.pixels);
  CHECK(timed.modelLast == timed.rtlLast);
  // the PRG's first and last accepts
  for (const RaypipeCycleRun* r : {&refRun, &timedRun}) {
    CHECK(r->results.front().issueCycle == 0);
    CHECK(r->results.back().issueCycle == run.lastAccept - 1);
  }
  // rendering_done comes with the writer's take of the frame's last pixel
  if (vgaWindow) {
    CHECK(refRun.lastWriteCycle == run.renderingDone - 1);
    CHECK(timedRun.lastWriteCycle == run.renderingDone - 1);
  }
}

TEST_CASE("t4s3 rebuilt from its corners equals R1's t4s3_color_aabb.scene byte for byte",
          "[raypipe_rtl][kd_r1]") {
  const std::vector<uint8_t> built = writeTrayRacerScene(buildT4s3(), TrayRacerFormat::Narrow);
  CHECK(built.size() == 324);
  if (!trayRacerDir()) {
    WARN("RTUSIM_TRAYRACER_DIR unset (scripts/extract_trayracer.sh): R1's file not compared");
    return;
  }
  const std::vector<uint8_t> r1Bytes =
      readBytes(std::string(trayRacerDir()) + "/SCENES/t4s3_color_aabb.scene");
  // Section by section, so that a failure says which.
  const TrayRacerScene ours = readTrayRacerScene(built, TrayRacerFormat::Narrow);
  const TrayRacerScene r1 = readTrayRacerScene(r1Bytes, TrayRacerFormat::Narrow);
  CHECK(ours.box == r1.box);
  CHECK(ours.nodes == r1.nodes);
  CHECK(ours.lists == r1.lists);
  for (size_t i = 0; i < std::min(ours.uttms.size(), r1.uttms.size()); ++i) {
    INFO("triangle " << i);
    CHECK(ours.uttms[i] == r1.uttms[i]);
    CHECK(ours.shades[i] == r1.shades[i]);
  }
  CHECK(built == r1Bytes);
}

// The CI's check: no R1 file needed. With the VGA reader's window (the pixel buffer fills at
// 160x120), every figure; without it, levels 0-2, where the buffer never fills.
TEST_CASE("raypipe models against the RTL: t4s3 levels 0-3", "[raypipe_rtl]") {
  const KdImage image = t4s3Image();
  for (const RtlRun& run : t4s3Runs()) {
    checkAgainstRtl(image, run, true, true);
    if (run.level <= 2) checkAgainstRtl(image, run, false, true);
  }
}

// The shipped divider's own algorithm (raypipe.division = altfp_div) gives the RTL's figures too.
TEST_CASE("raypipe models against the RTL: t4s3 levels 0-3 with altfp_div", "[raypipe_rtl]") {
  const KdImage image = t4s3Image();
  for (const RtlRun& run : t4s3Runs()) checkAgainstRtl(image, run, true, true, Division::Altfp);
}

// A run recorded as frame figures only (README's table: no per-pixel CSV at the larger sizes).
struct RtlFrame {
  int level = 0;
  bool close = false;
  size_t hits = 0, misses = 0, boxMisses = 0;
  int64_t lastAccept = 0, lastExit = 0, renderingDone = 0, start = 0;  // the RTL's frame cycles
};

// `expectExact` false: the models must agree with each other; the RTL's figures are reported.
void checkFrameFigures(const KdImage& image, const RtlFrame& f, bool expectExact = true) {
  INFO("level " << f.level << (f.close ? ", the close camera" : ""));
  const std::vector<RaypipeCycleRay> rays =
      rtlRays(f.close ? closeCamera() : RaypipeCamera{}, f.level);
  RaypipeCycleOptions options;
  options.writer.vgaReadWindow = true;
  options.writer.vgaPhase = f.start + 1;
  const RaypipeCycleRun ref = runRaypipeCycles(RaypipeConfig{}, image, rays, options);
  const RaypipeCycleRun timed = runRaypipeTimed(RaypipeConfig{}, image, rays, options);
  for (const RaypipeCycleRun& run : {ref, timed}) {
    size_t hits = 0, misses = 0, boxMisses = 0;
    for (const RaypipeCycleResult& r : run.results) {
      hits += r.hit;
      boxMisses += r.boxMiss;
      misses += !r.hit && !r.boxMiss;
    }
    if (!expectExact) {
      CHECK(run.lastExitCycle == ref.lastExitCycle);
      CHECK(run.lastWriteCycle == ref.lastWriteCycle);
      WARN("level " << f.level << ": model hits / misses / box misses " << hits << " / " << misses
                    << " / " << boxMisses << ", last accept " << run.results.back().issueCycle
                    << ", last exit " << run.lastExitCycle << "; RTL " << f.hits << " / "
                    << f.misses << " / " << f.boxMisses << ", " << f.lastAccept - 1 << ", "
                    << f.lastExit - 1 << "; stale list hits in the model " << run.staleListHits);
      continue;
    }
    CHECK(hits == f.hits);
    CHECK(misses == f.misses);
    CHECK(boxMisses == f.boxMisses);
    CHECK(run.results.back().issueCycle == f.lastAccept - 1);
    CHECK(run.lastExitCycle == f.lastExit - 1);
    CHECK(run.lastWriteCycle == f.renderingDone - 1);
  }
}

// t4s3 at 320x240 and 640x480: the pixel buffer full for 4229 and 14343 cycles.
TEST_CASE("raypipe models against the RTL: t4s3 at 320x240 and 640x480\\, the frame figures",
          "[raypipe_rtl]") {
  const KdImage image = t4s3Image();
  checkFrameFigures(image, {4, false, 8802, 28447, 39551, 278251, 278321, 278322, 5207});
  checkFrameFigures(image, {5, false, 35059, 113166, 158975, 1149202, 1149272, 1149274, 5207});
}

TEST_CASE("raypipe models against the RTL: the bunny's frame figures", "[raypipe_rtl][kd_r1]") {
  if (!trayRacerDir()) {
    WARN(
        "RTUSIM_TRAYRACER_DIR unset (scripts/extract_trayracer.sh): the bunny's runs not compared");
    return;
  }
  const KdImage bunny = layOutKd(
      readTrayRacerScene(readBytes(std::string(trayRacerDir()) + "/SCENES/bunny_color_aabb.scene"),
                         TrayRacerFormat::Narrow));
  checkFrameFigures(bunny, {4, false, 2023, 2947, 71830, 280654, 280724, 280726, 153161});
  // 640x480: the RTL's classes differ from the models' (and the golden traversal's, which the
  // models equal): docs/raypipe.md, "Against the RTL".
  checkFrameFigures(bunny, {5, false, 5387, 15481, 286332, 1379386, 1379456, 1379458, 153161},
                    false);
  checkFrameFigures(bunny, {4, true, 11508, 34926, 30366, 1099528, 1099598, 1099600, 153161});
}

TEST_CASE("raypipe models against the RTL: bunny levels 0-3 and the close camera at 0-3",
          "[raypipe_rtl][kd_r1]") {
  if (!trayRacerDir()) {
    WARN(
        "RTUSIM_TRAYRACER_DIR unset (scripts/extract_trayracer.sh): the bunny's runs not compared");
    return;
  }
  const KdImage bunny = layOutKd(
      readTrayRacerScene(readBytes(std::string(trayRacerDir()) + "/SCENES/bunny_color_aabb.scene"),
                         TrayRacerFormat::Narrow));
  for (const RtlRun& run : bunnyRuns()) {
    checkAgainstRtl(bunny, run, true, true);
    checkAgainstRtl(bunny, run, true, true, Division::Altfp);
  }
}

// A report of every recorded run (both models, all counts), for docs/raypipe.md.
TEST_CASE("raypipe models against the RTL: report", "[.raypipe_rtl_report]") {
  const KdImage t4s3 = t4s3Image();
  for (const RtlRun& run : t4s3Runs()) {
    checkAgainstRtl(t4s3, run, true, false);
    checkAgainstRtl(t4s3, run, false, false);
  }
  if (!trayRacerDir()) return;
  const KdImage bunny = layOutKd(
      readTrayRacerScene(readBytes(std::string(trayRacerDir()) + "/SCENES/bunny_color_aabb.scene"),
                         TrayRacerFormat::Narrow));
  for (const RtlRun& run : bunnyRuns()) {
    checkAgainstRtl(bunny, run, true, false);
    checkAgainstRtl(bunny, run, false, false);
  }
}

}  // namespace
}  // namespace rtu
