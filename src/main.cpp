// choc: implicit structural dynamics for impact and contact.
#include "app/Application.hpp"
#include "output/Interrupt.hpp"

namespace {
// Before the shared libraries' constructors run: the handlers first, then the signals the
// launcher blocked (build/choc, src/launcher/launcher.c) are let through, a pending one now.
void installEarly(int, char**, char**) {
  choc::installInterruptHandlers();
  choc::unblockInterruptSignals();
}
__attribute__((section(".preinit_array"), used)) void (*const preinit)(int, char**, char**) = installEarly;
}  // namespace

int main(int argc, char** argv) { return choc::runApplication(argc, argv); }
