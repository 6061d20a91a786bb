#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli_options.h"
#include "commands.h"
#include "frame_images.h"
#include "golden_model.h"
#include "result_summary.h"

namespace rtu {

void addRenderCommand(CLI::App& app) {
  struct Options {
    FrameOptions frame;
    std::string image, depthImage, costImage;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "render", "render one frame of primary rays with the golden model and report it");
  addFrameOptions(*command, options->frame);
  command->add_option("--image", options->image, "shaded image (PNG, EXR, ...)");
  command->add_option("--depth-image", options->depthImage,
                      "depth image: float t in EXR/TIFF, grey levels otherwise");
  command->add_option("--cost-image", options->costImage,
                      "cost heat map in the style of thesis figure 8.2");
  command->callback([options] {
    const Scene scene = loadScene(options->frame.scene);
    const std::vector<TraversalJob> jobs =
        makeFrameJobs(options->frame.camera, scene.image.root, options->frame.epsilon);
    GoldenModel model(scene.image.memory(), options->frame.config);
    const auto start = std::chrono::steady_clock::now();
    const std::vector<TraversalResult> results = model.traceAll(jobs);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const RenderedFrame rendered =
        RenderedFrame::fromResults(options->frame.camera, options->frame.config.format, results);
    if (!options->image.empty()) writeShadedImage(rendered, options->image);
    if (!options->depthImage.empty()) writeDepthImage(rendered, options->depthImage);
    if (!options->costImage.empty()) writeCostImage(rendered, options->costImage);

    char host[128];
    std::snprintf(host, sizeof host, "host        %.3f s, %.2f M rays/s (golden model)\n",
                  seconds, results.size() / seconds / 1e6);
    std::cout << "scene       " << scene.name << ": " << scene.summary << "\n"
              << "model       golden, " << options->frame.config.format.describe() << ", "
              << toString(options->frame.config.conversion) << " conversion, "
              << options->frame.config.stackFrames << " stack frames\n"
              << "frame       " << options->frame.camera.width << "x" << options->frame.camera.height << "\n"
              << ResultSummary::of(results).describe() << host;
    for (const std::string* path : {&options->image, &options->depthImage, &options->costImage})
      if (!path->empty()) std::cout << "wrote       " << *path << "\n";
  });
}

}  // namespace rtu
