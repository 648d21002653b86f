#include "surfaces/cylindrical/elastic/harmonic_compliance.h"

#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Dense>

#include "framework/core/error.h"

namespace fitfeel::cylindrical {
namespace {

// Effective constants of the 2-D problem: plane strain is plane stress with E / (1 - nu^2) and
// nu / (1 - nu).
struct Elastic {
  double e;
  double nu;
};

Elastic Effective(const Material& m, bool plane_strain) {
  if (!(m.youngs_modulus > 0.0) || !PoissonInRange(m.poisson)) {
    throw UserError("material '" + m.name +
                    "': elastic compliance needs E > 0 and 0 <= Poisson < 0.5");
  }
  if (!plane_strain) return {m.youngs_modulus, m.poisson};
  return {m.youngs_modulus / (1.0 - m.poisson * m.poisson), m.poisson / (1.0 - m.poisson)};
}

// One Michell term, Airy function phi = (r / R)^k cos(n theta): its sigma_rr and sigma_rtheta
// amplitudes (cos and sin parts) and the radial displacement u_r at radius r. Normalising each
// power at its own radius R keeps every value at most of order one for any n.
struct Term {
  double srr, srt, ur;
};

Term MichellTerm(double k, double big_r, double r, int n, const Elastic& m) {
  const double nn = static_cast<double>(n) * n;
  const double s = std::pow(r / big_r, k - 2.0) / (big_r * big_r);
  Term t;
  t.srr = (k - nn) * s;
  t.srt = n * (k - 1.0) * s;
  // eps_rr = (sigma_rr - nu sigma_tt) / E integrated in r; for n >= 2 no rigid motion remains.
  t.ur = ((k - nn) - m.nu * k * (k - 1.0)) / ((k - 1.0) * m.e) * std::pow(r / big_r, k - 1.0) /
         big_r;
  return t;
}

// Radial displacement at r = a of a ring a0 < a1 (solid when a0 = 0) loaded by p cos(n theta) on
// the boundary `loaded` (a0 or a1, the other free), per unit p: the ring's part of the closure.
double RingDisplacement(double a0, double a1, bool load_outer, int n, const Elastic& m) {
  const double nd = n;
  const double loaded = load_outer ? a1 : a0;
  if (a0 == 0.0) {
    // Solid disc: the regular terms r^n and r^{n+2}.
    const double ks[2] = {nd, nd + 2.0};
    Eigen::Matrix2d a;
    for (int c = 0; c < 2; ++c) {
      const Term t = MichellTerm(ks[c], a1, a1, n, m);
      a(0, c) = t.srr;
      a(1, c) = t.srt;
    }
    const Eigen::Vector2d coef = a.fullPivLu().solve(Eigen::Vector2d(-1.0, 0.0));
    double u = 0.0;
    for (int c = 0; c < 2; ++c) u += coef[c] * MichellTerm(ks[c], a1, a1, n, m).ur;
    return u;
  }
  // Growing powers normalised at the outer radius, decaying ones at the inner.
  const double ks[4] = {nd, nd + 2.0, -nd, 2.0 - nd};
  const double rs[4] = {a1, a1, a0, a0};
  Eigen::Matrix4d a;
  Eigen::Vector4d rhs(0.0, 0.0, 0.0, 0.0);
  const double radii[2] = {a0, a1};
  for (int b = 0; b < 2; ++b) {
    for (int c = 0; c < 4; ++c) {
      const Term t = MichellTerm(ks[c], rs[c], radii[b], n, m);
      a(2 * b, c) = t.srr;
      a(2 * b + 1, c) = t.srt;
    }
    if (radii[b] == loaded) rhs[2 * b] = -1.0;  // sigma_rr = -p, sigma_rtheta = 0
  }
  const Eigen::Vector4d coef = a.fullPivLu().solve(rhs);
  double u = 0.0;
  for (int c = 0; c < 4; ++c) u += coef[c] * MichellTerm(ks[c], rs[c], loaded, n, m).ur;
  return u;
}

// Order 1 of the ring a0 < r < a1 (solid when a0 = 0) loaded by p cos(theta) on the boundary
// `load_outer` names (the other free), the net force balanced by a uniform body force (the
// rest of the part, whose axis is rigid in the model, carries it): the loaded face's radial
// displacement amplitude relative to the section's area-mean displacement, per unit p.
//
// Plane stress with body force f = -beta e_x; u_r = U(r) cos theta, u_theta = V(r) sin theta.
// With the dilatation D cos theta and the rotation W sin theta, Navier's equations in polar
// coordinates read L D' - 2 mu W / r = beta, -L D / r + 2 mu W' = -beta (L = E / (1 - nu^2)), so
// D = alpha r + gamma / r, W = (L / 2 mu)(alpha r - gamma / r) - beta r / (2 mu). With
// S = U + V and T = U - V (T's constant is the rigid translation, left out):
//   S = alpha (1 + L/mu) r^2 / 4 + gamma (1 - L/mu) / 2 - beta r^2 / (4 mu) + kappa / r^2,
//   T = alpha (1 - L/mu) r^2 / 2 + gamma (1 + L/mu) ln(r / a1) + beta r^2 / (2 mu),
// sigma_rr = L (U' + nu S / r), sigma_rtheta = mu (V' - S / r), and the area-mean u_x is the mean
// of T / 2. A solid disc keeps only alpha (regular at the axis): its stress is sigma_xx =
// sigma_yy = -p x / a1, and the rim moves (1 - nu) p a1 / (2E) towards the centre relative to the
// centroid (tested).
double OrderOneDisplacement(double a0, double a1, bool load_outer, const Elastic& m) {
  const double mu = m.e / (2.0 * (1.0 + m.nu)), l = m.e / (1.0 - m.nu * m.nu);
  const double loaded = load_outer ? a1 : a0;
  // Net force of the face load along x: -pi a1 (pressed inwards) or +pi a0 (pushed outwards).
  const double beta = (load_outer ? -a1 : a0) / (a1 * a1 - a0 * a0);
  // The fields at r for the coefficients c = (alpha, gamma, kappa) (linear, plus beta's part):
  // each row is (the three coefficients' parts, beta's part).
  struct Row {
    Eigen::Vector3d c;
    double b;
  };
  const double g = l / mu;
  // kx x + ky y, row by row.
  auto add = [](const Row& x, double kx, const Row& y, double ky) {
    return Row{kx * x.c + ky * y.c, kx * x.b + ky * y.b};
  };
  auto fields = [&](double r, Row* u, Row* srr, Row* srt) {
    const Row d{{r, 1.0 / r, 0.0}, 0.0};
    const Row w{{0.5 * g * r, -0.5 * g / r, 0.0}, -r / (2.0 * mu)};
    const Row sv{{(1.0 + g) * r * r / 4.0, (1.0 - g) / 2.0, 1.0 / (r * r)}, -r * r / (4.0 * mu)};
    const Row t{{(1.0 - g) * r * r / 2.0, (1.0 + g) * std::log(r / a1), 0.0}, r * r / (2.0 * mu)};
    const Row sp = add(add(d, 1.0, w, 2.0), 1.0, sv, -2.0 / r);  // S'
    const Row tp = add(d, 1.0, w, -2.0);                         // T'
    if (u != nullptr) *u = add(sv, 0.5, t, 0.5);
    // U' = (S' + T') / 2, V' = (S' - T') / 2.
    *srr = add(add(sp, 0.5 * l, tp, 0.5 * l), 1.0, sv, l * m.nu / r);
    *srt = add(add(sp, 0.5 * mu, tp, -0.5 * mu), 1.0, sv, -mu / r);
  };
  // Traction conditions: sigma_rr = -1 and sigma_rtheta = 0 on the loaded face, both zero on a
  // free one; equilibrium makes one of them redundant (least squares solves them exactly).
  const bool solid = a0 == 0.0;
  const int faces = solid ? 1 : 2;
  Eigen::MatrixXd a(2 * faces, 3);
  Eigen::VectorXd rhs(2 * faces);
  for (int f = 0; f < faces; ++f) {
    const double r = solid || f == 1 ? a1 : a0;
    Row srr, srt;
    fields(r, nullptr, &srr, &srt);
    a.row(2 * f) = srr.c.transpose();
    a.row(2 * f + 1) = srt.c.transpose();
    rhs[2 * f] = (r == loaded ? -1.0 : 0.0) - srr.b * beta;
    rhs[2 * f + 1] = -srt.b * beta;
  }
  // Columns scaled to unit norm: the coefficients differ by powers of the radius.
  const int unknowns = solid ? 1 : 3;
  Eigen::VectorXd scale = a.leftCols(unknowns).colwise().norm().cwiseInverse().transpose();
  const Eigen::VectorXd y =
      (a.leftCols(unknowns) * scale.asDiagonal()).colPivHouseholderQr().solve(rhs);
  Eigen::Vector3d coef = Eigen::Vector3d::Zero();
  coef.head(unknowns) = scale.cwiseProduct(y);
  Row u, srr, srt;
  fields(loaded, &u, &srr, &srt);
  const double face = u.c.dot(coef) + u.b * beta;
  // Area-mean of T / 2: integral of T r dr over the section's (a1^2 - a0^2) / 2.
  auto t_moment = [&](double r) {  // integral of T r dr from 0 (the log term: r^2 ln / 2 - r^2 / 4)
    const double log_part = r == 0.0 ? 0.0 : r * r / 2.0 * std::log(r / a1) - r * r / 4.0;
    return coef[0] * (1.0 - g) * std::pow(r, 4) / 8.0 + coef[1] * (1.0 + g) * log_part +
           beta / (2.0 * mu) * std::pow(r, 4) / 4.0;
  };
  const double mean = (t_moment(a1) - t_moment(a0)) / (a1 * a1 - a0 * a0);
  return face - mean;
}

void CheckSection(const PressFitSection& s) {
  if (!(s.d1 > 0.0) || !(s.d2 > s.d1) || !(s.di >= 0.0 && s.di < s.d1)) {
    throw UserError("press-fit section needs 0 <= shaft bore < interface diameter < hub outer "
                    "diameter");
  }
}

}  // namespace

double HarmonicCompliance(const PressFitSection& s, int n) {
  CheckSection(s);
  if (n < 0) {
    throw UserError("harmonic compliance is defined for orders >= 0 (order " + std::to_string(n) +
                    " asked)");
  }
  const Elastic ms = Effective(s.shaft, s.plane_strain);
  const Elastic mh = Effective(s.hub, s.plane_strain);
  const double a = 0.5 * s.d1, b = 0.5 * s.d2, c = 0.5 * s.di;
  if (n == 0) {
    // Lame: u = a (c_shaft / E1 + c_hub / E2) per unit pressure.
    const double c_shaft = (a * a + c * c) / (a * a - c * c) - ms.nu;
    const double c_hub = (b * b + a * a) / (b * b - a * a) + mh.nu;
    return a * (c_shaft / ms.e + c_hub / mh.e);
  }
  // The shaft's share and the hub's, each opening the interface.
  return RingHarmonicCompliance(c, a, /*loaded_inside=*/false, s.shaft, s.plane_strain, n) +
         RingHarmonicCompliance(a, b, /*loaded_inside=*/true, s.hub, s.plane_strain, n);
}

double RingHarmonicCompliance(double inner_radius, double outer_radius, bool loaded_inside,
                              const Material& material, bool plane_strain, int n) {
  if (!(inner_radius >= 0.0) || !(outer_radius > inner_radius) || n < 1) {
    throw UserError("a ring's harmonic compliance needs 0 <= inner < outer radius and order >= 1");
  }
  const Elastic m = Effective(material, plane_strain);
  const double u = n == 1 ? OrderOneDisplacement(inner_radius, outer_radius, !loaded_inside, m)
                          : RingDisplacement(inner_radius, outer_radius, !loaded_inside, n, m);
  // A shaft moves inward (its displacement along +r is negative under pressure), a hub out.
  return loaded_inside ? u : -u;
}

std::vector<double> CirculantCompliance(const PressFitSection& section, int n_columns) {
  if (n_columns < 4 || n_columns % 2 != 0) {
    throw UserError("a circulant contact needs an even number of columns >= 4");
  }
  std::vector<double> c(static_cast<std::size_t>(n_columns / 2) + 1);
  for (int k = 0; k <= n_columns / 2; ++k) {
    c[static_cast<std::size_t>(k)] = HarmonicCompliance(section, k);
  }
  return c;
}

double Din7190RadialSmoothing(const TextureSpec& inner, const TextureSpec& outer) {
  return 0.4 * (inner.rz + outer.rz);
}

double ContactModulus(const Material& a, const Material& b) {
  return 1.0 / ((1.0 - a.poisson * a.poisson) / a.youngs_modulus +
                (1.0 - b.poisson * b.poisson) / b.youngs_modulus);
}

double PlasticityIndex(double contact_modulus, double hardness, double sigma,
                       double summit_radius) {
  if (!(hardness > 0.0) || !(summit_radius > 0.0) || !(sigma >= 0.0)) {
    throw UserError("plasticity index needs hardness > 0, summit radius > 0 and sigma >= 0");
  }
  return contact_modulus / hardness * std::sqrt(sigma / summit_radius);
}

double EquivalentSigmaFromRa(const TextureSpec& a, const TextureSpec& b) {
  const double k = std::sqrt(std::numbers::pi / 2.0);
  return std::hypot(k * a.ra, k * b.ra);
}

}  // namespace fitfeel::cylindrical
