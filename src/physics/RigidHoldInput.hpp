// A rigid block's held motion (Model/Blocks/<name>/Held and Held Velocity; rigid/RigidBody.hpp
// RigidHold): the components of its centre's velocity kept at a given speed and its rotation
// stopped. Throws InputError naming the file and parameter for a hold on a block that is not
// rigid, an unknown component, some rotations held and not others, or a velocity given for a
// component that is not held.
#pragma once
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "rigid/RigidBody.hpp"

namespace choc {

// notRigid: why a hold does not apply when rigid is false ("the block is not rigid").
RigidHold rigidHoldOf(const Teuchos::ParameterList& block, bool rigid, const std::string& file,
                      const std::string& path, const std::string& notRigid = "the block is not rigid");

}  // namespace choc
