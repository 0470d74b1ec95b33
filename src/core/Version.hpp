// choc's version and the commit it was built from ("unknown" outside a git checkout; a
// "-modified" suffix when the tree had uncommitted changes). Generated at build time
// (cmake/Version.cmake).
#pragma once

namespace choc {

const char* chocVersion();
const char* chocCommit();

}  // namespace choc
