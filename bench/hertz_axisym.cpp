// Independent reference for the Hertz sphere: an axisymmetric, small-strain, linear-elastic finite-element model of a
// sphere held on a rigid frictionless flat by a uniform body force (the quasi-static picture of an impact: the contact
// force decelerates the whole mass). It gives the force against the approach of the centre of mass, the relation the
// impact integrates, without Hertz's half-space assumption (Johnson 1985, sec. 4.2 and 11.4). Frictionless unilateral
// contact by an active set on the surface nodes. Bilinear axisymmetric quadrilaterals on a polar mesh about the centre,
// graded towards the contact. Not a test: prints a table.   build/bench/hertz_axisym [refine]
#include <Eigen/Sparse>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Mesh {
  std::vector<double> r, z;           // node coordinates
  std::vector<std::array<int, 4>> q;  // counter-clockwise quads (first ring collapsed at the centre)
  std::vector<int> surface;           // surface nodes, theta ascending from the pole
  std::vector<double> surface_theta;
  int centre = 0;
};

// Graded 1D spacing from a to b: step d0 at a, growing by g per step up to dmax.
std::vector<double> graded(double a, double b, double d0, double g, double dmax) {
  std::vector<double> x{a};
  double d = d0;
  while (x.back() + d < b - 0.5 * d) {
    x.push_back(x.back() + d);
    d = std::min(d * g, dmax);
  }
  x.push_back(b);
  return x;
}

// theta from the pole (contact point) to the top; rho from the surface inwards.
Mesh polar_mesh(double R, double refine, double theta_fine) {
  const double ds = 2.5e-4 / refine;
  std::vector<double> th = graded(0.0, kPi, ds / R, 1.0, ds / R);
  {  // fine up to theta_fine, then growing
    std::vector<double> a = graded(0.0, theta_fine, ds / R, 1.0, ds / R);
    std::vector<double> b = graded(theta_fine, kPi, ds / R, 1.08, 0.01 / refine);
    a.insert(a.end(), b.begin() + 1, b.end());
    th = a;
  }
  std::vector<double> depth = graded(0.0, R, ds, 1.08, R / 100 / refine);  // from the surface inwards
  Mesh m;
  const int nt = static_cast<int>(th.size()), nr = static_cast<int>(depth.size());
  m.centre = 0;
  m.r.push_back(0.0);
  m.z.push_back(R);
  auto id = [&](int i, int j) { return 1 + (i - 1) * nt + j; };  // i: ring counted from the centre (1..nr-1), j: theta
  for (int i = 1; i < nr; ++i) {
    const double rho = R - depth[nr - 1 - i];
    for (int j = 0; j < nt; ++j) {
      m.r.push_back(j == 0 || j == nt - 1 ? 0.0 : rho * std::sin(th[j]));
      m.z.push_back(R - rho * std::cos(th[j]));
    }
  }
  for (int j = 0; j + 1 < nt; ++j) m.q.push_back({m.centre, id(1, j), id(1, j + 1), m.centre});
  for (int i = 1; i + 1 < nr; ++i)
    for (int j = 0; j + 1 < nt; ++j) m.q.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  for (auto& e : m.q) {  // counter-clockwise in (r, z)
    double area = 0;
    for (int k = 0; k < 4; ++k) area += m.r[e[k]] * m.z[e[(k + 1) % 4]] - m.r[e[(k + 1) % 4]] * m.z[e[k]];
    if (area < 0) std::swap(e[1], e[3]);
  }
  for (int j = 0; j < nt; ++j) {
    m.surface.push_back(id(nr - 1, j));
    m.surface_theta.push_back(th[j]);
  }
  return m;
}

struct Result {
  double force, delta_com, delta_centre, contact_radius;
  int dofs;
};

