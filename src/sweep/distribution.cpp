#include "distribution.hpp"

#include <dlfcn.h>
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <system_error>
#include <vector>

#include "mpi_transport.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos::detail {
namespace {

// Launchers set these (Open MPI's mpirun, PMI/PMIx-based ones such as srun).
bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(v) != nullptr) return true;
  }
  return false;
}

#ifdef PNEUMACHAOS_MPI_MODULE_RELDIR
// Where the module is looked for: beside the program (the build tree), then in the library
// directory relative to it (an installed tree: bin/ and lib/pneumachaos/).
std::vector<std::filesystem::path> module_candidates() {
  std::error_code ec;
  const auto exe_dir = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path();
  return {exe_dir / kMpiModuleFile, exe_dir / PNEUMACHAOS_MPI_MODULE_RELDIR / kMpiModuleFile};
}

// RTLD_GLOBAL: Open MPI's own plugins, which it opens in turn, resolve MPI symbols globally.
const PneumachaosMpiTransport& load_transport() {
  std::string tried;
  for (const auto& path : module_candidates()) {
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (handle == nullptr) {
      tried += fmt::format("\n  {}", dlerror());  // names the path
      continue;
    }
    using Get = const PneumachaosMpiTransport* (*)();
    auto get = reinterpret_cast<Get>(dlsym(handle, kMpiTransportSymbol));
    const PneumachaosMpiTransport* t = get != nullptr ? get() : nullptr;
    if (t != nullptr && t->version == kMpiTransportVersion) return *t;
    tried += fmt::format("\n  {}: not a pneumachaos MPI module of this version", path.string());
  }
  throw RunError("MPI module", "started by an MPI launcher, but the module that distributes "
                               "the sweep cannot be opened:" + tried);
}
#endif

}  // namespace

Distribution& Distribution::instance() {
  static Distribution d;
  return d;
}

Distribution::Distribution() {
#ifdef PNEUMACHAOS_MPI_MODULE_RELDIR
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
#ifdef PNEUMACHAOS_MPI_MODULE_RELDIR
  return true;
#else
  return false;
#endif
}

}  // namespace pneumachaos::detail
