#include "surfaces/spherical/local_contact.h"

#include <cmath>

#include <algorithm>
#include <numbers>

#include <Eigen/Dense>

#include "framework/core/demand.h"
#include "framework/core/error.h"
#include "surfaces/spherical/gauss_legendre.h"

namespace fitfeel::spherical {

double ContactModulus(const Material& a, const Material& b) {
  return 1.0 / ((1.0 - a.poisson * a.poisson) / a.youngs_modulus +
                (1.0 - b.poisson * b.poisson) / b.youngs_modulus);
}

namespace {

// Hertz's contact at the curvature radius r and the approach, its load times `share`.
HertzContact Hertz(double r, double approach, double contact_modulus, double share) {
  HertzContact h;
  h.radius = std::sqrt(r * approach);
  h.load = 4.0 / 3.0 * contact_modulus * std::sqrt(r) * approach * std::sqrt(approach) * share;
  h.peak_pressure = 1.5 * h.load / (std::numbers::pi * h.radius * h.radius);
  return h;
}

}  // namespace

HertzContact ConformalHertz(double ball_radius, double clearance, double approach,
                            double contact_modulus) {
  if (!(ball_radius > 0.0) || !(clearance > 0.0) || !(approach > 0.0)) return {};
  return Hertz(ball_radius * (ball_radius + clearance) / clearance, approach, contact_modulus, 1.0);
}

HertzContact LocalContact(double ball_radius, double clearance, double approach,
                          double contact_modulus) {
  if (!(ball_radius > 0.0) || !(clearance > 0.0) || !(approach > 0.0)) return {};
  // The gap's curvature R = R1 R2 / e (e = c + delta, the centres' distance), held to the radius
  // that keeps a = sqrt(R delta) at 0.3 R1.
  const double r =
      std::min(ball_radius * (ball_radius + clearance) / (clearance + approach),
               kHertzMaxSpread * kHertzMaxSpread * ball_radius * ball_radius / approach);
  return Hertz(r, approach, contact_modulus, std::min(1.0, clearance / approach));
}

double BondedLayerFactor(double kh, double poisson) {
  // Beyond kh = 20 the layer's face is a half-space's to 1e-14 (and cosh would overflow later).
  if (kh > 20.0) return 1.0;
  const double kappa = 3.0 - 4.0 * poisson;
  return (kappa * std::sinh(2.0 * kh) - 2.0 * kh) /
         (kappa * std::cosh(2.0 * kh) + 2.0 * kh * kh + 5.0 - 12.0 * poisson +
          8.0 * poisson * poisson);
}

namespace {

constexpr double kPi = std::numbers::pi;

// Boussinesq: the normal displacement at radius r of a half-space's face under a unit pressure on
// a disc of radius b, times E / (1 - nu^2) (Johnson 1985, 3.4).
double DiscDisplacement(double b, double r) {
  if (!(b > 0.0)) return 0.0;
  if (r <= b) return 4.0 * b / kPi * std::comp_ellint_2(r / b);
  const double m = b / r;
  return 4.0 * r / kPi * (std::comp_ellint_2(m) - (1.0 - m * m) * std::comp_ellint_1(m));
}

struct Patch {
  double load = 0.0, radius = 0.0, peak = 0.0;
};

// Boussinesq's displacement of ring i's middle under a unit pressure on ring j, times E / (1 -
// nu^2), on rings of width 1.8 / kRings: for rings of width w it scales with w.
Eigen::MatrixXd UnitRingInfluence() {
  constexpr int n = LayeredConformalContact::kRings;
  const double dr = 1.8 / n;
  Eigen::MatrixXd influence(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      influence(i, j) =
          DiscDisplacement((j + 1) * dr, (i + 0.5) * dr) - DiscDisplacement(j * dr, (i + 0.5) * dr);
    }
  }
  return influence;
}

// The axisymmetric contact of Hertz radius a_h (the gap r^2 / (2 R) - delta with R = a_h^2 /
// delta) with the walls' corrections when `walls`, on kRings rings out to 1.8 a_h: a bonded layer
// carries its patch out to sqrt(2) a_h at most (a Winkler bed's), a half-space to a_h.
Patch SolvePatch(double a_h, double delta, const ContactSide& ball, const ContactSide& ring,
                 const Eigen::MatrixXd& unit_influence, bool walls) {
  constexpr int n = LayeredConformalContact::kRings;
  const double extent = 1.8 * a_h, dr = extent / n;
  Eigen::VectorXd edge(n + 1), mid(n);
  for (int j = 0; j <= n; ++j) edge[j] = j * dr;
  for (int i = 0; i < n; ++i) mid[i] = (i + 0.5) * dr;
  const ContactSide* sides[2] = {&ball, &ring};
  double compliance = 0.0;
  for (const ContactSide* side : sides) {
    compliance +=
        (1.0 - side->material.poisson * side->material.poisson) / side->material.youngs_modulus;
  }
  Eigen::MatrixXd influence = (compliance * a_h) * unit_influence;
  const double thinnest = std::min(ball.wall, ring.wall);
  if (walls && std::isfinite(thinnest)) {
    // Each wall adds the integral over k of 2 (1 - nu^2)/E (K(kh) - 1) p_hat(k) J0(k r), p_hat of
    // a unit ring [a, b] being (b J1(kb) - a J1(ka)) / k; K - 1 falls as (kh)^2 exp(-2kh), under
    // 1e-8 beyond kh = 12, so k runs to 12 / h, in Gauss panels of half J0's period at the
    // grid's far edge.
    const double k_end = 12.0 / thinnest, panel = kPi / (2.0 * extent);
    const int panels = std::max(4, static_cast<int>(std::ceil(k_end / panel)));
    const int q = 4 * panels;
    Eigen::MatrixXd j0(n, q), ring_transform(q, n);
    Eigen::VectorXd weight = Eigen::VectorXd::Zero(q);
    for (int p = 0; p < panels; ++p) {
      for (int g = 0; g < 4; ++g) {
        const int c = 4 * p + g;
        const double k = (p + 0.5 + 0.5 * kGaussNodes4[g]) * (k_end / panels);
        for (const ContactSide* side : sides) {
          if (!std::isfinite(side->wall)) continue;
          const double nu = side->material.poisson;
          weight[c] += 2.0 * (1.0 - nu * nu) / side->material.youngs_modulus *
                       (BondedLayerFactor(k * side->wall, nu) - 1.0);
        }
        weight[c] *= 0.5 * kGaussWeights4[g] * (k_end / panels) / k;
        for (int i = 0; i < n; ++i) j0(i, c) = std::cyl_bessel_j(0.0, k * mid[i]);
        double inner = 0.0;
        for (int j = 0; j < n; ++j) {
          const double outer = edge[j + 1] * std::cyl_bessel_j(1.0, k * edge[j + 1]);
          ring_transform(c, j) = outer - inner;
          inner = outer;
        }
      }
    }
    influence.noalias() += j0 * weight.asDiagonal() * ring_transform;
  }
  // The patch is a disc: drop outer rings while the outermost pulls.
  int m = n;
  Eigen::VectorXd pressure;
  for (;; --m) {
    const Eigen::ArrayXd r = mid.head(m).array();
    const Eigen::VectorXd interference = delta * (1.0 - r * r / (2.0 * a_h * a_h));
    pressure = influence.topLeftCorner(m, m).partialPivLu().solve(interference);
    if (pressure[m - 1] >= 0.0 || m == 2) break;
  }
  FITFEEL_DEMAND(m < n && m >= 2);
  Patch patch;
  for (int j = 0; j < m; ++j) {
    patch.load += pressure[j] * kPi * (edge[j + 1] * edge[j + 1] - edge[j] * edge[j]);
  }
  patch.peak = pressure[0];
  // The edge where p^2 (linear near a smooth contact's edge) reaches zero, from the last two rings.
  const double outer = pressure[m - 1] * pressure[m - 1], inner = pressure[m - 2] * pressure[m - 2];
  patch.radius = mid[m - 1] + (inner > outer ? outer / (inner - outer) * dr : 0.5 * dr);
  patch.radius = std::min(patch.radius, edge[m] + 0.5 * dr);
  return patch;
}

// a + t (b - a), field by field.
LayeredConformalContact::Ratios Mix(const LayeredConformalContact::Ratios& a,
                                    const LayeredConformalContact::Ratios& b, double t) {
  return {a.load + t * (b.load - a.load), a.radius + t * (b.radius - a.radius),
          a.peak_pressure + t * (b.peak_pressure - a.peak_pressure)};
}

}  // namespace

