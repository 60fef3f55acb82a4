#include "pneumachaos/sweep/distribution.hpp"

#include <cstdlib>
#include <initializer_list>

#include "mpi_transport.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/module_loader.hpp"

namespace pneumachaos::detail {
namespace {

// Launchers set these (Open MPI's mpirun, PMI/PMIx-based ones such as srun).
bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(v) != nullptr) return true;
  }
  return false;
}

#ifdef PNEUMACHAOS_HAVE_MPI
const PneumachaosMpiTransport& load_transport() {
  using Get = const PneumachaosMpiTransport* (*)();
  const auto get = reinterpret_cast<Get>(module_symbol(kMpiModuleFile, kMpiTransportSymbol));
  const PneumachaosMpiTransport* t = get();
  if (t == nullptr || t->version != kMpiTransportVersion) {
    throw RunError(kMpiModuleFile, "an MPI module of another version of pneumachaos");
  }
  return *t;
}
#endif

}  // namespace

Distribution& Distribution::instance() {
  static Distribution d;
  return d;
}

Distribution::Distribution() {
#ifdef PNEUMACHAOS_HAVE_MPI
  if (!launched_by_mpi()) return;
  mpi_ = &load_transport();
  initialized_here_ = mpi_->init(&rank_, &size_) != 0;
#endif
}

Distribution::~Distribution() {
  if (mpi_ != nullptr && initialized_here_) mpi_->finalize();
}

void Distribution::barrier() const {
  if (size_ > 1) mpi_->barrier();
}

bool Distribution::all_ok(bool ok) const {
  if (size_ > 1) return mpi_->all_ok(ok ? 1 : 0) != 0;
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
