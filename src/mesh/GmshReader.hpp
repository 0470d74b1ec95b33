// Reading a gmsh mesh (.msh, format 4 or 2.2) with gmsh's own library:
//   - the physical groups of the mesh's highest dimension (volumes in 3D, surfaces in 2D)
//     become element blocks, one element type per block, named by the group's name
//     ("volume_<tag>" / "surface_<tag>" when unnamed), and node sets of the same name;
//   - the physical groups one dimension lower (surfaces in 3D, curves in 2D) become side
//     sets (each face or edge matched to the block element it bounds, Exodus side
//     numbering) and node sets of the same name;
//   - the other physical groups (points, and curves in 3D) become node sets.
// Element node orders are converted to Exodus' (mid-edge nodes matched through gmsh's
// reference coordinates). Nodes are numbered by ascending gmsh tag. Errors are one-line
// InputErrors naming the file and the group or element: an element type choc does not
// support, a group mixing element types, a name used at two dimensions, a face that bounds
// no block element, a mesh without blocks. The library reads in a child process
// (ChildProcess.hpp): a crash inside it on a corrupt file is an input error too.
#pragma once
#include <string>

#include "mesh/Mesh.hpp"

namespace choc {

Mesh readGmshMesh(const std::string& path);

}  // namespace choc