// The axisymmetric stiffness (4-node rings, 2 x 2 Gauss points; strains rr, zz, tt, rz) and the consistent nodal
// weights of a unit downward body force; `volume` is the sphere's.
Eigen::SparseMatrix<double> stiffness(const Mesh& m, double E, double nu, Eigen::VectorXd& vol_z, double& volume) {
  const int n = static_cast<int>(m.r.size()), N = 2 * n;
  Eigen::Matrix4d D = Eigen::Matrix4d::Zero();  // (rr, zz, tt, rz)
  const double c = E / ((1 + nu) * (1 - 2 * nu));
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) D(a, b) = c * (a == b ? 1 - nu : nu);
  D(3, 3) = c * (1 - 2 * nu) / 2;
  const double gp = 1.0 / std::sqrt(3.0);
  std::vector<Eigen::Triplet<double>> trip;
  vol_z = Eigen::VectorXd::Zero(N);
  volume = 0;
  for (const auto& e : m.q) {
    Eigen::Matrix<double, 8, 8> ke = Eigen::Matrix<double, 8, 8>::Zero();
    for (double xi : {-gp, gp})
      for (double eta : {-gp, gp}) {
        const double N4[4] = {(1 - xi) * (1 - eta) / 4, (1 + xi) * (1 - eta) / 4, (1 + xi) * (1 + eta) / 4,
                              (1 - xi) * (1 + eta) / 4};
        const double dxi[4] = {-(1 - eta) / 4, (1 - eta) / 4, (1 + eta) / 4, -(1 + eta) / 4};
        const double deta[4] = {-(1 - xi) / 4, -(1 + xi) / 4, (1 + xi) / 4, (1 - xi) / 4};
        double J[2][2] = {{0, 0}, {0, 0}}, rg = 0;
        for (int k = 0; k < 4; ++k) {
          J[0][0] += dxi[k] * m.r[e[k]];
          J[0][1] += dxi[k] * m.z[e[k]];
          J[1][0] += deta[k] * m.r[e[k]];
          J[1][1] += deta[k] * m.z[e[k]];
          rg += N4[k] * m.r[e[k]];
        }
        const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        if (det <= 0) {
          std::fprintf(stderr, "inverted element\n");
          std::exit(1);
        }
        Eigen::Matrix<double, 4, 8> B = Eigen::Matrix<double, 4, 8>::Zero();
        for (int k = 0; k < 4; ++k) {
          const double dr = (J[1][1] * dxi[k] - J[0][1] * deta[k]) / det;
          const double dz = (-J[1][0] * dxi[k] + J[0][0] * deta[k]) / det;
          B(0, 2 * k) = dr;
          B(1, 2 * k + 1) = dz;
          B(2, 2 * k) = N4[k] / rg;
          B(3, 2 * k) = dz;
          B(3, 2 * k + 1) = dr;
        }
        const double w = 2 * kPi * rg * det;
        ke += B.transpose() * D * B * w;
        volume += w;
        for (int k = 0; k < 4; ++k) vol_z[2 * e[k] + 1] += N4[k] * w;
      }
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b) trip.emplace_back(2 * e[a / 2] + a % 2, 2 * e[b / 2] + b % 2, ke(a, b));
  }
  Eigen::SparseMatrix<double> K(N, N);
  K.setFromTriplets(trip.begin(), trip.end());
  return K;
}

// Quasi-static sphere under a uniform downward body force b (N/m^3) on the flat z = 0: the active set of surface nodes
// held on the plane (penalty), iterated until no node is pulled or penetrates.
Result solve(const Mesh& m, double R, double E, double nu, double F) {
  const int n = static_cast<int>(m.r.size()), N = 2 * n;
  Eigen::VectorXd vol_z;
  double volume = 0;
  const Eigen::SparseMatrix<double> K = stiffness(m, E, nu, vol_z, volume);
  const double big = 1e8 * E * R;
  std::vector<int> fixed_r;  // axis
  for (int i = 0; i < n; ++i)
    if (m.r[i] == 0.0) fixed_r.push_back(2 * i);
  const double b = F / volume;
  Eigen::VectorXd f = -b * vol_z;
  std::vector<char> active(m.surface.size(), 0);
  active[0] = 1;
  Eigen::VectorXd u;
  for (int it = 0; it < 200; ++it) {
    Eigen::SparseMatrix<double> Kc = K;
    Eigen::VectorXd fc = f;
    for (int d : fixed_r) Kc.coeffRef(d, d) += big;
    for (size_t s = 0; s < m.surface.size(); ++s)
      if (active[s]) {
        const int d = 2 * m.surface[s] + 1;
        Kc.coeffRef(d, d) += big;
        fc[d] += big * (-m.z[m.surface[s]]);
      }
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Kc);
    u = ldlt.solve(fc);
    bool changed = false;
    for (size_t s = 0; s < m.surface.size(); ++s) {
      const int node = m.surface[s];
      const double gap = m.z[node] + u[2 * node + 1];
      const double reaction = big * (-m.z[node] - u[2 * node + 1]);  // upward on the sphere when positive
      if (active[s] && reaction < 0) active[s] = 0, changed = true;
      else if (!active[s] && gap < -1e-12 * R) active[s] = 1, changed = true;
    }
    if (!changed) break;
  }
  Result res{F, 0, -u[2 * m.centre + 1], 0, N};
  res.delta_com = -u.dot(vol_z) / volume;
  for (size_t s = 0; s < m.surface.size(); ++s)
    if (active[s]) res.contact_radius = std::max(res.contact_radius, m.r[m.surface[s]]);
  return res;
}

}  // namespace

