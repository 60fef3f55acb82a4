#pragma once
// Output files that are either complete or absent: written to a temporary beside the target
// and renamed into place on commit(), so an interrupted run never leaves a half-written file
// that looks complete.

#include <fstream>
#include <string>

namespace pneumachaos {

class AtomicFile {
 public:
  /// Opens "<path>.part"; throws Error if it cannot be created.
  explicit AtomicFile(std::string path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  /// Removes the temporary if commit() was not reached.
  ~AtomicFile();

  std::ofstream& stream() { return out_; }
  /// Flushes, checks for write errors and renames into place; throws Error on failure.
  void commit();

 private:
  std::string path_;
  std::string temp_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace pneumachaos
