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

void AtomicFile::finish() {
  out_.flush();
  if (!out_) throw RunError(path_, "write failed (disk full?)");
  out_.close();
  if (!out_) throw RunError(path_, "write failed (disk full?)");
}

void AtomicFile::publish() {
  std::error_code ec;
  std::filesystem::rename(temp_, path_, ec);
  if (ec) throw RunError(path_, "cannot move the finished file into place: " + ec.message());
  committed_ = true;
}

std::ofstream& OutputSet::add(const std::string& path) {
  const std::filesystem::path target(path);
  std::error_code ec;
  if (std::filesystem::is_directory(target, ec)) {
    throw Error(path, "is a directory; expected a file name");
  }
  if (target.has_parent_path()) {
    std::filesystem::create_directories(target.parent_path(), ec);
    if (ec) throw Error(target.parent_path().string(), "cannot create the directory: " + ec.message());
  }
  files_.push_back(std::make_unique<AtomicFile>(path));
  return files_.back()->stream();
}

void OutputSet::commit() {
  for (auto& f : files_) f->finish();
  for (std::size_t i = 0; i < files_.size(); ++i) {
    try {
      files_[i]->publish();
    } catch (const Error&) {
      for (std::size_t k = 0; k < i; ++k) {
        std::error_code ec;
        std::filesystem::remove(files_[k]->path(), ec);
      }
      throw;
    }
  }
}

}  // namespace pneumachaos
