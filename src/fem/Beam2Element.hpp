// Two-node 3D Timoshenko beam: 6 DOF per node (DX DY DZ DRX DRY DRZ), matrices in global axes.
#pragma once
#include <array>
#include <memory>

#include "fem/BeamSection.hpp"
#include "fem/ElementKernel.hpp"
#include "fem/Material.hpp"

namespace choc {

// Local unit axes {ex, ey, ez} of a beam from node a to node b: ex along the axis, ey the part
// of `orientation` orthogonal to ex (default when zero: see BeamSection), ez = ex x ey.
// Throws std::invalid_argument for a zero-length beam or an orientation parallel to the axis.
std::array<Point3, 3> beamLocalAxes(const Point3& a, const Point3& b, const Point3& orientation);

// Throws std::invalid_argument for non-positive E, A, I, J, shear coefficients or density < 0.
std::unique_ptr<ElementKernel> makeBeam2(const Material& material, const BeamSection& section);

}  // namespace choc
