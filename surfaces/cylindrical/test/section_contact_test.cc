#include "surfaces/cylindrical/elastic/section_contact.h"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "surfaces/cylindrical/test/steel_pair.h"
#include "framework/testing/units.h"

namespace fitfeel::cylindrical {
namespace {

using testing::SteelPair;

using fitfeel::test_support::kPi;

// One slice of length L as a section of n cells.
ContactSection Slice(const std::vector<double>& gap, double length, double d = 0.020) {
  ContactSection s;
  s.gap = gap.data();
  s.cell_area = kPi * d * length / static_cast<double>(gap.size());
  return s;
}

// A part `length` long in gaps->size() equal slices about its middle, slice i's gap at column j
// (of n, at angle theta) gap(i, theta), free to tilt under a radial load of (30, -50) N.
template <typename Gap>
std::vector<ContactSection> LoadedStack(std::vector<std::vector<double>>* gaps, int n,
                                        double length, const Gap& gap, RigidFreedom* freedom) {
  const int rows = static_cast<int>(gaps->size());
  std::vector<ContactSection> sections;
  for (int i = 0; i < rows; ++i) {
    (*gaps)[i].resize(n);
    for (int j = 0; j < n; ++j) (*gaps)[i][j] = gap(i, 2 * kPi * j / n);
    ContactSection s = Slice((*gaps)[i], length / rows);
    s.y = (i + 0.5) * length / rows - length / 2;
    sections.push_back(s);
  }
  freedom->tilt = true;
  freedom->force = Eigen::Vector2d(30.0, -50.0);
  return sections;
}

TEST(CirculantContact, SolutionIsComplementary) {
  const int n = 72;
  CirculantContact c(CirculantCompliance(SteelPair(), n), n);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2e-6, 1e-6);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> delta(n), p(n);
    for (double& d : delta) d = u(rng);
    std::vector<char> active;
    c.Solve(delta.data(), p.data(), &active);
    const Eigen::Map<const Eigen::VectorXd> pv(p.data(), n), dv(delta.data(), n);
    const Eigen::VectorXd w = c.matrix() * pv - dv;
    for (int j = 0; j < n; ++j) {
      EXPECT_GE(p[j], 0.0);
      EXPECT_GE(w[j], -1e-17);
      EXPECT_LE(p[j] * w[j], 1e-9 * 1e-6 * 1e6) << j;
    }
  }
}

// The axial coupling's Newton step needs a section's response to harmonic gap shifts: E_F^T
// G_FF^-1 E_F on its contact set, whichever factor (primal, dual, full contact) the solve left.
// Against finite differences of the solve itself, on random partial and full contacts.
TEST(CirculantContact, ShiftStiffnessIsThePressuresDerivative) {
  const int n = 48;
  const std::vector<double> compliance = CirculantCompliance(SteelPair(), n);
  CirculantContact c(compliance, n);
  Eigen::MatrixXd basis(n, 5), inverse(n, 5);
  for (int j = 0; j < n; ++j) {
    const double t = 2 * kPi * j / n;
    basis.row(j) << 1.0, std::cos(2 * t), std::sin(2 * t), std::cos(t), std::sin(t);
  }
  for (int k = 0; k < 5; ++k) c.InverseTimes(basis.col(k).data(), inverse.col(k).data());
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2e-6, 1e-6);
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<double> delta(n), p(n), q(n);
    const double mean = trial % 4 == 0 ? 6e-6 : 0.0;  // every fourth all round
    for (double& d : delta) d = u(rng) + mean;
    CirculantContact::Factorization ws;
    std::vector<char> active, again;
    c.Solve(delta.data(), p.data(), &active, nullptr, &ws);
    const Eigen::MatrixXd s = c.ShiftStiffness(ws, basis, inverse, basis.transpose() * inverse);
    const double h = 1e-13;  // small enough to keep the contact set
    for (int k = 0; k < 5; ++k) {
      std::vector<double> shifted(delta);
      for (int j = 0; j < n; ++j) shifted[j] -= h * basis(j, k);
      again = active;
      c.Solve(shifted.data(), q.data(), &again);
      ASSERT_EQ(again, active) << trial;
      const Eigen::VectorXd dp = (Eigen::Map<const Eigen::VectorXd>(q.data(), n) -
                                  Eigen::Map<const Eigen::VectorXd>(p.data(), n)) /
                                 h;
      const Eigen::VectorXd response = basis.transpose() * dp;
      EXPECT_LT((response + s.col(k)).norm(), 1e-5 * s.norm()) << trial << " " << k;
    }
  }
}

