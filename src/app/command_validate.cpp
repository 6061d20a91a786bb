#include <iostream>
#include <memory>
#include <stdexcept>

#include "app/commands.h"
#include "app/image_files.h"
#include "app/input_file_check.h"
#include "app/placement_flags.h"
#include "base/binary_file.h"
#include "kinds/svo/svo_image.h"
#include "kinds/svo/svo_validator.h"

namespace rtu {
namespace {

struct ValidateOptions {
  std::string file;
  uint32_t root = 0;
  SvoLimits limits;
};

void validateSvoFile(const ValidateOptions& options, std::vector<uint32_t> words) {
  const SvoImage image{std::move(words), options.root};
  SvoReport report;
  try {
    report = validateSvo(image, options.limits);
  } catch (const SvoFormatError& error) {
    throw std::runtime_error("SVO image '" + options.file + "': " + error.what());
  }
  std::cout << options.file << ": valid, " << describe(report) << "\n";
}

}  // namespace

void addValidateCommand(CLI::App& app) {
  auto options = std::make_shared<ValidateOptions>();
  CLI::App* command = app.add_subcommand(
      "validate",
      "check a memory image: an SVO, or a BVH, BIH or k-d tree (recognised by its header)");
  command->add_option("file", options->file, ".svo, .bvh, .bih or .kd file")
      ->required()
      ->check(regularInputFile());
  command->add_option("--root", options->root, "SVO: word address of the root descriptor")
      ->capture_default_str()
      ->check(kNotNegative);
  command->add_option("--max-depth", options->limits.maxDepth, "SVO: deepest octree level allowed")
      ->capture_default_str();
  command->callback([options] {
    std::vector<uint32_t> words = readWordFile(options->file, sizeof(uint32_t), "memory image");
    const std::string kind = imageKindOf(words);
    if (kind.empty()) return validateSvoFile(*options, std::move(words));
    withImageKind(kind, [&](auto image) {
      std::cout << options->file << ": "
                << KindImageFile<decltype(image)>::describeValid(options->file, words) << "\n";
    });
  });
}

}  // namespace rtu