LayeredConformalContact::LayeredConformalContact(double ball_radius, const ContactSide& ball,
                                                 const ContactSide& ring)
    : ball_radius_(ball_radius), contact_modulus_(ContactModulus(ball.material, ring.material)) {
  if (!(ball_radius > 0.0)) throw UserError("layered contact needs a positive ball radius");
  for (const ContactSide* side : {&ball, &ring}) {
    if (!(side->material.youngs_modulus > 0.0) || !(side->wall > 0.0)) {
      throw UserError("layered contact needs positive Young's moduli and walls");
    }
  }
  wall_ = std::min(ball.wall, ring.wall);
  if (!std::isfinite(wall_)) return;
  // s at the cap a = 0.3 R1 (LocalContact never goes past it) or where the walls are a bed, and
  // kSpan below.
  const double highest = std::min(std::pow(kHertzMaxSpread * ball_radius / wall_, 2), kBed);
  log_lowest_ = std::log(highest / kSpan);
  log_step_ = std::log(kSpan) / (kPoints - 1);
  constexpr double kApproach = 1e-6;  // any: the ratios depend on s alone
  const Eigen::MatrixXd unit = UnitRingInfluence();
  for (int k = 0; k < kPoints; ++k) {
    const double a_h = wall_ * std::exp(0.5 * (log_lowest_ + k * log_step_));
    const Patch walls = SolvePatch(a_h, kApproach, ball, ring, unit, true);
    const Patch halves = SolvePatch(a_h, kApproach, ball, ring, unit, false);
    table_[k] = {walls.load / halves.load, walls.radius / halves.radius, walls.peak / halves.peak};
  }
}

