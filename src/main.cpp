// choc: implicit structural dynamics for impact and contact.
#include "app/Application.hpp"

int main(int argc, char** argv) { return choc::runApplication(argc, argv); }
