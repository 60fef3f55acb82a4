// The MPI side of a distributed sweep, built as the module libpneumachaos_mpi.so (see
// mpi_transport.hpp for why it is a separate module).

#include "mpi_transport.hpp"

#include <mpi.h>

namespace {

int init(int* rank, int* size) {
  int already = 0;
  MPI_Initialized(&already);
  if (already == 0) MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, size);
  return already == 0 ? 1 : 0;
}

void finalize() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized == 0) MPI_Finalize();
}

void barrier() { MPI_Barrier(MPI_COMM_WORLD); }

int all_ok(int ok) {
  int all = 0;
  MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
  return all;
}

constexpr PneumachaosMpiTransport kTransport{kMpiTransportVersion, init, finalize, barrier, all_ok};

}  // namespace

extern "C" __attribute__((visibility("default"))) const PneumachaosMpiTransport*
pneumachaos_mpi_transport() {
  return &kTransport;
}
