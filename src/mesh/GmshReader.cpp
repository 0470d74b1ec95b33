#include "mesh/GmshReader.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "core/Errors.hpp"
#include "mesh/ChildProcess.hpp"
#include "mesh/MeshBytes.hpp"
#include "mesh/Topology.hpp"

namespace choc {

namespace {

// gmsh element types (MSH numbering) choc reads, with their Exodus topology.
const std::map<int, std::string>& gmshTypes() {
  static const std::map<int, std::string> t = {
      {1, "BEAM2"}, {2, "TRI3"}, {3, "QUAD4"}, {4, "TET4"}, {5, "HEX8"},
      {9, "TRI6"},  {11, "TET10"}, {16, "QUAD8"}, {17, "HEX20"},
      {8, "LINE3"}, {15, "POINT"}};
  return t;
}

// Exodus position k -> gmsh position perm[k]: corners in the same order, each mid-edge node
// found by its reference coordinates (the midpoint of its two corners).
std::vector<int> exodusOrder(int gmshType, const Topology& topo) {
  std::string name;
  int dim = 0, order = 0, n = 0, primary = 0;
  std::vector<double> ref;
  gmsh::model::mesh::getElementProperties(gmshType, name, dim, order, n, ref, primary);
  std::vector<int> perm(topo.numNodes);
  for (int k = 0; k < topo.numCorners; ++k) perm[k] = k;
  for (size_t i = 0; i < topo.midEdges.size(); ++i) {
    const auto [a, b] = topo.midEdges[i];
    int found = -1;
    for (int g = topo.numCorners; g < n && found < 0; ++g) {
      bool same = true;
      for (int d = 0; d < dim; ++d)
        same = same && std::abs(ref[g * dim + d] - 0.5 * (ref[a * dim + d] + ref[b * dim + d])) < 1e-12;
      if (same) found = g;
    }
    if (found < 0) throw std::logic_error("gmsh element type " + name + ": no node at an edge midpoint");
    perm[topo.numCorners + i] = found;
  }
  return perm;
}

struct Group {
  int dim = 0, tag = 0;
  std::string name;
};

class GmshFile {
 public:
  explicit GmshFile(std::string path) : path_(std::move(path)) {}

  Mesh read() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 0);
    try {
      gmsh::open(path_);
    } catch (const std::exception& e) {
      gmsh::finalize();
      throwInput(path_, "", "", std::string("gmsh cannot read this file: ") + e.what(),
                 "give a gmsh mesh (.msh, format 4 or 2.2)");
    }
    Mesh mesh;
    try {
      mesh = build();
    } catch (...) {
      gmsh::finalize();
      throw;
    }
    gmsh::finalize();
    return mesh;
  }

 private:
  Mesh build() {
    Mesh mesh;
    mesh.title = std::filesystem::path(path_).filename().string();
    // A 1D mesh is a beam structure (BEAM2 blocks, node sets from its physical points) in
    // 3D space; a 2D or 3D one has side sets one dimension below its blocks.
    const int dim = gmsh::model::getDimension();
    if (dim < 1) fail("the mesh has dimension " + std::to_string(dim), "mesh curves (beams), a surface (2D) or a volume (3D)");
    mesh.dimension = dim == 1 ? 3 : dim;
    readNodes(mesh);
    const std::vector<Group> groups = physicalGroups();
    for (const Group& g : groups)
      if (g.dim == dim) readBlock(mesh, g);
    if (mesh.blocks.empty())
      fail("no physical group of dimension " + std::to_string(dim) + " (the element blocks)",
           std::string("define ") + (dim == 3 ? "Physical Volume" : dim == 2 ? "Physical Surface" : "Physical Curve") +
               " groups");
    if (dim >= 2) indexSides(mesh);
    for (const Group& g : groups)
      if (dim >= 2 && g.dim == dim - 1) readSideSet(mesh, g);
      else if (g.dim < dim && (dim >= 2 ? g.dim < dim - 1 : true)) readNodeSet(mesh, g, groupNodes(g));
    return mesh;
  }

  [[noreturn]] void fail(const std::string& problem, const std::string& fix = "") const {
    throwInput(path_, "", "", problem, fix);
  }

