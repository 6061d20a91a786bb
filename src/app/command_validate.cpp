#include <iostream>
#include <memory>
#include <stdexcept>

#include "app/commands.h"
#include "app/input_file_check.h"
#include "app/placement_flags.h"
#include "base/binary_file.h"
#include "kinds/bih/bih_file.h"
#include "kinds/bih/bih_validator.h"
#include "kinds/bvh/bvh_file.h"
#include "kinds/bvh/bvh_validator.h"
#include "kinds/kd/kd_image.h"
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

void validateBvhFile(const ValidateOptions& options, const std::vector<uint32_t>& words) {
  const std::vector<BvhProblem> problems = validateBvh(words);
  if (!problems.empty())
    throw std::runtime_error(describeBvhProblems("'" + options.file + "'", problems));
  const BvhHeader header = decodeHeader(words.data());
  std::cout << options.file << ": valid BVH image, " << header.nodeCount << " nodes, "
            << header.triangleCount << " triangles, " << words.size() * sizeof(uint32_t)
            << " bytes\n";
}

void validateBihFile(const ValidateOptions& options, const std::vector<uint32_t>& words) {
  const std::vector<ImageProblem> problems = validateBih(words);
  if (!problems.empty())
    throw std::runtime_error(describeBihProblems("'" + options.file + "'", problems));
  const BihHeader header = decodeBihHeader(words.data());
  std::cout << options.file << ": valid BIH image, " << header.nodeCount << " nodes, "
            << header.listCount << " list entries, " << header.triangleCount << " triangles, "
            << words.size() * sizeof(uint32_t) << " bytes\n";
}

void validateKdFile(const ValidateOptions& options, const std::vector<uint32_t>& words) {
  const std::vector<ImageProblem> problems = validateKd(words);
  if (!problems.empty())
    throw std::runtime_error(describeImageProblems("'" + options.file + "'", "k-d", problems, 10));
  const KdHeader header = decodeKdHeader(words.data());
  std::cout << options.file << ": valid k-d image, " << header.nodeCount << " nodes, "
            << header.listCount << " list entries, " << header.uttmCount << " triangles, "
            << words.size() * sizeof(uint32_t) << " bytes\n";
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
    if (looksLikeBvhImage(words))
      validateBvhFile(*options, words);
    else if (looksLikeBihImage(words))
      validateBihFile(*options, words);
    else if (!words.empty() && words[0] == kKdMagic)
      validateKdFile(*options, words);
    else
      validateSvoFile(*options, std::move(words));
  });
}

}  // namespace rtu
