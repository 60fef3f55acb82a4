#pragma once
// Parts of the program that pull in large libraries (Open MPI; Ceres with SuiteSparse and
// BLAS) are built as modules and opened only when needed, so the other commands start
// without loading them (docs/architecture.md "Modules opened at run time").

#include <string>

namespace pneumachaos {

/// Opens the module `file` (e.g. "libpneumachaos_mpi.so") from beside the running program
/// (the build tree), else from the installed module directory relative to it
/// (LIBDIR/pneumachaos), and returns the address of its extern "C" symbol `symbol`.
/// Throws RunError naming every path tried and why it failed.
void* module_symbol(const std::string& file, const char* symbol);

}  // namespace pneumachaos
