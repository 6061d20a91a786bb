#pragma once
// An animated image of a frame sequence, assembled by a Debian tool when one is installed:
// img2webp (package webp) gives an animated WebP, else ffmpeg an MP4.

#include <string>
#include <vector>

namespace rtu {

struct AnimatedImage {
  std::string path;  // empty: no tool installed
  std::string tool;
};

// Frames in order, shown at `frameRate` per second, looping. Throws std::runtime_error when the
// tool fails.
AnimatedImage assembleAnimatedImage(const std::vector<std::string>& frames, double frameRate,
                                    const std::string& outputStem);

}  // namespace rtu
