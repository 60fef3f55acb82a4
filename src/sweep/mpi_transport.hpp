#pragma once
// The few MPI calls a distributed sweep makes, behind a C interface so that the MPI library
// lives in a module the sweep opens (dlopen) only when the process was started by an MPI
// launcher. A program that never distributes a sweep then does not load Open MPI and its
// dependencies at start-up (docs/notes/performance.md, "Start-up").

extern "C" {

/// Bumped when the table below changes, so a stale module is refused rather than misused.
inline constexpr int kMpiTransportVersion = 1;

struct PneumachaosMpiTransport {
  int version;
  /// MPI_Init unless already initialised; writes rank and size; returns 1 if it initialised.
  int (*init)(int* rank, int* size);
  /// MPI_Finalize unless already finalised.
  void (*finalize)();
  void (*barrier)();
  /// Logical AND of `ok` over every rank (a collective: every rank must call it).
  int (*all_ok)(int ok);
};

/// The module's one exported symbol.
const PneumachaosMpiTransport* pneumachaos_mpi_transport();
}

/// Name of that symbol and of the module's file, shared by the module and its loader.
inline constexpr const char* kMpiTransportSymbol = "pneumachaos_mpi_transport";
inline constexpr const char* kMpiModuleFile = "libpneumachaos_mpi.so";
