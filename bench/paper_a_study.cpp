// Lin & Yang (2024) verifications 1-2 study: prints the markdown tables of docs/verification.md.
//   build/bench/paper_a_study [--threads N]
// Not a test: it runs every variant (element counts, distance modes, depths, beam models) and
// reports errors and wall times; the pass/fail checks are the validate cases paper_a5/a6/a6_large.
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "verify/cases_members.hpp"

using namespace dmi;

namespace {

void a5() {
  std::vector<double> tr, ur, t2, u2;
  paper_a5_point_mass_reference(64, 1e-5, 5.0, 1e-4, tr, ur);
  paper_a5_point_mass_reference(128, 5e-6, 5.0, 1e-4, t2, u2);
  const std::function<double(double)> fe = [&](double t) { return interpolate(tr, ur, t); };
  const ErrorPair conv = compare_history(t2, u2, 0.0, fe);
  const ErrorPair fe30 = compare_history(tr, ur, 0.0, paper_a5_eq30);
  std::printf("Point-mass FE reference (64 elements, consistent mass, dt 1e-5): vs 128 elements NRMS %.2e; vs eq. (30) NRMS %.4f, peak %+.4f\n\n",
              conv.nrms, fe30.nrms, fe30.peak);
  std::printf("| distance | elements | contact onset (s) | NRMS vs eq. (30) | peak vs eq. (30) | NRMS vs FE | NRMS vs eq. (30), origin sqrt(2d/g) | wall (s) |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const char* dist : {"node", "material"})
    for (int n : {1, 2, 4, 8}) {
      const A5Run r = paper_a5_run(n, {{"/member_contact/distance", dist}});
      const ErrorPair e = compare_history(r.time, r.midspan, r.t_impact, paper_a5_eq30);
      const ErrorPair f = compare_history(r.time, r.midspan, r.t_impact, fe);
      const ErrorPair th = compare_history(r.time, r.midspan, std::sqrt(2 * 0.75 / 10), paper_a5_eq30);
      std::printf("| %s | %d | %.3f | %.4f | %+.4f | %.4f | %.4f | %.2f |\n", dist, n, r.t_impact, e.nrms, e.peak, f.nrms, th.nrms, r.wall);
    }
}

void a6() {
  std::printf("\n| h/L | model | peak deflection (m) | paper (m) | peak von Mises top (MPa) | disc final v_y (m/s) | min centroid gap (m) | steps | wall (s) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  const double* depth = kPaperA6Depth;
  const double* paper_p = kPaperA6PeakParticles;
  const double paper_bc[] = {kPaperA6PeakBeamColumn[0], kPaperA6PeakBeamColumn[1], kPaperA6PeakBeamColumn[2], NAN};
  for (int k = 0; k < 4; ++k) {
    struct V { const char* name; bool bc; std::vector<std::pair<std::string, nlohmann::json>> ov; double paper; };
    std::vector<V> vs = {{"particles", false, {}, paper_p[k]},
                         {"beam-column, node distance", true, {{"/member_contact/distance", "node"}}, paper_bc[k]},
                         {"beam-column", true, {}, paper_bc[k]}};
    if (k == 3) vs.push_back({"beam-column, corotational", true, {{"/structure/transformation", "corotational"}}, NAN});
    for (const V& v : vs) {
      const A6Run r = paper_a6_run(depth[k], v.bc, v.ov);
      std::printf("| %.3f | %s | %.3f | %s | %.2f | %+.2f | %+.3f | %ld | %.3f |\n", depth[k] / 2.5, v.name, r.peak_displacement,
                  std::isnan(v.paper) ? "-" : std::to_string(v.paper).substr(0, 5).c_str(), r.peak_von_mises / 1e6,
                  r.disc_final_vy, r.min_gap, r.steps, r.wall);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--threads") omp_set_num_threads(std::stoi(argv[2]));
  a5();
  a6();
}
