// Exodus II mesh reader. Every ex_* return code is checked: a bad file gives an InputError.
#include "mesh/ExodusReader.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <unordered_set>
#include <vector>

#include "core/Errors.hpp"
#include "mesh/ChildProcess.hpp"
#include "mesh/MeshBytes.hpp"
#include "mesh/NetcdfHeader.hpp"
#include "mesh/Topology.hpp"
#include "core/Format.hpp"

namespace choc {

namespace {


[[noreturn]] void badFile(const std::string& path, const std::string& problem) {
  throwInput(path, "", "", problem, "check that the file is a complete Exodus II mesh");
}

void check(int rc, const std::string& path, const std::string& what) {
  if (rc < 0) badFile(path, "cannot read " + what + " (file truncated or corrupt)");
}

// Closes the file on every exit path.
struct OpenFile {
  int id = -1;
  ~OpenFile() {
    if (id >= 0) ex_close(id);
  }
};

class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path) {}

  // choc's own header check runs here; the libraries read the file in a child process
  // (ChildProcess.hpp), which sends the mesh back.
  Mesh read() {
    const NetcdfStorage storage = checkFile();
    return meshFromBytes(runInChildProcess(
        path_, storage == NetcdfStorage::Hdf5 ? "HDF5" : "Exodus/netCDF",
        [this] { return meshToBytes(readWithLibraries()); }));
  }

 private:
  Mesh readWithLibraries() {
    open();
    ex_init_params p{};
    check(ex_get_init_ext(file_.id, &p), path_, "the file header");
    if (p.num_dim < 1 || p.num_dim > 3 || p.num_nodes < 0 || p.num_elem < 0 ||
        p.num_elem_blk < 0 || p.num_node_sets < 0 || p.num_side_sets < 0 ||
        p.num_nodes > fileBytes_ || p.num_elem > fileBytes_ || p.num_elem_blk > fileBytes_ ||
        p.num_node_sets > fileBytes_ || p.num_side_sets > fileBytes_)
      badFile(path_, "invalid sizes in the file header");
    Mesh mesh;
    p.title[MAX_LINE_LENGTH] = '\0';
    mesh.title = trimRight(p.title);
    mesh.dimension = static_cast<int>(p.num_dim);
    readCoordinates(mesh, static_cast<int>(p.num_dim), static_cast<int>(p.num_nodes));
    readBlocks(mesh, static_cast<int>(p.num_elem_blk));
    if (mesh.numElements() != p.num_elem)
      badFile(path_, "the element blocks hold " + std::to_string(mesh.numElements()) +
                         " elements but the header declares " + std::to_string(p.num_elem));
    readNodeSets(mesh, static_cast<int>(p.num_node_sets));
    readSideSets(mesh, static_cast<int>(p.num_side_sets));
    return mesh;
  }

  // Exists, is a file, has a netCDF signature; a corrupt classic header is refused before
  // netCDF trusts its counts (NetcdfHeader.hpp).
  NetcdfStorage checkFile() {
    std::error_code ec;
    if (!std::filesystem::exists(path_, ec))
      throwInput(path_, "", "", "mesh file not found", "check the file name and directory");
    if (std::filesystem::is_directory(path_, ec))
      throwInput(path_, "", "", "is a directory, not a mesh file", "give an Exodus II file");
    fileBytes_ = static_cast<int64_t>(std::filesystem::file_size(path_, ec));
    if (ec) fileBytes_ = 0;
    const NetcdfStorage storage = checkNetcdfHeader(path_);
    if (storage == NetcdfStorage::Unknown) notExodus();
    return storage;
  }

  void open() {
    ex_opts(EX_DEFAULT);  // no library messages on stderr: our error is the one line
    int cpuWordSize = 8, ioWordSize = 0;
    float version = 0.0f;
    file_.id = ex_open(path_.c_str(), EX_READ, &cpuWordSize, &ioWordSize, &version);
    if (file_.id < 0) notExodus();
    const int64_t used = ex_inquire_int(file_.id, EX_INQ_DB_MAX_USED_NAME_LENGTH);
    nameLength_ = static_cast<int>(std::clamp<int64_t>(used, 32, 256));
    check(ex_set_max_name_length(file_.id, nameLength_), path_, "the name length");
  }

  [[noreturn]] void notExodus() const {
    throwInput(path_, "", "", "not a readable Exodus II file (empty, truncated or another format)",
               "give a mesh written by an Exodus II tool (e.g. 'choc mesh')");
  }

  std::vector<std::string> names(ex_entity_type type, int count, const std::string& what) {
    std::vector<std::vector<char>> buffers(count, std::vector<char>(nameLength_ + 1, '\0'));
    std::vector<char*> pointers(count);
    for (int i = 0; i < count; ++i) pointers[i] = buffers[i].data();
    if (count > 0) check(ex_get_names(file_.id, type, pointers.data()), path_, what + " names");
    std::vector<std::string> result;
    for (auto& b : buffers) {
      b.back() = '\0';
      result.push_back(trimRight(b.data()));
    }
    return result;
  }

