#include "journal.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos::detail {

namespace {

std::string header_of(const std::string& fingerprint) {
  return "# pneumachaos sweep journal, spec " + fingerprint;
}

// Records of one journal file; `cut` truncates a torn tail (only for the own file: another
// rank may be writing its tail right now).
std::vector<RunRecord> read_journal(const std::string& path, const std::string& fingerprint,
                                    bool cut) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string all = text.str();
  const auto last_newline = all.rfind('\n');
  const std::size_t keep = last_newline == std::string::npos ? 0 : last_newline + 1;
  if (keep < all.size()) {
    all.resize(keep);
    if (cut) std::filesystem::resize_file(path, keep);
  }
  std::vector<RunRecord> records;
  std::istringstream lines(all);
  std::string line;
  std::size_t n = 0;
  while (std::getline(lines, line)) {
    ++n;
    if (n == 1) {
      if (line != header_of(fingerprint)) {
        throw Error(path,
                    "the journal belongs to a different sweep (another scenario, grid, "
                    "repeats or seed); refusing to resume into it");
      }
      continue;
    }
    try {
      records.push_back(RunRecord::decode(line));
    } catch (const Error& e) {
      throw Error(fmt::format("{}:{}", path, n), e.what());
    }
  }
  return records;
}

std::vector<std::string> journal_files(const std::string& dir) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("journal", 0) == 0 && entry.path().extension() == ".csv") {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

std::vector<RunRecord> Journal::read_all(const std::string& dir, const std::string& fingerprint) {
  std::vector<RunRecord> all;
  for (const auto& f : journal_files(dir)) {
    auto r = read_journal(f, fingerprint, false);
    all.insert(all.end(), r.begin(), r.end());
  }
  return all;
}

Journal::Journal(const std::string& dir, const std::string& own_name,
                 const std::string& fingerprint, bool resume)
    : path_(dir + "/" + own_name) {
  const auto files = journal_files(dir);
  if (!files.empty() && !resume) {
    throw Error(dir,
                "this directory already holds a sweep: add --resume to finish it, or "
                "choose another --out");
  }
  for (const auto& f : files) {
    auto r = read_journal(f, fingerprint, f == path_);
    existing_.insert(existing_.end(), r.begin(), r.end());
  }
  const bool fresh = !std::filesystem::exists(path_) || std::filesystem::file_size(path_) == 0;
  file_ = std::fopen(path_.c_str(), "ab");
  if (file_ == nullptr) throw Error(path_, "cannot open the journal for writing");
  if (fresh) {
    std::fputs((header_of(fingerprint) + "\n").c_str(), file_);
    std::fflush(file_);
    ::fsync(::fileno(file_));
  }
}

Journal::~Journal() {
  if (file_ != nullptr) std::fclose(file_);
}

void Journal::append(const RunRecord& record) {
  const std::string line = record.encode() + "\n";
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size() || std::fflush(file_) != 0 ||
      ::fsync(::fileno(file_)) != 0) {
    throw Error(path_, "cannot append to the journal (disk full?)");
  }
}

}  // namespace pneumachaos::detail
