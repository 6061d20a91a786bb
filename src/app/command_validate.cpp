#include <iostream>
#include <memory>
#include <stdexcept>

#include "app/commands.h"
#include "app/placement_flags.h"
#include "kinds/svo/svo_image.h"
#include "kinds/svo/svo_validator.h"

namespace rtu {

void addValidateCommand(CLI::App& app) {
  struct Options {
    std::string file;
    uint32_t root = 0;
    SvoLimits limits;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("validate", "check an SVO memory image");
  command->add_option("file", options->file, ".svo file")->required()->check(CLI::ExistingFile);
  command->add_option("--root", options->root, "word address of the root descriptor")
      ->capture_default_str()
      ->check(kNotNegative);
  command->add_option("--max-depth", options->limits.maxDepth, "deepest octree level allowed")
      ->capture_default_str();
  command->callback([options] {
    const SvoImage image = readSvoFile(options->file, options->root);
    SvoReport report;
    try {
      report = validateSvo(image, options->limits);
    } catch (const SvoFormatError& error) {
      throw std::runtime_error("SVO image '" + options->file + "': " + error.what());
    }
    std::cout << options->file << ": valid, " << describe(report) << "\n";
  });
}

}  // namespace rtu
