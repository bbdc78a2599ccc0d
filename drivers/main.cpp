// granmc: the command line. Everything happens in drivers/cli.cpp.
#include "drivers/cli.hpp"
#ifdef GRANMC_HAVE_MPI
#include "drivers/mpi_replicas.hpp"
#endif

int main(int argc, char** argv) {
#ifdef GRANMC_HAVE_MPI
  granmc::mpi::Session mpi(
      argc, argv);  // MPI_Init_thread here, MPI_Finalize after cli_main (docs/developer-guide/scaling.md)
#endif
  return granmc::cli_main(argc, argv);
}
