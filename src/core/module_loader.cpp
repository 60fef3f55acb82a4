#include "pneumachaos/core/module_loader.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>

#include "pneumachaos/core/error.hpp"

#ifndef PNEUMACHAOS_MODULE_RELDIR
#error "PNEUMACHAOS_MODULE_RELDIR: the module directory relative to the program's (CMakeLists.txt)"
#endif

namespace pneumachaos {

void* module_symbol(const std::string& file, const char* symbol) {
  std::error_code ec;
  const auto dir = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path();
  std::string tried;
  for (const auto& path : {dir / file, dir / PNEUMACHAOS_MODULE_RELDIR / file}) {
    // RTLD_GLOBAL: Open MPI opens its own plugins, which look up MPI's symbols globally.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (handle == nullptr) {
      tried += std::string("\n  ") + dlerror();  // names the path
      continue;
    }
    if (void* address = dlsym(handle, symbol)) return address;
    tried += "\n  " + path.string() + ": no symbol " + symbol;
  }
  throw RunError(file, "this part of the program is a module that cannot be opened:" + tried);
}

}  // namespace pneumachaos
