#pragma once
// The volume of a closed surface thickened outwards by an offset delta (its parallel body),
// by Steiner's formula:
//     V(delta) = V + S delta + M delta^2 + (4 pi / 3) delta^3,
// with S the area and M the integral of the mean curvature. For a polyhedron
// M = 1/2 sum over edges of (edge length x exterior dihedral angle), exact for convex
// bodies; for the biconcave cell, whose concave dimples curve far more gently than any
// offset used here, it is the small-offset expansion.
//
// Why: the immersed boundary makes a membrane act thicker than its mesh. A sphere of radius
// a acts as one of radius a + c dx, c about 0.75-0.79 (docs/validation.md), so a
// suspension at volume fraction phi behaves as one at phi V(c dx) / V
// (surrogate/effective_volume_fraction.hpp; docs/library.md).
#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

struct SteinerTerms {
  double area = 0.0;
  double volume = 0.0;
  double mean_curvature_integral = 0.0;  // M (a length)
};

// Throws std::invalid_argument unless the mesh is closed, consistently oriented and faces
// outwards (positive volume).
SteinerTerms steiner_terms(const TriangleMesh& mesh);

// V(delta) / V.
double thickened_volume_ratio(const SteinerTerms& s, double delta);

}  // namespace rbcal::solver
