// Exodus II mesh writer.
#include "mesh/ExodusMeshWriter.hpp"

#include "core/Errors.hpp"

#include <exodusII.h>

#include <unistd.h>
#include <set>
#include <stdexcept>
#include <vector>

namespace choc {

namespace {

class MeshFileWriter {
 public:
  MeshFileWriter(const Mesh& mesh, const std::string& path, bool netcdf4)
      : mesh_(mesh), path_(path), netcdf4_(netcdf4) {}

  // 2D meshes (planar elements) are written as 2D, so that ParaView shows them as such.
  int dimension() const { return mesh_.dimension == 2 ? 2 : 3; }

  int create() {
    validateNames();
    ex_opts(EX_DEFAULT);  // no library messages: failures become exceptions
    int cpuWordSize = 8, ioWordSize = 8;
    id_ = ex_create(path_.c_str(), EX_CLOBBER | (netcdf4_ ? EX_NETCDF4 : EX_LARGE_MODEL),
                    &cpuWordSize, &ioWordSize);
    if (id_ < 0) throw OutputError(exodusFailure("creating the Exodus file", path_));
    try {
      check(ex_set_max_name_length(id_, kExodusMaxNameLength), "setting the name length");
      check(ex_put_init(id_, mesh_.title.substr(0, MAX_LINE_LENGTH).c_str(), dimension(), mesh_.numNodes(),
                        mesh_.numElements(), static_cast<int64_t>(mesh_.blocks.size()),
                        static_cast<int64_t>(mesh_.nodeSets.size()),
                        static_cast<int64_t>(mesh_.sideSets.size())),
            "writing the header");
      writeCoordinates();
      writeBlocks();
      writeNodeSets();
      writeSideSets();
    } catch (...) {
      ex_close(id_);
      ::unlink(path_.c_str());  // no half-written mesh left behind
      throw;
    }
    return id_;
  }

 private:
  void check(int rc, const std::string& what) const {
    if (rc < 0) throw OutputError(exodusFailure(what, path_));
  }

  void validateNames() const {
    auto checkName = [&](const std::string& name, const char* kind) {
      if (static_cast<int>(name.size()) > kExodusMaxNameLength)
        throw std::invalid_argument("writing " + path_ + ": " + kind + " name '" + name +
                                    "' is longer than " +
                                    std::to_string(kExodusMaxNameLength) + " characters");
    };
    for (const auto& b : mesh_.blocks) checkName(b.name, "element block");
    for (const auto& s : mesh_.nodeSets) checkName(s.name, "node set");
    for (const auto& s : mesh_.sideSets) checkName(s.name, "side set");
  }

  // Positive, unique ids in entity order (non-positive ids replaced by fresh ones).
  template <class T>
  std::vector<int> ids(const std::vector<T>& items, const char* kind) const {
    std::set<int> used;
    int next = 1;
    for (const T& item : items) {
      if (item.id > 0 && !used.insert(item.id).second)
        throw std::invalid_argument("writing " + path_ + ": duplicate " + kind + " id " +
                                    std::to_string(item.id));
      if (item.id >= next) next = item.id + 1;
    }
    std::vector<int> result;
    for (const T& item : items) result.push_back(item.id > 0 ? item.id : next++);
    return result;
  }

  template <class T>
  void writeNames(const std::vector<T>& items, ex_entity_type type, const std::string& what) {
    if (items.empty()) return;
    std::vector<std::string> names;
    for (const T& item : items) names.push_back(item.name);
    std::vector<char*> pointers;
    for (auto& n : names) pointers.push_back(n.data());
    check(ex_put_names(id_, type, pointers.data()), "writing the " + what + " names");
  }

  void writeCoordinates() {
    const int n = mesh_.numNodes();
    std::vector<double> c[3];
    for (int d = 0; d < 3; ++d) {
      c[d].resize(n);
      for (int i = 0; i < n; ++i) c[d][i] = mesh_.coords[i][d];
    }
    const int dim = dimension();
    if (n > 0)
      check(ex_put_coord(id_, c[0].data(), dim > 1 ? c[1].data() : nullptr, dim > 2 ? c[2].data() : nullptr),
            "writing coordinates");
    char x[] = "x", y[] = "y", z[] = "z";
    char* names[3] = {x, y, z};
    check(ex_put_coord_names(id_, names), "writing coordinate names");
  }

