// The loads of a transient from its input: 'Nodal Forces' (a force per node of a node set) and
// 'Pressures' (dead on the reference faces, or followers on finite-strain blocks), each a load
// group with its ramp (Loads.hpp).
#pragma once
#include <memory>
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "physics/Loads.hpp"
#include "physics/Model.hpp"

namespace choc {

// The loads of the analysis whose parameters are `analysis` (at analysisPath, "Analyses/<name>",
// in inputFile); null when it has none. Throws InputError naming the key at fault.
std::shared_ptr<const Loads> assembleLoads(Model& model, const Teuchos::ParameterList& analysis,
                                           const std::string& inputFile, const std::string& analysisPath);

}  // namespace choc
