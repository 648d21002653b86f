#pragma once

#include <Eigen/Core>

#include "framework/core/export.h"

namespace fitfeel {

// The x of least norm among the minimisers of |A x - b| (Eigen's complete orthogonal
// decomposition), for small systems whose rank may fall short (a coefficient a grid cannot
// observe, a direction without stiffness). Compiled here once: the decomposition's templates
// cost a plugin's or a model file's compile about ten seconds wherever they are instantiated.
FITFEEL_API Eigen::VectorXd LeastNormSolve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);
// The same for every column of b at once (one decomposition).
FITFEEL_API Eigen::MatrixXd LeastNormSolveColumns(const Eigen::MatrixXd& a,
                                                  const Eigen::MatrixXd& b);

}  // namespace fitfeel
