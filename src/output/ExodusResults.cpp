// Exodus II results writer (ExodusResults.hpp).
#include "output/ExodusResults.hpp"

#include <exodusII.h>

#include <cmath>
#include <unistd.h>

#include <set>
#include <sstream>
#include <stdexcept>

#include "core/Errors.hpp"
#include "core/Files.hpp"
#include "mesh/ExodusMeshWriter.hpp"

namespace choc {

namespace {

void validateNames(const std::vector<std::string>& names, const char* kind,
                   const std::string& path) {
  std::set<std::string> seen;
  for (const std::string& n : names) {
    std::string problem;
    if (n.empty()) problem = "is empty";
    else if (static_cast<int>(n.size()) > kExodusMaxNameLength)
      problem = "is longer than " + std::to_string(kExodusMaxNameLength) + " characters";
    else if (!seen.insert(n).second) problem = "is given twice";
    if (!problem.empty())
      throw std::invalid_argument("results file " + path + ": " + kind + " variable name '" + n +
                                  "' " + problem);
  }
}

std::string str(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

[[noreturn]] void refuseResume(const std::string& file, const std::string& why) {
  throw InputError(file + ": cannot continue the results of the checkpointed run: " + why +
                   "; restart with the results the checkpoint was written with, or run from the start");
}

}  // namespace

namespace {

std::vector<int> blockSizes(const Mesh& mesh) {
  std::vector<int> n;
  for (const ElementBlock& b : mesh.blocks) n.push_back(b.numElements());
  return n;
}

}  // namespace

ExodusResultsWriter::ExodusResultsWriter(const std::string& path, const Mesh& mesh,
                                         std::vector<std::string> nodalVariables,
                                         std::vector<std::string> globalVariables, ElementVariables element)
    : path_(path),
      numNodes_(mesh.numNodes()),
      nodalNames_(std::move(nodalVariables)),
      globalNames_(std::move(globalVariables)),
      element_(std::move(element)),
      blockSizes_(blockSizes(mesh)) {
  validateNames(nodalNames_, "nodal", path_);
  validateNames(element_.names, "element", path_);
  validateNames(globalNames_, "global", path_);
  // a result of an earlier run must not pass for this run's
  removeFile(path_);
  removeFile(incompletePath());
  exoid_ = createExodusMeshFile(mesh, partPath());
  try {
    auto define = [&](ex_entity_type type, std::vector<std::string>& names, const char* kind) {
      if (names.empty()) return;
      check(ex_put_variable_param(exoid_, type, static_cast<int>(names.size())),
            std::string("defining the ") + kind + " variables");
      std::vector<char*> pointers;
      for (auto& n : names) pointers.push_back(n.data());
      check(ex_put_variable_names(exoid_, type, static_cast<int>(names.size()), pointers.data()),
            std::string("writing the ") + kind + " variable names");
    };
    define(EX_GLOBAL, globalNames_, "global");
    define(EX_NODAL, nodalNames_, "nodal");
    define(EX_ELEM_BLOCK, element_.names, "element");
    defineElementVariables();
    check(ex_update(exoid_), "flushing the mesh");
  } catch (...) {
    ex_close(exoid_);
    exoid_ = -1;
    ::unlink(partPath().c_str());  // nothing worth keeping
    throw;
  }
}

ExodusResultsWriter::ExodusResultsWriter(const std::string& path, const Mesh& mesh,
                                         std::vector<std::string> nodalVariables,
                                         std::vector<std::string> globalVariables, const Resume& at,
                                         ElementVariables element)
    : path_(path),
      numNodes_(mesh.numNodes()),
      nodalNames_(std::move(nodalVariables)),
      globalNames_(std::move(globalVariables)),
      element_(std::move(element)),
      blockSizes_(blockSizes(mesh)) {
  const std::string source = checkResumable(path_, at.steps);
  const auto refuse = [&](const std::string& file, const std::string& why) {
    if (exoid_ >= 0) ex_close(exoid_);
    exoid_ = -1;
    refuseResume(file, why);
  };
  if (source != partPath()) renameFile(source, partPath());
  int cpu = sizeof(double), io = 0;
  float version = 0;
  exoid_ = ex_open(partPath().c_str(), EX_WRITE, &cpu, &io, &version);
  if (exoid_ < 0) refuse(partPath(), "not a readable Exodus file");
  const auto names = [&](ex_entity_type type) {
    int n = 0;
    std::vector<std::string> out;
    if (ex_get_variable_param(exoid_, type, &n) < 0 || n < 0) return out;
    std::vector<std::vector<char>> buf(n, std::vector<char>(kExodusMaxNameLength + 1, '\0'));
    std::vector<char*> ptr;
    for (auto& b : buf) ptr.push_back(b.data());
    if (n > 0 && ex_get_variable_names(exoid_, type, n, ptr.data()) < 0) return out;
    for (auto& b : buf) out.emplace_back(b.data());
    return out;
  };
  if (ex_inquire_int(exoid_, EX_INQ_NODES) != numNodes_) refuse(partPath(), "its node count differs");
  if (names(EX_NODAL) != nodalNames_ || names(EX_GLOBAL) != globalNames_ || names(EX_ELEM_BLOCK) != element_.names)
    refuse(partPath(), "its variables differ");
  const int stored = static_cast<int>(ex_inquire_int(exoid_, EX_INQ_TIME));
  double t = 0.0;
  if (stored < at.steps || (at.steps > 0 && (ex_get_time(exoid_, at.steps, &t) < 0 || t != at.lastTime)))
    refuse(partPath(), "it holds " + std::to_string(stored) + " time steps, not the checkpoint's " +
                           std::to_string(at.steps));
  steps_ = at.steps;
  lastTime_ = at.lastTime;
}

std::string ExodusResultsWriter::checkResumable(const std::string& path, int steps) {
  const ExodusResultsWriter::Names n{path};
  std::string source;
  for (const std::string& p : {n.part(), n.incomplete(), path})
    if (isRegularFile(p)) {
      source = p;
      break;
    }
  if (source.empty()) refuseResume(n.part(), "no such file (nor " + n.incomplete() + " or " + path + ")");
  int cpu = sizeof(double), io = 0;
  float version = 0;
  const int id = ex_open(source.c_str(), EX_READ, &cpu, &io, &version);
  if (id < 0) refuseResume(source, "not a readable Exodus file");
  const int stored = static_cast<int>(ex_inquire_int(id, EX_INQ_TIME));
  ex_close(id);
  if (stored < steps)
    refuseResume(source, "it holds " + std::to_string(stored) + " time steps, not the checkpoint's " +
                             std::to_string(steps));
  return source;
}

ExodusResultsWriter::~ExodusResultsWriter() {
  try {
    abandon();
  } catch (...) {
    // A destructor must not throw; the .part file stays for inspection.
  }
}

void ExodusResultsWriter::check(int rc, const std::string& what) const {
  if (rc < 0) throw OutputError(exodusFailure(what, partPath()) + " (disk full or file-size limit?)");
}

void ExodusResultsWriter::writeStep(double time, const std::vector<std::vector<double>>& nodal,
                                    const std::vector<double>& globals,
                                    const std::vector<std::vector<double>>& element) {
  if (exoid_ < 0)
    throw std::logic_error("results file " + path_ + ": writeStep after the file was closed");
  if (nodal.size() != nodalNames_.size() || globals.size() != globalNames_.size())
    throw std::invalid_argument("results file " + path_ + ": " + std::to_string(nodal.size()) +
                                " nodal and " + std::to_string(globals.size()) +
                                " global fields given, " + std::to_string(nodalNames_.size()) +
                                " and " + std::to_string(globalNames_.size()) + " declared");
  if (!std::isfinite(time))
    throw NumericalError("results file " + path_ + ": non-finite time value " + str(time));
  for (std::size_t v = 0; v < nodal.size(); ++v) {
    if (static_cast<int>(nodal[v].size()) != numNodes_)
      throw std::invalid_argument("results file " + path_ + ": nodal variable " + nodalNames_[v] +
                                  " has " + std::to_string(nodal[v].size()) + " values for " +
                                  std::to_string(numNodes_) + " nodes");
    for (int n = 0; n < numNodes_; ++n)
      if (!std::isfinite(nodal[v][n]))
        throw NumericalError("non-finite value " + str(nodal[v][n]) + " of " + nodalNames_[v] +
                             " at node " + std::to_string(n + 1) + " at time " + str(time) +
                             " (not written to " + path_ + ")");
  }
  for (std::size_t g = 0; g < globals.size(); ++g)
    if (!std::isfinite(globals[g]))
      throw NumericalError("non-finite value " + str(globals[g]) + " of " + globalNames_[g] +
                           " at time " + str(time) + " (not written to " + path_ + ")");
  if (!element_.names.empty()) checkElementValues(element, time);
  const int step = steps_ + 1;
  check(ex_put_time(exoid_, step, &time), "writing time step " + std::to_string(step));
  for (std::size_t v = 0; v < nodal.size(); ++v)
    if (numNodes_ > 0)
      check(ex_put_var(exoid_, step, EX_NODAL, static_cast<int>(v) + 1, 1, numNodes_,
                       nodal[v].data()),
            "writing " + nodalNames_[v] + " at step " + std::to_string(step));
  if (!globals.empty())
    check(ex_put_var(exoid_, step, EX_GLOBAL, 1, 1, static_cast<int64_t>(globals.size()),
                     globals.data()),
          "writing the global variables at step " + std::to_string(step));
  if (!element_.names.empty()) writeElementStep(step, element);
  check(ex_update(exoid_), "flushing step " + std::to_string(step));
  steps_ = step;
  lastTime_ = time;
}

// The truth table: variable v on block b when the block carries the element variables.
void ExodusResultsWriter::defineElementVariables() {
  const int nb = static_cast<int>(blockSizes_.size()), nv = static_cast<int>(element_.names.size());
  if (nv == 0 || nb == 0) return;
  std::vector<int> table(size_t(nb) * nv, 0);
  for (int b = 0; b < nb; ++b)
    for (int v = 0; v < nv; ++v)
      table[size_t(b) * nv + v] = b < static_cast<int>(element_.blocks.size()) && element_.blocks[size_t(b)] ? 1 : 0;
  check(ex_put_truth_table(exoid_, EX_ELEM_BLOCK, nb, nv, table.data()), "writing the element variables' table");
}

void ExodusResultsWriter::checkElementValues(const std::vector<std::vector<double>>& element, double time) const {
  size_t total = 0;
  for (int n : blockSizes_) total += size_t(n);
  if (element.size() != element_.names.size())
    throw std::invalid_argument("results file " + path_ + ": " + std::to_string(element.size()) + " element fields given, " +
                                std::to_string(element_.names.size()) + " declared");
  for (size_t v = 0; v < element.size(); ++v) {
    if (element[v].size() != total)
      throw std::invalid_argument("results file " + path_ + ": element variable " + element_.names[v] + " has " +
                                  std::to_string(element[v].size()) + " values for " + std::to_string(total) +
                                  " elements");
    for (size_t e = 0; e < total; ++e)
      if (!std::isfinite(element[v][e]))
        throw NumericalError("non-finite value " + str(element[v][e]) + " of " + element_.names[v] + " at element " +
                             std::to_string(e + 1) + " at time " + str(time) + " (not written to " + path_ + ")");
  }
}

void ExodusResultsWriter::writeElementStep(int step, const std::vector<std::vector<double>>& element) {
  std::vector<int> ids(blockSizes_.size());  // the files use the 32-bit integer API
  if (!ids.empty()) check(ex_get_ids(exoid_, EX_ELEM_BLOCK, ids.data()), "reading the element block ids");
  for (size_t v = 0; v < element.size(); ++v) {
    size_t first = 0;
    for (size_t b = 0; b < blockSizes_.size(); ++b) {
      const bool carries = b < element_.blocks.size() && element_.blocks[b];
      if (carries && blockSizes_[b] > 0)
        check(ex_put_var(exoid_, step, EX_ELEM_BLOCK, static_cast<int>(v) + 1, ids[b], blockSizes_[b],
                         element[v].data() + first),
              "writing " + element_.names[v] + " at step " + std::to_string(step));
      first += size_t(blockSizes_[b]);
    }
  }
}

void ExodusResultsWriter::close() {
  const int id = exoid_;
  exoid_ = -1;
  if (ex_close(id) < 0) throw OutputError(exodusFailure("closing", partPath()) + " (disk full or file-size limit?)");
}

void ExodusResultsWriter::finish() {
  if (exoid_ < 0)
    throw std::logic_error("results file " + path_ + ": finish after the file was closed");
  close();
  renameFile(partPath(), path_);
}

void ExodusResultsWriter::abandon() {
  if (exoid_ < 0) return;
  const int id = exoid_;
  exoid_ = -1;
  ex_close(id);  // best effort: the steps written so far are already flushed
  renameFile(partPath(), incompletePath());
}

std::string ExodusResultsWriter::Names::incomplete() const {
  const std::size_t slash = path.rfind('/'), dot = path.rfind('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return path + ".incomplete.exo";
  return path.substr(0, dot) + ".incomplete" + path.substr(dot);
}

std::string ExodusResultsWriter::incompletePath() const { return Names{path_}.incomplete(); }

}  // namespace choc
