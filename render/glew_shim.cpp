// Debian's GLEW is the GLX flavour: under an EGL context glewInit() loads every GL entry point, then
// fails its GLX part with GLEW_ERROR_NO_GLX_DISPLAY (4) and VTK skips part of its set-up. This forwards to
// the real glewInit and maps 4 to GLEW_OK (docs/report.md, "Off-screen rendering"). It must be linked into the
// executable itself (dlsym RTLD_NEXT finds the library's symbol after ours).
#include <dlfcn.h>

extern "C" unsigned glewInit() {
  using Fn = unsigned (*)();
  static Fn real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "glewInit"));
  if (!real) return 0;
  const unsigned rc = real();
  return rc == 4 ? 0 : rc;
}