  static std::string trimRight(const char* s) {
    std::string r(s);
    while (!r.empty() && std::isspace(static_cast<unsigned char>(r.back()))) r.pop_back();
    return r;
  }

  // netCDF writes a whole variable into the buffer exodus passes on, whatever size the
  // Exodus dimension of the same name declares: a corrupt file may make the two differ. The
  // variable `var` must hold exactly `count` values before it is read into `count` slots.
  void expectValues(const std::string& var, int64_t count, const std::string& what) {
    int varId = -1, rank = 0;
    if (nc_inq_varid(file_.id, var.c_str(), &varId) != NC_NOERR) return;  // exodus says so
    int dimIds[NC_MAX_VAR_DIMS];
    if (nc_inq_varndims(file_.id, varId, &rank) != NC_NOERR || rank < 0 ||
        rank > NC_MAX_VAR_DIMS || nc_inq_vardimid(file_.id, varId, dimIds) != NC_NOERR)
      badFile(path_, "cannot read the shape of variable '" + var + "'");
    int64_t values = 1;
    for (int d = 0; d < rank; ++d) {
      size_t length = 0;
      if (nc_inq_dimlen(file_.id, dimIds[d], &length) != NC_NOERR)
        badFile(path_, "cannot read the shape of variable '" + var + "'");
      values = length > static_cast<size_t>(fileBytes_) ? fileBytes_ + 1
                                                          : values * static_cast<int64_t>(length);
      if (values > fileBytes_) break;
    }
    if (values != count)
      badFile(path_, what + ": variable '" + var + "' holds " +
                         (values > fileBytes_ ? "more than the file's size in" : std::to_string(values)) +
                         " values but its Exodus dimensions declare " + std::to_string(count) +
                         " (file corrupt)");
  }

  // The ids of `count` entities, from variable `var` (eb_prop1, ns_prop1, ss_prop1). They must
  // be distinct: exodus finds an entity's variables by the position of its id, reading `var`
  // and the status variable (eb_status, ...) whole into buffers of `count` values.
  std::vector<int> ids(ex_entity_type type, int count, const std::string& what,
                       const std::string& var) {
    std::vector<int> result(count);
    if (count == 0) return result;
    expectValues(var, count, what + " ids");
    expectValues(var.substr(0, 2) + "_status", count, what + " status");
    check(ex_get_ids(file_.id, type, result.data()), path_, what + " ids");
    std::unordered_set<int> seen;
    for (int id : result)
      if (!seen.insert(id).second) badFile(path_, what + " id " + std::to_string(id) + " is used twice");
    return result;
  }

  void readCoordinates(Mesh& mesh, int dim, int numNodes) {
    std::vector<double> c[3];
    for (int d = 0; d < 3; ++d) c[d].assign(numNodes, 0.0);
    if (numNodes > 0) {
      int varId = -1;  // one variable per axis (coordx...) or one for all (coord)
      if (nc_inq_varid(file_.id, "coordx", &varId) == NC_NOERR) {
        for (int d = 0; d < dim; ++d)
          expectValues(std::string("coord") + "xyz"[d], numNodes, "the node coordinates");
      } else {
        expectValues("coord", int64_t{dim} * numNodes, "the node coordinates");
      }
      check(ex_get_coord(file_.id, c[0].data(), dim > 1 ? c[1].data() : nullptr,
                         dim > 2 ? c[2].data() : nullptr),
            path_, "the node coordinates");
    }
    mesh.coords.resize(numNodes);
    for (int n = 0; n < numNodes; ++n) {
      mesh.coords[n] = {c[0][n], c[1][n], c[2][n]};
      for (double x : mesh.coords[n])
        if (!std::isfinite(x))
          badFile(path_, "node " + std::to_string(n + 1) + " has a non-finite coordinate");
    }
  }

  void toZeroBased(std::vector<int>& list, int limit, const std::string& what) {
    for (int& v : list) {
      if (v < 1 || v > limit)
        badFile(path_, what + " refers to index " + std::to_string(v) + " outside 1.." +
                           std::to_string(limit) + " (file truncated or corrupt)");
      --v;
    }
  }

