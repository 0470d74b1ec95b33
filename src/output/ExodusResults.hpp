// Exodus II results file: the mesh, then one time step per writeStep() call.
// The file is written as "<path>.part" and renamed by finish() (→ path) or abandon()
// (→ "<stem>.incomplete<ext>", e.g. "x/run.exo" → "x/run.incomplete.exo"), so a final
// name always means a complete run. Each step is flushed, so an interrupted run is still
// readable. Call it on one MPI rank only (the caller gathers the fields).
#pragma once
#include <string>
#include <vector>

#include "mesh/Mesh.hpp"

namespace choc {

// Element variables: their names and the blocks (one flag per mesh block) that carry them.
struct ElementVariables {
  std::vector<std::string> names;
  std::vector<char> blocks;
};

class ExodusResultsWriter {
 public:
  // Creates "<path>.part" containing the mesh and the variable definitions (names as
  // given, e.g. DISP_X, DISP_Y, DISP_Z so that ParaView groups them into vectors).
  // Throws choc::OutputError naming the path on an I/O failure, std::invalid_argument
  // for empty, duplicate or too long variable names.
  ExodusResultsWriter(const std::string& path, const Mesh& mesh,
                      std::vector<std::string> nodalVariables,
                      std::vector<std::string> globalVariables, ElementVariables element = {});
  // Continues the results of a checkpointed run: <path>.part (or the .incomplete or final
  // file when that run ended), which must hold this mesh's node count, these variables and at
  // least `steps` time steps, the last of them at `lastTime`; later steps are overwritten as
  // the run goes on. Throws InputError naming the file otherwise.
  struct Resume {
    int steps = 0;
    double lastTime = 0.0;
  };
  ExodusResultsWriter(const std::string& path, const Mesh& mesh,
                      std::vector<std::string> nodalVariables,
                      std::vector<std::string> globalVariables, const Resume& at,
                      ElementVariables element = {});
  // Throws the InputError the resuming constructor would when no earlier file of <path> holds
  // `steps` time steps, without changing anything (a refused restart writes nothing); returns
  // the file it would continue.
  static std::string checkResumable(const std::string& path, int steps);
  ~ExodusResultsWriter();  // abandon() unless finish() or abandon() was called
  ExodusResultsWriter(const ExodusResultsWriter&) = delete;
  ExodusResultsWriter& operator=(const ExodusResultsWriter&) = delete;

  // nodal[v][node] for every nodal variable and node, globals[g] for every global
  // variable. Appends one time step and flushes. Throws choc::NumericalError (naming the
  // variable, the node and the time) for a non-finite value or time, writing nothing;
  // std::invalid_argument for wrong sizes; choc::OutputError on I/O failure;
  // std::logic_error after finish()/abandon().
  // element[v][e]: element variable v of every element e of the mesh (global order; the
  // blocks without the variable are not written), when element variables were declared.
  void writeStep(double time, const std::vector<std::vector<double>>& nodal,
                 const std::vector<double>& globals, const std::vector<std::vector<double>>& element = {});
  void finish();   // closes and renames <path>.part → <path>
  void abandon();  // closes and renames <path>.part → <stem>.incomplete<ext>; quiet if closed
  int stepsWritten() const { return steps_; }
  double lastTime() const { return lastTime_; }

  const std::string& path() const { return path_; }
  std::string partPath() const { return path_ + ".part"; }
  std::string incompletePath() const;

 private:
  struct Names {  // the file's names, before any writer exists
    std::string path;
    std::string part() const { return path + ".part"; }
    std::string incomplete() const;
  };
  void close();
  void check(int rc, const std::string& what) const;

  std::string path_;
  int numNodes_ = 0;
  std::vector<std::string> nodalNames_, globalNames_;
  ElementVariables element_;
  std::vector<int> blockSizes_;  // elements per block, in the mesh's order
  void defineElementVariables();
  // Sizes and finiteness of the element values (before anything of the step is written).
  void checkElementValues(const std::vector<std::vector<double>>& element, double time) const;
  void writeElementStep(int step, const std::vector<std::vector<double>>& element);
  int exoid_ = -1;
  int steps_ = 0;
  double lastTime_ = 0.0;
};

}  // namespace choc
