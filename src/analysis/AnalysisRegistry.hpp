// The analysis types an input may ask for, with their valid parameters and factories.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "analysis/Analysis.hpp"

namespace choc {

struct AnalysisType {
  std::string type;  // value of the 'Type' key
  std::string doc;
  std::function<Teuchos::ParameterList()> parameters;  // includes 'Type'
  std::function<std::unique_ptr<Analysis>(const std::string& name, const Teuchos::ParameterList&,
                                          const std::string& inputFile)>
      create;
};

const std::vector<AnalysisType>& analysisTypes();

// Validates every sublist of `analyses` (in place, filling defaults) against its Type.
void validateAnalyses(Teuchos::ParameterList& analyses, const std::string& inputFile);

std::vector<std::unique_ptr<Analysis>> createAnalyses(const Teuchos::ParameterList& analyses,
                                                      const std::string& inputFile);

// Sets every analysis up on the model, in input order (a modal transient sees the Modal
// analyses before it): every reference is resolved, nothing is computed or written.
void setupAnalyses(const std::vector<std::unique_ptr<Analysis>>& analyses, Model& model);

}  // namespace choc
