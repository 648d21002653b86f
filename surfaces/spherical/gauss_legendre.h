#pragma once

namespace fitfeel::spherical {

// 4-point Gauss-Legendre rule on [-1, 1]: exact for polynomials to degree 7.
inline constexpr double kGaussNodes4[4] = {-0.8611363115940526, -0.3399810435848563,
                                           0.3399810435848563, 0.8611363115940526};
inline constexpr double kGaussWeights4[4] = {0.3478548451374538, 0.6521451548625461,
                                             0.6521451548625461, 0.3478548451374538};

}  // namespace fitfeel::spherical
