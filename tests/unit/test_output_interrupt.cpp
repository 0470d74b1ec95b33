// The interruption flag: a signal only sets it; throwIfInterrupted turns it into
// choc::Interrupted with the shell's exit code (128 + signal) and a message naming the time.
#include <gtest/gtest.h>

#include <csignal>
#include <string>

#include "output/Interrupt.hpp"

namespace choc {
namespace {

struct ClearFlag {
  ~ClearFlag() { setInterruptForTesting(0); }
};

TEST(Interrupt, NoSignalNoThrow) {
  ClearFlag clear;
  setInterruptForTesting(0);
  EXPECT_FALSE(interruptRequested());
  EXPECT_NO_THROW(throwIfInterrupted("modal transient 'x'", 1e-3));
}

TEST(Interrupt, SigtermGives143AndNamesTheTime) {
  ClearFlag clear;
  installInterruptHandlers();
  std::raise(SIGTERM);  // the handler only records it: the process goes on
  ASSERT_TRUE(interruptRequested());
  EXPECT_EQ(interruptSignal(), SIGTERM);
  try {
    throwIfInterrupted("modal transient 'x'", 2.5e-4);
    FAIL() << "no exception";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.exitCode(), 143);
    EXPECT_EQ(std::string(e.what()),
              "SIGTERM received: modal transient 'x' stopped at t = 2.500000e-04 s "
              "(the last completed step)");
  }
}

TEST(Interrupt, SigintGives130) {
  ClearFlag clear;
  installInterruptHandlers();
  std::raise(SIGINT);
  try {
    throwIfInterruptedBefore("analysis 'b'");
    FAIL() << "no exception";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.exitCode(), 130);
    EXPECT_EQ(std::string(e.what()), "SIGINT received: run stopped before analysis 'b'");
  }
}

}  // namespace
}  // namespace choc
