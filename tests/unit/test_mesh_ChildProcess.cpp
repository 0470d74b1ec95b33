// runInChildProcess: the child's result comes back as bytes; a crash, an abort, a hang or an
// input error in the child becomes one InputError in the parent, which goes on running.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "core/Errors.hpp"
#include "mesh/ChildProcess.hpp"

namespace {

std::string childError(const std::function<std::string()>& work, int timeout = 120) {
  try {
    choc::runInChildProcess("/some/mesh.exo", "HDF5", work, timeout);
  } catch (const choc::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ChildProcess, TheResultComesBackAndSideEffectsStayInTheChild) {
  int touched = 0;
  const std::string big(1 << 20, 'x');  // more than a pipe buffer
  EXPECT_EQ(choc::runInChildProcess("/some/mesh.exo", "HDF5", [&] {
              touched = 1;
              return big + "end";
            }),
            big + "end");
  EXPECT_EQ(touched, 0);  // the work ran on the child's copy of the memory
}

TEST(ChildProcess, TheChildsInputErrorIsRethrownWithItsMessage) {
  EXPECT_EQ(childError([]() -> std::string {
              throw choc::InputError("/some/mesh.exo: not a mesh; fix it");
            }),
            "/some/mesh.exo: not a mesh; fix it");
}

TEST(ChildProcess, ACrashNamesTheLibraryAndTheSignal) {
  const std::string m = childError([] {
    ::raise(SIGSEGV);
    return std::string();
  });
  EXPECT_NE(m.find("/some/mesh.exo: the HDF5 library crashed (signal 11"), std::string::npos) << m;
  EXPECT_NE(m.find("it is corrupt; check that the file is a complete Exodus II mesh"),
            std::string::npos) << m;
  EXPECT_NE(childError([]() -> std::string { std::abort(); }).find("crashed (signal 6"),
            std::string::npos);
}

TEST(ChildProcess, AnyOtherExitOrExceptionIsAFailure) {
  EXPECT_NE(childError([]() -> std::string { ::_exit(1); }).find("failed (exit code 1)"),
            std::string::npos);
  EXPECT_NE(childError([]() -> std::string { throw 42; }).find("failed (exit code 98)"),
            std::string::npos);
}

TEST(ChildProcess, AHangIsKilledAtTheDeadline) {
  const std::string m = childError(
      [] {
        ::pause();
        return std::string();
      },
      1);
  EXPECT_NE(m.find("took more than 1 s"), std::string::npos) << m;
}

}  // namespace