  void readNodes(Mesh& mesh) {
    std::vector<std::size_t> tags;
    std::vector<double> xyz, param;
    gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, false, false);
    std::vector<std::size_t> order(tags.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return tags[a] < tags[b]; });
    mesh.coords.resize(tags.size());
    for (size_t k = 0; k < order.size(); ++k) {
      const size_t i = order[k];
      if (!index_.emplace(tags[i], int(k)).second) fail("node tag " + std::to_string(tags[i]) + " appears twice");
      mesh.coords[k] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
      for (double x : mesh.coords[k])
        if (!std::isfinite(x)) fail("node " + std::to_string(tags[i]) + " has a non-finite coordinate");
    }
  }

  std::vector<Group> physicalGroups() const {
    gmsh::vectorpair dimTags;
    gmsh::model::getPhysicalGroups(dimTags);
    std::vector<Group> groups;
    std::map<std::string, int> dimOfName;
    for (const auto& [dim, tag] : dimTags) {
      Group g{dim, tag, ""};
      gmsh::model::getPhysicalName(dim, tag, g.name);
      if (g.name.empty()) g.name = (dim == 0 ? "point_" : dim == 1 ? "curve_" : dim == 2 ? "surface_" : "volume_") + std::to_string(tag);
      const auto [it, fresh] = dimOfName.emplace(g.name, dim);
      if (!fresh)
        fail("physical group '" + g.name + "' is defined in dimensions " + std::to_string(it->second) +
                 " and " + std::to_string(dim) + " (mixed dimension)",
             "give each physical group its own name");
      groups.push_back(g);
    }
    std::sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) {
      return a.dim != b.dim ? a.dim > b.dim : a.tag < b.tag;
    });
    return groups;
  }

  // Every element of the group's entities: (gmsh type, element tags, node tags).
  struct Elements {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
  };
  Elements groupElements(const Group& g) const {
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(g.dim, g.tag, entities);
    Elements all;
    for (int e : entities) {
      Elements part;
      gmsh::model::mesh::getElements(part.types, part.tags, part.nodes, g.dim, e);
      for (size_t t = 0; t < part.types.size(); ++t) {
        all.types.push_back(part.types[t]);
        all.tags.push_back(std::move(part.tags[t]));
        all.nodes.push_back(std::move(part.nodes[t]));
      }
    }
    return all;
  }

  int node(std::size_t tag) const {
    const auto it = index_.find(tag);
    if (it == index_.end()) fail("an element refers to node tag " + std::to_string(tag) + ", which the mesh does not define");
    return it->second;
  }

  std::string topologyOf(int gmshType, const std::string& group) const {
    const auto it = gmshTypes().find(gmshType);
    std::string name;
    int dim = 0, order = 0, n = 0, primary = 0;
    std::vector<double> ref;
    gmsh::model::mesh::getElementProperties(gmshType, name, dim, order, n, ref, primary);
    if (it == gmshTypes().end() || !findTopology(it->second))
      fail("physical group '" + group + "' has elements of type '" + name + "' (gmsh type " +
               std::to_string(gmshType) + "), which choc does not support",
           "use TET4, TET10, HEX8, HEX20 (3D) or TRI3, TRI6, QUAD4, QUAD8 (2D; Mesh.SecondOrderIncomplete = 1 for QUAD8/HEX20)");
    return it->second;
  }

  void readBlock(Mesh& mesh, const Group& g) {
    const Elements els = groupElements(g);
    ElementBlock block;
    block.name = g.name;
    block.id = g.tag;
    for (size_t t = 0; t < els.types.size(); ++t) {
      const std::string topo = topologyOf(els.types[t], g.name);
      if (!block.topology.empty() && block.topology != topo)
        fail("physical group '" + g.name + "' mixes " + block.topology + " and " + topo + " elements",
             "put each element type in its own physical group (one element block each)");
      block.topology = topo;
      const Topology& tp = *findTopology(topo);
      block.nodesPerElement = tp.numNodes;
      const std::vector<int> perm = exodusOrder(els.types[t], tp);
      const auto& nodes = els.nodes[t];
      for (size_t e = 0; e * tp.numNodes < nodes.size(); ++e)
        for (int k = 0; k < tp.numNodes; ++k) block.connectivity.push_back(node(nodes[e * tp.numNodes + perm[k]]));
    }
    if (block.topology.empty()) fail("physical group '" + g.name + "' has no element", "mesh it, or remove the group");
    std::vector<int> nodes = block.connectivity;
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    readNodeSet(mesh, g, std::move(nodes));  // the block's nodes, for initial conditions and loads
    mesh.blocks.push_back(std::move(block));
  }

  // Key of a side: its corner nodes, sorted.
  static std::vector<int> key(std::vector<int> corners) {
    std::sort(corners.begin(), corners.end());
    return corners;
  }

  void indexSides(const Mesh& mesh) {
    int element = 0;
    for (const ElementBlock& b : mesh.blocks) {
      const Topology& tp = *findTopology(b.topology);
      for (int e = 0; e < b.numElements(); ++e, ++element)
        for (int s = 0; s < tp.numSides(); ++s) {
          std::vector<int> corners;
          const size_t nc = tp.sideTopologies[s] == "TRI6" ? 3 : tp.sideTopologies[s] == "QUAD8" ? 4
                            : tp.sideTopologies[s] == "LINE3" ? 2 : tp.sides[s].size();
          for (size_t k = 0; k < nc; ++k) corners.push_back(b.connectivity[size_t(e) * b.nodesPerElement + tp.sides[s][k]]);
          sides_[key(corners)].push_back({element, s + 1});
        }
    }
  }

  void readSideSet(Mesh& mesh, const Group& g) {
    const Elements els = groupElements(g);
    SideSet set;
    set.name = g.name;
    set.id = g.tag;
    std::set<int> nodes;
    for (size_t t = 0; t < els.types.size(); ++t) {
      std::string name;
      int dim = 0, order = 0, n = 0, primary = 0;
      std::vector<double> ref;
      gmsh::model::mesh::getElementProperties(els.types[t], name, dim, order, n, ref, primary);
      for (size_t f = 0; f < els.tags[t].size(); ++f) {
        std::vector<int> corners;
        for (int k = 0; k < n; ++k) {
          const int nd = node(els.nodes[t][f * n + k]);
          nodes.insert(nd);
          if (k < primary) corners.push_back(nd);
        }
        const auto it = sides_.find(key(corners));
        if (it == sides_.end())
          fail("physical group '" + g.name + "': element " + std::to_string(els.tags[t][f]) +
                   " is not a side of any element of the blocks",
               "put only boundary faces of the meshed bodies in side groups");
        for (const auto& [element, side] : it->second) {
          set.elements.push_back(element);
          set.sides.push_back(side);
        }
      }
    }
    mesh.sideSets.push_back(std::move(set));
    readNodeSet(mesh, g, std::vector<int>(nodes.begin(), nodes.end()));
  }

  std::vector<int> groupNodes(const Group& g) const {
    std::vector<std::size_t> tags;
    std::vector<double> xyz;
    gmsh::model::mesh::getNodesForPhysicalGroup(g.dim, g.tag, tags, xyz);
    std::vector<int> nodes;
    for (std::size_t t : tags) nodes.push_back(node(t));
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
  }

  static void readNodeSet(Mesh& mesh, const Group& g, std::vector<int> nodes) {
    NodeSet ns;
    ns.name = g.name;
    ns.id = g.tag;
    ns.nodes = std::move(nodes);
    mesh.nodeSets.push_back(std::move(ns));
  }

  std::string path_;
  std::map<std::size_t, int> index_;                                 // gmsh node tag -> index
  std::map<std::vector<int>, std::vector<std::pair<int, int>>> sides_;  // corners -> (element, side)
};

}  // namespace

Mesh readGmshMesh(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throwInput(path, "", "", "mesh file not found", "check the file name and directory");
  if (std::filesystem::is_directory(path, ec))
    throwInput(path, "", "", "is a directory, not a mesh file", "give a gmsh .msh file");
  return meshFromBytes(runInChildProcess(path, "gmsh", [&] { return meshToBytes(GmshFile(path).read()); }));
}

}  // namespace choc
