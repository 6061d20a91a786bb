#pragma once
// Plug-in modules: code with heavy library dependencies (assimp for meshes, OpenImageIO for
// images) lives in shared modules next to the rtusim binary and is loaded with dlopen on first
// use, so commands that never read a mesh or write an image do not pay for loading those
// libraries (see docs/performance.md, "Start-up").
//
// A module is looked for in the directory of the running executable (/proc/self/exe), then in
// the directory the build wrote it to (for the test executables, which live elsewhere). It
// exports `int rtusim_plugin_abi(void)` returning kPluginAbi, and C entry points.

#include <string>

namespace rtu {

// Bumped whenever an entry point's signature or a type passed through one changes, so a stale
// module from an older build is refused instead of misread.
constexpr int kPluginAbi = 2;

// The address of `symbol` in module `file` (e.g. "librtusim_meshes.so"), loading the module on
// first use; handles are kept for the life of the process. `purpose` completes the error
// message ("needed to read meshes"). Throws std::runtime_error naming the file and the
// directories searched when the module is missing, cannot be loaded, is of another ABI or
// lacks the symbol. Thread-safe.
void* pluginSymbol(const std::string& file, const char* symbol, const std::string& purpose);

// pluginSymbol cast to the entry point's function type.
template <typename Function>
Function* pluginFunction(const std::string& file, const char* symbol, const std::string& purpose) {
  return reinterpret_cast<Function*>(pluginSymbol(file, symbol, purpose));
}

}  // namespace rtu