TEST(RigidSectionContact, OvalFieldInFullContactCarriesOnlyItsMean) {
  // delta0 + delta2 cos 2 theta with delta0 >= 0.145 delta2 stays in full contact, and the normal
  // force is P0 delta0 pi d L exactly: cos 2 theta integrates to zero.
  const PressFitSection sec = SteelPair();
  const double p0 = 1.0 / HarmonicCompliance(sec, 0);
  const int n = 90;
  const double d2 = 4e-6, l = 0.02;
  RigidSectionContact solver(sec, n);
  for (double ratio : {0.146, 0.2, 0.5}) {
    std::vector<double> gap(n);
    for (int j = 0; j < n; ++j) gap[j] = -(ratio * d2 + d2 * std::cos(2 * 2 * kPi * j / n));
    const ContactSection s = Slice(gap, l);
    const RigidContactResult r = solver.Solve({&s, 1}, RigidFreedom{}, Eigen::Vector4d::Zero());
    EXPECT_NEAR(r.normal_force / (p0 * ratio * d2 * kPi * 0.020 * l), 1.0, 1e-9) << ratio;
    EXPECT_LT(r.offset.norm(), 1e-15);
  }
  // Below the threshold contact opens and the force exceeds the mean's share.
  std::vector<double> gap(n);
  for (int j = 0; j < n; ++j) gap[j] = -(0.05 * d2 + d2 * std::cos(2 * 2 * kPi * j / n));
  const ContactSection s = Slice(gap, l);
  const RigidContactResult r = solver.Solve({&s, 1}, RigidFreedom{}, Eigen::Vector4d::Zero());
  EXPECT_GT(r.normal_force, 1.01 * p0 * 0.05 * d2 * kPi * 0.020 * l);
}

TEST(RigidSectionContact, OffsetFieldIsTakenUpByTheRigidOffset) {
  // A shaft displaced sideways in a bore of equal size: the part moves back, no force remains.
  const int n = 48;
  RigidSectionContact solver(SteelPair(), n);
  std::vector<double> gap(n);
  for (int j = 0; j < n; ++j) gap[j] = 0.5e-6 - 3e-6 * std::cos(2 * kPi * j / n);
  const ContactSection s = Slice(gap, 0.01);
  const RigidContactResult r = solver.Solve({&s, 1}, RigidFreedom{}, Eigen::Vector4d::Zero());
  EXPECT_LT(r.normal_force, 1e-6);
}

TEST(RigidSectionContact, TiltedBoreWithinClearanceCarriesNoForceWhenTiltIsFree) {
  // Bore tilted by phi over L = 20 mm: phi L / 2 = 3 um against a radial clearance of 2 um, so a
  // shaft that may not tilt interferes at both ends, and one that may tilt carries nothing.
  const int n = 48, rows = 20;
  const double l = 0.02, phi = 3e-4, clearance = 2e-6;
  RigidSectionContact solver(SteelPair(), n);
  std::vector<std::vector<double>> gaps(rows, std::vector<double>(n));
  std::vector<ContactSection> sections;
  for (int i = 0; i < rows; ++i) {
    const double y = (i + 0.5) * l / rows - l / 2;
    for (int j = 0; j < n; ++j) gaps[i][j] = clearance + phi * y * std::sin(2 * kPi * j / n);
    ContactSection s = Slice(gaps[i], l / rows);
    s.y = y;
    sections.push_back(s);
  }
  RigidFreedom fixed;
  EXPECT_GT(solver.Solve(sections, fixed, Eigen::Vector4d::Zero()).normal_force, 10.0);
  RigidFreedom free;
  free.tilt = true;
  const RigidContactResult r = solver.Solve(sections, free, Eigen::Vector4d::Zero());
  EXPECT_LT(r.normal_force, 1e-6);
  // A holder that resists tilt shares the misalignment with the contact.
  free.tilt_stiffness = 1e5;
  const RigidContactResult held = solver.Solve(sections, free, Eigen::Vector4d::Zero());
  EXPECT_GT(held.normal_force, 0.0);
  EXPECT_LT(held.normal_force, solver.Solve(sections, fixed, Eigen::Vector4d::Zero()).normal_force);
}

TEST(RigidSectionContact, WeightIsCarriedInClearance) {
  const int n = 64;
  RigidSectionContact solver(SteelPair(), n);
  std::vector<double> gap(n, 5e-6);
  const ContactSection s = Slice(gap, 0.02);
  RigidFreedom load;
  load.force = Eigen::Vector2d(0.0, -2.0);
  const RigidContactResult r = solver.Solve({&s, 1}, load, Eigen::Vector4d::Zero());
  EXPECT_NEAR(r.resultant.y(), -2.0, 1e-6);
  EXPECT_NEAR(r.normal_force, 2.0, 0.2);  // a narrow contact patch: sum p A close to its resultant
  EXPECT_NEAR(r.offset.y(), -5e-6, 1e-7);
}

