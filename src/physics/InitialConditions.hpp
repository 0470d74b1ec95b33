// Initial displacement and velocity fields from node sets, as 'Initial Conditions' named
// sublists: Node Set, Field (Displacement|Velocity: Components and Value; Rigid Velocity: the
// velocity of a rigid motion, Translation + Angular Velocity x (x - Centre), on every
// translation and Angular Velocity on the rotations). Components that are not unknowns are
// ignored (they are fixed at zero).
#pragma once
#include <Teuchos_ParameterList.hpp>

#include "physics/Model.hpp"

namespace choc {

void declareInitialConditions(Teuchos::ParameterList& analysisParameters);

struct InitialFields {
  RCP<Vector> displacement, velocity;
};

InitialFields buildInitialFields(const Teuchos::ParameterList& analysisParameters,
                                 const Model& model, const std::string& analysisPath);

}  // namespace choc