int main(int argc, char** argv) {
  const double refine = argc > 1 ? std::atof(argv[1]) : 1.0;
  const double R = 0.1, E = 1e8, nu = 0.3, Es = E / (1 - nu * nu);
  const Mesh m = polar_mesh(R, refine, 0.35);
  std::printf("sphere R %g m, E %g Pa, nu %g on a rigid flat; axisymmetric FE, %zu elements, surface step %.3g mm\n\n", R,
              E, nu, m.q.size(), 0.25 / refine);
  std::printf("| F (kN) | approach of centre of mass (mm) | Hertz approach (mm) | F / Hertz F at that approach | "
              "contact radius (mm) | Hertz a (mm) |\n|---|---|---|---|---|---|\n");
  // The force-approach curve: ratio to Hertz's force at the same approach, tabulated against the approach.
  std::vector<double> dd{0.0}, ratio{1.0};
  for (double F = 20.0; F < 9500.0; F *= 1.25) {
    const Result r = solve(m, R, E, nu, F);
    const double dh = std::cbrt(9 * F * F / (16 * Es * Es * R));
    const double ah = std::cbrt(3 * F * R / (4 * Es));
    const double fh = 4.0 / 3.0 * Es * std::sqrt(R) * std::pow(r.delta_com, 1.5);
    dd.push_back(r.delta_com);
    ratio.push_back(F / fh);
    std::printf("| %.3f | %.4f | %.4f | %.4f | %.2f | %.2f |\n", F / 1e3, r.delta_com * 1e3, dh * 1e3, F / fh,
                r.contact_radius * 1e3, ah * 1e3);
    std::fflush(stdout);
  }
  // Quasi-static impact on this curve (Johnson 1985, sec. 11.4): m v dv = -F(delta) d delta.
  const double rho = 1000.0, v0 = 2.0, mass = rho * 4.0 / 3.0 * kPi * R * R * R;
  auto force = [&](double d) {
    size_t k = 1;
    while (k + 1 < dd.size() && dd[k] < d) ++k;
    const double w = (d - dd[k - 1]) / (dd[k] - dd[k - 1]);
    return (ratio[k - 1] + w * (ratio[k] - ratio[k - 1])) * 4.0 / 3.0 * Es * std::sqrt(R) * std::pow(d, 1.5);
  };
  double d = 0, v = v0, t = 0, fmax = 0, dmax = 0, t_all = 0;
  std::vector<std::pair<double, double>> hist;  // (t, F), velocity Verlet
  const double dt = 1e-8;
  double a = 0;
  do {
    d += v * dt + 0.5 * a * dt * dt;
    const double an = d > 0 ? -force(d) / mass : 0.0;
    v += 0.5 * (a + an) * dt;
    a = an;
    t += dt;
    const double F = -a * mass;
    hist.emplace_back(t, F);
    fmax = std::max(fmax, F);
    dmax = std::max(dmax, d);
  } while (d > 0);
  t_all = t;
  double t_1pc = 0;
  for (const auto& [ti, F] : hist)
    if (F > 0.01 * fmax) t_1pc += dt;
  const double dh = std::pow(15 * mass * v0 * v0 / (16 * Es * std::sqrt(R)), 0.4);
  const double fh = 4.0 / 3.0 * Es * std::sqrt(R) * std::pow(dh, 1.5);
  const double th = 2.9432 * dh / v0, th1 = th - 2 * std::pow(0.01, 2.0 / 3.0) * dh / v0;
  std::printf("\nimpact at %g m/s, mass %.4f kg\n\n| | peak force (kN) | max approach (mm) | contact time (ms) | "
              "time above 1 %% of peak (ms) |\n|---|---|---|---|---|\n", v0, mass);
  std::printf("| Hertz | %.3f | %.4f | %.3f | %.3f |\n", fh / 1e3, dh * 1e3, th * 1e3, th1 * 1e3);
  std::printf("| finite sphere (this model) | %.3f | %.4f | %.3f | %.3f |\n", fmax / 1e3, dmax * 1e3, t_all * 1e3,
              t_1pc * 1e3);
  std::printf("| ratio | %.4f | %.4f | %.4f | %.4f |\n", fmax / fh, dmax / dh, t_all / th, t_1pc / th1);
  return 0;
}
