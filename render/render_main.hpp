// `damimpact render OUT/`: the pictures of a finished run (or a with/without-buffer comparison) into OUT/images/,
// with a manifest OUT/images/images.json (file, kind, title, caption, size, colour ranges) the report reads.
#pragma once
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "design/design_document.hpp"
#include "design/members.hpp"
#include "engine/io/results.hpp"
#include "render/charts.hpp"
#include "render/manifest.hpp"

namespace dmi::render {

// One run as the pictures and the report see it.
struct RunData {
  std::string variant, file;             // "" | with_buffer | without_buffer; the results.h5 path
  Results results;                       // with snapshots
  design::RunDesign design;              // its entry of design.json "runs", read once
  std::optional<design::FrameInfo> frame;
};


// A variant's name in words ("with buffer", "without buffer", "" for a single run) and run i's colour in the charts.
std::string nice_variant(const std::string& v);
std::array<unsigned char, 3> colour(std::size_t i);
// The contact pressure along each run's struck face (design.json runs[].face_profile) at its largest moment about the
// foot: a step curve per run (render/report_pressure.cpp); no curves when no run has a face profile.
ChartSpec face_profile_chart(const std::vector<RunData>& runs);

// The runs of OUT (OUT/results.h5, or OUT/with_buffer and OUT/without_buffer) and design.json (OUT/design.json when
// present, else computed with the default limits). Throws dmi::InputError naming the path.
std::vector<RunData> load_runs(const std::string& out_dir, design::DesignDocument& design_doc);
// The runs the pictures show: the plane runs when compare_3d put 3D models beside them (the report's tables set the
// two side by side), else all.
std::vector<RunData> pictured_runs(const std::vector<RunData>& runs);

struct RenderOptions {
  std::string quantity = "von_mises";
  bool quiet = false;
  int processes = 1;  // 2: a second process shares the pictures where two CPUs are free (PictureHelper)
  // helper_of > 0: this process is the second picture process of that process id; it draws the pictures whose claim
  // it creates first in the folder `claims` (PictureHelper) and writes no images.json.
  long helper_of = 0;
  std::string claims;
};

class PictureHelper;

// Renders everything into OUT/images/ and returns the manifest (also written as images.json).
nlohmann::json render_main(const std::string& out_dir, const RenderOptions& o);
// With an active helper, each picture is drawn by the process that claims it first (an exclusive file in the helper's
// claims folder), so the helper takes pictures as soon as it is ready; render_runs waits for it (and draws every
// picture itself if it failed; on an error of its own it stops the helper first).
Manifest render_runs(const std::vector<RunData>& runs, const design::DesignDocument& design_doc, const std::string& image_dir,
                     const RenderOptions& o, PictureHelper* helper = nullptr);

}  // namespace dmi::render
