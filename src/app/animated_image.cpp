#include "app/animated_image.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace rtu {

namespace {

bool onPath(const std::string& tool) {
  const char* path = std::getenv("PATH");
  std::istringstream directories(path ? path : "/usr/bin:/bin");
  for (std::string directory; std::getline(directories, directory, ':');)
    if (!directory.empty() && ::access((directory + "/" + tool).c_str(), X_OK) == 0) return true;
  return false;
}

// Runs the tool with its output discarded; throws naming it when it fails.
void run(std::vector<std::string> words) {
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  if (spawned == 0) ::waitpid(pid, &status, 0);
  if (spawned != 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("cannot assemble the animated image: " + words[0] + " failed");
}

std::vector<std::string> img2webp(const std::vector<std::string>& frames, double frameRate,
                                  const std::string& out) {
  const long milliseconds = std::lround(1000.0 / frameRate);
  std::vector<std::string> words = {
      "img2webp", "-loop", "0",  "-lossy",
      "-q",       "85",    "-d", std::to_string(std::max(milliseconds, 1L))};
  words.insert(words.end(), frames.begin(), frames.end());
  words.insert(words.end(), {"-o", out});
  return words;
}

// ffmpeg reads a numbered sequence: the frames must be named PREFIX%04d.png, which
// animate does.
std::vector<std::string> ffmpeg(const std::vector<std::string>& frames, double frameRate,
                                const std::string& out) {
  const std::string& first = frames.front();
  const std::string pattern = first.substr(0, first.size() - 8) + "%04d.png";
  return {"ffmpeg", "-y",    "-loglevel", "error",   "-framerate", std::to_string(frameRate),
          "-i",     pattern, "-pix_fmt",  "yuv420p", "-vf",        "pad=ceil(iw/2)*2:ceil(ih/2)*2",
          out};
}

}  // namespace

AnimatedImage assembleAnimatedImage(const std::vector<std::string>& frames, double frameRate,
                                    const std::string& outputStem) {
  if (frames.empty()) return {};
  if (onPath("img2webp")) {
    const std::string out = outputStem + ".webp";
    run(img2webp(frames, frameRate, out));
    return {out, "img2webp"};
  }
  if (onPath("ffmpeg")) {
    const std::string out = outputStem + ".mp4";
    run(ffmpeg(frames, frameRate, out));
    return {out, "ffmpeg"};
  }
  return {};
}

}  // namespace rtu
