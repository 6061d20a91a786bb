#include "sim/kernel/sc_kernel.h"

#if defined(__SANITIZE_ADDRESS__)
#include <pthread.h>

#include <sanitizer/common_interface_defs.h>
#endif

namespace rtu {

namespace {

#if defined(__SANITIZE_ADDRESS__)
// SystemC 2.3.4's coroutines (sc_cor_qt.cpp) tell AddressSanitizer of a switch to a thread
// process's stack, but not of the switch back when the process ends (sc_cor_pkg_qt::abort), nor
// of the main stack's bounds when they yield to it: ASan goes on taking the ended process's freed
// stack for the main thread's, and LeakSanitizer's scan of that range at exit faults ("Tracer
// caught signal 11", three runs in four of a test that ends with a loosely-timed run). Once a
// simulation has returned, the main thread is on its own stack again: say so.
void backOnMainStack() {
  pthread_attr_t attributes;
  if (pthread_getattr_np(pthread_self(), &attributes) != 0) return;
  void* bottom = nullptr;
  size_t size = 0;
  const bool known = pthread_attr_getstack(&attributes, &bottom, &size) == 0;
  pthread_attr_destroy(&attributes);
  if (!known) return;
  void* fakeStack = nullptr;
  __sanitizer_start_switch_fiber(&fakeStack, bottom, size);
  __sanitizer_finish_switch_fiber(fakeStack, nullptr, nullptr);
}
#else
void backOnMainStack() {}
#endif

}  // namespace

void freshKernel() {
  sc_core::sc_curr_simcontext = new sc_core::sc_simcontext();
  sc_core::sc_default_global_context = sc_core::sc_curr_simcontext;
}

void simulate() {
  sc_core::sc_start();
  backOnMainStack();
}

void simulateFor(const sc_core::sc_time& duration) {
  sc_core::sc_start(duration);
  backOnMainStack();
}

}  // namespace rtu
