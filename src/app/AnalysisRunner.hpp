// Runs the analyses of an input in order. Each one's <analysis>.summary.json is written when
// it ends, completed or not: its status and exit reason, what it did (the analysis fills
// RunContext::summary), its cost, the ranks, choc's version and commit and the input's hash.
// When one fails, the log lists the partial results of the run.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "analysis/Analysis.hpp"
#include "output/OutputDirectory.hpp"

namespace choc {

struct RunFacts {
  std::string inputFile;
  std::string inputHash;  // FNV-1a of the input file's bytes, hexadecimal
};

void runAnalyses(RunContext& ctx, const std::vector<std::unique_ptr<Analysis>>& analyses,
                 const Teuchos::ParameterList& input, const RunFacts& facts, const OutputDirectory& out);

// FNV-1a of a file's bytes as 16 hexadecimal digits ("" when it cannot be read).
std::string fileHash(const std::string& path);

}  // namespace choc
