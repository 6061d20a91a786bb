#pragma once
// The plug-in side of plugin_loader.h: what every module's C entry points share. No exception
// may cross the C boundary, so an entry point runs its body through pluginCall, which turns
// any exception into the message handed back to the caller.

#include <exception>
#include <string>

#include "base/plugin_loader.h"

#define RTUSIM_PLUGIN_EXPORT extern "C" __attribute__((visibility("default")))

// Every module exports its ABI version under this name; pluginSymbol checks it before use.
#define RTUSIM_PLUGIN_ABI_ENTRY \
  RTUSIM_PLUGIN_EXPORT int rtusim_plugin_abi() { return rtu::kPluginAbi; }

namespace rtu {

// Runs `body` (returning an error message, empty on success) and gives nullptr on success or
// the message, valid until the calling thread's next call of this entry point.
template <typename Body>
const char* pluginCall(Body&& body) {
  thread_local std::string error;
  try {
    error = body();
  } catch (const std::exception& exception) {
    error = exception.what();
  } catch (...) {
    error = "unknown error";
  }
  return error.empty() ? nullptr : error.c_str();
}

}  // namespace rtu
