#include <iostream>
#include <memory>

#include "cli_options.h"
#include "commands.h"
#include "svo_image.h"

namespace rtu {

void addBuildCommand(CLI::App& app) {
  struct Options {
    SceneSpec scene;
    std::string out;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "build", "build an SVO memory image from a procedural scene, a mesh or a .binvox file");
  addSceneOptions(*command, options->scene);
  command->add_option("--out", options->out, "output .svo file")->required();
  command->callback([options] {
    const Scene scene = loadScene(options->scene);
    writeSvoFile(options->out, scene.image);
    std::cout << scene.name << ": " << scene.summary << ", root at word " << scene.image.root
              << "\nwrote " << options->out << "\n";
  });
}

}  // namespace rtu
