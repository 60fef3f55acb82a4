#include "pneumachaos/io/atomic_file.hpp"

#include <cstdio>
#include <filesystem>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), temp_(path_ + ".part") {
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) throw Error(path_, "cannot create the output file");
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw RunError(path_, "write failed (disk full?)");
  out_.close();
  std::error_code ec;
  std::filesystem::rename(temp_, path_, ec);
  if (ec) throw RunError(path_, "cannot move the finished file into place: " + ec.message());
  committed_ = true;
}

}  // namespace pneumachaos
