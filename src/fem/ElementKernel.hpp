// What the assembler needs from an element type: its nodal components and its matrices.
// Element DOF ordering is node-major: for node k and its j-th component, row k*nc + j, with
// nc = components().size(). Matrices are in global axes.
#pragma once
#include <memory>
#include <vector>

#include "fem/DenseMatrix.hpp"
#include "mesh/Mesh.hpp"

namespace choc {

enum class MassKind { Consistent, Lumped };

class ElementKernel {
 public:
  virtual ~ElementKernel() = default;
  virtual int numNodes() const = 0;
  // The components each node carries in this element (e.g. {DX,DY,DZ} for HEX8).
  virtual const std::vector<int>& components() const = 0;
  virtual void stiffness(const std::vector<Point3>& x, DenseMatrix& K) const = 0;
  virtual void mass(const std::vector<Point3>& x, MassKind kind, DenseMatrix& M) const = 0;
  // Throws std::invalid_argument (naming the element type and the point) when the element
  // with nodes x is inverted or degenerate. The default computes the stiffness.
  virtual void checkGeometry(const std::vector<Point3>& x) const {
    DenseMatrix K;
    stiffness(x, K);
  }
};

}  // namespace choc