// Gap changes of sections in contact all round are linear: ShiftFullContact against a solve of
// the shifted gaps, for a uniform change (the breathing mode alone: the part stays where it was)
// and for changes with orders 1 and 2 (order 1's net forces move the part's offset and tilt),
// and its refusals.
TEST(RigidSectionContact, ShiftFullContactIsTheSolveOfShiftedGaps) {
  const int n = 48, rows = 6;
  const double l = 0.012;
  for (const std::vector<int>& orders : {std::vector<int>{}, std::vector<int>{1, 2}}) {
    const std::size_t components = 1 + 2 * orders.size();
    std::vector<std::vector<double>> gaps(rows, std::vector<double>(n)), shifted = gaps;
    std::vector<ContactSection> before, after;
    std::vector<double> dx(rows * components, 0.0);
    for (int i = 0; i < rows; ++i) {
      dx[i * components] = 0.1e-6 * (i - 2);  // some grow, some shrink
      if (!orders.empty()) {
        dx[i * components + 1] = 0.05e-6 * (i - 3);  // cos theta: a bend
        dx[i * components + 4] = 0.2e-6;             // sin 2 theta
      }
      for (int j = 0; j < n; ++j) {
        const double t = 2 * kPi * j / n;
        gaps[i][j] = -4e-6 + 1e-6 * std::cos(3 * t) + 0.2e-6 * i;
        shifted[i][j] = gaps[i][j] + dx[i * components];
        if (!orders.empty()) {
          shifted[i][j] += dx[i * components + 1] * std::cos(t) + 0.2e-6 * std::sin(2 * t);
        }
      }
      ContactSection s = Slice(gaps[i], l / rows);
      s.y = (i + 0.5) * l / rows - l / 2;
      before.push_back(s);
      s.gap = shifted[i].data();
      after.push_back(s);
    }
    RigidFreedom freedom;
    freedom.tilt = true;
    RigidSectionContact solver(SteelPair(), n, orders), reference(SteelPair(), n);
    RigidContactResult r = solver.Solve(before, freedom, Eigen::Vector4d::Zero());
    ASSERT_TRUE(solver.ShiftFullContact(before, freedom, dx, &r));
    const RigidContactResult expected = reference.Solve(after, freedom, Eigen::Vector4d::Zero());
    EXPECT_NEAR(r.normal_force, expected.normal_force, 1e-9 * expected.normal_force);
    EXPECT_NEAR(r.max_pressure, expected.max_pressure, 1e-9 * expected.max_pressure);
    EXPECT_LT((r.offset - expected.offset).norm(), 1e-12);
    EXPECT_LT((r.tilt - expected.tilt).norm(), 1e-10);
    if (!orders.empty()) {
      EXPECT_GT(r.tilt.norm(), 1e-6);  // order 1 did move the part
    }
    for (std::size_t k = 0; k < solver.pressures().size(); ++k) {
      EXPECT_NEAR(solver.pressures()[k], reference.pressures()[k], 1e-6 * expected.max_pressure);
    }
    // A pressure that would turn negative, or a section not in contact all round: refused,
    // unchanged.
    const std::vector<double> kept = solver.pressures();
    std::vector<double> too_much(rows * components, 0.0);
    for (int i = 0; i < rows; ++i) too_much[i * components] = 10e-6;
    EXPECT_FALSE(solver.ShiftFullContact(before, freedom, too_much, &r));
    EXPECT_EQ(solver.pressures(), kept);
    for (int j = 0; j < n; ++j) gaps[0][j] += 10e-6 * std::cos(2 * kPi * j / n) + 3e-6;
    solver.Solve(before, freedom, Eigen::Vector4d::Zero());
    EXPECT_FALSE(solver.ShiftFullContact(before, freedom, dx, &r));
  }
}

