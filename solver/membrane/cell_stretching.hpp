#pragma once
// Optical-tweezers stretching of one red blood cell in static equilibrium, the classic
// single-cell test of a membrane model (experiments: Mills et al., Mech. Chem.
// Biosyst. 1 (2004) 169; modelling: Li et al., Biophys. J. 88 (2005) 3707).
//
// Equal and opposite forces +-F, spread evenly over the vertices of two end patches
// (the contact_fraction of vertices with the largest and the smallest x, along the
// stretch axis x in the plane of the disc), pull the cell; the equilibrium minimises
// elastic + bending energy minus the work of the forces (L-BFGS), with the enclosed
// volume held at its reference value by an augmented Lagrangian. Forces are applied in
// increasing order, each solve starting from the previous shape.
#include <vector>

#include "solver/membrane/cell_shapes.hpp"
#include "solver/membrane/strain_energy.hpp"

namespace rbcal::solver {

struct StretchSettings {
  int triangles = 1280;
  double radius = 3.91e-6;  // m; Evans-Fung R0 (diameter 7.82 um)
  BiconcaveProfile profile = BiconcaveProfile::EvansFung;
  MembraneMaterial material{MembraneLaw::Skalak, 5.5e-6, 100.0};  // G_s in N/m
  double bending_modulus = 5e-19;    // J (seed study's k_b)
  double contact_fraction = 0.05;    // of all vertices, at each end
  double volume_tolerance = 1e-7;    // relative volume error allowed
  double gradient_tolerance = 1e-9;  // in units of G_s a, per vertex component
};

struct StretchPoint {
  double force = 0;                // N
  double axial_diameter = 0;       // m, extent along the stretch axis
  double transverse_diameter = 0;  // m, in-plane extent perpendicular to it
  double volume_error = 0;         // relative
  double area_change = 0;          // relative
  int iterations = 0;              // L-BFGS iterations, all volume passes
  bool converged = false;
};

std::vector<StretchPoint> stretch_cell(const StretchSettings& settings, const std::vector<double>& forces);

}  // namespace rbcal::solver
