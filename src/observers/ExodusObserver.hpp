// Exodus results of a transient: DISP_X/Y/Z, VEL_X/Y/Z, ACC_X/Y/Z and the interactions' nodal
// variables; the energies (read from the history) and the interactions' global variables;
// every `interval` recorded states and the last one. Rank 0 writes, every rank gathers.
#pragma once
#include <memory>
#include <string>

#include "observers/HistoryObserver.hpp"
#include "output/ExodusResults.hpp"
#include "physics/Model.hpp"

namespace choc {

class ExodusObserver : public TransientObserver {
 public:
  // resume (may be null): continue the file of a checkpointed run.
  ExodusObserver(const std::string& path, const Model& model, const HistoryObserver& history,
                 int interval, const StateArchive* resume = nullptr);
  void begin(TransientView& view) override;
  void step(TransientView& view) override;
  void end(bool ok) override;
  void failed(TransientView& view) override;  // writes the last accepted state if it was not
  void archive(StateArchive& a) const override;

 private:
  void open(TransientView& view);  // rank 0
  void write(TransientView& view);  // the view's state as the file's next step (collective)
  bool pending_ = false;            // the last state the observer saw is not in the file
  std::string path_;
  const Model& model_;
  const HistoryObserver& history_;
  int interval_;
  const StateArchive* resume_;
  std::unique_ptr<ExodusResultsWriter> exo_;
  RCP<Vector> u_, v_, a_;
};

}  // namespace choc
