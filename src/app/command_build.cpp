#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/output_paths.h"
#include "app/placement_flags.h"
#include "app/schema_flags.h"
#include "kinds/svo/svo_image.h"

namespace rtu {

void addBuildCommand(CLI::App& app) {
  struct Options {
    std::string out;
    bool modelHeader = false;
    ModelPlacement placement;
    glm::dvec3 rotationDegrees{0.0};
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "build", "build an SVO memory image from a procedural scene, a mesh or a .binvox file");
  auto request = addConfigOptions(*command, kUseScene);
  command->add_option("--out", options->out, "output .svo file")->required();
  CLI::Option* header = command->add_flag(
      "--model-header", options->modelHeader,
      "append an animated model's header (16 words) after the image and print its word address");
  addPlacementOptions(*command, options->placement, options->rotationDegrees, header);
  command->callback([options, request] {
    const Configuration configuration = request->resolve();
    checkOutputPaths({{"--out", options->out}}, inputPaths(configuration.values()));
    Scene scene = loadScene(configuration.values().scene);
    std::string headerReport;
    if (options->modelHeader) {
      options->placement.rotation = rotationFromEulerDegrees(options->rotationDegrees);
      headerReport = "model header at word " +
                     std::to_string(appendModelHeader(scene.image, options->placement)) + "\n";
    }
    writeSvoFile(options->out, scene.image);
    std::cout << scene.name << ": " << scene.summary << ", root at word " << scene.image.root
              << "\n"
              << headerReport << "wrote " << options->out << "\n";
  });
}

}  // namespace rtu
