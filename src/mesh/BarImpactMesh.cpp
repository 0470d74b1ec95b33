// Bar impact mesh generator: every loop is linear in the number of nodes or elements.
#include "mesh/BarImpactMesh.hpp"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

#include "core/Errors.hpp"

namespace choc {

namespace {

const char* const kCommand = "choc mesh";
constexpr int64_t kMaxNodes = 50'000'000;

std::string str(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

void requirePositive(double v, const char* option, const char* what) {
  if (!(std::isfinite(v) && v > 0.0))
    throwInput(kCommand, option, str(v), "must be a finite number > 0",
               std::string("give the ") + what + " in metres");
}

void requireCount(int n, const char* option, const char* what) {
  if (n < 1)
    throwInput(kCommand, option, std::to_string(n), "must be an integer >= 1",
               std::string("give the number of elements ") + what);
}

// Frame of the scene: the axis index and the two lateral indices in cyclic order.
struct Frame {
  int axis, lateral1, lateral2;
  explicit Frame(char a) : axis(a - 'x'), lateral1((axis + 1) % 3), lateral2((axis + 2) % 3) {}
  Point3 point(double s, double u = 0.0, double v = 0.0) const {
    Point3 p{0.0, 0.0, 0.0};
    p[axis] = s;
    p[lateral1] = u;
    p[lateral2] = v;
    return p;
  }
};

std::vector<int> range(int first, int count) {
  std::vector<int> r(count);
  for (int i = 0; i < count; ++i) r[i] = first + i;
  return r;
}

void addNodeSet(Mesh& mesh, const std::string& name, std::vector<int> nodes) {
  NodeSet set;
  set.name = name;
  set.id = static_cast<int>(mesh.nodeSets.size()) + 1;
  set.nodes = std::move(nodes);
  mesh.nodeSets.push_back(std::move(set));
}

ElementBlock makeBlock(const std::string& name, int id, const std::string& topology, int nodes) {
  ElementBlock b;
  b.name = name;
  b.id = id;
  b.topology = topology;
  b.nodesPerElement = nodes;
  return b;
}

Mesh generate1D(const BarImpactOptions& o) {
  const Frame f(o.axis);
  Mesh mesh;
  mesh.title = std::string("choc bar impact, 1D, axis ") + o.axis;
  const int n1 = o.along1 + 1, n2 = o.along2 + 1;
  mesh.coords.reserve(n1 + n2);
  mesh.coords.push_back(f.point(o.gap + o.shiftA));  // A
  for (int i = 1; i < o.along1; ++i) mesh.coords.push_back(f.point(o.gap + o.length1 * i / o.along1));
  mesh.coords.push_back(f.point(o.gap + o.length1));  // B
  for (int j = 0; j < o.along2; ++j) mesh.coords.push_back(f.point(-o.length2 * j / o.along2));
  mesh.coords.push_back(f.point(-o.length2));  // D
  ElementBlock pou1 = makeBlock("POU1", 1, "BEAM2", 2), pou2 = makeBlock("POU2", 2, "BEAM2", 2);
  for (int e = 0; e < o.along1; ++e) pou1.connectivity.insert(pou1.connectivity.end(), {e, e + 1});
  for (int e = 0; e < o.along2; ++e)
    pou2.connectivity.insert(pou2.connectivity.end(), {n1 + e, n1 + e + 1});
  mesh.blocks = {std::move(pou1), std::move(pou2)};
  addNodeSet(mesh, "A", {0});
  addNodeSet(mesh, "B", {n1 - 1});
  addNodeSet(mesh, "C", {n1});
  addNodeSet(mesh, "D", {n1 + n2 - 1});
  addNodeSet(mesh, "POU1", range(0, n1));
  addNodeSet(mesh, "POU2", range(n1, n2));
  return mesh;
}

// One 3D bar: layers k = 0..along of (across+1)^2 nodes, layer 0 on the contact face.
struct Bar3D {
  int firstNode, firstElement, along, across;
  double s0, ds;  // s of layer k = s0 + k * ds (ds > 0 for bar 1, < 0 for bar 2)
  int perLayer() const { return (across + 1) * (across + 1); }
  int numNodes() const { return (along + 1) * perLayer(); }
  int numElements() const { return along * across * across; }
  int node(int k, int i, int j) const { return firstNode + k * perLayer() + j * (across + 1) + i; }
  std::vector<int> layer(int k) const { return range(node(k, 0, 0), perLayer()); }
};

void addBar3D(Mesh& mesh, const Frame& f, const Bar3D& bar, const BarImpactOptions& o,
              ElementBlock& block) {
  for (int k = 0; k <= bar.along; ++k) {
    const double s = k == bar.along ? bar.s0 + bar.along * bar.ds : bar.s0 + k * bar.ds;
    for (int j = 0; j <= bar.across; ++j)
      for (int i = 0; i <= bar.across; ++i)
        mesh.coords.push_back(f.point(s, o.width * i / bar.across, o.height * j / bar.across));
  }
  block.connectivity.reserve(static_cast<std::size_t>(bar.numElements()) * 8);
  for (int k = 0; k < bar.along; ++k) {
    // Nodes 1-4 on the layer of lower s so that (lateral1, lateral2, axis) is right-handed.
    const int lo = bar.ds > 0 ? k : k + 1, hi = bar.ds > 0 ? k + 1 : k;
    for (int j = 0; j < bar.across; ++j)
      for (int i = 0; i < bar.across; ++i)
        block.connectivity.insert(
            block.connectivity.end(),
            {bar.node(lo, i, j), bar.node(lo, i + 1, j), bar.node(lo, i + 1, j + 1),
             bar.node(lo, i, j + 1), bar.node(hi, i, j), bar.node(hi, i + 1, j),
             bar.node(hi, i + 1, j + 1), bar.node(hi, i, j + 1)});
  }
}

// The elements of a bar's layer 0 (its contact face), all on the same Exodus side.
void addContactSideSet(Mesh& mesh, const std::string& name, const Bar3D& bar, int side) {
  SideSet set;
  set.name = name;
  set.id = static_cast<int>(mesh.sideSets.size()) + 1;
  set.elements = range(bar.firstElement, bar.across * bar.across);
  set.sides.assign(set.elements.size(), side);
  mesh.sideSets.push_back(std::move(set));
}

Mesh generate3D(const BarImpactOptions& o) {
  const Frame f(o.axis);
  Mesh mesh;
  mesh.title = std::string("choc bar impact, 3D, axis ") + o.axis;
  const Bar3D bar1{0, 0, o.along1, o.across1, o.gap, o.length1 / o.along1};
  const Bar3D bar2{bar1.numNodes(), bar1.numElements(), o.along2, o.across2, 0.0,
                   -o.length2 / o.along2};
  mesh.coords.reserve(static_cast<std::size_t>(bar1.numNodes() + bar2.numNodes()));
  ElementBlock pou1 = makeBlock("POU1", 1, "HEX8", 8), pou2 = makeBlock("POU2", 2, "HEX8", 8);
  addBar3D(mesh, f, bar1, o, pou1);
  addBar3D(mesh, f, bar2, o, pou2);
  // Exact end positions (no rounding in s0 + along * ds).
  for (int n : bar1.layer(bar1.along)) mesh.coords[n][f.axis] = o.gap + o.length1;
  for (int n : bar2.layer(bar2.along)) mesh.coords[n][f.axis] = -o.length2;
  mesh.blocks = {std::move(pou1), std::move(pou2)};
  addNodeSet(mesh, "POU1", range(0, bar1.numNodes()));
  addNodeSet(mesh, "POU2", range(bar2.firstNode, bar2.numNodes()));
  addNodeSet(mesh, "N1", {bar1.node(0, 0, 0)});
  addNodeSet(mesh, "A", {bar1.node(0, 0, 0)});
  addNodeSet(mesh, "B", {bar1.node(bar1.along, 0, 0)});
  addNodeSet(mesh, "C", {bar2.node(0, 0, 0)});
  addNodeSet(mesh, "D", {bar2.node(bar2.along, 0, 0)});
  addNodeSet(mesh, "CL_POU2", bar2.layer(bar2.along));
  addNodeSet(mesh, "FACE_POU1", bar1.layer(0));
  addNodeSet(mesh, "FACE_POU2", bar2.layer(0));
  addContactSideSet(mesh, "CNT_POU1", bar1, 5);  // nodes 1-4 face: normal -axis
  addContactSideSet(mesh, "CNT_POU2", bar2, 6);  // nodes 5-8 face: normal +axis
  return mesh;
}

}  // namespace

void validateBarImpactOptions(const BarImpactOptions& o) {
  if (o.dimension != 1 && o.dimension != 3)
    throwInput(kCommand, "--dim", std::to_string(o.dimension), "must be 1 or 3",
               "use 1 for beam elements or 3 for hexahedra");
  if (o.axis != 'x' && o.axis != 'y' && o.axis != 'z')
    throwInput(kCommand, "--axis", std::string(1, o.axis), "must be x, y or z",
               "give the axis of the bars");
  requirePositive(o.length1, "--length1", "length of bar 1");
  requirePositive(o.length2, "--length2", "length of bar 2");
  requirePositive(o.width, "--width", "section width");
  requirePositive(o.height, "--height", "section height");
  requireCount(o.along1, "--along1", "along bar 1");
  requireCount(o.along2, "--along2", "along bar 2");
  requireCount(o.across1, "--across1", "across bar 1");
  requireCount(o.across2, "--across2", "across bar 2");
  // In double: no overflow whatever the counts.
  const double a1 = o.dimension == 3 ? o.across1 + 1.0 : 1.0;
  const double a2 = o.dimension == 3 ? o.across2 + 1.0 : 1.0;
  const double nodes1 = (o.along1 + 1.0) * a1 * a1, nodes2 = (o.along2 + 1.0) * a2 * a2;
  if (nodes1 + nodes2 > double(kMaxNodes)) {
    const int bar = nodes1 >= nodes2 ? 1 : 2;
    const int along = bar == 1 ? o.along1 : o.along2, across = bar == 1 ? o.across1 : o.across2;
    const bool acrossDominates = o.dimension == 3 && (across + 1.0) * (across + 1.0) > along + 1.0;
    throwInput(kCommand, (acrossDominates ? "--across" : "--along") + std::to_string(bar),
               std::to_string(acrossDominates ? across : along),
               "the mesh would have more than " + std::to_string(kMaxNodes) + " nodes",
               "use fewer elements along or across the bars");
  }
  if (!std::isfinite(o.gap))
    throwInput(kCommand, "--gap", str(o.gap), "must be a finite number",
               "give the distance from C to A in metres (0 or negative allowed)");
  if (!std::isfinite(o.shiftA))
    throwInput(kCommand, "--shift-a", str(o.shiftA), "must be a finite number",
               "give the shift of node A in metres");
  if (o.shiftA != 0.0 && o.dimension != 1)
    throwInput(kCommand, "--shift-a", str(o.shiftA), "is only available with --dim 1",
               "remove --shift-a or use --dim 1");
  if (o.shiftA >= o.length1 / o.along1)
    throwInput(kCommand, "--shift-a", str(o.shiftA),
               "moves node A onto or past the next node of bar 1 (element length " +
                   str(o.length1 / o.along1) + ")",
               "use a shift smaller than the element length");
}

Mesh generateBarImpactMesh(const BarImpactOptions& o) {
  validateBarImpactOptions(o);
  return o.dimension == 1 ? generate1D(o) : generate3D(o);
}

}  // namespace choc
