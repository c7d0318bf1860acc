#include "engine/solid/table1.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "engine/solid/loads.hpp"
#include "engine/solid/static_solver.hpp"

namespace dmi::solid {

std::vector<Table1Case> table1_cases() {
  return {{"point", 0, 0}, {"0.4x0.4", 0.4, 0.4}, {"0.8x0.4", 0.8, 0.4}, {"0.4x0.8", 0.4, 0.8}};
}

std::vector<Table1Row> table1_study(const Table1Setup& setup) {
  if (setup.measures.empty() || setup.locations.empty() || setup.sloped.empty())
    throw std::invalid_argument("table1_study: measures, locations and sloped must be non-empty");
  Elastic mat;
  mat.E_Pa = setup.E_Pa, mat.nu = setup.nu, mat.analysis = Analysis::solid3d;
  std::vector<Table1Row> rows;
  for (SlopedFace sf : setup.sloped) {
    TaperedBlock b = setup.block;
    b.sloped = sf;
    const Mesh m = hex8_tapered_block(b);
    const std::vector<int> base = nodes_at_height(m, 0.0);
    const StaticSolver solver(assemble_stiffness(m, mat), node_dofs(m, base));
    const double yc = 0.5 * b.width_m, zc = b.height_m - setup.load_depth_below_crest_m;
    const int load_node = nearest_face_node(m, Face::upstream, yc, zc);
    for (const Table1Case& c : table1_cases()) {
      Table1Row r;
      r.sloped = sf;
      r.load = c;
      Eigen::VectorXd f = Eigen::VectorXd::Zero(m.n_dofs());
      if (c.width_m == 0) {
        add_point_load(m, load_node, Eigen::Vector3d(setup.force_N, 0, 0), f);
        r.patch_scale = 1.0;
      } else {
        PatchLoad p;
        p.centre_y_m = yc, p.centre_z_m = zc, p.width_m = c.width_m, p.height_m = c.height_m;
        p.total_force_N = setup.force_N;
        p.shape = PatchShape::pyramid;
        r.patch_scale = add_patch_load(m, p, f).scale;
      }
      const StaticSolution sol = solver.solve(f);
      const StressField s = recover_stress(m, mat, sol.u);
      for (Measure me : setup.measures) {
        r.peak_kPa.emplace_back(), r.peak_z_m.emplace_back();
        for (Location lo : setup.locations) {
          const Peak pk = peak(s, me, lo);
          r.peak_kPa.back().push_back(pk.value / 1e3);
          r.peak_z_m.back().push_back(point_coordinates(m, lo, pk.index)(2));
        }
      }
      r.max_node_reaction_kN = r.max_node_reaction_x_kN = r.max_node_reaction_z_kN = 0;
      for (int n : base) {
        const Eigen::Vector3d rn = sol.reaction.segment<3>(3 * n) / 1e3;
        r.max_node_reaction_x_kN = std::max(r.max_node_reaction_x_kN, std::abs(rn(0)));
        r.max_node_reaction_z_kN = std::max(r.max_node_reaction_z_kN, std::abs(rn(2)));
        if (rn.norm() > r.max_node_reaction_kN) {
          r.max_node_reaction_kN = rn.norm();
          r.max_node_reaction_components_kN = rn;
          r.max_node_reaction_position_m = m.nodes.row(n).transpose();
        }
      }
      r.total_reaction_kN = total_reaction(m, sol.reaction, base) / 1e3;
      r.tip_displacement_mm = sol.u(3 * load_node) * 1e3;
      rows.push_back(std::move(r));
    }
  }
  return rows;
}

std::vector<Table1Match> rank_table1_matches(const Table1Setup& setup, const std::vector<Table1Row>& rows) {
  std::vector<Table1Match> out;
  const std::size_t nc = table1_cases().size();
  for (std::size_t r0 = 0; r0 + nc <= rows.size(); r0 += nc)
    for (std::size_t mi = 0; mi < setup.measures.size(); ++mi)
      for (std::size_t li = 0; li < setup.locations.size(); ++li) {
        double sum = 0;
        for (std::size_t c = 0; c < nc; ++c) {
          const double e = rows[r0 + c].peak_kPa[mi][li] / kPaperBTable1PeakStress_kPa[c] - 1;
          sum += e * e;
        }
        out.push_back({rows[r0].sloped, setup.measures[mi], setup.locations[li], std::sqrt(sum / nc)});
      }
  std::sort(out.begin(), out.end(), [](const Table1Match& a, const Table1Match& b) { return a.rms_rel_error < b.rms_rel_error; });
  return out;
}

std::string format_table1(const Table1Setup& setup, const std::vector<Table1Row>& rows) {
  std::string s;
  char buf[512];
  auto add = [&](const char* text) { s += text; };
  add("| sloped face | measure | location |");
  for (const Table1Case& c : table1_cases()) {
    std::snprintf(buf, sizeof buf, " %s kPa (z m) |", c.name.c_str());
    add(buf);
  }
  add("\n|---|---|---|---|---|---|---|\n| paper | ? | ? |");
  for (double v : kPaperBTable1PeakStress_kPa) {
    std::snprintf(buf, sizeof buf, " %.2f |", v);
    add(buf);
  }
  add("\n");
  const std::size_t nc = table1_cases().size();
  for (std::size_t r0 = 0; r0 + nc <= rows.size(); r0 += nc)
    for (std::size_t mi = 0; mi < setup.measures.size(); ++mi)
      for (std::size_t li = 0; li < setup.locations.size(); ++li) {
        std::snprintf(buf, sizeof buf, "| %s | %s | %s |", to_string(rows[r0].sloped), to_string(setup.measures[mi]),
                      to_string(setup.locations[li]));
        add(buf);
        for (std::size_t c = 0; c < nc; ++c) {
          std::snprintf(buf, sizeof buf, " %.1f (%.2f) |", rows[r0 + c].peak_kPa[mi][li], rows[r0 + c].peak_z_m[mi][li]);
          add(buf);
        }
        add("\n");
      }
  std::snprintf(buf, sizeof buf,
                "\n| sloped face | load | patch scale | max nodal base reaction kN (paper %.2f) | components x, y, z kN | at x, y m |"
                " max abs r_x kN | max abs r_z kN | total reaction x, y, z kN | u_x at load node mm |\n|---|---|---|---|---|---|---|---|---|---|\n",
                kPaperBTable1FixedEndForce_kN);
  add(buf);
  for (const Table1Row& r : rows) {
    const auto& c = r.max_node_reaction_components_kN;
    const auto& t = r.total_reaction_kN;
    std::snprintf(buf, sizeof buf, "| %s | %s | %.5f | %.2f | %.2f, %.2f, %.2f | %.2f, %.2f | %.2f | %.2f | %.6f, %.2e, %.2e | %.4f |\n",
                  to_string(r.sloped), r.load.name.c_str(), r.patch_scale, r.max_node_reaction_kN, c(0), c(1), c(2),
                  r.max_node_reaction_position_m(0), r.max_node_reaction_position_m(1), r.max_node_reaction_x_kN,
                  r.max_node_reaction_z_kN, t(0), t(1), t(2), r.tip_displacement_mm);
    add(buf);
  }
  add("\n| rank | sloped face | measure | location | RMS relative error vs paper peaks |\n|---|---|---|---|---|\n");
  const std::vector<Table1Match> ranked = rank_table1_matches(setup, rows);
  for (std::size_t i = 0; i < std::min<std::size_t>(ranked.size(), 10); ++i) {
    std::snprintf(buf, sizeof buf, "| %zu | %s | %s | %s | %.4f |\n", i + 1, to_string(ranked[i].sloped),
                  to_string(ranked[i].measure), to_string(ranked[i].location), ranked[i].rms_rel_error);
    add(buf);
  }
  return s;
}

}  // namespace dmi::solid
