#include "rtu/image_sections.h"

#include <array>

namespace rtu {
namespace {

constexpr std::array<uint32_t ImageSections::*, kImageSectionWords> kFields = {
    &ImageSections::magic,         &ImageSections::kind,      &ImageSections::version,
    &ImageSections::flags,         &ImageSections::nodeBase,  &ImageSections::nodeCount,
    &ImageSections::listBase,      &ImageSections::listCount, &ImageSections::triangleBase,
    &ImageSections::triangleCount, &ImageSections::totalWords};

constexpr uint64_t kMaxWords = (uint64_t{1} << 32) - 1;  // the size in header word 10

uint64_t alignedToAccess(uint64_t words) { return (words + 3) / 4 * 4; }

}  // namespace

std::string capacityExceeded(uint64_t count, uint64_t limit, const std::string& what,
                             const std::string& why) {
  if (count <= limit) return "";
  return std::to_string(count) + " " + what + ", more than " + std::to_string(limit) + " (" + why +
         ")";
}

bool placeSections(uint64_t nodes, uint32_t nodeWords, uint64_t entries, uint64_t triangles,
                   uint32_t triangleWords, ImageSections& sections, std::string& error) {
  const uint64_t listBase = kImageHeaderWords + nodeWords * nodes;
  const uint64_t triangleBase = alignedToAccess(listBase + entries);
  const uint64_t totalWords = triangleBase + triangleWords * triangles;
  error = capacityExceeded(totalWords, kMaxWords, "words", "word addresses have 32 bits");
  if (!error.empty()) return false;
  sections.nodeBase = kImageHeaderWords;
  sections.nodeCount = static_cast<uint32_t>(nodes);
  sections.listBase = static_cast<uint32_t>(listBase);
  sections.listCount = static_cast<uint32_t>(entries);
  sections.triangleBase = static_cast<uint32_t>(triangleBase);
  sections.triangleCount = static_cast<uint32_t>(triangles);
  sections.totalWords = static_cast<uint32_t>(totalWords);
  return true;
}

void writeSections(const ImageSections& sections, uint32_t* header) {
  for (size_t i = 0; i < kFields.size(); ++i) header[i] = sections.*kFields[i];
}

ImageSections readSections(const uint32_t* header) {
  ImageSections sections;
  for (size_t i = 0; i < kFields.size(); ++i) sections.*kFields[i] = header[i];
  return sections;
}

void checkHeaderWord(ImageProblems& problems, uint32_t word, const std::string& name,
                     uint32_t value, uint32_t expected) {
  if (value != expected)
    problems.add(word, "the header's " + name + " is " + std::to_string(value) + ", not " +
                           std::to_string(expected));
}

void checkPlacement(const ImageSections& found, const ImageSections& placed, size_t imageWords,
                    const std::string& listName, ImageProblems& problems) {
  checkHeaderWord(problems, 4, "node base", found.nodeBase, placed.nodeBase);
  checkHeaderWord(problems, 6, listName + " base", found.listBase, placed.listBase);
  checkHeaderWord(problems, 8, "triangle base", found.triangleBase, placed.triangleBase);
  checkHeaderWord(problems, 10, "size in words", found.totalWords, placed.totalWords);
  if (imageWords != found.totalWords)
    problems.add(10, "the header says " + std::to_string(found.totalWords) +
                         " words, the image has " + std::to_string(imageWords));
}

}  // namespace rtu
