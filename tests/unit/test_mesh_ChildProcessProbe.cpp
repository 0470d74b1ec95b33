// probeInChildProcess: a crash, an abort, a hang or an input error in the child becomes one
// InputError in the parent, which goes on running.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "input/Errors.hpp"
#include "mesh/ChildProcessProbe.hpp"

namespace {

std::string probeError(const std::function<void()>& read, int timeout = 120) {
  try {
    choc::probeInChildProcess("/some/mesh.exo", "HDF5", read, timeout);
  } catch (const choc::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ChildProcessProbe, SuccessReturnsAndSideEffectsStayInTheChild) {
  int touched = 0;
  EXPECT_EQ(probeError([&] { touched = 1; }), "");
  EXPECT_EQ(touched, 0);  // the read ran in the child's copy of the memory
}

TEST(ChildProcessProbe, TheChildsInputErrorIsRethrownWithItsMessage) {
  EXPECT_EQ(probeError([] { throw choc::InputError("/some/mesh.exo: not a mesh; fix it"); }),
            "/some/mesh.exo: not a mesh; fix it");
}

TEST(ChildProcessProbe, ACrashNamesTheLibraryAndTheSignal) {
  const std::string m = probeError([] { ::raise(SIGSEGV); });
  EXPECT_NE(m.find("/some/mesh.exo: the HDF5 library crashed (signal 11"), std::string::npos) << m;
  EXPECT_NE(m.find("it is corrupt; check that the file is a complete Exodus II mesh"),
            std::string::npos) << m;
  EXPECT_NE(probeError([] { std::abort(); }).find("crashed (signal 6"), std::string::npos);
}

TEST(ChildProcessProbe, AnyOtherExitOrExceptionIsAFailure) {
  EXPECT_NE(probeError([] { ::_exit(1); }).find("failed (exit code 1)"), std::string::npos);
  EXPECT_NE(probeError([] { throw 42; }).find("failed (exit code 98)"), std::string::npos);
}

TEST(ChildProcessProbe, AHangIsKilledAtTheDeadline) {
  const std::string m = probeError([] { ::pause(); }, 1);
  EXPECT_NE(m.find("took more than 1 s"), std::string::npos) << m;
}

}  // namespace
