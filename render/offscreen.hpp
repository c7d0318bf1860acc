// Off-screen rendering without any X server: Mesa's surfaceless EGL platform (software llvmpipe) made
// current, then handed to a vtkGenericOpenGLRenderWindow (docs/report.md, "Off-screen rendering").
#pragma once
#include <memory>
#include <string>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkSmartPointer.h>

namespace dmi::render {

// One EGL display + context for the process (created on first use, kept until exit). Throws
// std::runtime_error with the EGL step that failed.
class Offscreen {
 public:
  static Offscreen& instance();
  // A render window of w x h pixels on the shared context (multisampling off, as charts need).
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window(int w, int h);
  ~Offscreen();

 private:
  Offscreen();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Renders `win` and writes its pixels as PNG to `path` (via `path`.tmp, renamed when complete).
void write_png(vtkGenericOpenGLRenderWindow* win, const std::string& path);

// DejaVu Sans (fonts-dejavu-core): correct square brackets and unit symbols, unlike VTK's fallback.
const char* font_file();

}  // namespace dmi::render
