// granmc: the command line. Everything happens in drivers/cli.cpp.
#include "drivers/cli.hpp"

int main(int argc, char** argv) { return granmc::cli_main(argc, argv); }