// A solve that hands off (returns the next Newton point unevaluated once the unbalanced force is
// below a fraction of the load) and is resumed from that point, as the axial coupling's joint
// iteration does, reaches the equilibrium of a solve run to its end: lobed sections in partial
// contact under a sideways load, the part free to tilt.
TEST(RigidSectionContact, AHandedOffSolveResumedReachesTheSameEquilibrium) {
  const int n = 48, rows = 8;
  const double l = 0.016;
  std::vector<std::vector<double>> gaps(rows);
  RigidFreedom freedom;
  const std::vector<ContactSection> sections = LoadedStack(
      &gaps, n, l,
      [](int i, double theta) {
        return -1e-6 + 3e-6 * std::cos(3 * theta + 0.4 * i) + 0.3e-6 * i * std::sin(theta);
      },
      &freedom);
  RigidSectionContact full(SteelPair(), n), joint(SteelPair(), n);
  const RigidContactResult expected = full.Solve(sections, freedom, Eigen::Vector4d::Zero());
  ASSERT_TRUE(expected.converged);
  RigidContactResult r = joint.Solve(sections, freedom, Eigen::Vector4d::Zero(), {}, 1e-2);
  // It stopped short of the equilibrium (else this test checks nothing) ...
  ASSERT_FALSE(r.converged);
  EXPECT_GT((r.next.head<2>() - r.offset).norm(), 0.0);
  int handoffs = 1;
  const std::vector<double> unchanged(rows, 0.0);
  while (!r.converged && handoffs < 20) {
    r = joint.Solve(sections, freedom, r.next, unchanged, 1e-2);
    ++handoffs;
  }
  // ... and resumed from its Newton points it lands where the whole solve did.
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.normal_force, expected.normal_force, 1e-8 * expected.normal_force);
  EXPECT_LT((r.offset - expected.offset).norm(), 1e-12);
  EXPECT_LT((r.tilt - expected.tilt).norm(), 1e-12 / l);
  EXPECT_NEAR(r.resultant.x(), 30.0, 1e-6);
  EXPECT_NEAR(r.resultant.y(), -50.0, 1e-6);
  // A converged solve returns its own pose as the next point.
  EXPECT_EQ(expected.next.head<2>(), expected.offset);
}

// Only speed depends on the warm contact sets: an oval shaft in partial contact (interfering by
// 3 um on two narrow lobes, 0.3 um clear between them) reaches the same equilibrium from none,
// from the answer's own sets, from every column, from the columns out of contact, and from random
// flags. The answer's sets hold columns whose rigid gap is open at the equilibrium (the lobes'
// pressure ovalises the parts and closes them), which is why a warm set keeps such columns
// instead of dropping them.
TEST(RigidSectionContact, AnyWarmContactSetReachesTheSameEquilibrium) {
  const int n = 48, rows = 8;
  const double l = 0.016, clear = 0.3e-6, lobe = 3e-6;
  std::vector<std::vector<double>> gaps(rows);
  RigidFreedom freedom;
  const std::vector<ContactSection> sections = LoadedStack(
      &gaps, n, l,
      [&](int i, double theta) {
        return clear - (lobe + clear) * std::pow(std::cos(theta + 0.05 * i), 8);
      },
      &freedom);
  RigidSectionContact cold(SteelPair(), n);
  const RigidContactResult expected = cold.Solve(sections, freedom, Eigen::Vector4d::Zero());
  ASSERT_TRUE(expected.converged);
  std::vector<std::vector<char>> answer = cold.contact_sets();
  // Columns in contact although the rigid parts, at the equilibrium's pose, leave them open.
  int closed_by_deformation = 0, in_contact = 0;
  for (int i = 0; i < rows; ++i) {
    const Eigen::Vector2d e = expected.offset + sections[i].y * expected.tilt;
    for (int j = 0; j < n; ++j) {
      const double theta = 2 * kPi * j / n;
      if (!answer[i][j]) continue;
      ++in_contact;
      if (e.x() * std::cos(theta) + e.y() * std::sin(theta) <= gaps[i][j]) ++closed_by_deformation;
    }
  }
  EXPECT_GT(in_contact, 0);
  EXPECT_LT(in_contact, rows * n);  // partial contact, else the warm sets matter for nothing
  EXPECT_GT(closed_by_deformation, 0);

  std::mt19937 rng(7);
  std::bernoulli_distribution coin(0.5);
  std::vector<std::vector<char>> all(rows, std::vector<char>(n, 1)), open(rows), random(rows);
  for (int i = 0; i < rows; ++i) {
    open[i].resize(n);
    random[i].resize(n);
    for (int j = 0; j < n; ++j) {
      open[i][j] = !answer[i][j];
      random[i][j] = coin(rng) ? 1 : 0;
    }
  }
  for (const auto* warm : {&answer, &all, &open, &random}) {
    std::vector<ContactSection> started = sections;  // the same gaps, with warm sets
    for (int i = 0; i < rows; ++i) started[i].warm_contact = (*warm)[i].data();
    RigidSectionContact solver(SteelPair(), n);
    const RigidContactResult r = solver.Solve(started, freedom, Eigen::Vector4d::Zero());
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.normal_force, expected.normal_force, 1e-9 * expected.normal_force);
    EXPECT_LT((r.offset - expected.offset).norm(), 1e-13);
    EXPECT_LT((r.tilt - expected.tilt).norm(), 1e-13 / l);
    EXPECT_EQ(solver.contact_sets(), answer);
  }
}

}  // namespace
}  // namespace fitfeel::cylindrical
