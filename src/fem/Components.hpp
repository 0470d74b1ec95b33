// Nodal degrees of freedom by name. DX..DZ translations, DRX..DRZ rotations.
#pragma once
#include <string>
#include <vector>

namespace choc {

enum Component : int { DX = 0, DY = 1, DZ = 2, DRX = 3, DRY = 4, DRZ = 5 };

// The components of a vector field written to Exodus: DX, DY for a 2D mesh (ParaView then
// shows it as 2D), DX, DY, DZ otherwise.
inline std::vector<int> spatialComponents(int meshDimension) {
  return meshDimension == 2 ? std::vector<int>{DX, DY} : std::vector<int>{DX, DY, DZ};
}
constexpr int kNumComponents = 6;

const char* componentName(int c);                 // "DX" ...
int componentFromName(const std::string& name);   // -1 when unknown (case-insensitive)
// Parses "DX DY" / "DX,DY" / "all" / "translations" into components; throws
// std::invalid_argument naming the bad token.
std::vector<int> parseComponents(const std::string& text);

}  // namespace choc
