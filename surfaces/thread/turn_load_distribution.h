#pragma once

#include <vector>

namespace fitfeel::thread {

// Distribution of the axial load over the engaged turns after D. G. Sopwith, "The distribution of
// load in screw threads", Proc. IMechE 159 (1948): the bolt's core and the nut's body are bars of
// axial stiffness E_b A_b and E_n A_n, the flank pair between them a distributed spring of
// stiffness k' per unit axial length. For a standard nut (bolt in tension, nut in compression)
// the load per unit length at distance x from the nut's bearing face is
//   q(x) = F lambda cosh(lambda (L - x)) / sinh(lambda L),
//   lambda^2 = k' (1 / (E_b A_b) + 1 / (E_n A_n)),
// L the engaged length: the turn at the bearing face carries most, the far turns least, and the
// load is uniform as lambda L -> 0.

// lambda from k' (N/m per metre of engagement, i.e. Pa) and the two axial stiffnesses (N).
double SopwithDecayRate(double flank_stiffness_per_length, double bolt_axial_stiffness,
                        double nut_axial_stiffness);

// The share of F each turn carries, the integral of q / F over each pitch from the bearing face:
//   share_i = [sinh(lambda (L - i P)) - sinh(lambda (L - (i + 1) P))] / sinh(lambda L),
// the last turn partial where L is not a whole number of pitches; the shares sum to 1.
// decay_rate = 0 gives the uniform distribution.
std::vector<double> TurnLoadShares(double engaged_length, double pitch, double decay_rate);

}  // namespace fitfeel::thread