  void writeBlocks() {
    const std::vector<int> blockIds = ids(mesh_.blocks, "element block");
    for (std::size_t b = 0; b < mesh_.blocks.size(); ++b) {
      const ElementBlock& block = mesh_.blocks[b];
      const bool empty = block.connectivity.empty();
      if (block.nodesPerElement < 0 || (!empty && block.nodesPerElement == 0) ||
          (!empty && block.connectivity.size() % static_cast<std::size_t>(block.nodesPerElement)))
        throw std::invalid_argument("writing " + path_ + ": element block '" + block.name +
                                    "' has an inconsistent connectivity");
      // Exodus' own names for tetrahedra (TETRA4, TETRA10): what ParaView's reader expects.
      const std::string type = block.topology.empty()              ? std::string("NULL")
                               : block.topology.rfind("TET", 0) == 0 ? "TETRA" + block.topology.substr(3)
                                                                     : block.topology;
      check(ex_put_block(id_, EX_ELEM_BLOCK, blockIds[b], type.c_str(),
                         block.numElements(), block.nodesPerElement, 0, 0, 0),
            "writing element block '" + block.name + "'");
      if (block.numElements() == 0) continue;
      std::vector<int> conn = oneBased(block.connectivity, mesh_.numNodes(), block.name);
      check(ex_put_conn(id_, EX_ELEM_BLOCK, blockIds[b], conn.data(), nullptr, nullptr),
            "writing the connectivity of element block '" + block.name + "'");
    }
    writeNames(mesh_.blocks, EX_ELEM_BLOCK, "element block");
  }

  std::vector<int> oneBased(const std::vector<int>& list, int limit, const std::string& owner) const {
    std::vector<int> result(list);
    for (int& v : result) {
      if (v < 0 || v >= limit)
        throw std::invalid_argument("writing " + path_ + ": '" + owner + "' refers to index " +
                                    std::to_string(v) + " outside 0.." +
                                    std::to_string(limit - 1));
      ++v;
    }
    return result;
  }

  void writeNodeSets() {
    const std::vector<int> setIds = ids(mesh_.nodeSets, "node set");
    for (std::size_t s = 0; s < mesh_.nodeSets.size(); ++s) {
      const NodeSet& set = mesh_.nodeSets[s];
      const std::string what = "writing node set '" + set.name + "'";
      check(ex_put_set_param(id_, EX_NODE_SET, setIds[s], static_cast<int64_t>(set.nodes.size()), 0),
            what);
      if (set.nodes.empty()) continue;
      std::vector<int> nodes = oneBased(set.nodes, mesh_.numNodes(), set.name);
      check(ex_put_set(id_, EX_NODE_SET, setIds[s], nodes.data(), nullptr), what);
    }
    writeNames(mesh_.nodeSets, EX_NODE_SET, "node set");
  }

  void writeSideSets() {
    const std::vector<int> setIds = ids(mesh_.sideSets, "side set");
    for (std::size_t s = 0; s < mesh_.sideSets.size(); ++s) {
      const SideSet& set = mesh_.sideSets[s];
      const std::string what = "writing side set '" + set.name + "'";
      if (set.elements.size() != set.sides.size())
        throw std::invalid_argument(what + " to " + path_ + ": elements and sides differ in size");
      check(ex_put_set_param(id_, EX_SIDE_SET, setIds[s], static_cast<int64_t>(set.elements.size()),
                             0),
            what);
      if (set.elements.empty()) continue;
      std::vector<int> elements = oneBased(set.elements, mesh_.numElements(), set.name);
      std::vector<int> sides(set.sides);
      check(ex_put_set(id_, EX_SIDE_SET, setIds[s], elements.data(), sides.data()), what);
    }
    writeNames(mesh_.sideSets, EX_SIDE_SET, "side set");
  }

  const Mesh& mesh_;
  std::string path_;
  bool netcdf4_ = false;
  int id_ = -1;
};

}  // namespace

std::string exodusFailure(const std::string& what, const std::string& path) {
  const char* message = nullptr;
  const char* function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  std::string m = what + " failed for " + path;
  if (message && *message) m += ": " + std::string(message);
  return m;
}

int createExodusMeshFile(const Mesh& mesh, const std::string& path, bool netcdf4) {
  return MeshFileWriter(mesh, path, netcdf4).create();
}

void writeExodusMesh(const Mesh& mesh, const std::string& path, bool netcdf4) {
  const int id = createExodusMeshFile(mesh, path, netcdf4);
  if (ex_close(id) < 0) throw OutputError(exodusFailure("closing the Exodus file", path));
}

}  // namespace choc
