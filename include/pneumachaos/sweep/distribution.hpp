#pragma once
// Which share of a sweep this process computes: all of it, or under `mpirun -np N` the runs
// whose index is congruent to its rank. MPI is used only when the build has it AND the
// process was started by an MPI launcher, so the same binary works on its own; only then is
// the MPI module (libpneumachaos_mpi.so, mpi_transport.hpp) opened.

struct PneumachaosMpiTransport;

namespace pneumachaos::detail {

class Distribution {
 public:
  static Distribution& instance();
  [[nodiscard]] int rank() const { return rank_; }
  [[nodiscard]] int size() const { return size_; }
  /// Waits for every rank (no-op without MPI).
  void barrier() const;
  /// Waits for every rank and tells whether all of them passed `ok` = true: a barrier that a
  /// failed rank still reaches, so no rank waits forever for one that threw.
  [[nodiscard]] bool all_ok(bool ok) const;
  /// Whether this build has the MPI module.
  static bool built_with_mpi();

 private:
  Distribution();
  ~Distribution();
  const PneumachaosMpiTransport* mpi_ = nullptr;  ///< set only under an MPI launcher
  int rank_ = 0;
  int size_ = 1;
  bool initialized_here_ = false;
};

}  // namespace pneumachaos::detail
