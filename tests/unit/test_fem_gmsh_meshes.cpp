// gmsh meshes read through gmsh's library: blocks from the physical groups of the highest
// dimension, side sets and node sets from the others, Exodus node order and side numbering,
// and the same mesh after an Exodus round trip. The meshes are made here with gmsh's API.
#include <gtest/gtest.h>

#include <gmsh.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "core/Errors.hpp"
#include "fem/SolidElement.hpp"
#include "mesh/ExodusMeshWriter.hpp"
#include "mesh/ExodusReader.hpp"
#include "mesh/GmshReader.hpp"
#include "mesh/MeshFile.hpp"
#include "mesh/Topology.hpp"
#include "test_mesh_helpers.hpp"

namespace choc {
namespace {

std::string scratch(const std::string& name) {
  const std::string dir = std::string(CHOC_BINARY_DIR) + "/test-scratch/gmsh";
  std::filesystem::create_directories(dir);
  return dir + "/" + name;
}

// A box [0, 2] x [0, 1] x [0, 1] (or its face z = 0 in 2D), physical groups named.
void makeBox(const std::string& path, int dim, int order, bool quads) {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("box");
  const double h = 0.5;
  const int p1 = gmsh::model::geo::addPoint(0, 0, 0, h), p2 = gmsh::model::geo::addPoint(2, 0, 0, h);
  const int p3 = gmsh::model::geo::addPoint(2, 1, 0, h), p4 = gmsh::model::geo::addPoint(0, 1, 0, h);
  const int l1 = gmsh::model::geo::addLine(p1, p2), l2 = gmsh::model::geo::addLine(p2, p3);
  const int l3 = gmsh::model::geo::addLine(p3, p4), l4 = gmsh::model::geo::addLine(p4, p1);
  const int loop = gmsh::model::geo::addCurveLoop({l1, l2, l3, l4});
  const int s = gmsh::model::geo::addPlaneSurface({loop});
  gmsh::vectorpair out;
  if (dim == 3) gmsh::model::geo::extrude({{2, s}}, 0, 0, 1, out, {2}, {}, quads);
  if (quads) gmsh::model::geo::mesh::setRecombine(2, s);
  gmsh::model::geo::synchronize();
  if (dim == 3) {
    gmsh::model::addPhysicalGroup(3, {out[1].second}, 1);
    gmsh::model::setPhysicalName(3, 1, "box");
    gmsh::model::addPhysicalGroup(2, {s}, 2);
    gmsh::model::setPhysicalName(2, 2, "bottom");
  } else {
    gmsh::model::addPhysicalGroup(2, {s}, 1);
    gmsh::model::setPhysicalName(2, 1, "box");
    gmsh::model::addPhysicalGroup(1, {l4}, 2);
    gmsh::model::setPhysicalName(1, 2, "left");
  }
  gmsh::model::addPhysicalGroup(0, {p1}, 3);
  gmsh::model::setPhysicalName(0, 3, "origin");
  gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 1);
  gmsh::model::mesh::generate(dim);
  if (order == 2) gmsh::model::mesh::setOrder(2);
  gmsh::write(path);
  gmsh::finalize();
}

double measure(const Mesh& m, Kinematics k) {
  double total = 0;
  for (const ElementBlock& b : m.blocks)
    for (int e = 0; e < b.numElements(); ++e) {
      std::vector<Point3> x;
      for (int a = 0; a < b.nodesPerElement; ++a) x.push_back(m.coords[b.connectivity[size_t(e) * b.nodesPerElement + a]]);
      total += solidElementMeasure(b.topology, k, x);
    }
  return total;
}

TEST(Gmsh, Tet10BoxBlocksSidesAndSets) {
  const std::string path = scratch("box_tet10.msh");
  makeBox(path, 3, 2, false);
  ASSERT_TRUE(isGmshFile(path));
  const Mesh m = readMeshFile(path);
  EXPECT_EQ(m.dimension, 3);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "box");
  EXPECT_EQ(m.blocks[0].topology, "TET10");
  EXPECT_NEAR(measure(m, Kinematics::ThreeD), 2.0, 1e-12);  // every element positive, none missing
  // Side set 'bottom': faces of the tetrahedra on z = 0 covering the area 2, Exodus numbering.
  const SideSet* bottom = m.findSideSet("bottom");
  ASSERT_NE(bottom, nullptr);
  double area = 0;
  for (size_t k = 0; k < bottom->elements.size(); ++k) {
    const std::vector<int> f = m.sideNodes(bottom->elements[k], bottom->sides[k]);
    ASSERT_EQ(f.size(), 6u);
    for (int n : f) EXPECT_EQ(m.coords[n][2], 0.0);
    const Vec3 nrm = cross(m.coords[f[1]] - m.coords[f[0]], m.coords[f[2]] - m.coords[f[0]]);
    EXPECT_LT(nrm[2], 0.0) << "the side's normal points out of the box";
    area += 0.5 * norm(nrm);
  }
  EXPECT_NEAR(area, 2.0, 1e-12);
  ASSERT_NE(m.findNodeSet("bottom"), nullptr);
  for (int n : m.findNodeSet("bottom")->nodes) EXPECT_EQ(m.coords[n][2], 0.0);
  ASSERT_NE(m.findNodeSet("origin"), nullptr);
  ASSERT_EQ(m.findNodeSet("origin")->nodes.size(), 1u);
  EXPECT_EQ(m.coords[m.findNodeSet("origin")->nodes[0]], (Point3{0, 0, 0}));
  ASSERT_NE(m.findNodeSet("box"), nullptr);  // the block's nodes
  // The same mesh through Exodus.
  const std::string exo = scratch("box_tet10.exo");
  writeExodusMesh(m, exo);
  expectSameMesh(m, readExodusMesh(exo));
}

TEST(Gmsh, Quad8RectangleIs2D) {
  const std::string path = scratch("rect_quad8.msh");
  makeBox(path, 2, 2, true);
  const Mesh m = readMeshFile(path);
  EXPECT_EQ(m.dimension, 2);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].topology, "QUAD8");
  EXPECT_NEAR(measure(m, Kinematics::PlaneStrain), 2.0, 1e-12);
  const SideSet* left = m.findSideSet("left");
  ASSERT_NE(left, nullptr);
  double length = 0;
  for (size_t k = 0; k < left->elements.size(); ++k) {
    const std::vector<int> e = m.sideNodes(left->elements[k], left->sides[k]);
    ASSERT_EQ(e.size(), 3u);
    for (int n : e) EXPECT_EQ(m.coords[n][0], 0.0);
    length += norm(m.coords[e[1]] - m.coords[e[0]]);
  }
  EXPECT_NEAR(length, 1.0, 1e-12);
  const std::string exo = scratch("rect_quad8.exo");
  writeExodusMesh(m, exo);
  const Mesh back = readExodusMesh(exo);
  EXPECT_EQ(back.dimension, 2);
  expectSameMesh(m, back);
}

TEST(Gmsh, MissingAndForeignFilesAreInputErrors) {
  EXPECT_THROW(readMeshFile(scratch("none.msh")), InputError);
  const std::string junk = scratch("junk.msh");
  std::ofstream(junk) << "not a mesh\n";
  EXPECT_THROW(readMeshFile(junk), InputError);
}

}  // namespace
}  // namespace choc