  void readBlocks(Mesh& mesh, int count) {
    const std::vector<int> blockIds = ids(EX_ELEM_BLOCK, count, "element block", "eb_prop1");
    const std::vector<std::string> blockNames = names(EX_ELEM_BLOCK, count, "element block");
    for (int b = 0; b < count; ++b) {
      ex_block info{};
      info.id = blockIds[b];
      info.type = EX_ELEM_BLOCK;
      check(ex_get_block_param(file_.id, &info), path_, "element block " + std::to_string(info.id));
      ElementBlock block;
      block.id = blockIds[b];
      block.name = blockNames[b].empty() ? "block_" + std::to_string(block.id) : blockNames[b];
      info.topology[MAX_STR_LENGTH] = '\0';
      const std::string type = upperTrimmed(info.topology);
      const int nodes = static_cast<int>(info.num_nodes_per_entry);
      block.topology = canonicalTopology(type, nodes);
      // Exodus stores an empty block as type "NULL" with 0 nodes: keep it, without topology.
      if (block.topology.empty() && info.num_entry == 0) {
        mesh.blocks.push_back(std::move(block));
        continue;
      }
      if (block.topology.empty())
        throwInput(path_, "element block '" + block.name + "' topology",
                   type + " with " + std::to_string(nodes) + " nodes",
                   "unsupported element topology", supportedTopologiesText());
      // Each connectivity entry takes at least 4 bytes: more than the file holds is corrupt.
      if (info.num_entry < 0 || info.num_entry * nodes > fileBytes_ / 4)
        badFile(path_, "element block '" + block.name + "' has an invalid element count");
      block.nodesPerElement = nodes;
      block.connectivity.resize(static_cast<std::size_t>(info.num_entry) * nodes);
      if (info.num_entry > 0) {
        expectValues("connect" + std::to_string(b + 1), info.num_entry * nodes,
                     "element block '" + block.name + "'");
        check(ex_get_conn(file_.id, EX_ELEM_BLOCK, block.id, block.connectivity.data(), nullptr,
                          nullptr),
              path_, "the connectivity of element block '" + block.name + "'");
      }
      toZeroBased(block.connectivity, mesh.numNodes(),
                  "the connectivity of element block '" + block.name + "'");
      mesh.blocks.push_back(std::move(block));
    }
  }

  // Reads the parameters of one set; returns its entry count.
  int setSize(ex_entity_type type, int id, const std::string& what) {
    int entries = 0, distFactors = 0;
    check(ex_get_set_param(file_.id, type, id, &entries, &distFactors), path_, what);
    if (entries < 0 || entries > fileBytes_ / 4) badFile(path_, what + " has an invalid size");
    return entries;
  }

  void readNodeSets(Mesh& mesh, int count) {
    const std::vector<int> setIds = ids(EX_NODE_SET, count, "node set", "ns_prop1");
    const std::vector<std::string> setNames = names(EX_NODE_SET, count, "node set");
    for (int s = 0; s < count; ++s) {
      NodeSet set;
      set.id = setIds[s];
      set.name = setNames[s].empty() ? "nodeset_" + std::to_string(set.id) : setNames[s];
      const std::string what = "node set '" + set.name + "'";
      set.nodes.resize(setSize(EX_NODE_SET, set.id, what));
      if (!set.nodes.empty()) {
        expectValues("node_ns" + std::to_string(s + 1), set.nodes.size(), what);
        check(ex_get_set(file_.id, EX_NODE_SET, set.id, set.nodes.data(), nullptr), path_, what);
      }
      toZeroBased(set.nodes, mesh.numNodes(), what);
      mesh.nodeSets.push_back(std::move(set));
    }
  }

  void readSideSets(Mesh& mesh, int count) {
    const std::vector<int> setIds = ids(EX_SIDE_SET, count, "side set", "ss_prop1");
    const std::vector<std::string> setNames = names(EX_SIDE_SET, count, "side set");
    for (int s = 0; s < count; ++s) {
      SideSet set;
      set.id = setIds[s];
      set.name = setNames[s].empty() ? "sideset_" + std::to_string(set.id) : setNames[s];
      const std::string what = "side set '" + set.name + "'";
      const int n = setSize(EX_SIDE_SET, set.id, what);
      set.elements.resize(n);
      set.sides.resize(n);
      if (n > 0) {
        expectValues("elem_ss" + std::to_string(s + 1), n, what);
        expectValues("side_ss" + std::to_string(s + 1), n, what);
        check(ex_get_set(file_.id, EX_SIDE_SET, set.id, set.elements.data(), set.sides.data()),
              path_, what);
      }
      toZeroBased(set.elements, mesh.numElements(), what);
      for (int i = 0; i < n; ++i) {
        const ElementBlock& block = mesh.blocks[mesh.locateElement(set.elements[i]).first];
        const Topology* topo = findTopology(block.topology);
        const int maxSide = topo ? topo->numSides() : 0;
        if (set.sides[i] < 1 || set.sides[i] > maxSide)
          badFile(path_, what + " has side " + std::to_string(set.sides[i]) + " on a " +
                             block.topology + " element (valid: 1.." + std::to_string(maxSide) +
                             ")");
      }
      mesh.sideSets.push_back(std::move(set));
    }
  }

  std::string path_;
  OpenFile file_;
  int nameLength_ = 32;
  int64_t fileBytes_ = 0;  // size of the file: bounds every count read from the header
};

}  // namespace

Mesh readExodusMesh(const std::string& path) { return Reader(path).read(); }

}  // namespace choc
