#include "distribution.hpp"

#include <cstdlib>
#include <initializer_list>

#ifdef PNEUMACHAOS_HAVE_MPI
#include <mpi.h>
#endif

namespace pneumachaos::detail {
namespace {

// Launchers set these (Open MPI's mpirun, PMI/PMIx-based ones such as srun).
bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(v) != nullptr) return true;
  }
  return false;
}

}  // namespace

Distribution& Distribution::instance() {
  static Distribution d;
  return d;
}

Distribution::Distribution() {
#ifdef PNEUMACHAOS_HAVE_MPI
  if (!launched_by_mpi()) return;
  int already = 0;
  MPI_Initialized(&already);
  if (already == 0) {
    MPI_Init(nullptr, nullptr);
    initialized_here_ = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#endif
}

Distribution::~Distribution() {
#ifdef PNEUMACHAOS_HAVE_MPI
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (initialized_here_ && finalized == 0) MPI_Finalize();
#endif
}

void Distribution::barrier() const {
#ifdef PNEUMACHAOS_HAVE_MPI
  if (size_ > 1) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

bool Distribution::all_ok(bool ok) const {
#ifdef PNEUMACHAOS_HAVE_MPI
  if (size_ > 1) {
    int mine = ok ? 1 : 0, all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
    return all != 0;
  }
#endif
  return ok;
}

bool Distribution::built_with_mpi() {
#ifdef PNEUMACHAOS_HAVE_MPI
  return true;
#else
  return false;
#endif
}

}  // namespace pneumachaos::detail
