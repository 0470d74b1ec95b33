// Elements that enclose no volume (no area in 2D, no length for beams) though every quadrature
// point may still see a positive Jacobian: a node id repeated in an element (a wedge written as
// a hexahedron), two corners at one place, a face whose corners are collinear. They are input
// errors naming the element, found before the coincident-node search (which would suggest
// merging those corners, making the element worse).
#pragma once
#include <string>

#include "mesh/Mesh.hpp"

namespace choc {

// Throws InputError: "<inputFile>: parameter 'Mesh/File' = '<meshFile>': block 'B', element N: ...".
void checkDegenerateElements(const Mesh& mesh, const std::string& inputFile, const std::string& meshFile);

}  // namespace choc
