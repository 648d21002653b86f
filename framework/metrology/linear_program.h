#pragma once

#include <vector>

#include <Eigen/Core>

#include "framework/core/export.h"

namespace fitfeel::metrology {

// Result of a small dense linear program.
struct LinearProgramResult {
  Eigen::VectorXd x;       // the minimiser
  double objective = 0.0;  // c . x
  int iterations = 0;      // simplex pivots (both phases)
};

// Minimises c . x subject to A x <= b with x free (no sign constraints), for the few-variable,
// many-constraint programs of form evaluation (minimum zone: 3 to 7 variables, up to ~10^4
// constraints). Solved exactly (up to rounding) by the revised primal simplex method on the dual
//   min b . y  s.t.  A^T y = -c,  y >= 0
// whose basis is only d x d (d = number of variables); the primal minimiser is the dual's simplex
// multiplier vector. Phase 1 uses artificial variables; Dantzig pricing with Bland's rule after a
// run of degenerate pivots guarantees termination. Callers should scale A and b to order one.
// Throws std::runtime_error if the program is infeasible or unbounded (a caller's bug here: every
// form evaluation has a feasible, bounded program).
FITFEEL_API LinearProgramResult MinimiseLinearProgram(const Eigen::VectorXd& c,
                                                      const Eigen::MatrixXd& A,
                                                      const Eigen::VectorXd& b);

// The same, for a cutting-plane or working-set loop that adds rows to A and solves again: `basis`
// holds (on return) the rows of A whose constraints the optimum's basis holds, d of them, or
// nothing where the program's basis kept an artificial column. Given on entry (the last call's,
// with the same c and A's rows then a prefix of these), that basis is still feasible for the dual
// program, so the simplex starts its second phase there instead of from the artificial basis:
// a few pivots to admit the new rows instead of a whole solve. A basis that does not fit (wrong
// size, out of range, singular or infeasible to rounding) is ignored.
FITFEEL_API LinearProgramResult MinimiseLinearProgram(const Eigen::VectorXd& c,
                                                      const Eigen::MatrixXd& A,
                                                      const Eigen::VectorXd& b,
                                                      std::vector<int>* basis);

}  // namespace fitfeel::metrology