LayeredConformalContact::Ratios LayeredConformalContact::RatiosAt(double s) const noexcept {
  if (!std::isfinite(wall_) || !(s > 0.0)) return {};
  const double x = (std::log(s) - log_lowest_) / log_step_;
  if (x <= 0.0) {
    // Below the table the walls' effect fades as a / h, i.e. sqrt(s).
    return Mix(Ratios{}, table_[0], std::sqrt(s / std::exp(log_lowest_)));
  }
  if (x >= kPoints - 1) {
    // A bed's load and peak pressure grow as a / h against Hertz's, its patch as Hertz's.
    const double f = std::sqrt(s / std::exp(log_lowest_ + (kPoints - 1) * log_step_));
    const Ratios& top = table_[kPoints - 1];
    return {top.load * f, top.radius, top.peak_pressure * f};
  }
  const int k = static_cast<int>(x);
  return Mix(table_[k], table_[k + 1], x - k);
}

HertzContact LayeredConformalContact::Load(double clearance, double approach) const noexcept {
  HertzContact h = LocalContact(ball_radius_, clearance, approach, contact_modulus_);
  if (!(h.load > 0.0) || !std::isfinite(wall_)) return h;
  const Ratios r = RatiosAt(h.radius * h.radius / (wall_ * wall_));
  h.load *= r.load;
  h.radius *= r.radius;
  h.peak_pressure *= r.peak_pressure;
  return h;
}

}  // namespace fitfeel::spherical
