// libsystemc references sc_main, its own entry point. rtusim's programs have their own main and
// drive the kernel themselves (src/run/rtu_simulation.cpp), so this one is never called.
extern "C" int sc_main(int, char**) { return 1; }
