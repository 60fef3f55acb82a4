#include "journal.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos::detail {

Journal::Journal(const std::string& path, const std::string& fingerprint, bool resume)
    : path_(path) {
  const std::string header = "# pneumachaos sweep journal, spec " + fingerprint;
  if (std::filesystem::exists(path)) {
    if (!resume) {
      throw Error(path,
                  "this directory already holds a sweep: add --resume to finish it, or "
                  "choose another --out");
    }
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    std::string all = text.str();
    // Keep only complete lines: a kill during a write leaves a torn tail.
    const auto last_newline = all.rfind('\n');
    const std::size_t keep = last_newline == std::string::npos ? 0 : last_newline + 1;
    if (keep < all.size()) {
      all.resize(keep);
      std::filesystem::resize_file(path, keep);
    }
    std::istringstream lines(all);
    std::string line;
    std::size_t n = 0;
    while (std::getline(lines, line)) {
      ++n;
      if (n == 1) {
        if (line != header) {
          throw Error(path,
                      "the journal belongs to a different sweep (another scenario, grid, "
                      "repeats or seed); refusing to resume into it");
        }
        continue;
      }
      try {
        existing_.push_back(RunRecord::decode(line));
      } catch (const Error& e) {
        throw Error(fmt::format("{}:{}", path, n), e.what());
      }
    }
    if (n == 0) throw Error(path, "the journal is empty; remove it to start afresh");
  } else if (resume) {
    // Nothing to resume is fine: start the sweep.
  }
  file_ = std::fopen(path.c_str(), "ab");
  if (file_ == nullptr) throw Error(path, "cannot open the journal for writing");
  if (existing_.empty() && std::ftell(file_) == 0) {
    std::fputs((header + "\n").c_str(), file_);
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
