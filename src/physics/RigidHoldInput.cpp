#include "physics/RigidHoldInput.hpp"

#include <stdexcept>

#include "core/Errors.hpp"
#include "fem/Components.hpp"
#include "input/Vector3.hpp"

namespace choc {

RigidHold rigidHoldOf(const Teuchos::ParameterList& block, bool rigid, const std::string& file,
                      const std::string& path, const std::string& notRigid) {
  const std::string held = block.get<std::string>("Held");
  const std::string speed = block.get<std::string>("Held Velocity");
  RigidHold h;
  std::vector<int> components;
  try {
    components = parseComponents(held);
  } catch (const std::invalid_argument& e) {
    throwInput(file, path + "/Held", held, e.what(), "valid: some of DX DY DZ, and DRX DRY DRZ together");
  }
  int rotations = 0;
  for (int c : components) {
    if (c < 3) h.translation[size_t(c)] = true;
    else ++rotations;
  }
  if (!components.empty() && !rigid)
    throwInput(file, path + "/Held", held, "holds the motion of a rigid body, and " + notRigid,
               "set 'Rigid' = true (a coupling's 'Type' = kinematic), or fix its nodes with a Dirichlet condition");
  if (rotations != 0 && rotations != 3)
    throwInput(file, path + "/Held", held, "a rigid body's rotations are held together (its angular velocity kept at 0)",
               "give all of DRX DRY DRZ, or none");
  h.rotation = rotations == 3;
  h.velocity = parseVector3(speed, file, path + "/Held Velocity");
  for (int c = 0; c < 3; ++c)
    if (h.velocity[size_t(c)] != 0.0 && !h.translation[size_t(c)])
      throwInput(file, path + "/Held Velocity", speed,
                 std::string("gives a speed along ") + "XYZ"[c] + ", whose component is not held",
                 "add D" + std::string(1, "XYZ"[c]) + " to 'Held', or give 0 there");
  return h;
}

}  // namespace choc
