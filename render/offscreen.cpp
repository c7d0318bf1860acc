#include "render/offscreen.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <malloc.h>

#include <filesystem>
#include <stdexcept>

#include <vtkPNGWriter.h>
#include <vtkWindowToImageFilter.h>

namespace dmi::render {

struct Offscreen::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLSurface surface = EGL_NO_SURFACE;
  EGLContext context = EGL_NO_CONTEXT;
};

namespace {
[[noreturn]] void fail(const char* step) {
  throw std::runtime_error(std::string("off-screen rendering: ") + step + " failed (EGL error 0x" +
                           [] { char b[16]; std::snprintf(b, sizeof b, "%x", eglGetError()); return std::string(b); }() +
                           "); Mesa's EGL (libegl1-mesa) is needed, no X server is used");
}
}  // namespace

Offscreen::Offscreen() : impl_(std::make_unique<Impl>()) {
  // Mesa's software rasteriser allocates each picture's buffers afresh (9.2 MB each for the demo's field pictures; 119
  // of them, 1.0 GB, cleared on allocation, for its 17 pictures) and frees them after the picture. glibc took them from
  // the heap after its automatic mmap threshold rose, but gave the heap top back after each picture (~350 MB trimmed
  // over the demo, strace) and faulted it in again page by page: page faults and clearing were ~60 % of `render`'s
  // samples (perf). Fixed thresholds keep the buffers in the heap: 32 MB for mmap, 512 MB before trimming (either one
  // alone switches glibc's automatic threshold off and was slower: 389 k faults with the trim setting alone). Minor
  // faults ~200 k -> ~60 k, `render` of the demo 4.3-5.0 -> 3.2-3.6 s (docs/performance.md, "Program start and
  // pictures"). Set when the first picture is made: a sweep that writes case reports keeps the setting for its later
  // cases (their memory is bounded by the peak already reached; a 6-case sweep ran faster, not larger).
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_display) fail("eglGetPlatformDisplayEXT lookup");
  impl_->display = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (impl_->display == EGL_NO_DISPLAY) fail("surfaceless display");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(impl_->display, &major, &minor)) fail("eglInitialize");
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                                   EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config;
  EGLint n = 0;
  if (!eglChooseConfig(impl_->display, config_attribs, &config, 1, &n) || n < 1) fail("eglChooseConfig");
  const EGLint pbuffer[] = {EGL_WIDTH, 64, EGL_HEIGHT, 64, EGL_NONE};  // VTK renders into its own framebuffers
  impl_->surface = eglCreatePbufferSurface(impl_->display, config, pbuffer);
  if (impl_->surface == EGL_NO_SURFACE) fail("eglCreatePbufferSurface");
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI");
  const EGLint ctx[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2, EGL_CONTEXT_OPENGL_PROFILE_MASK,
                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  impl_->context = eglCreateContext(impl_->display, config, EGL_NO_CONTEXT, ctx);
  if (impl_->context == EGL_NO_CONTEXT) fail("eglCreateContext (OpenGL 3.2 core)");
  if (!eglMakeCurrent(impl_->display, impl_->surface, impl_->surface, impl_->context)) fail("eglMakeCurrent");
}

Offscreen::~Offscreen() {
  if (impl_->display == EGL_NO_DISPLAY) return;
  eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (impl_->context != EGL_NO_CONTEXT) eglDestroyContext(impl_->display, impl_->context);
  if (impl_->surface != EGL_NO_SURFACE) eglDestroySurface(impl_->display, impl_->surface);
  eglTerminate(impl_->display);
}

Offscreen& Offscreen::instance() {
  static Offscreen o;
  return o;
}

vtkSmartPointer<vtkGenericOpenGLRenderWindow> Offscreen::window(int w, int h) {
  eglMakeCurrent(impl_->display, impl_->surface, impl_->surface, impl_->context);
  auto win = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  win->SetSize(w, h);
  win->SetOffScreenRendering(1);
  win->SetMultiSamples(0);
  win->SetReadyForRendering(true);
  win->SetIsCurrent(true);
  win->SetOwnContext(0);
  return win;
}

void write_png(vtkGenericOpenGLRenderWindow* win, const std::string& path) {
  win->Render();
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(win);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  const std::string tmp = path + ".tmp";
  auto png = vtkSmartPointer<vtkPNGWriter>::New();
  png->SetFileName(tmp.c_str());
  png->SetInputConnection(grab->GetOutputPort());
  png->Write();
  if (png->GetErrorCode() != 0 || !std::filesystem::exists(tmp)) throw std::runtime_error(path + ": cannot write the PNG");
  std::filesystem::rename(tmp, path);
}

const char* font_file() { return "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"; }

}  // namespace dmi::render
