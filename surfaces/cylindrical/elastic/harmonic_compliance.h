#pragma once

#include <vector>

#include "framework/model/gps_spec.h"

namespace fitfeel::cylindrical {

// A press-fit cross-section: a shaft (solid, or hollow with bore di) in a thick ring hub of outer
// diameter d2, both linear elastic, frictionless at the interface of diameter d1.
struct PressFitSection {
  double d1 = 0.0;  // interface diameter, m
  double d2 = 0.0;  // hub outer diameter, m
  double di = 0.0;  // shaft bore, m (0 = solid)
  Material shaft;
  Material hub;
  // Plane stress (the default) suits a hub no longer than a few wall thicknesses, free at both
  // faces; plane strain a long one. docs/contact-mechanics.md says when each applies.
  bool plane_strain = false;
};

// Radial closure of the interface per unit normal pressure p cos(n theta), m/Pa: the shaft's
// inward plus the hub's outward radial displacement amplitude, from the Michell solution of each
// ring (Airy stress function r^{+-n}, r^{2+-n} times cos n theta; Lame for n = 0). The interface
// stiffness per harmonic is K_n = 1 / HarmonicCompliance(n). Order 1 carries a net force, which
// the model's rigid parts carry along their axes: its compliance is each section's face moving
// relative to the section's centroid, the net force balanced by a uniform body force (the rest
// of a rigid part pulling on the section; docs/contact-mechanics.md section 1): 0.36 of order 0's
// for the steel 20 mm shaft in its 30 mm hub.
double HarmonicCompliance(const PressFitSection& section, int n);

// One part's share of HarmonicCompliance for an order n >= 1: the radial displacement opening the
// interface of the ring inner_radius < r < outer_radius (solid when inner_radius = 0) loaded by
// p cos(n theta) on its bore (`loaded_inside`, a hub) or on its outside (a shaft), per unit p.
double RingHarmonicCompliance(double inner_radius, double outer_radius,
                                          bool loaded_inside, const Material& material,
                                          bool plane_strain, int n);

// The compliance of every order 0 .. n_columns/2 a circulant contact solve on n_columns needs.
std::vector<double> CirculantCompliance(const PressFitSection& section, int n_columns);

// DIN 7190-1 smoothing: the diametral interference lost while joining as the asperity peaks are
// flattened, 0.8 (Rz_inner + Rz_outer). Radial: half of it.
double Din7190RadialSmoothing(const TextureSpec& inner, const TextureSpec& outer);

// Plasticity index of Greenwood and Williamson (1966), psi = (E*/H) sqrt(sigma / beta), with E* the
// contact modulus 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2), H the softer part's hardness (Pa), sigma
// the equivalent surface's asperity height deviation and beta the asperity summit radius (m).
// psi > 1: the asperities yield on first contact (the case for ground and turned steel), so an
// elastic asperity model does not apply and DIN 7190 smoothing does. Reported, not used in forces.
double ContactModulus(const Material& a, const Material& b);
double PlasticityIndex(double contact_modulus, double hardness, double sigma,
                                   double summit_radius);
// Equivalent height deviation of two Gaussian textures from their Ra: sigma = sqrt(pi/2) Ra per
// surface, root-sum-square of the two (independent heights add).
double EquivalentSigmaFromRa(const TextureSpec& a, const TextureSpec& b);

}  // namespace fitfeel::cylindrical
