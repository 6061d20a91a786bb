#pragma once
// The first eleven words of a triangle kind's memory image (the BVH's, the BIH's): which format
// it is, and where its three sections lie after the 16-word header. Nodes come first; then a list
// of one-word entries (the BVH's triangle references, the BIH's triangle numbers); then the
// triangle records, from a 4-word boundary so that a record begins an access. Words 11-15 are the
// kind's own. Shared so that every image is placed, written, read and checked alike.

#include <cstdint>
#include <string>

#include "rtu/image_problems.h"

namespace rtu {

constexpr uint32_t kImageHeaderWords = 16;
constexpr uint32_t kImageSectionWords = 11;  // words 0-10 below, in this order

struct ImageSections {
  uint32_t magic = 0, kind = 0, version = 0, flags = 0;
  uint32_t nodeBase = 0, nodeCount = 0;
  uint32_t listBase = 0, listCount = 0;
  uint32_t triangleBase = 0, triangleCount = 0;
  uint32_t totalWords = 0;  // the image's size
};

// A count beyond what a field can hold, named: "N what, more than LIMIT (why)"; empty when it fits.
std::string capacityExceeded(uint64_t count, uint64_t limit, const std::string& what,
                             const std::string& why);

// The sections of an image of `nodes` nodes of `nodeWords` words, `entries` list entries and
// `triangles` records of `triangleWords` words; empty when its size does not fit 32-bit word
// addresses (`error` then says so).
bool placeSections(uint64_t nodes, uint32_t nodeWords, uint64_t entries, uint64_t triangles,
                   uint32_t triangleWords, ImageSections& sections, std::string& error);

void writeSections(const ImageSections& sections, uint32_t* header);  // header words 0-10
ImageSections readSections(const uint32_t* header);

// A header word against what it should be, as a problem naming it: "the header's <name> is V, not
// E".
void checkHeaderWord(ImageProblems& problems, uint32_t word, const std::string& name,
                     uint32_t value, uint32_t expected);
// Words 4-10 of `found` against `placed` (the placement its counts imply), and the image's size.
void checkPlacement(const ImageSections& found, const ImageSections& placed, size_t imageWords,
                    const std::string& listName, ImageProblems& problems);

}  // namespace rtu
