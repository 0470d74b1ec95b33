// Generator of the "two bars on one axis" impact scene of SDNL111 (`choc mesh`; the scene is
// defined in docs/verification/benchmarks.md).
//
// s = coordinate along the axis. Bar 1 (block POU1, moving towards -s) runs from A at
// s = gap (+ shiftA for node A alone, 1D) to B at s = gap + length1; bar 2 (block POU2,
// clamped at D) from C at s = 0 to D at s = -length2.
//  1D: BEAM2 elements on the axis; nodes of bar 1 from A to B, then bar 2 from C to D.
//      Node sets A, B, C, D, POU1, POU2.
//  3D: HEX8 bricks (positive Jacobian); section [0,width]x[0,height] in the two other axes
//      taken in cyclic order (axis x → (y,z), y → (z,x), z → (x,y)). Node sets POU1, POU2,
//      N1 = A (bar 1's contact-face node at lateral (0,0)), B, C, D (same lateral corner),
//      CL_POU2 (face s = -length2), FACE_POU1, FACE_POU2 (the two contact faces). Side sets
//      CNT_POU1 (bar 1 at s = gap, side 5, outward normal -axis) and CNT_POU2 (bar 2 at
//      s = 0, side 6, outward normal +axis).
#pragma once
#include "mesh/Mesh.hpp"

namespace choc {

struct BarImpactOptions {
  int dimension = 1;                    // 1: BEAM2 line elements, 3: HEX8 bricks
  double length1 = 1.0, length2 = 1.0;  // bar 1 (AB, moving) and bar 2 (CD, clamped at D)
  double width = 0.02, height = 0.02;   // section sides (3D geometry; 1D ignores them)
  int along1 = 50, along2 = 50;         // elements along each bar
  int across1 = 1, across2 = 1;         // elements across the section, each lateral direction (3D)
  double gap = 1e-5;                    // distance from C to A along the axis
  double shiftA = 0.0;                  // moves node A alone along the axis (1D only)
  char axis = 'x';                      // 'x','y','z'
};

// Validates the options (see validateBarImpactOptions) and builds the mesh.
Mesh generateBarImpactMesh(const BarImpactOptions& o);

// Throws choc::InputError (file "choc mesh", parameter = the CLI option name, e.g.
// "--length1") for: lengths, width, height not finite and > 0; element counts < 1 or a
// mesh too large; gap not finite; axis not x, y, z; dimension not 1 or 3; shiftA non-zero
// in 3D or moving A onto or past the next node of bar 1.
void validateBarImpactOptions(const BarImpactOptions& o);

}  // namespace choc
