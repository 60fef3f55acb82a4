#include "pneumachaos/io/atomic_file.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

namespace {

// The nearest ancestor of `p` that exists ("." for a relative path with none), and whether it
// is a directory this process may write into.
std::string ancestor_problem(const std::filesystem::path& p) {
  std::filesystem::path a = p.parent_path();
  std::error_code ec;
  while (!a.empty() && !std::filesystem::exists(a, ec)) a = a.parent_path();
  if (a.empty()) a = ".";
  if (!std::filesystem::is_directory(a, ec))
    return fmt::format("cannot be created: {} is not a directory", a.string());
  if (::access(a.c_str(), W_OK) != 0)
    return fmt::format("cannot be created: the directory {} is not writable", a.string());
  return "";
}

}  // namespace

std::string output_file_problem(const std::string& path) {
  std::error_code ec;
  if (path.empty()) return "is empty; expected a file name";
  if (std::filesystem::is_directory(path, ec) || path.ends_with('/'))
    return "is a directory; expected a file name";
  // A device or a pipe would be replaced by the finished file's rename: /dev/null with a
  // regular file. Standard output is the way to write there.
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    return "exists and is not a regular file (a device or a pipe?): write to standard output "
           "instead";
  return ancestor_problem(std::filesystem::path(path));
}

std::string output_directory_problem(const std::string& path) {
  std::error_code ec;
  if (path.empty()) return "is empty; expected a directory name";
  std::filesystem::path p(path);
  if (std::filesystem::exists(p, ec))
    return std::filesystem::is_directory(p, ec) ? "" : "exists and is not a directory";
  if (!p.has_filename()) p = p.parent_path();  // "out/" names "out"
  return ancestor_problem(p);
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), temp_(path_ + ".part") {
  if (const std::string problem = output_file_problem(path_); !problem.empty())
    throw Error(path_, problem);
  const std::filesystem::path target(path_);
  if (target.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(target.parent_path(), ec);
    if (ec) throw Error(target.parent_path().string(), "cannot create the directory: " + ec.message());
  }
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
