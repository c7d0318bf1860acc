// Google Benchmark of the space frame (figures only; docs/performance.md reads them):
//   build/bench/space_frame [--benchmark_filter=...]
//   ElementState/linear|corotational: one element's basic deformations and B (the internal force's ingredients).
//   CorotationalTangent: one element's tangent (B by automatic differentiation, the geometric part by central
//                        differences of B: 24 more evaluations).
//   Advance/linear|corotational: one Newmark step of a 10-element pipe column under a tip load (the coupled run's
//                                per-step frame cost; corotational: Newton iterations with the tangent).
#include <benchmark/benchmark.h>

#include "engine/structure/space_frame.hpp"
#include "engine/structure/space_transform.hpp"

using namespace dmi;

namespace {

SpaceChord chord() {
  SpaceChord c{Vec3(0.1, 0.2, 0.3), Eigen::Matrix3d::Identity(), 0.5};
  local_axes(Vec3(0.6, 0.8, 0).normalized(), Vec3::Zero(), c.R);
  return c;
}

Vec12 state_vector() {
  Vec12 d;
  d << 0.01, -0.02, 0.03, 0.3, -0.5, 0.2, 0.05, 0.12, -0.04, -0.1, 0.4, 0.6;
  return d;
}

void ElementState(benchmark::State& st) {
  const SpaceChord c = chord();
  const Vec12 d = state_vector();
  std::unique_ptr<SpaceTransform> t = make_space_transform(st.range(0) ? FrameTransform::corotational : FrameTransform::linear);
  for (auto _ : st) benchmark::DoNotOptimize(t->state(c, d));
  st.SetLabel(st.range(0) ? "corotational" : "linear");
}

void CorotationalTangent(benchmark::State& st) {
  const SpaceChord c = chord();
  const Vec12 d = state_vector();
  SpaceElementDef def;
  def.section = Section::pipe(0.4, 0.012), def.E = 2e11, def.nu = 0.3, def.rho = 7850;
  const SpaceBeamElement el(def, c.L0, BeamTheory::euler_bernoulli);
  const CorotationalSpaceTransform t;
  const SpaceChordState s = t.state(c, d);
  for (auto _ : st) benchmark::DoNotOptimize(t.tangent(c, d, s, el.stiffness(), el.forces(s.v)));
}

void Advance(benchmark::State& st) {
  SpaceFrameModel m;
  for (int k = 0; k <= 10; ++k) m.nodes.push_back(Vec3(0, 0.4 * k, 0));
  for (int k = 0; k < 10; ++k) {
    SpaceElementDef e;
    e.i = k, e.j = k + 1, e.section = Section::pipe(0.4, 0.012), e.E = 2e11, e.nu = 0.3, e.rho = 7850;
    m.elements.push_back(e);
  }
  m.supports.push_back(SpaceSupportDef::fixed_support(0));
  m.integrator = FrameIntegrator::newmark;
  m.hht_alpha = -0.1;
  m.transform = st.range(0) ? FrameTransform::corotational : FrameTransform::linear;
  SpaceFrame f(m);
  Vec6 load;
  load << 2e5, 0, 1e5, 0, 0, 0;
  f.add_nodal_load(10, load);
  for (auto _ : st) f.advance(1e-5);
  st.SetLabel(st.range(0) ? "corotational" : "linear");
}

}  // namespace

BENCHMARK(ElementState)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(CorotationalTangent)->Unit(benchmark::kMicrosecond);
BENCHMARK(Advance)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
